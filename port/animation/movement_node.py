"""MovementNode (MovementNode(), MovementNode(type, heading = 0.0f)).

ACE's Animation/MovementNode.cs: one step of a MoveToManager's PendingActions, a move to the
current target (MovementType.MoveToPosition) or a turn to `heading` (MovementType.TurnToHeading).
"""

from __future__ import annotations

from dataclasses import dataclass

from acconform.motion_enums import MovementType

from ..anchors import anchor


@dataclass(slots=True, eq=False)
class MovementNode:
    type: MovementType = MovementType.Invalid
    heading: object = 0.0  # float

    @staticmethod
    @anchor(None, "MovementNode.cs:MovementNode(MovementType, float)")
    def create(type_: MovementType, heading=0.0) -> "MovementNode":
        return MovementNode(type=type_, heading=heading)


__all__ = ["MovementNode"]
