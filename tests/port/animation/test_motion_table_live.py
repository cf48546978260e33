"""MotionTable and Sequence against live ACE (lane `live_oracle`): motion_tables.py's table and
animations written as DAT bytes by acconform/dat.py, unpacked by ACE's own DatLoader into
DatManager.PortalDat's FileCache (and removed after), then the same motions run through ACE's
Physics MotionTable (MotionTable.Get, SetDefaultState, GetObjectSequence, StopObjectMotion,
StopObjectCompletely), MotionState and Sequence (Update with an offset frame, a PhysicsObj as the
hook object) and through the port; after every call the motion state, the sequence (velocity,
omega, frame number, every queued animation, CurrAnim, FirstCyclic), numAnims, the offset frame and
the hooks queued on the object are compared bit for bit."""

from __future__ import annotations

import numpy as np
import pytest

from acconform.numerics import f32_bits, get_mode, runtime_named
from acconform.port.animation.motion_state import MotionState
from acconform.port.animation.motion_table import MotionTable
from acconform.port.animation.sequence import Sequence
from acconform.port.frame import AFrame

import motion_tables as mt

pytestmark = pytest.mark.live_oracle

f = np.float32
QUANTA = (1 / 30, 0.05, 0.2, 0.0, 1 / 7, 0.5)


class HookSink:
    """The port's stand-in for PhysicsObj.add_anim_hook: the hooks in order."""

    def __init__(self):
        self.anim_hooks = []

    def add_anim_hook(self, hook):
        self.anim_hooks.append(hook)


@pytest.fixture(scope="module")
def ace(live):
    from System.IO import BinaryReader, MemoryStream  # type: ignore[import-not-found]
    from ACE.DatLoader import DatManager  # type: ignore[import-not-found]
    from ACE.DatLoader.FileTypes import Animation, MotionTable as DatMotionTable  # type: ignore[import-not-found]
    from ACE.Server.Physics import Animation as A, PhysicsObj  # type: ignore[import-not-found]

    cache = DatManager.PortalDat.FileCache
    ids = []
    for rec in (mt.table(), *mt.ANIMATIONS):
        stream = MemoryStream(bytes(rec.data))
        file = DatMotionTable() if rec.kind == "MotionTable" else Animation()
        file.Unpack(BinaryReader(stream))
        assert int(stream.Position) == len(rec.data) and int(file.Id) == rec.id
        cache[rec.id] = file
        ids.append(rec.id)
    mode = get_mode("exact", runtime_named(live.versions.runtime))
    yield A, PhysicsObj, mode
    for i in ids:
        cache.TryRemove(i)


def _v(v) -> tuple:
    return (f32_bits(v.X), f32_bits(v.Y), f32_bits(v.Z))


def _pv(v) -> tuple:
    return (f32_bits(v.x), f32_bits(v.y), f32_bits(v.z))


def _frame(fr) -> tuple:
    o = fr.Orientation
    return _v(fr.Origin) + (f32_bits(o.X), f32_bits(o.Y), f32_bits(o.Z), f32_bits(o.W))


def _pframe(fr) -> tuple:
    o = fr.orientation
    return _pv(fr.origin) + (f32_bits(o.x), f32_bits(o.y), f32_bits(o.z), f32_bits(o.w))


def _ace_state(st) -> tuple:
    return (int(st.Style), int(st.Substate), f32_bits(st.SubstateMod),
            [(int(m.ID), f32_bits(m.SpeedMod)) for m in st.Modifiers], [(int(m.ID), f32_bits(m.SpeedMod)) for m in st.Actions])


def _port_state(st) -> tuple:
    return (st.style, st.substate, f32_bits(st.substate_mod),
            [(m.id, f32_bits(m.speed_mod)) for m in st.modifiers], [(m.id, f32_bits(m.speed_mod)) for m in st.actions])


def _index(node, first) -> int:
    i, n = 0, first
    while n is not None:
        if n.Equals(node) if hasattr(n, "Equals") else n is node:
            return i
        i, n = i + 1, n.Next if hasattr(n, "Next") else n.next
    return -1


def _ace_seq(seq) -> tuple:
    anims = [(int(n.Anim.ID), f32_bits(n.Framerate), int(n.LowFrame), int(n.HighFrame)) for n in seq.AnimList]
    first = seq.AnimList.First
    curr = _index(seq.CurrAnim, first) if seq.CurrAnim is not None else None
    cyc = _index(seq.FirstCyclic, first) if seq.FirstCyclic is not None else None
    return _v(seq.Velocity), _v(seq.Omega), f32_bits(seq.FrameNumber), anims, curr, cyc


def _port_seq(seq) -> tuple:
    anims = [(n.anim.id, f32_bits(n.framerate), n.low_frame, n.high_frame) for n in seq.anim_list]
    first = seq.anim_list.first
    curr = _index(seq.curr_anim, first) if seq.curr_anim is not None else None
    cyc = _index(seq.first_cyclic, first) if seq.first_cyclic is not None else None
    return _pv(seq.velocity), _pv(seq.omega), f32_bits(seq.frame_number), anims, curr, cyc


def _ace_hooks(obj) -> list:
    return [(int(h.HookType), int(h.Direction)) for h in obj.AnimHooks]


def _port_hooks(sink) -> list:
    return [(int(h.hook_type), int(h.direction)) for h in sink.anim_hooks]


def _pair(ace):
    A, PhysicsObj, mode = ace
    pd = mt.portal_dat(mode)
    a_table, p_table = A.MotionTable.Get(mt.TABLE_ID), MotionTable.get(mt.TABLE_ID, pd)
    a_state, p_state = A.MotionState(), MotionState.create(mode)
    a_seq, p_seq = A.Sequence(), Sequence.create(mode, pd)
    a_obj, p_obj = PhysicsObj(), HookSink()
    a_seq.SetObject(a_obj)
    p_seq.set_object(p_obj)
    return (a_table, a_state, a_seq, a_obj), (p_table, p_state, p_seq, p_obj), mode


def _same(a, p, where: str) -> None:
    _, a_state, a_seq, a_obj = a
    _, p_state, p_seq, p_obj = p
    assert _port_state(p_state) == _ace_state(a_state), f"{where}: motion state"
    assert _port_seq(p_seq) == _ace_seq(a_seq), f"{where}: sequence"
    assert _port_hooks(p_obj) == _ace_hooks(a_obj), f"{where}: hooks"


@pytest.mark.anchor("CMotionTable::GetObjectSequence")
@pytest.mark.anchor("CSequence::update_internal")
def test_a_script_of_motions_and_updates_leaves_ace_and_the_port_in_the_same_state_bit_for_bit(ace):
    from ACE.Server.Physics.Animation import AFrame as AceAFrame  # type: ignore[import-not-found]

    a, p, mode = _pair(ace)
    (a_table, a_state, a_seq, _), (p_table, p_state, p_seq, _) = a, p
    a_ok, a_n = a_table.SetDefaultState(a_state, a_seq, 0)
    p_ok, p_n = p_table.set_default_state(p_state, p_seq, 0)
    assert (bool(a_ok), int(a_n)) == (p_ok, p_n)
    _same(a, p, "SetDefaultState")
    a_frame, p_frame = AceAFrame(), AFrame.identity(mode)
    results, moved = set(), 0
    for step, (motion, speed) in enumerate(mt.SCRIPT * 2):
        a_ok, a_n = a_table.GetObjectSequence(motion, a_state, a_seq, float(f(speed)), 0, False)
        p_ok, p_n = p_table.get_object_sequence(motion, p_state, p_seq, f(speed), 0, False)
        assert (bool(a_ok), int(a_n)) == (p_ok, p_n), f"step {step}: GetObjectSequence({motion:#x}, {speed})"
        results.add((p_ok, p_n))
        _same(a, p, f"step {step} after GetObjectSequence({motion:#x}, {speed})")
        quantum = QUANTA[step % len(QUANTA)]
        a_frame = a_seq.Update(float(f(quantum)), a_frame)
        if isinstance(a_frame, tuple):  # pythonnet returns a void method's ref parameter alone or in a tuple
            a_frame = a_frame[-1]
        p_frame = p_seq.update(f(quantum), p_frame)
        assert _pframe(p_frame) == _frame(a_frame), f"step {step}: offset frame after Update({quantum})"
        _same(a, p, f"step {step} after Update({quantum})")
        moved += p_frame.origin != mode.vec(0, 0, 0)
    # the script is not vacuous: refused and accepted motions, counts of 0, 1 and 2, root motion, backward hooks and AnimDone
    assert {(False, 0), (True, 0), (True, 1), (True, 2)} <= results and moved > 10
    assert {d for _, d in _port_hooks(p[3])} >= {-1, 0} and 4 in {t for t, _ in _port_hooks(p[3])}


@pytest.mark.anchor("CMotionTable::StopObjectCompletely")
@pytest.mark.anchor("CMotionTable::StopSequenceMotion")
def test_stopping_motions_agrees_with_ace(ace):
    a, p, mode = _pair(ace)
    (a_table, a_state, a_seq, _), (p_table, p_state, p_seq, _) = a, p
    a_table.SetDefaultState(a_state, a_seq, 0)
    p_table.set_default_state(p_state, p_seq, 0)
    for motion, speed in ((mt.MODIFIER, 0.75), (mt.RUN, 1.0), (mt.MODIFIER, 1.0)):
        a_table.GetObjectSequence(motion, a_state, a_seq, float(f(speed)), 0, False)
        p_table.get_object_sequence(motion, p_state, p_seq, f(speed), 0, False)
    _same(a, p, "set up")
    a_ok, a_n = a_table.StopObjectMotion(mt.MODIFIER, 1.0, a_state, a_seq, 0)
    p_ok, p_n = p_table.stop_object_motion(mt.MODIFIER, f(1.0), p_state, p_seq, 0)
    assert (bool(a_ok), int(a_n)) == (p_ok, p_n)
    _same(a, p, "StopObjectMotion(modifier)")
    a_table.GetObjectSequence(mt.MODIFIER, a_state, a_seq, 0.5, 0, False)
    p_table.get_object_sequence(mt.MODIFIER, p_state, p_seq, f(0.5), 0, False)
    a_ok, a_n = a_table.StopObjectCompletely(a_state, a_seq, 0)
    p_ok, p_n = p_table.stop_object_completely(p_state, p_seq, 0)
    assert (bool(a_ok), int(a_n)) == (p_ok, p_n)
    _same(a, p, "StopObjectCompletely")


@pytest.mark.anchor("CMotionTable::get_link")
def test_get_link_finds_the_same_links_as_ace_for_every_state_pair_and_sign(ace):
    a, p, _ = _pair(ace)
    a_table, p_table = a[0], p[0]
    motions = (mt.READY, mt.WALK, mt.RUN, mt.ACTION, mt.HAND_COMBAT, mt.NON_COMBAT, 0)
    found = 0
    for style in (mt.NON_COMBAT, mt.HAND_COMBAT):
        for sub in motions:
            for motion in motions:
                for s1, s2 in ((1.0, 1.0), (-1.0, 1.0), (1.0, -1.0)):
                    got = a_table.get_link(style, sub, s1, motion, s2)
                    mine = p_table.get_link(style, sub, f(s1), motion, f(s2))
                    a_anims = None if got is None else [int(x.AnimId) for x in got.Anims]
                    p_anims = None if mine is None else [x.anim_id for x in mine.anims]
                    assert p_anims == a_anims, (hex(style), hex(sub), hex(motion), s1, s2)
                    found += got is not None
    assert found >= 10
