"""Trajectory: IsZero, SolveQuadric, SolveCubic, SolveQuartic, ballistic_range, solve_ballistic_arc (fixed target, moving target), SolveBallisticArc, solve_ballistic_arc_lateral (max height, moving target).

ACE's Physics/Trajectory.cs (Forrest Smith's public-domain solvers, the root finders from Graphics
Gems I), which the server's launch code calls: Creature.GetProjectileVelocity (arrows, bolts, thrown
weapons) calls solve_ballistic_arc, the moving-target overload when the target moves and the
fixed-target one otherwise; WorldObject.CalculateProjectileVelocity (spell projectiles) calls the
moving-target solve_ballistic_arc_lateral. The rest are ported for completeness (ACE calls none of
them).

C# ``out`` parameters come back in a tuple after the result, in ACE's order. The root finders are
all double (``np.float64``: IEEE division, so a zero leading coefficient gives inf/NaN as in C#,
never a Python ZeroDivisionError); the arc solvers are float32 where ACE declares floats, double
where ``Math`` returns a double, cast back where ACE casts. ``Math.Pow`` of a negative base and
``Math.Acos`` out of [-1, 1] are NaN as in C# (Python would raise). ``Math.Sin``/``Math.Cos`` are
the runtime's: mono's JIT computes them with the x87 (acconform/x87.py), .NET 10 with libm, and
near their zeros the two differ in the last bits; `runtime` says which (mono by default, as the
port's modes are).

Kept as ACE has them, since they decide the launch velocity:

* the moving-target solve_ballistic_arc sorts all four root slots, NaN first (.NET's Array.Sort
  orders NaN below every number), then reads only the first ``numTimes`` of them: with fewer than
  four real roots it reads NaN slots (``t <= 0`` is false for NaN) and returns NaN solutions, so
  LaunchProjectile's IsValid check misfires the shot;
* SolveQuartic leaves the resolvent cubic's third root in ``s2`` when the quadrics give fewer than
  three roots, and solves the second quadric twice when the first gave one root.
"""

from __future__ import annotations

import math

from acconform import x87
from acconform.numerics import MONO, D, Runtime, Vector3, cast_float, dot, normalize

from .anchors import anchor
from .constants import GRAVITY
from .vec import zero_like

NAN = D(math.nan)


def _pow(x, y):
    """C# ``Math.Pow`` on doubles: NaN for a negative base and a fractional exponent."""
    try:
        return D(math.pow(float(x), float(y)))
    except ValueError:
        return NAN
    except OverflowError:
        return D(math.inf)


def _acos(x):
    """C# ``Math.Acos``: NaN outside [-1, 1]."""
    try:
        return D(math.acos(float(x)))
    except ValueError:
        return NAN


def _sqrt(x):
    """C# ``Math.Sqrt``: NaN for a negative argument."""
    x = float(x)
    return D(math.sqrt(x)) if x >= 0.0 else NAN


def _cos(x, runtime: Runtime):
    """C# ``Math.Cos``: mono's JIT runs x87 FCOS (acconform/x87.py), .NET 10 libm's cos."""
    if runtime.name == "mono":
        return D(x87.fcos(x))
    x = float(x)
    return D(math.cos(x)) if math.isfinite(x) else NAN


def _sin(x, runtime: Runtime):
    """C# ``Math.Sin``: mono's JIT runs x87 FSIN (acconform/x87.py), .NET 10 libm's sin."""
    if runtime.name == "mono":
        return D(x87.fsin(x))
    x = float(x)
    return D(math.sin(x)) if math.isfinite(x) else NAN


def _sort_key(t: float):
    """.NET's Array.Sort order for doubles: NaN below every number (stable otherwise: ACE's four
    slots sort by insertion, and only the -0/+0 tie could differ, which ``t <= 0`` skips alike)."""
    return (0, 0.0) if t != t else (1, float(t))


@anchor(None, "Trajectory.cs:IsZero")
def is_zero(d) -> bool:
    eps = 1e-9
    return -eps < d < eps


@anchor(None, "Trajectory.cs:SolveQuadric")
def solve_quadric(c0, c1, c2):
    """c0*x^2 + c1*x + c2 = 0: (num, s0, s1), unset roots NaN."""
    c0, c1, c2 = D(c0), D(c1), D(c2)
    s0 = NAN
    s1 = NAN

    # normal form: x^2 + px + q = 0
    p = c1 / (2 * c0)
    q = c2 / c0

    disc = p * p - q

    if is_zero(disc):
        s0 = -p
        return 1, s0, s1
    elif disc < 0:
        return 0, s0, s1
    else:
        sqrt_d = _sqrt(disc)

        s0 = sqrt_d - p
        s1 = -sqrt_d - p
        return 2, s0, s1


@anchor(None, "Trajectory.cs:SolveCubic")
def solve_cubic(c0, c1, c2, c3, runtime: Runtime = MONO):
    """c0*x^3 + c1*x^2 + c2*x + c3 = 0: (num, s0, s1, s2), unset roots NaN."""
    c0, c1, c2, c3 = D(c0), D(c1), D(c2), D(c3)
    s0 = NAN
    s1 = NAN
    s2 = NAN

    # normal form: x^3 + Ax^2 + Bx + C = 0
    a = c1 / c0
    b = c2 / c0
    c = c3 / c0

    # substitute x = y - A/3 to eliminate the quadric term: x^3 + px + q = 0
    sq_a = a * a
    p = 1.0 / 3 * (-1.0 / 3 * sq_a + b)
    q = 1.0 / 2 * (2.0 / 27 * a * sq_a - 1.0 / 3 * a * b + c)

    # Cardano's formula
    cb_p = p * p * p
    disc = q * q + cb_p

    if is_zero(disc):
        if is_zero(q):  # one triple solution
            s0 = D(0.0)
            num = 1
        else:  # one single and one double solution
            u = _pow(-q, 1.0 / 3.0)
            s0 = 2 * u
            s1 = -u
            num = 2
    elif disc < 0:  # casus irreducibilis: three real solutions
        phi = 1.0 / 3 * _acos(-q / _sqrt(-cb_p))
        t = 2 * _sqrt(-p)

        s0 = t * _cos(phi, runtime)
        s1 = -t * _cos(phi + math.pi / 3, runtime)
        s2 = -t * _cos(phi - math.pi / 3, runtime)
        num = 3
    else:  # one real solution
        sqrt_d = _sqrt(disc)
        u = _pow(sqrt_d - q, 1.0 / 3.0)
        v = -_pow(sqrt_d + q, 1.0 / 3.0)

        s0 = u + v
        num = 1

    # resubstitute
    sub = 1.0 / 3 * a

    if num > 0:
        s0 -= sub
    if num > 1:
        s1 -= sub
    if num > 2:
        s2 -= sub

    return num, s0, s1, s2


@anchor(None, "Trajectory.cs:SolveQuartic")
def solve_quartic(c0, c1, c2, c3, c4, runtime: Runtime = MONO):
    """c0*x^4 + ... + c4 = 0: (num, s0, s1, s2, s3). A slot past `num` may hold a stale root."""
    c0, c1, c2, c3, c4 = D(c0), D(c1), D(c2), D(c3), D(c4)
    s0 = s1 = s2 = s3 = NAN

    # normal form: x^4 + Ax^3 + Bx^2 + Cx + D = 0
    a = c1 / c0
    b = c2 / c0
    c = c3 / c0
    d = c4 / c0

    # substitute x = y - A/4 to eliminate the cubic term: x^4 + px^2 + qx + r = 0
    sq_a = a * a
    p = -3.0 / 8 * sq_a + b
    q = 1.0 / 8 * sq_a * a - 1.0 / 2 * a * b + c
    r = -3.0 / 256 * sq_a * sq_a + 1.0 / 16 * sq_a * b - 1.0 / 4 * a * c + d

    if is_zero(r):
        # no absolute term: y(y^3 + py + q) = 0
        num, s0, s1, s2 = solve_cubic(D(1), D(0), p, q, runtime)
    else:
        # solve the resolvent cubic ...
        _, s0, s1, s2 = solve_cubic(D(1), -1.0 / 2 * p, -r, 1.0 / 2 * r * p - 1.0 / 8 * q * q, runtime)

        # ... and take the one real solution ...
        z = s0

        # ... to build two quadric equations
        u = z * z - r
        v = 2 * z - p

        if is_zero(u):
            u = D(0.0)
        elif u > 0:
            u = _sqrt(u)
        else:
            return 0, s0, s1, s2, s3

        if is_zero(v):
            v = D(0.0)
        elif v > 0:
            v = _sqrt(v)
        else:
            return 0, s0, s1, s2, s3

        num, s0, s1 = solve_quadric(D(1), -v if q < 0 else v, z - u)

        c1_second = v if q < 0 else -v
        c2_second = z + u

        if num == 0:
            n, s0, s1 = solve_quadric(D(1), c1_second, c2_second)
            num += n
        if num == 1:
            n, s1, s2 = solve_quadric(D(1), c1_second, c2_second)
            num += n
        if num == 2:
            n, s2, s3 = solve_quadric(D(1), c1_second, c2_second)
            num += n

    # resubstitute
    sub = 1.0 / 4 * a

    if num > 0:
        s0 -= sub
    if num > 1:
        s1 -= sub
    if num > 2:
        s2 -= sub
    if num > 3:
        s3 -= sub

    return num, s0, s1, s2, s3


@anchor(None, "Trajectory.cs:ballistic_range")
def ballistic_range(speed, gravity, initial_height, runtime: Runtime = MONO):
    """The range at 45 degrees (a float); speed and gravity > 0, initial_height >= 0, else 0."""
    if speed <= 0 or gravity <= 0 or initial_height < 0:
        return cast_float(speed, 0.0)

    angle = D(45 * 0.0174533)  # no air resistance: 45 degrees gives the maximum range (ACE)
    cos = _cos(angle, runtime)
    sin = _sin(angle, runtime)

    # float products stay float until they meet a double, as C# widens them
    rng = (D(speed) * cos / D(gravity)) * (D(speed) * sin + _sqrt(D(speed * speed) * sin * sin + D(2 * gravity * initial_height)))
    return cast_float(speed, rng)


@anchor(None, "Trajectory.cs:solve_ballistic_arc", "the fixed-target overload (s0, s1, t0, t1)")
def solve_ballistic_arc(proj_pos: Vector3, proj_speed, target: Vector3, gravity, runtime: Runtime = MONO):
    """Firing solutions at `proj_speed` under `gravity` (positive down) to a fixed point:
    (num, s0 low angle, s1 high angle, t0, t1). Creature.GetProjectileVelocity's stationary solver
    (gravity 9.8: -PhysicsGlobals.Gravity)."""
    s = type(proj_speed)
    s0 = zero_like(proj_speed)
    s1 = zero_like(proj_speed)
    t0 = s(math.inf)
    t1 = s(math.inf)

    if proj_pos == target or proj_speed <= 0 or gravity <= 0:
        return 0, s0, s1, t0, t1

    diff = target - proj_pos
    diff_xy = Vector3(diff.x, diff.y, s(0.0))
    ground_dist = diff_xy.length()

    speed2 = proj_speed * proj_speed
    speed4 = proj_speed * proj_speed * proj_speed * proj_speed
    z = diff.z
    x = ground_dist
    gx = gravity * x

    root = speed4 - gravity * (gravity * x * x + 2 * z * speed2)

    # no solution
    if root < 0:
        return 0, s0, s1, t0, t1

    root = cast_float(proj_speed, _sqrt(root))

    low_ang = D(math.atan2(float(speed2 - root), float(gx)))
    high_ang = D(math.atan2(float(speed2 + root), float(gx)))
    num_solutions = 2 if low_ang != high_ang else 1

    ground_dir = normalize(diff_xy)
    unit_z = Vector3(s(0.0), s(0.0), s(1.0))
    s0 = (ground_dir * cast_float(proj_speed, _cos(low_ang, runtime)) * proj_speed
          + unit_z * cast_float(proj_speed, _sin(low_ang, runtime)) * proj_speed)
    if num_solutions > 1:
        s1 = (ground_dir * cast_float(proj_speed, _cos(high_ang, runtime)) * proj_speed
              + unit_z * cast_float(proj_speed, _sin(high_ang, runtime)) * proj_speed)

    t0 = x / (cast_float(proj_speed, _cos(low_ang, runtime)) * proj_speed)
    t1 = x / (cast_float(proj_speed, _cos(high_ang, runtime)) * proj_speed)

    return num_solutions, s0, s1, t0, t1


@anchor(None, "Trajectory.cs:solve_ballistic_arc(Vector3, float, Vector3, Vector3, float, out Vector3, out Vector3, out float)",
        "the moving-target overload (s0, s1, time)")
def solve_ballistic_arc_moving(proj_pos: Vector3, proj_speed, target_pos: Vector3, target_velocity: Vector3, gravity,
                               runtime: Runtime = MONO):
    """Firing solutions to a target moving at constant velocity: (num, s0, s1, time), the quartic
    in time solved in double. Creature.GetProjectileVelocity's solver for a moving target."""
    s = type(proj_speed)
    s0 = zero_like(proj_speed)
    s1 = zero_like(proj_speed)

    g = D(gravity)

    a = D(proj_pos.x)
    b = D(proj_pos.z)
    c = D(proj_pos.y)
    m = D(target_pos.x)
    n = D(target_pos.z)
    o = D(target_pos.y)
    p = D(target_velocity.x)
    q = D(target_velocity.z)
    r = D(target_velocity.y)
    sp = D(proj_speed)

    h = m - a
    j = o - c
    k = n - b
    ll = D(-0.5) * g  # -.5f * G: the float literal widened to double

    # quartic coefficients
    c0 = ll * ll
    c1 = 2 * q * ll
    c2 = q * q + 2 * k * ll - sp * sp + p * p + r * r
    c3 = 2 * k * q + 2 * h * p + 2 * j * r
    c4 = k * k + h * h + j * j

    num_times, *slots = solve_quartic(c0, c1, c2, c3, c4, runtime)

    # sort so the faster collision comes first (ACE): NaN slots sort first
    times = sorted(slots, key=_sort_key)

    solutions = [zero_like(proj_speed), zero_like(proj_speed)]
    num_solutions = 0

    time = s(0.0)
    i = 0
    while i < num_times and num_solutions < 2:
        t = times[i]
        i += 1
        if t <= 0:
            continue

        if num_solutions == 0:
            time = s(t)

        solutions[num_solutions] = Vector3(s((h + p * t) / t), s((j + r * t) / t), s((k + q * t - ll * t * t) / t))
        num_solutions += 1

    if num_solutions > 0:
        s0 = solutions[0]
    if num_solutions > 1:
        s1 = solutions[1]

    return num_solutions, s0, s1, time


@anchor(None, "Trajectory.cs:SolveBallisticArc", "gmriggs' fixed-gravity lateral solver (velocity, time)")
def solve_ballistic_arc_fixed_gravity(projectile_position: Vector3, lateral_speed, target_position: Vector3):
    """(ok, velocity, time) at `lateral_speed` along the ground under PhysicsGlobals.Gravity."""
    s = type(lateral_speed)
    velocity = zero_like(lateral_speed)
    time = s(math.nan)

    if projectile_position == target_position or lateral_speed <= 0:
        return False, velocity, time

    diff = target_position - projectile_position
    diff_xy = Vector3(diff.x, diff.y, s(0.0))
    lateral_dist = diff_xy.length()

    if lateral_dist == 0:
        return False, velocity, time

    time = lateral_dist / lateral_speed

    velocity = normalize(diff_xy) * lateral_speed

    a = projectile_position.z  # initial
    c = target_position.z  # final

    g = s(GRAVITY)
    _b = (4 * a + 4 * c - g * time * time) / 8  # the peak, computed and unused (ACE)

    velocity = velocity.with_z((2 * a - 2 * c + g * time * time) / (time * 2) * -1)

    return True, velocity, time


@anchor(None, "Trajectory.cs:solve_ballistic_arc_lateral", "the max-height overload (fire_velocity, gravity)")
def solve_ballistic_arc_lateral_max_height(proj_pos: Vector3, lateral_speed, target_pos: Vector3, max_height):
    """(ok, fire_velocity, gravity): the gravity that peaks the arc at `max_height`. ACE's
    Debug.Assert is compiled out of a Release build; the same bad input returns false after it."""
    s = type(lateral_speed)
    fire_velocity = zero_like(lateral_speed)
    gravity = s(math.nan)

    if proj_pos == target_pos or lateral_speed <= 0 or max_height <= proj_pos.z:
        return False, fire_velocity, gravity

    diff = target_pos - proj_pos
    diff_xy = Vector3(diff.x, diff.y, s(0.0))
    lateral_dist = diff_xy.length()

    if lateral_dist == 0:
        return False, fire_velocity, gravity

    time = lateral_dist / lateral_speed

    fire_velocity = normalize(diff_xy) * lateral_speed

    a = proj_pos.z  # initial
    b = max_height  # peak
    c = target_pos.z  # final

    gravity = -4 * (a - 2 * b + c) / (time * time)
    fire_velocity = fire_velocity.with_z(-(3 * a - 4 * b + c) / time)

    return True, fire_velocity, gravity


@anchor(None,
        "Trajectory.cs:solve_ballistic_arc_lateral(Vector3, float, Vector3, Vector3, float, out Vector3, out float, out Vector3)",
        "the moving-target overload (fire_velocity, time, impact_point)")
def solve_ballistic_arc_lateral(proj_pos: Vector3, lateral_speed, target: Vector3, target_velocity: Vector3, gravity):
    """(ok, fire_velocity, time, impact_point) at `lateral_speed` along the ground to a target
    moving at `target_velocity`, under `gravity` (ACE passes PhysicsGlobals.Gravity, -9.8, for an
    arc spell and 0 otherwise). WorldObject.CalculateProjectileVelocity's solver."""
    s = type(lateral_speed)
    fire_velocity = zero_like(lateral_speed)
    time = s(0.0)
    impact_point = zero_like(lateral_speed)

    if proj_pos == target or lateral_speed <= 0:
        return False, fire_velocity, time, impact_point

    # ground plane terms
    target_vel_xy = Vector3(target_velocity.x, target_velocity.y, s(0.0))
    diff_xy = (target - proj_pos).with_z(s(0.0))

    # |diffXY + targetVelXY*t| = S*t, squared: a quadratic in t (ACE's derivation)
    c0 = dot(target_vel_xy, target_vel_xy) - lateral_speed * lateral_speed
    c1 = 2 * dot(diff_xy, target_vel_xy)
    c2 = dot(diff_xy, diff_xy)
    n, t0, t1 = solve_quadric(c0, c1, c2)

    # pick the smallest positive time
    valid0 = n > 0 and t0 > 0
    valid1 = n > 1 and t1 > 0

    if not valid0 and not valid1:
        return False, fire_velocity, time, impact_point
    elif valid0 and valid1:
        t = min(s(t0), s(t1))  # Math.Min(float, float) of two positive floats
    else:
        t = s(t0) if valid0 else s(t1)

    # the impact point
    impact_point = target + target_velocity * t

    # the fire velocity along the ground
    direction = impact_point - proj_pos
    fire_velocity = normalize(Vector3(direction.x, direction.y, s(0.0))) * lateral_speed

    a = proj_pos.z  # initial
    c = impact_point.z  # final

    g = gravity
    _b = (4 * a + 4 * c - g * t * t) / 8  # the peak, computed and unused (ACE)

    fire_velocity = fire_velocity.with_z((2 * a - 2 * c + g * t * t) / (t * 2) * -1)

    time = t

    return True, fire_velocity, time, impact_point
