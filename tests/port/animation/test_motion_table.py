"""MotionTable (port/animation/motion_table.py) on motion_tables.py's small table: links, the four
kinds of motion GetObjectSequence plays, the default state, stops and the static helpers. Expected
values follow MotionTable.cs at 7b47913 (and the live lane compares the same calls with ACE)."""

from __future__ import annotations

import numpy as np
import pytest

from acconform.numerics import EXACT
from acconform.port.animation.motion_state import MotionState
from acconform.port.animation.motion_table import MotionTable
from acconform.port.animation.sequence import Sequence
from acconform.port.errors import ArithmeticException

import motion_tables as mt

f = np.float32


def setup():
    pd = mt.portal_dat(EXACT)
    table = MotionTable.get(mt.TABLE_ID, pd)
    state, seq = MotionState.create(EXACT), Sequence.create(EXACT, pd)
    assert table.set_default_state(state, seq, 7) == (True, 0)
    return table, state, seq, pd


def queued(seq) -> list:
    return [(n.anim.id, float(n.framerate)) for n in seq.anim_list]


@pytest.mark.anchor("CMotionTable::get_link")
def test_get_link_looks_forward_from_the_substate_and_backward_when_a_speed_is_negative():
    table, *_ = setup()
    one, back = f(1), f(-1)
    assert table.get_link(mt.NON_COMBAT, mt.READY, one, mt.WALK, one).anims[0].anim_id == mt.A_LINK_WALK
    assert table.get_link(mt.NON_COMBAT, mt.RUN, one, mt.RUN, one).anims[0].framerate == f(-30)  # the style's own links
    # backwards: the link from the motion to the substate, else the substate's link to the style default
    assert table.get_link(mt.NON_COMBAT, mt.READY, one, mt.WALK, back).anims[0].anim_id == mt.A_LINK_READY
    assert table.get_link(mt.NON_COMBAT, mt.WALK, back, mt.RUN, one).anims[0].anim_id == mt.A_LINK_READY
    assert table.get_link(mt.HAND_COMBAT, mt.READY, one, mt.WALK, one) is None


@pytest.mark.anchor("CMotionTable::SetDefaultState")
def test_the_default_state_is_the_default_styles_default_cycle():
    table, state, seq, _ = setup()
    assert (state.style, state.substate, state.substate_mod) == (mt.NON_COMBAT, mt.READY, f(1))
    assert queued(seq) == [(mt.A_READY, 30.0)] and seq.curr_anim is seq.first_cyclic


@pytest.mark.anchor("CMotionTable::GetObjectSequence")
def test_a_new_substate_plays_its_link_then_its_cycle_at_the_speed_given():
    table, state, seq, _ = setup()
    assert table.get_object_sequence(mt.WALK, state, seq, f(1.5), 99, False) == (True, 1)
    # the old cycle (Ready, the current animation) is removed: CurrAnim becomes the link
    assert queued(seq) == [(mt.A_LINK_WALK, 45.0), (mt.A_WALK, 45.0)] and seq.curr_anim is seq.anim_list.first
    assert seq.velocity == EXACT.vec(0, 3.12, 0) * f(1.5) and (state.substate, state.substate_mod) == (mt.WALK, f(1.5))


@pytest.mark.anchor("CMotionTable::change_cycle_speed")
def test_the_same_substate_at_a_new_speed_rescales_the_cycle_and_its_velocity():
    table, state, seq, _ = setup()
    table.get_object_sequence(mt.WALK, state, seq, f(1), 0, False)
    assert table.get_object_sequence(mt.WALK, state, seq, f(2), 0, False) == (True, 0)
    assert queued(seq)[-1] == (mt.A_WALK, 60.0) and seq.velocity == EXACT.vec(0, 3.12, 0) * f(2)


@pytest.mark.anchor("CMotionTable::GetObjectSequence")
def test_an_action_plays_its_link_and_returns_to_the_cycle():
    table, state, seq, _ = setup()
    assert table.get_object_sequence(mt.ACTION, state, seq, f(2), 0, False) == (True, 1)
    assert queued(seq) == [(mt.A_ACTION, 30.0), (mt.A_READY, 30.0)]
    assert [(m.id, m.speed_mod) for m in state.actions] == [(mt.ACTION, f(2))]


@pytest.mark.anchor("CMotionTable::combine_motion")
def test_a_modifier_adds_its_omega_unless_the_cycle_clears_modifiers():
    table, state, seq, _ = setup()
    assert table.get_object_sequence(mt.MODIFIER, state, seq, f(0.5), 0, False) == (True, 0)
    assert seq.omega == EXACT.vec(0, 0, 0.75) and [m.id for m in state.modifiers] == [mt.MODIFIER]
    assert table.stop_object_motion(mt.MODIFIER, f(1), state, seq, 0) == (True, 0)
    assert seq.omega == EXACT.vec(0, 0, 0) and state.modifiers.count == 0
    table.get_object_sequence(mt.WALK, state, seq, f(1), 0, False)  # Walk's Bitfield 1: no modifiers
    assert table.get_object_sequence(mt.MODIFIER, state, seq, f(1), 0, False) == (False, 0)


@pytest.mark.anchor("CMotionTable::GetObjectSequence")
def test_a_style_change_plays_the_link_into_the_style_and_its_default_cycle():
    table, state, seq, _ = setup()
    assert table.get_object_sequence(mt.HAND_COMBAT, state, seq, f(1), 0, False) == (True, 1)
    assert queued(seq)[-2:] == [(mt.A_LINK_STYLE, 10.0), (mt.A_HAND_READY, 20.0)]
    assert (state.style, state.substate) == (mt.HAND_COMBAT, mt.READY)
    assert table.get_object_sequence(mt.HAND_COMBAT, state, seq, f(1), 0, False) == (True, 0)  # already there


@pytest.mark.anchor("CMotionTable::GetObjectSequence")
def test_a_nan_speed_meets_math_sign_and_throws():
    table, state, seq, _ = setup()
    with pytest.raises(ArithmeticException):
        table.get_object_sequence(mt.WALK, state, seq, f("nan"), 0, False)


@pytest.mark.anchor("CMotionTable::StopObjectCompletely")
def test_stopping_completely_removes_the_modifiers_and_returns_to_the_style_default():
    table, state, seq, _ = setup()
    table.get_object_sequence(mt.MODIFIER, state, seq, f(1), 0, False)
    table.get_object_sequence(mt.RUN, state, seq, f(1), 0, False)
    assert table.stop_object_completely(state, seq, 0)[0] is True
    assert state.substate == mt.READY and state.modifiers.count == 0


@pytest.mark.anchor("MotionTable.cs:GetRunSpeed")
def test_run_speed_is_the_root_motion_per_frame_times_the_framerate_and_remembered():
    _, _, _, pd = setup()
    speed = MotionTable.get_run_speed(mt.TABLE_ID, pd)
    # A_RUN's PosFrames step 0.375, 0.75, 1.125 along y: (2.25 / 3) * 24
    assert speed == f(f(2.25) / f(3)) * f(24) and pd.run_speed == {mt.TABLE_ID: speed}
    assert MotionTable.get_turn_speed(mt.TABLE_ID, pd) == f(0)  # no TurnRight cycle
    assert MotionTable.get_animation_length(mt.TABLE_ID, mt.NON_COMBAT, mt.WALK, pd) == f(3) / f(30)
