"""CellStruct: CellStruct(DatLoader CellStruct), box_intersects_cell, sphere_intersects_cell, point_in_cell.

ACE's Common/CellStruct.cs: an EnvCell's geometry, built from the Environment's DAT cell
structure. Polygons and physics polygons are built per id (PolygonCache is off: a new Polygon
each), the portals are the polygons the DAT portal ids name, and the three trees are built by
BSPCache.Get (off: a new BSPTree each): the cell tree (over the physics polygons, though its
nodes name none), the drawing tree (over the polygons, when the DAT has one) and the physics tree.
The cell tree answers the three containment questions in the cell's local frame. Not ported:
ACE's empty constructor and get_portal, which nothing in ACE calls.

Across runs the port remembers the CellStruct built from a structure of an Environment record's
exact bytes (`remembered`, keyed by the bytes, the structure's id and the mode): building the
polygons' planes and the trees is about 40% of an indoor run. The answer cannot change:
CellStruct(DatLoader CellStruct) is a function of those bytes, and nothing after construction
writes to a CellStruct, its polygons, vertices or BSP nodes (sharing one between cells is
unobservable: nothing compares polygons or nodes by identity). A record the run does not hold is
never remembered. The drawing tree, which ACE builds and its physics never reads, is built when
first read (a tenth of an indoor run's building); what would throw building it throws at once.
Within a run two EnvCells of one structure share the CellStruct, where ACE builds one each; a
traced run builds one each (anchors.remembers), so its trace holds every construction's records.
"""

from __future__ import annotations

from acconform.numerics import Mode

from ..anchors import anchor, harness, remembers
from ..errors import KeyNotFoundException
from ..geom.bsp import BoundingType, BSPTree
from ..geom.polygon import Polygon


BUILT_LIMIT = 256  # remembered CellStructs before the memory forgets them all
BUILT: dict[tuple, "CellStruct"] = {}


class CellStruct:
    __slots__ = ("cell_struct_id", "vertex_array", "polygons", "physics_polygons", "portals",
                 "drawing_bsp", "physics_bsp", "cell_bsp", "_drawing")

    @classmethod
    @anchor("CCellStruct::UnPack", "CellStruct.cs:CellStruct(DatLoader.Entity.CellStruct)", "the DAT constructor")
    def from_dat(cls, cell_struct, mode: Mode) -> "CellStruct":
        """`mode` types the default splitting plane of a DAT leaf at a tree's root (BSPTree.from_dat).
        ACE's only constructor of a CellStruct (the empty one, EnvCell.Init's, is called nowhere)."""
        c = cls.__new__(cls)
        c.cell_struct_id = 0  # never set: C#'s defaults
        c.vertex_array = None
        c.drawing_bsp = None
        c.physics_bsp = None
        c.cell_bsp = None
        c.polygons = {}
        for key, value in cell_struct.polygons.items():
            c.polygons[key] = Polygon.from_dat(value, cell_struct.vertex_array)  # PolygonCache is off

        c.portals = []
        for portal in cell_struct.portals:
            polygon = c.polygons.get(portal)
            if polygon is None:
                raise KeyNotFoundException(f"The given key '{portal}' was not present in the dictionary.")
            c.portals.append(polygon)

        c.physics_polygons = {}
        for key, value in cell_struct.physics_polygons.items():
            c.physics_polygons[key] = Polygon.from_dat(value, cell_struct.vertex_array)

        if cell_struct.cell_bsp is not None:
            c.cell_bsp = BSPTree.from_dat(cell_struct.cell_bsp, cell_struct.physics_polygons, cell_struct.vertex_array, mode)

        c._drawing = None
        if cell_struct.drawing_bsp is not None:
            # BSPTree.from_dat(...), run when drawing_bsp is first read (`__getattr__`): the physics never
            # reads it. What could throw while building it throws here, as ACE's build would: a
            # polygon id the polygons lack (its polygons' vertices were found building c.polygons).
            _check_polygon_ids(cell_struct.drawing_bsp.root_node, cell_struct.polygons)
            c._drawing = (cell_struct.drawing_bsp, cell_struct.polygons, cell_struct.vertex_array, mode)
            del c.drawing_bsp
        if cell_struct.physics_bsp is not None:
            c.physics_bsp = BSPTree.from_dat(cell_struct.physics_bsp, cell_struct.physics_polygons,
                                             cell_struct.vertex_array, mode)
        return c

    def __getattr__(self, name: str):
        # an unset slot: only `drawing_bsp` is ever left unset (from_dat), until it is first read
        if name != "drawing_bsp" or self._drawing is None:
            raise AttributeError(f"'CellStruct' object has no attribute {name!r}")
        self.drawing_bsp = BSPTree.from_dat(*self._drawing)
        return self.drawing_bsp

    @anchor("CCellStruct::box_intersects_cell", "CellStruct.cs:box_intersects_cell")
    def box_intersects_cell(self, bbox) -> bool:
        return self.cell_bsp.box_intersects_cell_bsp(bbox)

    @anchor("CCellStruct::sphere_intersects_cell", "CellStruct.cs:sphere_intersects_cell")
    def sphere_intersects_cell(self, sphere) -> BoundingType:
        return self.cell_bsp.sphere_intersects_cell_bsp(sphere)

    @anchor("CCellStruct::point_in_cell", "CellStruct.cs:point_in_cell")
    def point_in_cell(self, point) -> bool:
        return self.cell_bsp.point_inside_cell_bsp(point)


def _check_polygon_ids(root, polys: dict) -> None:
    """KeyNotFoundException for the first node (in BSPNode.from_dat's order: node, front, back)
    naming a polygon id `polys` lacks, as BSPNode.from_dat raises it."""
    stack = [root]
    while stack:
        node = stack.pop()
        for poly in node.in_polys or ():
            if poly not in polys:
                raise KeyNotFoundException(f"The given key '{poly}' was not present in the dictionary.")
        stack.extend(child for child in (node.neg_node, node.pos_node) if child is not None)


def _built_every_time(portal_dat, environment_id: int, cell_structure_id: int, cell_struct) -> CellStruct:
    """``new CellStruct(cellStruct)``, nothing remembered (what a traced run runs)."""
    return CellStruct.from_dat(cell_struct, portal_dat.mode)


@harness("CellStruct(DatLoader CellStruct) for an Environment's structure, remembered across runs by the record's bytes")
@remembers(_built_every_time)
def remembered(portal_dat, environment_id: int, cell_structure_id: int, cell_struct) -> CellStruct:
    """``new CellStruct(cellStruct)`` for structure `cell_structure_id` of the Environment record
    `environment_id` of the run's portal DAT (see the module docstring)."""
    data = portal_dat.records.get(environment_id)
    key = (data, cell_structure_id, portal_dat.mode) if data is not None else None
    built = BUILT.get(key) if key is not None else None
    if built is None:
        built = CellStruct.from_dat(cell_struct, portal_dat.mode)
        if key is not None:
            if len(BUILT) >= BUILT_LIMIT:
                BUILT.clear()
            BUILT[key] = built
    return built


@harness("empties the CellStructs remembered across runs")
def clear_built() -> None:
    BUILT.clear()
