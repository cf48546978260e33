"""RawMotionState: RawMotionState(), AddAction, SetState, ApplyMotion, InitDefaults, RemoveAction, RemoveMotion.

ACE's Animation/RawMotionState.cs: the motion commands as the client sent them (walk backward,
turn left, ...), with the hold key each was given; MotionInterp.adjust_motion turns them into the
InterpretedMotionState the motion table plays. SetState takes the network's RawMotionState (a
MoveToState's: a scene's tick input ``motion``, acconform.motion_scene.MotionInput). Speeds are the
run's scalars (float32 in exact mode).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from acconform.motion_enums import CommandMask, HoldKey, MotionCommand

from ..anchors import anchor
from .action_node import ActionNode


@dataclass(slots=True, eq=False)
class RawMotionState:
    actions: list = field(default_factory=list)  # List<ActionNode>
    current_hold_key: HoldKey = HoldKey.None_
    current_style: int = MotionCommand.NonCombat  # uint
    forward_command: int = MotionCommand.Ready  # uint
    forward_hold_key: HoldKey = HoldKey.Invalid
    forward_speed: object = None  # float
    side_step_command: int = 0  # uint
    side_step_hold_key: HoldKey = HoldKey.Invalid
    side_step_speed: object = None  # float
    turn_command: int = 0  # uint
    turn_hold_key: HoldKey = HoldKey.Invalid
    turn_speed: object = None  # float

    @anchor(None, "RawMotionState.cs:SetState", "from Network.Structure.RawMotionState (a scene's MotionInput)")
    def set_state(self, state, mode) -> None:
        s = mode.scalar
        self.current_hold_key = HoldKey(state.hold_key)
        self.current_style = state.style
        if self.current_style == 0:
            self.current_style = MotionCommand.NonCombat
        self.forward_command = state.forward
        if self.forward_command == 0:
            self.forward_command = MotionCommand.Ready
        self.forward_hold_key = HoldKey(state.forward_hold_key)
        self.forward_speed = s(state.forward_speed)  # todo: verifications (ACE)
        if self.forward_speed == 0:
            self.forward_speed = s(1.0)
        self.side_step_command = state.sidestep
        self.side_step_hold_key = HoldKey(state.sidestep_hold_key)
        self.side_step_speed = s(state.sidestep_speed)
        if self.side_step_speed == 0:
            self.side_step_speed = s(1.0)
        self.turn_command = state.turn
        self.turn_hold_key = HoldKey(state.turn_hold_key)
        self.turn_speed = s(state.turn_speed)
        if self.turn_speed == 0:
            self.turn_speed = s(1.0)

    @staticmethod
    @anchor("RawMotionState::RawMotionState", "RawMotionState.cs:RawMotionState()", "the constructor: InitDefaults")
    def create(mode) -> "RawMotionState":
        state = RawMotionState()
        state.init_defaults(mode)
        return state

    @anchor("RawMotionState::AddAction", "RawMotionState.cs:AddAction")
    def add_action(self, action: int, speed, stamp: int, autonomous: bool) -> None:
        self.actions.append(ActionNode.create(action, speed, stamp, autonomous))

    @anchor("RawMotionState::ApplyMotion", "RawMotionState.cs:ApplyMotion")
    def apply_motion(self, motion: int, movement_params) -> None:
        if motion == MotionCommand.TurnRight or motion == MotionCommand.TurnLeft:
            self.turn_command = motion
            if movement_params.set_hold_key:
                self.turn_hold_key = HoldKey.Invalid
                self.turn_speed = movement_params.speed
            else:
                self.turn_hold_key = movement_params.hold_key_to_apply
                self.turn_speed = movement_params.speed

        elif motion == MotionCommand.SideStepRight or motion == MotionCommand.SideStepLeft:
            self.side_step_command = motion
            if movement_params.set_hold_key:
                self.side_step_hold_key = HoldKey.Invalid
                self.side_step_speed = movement_params.speed
            else:
                self.side_step_hold_key = movement_params.hold_key_to_apply
                self.side_step_speed = movement_params.speed

        else:
            if motion & CommandMask.SubState:
                if motion != MotionCommand.RunForward:
                    self.forward_command = motion
                    if movement_params.set_hold_key:
                        self.forward_hold_key = HoldKey.Invalid
                        self.forward_speed = movement_params.speed
                    else:
                        self.forward_hold_key = movement_params.hold_key_to_apply
                        self.forward_speed = movement_params.speed
            elif motion & CommandMask.Style:
                if self.current_style != motion:
                    self.forward_command = MotionCommand.Ready
                    self.current_style = motion
            elif motion & CommandMask.Action:
                self.add_action(motion, movement_params.speed, movement_params.action_stamp, movement_params.autonomous)

    @anchor("RawMotionState::InitDefaults", "RawMotionState.cs:InitDefaults")
    def init_defaults(self, mode) -> None:
        """`mode` gives the speeds' scalar type (ACE's literals 1.0f)."""
        self.actions = []

        self.current_hold_key = HoldKey.None_
        self.current_style = MotionCommand.NonCombat
        self.forward_command = MotionCommand.Ready
        self.forward_hold_key = HoldKey.Invalid
        self.forward_speed = mode.scalar(1.0)
        self.side_step_command = 0
        self.side_step_hold_key = HoldKey.Invalid
        self.side_step_speed = mode.scalar(1.0)
        self.turn_command = 0
        self.turn_hold_key = HoldKey.Invalid
        self.turn_speed = mode.scalar(1.0)

    @anchor("RawMotionState::RemoveAction", "RawMotionState.cs:RemoveAction")
    def remove_action(self) -> int:
        if len(self.actions) == 0:
            return 0

        action = self.actions[0]
        del self.actions[0]
        return action.action

    @anchor("RawMotionState::RemoveMotion", "RawMotionState.cs:RemoveMotion")
    def remove_motion(self, motion: int) -> None:
        if motion == MotionCommand.TurnRight or motion == MotionCommand.TurnLeft:
            self.turn_command = 0

        elif motion == MotionCommand.SideStepRight or motion == MotionCommand.SideStepLeft:
            self.side_step_command = 0

        else:
            if motion & CommandMask.SubState:
                if motion == self.forward_command:
                    self.forward_command = MotionCommand.Ready
                    self.forward_speed = type(self.forward_speed)(1.0)
            elif motion & CommandMask.Style:
                if motion == self.current_style:
                    self.current_style = MotionCommand.NonCombat


__all__ = ["RawMotionState"]
