"""Ammunition, Missile, SpellProjectile: the server WorldObjects a launched projectile is, as records.

Stand-ins for ACE's WorldObjects/Ammunition.cs (arrows, bolts, darts), Missile.cs (thrown weapons,
which keep WorldObject's own OnCollideObject/OnCollideEnvironment) and SpellProjectile.cs, holding
only the members the projectile's physics calls read or write (port/missile_launch.py makes those
calls). A projectile's PhysicsObj carries the record as its WeenieObject's WorldObject, as
WorldObject.InitPhysicsObj gives it ``new WeenieObject(this)``.

WorldObject members as ACE spells them: ProjectileSource and ProjectileTarget are WorldObjects in
ACE; here each is the object's PhysicsObj (ACE's WorldObject and PhysicsObj are one-to-one, and the
physics compares them by identity). ``report_collisions`` and ``ethereal`` are the PropertyBool
values (WorldObject.ReportCollisions / Ethereal getters), not the PhysicsState bits the setters also
change. ``in_landblock`` is CurrentLandblock != null; ``listed`` says the landblock holds the
object in worldObjects or pendingAdditions (Landblock.RemoveWorldObjectInternal destroys the
physics object only then: during AddPhysicsObj's enter_world neither holds it yet).
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(slots=True, eq=False)
class Projectile:
    """The WorldObject members every projectile kind shares."""

    physics_obj: object = None  # PhysicsObj (port/physics_obj.py); None after AddPhysicsObj fails
    projectile_source: object = None  # ProjectileSource: the launcher's PhysicsObj
    projectile_target: object = None  # ProjectileTarget: the target's PhysicsObj, or None
    report_collisions: bool | None = None  # PropertyBool.ReportCollisions
    ethereal: bool | None = None  # PropertyBool.Ethereal
    rotation_speed: float | None = None  # PropertyFloat.RotationSpeed (a double)
    physics_creation_time: float = 0.0  # physicsCreationTime: PhysicsTimer.CurrentTime when constructed
    in_landblock: bool = False  # CurrentLandblock != null
    listed: bool = False  # in the landblock's worldObjects or pendingAdditions
    hit_msg: bool = False  # HitMsg
    is_destroyed: bool = False  # IsDestroyed
    scatter_pos: object = None  # ScatterPos (PhysicsObj.SetPositionInternal reads it): never set for a projectile


@dataclass(slots=True, eq=False)
class Ammunition(Projectile):
    """WorldObjects.Ammunition: its OnCollideObject/OnCollideEnvironment always call
    ProjectileCollisionHelper."""


@dataclass(slots=True, eq=False)
class Missile(Projectile):
    """WorldObjects.Missile (a thrown weapon): WorldObject's own OnCollideObject/OnCollideEnvironment,
    which call ProjectileCollisionHelper only when ProjectileTarget is set."""


@dataclass(slots=True, eq=False)
class SpellProjectile(Projectile):
    """WorldObjects.SpellProjectile. ``spell_type`` is its ProjectileSpellType (port/missile_launch.py
    names them); ``world_entry_collision`` WorldEntryCollision."""

    spell_type: int = 0
    world_entry_collision: bool = False
