"""AnimNode: AnimNode(), AnimNode(motion, numAnims) -- a motion and how many of its animations are still queued (ACE's Physics/Animation/AnimNode.cs; MotionTableManager's PendingAnimations hold them)."""

from __future__ import annotations

from dataclasses import dataclass

from ..anchors import anchor


@dataclass(slots=True, eq=False)
class AnimNode:
    motion: int = 0
    num_anims: int = 0

    @staticmethod
    @anchor(None, "AnimNode.cs:AnimNode(uint, uint)")
    def create(motion: int, num_anims: int) -> "AnimNode":
        return AnimNode(motion, num_anims)
