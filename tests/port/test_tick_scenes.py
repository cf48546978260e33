"""The port's tick (port/physics_obj.py update_object and the legacy RequestPos path, driven by
port/run.py's run_ticks) against ACE's recorded answers for the example tick scenes
(examples/tick_*.json; tests/oracle/data/ace_tick_outcomes.json, from ACE on mono and on .NET 10),
every tick, bit for bit, under each runtime's arithmetic; and every tick branch the port counts as
reached by them (branches.REACHED_BY_TICK_SCENES) really reached by one.
"""

from __future__ import annotations

import json
from collections import Counter
from pathlib import Path

import pytest

from acconform.case import load_document
from acconform.compare import compare
from acconform.outcome import Outcome
from acconform.port.run import run_scene
from acconform.port.transition.branches import BRANCHES, NOT_YET_REACHED, REACHED_BY_TICK_SCENES

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "tests" / "oracle" / "data" / "ace_tick_outcomes.json"
SCENES = {p.stem: load_document(p) for p in sorted((ROOT / "examples").glob("tick_*.json"))}
RUNTIMES = ("mono", "coreclr")


def ace(runtime: str, name: str) -> Outcome:
    return Outcome.from_json(json.loads(DATA.read_text())["outcomes"][runtime][name])


@pytest.mark.anchor("CPhysicsObj::update_object")
@pytest.mark.parametrize("runtime", RUNTIMES)
@pytest.mark.parametrize("name", sorted(SCENES))
def test_the_port_matches_ace_on_every_tick_of_the_example_tick_scene(name, runtime):
    got = run_scene(SCENES[name], runtime=runtime)
    assert got.ticks is not None and len(got.ticks) == len(SCENES[name].ticks.steps)
    assert compare(got, ace(runtime, name), "exact") == []


@pytest.mark.anchor("CPhysicsObj::update_object")
@pytest.mark.parametrize("branch", sorted(REACHED_BY_TICK_SCENES))
def test_tick_branch_is_reached_by_an_example_tick_scene(branch):
    reached = []
    for name, scene in SCENES.items():
        trace = Counter()
        run_scene(scene, trace=trace)
        if trace[branch]:
            reached.append(name)
    assert reached, f"no example tick scene reaches {branch}"


def test_the_tick_branch_registries_are_documented_branches_and_disjoint():
    assert set(REACHED_BY_TICK_SCENES) <= set(BRANCHES)
    assert not set(REACHED_BY_TICK_SCENES) & set(NOT_YET_REACHED)


@pytest.mark.anchor("CPhysicsObj::update_object")
def test_a_scene_without_ticks_has_no_tick_states():
    scene = next(iter(SCENES.values()))
    import dataclasses

    from acconform.scene import Mover

    plain = dataclasses.replace(scene, ticks=None, mover=dataclasses.replace(scene.mover, end=scene.mover.begin))
    assert isinstance(plain.mover, Mover) and run_scene(plain).ticks is None


@pytest.mark.anchor("PhysicsObj.cs:enter_cell_server")
def test_a_request_pos_off_the_scenes_landblocks_throws_building_the_missing_one_and_ends_the_run():
    """The live lane's scene (tests/oracle/test_tick_scenes.py::test_live_an_exception_in_a_tick_is_that_ticks_error_and_ends_the_scene):
    the landblock ACE reads from its DAT is an empty CellLandblock, whose construction throws
    ArgumentOutOfRangeException in that tick, and the scene ends there."""
    import dataclasses

    from tests.oracle.test_tick_scenes import off_the_world

    out = run_scene(off_the_world(SCENES["tick_request_pos"]))
    assert out.error is None and [t.error is None for t in out.ticks] == [True, True, True, True, False], out.ticks
    assert out.ticks[4].error.startswith("ArgumentOutOfRangeException"), out.ticks[4].error
    assert out.ticks[4] == dataclasses.replace(out.ticks[4].__class__(), error=out.ticks[4].error)
