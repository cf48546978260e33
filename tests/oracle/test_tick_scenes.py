"""Tick scenes through ACE (issue 19): the example tick scenes' answers from live ACE, recorded on both
runtimes, what each shows, and the facade's tick driver asked live.

data/ace_tick_outcomes.json holds live ACE's outcomes (ACE 7b47913 on mono and on .NET 10 through the
live oracle) for the tick scenes in examples/ (every ``tick_*.json``). The fast lane reads them back and
checks what each scene is built to show (ACE's answers, never computed here); the live lane
(`live_oracle`) asks the configured ACE again and requires the same answer bit for bit. Record anew with

    ACE_ASSEMBLY=/path/to/ACE.Server.dll python tests/oracle/test_tick_scenes.py --record

once with a mono build and once with a .NET 10 build (each is recorded under its runtime).
"""

from __future__ import annotations

import dataclasses
import json
import sys
from pathlib import Path

import pytest

from acconform.case import load_document
from acconform.compare import compare
from acconform.flags import TransientState
from acconform.outcome import FORMAT_V4, Outcome
from acconform.scene import Frame, Position, Scene, TickStep

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from oracle.live_answers import record_outcomes, recorded_outcomes  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
DATA = Path(__file__).resolve().parent / "data" / "ace_tick_outcomes.json"
RUNTIMES = ("mono", "coreclr")
SCENES: dict[str, Scene] = {p.stem: load_document(p) for p in sorted((ROOT / "examples").glob("tick_*.json"))}
ON_GROUND = TransientState.Contact | TransientState.OnWalkable


def recorded(runtime: str) -> dict[str, Outcome]:
    return recorded_outcomes(DATA, runtime)


# ---------------------------------------------------------------- the recorded answers


@pytest.mark.parametrize("runtime", RUNTIMES)
def test_every_example_tick_scene_has_ace_answers_on_each_runtime_one_tick_state_per_step(runtime):
    answers = recorded(runtime)
    assert set(answers) == set(SCENES)
    raw = json.loads(DATA.read_text())["outcomes"][runtime]
    for name, scene in SCENES.items():
        assert raw[name]["format"] == FORMAT_V4 and answers[name].error is None, name  # no motion table: outcome/4
        assert len(answers[name].ticks) == len(scene.ticks.steps) and not any(t.error for t in answers[name].ticks), name


def test_both_runtimes_answer_the_example_tick_scenes_alike():
    mono, coreclr = recorded("mono"), recorded("coreclr")
    assert {name: compare(mono[name], coreclr[name]) for name in SCENES} == {name: [] for name in SCENES}


def test_ace_lands_the_fall_on_the_terrain_and_stops_it():
    ticks = recorded("mono")["tick_fall"].ticks
    # the velocity input moves it; gravity comes with the first SetPositionInternal (calc_acceleration)
    assert ticks[0].velocity == (0.0, 0.0, -0.5) and ticks[0].acceleration[2] < 0.0 and ticks[1].velocity[2] < -0.5
    landed = next(i for i, t in enumerate(ticks) if t.transient_state & ON_GROUND == ON_GROUND)
    assert 10 < landed < len(ticks) - 1
    assert ticks[-1].origin[2] == 20.0 and ticks[-1].velocity == (0.0, 0.0, 0.0) and ticks[-1].acceleration == (0.0, 0.0, 0.0)
    assert not ticks[-1].transient_state & TransientState.Active  # at rest: handle_all_collisions made it inactive


def test_ace_does_not_update_a_tick_shorter_than_tick_rate_and_keeps_its_time_for_the_next():
    """dt = 1/30 in double is less than TickRate (1/30 in float32): update_object returns false and leaves
    UpdateTime, so the next tick runs the two together."""
    scene, answer = SCENES["tick_walk"], recorded("mono")["tick_walk"]
    times = scene.ticks.times()
    assert [t.updated for t in answer.ticks[:4]] == [False, True, False, True]
    assert answer.ticks[0].update_time == scene.ticks.start and answer.ticks[1].update_time == times[1]


def test_ace_walks_the_mover_by_the_sequences_velocity_as_root_motion():
    ticks = recorded("mono")["tick_walk"].ticks
    moved = [t for t in ticks if t.updated]
    assert moved[0].origin[1] > 12.0 and moved[-1].origin[1] > moved[0].origin[1]
    assert all(t.velocity == (0.0, 0.0, 0.0) for t in ticks)  # root motion moves the frame, not the velocity
    assert moved[0].cached_velocity[1] > 0.0


def test_ace_jumps_the_mover_in_an_arc_and_lands_it():
    ticks = recorded("mono")["tick_jump"].ticks
    top = max(range(len(ticks)), key=lambda i: ticks[i].origin[2])
    assert 0 < top < len(ticks) - 1 and ticks[top].origin[2] > 21.0
    assert not ticks[0].transient_state & TransientState.Contact and ticks[0].velocity[2] > 5.0
    assert any(t.transient_state & ON_GROUND == ON_GROUND for t in ticks[top:])


def test_ace_skips_a_tick_over_huge_quantum_and_splits_a_long_one_into_max_quanta_and_a_remainder():
    scene, ticks = SCENES["tick_clock"], recorded("mono")["tick_clock"].ticks
    times = scene.ticks.times()
    assert scene.ticks.steps[3].dt == 2.5 and not ticks[3].updated and ticks[3].update_time == times[3]
    assert ticks[3].origin == ticks[2].origin  # the skipped time is consumed, nothing moved
    # 0.35 s: three MaxQuanta (0.1f) and the remainder, each over MinQuantum, consume it all
    assert ticks[4].updated and ticks[4].update_time == times[4] and ticks[4].origin[2] < ticks[3].origin[2] - 0.5


def test_ace_moves_the_mover_to_each_request_pos_and_keeps_no_cached_velocity():
    scene, ticks = SCENES["tick_request_pos"], recorded("mono")["tick_request_pos"].ticks
    for step, t in zip(scene.ticks.steps, ticks):
        assert t.updated and t.cell == step.request_pos.cell and t.origin == step.request_pos.frame.origin
        assert t.cached_velocity == (0.0, 0.0, 0.0)  # set_current_pos: requestCachedVelocity (set_request_pos not run)


# ---------------------------------------------------------------- hand-written scenes, the port against ACE

HANDWRITTEN = Path(__file__).resolve().parent / "data" / "ace_tick_handwritten.json"


def _handwritten():
    doc = json.loads(HANDWRITTEN.read_text())
    return {name: Scene.from_json(s) for name, s in doc["scenes"].items()}, doc["outcomes"]


@pytest.mark.anchor("CPhysicsObj::update_object")
@pytest.mark.parametrize("runtime", RUNTIMES)
def test_the_port_matches_ace_every_tick_on_the_hand_written_tick_scenes(runtime):
    """A fall onto a slope steeper than FloorZ, a turning root-motion walk up a slope, a jump arc on a
    slope, sledding, a diagonal crossing of four landblocks, RequestPos across a cell border, a fall at
    MaxVelocity and a walk on an irregular clock: ACE's answers on each runtime (ACE's own orientation
    bits differ between the runtimes in two of them), the port bit for bit."""
    from acconform.port.run import run_scene

    scenes, outcomes = _handwritten()
    assert len(scenes) == 8 and set(outcomes[runtime]) == set(scenes)
    for name, scene in scenes.items():
        ace = Outcome.from_json(outcomes[runtime][name])
        assert len(ace.ticks) == len(scene.ticks.steps) and not any(t.error for t in ace.ticks), name
        assert compare(run_scene(scene, runtime=runtime), ace, "exact") == [], name


# ---------------------------------------------------------------- the facade's members


def test_every_physics_obj_member_the_facades_tick_code_touches_is_in_members_py():
    import re

    from acconform.oracle.members import REQUIRED

    source = (ROOT / "oracle" / "facade" / "Facade.cs").read_text()
    ticks = source[source.index("// ------------------------------------------------------------------ ticks"):
                   source.index("// ------------------------------------------------------------------ content keys")]
    touched = set(re.findall(r"\bobj\.(\w+)", ticks))
    listed = {m for t, members in REQUIRED if t == "ACE.Server.Physics.PhysicsObj" for m in members}
    assert touched >= {"update_object", "set_request_pos", "update_object_server", "IsMovingOrAnimating"}
    assert touched - listed == set()


def test_an_ace_build_without_the_tick_members_is_refused_naming_them():
    from acconform.errors import OracleUnavailable
    from acconform.oracle.members import REQUIRED, check_members

    types: dict[str, set] = {}
    for t, members in REQUIRED:  # a type may be listed more than once
        types.setdefault(t, set()).update(members)
    del types["ACE.Server.Entity.Timers"]
    types["ACE.Server.Physics.Animation.Sequence"] -= {"SetVelocity"}
    with pytest.raises(OracleUnavailable) as e:
        check_members(types.get, lambda t, m: m in t, "/opt/ace")
    assert "type ACE.Server.Entity.Timers" in str(e.value) and "Sequence.SetVelocity" in str(e.value)


# ---------------------------------------------------------------- live


@pytest.mark.live_oracle
@pytest.mark.parametrize("name", sorted(SCENES))
def test_live_ace_answers_each_example_tick_scene_as_recorded(live, name):
    assert compare(live.run(SCENES[name]), recorded(live.location.runtime)[name], "exact") == [], name


@pytest.mark.live_oracle
def test_live_tick_scenes_run_on_the_scenes_clock_and_leave_no_mover_behind(live):
    """The clock is scene data (Timers.PortalYearTicks set from the scene, never the wall clock), and the
    mover leaves the cells it entered: the same answers again, in another order, after other scenes, and
    with the landblock cache off; a later start moves every update_time by the same amount."""
    names = sorted(SCENES)
    first = {name: live.run(SCENES[name]) for name in names}
    assert all(live.run(SCENES[name]) == first[name] for name in reversed(names))
    live.set_landblock_cache(False)
    try:
        assert all(live.run(SCENES[name]) == first[name] for name in names)
    finally:
        live.set_landblock_cache(True)
    fall = SCENES["tick_fall"]
    later = live.run(fall.replace(ticks=dataclasses.replace(fall.ticks, start=fall.ticks.start + 1024.0)))
    assert [t.update_time - 1024.0 for t in later.ticks] == [t.update_time for t in first["tick_fall"].ticks]
    assert [t.origin for t in later.ticks] == [t.origin for t in first["tick_fall"].ticks]


@pytest.mark.live_oracle
def test_live_an_exception_in_a_tick_is_that_ticks_error_and_ends_the_scene(live):
    """A RequestPos in a landblock the scene does not hold: Player.UpdatePlayerPosition's LScape.get_landcell
    loads it through LandblockManager, whose server Landblock reads it from ACE's DAT, which lacks it: an empty
    CellLandblock, whose LandblockStruct throws ArgumentOutOfRangeException reading Height[0]. That tick's
    error ends the scene (docs/oracle.md, the world's edge row)."""
    out = live.run(off_the_world(SCENES["tick_request_pos"]))
    assert out.error is None and [t.error is None for t in out.ticks] == [True, True, True, True, False], out.ticks
    assert out.ticks[4].error.startswith("ArgumentOutOfRangeException"), out.ticks[4].error
    assert out.ticks[4] == dataclasses.replace(out.ticks[4].__class__(), error=out.ticks[4].error)


def off_the_world(scene):
    """The example request_pos scene, its fifth step a RequestPos in landblock AAB4, which the scene lacks."""
    up = Position(0xA9B40001, Frame((12.0, 12.0, 30.0)))
    beyond = Position(0xAAB40001, Frame((2.0, 12.0, 20.0)))
    steps = scene.ticks.steps[:3] + (TickStep(0.1, request_pos=up), TickStep(0.1, request_pos=beyond),
                                     TickStep(0.1, request_pos=up))
    return scene.replace(ticks=dataclasses.replace(scene.ticks, steps=steps))


# ---------------------------------------------------------------- recording


if __name__ == "__main__":
    if sys.argv[1:] != ["--record"]:
        sys.exit(__doc__)
    record_outcomes(SCENES, DATA, "tick")
