"""Several movers (issue 41; scene/8 `others`, feature objects.moving, outcome/6). The scene fields and their
refusals, the pack bytes, the outcome's form and the comparator's paths (fast lane); each named scene of
tests/oracle/mover_scenes.py answered by the port as ACE answered it on both runtimes (recorded: fast lane) and
by live ACE again (live lane)."""

from __future__ import annotations

import json
import struct
import sys
from dataclasses import replace
from pathlib import Path

import pytest

from acconform.compare import compare
from acconform.errors import InvalidScene
from acconform.outcome import FORMAT as OUTCOME_FORMAT, FORMAT_V5 as OUTCOME_FORMAT_V5, CollisionState, Outcome
from acconform.oracle.pack import PACK_VERSION, pack_scene, unpack_outcome
from acconform.protocol import dat_from_json, dat_json, scene_features
from acconform.dat import dat_world
from acconform.scene import FORMAT, FORMAT_V7, Scene

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from oracle.live_answers import recorded_outcomes  # noqa: E402
from oracle.mover_scenes import DATA, MONSTER, PLAYER_2, scenes  # noqa: E402

SCENES = scenes()
HEAD_ON = "collide_with_a_moving_object"


def _doc(name: str = HEAD_ON) -> dict:
    return json.loads(SCENES[name].dumps())


@pytest.mark.parametrize("name", sorted(SCENES))
def test_each_mover_scene_reads_back_as_the_same_scene_in_format_8_and_needs_objects_moving(name):
    scene = SCENES[name]
    assert Scene.loads(scene.dumps()) == scene
    assert scene.format == FORMAT == "acconform.scene/8" and "objects.moving" in scene_features(scene)


def test_a_scene_without_other_movers_keeps_its_older_format():
    scene = SCENES[HEAD_ON]
    plain = scene.replace(others=(), ticks=replace(scene.ticks, steps=tuple(replace(s, others=()) for s in scene.ticks.steps)))
    assert plain.format != FORMAT and "objects.moving" not in scene_features(plain)


@pytest.mark.parametrize("edit, where, problem", [
    (lambda d: d["others"][0].__setitem__("id", "0x50000001"), r"others\[0\]\.id", "dynamic range"),
    (lambda d: d["others"][0].__setitem__("weenie", "dragon"), r"others\[0\]\.weenie", "unknown weenie 'dragon'"),
    (lambda d: d["others"][0].__setitem__("weenie", "player"), r"others\[0\]\.id", "player's id is in ACE's player range"),
    (lambda d: d["others"][0].__setitem__("weenie", "object") or d["others"][0].__setitem__("player_killer_status", "PK"),
     r"others\[0\]\.player_killer_status", "only from a Creature"),
    (lambda d: d["others"].append(dict(d["others"][0])), r"others\[1\]\.id", "already others\\[0\\]'s"),
    (lambda d: d["others"][0]["begin"].__setitem__("cell", "0x12340001"), r"others\[0\]\.begin\.cell", "not defined"),
    (lambda d: d["ticks"]["steps"][3]["others"][0].__setitem__("id", "0x80000009"), r"steps\[3\]\.others\[0\]\.id",
     "no other mover has id 0x80000009"),
    (lambda d: d["ticks"]["steps"][3]["others"].append(dict(d["ticks"]["steps"][3]["others"][0])),
     r"steps\[3\]\.others\[1\]\.id", "inputs twice in one step"),
    (lambda d: d["ticks"]["steps"][3]["others"][0].__setitem__("jump", [0, 0, 5]), r"steps\[3\]\.others\[0\]\.jump",
     "a jump is a player's"),
    (lambda d: d["ticks"]["steps"][3]["others"][0].__setitem__("motion", {}), r"steps\[3\]\.others\[0\]",
     "unknown field .motion."),
])
def test_a_bad_other_mover_is_refused_naming_the_field(edit, where, problem):
    doc = _doc()
    edit(doc)
    with pytest.raises(InvalidScene, match=where + ".*" + problem):
        Scene.from_json(doc)


def test_other_movers_need_format_8():
    doc = _doc()
    doc["format"] = FORMAT_V7
    with pytest.raises(InvalidScene, match=r"others.*need format 'acconform.scene/8'"):
        Scene.from_json(doc)


def test_an_other_movers_record_and_inputs_pack_after_the_movers():
    assert PACK_VERSION == 18
    scene = SCENES[HEAD_ON]
    data = pack_scene(scene)
    o = scene.others[0]
    # the other's record: Setup id, id, weenie class 2 (monster), NPK, scale, State, TransientState, velocity, begin
    record = struct.pack("<IIBIfII3f", 0x02F00000, MONSTER, 2, 2, 1.0, o.state, o.transient_state, 0.0, 0.0, 0.0)
    assert record in data
    # each step: the mover's velocity, then one other's inputs: index 0, mask velocity (bit 2), the velocity
    step = struct.pack("<I3f", 4, 0.0, 3.0, 0.0) + struct.pack("<iiI3f", 1, 0, 4, 0.0, -3.0, 0.0)
    assert data.count(step) == len(scene.ticks.steps)


def test_an_outcome_with_other_movers_is_format_6_and_reads_back():
    outcome = recorded_outcomes(DATA, "mono")[HEAD_ON]
    doc = outcome.to_json()
    assert doc["format"] == OUTCOME_FORMAT == "acconform.outcome/6"
    assert Outcome.from_json(json.loads(json.dumps(doc))) == outcome
    assert doc["ticks"][-1]["others"][0]["id"] == "0x80000001" and "collisions" in doc["ticks"][-1]
    doc["format"] = OUTCOME_FORMAT_V5
    with pytest.raises(InvalidScene, match="other_placements"):
        Outcome.from_json(doc)


def test_the_comparator_names_the_tick_the_other_mover_and_the_field():
    outcome = recorded_outcomes(DATA, "mono")[HEAD_ON]
    last = outcome.ticks[-1]
    moved = replace(last.others[0], origin=(60.0, 62.5, 20.0))
    other = replace(outcome, ticks=outcome.ticks[:-1] + (replace(last, others=(moved,)),))
    assert [d.field for d in compare(other, outcome)] == [f"ticks[{len(outcome.ticks) - 1}].others[0x80000001].origin[1]"]
    touched = replace(last, collisions=(CollisionState(MONSTER, 0.5, False),))
    table = replace(outcome, ticks=outcome.ticks[:-1] + (touched,))
    assert [d.field for d in compare(table, outcome)] == [f"ticks[{len(outcome.ticks) - 1}].collisions[0].touched_time"]


def test_the_dat_form_carries_the_other_movers_and_reads_back():
    world = dat_world(SCENES["a_monster_and_a_player_meet_the_player"])
    doc = json.loads(json.dumps(dat_json(world)))
    assert [o["weenie"] for o in doc["others"]] == ["monster", "player"] and doc["others"][1]["player_killer_status"] == "PK"
    assert dat_from_json(doc) == world


@pytest.mark.parametrize("runtime", ["mono", "coreclr"])
def test_the_port_answers_each_mover_scene_as_ace_did_every_tick(runtime):
    from acconform.port.run import run_scene

    ace = recorded_outcomes(DATA, runtime)
    for name, scene in SCENES.items():
        assert compare(run_scene(scene, runtime=runtime), ace[name], "exact") == [], name


def test_ace_stops_a_player_and_a_monster_walking_into_each_other_each_with_the_other_in_its_table():
    last = recorded_outcomes(DATA, "mono")[HEAD_ON].ticks[-1]
    assert last.origin[1] < last.others[0].origin[1]  # they met and stopped, the player short of the monster
    assert [c.id for c in last.collisions] == [MONSTER] and [c.id for c in last.others[0].collisions] == [0x50000001]


def test_ace_lets_npk_players_pass_through_each_other_and_stops_pk_players():
    ace = recorded_outcomes(DATA, "mono")
    passed = ace["two_players_run_through_each_other"].ticks[-1]
    stopped = ace["pk_players_run_into_each_other"].ticks[-1]
    mixed = ace["pk_and_npk_players_pass_through_each_other"].ticks[-1]
    assert passed.origin[1] > passed.others[0].origin[1] and not passed.collisions
    assert mixed.origin[1] > mixed.others[0].origin[1]
    assert stopped.origin[1] < stopped.others[0].origin[1] and [c.id for c in stopped.collisions] == [PLAYER_2]


@pytest.mark.live_oracle
@pytest.mark.parametrize("name", sorted(SCENES))
def test_live_ace_answers_each_mover_scene_as_recorded_and_as_the_port(live, name):
    from acconform.port.run import run_scene

    ace = live.run(SCENES[name])
    assert compare(ace, recorded_outcomes(DATA, live.location.runtime)[name], "exact") == [], name
    assert compare(run_scene(SCENES[name], runtime=live.location.runtime), ace, "exact") == [], name
