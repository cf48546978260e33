"""InterpretedMotionState: InterpretedMotionState(), AddAction, ApplyMotion, copy_movement_from, InitDefaults, GetNumActions, RemoveAction, RemoveMotion, HasCommands.

ACE's Animation/InterpretedMotionState.cs: the motion as the motion table plays it (forward, a
sidestep right and a turn right, each with a signed speed; MotionInterp.adjust_motion makes it from
the raw commands). The constructor from the network's InterpretedMotionState is not ported (a
client's packet, which no scene carries). Speeds are the run's scalars (float32 in exact mode).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from acconform.motion_enums import CommandMask, MotionCommand

from ..anchors import anchor
from .action_node import ActionNode


@dataclass(slots=True, eq=False)
class InterpretedMotionState:
    current_style: int = MotionCommand.NonCombat  # uint
    forward_command: int = MotionCommand.Ready  # uint
    forward_speed: object = None  # float
    side_step_command: int = 0  # uint
    side_step_speed: object = None  # float
    turn_command: int = 0  # uint
    turn_speed: object = None  # float
    actions: list = field(default_factory=list)  # List<ActionNode>

    @staticmethod
    @anchor("InterpretedMotionState::InterpretedMotionState", "InterpretedMotionState.cs:InterpretedMotionState()",
            "the constructor: InitDefaults")
    def create(mode) -> "InterpretedMotionState":
        state = InterpretedMotionState()
        state.init_defaults(mode)
        return state

    @anchor("InterpretedMotionState::AddAction", "InterpretedMotionState.cs:AddAction")
    def add_action(self, action: int, speed, stamp: int, autonomous: bool) -> None:
        self.actions.append(ActionNode.create(action, speed, stamp, autonomous))

    @anchor("InterpretedMotionState::ApplyMotion", "InterpretedMotionState.cs:ApplyMotion")
    def apply_motion(self, motion: int, movement_params) -> None:
        if motion == MotionCommand.TurnRight:
            self.turn_command = MotionCommand.TurnRight
            self.turn_speed = movement_params.speed

        elif motion == MotionCommand.SideStepRight:
            self.side_step_command = MotionCommand.SideStepRight
            self.side_step_speed = movement_params.speed

        else:
            if motion & CommandMask.SubState:
                self.forward_command = motion
                self.forward_speed = movement_params.speed
            elif motion & CommandMask.Style:
                self.forward_command = MotionCommand.Ready
                self.current_style = motion
            elif motion & CommandMask.Action:
                self.add_action(motion, movement_params.speed, movement_params.action_stamp, movement_params.autonomous)

    @anchor("InterpretedMotionState::copy_movement_from", "InterpretedMotionState.cs:copy_movement_from")
    def copy_movement_from(self, state: "InterpretedMotionState") -> None:
        self.current_style = state.current_style
        self.forward_command = state.forward_command
        self.forward_speed = state.forward_speed
        self.side_step_command = state.side_step_command
        self.side_step_speed = state.side_step_speed
        self.turn_command = state.turn_command
        self.turn_speed = state.turn_speed

    @anchor("InterpretedMotionState::InitDefaults", "InterpretedMotionState.cs:InitDefaults")
    def init_defaults(self, mode) -> None:
        """`mode` gives the speeds' scalar type (ACE's literals 1.0f)."""
        self.actions = []
        self.current_style = MotionCommand.NonCombat
        self.forward_command = MotionCommand.Ready
        self.forward_speed = mode.scalar(1.0)
        self.side_step_command = 0
        self.side_step_speed = mode.scalar(1.0)
        self.turn_command = 0
        self.turn_speed = mode.scalar(1.0)

    @anchor("InterpretedMotionState::GetNumActions", "InterpretedMotionState.cs:GetNumActions")
    def get_num_actions(self) -> int:
        return len(self.actions)

    @anchor("InterpretedMotionState::RemoveAction", "InterpretedMotionState.cs:RemoveAction")
    def remove_action(self) -> int:
        if len(self.actions) == 0:
            return 0

        action = self.actions[0]
        del self.actions[0]
        return action.action

    @anchor("InterpretedMotionState::RemoveMotion", "InterpretedMotionState.cs:RemoveMotion")
    def remove_motion(self, motion: int) -> None:
        if motion == MotionCommand.TurnRight:
            self.turn_command = 0
        elif motion == MotionCommand.SideStepRight:
            self.side_step_command = 0

        else:
            if motion & CommandMask.SubState:
                if self.forward_command == motion:
                    self.forward_command = MotionCommand.Ready
                    self.forward_speed = type(self.forward_speed)(1.0)
            elif motion & CommandMask.Style:
                if self.current_style == motion:
                    self.current_style = MotionCommand.NonCombat

    @anchor(None, "InterpretedMotionState.cs:HasCommands")
    def has_commands(self) -> bool:
        """ACE's (ForwardCommand is left out: its own line is commented out)."""
        return self.side_step_command != 0 or self.turn_command != 0


__all__ = ["InterpretedMotionState"]
