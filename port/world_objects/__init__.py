"""ACE's ACE.Server/WorldObjects as the physics reads them: WorldObject, GenericObject, Creature, Player, Stackable, Ammunition, Missile, SpellProjectile, ProjectileCollisionHelper; one module per ACE class.

The port's WorldObjects are records of the members the physics (WeenieObject, PhysicsObj) reads, and
the bodies of the methods it calls on them (OnCollideObject, OnCollideObjectEnd, OnCollideEnvironment),
each as ACE writes it, kept to the branches the classes a scene can make reach.
"""

from .world_object import WorldObject
from .generic_object import GenericObject
from .creature import Creature
from .player import Player
from .stackable import Stackable
from .ammunition import Ammunition
from .missile import Missile
from .spell_projectile import SpellProjectile
from .projectile_collision_helper import ProjectileCollisionHelper

__all__ = ["WorldObject", "GenericObject", "Creature", "Player", "Stackable", "Ammunition", "Missile", "SpellProjectile",
           "ProjectileCollisionHelper"]
