"""ActionNode: ActionNode(), ActionNode(action, speed, stamp, autonomous) -- an action in a motion state's queue (ACE's Physics/Animation/ActionNode.cs)."""

from __future__ import annotations

from dataclasses import dataclass

from ..anchors import anchor


@dataclass(slots=True, eq=False)
class ActionNode:
    action: int = 0
    speed: object = 0.0  # float
    stamp: int = 0
    autonomous: bool = False

    @staticmethod
    @anchor(None, "ActionNode.cs:ActionNode(uint, float, int, bool)")
    def create(action: int, speed, stamp: int, autonomous: bool) -> "ActionNode":
        return ActionNode(action, speed, stamp, autonomous)
