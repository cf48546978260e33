"""SpellProjectile: ProjectileImpact, OnCollideObject, OnCollideEnvironment -- a war or life spell's projectile (ACE's WorldObjects/SpellProjectile.cs).

ProjectileImpact's property setters (ReportCollisions, Ethereal, IgnoreCollisions, NoDraw, Cloaked,
LightsStatus) each set or clear their PhysicsState bit directly (WorldObject.SetPhysicsState), never
through a PhysicsObj setter; ReportCollisions and Ethereal also keep their PropertyBool. Its
broadcasts, its damage to a creature target (OnCollideObject after ProjectileImpact: DamageTarget,
procs, PK checks) and the Destroy five seconds later (an ActionChain delay on the server's wall
clock) are no physics a scene's ticks reach.
"""

from __future__ import annotations

from dataclasses import dataclass

from acconform.flags import PhysicsState

from ..anchors import anchor
from ..vec import zero_like
from .world_object import WorldObject

# ProjectileSpellType (ACE.Server/Entity/SpellProjectileType.cs)
UNDEF, BOLT, BLAST, VOLLEY, STREAK, ARC, RING, WALL, STRIKE = range(9)


@dataclass(slots=True, eq=False, kw_only=True)
class SpellProjectile(WorldObject):
    spell_type: int = UNDEF  # SpellType (ProjectileSpellType)
    world_entry_collision: bool = False  # WorldEntryCollision

    @anchor(None, "ACE.Server/WorldObjects/SpellProjectile.cs:ProjectileImpact")
    def projectile_impact(self) -> None:
        obj = self.physics_obj

        self.report_collisions = False
        obj.state &= ~PhysicsState.ReportCollisions
        self.ethereal = True
        obj.state |= PhysicsState.Ethereal
        obj.state |= PhysicsState.IgnoreCollisions  # IgnoreCollisions = true
        obj.state |= PhysicsState.NoDraw  # NoDraw = true
        obj.state |= PhysicsState.Cloaked  # Cloaked = true
        obj.state &= ~PhysicsState.LightingOn  # LightsStatus = false

        obj.set_active(False)

        if obj.entering_world:
            # this path should only happen if spell_projectile_ethereal = false (ACE)
            self.world_entry_collision = True

        obj.velocity = zero_like(obj.velocity.x)

        # selfDestructChain: Destroy after 5 s (the server's action chain; no scene's tick reaches it)

    @anchor(None, "ACE.Server/WorldObjects/SpellProjectile.cs:OnCollideEnvironment")
    def on_collide_environment(self) -> None:
        self.projectile_impact()

    @anchor(None, "ACE.Server/WorldObjects/SpellProjectile.cs:OnCollideObject",
            "ProjectileImpact; the damage to a creature target after it is no physics")
    def on_collide_object(self, target: WorldObject) -> None:
        self.projectile_impact()


__all__ = ["SpellProjectile", "UNDEF", "BOLT", "BLAST", "VOLLEY", "STREAK", "ARC", "RING", "WALL", "STRIKE"]
