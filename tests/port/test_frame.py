"""AFrame and Position (port/frame.py): hand-checked frames, and the System.Numerics calls they
make checked bit for bit, under each runtime's arithmetic, against mono and .NET 10 live and
against their recorded answers (tests/data/numerics_mono.json, numerics_net10.json, replayed
without either runtime).

Re-record after changing the inputs: ``python tests/port/test_frame.py --record --runtime mono``
and ``--runtime coreclr`` (needs pythonnet with that runtime).
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest

from acconform.numerics import EXACT, FAST, Matrix4x4
from acconform.port.frame import AFrame, Position
from acconform.port.land_defs import InvalidOperation

import numerics_replay
from numerics_replay import assert_matches_answers, assert_matches_live_mono, assert_matches_recorded, bits, load_recorded

F = np.float32


def v(x, y, z):
    return EXACT.vec(x, y, z)


def q(x, y, z, w):
    return EXACT.quat(x, y, z, w)




# ---------------------------------------------------------------- hand-checked frames

QUARTER_TURN_Z = q(0.0, 0.0, math.sqrt(0.5), math.sqrt(0.5))  # +90 deg about z


@pytest.mark.anchor("AFrame::local_to_global")
def test_local_to_global_rotates_then_translates():
    frame = AFrame(v(10, 20, 30), q(0, 0, 0, 1))
    assert frame.local_to_global(v(1, 2, 3)) == v(11, 22, 33)
    turned = AFrame(v(0, 0, 0), QUARTER_TURN_Z)
    out = turned.local_to_global_vec(v(1, 0, 0))
    # x axis turned +90 deg about z is y (within float32 rounding of sqrt(0.5))
    assert abs(float(out.x)) < 1e-6 and abs(float(out.y) - 1) < 1e-6 and out.z == 0


@pytest.mark.anchor("AFrame::global_to_local")
def test_global_to_local_undoes_local_to_global_for_a_quarter_turn():
    frame = AFrame(v(5, -7, 2), QUARTER_TURN_Z)
    local = frame.global_to_local(v(5, -6, 2))  # one metre along global y = local x
    assert abs(float(local.x) - 1) < 1e-6 and abs(float(local.y)) < 1e-6 and local.z == 0


@pytest.mark.anchor("AFrame::global_to_local_vec")
def test_global_to_local_vec_of_identity_turns_negative_zero_positive():
    # Vector3.Transform(v, Matrix4x4) adds the zero translation row, so -0 comes back +0
    out = AFrame(v(0, 0, 0), q(0, 0, 0, 1)).global_to_local_vec(v(-0.0, 1, -0.0))
    assert bits([out.x, out.y, out.z]) == bits([0.0, 1.0, 0.0])


@pytest.mark.anchor("AFrame::interpolate_rotation")
def test_interpolate_rotation_takes_the_short_way_round():
    a = AFrame(v(0, 0, 0), q(0, 0, 0, 1))
    b = AFrame(v(0, 0, 0), q(0, 0, 0, -1))  # the same rotation, opposite sign: dot < 0
    mid = AFrame.identity(EXACT)
    mid.interpolate_rotation(a, b, F(0.5))
    assert mid.orientation == q(0, 0, 0, 1)


@pytest.mark.anchor("AFrame::combine")
def test_combine_composes_translation_through_the_first_rotation():
    a = AFrame(v(1, 0, 0), QUARTER_TURN_Z)
    b = AFrame(v(2, 0, 0), q(0, 0, 0, 1))
    c = AFrame.combine(a, b)
    assert abs(float(c.origin.x) - 1) < 1e-6 and abs(float(c.origin.y) - 2) < 1e-6
    assert c.orientation == QUARTER_TURN_Z


@pytest.mark.anchor("AFrame::set_heading")
@pytest.mark.parametrize("degrees", [0.0, 90.0, 180.0, 270.0, 45.0])
def test_set_heading_then_get_heading_round_trips(degrees):
    frame = AFrame.identity(EXACT)
    frame.set_heading(F(degrees))
    got = float(frame.get_heading())
    assert min(abs(got - degrees), 360 - abs(got - degrees)) < 1e-3


@pytest.mark.anchor("AFrame::set_vector_heading")
def test_set_vector_heading_ignores_a_vector_shorter_than_epsilon():
    frame = AFrame(v(0, 0, 0), q(0.1, 0.2, 0.3, 0.9))
    frame.set_vector_heading(v(1e-5, 0, 0))
    assert frame.orientation == q(0.1, 0.2, 0.3, 0.9)


@pytest.mark.anchor("AFrame::equals")
def test_frame_equals_ignores_orientation_as_ace_does():
    # ACE compares frame.Orientation with itself, so only origins matter (and NaN)
    a = AFrame(v(1, 2, 3), q(0, 0, 0, 1))
    b = AFrame(v(1.0001, 2, 3), QUARTER_TURN_Z)
    assert a.equals(b)
    assert not a.equals(AFrame(v(1.001, 2, 3), q(0, 0, 0, 1)))


@pytest.mark.anchor("Position::get_offset")
def test_get_offset_adds_the_block_offset_between_landblocks():
    here = Position(0xA9B40001, AFrame(v(10, 10, 0), q(0, 0, 0, 1)))
    east = Position(0xAAB40001, AFrame(v(2, 10, 0), q(0, 0, 0, 1)))  # one block east (x + 1)
    north = Position(0xA9B50001, AFrame(v(10, 3, 1), q(0, 0, 0, 1)))
    assert here.get_offset(east) == v(192 + 2 - 10, 0, 0)
    assert here.get_offset(north) == v(0, 192 + 3 - 10, 1)
    assert here.get_offset(here) == v(0, 0, 0)


@pytest.mark.anchor("Position::get_offset")
def test_get_offset_into_landblock_column_ff_raises_as_ace_does():
    here = Position(0xFEB40001, AFrame(v(10, 10, 0), q(0, 0, 0, 1)))
    there = Position(0xFFB40001, AFrame(v(10, 10, 0), q(0, 0, 0, 1)))
    with pytest.raises(InvalidOperation):
        here.get_offset(there)


@pytest.mark.anchor("Position::local_to_local")
def test_local_to_local_expresses_a_neighbour_point_in_this_frame():
    here = Position(0xA9B40001, AFrame(v(190, 10, 0), QUARTER_TURN_Z))
    east = Position(0xAAB40001, AFrame(v(2, 10, 0), q(0, 0, 0, 1)))
    local = here.local_to_local(east, v(0, 0, 0))  # 4 m east of here = local -y after +90 about z
    assert abs(float(local.x)) < 1e-5 and abs(float(local.y) + 4) < 1e-5


@pytest.mark.anchor("Position::get_outdoor_cell")
@pytest.mark.parametrize(
    "x, y, cell",
    [(0.0, 0.0, 0x0001), (23.999, 0.0, 0x0001), (24.0, 0.0, 0x0009), (0.0, 24.0, 0x0002), (191.9, 191.9, 0x0040)],
)
def test_get_outdoor_cell_numbers_cells_x_major(x, y, cell):
    pos = Position(0xA9B40001, AFrame(v(x, y, 0), q(0, 0, 0, 1)))
    assert pos.get_outdoor_cell(0xA9B4FFFF) == 0xA9B40000 | cell


@pytest.mark.anchor("AFrame::global_to_local_vec")
def test_frame_math_keeps_the_run_mode_scalar_type():
    fast = AFrame(FAST.vec(1, 2, 3), FAST.quat(0.1, 0.2, 0.3, 0.9))
    out = fast.global_to_local(FAST.vec(4, 5, 6))
    assert all(type(c) is np.float64 for c in out)
    exact = AFrame(v(1, 2, 3), q(0.1, 0.2, 0.3, 0.9))
    assert all(type(c) is np.float32 for c in exact.global_to_local(v(4, 5, 6)))


# ---------------------------------------------------------------- System.Numerics, bit for bit
# Each op: (number of float32 inputs, port function from (mode, input floats) to output floats).
# The mode carries the runtime: the same port code computes mono's or .NET 10's arithmetic.


def _frame(m, qx, qy, qz, qw):
    return AFrame(m.vec(0, 0, 0), m.quat(qx, qy, qz, qw))


def _port_quat_lerp(m, a):
    f = AFrame.identity(m)
    f.interpolate_rotation(_frame(m, *a[0:4]), _frame(m, *a[4:8]), F(a[8]))
    o = f.orientation
    return [o.x, o.y, o.z, o.w]


def _port_global_to_local_vec(m, a):
    return list(_frame(m, *a[0:4]).global_to_local_vec(m.vec(*a[4:7])))


def _port_local_to_global_vec(m, a):
    return list(_frame(m, *a[0:4]).local_to_global_vec(m.vec(*a[4:7])))


def _port_vector3_lerp(m, a):
    f = AFrame.identity(m)
    f.interpolate_origin(AFrame(m.vec(*a[0:3]), m.quat(0, 0, 0, 1)), AFrame(m.vec(*a[3:6]), m.quat(0, 0, 0, 1)), F(a[6]))
    return list(f.origin)


def _port_create_from_quaternion(m, a):
    return list(Matrix4x4.create_from_quaternion(m.quat(*a)).m)


def _port_yaw_pitch_roll(m, a):
    o = m.runtime.quat_create_from_yaw_pitch_roll(F(a[0]), F(a[1]), F(a[2]))
    return [o.x, o.y, o.z, o.w]


def _port_set_rotate(m, a):
    f = AFrame.identity(m)
    f.set_rotate(m.quat(*a))
    o = f.orientation
    return [o.x, o.y, o.z, o.w]


def _port_quat_multiply(m, a):
    o = AFrame.combine(_frame(m, *a[0:4]), _frame(m, *a[4:8])).orientation
    return [o.x, o.y, o.z, o.w]


def _port_quat_inverse(m, a):
    o = m.runtime.quat_inverse(m.quat(*a))
    return [o.x, o.y, o.z, o.w]


def _port_transform_by_matrix(m, a):
    rot = Matrix4x4.create_from_quaternion(m.quat(*a[0:4])).m
    mat = Matrix4x4((*rot[0:12], F(a[4]), F(a[5]), F(a[6]), rot[15]))
    return list(m.runtime.transform_by_matrix(m.vec(*a[7:10]), mat))


OPS = {
    # name: (inputs, port, ACE spot it stands for)
    "Quaternion.Lerp": (9, _port_quat_lerp),  # AFrame.InterpolateRotation
    "Matrix4x4.CreateFromQuaternion": (4, _port_create_from_quaternion),
    "GlobalToLocalVec": (7, _port_global_to_local_vec),  # Transform(v, Transpose(CreateFromQuaternion(q)))
    "Vector3.Transform(v,q)": (7, _port_local_to_global_vec),  # AFrame.LocalToGlobalVec
    "Vector3.Transform(v,m)": (10, _port_transform_by_matrix),  # a rotation with a translation row (BBox, Environment)
    "Vector3.Lerp": (7, _port_vector3_lerp),  # AFrame.InterpolateOrigin
    "Quaternion.CreateFromYawPitchRoll": (3, _port_yaw_pitch_roll),  # set_vector_heading, GRotate
    "Quaternion.Normalize": (4, _port_set_rotate),  # AFrame.set_rotate
    "Quaternion.Multiply": (8, _port_quat_multiply),  # AFrame.Combine, Rotate, GRotate, Subtract
    "Quaternion.Inverse": (4, _port_quat_inverse),  # AFrame.Subtract
}


def _yaw_pitch_roll(rng) -> list[float]:
    """Angles for every branch of .NET 10's Vector128.SinCos, which picks one branch for all
    three half angles: all within pi/4 (polynomial), all below 2^-7 (Taylor terms; below 2^-13
    the angle itself), any at or above 5e6 or not finite (the C library's sinf/cosf), otherwise
    reduced by multiples of pi/2 -- mostly the last, as ACE's headings are."""
    r = rng.random()
    if r < 0.15:
        return list(rng.uniform(-math.pi / 2, math.pi / 2, size=3))
    if r < 0.25:
        return list(rng.uniform(-1, 1, size=3) * 2.0 ** rng.integers(-30, -6, size=3))
    if r < 0.3:
        a = list(rng.uniform(-2 * math.pi, 2 * math.pi, size=3))
        a[rng.integers(0, 3)] = [1e7, -3e9, math.inf, -math.inf, math.nan][rng.integers(0, 5)]
        return a
    return list(rng.uniform(-2 * math.pi, 2 * math.pi, size=3) * (10.0 if rng.random() < 0.1 else 1.0))


def _inputs(name: str, n: int, seed: int) -> list[list[float]]:
    """Random float32 inputs: unit and non-unit quaternions (both signs of the lerp dot),
    vectors from centimetres to kilometres, interpolation t mostly in [0, 1]."""
    rng = np.random.default_rng(seed)
    cases = []
    for _ in range(n):
        qs = rng.normal(size=8)
        qs[0:4] /= np.linalg.norm(qs[0:4]) if rng.random() < 0.8 else 1.0
        qs[4:8] /= np.linalg.norm(qs[4:8]) if rng.random() < 0.8 else 1.0
        vec = rng.uniform(-1, 1, size=6) * 10.0 ** rng.integers(-2, 4)
        t = rng.random() if rng.random() < 0.9 else rng.uniform(-1, 2)
        if name in ("Quaternion.Lerp", "Quaternion.Multiply"):
            a = [*qs[0:8], t][: OPS[name][0]]
        elif name in ("GlobalToLocalVec", "Vector3.Transform(v,q)"):
            a = [*qs[0:4], *vec[0:3]]
        elif name == "Vector3.Transform(v,m)":
            a = [*qs[0:4], *vec[0:6]]
        elif name == "Vector3.Lerp":
            a = [*vec, t]
        elif name == "Quaternion.CreateFromYawPitchRoll":
            a = _yaw_pitch_roll(rng)
        else:
            a = list(qs[0:4])
        cases.append([float(np.float32(x)) for x in a])
    return cases


def _net_op(sn, name, a):
    """The same question asked of System.Numerics (mono's or .NET 10's, whichever is loaded)."""
    Q, V, M = sn.Quaternion, sn.Vector3, sn.Matrix4x4
    if name == "Quaternion.Lerp":
        o = Q.Lerp(Q(*a[0:4]), Q(*a[4:8]), a[8])
        return [o.X, o.Y, o.Z, o.W]
    if name == "Matrix4x4.CreateFromQuaternion":
        m = M.CreateFromQuaternion(Q(*a))
        return [m.M11, m.M12, m.M13, m.M14, m.M21, m.M22, m.M23, m.M24,
                m.M31, m.M32, m.M33, m.M34, m.M41, m.M42, m.M43, m.M44]
    if name == "GlobalToLocalVec":
        o = V.Transform(V(*a[4:7]), M.Transpose(M.CreateFromQuaternion(Q(*a[0:4]))))
        return [o.X, o.Y, o.Z]
    if name == "Vector3.Transform(v,q)":
        o = V.Transform(V(*a[4:7]), Q(*a[0:4]))
        return [o.X, o.Y, o.Z]
    if name == "Vector3.Transform(v,m)":
        r = M.CreateFromQuaternion(Q(*a[0:4]))
        mat = M(r.M11, r.M12, r.M13, r.M14, r.M21, r.M22, r.M23, r.M24, r.M31, r.M32, r.M33, r.M34,
                a[4], a[5], a[6], r.M44)
        o = V.Transform(V(*a[7:10]), mat)
        return [o.X, o.Y, o.Z]
    if name == "Vector3.Lerp":
        o = V.Lerp(V(*a[0:3]), V(*a[3:6]), a[6])
        return [o.X, o.Y, o.Z]
    if name == "Quaternion.CreateFromYawPitchRoll":
        o = Q.CreateFromYawPitchRoll(*a)
        return [o.X, o.Y, o.Z, o.W]
    if name == "Quaternion.Normalize":
        o = Q.Normalize(Q(*a))
        return [o.X, o.Y, o.Z, o.W]
    if name == "Quaternion.Multiply":
        o = Q.Multiply(Q(*a[0:4]), Q(*a[4:8]))
        return [o.X, o.Y, o.Z, o.W]
    if name == "Quaternion.Inverse":
        o = Q.Inverse(Q(*a))
        return [o.X, o.Y, o.Z, o.W]
    raise KeyError(name)


def _data(runtime: str) -> Path:
    return numerics_replay.data_path(runtime)


@pytest.mark.live_runtime
@pytest.mark.anchor("AFrame::global_to_local_vec")
@pytest.mark.parametrize("name", sorted(OPS))
def test_frame_numerics_match_mono_system_numerics_bit_for_bit(name):
    assert_matches_live_mono(OPS, name, _inputs, _net_op)


@pytest.fixture(scope="module")
def live_net10():
    return numerics_replay.live_coreclr_answers(Path(__file__))


@pytest.mark.live_runtime
@pytest.mark.anchor("AFrame::global_to_local_vec")
@pytest.mark.parametrize("name", sorted(OPS))
def test_frame_numerics_match_dotnet10_system_numerics_bit_for_bit(name, live_net10):
    assert_matches_answers(OPS, name, live_net10, "coreclr", "live .NET 10 answers")


@pytest.mark.anchor("AFrame::global_to_local_vec")
@pytest.mark.parametrize("runtime", sorted(numerics_replay.DATA_NAMES))
@pytest.mark.parametrize("name", sorted(OPS))
def test_frame_numerics_match_each_runtimes_recorded_answers(name, runtime):
    assert_matches_recorded(OPS, name, _data(runtime), Path(__file__).name, runtime)


@pytest.mark.parametrize("runtime", sorted(numerics_replay.DATA_NAMES))
def test_recorded_answers_cover_every_frame_op(runtime):
    assert sorted(load_recorded(_data(runtime), Path(__file__).name, runtime)["ops"]) == sorted(OPS)


if __name__ == "__main__":
    numerics_replay.main(sys.argv[1:], _data, OPS, _inputs, _net_op,
                         "{runtime} System.Numerics answers (float32 bit patterns, 8 hex digits each) for the "
                         "calls port/frame.py makes; written by tests/port/test_frame.py --record --runtime {runtime}")


# ---------------------------------------------------------------- the runtime reaches the physics


@pytest.mark.anchor("AFrame::global_to_local_vec")
def test_a_run_rotates_frames_as_its_runtime_does_which_moves_a_rotated_bsp_contact_plane():
    """A recorded mono scene (a BSP ledge turned 30 degrees about z): mono arithmetic reproduces
    ACE-on-mono's contact plane bit for bit; .NET 10 arithmetic rotates the ledge's plane into the
    world by other roundings (its normal's z is 0.99999994, not 1.0)."""
    from acconform.compare import compare
    from acconform.oracle import default_corpus
    from acconform.oracle.recorded import RecordedOracle, scene_key
    from acconform.port.run import run_scene

    corpus = RecordedOracle(default_corpus("mono"))
    key = "e42adc88320d7aaff503ee9c19d28006a007898ce1f063f6341a174550ba19c9"
    rec = next(r for r in corpus.records() if r.scene.name == "bsp:ledge" and scene_key(r.scene) == key)
    assert compare(run_scene(rec.scene, runtime="mono"), rec.outcome, "exact") == []
    net10 = run_scene(rec.scene, runtime="coreclr")
    assert bits([rec.outcome.contact_plane.normal[2]]) == [0x3F800000]
    assert bits([net10.contact_plane.normal[2]]) == [0x3F7FFFFF]
