"""Exact mode is binary32 after every operation; C# scalar rules; constants pinned by bits."""

import functools
import math
import struct

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from acconform import numerics as nx
from acconform.numerics import EXACT, FAST, MONO, NET10, cs_ceiling, cs_floor, cs_fmod, f32_bits
from acconform.port import constants as k

_P = struct.Struct("<f")


def r32(x: float) -> float:
    """Independent float32 rounding (struct, not numpy): a double rounded to binary32."""
    try:
        return _P.unpack(_P.pack(x))[0]
    except OverflowError:
        return math.copysign(math.inf, x)


def bits_of(x) -> int:
    return struct.unpack("<I", _P.pack(float(x)))[0] if math.isfinite(x) or math.isinf(x) else f32_bits(x)


f32s = st.floats(width=32, allow_nan=False)


def same(a, b) -> bool:
    return f32_bits(a) == f32_bits(b)


@settings(max_examples=2000)
@given(f32s, f32s)
def test_exact_scalar_ops_equal_double_ops_rounded_to_float32(a, b):
    # Includes subnormals, signed zeros and overflow to inf: hypothesis draws all of them.
    x, y = np.float32(a), np.float32(b)
    with np.errstate(all="ignore"):
        assert same(x + y, r32(a + b))
        assert same(x - y, r32(a - b))
        assert same(x * y, r32(a * b))
        if b != 0:
            assert same(x / y, r32(a / b))
        if a >= 0:
            assert same(np.float32(math.sqrt(x)), r32(math.sqrt(a)))


def test_overflow_goes_to_infinity_and_subnormals_survive():
    big = np.float32(3e38)
    with np.errstate(over="ignore"):
        assert np.isinf(big * np.float32(2))
    tiny = np.float32(1e-45)
    assert f32_bits(tiny) == 1 and f32_bits(tiny * np.float32(0.5)) == 0


@settings(max_examples=1000)
@given(st.lists(f32s.filter(lambda v: abs(v) < 1e15), min_size=6, max_size=6))
def test_vector_ops_round_every_step_to_float32(c):
    a = EXACT.vec(*c[:3])
    b = EXACT.vec(*c[3:])
    with np.errstate(all="ignore"):
        d = nx.dot(a, b)
        ref = r32(r32(r32(c[0] * c[3]) + r32(c[1] * c[4])) + r32(c[2] * c[5]))
        assert same(d, ref)
        cr = nx.cross(a, b)
        assert same(cr.x, r32(r32(c[1] * c[5]) - r32(c[2] * c[4])))
        ls = r32(r32(r32(c[0] * c[0]) + r32(c[1] * c[1])) + r32(c[2] * c[2]))
        assert same(a.length(), r32(math.sqrt(ls)))
        if ls > 0 and math.isfinite(ls):
            n = nx.normalize(a)
            L = r32(math.sqrt(ls))
            assert same(n.x, r32(c[0] / L)) and same(n.z, r32(c[2] / L))


def test_weak_python_constants_take_the_modes_type():
    v = EXACT.scalar(1.0) * k.FLOOR_Z
    assert type(v) is np.float32 and f32_bits(v) == 0x3F2A0751
    w = FAST.scalar(1.0) * k.FLOOR_Z
    assert type(w) is np.float64


def test_fast_mode_vectors_compute_in_double():
    a = FAST.vec(0.1, 0.2, 0.3)
    assert type(nx.dot(a, a)) is np.float64
    assert nx.dot(a, a) == 0.1 * 0.1 + 0.2 * 0.2 + 0.3 * 0.3


@pytest.mark.parametrize(
    "name, value, bits",
    [
        ("EPSILON", k.EPSILON, 0x3951B717),
        ("EPSILON_SQ", k.EPSILON_SQ, 0x332BCC76),
        ("FLOOR_Z", k.FLOOR_Z, 0x3F2A0751),
        ("LANDING_Z", k.LANDING_Z, 0x3DB27EB0),
        ("DUMMY_SPHERE_RADIUS", k.DUMMY_SPHERE_RADIUS, 0x3DCCCCCD),
        ("GRAVITY", k.GRAVITY, 0xC11CCCCD),
        ("DEFAULT_STEP_HEIGHT", k.DEFAULT_STEP_HEIGHT, 0x3C23D70A),
        ("STEP_DOWN_PROBE", k.STEP_DOWN_PROBE, 0x3D23D70A),
        ("STEP_INTERP_LIMIT", k.STEP_INTERP_LIMIT, 0xBDCCCCCD),
        ("ADJUST_TO_PLANE_INTERP_LIMIT", k.ADJUST_TO_PLANE_INTERP_LIMIT, 0xBF000000),
        ("CELL_BSP_SLACK", k.CELL_BSP_SLACK, 0x3C23D70A),
        ("WATER_DEPTH_PARTIAL_WATER", k.WATER_DEPTH_PARTIAL_WATER, 0x3EE66666),
        ("WATER_DEPTH_ENTIRELY_WATER", k.WATER_DEPTH_ENTIRELY_WATER, 0x3F666666),
        ("WATER_DEPTH_DRY", k.WATER_DEPTH_DRY, 0x3DCCCCCD),
        ("PLACEMENT_ADJUST_DIST", k.PLACEMENT_ADJUST_DIST, 0x40800000),
        ("PLACEMENT_FAKE_ADJUST_RAD", k.PLACEMENT_FAKE_ADJUST_RAD, 0x40000000),
        ("PLACEMENT_FAKE_SPHERE_RADIUS", k.PLACEMENT_FAKE_SPHERE_RADIUS, 0x3E000000),
        ("PLACEMENT_MIN_RADIUS", k.PLACEMENT_MIN_RADIUS, 0x3EF5C28F),
        ("PLACEMENT_CLOSE", k.PLACEMENT_CLOSE, 0x3D4CCCCD),
        ("QUAT_VALID_SLACK", k.QUAT_VALID_SLACK, 0x3A83126E),
        ("DEFAULT_ELASTICITY", k.DEFAULT_ELASTICITY, 0x3D4CCCCD),
        ("MIN_QUANTUM", k.MIN_QUANTUM, 0x3D088889),
        ("MAX_QUANTUM", k.MAX_QUANTUM, 0x3DCCCCCD),
        ("HUGE_QUANTUM", k.HUGE_QUANTUM, 0x40000000),
        ("TICK_RATE", k.TICK_RATE, 0x3D088889),
        ("MAX_VELOCITY", k.MAX_VELOCITY, 0x42480000),
        ("MAX_VELOCITY_SQUARED", k.MAX_VELOCITY_SQUARED, 0x451C4000),
        ("SMALL_VELOCITY", k.SMALL_VELOCITY, 0x3E800000),
        ("SMALL_VELOCITY_SQUARED", k.SMALL_VELOCITY_SQUARED, 0x3D800000),
        ("DEFAULT_FRICTION", k.DEFAULT_FRICTION, 0x3F733333),
        ("FRICTION_LEAVING_ANGLE", k.FRICTION_LEAVING_ANGLE, 0x3E800000),
        ("SLEDDING_STOP_SPEED_SQUARED", k.SLEDDING_STOP_SPEED_SQUARED, 0x3FC80000),
        ("SLEDDING_STOP_FRICTION", k.SLEDDING_STOP_FRICTION, 0x3F800000),
        ("SLEDDING_GLIDE_SPEED_SQUARED", k.SLEDDING_GLIDE_SPEED_SQUARED, 0x40C80000),
        ("SLEDDING_FLAT_Z", k.SLEDDING_FLAT_Z, 0x3F7FFFB2),
        ("SLEDDING_GLIDE_FRICTION", k.SLEDDING_GLIDE_FRICTION, 0x3E4CCCCD),
        ("COLLISION_RECORD_LIFETIME", k.COLLISION_RECORD_LIFETIME, 0x3F800000),
    ],
)
def test_constants_are_pinned_by_their_float32_bit_patterns(name, value, bits):
    assert f32_bits(value) == bits
    assert float(np.float32(value)) == value, f"{name} must be an exact float32"


def test_constants_match_the_csharp_literals_they_come_from():
    assert f32_bits(0.0002) == f32_bits(k.EPSILON)
    assert f32_bits(0.66417414618662751) == f32_bits(k.FLOOR_Z)
    assert f32_bits(0.0871557) == f32_bits(k.LANDING_Z)
    assert f32_bits(0.039999999) == f32_bits(k.STEP_DOWN_PROBE)
    assert f32_bits(np.float32(0.0002) * np.float32(0.0002)) == f32_bits(k.EPSILON_SQ)
    assert f32_bits(-0.1) == f32_bits(k.STEP_INTERP_LIMIT)
    assert f32_bits(0.44999999) == f32_bits(k.WATER_DEPTH_PARTIAL_WATER)
    assert f32_bits(0.89999998) == f32_bits(k.WATER_DEPTH_ENTIRELY_WATER)
    assert f32_bits(0.48) == f32_bits(k.PLACEMENT_MIN_RADIUS)
    assert f32_bits(0.05) == f32_bits(k.PLACEMENT_CLOSE)
    assert f32_bits(np.float32(0.0002) * np.float32(5.0)) == f32_bits(k.QUAT_VALID_SLACK)
    # the tick's: 1.0f / 30.0f and the squares are folded by the C# compiler in float32
    assert f32_bits(np.float32(1.0) / np.float32(30.0)) == f32_bits(k.MIN_QUANTUM) == f32_bits(k.TICK_RATE)
    assert f32_bits(0.1) == f32_bits(k.MAX_QUANTUM) and f32_bits(0.95) == f32_bits(k.DEFAULT_FRICTION)
    assert f32_bits(np.float32(50.0) * np.float32(50.0)) == f32_bits(k.MAX_VELOCITY_SQUARED)
    assert f32_bits(np.float32(0.25) * np.float32(0.25)) == f32_bits(k.SMALL_VELOCITY_SQUARED)
    assert f32_bits(0.99999536) == f32_bits(k.SLEDDING_FLAT_Z) and f32_bits(0.2) == f32_bits(k.SLEDDING_GLIDE_FRICTION)
    assert f32_bits(1.5625) == f32_bits(k.SLEDDING_STOP_SPEED_SQUARED) and f32_bits(6.25) == f32_bits(k.SLEDDING_GLIDE_SPEED_SQUARED)


def test_the_quanta_widen_to_double_as_their_float32_values_not_the_decimal_literals():
    # update_object compares a double deltaTime with the float constants: (double)0.1f, not 0.1
    assert k.MAX_QUANTUM == 0.10000000149011612 and k.MAX_QUANTUM != 0.1
    assert k.MIN_QUANTUM == 0.03333333507180214 and k.MIN_QUANTUM != 1.0 / 30.0
    assert type(k.MAX_QUANTUM) is float and type(k.MIN_QUANTUM) is float


def test_math_floor_and_ceiling_pass_infinities_and_nan_through_as_csharp_does():
    assert cs_floor(-2.5) == -3.0 and cs_ceiling(-2.5) == -2.0
    assert cs_floor(math.inf) == math.inf and math.isnan(cs_ceiling(math.nan))
    assert math.copysign(1, cs_floor(-0.0)) == -1
    assert math.copysign(1, cs_ceiling(-0.5)) == -1 and math.copysign(1, cs_ceiling(0.5)) == 1
    for x in (-3.5, -1.0, -0.75, -0.0, 0.0, 0.25, 1.0, 7.999):
        assert math.copysign(1, cs_floor(x)) == math.copysign(1, float(np.floor(x))) and cs_floor(x) == np.floor(x)
        assert math.copysign(1, cs_ceiling(x)) == math.copysign(1, float(np.ceil(x))) and cs_ceiling(x) == np.ceil(x)


def test_float_remainder_truncates_toward_zero_like_csharp():
    # C#: 5.5f % -2f == 1.5f and -5.5f % 2f == -1.5f (checked on mono)
    assert cs_fmod(np.float32(5.5), np.float32(-2)) == 1.5
    assert cs_fmod(np.float32(-5.5), np.float32(2)) == -1.5
    assert type(cs_fmod(np.float32(1), np.float32(3))) is np.float32


def test_int_wraparound_matches_unchecked_csharp():
    assert nx.wrap_i32(0x7FFFFFFF + 1) == -0x80000000
    assert nx.wrap_i32(-0x80000000 - 1) == 0x7FFFFFFF
    assert nx.wrap_u32(-1) == 0xFFFFFFFF


def test_float_to_int_casts_follow_the_runtime():
    # mono 6.8 (checked with mcs): out of range and NaN give int.MinValue; uint goes through int64.
    assert MONO.to_int32(3e9) == -2147483648 and MONO.to_int32(math.nan) == -2147483648
    assert MONO.to_int32(-2.5) == -2 and MONO.to_int32(2147483520.0) == 2147483520
    assert MONO.to_uint32(-3e9) == 1294967296 and MONO.to_uint32(-2.5) == 4294967294
    assert MONO.to_uint32(math.inf) == 0
    # .NET 9+ CoreCLR saturates and maps NaN to 0.
    assert NET10.to_int32(3e9) == 2147483647 and NET10.to_int32(math.nan) == 0
    assert NET10.to_uint32(-2.5) == 0


def test_quaternion_identity_rotation_leaves_vectors_bit_identical():
    v = EXACT.vec(1.5, -2.25, 3.0)
    q = EXACT.quat(0, 0, 0, 1)
    r = nx.transform_by_quaternion(v, q)
    assert (f32_bits(r.x), f32_bits(r.y), f32_bits(r.z)) == (f32_bits(1.5), f32_bits(-2.25), f32_bits(3.0))
    m = nx.Matrix4x4.create_from_quaternion(q).transpose()
    r2 = nx.transform_by_matrix(v, m)
    assert r2 == v


def test_the_matrix_transform_adds_its_translation_row_so_negative_zero_becomes_positive():
    q = EXACT.quat(0, 0, 0, 1)
    m = nx.Matrix4x4.create_from_quaternion(q)
    r = nx.transform_by_matrix(EXACT.vec(-0.0, 0.0, 0.0), m)
    assert f32_bits(r.x) == 0  # -0*1 + 0*0 + 0*0 + 0 == +0


def test_vectors_are_immutable_values():
    v = EXACT.vec(1, 2, 3)
    w = v.with_z(np.float32(5))
    assert v.z == 3 and w.z == 5
    with pytest.raises(TypeError):
        hash(v)


def test_unknown_modes_and_runtimes_are_refused_with_a_clear_message():
    from acconform.errors import AcconformError

    with pytest.raises(AcconformError, match="unknown numerics mode"):
        nx.get_mode("quad")
    with pytest.raises(AcconformError, match="unknown runtime"):
        nx.get_mode("exact", "net48")


def test_a_mode_computes_as_the_runtime_it_names_and_keeps_its_scalar_type():
    for name, scalar in (("exact", np.float32), ("fast", np.float64)):
        for runtime, rt in (("mono", MONO), ("coreclr", NET10)):
            m = nx.get_mode(name, runtime)
            assert m.scalar is scalar and m.runtime is rt and m.quat(0, 0, 0, 1).runtime is rt
    assert nx.get_mode("exact") is EXACT and nx.get_mode("fast") is FAST


def test_each_runtimes_quaternion_operations_return_that_runtimes_quaternions():
    for rt in (MONO, NET10):
        a, b = rt.quaternion(*map(np.float32, (0.1, 0.2, 0.3, 0.9))), rt.quaternion(*map(np.float32, (0.5, -0.5, 0.5, 0.5)))
        made = [rt.quat_multiply(a, b), rt.quat_inverse(a), rt.quat_normalize(a), rt.quat_lerp(a, b, np.float32(0.3)),
                rt.quat_create_from_yaw_pitch_roll(np.float32(0.1), np.float32(0.2), np.float32(0.3)), a * b]
        assert all(type(q) is rt.quaternion and q.runtime is rt for q in made)


def test_a_record_or_oracle_runtime_string_names_the_arithmetic_to_use():
    from acconform.errors import AcconformError

    assert nx.runtime_named("mono 6.8.0.105") == "mono"
    assert nx.runtime_named("coreclr .NET 10.0.12") == "coreclr"
    assert nx.runtime_named("mono 6.8.0.105; mono 6.8.0.123") == "mono"
    with pytest.raises(AcconformError, match="one runtime"):
        nx.runtime_named("coreclr .NET 10.0.12; mono 6.8.0.105")
    assert nx.runtime_named("") == "mono"  # written before runtimes were recorded: all from mono
    with pytest.raises(AcconformError, match="cannot tell"):
        nx.runtime_named("net48 4.8")


# ---------------------------------------------------------------- fused multiply-add (.NET 10)


@functools.cache  # find_library runs ldconfig: once per example, it was nearly all of these tests' time
def _libm_fma():
    import ctypes
    import ctypes.util

    lib = ctypes.CDLL(ctypes.util.find_library("m") or "libm.so.6")
    lib.fmaf.restype = ctypes.c_float
    lib.fmaf.argtypes = [ctypes.c_float] * 3
    lib.fma.restype = ctypes.c_double
    lib.fma.argtypes = [ctypes.c_double] * 3
    return lib


def _fma_exact(a: float, b: float, c: float) -> float:
    """a*b + c rounded once to float32 (ties to even), from exact rationals: an independent reference."""
    from fractions import Fraction

    exact = Fraction(a) * Fraction(b) + Fraction(c)
    if exact == 0:
        return -0.0 if math.copysign(1, a) * math.copysign(1, b) < 0 and math.copysign(1, c) < 0 else 0.0
    mag = abs(exact)
    e = mag.numerator.bit_length() - mag.denominator.bit_length()  # 2^e <= mag < 2^(e+2)
    if Fraction(2) ** e > mag:
        e -= 1
    ulp = Fraction(2) ** (max(e, -126) - 23)
    q, rem = divmod(mag, ulp)
    if rem * 2 > ulp or (rem * 2 == ulp and q % 2 == 1):
        q += 1
    out = float(q * ulp)
    if out > 3.4028234663852886e38:
        out = math.inf
    return math.copysign(out, exact)


# Hard cases: the double sum lands exactly halfway between two float32s (a tie) although the exact
# value does not (double rounding would go the wrong way), ties that are exact, subnormal results,
# cancellation to zero, overflow, infinities and NaN.
_HARD = [
    (1.0 + 2.0 ** -23, 1.0 + 2.0 ** -23, -(2.0 ** -46)),  # (1+u)^2 - u^2 = 1 + 2u exactly
    (1.0 + 2.0 ** -12, 1.0 + 2.0 ** -12, 2.0 ** -70),  # 1 + 2^-11 + 2^-24 + tiny: just above a tie
    (1.0 + 2.0 ** -12, 1.0 + 2.0 ** -12, -(2.0 ** -70)),  # just below a tie
    (1.0 + 2.0 ** -12, 1.0 - 2.0 ** -12, 2.0 ** -24),  # 1 - 2^-24 + 2^-24 = 1 exactly
    (3.0, 2.0 ** -25, 1.0),  # 1 + 3*2^-25: not a tie, rounds up
    (1.0, 2.0 ** -24, 1.0),  # exactly halfway: to even (1.0)
    (1.0, 3.0 * 2.0 ** -24, 1.0),  # exactly halfway: to even (1 + 2^-22)
    (2.0 ** -75, 2.0 ** -75, 2.0 ** -149),  # subnormal addend, tiny product
    (2.0 ** -70, 2.0 ** -70, -(2.0 ** -140)),  # subnormal result
    (1.5 * 2.0 ** -75, 2.0 ** -75, 2.0 ** -149),  # subnormal tie
    (2.0, 3.0, -6.0),  # exact cancellation: +0
    (-0.0, 1.0, -0.0),  # -0 * 1 + -0 = -0
    (0.0, -1.0, 0.0),  # -0 + +0 = +0
    (3.0e38, 10.0, -3.0e38),  # the product overflows float32 but the sum does not
    (3.0e38, 2.0, 1.0),  # overflow to inf
    (math.inf, 0.0, 1.0),  # inf * 0 = NaN
    (math.inf, 1.0, -math.inf),  # inf - inf = NaN
    (math.inf, 2.0, 1.0),
    (math.nan, 1.0, 1.0),
    (1.0, 1.0, math.nan),
    (2.0 ** -63, 2.0 ** -63, 0.0),  # exactly 2^-126, the smallest normal: the tie test applies
    (1.5 * 2.0 ** -64, 2.0 ** -63, -(2.0 ** -149)),  # just below it: float32's subnormal spacing
    (3.4028234663852886e38, 1.0, 2.0 ** 103),  # FLT_MAX + half an ulp, a tie: to even, inf
    (3.4028234663852886e38, 1.0 + 2.0 ** -23, -(2.0 ** 104)),  # near FLT_MAX, inexact in double
]


@pytest.mark.parametrize("a, b, c", _HARD)
def test_float32_fma_rounds_once_on_hard_cases(a, b, c):
    lib = _libm_fma()
    with np.errstate(all="ignore"):  # overflow to inf is one of the cases
        got = nx.fma(np.float32(a), np.float32(b), np.float32(c))
    assert type(got) is np.float32
    want = lib.fmaf(r32(a), r32(b), r32(c))
    assert f32_bits(got) == f32_bits(want) or (math.isnan(got) and math.isnan(want))
    if all(math.isfinite(x) for x in (a, b, c)) and math.isfinite(want):
        assert f32_bits(got) == f32_bits(_fma_exact(r32(a), r32(b), r32(c)))


def test_the_double_rounding_case_is_one_that_a_plain_double_sum_gets_wrong():
    x, y, z = (np.float32(v) for v in _HARD[1])
    fused = nx.fma(x, y, z)
    naive = np.float32(float(x) * float(y) + float(z))
    assert f32_bits(fused) != f32_bits(naive)
    assert f32_bits(fused) == f32_bits(_fma_exact(float(x), float(y), float(z)))


@settings(max_examples=3000)
@given(f32s, f32s, f32s)
def test_float32_fma_equals_the_c_librarys_fmaf(a, b, c):
    with np.errstate(all="ignore"):
        got = nx.fma(np.float32(a), np.float32(b), np.float32(c))
    want = _libm_fma().fmaf(a, b, c)
    assert f32_bits(got) == f32_bits(want) or (math.isnan(got) and math.isnan(want))


@settings(max_examples=2000)
@given(st.floats(allow_nan=False, allow_infinity=False), st.floats(allow_nan=False, allow_infinity=False),
       st.floats(allow_nan=False, allow_infinity=False))
def test_double_fma_equals_the_c_librarys_fma(a, b, c):
    got = nx.fma_double(a, b, c)
    want = _libm_fma().fma(a, b, c)
    assert got == want or (math.isnan(got) and math.isnan(want)) or (math.isinf(want) and got == want)
    assert math.copysign(1.0, got) == math.copysign(1.0, want) or math.isnan(want)


def test_fma_in_fast_mode_is_the_plain_double_expression():
    a, b, c = np.float64(0.1), np.float64(0.2), np.float64(0.3)
    assert nx.fma(a, b, c) == a * b + c and type(nx.fma(a, b, c)) is np.float64


# ---------------------------------------------------------------- results kept on their operand


def _bits(v) -> tuple[int, int, int]:
    return (f32_bits(v.x), f32_bits(v.y), f32_bits(v.z))


def _quat(runtime, x, y, z, w):
    return runtime.quaternion(np.float32(x), np.float32(y), np.float32(z), np.float32(w))


def test_a_rotation_asked_again_tells_minus_zero_from_plus_zero():
    zero, minus = EXACT.vec(0.0, 0.0, 0.0), EXACT.vec(-0.0, -0.0, -0.0)
    q = _quat(MONO, 0.0, 0.0, 0.0, 1.0)
    assert _bits(nx.transform_by_quaternion(zero, q)) == (0, 0, 0)
    # the same quaternion, a vector equal to the first (== is true) but for its zeros' signs
    assert _bits(nx.transform_by_quaternion(minus, q)) == (0x80000000,) * 3
    assert _bits(nx.transform_by_quaternion(minus, _quat(MONO, 0.0, 0.0, 0.0, 1.0))) == (0x80000000,) * 3


@settings(max_examples=200)
@given(st.tuples(f32s, f32s, f32s), st.tuples(f32s, f32s, f32s, f32s))
def test_an_operand_answers_each_runtimes_formula_as_a_fresh_one_does(v, q):
    """One quaternion (and its matrix) asked by both runtimes' formulas, each twice, in turn:
    every answer is the one a new operand with the same value gives."""
    vec = EXACT.vec(*v)
    with np.errstate(all="ignore"):
        shared = _quat(NET10, *q)
        shared_matrix = nx.Matrix4x4.create_from_quaternion(shared).transpose()
        for _ in range(2):
            for rt in (MONO, NET10):
                fresh = _quat(NET10, *q)
                fresh_matrix = nx.Matrix4x4._from_quaternion(fresh).transpose()
                got = (rt.transform_by_quaternion(vec, shared), rt.transform_by_matrix(vec, shared_matrix))
                want = (rt.transform_by_quaternion(vec, fresh), rt.transform_by_matrix(vec, fresh_matrix))
                assert [_bits(g) for g in got] == [_bits(w) for w in want]


def _double_bits(x: float) -> int:
    return struct.unpack("<Q", struct.pack("<d", x))[0]


@pytest.mark.filterwarnings("ignore::RuntimeWarning")  # numpy's overflow warning, on both sides
@settings(max_examples=3000)
@given(st.one_of(st.floats(), st.integers(0, 2**64 - 1).map(lambda b: struct.unpack("<d", struct.pack("<Q", b))[0]),
                 st.floats(min_value=3.4e38, max_value=3.5e38), st.floats(min_value=-1e-44, max_value=1e-44)))
def test_to_f32_and_f32_bits_round_every_double_as_numpys_float32_cast_does_nan_payloads_and_overflow_included(x):
    want = float(np.float32(x))
    got = nx.to_f32(x)
    assert _double_bits(got) == _double_bits(want)
    assert nx.to_f32s((x, -x, x)) == (got, nx.to_f32(-x), got) or math.isnan(x)
    assert nx.to_f32s((x, -x, x, -x)) == (got, nx.to_f32(-x), got, nx.to_f32(-x)) or math.isnan(x)
    assert nx.f32_bits(x) == int(np.float32(x).view(np.uint32)) == nx.f32_bits(np.float32(x))


@given(st.floats(min_value=0.0, max_value=float(np.float32(3.4e38)), width=32))
def test_f32_next_up_is_numpys_nextafter_toward_infinity_for_non_negative_float32s(x):
    want = float(np.nextafter(np.float32(x), np.float32(np.inf)))
    assert nx.f32_next_up(x) == want and nx.f32_next_up(-0.0) == nx.f32_next_up(0.0)
