"""Ammunition: OnCollideObject, OnCollideEnvironment -- an arrow, bolt or dart in flight (ACE's WorldObjects/Ammunition.cs).

Both overrides hand the collision to ProjectileCollisionHelper whatever the ProjectileTarget (WorldObject's
own bodies, which a thrown Missile keeps, need one).
"""

from __future__ import annotations

from dataclasses import dataclass

from ..anchors import anchor
from .projectile_collision_helper import ProjectileCollisionHelper
from .stackable import Stackable
from .world_object import WorldObject


@dataclass(slots=True, eq=False, kw_only=True)
class Ammunition(Stackable):
    @anchor(None, "ACE.Server/WorldObjects/Ammunition.cs:OnCollideObject")
    def on_collide_object(self, target: WorldObject) -> None:
        ProjectileCollisionHelper.on_collide_object(self, target)

    @anchor(None, "ACE.Server/WorldObjects/Ammunition.cs:OnCollideEnvironment")
    def on_collide_environment(self) -> None:
        ProjectileCollisionHelper.on_collide_environment(self)


__all__ = ["Ammunition"]
