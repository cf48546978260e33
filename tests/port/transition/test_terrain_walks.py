"""The port against ACE's recorded answers on the issue-5 terrain scenes, bit for bit.

data/ace_terrain_outcomes.json holds real ACE's outcomes (ACE 7b47913 on mono) for the scenes in
terrain_scenes.py. The four scenes the brief measured are also checked against its literal values.
"""

from __future__ import annotations

import json
from collections import Counter
from pathlib import Path

import pytest

from acconform.compare import compare
from acconform.numerics import f32_bits
from acconform.outcome import Outcome
from acconform.port.run import run_scene
from acconform.port.transition.branches import (BRANCHES, NOT_YET_REACHED, REACHED_BY_BUILDING_SCENES, REACHED_BY_INDOOR_SCENES,
                                                REACHED_BY_OBJECT_SCENES, REACHED_BY_PLACEMENT_SCENES, REACHED_BY_TICK_SCENES)
from terrain_scenes import SCENES

RECORDED = json.loads((Path(__file__).parent / "data" / "ace_terrain_outcomes.json").read_text())["outcomes"]


def ace_outcome(name: str) -> Outcome:
    return Outcome.from_json(RECORDED[name])


@pytest.mark.anchor("CTransition::find_valid_position")
def test_every_scene_has_a_recorded_ace_answer():
    assert set(SCENES) == set(RECORDED)


@pytest.mark.anchor("CTransition::find_transitional_position")
@pytest.mark.parametrize("name", sorted(SCENES))
def test_terrain_walk_matches_ace_bit_for_bit(name):
    scene, _behaviour = SCENES[name]
    assert compare(run_scene(scene), ace_outcome(name), "exact") == []


def _scenes_reaching(branch: str) -> list[str]:
    names = []
    for name, (scene, _) in sorted(SCENES.items()):
        trace = Counter()
        run_scene(scene, trace=trace)
        if trace[branch]:
            names.append(name)
    return names


@pytest.mark.anchor("CTransition::edge_slide")
@pytest.mark.parametrize("branch", sorted(b for b in BRANCHES if b not in NOT_YET_REACHED and b not in REACHED_BY_OBJECT_SCENES
                                           and b not in REACHED_BY_INDOOR_SCENES and b not in REACHED_BY_PLACEMENT_SCENES
                                           and b not in REACHED_BY_TICK_SCENES and b not in REACHED_BY_BUILDING_SCENES))
def test_branch_is_reached_by_a_scene_where_the_port_matches_ace(branch):
    names = _scenes_reaching(branch)
    assert names, f"no recorded scene reaches {branch}"
    for name in names:
        assert compare(run_scene(SCENES[name][0]), ace_outcome(name), "exact") == [], name


# ---------------------------------------------------------------- the brief's measured ACE facts


def _state(o: Outcome):
    return (o.ok, hex(o.cell), o.contact_plane.valid, hex(o.contact_plane.cell), o.contact_plane.normal,
            o.contact_plane.d, o.last_known_contact_plane == o.contact_plane, o.object_info_state,
            o.collided_with_environment, o.frames_stationary_fall)


@pytest.mark.anchor("CTransition::find_transitional_position")
def test_flat_one_step_walk_ends_where_asked_on_the_ground():
    o = run_scene(SCENES["flat-short"][0])
    assert o.origin == (pytest.approx(12.4, abs=1e-6), 12.0, 20.0) and f32_bits(o.origin[0]) == f32_bits(12.4)
    assert _state(o) == (True, "0xa9b40001", True, "0xa9b40001", (0.0, 0.0, 1.0), -20.0, True, 771, False, 0)
    assert not o.sliding_normal.valid and not o.collision_normal.valid


@pytest.mark.anchor("CTransition::calc_num_steps")
def test_flat_eleven_step_walk_accumulates_in_float32():
    o = run_scene(SCENES["flat-11-steps"][0])
    assert f32_bits(o.origin[0]) == f32_bits(16.999998)
    assert _state(o) == (True, "0xa9b40001", True, "0xa9b40001", (0.0, 0.0, 1.0), -20.0, True, 771, False, 0)


@pytest.mark.anchor("CTransition::edge_slide")
def test_walk_off_a_terrain_cliff_stops_at_the_edge_through_the_back_probe():
    trace = Counter()
    o = run_scene(SCENES["cliff-edge-slide"][0], trace=trace)
    assert f32_bits(o.origin[0]) == f32_bits(71.818176) and o.origin[1:] == (12.0, 200.0)
    assert _state(o) == (True, "0xa9b40011", True, "0xa9b40011", (0.0, 0.0, 1.0), -200.0, True, 771, False, 0)
    assert o.sliding_normal.valid and o.sliding_normal.vector == (0.0, 0.0, 0.0)
    assert o.collision_normal.valid and o.collision_normal.vector == (0.0, 0.0, 1.0)
    assert trace["edge_slide:back_probe"] and trace["edge_slide:back_probe_no_walkable"]
    assert not trace["edge_slide:precipice_slide"]  # terrain never sets SpherePath.Walkable


@pytest.mark.anchor("CTransition::adjust_offset")
def test_uphill_ramp_walk_follows_the_slope():
    o = run_scene(SCENES["ramp-uphill"][0])
    assert [f32_bits(c) for c in o.origin] == [f32_bits(34.999992), f32_bits(12.0), f32_bits(22.916666)]
    assert hex(o.cell) == "0xa9b40009" and o.contact_plane.valid
    assert [round(c, 6) for c in o.contact_plane.normal] == [-0.083045, 0.0, 0.996546]
    assert round(o.contact_plane.d, 6) == -19.930916
