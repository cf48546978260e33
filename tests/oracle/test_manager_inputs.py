"""The tick inputs that drive ACE's managers as the server does (issue 40): move_to, move_to_object,
turn_to_heading, turn_to_object, stop, do_motion, stop_motion (acconform/motion_scene.py). Their scene
fields and pack bytes (fast lane), and each named scene of tests/oracle/manager_scenes.py answered by
the port as ACE answered it on mono and .NET 10 (recorded, fast lane) and as live ACE answers it (live
lane), bit for bit."""

from __future__ import annotations

import json
import struct
import sys
from pathlib import Path

import pytest

from acconform.compare import compare
from acconform.errors import InvalidScene
from acconform.motion_scene import DEFAULT_MOVEMENT_FLAGS, MovementParams
from acconform.oracle.pack import pack_scene
from acconform.protocol import scene_features
from acconform.scene import FORMAT_V5, TICK_INPUTS, Scene

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from oracle.live_answers import recorded_outcomes  # noqa: E402
from oracle.manager_scenes import BALL, DATA, scenes  # noqa: E402

SCENES = scenes()


def _doc(name: str) -> dict:
    return json.loads(SCENES[name].dumps())


@pytest.mark.parametrize("name", sorted(SCENES))
def test_each_manager_scene_reads_back_as_the_same_scene_and_needs_the_motion_feature(name):
    scene = SCENES[name]
    assert Scene.loads(scene.dumps()) == scene
    # a scene with another mover (the target of sticky_follow_of_a_moving_target) is written as scene/8
    assert "mover.motion" in scene_features(scene)
    assert scene.format == ("acconform.scene/8" if scene.others else "acconform.scene/6")


def test_movement_parameters_left_at_the_constructors_values_are_left_out_of_the_json():
    assert MovementParams().to_json() == {}
    assert _doc("move_to_a_point")["ticks"]["steps"][0]["move_to"].keys() == {"position"}
    params = _doc("sticky_move_to_a_static")["ticks"]["steps"][0]["move_to_object"]["params"]
    assert "Sticky" in params["flags"] and _doc("sticky_move_to_a_static")["ticks"]["steps"][0]["move_to_object"]["object"] == "0x70000002"


@pytest.mark.parametrize("edit, where, problem", [
    (lambda s: s.__setitem__("stop", "halt"), r"steps\[0\]\.stop", "unknown stop 'halt'"),
    (lambda s: s["move_to_object"].__setitem__("object", "0x70000003"), r"steps\[0\]\.move_to_object\.object",
     "no outdoor static object or other mover in the world has id 0x70000003"),
    (lambda s: s["move_to_object"]["params"].__setitem__("flags", ["Sticky", "Glue"]), r"params\.flags\[1\]",
     "unknown MovementParamFlags flag 'Glue'"),
    (lambda s: s["move_to_object"]["params"].__setitem__("speed", "fast"), r"params\.speed", ""),
    (lambda s: s["move_to_object"]["params"].__setitem__("hold_key_to_apply", "Walk"), r"hold_key_to_apply", "unknown hold key"),
])
def test_a_bad_manager_input_is_refused_naming_the_field(edit, where, problem):
    doc = _doc("sticky_move_to_a_static")
    step = doc["ticks"]["steps"][0]
    edit(step)
    with pytest.raises(InvalidScene, match=where + ".*" + problem):
        Scene.from_json(doc)


def test_a_manager_input_needs_the_movers_motion_table_and_format_6():
    doc = _doc("turn_to_heading_in_place")
    del doc["mover"]["motion_table"]
    with pytest.raises(InvalidScene, match=r"steps\[0\]\.turn_to_heading.*needs the mover's motion_table"):
        Scene.from_json(doc)
    doc = _doc("move_to_then_cancel_moveto")
    doc["format"] = FORMAT_V5
    del doc["mover"]["motion_table"]
    with pytest.raises(InvalidScene, match=r"steps\[0\]\.move_to.*needs format 'acconform.scene/6'"):
        Scene.from_json(doc)


def _step_bytes(scene, i: int) -> bytes:
    """Step i's packed head (time, mask) and inputs, found after the step head in the packed scene."""
    data = pack_scene(scene)
    head = struct.pack("<d", scene.ticks.times()[i])
    at = data.index(head, 5 + 14)
    return data[at:]


def test_each_manager_input_packs_its_bit_and_its_fields_in_order():
    bit = {name: 1 << i for i, name in enumerate(TICK_INPUTS)}
    assert [bit[n] for n in ("stop", "do_motion", "stop_motion", "move_to", "move_to_object", "turn_to_heading",
                             "turn_to_object")] == [1024, 2048, 4096, 8192, 16384, 32768, 65536]
    default = struct.pack("<I6fI", DEFAULT_MOVEMENT_FLAGS, 0.6, 0.0, 3.4028234663852886e38, 1.0, 1.0, 0.0, 0)
    move = SCENES["move_to_a_point"]
    pos = move.ticks.steps[0].move_to.position
    assert _step_bytes(move, 0)[8:12 + 32 + 32] == struct.pack("<I", 8192) + struct.pack(
        "<I3f4f", pos.cell, *pos.frame.origin, *pos.frame.orientation) + default
    sticky = SCENES["sticky_move_to_a_static"]
    assert _step_bytes(sticky, 0)[8:12 + 4 + 32] == struct.pack("<II", 16384, BALL) + struct.pack(
        "<I6fI", DEFAULT_MOVEMENT_FLAGS | 0x80, 0.6, 0.0, 3.4028234663852886e38, 1.0, 1.0, 0.0, 0)
    turn = SCENES["turn_to_heading_in_place"]
    assert _step_bytes(turn, 0)[8:12 + 32] == struct.pack("<I", 32768) + struct.pack(
        "<I6fI", DEFAULT_MOVEMENT_FLAGS, 0.6, 0.0, 3.4028234663852886e38, 1.0, 1.0, 135.0, 0)
    keys = SCENES["keys_do_and_stop_motion"]
    assert _step_bytes(keys, 1)[8:20] == struct.pack("<III", 2048, 0x45000005, 1)
    assert _step_bytes(keys, 12)[8:20] == struct.pack("<III", 4096, 0x45000005, 1)
    for i, stop in enumerate(("stop_completely", "cancel_moveto", "move_to_manager_cancel")):
        assert _step_bytes(SCENES[f"move_to_then_{stop}"], 9)[8:16] == struct.pack("<II", 1024, i)


def test_the_port_runs_every_manager_scene_to_its_last_tick_without_an_error():
    from acconform.port.run import run_scene

    for name, scene in SCENES.items():
        ticks = run_scene(scene).ticks
        assert len(ticks) == len(scene.ticks.steps) and not any(t.error for t in ticks), name
    moved = run_scene(SCENES["move_to_a_point"]).ticks
    assert moved[-1].origin != moved[0].origin


@pytest.mark.parametrize("runtime", ("mono", "coreclr"))
def test_the_port_answers_each_manager_scene_as_ace_did_every_tick(runtime):
    from acconform.port.run import run_scene

    ace = recorded_outcomes(DATA, runtime)
    assert set(ace) == set(SCENES)
    for name, scene in SCENES.items():
        assert ace[name].error is None and len(ace[name].ticks) == len(scene.ticks.steps), name
        assert compare(run_scene(scene, runtime=runtime), ace[name], "exact") == [], name


def test_ace_moves_the_player_toward_the_point_behind_the_box_and_slides_it_along_the_box():
    ticks = recorded_outcomes(DATA, "mono")["move_to_around_a_box"].ticks
    start, mid, end = ticks[0].origin, ticks[30].origin, ticks[-1].origin
    assert mid[1] > start[1] + 2.0 and end[1] > mid[1]  # on toward y = 66
    assert 61.0 < mid[0] == end[0] < 62.0  # held at the box's face (x = 62 less the sphere's radius)


@pytest.mark.live_oracle
@pytest.mark.parametrize("name", sorted(SCENES))
def test_live_ace_and_the_port_answer_each_manager_scene_bit_for_bit(live, name):
    from acconform.port.run import run_scene

    scene = SCENES[name]
    ace = live.run(scene)
    assert ace.error is None and len(ace.ticks) == len(scene.ticks.steps) and not any(t.error for t in ace.ticks)
    assert compare(run_scene(scene, runtime=live.location.runtime), ace, "exact") == [], name


# ---------------------------------------------------------------- a moving target (feature objects.targets)

def _follow_with(stick_at: int | None = None, destroy_at: int | None = None):
    """sticky_follow_of_a_moving_target with a melee swing's stick_to at a step and the target destroyed at one."""
    from dataclasses import replace

    from acconform.scene import OtherInputs
    from oracle.mover_scenes import PLAYER_2

    scene = SCENES["sticky_follow_of_a_moving_target"]
    steps = list(scene.ticks.steps)
    if stick_at is not None:
        steps[stick_at] = replace(steps[stick_at], stick_to=PLAYER_2)
    if destroy_at is not None:
        steps[destroy_at] = replace(steps[destroy_at], others=(OtherInputs(PLAYER_2, destroy=True),))
        steps[destroy_at + 1:] = [replace(s, others=()) for s in steps[destroy_at + 1:]]
    return scene.replace(ticks=replace(scene.ticks, steps=tuple(steps)))


def test_a_move_to_object_at_another_mover_needs_objects_targets_and_a_static_target_does_not():
    assert {"objects.moving", "objects.targets"} <= set(scene_features(SCENES["sticky_follow_of_a_moving_target"]))
    assert "objects.targets" not in scene_features(SCENES["sticky_move_to_a_static"])


def test_stick_to_and_destroy_read_back_and_pack_their_bits():
    from oracle.mover_scenes import PLAYER_2

    scene = _follow_with(stick_at=3, destroy_at=50)
    assert Scene.loads(scene.dumps()) == scene and "objects.targets" in scene_features(scene)
    doc = json.loads(scene.dumps())["ticks"]["steps"]
    assert doc[3]["stick_to"] == "0x50000002" and doc[50]["others"] == [{"id": "0x50000002", "destroy": True}]
    assert 1 << TICK_INPUTS.index("stick_to") == 262144
    stick = _step_bytes(scene, 3)
    assert stick[8:12] == struct.pack("<I", 262144) and stick[12:16] == struct.pack("<I", PLAYER_2)
    # no input of the mover; one other's inputs: its index 0 and the mask of bit 8 (destroy) with no value
    assert _step_bytes(scene, 50)[8:24] == struct.pack("<Iiii", 0, 1, 0, 256)


@pytest.mark.parametrize("edit, where, problem", [
    (lambda d: d["ticks"]["steps"][3].__setitem__("stick_to", "0x50000009"), r"steps\[3\]\.stick_to",
     "no outdoor static object or other mover in the world has id 0x50000009"),
    (lambda d: d["ticks"]["steps"][60].__setitem__("others", [{"id": "0x50000002", "velocity": [1, 0, 0]}]),
     r"steps\[60\]\.others\[0\]\.id", "was destroyed at step 50: it takes no input after"),
])
def test_a_stick_to_at_no_object_and_an_input_to_a_destroyed_mover_are_refused(edit, where, problem):
    doc = json.loads(_follow_with(stick_at=3, destroy_at=50).dumps())
    edit(doc)
    with pytest.raises(InvalidScene, match=where + ".*" + problem):
        Scene.from_json(doc)


def test_the_mover_itself_is_a_target_and_a_tableless_mover_may_be_sent_after_another_mover():
    """A client's attack at its own guid (stick_to) or the server's MoveTo/turn at the mover's id: set_object_guid
    filed the mover too. MoveToObject and TurnToObject at another mover make their own MovementManager, so they
    need no motion table; a MoveTo to a point still does, and a static scene's mover id is still no target."""
    from dataclasses import replace

    from acconform.motion_scene import MovementParams, ObjectMoveInput
    from acconform.staging import MOVER_ID

    scene = _follow_with(stick_at=3)
    steps = list(scene.ticks.steps)
    steps[5] = replace(steps[5], stick_to=MOVER_ID, turn_to_object=ObjectMoveInput(MOVER_ID, MovementParams()))
    own = scene.replace(ticks=replace(scene.ticks, steps=tuple(steps)))
    assert Scene.loads(own.dumps()) == own and "objects.targets" in scene_features(own)
    tableless = own.replace(mover=replace(own.mover, motion_table=None))
    assert Scene.loads(tableless.dumps()) == tableless
    doc = json.loads(tableless.dumps())
    doc["ticks"]["steps"][6]["move_to"] = {"position": doc["mover"]["begin"]}
    with pytest.raises(InvalidScene, match=r"steps\[6\]\.move_to.*needs the mover's motion_table"):
        Scene.from_json(doc)
    doc = _doc("sticky_move_to_a_static")
    doc["ticks"]["steps"][0]["move_to_object"]["object"] = f"0x{MOVER_ID:08X}"
    with pytest.raises(InvalidScene, match=r"steps\[0\]\.move_to_object\.object"):
        Scene.from_json(doc)


def test_the_port_stops_stepping_a_destroyed_target_and_the_follower_lets_go_of_it():
    from acconform.port.run import run_scene

    ticks = run_scene(_follow_with(destroy_at=20)).ticks
    assert not any(t.error for t in ticks)
    assert ticks[20].others[0].origin == ticks[-1].others[0].origin  # destroyed: no landblock steps it
    follow = run_scene(SCENES["sticky_follow_of_a_moving_target"]).ticks
    assert ticks[-1].origin != follow[-1].origin  # the MoveTo lost its target (ObjectGone) and stopped short
