"""Float32-exact (and fast double) arithmetic with System.Numerics semantics, plus C# scalar rules.

ACE computes in float32 through System.Numerics. Values here are numpy scalars: in exact mode
``np.float32`` (every +, -, *, / is IEEE binary32, bit for bit what C# float arithmetic does,
with no explicit rounding calls), in fast mode ``np.float64``. The same physics code runs in
either mode because the mode travels with the values: Python ints and floats are NumPy-2 "weak"
scalars and take the type of the other operand, so constants written as exact float32 values
(see acconform.port.constants) are float32 in exact mode and double in fast mode.

Where C# leaves float32 -- ``Math.Sqrt``/``Math.Floor`` return double, ``(float)`` casts back --
the port writes it out: ``D(x)`` makes a double (``np.float64``) in both modes, ``cast_float(like, x)``
is C#'s ``(float)x`` in the mode of ``like``.

The runtime that executes ACE matters where System.Numerics or the JIT differ; `Runtime` holds
those spots (float->int casts today) so another runtime's arithmetic can be added without touching
physics code. Only mono's is implemented and checked here (see tests/numerics).
"""

from __future__ import annotations

import ctypes
import ctypes.util
import math
from dataclasses import dataclass

import numpy as np

F32 = np.float32
D = np.float64  # C# double spots (Math.Sqrt results, double literals)


def f32_bits(x) -> int:
    """The binary32 bit pattern of x (rounded to float32 first)."""
    return int(np.float32(x).view(np.uint32))


def f32_from_bits(bits: int) -> float:
    return float(np.uint32(bits & 0xFFFFFFFF).view(np.float32))


def to_f32(x) -> float:
    """Round a number to the nearest float32 and hand it back as a Python float (exact)."""
    return float(np.float32(x))


def cast_float(like, x):
    """C# ``(float)x`` (or ``(double)`` in fast mode): x converted to the scalar type of `like`."""
    return type(like)(x)


# ---------------------------------------------------------------- C# scalar semantics


def cs_floor(x):
    """``Math.Floor(double)``: a double; +-inf, NaN and signed zeros pass through as in IEEE floor."""
    x = float(x)
    if x != 0.0 and -4503599627370496.0 < x < 4503599627370496.0:  # |x| < 2^52: may have a fraction
        return float(math.floor(x))
    return x  # +-0, +-inf, NaN and |x| >= 2^52 (already whole) are their own floor


def cs_ceiling(x):
    """``Math.Ceiling(double)``: a double; IEEE ceil keeps the sign, so (-1, -0] gives -0.0."""
    x = float(x)
    if not math.isfinite(x):
        return x
    r = float(math.ceil(x))
    return math.copysign(0.0, x) if r == 0.0 else r


def cs_fmod(a, b):
    """C# ``%`` on floats: IEEE fmod (truncated, sign of the dividend), exact in the operands' type."""
    return type(a)(math.fmod(float(a), float(b))) if b != 0 else type(a)(math.nan)


def wrap_i32(n: int) -> int:
    """C# ``int`` arithmetic in an unchecked context: wrap to [-2^31, 2^31)."""
    n &= 0xFFFFFFFF
    return n - 0x100000000 if n & 0x80000000 else n


def wrap_u32(n: int) -> int:
    """C# ``uint`` arithmetic in an unchecked context: wrap to [0, 2^32)."""
    return n & 0xFFFFFFFF


@dataclass(frozen=True, slots=True)
class Runtime:
    """The .NET runtime ACE runs on: where its arithmetic differs, the difference lives here."""

    name: str

    def to_int32(self, x) -> int:
        """C# ``(int)x`` for a float or double x."""
        x = float(x)
        if self.name == "mono":
            # x86-64 cvttsd2si: NaN and out-of-range give int.MinValue (checked on mono 6.8).
            # (NaN and +-inf fail the range test.)
            if -2147483649.0 < x < 2147483648.0:
                return int(x)
            return -2147483648
        # .NET 9+ (CoreCLR): conversions saturate and NaN gives 0.
        if math.isnan(x):
            return 0
        if x >= 2147483647.0:
            return 2147483647
        if x <= -2147483648.0:
            return -2147483648
        return int(x)

    def to_uint32(self, x) -> int:
        """C# ``(uint)x`` for a float or double x."""
        x = float(x)
        if self.name == "mono":
            # mono converts through a 64-bit cvtt and keeps the low 32 bits (NaN, +-inf and
            # out-of-range fail the range test and give 0).
            if -9.223372036854775808e18 <= x < 9.223372036854775808e18:
                return int(x) & 0xFFFFFFFF
            return 0
        if math.isnan(x) or x <= 0.0:
            return 0
        if x >= 4294967295.0:
            return 4294967295
        return int(x)


MONO = Runtime("mono")
CORECLR = Runtime("coreclr")
RUNTIMES = {"mono": MONO, "coreclr": CORECLR}


@dataclass(frozen=True, slots=True)
class Mode:
    """How a run computes: `scalar` is the component type every value is made of."""

    name: str
    scalar: type
    runtime: Runtime = MONO

    def vec(self, x, y, z) -> "Vector3":
        s = self.scalar
        return Vector3(s(x), s(y), s(z))

    def quat(self, x, y, z, w) -> "Quaternion":
        s = self.scalar
        return Quaternion(s(x), s(y), s(z), s(w))


EXACT = Mode("exact", np.float32)
FAST = Mode("fast", np.float64)
MODES = {"exact": EXACT, "fast": FAST}


def get_mode(name: str, runtime: str = "mono") -> Mode:
    from .errors import AcconformError

    if name not in MODES:
        raise AcconformError(f"unknown numerics mode {name!r}: choose one of {sorted(MODES)}")
    if runtime not in RUNTIMES:
        raise AcconformError(f"unknown runtime {runtime!r}: choose one of {sorted(RUNTIMES)}")
    if runtime != "mono":
        raise AcconformError(
            "only the mono runtime's System.Numerics arithmetic is ported so far; "
            "CoreCLR (.NET 10) rotates by quaternions through another formula and fuses "
            "multiply-adds -- run the oracle on mono or compare with --mode fast"
        )
    return MODES[name]


# ---------------------------------------------------------------- System.Numerics types
# Immutable value types: C# assigns structs by copy, so Python must never alias a mutable one.


_new = object.__new__  # a Vector3 built without __init__ (its slots set directly: cheaper)


class Vector3:
    """System.Numerics.Vector3 as mono's implementation computes it (component order kept)."""

    __slots__ = ("x", "y", "z")

    def __init__(self, x, y, z):
        self.x = x
        self.y = y
        self.z = z

    def __add__(self, o: "Vector3") -> "Vector3":
        r = _new(Vector3)
        r.x = self.x + o.x
        r.y = self.y + o.y
        r.z = self.z + o.z
        return r

    def __sub__(self, o: "Vector3") -> "Vector3":
        r = _new(Vector3)
        r.x = self.x - o.x
        r.y = self.y - o.y
        r.z = self.z - o.z
        return r

    def __neg__(self) -> "Vector3":
        # System.Numerics: operator -(Vector3 value) => Zero - value (so -(0) is +0, not -0)
        r = _new(Vector3)
        r.x = 0.0 - self.x
        r.y = 0.0 - self.y
        r.z = 0.0 - self.z
        return r

    def __mul__(self, o) -> "Vector3":
        if type(o) is Vector3:
            r = _new(Vector3)
            r.x = self.x * o.x
            r.y = self.y * o.y
            r.z = self.z * o.z
            return r
        r = _new(Vector3)
        r.x = self.x * o
        r.y = self.y * o
        r.z = self.z * o
        return r

    def __rmul__(self, s) -> "Vector3":
        r = _new(Vector3)
        r.x = s * self.x
        r.y = s * self.y
        r.z = s * self.z
        return r

    def __truediv__(self, s) -> "Vector3":
        # mono divides each component (checked against System.Numerics: no reciprocal multiply).
        r = _new(Vector3)
        r.x = self.x / s
        r.y = self.y / s
        r.z = self.z / s
        return r

    def __eq__(self, o) -> bool:
        return type(o) is Vector3 and self.x == o.x and self.y == o.y and self.z == o.z

    __hash__ = None

    def __repr__(self) -> str:
        return f"Vector3({float(self.x)!r}, {float(self.y)!r}, {float(self.z)!r})"

    def __iter__(self):
        yield self.x
        yield self.y
        yield self.z

    def with_x(self, x) -> "Vector3":
        r = _new(Vector3)
        r.x = x
        r.y = self.y
        r.z = self.z
        return r

    def with_y(self, y) -> "Vector3":
        r = _new(Vector3)
        r.x = self.x
        r.y = y
        r.z = self.z
        return r

    def with_z(self, z) -> "Vector3":
        r = _new(Vector3)
        r.x = self.x
        r.y = self.y
        r.z = z
        return r

    def length_squared(self):
        return self.x * self.x + self.y * self.y + self.z * self.z

    def length(self):
        ls = self.x * self.x + self.y * self.y + self.z * self.z
        return type(ls)(math.sqrt(ls))

    def to_tuple(self) -> tuple[float, float, float]:
        return (float(self.x), float(self.y), float(self.z))


def dot(a: Vector3, b: Vector3):
    """Vector3.Dot: ((ax*bx + ay*by) + az*bz), left to right."""
    return a.x * b.x + a.y * b.y + a.z * b.z


def cross(a: Vector3, b: Vector3) -> Vector3:
    """Vector3.Cross."""
    r = _new(Vector3)
    r.x = a.y * b.z - a.z * b.y
    r.y = a.z * b.x - a.x * b.z
    r.z = a.x * b.y - a.y * b.x
    return r


def normalize(v: Vector3) -> Vector3:
    """Vector3.Normalize (mono, no hardware acceleration): divide by (float)Math.Sqrt(ls)."""
    ls = v.x * v.x + v.y * v.y + v.z * v.z
    length = type(ls)(math.sqrt(ls))
    r = _new(Vector3)
    r.x = v.x / length
    r.y = v.y / length
    r.z = v.z / length
    return r


def distance(a: Vector3, b: Vector3):
    """Vector3.Distance."""
    dx = a.x - b.x
    dy = a.y - b.y
    dz = a.z - b.z
    ls = dx * dx + dy * dy + dz * dz
    return type(ls)(math.sqrt(ls))


def lerp(a: Vector3, b: Vector3, t) -> Vector3:
    """Vector3.Lerp as mono computes it: a + (b - a) * t."""
    r = _new(Vector3)
    r.x = a.x + (b.x - a.x) * t
    r.y = a.y + (b.y - a.y) * t
    r.z = a.z + (b.z - a.z) * t
    return r


class Quaternion:
    """System.Numerics.Quaternion (X, Y, Z, W) -- note AC files write (W, X, Y, Z)."""

    __slots__ = ("x", "y", "z", "w")

    def __init__(self, x, y, z, w):
        self.x = x
        self.y = y
        self.z = z
        self.w = w

    def __eq__(self, o) -> bool:
        return (
            type(o) is Quaternion and self.x == o.x and self.y == o.y and self.z == o.z and self.w == o.w
        )

    __hash__ = None

    def __repr__(self) -> str:
        return f"Quaternion({float(self.x)!r}, {float(self.y)!r}, {float(self.z)!r}, {float(self.w)!r})"

    def __mul__(self, o: "Quaternion") -> "Quaternion":
        return quat_multiply(self, o)


def quat_multiply(a: Quaternion, b: Quaternion) -> Quaternion:
    """Quaternion.Multiply (and operator *)."""
    cx = a.y * b.z - a.z * b.y
    cy = a.z * b.x - a.x * b.z
    cz = a.x * b.y - a.y * b.x
    d = a.x * b.x + a.y * b.y + a.z * b.z
    return Quaternion(
        a.x * b.w + b.x * a.w + cx,
        a.y * b.w + b.y * a.w + cy,
        a.z * b.w + b.z * a.w + cz,
        a.w * b.w - d,
    )


def quat_inverse(q: Quaternion) -> Quaternion:
    """Quaternion.Inverse: conjugate times 1/|q|^2."""
    ls = q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w
    inv = 1.0 / ls
    return Quaternion(-q.x * inv, -q.y * inv, -q.z * inv, q.w * inv)


def quat_normalize(q: Quaternion) -> Quaternion:
    """Quaternion.Normalize: times 1/(float)Math.Sqrt(ls)."""
    ls = q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w
    inv = 1.0 / type(ls)(math.sqrt(ls))
    return Quaternion(q.x * inv, q.y * inv, q.z * inv, q.w * inv)


def quat_lerp(a: Quaternion, b: Quaternion, t) -> Quaternion:
    """Quaternion.Lerp (mono): blend along the shorter arc, then normalise by 1/sqrt."""
    t1 = 1.0 - t
    d = a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w
    if d >= 0.0:
        x = t1 * a.x + t * b.x
        y = t1 * a.y + t * b.y
        z = t1 * a.z + t * b.z
        w = t1 * a.w + t * b.w
    else:
        x = t1 * a.x - t * b.x
        y = t1 * a.y - t * b.y
        z = t1 * a.z - t * b.z
        w = t1 * a.w - t * b.w
    ls = x * x + y * y + z * z + w * w
    inv = 1.0 / type(ls)(math.sqrt(ls))
    return Quaternion(x * inv, y * inv, z * inv, w * inv)


def transform_by_quaternion(v: Vector3, q: Quaternion) -> Vector3:
    """Vector3.Transform(Vector3, Quaternion), mono's formula (CoreCLR's differs)."""
    x2 = q.x + q.x
    y2 = q.y + q.y
    z2 = q.z + q.z
    wx2 = q.w * x2
    wy2 = q.w * y2
    wz2 = q.w * z2
    xx2 = q.x * x2
    xy2 = q.x * y2
    xz2 = q.x * z2
    yy2 = q.y * y2
    yz2 = q.y * z2
    zz2 = q.z * z2
    r = _new(Vector3)
    r.x = v.x * (1.0 - yy2 - zz2) + v.y * (xy2 - wz2) + v.z * (xz2 + wy2)
    r.y = v.x * (xy2 + wz2) + v.y * (1.0 - xx2 - zz2) + v.z * (yz2 - wx2)
    r.z = v.x * (xz2 - wy2) + v.y * (yz2 + wx2) + v.z * (1.0 - xx2 - yy2)
    return r


class Matrix4x4:
    """The parts of System.Numerics.Matrix4x4 ACE's frames use: M11..M44, row-major fields."""

    __slots__ = ("m",)

    def __init__(self, m: tuple):
        self.m = m  # (M11, M12, M13, M14, M21, ..., M44)

    @staticmethod
    def create_from_quaternion(q: Quaternion) -> "Matrix4x4":
        xx = q.x * q.x
        yy = q.y * q.y
        zz = q.z * q.z
        xy = q.x * q.y
        wz = q.z * q.w
        xz = q.z * q.x
        wy = q.y * q.w
        yz = q.y * q.z
        wx = q.x * q.w
        zero = type(xx)(0.0)
        one = type(xx)(1.0)
        return Matrix4x4(
            (
                1.0 - 2.0 * (yy + zz), 2.0 * (xy + wz), 2.0 * (xz - wy), zero,
                2.0 * (xy - wz), 1.0 - 2.0 * (zz + xx), 2.0 * (yz + wx), zero,
                2.0 * (xz + wy), 2.0 * (yz - wx), 1.0 - 2.0 * (yy + xx), zero,
                zero, zero, zero, one,
            )
        )

    def transpose(self) -> "Matrix4x4":
        m = self.m
        return Matrix4x4(
            (m[0], m[4], m[8], m[12], m[1], m[5], m[9], m[13], m[2], m[6], m[10], m[14], m[3], m[7], m[11], m[15])
        )


def transform_by_matrix(v: Vector3, mat: Matrix4x4) -> Vector3:
    """Vector3.Transform(Vector3, Matrix4x4): the translation row is added (so -0 + 0 = +0)."""
    m = mat.m
    r = _new(Vector3)
    r.x = v.x * m[0] + v.y * m[4] + v.z * m[8] + m[12]
    r.y = v.x * m[1] + v.y * m[5] + v.z * m[9] + m[13]
    r.z = v.x * m[2] + v.y * m[6] + v.z * m[10] + m[14]
    return r


class Plane:
    """System.Numerics.Plane: Normal and D, a value type."""

    __slots__ = ("normal", "d")

    def __init__(self, normal: Vector3, d):
        self.normal = normal
        self.d = d

    def __eq__(self, o) -> bool:
        return type(o) is Plane and self.normal == o.normal and self.d == o.d

    __hash__ = None

    def __repr__(self) -> str:
        return f"Plane({self.normal!r}, {float(self.d)!r})"


def plane_dot_coordinate(p: Plane, v: Vector3):
    """Plane.DotCoordinate: dot(normal, v) + D."""
    n = p.normal
    return n.x * v.x + n.y * v.y + n.z * v.z + p.d


def plane_dot_normal(p: Plane, v: Vector3):
    """Plane.DotNormal."""
    n = p.normal
    return n.x * v.x + n.y * v.y + n.z * v.z


# ---------------------------------------------------------------- MathF (float trig through libm)


def cs_math(fn, x: float) -> float:
    """Math.Sin/Cos/Asin on a double: NaN where C# gives NaN (Python raises on +-inf and out-of-domain)."""
    try:
        return fn(x)
    except ValueError:
        return math.nan


def _load_libm():
    """The C library's float sinf/cosf, which mono's System.Numerics calls (through MathF)."""
    path = ctypes.util.find_library("m") or "libm.so.6"
    lib = ctypes.CDLL(path)
    for name in ("sinf", "cosf"):
        fn = getattr(lib, name)
        fn.restype = ctypes.c_float
        fn.argtypes = [ctypes.c_float]
    return lib


_LIBM = _load_libm()


def mathf_sin(x):
    """MathF.Sin(x) for a float32 x (libm sinf); Math.Sin in fast mode."""
    if type(x) is np.float32:
        return np.float32(_LIBM.sinf(float(x)))
    return cast_float(x, cs_math(math.sin, float(x)))


def mathf_cos(x):
    """MathF.Cos(x) for a float32 x (libm cosf); Math.Cos in fast mode."""
    if type(x) is np.float32:
        return np.float32(_LIBM.cosf(float(x)))
    return cast_float(x, cs_math(math.cos, float(x)))


def quat_create_from_yaw_pitch_roll(yaw, pitch, roll) -> Quaternion:
    """Quaternion.CreateFromYawPitchRoll as mono computes it: half angles in float, then
    MathF.Sin/Cos -- libm's float sinf/cosf, not (float)Math.Sin (checked against mono: the
    double route is one ulp off in about 7% of cases)."""
    half_roll = roll * 0.5
    sr = mathf_sin(half_roll)
    cr = mathf_cos(half_roll)
    half_pitch = pitch * 0.5
    sp = mathf_sin(half_pitch)
    cp = mathf_cos(half_pitch)
    half_yaw = yaw * 0.5
    sy = mathf_sin(half_yaw)
    cy = mathf_cos(half_yaw)
    return Quaternion(
        cy * sp * cr + sy * cp * sr,
        sy * cp * cr - cy * sp * sr,
        cy * cp * sr - sy * sp * cr,
        cy * cp * cr + sy * sp * sr,
    )
