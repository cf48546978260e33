"""The comparator on tick outcomes (outcome/4, and /5 whose ticks carry the motion layer): every TickState
field, the first differing tick on top."""

from __future__ import annotations

import dataclasses
import json
import math

import pytest

from acconform.compare import Difference, compare, first_tick_difference
from acconform.errors import InvalidScene
from acconform.outcome import (FORMAT_V5 as FORMAT, FORMAT_V4, CommandState, MotionTickState, Outcome, PlacementState, PlaneState,
                               TickState)

TICK = TickState(True, 1000.0999999999999, 0xA9B40001, 0xA9B40001, (12.0, 12.5, 20.0), (1.0, 0.0, 0.0, 0.0),
                 (0.0, 2.0, -1.5), (0.0, 0.0, -9.75), (0.0, 0.0, 0.5), (0.0, 2.0, 0.0), 0x400, 0x83, 0xA9B40001,
                 PlaneState((0.0, 0.0, 1.0), -20.0), (0.0, 0.0, 0.0), True, (0xA9B40001, 0xA9B40009))
BASE = Outcome(static_cells=(), ticks=tuple(dataclasses.replace(TICK, update_time=1000.0 + 0.1 * i) for i in range(10)))
WALK = CommandState(0x8000003D, 0x45000005, 1.0, 0x6500000F, 0.5, 0x6500000D, 1.5)
MOTION = MotionTickState(WALK, dataclasses.replace(WALK, turn_command=0), 0x03000004, 2.75, (0.0, 3.0, 0.0),
                         (0.0, 0.0, -1.5), 0, False)
MOVING = Outcome(static_cells=(), ticks=tuple(dataclasses.replace(t, motion=MOTION) for t in BASE.ticks))


def with_tick(i: int, **changes) -> Outcome:
    ticks = list(BASE.ticks)
    ticks[i] = dataclasses.replace(ticks[i], **changes)
    return dataclasses.replace(BASE, ticks=tuple(ticks))


def _changed(name: str, v):
    """A value of TickState field `name` that differs from `v`."""
    if isinstance(v, bool):
        return not v
    if name == "update_time":
        return math.nextafter(v, math.inf)  # one double ulp
    if isinstance(v, int):
        return v + 1
    if name == "shadow_cells":
        return tuple(reversed(v))
    if isinstance(v, tuple):
        return (v[0], v[1] + 0.5, *v[2:])
    if isinstance(v, PlaneState):
        return dataclasses.replace(v, d=v.d - 1.0)
    if name == "motion":
        return MOTION
    return "NullReferenceException: x"


@pytest.mark.parametrize("name", [f.name for f in dataclasses.fields(TickState)])
def test_each_tick_state_field_is_compared_and_named_with_its_tick(name):
    v = getattr(TICK, name)
    other = with_tick(7, **{name: _changed(name, v)})
    for mode in ("exact", "fast"):
        diffs = compare(BASE, other, mode)
        assert diffs, (name, mode)
        assert all(d.field.startswith(f"ticks[7].{name}") for d in diffs), diffs
        assert first_tick_difference(diffs) == diffs[0]


def test_the_first_differing_tick_and_field_come_first_whatever_else_differs():
    other = with_tick(7, origin=(12.0, 12.5, 20.5), cell=0xA9B40009)
    other = dataclasses.replace(other, ticks=other.ticks[:3] + (dataclasses.replace(other.ticks[3], omega=(0.0, 0.0, 1.0)),)
                                + other.ticks[4:], static_cells=((0xA9B40001,),))
    diffs = compare(BASE, other)
    assert [d.field for d in diffs] == ["ticks[3].omega[2]", "ticks[7].cell", "ticks[7].origin[2]", "static_cells"]
    assert first_tick_difference(diffs).render() == "ticks[3].omega[2]: port=0.5 (0x3f000000) oracle=1.0 (0x3f800000)"


def test_a_placement_difference_comes_before_the_ticks_it_caused():
    placed = dataclasses.replace(BASE, placement=PlacementState(1, 0xA9B40001))
    other = dataclasses.replace(with_tick(0, cell=0xA9B40002), placement=PlacementState(2, 0xA9B40001))
    diffs = compare(placed, other)
    assert [d.field for d in diffs] == ["placement.result", "ticks[0].cell"]
    assert first_tick_difference(diffs).field == "ticks[0].cell"


def test_update_time_is_a_double_compared_by_bits_in_every_mode():
    t = BASE.ticks[2].update_time
    other = with_tick(2, update_time=math.nextafter(t, 0.0))
    for mode in ("exact", "fast"):
        (d,) = compare(BASE, other, mode)
        assert d.field == "ticks[2].update_time"
    assert d.render().startswith(f"ticks[2].update_time: port={t!r} (0x")


def test_fewer_ticks_on_one_side_is_a_difference_at_the_first_missing_tick():
    ended = dataclasses.replace(BASE, ticks=BASE.ticks[:5])
    diffs = compare(BASE, ended)
    assert [d.field for d in diffs] == ["ticks[5]"]
    assert diffs[-1].b is None and diffs[-1].render() == "ticks[5]: port=a TickState oracle=None"


def test_a_ticks_error_counts_by_presence_and_in_exact_mode_by_type_only():
    a = with_tick(3, error="NullReferenceException: Object reference not set")
    a2 = with_tick(3, error="NullReferenceException: another message")
    b = with_tick(3, error="InvalidOperationException: x")
    assert compare(a, a2) == [] and [d.field for d in compare(a, b)] == ["ticks[3].error"]
    assert compare(a, b, "fast") == []


def test_ticks_on_one_side_only_is_one_difference():
    plain = dataclasses.replace(BASE, ticks=None)
    assert compare(plain, BASE) == [Difference("ticks", None, BASE.ticks)]
    assert compare(plain, BASE)[0].render() == "ticks: port=None oracle=10 ticks"


def test_fast_mode_allows_ulps_in_a_ticks_floats_but_not_in_its_ids_or_flags():
    from acconform.numerics import f32_from_bits

    import numpy as np

    near = f32_from_bits(int(np.float32(12.5).view(np.uint32)) + 3)
    other = with_tick(5, origin=(12.0, near, 20.0))
    assert [d.field for d in compare(BASE, other)] == ["ticks[5].origin[1]"] and compare(BASE, other, "fast") == []
    assert compare(BASE, with_tick(5, transient_state=0x81), "fast")[0].render() == \
        "ticks[5].transient_state: port=Contact|OnWalkable|Active oracle=Contact|Active"


def test_a_tick_outcome_is_written_as_outcome_4_and_reads_back_bit_for_bit():
    odd = with_tick(1, sliding_normal=(-0.0, 0.0, 0.0), update_time=0.1 + 0.2, velocity=(math.nan, 0.0, math.inf))
    doc = json.loads(json.dumps(odd.to_json()))
    assert doc["format"] == FORMAT_V4 == "acconform.outcome/4"  # no tick has motion: written as before
    back = Outcome.from_json(doc)
    assert compare(odd, back) == [] and back.ticks[1].update_time == 0.30000000000000004
    assert math.copysign(1.0, back.ticks[1].sliding_normal[0]) == -1.0
    errored = dataclasses.replace(BASE, ticks=(TickState(error="NullReferenceException: x"),))
    assert Outcome.from_json(errored.to_json()) == errored
    assert "error" not in BASE.to_json()["ticks"][0]


def test_an_older_outcome_format_cannot_carry_ticks_and_a_bad_tick_names_its_field():
    doc = BASE.to_json()
    with pytest.raises(InvalidScene, match="unknown field 'ticks'"):
        Outcome.from_json(dict(doc, format="acconform.outcome/3"))
    bad = json.loads(json.dumps(doc))
    bad["ticks"][2]["update_time"] = "soon"
    with pytest.raises(InvalidScene, match=r"ticks\[2\]\.update_time: expected a number"):
        Outcome.from_json(bad)
    del bad["ticks"][2]["update_time"]
    with pytest.raises(InvalidScene, match=r"ticks\[2\]\.update_time: missing required field"):
        Outcome.from_json(bad)


def _motion_changed(name: str, v):
    """A value of MotionTickState or CommandState field `name` that differs from `v`."""
    if name == "movement_type":
        return 7  # MoveToPosition
    if isinstance(v, CommandState):
        return dataclasses.replace(v, forward_speed=2.0)
    return _changed(name, v) if not isinstance(v, float) else v + 0.25


@pytest.mark.parametrize("name", [f.name for f in dataclasses.fields(MotionTickState)])
def test_each_field_of_a_ticks_motion_layer_is_compared_and_named_with_its_tick(name):
    motion = dataclasses.replace(MOTION, **{name: _motion_changed(name, getattr(MOTION, name))})
    other = dataclasses.replace(MOVING, ticks=tuple(dataclasses.replace(t, motion=motion) if i >= 3 else t
                                                    for i, t in enumerate(MOVING.ticks)))
    for mode in ("exact", "fast"):
        diffs = compare(MOVING, other, mode)
        assert diffs and first_tick_difference(diffs).field.startswith(f"ticks[3].motion.{name}"), (name, mode, diffs)


@pytest.mark.parametrize("name", [f.name for f in dataclasses.fields(CommandState)])
def test_each_command_of_the_interpreted_and_raw_state_is_named_by_its_path(name):
    for part in ("interpreted", "raw"):
        state = getattr(MOTION, part)
        v = getattr(state, name)
        changed = dataclasses.replace(state, **{name: v + 1 if isinstance(v, int) else v * 2.0})
        other = dataclasses.replace(MOVING, ticks=(dataclasses.replace(MOVING.ticks[0], motion=dataclasses.replace(
            MOTION, **{part: changed})), *MOVING.ticks[1:]))
        assert [d.field for d in compare(MOVING, other)] == [f"ticks[0].motion.{part}.{name}"]


def test_a_motion_difference_renders_commands_as_ids_and_the_move_to_state_by_name():
    stopped = dataclasses.replace(MOTION, interpreted=dataclasses.replace(WALK, forward_command=0x41000003), movement_type=7)
    other = dataclasses.replace(MOVING, ticks=(*MOVING.ticks[:4], dataclasses.replace(MOVING.ticks[4], motion=stopped),
                                               *MOVING.ticks[5:]))
    assert [d.render() for d in compare(MOVING, other)] == [
        "ticks[4].motion.interpreted.forward_command: port=0x45000005 oracle=0x41000003",
        "ticks[4].motion.movement_type: port=Invalid oracle=MoveToPosition"]


def test_a_motion_layer_or_a_part_of_it_on_one_side_only_is_one_difference_naming_it():
    assert [d.field for d in compare(MOVING, BASE)] == [f"ticks[{i}].motion" for i in range(10)]
    bare = dataclasses.replace(MOTION, interpreted=None, animation=None)
    other = dataclasses.replace(MOVING, ticks=(dataclasses.replace(MOVING.ticks[0], motion=bare), *MOVING.ticks[1:]))
    assert [d.field for d in compare(MOVING, other)] == ["ticks[0].motion.interpreted", "ticks[0].motion.animation"]


def test_a_motion_outcome_is_written_as_outcome_5_and_reads_back_bit_for_bit():
    odd = dataclasses.replace(MOTION, frame_number=-0.0, interpreted=dataclasses.replace(WALK, turn_speed=math.nan),
                              raw=None, animation=None, movement_type=None)
    outcome = dataclasses.replace(MOVING, ticks=(dataclasses.replace(MOVING.ticks[0], motion=odd), *MOVING.ticks[1:]))
    doc = json.loads(json.dumps(outcome.to_json()))
    assert doc["format"] == FORMAT == "acconform.outcome/5"
    assert doc["ticks"][0]["motion"]["raw"] is None and doc["ticks"][0]["motion"]["movement_type"] is None
    assert doc["ticks"][1]["motion"]["movement_type"] == "Invalid"
    back = Outcome.from_json(doc)
    assert compare(outcome, back) == [] and back == dataclasses.replace(back, ticks=back.ticks)
    assert math.copysign(1.0, back.ticks[0].motion.frame_number) == -1.0 and math.isnan(back.ticks[0].motion.interpreted.turn_speed)
    assert back.ticks[1:] == outcome.ticks[1:]


def test_an_outcome_4_record_still_reads_and_cannot_carry_a_motion_layer():
    """The recorded corpus's tick records are outcome/4: they read as before, with no tick's motion."""
    doc = json.loads(json.dumps(BASE.to_json()))
    assert doc["format"] == "acconform.outcome/4" and Outcome.from_json(doc) == BASE
    assert all(t.motion is None for t in Outcome.from_json(doc).ticks)
    moving = json.loads(json.dumps(MOVING.to_json()))
    with pytest.raises(InvalidScene, match=r"ticks\[0\]: unknown field 'motion'"):
        Outcome.from_json(dict(moving, format="acconform.outcome/4"))
    del moving["ticks"][2]["motion"]["frame_number"]
    with pytest.raises(InvalidScene, match=r"ticks\[2\]\.motion\.frame_number: missing required field"):
        Outcome.from_json(moving)
    moving["ticks"][2]["motion"]["frame_number"] = 1.0
    moving["ticks"][2]["motion"]["movement_type"] = "Sideways"
    with pytest.raises(InvalidScene, match=r"ticks\[2\]\.motion\.movement_type: unknown MovementType 'Sideways'"):
        Outcome.from_json(moving)
