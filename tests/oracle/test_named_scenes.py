"""The named tick scenes (tests/oracle/named_scenes.py, files in examples/named/): dereth's 13 required
trace-gate scenarios, the acceptance list's six, one for a planted bug and two through a house, with live ACE's answers recorded on both runtimes,
the port against them every tick bit for bit, and what each scene shows.

data/ace_named_outcomes.json holds live ACE's outcomes (ACE 7b47913 on mono and on .NET 10 through the
live oracle). The fast lane replays them against the port; the live lane (`live_oracle`) asks the
configured ACE again and requires the same answer. Record anew (after `named_scenes.py --write`) with

    ACE_ASSEMBLY=/path/to/ACE.Server.dll python tests/oracle/test_named_scenes.py --record

once with a mono build and once with a .NET 10 build (each is recorded under its runtime).
"""

from __future__ import annotations

import json
import sys
from collections import Counter
from pathlib import Path

import pytest

from acconform.compare import compare
from acconform.flags import PhysicsState, TransientState
from acconform.outcome import Outcome

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from oracle.live_answers import record_outcomes, recorded_outcomes  # noqa: E402
from oracle.named_scenes import DERETH, NAMED, build, load  # noqa: E402

DATA = Path(__file__).resolve().parent / "data" / "ace_named_outcomes.json"
RUNTIMES = ("mono", "coreclr")
SCENES = load()
ON_GROUND = TransientState.Contact | TransientState.OnWalkable

# dereth-network/dereth core/physics/src/trace.rs REQUIRED_SCENARIOS, as named there
DERETH_REQUIRED = ("walk_up_48_degree_slope", "sled_9_degree_slope", "sled_11_degree_slope", "step_onto_4cm_lip",
                   "step_onto_lip_1mm_over_step_up_height", "walk_off_narrow_ledge", "swim_into_deep_sea",
                   "cross_landblock_boundary_diagonally", "walk_through_portal_into_dungeon",
                   "collide_with_moving_object", "same_walk_at_250fps", "same_walk_at_30fps", "same_walk_at_4fps")


def recorded(runtime: str) -> dict[str, Outcome]:
    return recorded_outcomes(DATA, runtime)


# ---------------------------------------------------------------- the list and the files


def test_the_named_scenes_are_derets_thirteen_by_name_the_acceptance_lists_six_and_three_more():
    assert DERETH == DERETH_REQUIRED
    assert {name for name, _, _ in NAMED} - set(DERETH) == {
        "fall_landing_on_lower_floor", "walk_off_ledge_with_edge_slide", "walk_off_ledge_without_edge_slide",
        "bounce_with_elasticity", "remainder_carried_across_ticks", "huge_quantum_skip", "block_dist_refusal",
        "skid_from_over_max_velocity",  # for a planted tick-loop bug (tests/runner/mutants.py)
        "walk_into_house_over_ticks", "fall_down_cellar_hatch"}  # issue 20's ticks through a house
    assert all(behaviour for _, behaviour, _ in NAMED)


def test_each_named_scene_file_is_what_its_builder_makes_and_is_a_server_tick_scene():
    built = build()
    for name, scene in SCENES.items():
        assert scene == built[name], f"examples/named/{name}.json differs from its builder: run named_scenes.py --write"
        assert scene.name == name and scene.ticks is not None and scene.engine_mode == "server"


# ---------------------------------------------------------------- ACE's answers, the port against them


@pytest.mark.parametrize("runtime", RUNTIMES)
def test_ace_answered_every_named_scene_on_each_runtime_one_tick_state_per_step(runtime):
    answers = recorded(runtime)
    assert set(answers) == set(SCENES)
    for name, scene in SCENES.items():
        assert answers[name].error is None and len(answers[name].ticks) == len(scene.ticks.steps), name
        assert not any(t.error for t in answers[name].ticks), name


@pytest.mark.anchor("CPhysicsObj::update_object")
@pytest.mark.parametrize("runtime", RUNTIMES)
@pytest.mark.parametrize("name", sorted(SCENES))
def test_the_port_matches_ace_on_every_tick_of_the_named_scene(name, runtime):
    from acconform.port.run import run_scene

    assert compare(run_scene(SCENES[name], runtime=runtime), recorded(runtime)[name], "exact") == []


# ---------------------------------------------------------------- what each shows (ACE's answers)


def _ticks(name, runtime="coreclr"):
    return recorded(runtime)[name].ticks


def _trace(name) -> Counter:
    from acconform.port.run import run_scene

    trace = Counter()
    run_scene(SCENES[name], trace=trace)
    return trace


def test_ace_walks_the_mover_up_the_48_degree_ramp_standing_on_it():
    """cos 48 deg is over FloorZ (cos 48.4 deg): the ramp is walkable, and root motion carries the mover up
    it, slower along x (the offset is horizontal; the transition turns it along the plane)."""
    import math

    ticks = _ticks("walk_up_48_degree_slope")
    on_ramp = [t for t in ticks if t.contact_plane.normal[2] < 1.0]
    assert on_ramp and all(t.transient_state & ON_GROUND == ON_GROUND for t in on_ramp)
    assert on_ramp[0].contact_plane.normal[2] == pytest.approx(math.cos(math.radians(48.0)), abs=1e-6)
    assert on_ramp[-1].origin[2] > on_ramp[0].origin[2] + 1.0 and 0.0 < on_ramp[-1].cached_velocity[0] < 3.0


def test_ace_keeps_the_mover_out_of_an_entirely_water_landblock():
    ticks = _ticks("swim_into_deep_sea")
    assert all(t.cell >> 16 == 0xA9B4 for t in ticks) and ticks[-1].origin[0] < 192.0
    assert ticks[-1].origin[0] > 190.0  # it walked up to the shore line
    assert _trace("swim_into_deep_sea")["land_cell:entirely_water_block"]


def test_ace_refuses_a_request_pos_two_landblocks_away_and_runs_one_into_the_next():
    scene, ticks = SCENES["block_dist_refusal"], _ticks("block_dist_refusal")
    assert ticks[1].cell == scene.ticks.steps[1].request_pos.cell  # AAB4: GetBlockDist 1
    assert ticks[2].cell == ticks[1].cell and ticks[2].origin == ticks[1].origin  # ACB4: refused
    assert ticks[3].cell == scene.ticks.steps[3].request_pos.cell
    assert _trace("block_dist_refusal")["update_object_internal_server:block_dist_refused"] == 1


def test_ace_lets_edge_slide_keep_the_mover_on_the_ledge_and_drops_it_without():
    kept, fell = _ticks("walk_off_ledge_with_edge_slide"), _ticks("walk_off_ledge_without_edge_slide")
    assert min(t.origin[2] for t in kept) == 22.0
    assert fell[-1].origin[2] == 20.0 and fell[-1].transient_state & ON_GROUND == ON_GROUND


def test_ace_lands_the_fall_on_the_lower_floor():
    ticks = _ticks("fall_landing_on_lower_floor")
    assert ticks[-1].origin[2] == 21.0 and ticks[-1].origin[0] > 16.0
    assert any(t.origin[2] < 23.0 and not t.transient_state & TransientState.Contact for t in ticks)


def test_ace_bounces_the_thrown_mover_with_its_elasticity():
    ticks = _ticks("bounce_with_elasticity")
    landed = next(i for i, t in enumerate(ticks) if t.transient_state & TransientState.Contact)
    assert ticks[landed - 1].velocity[2] < 0.0
    assert _trace("bounce_with_elasticity")["handle_all_collisions:elastic_bounce"]


def test_ace_carries_the_remainder_under_min_quantum_to_the_next_tick():
    scene, ticks = SCENES["remainder_carried_across_ticks"], _ticks("remainder_carried_across_ticks")
    times = scene.ticks.times()
    assert ticks[0].updated and ticks[0].update_time != times[0]  # 0.1 run, 0.02 kept
    assert any(t.update_time == times[i] for i, t in enumerate(ticks))  # a later tick runs it
    trace = _trace("remainder_carried_across_ticks")
    assert trace["update_object:remainder_kept"] and trace["update_object:remainder_step"]


def test_ace_runs_a_tick_of_exactly_huge_quantum_and_skips_one_over_it():
    scene, ticks = SCENES["huge_quantum_skip"], _ticks("huge_quantum_skip")
    times = scene.ticks.times()
    assert scene.ticks.steps[3].dt == 2.0 and ticks[3].updated and ticks[3].origin[2] < ticks[2].origin[2] - 10.0
    assert scene.ticks.steps[6].dt == 2.5 and not ticks[6].updated and ticks[6].update_time == times[6]
    assert ticks[6].origin == ticks[5].origin


def test_ace_tells_the_three_frame_rates_of_the_same_walk_apart():
    ends = {fps: _ticks(f"same_walk_at_{fps}fps")[-1].origin for fps in (250, 30, 4)}
    assert len(set(ends.values())) == 3
    assert not any(t.updated for t in _ticks("same_walk_at_250fps")[:8])  # 1/250 s is under TickRate


def test_ace_sleds_both_slopes_without_the_glide_friction():
    """ACE's glide needs normal.z > 0.99999536 (under 0.2 deg): neither 9 nor 11 deg glides."""
    for name in ("sled_9_degree_slope", "sled_11_degree_slope"):
        assert SCENES[name].mover.state & PhysicsState.Sledding
        assert not _trace(name)["calc_friction:sledding_glide"], name
    assert _ticks("sled_9_degree_slope")[-1].origin != _ticks("sled_11_degree_slope")[-1].origin


def test_ace_steps_onto_the_4cm_lip_and_onto_one_1mm_over_the_step_height_too():
    """ACE's limit is not StepUpHeight: the mover's sphere (r 0.48) meets a lip lower than its centre at the
    lip's edge, under the centre, and rides up onto it (ACE's answer, on both runtimes); at the far edge
    the 0.401 m drop is deeper than StepDownHeight (0.4) and EdgeSlide holds it there."""
    low, high = _ticks("step_onto_4cm_lip"), _ticks("step_onto_lip_1mm_over_step_up_height")
    assert max(t.origin[2] for t in low) == pytest.approx(20.04) and low[-1].origin[0] > 15.4 and low[-1].origin[2] == 20.0
    assert high[-1].origin[2] == pytest.approx(20.401) and 15.0 < high[-1].origin[0] < 15.5


def test_ace_walks_through_the_portal_into_the_next_dungeon_cell_and_across_the_landblock_corner():
    assert _ticks("walk_through_portal_into_dungeon")[-1].cell == 0x01D90101
    assert _ticks("cross_landblock_boundary_diagonally")[-1].cell >> 16 == 0xAAB5


def test_ace_clamps_a_start_velocity_over_max_velocity_before_friction():
    ticks = _ticks("skid_from_over_max_velocity")
    assert 40.0 < ticks[0].velocity[0] < 50.0 and ticks[0].origin[0] > 14.0
    assert _trace("skid_from_over_max_velocity")["update_physics:velocity_clamped"] == 1


def test_ace_zeroes_the_cached_velocity_when_the_walk_is_stopped_by_the_object():
    ticks = _ticks("collide_with_moving_object")
    assert ticks[0].cached_velocity[0] > 0.0 and ticks[-1].cached_velocity == (0.0, 0.0, 0.0)


@pytest.mark.anchor("CBuildingObj::find_building_transit_cells")
@pytest.mark.parametrize("runtime", RUNTIMES)
def test_ace_walks_the_mover_in_through_the_house_door_over_ticks_vestibule_then_room(runtime):
    """Outdoors, then the vestibule (0x0100, reached through the building's portal), then the room."""
    cells = [t.cell for t in _ticks("walk_into_house_over_ticks", runtime)]
    assert cells[0] & 0xFFFF < 0x100 and cells[-1] == 0xA9B40101
    firsts = [c for i, c in enumerate(cells) if i == 0 or cells[i - 1] != c]
    assert [c & 0xFFFF for c in firsts[1:]] == [0x100, 0x101]
    assert _trace("walk_into_house_over_ticks")["building:transit_cell"]


@pytest.mark.parametrize("runtime", RUNTIMES)
def test_ace_drops_the_mover_through_the_hatch_onto_the_cellar_floor_in_free_fall_between(runtime):
    """Pushed over the hatch's edge (x 104) without EdgeSlide, it leaves the floor, falls the 2.5 m to the
    cellar floor (z 17.5) in the room's cell, and stands there."""
    ticks = _ticks("fall_down_cellar_hatch", runtime)
    assert ticks[0].origin[2] == 20.0 and ticks[-1].origin[2] == 17.5 and ticks[-1].cell == 0xA9B40101
    assert any(17.5 < t.origin[2] < 20.0 and not t.transient_state & TransientState.Contact for t in ticks)
    assert ticks[-1].transient_state & ON_GROUND == ON_GROUND and 104.0 < ticks[-1].origin[0] < 105.5


# ---------------------------------------------------------------- live


@pytest.mark.live_oracle
@pytest.mark.parametrize("name", sorted(SCENES))
def test_live_ace_answers_each_named_scene_as_recorded(live, name):
    assert compare(live.run(SCENES[name]), recorded(live.location.runtime)[name], "exact") == [], name


# ---------------------------------------------------------------- recording


if __name__ == "__main__":
    if sys.argv[1:] != ["--record"]:
        sys.exit(__doc__)
    record_outcomes(SCENES, DATA, "named")
