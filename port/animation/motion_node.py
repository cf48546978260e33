"""MotionNode: MotionNode(), MotionNode(contextID, motion, jumpErrorCode) -- a motion the interpreter waits on (ACE's Physics/Animation/MotionNode.cs)."""

from __future__ import annotations

from dataclasses import dataclass

from ..anchors import anchor


@dataclass(slots=True, eq=False)
class MotionNode:
    context_id: int = 0
    motion: int = 0
    jump_error_code: int = 0  # WeenieError

    @staticmethod
    @anchor(None, "MotionNode.cs:MotionNode(int, uint, WeenieError)")
    def create(context_id: int, motion: int, jump_error_code: int) -> "MotionNode":
        return MotionNode(context_id, motion, jump_error_code)
