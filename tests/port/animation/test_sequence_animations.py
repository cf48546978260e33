"""Sequence with animations (port/animation/sequence.py): frame advancement, root motion, the move to
the next animation and the cycle, hooks, apricot and the queue edits MotionTable makes; PartArray's
default animation. Expected values follow Sequence.cs and AnimSequenceNode.cs at 7b47913."""

from __future__ import annotations

import numpy as np
import pytest

from acconform.numerics import EXACT
from acconform.port.animation.anim_data import AnimData
from acconform.port.animation.sequence import Sequence
from acconform.port.constants import EPSILON
from acconform.port.frame import AFrame

import motion_tables as mt

f = np.float32


class HookSink:
    def __init__(self):
        self.anim_hooks = []

    def add_anim_hook(self, hook):
        self.anim_hooks.append(hook)


def sequence(*anims):
    """A sequence playing `anims` ((id, framerate, low, high) each), hooks kept in a sink."""
    pd = mt.portal_dat(EXACT)
    seq = Sequence.create(EXACT, pd)
    seq.set_object(HookSink())
    for anim_id, framerate, low, high in anims:
        seq.append_animation(AnimData(anim_id, low, high, f(framerate)))
    return seq, pd


@pytest.mark.anchor("AnimSequenceNode::set_animation_id")
def test_a_node_clamps_its_frames_to_the_animation_and_starts_at_its_low_or_ending_frame():
    seq, _ = sequence((mt.A_WALK, 30, 0, -1), (mt.A_WALK, -30, 2, 99), (mt.A_WALK, 30, 9, 1))
    nodes = [n for n in seq.anim_list]
    assert [(n.low_frame, n.high_frame) for n in nodes] == [(0, 4), (2, 4), (4, 4)]
    assert nodes[0].get_starting_frame() == f(0) and nodes[1].get_starting_frame() == f(5) - f(EPSILON)
    assert seq.curr_anim.value is nodes[0] and seq.first_cyclic.value is nodes[2]


@pytest.mark.anchor("CSequence::update_internal")
def test_each_whole_frame_passed_combines_its_root_motion_and_a_frames_worth_of_velocity():
    seq, _ = sequence((mt.A_WALK, 30, 0, -1))
    seq.set_velocity(EXACT.vec(0, 3, 0))
    frame = seq.update(f(2) / f(30), AFrame.identity(EXACT))
    assert seq.frame_number == f(2) / f(30) * f(30)
    node = seq.curr_anim.value
    want = AFrame.identity(EXACT)
    for k in range(2):
        want = AFrame.combine(want, node.get_pos_frame(k))
        seq.apply_physics(want, f(1) / f(30), f(2) / f(30))
    assert (frame.origin, frame.orientation) == (want.origin, want.orientation) and frame.origin.y > 0.3


@pytest.mark.anchor("CSequence::advance_to_next_animation")
def test_at_the_end_of_a_link_the_sequence_moves_on_says_anim_done_and_apricot_drops_the_link():
    seq, _ = sequence((mt.A_LINK_WALK, 30, 0, -1), (mt.A_WALK, 30, 0, -1))
    seq.update(f(0.2), AFrame.identity(EXACT))  # 6 frames: the 3-frame link, then 3 of the cycle
    assert [n.anim.id for n in seq.anim_list] == [mt.A_WALK] and seq.curr_anim is seq.first_cyclic
    assert seq.frame_number == f(f(6) - f(2) - 1) + f(0)  # the overflow past the link's frame 2 carried on
    kinds = [(int(h.hook_type), int(h.direction)) for h in seq.hook_obj.anim_hooks]
    # only AnimDoneHook: the link's hooks sit on its last frame (2), which the forward loop never passes (it
    # stops when the frame number, clamped to the high frame, is reached), as in ACE
    assert kinds == [(4, 0)] and seq.hook_obj.anim_hooks[0].direction == 0


@pytest.mark.anchor("CSequence::update_internal")
def test_a_cycle_played_backwards_subtracts_its_root_motion_and_runs_backward_hooks():
    seq, _ = sequence((mt.A_READY, -30, 0, -1))
    assert seq.frame_number == f(4) - f(EPSILON)
    frame = seq.update(f(3) / f(30), AFrame.identity(EXACT))
    assert [(int(h.hook_type), int(h.direction)) for h in seq.hook_obj.anim_hooks] == [(1, -1), (4, 0)]
    assert frame.orientation.z < 0  # frames 3, 2, 1 turned back about z


@pytest.mark.anchor("CSequence::remove_cyclic_anims")
def test_removing_the_cycle_moves_the_current_animation_back_to_the_link_s_end():
    seq, _ = sequence((mt.A_LINK_WALK, 30, 0, -1), (mt.A_WALK, 30, 0, -1))
    seq.update(f(0.2), AFrame.identity(EXACT))
    seq.append_animation(AnimData(mt.A_LINK_READY, 0, -1, f(30)))
    seq.remove_cyclic_anims()
    assert [n.anim.id for n in seq.anim_list] == [mt.A_WALK] and seq.curr_anim is seq.first_cyclic
    seq.remove_cyclic_anims()
    assert seq.curr_anim is None and seq.first_cyclic is None and seq.frame_number == f(0)


@pytest.mark.anchor("CSequence::multiply_cyclic_animation_framerate")
def test_a_negative_rate_swaps_the_cycles_frame_range():
    seq, _ = sequence((mt.A_LINK_WALK, 30, 0, -1), (mt.A_WALK, 30, 1, 3))
    seq.multiply_cyclic_animation_framerate(f(-0.5))
    last = seq.first_cyclic.value
    assert (last.low_frame, last.high_frame, last.framerate) == (3, 1, f(-15))
    assert seq.anim_list.first.value.framerate == f(30)


@pytest.mark.anchor("CPartArray::InitDefaults")
def test_a_setup_s_default_animation_plays_all_its_frames_from_creation():
    from acconform import dat
    from acconform.port.dat.portal_dat import PortalDat
    from acconform.port.part_array import PartArray

    records = mt.records()
    records[0x01000001] = dat.gfx_obj_mesh(0x01000001, [])
    records[0x02000001] = dat.setup(0x02000001, [0x01000001], default_animation=mt.A_WALK)
    pd = PortalDat(records, EXACT, server=True)
    pa = PartArray.create_setup(None, 0x02000001, True, pd)
    node = pa.sequence.curr_anim.value
    assert (node.anim.id, node.low_frame, node.high_frame, node.framerate) == (mt.A_WALK, 0, 4, f(0))
    assert pa.has_anims() and pa.sequence.get_curr_anim_frame() is node.anim.part_frames[0]
