"""WeenieObject: WeenieObject(WorldObject), DummyObject, IsImpenetrable, IsPK, IsPKLite, InqJumpVelocity, InqBurden, InqRunRate, DoCollision(EnvCollisionProfile), DoCollisionEnd -- what the physics asks of an object's game object; and the members of ACE's WorldObjects.Player the physics reads.

ACE's Physics/Common/WeenieObject.cs. A static placed from the DAT (Landblock.init_static_objs) keeps
DummyObject: no WorldObject, every flag false. The mover is a player: WorldObject.InitPhysicsObj gives
its PhysicsObj ``new WeenieObject(player)``, so IsPlayer and IsCreature are true and the PK answers
come from the Player's PlayerKillerStatus. What the Player's own code does when the physics calls it
(HandleFallingDamage: Health only; SyncLocation: its Location) reaches nothing the physics reads.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from acconform.flags import PlayerKillerStatus
from acconform.numerics import D, MODES, wrap_i32

from .anchors import anchor, harness
from .constants import JUMP_VELOCITY_FACTOR
from .encumbrance_system import encumbrance_capacity, get_burden

# the run's mode from the float type a routine is given (InqJumpVelocity's extent): ACE's static float type
_MODE_OF = {m.scalar: m for m in MODES.values()}
_MODE_OF[float] = MODES["fast"]


@dataclass(slots=True)
class Player:
    """The members of ACE's WorldObjects.Player (and the WorldObject and Creature it derives from)
    that the physics reads. PlayerKillerStatus: a player without the property is NPK
    (WorldObject_Properties.cs); LastContact: true until the client's first AutonomousPosition says
    otherwise (Player.cs); ScatterPos none and not Teleporting: a player walking in the world. The skills,
    vitals, attributes and burden are the scene's (acconform.scene.MoverSkills, scene/8), whose defaults
    are the database-free Player's: no skill, Stamina and Strength 1 (their floors), no load."""

    player_killer_status: PlayerKillerStatus = PlayerKillerStatus.NPK
    last_contact: bool = True
    teleporting: bool = False
    scatter_pos: object = None
    run_skill: int = 0  # GetCreatureSkill(Skill.Run).Current (a uint)
    jump_skill: int = 0  # GetCreatureSkill(Skill.Jump).Current (a uint)
    stamina: int = 1  # Stamina.Current (a uint)
    strength: int = 1  # Strength.Current (a uint)
    encumbrance_val: int | None = 0  # EncumbranceVal (an int?; a Container's is 0 from its constructor on)
    augmentation_increased_carrying_capacity: int = 0  # AugmentationIncreasedCarryingCapacity (an int)

    @staticmethod
    @harness("the mover's Player as the oracle's facade makes it: its PlayerKillerStatus and skills (Facade.SetPlayerSkills)")
    def of_skills(player_killer_status: PlayerKillerStatus, skills) -> "Player":
        """The Player of a scene's mover (or a request's dat.DatMover): its PlayerKillerStatus and its
        acconform.scene.MoverSkills, field by field."""
        return Player(player_killer_status=player_killer_status, run_skill=skills.run, jump_skill=skills.jump,
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


@dataclass(frozen=True, slots=True)
class WeenieObject:
    world_object: Player | None = None
    is_player: bool = False
    is_creature: bool = False
    is_storage: bool = False
    is_corpse: bool = False

    @staticmethod
    @anchor(None, "WeenieObject.cs:WeenieObject(WorldObject)", "for a Player: IsCreature, IsPlayer")
    def of_player(player: Player) -> "WeenieObject":
        return WeenieObject(world_object=player, is_player=True, is_creature=True)

    @anchor(None, "WeenieObject.cs:IsImpenetrable")
    def is_impenetrable(self) -> bool:
        return self.is_player and isinstance(self.world_object, Player) and \
            self.world_object.player_killer_status == PlayerKillerStatus.Free

    @anchor(None, "WeenieObject.cs:IsPK")
    def is_pk(self) -> bool:
        return self.is_player and isinstance(self.world_object, Player) and self.world_object.is_pk

    @anchor(None, "WeenieObject.cs:IsPKLite")
    def is_pk_lite(self) -> bool:
        return self.is_player and isinstance(self.world_object, Player) and self.world_object.is_pkl

    @anchor(None, "WeenieObject.cs:CanJump")
    def can_jump(self, extent) -> bool:
        return True

    @anchor(None, "WeenieObject.cs:InqJumpVelocity")
    def inq_jump_velocity(self, extent):
        """``InqJumpVelocity(float extent, out float velocity_z)``: returns (the bool, velocity_z) in
        `extent`'s float type. A Player with no stamina jumps as with no skill; the height is
        ``MovementSystem.GetJumpHeight((float)burden, jumpSkill, extent, 1.0f)`` and the velocity
        ``(float)Math.Sqrt(height * 19.6)`` (JUMP_VELOCITY_FACTOR) (a double product and root, cast back)."""
        from .animation.movement_system import get_jump_height

        s = type(extent)
        velocity_z = s(0.0)

        if not self.is_player:
            return False, velocity_z

        player = self.world_object if isinstance(self.world_object, Player) else None

        if player is None:
            return False, velocity_z

        burden = self.inq_burden(_MODE_OF[s])
        if burden is None:
            return False, velocity_z

        stamina = player.stamina

        jump_skill = player.jump_skill

        if stamina == 0:
            jump_skill = 0

        height = get_jump_height(s(burden), jump_skill, extent, s(1.0))

        velocity_z = s(np.sqrt(D(height) * D(JUMP_VELOCITY_FACTOR)))

        return True, velocity_z

    @anchor(None, "WeenieObject.cs:InqBurden")
    def inq_burden(self, mode):
        """``float? InqBurden()``: None, or the load over the capacity as a float in `mode`'s scalar
        type (the port's mode stands for C#'s static float type)."""
        if not self.is_player:
            return None

        player = self.world_object if isinstance(self.world_object, Player) else None

        if player is None:
            return None

        strength = wrap_i32(player.strength)  # (int)player.Strength.Current

        num_augs = player.augmentation_increased_carrying_capacity

        capacity = encumbrance_capacity(strength, num_augs)

        encumbrance = player.encumbrance_val if player.encumbrance_val is not None else 0

        burden = get_burden(capacity, encumbrance, mode)

        return burden

    @anchor(None, "WeenieObject.cs:InqRunRate")
    def inq_run_rate(self, rate):
        """``InqRunRate(ref float rate)``: returns (true, the new rate); `rate` (its float type) is
        overwritten. The run skill is the Creature's (GetCreatureSkill(Skill.Run).Current); the rate
        ``(float)MovementSystem.GetRunRate(0.0f, runSkill, 1.0f)``."""
        from .animation.movement_system import get_run_rate

        run_skill = 0
        if isinstance(self.world_object, Player):
            run_skill = self.world_object.run_skill
        s = type(rate)
        return True, s(get_run_rate(s(0.0), wrap_i32(run_skill), s(1.0)))  # (int)runSkill

    @anchor(None, "WeenieObject.cs:JumpStaminaCost")
    def jump_stamina_cost(self, extent, stamina_cost: int):
        return 0

    @anchor(None, "WeenieObject.cs:OnMotionDone", "Player.HandleMotionDone: a player neither chugging nor casting does nothing")
    def on_motion_done(self, motion_id: int, success: bool) -> None:
        pass

    @anchor(None, "WeenieObject.cs:OnMoveComplete", "Player.OnMoveComplete: IsMoving, the player's MoveTo chains (none here)")
    def on_move_complete(self, status) -> None:
        pass


# WeenieObject.DummyObject: what a PhysicsObj made without a WorldObject carries
DUMMY_OBJECT = WeenieObject()
