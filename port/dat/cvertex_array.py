"""CVertexArray: Unpack -- a GfxObj's vertices by ushort id (ACE.DatLoader Entity/CVertexArray.cs)."""

from __future__ import annotations

from dataclasses import dataclass, field

from ..anchors import anchor
from ..errors import NotImplementedException
from .sw_vertex import SWVertex
from .unpackable_extensions import unpack_ushort_dict_fixed


@dataclass(slots=True)
class CVertexArray:
    vertex_type: int = 0
    vertices: dict = field(default_factory=dict)  # ushort -> SWVertex, in DAT order

    @staticmethod
    @anchor(None, "ACE.DatLoader/Entity/CVertexArray.cs:Unpack")
    def unpack(reader) -> "CVertexArray":
        a = CVertexArray()
        a.vertex_type = reader.read_int32()
        num_vertices = reader.read_uint32()
        if a.vertex_type == 1:
            a.vertices = unpack_ushort_dict_fixed(reader, SWVertex.unpack, num_vertices)
        else:
            raise NotImplementedException("The method or operation is not implemented.")
        return a
