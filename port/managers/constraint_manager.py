"""ConstraintManager: ConstraintManager(obj), Create, ConstrainTo, IsFullyConstrained, SetPhysicsObject, Unconstrain, UseTime, adjust_offset.

ACE's Managers/ConstraintManager.cs: a leash. ConstrainTo pins a position and two distances; while
the object is in contact with the ground, adjust_offset shortens each frame's offset linearly from
the start distance to nothing at the max distance. Note that ACE measures the leash by the *offset's*
length, not by the distance from the pinned position: ConstraintPosOffset is set to the distance at
ConstrainTo and from then on to the length of the last offset (ACE's code, kept as it is).
"""

from __future__ import annotations

from dataclasses import dataclass

from acconform.flags import TransientState
from acconform.numerics import Vector3

from ..anchors import anchor
from ..constants import CONSTRAINT_FULL_FRACTION


@dataclass(slots=True, eq=False)
class ConstraintManager:
    physics_obj: object = None
    is_constrained: bool = False
    constraint_pos_offset: object = 0.0  # float
    constraint_pos: object = None  # Position
    constraint_distance_start: object = 0.0  # float
    constraint_distance_max: object = 0.0  # float

    @staticmethod
    @anchor("ConstraintManager::Create", "ConstraintManager.cs:Create")
    def create(obj) -> "ConstraintManager":
        """``new ConstraintManager(obj)``: SetPhysicsObject(obj)."""
        manager = ConstraintManager()
        manager.set_physics_object(obj)
        return manager

    @anchor("ConstraintManager::ConstrainTo", "ConstraintManager.cs:ConstrainTo")
    def constrain_to(self, position, start_distance, max_distance) -> None:
        self.is_constrained = True

        self.constraint_pos = position.copy()
        self.constraint_distance_start = start_distance
        self.constraint_distance_max = max_distance
        self.constraint_pos_offset = position.distance(self.physics_obj.position)

    @anchor("ConstraintManager::IsFullyConstrained", "ConstraintManager.cs:IsFullyConstrained")
    def is_fully_constrained(self) -> bool:
        return bool(self.constraint_distance_max * CONSTRAINT_FULL_FRACTION < self.constraint_pos_offset)

    @anchor("ConstraintManager::SetPhysicsObject", "ConstraintManager.cs:SetPhysicsObject")
    def set_physics_object(self, obj) -> None:
        if self.physics_obj is not None:
            self.is_constrained = False
            self.constraint_pos_offset = type(self.constraint_pos_offset)(0.0)
        self.physics_obj = obj

    @anchor("ConstraintManager::UnConstrain", "ConstraintManager.cs:Unconstrain")
    def unconstrain(self) -> None:
        self.is_constrained = False

    @anchor("ConstraintManager::UseTime", "ConstraintManager.cs:UseTime")
    def use_time(self) -> None:
        pass  # empty (ACE)

    @anchor("ConstraintManager::adjust_offset", "ConstraintManager.cs:adjust_offset")
    def adjust_offset(self, offset, quantum: float) -> None:
        """`offset` (an AFrame) is changed in place; `quantum` (a double) is not read."""
        if self.physics_obj is None or not self.is_constrained:
            return

        if self.physics_obj.transient_state & TransientState.Contact:
            if self.constraint_pos_offset < self.constraint_distance_max:
                if self.constraint_pos_offset > self.constraint_distance_start:
                    offset.origin = offset.origin * ((self.constraint_distance_max - self.constraint_pos_offset)
                                                     / (self.constraint_distance_max - self.constraint_distance_start))
            else:
                z = type(offset.origin.x)(0.0)
                offset.origin = Vector3(z, z, z)
        self.constraint_pos_offset = offset.origin.length()


__all__ = ["ConstraintManager"]
