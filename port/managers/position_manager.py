"""PositionManager: PositionManager(obj), Create, AdjustOffset, ConstrainTo, GetStickyObjectID, HandleUpdateTarget, InterpolateTo, IsFullyConstrained, IsInterpolating, MakeStickyManager, SetPhysicsObject, StickTo, StopInterpolating, Unconstrain, Unstick, UseTime.

ACE's Managers/PositionManager.cs: the three managers that change a frame's offset before
UpdatePositionInternal combines it with the object's frame, each made on first use. AdjustOffset
runs them in ACE's order: interpolation, then sticky (which replaces the origin and heading), then
the constraint (which shortens whatever offset the others left).
"""

from __future__ import annotations

from dataclasses import dataclass

from ..anchors import anchor
from .constraint_manager import ConstraintManager
from .interpolation_manager import InterpolationManager
from .sticky_manager import StickyManager


@dataclass(slots=True, eq=False)
class PositionManager:
    interpolation_manager: InterpolationManager | None = None
    sticky_manager: StickyManager | None = None
    constraint_manager: ConstraintManager | None = None
    physics_obj: object = None

    @staticmethod
    @anchor("PositionManager::Create", "PositionManager.cs:Create")
    def create(physics_obj) -> "PositionManager":
        """``new PositionManager(obj)``: SetPhysicsObject(obj)."""
        manager = PositionManager()
        manager.set_physics_object(physics_obj)
        return manager

    @anchor("PositionManager::adjust_offset", "PositionManager.cs:AdjustOffset")
    def adjust_offset(self, frame, quantum: float) -> None:
        """`frame` (an AFrame) is changed in place; `quantum` is a double."""
        if self.interpolation_manager is not None:
            self.interpolation_manager.adjust_offset(frame, quantum)
        if self.sticky_manager is not None:
            self.sticky_manager.adjust_offset(frame, quantum)
        if self.constraint_manager is not None:
            self.constraint_manager.adjust_offset(frame, quantum)

    @anchor("PositionManager::ConstrainTo", "PositionManager.cs:ConstrainTo")
    def constrain_to(self, position, start_distance, max_distance) -> None:
        if self.constraint_manager is None:
            self.constraint_manager = ConstraintManager.create(self.physics_obj)

        self.constraint_manager.constrain_to(position, start_distance, max_distance)

    @anchor("PositionManager::GetStickyObjectID", "PositionManager.cs:GetStickyObjectID")
    def get_sticky_object_id(self) -> int:
        if self.sticky_manager is None:
            return 0
        return self.sticky_manager.target_id

    @anchor("PositionManager::HandleUpdateTarget", "PositionManager.cs:HandleUpdateTarget")
    def handle_update_target(self, target_info) -> None:
        if self.sticky_manager is not None:
            self.sticky_manager.handle_update_target(target_info)

    @anchor("PositionManager::InterpolateTo", "PositionManager.cs:InterpolateTo")
    def interpolate_to(self, position, keep_heading: bool) -> None:
        if self.interpolation_manager is None:
            self.interpolation_manager = InterpolationManager.create(self.physics_obj)

        self.interpolation_manager.interpolate_to(position, keep_heading)

    @anchor("PositionManager::IsFullyConstrained", "PositionManager.cs:IsFullyConstrained")
    def is_fully_constrained(self) -> bool:
        if self.constraint_manager is None:
            return False
        else:
            return self.constraint_manager.is_fully_constrained()

    @anchor("PositionManager::IsInterpolating", "PositionManager.cs:IsInterpolating")
    def is_interpolating(self) -> bool:
        return self.interpolation_manager is not None and self.interpolation_manager.is_interpolating()

    @anchor("PositionManager::MakeStickyManager", "PositionManager.cs:MakeStickyManager")
    def make_sticky_manager(self) -> None:
        if self.sticky_manager is None:
            self.sticky_manager = StickyManager.create(self.physics_obj)

    @anchor("PositionManager::SetPhysicsObject", "PositionManager.cs:SetPhysicsObject")
    def set_physics_object(self, obj) -> None:
        self.physics_obj = obj
        if self.interpolation_manager is not None:
            self.interpolation_manager.set_physics_object(obj)
        if self.sticky_manager is not None:
            self.sticky_manager.set_physics_object(obj)
        if self.constraint_manager is not None:
            self.constraint_manager.set_physics_object(obj)

    @anchor("PositionManager::StickTo", "PositionManager.cs:StickTo")
    def stick_to(self, object_id: int, radius, height) -> None:
        if self.sticky_manager is None:
            self.make_sticky_manager()

        self.sticky_manager.stick_to(object_id, radius, height)

    @anchor("PositionManager::StopInterpolating", "PositionManager.cs:StopInterpolating")
    def stop_interpolating(self) -> None:
        if self.interpolation_manager is not None:
            self.interpolation_manager.stop_interpolating()

    @anchor("PositionManager::UnConstrain", "PositionManager.cs:Unconstrain")
    def unconstrain(self) -> None:
        if self.constraint_manager is not None:
            self.constraint_manager.unconstrain()

    @anchor("PositionManager::UnStick", "PositionManager.cs:Unstick")
    def unstick(self) -> None:
        if self.sticky_manager is not None:
            self.sticky_manager.handle_exit_world()

    @anchor("PositionManager::UseTime", "PositionManager.cs:UseTime")
    def use_time(self) -> None:
        if self.interpolation_manager is not None:
            self.interpolation_manager.use_time()

        if self.sticky_manager is not None:
            self.sticky_manager.use_time()

        if self.constraint_manager is not None:
            self.constraint_manager.use_time()


__all__ = ["PositionManager"]
