"""Buildings scenes whose cell DAT records take shapes ACE's DatLoader reads and its physics runs but no other draw
gives: housing barriers (scene/8 `env_cells[].restriction_obj`, `landblocks[].restrictions`) and visible cells or
building portals naming a low word below 0x0100 (scene/8, acconform.scene.OUTDOOR_WORD_LAST).

`draw_cell_records_scene` takes a drawn buildings scene (placed or not, as `scenes_of` draws it) and changes one of:

- `restriction`: some EnvCells get a RestrictionObj and the landblock a restriction table over some of its land
  cells (a key may be an EnvCell's id, which has no land coordinate, or a neighbour landblock's land cell, whose low
  three coordinate bits name a cell of this one). The object is the mover's id (ServerObjectManager finds it, its
  WeenieObject is no House's: CanMoveInto answers true and the restriction is verified for the transition) or an id
  no object has (GetObjectA answers null: Collided on entering the cell);
- `visible`: an EnvCell sees a low word 0x0000 or 0x0041..0x00FF (VisibleCells holds null) or, rarely, a land
  cell's 0x0001..0x0040 (build_visible_cells' cast throws InvalidCastException);
- `portal`: a building gets one more portal whose other cell is such a low word (GetOtherCell answers null, or its
  cast throws);
- `no_drawing_bsp`: some cell structures are written with hasDrawingBSP 0 (scene/8 `drawing_bsp: false`): ACE's
  CellStruct keeps DrawingBSP null, which its physics never reads;
- `missing_key` (Scene.has_missing_keys): an EnvCell names a cell structure its Environment lacks (CellStructure
  stays null: the first physics read of it throws NullReferenceException), one of its portals a polygon past its
  structure's (find_transit_cells' Polygons[PolygonId] throws KeyNotFoundException), or a structure lists a portal
  past its polygons (CellStruct's constructor throws KeyNotFoundException building the cell), or a leaf of a
  building shell's or a cell structure's physics tree names a polygon past the shape's (BSPNode's constructor throws
  KeyNotFoundException building the tree: at PostInit's init_buildings, or loading the cell);
- `cell_bsp_portal`: some nodes of the cell structures' cell trees are written with the tag PORT (scene/8 `portal`;
  a missing child becomes a leaf, as a PORT node has both): DatLoader's BSPPortal reads them as BPIN nodes.

No campaign kind draws it: a draw added to a kind would move every seeded sample the tests pin.
"""

from __future__ import annotations

from dataclasses import replace

from hypothesis import strategies as st

from acconform.scene import BSPLeaf, BuildingPortalRec, CellBSPLeaf, CellBSPNode, Scene
from acconform.staging import MOVER_ID

from .scenes import draw_scene
from .set_position import with_placement

CELL_RECORD_SHAPES = st.sampled_from(("restriction", "restriction", "visible", "portal", "no_drawing_bsp", "missing_key",
                                      "cell_bsp_portal"))
MISSING_KEYS = st.sampled_from(("cell_structure", "cell_portal", "struct_portal", "shell_leaf", "cell_leaf"))
# ServerObjectManager's answers: the mover (a Player's WeenieObject: CanMoveInto true) or nothing (null: Collided)
RESTRICTION_OBJECTS = st.sampled_from((MOVER_ID, 0x7ABC0001, 0x7ABC0001))
# low words with no land coordinate (get_landcell: null) and, one in five, a land cell's (a LandCell: the cast throws)
NULL_WORDS = st.sampled_from((0x0000, 0x0041, 0x0080, 0x00FF))
LAND_WORDS = st.integers(0x0001, 0x0040)


def _low_word(draw) -> int:
    return draw(LAND_WORDS) if draw(st.integers(0, 4)) == 0 else draw(NULL_WORDS)


def _restrict(draw, scene: Scene) -> Scene:
    obj = draw(RESTRICTION_OBJECTS)
    cells = tuple(replace(c, restriction_obj=obj) if draw(st.booleans()) else c for c in scene.env_cells)
    with_buildings = {b.landblock for b in scene.buildings}
    landblocks = []
    for lb in scene.landblocks:
        if lb.id in with_buildings:
            block = lb.id & 0xFFFF0000
            keys = sorted({draw(st.integers(1, 64)) for _ in range(draw(st.integers(0, 64)))}) if draw(
                st.integers(0, 3)) else list(range(1, 65))  # some land cells, or all 64
            pairs = [(block | k, obj) for k in keys]
            if draw(st.integers(0, 3)) == 0 and scene.env_cells:  # an EnvCell's id: no land coordinate, skipped
                pairs.insert(draw(st.integers(0, len(pairs))), (scene.env_cells[0].id, obj))
            if draw(st.integers(0, 3)) == 0:  # a neighbour's land cell: this landblock's cell at the same place
                pairs.append(((block + 0x01000000) & 0xFFFF0000 | draw(st.integers(1, 64)), obj))
                if len({c for c, _ in pairs}) != len(pairs):
                    pairs.pop()
            lb = replace(lb, restrictions=tuple(pairs))
        landblocks.append(lb)
    return scene.replace(env_cells=cells, landblocks=tuple(landblocks))


def _visible(draw, scene: Scene) -> Scene:
    if not scene.env_cells:
        return scene
    # mostly the mover's begin cell, its null first: a placement's adjust_position meets it in
    # find_visible_child_cell before the cell that holds the point
    begin = [k for k, c in enumerate(scene.env_cells) if c.id == scene.mover.begin.cell]
    i = begin[0] if begin and draw(st.integers(0, 3)) else draw(st.integers(0, len(scene.env_cells) - 1))
    cells = list(scene.env_cells)
    words = list(cells[i].visible_cells)
    words.insert(0 if draw(st.booleans()) else draw(st.integers(0, len(words))), _low_word(draw))
    cells[i] = replace(cells[i], visible_cells=tuple(words))
    return scene.replace(env_cells=tuple(cells))


def _portal(draw, scene: Scene) -> Scene:
    if not scene.buildings:
        return scene
    i = draw(st.integers(0, len(scene.buildings) - 1))
    buildings = list(scene.buildings)
    portals = list(buildings[i].portals)
    portals.insert(draw(st.integers(0, len(portals))), BuildingPortalRec(_low_word(draw), 0xFFFF))
    buildings[i] = replace(buildings[i], portals=tuple(portals))
    return scene.replace(buildings=tuple(buildings))


def _no_drawing_bsp(draw, scene: Scene) -> Scene:
    envs = tuple(replace(e, cell_structs=tuple(replace(c, drawing_bsp=False) if draw(st.integers(0, 3)) else c
                                               for c in e.cell_structs)) for e in scene.environments)
    return scene.replace(environments=envs)


def _leaf_plus(node, poly: int):
    """The tree with polygon id `poly` added to its first leaf (pre-order)."""
    if isinstance(node, BSPLeaf):
        return replace(node, polygons=(*node.polygons, poly))
    return replace(node, front=_leaf_plus(node.front, poly))


def _missing_key(draw, scene: Scene) -> Scene:
    if not scene.env_cells:
        return scene
    which = draw(MISSING_KEYS)
    if which == "shell_leaf" and scene.buildings:
        b = scene.buildings[0]
        shape = replace(b.shape, root=_leaf_plus(b.shape.root, len(b.shape.polygons) + draw(st.integers(0, 2))))
        return scene.replace(buildings=(replace(b, shape=shape), *scene.buildings[1:]))
    begin = [k for k, c in enumerate(scene.env_cells) if c.id == scene.mover.begin.cell]
    i = begin[0] if begin and draw(st.booleans()) else draw(st.integers(0, len(scene.env_cells) - 1))
    cells, envs = list(scene.env_cells), {e.id: e for e in scene.environments}
    env = envs[cells[i].environment]
    struct = env.cell_structs[cells[i].cell_structure]
    if which == "cell_structure":
        cells[i] = replace(cells[i], cell_structure=len(env.cell_structs) + draw(st.integers(0, 2)))
    elif which == "cell_leaf" and struct.physics_bsp is not None:
        changed = replace(struct, physics_bsp=_leaf_plus(struct.physics_bsp, len(struct.physics_polygons)))
        structs = tuple(changed if c is struct else c for c in env.cell_structs)
        return scene.replace(environments=tuple(replace(e, cell_structs=structs) if e.id == env.id else e
                                                for e in scene.environments))
    elif which == "cell_portal" and cells[i].portals:
        k = draw(st.integers(0, len(cells[i].portals) - 1))
        portals = list(cells[i].portals)
        portals[k] = replace(portals[k], polygon=len(struct.polygons) + draw(st.integers(0, 2)))
        cells[i] = replace(cells[i], portals=tuple(portals))
    else:
        changed = replace(struct, portals=(*struct.portals, len(struct.polygons) + draw(st.integers(0, 2))))
        structs = tuple(changed if c is struct else c for c in env.cell_structs)
        return scene.replace(environments=tuple(replace(e, cell_structs=structs) if e.id == env.id else e
                                                for e in scene.environments))
    return scene.replace(env_cells=tuple(cells))


def _port_nodes(draw, node):
    """The cell tree with some of its nodes tagged PORT, a missing child made a leaf (a PORT node has both)."""
    if not isinstance(node, CellBSPNode):
        return node
    front, back = _port_nodes(draw, node.front), _port_nodes(draw, node.back)
    if draw(st.booleans()):
        return replace(node, front=front or CellBSPLeaf(), back=back or CellBSPLeaf(), portal=True)
    return replace(node, front=front, back=back)


def _cell_bsp_portal(draw, scene: Scene) -> Scene:
    envs = tuple(replace(e, cell_structs=tuple(replace(c, cell_bsp=_port_nodes(draw, c.cell_bsp)) for c in e.cell_structs))
                 for e in scene.environments)
    return scene.replace(environments=envs)


def draw_cell_records_scene(draw, kind: str = "buildings") -> Scene:
    """A buildings scene with one of the cell-record shapes of the module docstring."""
    scene = with_placement(draw, draw_scene(draw, kind))
    shape = draw(CELL_RECORD_SHAPES)
    changed = {"restriction": _restrict, "visible": _visible, "portal": _portal,
               "no_drawing_bsp": _no_drawing_bsp, "missing_key": _missing_key, "cell_bsp_portal": _cell_bsp_portal}[shape](draw, scene)
    return changed.replace(name=f"{scene.name}:{shape}")
