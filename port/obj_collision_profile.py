"""ObjCollisionProfile: ObjCollisionProfile(uint, Vector3, bool, bool, bool); ObjCollisionProfileFlags.

ACE's Collision/ObjCollisionProfile.cs: what PhysicsObj.build_collision_profile tells a WeenieObject
about the object it touched (its id, the relative velocity, missile / contact flags), which
WeenieObject.InqCollisionProfile completes (ItemType; Creature, Player, Door, Attackable).
WeenieObject.DoCollision(ObjCollisionProfile, ...) reads none of it.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import IntFlag

from .anchors import anchor


class ObjCollisionProfileFlags(IntFlag):
    Undefined = 0x0
    Creature = 0x1
    Player = 0x2
    Attackable = 0x4
    Missile = 0x8
    Contact = 0x10
    MyContact = 0x20
    Door = 0x40
    Cloaked = 0x80


@dataclass(slots=True, eq=False)
class ObjCollisionProfile:
    id: int = 0  # ID (uint)
    velocity: object = None  # Velocity (Vector3)
    wcid: int = 0  # WCID (never set: InqCollisionProfile's `prof.WCID = ID` is commented out in ACE)
    item_type: int = 0  # ItemType
    flags: int = 0  # ObjCollisionProfileFlags

    @classmethod
    @anchor(None, "ObjCollisionProfile.cs:ObjCollisionProfile(uint, Vector3, bool, bool, bool)")
    def create(cls, id: int, velocity, missile: bool, contact: bool, my_contact: bool) -> "ObjCollisionProfile":
        profile = cls(id=id, velocity=velocity)

        if missile:
            profile.flags |= ObjCollisionProfileFlags.Missile
        if contact:
            profile.flags |= ObjCollisionProfileFlags.Contact
        if my_contact:
            profile.flags |= ObjCollisionProfileFlags.MyContact
        return profile


__all__ = ["ObjCollisionProfile", "ObjCollisionProfileFlags"]
