"""The motion layer in scenes (issue 40): the mover's motion table and MoveToState inputs, ACE's answers
recorded on both runtimes (tests/oracle/motion_scenes.py says how), the port checked against them every
push, and live ACE asked again in the live lane.

The answers were recorded on ACE builds whose mover's Player answers what the physics asks of it when a
motion table is made: ACE's own full build (.NET 10, real Player) and a mono physics build whose
stand-in Creature.GetCreatureSkill gives a skill of Current 0 and whose HandleMotionDone / OnMoveComplete
have empty bodies, as the database-free Player's are in ACE (docs/oracle.md's audit rows "the mover's
motion table" and "the physics builds' stand-ins for the motion layer").
"""

from __future__ import annotations

import dataclasses
import json
import sys
from pathlib import Path

import numpy as np
import pytest

from acconform.compare import compare
from acconform.errors import InvalidScene
from acconform.motion_enums import MotionCommand as MC
from acconform.scene import Scene

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from oracle.live_answers import recorded_outcomes  # noqa: E402
from oracle.motion_scenes import DATA, scenes  # noqa: E402

RUNTIMES = ("mono", "coreclr")
SCENES = scenes()
WALK = "player_walks_turns_and_stops"


def test_a_motion_scene_is_format_6_and_reads_back_as_the_same_scene():
    scene = SCENES[WALK]
    assert scene.format == "acconform.scene/6" and scene.has_motion
    assert Scene.loads(scene.dumps()) == scene


def test_a_motion_table_in_an_older_format_is_refused_naming_the_field():
    doc = json.loads(SCENES[WALK].dumps())
    doc["format"] = "acconform.scene/5"
    for step in doc["ticks"]["steps"]:
        step.pop("motion", None)
    with pytest.raises(InvalidScene, match=r"mover\.motion_table.*needs format 'acconform.scene/6'"):
        Scene.from_json(doc)


def test_a_mover_without_a_motion_table_takes_keys_and_stops_but_not_the_move_to_managers_cancel():
    doc = json.loads(SCENES[WALK].dumps())
    del doc["mover"]["motion_table"]
    doc["ticks"]["steps"][1]["do_motion"] = {"motion": "TurnLeft"}
    doc["ticks"]["steps"][1]["stop"] = "stop_completely"
    scene = Scene.from_json(doc)  # get_minterp makes its MovementManager; DoMotion answers NoAnimationTable before
    assert scene.mover.motion_table is None and scene.has_motion
    doc["ticks"]["steps"][1]["stop"] = "move_to_manager_cancel"
    with pytest.raises(InvalidScene, match=r"ticks\.steps\[1\]\.stop.*needs the mover's motion_table"):
        Scene.from_json(doc)


def test_an_unknown_motion_command_and_an_animation_out_of_range_are_refused_naming_the_field():
    doc = json.loads(SCENES[WALK].dumps())
    doc["ticks"]["steps"][0]["motion"]["forward"] = "Sprint"
    with pytest.raises(InvalidScene, match=r"steps\[0\]\.motion\.forward.*unknown motion command 'Sprint'"):
        Scene.from_json(doc)
    doc = json.loads(SCENES[WALK].dumps())
    doc["mover"]["motion_table"]["cycles"][0]["anims"][0]["animation"] = 99
    with pytest.raises(InvalidScene, match=r"motion_table\.cycles\[0\]\.anims\[0\]\.animation"):
        Scene.from_json(doc)


@pytest.mark.parametrize("runtime", RUNTIMES)
def test_the_port_walks_turns_and_stops_the_player_as_ace_does_every_tick(runtime):
    from acconform.port.run import run_scene

    ace = recorded_outcomes(DATA, runtime)
    for name, scene in SCENES.items():
        assert ace[name].error is None and len(ace[name].ticks) == len(scene.ticks.steps), name
        assert compare(run_scene(scene, runtime=runtime), ace[name], "exact") == [], name


def test_ace_moves_the_walking_player_forward_then_turns_it_and_stops_it():
    ticks = recorded_outcomes(DATA, "mono")[WALK].ticks
    walked, turned, stopped = ticks[11], ticks[23], ticks[35]
    assert walked.origin[1] > ticks[0].origin[1] + 1.0  # root motion and the cycle's velocity carry it forward
    assert turned.orientation != walked.orientation  # the TurnRight modifier's omega turns it
    assert stopped.origin == ticks[25].origin  # released: it stands where it stopped


def test_the_runtimes_differ_only_in_the_turns_last_bits_and_the_port_follows_each():
    """mono and CoreCLR round the turn's quaternion differently (the runtimes' float math, docs/runtimes.md);
    positions agree. The port, run as each runtime, matches each (the test above)."""
    mono, coreclr = recorded_outcomes(DATA, "mono"), recorded_outcomes(DATA, "coreclr")
    fields = {d.field.split(".")[1].split("[")[0] for d in compare(mono[WALK], coreclr[WALK])}
    assert fields == {"orientation"}


@pytest.mark.parametrize("runtime", RUNTIMES)
def test_aces_ticks_carry_the_motion_layer_walking_turning_and_standing(runtime):
    """Each tick of the motion scene carries its motion layer (outcome/5): the MoveToState's keys as the
    interpreted and raw states, the cycle playing, the velocity and turn the Sequence asks for, no MoveTo."""
    ticks = recorded_outcomes(DATA, runtime)[WALK].ticks
    assert all(t.motion is not None and t.motion.interpreted is not None for t in ticks)
    walked, turned, stopped = ticks[11].motion, ticks[23].motion, ticks[35].motion
    assert walked.interpreted.forward_command == walked.raw.forward_command == int(MC.WalkForward)
    assert walked.sequence_velocity[1] > 0.0 and walked.animation is not None
    assert turned.interpreted.turn_command == int(MC.TurnRight) and turned.sequence_omega[2] != 0.0
    assert stopped.interpreted.forward_command == int(MC.Ready) and stopped.sequence_velocity == (0.0, 0.0, 0.0)
    assert {t.motion.movement_type for t in ticks} == {0} and not any(t.motion.is_moving_to for t in ticks)
    assert len({t.motion.frame_number for t in ticks}) > 3  # the frame advances through the cycles


def test_a_tick_scene_without_a_motion_table_answers_no_motion_layer_as_outcome_4():
    from acconform.port.run import run_scene

    plain = dataclasses.replace(SCENES[WALK], mover=dataclasses.replace(SCENES[WALK].mover, motion_table=None),
                                ticks=dataclasses.replace(SCENES[WALK].ticks, steps=tuple(
                                    dataclasses.replace(s, motion=None) for s in SCENES[WALK].ticks.steps)))
    out = run_scene(plain, runtime="mono")
    assert out.to_json()["format"] == "acconform.outcome/4" and all(t.motion is None for t in out.ticks)


def drawn_motion_records(runtime: str, n: int = 4) -> list:
    """The first `n` records of the recorded motion shard (ticks-0030: drawn motion tick scenes) on `runtime`."""
    import gzip

    from acconform.case import Record

    shard = Path(__file__).resolve().parents[1] / "data" / "corpus" / runtime / "ticks-0030.jsonl.gz"
    with gzip.open(shard, "rt") as f:
        return [Record.from_json(json.loads(line)) for line, _ in zip(f, range(n))]


@pytest.mark.live_oracle
@pytest.mark.parametrize("name", sorted(SCENES))
def test_live_ace_answers_each_motion_scene_as_recorded(live, name):
    assert compare(live.run(SCENES[name]), recorded_outcomes(DATA, live.location.runtime)[name], "exact") == [], name


@pytest.mark.live_oracle
def test_live_ace_and_the_port_agree_bit_for_bit_on_drawn_motion_scenes_motion_layers_included(live):
    from acconform.port.run import run_scene

    runtime = live.location.runtime
    for record in drawn_motion_records(runtime):
        ace = live.run(record.scene)
        assert ace.ticks and all(t.motion is not None for t in ace.ticks if t.error is None), record.scene.name
        assert compare(run_scene(record.scene, runtime=runtime), ace, "exact") == [], record.scene.name
        assert compare(ace, record.outcome, "exact") == [], record.scene.name  # the shard holds this answer


def test_a_movers_player_killer_status_reads_back_and_an_unknown_one_is_refused_naming_the_field():
    scene = SCENES["pk_player_jumps_while_running"]
    doc = json.loads(scene.dumps())
    assert doc["mover"]["player_killer_status"] == "PK" and Scene.from_json(doc) == scene
    doc["mover"]["player_killer_status"] = "Pk"
    with pytest.raises(InvalidScene, match=r"mover\.player_killer_status: unknown PlayerKillerStatus 'Pk'"):
        Scene.from_json(doc)
    assert "player_killer_status" not in json.loads(SCENES[WALK].dumps())["mover"]  # NPK, ACE's default, is not written


RUN300 = "run_with_run_skill_300"
SKILLED_JUMP = "skilled_player_jumps_while_running"


def test_a_movers_skills_read_back_and_only_the_fields_that_differ_from_the_database_free_players_are_written():
    from acconform.scene import FORMAT

    scene = SCENES[SKILLED_JUMP]
    doc = json.loads(scene.dumps())
    assert doc["format"] == FORMAT and Scene.from_json(doc) == scene
    assert doc["mover"]["skills"] == {"run": 300, "jump": 250, "stamina": 0, "strength": 100, "encumbrance_val": 20000,
                                      "augmentation_increased_carrying_capacity": 1}
    assert json.loads(SCENES[RUN300].dumps())["mover"]["skills"] == {"run": 300}
    assert "skills" not in json.loads(SCENES[WALK].dumps())["mover"]  # the database-free Player's are not written


@pytest.mark.parametrize("field, value, problem", [
    ("strength", 0, r"expected an integer in \[1, 16777216\], got 0"),
    ("run", 16777217, r"expected an integer in \[0, 16777216\]"),
    ("stamina", -1, r"expected an integer in \[0, 4294967295\]"),
    ("encumbrance_val", 2**31, r"expected an integer in \[-2147483648, 2147483647\]"),
    ("jump", 1.5, r"expected an integer, got"),
    ("sprint", 1, r"unknown field 'sprint'"),
])
def test_a_movers_skill_out_of_aces_range_is_refused_naming_the_field(field, value, problem):
    doc = json.loads(SCENES[RUN300].dumps())
    doc["mover"]["skills"][field] = value
    where = r"mover\.skills" + ("" if field == "sprint" else rf"\.{field}")
    with pytest.raises(InvalidScene, match=rf"{where}: {problem}"):
        Scene.from_json(doc)


def test_a_movers_skills_in_an_older_format_are_refused_naming_the_field():
    from acconform.scene import FORMAT

    doc = json.loads(SCENES[RUN300].dumps())
    doc["format"] = "acconform.scene/6"
    with pytest.raises(InvalidScene, match=rf"mover\.skills: skills need format '{FORMAT}'"):
        Scene.from_json(doc)


def test_the_ports_runner_runs_faster_with_a_run_skill_of_300_than_the_database_free_player():
    from acconform.port.run import run_scene
    from acconform.scene import DEFAULT_SKILLS

    scene = SCENES[RUN300]
    skilled = run_scene(scene, runtime="mono").ticks
    plain = run_scene(scene.replace(mover=dataclasses.replace(scene.mover, skills=DEFAULT_SKILLS)), runtime="mono").ticks
    assert skilled[0].motion.interpreted.forward_speed == np.float32(2.65)  # GetRunRate(0, 300, 1)
    assert plain[0].motion.interpreted.forward_speed == 1.0
    assert skilled[29].origin[1] - scene.mover.begin.frame.origin[1] > 2.5 * (plain[29].origin[1] - scene.mover.begin.frame.origin[1])


@pytest.mark.parametrize("runtime", RUNTIMES)
def test_ace_runs_the_player_with_a_run_skill_of_300_at_its_run_rate(runtime):
    ace = recorded_outcomes(DATA, runtime)
    assert ace[RUN300].ticks[0].motion.interpreted.forward_speed == np.float32(2.65)
    assert ace[SKILLED_JUMP].ticks[0].motion.interpreted.forward_speed == np.float32(2.65)


def test_a_table_with_hooks_no_root_motion_or_a_default_animation_is_format_8_and_refused_in_older_ones():
    from acconform.motion_scene import HookSpec

    table = SCENES[WALK].mover.motion_table
    for changed in (dataclasses.replace(table, default_animation=0),
                    dataclasses.replace(table, animations=(dataclasses.replace(table.animations[0], root_motion=False),)
                                        + table.animations[1:]),
                    dataclasses.replace(table, animations=(dataclasses.replace(
                        table.animations[0], hooks=(HookSpec(0, "AnimationDone", -1),)),) + table.animations[1:])):
        scene = SCENES[WALK].replace(mover=dataclasses.replace(SCENES[WALK].mover, motion_table=changed))
        assert scene.format == "acconform.scene/8" and Scene.loads(scene.dumps()) == scene
        doc = json.loads(scene.dumps())
        doc["format"] = "acconform.scene/6"
        with pytest.raises(InvalidScene, match=r"mover\.motion_table.*need format 'acconform.scene/8'"):
            Scene.from_json(doc)


def test_an_unknown_hook_is_refused_naming_it():
    doc = json.loads(SCENES[WALK].dumps())
    doc["format"] = "acconform.scene/8"
    doc["mover"]["motion_table"]["animations"][0]["hooks"] = [{"frame": 0, "hook": "Sound3D"}]
    with pytest.raises(InvalidScene, match=r"animations\[0\]\.hooks\[0\]\.hook.*unknown hook 'Sound3D'"):
        Scene.from_json(doc)
