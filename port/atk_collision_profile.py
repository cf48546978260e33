"""AtkCollisionProfile: AtkCollisionProfile(uint, int, Quadrant) -- what a missile's PhysicsObj tells its WeenieObject about the object it struck.

ACE's Physics/Combat/AtkCollisionProfile.cs, an ObjCollisionProfile (port/obj_collision_profile.py)
with the part struck (always -1 from PhysicsObj.build_collision_profile) and the Quadrant
(Position.DetermineQuadrant). Its Velocity stays null and its Flags empty: ACE's constructor sets
only ID, Part and Location; WeenieObject.DoCollision(ObjCollisionProfile) reads none of it.
"""

from __future__ import annotations

from dataclasses import dataclass

from .anchors import anchor
from .obj_collision_profile import ObjCollisionProfile


@dataclass(slots=True, eq=False)
class AtkCollisionProfile(ObjCollisionProfile):
    part: int = 0  # Part
    location: int = 0  # Location (ACE.Entity.Enum.Quadrant)

    @classmethod
    @anchor(None, "AtkCollisionProfile.cs:AtkCollisionProfile(uint, int, Quadrant)")
    def create_atk(cls, id: int, part: int, location: int) -> "AtkCollisionProfile":
        profile = cls()
        profile.id = id
        profile.part = part
        profile.location = location
        return profile


__all__ = ["AtkCollisionProfile"]
