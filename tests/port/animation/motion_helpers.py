"""Hand-built stand-ins for what a MotionInterp asks of others, for tests/port/animation.

`Obj` answers the PhysicsObj calls MotionInterp makes and records them (the motion table's answer
is `WeenieError.None_` unless told); `CreatureWeenie` is ACE's WeenieObject for a creature with no
WorldObject behind it: InqRunRate from MovementSystem.GetRunRate(0, run skill, 1) (a creature's run
skill; 0 with no WorldObject), InqJumpVelocity false, CanJump true, JumpStaminaCost 0 (ACE's
WeenieObject.JumpStaminaCost always answers 0).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from acconform.flags import PhysicsState, TransientState
from acconform.motion_enums import WeenieError
from acconform.numerics import EXACT
from acconform.port.animation import movement_system
from acconform.port.animation.motion_interp import MotionInterp
from acconform.port.frame import AFrame, Position

S = EXACT.scalar


@dataclass
class Obj:
    state: int = PhysicsState.Gravity
    transient_state: int = TransientState.Contact | TransientState.OnWalkable
    cur_cell: object = "cell"
    is_animating: bool = False
    autonomous: bool = True
    answer: WeenieError = WeenieError.None_
    position: object = field(default_factory=lambda: Position(0xA9B40001, AFrame.identity(EXACT)))
    velocity: object = field(default_factory=lambda: EXACT.vec(0, 0, 0))
    calls: list = field(default_factory=list)
    fully_constrained: bool = False

    def do_interpreted_motion(self, motion, params):
        self.calls.append(("do", int(motion), params.speed))
        return self.answer

    def stop_interpreted_motion(self, motion, params):
        self.calls.append(("stop", int(motion)))
        return self.answer

    def remove_link_animations(self):
        self.calls.append(("remove_link_animations",))

    def cancel_moveto(self):
        self.calls.append(("cancel_moveto",))

    def movement_is_autonomous(self):
        return self.autonomous

    def initialize_motion_tables(self):
        self.calls.append(("initialize_motion_tables",))

    def set_local_velocity(self, v, send_event):
        self.calls.append(("set_local_velocity", v.to_tuple()))

    def set_on_walkable(self, on):
        self.calls.append(("set_on_walkable", on))

    def is_fully_constrained(self):
        return self.fully_constrained

    def stop_completely_internal(self):
        self.calls.append(("stop_completely_internal",))

    def unstick_from_object(self):
        self.calls.append(("unstick_from_object",))

    def check_for_completed_motions(self):
        self.calls.append(("check_for_completed_motions",))


@dataclass(frozen=True)
class CreatureWeenie:
    run_skill: int = 0
    is_creature: bool = True
    is_player: bool = False

    def inq_run_rate(self, rate):
        return True, S(movement_system.get_run_rate(S(0.0), self.run_skill, S(1.0)))

    def inq_jump_velocity(self, extent):
        return False, S(0.0)

    def can_jump(self, extent):
        return True

    def jump_stamina_cost(self, extent, stamina_cost):
        return S(0.0)


@dataclass(frozen=True)
class ItemWeenie:
    """WeenieObject.DummyObject (no creature): MotionInterp leaves its motions as they are."""

    is_creature: bool = False

    def inq_run_rate(self, rate):
        return True, S(1.0)

    def inq_jump_velocity(self, extent):
        return False, S(0.0)

    def can_jump(self, extent):
        return True

    def jump_stamina_cost(self, extent, stamina_cost):
        return S(0.0)


def interp(weenie=CreatureWeenie(), obj=None, default_state=True) -> MotionInterp:
    """A MotionInterp on `obj` (a fresh Obj) and `weenie`, in its default state (enter_default_state)
    with the calls that made it forgotten."""
    obj = Obj() if obj is None else obj
    mi = MotionInterp.create(obj, weenie, EXACT)
    if default_state:
        mi.enter_default_state()
    obj.calls.clear()
    return mi
