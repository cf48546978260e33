"""MoveToManager: MoveToManager(obj, wobj), Create, Init, InitializeLocalVars, PerformMovement, MoveToObject, MoveToObject_Internal, MoveToPosition, TurnToObject, TurnToObject_Internal, TurnToHeading, AddMoveToPositionNode, AddTurnToHeadingNode, BeginNextNode, BeginMoveForward, HandleMoveToPosition, BeginTurnToHeading, HandleTurnToHeading, HandleUpdateTarget, CheckProgressMade, CancelMoveTo, CleanUp, CleanUpAndCallWeenie, GetCurrentDistance, HitGround, RemovePendingActionsHead, SetPhysicsObject, SetWeenieObject, UseTime, _DoMotion, _StopMotion, heading_diff, heading_greater, is_moving_to, stop_aux_command.

ACE's Managers/MoveToManager.cs: how a monster walks to a position or an object. A move is a list
of MovementNodes (PendingActions): a turn to face the target, a move forward, and with
UseFinalHeading a last turn. Each UseTime (only while the object is in contact) steps the head node:
HandleTurnToHeading turns until the heading passes the node's (heading_greater), then snaps to it;
HandleMoveToPosition keeps the heading within 20 degrees of the target by an auxiliary turn,
stops within DistanceToObject (or beyond MinDistance when moving away), and cancels the move when
the object is FailDistance from where it started (YouChargedTooFar) -- checked only on a frame that
made progress. A move to an object waits for the target's first update (through the
TargetManager: PhysicsObj.set_target); a sticky move ends by sticking to the object
(PositionManager.StickTo).

ACE's code kept as it is (each pinned by tests/port/managers/test_move_to_manager.py):
- MoveToPosition asks the *argument's* get_command but reads the *old* MovementParams'
  UseFinalHeading, before it replaces MovementParams with a copy of the argument;
- HandleMoveToPosition's "custom" arrival: without UseSpheres, a distance under 1 that grew since
  the last frame counts as arrived; with an auxiliary turn running, a heading within 20 degrees
  is snapped to (set_heading) before the turn stops;
- TurnToHeading queues its node but does not begin it (UseTime does, at the next tick).

The clock is the object's run's PhysicsTimer (doubles). `mode` is the run's mode: ACE's
``new MovementParameters()`` and ``new Position()`` take its scalar type and runtime.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from acconform.flags import TransientState
from acconform.motion_enums import HoldKey, MotionCommand, MovementType, WeenieError
from acconform.numerics import cs_fmod

from ..anchors import anchor
from ..animation.movement_node import MovementNode
from ..animation.movement_parameters import MovementParameters
from ..combat.target_info import TargetStatus
from ..constants import EPSILON, FLOAT_MAX_VALUE, MOVE_TO_MIN_VELOCITY
from ..frame import AFrame, Position

TURN_SLACK = 20.0  # HandleMoveToPosition: an auxiliary turn starts outside (20, 340) degrees (exact)
ARRIVAL_DISTANCE = 1.0  # HandleMoveToPosition's custom arrival: `dist < 1.0f` (exact)
MIN_PROGRESS_RATE = 0.25  # CheckProgressMade: `diffDist / deltaTime < 0.25f`, per second (exact)
PROGRESS_INTERVAL = 1.0  # CheckProgressMade: `deltaTime > 1.0f` (exact)
QUANTUM_SLACK = 1.0  # HandleMoveToPosition: `Math.Abs(time - get_target_quantum()) > 1.0f` (exact)


@dataclass(slots=True, eq=False)
class MoveToManager:
    movement_type: MovementType = MovementType.Invalid
    sought_position: Position | None = None
    current_target_position: Position | None = None
    starting_position: Position | None = None
    movement_params: MovementParameters | None = None
    previous_heading: object = 0.0  # float
    previous_distance: object = 0.0  # float
    previous_distance_time: float = 0.0  # double
    original_distance: object = 0.0  # float
    original_distance_time: float = 0.0  # double
    fail_progress_count: int = 0
    sought_object_id: int = 0
    top_level_object_id: int = 0
    sought_object_radius: object = 0.0  # float
    sought_object_height: object = 0.0  # float
    current_command: int = 0
    aux_command: int = 0
    moving_away: bool = False
    initialized: bool = False
    pending_actions: list = field(default_factory=list)  # List<MovementNode>
    physics_obj: object = None
    weenie_obj: object = None
    always_turn: bool = False
    mode: object = None  # the run's mode (the port's: ACE's scalar types)

    @staticmethod
    @anchor("MoveToManager::Create", "MoveToManager.cs:Create")
    def create(obj, wobj, mode) -> "MoveToManager":
        """``new MoveToManager(obj, wobj)``: Init, InitializeLocalVars."""
        s = mode.scalar
        manager = MoveToManager(physics_obj=obj, weenie_obj=wobj, mode=mode, previous_heading=s(0.0),
                                previous_distance=s(0.0), original_distance=s(0.0), sought_object_radius=s(0.0),
                                sought_object_height=s(0.0))
        manager.init()
        manager.initialize_local_vars()
        return manager

    def _now(self) -> float:
        """PhysicsTimer.CurrentTime: the clock of the object's run."""
        return self.physics_obj.timer.current_time

    @anchor("MoveToManager::Init", "MoveToManager.cs:Init")
    def init(self) -> None:
        self.movement_params = MovementParameters.create(self.mode)

        self.pending_actions = []

    @anchor("MoveToManager::InitializeLocalVars", "MoveToManager.cs:InitializeLocalVars")
    def initialize_local_vars(self) -> None:
        s = self.mode.scalar
        self.movement_type = MovementType.Invalid

        self.movement_params.distance_to_object = s(0.0)
        self.movement_params.context_id = 0

        self.previous_distance_time = self._now()
        self.original_distance_time = self._now()

        self.previous_heading = s(0.0)

        self.fail_progress_count = 0
        self.current_command = 0
        self.aux_command = 0
        self.moving_away = False
        self.initialized = False

        self.sought_position = Position(0, AFrame.identity(self.mode))  # new Position()
        self.current_target_position = Position(0, AFrame.identity(self.mode))

        self.sought_object_id = 0
        self.top_level_object_id = 0
        self.sought_object_radius = s(0.0)
        self.sought_object_height = s(0.0)

    @anchor("MoveToManager::PerformMovement", "MoveToManager.cs:PerformMovement")
    def perform_movement(self, mvs) -> WeenieError:
        self.cancel_move_to(WeenieError.ActionCancelled)
        self.physics_obj.unstick_from_object()
        if mvs.type == MovementType.MoveToObject:
            self.move_to_object(mvs.object_id, mvs.top_level_id, mvs.radius, mvs.height, mvs.params)
        elif mvs.type == MovementType.MoveToPosition:
            self.move_to_position(mvs.position, mvs.params)
        elif mvs.type == MovementType.TurnToObject:
            self.turn_to_object(mvs.object_id, mvs.top_level_id, mvs.params)
        elif mvs.type == MovementType.TurnToHeading:
            self.turn_to_heading(mvs.params)
        # server - movement/anim update (ACE)
        return WeenieError.None_

    @anchor("MoveToManager::MoveToObject", "MoveToManager.cs:MoveToObject")
    def move_to_object(self, object_id: int, top_level_id: int, radius, height, movement_params) -> None:
        if self.physics_obj is None:
            return

        self.physics_obj.stop_completely(False)

        self.starting_position = self.physics_obj.position.copy()
        self.sought_object_id = object_id
        self.sought_object_radius = radius
        self.sought_object_height = height
        self.movement_type = MovementType.MoveToObject
        self.top_level_object_id = top_level_id

        self.movement_params = MovementParameters.create_copy(movement_params)

        self.initialized = False
        if self.physics_obj.id != top_level_id:
            self.physics_obj.set_target(0, self.top_level_object_id, 0.5, 0.0)
            return
        self.clean_up()
        self.physics_obj.stop_completely(False)

    @anchor("MoveToManager::MoveToObject_Internal", "MoveToManager.cs:MoveToObject_Internal")
    def move_to_object_internal(self, target_position, interpolated_position) -> None:
        if self.physics_obj is None:
            self.cancel_move_to(WeenieError.NoPhysicsObject)
            return

        self.sought_position = interpolated_position.copy()
        self.current_target_position = target_position.copy()

        i_heading = self.physics_obj.position.heading(interpolated_position)
        heading = i_heading - self.physics_obj.get_heading()
        dist = self.get_current_distance()

        if abs(heading) < EPSILON:
            heading = type(heading)(0.0)
        if heading < -EPSILON:
            heading += 360.0

        hold_key = HoldKey.Invalid
        motion_id = 0
        move_away = False
        motion_id, hold_key, move_away = self.movement_params.get_command(dist, heading, motion_id, hold_key, move_away)

        if motion_id != 0:
            self.add_turn_to_heading_node(i_heading)
            self.add_move_to_position_node()
        if self.movement_params.use_final_heading:
            d_heading = i_heading + self.movement_params.desired_heading
            if d_heading >= 360.0:
                d_heading -= 360.0
            self.add_turn_to_heading_node(d_heading)
        self.initialized = True
        self.begin_next_node()

    @anchor("MoveToManager::MoveToPosition", "MoveToManager.cs:MoveToPosition")
    def move_to_position(self, position, movement_params) -> None:
        if self.physics_obj is None:
            return

        self.physics_obj.stop_completely(False)

        self.current_target_position = position.copy()
        self.sought_object_radius = type(self.sought_object_radius)(0.0)

        distance = self.get_current_distance()
        heading_diff = self.physics_obj.position.heading(position) - self.physics_obj.get_heading()

        if abs(heading_diff) < EPSILON:
            heading_diff = type(heading_diff)(0.0)
        if heading_diff < -EPSILON:
            heading_diff += 360.0

        hold_key = HoldKey.Invalid
        command = 0
        move_away = False
        command, hold_key, move_away = movement_params.get_command(distance, heading_diff, command, hold_key, move_away)

        if command != 0:
            self.add_turn_to_heading_node(self.physics_obj.position.heading(position))
            self.add_move_to_position_node()

        if self.movement_params.use_final_heading:  # the old MovementParams (ACE)
            self.add_turn_to_heading_node(movement_params.desired_heading)

        self.sought_position = position.copy()
        self.starting_position = self.physics_obj.position.copy()

        self.movement_type = MovementType.MoveToPosition

        self.movement_params = MovementParameters.create_copy(movement_params)
        self.movement_params.sticky = False

        self.begin_next_node()

    @anchor("MoveToManager::TurnToObject", "MoveToManager.cs:TurnToObject")
    def turn_to_object(self, object_id: int, top_level_id: int, movement_params) -> None:
        if self.physics_obj is None:
            self.movement_params.context_id = movement_params.context_id
            return

        if movement_params.stop_completely:
            self.physics_obj.stop_completely(False)

        self.movement_type = MovementType.TurnToObject
        self.sought_object_id = object_id

        self.current_target_position.frame.set_heading(movement_params.desired_heading)

        self.top_level_object_id = top_level_id
        self.movement_params = MovementParameters.create_copy(movement_params)

        if self.physics_obj.id != top_level_id:
            self.initialized = False
            self.physics_obj.set_target(0, top_level_id, 0.5, 0.0)
            return
        self.clean_up()
        self.physics_obj.stop_completely(False)

    @anchor("MoveToManager::TurnToObject_Internal", "MoveToManager.cs:TurnToObject_Internal")
    def turn_to_object_internal(self, target_position) -> None:
        if self.physics_obj is None:
            self.cancel_move_to(WeenieError.NoPhysicsObject)
            return

        self.current_target_position = target_position.copy()

        target_heading = self.physics_obj.position.heading(self.current_target_position)
        sought_heading = self.sought_position.frame.get_heading()
        heading = cs_fmod(target_heading + sought_heading, type(target_heading)(360.0))
        self.sought_position.frame.set_heading(heading)

        self.pending_actions.append(MovementNode.create(MovementType.TurnToHeading, heading))
        self.initialized = True

        self.begin_next_node()

    @anchor("MoveToManager::TurnToHeading", "MoveToManager.cs:TurnToHeading")
    def turn_to_heading(self, movement_params) -> None:
        if self.physics_obj is None:
            self.movement_params.context_id = movement_params.context_id
            return

        if movement_params.stop_completely:
            self.physics_obj.stop_completely(False)

        self.movement_params = MovementParameters.create_copy(movement_params)
        self.movement_params.sticky = False

        self.sought_position.frame.set_heading(movement_params.desired_heading)
        self.movement_type = MovementType.TurnToHeading

        self.pending_actions.append(MovementNode.create(MovementType.TurnToHeading, movement_params.desired_heading))

    @anchor("MoveToManager::AddMoveToPositionNode", "MoveToManager.cs:AddMoveToPositionNode")
    def add_move_to_position_node(self) -> None:
        self.pending_actions.append(MovementNode.create(MovementType.MoveToPosition))

    @anchor("MoveToManager::AddTurnToHeadingNode", "MoveToManager.cs:AddTurnToHeadingNode")
    def add_turn_to_heading_node(self, heading) -> None:
        self.pending_actions.append(MovementNode.create(MovementType.TurnToHeading, heading))

    @anchor("MoveToManager::BeginNextNode", "MoveToManager.cs:BeginNextNode")
    def begin_next_node(self) -> None:
        if len(self.pending_actions) > 0:
            pending_action = self.pending_actions[0]

            if pending_action.type == MovementType.MoveToPosition:
                self.begin_move_forward()
            elif pending_action.type == MovementType.TurnToHeading:
                self.begin_turn_to_heading()
        else:
            if self.movement_params.sticky:
                sought_object_radius = self.sought_object_radius
                sought_object_height = self.sought_object_height
                top_level_object_id = self.top_level_object_id

                # unsets sticky flag (ACE)
                self.clean_up_and_call_weenie(WeenieError.None_)

                if self.physics_obj is not None:
                    self.physics_obj.get_position_manager().stick_to(top_level_object_id, sought_object_radius, sought_object_height)
            else:
                self.clean_up_and_call_weenie(WeenieError.None_)

    @anchor("MoveToManager::BeginMoveForward", "MoveToManager.cs:BeginMoveForward")
    def begin_move_forward(self) -> None:
        if self.physics_obj is None:
            self.cancel_move_to(WeenieError.NoPhysicsObject)
            return

        dist = self.get_current_distance()
        heading = self.physics_obj.position.heading(self.current_target_position) - self.physics_obj.get_heading()
        if abs(heading) < EPSILON:
            heading = type(heading)(0.0)
        if heading < -EPSILON:
            heading += 360.0

        motion = 0
        move_away = False
        hold_key = HoldKey.Invalid
        motion, hold_key, move_away = self.movement_params.get_command(dist, heading, motion, hold_key, move_away)

        if motion == 0:
            self.remove_pending_actions_head()
            self.begin_next_node()
            return

        movement_params = MovementParameters.create(self.mode)
        movement_params.hold_key_to_apply = hold_key
        movement_params.cancel_move_to = False
        movement_params.speed = self.movement_params.speed

        result = self.do_motion(motion, movement_params)
        if result != WeenieError.None_:
            self.cancel_move_to(result)
            return

        self.current_command = motion
        self.moving_away = move_away
        self.movement_params.hold_key_to_apply = hold_key
        self.previous_distance = dist
        self.previous_distance_time = self._now()
        self.original_distance = dist
        self.original_distance_time = self._now()

    @anchor("MoveToManager::HandleMoveToPosition", "MoveToManager.cs:HandleMoveToPosition")
    def handle_move_to_position(self) -> None:
        """The main iterator for movement (ACE)."""
        if self.physics_obj is None:
            self.cancel_move_to(WeenieError.NoPhysicsObject)
            return

        cur_pos = self.physics_obj.position.copy()

        movement_params = MovementParameters.create(self.mode)
        movement_params.cancel_move_to = False

        movement_params.speed = self.movement_params.speed
        movement_params.hold_key_to_apply = self.movement_params.hold_key_to_apply

        if not self.physics_obj.is_animating:
            heading = self.movement_params.get_desired_heading(self.current_command, self.moving_away) + cur_pos.heading(self.current_target_position)
            if heading >= 360.0:
                heading -= 360.0

            diff = heading - self.physics_obj.get_heading()

            if abs(diff) < EPSILON:
                diff = type(diff)(0.0)
            if diff < -EPSILON:
                diff += 360.0

            if diff > TURN_SLACK and diff < 360.0 - TURN_SLACK:
                motion_id = MotionCommand.TurnLeft if diff >= 180.0 else MotionCommand.TurnRight
                if motion_id != self.aux_command:
                    self.do_motion(motion_id, movement_params)
                    self.aux_command = motion_id
            else:
                # custom: sync for server ticrate (ACE)
                if self.aux_command != 0:
                    self.physics_obj.set_heading(heading, True)

                self.stop_aux_command(movement_params)
        else:
            self.stop_aux_command(movement_params)

        dist = self.get_current_distance()

        if not self.check_progress_made(dist):
            if not self.physics_obj.is_interpolating() and not self.physics_obj.is_animating:
                self.fail_progress_count += 1
        else:
            # custom for low monster update rate (ACE)
            in_range = False

            if not self.movement_params.use_spheres:
                if dist < ARRIVAL_DISTANCE and self.previous_distance < dist:
                    in_range = True

                self.previous_distance = dist
                self.previous_distance_time = self._now()

            self.fail_progress_count = 0
            if (self.moving_away and dist >= self.movement_params.min_distance
                    or not self.moving_away and dist <= self.movement_params.distance_to_object or in_range):
                del self.pending_actions[0]
                self.stop_motion(self.current_command, movement_params)

                self.current_command = 0
                self.stop_aux_command(movement_params)

                self.begin_next_node()
            else:
                if self.starting_position.distance(self.physics_obj.position) > self.movement_params.fail_distance:
                    self.cancel_move_to(WeenieError.YouChargedTooFar)

        if self.top_level_object_id != 0 and self.movement_type != MovementType.Invalid:
            velocity = self.physics_obj.get_velocity()
            velocity_length = velocity.length()
            if velocity_length > MOVE_TO_MIN_VELOCITY:
                time = dist / velocity_length
                if abs(float(time) - self.physics_obj.get_target_quantum()) > QUANTUM_SLACK:  # float - double
                    self.physics_obj.set_target_quantum(float(time))

    @anchor("MoveToManager::BeginTurnToHeading", "MoveToManager.cs:BeginTurnToHeading")
    def begin_turn_to_heading(self) -> None:
        """Starts a new and discrete turn to heading node; turning while moving forward is handled
        in HandleMoveToPosition (ACE)."""
        if self.physics_obj is None:
            self.cancel_move_to(WeenieError.NoPhysicsObject)
            return

        if self.physics_obj.is_animating and not self.always_turn:
            return

        pending_action = self.pending_actions[0]
        heading_diff = self.heading_diff(pending_action.heading, self.physics_obj.get_heading(), MotionCommand.TurnRight)
        motion_id = 0

        if heading_diff <= 180.0:
            if heading_diff > EPSILON:
                motion_id = MotionCommand.TurnRight
            else:
                self.remove_pending_actions_head()
                self.begin_next_node()
                return
        else:
            if heading_diff + EPSILON <= 360.0:
                motion_id = MotionCommand.TurnLeft
            else:
                self.remove_pending_actions_head()
                self.begin_next_node()
                return

        movement_params = MovementParameters.create(self.mode)
        movement_params.cancel_move_to = False
        movement_params.speed = self.movement_params.speed  # only for turning, too fast? (ACE)
        movement_params.hold_key_to_apply = self.movement_params.hold_key_to_apply

        result = self.do_motion(motion_id, movement_params)

        if result != WeenieError.None_:
            self.cancel_move_to(result)
            return

        self.current_command = motion_id
        self.previous_heading = heading_diff

    @anchor("MoveToManager::HandleTurnToHeading", "MoveToManager.cs:HandleTurnToHeading")
    def handle_turn_to_heading(self) -> None:
        """The main iterator for turning (ACE)."""
        if self.physics_obj is None:
            self.cancel_move_to(WeenieError.NoPhysicsObject)
            return

        if self.current_command != MotionCommand.TurnRight and self.current_command != MotionCommand.TurnLeft:
            self.begin_turn_to_heading()
            return

        pending_action = self.pending_actions[0]
        heading = self.physics_obj.get_heading()

        if self.heading_greater(heading, pending_action.heading, self.current_command):
            self.fail_progress_count = 0
            self.physics_obj.set_heading(pending_action.heading, True)

            self.remove_pending_actions_head()

            movement_params = MovementParameters.create(self.mode)
            movement_params.cancel_move_to = False
            movement_params.hold_key_to_apply = self.movement_params.hold_key_to_apply

            self.stop_motion(self.current_command, movement_params)

            self.current_command = 0
            self.begin_next_node()
            return

        diff = self.heading_diff(heading, self.previous_heading, self.current_command)

        if diff > EPSILON and diff < 180.0:
            self.fail_progress_count = 0
            self.previous_heading = heading
        else:
            self.previous_heading = heading

            if not self.physics_obj.is_interpolating() and not self.physics_obj.is_animating:
                self.fail_progress_count += 1

    @anchor("MoveToManager::HandleUpdateTarget", "MoveToManager.cs:HandleUpdateTarget")
    def handle_update_target(self, target_info) -> None:
        if self.physics_obj is None:
            self.cancel_move_to(WeenieError.NoPhysicsObject)
            return

        if self.top_level_object_id != target_info.object_id:
            return

        if self.initialized:
            if target_info.status == TargetStatus.OK:
                if self.movement_type == MovementType.MoveToObject:
                    self.sought_position = target_info.interpolated_position.copy()
                    self.current_target_position = target_info.target_position.copy()
                    self.previous_distance = type(self.previous_distance)(FLOAT_MAX_VALUE)
                    self.previous_distance_time = self._now()
                    self.original_distance = type(self.original_distance)(FLOAT_MAX_VALUE)
                    self.original_distance_time = self._now()
            else:
                self.cancel_move_to(WeenieError.ObjectGone)
        elif self.top_level_object_id == self.physics_obj.id:
            self.sought_position = self.physics_obj.position.copy()
            self.current_target_position = self.physics_obj.position.copy()
            self.clean_up_and_call_weenie(WeenieError.None_)
        elif target_info.status == TargetStatus.OK:
            if self.movement_type == MovementType.MoveToObject:
                self.move_to_object_internal(target_info.target_position, target_info.interpolated_position)
            elif self.movement_type == MovementType.TurnToObject:
                self.turn_to_object_internal(target_info.target_position)
        else:
            self.cancel_move_to(WeenieError.NoObject)

    @anchor("MoveToManager::CheckProgressMade", "MoveToManager.cs:CheckProgressMade")
    def check_progress_made(self, curr_distance) -> bool:
        """The rates are doubles: a float32 distance over the double clock's delta."""
        delta_time = self._now() - self.previous_distance_time

        if delta_time > PROGRESS_INTERVAL:
            diff_dist = curr_distance - self.previous_distance if self.moving_away else self.previous_distance - curr_distance

            if float(diff_dist) / delta_time < MIN_PROGRESS_RATE:
                return False

            self.previous_distance = curr_distance
            self.previous_distance_time = self._now()

            d_orig_dist = curr_distance - self.original_distance if self.moving_away else self.original_distance - curr_distance

            if float(d_orig_dist) / (self._now() - self.original_distance_time) < MIN_PROGRESS_RATE:
                return False
        return True

    @anchor("MoveToManager::CancelMoveTo", "MoveToManager.cs:CancelMoveTo")
    def cancel_move_to(self, retval: WeenieError) -> None:
        if self.movement_type == MovementType.Invalid:
            return

        self.pending_actions.clear()
        self.clean_up_and_call_weenie(retval)

    @anchor("MoveToManager::CleanUp", "MoveToManager.cs:CleanUp")
    def clean_up(self) -> None:
        movement_params = MovementParameters.create(self.mode)
        movement_params.hold_key_to_apply = self.movement_params.hold_key_to_apply
        movement_params.cancel_move_to = False

        if self.physics_obj is not None:
            if self.current_command != 0:
                self.stop_motion(self.current_command, movement_params)

            if self.aux_command != 0:
                self.stop_motion(self.aux_command, movement_params)

            if self.top_level_object_id != 0 and self.movement_type != MovementType.Invalid:
                self.physics_obj.clear_target()
        self.initialize_local_vars()

    @anchor("MoveToManager::CleanUpAndCallWeenie", "MoveToManager.cs:CleanUpAndCallWeenie")
    def clean_up_and_call_weenie(self, status: WeenieError) -> None:
        self.clean_up()
        if self.physics_obj is not None:
            self.physics_obj.stop_completely(False)

        # server custom (ACE): WeenieObject.OnMoveComplete -> WorldObject.OnMoveComplete
        self.weenie_obj.on_move_complete(status)

    @anchor("MoveToManager::GetCurrentDistance", "MoveToManager.cs:GetCurrentDistance")
    def get_current_distance(self):
        if self.physics_obj is None:
            return self.mode.scalar(FLOAT_MAX_VALUE)

        if not self.movement_params.use_spheres:  # Flags.HasFlag(MovementParamFlags.UseSpheres)
            return self.physics_obj.position.distance(self.current_target_position)

        return self.mode.scalar(Position.cylinder_distance(  # (float)
            self.physics_obj.get_radius(), self.physics_obj.get_height(), self.physics_obj.position,
            self.sought_object_radius, self.sought_object_height, self.current_target_position))

    @anchor("MoveToManager::HitGround", "MoveToManager.cs:HitGround")
    def hit_ground(self) -> None:
        if self.movement_type != MovementType.Invalid:
            self.begin_next_node()

    @anchor("MoveToManager::RemovePendingActionsHead", "MoveToManager.cs:RemovePendingActionsHead")
    def remove_pending_actions_head(self) -> None:
        if len(self.pending_actions) > 0:
            del self.pending_actions[0]

    @anchor("MoveToManager::SetPhysicsObject", "MoveToManager.cs:SetPhysicsObject")
    def set_physics_object(self, obj) -> None:
        self.physics_obj = obj

    @anchor("MoveToManager::SetWeenieObject", "MoveToManager.cs:SetWeenieObject")
    def set_weenie_object(self, wobj) -> None:
        self.weenie_obj = wobj

    @anchor("MoveToManager::UseTime", "MoveToManager.cs:UseTime")
    def use_time(self) -> None:
        if self.physics_obj is None or not self.physics_obj.transient_state & TransientState.Contact:
            return

        if len(self.pending_actions) == 0:
            return

        pending_action = self.pending_actions[0]

        if self.top_level_object_id != 0 or self.movement_type != MovementType.Invalid or self.initialized:
            if pending_action.type == MovementType.MoveToPosition:
                self.handle_move_to_position()
            elif pending_action.type == MovementType.TurnToHeading:
                self.handle_turn_to_heading()

    @anchor("MoveToManager::_DoMotion", "MoveToManager.cs:_DoMotion", "ACE's _DoMotion (a leading underscore would make it private here)")
    def do_motion(self, motion: int, movement_params) -> WeenieError:
        if self.physics_obj is None:
            return WeenieError.NoPhysicsObject

        minterp = self.physics_obj.get_minterp()
        if minterp is None:
            return WeenieError.NoMotionInterpreter

        motion, movement_params.speed = minterp.adjust_motion(motion, movement_params.speed, movement_params.hold_key_to_apply)

        return minterp.do_interpreted_motion(motion, movement_params)

    @anchor("MoveToManager::_StopMotion", "MoveToManager.cs:_StopMotion", "ACE's _StopMotion")
    def stop_motion(self, motion: int, movement_params) -> WeenieError:
        if self.physics_obj is None:
            return WeenieError.NoPhysicsObject

        minterp = self.physics_obj.get_minterp()
        if minterp is None:
            return WeenieError.NoMotionInterpreter

        motion, movement_params.speed = minterp.adjust_motion(motion, movement_params.speed, movement_params.hold_key_to_apply)

        return minterp.stop_interpreted_motion(motion, movement_params)

    @staticmethod
    @anchor("MoveToManager::heading_diff", "MoveToManager.cs:heading_diff")
    def heading_diff(h1, h2, motion: int):
        """How far (degrees, [0, 360)) h1 lies past h2 turning right; turning any other way, the
        rest of the circle (when beyond EPSILON)."""
        result = h1 - h2

        if abs(result) < EPSILON:
            result = type(result)(0.0)
        if result < -EPSILON:
            result += 360.0
        if result > EPSILON and motion != MotionCommand.TurnRight:
            result = 360.0 - result
        return result

    @staticmethod
    @anchor("MoveToManager::heading_greater", "MoveToManager.cs:heading_greater")
    def heading_greater(h1, h2, motion: int) -> bool:
        """Whether h1 has passed h2 in the turn's direction (across north when they are more than
        180 degrees apart)."""
        diff = abs(h1 - h2)

        if diff <= 180.0:
            v1 = h2
            v2 = h1
        else:
            v1 = h1
            v2 = h2

        result = True if v2 > v1 else False

        if motion != MotionCommand.TurnRight:
            result = not result

        return bool(result)

    @anchor("MoveToManager::is_moving_to", "MoveToManager.cs:is_moving_to")
    def is_moving_to(self) -> bool:
        return self.movement_type != MovementType.Invalid

    @anchor("MoveToManager::stop_aux_command", "MoveToManager.cs:stop_aux_command")
    def stop_aux_command(self, movement_params) -> None:
        if self.aux_command != 0:
            self.stop_motion(self.aux_command, movement_params)
            self.aux_command = 0


__all__ = ["MoveToManager"]
