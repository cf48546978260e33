"""InterpolationNodeType, InterpolationNode (InterpolationNode(), InterpolationNode(type, position)).

ACE's Animation/InterpolationNode.cs: one entry of an InterpolationManager's PositionQueue. ACE's
constructor keeps the Position it is given (no copy), so a node shares it with the caller; the
manager's adjust_offset later subtracts the mover's frame from it in place, as ACE does.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import IntEnum

from acconform.numerics import Vector3

from ..anchors import anchor


class InterpolationNodeType(IntEnum):
    InvalidType = 0x0
    PositionType = 0x1
    JumpType = 0x2
    VelocityType = 0x3


@dataclass(slots=True, eq=False)
class InterpolationNode:
    type: InterpolationNodeType = InterpolationNodeType.InvalidType
    position: object = None  # Position (shared with the caller, as ACE keeps the reference)
    velocity: Vector3 | None = None  # default(Vector3) in ACE: the zero vector; nothing here sets it
    extent: object = 0.0  # float

    @staticmethod
    @anchor(None, "InterpolationNode.cs:InterpolationNode(InterpolationNodeType, Position)")
    def create(type_: InterpolationNodeType, position) -> "InterpolationNode":
        return InterpolationNode(type=type_, position=position)


__all__ = ["InterpolationNode", "InterpolationNodeType"]
