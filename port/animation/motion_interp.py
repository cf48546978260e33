"""MotionInterp (CMotionInterp): MotionInterp(obj, wobj), Create, DoInterpretedMotion, DoMotion, HandleExitWorld, HitGround, InqStyle, LeaveGround, MotionDone, PerformMovement, ReportExhaustion, SetHoldKey, SetPhysicsObject, SetWeenieObject, StopCompletely, StopInterpretedMotion, StopMotion, add_to_queue, adjust_motion, apply_current_movement, apply_interpreted_movement, apply_raw_movement, apply_run_to_command, charge_jump, contact_allows_move, enter_default_state, get_adjusted_max_speed, get_jump_v_z, get_leave_ground_velocity, get_max_speed, get_state_velocity, is_standing_still, jump, jump_charge_is_allowed, jump_is_allowed, motion_allows_jump, motions_pending, move_to_interpreted_state, set_hold_run.

ACE's Animation/MotionInterp.cs, the motion network command interpreter: it keeps the raw commands
(RawMotionState: walk backward, turn left, with the hold keys the client gave) and their
interpretation (InterpretedMotionState: forward, sidestep right, turn right, with signed speeds,
run applied by the HoldKey rule), hands the interpreted motions to the PhysicsObj's motion table
(PhysicsObj.DoInterpretedMotion / StopInterpretedMotion), queues the motions it waits for
(PendingMotions) and decides jumps: whether one is allowed (jump_is_allowed, motion_allows_jump,
jump_charge_is_allowed) and the velocity a creature leaves the ground with (get_leave_ground_velocity:
the state's velocity, capped at the run rate's speed, and get_jump_v_z).

What it asks of others, by ACE's names in snake_case:
- the WeenieObject: ``is_creature`` (a field, as DummyWeenie's), ``inq_run_rate(rate) -> (bool, rate)``,
  ``inq_jump_velocity(extent) -> (bool, velocity_z)``, ``can_jump(extent) -> bool``,
  ``jump_stamina_cost(extent, stamina_cost) -> float`` (C#'s ref/out parameters returned);
- the PhysicsObj: ``do_interpreted_motion``, ``stop_interpreted_motion`` (each -> WeenieError),
  ``remove_link_animations``, ``cancel_moveto``, ``unstick_from_object``, ``check_for_completed_motions``,
  ``movement_is_autonomous``, ``stop_completely_internal``, ``initialize_motion_tables``,
  ``is_fully_constrained``, ``set_local_velocity``, ``set_on_walkable``, and its fields ``state``,
  ``transient_state``, ``cur_cell``, ``is_animating``, ``position``, ``velocity``.

`mode` is not ACE's: the run's numerics mode, for the float literals ACE writes (1.0f, 0.0f) and the
records ACE makes with `new` (RawMotionState, InterpretedMotionState, MovementParameters).
"""

from __future__ import annotations

from dataclasses import dataclass

from acconform.flags import PhysicsState, TransientState
from acconform.motion_enums import CommandMask, HoldKey, MotionCommand, MovementType, WeenieError
from acconform.numerics import normalize

from ..anchors import anchor
from ..constants import (BACKWARDS_FACTOR, EPSILON, MAX_SIDESTEP_ANIM_RATE, RUN_ANIM_SPEED, RUN_TURN_FACTOR,
                         SIDESTEP_ANIM_SPEED, SIDESTEP_SPEED_SCALE, WALK_ANIM_SPEED)
from ..linked_list import LinkedList
from ..vec import is_zero
from .interpreted_motion_state import InterpretedMotionState
from .motion_node import MotionNode
from .movement_parameters import MovementParameters
from .raw_motion_state import RawMotionState

CONTACT_ON_WALKABLE = TransientState.Contact | TransientState.OnWalkable


@dataclass(slots=True, eq=False)
class MotionInterp:
    initted: bool = False
    weenie_obj: object = None  # WeenieObject
    physics_obj: object = None  # PhysicsObj
    raw_state: RawMotionState | None = None
    interpreted_state: InterpretedMotionState | None = None
    current_speed_factor: object = 0.0  # float
    standing_long_jump: bool = False
    jump_extent: object = 0.0  # float
    server_action_stamp: int = 0
    my_run_rate: object = 0.0  # float
    pending_motions: LinkedList | None = None  # LinkedList<MotionNode>
    mode: object = None  # the run's numerics Mode (not ACE's; see the module note)

    # ---------------------------------------------------------------- construction

    @staticmethod
    @anchor("CMotionInterp::CMotionInterp", "MotionInterp.cs:MotionInterp(PhysicsObj, WeenieObject)")
    def create(obj, wobj, mode) -> "MotionInterp":
        """``MotionInterp.Create(obj, wobj)`` (= ``new MotionInterp(obj, wobj)``). The states and
        PendingMotions stay null until enter_default_state, as in ACE; JumpExtent is C#'s default 0."""
        s = mode.scalar
        interp = MotionInterp(mode=mode, jump_extent=s(0.0))
        interp.current_speed_factor = s(1.0)
        interp.my_run_rate = s(1.0)

        interp.set_physics_object(obj)
        interp.set_weenie_object(wobj)
        return interp

    # ---------------------------------------------------------------- public: commands

    @anchor("CMotionInterp::DoInterpretedMotion", "MotionInterp.cs:DoInterpretedMotion")
    def do_interpreted_motion(self, motion: int, movement_params: MovementParameters) -> WeenieError:
        if self.physics_obj is None:
            return WeenieError.NoPhysicsObject

        result = WeenieError.None_

        if self.contact_allows_move(motion):
            if self.standing_long_jump and (motion == MotionCommand.WalkForward or motion == MotionCommand.RunForward
                                            or motion == MotionCommand.SideStepRight):
                if movement_params.modify_interpreted_state:
                    self.interpreted_state.apply_motion(motion, movement_params)
            else:
                if motion == MotionCommand.Dead:
                    self.physics_obj.remove_link_animations()

                result = self.physics_obj.do_interpreted_motion(motion, movement_params)

                if result == WeenieError.None_:
                    jump_error_code = WeenieError.None_

                    if movement_params.disable_jump_during_link:
                        jump_error_code = WeenieError.YouCantJumpFromThisPosition
                    else:
                        jump_error_code = self.motion_allows_jump(motion)

                        if jump_error_code == WeenieError.None_ and (motion & CommandMask.Action) == 0:
                            jump_error_code = self.motion_allows_jump(self.interpreted_state.forward_command)

                    self.add_to_queue(movement_params.context_id, motion, jump_error_code)

                    if movement_params.modify_interpreted_state:
                        self.interpreted_state.apply_motion(motion, movement_params)
        else:
            if (motion & CommandMask.Action) != 0:
                result = WeenieError.YouCantJumpWhileInTheAir

            else:
                if movement_params.modify_interpreted_state:
                    self.interpreted_state.apply_motion(motion, movement_params)

                result = WeenieError.None_

        if self.physics_obj.cur_cell is None:
            self.physics_obj.remove_link_animations()

        return result

    @anchor("CMotionInterp::DoMotion", "MotionInterp.cs:DoMotion")
    def do_motion(self, motion: int, movement_params: MovementParameters) -> WeenieError:
        if self.physics_obj is None:
            return WeenieError.NoPhysicsObject

        # movementparams ref? (ACE)
        current_params = MovementParameters.create(self.mode)
        current_params.copy_some(movement_params)

        current_motion = motion

        if movement_params.cancel_move_to:
            self.physics_obj.cancel_moveto()

        if movement_params.set_hold_key:
            self.set_hold_key(movement_params.hold_key_to_apply, movement_params.cancel_move_to)

        current_motion, current_params.speed = self.adjust_motion(current_motion, current_params.speed,
                                                                  movement_params.hold_key_to_apply)

        if self.interpreted_state.current_style != MotionCommand.NonCombat:
            if motion == MotionCommand.Crouch:
                return WeenieError.CantCrouchInCombat
            elif motion == MotionCommand.Sitting:
                return WeenieError.CantSitInCombat
            elif motion == MotionCommand.Sleeping:
                return WeenieError.CantLieDownInCombat

            if (motion & CommandMask.ChatEmote) != 0:
                return WeenieError.CantChatEmoteInCombat

        if (motion & CommandMask.Action) != 0:
            if self.interpreted_state.get_num_actions() >= 6:
                return WeenieError.TooManyActions

        result = self.do_interpreted_motion(current_motion, current_params)

        if result == WeenieError.None_ and movement_params.modify_raw_state:
            self.raw_state.apply_motion(motion, movement_params)

        return result

    @anchor("CMotionInterp::HandleExitWorld", "MotionInterp.cs:HandleExitWorld")
    def handle_exit_world(self) -> None:
        for pending_motion in self.pending_motions:
            if self.physics_obj is not None and (pending_motion.motion & CommandMask.Action) != 0:
                self.physics_obj.unstick_from_object()
                self.interpreted_state.remove_action()
                self.raw_state.remove_action()
        self.pending_motions.clear()
        if self.physics_obj is not None:
            self.physics_obj.is_animating = False

    @anchor("CMotionInterp::HitGround", "MotionInterp.cs:HitGround")
    def hit_ground(self) -> None:
        if self.physics_obj is None:
            return

        if self.weenie_obj is not None and not self.weenie_obj.is_creature:
            return

        if not self.physics_obj.state & PhysicsState.Gravity:
            return

        self.physics_obj.remove_link_animations()
        self.apply_current_movement(False, True)

    @anchor("CMotionInterp::InqStyle", "MotionInterp.cs:InqStyle")
    def inq_style(self) -> int:
        return self.interpreted_state.current_style

    @anchor("CMotionInterp::LeaveGround", "MotionInterp.cs:LeaveGround")
    def leave_ground(self) -> None:
        if self.physics_obj is None:
            return

        if self.weenie_obj is not None and not self.weenie_obj.is_creature:
            return

        if not self.physics_obj.state & PhysicsState.Gravity:
            return

        velocity = self.get_leave_ground_velocity()
        self.physics_obj.set_local_velocity(velocity, True)

        self.standing_long_jump = False
        self.jump_extent = self.mode.scalar(0.0)

        self.physics_obj.remove_link_animations()
        self.apply_current_movement(False, True)

    @anchor("CMotionInterp::MotionDone", "MotionInterp.cs:MotionDone")
    def motion_done(self, success: bool) -> None:
        if self.physics_obj is None:
            return

        motion_data = self.pending_motions.first

        # null or != last in list? (ACE)
        if motion_data is not None:
            pending_motion = motion_data.value
            if (pending_motion.motion & CommandMask.Action) != 0:
                self.physics_obj.unstick_from_object()
                self.interpreted_state.remove_action()
                self.raw_state.remove_action()

            motion_data = self.pending_motions.first
            if motion_data is not None:
                self.pending_motions.remove_node(motion_data)
                self.physics_obj.is_animating = len(self.pending_motions) > 0

    @anchor("CMotionInterp::PerformMovement", "MotionInterp.cs:PerformMovement")
    def perform_movement(self, mvs) -> WeenieError:
        result = WeenieError.None_

        if mvs.type == MovementType.RawCommand:
            result = self.do_motion(mvs.motion, mvs.params)
        elif mvs.type == MovementType.InterpretedCommand:
            result = self.do_interpreted_motion(mvs.motion, mvs.params)
        elif mvs.type == MovementType.StopRawCommand:
            result = self.stop_motion(mvs.motion, mvs.params)
        elif mvs.type == MovementType.StopInterpretedCommand:
            result = self.stop_interpreted_motion(mvs.motion, mvs.params)
        elif mvs.type == MovementType.StopCompletely:
            result = self.stop_completely()
        else:
            return WeenieError.GeneralMovementFailure
        self.physics_obj.check_for_completed_motions()
        return result

    @anchor("CMotionInterp::ReportExhaustion", "MotionInterp.cs:ReportExhaustion")
    def report_exhaustion(self) -> None:
        if self.physics_obj is None or not self.initted:
            return

        # C#'s precedence: WeenieObj == null || (WeenieObj.IsCreature && movement_is_autonomous())
        if self.weenie_obj is None or self.weenie_obj.is_creature and self.physics_obj.movement_is_autonomous():
            self.apply_raw_movement(False, False)
        else:
            self.apply_interpreted_movement(False, False)

    @anchor("CMotionInterp::SetHoldKey", "MotionInterp.cs:SetHoldKey")
    def set_hold_key(self, key: HoldKey, cancel_move_to: bool) -> None:
        """Only a change to HoldKey.None from Run does anything (ACE's switch has that one case)."""
        if key == self.raw_state.current_hold_key:
            return
        if key == HoldKey.None_:
            if self.raw_state.current_hold_key == HoldKey.Run:
                self.raw_state.current_hold_key = HoldKey.None_
                self.apply_current_movement(cancel_move_to, True)

    @anchor("CMotionInterp::SetPhysicsObject", "MotionInterp.cs:SetPhysicsObject")
    def set_physics_object(self, obj) -> None:
        self.physics_obj = obj
        self.apply_current_movement(True, True)

    @anchor("CMotionInterp::SetWeenieObject", "MotionInterp.cs:SetWeenieObject")
    def set_weenie_object(self, wobj) -> None:
        self.weenie_obj = wobj
        self.apply_current_movement(True, True)

    @anchor("CMotionInterp::StopCompletely", "MotionInterp.cs:StopCompletely")
    def stop_completely(self) -> WeenieError:
        if self.physics_obj is None:
            return WeenieError.NoPhysicsObject

        self.physics_obj.cancel_moveto()

        jump = self.motion_allows_jump(self.interpreted_state.forward_command)

        s = self.mode.scalar
        self.raw_state.forward_command = MotionCommand.Ready
        self.raw_state.forward_speed = s(1.0)
        self.raw_state.side_step_command = 0
        self.raw_state.turn_command = 0

        self.interpreted_state.forward_command = MotionCommand.Ready
        self.interpreted_state.forward_speed = s(1.0)
        self.interpreted_state.side_step_command = 0
        self.interpreted_state.turn_command = 0

        self.physics_obj.stop_completely_internal()

        self.add_to_queue(0, MotionCommand.Ready, jump)

        if self.physics_obj.cur_cell is None:
            self.physics_obj.remove_link_animations()

        return WeenieError.None_

    @anchor("CMotionInterp::StopInterpretedMotion", "MotionInterp.cs:StopInterpretedMotion")
    def stop_interpreted_motion(self, motion: int, movement_params: MovementParameters) -> WeenieError:
        if self.physics_obj is None:
            return WeenieError.NoPhysicsObject

        result = WeenieError.None_

        if self.contact_allows_move(motion):
            if self.standing_long_jump and (motion == MotionCommand.WalkForward or motion == MotionCommand.RunForward
                                            or motion == MotionCommand.SideStepRight):
                if movement_params.modify_interpreted_state:
                    self.interpreted_state.remove_motion(motion)
            else:
                result = self.physics_obj.stop_interpreted_motion(motion, movement_params)

                if result == WeenieError.None_:
                    self.add_to_queue(movement_params.context_id, MotionCommand.Ready, WeenieError.None_)

                    if movement_params.modify_interpreted_state:
                        self.interpreted_state.remove_motion(motion)
        else:
            if movement_params.modify_interpreted_state:
                self.interpreted_state.remove_motion(motion)

        if self.physics_obj.cur_cell is None:
            self.physics_obj.remove_link_animations()

        return result

    @anchor("CMotionInterp::StopMotion", "MotionInterp.cs:StopMotion")
    def stop_motion(self, motion: int, movement_params: MovementParameters) -> WeenieError:
        if self.physics_obj is None:
            return WeenieError.NoPhysicsObject

        if movement_params.cancel_move_to:
            self.physics_obj.cancel_moveto()

        current_motion = motion
        current_params = MovementParameters.create(self.mode)
        current_params.copy_some(movement_params)

        current_motion, current_params.speed = self.adjust_motion(current_motion, current_params.speed,
                                                                  movement_params.hold_key_to_apply)

        result = self.stop_interpreted_motion(current_motion, current_params)

        if result == WeenieError.None_ and movement_params.modify_raw_state:
            self.raw_state.remove_motion(motion)

        return result

    # ---------------------------------------------------------------- the interpretation

    @anchor("CMotionInterp::add_to_queue", "MotionInterp.cs:add_to_queue")
    def add_to_queue(self, context_id: int, motion: int, jump_error_code: WeenieError) -> None:
        self.pending_motions.add_last(MotionNode.create(context_id, motion, jump_error_code))
        self.physics_obj.is_animating = True

    @anchor("CMotionInterp::adjust_motion", "MotionInterp.cs:adjust_motion")
    def adjust_motion(self, motion: int, speed, hold_key: HoldKey) -> tuple[int, object]:
        """`motion` and `speed` are C# refs: returns them after the call. Backward, left turn and left
        sidestep become forward, right turn and right sidestep at a negated speed (backward at
        -BackwardsFactor); a sidestep's speed is scaled to the walk's; with the Run hold key (the
        raw state's where `hold_key` is Invalid) apply_run_to_command runs."""
        if self.weenie_obj is not None and not self.weenie_obj.is_creature:
            return motion, speed

        if motion == MotionCommand.RunForward:
            return motion, speed

        elif motion == MotionCommand.WalkBackwards:
            motion = MotionCommand.WalkForward
            speed *= -BACKWARDS_FACTOR

        elif motion == MotionCommand.TurnLeft:
            motion = MotionCommand.TurnRight
            speed *= -1.0

        elif motion == MotionCommand.SideStepLeft:
            motion = MotionCommand.SideStepRight
            speed *= -1.0

        if motion == MotionCommand.SideStepRight:
            speed *= SIDESTEP_SPEED_SCALE  # SidestepFactor * (WalkAnimSpeed / SidestepAnimSpeed), folded

        if hold_key == HoldKey.Invalid:
            hold_key = self.raw_state.current_hold_key

        if hold_key == HoldKey.Run:
            motion, speed = self.apply_run_to_command(motion, speed)
        return motion, speed

    @anchor("CMotionInterp::apply_current_movement", "MotionInterp.cs:apply_current_movement")
    def apply_current_movement(self, cancel_move_to: bool, allow_jump: bool) -> None:
        if self.physics_obj is None or not self.initted:
            return

        # C#'s precedence: (WeenieObj != null && !WeenieObj.IsCreature) || !movement_is_autonomous()
        if self.weenie_obj is not None and not self.weenie_obj.is_creature or not self.physics_obj.movement_is_autonomous():
            self.apply_interpreted_movement(cancel_move_to, allow_jump)
        else:
            self.apply_raw_movement(cancel_move_to, allow_jump)

    @anchor("CMotionInterp::apply_interpreted_movement", "MotionInterp.cs:apply_interpreted_movement")
    def apply_interpreted_movement(self, cancel_move_to: bool, allow_jump: bool) -> None:
        if self.physics_obj is None:
            return

        s = self.mode.scalar
        movement_params = MovementParameters.create(self.mode)

        movement_params.set_hold_key = False
        movement_params.modify_interpreted_state = False
        movement_params.cancel_move_to = cancel_move_to
        movement_params.disable_jump_during_link = not allow_jump

        state = self.interpreted_state
        if state.forward_command == MotionCommand.RunForward:
            self.my_run_rate = state.forward_speed

        self.do_interpreted_motion(state.current_style, movement_params)

        if self.contact_allows_move(state.forward_command):
            if not self.standing_long_jump:
                movement_params.speed = state.forward_speed
                self.do_interpreted_motion(state.forward_command, movement_params)

                if state.side_step_command != 0:
                    movement_params.speed = state.side_step_speed
                    self.do_interpreted_motion(state.side_step_command, movement_params)
                else:
                    self.stop_interpreted_motion(MotionCommand.SideStepRight, movement_params)
            else:
                movement_params.speed = s(1.0)
                self.do_interpreted_motion(MotionCommand.Ready, movement_params)
                self.stop_interpreted_motion(MotionCommand.SideStepRight, movement_params)
        else:
            movement_params.speed = s(1.0)
            self.do_interpreted_motion(MotionCommand.Falling, movement_params)

        if state.turn_command != 0:
            movement_params.speed = state.turn_speed
            self.do_interpreted_motion(state.turn_command, movement_params)
        else:
            result = self.physics_obj.stop_interpreted_motion(MotionCommand.TurnRight, movement_params)

            if result == WeenieError.None_:
                self.add_to_queue(movement_params.context_id, MotionCommand.Ready, WeenieError.None_)

                if movement_params.modify_interpreted_state:
                    state.remove_motion(MotionCommand.TurnRight)

            if self.physics_obj.cur_cell is None:
                self.physics_obj.remove_link_animations()

    @anchor("CMotionInterp::apply_raw_movement", "MotionInterp.cs:apply_raw_movement")
    def apply_raw_movement(self, cancel_move_to: bool, allow_jump: bool) -> None:
        if self.physics_obj is None:
            return

        raw = self.raw_state
        state = self.interpreted_state
        state.current_style = raw.current_style
        state.forward_command = raw.forward_command
        state.forward_speed = raw.forward_speed
        state.side_step_command = raw.side_step_command
        state.side_step_speed = raw.side_step_speed
        state.turn_command = raw.turn_command
        state.turn_speed = raw.turn_speed

        state.forward_command, state.forward_speed = self.adjust_motion(state.forward_command, state.forward_speed,
                                                                        raw.forward_hold_key)
        state.side_step_command, state.side_step_speed = self.adjust_motion(state.side_step_command, state.side_step_speed,
                                                                            raw.side_step_hold_key)
        state.turn_command, state.turn_speed = self.adjust_motion(state.turn_command, state.turn_speed, raw.turn_hold_key)

        self.apply_interpreted_movement(cancel_move_to, allow_jump)

    @anchor("CMotionInterp::apply_run_to_command", "MotionInterp.cs:apply_run_to_command")
    def apply_run_to_command(self, motion: int, speed) -> tuple[int, object]:
        """`motion` and `speed` are C# refs: returns them after the call. The run rate is the
        WeenieObject's (InqRunRate), MyRunRate where it has none, 1.0 with no WeenieObject: a forward
        walk at a positive speed becomes a run, a turn is 1.5 times faster, a sidestep takes the run
        rate up to MaxSidestepAnimRate either way."""
        s = self.mode.scalar
        speed_mod = s(1.0)

        if self.weenie_obj is not None:
            ok, run_factor = self.weenie_obj.inq_run_rate(s(0.0))
            if ok:
                speed_mod = run_factor
            else:
                speed_mod = self.my_run_rate

        if motion == MotionCommand.WalkForward:
            if speed > 0.0:
                motion = MotionCommand.RunForward

            speed *= speed_mod

        elif motion == MotionCommand.TurnRight:
            speed *= RUN_TURN_FACTOR

        elif motion == MotionCommand.SideStepRight:
            speed *= speed_mod

            if MAX_SIDESTEP_ANIM_RATE < abs(speed):
                if speed > 0.0:
                    speed = s(MAX_SIDESTEP_ANIM_RATE * 1.0)
                else:
                    speed = s(MAX_SIDESTEP_ANIM_RATE * -1.0)
        return motion, speed

    # ---------------------------------------------------------------- jumps and the ground

    @anchor("CMotionInterp::charge_jump", "MotionInterp.cs:charge_jump")
    def charge_jump(self) -> int:
        if self.weenie_obj is not None and not self.weenie_obj.can_jump(self.jump_extent):
            return 0x49

        forward = self.interpreted_state.forward_command

        if forward == MotionCommand.Falling or forward >= MotionCommand.Crouch and forward < MotionCommand.Sleeping:
            return 0x48
        else:
            if ((self.physics_obj.transient_state & CONTACT_ON_WALKABLE) == CONTACT_ON_WALKABLE
                    and forward == MotionCommand.Ready
                    and self.interpreted_state.side_step_command == 0 and self.interpreted_state.turn_command == 0):
                self.standing_long_jump = True
        return 0

    @anchor("CMotionInterp::contact_allows_move", "MotionInterp.cs:contact_allows_move")
    def contact_allows_move(self, motion: int) -> bool:
        if self.physics_obj is None:
            return False

        if (motion == MotionCommand.Dead or motion == MotionCommand.Falling
                or motion >= MotionCommand.TurnRight and motion <= MotionCommand.TurnLeft):
            return True

        if self.weenie_obj is not None and not self.weenie_obj.is_creature:
            return True

        if not self.physics_obj.state & PhysicsState.Gravity:
            return True
        if not self.physics_obj.transient_state & TransientState.Contact:
            return False
        if self.physics_obj.transient_state & TransientState.OnWalkable:
            return True

        return False

    @anchor("CMotionInterp::enter_default_state", "MotionInterp.cs:enter_default_state")
    def enter_default_state(self) -> None:
        self.raw_state = RawMotionState.create(self.mode)
        self.interpreted_state = InterpretedMotionState.create(self.mode)

        self.physics_obj.initialize_motion_tables()
        self.pending_motions = LinkedList()  # ?? (ACE)

        self.add_to_queue(0, MotionCommand.Ready, WeenieError.None_)

        self.initted = True
        self.leave_ground()

    @anchor("CMotionInterp::get_adjusted_max_speed", "MotionInterp.cs:get_adjusted_max_speed")
    def get_adjusted_max_speed(self):
        rate = self.mode.scalar(1.0)

        if self.weenie_obj is not None:
            ok, rate = self.weenie_obj.inq_run_rate(rate)
            if not ok:
                rate = self.my_run_rate

        if self.interpreted_state.forward_command == MotionCommand.RunForward:
            rate = self.interpreted_state.forward_speed / self.current_speed_factor

        return rate * 4.0

    @anchor("CMotionInterp::get_jump_v_z", "MotionInterp.cs:get_jump_v_z")
    def get_jump_v_z(self):
        s = self.mode.scalar
        if self.jump_extent < EPSILON:
            return s(0.0)

        extent = self.jump_extent

        if extent > 1.0:
            extent = s(1.0)

        if self.weenie_obj is None:
            return s(10.0)

        ok, vz = self.weenie_obj.inq_jump_velocity(extent)
        if ok:
            return vz

        return s(0.0)

    @anchor("CMotionInterp::get_leave_ground_velocity", "MotionInterp.cs:get_leave_ground_velocity")
    def get_leave_ground_velocity(self):
        velocity = self.get_state_velocity()
        velocity = velocity.with_z(self.get_jump_v_z())

        if is_zero(velocity):
            velocity = self.physics_obj.position.global_to_local_vec(self.physics_obj.velocity)

        return velocity

    @anchor("CMotionInterp::get_max_speed", "MotionInterp.cs:get_max_speed")
    def get_max_speed(self):
        rate = self.mode.scalar(1.0)

        if self.weenie_obj is not None:
            ok, rate = self.weenie_obj.inq_run_rate(rate)
            if not ok:
                rate = self.my_run_rate

        return RUN_ANIM_SPEED * rate

    @anchor("CMotionInterp::get_state_velocity", "MotionInterp.cs:get_state_velocity")
    def get_state_velocity(self):
        """The interpreted state's velocity in the object's frame (x sidestep, y forward), no longer than
        RunAnimSpeed times the run rate (the WeenieObject's, else MyRunRate)."""
        velocity = self.mode.vec(0.0, 0.0, 0.0)

        state = self.interpreted_state
        if state.side_step_command == MotionCommand.SideStepRight:
            velocity = velocity.with_x(SIDESTEP_ANIM_SPEED * state.side_step_speed)
        if state.forward_command == MotionCommand.WalkForward:
            velocity = velocity.with_y(WALK_ANIM_SPEED * state.forward_speed)
        elif state.forward_command == MotionCommand.RunForward:
            velocity = velocity.with_y(RUN_ANIM_SPEED * state.forward_speed)

        rate = self.my_run_rate

        if self.weenie_obj is not None:
            _, rate = self.weenie_obj.inq_run_rate(rate)

        max_speed = RUN_ANIM_SPEED * rate
        if velocity.length() > max_speed:
            velocity = normalize(velocity)
            velocity = velocity * max_speed
        return velocity

    @anchor("CMotionInterp::is_standing_still", "MotionInterp.cs:is_standing_still")
    def is_standing_still(self) -> bool:
        return ((self.physics_obj.transient_state & CONTACT_ON_WALKABLE) == CONTACT_ON_WALKABLE
                and self.interpreted_state.forward_command == MotionCommand.Ready
                and self.interpreted_state.side_step_command == 0
                and self.interpreted_state.turn_command == 0)

    @anchor("CMotionInterp::jump", "MotionInterp.cs:jump")
    def jump(self, extent, adjust_stamina: int) -> WeenieError:
        if self.physics_obj is None:
            return WeenieError.NoPhysicsObject

        self.physics_obj.cancel_moveto()

        result = self.jump_is_allowed(extent, adjust_stamina)

        if result == WeenieError.None_:
            self.jump_extent = extent
            self.physics_obj.set_on_walkable(False)
        else:
            self.standing_long_jump = False

        return result

    @anchor("CMotionInterp::jump_charge_is_allowed", "MotionInterp.cs:jump_charge_is_allowed")
    def jump_charge_is_allowed(self) -> WeenieError:
        """Unlike charge_jump, Fallen (not Falling) and Crouch through Sleeping inclusive."""
        if self.weenie_obj is not None and not self.weenie_obj.can_jump(self.jump_extent):
            return WeenieError.CantJumpLoadedDown

        forward = self.interpreted_state.forward_command

        if forward == MotionCommand.Fallen or forward >= MotionCommand.Crouch and forward <= MotionCommand.Sleeping:
            return WeenieError.YouCantJumpFromThisPosition

        return WeenieError.None_

    @anchor("CMotionInterp::jump_is_allowed", "MotionInterp.cs:jump_is_allowed")
    def jump_is_allowed(self, extent, stamina_cost: int) -> WeenieError:
        if self.physics_obj is None:
            return WeenieError.NoPhysicsObject

        if (self.weenie_obj is None or not self.weenie_obj.is_creature
                or not self.physics_obj.state & PhysicsState.Gravity
                or (self.physics_obj.transient_state & CONTACT_ON_WALKABLE) == CONTACT_ON_WALKABLE):
            if self.physics_obj.is_fully_constrained():
                return WeenieError.GeneralMovementFailure

            if len(self.pending_motions) > 1 and self.pending_motions.first.value.jump_error_code != 0:
                return self.pending_motions.first.value.jump_error_code

            jump_error = self.jump_charge_is_allowed()

            if jump_error == WeenieError.None_:
                jump_error = self.motion_allows_jump(self.interpreted_state.forward_command)

                if (jump_error == WeenieError.None_ and self.weenie_obj is not None
                        and self.weenie_obj.jump_stamina_cost(extent, stamina_cost) == 0):
                    jump_error = WeenieError.GeneralMovementFailure
            return jump_error
        return WeenieError.YouCantJumpWhileInTheAir

    @anchor("CMotionInterp::motion_allows_jump", "MotionInterp.cs:motion_allows_jump")
    def motion_allows_jump(self, substate: int) -> WeenieError:
        if (MotionCommand.Reload <= substate <= MotionCommand.Pickup
                or MotionCommand.TripleThrustLow <= substate <= MotionCommand.MagicPowerUp07Purple
                or MotionCommand.MagicPowerUp01 <= substate <= MotionCommand.MagicPowerUp10
                or MotionCommand.Crouch <= substate <= MotionCommand.Sleeping
                or MotionCommand.AimLevel <= substate <= MotionCommand.MagicPray
                or substate == MotionCommand.Falling):
            return WeenieError.YouCantJumpFromThisPosition
        return WeenieError.None_

    @anchor("CMotionInterp::motions_pending", "MotionInterp.cs:motions_pending")
    def motions_pending(self) -> bool:
        """Alternatively, you can use PhysicsObj.IsAnimating for better performance. (ACE)"""
        return len(self.pending_motions) > 0

    @anchor("CMotionInterp::move_to_interpreted_state", "MotionInterp.cs:move_to_interpreted_state")
    def move_to_interpreted_state(self, state: InterpretedMotionState) -> bool:
        if self.physics_obj is None:
            return False

        self.raw_state.current_style = state.current_style
        self.physics_obj.cancel_moveto()

        allow_jump = self.motion_allows_jump(self.interpreted_state.forward_command) == WeenieError.None_

        self.interpreted_state.copy_movement_from(state)
        self.apply_current_movement(True, allow_jump)

        movement_params = MovementParameters.create(self.mode)

        for action in state.actions:
            current_stamp = action.stamp & 0x7FFF
            server_stamp = self.server_action_stamp & 0x7FFFF  # 0x7FFFF, not 0x7FFF (ACE)

            delta_stamp = abs(current_stamp - server_stamp)

            diff = server_stamp < current_stamp if delta_stamp <= 0x3FFF else current_stamp < server_stamp

            if diff:
                if self.weenie_obj is not None and self.weenie_obj.is_creature or action.autonomous:
                    self.server_action_stamp = action.stamp
                    movement_params.speed = action.speed
                    movement_params.autonomous = action.autonomous
                    self.do_interpreted_motion(action.action, movement_params)
        return True

    @anchor("CMotionInterp::set_hold_run", "MotionInterp.cs:set_hold_run")
    def set_hold_run(self, val: int, cancel_move_to: bool) -> None:
        if (val == 0) != (self.raw_state.current_hold_key != HoldKey.Run):
            self.raw_state.current_hold_key = HoldKey.Run if val != 0 else HoldKey.None_
            self.apply_current_movement(cancel_move_to, True)


__all__ = ["MotionInterp"]
