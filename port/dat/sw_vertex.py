"""SWVertex: Unpack -- a vertex's origin, normal and UVs (ACE.DatLoader Entity/SWVertex.cs)."""

from __future__ import annotations

from dataclasses import dataclass, field

from acconform.numerics import Vector3

from ..anchors import anchor
from .unpackable_extensions import unpack_list_fixed
from .vec2duv import Vec2Duv


@dataclass(slots=True)
class SWVertex:
    origin: Vector3 | None = None
    normal: Vector3 | None = None
    uvs: list = field(default_factory=list)

    @staticmethod
    @anchor(None, "ACE.DatLoader/Entity/SWVertex.cs:Unpack")
    def unpack(reader) -> "SWVertex":
        v = SWVertex()
        num_uvs = reader.read_uint16()
        v.origin = reader.read_vector3()
        v.normal = reader.read_vector3()
        v.uvs = unpack_list_fixed(reader, Vec2Duv.unpack, num_uvs)
        return v
