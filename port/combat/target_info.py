"""TargetStatus, TargetInfo (TargetInfo(), TargetInfo(contextID, objectID, radius, quantum), TargetInfo(TargetInfo)).

ACE's Combat/TargetInfo.cs: what a TargetManager hands its PhysicsObj about the object it targets
(or about itself, to a voyeur): where it is, where it will be after the voyeur's quantum, and
whether it is still there. A C# class: mutable here; its Positions are copied where ACE copies them.
`Quantum` and `LastUpdateTime` are doubles (PhysicsTimer.CurrentTime is a double).
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import IntEnum

from acconform.numerics import Vector3

from ..anchors import anchor
from ..frame import AFrame, Position


class TargetStatus(IntEnum):
    """Combat/TargetInfo.cs TargetStatus."""

    Undefined = 0x0
    OK = 0x1
    ExitWorld = 0x2
    Teleported = 0x3
    Contained = 0x4
    Parented = 0x5
    TimedOut = 0x6


@dataclass(slots=True, eq=False)
class TargetInfo:
    context_id: int = 0
    object_id: int = 0
    radius: object = 0.0  # float
    quantum: float = 0.0  # double
    target_position: object = None  # Position
    interpolated_position: object = None  # Position
    interpolated_heading: Vector3 | None = None  # default(Vector3) in ACE: the zero vector
    velocity: Vector3 | None = None  # default(Vector3) in ACE: the zero vector
    status: TargetStatus = TargetStatus.Undefined
    last_update_time: float = 0.0  # double

    @staticmethod
    @anchor(None, "TargetInfo.cs:TargetInfo(uint, uint, float, double)")
    def create(context_id: int, object_id: int, radius, quantum: float, timer) -> "TargetInfo":
        """``new TargetInfo(contextID, objectID, radius, quantum)``; `timer` is the run's PhysicsTimer
        (LastUpdateTime = PhysicsTimer.CurrentTime)."""
        return TargetInfo(context_id=context_id, object_id=object_id, radius=radius, quantum=float(quantum),
                          last_update_time=timer.current_time)

    @anchor(None, "TargetInfo.cs:TargetInfo(TargetInfo)", "the copy constructor")
    def copy(self) -> "TargetInfo":
        """``new TargetInfo(info)``: both Positions copied. ``new Position(null)`` does not throw in
        ACE: it makes a Position in cell 0 with the identity frame, made here in the scalar type and
        runtime of the info's other Position (ACE's callers copy only infos holding both)."""
        target, interpolated = self.target_position, self.interpolated_position
        return TargetInfo(
            context_id=self.context_id,
            object_id=self.object_id,
            radius=self.radius,
            quantum=self.quantum,
            target_position=_copy_position(target, interpolated),
            interpolated_position=_copy_position(interpolated, target),
            interpolated_heading=self.interpolated_heading,
            velocity=self.velocity,
            status=self.status,
            last_update_time=self.last_update_time,
        )


def _copy_position(pos, other):
    """``new Position(pos)``, whose null case is a default Position (in the types of `other`)."""
    if pos is not None:
        return pos.copy()
    origin, orientation = other.frame.origin, other.frame.orientation
    zero, one = type(origin.x)(0.0), type(origin.x)(1.0)
    return Position(0, AFrame(type(origin)(zero, zero, zero), orientation.runtime.quaternion(zero, zero, zero, one)))

__all__ = ["TargetInfo", "TargetStatus"]
