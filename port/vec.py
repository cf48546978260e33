"""Vec.NormalizeCheckSmall, Vec.IsZero; Vector3Extensions (Dot2D, IsValid, Length2D, LengthSquared2D, get_heading); PlaneExtensions (LocalToGlobal, GetSide, intersect_box, SnapToPlane, compute_time_of_intersection, set_height, is_equal); Ray.

ACE's static helpers on System.Numerics values (Common/Vector.cs, Extensions/Vector3Extensions.cs,
Extensions/PlaneExtensions.cs) and the Ray record (Ray.cs) the plane extension takes. C# ``ref``
parameters come back in a tuple beside the result, as each docstring says.

Where C# widens to double the port does too: ``Length2D``/``LengthSquared2D`` compute in float32
and return the result as a double; ``Math.Sqrt`` is `cs_sqrt` (a double, NaN for a negative
argument as in C#, where Python's math.sqrt would raise).
"""

from __future__ import annotations

import math
from enum import IntEnum

from acconform.numerics import D, Plane, Vector3, cast_float, cs_fmod, dot

from .anchors import anchor, harness
from .constants import EPSILON


class Side(IntEnum):
    """BSPNode.cs Side: where a point lies against a plane (GetSide)."""

    Front = 0x0
    Behind = 0x1
    Close = 0x2


@harness(".NET Math.Sqrt: a double, NaN for a negative argument")
def cs_sqrt(x):
    """C# ``Math.Sqrt(x)``: a double; NaN for a negative (or NaN) argument, -0 for -0."""
    x = float(x)
    if x < 0.0 or x != x:
        return D(math.nan)
    return D(math.sqrt(x))


@harness(".NET Vector3.Zero in the run's scalar type")
def zero_like(s) -> Vector3:
    """``Vector3.Zero`` in the scalar type of `s` (exact float32 or fast double)."""
    z = type(s)(0.0)
    return Vector3(z, z, z)


@harness(".NET Vector3.UnitZ in the run's scalar type")
def unit_z_like(s) -> Vector3:
    """``Vector3.UnitZ`` in the scalar type of `s`."""
    t = type(s)
    return Vector3(t(0.0), t(0.0), t(1.0))


# ---------------------------------------------------------------- Common/Vector.cs


@anchor(None, "Vector.cs:NormalizeCheckSmall")
def normalize_check_small(v: Vector3) -> tuple[bool, Vector3]:
    """``Vec.NormalizeCheckSmall(ref v)``: returns (is_small, v after the call).

    When the length is below EPSILON the vector comes back unchanged and is_small is True;
    otherwise v is scaled by ``1.0f / length`` (a reciprocal multiply, not a divide).
    """
    dist = v.length()
    if dist < EPSILON:
        return True, v
    return False, v * (1.0 / dist)


@anchor(None, "Vector.cs:IsZero")
def is_zero(v: Vector3) -> bool:
    return abs(v.x) < EPSILON and abs(v.y) < EPSILON and abs(v.z) < EPSILON


# ---------------------------------------------------------------- Extensions/Vector3Extensions.cs


@anchor(None, "Vector3Extensions.cs:Dot2D")
def dot2d(a: Vector3, b: Vector3):
    return a.x * b.x + a.y * b.y


@anchor(None, "Vector3Extensions.cs:IsValid")
def is_valid(v: Vector3) -> bool:
    return not (math.isnan(v.x) or math.isnan(v.y) or math.isnan(v.z))


@anchor(None, "Vector3Extensions.cs:Length2D")
def length_2d(v: Vector3):
    """``new Vector2(X, Y).Length()`` (float32 sqrt of the float32 sum), returned as a double."""
    ls = v.x * v.x + v.y * v.y
    return D(type(ls)(math.sqrt(ls)))


@anchor(None, "Vector3Extensions.cs:LengthSquared2D")
def length_squared_2d(v: Vector3):
    """``X * X + Y * Y`` in float32, returned as a double."""
    return D(v.x * v.x + v.y * v.y)


@anchor(None, "Vector3Extensions.cs:get_heading")
def get_heading(v: Vector3):
    normal = Vector3(v.x, v.y, type(v.x)(0.0))
    small, normal = normalize_check_small(normal)
    if small:
        return type(v.x)(0.0)
    # (float)Math.Atan2(y, x), then ToDegrees: (float)(180.0f / Math.PI * rads)
    rads = cast_float(v.x, math.atan2(float(normal.y), float(normal.x)))
    degrees = cast_float(v.x, 180.0 / math.pi * float(rads))
    return cs_fmod(450.0 - degrees, type(degrees)(360.0))


# ---------------------------------------------------------------- Extensions/PlaneExtensions.cs


@anchor(None, "PlaneExtensions.cs:LocalToGlobal")
def plane_local_to_global(plane: Plane, to, from_, local_plane: Plane) -> Plane:
    """``plane.LocalToGlobal(to, from, localPlane)``; `plane` itself is unused, as in ACE.

    `to` and `from_` are Positions (port/frame.py): ``from_.frame.local_to_global_vec`` and
    ``to.local_to_global_from(from_, point)``.
    """
    normal = from_.frame.local_to_global_vec(local_plane.normal)
    dist = to.local_to_global_from(from_, local_plane.normal * -local_plane.d)
    return Plane(normal, -dot(normal, dist))


@anchor(None, "PlaneExtensions.cs:GetSide")
def get_side(plane: Plane, p: Vector3, bias=0.0) -> Side:
    dist = dot(plane.normal, p) + plane.d + bias
    side = Side.Front
    if dist <= EPSILON:
        side = Side.Behind if dist < -EPSILON else Side.Close
    return side


class Sidedness(IntEnum):
    """ACE.Entity.Enum.Sidedness: where a box lies against a plane (intersect_box)."""

    Positive = 0x0
    Negative = 0x1
    InPlane = 0x2
    Crossing = 0x3


@anchor(None, "PlaneExtensions.cs:intersect_box")
def intersect_box(p: Plane, box) -> Sidedness:
    """Note ACE compares each corner's Side cast to Sidedness: a corner Close to the plane
    (Side 2, InPlane) differs from Positive and Negative, so it makes the box Crossing."""
    dist = dot(box.min, p.normal) + p.d
    if dist <= EPSILON:
        if dist >= -EPSILON:
            return Sidedness.Crossing
        else:
            result = Sidedness.Negative
    else:
        result = Sidedness.Positive

    corners = box.get_corners()

    for corner in corners:
        if result != int(get_side(p, corner, EPSILON)):
            return Sidedness.Crossing
    return result


@anchor(None, "PlaneExtensions.cs:SnapToPlane")
def snap_to_plane(p: Plane, offset: Vector3) -> Vector3:
    """``p.SnapToPlane(ref offset)``: returns offset after the call (Z replaced, or unchanged)."""
    if abs(p.normal.z) <= EPSILON:
        return offset
    z = -(dot2d(offset, p.normal) + p.d) * (1.0 / p.normal.z) - 1.0 / p.normal.z * -p.d
    return offset.with_z(z)


class Ray:
    """Ray.cs: a start point, a direction and a length (fields as ACE's)."""

    __slots__ = ("point", "dir", "length")

    def __init__(self, point: Vector3, dir: Vector3, length):
        self.point = point
        self.dir = dir
        self.length = length


@anchor(None, "PlaneExtensions.cs:compute_time_of_intersection")
def compute_time_of_intersection(p: Plane, ray: Ray, time) -> tuple[bool, object]:
    """``p.compute_time_of_intersection(ray, ref time)``: returns (hit, time after the call)."""
    angle = dot(ray.dir, p.normal)
    if abs(angle) < EPSILON:
        return False, time
    time = (dot(ray.point, p.normal) + p.d) * (-1.0 / angle)
    return time >= 0.0, time


@anchor(None, "PlaneExtensions.cs:set_height")
def set_height(p: Plane, v: Vector3) -> tuple[bool, Vector3]:
    """``p.set_height(ref v)``: returns (ok, v after the call)."""
    if abs(p.normal.z) <= EPSILON:
        return False, v
    return True, v.with_z(-((v.y * p.normal.y + v.x * p.normal.x + p.d) / p.normal.z))


@anchor(None, "PlaneExtensions.cs:is_equal")
def is_equal(p1: Plane, p2: Plane) -> bool:
    return (
        p1.normal.x == p2.normal.x and p1.normal.y == p2.normal.y and p1.normal.z == p2.normal.z
        and p1.d == p2.d
    )
