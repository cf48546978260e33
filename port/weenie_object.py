"""WeenieObject: WeenieObject(WorldObject), DummyObject, IsImpenetrable, IsPK, IsPKLite, InqJumpVelocity, InqBurden, InqRunRate, InqCollisionProfile, DoCollision(ObjCollisionProfile), DoCollision(EnvCollisionProfile), DoCollisionEnd -- what the physics asks of an object's game object.

ACE's Physics/Common/WeenieObject.cs. A static placed from the DAT (Landblock.init_static_objs) keeps
DummyObject: no WorldObject, every flag false. A mover's PhysicsObj gets ``new WeenieObject(worldObject)``
(WorldObject.InitPhysicsObj): `WeenieObject.of` over a port WorldObject record (port/world_objects/:
Player, Creature -- an NPC, or a monster with is_monster -- a plain WorldObject, an object that moves, or a
projectile's Ammunition or SpellProjectile, whose OnCollideObject / OnCollideEnvironment DoCollision runs on a hit).
ACE's WorldObject getter reads a WeakReference (WorldObjectInfo); a scene's WorldObjects live as long as
the run (the oracle holds them), so the port holds the record itself.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from acconform.flags import PlayerKillerStatus
from acconform.numerics import D, MODES, wrap_i32

from .anchors import anchor
from .constants import JUMP_VELOCITY_FACTOR
from .encumbrance_system import encumbrance_capacity, get_burden
from .world_objects import Creature, Player, WorldObject

# the run's mode from the float type a routine is given (InqJumpVelocity's extent): ACE's static float type
_MODE_OF = {m.scalar: m for m in MODES.values()}
_MODE_OF[float] = MODES["fast"]


@dataclass(frozen=True, slots=True)
class WeenieObject:
    world_object: WorldObject | None = None
    is_player: bool = False
    is_creature: bool = False
    is_storage: bool = False
    is_corpse: bool = False
    is_monster: bool = False
    is_combat_pet: bool = False
    is_faction_mob: bool = False
    faction1_bits: int = 0  # FactionBits
    foe_type: int | None = None  # CreatureType?
    player_killer_status: PlayerKillerStatus = PlayerKillerStatus.Undef  # default(PlayerKillerStatus): 0

    @staticmethod
    @anchor(None, "WeenieObject.cs:WeenieObject(WorldObject)")
    def of(world_object: WorldObject) -> "WeenieObject":
        """``new WeenieObject(worldObject)``. A Corpse or Storage (IsCorpse, IsStorage) and a CombatPet
        are classes no scene makes."""
        if not isinstance(world_object, Creature):
            return WeenieObject(world_object=world_object)

        creature = world_object
        is_player = is_monster = False
        if isinstance(creature, Player):
            is_player = True
        elif creature.is_monster:
            is_monster = True

        faction1_bits = creature.faction1_bits if creature.faction1_bits is not None else 0

        return WeenieObject(world_object=creature, is_player=is_player, is_creature=True, is_monster=is_monster,
                            faction1_bits=faction1_bits, is_faction_mob=is_monster and faction1_bits != 0,
                            foe_type=creature.foe_type, player_killer_status=creature.player_killer_status)

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
        if isinstance(self.world_object, Creature):
            run_skill = self.world_object.run_skill
        s = type(rate)
        return True, s(get_run_rate(s(0.0), wrap_i32(run_skill), s(1.0)))  # (int)runSkill

    @anchor(None, "WeenieObject.cs:JumpStaminaCost")
    def jump_stamina_cost(self, extent, stamina_cost: int):
        return 0

    @anchor(None, "WeenieObject.cs:InqCollisionProfile")
    def inq_collision_profile(self, prof) -> None:
        """Completes `prof` (an ObjCollisionProfile). ``WorldObject is Door``: a scene makes no Door
        WorldObject (its doors are statics with no WorldObject)."""
        from .obj_collision_profile import ObjCollisionProfileFlags

        if self.world_object is None:
            return

        # prof.WCID = ID; (commented out in ACE)
        prof.item_type = self.world_object.item_type

        if self.is_creature:
            prof.flags |= ObjCollisionProfileFlags.Creature

            if self.is_player:
                prof.flags |= ObjCollisionProfileFlags.Player

        if self.world_object.attackable:
            prof.flags |= ObjCollisionProfileFlags.Attackable

    @anchor(None, "WeenieObject.cs:DoCollision(ObjCollisionProfile, ObjectGuid, PhysicsObj)")
    def do_collision_obj(self, prof, guid: int, target) -> int:
        """-1 without a WorldObject on either side or when `target`'s WorldObject has this one's Guid (PhysicsObj
        .report_object_collision's second call passes the touched object as its own target: always -1);
        0 once OnCollideObject ran."""
        wo = self.world_object

        if wo is None:
            return -1

        target_wo = target.weenie_obj.world_object

        if target_wo is None:
            return -1

        # no collision with self (ACE)
        if wo.guid == target_wo.guid:
            return -1

        wo.on_collide_object(target_wo)

        return 0

    @anchor(None, "WeenieObject.cs:DoCollision(EnvCollisionProfile, ObjectGuid, PhysicsObj)")
    def do_collision_env(self, prof, guid: int, target) -> int:
        wo = self.world_object

        if wo is None:
            return 0

        if self.is_player and isinstance(wo, Player):
            wo.handle_falling_damage(prof)
        else:
            wo.on_collide_environment()

        return 0

    @anchor(None, "WeenieObject.cs:DoCollisionEnd")
    def do_collision_end(self, target_guid: int) -> None:
        """``wo.CurrentLandblock?.GetObject(targetGuid)``: a scene's WorldObjects are on no server
        landblock, so no target is found and OnCollideObjectEnd is not called (as on the oracle)."""
        wo = self.world_object

        if wo is None:
            return

        target = wo.current_landblock.get_object(target_guid) if wo.current_landblock is not None else None

        if target is not None:
            wo.on_collide_object_end(target)

    @anchor(None, "WeenieObject.cs:OnMotionDone", "Player.HandleMotionDone: a player neither chugging nor casting does nothing")
    def on_motion_done(self, motion_id: int, success: bool) -> None:
        pass

    @anchor(None, "WeenieObject.cs:OnMoveComplete", "Player.OnMoveComplete: IsMoving, the player's MoveTo chains (none here)")
    def on_move_complete(self, status) -> None:
        pass

    @anchor(None, "WeenieObject.cs:CanBypassMoveRestrictions")
    def can_bypass_move_restrictions(self) -> bool:
        # acclient checks both of these here (ACE: IgnoreHouseBarriers alone); ObjCell.check_entry_restrictions asks
        # only a player's, whose WorldObject is its Player
        return self.world_object.ignore_house_barriers

    @anchor(None, "WeenieObject.cs:CanMoveInto")
    def can_move_into(self, mover: "WeenieObject") -> bool:
        """`WorldObject as House` is null for every WorldObject a scene makes (it makes no House: acconform.scene's
        WEENIE_CLASSES), so ACE logs "couldn't find house" and answers true; the root house and the owner's
        permissions are never read."""
        return True


# WeenieObject.DummyObject: what a PhysicsObj made without a WorldObject carries
DUMMY_OBJECT = WeenieObject()
