"""Exact mode is binary32 after every operation; C# scalar rules; constants pinned by bits."""

import math
import struct

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from acconform import numerics as nx
from acconform.numerics import EXACT, FAST, MONO, CORECLR, cs_ceiling, cs_floor, cs_fmod, f32_bits
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
    assert CORECLR.to_int32(3e9) == 2147483647 and CORECLR.to_int32(math.nan) == 0
    assert CORECLR.to_uint32(-2.5) == 0


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
    with pytest.raises(AcconformError, match="only the mono runtime"):
        nx.get_mode("exact", "coreclr")
