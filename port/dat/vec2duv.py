"""Vec2Duv: Unpack -- a vertex's texture coordinates (ACE.DatLoader Entity/Vec2Duv.cs)."""

from __future__ import annotations

from dataclasses import dataclass

from ..anchors import anchor


@dataclass(slots=True)
class Vec2Duv:
    u: object = None
    v: object = None

    @staticmethod
    @anchor(None, "ACE.DatLoader/Entity/Vec2Duv.cs:Unpack")
    def unpack(reader) -> "Vec2Duv":
        t = Vec2Duv()
        t.u = reader.read_single()
        t.v = reader.read_single()
        return t
