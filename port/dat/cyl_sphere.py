"""CylSphere: Unpack -- a Setup's cylinder sphere as DatLoader reads it (ACE.DatLoader Entity/CylSphere.cs)."""

from __future__ import annotations

from dataclasses import dataclass

from acconform.numerics import Vector3

from ..anchors import anchor


@dataclass(slots=True)
class CylSphere:
    origin: Vector3 | None = None
    radius: object = None
    height: object = None

    @staticmethod
    @anchor(None, "ACE.DatLoader/Entity/CylSphere.cs:Unpack")
    def unpack(reader) -> "CylSphere":
        c = CylSphere()
        x = reader.read_single()
        y = reader.read_single()
        z = reader.read_single()
        c.origin = Vector3(x, y, z)
        c.radius = reader.read_single()
        c.height = reader.read_single()
        return c
