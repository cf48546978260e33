"""EnvCollisionProfile: SetMeInContact; EnvCollisionProfileFlags.

ACE's Collision/EnvCollisionProfile.cs: what PhysicsObj.report_environment_collision tells a
WeenieObject about a collision with the environment (the velocity, whether the object was in contact).
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import IntEnum

from .anchors import anchor


class EnvCollisionProfileFlags(IntEnum):
    Undefined = 0x0
    MyContact = 0x1


@dataclass(slots=True, eq=False)
class EnvCollisionProfile:
    velocity: object = None  # Velocity (Vector3)
    flags: int = EnvCollisionProfileFlags.Undefined

    @anchor(None, "EnvCollisionProfile.cs:SetMeInContact")
    def set_me_in_contact(self, has_contact: bool) -> None:
        if has_contact:
            self.flags = EnvCollisionProfileFlags.MyContact
        else:
            self.flags = EnvCollisionProfileFlags.Undefined


__all__ = ["EnvCollisionProfile", "EnvCollisionProfileFlags"]
