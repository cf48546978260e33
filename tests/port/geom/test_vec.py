"""port/vec.py: ACE's Vec helpers and Vector3/Plane extensions, hand-checked."""

from __future__ import annotations

import math

import numpy as np
import pytest

from acconform.numerics import EXACT, Plane
from acconform.port.constants import EPSILON
from acconform.port.vec import Side, cs_sqrt, get_side, is_zero, length_squared_2d, set_height, snap_to_plane

F = np.float32


def v(x, y, z):
    return EXACT.vec(x, y, z)


@pytest.mark.anchor("Plane::GetSide")
def test_get_side_calls_within_epsilon_close():
    p = Plane(v(0, 0, 1), F(0))
    assert get_side(p, v(0, 0, EPSILON)) == Side.Close and get_side(p, v(0, 0, -EPSILON)) == Side.Close
    assert get_side(p, v(0, 0, 0.001)) == Side.Front and get_side(p, v(0, 0, -0.001)) == Side.Behind


@pytest.mark.anchor("Plane::set_height")
def test_set_height_puts_the_point_on_a_sloped_plane_and_refuses_a_wall():
    p = Plane(v(0, F(0.6), F(0.8)), F(-1.6))  # z = (1.6 - 0.6 y) / 0.8
    ok, out = set_height(p, v(3, 1, 99))
    assert ok and out == v(3, 1, -((F(1) * F(0.6) + F(3) * F(0) + F(-1.6)) / F(0.8)))
    assert set_height(Plane(v(1, 0, 0), F(0)), v(1, 2, 3)) == (False, v(1, 2, 3))


@pytest.mark.anchor("Plane::SnapToPlane")
def test_snap_to_plane_of_a_flat_plane_zeroes_z():
    assert snap_to_plane(Plane(v(0, 0, 1), F(-2)), v(1, 2, 3)) == v(1, 2, 0)


@pytest.mark.anchor("Vec::IsZero")
def test_is_zero_is_strict_at_epsilon_and_length_squared_2d_widens_to_double():
    assert is_zero(v(0, 0, np.nextafter(F(EPSILON), F(0)))) and not is_zero(v(0, 0, EPSILON))
    d = length_squared_2d(v(0.1, 0.2, 5))
    assert type(d) is np.float64 and d == float(F(0.1) * F(0.1) + F(0.2) * F(0.2))


@pytest.mark.anchor("Math::Sqrt")
def test_cs_sqrt_gives_nan_for_a_negative_argument_as_csharp_does():
    assert math.isnan(cs_sqrt(F(-1))) and type(cs_sqrt(F(4))) is np.float64 and cs_sqrt(F(4)) == 2.0
