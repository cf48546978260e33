"""GfxObj: Unpack -- a 0x01 GfxObj record: vertices, physics polygons and BSP, sort center, drawing polygons and BSP (ACE.DatLoader FileTypes/GfxObj.cs)."""

from __future__ import annotations

from dataclasses import dataclass, field

from acconform.numerics import Vector3

from ..anchors import anchor
from .bsp_node import BSP_TYPE_DRAWING, BSP_TYPE_PHYSICS
from .bsp_tree import BSPTree
from .cvertex_array import CVertexArray
from .polygon import Polygon
from .unpackable_extensions import unpack_smart_array_uint, unpack_smart_array_ushort_dict

# ACE.Entity.Enum.GfxObjFlags
GFX_OBJ_HAS_PHYSICS = 0x1
GFX_OBJ_HAS_DRAWING = 0x2
GFX_OBJ_HAS_DID_DEGRADE = 0x8


@dataclass(slots=True, eq=False)
class GfxObj:
    id: int = 0
    flags: int = 0
    surfaces: list = field(default_factory=list)
    vertex_array: CVertexArray = field(default_factory=CVertexArray)
    physics_polygons: dict = field(default_factory=dict)  # ushort -> Polygon
    physics_bsp: BSPTree = field(default_factory=BSPTree)
    sort_center: Vector3 | None = None
    polygons: dict = field(default_factory=dict)
    drawing_bsp: BSPTree = field(default_factory=BSPTree)
    did_degrade: int = 0

    @staticmethod
    @anchor(None, "ACE.DatLoader/FileTypes/GfxObj.cs:Unpack")
    def unpack(reader) -> "GfxObj":
        g = GfxObj()
        g.id = reader.read_uint32()
        g.flags = reader.read_uint32()

        g.surfaces = unpack_smart_array_uint(reader)

        g.vertex_array = CVertexArray.unpack(reader)

        if g.flags & GFX_OBJ_HAS_PHYSICS:
            g.physics_polygons = unpack_smart_array_ushort_dict(reader, Polygon.unpack)
            g.physics_bsp.unpack(reader, BSP_TYPE_PHYSICS)

        g.sort_center = reader.read_vector3()

        if g.flags & GFX_OBJ_HAS_DRAWING:
            g.polygons = unpack_smart_array_ushort_dict(reader, Polygon.unpack)
            g.drawing_bsp.unpack(reader, BSP_TYPE_DRAWING)

        if g.flags & GFX_OBJ_HAS_DID_DEGRADE:
            g.did_degrade = reader.read_uint32()
        return g
