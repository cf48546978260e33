"""Trajectory2: CalculateTrajectory.

ACE's Physics/Trajectory2.cs: the "alternate" solver the server uses for missiles and spell
projectiles when its trajectory_alt_solver property is set (false by default, so a default
server never calls it). Float32 throughout except the quadratic's roots, which ``Math.Sqrt``
makes double; ``Math.Min(double, double)`` of the two roots (the runtime's: `runtime`) is cast back
to float.
"""

from __future__ import annotations

import math

from acconform.numerics import MONO, D, Runtime, Vector3, cast_float

from .anchors import anchor
from .constants import GRAVITY
from .vec import normalize_check_small, zero_like

FLOAT_MAX_VALUE = D(3.4028234663852886e38)  # float.MaxValue, widened to double where ACE stores it


# Math.Sqrt of a negative number: x64's SQRTSD answers the default NaN (the "indefinite"), whose sign bit is set
# (0xFFF8000000000000), on both runtimes; it carries through the roots into the velocity, whose NaN sign an outcome
# reads (Python's math.nan has the sign bit clear)
SQRT_NAN = D(-math.nan)


def _sqrt(x):
    x = float(x)
    return D(math.sqrt(x)) if x >= 0.0 else SQRT_NAN


def _min(a, b, runtime: Runtime):
    """``Math.Min(double, double)``: NaN when either is NaN; the runtimes differ on a -0/+0 tie (both
    roots zero: a target straight above or below the start). Mono (the reference source):
    ``val1 < val2 ? val1 : IsNaN(val1) ? val1 : val2``, so the second; .NET 10 the negative one."""
    if runtime.name == "mono":
        if a < b:
            return a
        if a != a:
            return a
        return b
    if a != b:
        if a == a:
            return b if b < a else a
        return a
    return b if math.copysign(1.0, b) < 0 else a


@anchor(None, "Trajectory2.cs:CalculateTrajectory")
def calculate_trajectory(start_pos: Vector3, end_pos: Vector3, target_velocity: Vector3, speed, gravity: bool,
                         runtime: Runtime = MONO) -> Vector3:
    s = type(speed)
    target_offset = end_pos - start_pos

    t = s(0.0)

    if target_velocity == zero_like(speed):
        target_dist = target_offset.length()

        t = target_dist / speed
        result = target_offset / t
    else:
        p0 = target_offset
        p1 = zero_like(speed)

        v0 = target_velocity
        small, v0 = normalize_check_small(v0)
        if small:
            v0 = zero_like(speed)

        s1 = speed

        a = (v0.x * v0.x) + (v0.y * v0.y) - (s1 * s1)
        b = 2 * ((p0.x * v0.x) + (p0.y * v0.y) - (p1.x * v0.x) - (p1.y * v0.y))
        c = (p0.x * p0.x) + (p0.y * p0.y) + (p1.x * p1.x) + (p1.y * p1.y) - (2 * p1.x * p0.x) - (2 * p1.y * p0.y)

        t0 = _sqrt((b * b) - (4 * a * c))
        t1 = (D(-b) + t0) / D(2 * a)
        t2 = (D(-b) - t0) / D(2 * a)

        if t1 < 0:
            t1 = FLOAT_MAX_VALUE
        if t2 < 0:
            t2 = FLOAT_MAX_VALUE

        t = cast_float(speed, _min(t1, t2, runtime))

        if t >= 100:
            return calculate_trajectory(start_pos, end_pos, zero_like(speed), speed, gravity, runtime)

        s0 = target_velocity.length()

        result = (p0 + v0 * (t * s0)) / t  # float * Vector3: each lane times (t * s0), as v0 * it

    if gravity:
        result = result.with_z(result.z - s(GRAVITY) * t * 0.5)

    return result
