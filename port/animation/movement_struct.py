"""MovementStruct (MovementStruct(), MovementStruct(type), MovementStruct(type, motion, params)).

ACE's Animation/MovementStruct.cs: one movement request for a MovementManager (PerformMovement):
its kind, and the motion, object, position and parameters the kind needs.
"""

from __future__ import annotations

from dataclasses import dataclass

from acconform.motion_enums import MovementType

from ..anchors import anchor


@dataclass(slots=True, eq=False)
class MovementStruct:
    type: MovementType = MovementType.Invalid
    motion: int = 0  # uint: a MotionCommand
    object_id: int = 0  # uint
    top_level_id: int = 0  # uint
    position: object = None  # Position
    radius: object = 0.0  # float: set in the run's scalar type by whoever reads it
    height: object = 0.0  # float
    params: object = None  # MovementParameters

    @staticmethod
    @anchor(None, "MovementStruct.cs:MovementStruct(MovementType, uint, MovementParameters)")
    def create(type_: MovementType, motion: int = 0, movement_params=None) -> "MovementStruct":
        """``new MovementStruct(type)`` (motion 0, no parameters) or ``new MovementStruct(type, motion,
        movementParams)`` (the parameters are kept, not copied, as ACE keeps the reference)."""
        return MovementStruct(type=type_, motion=motion, params=movement_params)


__all__ = ["MovementStruct"]
