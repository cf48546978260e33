"""Sequence (port/animation/sequence.py) and PartArray.Update: root motion without animations.

Expected values follow Sequence.cs at 7b47913: with an empty AnimList, Update applies
apply_physics(offsetFrame, quantum, quantum): Origin += Velocity * |quantum|, Rotate(Omega * |quantum|).
"""

from __future__ import annotations

import numpy as np
import pytest

from acconform.numerics import EXACT
from acconform.port.frame import AFrame
from acconform.port.part_array import PartArray
from acconform.port.animation.sequence import Sequence

F = np.float32


def v(x, y, z):
    return EXACT.vec(x, y, z)


@pytest.mark.anchor("CSequence::CSequence")
def test_a_new_sequence_has_no_velocity_no_omega_no_animations_and_is_at_its_first_cyclic():
    s = Sequence.create(EXACT)
    assert s.velocity == v(0, 0, 0) and s.omega == v(0, 0, 0) and not s.has_anims() and s.is_first_cyclic()


@pytest.mark.anchor("CSequence::apply_physics")
def test_apply_physics_moves_by_velocity_times_the_quantums_size_signed_by_sign():
    s = Sequence.create(EXACT)
    s.set_velocity(v(1.0, 2.0, -3.0))
    frame = AFrame.identity(EXACT)
    s.apply_physics(frame, F(-0.5), F(1.0))  # sign >= 0: quantum = Math.Abs(quantum)
    assert frame.origin == v(0.5, 1.0, -1.5)
    s.apply_physics(frame, F(0.5), F(-1.0))  # sign < 0: quantum = -Math.Abs(quantum)
    assert frame.origin == v(0.0, 0.0, 0.0)


@pytest.mark.anchor("CSequence::apply_physics")
def test_apply_physics_turns_by_omega_in_the_frames_own_axes():
    s = Sequence.create(EXACT)
    s.set_omega(v(0.0, 0.0, 1.0))
    frame = AFrame.identity(EXACT)
    s.apply_physics(frame, F(0.25), F(0.25))
    rt = EXACT.runtime
    ident = EXACT.quat(0, 0, 0, 1)
    angles = rt.transform_by_quaternion(v(0.0, 0.0, 0.25), ident)  # AFrame.Rotate(Vector3): Transform, then GRotate
    want = rt.quat_normalize(rt.quat_multiply(ident, rt.quat_create_from_yaw_pitch_roll(angles.x, angles.y, angles.z)))
    assert frame.orientation == want


@pytest.mark.anchor("CSequence::update")
def test_update_without_animations_applies_root_motion_and_ignores_a_null_frame():
    s = Sequence.create(EXACT)
    s.set_velocity(v(4.0, 0.0, 0.0))
    frame = AFrame.identity(EXACT)
    s.update(F(0.25), frame)
    assert frame.origin == v(1.0, 0.0, 0.0)
    s.update(F(0.25), None)  # `else if (offsetFrame != null)`: nothing


@pytest.mark.anchor("CPartArray::Update")
def test_part_array_update_casts_the_double_quantum_to_float():
    pa = PartArray.create(EXACT)
    pa.sequence.set_velocity(v(3.0, 0.0, 0.0))
    frame = AFrame.identity(EXACT)
    pa.update(0.1, frame)  # (float)0.1 == 0.1f
    assert frame.origin == v(F(3.0) * F(0.1), 0.0, 0.0)
