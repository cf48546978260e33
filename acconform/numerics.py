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
those spots: float->int casts and the System.Numerics operations whose formula differs (quaternion
rotation and products, lerps, matrix transforms, CreateFromYawPitchRoll, Vector3 negation). `MONO` is mono 6.8's
System.Numerics; `NET10` is .NET 10 on CoreCLR (x64 with FMA), measured against both runtimes'
recorded answers (tests/data/numerics_*.json). A quaternion carries the runtime that made it
(`Quaternion.runtime`), so frame code asks its orientation which formulas to use; the mode's
`quat` makes quaternions of the mode's runtime.
"""

from __future__ import annotations

import ctypes
import ctypes.util
import math
import struct
from dataclasses import dataclass, field

import numpy as np

F32 = np.float32
D = np.float64  # C# double spots (Math.Sqrt results, double literals)


_F32 = struct.Struct("=f")
_U32 = struct.Struct("=I")


def f32_bits(x) -> int:
    """The binary32 bit pattern of x (rounded to float32 first)."""
    if type(x) is float:  # a C cast, as numpy's, at a fifth of the cost (tests/test_numerics.py pins them equal)
        try:
            return _U32.unpack(_F32.pack(x))[0]
        except OverflowError:  # past float32's range: numpy's infinity
            pass
    return int(np.float32(x).view(np.uint32))


def f32_from_bits(bits: int) -> float:
    return float(np.uint32(bits & 0xFFFFFFFF).view(np.float32))


def to_f32(x) -> float:
    """Round a number to the nearest float32 and hand it back as a Python float (exact)."""
    try:  # a C cast, as numpy's, at 2.5x less cost (tests/test_numerics.py pins them equal)
        return _F32.unpack(_F32.pack(x))[0]
    except OverflowError:  # past float32's range: numpy's infinity (struct refuses it)
        return float(np.float32(x))


_F32xN = {3: struct.Struct("=3f"), 4: struct.Struct("=4f")}  # a point's or a quaternion's float32s


def to_f32s(p) -> tuple[float, ...]:
    """to_f32 of each of three or four numbers (a point, a quaternion), in one struct pack."""
    try:
        st = _F32xN[len(p)]
        return st.unpack(st.pack(*p))
    except OverflowError:
        return tuple(to_f32(c) for c in p)


def f32_next_up(x: float) -> float:
    """The next float32 above a float32 value x >= 0 (numpy's nextafter toward +inf, for x >= 0)."""
    return _F32.unpack(_U32.pack(_U32.unpack(_F32.pack(x + 0.0))[0] + 1))[0]  # + 0.0: -0 is 0


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
        # mono's System.Numerics: operator -(Vector3 value) => Zero - value (so -(0) is +0, not
        # -0); .NET 10 flips the sign bits (`net10_negate`). Port code negates through
        # `runtime.negate`, never with a bare `-v`.
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
    """System.Numerics.Quaternion (X, Y, Z, W) -- note AC files write (W, X, Y, Z).

    ``runtime`` (a class attribute, set below) is the runtime whose arithmetic made the value: this
    class is mono's, `Net10Quaternion` .NET 10's; each runtime's operations return its own class.

    A quaternion is never changed after construction, so what is computed from it alone is kept
    on it (see "memos" below): ``matrix``, its `Matrix4x4.create_from_quaternion`, and ``rotated``, the
    vectors `Vector3.Transform` has rotated by it."""

    __slots__ = ("x", "y", "z", "w", "matrix", "rotated")

    def __init__(self, x, y, z, w):
        self.x = x
        self.y = y
        self.z = z
        self.w = w
        self.matrix = None
        self.rotated = None

    def __eq__(self, o) -> bool:
        return (
            isinstance(o, Quaternion) and self.x == o.x and self.y == o.y and self.z == o.z and self.w == o.w
        )

    __hash__ = None

    def __repr__(self) -> str:
        return f"Quaternion({float(self.x)!r}, {float(self.y)!r}, {float(self.z)!r}, {float(self.w)!r})"

    def __mul__(self, o: "Quaternion") -> "Quaternion":
        return quat_multiply(self, o)

    def length(self):
        """Quaternion.Length (mono): (float)Math.Sqrt(X*X + Y*Y + Z*Z + W*W)."""
        ls = self.x * self.x + self.y * self.y + self.z * self.z + self.w * self.w
        return type(ls)(math.sqrt(ls))


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


# ---------------------------------------------------------------- memos
# A run applies the same rotation to the same vector again and again (a sphere's centre placed in
# every cell it is checked against, GlobalToLocal on one frame for every cell: about 80% of the
# rotations and 70% of the matrix transforms of a campaign scene repeat one done in that scene).
# The operand (a quaternion, a matrix) is immutable, so its results are kept on it, keyed by the
# vector's exact bits: the components packed as doubles (float32 and float64 both convert exactly,
# -0 and +0 stay apart; a NaN keeps its payload, a signalling NaN reads as the quiet one, which no
# scene or arithmetic here makes). Each runtime's formula packs with its own key layout, so one
# operand never answers for the other runtime's formula. A memo holds at most _MEMO_SIZE results
# and is emptied when full (operands in pooled landblocks live across runs).

_MEMO_SIZE = 64
_MONO_KEY = struct.Struct("<3d").pack  # 24 bytes
_NET10_KEY = struct.Struct("<3dx").pack  # 25 bytes: never equal to a mono key


def _remember(memo: dict, key: bytes, result: "Vector3") -> "Vector3":
    if len(memo) >= _MEMO_SIZE:
        memo.clear()
    memo[key] = result
    return result


def transform_by_quaternion(v: Vector3, q: Quaternion) -> Vector3:
    """Vector3.Transform(Vector3, Quaternion), mono's formula (.NET 10's: `net10_transform_by_quaternion`)."""
    memo = q.rotated
    if memo is None:
        memo = q.rotated = {}
    key = _MONO_KEY(v.x, v.y, v.z)
    r = memo.get(key)
    if r is not None:
        return r
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
    return _remember(memo, key, r)


class Matrix4x4:
    """The parts of System.Numerics.Matrix4x4 ACE's frames use: M11..M44, row-major fields.

    Immutable, like `Quaternion`: ``transposed`` keeps its `transpose`, ``transformed`` the vectors
    `Vector3.Transform` has transformed by it (see "memos" below)."""

    __slots__ = ("m", "transposed", "transformed")

    def __init__(self, m: tuple):
        self.m = m  # (M11, M12, M13, M14, M21, ..., M44)
        self.transposed = None
        self.transformed = None

    @staticmethod
    def create_from_quaternion(q: Quaternion) -> "Matrix4x4":
        """Matrix4x4.CreateFromQuaternion (the same bits on both runtimes), computed once per quaternion."""
        mat = q.matrix
        if mat is None:
            mat = q.matrix = Matrix4x4._from_quaternion(q)
        return mat

    @staticmethod
    def _from_quaternion(q: Quaternion) -> "Matrix4x4":
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
        t = self.transposed
        if t is None:
            m = self.m
            t = self.transposed = Matrix4x4(
                (m[0], m[4], m[8], m[12], m[1], m[5], m[9], m[13], m[2], m[6], m[10], m[14], m[3], m[7], m[11], m[15])
            )
        return t


def transform_by_matrix(v: Vector3, mat: Matrix4x4) -> Vector3:
    """Vector3.Transform(Vector3, Matrix4x4): the translation row is added (so -0 + 0 = +0)."""
    memo = mat.transformed
    if memo is None:
        memo = mat.transformed = {}
    key = _MONO_KEY(v.x, v.y, v.z)
    r = memo.get(key)
    if r is not None:
        return r
    m = mat.m
    r = _new(Vector3)
    r.x = v.x * m[0] + v.y * m[4] + v.z * m[8] + m[12]
    r.y = v.x * m[1] + v.y * m[5] + v.z * m[9] + m[13]
    r.z = v.x * m[2] + v.y * m[6] + v.z * m[10] + m[14]
    return _remember(memo, key, r)


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


# ---------------------------------------------------------------- .NET 10 (CoreCLR, x64 with FMA)
# .NET 10 computes System.Numerics through Vector128 helpers: horizontal sums pair up lanes
# ((x + y) + (z + w)), quaternion products follow DirectXMath's XMQuaternionMultiply, and every
# MultiplyAddEstimate is one fused multiply-add on hardware with FMA (all x64 since Haswell; the
# JIT emits vfmadd at every tier, checked with tiering on and off). Each formula below is checked
# bit for bit against .NET 10.0's answers (tests/data/numerics_net10*.json).

_DOUBLE = struct.Struct("<d")
_INT64 = struct.Struct("<q")


_NEG_ZERO = np.float32(-0.0)
_frexp = math.frexp


def fma(a, b, c):
    """``MultiplyAddEstimate(a, b, c)`` on float32 (fused on FMA hardware): a*b+c rounded once.

    a*b of two float32s is exact in a double, so s = a*b + c in double is rounded once there, and
    rounding s to float32 (a second rounding) gives the fused result unless s lands exactly halfway
    between two float32s: the exact sum is on the same side of every float32 tie as s (ties are
    doubles, and rounding to double is monotone). So the common case is one test of s's mantissa
    (a tie has a 1 right after float32's 24 bits and zeros after it: its frexp mantissa times 2^25
    is an odd integer) and a float32 rounding (``-0 + s``: NumPy rounds the Python float to float32,
    and adding -0 changes nothing, -0 included). A tie, or a result in float32's subnormal range
    (where the tie spacing is not the mantissa's), goes to `_fma_rounded_to_odd`. In fast mode
    (doubles) it is a*b + c, unfused: fast mode is a tolerance comparison anyway."""
    if type(a) is not np.float32:
        return a * b + c
    s = float(a) * float(b) + float(c)
    m, e = _frexp(s)  # s = m * 2^e, 0.5 <= |m| < 1 (inf and NaN: e = 0, and not a tie below)
    if e > -126 and (m * 33554432.0) % 2.0 != 1.0:  # |s| >= 2^-126 and not a tie
        return _NEG_ZERO + s
    return _fma_rounded_to_odd(a, b, c)


def _fma_rounded_to_odd(a, b, c):
    """`fma` where s may be a tie: TwoSum gives the double sum's error exactly, and rounding that
    sum to odd (when inexact, the neighbour with an odd last bit) keeps enough of it that the final
    float32 rounding is the correct one (the double has 53 >= 24 + 2 bits)."""
    p = float(a) * float(b)
    cc = float(c)
    s = p + cc
    if s - s != 0.0:  # inf or NaN: the IEEE result of a*b + c already
        return np.float32(s)
    bp = s - p
    e = (p - (s - bp)) + (cc - bp)  # TwoSum: p + cc == s + e exactly
    if e != 0.0 and not (_INT64.unpack(_DOUBLE.pack(s))[0] & 1):
        s = math.nextafter(s, math.inf if e > 0.0 else -math.inf)
    return np.float32(s)


def fma_double(a: float, b: float, c: float) -> float:
    """``double.MultiplyAddEstimate`` (fused): a*b+c rounded once, in exact integer arithmetic
    (Python's int true division rounds correctly, subnormals included)."""
    if a == 0.0 or b == 0.0 or not (math.isfinite(a) and math.isfinite(b) and math.isfinite(c)):
        return a * b + c  # an exact (signed zero) product, or IEEE's inf/NaN rules: one rounding
    na, da = a.as_integer_ratio()
    nb, db = b.as_integer_ratio()
    nc, dc = c.as_integer_ratio()
    n, d = na * nb, da * db  # denominators are powers of two
    if d >= dc:
        n, d = n + nc * (d // dc), d
    else:
        n, d = n * (dc // d) + nc, dc
    if n == 0:
        return 0.0  # an exact cancellation is +0 when rounding to nearest
    try:
        return n / d
    except OverflowError:
        return math.inf if n > 0 else -math.inf


class Net10Quaternion(Quaternion):
    """A quaternion made by .NET 10's arithmetic (see `Quaternion`)."""

    __slots__ = ()

    def __mul__(self, o: "Quaternion") -> "Quaternion":
        return net10_quat_multiply(self, o)

    def length(self):
        """Quaternion.Length on .NET 10: MathF.Sqrt of the Vector128.Dot LengthSquared."""
        ls = _net10_length_squared(self)
        return type(ls)(math.sqrt(ls))


def net10_quat_multiply(value1: Quaternion, value2: Quaternion) -> Quaternion:
    """Quaternion.Multiply / operator* on .NET 10: DirectXMath's order -- ``value2 * value1.W``,
    then three multiply-adds of shuffled value2 lanes times value1.X, .Y, .Z by +-1 (a fused
    multiply by +-1 rounds once, as the plain add or subtract written here does)."""
    lx, ly, lz, lw = value1.x, value1.y, value1.z, value1.w
    rx, ry, rz, rw = value2.x, value2.y, value2.z, value2.w
    return Net10Quaternion(
        ((rx * lw + rw * lx) + rz * ly) - ry * lz,
        ((ry * lw - rz * lx) + rw * ly) + rx * lz,
        ((rz * lw + ry * lx) - rx * ly) + rw * lz,
        ((rw * lw - rx * lx) - ry * ly) - rz * lz,
    )


def _net10_length_squared(q: Quaternion):
    """Quaternion.LengthSquared on .NET 10: Vector128.Dot, summed ((x*x + y*y) + (z*z + w*w))."""
    return (q.x * q.x + q.y * q.y) + (q.z * q.z + q.w * q.w)


def net10_quat_normalize(q: Quaternion) -> Quaternion:
    """Quaternion.Normalize on .NET 10: each lane divided by Length() (mono multiplies by 1/length)."""
    ls = _net10_length_squared(q)
    length = type(ls)(math.sqrt(ls))
    return Net10Quaternion(q.x / length, q.y / length, q.z / length, q.w / length)


def net10_quat_inverse(q: Quaternion) -> Quaternion:
    """Quaternion.Inverse on .NET 10: Conjugate(q) divided lane by lane by LengthSquared()."""
    ls = _net10_length_squared(q)
    return Net10Quaternion(-q.x / ls, -q.y / ls, -q.z / ls, q.w / ls)


def net10_quat_lerp(a: Quaternion, b: Quaternion, t) -> Quaternion:
    """Quaternion.Lerp on .NET 10: ``MultiplyAddEstimate(a, 1 - t, b * +-t)`` per lane (the sign
    of +-t from the pairwise Dot of a and b), then Normalize."""
    t1 = 1.0 - t
    d = (a.x * b.x + a.y * b.y) + (a.z * b.z + a.w * b.w)
    s = t if d >= 0.0 else -t
    return net10_quat_normalize(Net10Quaternion(
        fma(a.x, t1, b.x * s), fma(a.y, t1, b.y * s), fma(a.z, t1, b.z * s), fma(a.w, t1, b.w * s)))


def net10_transform_by_quaternion(v: Vector3, q: Quaternion) -> Vector3:
    """Vector3.Transform(Vector3, Quaternion) on .NET 10: Vector4.Transform of (v, 1), that is
    ``Concatenate(Concatenate(Conjugate(q), (v, 1)), q)`` = ``q * ((v, 1) * Conjugate(q))``, X Y Z
    kept; both products written out as `net10_quat_multiply` computes them (no objects between).
    The products by the fourth lane's 1 are left out: x * 1 is x, bit for bit (-0, inf and NaN too)."""
    memo = q.rotated
    if memo is None:
        memo = q.rotated = {}
    key = _NET10_KEY(v.x, v.y, v.z)
    out = memo.get(key)
    if out is not None:
        return out
    lx, ly, lz = v.x, v.y, v.z  # (v, 1): lw = 1
    rx, ry, rz, rw = -q.x, -q.y, -q.z, q.w
    tx = ((rx + rw * lx) + rz * ly) - ry * lz  # t = (v, 1) * Conjugate(q)
    ty = ((ry - rz * lx) + rw * ly) + rx * lz
    tz = ((rz + ry * lx) - rx * ly) + rw * lz
    tw = ((rw - rx * lx) - ry * ly) - rz * lz
    lx, ly, lz, lw = q.x, q.y, q.z, q.w  # q * t
    out = _new(Vector3)
    out.x = ((tx * lw + tw * lx) + tz * ly) - ty * lz
    out.y = ((ty * lw - tz * lx) + tw * ly) + tx * lz
    out.z = ((tz * lw + ty * lx) - tx * ly) + tw * lz
    return _remember(memo, key, out)


def net10_negate(v: Vector3) -> Vector3:
    """Vector3 unary minus on .NET 10: Vector128 negation flips each sign bit, so -(+0) is -0
    (mono computes Zero - v, which gives +0)."""
    r = _new(Vector3)
    r.x = -v.x
    r.y = -v.y
    r.z = -v.z
    return r


def net10_lerp(a: Vector3, b: Vector3, t) -> Vector3:
    """Vector3.Lerp on .NET 10: ``MultiplyAddEstimate(a, 1 - t, b * t)`` per lane (mono: a + (b - a) * t)."""
    t1 = 1.0 - t
    r = _new(Vector3)
    r.x = fma(a.x, t1, b.x * t)
    r.y = fma(a.y, t1, b.y * t)
    r.z = fma(a.z, t1, b.z * t)
    return r


def net10_transform_by_matrix(v: Vector3, mat: Matrix4x4) -> Vector3:
    """Vector3.Transform(Vector3, Matrix4x4) on .NET 10: rows X, Y, Z, W of the matrix,
    ``MultiplyAddEstimate(Z, v.z, MultiplyAddEstimate(Y, v.y, X * v.x)) + W`` per lane."""
    memo = mat.transformed
    if memo is None:
        memo = mat.transformed = {}
    key = _NET10_KEY(v.x, v.y, v.z)
    r = memo.get(key)
    if r is not None:
        return r
    m = mat.m
    x, y, z = v.x, v.y, v.z
    r = _new(Vector3)
    r.x = fma(m[8], z, fma(m[4], y, m[0] * x)) + m[12]
    r.y = fma(m[9], z, fma(m[5], y, m[1] * x)) + m[13]
    r.z = fma(m[10], z, fma(m[6], y, m[2] * x)) + m[14]
    return _remember(memo, key, r)


# Vector128.SinCos(Vector128<float>) on .NET 10 (VectorMath.SinCosSingle, from AMD's aocl-libm
# sinf/cosf): one branch for all four lanes, chosen by every lane's magnitude.
_SINCOS_HUGE = 0x4A989680  # 5e6: at or above it (or NaN/inf) in any lane, the scalar sinf/cosf
_SINCOS_LARGE = 0x3F490FDB  # pi/4: every lane at or below it, no argument reduction
_SINCOS_SMALL = 0x3C000000  # 2^-7: every lane below it, the float Taylor terms
_SINCOS_SMALLER = 0x39000000  # 2^-13: a lane below it gives (x, 1)
_SHIFT = 6755399441055744.0  # 1.5 * 2^52: rounds to an integer in the low mantissa bits


def _sin_single_poly(r: float) -> float:
    r2 = r * r
    r3 = r2 * r
    r4 = r2 * r2
    return fma_double(fma_double(fma_double(2.7557316103728802e-06, r2, -0.00019841269836761127), r4,
                                 fma_double(0.00833333333333095, r2, -1.0 / 6.0)), r3, r)


def _cos_single_poly(r: float) -> float:
    r2 = r * r
    r4 = r2 * r2
    return fma_double(fma_double(-2.755731727234489e-07, r2, 2.4801587298767044e-05), r4,
                      fma_double(-0.0013888888888887398, r2, 1.0 / 24.0))


def _cos_single_small(x: float) -> float:
    x2 = x * x
    x4 = x2 * x2
    half = x2 * 0.5
    t = 1.0 - half
    return fma_double(_cos_single_poly(x), x4, t + ((1.0 - t) - half))


def _cos_single_large(r: float) -> float:
    r2 = r * r
    return fma_double(_cos_single_poly(r), r2 * r2, fma_double(-0.5, r2, 1.0))


def _sin_cos_reduce(ax: float) -> tuple[float, int]:
    """|x| reduced by multiples of pi/2 (three-part pi/2), and the multiple's low bits (the region)."""
    npi2 = fma_double(2.0 / math.pi, ax, _SHIFT)
    region = _INT64.unpack(_DOUBLE.pack(npi2))[0]
    npi2 -= _SHIFT
    rhead = fma_double(-1.5707963267341256, npi2, ax)
    rtail = npi2 * 6.077100506303966e-11
    r = rhead - rtail
    rtail = fma_double(2.0222662487959506e-21, npi2, -((rhead - r) - rtail))
    return r - rtail, region


def _sin_cos_reduced(x: float) -> tuple[float, float]:
    r, region = _sin_cos_reduce(abs(x))
    s, c = _sin_single_poly(r), _cos_single_large(r)
    if region & 1:
        s, c = c, s
    sign = 1 if math.copysign(1.0, x) < 0.0 else 0
    half = region >> 1
    if ((sign & half) | (~sign & ~half)) & 1 == 0:
        s = -s
    if (region + 1) & 2:
        c = -c
    return s, c


def net10_sin_cos4(lanes: list) -> tuple[list, list]:
    """Vector128.SinCos over four float32 lanes: (sines, cosines)."""
    f = np.float32
    mags = [int(abs(f(x)).view(np.uint32)) for x in lanes]
    if all(m <= _SINCOS_LARGE for m in mags):
        if any(m >= _SINCOS_SMALL for m in mags):
            sin = [f(_sin_single_poly(float(x))) for x in lanes]
            cos = [f(_cos_single_small(float(x))) for x in lanes]
        else:
            sin = [fma(f(-0.16666667), (x * x) * x, x) for x in lanes]
            cos = [fma(f(-0.5), x * x, f(1.0)) for x in lanes]
    elif all(m < _SINCOS_HUGE for m in mags):
        pairs = [_sin_cos_reduced(float(x)) for x in lanes]
        sin = [f(s) for s, _ in pairs]
        cos = [f(c) for _, c in pairs]
    else:  # float.SinCos on each lane (the C library's sinf/cosf), returned as is
        return [mathf_sin(x) for x in lanes], [mathf_cos(x) for x in lanes]
    for i, m in enumerate(mags):
        if m < _SINCOS_SMALLER:
            sin[i] = lanes[i]
            cos[i] = f(1.0)
    return sin, cos


def net10_quat_create_from_yaw_pitch_roll(yaw, pitch, roll) -> Quaternion:
    """Quaternion.CreateFromYawPitchRoll on .NET 10: the half angles' sines and cosines from one
    Vector128.SinCos of (roll, pitch, yaw, 0) * 0.5, combined as mono does. Fast mode (doubles)
    takes Math.Sin/Cos of the half angles."""
    half_roll = roll * 0.5
    half_pitch = pitch * 0.5
    half_yaw = yaw * 0.5
    if type(half_roll) is np.float32:
        (sr, sp, sy, _), (cr, cp, cy, _) = net10_sin_cos4([half_roll, half_pitch, half_yaw, np.float32(0.0)])
    else:
        sr, sp, sy = (cast_float(a, cs_math(math.sin, float(a))) for a in (half_roll, half_pitch, half_yaw))
        cr, cp, cy = (cast_float(a, cs_math(math.cos, float(a))) for a in (half_roll, half_pitch, half_yaw))
    return Net10Quaternion(
        cy * sp * cr + sy * cp * sr,
        sy * cp * cr - cy * sp * sr,
        cy * cp * sr - sy * sp * cr,
        cy * cp * cr + sy * sp * sr,
    )


# ---------------------------------------------------------------- runtimes and modes


def _fn():
    """A Runtime field holding a function (not part of the runtime's identity)."""
    return field(compare=False, repr=False)


@dataclass(frozen=True, slots=True)
class Runtime:
    """The .NET runtime ACE runs on: where its arithmetic differs, the difference lives here.

    The System.Numerics operations are plain functions (call ``runtime.lerp(a, b, t)``); every
    operation not listed computes the same bits on both runtimes (measured: Vector3 Dot, Cross,
    Length, LengthSquared, Normalize, scalar multiply and divide, Equals, Vector2.Length,
    Matrix4x4.CreateFromQuaternion)."""

    name: str
    quaternion: type = _fn()  # the Quaternion class this runtime's operations return
    negate: object = _fn()  # Vector3 unary minus
    transform_by_quaternion: object = _fn()  # Vector3.Transform(Vector3, Quaternion)
    transform_by_matrix: object = _fn()  # Vector3.Transform(Vector3, Matrix4x4)
    lerp: object = _fn()  # Vector3.Lerp
    quat_multiply: object = _fn()  # Quaternion.Multiply, operator *
    quat_inverse: object = _fn()  # Quaternion.Inverse
    quat_normalize: object = _fn()  # Quaternion.Normalize
    quat_lerp: object = _fn()  # Quaternion.Lerp
    quat_create_from_yaw_pitch_roll: object = _fn()  # Quaternion.CreateFromYawPitchRoll

    def to_int32(self, x) -> int:
        """C# ``(int)x`` for a float or double x."""
        x = float(x)
        if -2147483649.0 < x < 2147483648.0:  # truncates into int's range (NaN and +-inf fail the test)
            return int(x)
        if self.name == "mono":
            # x86-64 cvttsd2si: NaN and out-of-range give int.MinValue (checked on mono 6.8).
            return -2147483648
        # .NET 9+ (CoreCLR): conversions saturate and NaN gives 0.
        if math.isnan(x):
            return 0
        return 2147483647 if x > 0.0 else -2147483648

    def to_uint32(self, x) -> int:
        """C# ``(uint)x`` for a float or double x."""
        x = float(x)
        if 0.0 < x < 4294967296.0:  # truncates into uint's range: the same on both runtimes
            return int(x)
        if self.name == "mono":
            # mono converts through a 64-bit cvtt and keeps the low 32 bits (NaN, +-inf and
            # out-of-range fail the range test and give 0).
            if -9.223372036854775808e18 <= x < 9.223372036854775808e18:
                return int(x) & 0xFFFFFFFF
            return 0
        # .NET 9+ (CoreCLR): saturate, NaN gives 0.
        if math.isnan(x) or x <= 0.0:
            return 0
        return 4294967295


MONO = Runtime(
    "mono", Quaternion, Vector3.__neg__, transform_by_quaternion, transform_by_matrix, lerp, quat_multiply, quat_inverse,
    quat_normalize, quat_lerp, quat_create_from_yaw_pitch_roll,
)
NET10 = Runtime(
    "coreclr", Net10Quaternion, net10_negate, net10_transform_by_quaternion, net10_transform_by_matrix, net10_lerp,
    net10_quat_multiply, net10_quat_inverse, net10_quat_normalize, net10_quat_lerp,
    net10_quat_create_from_yaw_pitch_roll,
)
RUNTIMES = {"mono": MONO, "coreclr": NET10}
Quaternion.runtime = MONO
Net10Quaternion.runtime = NET10


def runtime_named(versions_runtime: str) -> str:
    """The runtime key ("mono" or "coreclr") of a record's or oracle's runtime string, e.g.
    "mono 6.8.0.105" or "coreclr .NET 10.0.12" (its first word). An empty string is "mono":
    records and cases written without a runtime all came from ACE on mono."""
    from .errors import AcconformError

    if not versions_runtime.strip():
        return "mono"
    names = {part.strip().split(" ")[0] for part in versions_runtime.split(";") if part.strip()}
    if len(names) != 1 or not names <= set(RUNTIMES):
        raise AcconformError(
            f"cannot tell which runtime's arithmetic to use from {versions_runtime!r}: expected one of "
            f"{', '.join(sorted(RUNTIMES))} (a corpus must come from one runtime)")
    return names.pop()


@dataclass(frozen=True, slots=True)
class Mode:
    """How a run computes: `scalar` is the component type every value is made of, `runtime` the
    .NET runtime whose arithmetic it reproduces."""

    name: str
    scalar: type
    runtime: Runtime = MONO

    def vec(self, x, y, z) -> "Vector3":
        s = self.scalar
        return Vector3(s(x), s(y), s(z))

    def quat(self, x, y, z, w) -> "Quaternion":
        s = self.scalar
        return self.runtime.quaternion(s(x), s(y), s(z), s(w))


EXACT = Mode("exact", np.float32)
FAST = Mode("fast", np.float64)
MODES = {"exact": EXACT, "fast": FAST}
_MODES = {(m.name, r.name): m if r is MONO else Mode(m.name, m.scalar, r) for m in MODES.values() for r in RUNTIMES.values()}


def get_mode(name: str, runtime: str = "mono") -> Mode:
    """The mode `name` ("exact" or "fast") computing as `runtime` ("mono" or "coreclr") does."""
    from .errors import AcconformError

    if name not in MODES:
        raise AcconformError(f"unknown numerics mode {name!r}: choose one of {sorted(MODES)}")
    if runtime not in RUNTIMES:
        raise AcconformError(f"unknown runtime {runtime!r}: choose one of {sorted(RUNTIMES)}")
    return _MODES[name, runtime]
