"""Plane: Unpack, ToNumerics -- a BSP node's splitting plane as DatLoader reads it (ACE.DatLoader Entity/Plane.cs)."""

from __future__ import annotations

from dataclasses import dataclass

from acconform.numerics import Plane as NumericsPlane, Vector3

from ..anchors import anchor


@dataclass(slots=True)
class Plane:
    n: Vector3 | None = None
    d: object = None

    @staticmethod
    @anchor(None, "ACE.DatLoader/Entity/Plane.cs:Unpack")
    def unpack(reader) -> "Plane":
        p = Plane()
        p.n = reader.read_vector3()
        p.d = reader.read_single()
        return p

    @anchor(None, "ACE.DatLoader/Entity/Plane.cs:ToNumerics")
    def to_numerics(self) -> NumericsPlane:
        return NumericsPlane(self.n, self.d)
