"""CellStruct: Unpack -- one cell structure of an Environment: vertices, polygons, portal polygon ids, the cell, physics and drawing BSP trees (ACE.DatLoader Entity/CellStruct.cs).

The counts of polygons, physics polygons and portals come first; the polygons follow the
vertices as a fixed-count ushort dictionary; the reader aligns to a DWORD after the portal ids
and again at the end. The cell tree is read as BSPType.Cell (planes and children only), the
physics tree as BSPType.Physics, the drawing tree (when the flag before it is non-zero) as
BSPType.Drawing.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ..anchors import anchor
from .bsp_node import BSP_TYPE_CELL, BSP_TYPE_DRAWING, BSP_TYPE_PHYSICS
from .bsp_tree import BSPTree
from .cvertex_array import CVertexArray
from .polygon import Polygon
from .unpackable_extensions import unpack_ushort_dict_fixed


@dataclass(slots=True, eq=False)
class CellStruct:
    vertex_array: CVertexArray = field(default_factory=CVertexArray)
    polygons: dict = field(default_factory=dict)  # ushort -> Polygon
    portals: list = field(default_factory=list)  # ushort polygon ids
    cell_bsp: BSPTree = field(default_factory=BSPTree)
    physics_polygons: dict = field(default_factory=dict)  # ushort -> Polygon
    physics_bsp: BSPTree = field(default_factory=BSPTree)
    drawing_bsp: BSPTree | None = None

    @staticmethod
    @anchor(None, "ACE.DatLoader/Entity/CellStruct.cs:Unpack")
    def unpack(reader) -> "CellStruct":
        c = CellStruct()
        num_polygons = reader.read_uint32()
        num_physics_polygons = reader.read_uint32()
        num_portals = reader.read_uint32()

        c.vertex_array = CVertexArray.unpack(reader)

        c.polygons = unpack_ushort_dict_fixed(reader, Polygon.unpack, num_polygons)

        for _ in range(num_portals):
            c.portals.append(reader.read_uint16())

        reader.align_boundary()

        c.cell_bsp.unpack(reader, BSP_TYPE_CELL)

        c.physics_polygons = unpack_ushort_dict_fixed(reader, Polygon.unpack, num_physics_polygons)

        c.physics_bsp.unpack(reader, BSP_TYPE_PHYSICS)

        has_drawing_bsp = reader.read_uint32()
        if has_drawing_bsp != 0:
            c.drawing_bsp = BSPTree()
            c.drawing_bsp.unpack(reader, BSP_TYPE_DRAWING)

        reader.align_boundary()
        return c
