"""MotionState (MotionState(), MotionState(state), add_action, add_modifier, add_modifier_no_check, clear_actions, clear_modifiers, remove_action_head, remove_modifier) and Motion (Motion(id, speedMod)) -- a motion table's state: style, substate and its speed, modifiers, actions.

ACE's Physics/Animation/MotionState.cs, and Physics/Animation/Motion.cs (Animation.Internal.Motion:
an id and a speed, four lines of C#) which only MotionState's lists hold. Modifiers and Actions are
.NET LinkedLists (port/linked_list.py): MotionTable holds their nodes (remove_modifier takes a node).
The copy constructor copies the lists, not the Motions in them (the same objects).
"""

from __future__ import annotations

from dataclasses import dataclass

from ..anchors import anchor
from ..linked_list import LinkedList


@dataclass(slots=True, eq=False)
class Motion:
    id: int = 0
    speed_mod: object = 1.0  # float

    @staticmethod
    @anchor(None, "Motion.cs:Motion(uint, float)")
    def create(id: int, speed_mod) -> "Motion":
        return Motion(id, speed_mod)


@dataclass(slots=True, eq=False)
class MotionState:
    style: int = 0
    substate: int = 0
    substate_mod: object = 1.0  # float
    modifiers: LinkedList | None = None  # of Motion
    actions: LinkedList | None = None  # of Motion

    @staticmethod
    @anchor("MotionState::CMotionState", "MotionState.cs:MotionState()")
    def create(mode) -> "MotionState":
        return MotionState(0, 0, mode.scalar(1.0), LinkedList(), LinkedList())

    @staticmethod
    @anchor("MotionState::CMotionState", "MotionState.cs:MotionState(MotionState)", "the copy constructor")
    def copy_of(state: "MotionState") -> "MotionState":
        copy = MotionState(state.style, state.substate, state.substate_mod)
        copy.modifiers = LinkedList()
        for modifier in state.modifiers:
            copy.modifiers.add_last(modifier)
        copy.actions = LinkedList()
        for action in state.actions:
            copy.actions.add_last(action)
        return copy

    @anchor("MotionState::add_action", "MotionState.cs:add_action")
    def add_action(self, action: int, speed_mod) -> None:
        self.actions.add_last(Motion.create(action, speed_mod))

    @anchor("MotionState::add_modifier", "MotionState.cs:add_modifier")
    def add_modifier(self, _modifier: int, speed_mod) -> bool:
        if self.substate == _modifier:
            return False

        for modifier in self.modifiers:
            if modifier.id == _modifier:
                return False
        self.add_modifier_no_check(_modifier, speed_mod)
        return True

    @anchor("MotionState::add_modifier_no_check", "MotionState.cs:add_modifier_no_check")
    def add_modifier_no_check(self, modifier: int, speed_mod) -> None:
        self.modifiers.add_first(Motion.create(modifier, speed_mod))

    @anchor("MotionState::clear_actions", "MotionState.cs:clear_actions")
    def clear_actions(self) -> None:
        self.actions.clear()

    @anchor("MotionState::clear_modifiers", "MotionState.cs:clear_modifiers")
    def clear_modifiers(self) -> None:
        self.modifiers.clear()

    @anchor("MotionState::remove_action_head", "MotionState.cs:remove_action_head")
    def remove_action_head(self) -> None:
        if self.actions.count > 0:
            self.actions.remove_first()

    @anchor("MotionState::remove_modifier", "MotionState.cs:remove_modifier")
    def remove_modifier(self, modifier) -> None:
        """`modifier` is a node of Modifiers (LinkedListNode<Motion>)."""
        if modifier is None:
            return

        self.modifiers.remove_node(modifier)
