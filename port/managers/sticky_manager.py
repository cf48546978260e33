"""StickyManager: StickyManager(obj), Create, ClearTarget, HandleExitWorld, HandleUpdateTarget, SetPhysicsObject, StickTo, UseTime, adjust_offset.

ACE's Managers/StickyManager.cs: keeps an object glued to a target (a monster on its quarry after
a sticky MoveToObject). StickTo targets the object through the TargetManager; once the target's
first update arrives (HandleUpdateTarget, status OK) adjust_offset replaces each frame's offset by
a step toward the target -- at five times the mover's max speed (15 when it has none), never past
StickyRadius (0.3) from the target's cylinder -- and turns the offset to face it. UseTime drops the
target one second (StickyTime) after StickTo: ACE never extends StickyTimeoutTime.
"""

from __future__ import annotations

from dataclasses import dataclass

from acconform.numerics import Vector3, cast_float

from ..anchors import anchor
from ..combat.target_info import TargetStatus
from ..constants import EPSILON, STICKY_RADIUS
from ..frame import Position
from ..vec import normalize_check_small

STICKY_TIME = 1.0  # StickyManager.StickyTime = 1.0f (exact; added to the double clock)
STICKY_SPEED_FACTOR = 5.0  # adjust_offset: `minterp.get_max_speed() * 5.0f`
STICKY_DEFAULT_SPEED = 15.0  # adjust_offset: `speed = 15.0f` when the mover has no speed


@dataclass(slots=True, eq=False)
class StickyManager:
    target_id: int = 0
    target_radius: object = 0.0  # float
    target_position: object = None  # Position
    physics_obj: object = None
    initialized: bool = False
    sticky_timeout_time: float = 0.0  # double

    @staticmethod
    @anchor("StickyManager::Create", "StickyManager.cs:Create")
    def create(obj) -> "StickyManager":
        """``new StickyManager(obj)``: SetPhysicsObject(obj)."""
        manager = StickyManager()
        manager.set_physics_object(obj)
        return manager

    @anchor("StickyManager::ClearTarget", "StickyManager.cs:ClearTarget")
    def clear_target(self) -> None:
        if self.target_id == 0:
            return

        self.target_id = 0
        self.initialized = False

        self.physics_obj.clear_target()
        self.physics_obj.cancel_moveto()

    @anchor("StickyManager::HandleExitWorld", "StickyManager.cs:HandleExitWorld")
    def handle_exit_world(self) -> None:
        self.clear_target()

    @anchor("StickyManager::HandleUpdateTarget", "StickyManager.cs:HandleUpdateTarget")
    def handle_update_target(self, target_info) -> None:
        if target_info.object_id != self.target_id:
            return

        if target_info.status == TargetStatus.OK:
            self.initialized = True
            self.target_position = target_info.target_position  # the info's Position itself (ACE keeps the reference)
        elif self.target_id != 0:
            self.clear_target()

    @anchor("StickyManager::SetPhysicsObject", "StickyManager.cs:SetPhysicsObject")
    def set_physics_object(self, obj) -> None:
        self.physics_obj = obj

    @anchor("StickyManager::StickTo", "StickyManager.cs:StickTo")
    def stick_to(self, object_id: int, target_radius, target_height) -> None:
        if self.target_id != 0:
            self.clear_target()

        self.target_id = object_id
        self.initialized = False
        self.target_radius = target_radius
        self.sticky_timeout_time = self.physics_obj.timer.current_time + STICKY_TIME
        self.physics_obj.set_target(0, object_id, 0.5, 0.5)

    @anchor("StickyManager::UseTime", "StickyManager.cs:UseTime")
    def use_time(self) -> None:
        # PhysicsTimer.CurrentTime: the clock of the object's run (a StickyManager always has one)
        if self.physics_obj.timer.current_time > self.sticky_timeout_time:
            self.clear_target()

    @anchor("StickyManager::adjust_offset", "StickyManager.cs:adjust_offset")
    def adjust_offset(self, offset, quantum: float) -> None:
        """`offset` (an AFrame) is changed in place: origin and heading; `quantum` is a double."""
        if self.physics_obj is None or self.target_id == 0 or not self.initialized:
            return

        target = self.physics_obj.get_object_a(self.target_id)
        target_position = self.target_position if target is None else target.position

        offset.origin = self.physics_obj.position.get_offset(target_position)
        offset.origin = self.physics_obj.position.global_to_local_vec(offset.origin)
        zero = type(offset.origin.z)(0.0)
        offset.origin = offset.origin.with_z(zero)

        radius = self.physics_obj.get_radius()
        dist = Position.cylinder_distance_no_z(radius, self.physics_obj.position, self.target_radius, target_position) - STICKY_RADIUS

        small, offset.origin = normalize_check_small(offset.origin)
        if small:
            offset.origin = Vector3(zero, zero, zero)

        speed = zero
        minterp = self.physics_obj.get_minterp()
        if minterp is not None:
            speed = minterp.get_max_speed() * STICKY_SPEED_FACTOR

        if speed < EPSILON:
            speed = type(zero)(STICKY_DEFAULT_SPEED)

        delta = speed * cast_float(speed, quantum)
        if delta >= abs(dist):
            delta = dist

        offset.origin = offset.origin * delta

        cur_heading = self.physics_obj.position.frame.get_heading()
        target_heading = self.physics_obj.position.heading(target_position)
        heading = target_heading - cur_heading
        if abs(heading) < EPSILON:
            heading = type(heading)(0.0)
        if heading < -EPSILON:
            heading += 360.0

        offset.set_heading(heading)


__all__ = ["StickyManager"]
