"""The System.Numerics calls port/geom and port/vec make (Vector3.Cross, Normalize, Length,
LengthSquared, Dot, scalar multiply and divide, Equals, Vector2.Length for Length2D) and C#'s
float-to-int casts, checked bit for bit under each runtime's arithmetic against mono and .NET 10
live and against their recorded answers (tests/data/numerics_mono_geom.json,
numerics_net10_geom.json, replayed without either runtime).

Re-record after changing the inputs: ``PYTHONPATH=tests/port python tests/port/geom/test_numerics_geom.py
--record --runtime mono`` and ``--runtime coreclr`` (needs pythonnet with that runtime).
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest

from acconform.numerics import cross, dot, f32_bits, f32_from_bits, normalize
from acconform.port.vec import length_2d

import numerics_replay
from numerics_replay import assert_matches_answers, assert_matches_live_mono, assert_matches_recorded, load_recorded, unpack

F = np.float32


def _port_cross(m, a):
    return list(cross(m.vec(*a[0:3]), m.vec(*a[3:6])))


def _port_normalize(m, a):
    return list(normalize(m.vec(*a[0:3])))


def _port_length(m, a):
    return [m.vec(*a[0:3]).length()]


def _port_length_squared(m, a):
    return [m.vec(*a[0:3]).length_squared()]


def _port_dot(m, a):
    return [dot(m.vec(*a[0:3]), m.vec(*a[3:6]))]


def _port_multiply(m, a):
    return list(m.vec(*a[0:3]) * F(a[3]))


def _port_divide(m, a):
    return list(m.vec(*a[0:3]) / F(a[3]))


def _port_vector2_length(m, a):
    # Length2D returns the float32 length widened to double: narrowing back is exact
    return [F(length_2d(m.vec(a[0], a[1], a[2])))]


def _port_equals(m, a):
    # encoded as 0/1 in a float32 slot
    return [F(1.0) if m.vec(*a[0:3]) == m.vec(*a[3:6]) else F(0.0)]


def _port_negate(m, a):
    return list(m.runtime.negate(m.vec(*a[0:3])))


def _port_to_int32(m, a):
    return [m.runtime.to_int32(F(a[0]))]


def _port_to_uint32(m, a):
    return [m.runtime.to_uint32(F(a[0]))]


OPS = {
    # name: (number of float32 inputs, port function)
    "Vector3.Cross": (6, _port_cross),  # Polygon edges, make_plane, SlideSphere directions
    "Vector3.Normalize": (3, _port_normalize),  # Polygon.make_plane
    "Vector3.Length": (3, _port_length),  # find_crossed_edge, Vec.NormalizeCheckSmall
    "Vector3.LengthSquared": (3, _port_length_squared),  # every hit test
    "Vector3.Dot": (6, _port_dot),  # every plane distance
    "Vector3.Multiply(v,s)": (4, _port_multiply),
    "Vector3.Divide(v,s)": (4, _port_divide),  # IntersectsSphere disp / radsum, CylSphere
    "Vector2.Length": (3, _port_vector2_length),  # Vector3Extensions.Length2D
    "Vector3.Equals": (6, _port_equals),  # Sphere.SlideSphere collisionNormal.Equals(Vector3.Zero)
    "Vector3.Negate": (3, _port_negate),  # operator -: SlideSphere, CliffSlide, SetNegPolyHit
    "(int)float": (1, _port_to_int32),  # LandDefs.lcoord_to_gid, Landblock, Transition step counts
    "(uint)float": (1, _port_to_uint32),  # Position.GetOutdoorCell, LandCell
}


_CAST_EDGES = [2147483520.0, 2147483648.0, -2147483648.0, -2147483904.0, 4294967040.0, 4294967296.0, -0.5, -2.5,
               -0.0, 1e10, -1e10, 3e38, math.inf, -math.inf, math.nan]


def _inputs(name: str, n: int, seed: int) -> list[list[float]]:
    """Random float32 inputs from millimetres to kilometres, with signed zeros, exact duplicates
    (for Equals) and vectors near EPSILON in length (NormalizeCheckSmall's cut)."""
    rng = np.random.default_rng(seed)
    cases = []
    for _ in range(n):
        a = rng.uniform(-1, 1, size=6) * 10.0 ** rng.integers(-4, 4, size=6)
        r = rng.random()
        if r < 0.05:
            a[rng.integers(0, 6)] = -0.0
        elif r < 0.1:
            a[0:3] = rng.uniform(-1, 1, size=3) * 2e-4
        if name == "Vector3.Equals":
            if rng.random() < 0.5:
                a[3:6] = a[0:3]
            if rng.random() < 0.3:
                a[0:3] = [0.0, -0.0, 0.0] if rng.random() < 0.5 else [-0.0, -0.0, -0.0]
                a[3:6] = [0.0, 0.0, 0.0]
        if name.startswith("Vector3.Divide") and a[3] == 0:
            a[3] = 1.5
        if name == "Vector3.Negate":  # zeros of both signs, as collision normals carry them
            a[0:3] = [x if rng.random() < 0.6 else [0.0, -0.0][rng.integers(0, 2)] for x in a[0:3]]
        if name.startswith("("):  # casts: in range, around the int32/uint32 limits, beyond, not finite
            a[0] = [a[0], a[0] * 1e3, rng.uniform(-1, 1) * 2.0 ** rng.integers(30, 34), rng.choice(_CAST_EDGES)][rng.integers(0, 4)]
        cases.append([float(np.float32(x)) for x in a[: OPS[name][0]]])
    return cases


_CASTS: dict = {}


def _cast(name: str):
    """C#'s ``(int)x`` / ``(uint)x`` for a float x, compiled by the loaded runtime's JIT (conv.i4, conv.u4)."""
    if name not in _CASTS:
        import System
        from System.Linq.Expressions import Expression

        target = System.Int32 if name == "(int)float" else System.UInt32
        x = Expression.Parameter(System.Single, "x")
        _CASTS[name] = Expression.Lambda[System.Func[System.Single, target]](Expression.Convert(x, target), x).Compile()
    return _CASTS[name]


def _net_op(sn, name, a):
    """The same question asked of System.Numerics (mono's or .NET 10's, whichever is loaded)."""
    V = sn.Vector3
    if name == "Vector3.Cross":
        o = V.Cross(V(*a[0:3]), V(*a[3:6]))
        return [o.X, o.Y, o.Z]
    if name == "Vector3.Normalize":
        o = V.Normalize(V(*a[0:3]))
        return [o.X, o.Y, o.Z]
    if name == "Vector3.Length":
        return [V(*a[0:3]).Length()]
    if name == "Vector3.LengthSquared":
        return [V(*a[0:3]).LengthSquared()]
    if name == "Vector3.Dot":
        return [V.Dot(V(*a[0:3]), V(*a[3:6]))]
    if name == "Vector3.Multiply(v,s)":
        o = V.Multiply(V(*a[0:3]), F(a[3]).item())
        return [o.X, o.Y, o.Z]
    if name == "Vector3.Divide(v,s)":
        o = V.Divide(V(*a[0:3]), F(a[3]).item())
        return [o.X, o.Y, o.Z]
    if name == "Vector2.Length":
        return [sn.Vector2(a[0], a[1]).Length()]
    if name == "Vector3.Equals":
        return [1.0 if V(*a[0:3]).Equals(V(*a[3:6])) else 0.0]
    if name == "Vector3.Negate":
        o = V.op_UnaryNegation(V(*a[0:3]))
        return [o.X, o.Y, o.Z]
    if name.startswith("("):
        return [int(_cast(name)(F(a[0]).item()))]
    raise KeyError(name)


def _data(runtime: str) -> Path:
    return numerics_replay.data_path(runtime, "_geom")


@pytest.mark.live_runtime
@pytest.mark.anchor("CPolygon::make_plane")
@pytest.mark.parametrize("name", sorted(OPS))
def test_geom_numerics_match_mono_system_numerics_bit_for_bit(name):
    assert_matches_live_mono(OPS, name, _inputs, _net_op)


@pytest.fixture(scope="module")
def live_net10():
    return numerics_replay.live_coreclr_answers(Path(__file__))


@pytest.mark.live_runtime
@pytest.mark.anchor("CPolygon::make_plane")
@pytest.mark.parametrize("name", sorted(OPS))
def test_geom_numerics_match_dotnet10_system_numerics_bit_for_bit(name, live_net10):
    assert_matches_answers(OPS, name, live_net10, "coreclr", "live .NET 10 answers")


def _load_recorded(runtime: str = "mono"):
    return load_recorded(_data(runtime), Path(__file__).name, runtime)


@pytest.mark.anchor("CPolygon::make_plane")
@pytest.mark.parametrize("runtime", sorted(numerics_replay.DATA_NAMES))
@pytest.mark.parametrize("name", sorted(OPS))
def test_geom_numerics_match_each_runtimes_recorded_answers(name, runtime):
    assert_matches_recorded(OPS, name, _data(runtime), Path(__file__).name, runtime)


@pytest.mark.anchor("CPolygon::make_plane")
@pytest.mark.parametrize("runtime", sorted(numerics_replay.DATA_NAMES))
def test_recorded_geom_answers_cover_every_op(runtime):
    assert sorted(_load_recorded(runtime)["ops"]) == sorted(OPS)


@pytest.mark.anchor("CSphere::slide_sphere")
@pytest.mark.parametrize("runtime", sorted(numerics_replay.DATA_NAMES))
def test_recorded_equals_treats_negative_zero_as_zero(runtime):
    """Sphere.SlideSphere's ``collisionNormal.Equals(Vector3.Zero)``: -0 equals 0 on both runtimes."""
    rec = _load_recorded(runtime)["ops"]["Vector3.Equals"]
    cases = [[f32_from_bits(b) for b in row] for row in unpack(rec["inputs"], 6)]
    outs = [row[0] for row in unpack(rec["outputs"], 1)]
    signed_zero = [o for a, o in zip(cases, outs) if a[3:6] == [0.0, 0.0, 0.0] and a[0:3] == [0.0, 0.0, 0.0]
                   and any(str(x).startswith("-") for x in a[0:3])]
    assert signed_zero and all(o == f32_bits(1.0) for o in signed_zero)


@pytest.mark.parametrize("runtime, nan, too_big", [("mono", -2147483648, -2147483648), ("coreclr", 0, 2147483647)])
def test_recorded_int_casts_of_nan_and_out_of_range_floats_follow_the_runtime(runtime, nan, too_big):
    """mono's (int)x gives int.MinValue for NaN and out of range; .NET 9 and later saturate, NaN -> 0."""
    rec = _load_recorded(runtime)["ops"]["(int)float"]
    answers = {f32_from_bits(a[0]) if a[0] != 0x7FC00000 else "nan": o[0] - (o[0] >> 31 << 32)
               for a, o in zip(unpack(rec["inputs"], 1), unpack(rec["outputs"], 1))}
    assert answers["nan"] == nan and answers[1e10] == too_big and answers[-1e10] == -2147483648


if __name__ == "__main__":
    numerics_replay.main(sys.argv[1:], _data, OPS, _inputs, _net_op,
                         "{runtime} System.Numerics answers (float32 bit patterns, 8 hex digits each; casts: the "
                         "int's 32 bits) for the calls port/geom and the cell code make; written by "
                         "tests/port/geom/test_numerics_geom.py --record --runtime {runtime}")
