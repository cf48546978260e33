"""ProjectileCollisionHelper: OnCollideObject, OnCollideEnvironment -- what an arrow, a bolt or a thrown weapon does when its PhysicsObj reports a collision.

ACE's WorldObjects/ProjectileCollisionHelper.cs (a static class outside the WorldObject hierarchy).
Kept: every line that reaches the physics or the members the physics reads; the damage, procs,
sounds and chat of a hit (DamageTarget, TakeDamage, TryProcEquippedItems, the "hit the environment"
message, MonsterProjectile_OnCollideEnvironment) read and write no physics and are comments.
"""

from __future__ import annotations

from ..anchors import anchor


class ProjectileCollisionHelper:
    @staticmethod
    @anchor(None, "ACE.Server/WorldObjects/ProjectileCollisionHelper.cs:OnCollideObject")
    def on_collide_object(world_object, target) -> None:
        if not world_object.physics_obj.is_active():
            return

        if world_object.projectile_target is None or world_object.projectile_target is not target:
            # Unintended projectile target! (ACE)
            ProjectileCollisionHelper.on_collide_environment(world_object)
            return

        # take damage (ACE): the source's DamageTarget / CalculateDamage, the target's TakeDamage or OnEvade, Dirty
        # Fighting, MonsterOnAttackMonster and the target's procs change vitals and send messages, no physics

        if world_object.current_landblock is not None:
            world_object.current_landblock.remove_world_object(world_object.guid,
                                                               show_error=not world_object.physics_obj.entering_world)
        world_object.physics_obj.set_active(False)

        world_object.hit_msg = True

    @staticmethod
    @anchor(None, "ACE.Server/WorldObjects/ProjectileCollisionHelper.cs:OnCollideEnvironment")
    def on_collide_environment(world_object) -> None:
        if not world_object.physics_obj.is_active():
            return

        # do not send 'Your missile attack hit the environment' messages to player,
        # if projectile is still in the process of spawning into world. (ACE)
        if world_object.physics_obj.entering_world:
            return

        if world_object.current_landblock is not None:
            world_object.current_landblock.remove_world_object(world_object.guid,
                                                               show_error=not world_object.physics_obj.entering_world)
        world_object.physics_obj.set_active(False)

        # the source player's chat, or a source creature's MonsterProjectile_OnCollideEnvironment (its missile
        # combat's bookkeeping): no physics

        world_object.hit_msg = True


__all__ = ["ProjectileCollisionHelper"]
