"""The scene: everything one transition needs, as immutable records with a versioned JSON form.

A scene is what both the port and the oracle take. Format ``acconform.scene/8`` (README's
"Scene format" section documents every field); ``/7``, ``/6``, ``/5``, ``/4``, ``/3``, ``/2`` and ``/1`` files still read
(a /7 scene is a /8 scene without other movers (``others``); a /6 scene is a /7 scene whose statics each have one ``shape``, none a ``setup`` of several parts; a /5 scene is a /6 scene whose placements go through SetPosition: its ``placement`` has no ``via``, and
means ``"via": "set_position"``; a /4 scene is a /5 scene without ``buildings``; a /3 scene is a /4 scene without ``ticks``; a /2 scene is a /3 scene whose mover has no ``placement``; a
/1 scene is a /2 scene without indoor fields: no environments, no EnvCells, every landblock with
terrain). A scene with ``ticks`` is a tick scene: the mover has no ``end``, and ACE's per-tick
update (`Ticks.driver`) moves it once per step (issue 19). A scene is written in the
oldest version that holds it, so files, corpus records and their keys stay as they were. All floats are float32 values held as Python
floats; ids are uint32. Construction from JSON validates and names the bad field; records built
in code (e.g. by the strategies) are checked the same way by `validate_scene`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Union

from .codec import (Reader, as_text, dumps, dumps_compact, f32_text, ints_text, parse_json_text, vec_text, write_f32,
                    write_f64, write_id, write_vec)
from .errors import InvalidScene
from .motion_scene import CommandInput, MotionInput, MotionTableSpec, MoveToInput, ObjectMoveInput, read_stop
from .motion_enums import MotionCommand as _MotionCommand
from .flags import (PLAYER_KILLER_STATUS_NPK, CullMode, ParentLocation, PhysicsState, PlayerKillerStatus, SetPositionFlags,
                    TransientState, flag_names)

FORMAT = "acconform.scene/8"
FORMAT_V7 = "acconform.scene/7"  # what a scene with no other movers (`others`) is written as
FORMAT_V6 = "acconform.scene/6"  # what a scene with no multi-part static (a static's `setup`) is written as
FORMAT_V5 = "acconform.scene/5"  # what a scene with buildings and no placement through enter_world is written as
FORMAT_V4 = "acconform.scene/4"  # what a scene with ticks and no buildings is written as
FORMAT_V3 = "acconform.scene/3"  # what a scene with a placement and no ticks is written as
FORMAT_V2 = "acconform.scene/2"  # what a scene without a placement is written as (every /2 reader reads it)
FORMAT_V1 = "acconform.scene/1"  # what an outdoor scene is written as (every /1 reader reads it)

Vec3 = tuple[float, float, float]
Quat = tuple[float, float, float, float]  # (w, x, y, z), as AC's own files write frames

# ACE reads the land height table from the region DAT; with no DAT the scene carries one.
# Default: 2 m per index (index i -> 2.0 * i), exactly representable, covering 0..510 m.
DEFAULT_LAND_HEIGHT_TABLE: tuple[float, ...] = tuple(2.0 * i for i in range(256))

IDENTITY: Quat = (1.0, 0.0, 0.0, 0.0)

_CULL_NAMES = {"Landblock": CullMode.Landblock, "None": CullMode.None_,
               "Clockwise": CullMode.Clockwise, "CounterClockwise": CullMode.CounterClockwise}
_CULL_BY_VALUE = {v: k for k, v in _CULL_NAMES.items()}


@dataclass(frozen=True, slots=True)
class Frame:
    origin: Vec3
    orientation: Quat = IDENTITY

    def to_json(self):
        return {"origin": write_vec(self.origin), "orientation": write_vec(self.orientation)}

    @staticmethod
    def from_json(r: Reader) -> "Frame":
        r.obj({"origin", "orientation"})
        o = r["orientation"] if r.given("orientation") else None
        q = IDENTITY
        if o is not None:
            w, x, y, z = (c.f32() for c in o.list(count=4))
            if w == 0 and x == 0 and y == 0 and z == 0:
                o.fail("a zero quaternion is not a rotation")
            q = (w, x, y, z)
        return Frame(r["origin"].vec3(), q)


@dataclass(frozen=True, slots=True)
class Position:
    cell: int
    frame: Frame

    def to_json(self):
        return {"cell": write_id(self.cell), **self.frame.to_json()}

    @staticmethod
    def from_json(r: Reader) -> "Position":
        r.obj({"cell", "origin", "orientation"})
        cell = r["cell"].id_()
        return Position(cell, Frame.from_json(Reader({k: v for k, v in r.value.items() if k != "cell"}, r.path)))


@dataclass(frozen=True, slots=True)
class PlaneRec:
    normal: Vec3
    d: float

    def to_json(self):
        return {"normal": write_vec(self.normal), "d": write_f32(self.d)}

    def json_text(self) -> str:
        return '{"normal":' + vec_text(self.normal) + ',"d":' + f32_text(self.d) + "}"

    @staticmethod
    def from_json(r: Reader) -> "PlaneRec":
        r.obj({"normal", "d"})
        return PlaneRec(r["normal"].vec3(), r["d"].f32())


@dataclass(frozen=True, slots=True)
class SphereRec:
    center: Vec3
    radius: float

    def to_json(self):
        return {"center": write_vec(self.center), "radius": write_f32(self.radius)}

    def json_text(self) -> str:
        return '{"center":' + vec_text(self.center) + ',"radius":' + f32_text(self.radius) + "}"

    @staticmethod
    def from_json(r: Reader, bounding: bool = False) -> "SphereRec":
        """`bounding`: a BSP node's or leaf's bounding sphere, whose radius may be 0 (ACE's BSP code
        reads one: such a sphere only touches what reaches its centre; an empty leaf has one)."""
        r.obj({"center", "radius"})
        s = SphereRec(r["center"].vec3(), r["radius"].f32())
        if bounding:
            if not s.radius >= 0:
                r["radius"].fail(f"a bounding sphere needs a radius of 0 or more, got {s.radius}")
        elif not s.radius > 0:
            r["radius"].fail(f"a sphere needs a positive radius, got {s.radius}")
        return s


NO_TERRAIN: tuple[int, ...] = (0,) * 81


@dataclass(frozen=True, slots=True)
class Landblock:
    """One landblock as CellLandblock stores it: id 0xXXYYFFFF, 9x9 heights x-major.

    `has_terrain` False is a landblock written without heights and terrain (a dungeon's: indoor
    scenes build no terrain): its CellLandblock holds 81 zero heights and 81 zero terrain words,
    as a retail dungeon landblock's does (ACE's Landblock constructor builds a LandblockStruct
    from whatever CellLandblock it reads); `heights` and `terrain` are then NO_TERRAIN."""

    id: int
    heights: tuple[int, ...] = NO_TERRAIN  # 81 indices into the land height table, [x * 9 + y]
    terrain: tuple[int, ...] = NO_TERRAIN  # 81 terrain words (road, type, scenery bits); water type comes from them
    has_terrain: bool = True
    # scene/8: its LandblockInfo's RestrictionTables (PackMask bit 0), (cell id, object id) pairs in table order: a
    # housing barrier's owner per land cell (Landblock.init_static_objs gives the land cell at the key's land
    # coordinate the object as its RestrictionObj; a key with none, an EnvCell's, is skipped). Read only for a
    # landblock with buildings (its CellLandblock's HasObjects)
    restrictions: tuple[tuple[int, int], ...] = ()

    def to_json(self):
        extra = {"restrictions": [{"cell": write_id(c), "object": write_id(o)} for c, o in self.restrictions]} \
            if self.restrictions else {}
        if not self.has_terrain:
            return {"id": write_id(self.id), **extra}
        return {"id": write_id(self.id), "heights": list(self.heights), "terrain": list(self.terrain), **extra}

    @staticmethod
    def from_json(r: Reader, indoor: bool = True) -> "Landblock":
        """`indoor`: the format may omit heights and terrain (scene/2)."""
        r.obj({"id", "heights", "terrain", "restrictions"})
        restrictions = _restrictions(r["restrictions"]) if r.given("restrictions") else ()
        if restrictions:
            return replace(Landblock.from_json(Reader({k: v for k, v in r.value.items() if k != "restrictions"}, r.path),
                                               indoor), restrictions=restrictions)
        lb_id = r["id"].id_()
        if lb_id & 0xFFFF != 0xFFFF:
            r["id"].fail(f"a landblock id ends in FFFF (e.g. 0x{lb_id >> 16:04X}FFFF), got {write_id(lb_id)}")
        if indoor and not r.given("heights") and not r.given("terrain"):
            return Landblock(lb_id, has_terrain=False)
        if indoor and r.given("heights") != r.given("terrain"):
            missing = "terrain" if r.given("heights") else "heights"
            raise InvalidScene(f"{r.path}.{missing}", "missing: a landblock gives both heights and terrain, or "
                                                      "neither (a landblock without terrain, e.g. a dungeon's)")
        heights = r["heights"].ints(0, 255, count=81)
        terrain = r["terrain"].ints(0, 0xFFFF, count=81)
        return Landblock(lb_id, heights, terrain)


def _restrictions(r: Reader) -> tuple[tuple[int, int], ...]:
    """A LandblockInfo's RestrictionTables: {cell, object} pairs, each cell once (DatLoader's Dictionary.Add throws on
    a key it holds), each object not 0 (ObjCell.check_entry_restrictions reads 0 as none)."""
    pairs = []
    for i, e in enumerate(r.list(max_count=0xFFFF)):
        e.obj({"cell", "object"})
        cell, obj = e["cell"].id_(), e["object"].id_()
        if any(c == cell for c, _ in pairs):
            r[i]["cell"].fail(f"cell {write_id(cell)} is restricted twice (DatLoader's Dictionary.Add throws)")
        if obj == 0:
            r[i]["object"].fail("a restriction object is not 0 (ObjCell.check_entry_restrictions reads 0 as none)")
        pairs.append((cell, obj))
    return tuple(pairs)


@dataclass(frozen=True, slots=True)
class PolygonRec:
    vertices: tuple[Vec3, ...]
    sides_type: int = CullMode.None_

    def to_json(self):
        return {"vertices": [write_vec(v) for v in self.vertices], "sides_type": _CULL_BY_VALUE[CullMode(self.sides_type)]}

    def json_text(self) -> str:
        return ('{"vertices":[' + ",".join(map(vec_text, self.vertices)) + '],"sides_type":"'
                + _CULL_BY_VALUE[CullMode(self.sides_type)] + '"}')

    @staticmethod
    def from_json(r: Reader) -> "PolygonRec":
        r.obj({"vertices", "sides_type"})
        verts = tuple(r["vertices"].vec3s())
        if len(verts) < 3:
            r["vertices"].fail(f"a polygon needs at least 3 vertices, got {len(verts)}")
        if _newell_area2(verts) <= 1e-12:
            r["vertices"].fail("degenerate polygon: its vertices span no area")
        sides = CullMode.None_
        s = r["sides_type"] if r.given("sides_type") else None
        if s is not None:
            name = s.str_()
            if name not in _CULL_NAMES:
                s.fail(f"unknown sides_type {name!r} (known: {', '.join(_CULL_NAMES)})")
            sides = _CULL_NAMES[name]
        return PolygonRec(verts, int(sides))


def newell_normal(verts) -> tuple[float, float, float]:
    """Newell's (unnormalised) polygon normal, in doubles: its length is twice the polygon's area."""
    nx = ny = nz = 0.0
    n = len(verts)
    for i in range(n):
        x0, y0, z0 = verts[i]
        x1, y1, z1 = verts[(i + 1) % n]
        nx += (y0 - y1) * (z0 + z1)
        ny += (z0 - z1) * (x0 + x1)
        nz += (x0 - x1) * (y0 + y1)
    return nx, ny, nz


def _newell_area2(verts) -> float:
    return math.hypot(*newell_normal(verts))


@dataclass(frozen=True, slots=True)
class BSPLeaf:
    polygons: tuple[int, ...]  # indices into the shape's polygon list
    solid: bool
    sphere: SphereRec

    def to_json(self):
        return {"type": "leaf", "polygons": list(self.polygons), "solid": self.solid, "sphere": self.sphere.to_json()}

    def json_text(self) -> str:
        return ('{"type":"leaf","polygons":' + ints_text(self.polygons) + ',"solid":'
                + ("true" if self.solid else "false") + ',"sphere":' + self.sphere.json_text() + "}")


@dataclass(frozen=True, slots=True)
class BSPNode:
    plane: PlaneRec
    sphere: SphereRec
    front: "BSPLeaf | BSPNode"
    back: "BSPLeaf | BSPNode"

    def to_json(self):
        return {"type": "node", "plane": self.plane.to_json(), "sphere": self.sphere.to_json(),
                "front": self.front.to_json(), "back": self.back.to_json()}

    def json_text(self) -> str:
        return ('{"type":"node","plane":' + self.plane.json_text() + ',"sphere":' + self.sphere.json_text()
                + ',"front":' + self.front.json_text() + ',"back":' + self.back.json_text() + "}")


def _bsp_from_json(r: Reader, npolys: int) -> BSPLeaf | BSPNode:
    if not isinstance(r.value, dict):
        r.fail("expected a BSP node or leaf object")
    kind = r["type"].str_()
    if kind == "leaf":
        r.obj({"type", "polygons", "solid", "sphere"})
        # a polygon id past the shape's (scene/8, Scene.has_missing_keys): ACE's BSPNode throws KeyNotFoundException
        # building the tree (polys[poly])
        polys = r["polygons"].ints(0, 0xFFFF)
        solid = r["solid"].bool_() if r.given("solid") else False
        return BSPLeaf(polys, solid, SphereRec.from_json(r["sphere"], bounding=True))
    if kind == "node":
        r.obj({"type", "plane", "sphere", "front", "back"})
        for side in ("front", "back"):
            if not r.has(side):
                r.fail(f"an internal BSP node needs both children; {side!r} is missing")
        return BSPNode(PlaneRec.from_json(r["plane"]), SphereRec.from_json(r["sphere"], bounding=True),
                       _bsp_from_json(r["front"], npolys), _bsp_from_json(r["back"], npolys))
    r["type"].fail(f"unknown BSP element type {kind!r} (known: node, leaf)")


def _leaf_past(node, npolys: int) -> bool:
    """Whether a leaf of the physics tree names a polygon id at or past `npolys` (scene/8)."""
    if node is None:
        return False
    if isinstance(node, BSPLeaf):
        return any(k >= npolys for k in node.polygons)
    return _leaf_past(node.front, npolys) or _leaf_past(node.back, npolys)


@dataclass(frozen=True, slots=True)
class BSPShape:
    """A GfxObj's physics BSP: polygons, a tree (its root a node or a leaf), a bounding sphere.

    ACE's BSPTree constructor makes the root a BSPNode whatever the DAT holds, so a leaf root
    becomes a childless node: queries that would descend from it meet null (the port and ACE
    both report NullReferenceException) and the others find nothing. `sphere` is written in the
    scene but not in the GfxObj record (acconform/dat.py): ACE takes the physics sphere from
    the root's own sphere."""

    polygons: tuple[PolygonRec, ...]
    root: "BSPNode | BSPLeaf"
    sphere: SphereRec  # GfxObj.PhysicsSphere
    kind: str = field(default="bsp", init=False)

    def to_json(self):
        return as_text(self) or {"kind": "bsp", "polygons": [p.to_json() for p in self.polygons],
                "root": self.root.to_json(), "sphere": self.sphere.to_json()}

    def json_text(self) -> str:
        return ('{"kind":"bsp","polygons":[' + ",".join([p.json_text() for p in self.polygons]) + '],"root":'
                + self.root.json_text() + ',"sphere":' + self.sphere.json_text() + "}")


@dataclass(frozen=True, slots=True)
class SphereShape:
    sphere: SphereRec
    kind: str = field(default="sphere", init=False)

    def to_json(self):
        return {"kind": "sphere", **self.sphere.to_json()}


@dataclass(frozen=True, slots=True)
class CylSphereShape:
    low_point: Vec3
    radius: float
    height: float
    kind: str = field(default="cylsphere", init=False)

    def to_json(self):
        return {"kind": "cylsphere", "low_point": write_vec(self.low_point),
                "radius": write_f32(self.radius), "height": write_f32(self.height)}


Shape = Union[BSPShape, SphereShape, CylSphereShape]


def _shape_from_json(r: Reader) -> Shape:
    if not isinstance(r.value, dict):
        r.fail("expected a shape object")
    kind = r["kind"].str_()
    if kind == "bsp":
        r.obj({"kind", "polygons", "root", "sphere"})
        polys = tuple(PolygonRec.from_json(p) for p in r["polygons"].list(min_count=1))
        root = _bsp_from_json(r["root"], len(polys))
        return BSPShape(polys, root, SphereRec.from_json(r["sphere"]))
    if kind == "sphere":
        r.obj({"kind", "center", "radius"})
        return SphereShape(SphereRec.from_json(Reader({"center": r.value.get("center"), "radius": r.value.get("radius")}, r.path)))
    if kind == "cylsphere":
        r.obj({"kind", "low_point", "radius", "height"})
        cyl = CylSphereShape(r["low_point"].vec3(), r["radius"].f32(), r["height"].f32())
        if not cyl.radius > 0:
            r["radius"].fail(f"a cylsphere needs a positive radius, got {cyl.radius}")
        if not cyl.height > 0:
            r["height"].fail(f"a cylsphere needs a positive height, got {cyl.height}")
        return cyl
    r["kind"].fail(f"unknown shape kind {kind!r} (known: bsp, sphere, cylsphere)")


@dataclass(frozen=True, slots=True)
class CellBSPLeaf:
    """A cell BSP's leaf. The DAT holds only its LeafIndex (assigned in writing order); a cell
    BSP's queries never read a leaf's contents."""

    def to_json(self):
        return {"type": "leaf"}

    def json_text(self) -> str:
        return '{"type":"leaf"}'


@dataclass(frozen=True, slots=True)
class CellBSPNode:
    """A cell BSP's node: a splitting plane and up to two children (None where the DAT has none:
    point_in_cell and sphere_intersects_cell walk the front children and stop at None)."""

    plane: PlaneRec
    front: "CellBSPNode | CellBSPLeaf | None"
    back: "CellBSPNode | CellBSPLeaf | None"
    # scene/8: written with the tag PORT (a node with both children): DatLoader reads it as a BSPPortal, in a cell tree
    # exactly as a BPIN node (no sphere, no polygons), and ACE's physics BSPNode makes the same node of it
    portal: bool = False

    def to_json(self):
        d = {"type": "node", "plane": self.plane.to_json()}
        if self.portal:
            d["portal"] = True
        if self.front is not None:
            d["front"] = self.front.to_json()
        if self.back is not None:
            d["back"] = self.back.to_json()
        return d

    def json_text(self) -> str:
        text = '{"type":"node","plane":' + self.plane.json_text() + (',"portal":true' if self.portal else "")
        if self.front is not None:
            text += ',"front":' + self.front.json_text()
        if self.back is not None:
            text += ',"back":' + self.back.json_text()
        return text + "}"


def _cell_bsp_from_json(r: Reader) -> "CellBSPNode | CellBSPLeaf":
    if not isinstance(r.value, dict):
        r.fail("expected a cell BSP node or leaf object")
    kind = r["type"].str_()
    if kind == "leaf":
        r.obj({"type"})
        return CellBSPLeaf()
    if kind == "node":
        r.obj({"type", "plane", "front", "back", "portal"})
        portal = r["portal"].bool_() if r.given("portal") else False
        if portal and not (r.has("front") and r.has("back")):
            r["portal"].fail("a portal node (tag PORT) has both children (DatLoader's BSPPortal reads two)")
        return CellBSPNode(PlaneRec.from_json(r["plane"]),
                           _cell_bsp_from_json(r["front"]) if r.has("front") else None,
                           _cell_bsp_from_json(r["back"]) if r.has("back") else None, portal)
    r["type"].fail(f"unknown cell BSP element type {kind!r} (known: node, leaf)")


@dataclass(frozen=True, slots=True)
class CellStructRec:
    """One of an Environment's cell structures (DatLoader CellStruct), in the cell's own frame.

    Polygons are keyed by their index (the DAT's ushort poly id). `portals` lists the indices of
    `polygons` that are portals (CellStruct.Portals). `physics_bsp` indexes `physics_polygons`.
    """

    polygons: tuple[PolygonRec, ...]
    portals: tuple[int, ...]
    physics_polygons: tuple[PolygonRec, ...]
    physics_bsp: "BSPNode | BSPLeaf | None"
    cell_bsp: "CellBSPNode | CellBSPLeaf | None"
    # scene/8: false writes hasDrawingBSP 0 and no drawing tree (DatLoader and ACE's CellStruct leave DrawingBSP null;
    # the physics never reads it)
    drawing_bsp: bool = True

    def to_json(self):
        return {"polygons": [p.to_json() for p in self.polygons], "portals": list(self.portals),
                "physics_polygons": [p.to_json() for p in self.physics_polygons],
                "physics_bsp": None if self.physics_bsp is None else self.physics_bsp.to_json(),
                "cell_bsp": None if self.cell_bsp is None else self.cell_bsp.to_json(),
                **({} if self.drawing_bsp else {"drawing_bsp": False})}

    def json_text(self) -> str:
        return ('{"polygons":[' + ",".join([p.json_text() for p in self.polygons]) + '],"portals":'
                + ints_text(self.portals) + ',"physics_polygons":['
                + ",".join([p.json_text() for p in self.physics_polygons]) + '],"physics_bsp":'
                + ("null" if self.physics_bsp is None else self.physics_bsp.json_text()) + ',"cell_bsp":'
                + ("null" if self.cell_bsp is None else self.cell_bsp.json_text())
                + ("" if self.drawing_bsp else ',"drawing_bsp":false') + "}")

    @staticmethod
    def from_json(r: Reader) -> "CellStructRec":
        """Both trees are required: a DAT CellStruct always holds a cell BSP and a physics BSP."""
        r.obj({"polygons", "portals", "physics_polygons", "physics_bsp", "cell_bsp", "drawing_bsp"})
        polys = tuple(PolygonRec.from_json(p) for p in r["polygons"].list(max_count=0xFFFF))
        # a portal past the polygons (scene/8, Scene.has_missing_keys): CellStruct's Polygons[portal] throws
        portals = tuple(p.int_(0, 0xFFFF) for p in r["portals"].list()) if r.given("portals") else ()
        physics = tuple(PolygonRec.from_json(p) for p in r["physics_polygons"].list(max_count=0xFFFF))
        return CellStructRec(polys, portals, physics, _bsp_from_json(r["physics_bsp"], len(physics)),
                             _cell_bsp_from_json(r["cell_bsp"]),
                             r["drawing_bsp"].bool_() if r.given("drawing_bsp") else True)


@dataclass(frozen=True, slots=True)
class Environment:
    """A DatLoader Environment (portal DAT id 0x0D00XXXX): cell structures keyed by index."""

    id: int
    cell_structs: tuple[CellStructRec, ...]

    def to_json(self):
        return as_text(self) or {"id": write_id(self.id), "cell_structs": [c.to_json() for c in self.cell_structs]}

    def json_text(self) -> str:
        return '{"id":"' + write_id(self.id) + '","cell_structs":[' + ",".join([c.json_text() for c in self.cell_structs]) + "]}"

    @staticmethod
    def from_json(r: Reader) -> "Environment":
        r.obj({"id", "cell_structs"})
        env_id = r["id"].id_()
        if env_id >> 16 != 0x0D00:
            r["id"].fail(f"an Environment id is 0x0D00XXXX (an EnvCell stores its low word), got {write_id(env_id)}")
        return Environment(env_id, tuple(CellStructRec.from_json(c) for c in r["cell_structs"].list(min_count=1)))


# DatLoader CellPortal.Flags: PortalSide is true when bit 2 is CLEAR (CellPortal.cs)
PORTAL_EXACT_MATCH = 0x1
PORTAL_SIDE_BIT = 0x2
OUTSIDE_CELL = 0xFFFF  # a portal's OtherCellId that leads outdoors
# EnvCell low words: LScape.get_landcell loads 0x0100 and up from the cell DAT; 0xFFFE and 0xFFFF are
# the landblock's LandblockInfo and CellLandblock
ENV_CELL_FIRST = 0x0100
ENV_CELL_LAST = 0xFFFD


@dataclass(frozen=True, slots=True)
class CellPortalRec:
    """DatLoader CellPortal: which polygon of the cell structure is the portal, and where it leads."""

    polygon: int       # PolygonId: an index into the cell structure's polygons
    other_cell: int    # OtherCellId: the neighbour's low word (0x0100..), or 0xFFFF for outdoors
    other_portal: int  # OtherPortalId
    flags: int = 0     # PORTAL_EXACT_MATCH | PORTAL_SIDE_BIT

    def to_json(self):
        return {"polygon": self.polygon, "other_cell": f"0x{self.other_cell:04X}",
                "other_portal": self.other_portal, "flags": self.flags}

    @staticmethod
    def from_json(r: Reader) -> "CellPortalRec":
        r.obj({"polygon", "other_cell", "other_portal", "flags"})
        other = _low_word(r["other_cell"])
        if other != OUTSIDE_CELL and not ENV_CELL_FIRST <= other <= ENV_CELL_LAST:
            r["other_cell"].fail(f"a portal leads to an EnvCell (0x{ENV_CELL_FIRST:04X}..0x{ENV_CELL_LAST:04X}) "
                                 f"or outside (0xFFFF), got 0x{other:04X}")
        flags = r["flags"].int_(0, PORTAL_EXACT_MATCH | PORTAL_SIDE_BIT) if r.given("flags") else 0
        return CellPortalRec(r["polygon"].int_(0, 0xFFFF), other, r["other_portal"].int_(0, 0xFFFF), flags)


@dataclass(frozen=True, slots=True)
class EnvCell:
    """An indoor cell (DatLoader EnvCell, cell DAT id 0xXXYY0100 and up): a cell structure of an
    Environment placed at `frame` in its landblock, its portals and visible cells."""

    id: int
    frame: Frame
    environment: int      # the Environment's id (0x0D00XXXX)
    cell_structure: int   # index into that Environment's cell_structs
    portals: tuple[CellPortalRec, ...] = ()
    visible_cells: tuple[int, ...] = ()  # low words of the cells seen from this one
    seen_outside: bool = False
    # scene/8: its RestrictionObj (flag HasRestrictionObj): a housing barrier's owner, ObjCell.check_entry_restrictions
    # asks ServerObjectManager for it when a player enters the cell (0: none, no flag)
    restriction_obj: int = 0

    def to_json(self):
        extra = {"restriction_obj": write_id(self.restriction_obj)} if self.restriction_obj else {}
        return {"id": write_id(self.id), **self.frame.to_json(), "environment": write_id(self.environment),
                "cell_structure": self.cell_structure, "portals": [p.to_json() for p in self.portals],
                "visible_cells": [f"0x{c:04X}" for c in self.visible_cells], "seen_outside": self.seen_outside, **extra}

    @staticmethod
    def from_json(r: Reader) -> "EnvCell":
        r.obj({"id", "origin", "orientation", "environment", "cell_structure", "portals", "visible_cells",
               "seen_outside", "restriction_obj"})
        cell_id = r["id"].id_()
        if not ENV_CELL_FIRST <= cell_id & 0xFFFF <= ENV_CELL_LAST:
            r["id"].fail(f"an EnvCell id is 0xXXYY{ENV_CELL_FIRST:04X} to 0xXXYY{ENV_CELL_LAST:04X}, got {write_id(cell_id)}")
        frame = Frame.from_json(Reader({k: r.value[k] for k in ("origin", "orientation") if k in r.value}, r.path))
        portals = tuple(CellPortalRec.from_json(p) for p in r["portals"].list(max_count=0xFF)) if r.given("portals") else ()
        visible = _env_cell_words(r["visible_cells"], "a visible cell", low=True) if r.given("visible_cells") else ()
        return EnvCell(cell_id, frame, r["environment"].id_(), r["cell_structure"].int_(0, 0xFFFF), portals, visible,
                       r["seen_outside"].bool_() if r.given("seen_outside") else False,
                       r["restriction_obj"].id_() if r.given("restriction_obj") else 0)


def _low_word(r: Reader) -> int:
    """A cell's low word, written "0x0101" (or any id whose value fits 16 bits)."""
    v = r.id_()
    if v > 0xFFFF:
        r.fail(f"expected a cell's low word like '0x0101', got {r.value!r}")
    return v


# scene/8: a visible cell or a building portal's other cell below 0x0100 (what ACE's EnvCell and CBldPortal read as
# any ushort): LScape.get_landcell gives a LandCell for 0x0001..0x0040 (EnvCell.build_visible_cells' and
# BldPortal.GetOtherCell's (EnvCell) cast throws InvalidCastException) and null for 0x0000 and 0x0041..0x00FF (no land
# coordinate: VisibleCells holds null, GetOtherCell answers null)
OUTDOOR_WORD_LAST = 0x00FF


def _env_cell_words(r: Reader, what: str, low: bool = False) -> tuple[int, ...]:
    """A list of EnvCells' low words (visible cells, a building portal's stab list); `what` names one. `low`: a word
    0x0000..0x00FF too (OUTDOOR_WORD_LAST)."""
    words = tuple(_low_word(v) for v in r.list(max_count=0xFFFF))
    for i, v in enumerate(words):
        if not (ENV_CELL_FIRST <= v <= ENV_CELL_LAST or low and v <= OUTDOOR_WORD_LAST):
            r[i].fail(f"{what} is an EnvCell's low word (0x{ENV_CELL_FIRST:04X}..0x{ENV_CELL_LAST:04X})"
                      f"{' or 0x0000..0x00FF' if low else ''}, got 0x{v:04X}")
    return words


@dataclass(frozen=True, slots=True)
class BuildingPortalRec:
    """DatLoader CBldPortal: a building's portal into one of its EnvCells (the landblock's)."""

    other_cell: int    # OtherCellId: the EnvCell's low word (0x0100..)
    other_portal: int  # OtherPortalId: the index of that cell's portal (0xFFFF: none; ACE skips it)
    flags: int = 0     # PORTAL_EXACT_MATCH | PORTAL_SIDE_BIT (PortalSide is true when the bit is clear)
    stab_list: tuple[int, ...] = ()  # StabList: low words of the EnvCells seen through it

    def to_json(self):
        return {"other_cell": f"0x{self.other_cell:04X}", "other_portal": self.other_portal, "flags": self.flags,
                "stab_list": [f"0x{c:04X}" for c in self.stab_list]}

    @staticmethod
    def from_json(r: Reader) -> "BuildingPortalRec":
        r.obj({"other_cell", "other_portal", "flags", "stab_list"})
        other = _low_word(r["other_cell"])
        if not (ENV_CELL_FIRST <= other <= ENV_CELL_LAST or other <= OUTDOOR_WORD_LAST):
            r["other_cell"].fail(f"a building's portal leads into one of its EnvCells "
                                 f"(0x{ENV_CELL_FIRST:04X}..0x{ENV_CELL_LAST:04X}) or 0x0000..0x00FF, got 0x{other:04X}")
        flags = r["flags"].int_(0, PORTAL_EXACT_MATCH | PORTAL_SIDE_BIT) if r.given("flags") else 0
        stabs = _env_cell_words(r["stab_list"], "a stab") if r.given("stab_list") else ()
        return BuildingPortalRec(other, r["other_portal"].int_(0, 0xFFFF), flags, stabs)


@dataclass(frozen=True, slots=True)
class Building:
    """A building of a landblock (DatLoader BuildInfo in its LandblockInfo): the shell, a GfxObj
    with `shape` as its physics BSP, at `frame` in the landblock (0xXXYYFFFF), and its portals."""

    landblock: int
    frame: Frame
    shape: BSPShape
    portals: tuple[BuildingPortalRec, ...] = ()
    num_leaves: int = 0

    def to_json(self):
        return {"landblock": write_id(self.landblock), **self.frame.to_json(), "shape": self.shape.to_json(),
                "num_leaves": self.num_leaves, "portals": [p.to_json() for p in self.portals]}

    @staticmethod
    def from_json(r: Reader) -> "Building":
        r.obj({"landblock", "origin", "orientation", "shape", "num_leaves", "portals"})
        lb_id = r["landblock"].id_()
        if lb_id & 0xFFFF != 0xFFFF:
            r["landblock"].fail(f"a landblock id ends in FFFF (e.g. 0x{lb_id >> 16:04X}FFFF), got {write_id(lb_id)}")
        frame = Frame.from_json(Reader({k: r.value[k] for k in ("origin", "orientation") if k in r.value}, r.path))
        shape = _shape_from_json(r["shape"])
        if not isinstance(shape, BSPShape):
            r["shape"]["kind"].fail(f"a building's shell is a physics BSP (kind 'bsp'), got {shape.kind!r}")
        portals = tuple(BuildingPortalRec.from_json(p) for p in r["portals"].list()) if r.given("portals") else ()
        leaves = r["num_leaves"].int_(0, 0xFFFF) if r.given("num_leaves") else 0
        return Building(lb_id, frame, shape, portals, leaves)


MAX_SETUP_PARTS = 16  # acconform/dat.py gives each static 16 GfxObj ids for its Setup's parts


@dataclass(frozen=True, slots=True)
class PartRec:
    """One part of a static's Setup: a GfxObj with a physics BSP (`shape`), its frame in the Setup's
    default placement (PlacementFrames[0], which PartArray.SetPlacementFrame falls back to) and its
    Setup.DefaultScale entry (None: the Setup has no DefaultScale; given on every part or none)."""

    shape: BSPShape
    frame: Frame = Frame((0.0, 0.0, 0.0))
    scale: Vec3 | None = None

    def to_json(self):
        d = {"shape": self.shape.to_json(), **self.frame.to_json()}
        if self.scale is not None:
            d["scale"] = write_vec(self.scale)
        return d

    @staticmethod
    def from_json(r: Reader) -> "PartRec":
        r.obj({"shape", "origin", "orientation", "scale"})
        shape = _shape_from_json(r["shape"])
        if not isinstance(shape, BSPShape):
            r["shape"]["kind"].fail(f"a Setup's part is a GfxObj with a physics BSP (kind 'bsp'), got {shape.kind!r}; "
                                    "spheres and cylspheres are the Setup's own (setup.spheres, setup.cylspheres)")
        frame = Frame.from_json(Reader({k: r.value[k] for k in ("origin", "orientation") if k in r.value}, r.path))
        scale = None
        if r.given("scale"):
            scale = r["scale"].vec3()
            for axis, c in zip("xyz", scale):
                if not c > 0:
                    r["scale"].fail(f"a part's scale needs positive components, got {axis} = {c}")
        return PartRec(shape, frame, scale)


@dataclass(frozen=True, slots=True)
class SetupRec:
    """A static's Setup of several parts (scene/7): the parts (1..16, in scene/8 0..16: with none, feature
    setup.no_parts, ACE's InitParts fails and makeObject's PhysicsObj has no PartArray; each a BSP GfxObj at its
    placement frame, with or without a DefaultScale entry) and the Setup's own spheres and cylspheres
    (any number each). Its Height, Radius and step heights are 0, as every static's Setup's are."""

    parts: tuple[PartRec, ...]
    spheres: tuple[SphereRec, ...] = ()
    cylspheres: tuple[CylSphereShape, ...] = ()
    # scene/8: the Setup's ParentIndex, one uint per part (SetupFlags.HasParent): the DAT reader's, which ACE's
    # physics never reads (Physics/Setup.cs leaves it commented out); None: the flag clear, no array
    parent_index: tuple[int, ...] | None = None
    # scene/8: the Setup's DefaultScript (0 none): InitDefaults plays it (a ScriptManager) and, the object
    # being Static, sets HasDefaultScript
    default_script: int = 0
    # scene/8: the Setup's DefaultAnimation, an Animation of one frame given here as one frame per part
    # (acconform/dat.py writes it); None: DefaultAnimation 0. PartArray.InitDefaults appends it to the Sequence,
    # whose current frame then places the parts (in place of the placement frames), and InitDefaults sets
    # HasDefaultAnim on a Static object
    default_animation: tuple[Frame, ...] | None = None
    # scene/8, another mover's setup only (feature setup.multipart_movers): False, the Setup has no placement frames
    # (JSON "placement": false), so the parts' frames are not written: Sequence.GetCurrAnimFrame is null and
    # PartArray.UpdateParts moves a part only when there is one (its Pos the owner's Position)
    placement: bool = True

    def to_json(self):
        d = {"parts": [p.to_json() for p in self.parts]}
        if not self.placement:
            d["placement"] = False
        if self.default_script:
            d["default_script"] = write_id(self.default_script)
        if self.default_animation is not None:
            d["default_animation"] = [f.to_json() for f in self.default_animation]
        if self.spheres:
            d["spheres"] = [s.to_json() for s in self.spheres]
        if self.cylspheres:
            d["cylspheres"] = [{k: v for k, v in c.to_json().items() if k != "kind"} for c in self.cylspheres]
        if self.parent_index is not None:
            d["parent_index"] = list(self.parent_index)
        return d

    @staticmethod
    def from_json(r: Reader, v8: bool = True, mover: bool = False) -> "SetupRec":
        """`v8`: the format holds `parent_index`, `default_script` and `default_animation` (scene/8), and a Setup with
        no parts (feature setup.no_parts); `mover`: another mover's setup (scene/8), which may have `placement` false."""
        for name in ("parent_index", "default_script", "default_animation"):
            if not v8 and isinstance(r.value, dict) and name in r.value:
                r[name].fail(f"{name} needs format {FORMAT!r} (older formats have none)")
        if not mover and isinstance(r.value, dict) and "placement" in r.value:
            r["placement"].fail("a static's Setup has its placement frame (placement false is another mover's only)")
        r.obj({"parts", "spheres", "cylspheres", *(("parent_index", "default_script", "default_animation") if v8 else ()),
               *(("placement",) if mover else ())})
        parts = tuple(PartRec.from_json(p) for p in r["parts"].list(min_count=0 if v8 else 1, max_count=MAX_SETUP_PARTS))
        scaled = [p.scale is not None for p in parts]
        if any(scaled) and not all(scaled):
            r["parts"][scaled.index(False)].fail(
                f"no scale, but parts[{scaled.index(True)}] has one: a Setup's DefaultScale has an entry for every part "
                "or none (give scale on every part or on none)")
        spheres = tuple(SphereRec.from_json(s) for s in r["spheres"].list()) if r.given("spheres") else ()
        cylspheres = ()
        if r.given("cylspheres"):
            cylspheres = tuple(_shape_from_json(Reader({"kind": "cylsphere", **c.obj({"low_point", "radius", "height"}).value},
                                                       c.path)) for c in r["cylspheres"].list())
        parent_index = None
        if v8 and r.given("parent_index"):
            parent_index = tuple(x.int_(0, 0xFFFFFFFF) for x in r["parent_index"].list(min_count=len(parts),
                                                                                       max_count=len(parts)))
        default_animation = None
        if v8 and r.given("default_animation"):
            default_animation = tuple(Frame.from_json(f) for f in r["default_animation"].list(min_count=len(parts),
                                                                                              max_count=len(parts)))
        placement = r["placement"].bool_() if mover and r.given("placement") else True
        if not placement:
            for k, p in enumerate(parts):
                if p.frame != Frame((0.0, 0.0, 0.0)):
                    r["parts"][k].fail("a Setup with placement false has no frames for its parts: omit origin and orientation")
        return SetupRec(parts, spheres, cylspheres, parent_index,
                        default_script=r["default_script"].id_() if v8 and r.given("default_script") else 0,
                        default_animation=default_animation, placement=placement)


@dataclass(frozen=True, slots=True)
class StaticObject:
    """A static object: `shape` (one BSP GfxObj, or a one-part Setup with a sphere or a cylsphere),
    or, in scene/7, `setup` (a Setup of several parts; `shape` is then None)."""

    id: int
    position: Position
    shape: Shape | None
    state: int = int(PhysicsState.Static)  # PhysicsState flags
    scale: float = 1.0
    setup: SetupRec | None = None

    def to_json(self):
        body = {"setup": self.setup.to_json()} if self.setup is not None else {"shape": self.shape.to_json()}
        return {"id": write_id(self.id), "position": self.position.to_json(), **body,
                "state": flag_names(PhysicsState, self.state), "scale": write_f32(self.scale)}

    @staticmethod
    def from_json(r: Reader, setups: bool = True, v8: bool = True) -> "StaticObject":
        """`setups`: the format knows `setup` (scene/7); `v8`: a setup's `default_script` (scene/8)."""
        if not setups and isinstance(r.value, dict) and "setup" in r.value:
            r["setup"].fail(f"a static's setup needs format {FORMAT_V7!r} or later (older formats have one shape per static)")
        r.obj({"id", "position", "shape", "state", "scale", *(("setup",) if setups else ())})
        if setups and "shape" in r.value and "setup" in r.value:
            r["setup"].fail("a static has a shape or a setup (several parts), not both")
        if setups and "shape" not in r.value and "setup" not in r.value:
            r.fail("missing: a static needs a shape or a setup (several parts)")
        state = r["state"].flags(PhysicsState) if r.given("state") else int(PhysicsState.Static)
        scale = r["scale"].f32() if r.given("scale") else 1.0
        if not scale > 0:
            r["scale"].fail(f"scale must be positive, got {scale}")
        if setups and "setup" in r.value:
            return StaticObject(r["id"].id_(), Position.from_json(r["position"]), None, state, scale,
                                SetupRec.from_json(r["setup"], v8))
        return StaticObject(r["id"].id_(), Position.from_json(r["position"]), _shape_from_json(r["shape"]), state, scale)


@dataclass(frozen=True, slots=True)
class ContactPlane:
    """PhysicsObj.ContactPlane and ContactPlaneCellID. Whether it is water is not stored here:
    get_object_info reads that from TransientState.WaterContact, so the scene says it there."""

    cell: int
    plane: PlaneRec

    def to_json(self):
        return {"cell": write_id(self.cell), "plane": self.plane.to_json()}

    @staticmethod
    def from_json(r: Reader) -> "ContactPlane":
        r.obj({"cell", "plane"})
        return ContactPlane(r["cell"].id_(), PlaneRec.from_json(r["plane"]))


# SetPositionFlags a scene's placement cannot ask for: ACE's scatter (SetScatterPositionInternal, behind
# the Scatter retry) draws its positions from ThreadSafeRandom, so no two runs of it answer alike.
UNPLACEABLE_FLAGS = int(SetPositionFlags.Scatter | SetPositionFlags.RandomScatter)
# how the mover is placed: ACE's PhysicsObj.enter_world (a WorldObject entering its landblock:
# WorldObject.AddPhysicsObj) or its public PhysicsObj.SetPosition with the scene's flags (a teleport, a restore)
PLACEMENT_VIAS = ("enter_world", "set_position")


@dataclass(frozen=True, slots=True)
class Placement:
    """The mover placed by ACE at ``mover.begin`` before the transition or the ticks. `via`
    "enter_world": the mover enters the world as a server's WorldObject does (WorldObject.AddPhysicsObj:
    the begin cell's LScape.get_landcell, then PhysicsObj.enter_world, which places with Placement |
    Slide); `flags` stay 0. `via` "set_position": ACE's PhysicsObj.SetPosition with `flags`, the
    SetPositionFlags (a teleport's or a restore's placement). `get_cell` first replaces the begin
    position's cell id by ``Position.GetCell(ObjCellID)`` (the server's cell fix-up for a spawn or
    teleport: AdjustCell indoors, the cell under the point outdoors)."""

    flags: int = 0
    get_cell: bool = False
    via: str = "set_position"

    def to_json(self, explicit_via: bool = False):
        """`via` is written for enter_world, and for set_position only when `explicit_via` (a document whose
        readers default to enter_world: the protocol's dat); scene/3-5 placements have none."""
        if self.via == "enter_world":
            return {"via": "enter_world", "get_cell": self.get_cell}
        d = {"flags": flag_names(SetPositionFlags, self.flags), "get_cell": self.get_cell}
        return {"via": "set_position", **d} if explicit_via else d

    @staticmethod
    def from_json(r: Reader, vias: bool = True) -> "Placement":
        """`vias`: the format knows `via` (scene/6 and later; older formats place through SetPosition)."""
        if not vias and isinstance(r.value, dict) and "via" in r.value:
            r["via"].fail(f"via needs format {FORMAT_V6!r} or later (older formats place through SetPosition)")
        r.obj({"flags", "get_cell", *(("via",) if vias else ())})
        via = "enter_world" if vias else "set_position"
        if r.given("via"):
            via = r["via"].str_()
            if via not in PLACEMENT_VIAS:
                r["via"].fail(f"unknown placement {via!r} (known: enter_world, set_position)")
        if via == "enter_world" and r.given("flags"):
            r["flags"].fail("enter_world places with its own flags (Placement | Slide): omit flags, or use "
                            "\"via\": \"set_position\"")
        flags = r["flags"].flags(SetPositionFlags) if r.given("flags") else 0
        if flags & UNPLACEABLE_FLAGS:
            r["flags"].fail("Scatter and RandomScatter cannot be run alike twice: ACE's scatter draws its "
                            "positions from ThreadSafeRandom")
        return Placement(flags, r["get_cell"].bool_() if r.given("get_cell") else False, via)


DRIVERS = ("update_object", "request_pos")  # PhysicsObj.update_object / the legacy player path (RequestPos)

# a step's inputs, in the order both sides apply them (the clock still at the previous tick's time)
TICK_INPUTS = ("state", "transient_state", "velocity", "local_velocity", "omega", "jump", "sequence_velocity",
               "sequence_omega", "request_pos", "motion", "stop", "do_motion", "stop_motion", "move_to",
               "move_to_object", "turn_to_heading", "turn_to_object", "door", "stick_to")
# the motion layer's inputs (scene/6, feature mover.motion): each needs the mover's motion table
MOTION_INPUTS = ("motion", "stop", "do_motion", "stop_motion", "move_to", "move_to_object", "turn_to_heading",
                 "turn_to_object")
_MANAGER_INPUTS = MOTION_INPUTS[1:]
# the motion inputs a mover without a motion table may be given (scene/8, stop 50): the calls a server makes of any
# WorldObject (get_minterp makes its MovementManager; DoMotion, StopMotion and StopCompletely answer without one)
TABLELESS_INPUTS = ("motion", "stop", "do_motion", "stop_motion")
_TICK_VECTORS = ("velocity", "local_velocity", "omega", "jump", "sequence_velocity", "sequence_omega")


@dataclass(frozen=True, slots=True)
class DoorInput:
    """``door`` (scene/7, feature ``doors``): the outdoor static `object` (its id) opens (`ethereal`
    true) or closes (false) as ACE's server Door does it. The physics of Door.Open and
    Door.FinalizeClose: the WorldObject's ``Ethereal`` setter (SetPhysicsPropertyState ->
    SetPhysicsState) sets or clears PhysicsState.Ethereal on the PhysicsObj's State directly (not
    set_ethereal); closing then asks PhysicsObj.ethereal_check_for_collisions and, when an object
    overlaps the door, sets Ethereal again (a default server's allow_door_hold, true: the door is
    held open; the server polls again a second later, which a scene says with another ``door``
    input)."""

    object: int
    ethereal: bool

    def to_json(self):
        return {"object": write_id(self.object), "ethereal": self.ethereal}

    @staticmethod
    def from_json(r: Reader) -> "DoorInput":
        r.obj({"object", "ethereal"})
        return DoorInput(r["object"].id_(), r["ethereal"].bool_())


def _setters_json(step, d: dict) -> dict:
    """The setters and the jump (OTHER_INPUTS: a TickStep's first inputs, an OtherInputs' all), written into `d`."""
    if step.state is not None:
        d["state"] = flag_names(PhysicsState, step.state)
    if step.transient_state is not None:
        d["transient_state"] = flag_names(TransientState, step.transient_state)
    for name in _TICK_VECTORS:
        v = getattr(step, name)
        if v is not None:
            d[name] = write_vec(v)
    return d


def _read_setters(r: Reader) -> dict:
    """The setters and the jump a step or another mover's inputs give, as keyword arguments."""
    kw = {}
    if r.has("state"):
        kw["state"] = r["state"].flags(PhysicsState)
    if r.has("transient_state"):
        kw["transient_state"] = r["transient_state"].flags(TransientState)
    for name in _TICK_VECTORS:
        if r.has(name):
            kw[name] = r[name].vec3()
    return kw


# the inputs another mover takes (scene/8, ticks.steps[].others): the PhysicsObj's own setters and a player's jump
OTHER_INPUTS = ("state", "transient_state", "velocity", "local_velocity", "omega", "jump", "sequence_velocity",
                "sequence_omega")


@dataclass(frozen=True, slots=True)
class OtherInputs:
    """One tick's inputs to another mover (scene/8), named by its id: the same as the mover's inputs of
    the same names (``state`` and ``transient_state`` set State / TransientState; ``velocity``,
    ``local_velocity`` and ``omega`` call set_velocity / set_local_velocity / set_omega; ``jump`` runs
    the physics calls of Player.HandleActionJump, for a mover whose weenie is a player;
    ``sequence_velocity`` / ``sequence_omega`` set its Sequence's root motion), in `OTHER_INPUTS` order."""

    id: int
    state: int | None = None
    transient_state: int | None = None
    velocity: Vec3 | None = None
    local_velocity: Vec3 | None = None
    omega: Vec3 | None = None
    jump: Vec3 | None = None
    sequence_velocity: Vec3 | None = None
    sequence_omega: Vec3 | None = None
    # feature objects.targets: after the setters the server destroys it (WorldObject.Destroy: its landblock's
    # RemoveWorldObject, PhysicsObj.DestroyObject), and no tick steps it again
    destroy: bool = False
    # scene/8 children (objects.children), after the setters: the client's calls on a held item when the server moves
    # it (a ParentEvent: SetPlacementFrame, then set_parent at another holder's or location; a PickupEvent:
    # unset_parent): `unparent` first, then `parent`
    unparent: bool = False
    parent: "ChildOf | None" = None
    # feature objects.motion_tables, after the setters and before `destroy`: EmoteManager's Motion emote -- skipped when
    # PhysicsObj.IsMovingTo(), else the physics of WorldObject.ExecuteMotion (the same as a Chest's open or close, which
    # asks nothing first: no other mover is moving to anything) with this motion command -- the Motion's
    # ForwardCommand, or its Stance when that is Ready (ExecuteMotion runs no physics for Ready): get_minterp, a new
    # RawMotionState (ForwardCommand 0, CurrentHoldKey Run, CurrentStyle the command), UpdateTime when not moving or
    # animating, apply_raw_movement(true, true)
    execute_motion: int | None = None

    def to_json(self):
        d = _setters_json(self, {"id": write_id(self.id)})
        if self.execute_motion is not None:
            d["execute_motion"] = write_id(self.execute_motion)
        if self.destroy:
            d["destroy"] = True
        if self.unparent:
            d["unparent"] = True
        if self.parent is not None:
            d["parent"] = self.parent.to_json()
        return d

    @staticmethod
    def from_json(r: Reader) -> "OtherInputs":
        r.obj({"id", *OTHER_INPUTS, "execute_motion", "destroy", "unparent", "parent"})
        kw = _read_setters(r)
        if r.given("execute_motion"):
            command = r["execute_motion"].id_()
            if command in (0, int(_MotionCommand.Ready)):
                r["execute_motion"].fail("WorldObject.ExecuteMotion runs no physics for Ready (its Motion's stance is "
                                         "the command then): give the command it runs")
            kw["execute_motion"] = command
        if r.given("destroy"):
            kw["destroy"] = r["destroy"].bool_()
        if r.given("unparent"):
            kw["unparent"] = r["unparent"].bool_()
        if r.given("parent"):
            kw["parent"] = ChildOf.from_json(r["parent"])
        return OtherInputs(r["id"].id_(), **kw)


@dataclass(frozen=True, slots=True)
class TickStep:
    """One tick: the time the clock advances (a double, seconds) and the inputs applied before the
    tick, in `TICK_INPUTS` order, with the clock still at the previous tick's time: ``state`` and
    ``transient_state`` set PhysicsObj.State / TransientState; ``velocity``, ``local_velocity`` and
    ``omega`` call set_velocity / set_local_velocity / set_omega (sendEvent false); ``jump`` runs the
    physics calls of ACE's Player.HandleActionJump (the branch the mover's player_killer_status picks:
    FastTick for PK and PKLite) with that local jump velocity;
    ``sequence_velocity`` / ``sequence_omega`` set the PartArray's Sequence velocity / omega (root
    motion); ``request_pos`` is the RequestPos of the request_pos driver (required there, refused
    for update_object)."""

    dt: float                                  # double
    state: int | None = None                   # PhysicsState flags
    transient_state: int | None = None         # TransientState flags
    velocity: Vec3 | None = None
    local_velocity: Vec3 | None = None
    omega: Vec3 | None = None
    jump: Vec3 | None = None
    sequence_velocity: Vec3 | None = None
    sequence_omega: Vec3 | None = None
    request_pos: Position | None = None
    motion: MotionInput | None = None  # scene/6: a MoveToState's RawMotionState (acconform/motion_scene.py)
    # scene/6, the server's calls into the managers (acconform/motion_scene.py): a stop (one of STOPS),
    # a key's DoMotion / StopMotion, a MoveTo (position, object) or turn (heading, object)
    stop: str | None = None
    do_motion: CommandInput | None = None
    stop_motion: CommandInput | None = None
    move_to: MoveToInput | None = None
    move_to_object: ObjectMoveInput | None = None
    turn_to_heading: MoveToInput | None = None
    turn_to_object: ObjectMoveInput | None = None
    door: DoorInput | None = None  # scene/7: a static opens or closes (Door.Open / FinalizeClose's physics)
    # scene/8 (feature objects.targets): a melee swing's PhysicsObj.stick_to_object(the target's id), as
    # Monster_Melee.MeleeAttack and Player_Melee.DoSwingMotion call it: an outdoor static's or another mover's id
    stick_to: int | None = None
    others: tuple["OtherInputs", ...] = ()  # scene/8: the other movers' inputs, applied after the mover's, in this order

    def to_json(self):
        d = _setters_json(self, {"dt": write_f64(self.dt)})
        if self.request_pos is not None:
            d["request_pos"] = self.request_pos.to_json()
        if self.motion is not None:
            d["motion"] = self.motion.to_json()
        if self.stop is not None:
            d["stop"] = self.stop
        for name in _MANAGER_INPUTS[1:]:
            v = getattr(self, name)
            if v is not None:
                d[name] = v.to_json()
        if self.door is not None:
            d["door"] = self.door.to_json()
        if self.stick_to is not None:
            d["stick_to"] = write_id(self.stick_to)
        if self.others:
            d["others"] = [o.to_json() for o in self.others]
        return d

    def json_text(self) -> str:
        text = '{"dt":' + float.__repr__(write_f64(self.dt))
        if self.state is not None:
            text += ',"state":' + dumps_compact(flag_names(PhysicsState, self.state))
        if self.transient_state is not None:
            text += ',"transient_state":' + dumps_compact(flag_names(TransientState, self.transient_state))
        for name in _TICK_VECTORS:
            v = getattr(self, name)
            if v is not None:
                text += ',"' + name + '":' + vec_text(v)
        if self.request_pos is not None:
            text += ',"request_pos":' + dumps_compact(self.request_pos.to_json())
        if self.motion is not None:
            text += ',"motion":' + dumps_compact(self.motion.to_json())
        if self.stop is not None:
            text += ',"stop":' + dumps_compact(self.stop)
        for name in _MANAGER_INPUTS[1:]:
            v = getattr(self, name)
            if v is not None:
                text += ',"' + name + '":' + dumps_compact(v.to_json())
        if self.door is not None:
            text += ',"door":' + dumps_compact(self.door.to_json())
        if self.stick_to is not None:
            text += ',"stick_to":' + dumps_compact(write_id(self.stick_to))
        if self.others:
            text += ',"others":' + dumps_compact([o.to_json() for o in self.others])
        return text + "}"

    @staticmethod
    def from_json(r: Reader, driver: str, motion: bool = True, doors: bool = True, others: bool = True) -> "TickStep":
        """`driver`: the scene's driver (request_pos needs a RequestPos on every step, update_object refuses one).
        `motion`: the format knows the input motion (scene/6); `doors`: the input door (scene/7); `others`: the
        other movers' inputs (scene/8)."""
        if not motion and isinstance(r.value, dict):
            for name in MOTION_INPUTS:
                if name in r.value:
                    r[name].fail(f"a motion input needs format {FORMAT_V6!r} or later (older formats have none)")
        if not doors and isinstance(r.value, dict) and "door" in r.value:
            r["door"].fail(f"a door input needs format {FORMAT_V7!r} or later (older formats have none)")
        if not others and isinstance(r.value, dict) and "others" in r.value:
            r["others"].fail(f"the other movers' inputs need format {FORMAT!r} (older formats have one mover)")
        if not others and isinstance(r.value, dict) and "stick_to" in r.value:
            r["stick_to"].fail(f"the input stick_to needs format {FORMAT!r}")
        r.obj({"dt", *TICK_INPUTS, *(("others",) if others else ())})
        dt = r["dt"].f64()
        if dt < 0:
            r["dt"].fail(f"a tick's dt is the time the clock advances: 0 or more seconds, got {dt!r}")
        kw = _read_setters(r)
        if driver == "request_pos":
            if not r.has("request_pos"):
                raise InvalidScene(_p(r.path, "request_pos"), "missing: driver request_pos moves the mover to a "
                                   "RequestPos on every tick (give each step one, or use driver update_object)")
            kw["request_pos"] = Position.from_json(r["request_pos"])
        elif r.has("request_pos"):
            r["request_pos"].fail("driver update_object moves the mover by its own velocity and root motion: "
                                  "a RequestPos belongs to driver request_pos")
        if r.has("motion"):
            kw["motion"] = MotionInput.from_json(r["motion"])
        if r.has("stop"):
            kw["stop"] = read_stop(r["stop"])
        for name in ("do_motion", "stop_motion"):
            if r.has(name):
                kw[name] = CommandInput.from_json(r[name])
        if r.has("move_to"):
            kw["move_to"] = MoveToInput.from_json(r["move_to"], True)
        if r.has("turn_to_heading"):
            kw["turn_to_heading"] = MoveToInput.from_json(r["turn_to_heading"], False)
        for name in ("move_to_object", "turn_to_object"):
            if r.has(name):
                kw[name] = ObjectMoveInput.from_json(r[name])
        if r.has("door"):
            kw["door"] = DoorInput.from_json(r["door"])
        if r.has("stick_to"):
            kw["stick_to"] = r["stick_to"].id_()
        if others and r.given("others"):
            kw["others"] = tuple(OtherInputs.from_json(o) for o in r["others"].list())
        return TickStep(dt, **kw)


@dataclass(frozen=True, slots=True)
class Ticks:
    """A tick scene's timeline: the driver, the clock when the mover is made (Timers.PortalYearTicks,
    double seconds) and one step per tick, in order."""

    driver: str                                # "update_object" | "request_pos"
    start: float                               # double
    steps: tuple[TickStep, ...]

    def times(self) -> tuple[float, ...]:
        """The clock of each tick: ``t = start; t = t + dt`` per step, in double arithmetic, computed
        here once (the harness's clock, not a physics rule): the oracle packs these absolute values
        and the port runs on the same ones."""
        out = []
        t = float(self.start)
        for s in self.steps:
            t = t + float(s.dt)
            out.append(t)
        return tuple(out)

    def to_json(self):
        return as_text(self) or {"driver": self.driver, "start": write_f64(self.start),
                                 "steps": [s.to_json() for s in self.steps]}

    def json_text(self) -> str:
        return ('{"driver":' + dumps_compact(self.driver) + ',"start":' + float.__repr__(write_f64(self.start))
                + ',"steps":[' + ",".join([s.json_text() for s in self.steps]) + "]}")

    @staticmethod
    def from_json(r: Reader, motion: bool = True, doors: bool = True, others: bool = True) -> "Ticks":
        """`motion`: the format knows the tick input motion (scene/6); `doors`: the input door (scene/7);
        `others`: the other movers' inputs (scene/8)."""
        r.obj({"driver", "start", "steps"})
        driver = r["driver"].str_()
        if driver not in DRIVERS:
            r["driver"].fail(f"unknown driver {driver!r} (known: {', '.join(DRIVERS)})")
        start = r["start"].f64()
        steps = r["steps"].list()
        if not steps:
            r["steps"].fail("a tick scene needs at least one step (one per tick)")
        ticks = Ticks(driver, start, tuple(TickStep.from_json(s, driver, motion, doors, others) for s in steps))
        times = ticks.times()
        if not math.isfinite(times[-1]):
            r["steps"].fail(f"the clock overflows: start plus the steps' dt reaches {times[-1]}")
        return ticks


DEFAULT_MOVER_STATE = int(PhysicsState.EdgeSlide | PhysicsState.Gravity)
DEFAULT_MOVER_TRANSIENT = int(TransientState.Contact | TransientState.OnWalkable)


def mover_start_json(m, d: dict, explicit_via: bool = False) -> dict:
    """A mover's state and path after what its Setup holds, written into `d`: the scene's mover and the
    `dat` feature's (protocol.dat_json, whose Setup record carries the spheres and step heights, and whose
    placement always says its `via`)."""
    d.update({"state": flag_names(PhysicsState, m.state), "transient_state": flag_names(TransientState, m.transient_state),
              "velocity": write_vec(m.velocity), "begin": m.begin.to_json()})
    if m.end is not None:
        d["end"] = m.end.to_json()
    if m.contact_plane is not None:
        d["contact_plane"] = m.contact_plane.to_json()
    if m.sliding_normal is not None:
        d["sliding_normal"] = write_vec(m.sliding_normal)
    if m.placement is not None:
        d["placement"] = m.placement.to_json(explicit_via)
    return d


INT32 = (-0x80000000, 0x7FFFFFFF)
_LOCATION_NAMES = {("None" if m is ParentLocation.None_ else m.name): int(m) for m in ParentLocation}
_LOCATION_BY_VALUE = {v: k for k, v in _LOCATION_NAMES.items()}


def _location_json(location: int):
    return _LOCATION_BY_VALUE.get(location, location)


def _read_location(r: Reader) -> int:
    """A ParentLocation by its name (ACE.Entity.Enum.ParentLocation) or any int32 (a Setup's HoldingLocations
    and set_parent take an int)."""
    if isinstance(r.value, str):
        if r.value not in _LOCATION_NAMES:
            r.fail(f"unknown ParentLocation {r.value!r} (known: {', '.join(_LOCATION_NAMES)}, or a number)")
        return _LOCATION_NAMES[r.value]
    return r.int_(*INT32)


@dataclass(frozen=True, slots=True)
class HoldingLocation:
    """One of a Setup's HoldingLocations (scene/8 `holding_locations`, on the mover and on another mover): the
    ParentLocation a child is held at -> the part holding it and the child's frame in that part. A part id at or
    past the Setup's parts holds the frame in the holder's Position (PhysicsObj.UpdateChild); -1 (add_child's own
    "no part") throws there, as in ACE; any int32 is written as given."""

    location: int
    part: int
    frame: Frame

    def to_json(self):
        return {"location": _location_json(self.location), "part": self.part, "frame": self.frame.to_json()}

    @staticmethod
    def from_json(r: Reader) -> "HoldingLocation":
        r.obj({"location", "part", "frame"})
        return HoldingLocation(_read_location(r["location"]), r["part"].int_(*INT32), Frame.from_json(r["frame"]))


def _read_holding_locations(r: Reader) -> tuple[HoldingLocation, ...]:
    """A Setup's HoldingLocations, in the order given (its Dictionary's); a location given twice is refused (the
    DAT's dictionary holds each key once)."""
    out, seen = [], {}
    for i, item in enumerate(r.list()):
        h = HoldingLocation.from_json(item)
        if h.location in seen:
            item["location"].fail(f"location {_location_json(h.location)} is given twice (also [{seen[h.location]}]): a "
                                  "Setup's HoldingLocations is a dictionary keyed by location")
        seen[h.location] = i
        out.append(h)
    return tuple(out)


@dataclass(frozen=True, slots=True)
class ChildOf:
    """Another mover held by a parent (scene/8 `others[].parent`) instead of entering the world: the parent's id
    (the mover's or an earlier other's), the ParentLocation it is held at and the child's Placement id, as the
    client parents a wielded item: SetPlacementFrame(placement), then set_parent(parent, location) (port/parenting.py)."""

    id: int
    location: int
    placement: int = 0  # ACE.Entity.Enum.Placement.Default
    # the frame form instead of a location (scene/8, `part` and `frame`): set_parent(parent, part, frame), the
    # client's call for an object attached to a part (ParticleEmitter.SetParenting): add_child at that part (-1:
    # the parent's Position) with that frame, location 0, and no SetPlacementFrame
    part: int | None = None
    frame: Frame | None = None

    def to_json(self):
        if self.part is not None:
            return {"id": write_id(self.id), "part": self.part, "frame": self.frame.to_json()}
        return {"id": write_id(self.id), "location": _location_json(self.location), "placement": self.placement}

    @staticmethod
    def from_json(r: Reader) -> "ChildOf":
        if isinstance(r.value, dict) and ("part" in r.value or "frame" in r.value):
            r.obj({"id", "part", "frame"})
            if not (r.given("part") and r.given("frame")):
                r.fail("the frame form gives both part and frame (set_parent(parent, part, frame)), and no location")
            return ChildOf(r["id"].id_(), 0, 0, r["part"].int_(*INT32), Frame.from_json(r["frame"]))
        r.obj({"id", "location", "placement"})
        return ChildOf(r["id"].id_(), _read_location(r["location"]),
                       r["placement"].int_(*INT32) if r.given("placement") else 0)


@dataclass(frozen=True, slots=True)
class MoverSkills:
    """scene/8: what the physics reads of the mover's Player beyond its flags (WeenieObject.InqRunRate,
    InqJumpVelocity, InqBurden): ``GetCreatureSkill(Skill.Run).Current``, ``GetCreatureSkill(Skill.Jump).Current``,
    ``Stamina.Current``, ``Strength.Current``, ``EncumbranceVal`` and ``AugmentationIncreasedCarryingCapacity``.
    The defaults are what ACE's database-free Player answers (docs/oracle.md's audit): no skill, Stamina its
    MaxValue's floor 1 (Creature's constructor fills an empty vital), Strength its attribute floor 1, no load.
    The bounds are where ACE's own values stay exact: a skill's and an attribute's Current is rounded through a
    float (2^24), and an attribute's Current is never under 1 (CreatureAttribute.GetCurrent)."""

    run: int = 0
    jump: int = 0
    stamina: int = 1
    strength: int = 1
    encumbrance_val: int = 0
    augmentation_increased_carrying_capacity: int = 0

    # (field, lo, hi)
    BOUNDS = (("run", 0, 1 << 24), ("jump", 0, 1 << 24), ("stamina", 0, 0xFFFFFFFF), ("strength", 1, 1 << 24),
              ("encumbrance_val", -(1 << 31), (1 << 31) - 1),
              ("augmentation_increased_carrying_capacity", -(1 << 31), (1 << 31) - 1))

    def to_json(self) -> dict:
        """The fields that differ from the default."""
        return {name: getattr(self, name) for name, _, _ in self.BOUNDS if getattr(self, name) != getattr(DEFAULT_SKILLS, name)}

    @staticmethod
    def from_json(r: Reader) -> "MoverSkills":
        r.obj({name for name, _, _ in MoverSkills.BOUNDS})
        return MoverSkills(**{name: r[name].int_(lo, hi) for name, lo, hi in MoverSkills.BOUNDS if r.given(name)})


DEFAULT_SKILLS = MoverSkills()


def _read_body(r: Reader, min_spheres: int = 1) -> tuple:
    """A mover's Setup as the scene gives it (the mover's and another mover's): its spheres (1 or 2; 0 for another
    mover's of weenie object, `min_spheres`), scale and step heights, each checked."""
    spheres = tuple(SphereRec.from_json(x) for x in r["spheres"].list(min_count=min_spheres, max_count=2))
    scale = r["scale"].f32() if r.given("scale") else 1.0
    if not scale > 0:
        r["scale"].fail(f"scale must be positive, got {scale}")
    up = r["step_up_height"].f32()
    down = r["step_down_height"].f32()
    for name, v in (("step_up_height", up), ("step_down_height", down)):
        if v < 0:
            r[name].fail(f"a step height cannot be negative, got {v}")
    return spheres, scale, up, down


@dataclass(frozen=True, slots=True)
class Mover:
    """The moving PhysicsObj: its Setup spheres and step heights, flags, and the path to try
    (`end`; None in a tick scene, whose ticks move the mover)."""

    spheres: tuple[SphereRec, ...]
    begin: Position
    end: Position | None
    step_up_height: float
    step_down_height: float
    scale: float = 1.0
    state: int = DEFAULT_MOVER_STATE
    transient_state: int = DEFAULT_MOVER_TRANSIENT
    velocity: Vec3 = (0.0, 0.0, 0.0)
    contact_plane: ContactPlane | None = None
    sliding_normal: Vec3 | None = None
    placement: Placement | None = None  # None: Position = begin, CurCell = its cell (no placement)
    motion_table: MotionTableSpec | None = None  # scene/6: the Setup's DefaultMotionTable and the player's MotionTableId
    # scene/6: the mover's Player's PlayerKillerStatus (ACE.Entity.Enum), set before its WeenieObject is made
    # (which copies it); a player without the property is NPK. PK and PKLite are IsPKType: FastTick's jump.
    player_killer_status: int = PLAYER_KILLER_STATUS_NPK
    skills: MoverSkills = DEFAULT_SKILLS  # scene/8: its Player's skills, vitals, attributes and burden
    holding_locations: tuple[HoldingLocation, ...] = ()  # scene/8: its Setup's HoldingLocations (a child's parent)
    # scene/8: its Setup's DefaultScript (a PhysicsScript id, 0 none): InitDefaults plays it, which makes the
    # object's ScriptManager (ACE's server runs no script: AddScript refuses it, UpdateScripts is empty)
    default_script: int = 0
    # scene/8: its Setup's placement frame Resting (0x65) for its one part (None: the Setup has no placement
    # frames): PartArray.CreateSetup's SetPlacementFrame(0x65) (makeAnimObject) finds it, and the Sequence's placement frame places the part
    resting_frame: Frame | None = None
    # scene/8: its Setup's flag AllowFreeHeading (SetupFlags 0x4): PhysicsObj.get_object_info then sets
    # ObjectInfoState.FreeRotate, so a transition takes the end's orientation at once instead of turning by steps
    free_heading: bool = False

    @property
    def motion_table_id(self) -> int:
        """The player's MotionTableId: acconform.motion_scene.MOTION_TABLE_ID with a motion table, else 0."""
        from .motion_scene import MOTION_TABLE_ID

        return MOTION_TABLE_ID if self.motion_table is not None else 0

    def to_json(self, explicit_via: bool = False):
        """`explicit_via`: the placement says its `via` even through SetPosition (scene/7, whose
        placements, as /6's, go through enter_world unless they say otherwise)."""
        d = {"spheres": [s.to_json() for s in self.spheres], "scale": write_f32(self.scale),
             "step_up_height": write_f32(self.step_up_height), "step_down_height": write_f32(self.step_down_height)}
        mover_start_json(self, d, explicit_via)
        if self.motion_table is not None:
            d["motion_table"] = self.motion_table.to_json()
        if self.player_killer_status != PLAYER_KILLER_STATUS_NPK:
            d["player_killer_status"] = PlayerKillerStatus(self.player_killer_status).name
        if self.skills != DEFAULT_SKILLS:
            d["skills"] = self.skills.to_json()
        if self.holding_locations:
            d["holding_locations"] = [h.to_json() for h in self.holding_locations]
        if self.default_script:
            d["default_script"] = write_id(self.default_script)
        if self.resting_frame is not None:
            d["resting_frame"] = self.resting_frame.to_json()
        if self.free_heading:
            d["free_heading"] = True
        return d

    @staticmethod
    def from_json(r: Reader, placement: bool = True, ticks: bool = False, vias: bool = True,
                  skills: bool = True, children: bool = False) -> "Mover":
        """`placement`: the format may hold one (scene/3 and later). `ticks`: the scene is a tick
        scene, whose mover has no end. `vias`: a placement may say `via` (scene/6). `skills`: the
        format holds the mover's `skills` (scene/8). `children`: its Setup may have holding locations (scene/8)."""
        if not skills and isinstance(r.value, dict) and "skills" in r.value:
            r["skills"].fail(f"skills need format {FORMAT!r} (older formats have none)")
        for field in ("holding_locations", "default_script", "resting_frame", "free_heading"):
            if not children and isinstance(r.value, dict) and field in r.value:
                r[field].fail(f"{field} needs format {FORMAT!r} (older formats have none)")
        if not placement and isinstance(r.value, dict) and "placement" in r.value:
            r["placement"].fail(f"a placement needs format {FORMAT_V3!r} or later (older formats have no placement)")
        if ticks and isinstance(r.value, dict) and "end" in r.value:
            r["end"].fail("a tick scene's mover has no end: its ticks move it (omit end)")
        for field in ("motion_table", "player_killer_status"):
            if not vias and isinstance(r.value, dict) and field in r.value:
                r[field].fail(f"{field} needs format {FORMAT_V6!r} or later (older formats have none)")
        r.obj({"spheres", "scale", "step_up_height", "step_down_height", "state", "transient_state",
               "velocity", "contact_plane", "sliding_normal", "begin", "end", *(("placement",) if placement else ()),
               *(("motion_table", "player_killer_status") if vias else ()), *(("skills",) if skills else ()),
               *(("holding_locations", "default_script", "resting_frame", "free_heading") if children else ())})
        spheres, scale, up, down = _read_body(r)
        if vias and not skills and r.has("motion_table") and MotionTableSpec.from_json(r["motion_table"]).needs_v8:
            r["motion_table"].fail(f"hooks, root_motion and default_animation need format {FORMAT!r} (older formats have none)")
        return Mover(
            spheres=spheres,
            begin=Position.from_json(r["begin"]),
            end=None if ticks else Position.from_json(r["end"]),
            step_up_height=up,
            step_down_height=down,
            scale=scale,
            state=r["state"].flags(PhysicsState) if r.given("state") else DEFAULT_MOVER_STATE,
            transient_state=r["transient_state"].flags(TransientState) if r.given("transient_state") else DEFAULT_MOVER_TRANSIENT,
            velocity=r["velocity"].vec3() if r.given("velocity") else (0.0, 0.0, 0.0),
            contact_plane=ContactPlane.from_json(r["contact_plane"]) if r.has("contact_plane") else None,
            sliding_normal=r["sliding_normal"].vec3() if r.has("sliding_normal") else None,
            placement=Placement.from_json(r["placement"], vias) if r.has("placement") else None,
            motion_table=MotionTableSpec.from_json(r["motion_table"]) if vias and r.has("motion_table") else None,
            player_killer_status=r["player_killer_status"].enum_(PlayerKillerStatus) if vias and r.given("player_killer_status")
            else PLAYER_KILLER_STATUS_NPK,
            skills=MoverSkills.from_json(r["skills"]) if skills and r.given("skills") else DEFAULT_SKILLS,
            holding_locations=_read_holding_locations(r["holding_locations"]) if children and r.given("holding_locations")
            else (),
            default_script=r["default_script"].id_() if children and r.given("default_script") else 0,
            resting_frame=Frame.from_json(r["resting_frame"]) if children and r.given("resting_frame") else None,
            free_heading=r["free_heading"].bool_() if children and r.given("free_heading") else False,
        )


# the WorldObject a server makes for another mover (scene/8 `others[].weenie`): WeenieObject(WorldObject) reads its class;
# the last two are projectiles (an Ammunition: an arrow, bolt or dart; a SpellProjectile), which a `launch` puts in the world
WEENIE_CLASSES = ("player", "creature", "monster", "object", "ammunition", "spell_projectile", "missile")
# a `missile` is a thrown weapon (ACE's Missile: a Stackable that keeps WorldObject's OnCollideObject and
# OnCollideEnvironment, the helper run only with a ProjectileTarget), launched as an arrow is (Creature.LaunchProjectile)
PROJECTILE_WEENIES = ("ammunition", "spell_projectile", "missile")


@dataclass(frozen=True, slots=True)
class Launch:
    """A projectile's launch (scene/8 `others[].launch`, for weenie ``ammunition`` or ``spell_projectile``): at
    step `tick`, after that step's inputs and before its clock (a server's launch is an action, run after a
    landblock's physics with that tick's clock: the next physics step is the projectile's first), `launcher`
    (the mover's id or another mover's, not a projectile) launches it at `target` (the mover, another mover
    that is no projectile, or an outdoor static) at `speed` m/s. `origin` and `orientation` are where it
    appears: its Location (the launcher's, Pos = origin, whose setter finds the outdoor landblock and cell of `origin`
    anew: ACE.Entity.Position.SetPosition; Rotation = orientation), what ACE's
    CalculateProjectileVelocity (an arrow) or LaunchSpellProjectiles (a spell) computes from the launcher's
    spawn offset; a spell projectile's orientation is its velocity's heading (set_vector_heading), so it gives
    none. ACE computes the velocity: an arrow's by Creature.GetProjectileVelocity from `origin` to the target's
    aim point (its origin raised by Height / 2, GetAimHeight's answer for a creature and for a player at
    Medium), leading a moving target (its CachedVelocity) unless the launcher is a player without
    LeadMissileTargets (`lead_target` false); a spell's by WorldObject.CalculateProjectileVelocity (the aim
    point raised by Height * 2/3, or 5/6 for an `arc`, which falls under gravity; a `tracking` spell leads
    the target). `alt_solver` is the server's trajectory_alt_solver property (PropertyManager, false by default):
    both compute the velocity by Trajectory2.CalculateTrajectory instead (feature missiles.alt_solver).
    `rotation_speed` is the projectile's RotationSpeed (PropertyFloat, revolutions a second; 0: none, ACE's null),
    a weenie property of some arrows, bolts, thrown weapons and spells: SetProjectilePhysicsState (an arrow) and
    SpellProjectile.Setup (a spell) then clear AlignPath and set Omega = (2 pi RotationSpeed, 0, 0), so it
    tumbles as it flies (feature missiles.rotation_speed). A spell may have no `target` (None; feature
    missiles.untargeted): as ACE launches an untargeted cast, a side projectile of a multi-projectile spell or a
    trap's emote cast at no one, WorldObject.CalculateProjectileVelocity sends it along the caster's forward vector
    (Vector3.Transform(UnitY, the launcher's orientation) * speed: the launcher has no AttackTarget) and it flies
    with no ProjectileTarget. `spell` is the spell's kind as SpellProjectile.Setup reads it (SPELL_KINDS; feature
    missiles.spells): its name (Rolling Death), its projectile's weenie (a wall's) or its SpellType (Ring)."""

    tick: int
    launcher: int
    target: int | None
    speed: float
    origin: Vec3
    orientation: Quat = IDENTITY
    lead_target: bool = True
    arc: bool = False
    tracking: bool = False
    alt_solver: bool = False
    rotation_speed: float = 0.0
    spell: str = "plain"

    def to_json(self, spell: bool) -> dict:
        d = {"tick": self.tick, "launcher": write_id(self.launcher)}
        if self.target is not None:  # a spell may have none
            d["target"] = write_id(self.target)
        d |= {"speed": write_f32(self.speed), "origin": write_vec(self.origin)}
        if spell:
            d["arc"] = self.arc
            d["tracking"] = self.tracking
        else:
            d["orientation"] = write_vec(self.orientation)
            d["lead_target"] = self.lead_target
        if self.alt_solver:  # written only when set: a scene without it means what it meant
            d["alt_solver"] = True
        if self.rotation_speed != 0:  # written only when set, as alt_solver
            d["rotation_speed"] = write_f32(self.rotation_speed)
        if self.spell != "plain":  # a spell's, written only when not plain
            d["spell"] = self.spell
        return d

    @staticmethod
    def from_json(r: Reader, spell: bool) -> "Launch":
        r.obj({"tick", "launcher", "target", "speed", "origin", "alt_solver", "rotation_speed",
               *(("arc", "tracking", "spell") if spell else ("orientation", "lead_target"))})
        if not spell and not r.given("target"):
            r.fail("an arrow's or a thrown weapon's launch names its target (Creature.LaunchProjectile aims at one); "
                   "only a spell may have none")
        kind = r["spell"].str_() if r.given("spell") else "plain"
        if kind not in SPELL_KINDS:
            r["spell"].fail(f"unknown spell kind {kind!r} (known: {', '.join(SPELL_KINDS)})")
        if kind in ("wall", "ring", "ring_3818") and r.given("arc") and r["arc"].bool_():
            r["arc"].fail(f"a {kind} spell is no Arc (its SpellType is {'Wall' if kind == 'wall' else 'Ring'}): arc is false")
        speed = r["speed"].f32()
        if not speed > 0:
            r["speed"].fail(f"a launch speed is positive, got {speed}")
        frame = Frame.from_json(Reader({k: r.value[k] for k in ("origin", "orientation") if k in r.value}, r.path))
        return Launch(tick=r["tick"].int_(0, 2 ** 31 - 1), launcher=r["launcher"].id_(),
                      target=r["target"].id_() if r.given("target") else None, speed=speed,
                      origin=frame.origin, orientation=frame.orientation,
                      lead_target=r["lead_target"].bool_() if r.given("lead_target") else True,
                      arc=r["arc"].bool_() if r.given("arc") else False,
                      tracking=r["tracking"].bool_() if r.given("tracking") else False,
                      alt_solver=r["alt_solver"].bool_() if r.given("alt_solver") else False,
                      rotation_speed=r["rotation_speed"].f32() if r.given("rotation_speed") else 0.0, spell=kind)
# A spell's kind as SpellProjectile.Setup reads it (scene/8 launch.spell, feature missiles.spells): `plain` a Bolt or,
# with `arc`, an Arc; `rolling_death` the spell named "Rolling Death", whose Setup leaves Ethereal as the projectile was
# made; `wall` a wall spell of a weenie (7278, 7281, 7282, 23144) whose Setup clears ScriptedCollision (SpellType Wall);
# `ring` a Ring spell other than 3818 (ScriptedCollision cleared) and `ring_3818` Ring spell 3818 (ScriptedCollision set)
SPELL_KINDS = ("plain", "rolling_death", "wall", "ring", "ring_3818")
PLAYER_ID_RANGE = (0x50000001, 0x5FFFFFFF)  # ACE.Entity.ObjectGuid.PlayerMin / PlayerMax
DYNAMIC_ID_RANGE = (0x80000000, 0xFFFFFFFE)  # ObjectGuid.DynamicMin / DynamicMax: a server's generated objects


@dataclass(frozen=True, slots=True)
class OtherMover:
    """Another moving object (scene/8 `others`): a WorldObject of ACE's server with its PhysicsObj, made
    from its Setup (spheres and step heights, as the mover's) as WorldObject.InitPhysicsObj makes one
    (makeAnimObject, set_object_guid(id), set_weenie_obj(new WeenieObject(the WorldObject)),
    SetScaleStatic, State), then TransientState and Velocity, and entered into the world at `begin` as
    WorldObject.AddPhysicsObj enters it (LScape.get_landcell, enter_world), after the mover's placement
    and in `others` order. `weenie` names the WorldObject: ``player`` (a Player: its id in ACE's player
    range), ``creature`` (a Creature that is not a monster: an NPC), ``monster`` (a Creature with
    IsMonster) or ``object`` (a GenericObject: no creature); the others' ids are in ACE's dynamic range.
    A creature's PlayerKillerStatus is its WeenieObject's (IsPK, IsPKLite, IsImpenetrable for a player).
    Each tick steps it after the mover, in `others` order (the order the objects entered: a landblock's
    worldObjects), by update_object.

    Children (feature objects.children): its Setup may have `holding_locations` (as the mover's) and a
    `sorting_sphere` (None: a zero one; what calc_cross_cells finds a child's cells with when its Setup has no
    cylspheres). With `parent` (and no `begin`) it is a child: made as the others are, then held by its parent
    (SetPlacementFrame, set_parent: port/parenting.py) in `others` order instead of entering the world, and never
    stepped itself (its parent's UpdateChild carries it: a server's landblock never ticks a wielded item, which is
    no landblock object, and update_object of an object with a Parent only clears its Active flag).

    `report_collisions` is its WorldObject's PropertyBool.ReportCollisions (None: unset, as made; feature
    objects.report_collisions), which a weenie may carry: false, a Player's or a Creature's OnCollideObject with it
    returns at once. InitPhysicsObj makes the PhysicsState bit the property's, so `state` agrees with it.

    `setup` (feature setup.multipart_movers) makes its Setup one of several BSP parts, as a static's (`SetupRec`: the
    parts at their placement frames, or none with `placement` false, their DefaultScale and the Setup's cylspheres;
    its spheres stay `spheres`); with no parts (feature setup.no_parts) ACE's makeObject gives it no PartArray."""

    id: int
    weenie: str
    spheres: tuple[SphereRec, ...]
    begin: Position | None  # None: a child (it enters the world with its parent)
    step_up_height: float
    step_down_height: float
    scale: float = 1.0
    state: int = DEFAULT_MOVER_STATE
    transient_state: int = DEFAULT_MOVER_TRANSIENT
    velocity: Vec3 = (0.0, 0.0, 0.0)
    player_killer_status: int = PLAYER_KILLER_STATUS_NPK
    holding_locations: tuple[HoldingLocation, ...] = ()
    sorting_sphere: SphereRec | None = None
    parent: ChildOf | None = None
    launch: Launch | None = None  # a projectile's (weenie ammunition or spell_projectile): made at the start, in the world from its launch
    report_collisions: bool | None = None  # the WorldObject's PropertyBool.ReportCollisions (None: unset)
    # scene/8 (feature setup.multipart_movers): its Setup's parts (each a BSP GfxObj at its placement frame, with or
    # without a DefaultScale entry) and cylspheres, as a static's `setup` gives them; its spheres stay `spheres`.
    # None: one empty part, as before
    setup: SetupRec | None = None
    # scene/8 (feature objects.motion_tables): its WorldObject's MotionTableId is the scene's motion table (the mover's,
    # MOTION_TABLE_ID), which InitPhysicsObj's SetMotionTableID sets (a Chest's, a door's or an NPC's table); False: 0
    motion_table: bool = False

    @property
    def motion_table_id(self) -> int:
        from .motion_scene import MOTION_TABLE_ID

        return MOTION_TABLE_ID if self.motion_table else 0
    # scene/8 (feature missiles.missile_flight): an arrow's or a thrown weapon's Setup carries a placement frame keyed
    # MissileFlight (52; the identity, for its one part), as the Setups of many of ACE's arrows and bolts do: the
    # DatLoader's SetupModel.Unpack sets HasMissileFlightPlacement and SetProjectilePhysicsState gives the WorldObject
    # Placement MissileFlight (no physics: the PartArray takes only Resting, 0x65, or Default)
    missile_flight: bool = False

    def to_json(self):
        d = {"id": write_id(self.id), "weenie": self.weenie, "spheres": [s.to_json() for s in self.spheres],
             "scale": write_f32(self.scale), "step_up_height": write_f32(self.step_up_height),
             "step_down_height": write_f32(self.step_down_height), "state": flag_names(PhysicsState, self.state),
             "transient_state": flag_names(TransientState, self.transient_state), "velocity": write_vec(self.velocity)}
        if self.begin is not None:
            d["begin"] = self.begin.to_json()
        if self.player_killer_status != PLAYER_KILLER_STATUS_NPK:
            d["player_killer_status"] = PlayerKillerStatus(self.player_killer_status).name
        if self.holding_locations:
            d["holding_locations"] = [h.to_json() for h in self.holding_locations]
        if self.sorting_sphere is not None:
            d["sorting_sphere"] = self.sorting_sphere.to_json()
        if self.parent is not None:
            d["parent"] = self.parent.to_json()
        if self.launch is not None:
            d["launch"] = self.launch.to_json(self.weenie == "spell_projectile")
        if self.report_collisions is not None:
            d["report_collisions"] = self.report_collisions
        if self.setup is not None:
            d["setup"] = self.setup.to_json()
        if self.motion_table:  # written only when set: a scene without it means what it meant
            d["motion_table"] = True
        if self.missile_flight:
            d["missile_flight"] = True
        return d

    @staticmethod
    def from_json(r: Reader) -> "OtherMover":
        r.obj({"id", "weenie", "spheres", "scale", "step_up_height", "step_down_height", "state", "transient_state",
               "velocity", "begin", "player_killer_status", "holding_locations", "sorting_sphere", "parent", "launch",
               "report_collisions", "setup", "motion_table", "missile_flight"})
        setup = None
        if r.given("setup"):
            setup = SetupRec.from_json(r["setup"], mover=True)
            for name, given in (("spheres", setup.spheres), ("parent_index", setup.parent_index is not None),
                                ("default_script", setup.default_script), ("default_animation", setup.default_animation is not None)):
                if given:
                    r["setup"][name].fail(f"another mover's setup gives parts and cylspheres only ({name}: "
                                          + ("its spheres are the other's own `spheres`)" if name == "spheres" else "none)"))
        parent = ChildOf.from_json(r["parent"]) if r.given("parent") else None
        if parent is not None and r.given("begin"):
            r["begin"].fail("a child enters the world with its parent (set_parent, not enter_world): omit begin")
        weenie = r["weenie"].str_()
        if weenie not in WEENIE_CLASSES:
            r["weenie"].fail(f"unknown weenie {weenie!r} (known: {', '.join(WEENIE_CLASSES)})")
        oid = r["id"].id_()
        low, high = PLAYER_ID_RANGE if weenie == "player" else DYNAMIC_ID_RANGE
        if not low <= oid <= high:
            what = "a player's id is in ACE's player range" if weenie == "player" else \
                "a server's generated object has an id in ACE's dynamic range"
            r["id"].fail(f"{what} (0x{low:08X}..0x{high:08X}), got 0x{oid:08X}")
        # a GenericObject's Setup may have no spheres (feature objects.sphereless): ACE's items, chests and doors made
        # of BSP parts; enter_world's SetPosition then runs its transition on a dummy sphere, and UpdateObjectInternal
        # takes its arm for an object with none (the position kept, Active cleared on walkable ground)
        spheres, scale, up, down = _read_body(r, 0 if weenie == "object" else 1)
        launch = None
        if weenie in PROJECTILE_WEENIES:
            if not r.given("launch"):
                raise InvalidScene(f"{r.path}.launch", f"a projectile (weenie {weenie}) needs a launch: its tick, launcher, "
                                                       "target, speed and origin")
            launch = Launch.from_json(r["launch"], weenie == "spell_projectile")
        elif r.given("launch"):
            r["launch"].fail(f"a launch is a projectile's (weenie {' or '.join(PROJECTILE_WEENIES)}), not a {weenie}'s")
        pks = PLAYER_KILLER_STATUS_NPK
        if r.given("player_killer_status"):
            if weenie == "object" or weenie in PROJECTILE_WEENIES:
                r["player_killer_status"].fail("a PlayerKillerStatus is a creature's: WeenieObject(WorldObject) copies "
                                               "it only from a Creature (weenie player, creature or monster)")
            pks = r["player_killer_status"].enum_(PlayerKillerStatus)
        state = r["state"].flags(PhysicsState) if r.given("state") else DEFAULT_MOVER_STATE
        report = None
        if r.given("report_collisions"):
            if weenie in PROJECTILE_WEENIES:
                r["report_collisions"].fail("a projectile's launch sets its ReportCollisions (true): omit it")
            report = r["report_collisions"].bool_()
            if report != bool(state & PhysicsState.ReportCollisions):
                r["report_collisions"].fail(f"InitPhysicsObj makes the PhysicsState bit ReportCollisions the property's: "
                                            f"state {'needs' if report else 'has'} ReportCollisions")
        missile_flight = r["missile_flight"].bool_() if r.given("missile_flight") else False
        if missile_flight and (weenie not in ("ammunition", "missile") or setup is not None):
            r["missile_flight"].fail("a MissileFlight placement is an arrow's or a thrown weapon's (weenie ammunition or "
                                     "missile) Setup of one part: no `setup`")
        return OtherMover(
            id=oid, weenie=weenie, spheres=spheres, begin=None if parent is not None else Position.from_json(r["begin"]),
            step_up_height=up, step_down_height=down, scale=scale,
            state=state,
            transient_state=r["transient_state"].flags(TransientState) if r.given("transient_state") else DEFAULT_MOVER_TRANSIENT,
            velocity=r["velocity"].vec3() if r.given("velocity") else (0.0, 0.0, 0.0),
            player_killer_status=pks,
            holding_locations=_read_holding_locations(r["holding_locations"]) if r.given("holding_locations") else (),
            sorting_sphere=SphereRec.from_json(r["sorting_sphere"], bounding=True) if r.given("sorting_sphere") else None,
            parent=parent, launch=launch, report_collisions=report, setup=setup, missile_flight=missile_flight,
            motion_table=_read_other_motion_table(r, weenie))


def _read_other_motion_table(r: Reader, weenie: str) -> bool:
    """`others[].motion_table` (feature objects.motion_tables): a projectile's WorldObject has none."""
    if not r.given("motion_table"):
        return False
    table = r["motion_table"].bool_()
    if table and weenie in PROJECTILE_WEENIES:
        r["motion_table"].fail(f"a projectile (weenie {weenie}) has no motion table: omit it")
    return table


ENGINE_MODES = ("server", "client")


# scene/8 motion_queries (feature motion.queries): the server's questions to the mover's motion table, as ACE's
# WorldObjects ask them to time an attack, a cast, an emote, a pickup or a death. Each name is a call as the server
# makes it: the physics MotionTable's statics (GetAttackFrames; GetAnimationLength, its five-argument overload when
# current_motion is given; GetRunSpeed; GetTurnSpeed) and the DatLoader MotionTable's GetAnimationLength (with stance
# and current_motion: the three-argument overload of Player_Inventory and EmoteManager; without: the one of a
# MotionCommand, of Player_Death and Player_Location). ACE's server calls no other of them (GetCycleLength's one
# call is commented out, GetLinkData and HasDefaultScript have none; GetMotionData and GetAnimDist run inside
# GetRunSpeed and GetTurnSpeed).
MOTION_QUERY_FUNCTIONS = ("GetAttackFrames", "GetAnimationLength", "GetRunSpeed", "GetTurnSpeed", "Dat.GetAnimationLength")
_QUERY_FIELDS = {"GetAttackFrames": ({"stance", "motion"}, set()),
                 "GetAnimationLength": ({"stance", "motion"}, {"current_motion", "speed"}),
                 "GetRunSpeed": (set(), set()), "GetTurnSpeed": (set(), set()),
                 "Dat.GetAnimationLength": ({"motion"}, {"stance", "current_motion"})}  # name: (required, optional)
MAX_MOTION_QUERIES = 64


@dataclass(frozen=True, slots=True)
class MotionQuery:
    """One server query on the mover's motion table (its MotionTableId: the scene's table, or 0 for a mover without
    one): `function` a MOTION_QUERY_FUNCTIONS name; stance (MotionStance), motion and current_motion (MotionCommand)
    as uint32; speed the float argument (None: C#'s default, 1.0f)."""

    function: str
    stance: int = 0
    motion: int = 0
    current_motion: int | None = None
    speed: float | None = None

    def to_json(self):
        d = {"function": self.function}
        required, optional = _QUERY_FIELDS[self.function]
        for name in ("stance", "motion", "current_motion"):
            v = getattr(self, name)
            if name in required or (name in optional and v is not None and (name != "stance" or self.current_motion is not None)):
                d[name] = v
        if self.speed is not None:
            d["speed"] = write_f32(self.speed)
        return d

    @staticmethod
    def from_json(r: Reader) -> "MotionQuery":
        r.obj({"function", "stance", "motion", "current_motion", "speed"})
        function = r["function"].str_()
        if function not in _QUERY_FIELDS:
            r["function"].fail(f"unknown motion query {function!r} (known: {', '.join(MOTION_QUERY_FUNCTIONS)})")
        required, optional = _QUERY_FIELDS[function]
        for name in ("stance", "motion", "current_motion", "speed"):
            if r.given(name) and name not in required | optional:
                r[name].fail(f"{function} takes no {name}")
            if name in required and not r.given(name):
                r[name]  # raises: missing
        if function == "Dat.GetAnimationLength" and r.given("stance") != r.given("current_motion"):
            r["stance" if not r.given("stance") else "current_motion"].fail(
                "Dat.GetAnimationLength takes stance and current_motion together (its three-argument overload) or "
                "neither (the one of a MotionCommand)")
        u32 = (lambda name: r[name].int_(0, 0xFFFFFFFF) if r.given(name) else None)
        return MotionQuery(function, u32("stance") or 0, u32("motion") or 0, u32("current_motion"),
                           r["speed"].f32(allow_nonfinite=True) if r.given("speed") else None)


@dataclass(frozen=True, slots=True)
class Scene:
    landblocks: tuple[Landblock, ...]
    mover: Mover
    objects: tuple[StaticObject, ...] = ()
    land_height_table: tuple[float, ...] = DEFAULT_LAND_HEIGHT_TABLE
    engine_mode: str = "server"  # PhysicsEngine.Instance.Server: ACE's server default
    name: str = ""
    environments: tuple[Environment, ...] = ()
    env_cells: tuple[EnvCell, ...] = ()
    ticks: Ticks | None = None  # a tick scene: ACE's per-tick update moves the mover (scene/4)
    buildings: tuple[Building, ...] = ()  # scene/5
    others: tuple[OtherMover, ...] = ()  # scene/8: the other moving objects, in the order they enter the world
    # scene/8: the DAT records carry what a client draws, as retail's do (acconform/dat.py: polygons' UV indices, a
    # BSP GfxObj's drawing polygons, drawing BSP, surface and degrade table, an EnvCell's surface): DatLoader reads
    # them, ACE's physics reads only the drawing BSP's root sphere (GfxObj.DrawingSphere) and, in the client engine
    # mode, makes the drawing polygons
    drawing: bool = False
    # scene/8: the server's queries on the mover's motion table, asked in order after the last tick (a tick scene's)
    motion_queries: tuple[MotionQuery, ...] = ()

    @property
    def indoor(self) -> bool:
        """Whether the scene needs /2: EnvCells, Environments or a landblock without terrain."""
        return bool(self.env_cells or self.environments) or not all(lb.has_terrain for lb in self.landblocks)

    @property
    def has_motion(self) -> bool:
        """Whether the scene uses the motion layer (protocol feature mover.motion): a motion table or a
        motion input."""
        return self.mover.motion_table is not None or (
            self.ticks is not None and any(getattr(s, name) is not None for s in self.ticks.steps for name in MOTION_INPUTS))

    @property
    def has_doors(self) -> bool:
        """Whether a tick opens or closes a static (the input door; protocol feature doors)."""
        return self.ticks is not None and any(s.door is not None for s in self.ticks.steps)

    @property
    def has_restrictions(self) -> bool:
        """scene/8: an EnvCell's restriction_obj or a landblock's restriction table (housing barriers)."""
        return any(c.restriction_obj for c in self.env_cells) or any(lb.restrictions for lb in self.landblocks)

    @property
    def has_no_drawing_bsp(self) -> bool:
        """scene/8: a cell structure written with hasDrawingBSP 0 (CellStructRec.drawing_bsp false)."""
        return any(not c.drawing_bsp for e in self.environments for c in e.cell_structs)

    @property
    def has_missing_keys(self) -> bool:
        """scene/8: a key ACE's physics looks up and does not find: an EnvCell's cell_structure past its Environment's
        structures (CellStructure stays null), an EnvCell portal's polygon or a structure's portal past the structure's
        polygons (the Polygons indexer throws KeyNotFoundException)."""
        envs = {e.id: e for e in self.environments}
        for c in self.env_cells:
            env = envs.get(c.environment)
            if env is None:
                continue
            if c.cell_structure >= len(env.cell_structs):
                return True
            if any(p.polygon >= len(env.cell_structs[c.cell_structure].polygons) for p in c.portals):
                return True
        if any(k >= len(c.polygons) for e in self.environments for c in e.cell_structs for k in c.portals):
            return True
        shapes = [(len(c.physics_polygons), c.physics_bsp) for e in self.environments for c in e.cell_structs]
        shapes += [(len(b.shape.polygons), b.shape.root) for b in self.buildings]
        shapes += [(len(o.shape.polygons), o.shape.root) for o in self.objects if isinstance(o.shape, BSPShape)]
        shapes += [(len(p.shape.polygons), p.shape.root) for o in (*self.objects, *self.others)
                   if getattr(o, "setup", None) is not None for p in o.setup.parts]
        return any(_leaf_past(root, n) for n, root in shapes)

    @property
    def has_cell_bsp_portals(self) -> bool:
        """scene/8: a cell BSP node written with the tag PORT (CellBSPNode.portal)."""
        def walk(node) -> bool:
            return isinstance(node, CellBSPNode) and (node.portal or walk(node.front) or walk(node.back))
        return any(walk(c.cell_bsp) for e in self.environments for c in e.cell_structs)

    @property
    def has_outdoor_words(self) -> bool:
        """scene/8: a visible cell or a building portal's other cell below 0x0100 (OUTDOOR_WORD_LAST)."""
        return any(v <= OUTDOOR_WORD_LAST for c in self.env_cells for v in c.visible_cells) or any(
            p.other_cell <= OUTDOOR_WORD_LAST for b in self.buildings for p in b.portals)

    @property
    def format(self) -> str:
        """The oldest format that holds the scene (/8 for other movers, motion queries, the mover's skills or holding locations, a
        motion table's hooks, animations without root motion or DefaultAnimation, a Setup's parent_index,
        DefaultScript or DefaultAnimation, the mover's resting frame or free heading, drawn DAT records, /7
        for a static with a setup or a door input, /6 for a placement through enter_world, /5 for buildings, /4 for
        ticks, /3 for a placement, /2 indoors, else /1)."""
        if self.others or self.motion_queries or self.mover.skills != DEFAULT_SKILLS or self.mover.holding_locations or (
                self.mover.motion_table is not None and self.mover.motion_table.needs_v8) or self.mover.default_script or (
                self.mover.resting_frame is not None) or self.mover.free_heading or self.drawing or self.has_restrictions or (
                self.has_outdoor_words) or self.has_no_drawing_bsp or self.has_missing_keys or self.has_cell_bsp_portals or any(
                o.setup is not None and (o.setup.default_script or o.setup.parent_index is not None
                                         or o.setup.default_animation is not None or not o.setup.parts) for o in self.objects):
            return FORMAT
        if any(o.setup is not None for o in self.objects) or self.has_doors:
            return FORMAT_V7
        if self.has_motion or self.mover.player_killer_status != PLAYER_KILLER_STATUS_NPK:
            return FORMAT_V6
        if self.mover.placement is not None and self.mover.placement.via == "enter_world":
            return FORMAT_V6
        if self.buildings:
            return FORMAT_V5
        if self.ticks is not None:
            return FORMAT_V4
        if self.mover.placement is not None:
            return FORMAT_V3
        return FORMAT_V2 if self.indoor else FORMAT_V1

    def to_json(self):
        d = {"format": self.format}
        if self.name:
            d["name"] = self.name
        d["engine"] = {"mode": self.engine_mode}
        if self.land_height_table != DEFAULT_LAND_HEIGHT_TABLE:
            d["land_height_table"] = [write_f32(h) for h in self.land_height_table]
        d["landblocks"] = [lb.to_json() for lb in self.landblocks]
        if self.objects:
            d["objects"] = [o.to_json() for o in self.objects]
        if self.environments:
            d["environments"] = [e.to_json() for e in self.environments]
        if self.env_cells:
            d["env_cells"] = [c.to_json() for c in self.env_cells]
        if self.buildings:
            d["buildings"] = [b.to_json() for b in self.buildings]
        d["mover"] = self.mover.to_json(explicit_via=d["format"] in (FORMAT_V7, FORMAT))
        if self.others:
            d["others"] = [o.to_json() for o in self.others]
        if self.ticks is not None:
            d["ticks"] = self.ticks.to_json()
        if self.drawing:
            d["drawing"] = True
        if self.motion_queries:
            d["motion_queries"] = [q.to_json() for q in self.motion_queries]
        return d

    def dumps(self) -> str:
        return dumps(self.to_json())

    def replace(self, **changes) -> "Scene":
        return replace(self, **changes)

    @staticmethod
    def from_json(doc, path: str = "") -> "Scene":
        r = Reader(doc, path)
        fmt = doc.get("format") if isinstance(doc, dict) else None
        v1 = fmt == FORMAT_V1
        indoor = () if v1 else ("environments", "env_cells")
        ticks_field = ("ticks",) if fmt in (FORMAT_V4, FORMAT_V5, FORMAT_V6, FORMAT_V7, FORMAT) else ()
        buildings_field = ("buildings",) if fmt in (FORMAT_V5, FORMAT_V6, FORMAT_V7, FORMAT) else ()
        if fmt in (FORMAT_V1, FORMAT_V2, FORMAT_V3, FORMAT_V4, FORMAT_V5, FORMAT_V6, FORMAT_V7) and "others" in doc:
            r["others"].fail(f"other movers need format {FORMAT!r} (older formats have one mover)")
        if fmt in (FORMAT_V1, FORMAT_V2, FORMAT_V3, FORMAT_V4, FORMAT_V5, FORMAT_V6, FORMAT_V7) and "drawing" in doc:
            r["drawing"].fail(f"drawing needs format {FORMAT!r} (older formats have none)")
        if fmt in (FORMAT_V1, FORMAT_V2, FORMAT_V3) and "ticks" in doc:
            r["ticks"].fail(f"ticks need format {FORMAT_V4!r} or later (older formats have no ticks)")
        if fmt in (FORMAT_V1, FORMAT_V2, FORMAT_V3, FORMAT_V4) and "buildings" in doc:
            r["buildings"].fail(f"buildings need format {FORMAT_V5!r} or later (older formats have no buildings)")
        r.obj({"format", "name", "engine", "land_height_table", "landblocks", "objects", "mover", *indoor, *ticks_field,
               *buildings_field, *(("others", "drawing", "motion_queries") if fmt == FORMAT else ())})
        if fmt not in (FORMAT_V1, FORMAT_V2, FORMAT_V3, FORMAT_V4, FORMAT_V5, FORMAT_V6, FORMAT_V7):
            check_format(r, FORMAT)
        name = r["name"].str_() if r.given("name") else ""
        mode = "server"
        if r.given("engine"):
            e = r["engine"].obj({"mode"})
            if e.given("mode"):
                mode = e["mode"].str_()
                if mode not in ENGINE_MODES:
                    e["mode"].fail(f"unknown engine mode {mode!r} (known: server, client)")
        table = DEFAULT_LAND_HEIGHT_TABLE
        if r.given("land_height_table"):
            table = tuple(h.f32() for h in r["land_height_table"].list(count=256))
        landblocks = tuple(Landblock.from_json(lb, not v1) for lb in r["landblocks"].list(min_count=1))
        setups = fmt in (FORMAT_V7, FORMAT)
        objects = tuple(StaticObject.from_json(o, setups, fmt == FORMAT) for o in r["objects"].list()) if r.given("objects") else ()
        environments = env_cells = ()
        if r.given("environments"):
            environments = tuple(Environment.from_json(e) for e in r["environments"].list())
        if r.given("env_cells"):
            env_cells = tuple(EnvCell.from_json(c) for c in r["env_cells"].list())
        buildings = tuple(Building.from_json(b) for b in r["buildings"].list()) if r.given("buildings") else ()
        ticks = Ticks.from_json(r["ticks"], motion=fmt in (FORMAT_V6, FORMAT_V7, FORMAT), doors=fmt in (FORMAT_V7, FORMAT),
                                others=fmt == FORMAT) if r.has("ticks") else None
        mover = Mover.from_json(r["mover"], placement=fmt in (FORMAT_V3, FORMAT_V4, FORMAT_V5, FORMAT_V6, FORMAT_V7, FORMAT),
                                ticks=ticks is not None, vias=fmt in (FORMAT_V6, FORMAT_V7, FORMAT), skills=fmt == FORMAT,
                                children=fmt == FORMAT)
        others = tuple(OtherMover.from_json(o) for o in r["others"].list()) if fmt == FORMAT and r.given("others") else ()
        drawing = r["drawing"].bool_() if fmt == FORMAT and r.given("drawing") else False
        queries = tuple(MotionQuery.from_json(q) for q in r["motion_queries"].list(max_count=MAX_MOTION_QUERIES)) \
            if fmt == FORMAT and r.given("motion_queries") else ()
        if queries and ticks is None:
            r["motion_queries"].fail("motion queries need ticks (they are asked after the last tick)")
        for i, q in enumerate(queries):
            if q.function.startswith("Dat.") and mover.motion_table is None:
                r["motion_queries"][i]["function"].fail(
                    f"{q.function} reads the mover's MotionTable record: it needs the mover's motion_table (the "
                    "physics statics answer a MotionTableId of 0 themselves)")
        scene = Scene(landblocks, mover, objects, table, mode, name, environments, env_cells, ticks, buildings, others,
                      drawing, queries)
        check_consistency(scene, path)
        return scene

    @staticmethod
    def loads(text: str, source: str | None = None) -> "Scene":
        try:
            return Scene.from_json(parse_json_text(text, source))
        except InvalidScene as e:
            raise e.in_file(source) if source and not e.source else e


def check_format(r: Reader, expected: str) -> None:
    fmt = r["format"].str_()
    if fmt != expected:
        family, _, version = fmt.partition("/")
        want_family = expected.partition("/")[0]
        if family == want_family:
            r["format"].fail(f"unknown format version {version!r} (this acconform reads {expected})")
        r["format"].fail(f"expected format {expected!r}, got {fmt!r}")


def _p(base: str, rest: str) -> str:
    return f"{base}.{rest}" if base else rest


def check_consistency(scene: Scene, path: str = "") -> None:
    """The cross-field rules a single field's reader cannot see."""
    seen = {}
    for i, lb in enumerate(scene.landblocks):
        if lb.id in seen:
            raise InvalidScene(_p(path, f"landblocks[{i}].id"), f"landblock {lb.id:08X} is defined twice (also landblocks[{seen[lb.id]}])")
        seen[lb.id] = i
    defined = {lb.id >> 16 for lb in scene.landblocks}
    env_cells = _check_indoor(scene, path, defined)
    _check_buildings(scene, path, env_cells)
    if scene.ticks is not None:
        # a target is an outdoor static: ACE makes an EnvCell's statics itself when it loads the cell and
        # files none of them in ServerObjectManager (no WorldObject's set_object_guid)
        statics = {o.id for o in scene.objects if o.position.cell & 0xFFFF < ENV_CELL_FIRST}
        # or another mover that enters the world (feature objects.targets): its WorldObject's PhysicsObj is filed
        # under its id too (set_object_guid), and it moves, as the creature or player a server's MoveToObject chases
        movers = {o.id for o in scene.others if o.begin is not None and o.parent is None and o.launch is None}
        if movers:
            # or the mover itself (feature objects.targets): set_object_guid filed it too, and ACE's server aims at it
            # when a client names its own guid (Player_Melee's targeted attack: a swing's stick_to_object at itself; a
            # spell at its own wielded item: CreateTurnToChain2's TurnToObject at target.Wielder)
            from .staging import MOVER_ID

            movers.add(MOVER_ID)
        for i, step in enumerate(scene.ticks.steps):
            for name in MOTION_INPUTS:
                # but MoveToObject and TurnToObject, which make the MovementManager themselves when there is none
                # (a creature whose weenie has no MotionTableId), at another mover (feature objects.targets)
                if name in ("move_to_object", "turn_to_object") and movers:
                    continue
                if getattr(step, name) is not None and scene.mover.motion_table is None and (
                        name not in TABLELESS_INPUTS or name == "stop" and step.stop == "move_to_manager_cancel"):
                    raise InvalidScene(_p(path, f"ticks.steps[{i}].{name}"), "this motion input needs the mover's "
                                       "motion_table (the player's MotionTableId: without one it has no "
                                       "MovementManager; only motion, do_motion, stop_motion and the stops "
                                       "stop_completely and cancel_moveto are asked of a mover without one, and "
                                       "move_to_object and turn_to_object in a scene with other movers)")
            for name in ("move_to_object", "turn_to_object"):
                target = getattr(step, name)
                if target is not None and target.object not in statics and target.object not in movers:
                    raise InvalidScene(_p(path, f"ticks.steps[{i}].{name}.object"),
                                       f"no outdoor static object or other mover in the world has id "
                                       f"{write_id(target.object)} (the target is one of the scene's objects outside "
                                       "EnvCells, or one of its others with a begin, or the mover, named by its id)")
            if step.stick_to is not None and step.stick_to not in statics and step.stick_to not in movers:
                raise InvalidScene(_p(path, f"ticks.steps[{i}].stick_to"),
                                   f"no outdoor static object or other mover in the world has id {write_id(step.stick_to)} "
                                   "(the melee swing's target, or the mover, named by its id)")
            if step.door is not None and step.door.object not in statics:
                raise InvalidScene(_p(path, f"ticks.steps[{i}].door.object"),
                                   f"no outdoor static object has id {write_id(step.door.object)} (the door is one of "
                                   "the scene's objects outside EnvCells, named by its id: ACE makes an EnvCell's "
                                   "statics itself, with no WorldObject to open)")

    def check_landblock(where: str, cell: int) -> None:
        if cell >> 16 not in defined:
            raise InvalidScene(where, f"landblock {cell >> 16:04X} of cell {cell:08X} is not defined in landblocks "
                                      f"(defined: {', '.join(f'{b:04X}' for b in sorted(defined))})")

    begin = _p(path, "mover.begin.cell")
    if scene.mover.placement is None:
        _check_cell_id(begin, scene.mover.begin.cell)
        check_landblock(begin, scene.mover.begin.cell)
        _check_defined(begin, scene.mover.begin.cell, env_cells, "the mover starts in it (CurCell = LScape.get_landcell)")
    else:
        # any cell id in a defined landblock: AdjustPosition judges it (ACE's answer for a cell it cannot use)
        check_landblock(begin, scene.mover.begin.cell)
    if scene.mover.contact_plane is not None:
        where = _p(path, "mover.contact_plane.cell")
        _check_cell_id(where, scene.mover.contact_plane.cell)
        check_landblock(where, scene.mover.contact_plane.cell)
    if scene.ticks is None:
        end = _p(path, "mover.end.cell")
        if scene.mover.end is None:
            raise InvalidScene(end[:-len(".cell")], "missing: a scene without ticks moves the mover from begin to end "
                                                    "(only a tick scene's mover has no end)")
        _check_cell_id(end, scene.mover.end.cell)
        if scene.mover.end.cell & 0xFFFF >= ENV_CELL_FIRST:  # an outdoor end may lie in a landblock not listed (ACE's verdict)
            check_landblock(end, scene.mover.end.cell)
    else:
        _check_ticks(scene, path, check_landblock, env_cells)
    _check_others(scene, path, check_landblock, env_cells)
    ids = set()
    for i, o in enumerate(scene.objects):
        where = _p(path, f"objects[{i}]")
        if o.id in ids:
            raise InvalidScene(f"{where}.id", f"object id {o.id:08X} is used twice")
        ids.add(o.id)
        cell = o.position.cell
        _check_cell_id(f"{where}.position.cell", cell)
        check_landblock(f"{where}.position.cell", cell)
        if cell & 0xFFFF >= ENV_CELL_FIRST:
            _check_defined(f"{where}.position.cell", cell, env_cells, "its stab is in that EnvCell's DAT record")
            if o.state != int(PhysicsState.Static):
                raise InvalidScene(f"{where}.state", "a static in an EnvCell is a DAT stab: ACE's "
                                   "EnvCell.init_static_objects sets no state (omit it, or give [\"Static\"])")
            if o.scale != 1.0:
                raise InvalidScene(f"{where}.scale", f"a static in an EnvCell is a DAT stab: ACE's "
                                   f"EnvCell.init_static_objects sets no scale (omit it, or give 1), got {o.scale}")


def _check_others(scene: Scene, path: str, check_landblock, env_cells: dict) -> None:
    """Each other mover's id is its own (not the mover's, another's or a static's: ServerObjectManager files
    every object by its id), it begins in a cell the scene defines, and each tick's inputs name other movers,
    each once per step; a jump is a player's (Player.HandleActionJump)."""
    from .staging import MOVER_ID

    taken = {MOVER_ID: "the mover's", **{o.id: f"objects[{i}]'s" for i, o in enumerate(scene.objects)}}
    by_id = {}
    for i, o in enumerate(scene.others):
        where = _p(path, f"others[{i}]")
        if o.id in taken:
            raise InvalidScene(f"{where}.id", f"id 0x{o.id:08X} is already {taken[o.id]} (ServerObjectManager files every "
                                              "object by its id)")
        taken[o.id] = f"others[{i}]'s"
        by_id[o.id] = o
        if o.motion_table and scene.mover.motion_table is None:
            raise InvalidScene(f"{where}.motion_table", "its motion table is the scene's (the mover's motion_table), "
                                                        "and the mover has none")
        if o.parent is not None:
            # the parent is in the world (or held) when the child is parented: the mover, or an other made before it;
            # a location its Setup lacks is ACE's answer (set_parent refuses it), not the scene's error
            if o.parent.id != MOVER_ID and o.parent.id not in by_id or o.parent.id == o.id:
                earlier = ", ".join(f"0x{x.id:08X}" for x in scene.others[:i])
                raise InvalidScene(f"{where}.parent.id", f"no mover before it has id 0x{o.parent.id:08X} (a child's parent "
                                                         f"is the mover 0x{MOVER_ID:08X} or an earlier other: "
                                                         f"{earlier or 'none'})")
            continue
        cell = o.begin.cell
        _check_cell_id(f"{where}.begin.cell", cell)
        check_landblock(f"{where}.begin.cell", cell)
        _check_defined(f"{where}.begin.cell", cell, env_cells, "it enters the world there (LScape.get_landcell)")
    _check_launches(scene, path, by_id)
    if scene.ticks is None:
        return
    destroyed = {}  # id -> the step that destroyed it
    # every object that holds or is held in the scene, at the start or by a tick's `parent` input
    parenting = {o.id for o in scene.others if o.parent is not None} | {o.parent.id for o in scene.others if o.parent is not None}
    parenting |= {x for step in scene.ticks.steps for inputs in step.others if inputs.parent is not None
                  for x in (inputs.id, inputs.parent.id)}
    for i, step in enumerate(scene.ticks.steps):
        seen = set()
        for k, inputs in enumerate(step.others):
            where = _p(path, f"ticks.steps[{i}].others[{k}]")
            other = by_id.get(inputs.id)
            if other is None:
                raise InvalidScene(f"{where}.id", f"no other mover has id 0x{inputs.id:08X} (the scene's others: "
                                                  f"{', '.join(f'0x{o.id:08X}' for o in scene.others) or 'none'})")
            if other.weenie in PROJECTILE_WEENIES:
                raise InvalidScene(f"{where}.id", f"other mover 0x{inputs.id:08X} is a projectile: its launch and ACE's "
                                                  "flight move it, no input does")
            if inputs.id in seen:
                raise InvalidScene(f"{where}.id", f"other mover 0x{inputs.id:08X} is given inputs twice in one step")
            seen.add(inputs.id)
            if inputs.jump is not None and other.weenie != "player":
                raise InvalidScene(f"{where}.jump", f"a jump is a player's (Player.HandleActionJump); other mover "
                                                    f"0x{inputs.id:08X} is a {other.weenie}")
            if inputs.execute_motion is not None and other.begin is None:
                raise InvalidScene(f"{where}.execute_motion", f"other mover 0x{inputs.id:08X} is a child: a wielded item "
                                                              "is in no landblock, and no server code moves it")
            if inputs.execute_motion is not None and other.setup is not None and not other.setup.parts:
                raise InvalidScene(f"{where}.execute_motion", f"other mover 0x{inputs.id:08X} has a Setup of no parts: "
                                                              "its enter_world fails, and WorldObject.AddPhysicsObj then "
                                                              "destroys its PhysicsObj (null), which ExecuteMotion skips")
            if inputs.id in destroyed:
                raise InvalidScene(f"{where}.id", f"other mover 0x{inputs.id:08X} was destroyed at step "
                                                  f"{destroyed[inputs.id]}: it takes no input after")
            if inputs.destroy:
                if other.begin is None or inputs.id in parenting:
                    raise InvalidScene(f"{where}.destroy", f"other mover 0x{inputs.id:08X} is a child or holds one: "
                                                           "only a mover that entered the world alone is destroyed")
                destroyed[inputs.id] = i
            if inputs.parent is not None:
                _check_reparent(scene, f"{where}.parent.id", inputs.id, inputs.parent.id, by_id)


def _check_reparent(scene: Scene, where: str, child: int, parent: int, by_id: dict) -> None:
    """A tick's `parent` input names the mover or another other, and no object both holds and is held in one scene
    (a child held by its own child would carry itself: UpdateChild without end): the objects held (a child, or the
    target of a `parent` input) and the holders (the parents named) are apart."""
    from .staging import MOVER_ID

    if parent != MOVER_ID and parent not in by_id or parent == child:
        raise InvalidScene(where, f"no other mover but 0x{child:08X} has id 0x{parent:08X} (a holder is the mover "
                                  f"0x{MOVER_ID:08X} or another other)")
    held = {o.id for o in scene.others if o.parent is not None}
    holders = {o.parent.id for o in scene.others if o.parent is not None}
    for step in scene.ticks.steps:
        for inputs in step.others:
            if inputs.parent is not None:
                held.add(inputs.id)
                holders.add(inputs.parent.id)
    if held & holders:
        both = ", ".join(f"0x{x:08X}" for x in sorted(held & holders))
        raise InvalidScene(where, f"{both} would both hold and be held (a holder is never held in a scene)")


def _check_launches(scene: Scene, path: str, by_id: dict) -> None:
    """Each projectile's launch: in a tick scene on a server engine, at one of its steps, from the mover or another
    mover that is no projectile, at the mover, such another mover or an outdoor static (the facade holds a
    PhysicsObj for those only)."""
    from .staging import MOVER_ID

    statics = {o.id: o for o in scene.objects}
    for i, o in enumerate(scene.others):
        if o.launch is None:
            continue
        where = _p(path, f"others[{i}].launch")
        launch = o.launch
        if scene.ticks is None:
            raise InvalidScene(f"{where}.tick", "a launch happens at a tick: the scene needs ticks")
        if scene.engine_mode != "server":
            raise InvalidScene(_p(path, "engine.mode"), "a projectile joins a server landblock (Landblock.AddWorldObject): "
                                                        "the engine mode must be server")
        if not launch.tick < len(scene.ticks.steps):
            raise InvalidScene(f"{where}.tick", f"the scene has {len(scene.ticks.steps)} steps (0..{len(scene.ticks.steps) - 1}), "
                                                f"got {launch.tick}")

        def mover(key, value, what):
            if value == MOVER_ID:
                return
            other = by_id.get(value)
            if other is not None and other.weenie not in PROJECTILE_WEENIES:
                return
            if other is not None:
                raise InvalidScene(f"{where}.{key}", f"0x{value:08X} is a projectile; {what}")
            static = statics.get(value) if key == "target" else None
            if static is not None:
                if static.position.cell & 0xFFFF >= ENV_CELL_FIRST:
                    raise InvalidScene(f"{where}.{key}", f"static 0x{value:08X} is in an EnvCell (a DAT stab, which the "
                                                         "oracle's facade holds no PhysicsObj of): aim at an outdoor static")
                return
            raise InvalidScene(f"{where}.{key}", f"no mover{' or static' if key == 'target' else ''} has id 0x{value:08X}; {what}")

        mover("launcher", launch.launcher, "the launcher is the mover (0x50000001) or another mover that is no projectile")
        if launch.target is None:  # an untargeted spell (Launch.from_json refuses an arrow without one)
            continue
        mover("target", launch.target, "the target is the mover, another mover that is no projectile, or an outdoor static")
        if launch.launcher == launch.target:
            raise InvalidScene(f"{where}.target", f"the launcher 0x{launch.launcher:08X} cannot be its own target")


def _check_ticks(scene: Scene, path: str, check_landblock, env_cells: dict) -> None:
    """Each RequestPos of a tick scene names a cell the scene defines, or no cell of a defined landblock (feature
    ticks.no_cell_requests: a low word of 0x0000 or 0x0041..0x00FF, which Player.ValidateMovement lets through in the
    player's landblock and LScape.get_landcell answers null for)."""
    if scene.mover.end is not None:
        raise InvalidScene(_p(path, "mover.end"), "a tick scene's mover has no end: its ticks move it (omit end)")
    for i, step in enumerate(scene.ticks.steps):
        if step.request_pos is None:
            continue
        where = _p(path, f"ticks.steps[{i}].request_pos.cell")
        cell = step.request_pos.cell
        if cell & 0xFFFF == 0 or 0x41 <= cell & 0xFFFF <= 0xFF:
            check_landblock(where, cell)
            continue  # a RequestPos into no cell (feature ticks.no_cell_requests): get_landcell answers null
        _check_cell_id(where, cell)
        check_landblock(where, cell)
        _check_defined(where, cell, env_cells, "set_current_pos moves the mover into it (LScape.get_landcell)")


def _check_indoor(scene: Scene, path: str, defined: set[int]) -> dict[int, EnvCell]:
    """Environments and EnvCells: ids, the structure each cell names, portals; per landblock the
    EnvCells are numbered from 0x0100 without gaps (LandblockInfo.NumCells counts them, and ACE's
    AdjustCell loads 0x0100 .. 0x0100 + NumCells - 1). Returns the EnvCells by id."""
    envs: dict[int, Environment] = {}
    for i, env in enumerate(scene.environments):
        if env.id in envs:
            raise InvalidScene(_p(path, f"environments[{i}].id"), f"Environment {env.id:08X} is defined twice")
        envs[env.id] = env
    cells: dict[int, EnvCell] = {}
    for i, c in enumerate(scene.env_cells):
        where = _p(path, f"env_cells[{i}]")
        if c.id in cells:
            raise InvalidScene(f"{where}.id", f"EnvCell {c.id:08X} is defined twice")
        cells[c.id] = c
        if c.id >> 16 not in defined:
            raise InvalidScene(f"{where}.id", f"landblock {c.id >> 16:04X} of EnvCell {c.id:08X} is not defined in landblocks")
        env = envs.get(c.environment)
        if env is None:
            raise InvalidScene(f"{where}.environment", f"Environment {c.environment:08X} is not defined in environments")
        if c.cell_structure >= len(env.cell_structs):
            continue  # scene/8 (Scene.has_missing_keys): ACE's EnvCell finds no CellStruct and leaves CellStructure null
        struct = env.cell_structs[c.cell_structure]
        for k, portal in enumerate(c.portals):
            if portal.polygon >= len(struct.polygons):
                continue  # scene/8: CellStructure.Polygons[PolygonId] throws KeyNotFoundException where it is read
            if portal.polygon not in struct.portals:
                raise InvalidScene(f"{where}.portals[{k}].polygon", f"polygon {portal.polygon} is not one of the cell "
                                                                    f"structure's portals {list(struct.portals)}")
    by_block: dict[int, list[int]] = {}
    for c in scene.env_cells:
        by_block.setdefault(c.id >> 16, []).append(c.id & 0xFFFF)
    for block, lows in by_block.items():
        want = set(range(ENV_CELL_FIRST, ENV_CELL_FIRST + len(lows)))
        if set(lows) != want:
            gap = min(want - set(lows))
            i = next(i for i, c in enumerate(scene.env_cells) if c.id >> 16 == block and c.id & 0xFFFF not in want)
            raise InvalidScene(_p(path, f"env_cells[{i}].id"),
                               f"landblock {block:04X}'s EnvCells are numbered from 0x{ENV_CELL_FIRST:04X} without gaps "
                               f"(LandblockInfo.NumCells counts them): 0x{gap:04X} is missing")
    return cells


def _check_buildings(scene: Scene, path: str, env_cells: dict[int, EnvCell]) -> None:
    """A building stands on a landblock with terrain (its LandblockInfo is read because the
    landblock's CellLandblock says HasObjects); each portal leads into an EnvCell of that landblock
    the scene defines, names one of that cell's portals (or 0xFFFF, none), and its stab list names
    EnvCells of that landblock the scene defines."""
    by_id = {lb.id: lb for lb in scene.landblocks}
    with_buildings = {b.landblock for b in scene.buildings}
    for i, lb in enumerate(scene.landblocks):
        if lb.restrictions and lb.id not in with_buildings:
            raise InvalidScene(_p(path, f"landblocks[{i}].restrictions"),
                               f"landblock {lb.id:08X} has no buildings: ACE reads its LandblockInfo (and so the "
                               f"restriction table) only for a landblock whose CellLandblock has HasObjects")
    for i, b in enumerate(scene.buildings):
        where = _p(path, f"buildings[{i}]")
        lb = by_id.get(b.landblock)
        if lb is None:
            raise InvalidScene(f"{where}.landblock", f"landblock {b.landblock:08X} is not defined in landblocks")
        if not lb.has_terrain:
            raise InvalidScene(f"{where}.landblock", f"landblock {b.landblock:08X} has no terrain: a building stands "
                                                     f"in one of its outdoor cells (give it heights and terrain)")
        block = b.landblock & 0xFFFF0000
        for k, portal in enumerate(b.portals):
            if portal.other_cell <= OUTDOOR_WORD_LAST:
                continue  # scene/8: no EnvCell (OUTDOOR_WORD_LAST)
            cell = env_cells.get(block | portal.other_cell)
            if cell is None:
                raise InvalidScene(f"{where}.portals[{k}].other_cell",
                                   f"EnvCell {block | portal.other_cell:08X} is not defined in env_cells (a building's "
                                   f"portal leads into an EnvCell of its own landblock)")
            if portal.other_portal != 0xFFFF and portal.other_portal >= len(cell.portals):
                raise InvalidScene(f"{where}.portals[{k}].other_portal",
                                   f"EnvCell {cell.id:08X} has {len(cell.portals)} portals, got {portal.other_portal} "
                                   f"(0xFFFF names none)")
            for m, stab in enumerate(portal.stab_list):
                if block | stab not in env_cells:
                    raise InvalidScene(f"{where}.portals[{k}].stab_list[{m}]",
                                       f"EnvCell {block | stab:08X} is not defined in env_cells")


def _check_defined(path: str, cell: int, env_cells: dict, why: str) -> None:
    if cell & 0xFFFF >= ENV_CELL_FIRST and cell not in env_cells:
        raise InvalidScene(path, f"EnvCell {cell:08X} is not defined in env_cells ({why})")


def _check_cell_id(path: str, cell: int) -> None:
    low = cell & 0xFFFF
    if not (1 <= low <= 64 or ENV_CELL_FIRST <= low <= ENV_CELL_LAST):
        raise InvalidScene(path, f"cell {cell:08X} is neither an outdoor land cell (low word 0x0001..0x0040) nor an "
                                 f"EnvCell (0x{ENV_CELL_FIRST:04X}..0x{ENV_CELL_LAST:04X})")


def validate_scene(scene: Scene) -> Scene:
    """Check a scene built in code by the same rules as one read from JSON (round trip)."""
    return Scene.from_json(scene.to_json())
