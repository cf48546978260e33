"""Polygon: Unpack -- a GfxObj polygon as DatLoader reads it: vertex ids, sides, surfaces, UV indices (ACE.DatLoader Entity/Polygon.cs)."""

from __future__ import annotations

from dataclasses import dataclass, field

from acconform.flags import CullMode

from ..anchors import anchor

# ACE.Entity.Enum.StipplingType
STIPPLING_NO_POS = 0x4
STIPPLING_NO_NEG = 0x8


@dataclass(slots=True)
class Polygon:
    num_pts: int = 0
    stippling: int = 0
    sides_type: int = 0
    pos_surface: int = 0
    neg_surface: int = 0
    vertex_ids: list = field(default_factory=list)  # short
    pos_uv_indices: list = field(default_factory=list)
    neg_uv_indices: list = field(default_factory=list)

    @staticmethod
    @anchor(None, "ACE.DatLoader/Entity/Polygon.cs:Unpack")
    def unpack(reader) -> "Polygon":
        p = Polygon()
        p.num_pts = reader.read_byte()
        p.stippling = reader.read_byte()
        p.sides_type = reader.read_int32()
        p.pos_surface = reader.read_int16()
        p.neg_surface = reader.read_int16()

        for _ in range(p.num_pts):
            p.vertex_ids.append(reader.read_int16())

        if not p.stippling & STIPPLING_NO_POS:
            for _ in range(p.num_pts):
                p.pos_uv_indices.append(reader.read_byte())

        if p.sides_type == CullMode.Clockwise and not p.stippling & STIPPLING_NO_NEG:
            for _ in range(p.num_pts):
                p.neg_uv_indices.append(reader.read_byte())

        if p.sides_type == CullMode.None_:
            p.neg_surface = p.pos_surface
            p.neg_uv_indices = p.pos_uv_indices
        return p
