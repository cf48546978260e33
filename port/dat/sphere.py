"""Sphere: Unpack, CreateDummySphere -- a bounding sphere as DatLoader reads it (ACE.DatLoader Entity/Sphere.cs)."""

from __future__ import annotations

from dataclasses import dataclass

from acconform.numerics import Vector3

from ..anchors import anchor


@dataclass(slots=True)
class Sphere:
    origin: Vector3 | None = None
    radius: object = None

    @staticmethod
    @anchor(None, "ACE.DatLoader/Entity/Sphere.cs:Unpack")
    def unpack(reader) -> "Sphere":
        s = Sphere()
        s.origin = reader.read_vector3()
        s.radius = reader.read_single()
        return s

    @staticmethod
    @anchor(None, "ACE.DatLoader/Entity/Sphere.cs:CreateDummySphere")
    def create_dummy_sphere(mode) -> "Sphere":
        """Origin zero; Radius keeps C#'s default 0f."""
        s = Sphere()
        s.origin = mode.vec(0, 0, 0)
        s.radius = mode.scalar(0.0)
        return s
