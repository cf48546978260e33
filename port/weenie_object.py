"""WeenieObject: WeenieObject(WorldObject), DummyObject, IsImpenetrable, IsPK, IsPKLite, DoCollision(EnvCollisionProfile), DoCollisionEnd -- what the physics asks of an object's game object; and the members of ACE's WorldObjects.Player the physics reads.

ACE's Physics/Common/WeenieObject.cs. A static placed from the DAT (Landblock.init_static_objs) keeps
DummyObject: no WorldObject, every flag false. The mover is a player: WorldObject.InitPhysicsObj gives
its PhysicsObj ``new WeenieObject(player)``, so IsPlayer and IsCreature are true and the PK answers
come from the Player's PlayerKillerStatus. What the Player's own code does when the physics calls it
(HandleFallingDamage: Health only; SyncLocation: its Location) reaches nothing the physics reads.
"""

from __future__ import annotations

from dataclasses import dataclass
from acconform.flags import PlayerKillerStatus

from .anchors import anchor


@dataclass(slots=True)
class Player:
    """The members of ACE's WorldObjects.Player (and the WorldObject and Creature it derives from)
    that the physics reads. PlayerKillerStatus: a player without the property is NPK
    (WorldObject_Properties.cs); LastContact: true until the client's first AutonomousPosition says
    otherwise (Player.cs); ScatterPos none and not Teleporting: a player walking in the world."""

    player_killer_status: PlayerKillerStatus = PlayerKillerStatus.NPK
    guid: int = 0
    last_contact: bool = True
    teleporting: bool = False
    scatter_pos: object = None
    run_skill: int = 0  # GetCreatureSkill(Skill.Run).Current: the database-free Player's (no attributes, no skill)

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


@dataclass(slots=True)
class Creature:
    guid: int = 0
    is_monster: bool = False
    player_killer_status: PlayerKillerStatus = PlayerKillerStatus.NPK
    teleporting: bool = False
    scatter_pos: object = None


@dataclass(slots=True)
class GenericObject:
    guid: int = 0
    teleporting: bool = False
    scatter_pos: object = None


@dataclass(frozen=True, slots=True)
class WeenieObject:
    world_object: Player | None = None
    is_player: bool = False
    is_creature: bool = False
    is_storage: bool = False
    is_corpse: bool = False

    @staticmethod
    @anchor(None, "WeenieObject.cs:WeenieObject(WorldObject)", "IsCreature, IsPlayer")
    def of(world_object) -> "WeenieObject":
        if isinstance(world_object, Player):
            return WeenieObject(world_object=world_object, is_player=True, is_creature=True)
        return WeenieObject(world_object=world_object, is_creature=isinstance(world_object, Creature))

    @staticmethod
    def of_player(player: Player) -> "WeenieObject":
        return WeenieObject.of(player)

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
        return True, s(get_run_rate(s(0.0), run_skill, s(1.0)))

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
