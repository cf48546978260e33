"""The port against ACE's recorded answers on the named indoor scenes (indoor_rooms.SCENES), bit for
bit, and against live ACE when one is configured.

data/ace_indoor_outcomes.json holds real ACE's outcomes (ACE 7b47913 on mono, live oracle;
record_indoor_outcomes.py rewrites it).
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from acconform.compare import compare
from acconform.outcome import Outcome
from acconform.port.run import run_scene
from acconform.port.transition.branches import (BRANCHES, NOT_YET_REACHED, REACHED_BY_INDOOR_SCENES,
                                                REACHED_BY_OBJECT_SCENES, Trace)
from indoor_rooms import SCENES

RECORDED = json.loads((Path(__file__).parent / "data" / "ace_indoor_outcomes.json").read_text())["outcomes"]

# the indoor branches each named scene must fire (so a scene that stops reaching its branch fails)
FIRES = {
    "across-portal": {"env_cell:physics_bsp", "env_cell:other_cell", "find_cell_list:indoor"},
    "tall-ledge-edge-slide": {"edge_slide:back_probe_precipice_slide"},
    "outside-portal": {"env_cell:outside_portal"},
    "unloaded-neighbour": {"env_cell:unloaded_cell"},
}


@pytest.mark.anchor("CEnvCell::find_collisions")
def test_every_named_indoor_scene_has_a_recorded_ace_answer():
    assert set(SCENES) == set(RECORDED)


@pytest.mark.anchor("CEnvCell::find_collisions")
@pytest.mark.parametrize("name", sorted(SCENES))
def test_named_indoor_scene_matches_ace_bit_for_bit(name):
    trace = Trace()
    out = run_scene(SCENES[name][0], trace=trace)
    assert compare(out, Outcome.from_json(RECORDED[name]), "exact") == []
    assert FIRES.get(name, set()) <= set(trace)


@pytest.mark.live_oracle
@pytest.mark.anchor("CEnvCell::find_collisions")
@pytest.mark.parametrize("name", sorted(SCENES))
def test_named_indoor_scene_matches_live_ace(live, name):
    scene = SCENES[name][0]
    assert compare(run_scene(scene), live.run(scene), "exact") == []


@pytest.mark.anchor("CEnvCell::find_transit_cells")
def test_indoor_branch_list_is_documented_and_disjoint_from_the_others():
    assert set(REACHED_BY_INDOOR_SCENES) <= set(BRANCHES)
    assert not set(REACHED_BY_INDOOR_SCENES) & (set(NOT_YET_REACHED) | set(REACHED_BY_OBJECT_SCENES))


@pytest.mark.anchor("CEnvCell::find_transit_cells")
@pytest.mark.parametrize("branch", sorted(REACHED_BY_INDOOR_SCENES))
def test_branch_is_reached_by_a_named_indoor_scene_where_the_port_matches_ace(branch):
    names = []
    for name, (scene, _) in sorted(SCENES.items()):
        trace = Trace()
        out = run_scene(scene, trace=trace)
        if trace[branch]:
            assert compare(out, Outcome.from_json(RECORDED[name]), "exact") == [], name
            names.append(name)
    assert names, f"no named indoor scene reaches {branch}"
