"""The launch solvers (port/trajectory.py, port/trajectory2.py) against ACE's own Trajectory and
Trajectory2 classes, bit for bit, on fresh inputs (live lane only: ``-m live_oracle`` with
ACE_ASSEMBLY set; skipped visibly otherwise).

The inputs are float32 values biased to what a launch hands the solvers -- a launcher's spawn point
and its target's aim point a few metres to ~80 m apart, speeds up to MaxVelocity (50), targets
moving at walking and running speeds -- plus the boundaries the code branches on: the same point,
zero or negative speed and gravity, a target straight above (no ground distance), out of reach (a
negative root), and moving targets whose quartic has fewer than four real roots (where ACE reads
NaN slots). The port computes as the oracle's runtime does: its Math.Sin/Math.Cos are mono's x87
FSIN/FCOS or .NET 10's libm (acconform/x87.py); Vector3 Length, Normalize, Dot and the scalar
products are the same bits on both.
"""

from __future__ import annotations

import random
import warnings

import numpy as np
import pytest
from fn_specs import plain, same

from acconform.errors import OracleUnavailable
from acconform.numerics import EXACT, RUNTIMES, runtime_named
from acconform.port import trajectory, trajectory2

pytestmark = pytest.mark.live_oracle

F = np.float32
N = 1500


@pytest.fixture(scope="module")
def ace():
    from acconform.oracle import live_configured
    from acconform.oracle.functions import AceFunctions

    if not live_configured():
        pytest.skip("no ACE configured: set ACE_ASSEMBLY=/path/to/ACE.Server.dll to run the live-oracle lane")
    try:
        return AceFunctions()
    except OracleUnavailable as e:
        pytest.fail(f"ACE is configured but the function oracle cannot load: {e}")


@pytest.fixture(scope="module")
def runtime(ace):
    return RUNTIMES[runtime_named(ace.runtime_version)]


@pytest.fixture(autouse=True)
def _quiet_numpy():
    with warnings.catch_warnings(), np.errstate(all="ignore"):
        warnings.simplefilter("ignore", RuntimeWarning)
        yield


def f32(x) -> float:
    return float(F(x))


def vec(rng: random.Random, scale: float) -> tuple:
    return tuple(f32(rng.uniform(-scale, scale)) for _ in range(3))


def v3(t):
    return EXACT.vec(*t)


def s(x):
    return F(x)


def launch_pair(rng: random.Random) -> tuple[tuple, tuple]:
    """A spawn point and an aim point as a launch makes them (a launcher ~1.5 m up, a target's
    middle), with the boundary cases mixed in."""
    origin = (f32(rng.uniform(0, 192)), f32(rng.uniform(0, 192)), f32(rng.uniform(0, 60)))
    k = rng.random()
    if k < 0.05:
        return origin, origin  # the same point
    if k < 0.10:
        return origin, (origin[0], origin[1], f32(origin[2] + rng.uniform(-5, 5)))  # straight above/below
    dist = rng.choice([rng.uniform(0.5, 5), rng.uniform(5, 40), rng.uniform(40, 200)])
    ang = rng.uniform(-np.pi, np.pi)
    dz = rng.uniform(-20, 20)
    return origin, (f32(origin[0] + dist * np.cos(ang)), f32(origin[1] + dist * np.sin(ang)), f32(origin[2] + dz))


def speed(rng: random.Random) -> float:
    k = rng.random()
    if k < 0.04:
        return 0.0
    if k < 0.06:
        return f32(-rng.uniform(0, 10))
    return f32(rng.choice([20.0, 50.0, 24.0, rng.uniform(1, 50)]))


def target_velocity(rng: random.Random) -> tuple:
    k = rng.random()
    if k < 0.15:
        return (0.0, 0.0, 0.0)
    if k < 0.3:
        return (f32(rng.uniform(-4, 4)), f32(rng.uniform(-4, 4)), 0.0)  # walking
    if k < 0.4:
        return (f32(rng.uniform(-60, 60)), f32(rng.uniform(-60, 60)), f32(rng.uniform(-10, 10)))  # faster than the shot
    return (f32(rng.uniform(-12, 12)), f32(rng.uniform(-12, 12)), f32(rng.uniform(-3, 3)))


def gravity(rng: random.Random) -> float:
    k = rng.random()
    if k < 0.03:
        return 0.0
    if k < 0.05:
        return f32(-9.8)
    return f32(rng.choice([9.8, 9.8, 9.8, 0.00001, rng.uniform(0.1, 30)]))


def diff(port, ace_answer):
    return [] if same(plain(port), ace_answer) else [(plain(port), ace_answer)]


def run(ace, n: int, make, port_call, ace_call):
    rng = random.Random(f"trajectory-live-{ace_call.__name__}")
    bad = []
    for _ in range(n):
        args = make(rng)
        p = port_call(*args)
        a = ace_call(*args)
        if not same(plain(p), a):
            bad.append((args, plain(p), a))
    assert bad[:3] == [] and len(bad) == 0, f"{len(bad)} of {n} differ"
    return n


@pytest.mark.anchor("Trajectory.cs:solve_ballistic_arc")
def test_fixed_target_arc_is_aces_bit_for_bit(ace, runtime):
    def make(rng):
        o, t = launch_pair(rng)
        return o, speed(rng), t, gravity(rng)

    run(ace, N, make,
        lambda o, sp, t, g: trajectory.solve_ballistic_arc(v3(o), s(sp), v3(t), s(g), runtime),
        ace.solve_ballistic_arc)


@pytest.mark.anchor("Trajectory.cs:solve_ballistic_arc(Vector3, float, Vector3, Vector3, float, out Vector3, out Vector3, out float)")
def test_moving_target_arc_is_aces_bit_for_bit_nan_answers_included(ace, runtime):
    nan_answers = 0

    def make(rng):
        o, t = launch_pair(rng)
        return o, speed(rng), t, target_velocity(rng), gravity(rng)

    def port(o, sp, t, tv, g):
        nonlocal nan_answers
        r = trajectory.solve_ballistic_arc_moving(v3(o), s(sp), v3(t), v3(tv), s(g), runtime)
        if r[0] > 0 and np.isnan(r[1].x):
            nan_answers += 1
        return r

    run(ace, N, make, port, ace.solve_ballistic_arc_moving)
    assert nan_answers > 0, "no input reached ACE's NaN slots: the generator lost that case"


@pytest.mark.anchor("Trajectory.cs:solve_ballistic_arc_lateral(Vector3, float, Vector3, Vector3, float, out Vector3, out float, out Vector3)")
def test_lateral_arc_to_a_moving_target_is_aces_bit_for_bit(ace):
    def make(rng):
        o, t = launch_pair(rng)
        return o, speed(rng), t, target_velocity(rng), rng.choice([f32(-9.8), 0.0, gravity(rng)])

    run(ace, N, make,
        lambda o, sp, t, tv, g: trajectory.solve_ballistic_arc_lateral(v3(o), s(sp), v3(t), v3(tv), s(g)),
        ace.solve_ballistic_arc_lateral)


@pytest.mark.anchor("Trajectory.cs:solve_ballistic_arc_lateral")
def test_lateral_arc_to_a_peak_height_is_aces_bit_for_bit(ace):
    def make(rng):
        o, t = launch_pair(rng)
        return o, speed(rng), t, f32(o[2] + rng.uniform(-2, 20))

    run(ace, N, make,
        lambda o, sp, t, h: trajectory.solve_ballistic_arc_lateral_max_height(v3(o), s(sp), v3(t), s(h)),
        ace.solve_ballistic_arc_lateral_max_height)


@pytest.mark.anchor("Trajectory.cs:SolveBallisticArc")
def test_fixed_gravity_lateral_arc_is_aces_bit_for_bit(ace):
    def make(rng):
        o, t = launch_pair(rng)
        return o, speed(rng), t

    run(ace, N, make,
        lambda o, sp, t: trajectory.solve_ballistic_arc_fixed_gravity(v3(o), s(sp), v3(t)),
        ace.solve_ballistic_arc_fixed_gravity)


@pytest.mark.anchor("Trajectory.cs:ballistic_range")
def test_ballistic_range_is_aces_bit_for_bit(ace, runtime):
    def make(rng):
        return speed(rng), gravity(rng), f32(rng.choice([0.0, -1.0, rng.uniform(0, 50)]))

    run(ace, N, make, lambda sp, g, h: trajectory.ballistic_range(s(sp), s(g), s(h), runtime), ace.ballistic_range)


@pytest.mark.anchor("Trajectory.cs:SolveQuartic")
def test_root_finders_are_aces_bit_for_bit(ace, runtime):
    def coeff(rng):
        return rng.choice([0.0, 1.0, -1.0, rng.uniform(-100, 100), rng.uniform(-1e-3, 1e-3), float(rng.randint(-6, 6))])

    def quartic_from_roots(rng):
        roots = [float(rng.randint(-5, 5)) for _ in range(4)]
        a, b, c, d = roots
        return (1.0, -(a + b + c + d), a * b + a * c + a * d + b * c + b * d + c * d,
                -(a * b * c + a * b * d + a * c * d + b * c * d), a * b * c * d)

    run(ace, N, lambda rng: tuple(coeff(rng) for _ in range(3)), trajectory.solve_quadric, ace.solve_quadric)
    run(ace, N, lambda rng: tuple(coeff(rng) for _ in range(4)), lambda *c: trajectory.solve_cubic(*c, runtime=runtime), ace.solve_cubic)
    run(ace, N, lambda rng: quartic_from_roots(rng) if rng.random() < 0.3 else tuple(coeff(rng) for _ in range(5)),
        lambda *c: trajectory.solve_quartic(*c, runtime=runtime), ace.solve_quartic)


@pytest.mark.anchor("Trajectory2.cs:CalculateTrajectory")
def test_alternate_solver_is_aces_bit_for_bit(ace, runtime):
    def make(rng):
        o, t = launch_pair(rng)
        return o, t, target_velocity(rng), speed(rng), rng.random() < 0.7

    run(ace, N, make,
        lambda o, t, tv, sp, g: trajectory2.calculate_trajectory(v3(o), v3(t), v3(tv), s(sp), g, runtime),
        ace.calculate_trajectory)
