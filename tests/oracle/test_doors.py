"""The tick input door (issue 41; scene/7, feature doors): a static opens or closes at a tick as ACE's
server Door does (acconform/scene.py DoorInput). Its scene field and refusals, its pack bytes (fast
lane), and each named scene of tests/oracle/door_scenes.py answered by live ACE and by the port bit for
bit (live lane, mono and .NET 10)."""

from __future__ import annotations

import json
import struct
import sys
from pathlib import Path

import pytest

from acconform.compare import compare
from acconform.errors import InvalidScene
from acconform.flags import PhysicsState
from acconform.oracle.pack import PACK_VERSION, pack_scene
from acconform.protocol import scene_features
from acconform.scene import FORMAT_V7 as FORMAT, FORMAT_V6, TICK_INPUTS, Scene

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from oracle.door_scenes import DOOR, scenes  # noqa: E402

SCENES = scenes()


def _doc(name: str) -> dict:
    return json.loads(SCENES[name].dumps())


@pytest.mark.parametrize("name", sorted(SCENES))
def test_each_door_scene_reads_back_as_the_same_scene_in_format_7_and_needs_the_doors_feature(name):
    scene = SCENES[name]
    assert Scene.loads(scene.dumps()) == scene
    assert scene.format == FORMAT and "doors" in scene_features(scene)


def test_a_door_input_is_written_as_the_object_id_and_ethereal():
    steps = _doc("door_closes_behind_a_player")["ticks"]["steps"]
    assert [s["door"] for s in steps if "door" in s] == [{"object": "0x70000001", "ethereal": False}]


@pytest.mark.parametrize("edit, where, problem", [
    (lambda d: d.__setitem__("object", "0x70000003"), r"steps\[45\]\.door\.object", "no outdoor static object has id 0x70000003"),
    (lambda d: d.__setitem__("ethereal", "yes"), r"steps\[45\]\.door\.ethereal", ""),
    (lambda d: d.pop("ethereal"), r"steps\[45\]\.door\.ethereal", "missing"),
    (lambda d: d.__setitem__("open", True), r"steps\[45\]\.door", "unknown field .open."),
])
def test_a_bad_door_input_is_refused_naming_the_field(edit, where, problem):
    doc = _doc("door_closes_behind_a_player")
    edit(doc["ticks"]["steps"][45]["door"])
    with pytest.raises(InvalidScene, match=where + ".*" + problem):
        Scene.from_json(doc)


def test_a_door_input_needs_format_7():
    doc = _doc("door_closes_behind_a_player")
    doc["format"] = FORMAT_V6
    with pytest.raises(InvalidScene, match=r"steps\[45\]\.door.*needs format 'acconform.scene/7'"):
        Scene.from_json(doc)


def test_a_tick_scene_without_a_door_input_keeps_its_older_format():
    scene = SCENES["door_closes_behind_a_player"]
    plain = scene.replace(ticks=scene.ticks.__class__(scene.ticks.driver, scene.ticks.start,
                                                       tuple(s.__class__(s.dt, velocity=s.velocity) for s in scene.ticks.steps)))
    assert plain.format == FORMAT_V6 and "doors" not in scene_features(plain)  # /6: the placement through enter_world


def test_a_door_input_packs_its_bit_the_id_and_one_byte():
    bit = {name: 1 << i for i, name in enumerate(TICK_INPUTS)}
    assert bit["door"] == 131072 and TICK_INPUTS[-2:] == ("door", "stick_to") and PACK_VERSION == 18
    scene = SCENES["closed_door_opens_before_a_player"]
    data = pack_scene(scene)
    at = data.index(struct.pack("<d", scene.ticks.times()[40]), 5 + 14)
    assert data[at + 8:at + 8 + 4 + 12 + 5] == struct.pack("<I", 4 | 131072) + struct.pack("<3f", 0.0, 3.0, 0.0) + \
        struct.pack("<IB", DOOR, 1)


def _door_states(scene):
    import acconform.port.run as run

    states, door = [], run.door

    def spy(obj, ethereal, lscape):
        door(obj, ethereal, lscape)
        states.append(bool(obj.state & PhysicsState.Ethereal))

    run.door = spy
    try:
        outcome = run.run_scene(scene)
    finally:
        run.door = door
    return outcome, states


def test_a_door_closing_on_the_player_in_the_doorway_is_held_open_and_shuts_once_the_player_is_out():
    outcome, states = _door_states(SCENES["door_closes_on_a_player_in_the_doorway"])
    ys = [float(t.origin[1]) for t in outcome.ticks]
    assert states == [True, False]  # held (ethereal_check_for_collisions found the player), then shut
    assert max(ys) > 63.0 and 62.58 < ys[-1] < 62.7  # through, then stopped at the closed door's far face


def test_a_door_closing_behind_the_player_shuts_and_stops_it_on_the_way_back():
    outcome, states = _door_states(SCENES["door_closes_behind_a_player"])
    ys = [float(t.origin[1]) for t in outcome.ticks]
    assert states == [False] and 62.58 < ys[-1] < 62.7


def test_a_closed_door_that_opens_lets_the_player_through_once_its_sliding_state_is_cleared():
    held = [float(t.origin[1]) for t in _door_states(SCENES["closed_door_opens_before_a_player"])[0].ticks]
    through = [float(t.origin[1]) for t in _door_states(SCENES["closed_door_opens_and_the_player_walks_through"])[0].ticks]
    assert held[-1] == held[40] < 61.5 and through[-1] > 63.0


@pytest.mark.live_oracle
@pytest.mark.parametrize("name", sorted(SCENES))
def test_live_ace_and_the_port_answer_each_door_scene_bit_for_bit(live, name):
    from acconform.port.run import run_scene

    scene = SCENES[name]
    ace = live.run(scene)
    assert ace.error is None and len(ace.ticks) == len(scene.ticks.steps) and not any(t.error for t in ace.ticks)
    assert compare(run_scene(scene, runtime=live.location.runtime), ace, "exact") == [], name
