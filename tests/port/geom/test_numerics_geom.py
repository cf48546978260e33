"""The System.Numerics calls port/geom and port/vec make (Vector3.Cross, Normalize, Length,
LengthSquared, Dot, scalar multiply and divide, Equals, Vector2.Length for Length2D), checked bit
for bit against mono (live) and against mono's recorded answers (tests/data/numerics_mono_geom.json,
replayed without mono).

Re-record after changing the inputs: ``python tests/port/geom/test_numerics_geom.py --record``
(needs pythonnet + mono).
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

from acconform.numerics import EXACT, cross, dot, f32_bits, f32_from_bits, normalize
from acconform.port.vec import length_2d

import numerics_replay
from numerics_replay import assert_matches_live_mono, assert_matches_recorded_mono, load_recorded, unpack

DATA = Path(__file__).resolve().parents[2] / "data" / "numerics_mono_geom.json"
F = np.float32


def v(x, y, z):
    return EXACT.vec(x, y, z)




def _port_cross(a):
    return list(cross(v(*a[0:3]), v(*a[3:6])))


def _port_normalize(a):
    return list(normalize(v(*a[0:3])))


def _port_length(a):
    return [v(*a[0:3]).length()]


def _port_length_squared(a):
    return [v(*a[0:3]).length_squared()]


def _port_dot(a):
    return [dot(v(*a[0:3]), v(*a[3:6]))]


def _port_multiply(a):
    return list(v(*a[0:3]) * F(a[3]))


def _port_divide(a):
    return list(v(*a[0:3]) / F(a[3]))


def _port_vector2_length(a):
    # Length2D returns the float32 length widened to double: narrowing back is exact
    return [F(length_2d(v(a[0], a[1], a[2])))]


def _port_equals(a):
    # encoded as 0/1 in a float32 slot
    return [F(1.0) if v(*a[0:3]) == v(*a[3:6]) else F(0.0)]


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
}


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
        cases.append([float(np.float32(x)) for x in a[: OPS[name][0]]])
    return cases


def _mono_op(sn, name, a):
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
    raise KeyError(name)


@pytest.mark.live_runtime
@pytest.mark.anchor("CPolygon::make_plane")
@pytest.mark.parametrize("name", sorted(OPS))
def test_geom_numerics_match_mono_system_numerics_bit_for_bit(name):
    assert_matches_live_mono(OPS, name, _inputs, _mono_op)


def _load_recorded():
    return load_recorded(DATA, Path(__file__).name)


@pytest.mark.anchor("CPolygon::make_plane")
@pytest.mark.parametrize("name", sorted(OPS))
def test_geom_numerics_match_recorded_mono_answers(name):
    assert_matches_recorded_mono(OPS, name, DATA, Path(__file__).name)


@pytest.mark.anchor("CPolygon::make_plane")
def test_recorded_mono_geom_answers_cover_every_op():
    assert sorted(_load_recorded()["ops"]) == sorted(OPS)


@pytest.mark.anchor("CSphere::slide_sphere")
def test_recorded_mono_equals_treats_negative_zero_as_zero():
    """Sphere.SlideSphere's ``collisionNormal.Equals(Vector3.Zero)``: -0 equals 0 on mono."""
    rec = _load_recorded()["ops"]["Vector3.Equals"]
    cases = [[f32_from_bits(b) for b in row] for row in unpack(rec["inputs"], 6)]
    outs = [row[0] for row in unpack(rec["outputs"], 1)]
    signed_zero = [o for a, o in zip(cases, outs) if a[3:6] == [0.0, 0.0, 0.0] and a[0:3] == [0.0, 0.0, 0.0]
                   and any(str(x).startswith("-") for x in a[0:3])]
    assert signed_zero and all(o == f32_bits(1.0) for o in signed_zero)


def record(n: int = 600) -> None:
    numerics_replay.record(DATA, OPS, _inputs, _mono_op,
                           "mono System.Numerics answers (float32 bit patterns, 8 hex digits each) for the "
                           "calls port/geom makes; written by tests/port/geom/test_numerics_geom.py --record", n)


if __name__ == "__main__":
    if "--record" in sys.argv:
        record()
