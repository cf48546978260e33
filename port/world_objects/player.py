"""Player: OnCollideObject, OnCollideObjectEnd, OnCollideEnvironment, HandleFallingDamage; the members of ACE's Player the physics reads.

ACE's WorldObjects/Player.cs (Player_Combat.cs: IsPK, IsPKL, IsPKType; Player_Tick.cs: FastTick;
Player.cs: LastContact; Player_Move.cs: HandleFallingDamage). What the Player's own code does when the physics calls it
(HandleFallingDamage: Health only; SyncLocation: its Location) reaches nothing the physics reads.
"""

from __future__ import annotations

from dataclasses import dataclass

from acconform.flags import PlayerKillerStatus

from ..anchors import anchor, harness
from .creature import Creature
from .projectile_collision_helper import ProjectileCollisionHelper
from .spell_projectile import SpellProjectile
from .world_object import WorldObject


@dataclass(slots=True, eq=False, kw_only=True)
class Player(Creature):
    """A player without the PlayerKillerStatus property is NPK (WorldObject_Properties.cs); LastContact:
    true until the client's first AutonomousPosition says otherwise (Player.cs)."""

    last_contact: bool = True
    augmentation_increased_carrying_capacity: int = 0  # AugmentationIncreasedCarryingCapacity (an int)

    @staticmethod
    @harness("the mover's Player as the oracle's facade makes it: its id, PlayerKillerStatus and skills (Facade.SetPlayerSkills)")
    def of_skills(guid: int, player_killer_status: PlayerKillerStatus, skills) -> "Player":
        """The Player of a scene's mover (or a request's dat.DatMover): its id, its PlayerKillerStatus and its
        acconform.scene.MoverSkills, field by field."""
        return Player(guid=guid, player_killer_status=player_killer_status, run_skill=skills.run, jump_skill=skills.jump,
                      stamina=skills.stamina, strength=skills.strength, encumbrance_val=skills.encumbrance_val,
                      augmentation_increased_carrying_capacity=skills.augmentation_increased_carrying_capacity)

    @property
    def is_pk_type(self) -> bool:
        """Player_Combat.cs: IsPKType."""
        return self.player_killer_status in (PlayerKillerStatus.PK, PlayerKillerStatus.PKLite)

    @property
    def fast_tick(self) -> bool:
        """Player_Tick.cs: FastTick (which of HandleActionJump's branches runs)."""
        return self.is_pk_type

    @property
    def is_pk(self) -> bool:
        """Player_Combat.cs: IsPK."""
        return self.player_killer_status == PlayerKillerStatus.PK

    @property
    def is_pkl(self) -> bool:
        """Player_Combat.cs: IsPKL."""
        return self.player_killer_status == PlayerKillerStatus.PKLite

    @anchor(None, "ACE.Server/WorldObjects/Player.cs:OnCollideEnvironment")
    def on_collide_environment(self) -> None:
        # HandleFallingDamage(); (commented out in ACE)
        pass

    @anchor(None, "ACE.Server/WorldObjects/Player.cs:OnCollideObject")
    def on_collide_object(self, target: WorldObject) -> None:
        if target.report_collisions is False:  # `== false` on a bool?: null goes on
            return

        # `target is Portal`, `is PressurePlate`, `is Hotspot` -> that object's OnCollideObject(this): a scene makes
        # none of these WorldObjects
        if isinstance(target, SpellProjectile):
            target.on_collide_object(self)
        elif target.projectile_target is not None:
            ProjectileCollisionHelper.on_collide_object(target, self)

    @anchor(None, "ACE.Server/WorldObjects/Player.cs:OnCollideObjectEnd")
    def on_collide_object_end(self, target: WorldObject) -> None:
        # `target is Hotspot hotspot` -> hotspot.OnCollideObjectEnd(this): a scene makes no Hotspot
        pass

    @anchor(None, "ACE.Server/WorldObjects/Player_Move.cs:HandleFallingDamage",
            "reads PhysicsObj.Velocity and may call TakeDamage_Falling, which changes only Health")
    def handle_falling_damage(self, collision) -> None:
        pass


__all__ = ["Player"]
