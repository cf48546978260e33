"""MovementParameters: MovementParameters(), MovementParameters(mvp, onlyBits), Flags, CopySome, CopyNonFlag, get_command, get_desired_heading, towards_and_away.

ACE's Animation/MovementParameters.cs: how a motion command or a MoveTo is to be carried out. The
float fields are the run's scalars (float32 in exact mode); C#'s `default` for a field the
constructor leaves alone is 0 (false, HoldKey.Invalid). The constructor from the network's
MoveToParameters is not ported: it is how ACE reads a client's packet, which no scene carries.
"""

from __future__ import annotations

from dataclasses import dataclass

from acconform.motion_enums import HoldKey, MotionCommand

from ..anchors import anchor
from ..constants import DEFAULT_DISTANCE_TO_OBJECT, DEFAULT_WALK_RUN_THRESHOLD, EPSILON, FLOAT_MAX_VALUE
from . import movement_param_flags


@dataclass(slots=True, eq=False)
class MovementParameters:
    can_walk: bool = False
    can_run: bool = False
    can_sidestep: bool = False
    can_walk_backwards: bool = False
    can_charge: bool = False
    fail_walk: bool = False
    use_final_heading: bool = False
    sticky: bool = False
    move_away: bool = False
    move_towards: bool = False
    use_spheres: bool = False
    set_hold_key: bool = False
    autonomous: bool = False
    modify_raw_state: bool = False
    modify_interpreted_state: bool = False
    cancel_move_to: bool = False
    stop_completely: bool = False
    disable_jump_during_link: bool = False

    # floats: set in the run's scalar type by the constructors below
    distance_to_object: object = None
    min_distance: object = None
    desired_heading: object = None
    speed: object = None
    fail_distance: object = None
    walk_run_threshold: object = None

    context_id: int = 0
    hold_key_to_apply: HoldKey = HoldKey.Invalid
    action_stamp: int = 0

    @property
    def flags(self) -> int:
        """``Flags { get => MovementParamFlagsHelper.Get(this) }``."""
        return movement_param_flags.get(self)

    @flags.setter
    def flags(self, value: int) -> None:
        movement_param_flags.set_(self, value)

    @staticmethod
    @anchor(None, "MovementParameters.cs:MovementParameters()")
    def create(mode) -> "MovementParameters":
        s = mode.scalar
        mvp = MovementParameters(
            can_walk=True,
            can_run=True,
            can_sidestep=True,
            can_walk_backwards=True,
            can_charge=True,
            move_towards=True,
            use_spheres=True,
            set_hold_key=True,
            modify_raw_state=True,
            modify_interpreted_state=True,
            cancel_move_to=True,
            stop_completely=True,
            distance_to_object=s(DEFAULT_DISTANCE_TO_OBJECT),
            fail_distance=s(FLOAT_MAX_VALUE),
            desired_heading=s(0.0),
            min_distance=s(0.0),  # Default_MinDistance = 0.0f
            speed=s(1.0),  # Default_Speed = 1.0f
            walk_run_threshold=s(DEFAULT_WALK_RUN_THRESHOLD),
            hold_key_to_apply=HoldKey.Invalid,
        )
        return mvp

    @staticmethod
    @anchor(None, "MovementParameters.cs:MovementParameters(MovementParameters, bool)")
    def create_copy(mvp: "MovementParameters", only_bits: bool = False) -> "MovementParameters":
        """The copy constructor: the flags, and unless `only_bits` the other fields CopyNonFlag copies;
        the parameterless constructor does not run, so what neither sets is C#'s default 0."""
        zero = type(mvp.speed)(0.0)
        result = MovementParameters(distance_to_object=zero, min_distance=zero, desired_heading=zero, speed=zero,
                                    fail_distance=zero, walk_run_threshold=zero)
        result.flags = mvp.flags

        if not only_bits:
            result.copy_non_flag(mvp)
        return result

    @anchor(None, "MovementParameters.cs:CopySome")
    def copy_some(self, mvp: "MovementParameters") -> None:
        """Only some fields (ACE's TODO wonders whether it should be all): not FailWalk,
        UseFinalHeading, Sticky, MoveAway, Autonomous, DisableJumpDuringLink, DesiredHeading,
        ContextID, ActionStamp."""
        self.can_walk = mvp.can_walk
        self.can_run = mvp.can_run
        self.can_sidestep = mvp.can_sidestep
        self.can_walk_backwards = mvp.can_walk_backwards
        self.can_charge = mvp.can_charge
        self.move_towards = mvp.move_towards
        self.use_spheres = mvp.use_spheres
        self.set_hold_key = mvp.set_hold_key
        self.modify_raw_state = mvp.modify_raw_state
        self.modify_interpreted_state = mvp.modify_interpreted_state
        self.cancel_move_to = mvp.cancel_move_to
        self.stop_completely = mvp.stop_completely

        self.distance_to_object = mvp.distance_to_object
        self.fail_distance = mvp.fail_distance
        self.min_distance = mvp.min_distance
        self.speed = mvp.speed
        self.walk_run_threshold = mvp.walk_run_threshold

        self.hold_key_to_apply = mvp.hold_key_to_apply

    @anchor(None, "MovementParameters.cs:CopyNonFlag")
    def copy_non_flag(self, mvp: "MovementParameters") -> None:
        self.distance_to_object = mvp.distance_to_object
        self.fail_distance = mvp.fail_distance
        self.desired_heading = mvp.desired_heading
        self.min_distance = mvp.min_distance
        self.speed = mvp.speed
        self.walk_run_threshold = mvp.walk_run_threshold

        self.context_id = mvp.context_id
        self.hold_key_to_apply = mvp.hold_key_to_apply
        self.action_stamp = mvp.action_stamp

    @anchor("MovementParameters::get_command", "MovementParameters.cs:get_command")
    def get_command(self, dist, heading, motion: int, hold_key: HoldKey, moving_away: bool) -> tuple[int, HoldKey, bool]:
        """`motion`, `hold_key` and `moving_away` are C# refs: returns them after the call."""
        if self.move_towards or not self.move_away:
            if self.move_away:
                motion, moving_away = self.towards_and_away(dist, heading, motion, moving_away)
            else:
                if dist > self.distance_to_object:
                    motion = MotionCommand.WalkForward
                    moving_away = False
                else:
                    motion = 0
        elif self.move_away:
            if dist < self.min_distance:
                motion = MotionCommand.WalkForward
                moving_away = True
            else:
                motion = 0

        if self.can_run and (not self.can_walk or dist - self.distance_to_object > self.walk_run_threshold):
            hold_key = HoldKey.Run
        else:
            hold_key = HoldKey.None_
        return motion, hold_key, moving_away

    @anchor("MovementParameters::get_desired_heading", "MovementParameters.cs:get_desired_heading")
    def get_desired_heading(self, motion: int, moving_away: bool):
        """In the run's scalar type (ACE's float literals 180.0f and 0.0f)."""
        s = type(self.speed)
        if motion == MotionCommand.RunForward or motion == MotionCommand.WalkForward:
            return s(180.0) if moving_away else s(0.0)
        elif motion == MotionCommand.WalkBackwards:
            return s(0.0) if moving_away else s(180.0)
        return s(0.0)  # ACE's `default:` (MoveToManager's CurrentCommand is a walk there: unreachable-branches.json)

    @anchor("MovementParameters::towards_and_away", "MovementParameters.cs:towards_and_away")
    def towards_and_away(self, dist, heading, command: int, moving_away: bool) -> tuple[int, bool]:
        """`command` and `moving_away` are C# refs: returns them after the call."""
        if dist > self.distance_to_object:
            command = MotionCommand.WalkForward
            moving_away = False
        elif dist - self.min_distance < EPSILON:
            command = MotionCommand.WalkBackwards
            moving_away = True
        else:
            command = 0
        return command, moving_away


__all__ = ["MovementParameters"]
