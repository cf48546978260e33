"""The named placement scenes (placement_scenes.SCENES): the mover placed by ACE's PhysicsObj.SetPosition,
the port against ACE bit for bit on both runtimes, and what each scene is built to show.

data/ace_placement_outcomes.json holds live ACE's outcomes (ACE 7b47913 on mono and on .NET 10
through the live oracle); the fast lane replays them bit for bit, the live lane (`live_oracle`)
asks the configured ACE again. Record anew with

    ACE_ASSEMBLY=/path/to/ACE.Server.dll python tests/port/cell/test_placement_scenes.py --record

once with a mono build and once with a .NET 10 build (each is recorded under its runtime).
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest

_HERE = Path(__file__).resolve().parent
for _p in (_HERE, _HERE.parent / "objects"):
    if str(_p) not in sys.path:
        sys.path.insert(0, str(_p))

from acconform.compare import compare  # noqa: E402
from acconform.flags import SetPositionError, TransientState  # noqa: E402
from acconform.outcome import Outcome  # noqa: E402
from acconform.port.run import run_scene  # noqa: E402
from acconform.port.transition.branches import (BRANCHES, NOT_YET_REACHED, REACHED_BY_INDOOR_SCENES,  # noqa: E402
                                                REACHED_BY_OBJECT_SCENES, REACHED_BY_PLACEMENT_SCENES, Trace)
from placement_scenes import A, B, LB, SCENES  # noqa: E402

DATA = _HERE / "data" / "ace_placement_outcomes.json"
RUNTIMES = ("mono", "coreclr")


def recorded(runtime: str) -> dict:
    if not DATA.exists():
        pytest.fail(f"no recorded ACE answers at {DATA}: record them with the live oracle (see the module note)")
    return json.loads(DATA.read_text())["outcomes"][runtime]


def port(name: str, runtime: str = "mono") -> tuple[Outcome, Trace]:
    trace = Trace()
    return run_scene(SCENES[name][0], trace=trace, runtime=runtime), trace


# ---------------------------------------------------------------- against ACE


@pytest.mark.anchor("CPhysicsObj::SetPositionInternal")
@pytest.mark.parametrize("runtime", RUNTIMES)
@pytest.mark.parametrize("name", sorted(SCENES))
def test_named_placement_scene_matches_recorded_ace_bit_for_bit(name, runtime):
    answers = recorded(runtime)
    assert set(answers) == set(SCENES)
    assert compare(port(name, runtime)[0], Outcome.from_json(answers[name]), "exact") == [], name


@pytest.mark.live_oracle
@pytest.mark.anchor("CPhysicsObj::SetPositionInternal")
@pytest.mark.parametrize("name", sorted(SCENES))
def test_named_placement_scene_matches_live_ace(live, name):
    assert compare(port(name, live.location.runtime)[0], live.run(SCENES[name][0]), "exact") == [], name


@pytest.mark.live_oracle
@pytest.mark.anchor("CPhysicsObj::SetPositionInternal")
def test_a_placed_mover_leaves_the_cached_landblock_with_its_scene(live):
    """The mover enters its cell (ObjectList, shadows, the landblock's ServerObjects) and leaves it after
    the scene: each scene answers the same run again, after the others, and with the cache off."""
    names = sorted(SCENES)
    first = {name: live.run(SCENES[name][0]) for name in names}
    assert all(live.run(SCENES[name][0]) == first[name] for name in reversed(names))
    live.set_landblock_cache(False)
    try:
        assert all(live.run(SCENES[name][0]) == first[name] for name in names)
    finally:
        live.set_landblock_cache(True)


# ---------------------------------------------------------------- the branches


@pytest.mark.anchor("CPhysicsObj::CheckPositionInternal")
def test_placement_branch_list_is_documented_and_disjoint_from_the_others():
    assert set(REACHED_BY_PLACEMENT_SCENES) <= set(BRANCHES)
    assert not set(REACHED_BY_PLACEMENT_SCENES) & (set(NOT_YET_REACHED) | set(REACHED_BY_OBJECT_SCENES)
                                                   | set(REACHED_BY_INDOOR_SCENES))


@pytest.mark.anchor("CPhysicsObj::CheckPositionInternal")
@pytest.mark.parametrize("branch", sorted(REACHED_BY_PLACEMENT_SCENES))
def test_branch_is_reached_by_a_named_placement_scene_where_the_port_matches_ace(branch):
    names = []
    for name in sorted(SCENES):
        out, trace = port(name)
        if trace[branch]:
            assert compare(out, Outcome.from_json(recorded("mono")[name]), "exact") == [], name
            names.append(name)
    assert names, f"no named placement scene reaches {branch}"


# ---------------------------------------------------------------- what each scene shows


@pytest.mark.anchor("CEnvCell::find_visible_child_cell")
def test_a_placement_into_a_visible_neighbour_takes_the_neighbours_cell():
    out, _ = port("indoor-neighbour-child")
    assert out.placement.result == SetPositionError.OK and out.placement.cell == B and out.placement.cur_cell == B
    assert out.placement.shadow_cells == (B,)


@pytest.mark.anchor("Position::adjust_to_outside")
def test_a_seen_outside_cell_drops_a_point_in_no_cell_to_the_landblock():
    out, _ = port("seen-outside-fall-out")
    assert out.placement.result == SetPositionError.OK and out.placement.cur_cell & 0xFFFF < 0x100


@pytest.mark.anchor("CPhysicsObj::store_position")
def test_a_placement_in_no_cell_stores_the_position_and_runs_no_transition():
    out, _ = port("no-cell")
    assert out.placement.cur_cell == 0 and out.placement.cell == A
    assert not out.placement.transient_state & TransientState.Active
    assert out == Outcome(velocity=out.velocity, static_cells=out.static_cells, placement=out.placement)


@pytest.mark.anchor("LandDefs::AdjustToOutside")
def test_an_outdoor_placement_under_the_wrong_cell_id_is_moved_to_its_points_cell():
    out, _ = port("outdoor-wrong-cell-id")
    assert out.placement.cell == LB | 0x000A == out.placement.cur_cell


@pytest.mark.anchor("CPhysicsObj::CheckPositionInternal")
def test_without_slide_a_push_under_five_centimetres_is_kept_and_a_larger_one_toward_plus_x_refused():
    small, t_small = port("wall-push-small")
    large, t_large = port("wall-push-large")
    assert small.placement.result == SetPositionError.OK and t_small["check_position:kept_close"]
    assert large.placement.result == SetPositionError.NoValidPosition and t_large["check_position:moved_too_far"]
    slid, _ = port("wall-push-large-slide")
    assert slid.placement.result == SetPositionError.OK and slid.placement.origin[0] > 55.2


@pytest.mark.anchor("CPhysicsObj::CheckPositionInternal")
def test_without_slide_a_large_push_toward_minus_x_is_kept_because_ace_compares_without_abs():
    out, trace = port("wall-push-negative")
    assert out.placement.result == SetPositionError.OK and trace["check_position:kept_far_negative"]
    assert out.placement.origin[0] < 64.8 - 0.05


@pytest.mark.anchor("CTransition::find_placement_pos")
def test_inside_a_box_a_placement_slides_to_a_free_spot_only_with_slide():
    blocked, t_blocked = port("inside-box")
    slid, t_slid = port("inside-box-slide")
    assert blocked.placement.result != SetPositionError.OK and blocked.placement.cur_cell == 0
    assert slid.placement.result == SetPositionError.OK and t_slid["find_placement_pos:slid_to_free_spot"]


@pytest.mark.anchor("Position::get_indoor_cell")
def test_get_cell_finds_the_points_env_cell_through_adjust_cell_and_its_land_cell_outdoors():
    indoor, _ = port("get-cell-indoor")
    outdoor, _ = port("get-cell-outdoor")
    assert indoor.placement.cell == B and outdoor.placement.cell == LB | 0x000A


def _record() -> None:
    from acconform.oracle.live import LiveOracle

    oracle = LiveOracle()
    data = json.loads(DATA.read_text()) if DATA.exists() else {"ace": "7b47913, live oracle", "outcomes": {}}
    data["outcomes"][oracle.location.runtime] = {name: oracle.run(scene).to_json() for name, (scene, _) in sorted(SCENES.items())}
    DATA.write_text(json.dumps(data, indent=1, sort_keys=True) + "\n")
    print(f"{len(SCENES)} {oracle.location.runtime} outcomes -> {DATA}")


if __name__ == "__main__":
    if sys.argv[1:] != ["--record"]:
        sys.exit("usage: python tests/port/cell/test_placement_scenes.py --record")
    _record()
