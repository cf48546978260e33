"""The launch solvers (port/trajectory.py, port/trajectory2.py) and mono's x87 sine and cosine
(acconform/x87.py), on cases whose answers are worked out by hand from ACE's code (Trajectory.cs,
Trajectory2.cs at 7b47913); tests/port/functions/test_trajectory_live.py checks them against ACE
itself, bit for bit.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from acconform import x87
from acconform.numerics import EXACT, MONO, NET10
from acconform.port import trajectory, trajectory2
from acconform.port.missile_launch import NO_GRAVITY, get_projectile_velocity

F = np.float32


def v(x, y, z):
    return EXACT.vec(x, y, z)


@pytest.fixture(autouse=True)
def _quiet_numpy():
    with warnings.catch_warnings(), np.errstate(all="ignore"):
        warnings.simplefilter("ignore", RuntimeWarning)
        yield


@pytest.mark.anchor("Trajectory.cs:SolveQuadric")
def test_quadric_gives_both_roots_larger_first_and_none_below_zero_discriminant():
    # x^2 - 3x + 2: p = -1.5, q = 2, D = 0.25, roots sqrt(D) - p = 2 and -sqrt(D) - p = 1
    assert trajectory.solve_quadric(1.0, -3.0, 2.0) == (2, 2.0, 1.0)
    # x^2 - 2x + 1: D = 0, one root -p = 1, s1 left NaN
    n, s0, s1 = trajectory.solve_quadric(1.0, -2.0, 1.0)
    assert (n, s0) == (1, 1.0) and math.isnan(s1)
    # x^2 + 1: D = -1, nothing
    n, s0, s1 = trajectory.solve_quadric(1.0, 0.0, 1.0)
    assert n == 0 and math.isnan(s0) and math.isnan(s1)


@pytest.mark.anchor("Trajectory.cs:SolveQuadric")
def test_quadric_with_a_zero_leading_coefficient_divides_by_zero_as_ieee_does():
    # p = c1 / 0 = inf, q = c2 / 0 = inf, D = inf - inf = NaN: not zero, not below zero, so two NaN roots
    n, s0, s1 = trajectory.solve_quadric(0.0, 1.0, 1.0)
    assert n == 2 and math.isnan(s0) and math.isnan(s1)


@pytest.mark.anchor("Trajectory.cs:SolveQuartic")
def test_quartic_finds_the_four_roots_of_a_product_of_four_factors():
    # (x-1)(x-2)(x-3)(x-4) = x^4 - 10x^3 + 35x^2 - 50x + 24
    n, *roots = trajectory.solve_quartic(1.0, -10.0, 35.0, -50.0, 24.0)
    assert n == 4 and sorted(roots) == [1.0, 2.0, 3.0, 4.0]


@pytest.mark.anchor("Trajectory.cs:SolveQuartic")
def test_quartic_with_no_real_root_leaves_the_resolvent_cubics_root_in_a_slot():
    # x^4 + 1: p = 0, q = 0, r = 1; the resolvent z^3 - z = 0 ... here z^3 + 0z^2 - 1z + 0 has three real
    # roots (s0, s1, s2); u = z^2 - 1 and v = 2z decide; with none real the slots keep cubic values
    n, s0, s1, s2, s3 = trajectory.solve_quartic(1.0, 0.0, 0.0, 0.0, 1.0)
    assert n == 0
    assert math.isnan(s3)
    assert not (math.isnan(s0) and math.isnan(s1) and math.isnan(s2)), "a slot past num holds a cubic root, as in ACE"


@pytest.mark.anchor("Trajectory.cs:SolveCubic")
def test_cubic_roots_of_a_triple_and_of_a_double_root_and_math_pows_nan_for_a_negative_base():
    assert trajectory.solve_cubic(1, 0, 0, 0)[:2] == (1, 0.0)  # x^3: one triple root
    n, s0, s1, _ = trajectory.solve_cubic(1, 0, -3, -2)  # (x + 1)^2 (x - 2): the single root first
    assert (n, s0, s1) == (2, 2.0, -1.0)
    n, s0, s1, _ = trajectory.solve_cubic(1, 0, -3, 2)  # (x - 1)^2 (x + 2): Math.Pow(-1, 1/3) is NaN
    assert n == 2 and math.isnan(s0) and math.isnan(s1)


@pytest.mark.anchor("Trajectory.cs:SolveQuartic")
def test_quartic_of_two_double_roots_solves_its_second_quadric_twice():
    # (t^2 - 1)^2: the resolvent's root sqrt(r) makes u zero; the first quadric's one root, then the second's
    # twice (ACE's `if (num == 1)` and `if (num == 2)` both run it), so the root 1 comes back two times
    assert trajectory.solve_quartic(1, 0, -2, 0, 1)[:4] == (3, -1.0, 1.0, 1.0)


@pytest.mark.anchor("Trajectory.cs:solve_ballistic_arc(Vector3, float, Vector3, Vector3, float, out Vector3, out Vector3, out float)")
def test_an_arrow_spawned_at_its_moving_targets_aim_point_gets_a_nan_lead():
    # no absolute term (r = 0): the cubic y (y^2 + p) with p < 0 (the arrow outruns the target) gives 0 and
    # +-sqrt(-p); the sorted slots read NaN first, so the one "solution" is NaN and LaunchProjectile misfires
    at = v(100, 100, 16)
    n, s0, _, time = trajectory.solve_ballistic_arc_moving(at, F(10), at, v(3, 0, 0), F(9.8))
    assert n == 1 and math.isnan(s0.x) and math.isnan(time)


@pytest.mark.anchor("Trajectory.cs:solve_ballistic_arc")
def test_at_the_maximum_range_the_fixed_target_arc_has_one_solution_at_45_degrees():
    # v = 20, g = 10, x = v^2 / g = 40 at the same height: root = v^4 - g(g x^2) = 160000 - 160000 = 0,
    # lowAng = highAng = atan2(400, 400) = pi/4
    n, s0, s1, t0, t1 = trajectory.solve_ballistic_arc(v(0, 0, 0), F(20), v(40, 0, 0), F(10))
    c = F(math.cos(math.pi / 4))
    assert n == 1
    assert s0 == v(c * F(20), 0.0, F(math.sin(math.pi / 4)) * F(20))
    assert s1 == v(0, 0, 0)  # untouched
    assert t0 == t1 == F(40) / (c * F(20))


@pytest.mark.anchor("Trajectory.cs:solve_ballistic_arc")
def test_fixed_target_arc_gives_nothing_out_of_reach_on_the_same_point_or_without_speed():
    # x = 41 > v^2/g: root < 0
    assert trajectory.solve_ballistic_arc(v(0, 0, 0), F(20), v(41, 0, 0), F(10))[0] == 0
    n, s0, s1, t0, t1 = trajectory.solve_ballistic_arc(v(1, 2, 3), F(20), v(1, 2, 3), F(10))
    assert (n, s0, s1) == (0, v(0, 0, 0), v(0, 0, 0)) and t0 == t1 == np.inf
    assert trajectory.solve_ballistic_arc(v(0, 0, 0), F(0), v(10, 0, 0), F(10))[0] == 0
    assert trajectory.solve_ballistic_arc(v(0, 0, 0), F(20), v(10, 0, 0), F(0))[0] == 0


@pytest.mark.anchor("Trajectory.cs:solve_ballistic_arc(Vector3, float, Vector3, Vector3, float, out Vector3, out Vector3, out float)")
def test_moving_target_arc_reads_nan_slots_when_the_quartic_has_fewer_than_four_roots():
    # A 50 m/s shot from 10 m up at a target 2 m ahead on the ground running away at 50 m/s and
    # falling at 10 m/s: the quartic in time has two real roots; .NET's Array.Sort puts the two NaN
    # slots first and ACE's loop over the first numTimes slots reads only them (t <= 0 is false for
    # NaN): two NaN solutions, and GetProjectileVelocity's answer misfires the launch (ACE on mono
    # and .NET 10 answer the same: the live lane's generator meets this case)
    n, s0, s1, time = trajectory.solve_ballistic_arc_moving(v(0, 0, 10), F(50), v(0, 2, 0), v(0, 50, -10), F(9.8))
    assert n == 2 and math.isnan(s0.x) and math.isnan(s1.z) and math.isnan(time)
    velocity, _ = get_projectile_velocity(v(0, 0, 10), v(0, 2, 0), F(50), v(0, 50, -10))
    assert math.isnan(velocity.x)


@pytest.mark.anchor("Trajectory.cs:solve_ballistic_arc(Vector3, float, Vector3, Vector3, float, out Vector3, out Vector3, out float)")
def test_a_catchable_moving_target_gets_the_earliest_positive_time():
    # a target 10 m ahead walking sideways at 2 m/s, shot at 20 m/s: four real roots, two negative;
    # the first positive one is the time, and the solution leads the target (positive Y)
    n, s0, s1, time = trajectory.solve_ballistic_arc_moving(v(0, 0, 0), F(20), v(10, 0, 0), v(0, 2, 0), F(9.8))
    assert n == 2 and 0 < time < 1 and not math.isnan(s1.x)
    # Y = (J + R t) / t with J = 0, R = 2: 2t / t, exactly 2 in double
    assert s0.y == F(2.0)


@pytest.mark.anchor("Trajectory.cs:solve_ballistic_arc_lateral(Vector3, float, Vector3, Vector3, float, out Vector3, out float, out Vector3)")
def test_lateral_arc_to_a_still_target_without_gravity_flies_straight_at_the_lateral_speed():
    # diffXY = (30, 40): c0 = -100, c1 = 0, c2 = 2500 -> t = 5; fire = Normalize(30, 40, 0) * 10 = (6, 8, 0);
    # Z: (2a - 2c + 0) / (2t) * -1 = (0 - 2*5) / 10 * -1 = 1
    ok, fire, time, impact = trajectory.solve_ballistic_arc_lateral(v(0, 0, 0), F(10), v(30, 40, 5), v(0, 0, 0), F(0))
    assert ok and time == F(5) and impact == v(30, 40, 5)
    assert fire == v(F(30) / F(50) * F(10), F(40) / F(50) * F(10), 1.0)


@pytest.mark.anchor("Trajectory.cs:solve_ballistic_arc_lateral(Vector3, float, Vector3, Vector3, float, out Vector3, out float, out Vector3)")
def test_lateral_arc_fails_on_the_same_point_and_on_a_target_it_cannot_catch():
    assert trajectory.solve_ballistic_arc_lateral(v(1, 1, 1), F(10), v(1, 1, 1), v(0, 0, 0), F(-9.8))[0] is False
    # running away at 20 m/s from a 10 m/s shot: no positive time
    assert trajectory.solve_ballistic_arc_lateral(v(0, 0, 0), F(10), v(10, 0, 0), v(20, 0, 0), F(-9.8))[0] is False


@pytest.mark.anchor("Trajectory2.cs:CalculateTrajectory")
def test_alternate_solver_aims_straight_and_lifts_by_half_gravity_times_time():
    # |(30, 40, 0)| = 50, t = 50 / 10 = 5, result = offset / 5 = (6, 8, 0); gravity: Z -= -9.8 * 5 * 0.5
    r = trajectory2.calculate_trajectory(v(0, 0, 0), v(30, 40, 0), v(0, 0, 0), F(10), True)
    assert r == v(6, 8, F(0) - F(-9.8) * F(5) * F(0.5))


@pytest.mark.anchor("Trajectory2.cs:CalculateTrajectory")
def test_alternate_solver_min_of_a_signed_zero_tie_differs_by_runtime():
    # a target straight above moving sideways: b = c = 0, both roots zero (-0 and +0); mono's Math.Min
    # returns the second (+0), .NET 10's the negative one: Z = dz / t is +inf or -inf
    mono = trajectory2.calculate_trajectory(v(0, 0, 0), v(0, 0, 5), v(1, 0, 0), F(10), False, MONO)
    net10 = trajectory2.calculate_trajectory(v(0, 0, 0), v(0, 0, 5), v(1, 0, 0), F(10), False, NET10)
    assert mono.z == np.inf and net10.z == -np.inf


@pytest.mark.anchor("Trajectory2.cs:CalculateTrajectory")
def test_alternate_solver_answers_the_negative_nan_of_a_negative_square_root_when_the_target_cannot_be_caught():
    # a 0.5 m/s spell at a target 10 m off crossing the line: a = 1 - 0.25 > 0, b = 0, c = 100, so
    # Math.Sqrt(b*b - 4ac) is x64's default NaN (sign bit set, ACE on .NET 10 recorded 0xFFC00000 in the
    # velocity), which both roots and the velocity carry
    for runtime in (MONO, NET10):
        r = trajectory2.calculate_trajectory(v(0, 0, 0), v(10, 0, 0), v(0, 1, 0), F(0.5), False, runtime)
        assert all(int(np.float32(c).view(np.uint32)) == 0xFFC00000 for c in (r.x, r.y, r.z))


@pytest.mark.anchor("Trajectory.cs:SolveCubic")
def test_mono_cosine_is_the_x87s_and_differs_from_libm_near_its_zero():
    # the argument that SolveCubic's -t * Math.Cos(phi + pi/3) met in the differential: mono's answer
    # (measured from ACE on mono) is 3.2371938745723958e-06, libm's (.NET 10's) 3.237193874572398e-06
    x = 1.570793089601022
    assert x87.fcos(x) == 3.2371938745723958e-06
    assert math.cos(x) == 3.237193874572398e-06
    assert x87.fsin(0.5) == math.sin(0.5)
    assert x87.fcos(1e20) == 1e20  # FCOS leaves an argument past 2^63 unchanged


def test_no_gravity_is_the_float_aces_launch_uses():
    assert F(NO_GRAVITY) == F(0.00001)
