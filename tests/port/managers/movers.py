"""A PhysicsObj stand-in for the managers' tests: the PhysicsObj members the managers call, each
written as ACE's PhysicsObj.cs writes it (over the real port managers), plus recorders for what
leaves the motion layer (the MotionInterp's commands, the weenie's OnMoveComplete).

port/physics_obj.py does not have these members yet (the lead adds them when the managers are
integrated); this double lets each manager be tested on a small hand-built situation meanwhile.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from acconform.flags import SetPositionError, TransientState
from acconform.motion_enums import MovementType, WeenieError
from acconform.numerics import EXACT
from acconform.port.frame import AFrame, Position
from acconform.port.managers.position_manager import PositionManager
from acconform.port.managers.server_object_manager import ServerObjectManager
from acconform.port.managers.target_manager import TargetManager
from acconform.port.physics_timer import PhysicsTimer

MODE = EXACT
F = np.float32


def position(x, y, z=0.0, heading=None, cell=0xA9B40001) -> Position:
    frame = AFrame(MODE.vec(x, y, z), MODE.quat(0, 0, 0, 1))
    if heading is not None:
        frame.set_heading(F(heading))
    return Position(cell, frame)


@dataclass(eq=False)
class Weenie:
    """WeenieObject: records OnMoveComplete and OnMotionDone."""

    moves_completed: list = field(default_factory=list)
    motions_done: list = field(default_factory=list)

    def on_move_complete(self, status):
        self.moves_completed.append(WeenieError(status))

    def on_motion_done(self, motion, success):
        self.motions_done.append((motion, success))


@dataclass(eq=False)
class Minterp:
    """A MotionInterp that records the commands the MoveToManager sends it."""

    max_speed: object = F(0.0)
    adjusted_max_speed: object = F(0.0)
    done: list = field(default_factory=list)
    stopped: list = field(default_factory=list)

    def adjust_motion(self, motion, speed, hold_key):
        return motion, speed

    def do_interpreted_motion(self, motion, movement_params):
        self.done.append(int(motion))
        return WeenieError.None_

    def stop_interpreted_motion(self, motion, movement_params):
        self.stopped.append(int(motion))
        return WeenieError.None_

    def get_max_speed(self):
        return self.max_speed

    def get_adjusted_max_speed(self):
        return self.adjusted_max_speed


@dataclass(eq=False)
class Mover:
    id: int
    position: Position
    timer: PhysicsTimer
    objects: ServerObjectManager
    radius: object = F(0.0)
    height: object = F(0.0)
    transient_state: int = TransientState.Contact
    minterp: Minterp | None = None
    is_animating: bool = False
    cached_velocity: object = None
    weenie_obj: Weenie = field(default_factory=Weenie)
    position_manager: PositionManager | None = None
    target_manager: TargetManager | None = None
    move_to_manager: object = None  # stands in for MovementManager.MoveToManager
    set_positions: list = field(default_factory=list)
    velocities: list = field(default_factory=list)
    stops: int = 0

    def __post_init__(self):
        if self.cached_velocity is None:
            self.cached_velocity = MODE.vec(0, 0, 0)
        self.objects.add_server_object(self)

    # PhysicsObj.cs, as ACE writes each
    def get_heading(self):
        return self.position.frame.get_heading()

    def set_heading(self, degrees, send_event):
        self.position.frame.set_heading(degrees)

    def get_radius(self):
        return self.radius

    def get_height(self):
        return self.height

    def get_minterp(self):
        return self.minterp

    def get_velocity(self):
        return self.cached_velocity

    def get_object_a(self, object_id):
        return self.objects.get_object_a(object_id)

    def get_autonomy_blip_distance(self):
        return 100.0 if (self.position.obj_cell_id & 0xFFFF) < 0x100 else 20.0

    def stop_completely(self, send_event):
        self.stops += 1  # MovementManager.PerformMovement(StopCompletely): the MotionInterp's

    def get_position_manager(self):
        if self.position_manager is None:
            self.position_manager = PositionManager.create(self)
        return self.position_manager

    def get_sticky_object(self):
        return 0 if self.position_manager is None else self.position_manager.get_sticky_object_id()

    def is_interpolating(self):
        return self.position_manager is not None and self.position_manager.is_interpolating()

    def unstick_from_object(self):
        if self.position_manager is not None:
            self.position_manager.unstick()

    def cancel_moveto(self):
        if self.move_to_manager is not None:
            self.move_to_manager.cancel_move_to(WeenieError.ActionCancelled)

    def set_target(self, context_id, object_id, radius, quantum):
        if self.target_manager is None:
            self.target_manager = TargetManager.create(self)
        self.target_manager.set_target(context_id, object_id, radius, quantum)

    def clear_target(self):
        if self.target_manager is not None:
            self.target_manager.clear_target()

    def get_target_quantum(self):
        if self.target_manager is None or self.target_manager.target_info is None:
            return 0.0
        return self.target_manager.target_info.quantum

    def set_target_quantum(self, quantum):
        if self.target_manager is not None:
            self.target_manager.set_target_quantum(quantum)

    def add_voyeur(self, object_id, radius, quantum):
        if self.target_manager is None:
            self.target_manager = TargetManager.create(self)
        self.target_manager.add_voyeur(object_id, radius, quantum)

    def remove_voyeur(self, object_id):
        if self.target_manager is None:
            return False
        return self.target_manager.remove_voyeur(object_id)

    def receive_target_update(self, info):
        if self.target_manager is not None:
            self.target_manager.receive_update(info)

    def handle_update_target(self, target_info):
        if target_info.context_id != 0:
            return
        if self.move_to_manager is not None:
            self.move_to_manager.handle_update_target(target_info)
        if self.position_manager is not None:
            self.position_manager.handle_update_target(target_info)

    def set_position_simple(self, pos, sliding):
        self.set_positions.append(pos)
        self.position = pos.copy()
        return SetPositionError.OK

    def set_velocity(self, velocity, send_event):
        self.velocities.append(velocity)


def world():
    """A clock and an object table for one test."""
    return PhysicsTimer(), ServerObjectManager()


def mover(timer, objects, id=0x50000001, at=(0.0, 0.0), heading=0.0, **kw) -> Mover:
    return Mover(id=id, position=position(*at, heading=heading), timer=timer, objects=objects, **kw)


__all__ = ["MODE", "MovementType", "Minterp", "Mover", "Weenie", "mover", "position", "world"]
