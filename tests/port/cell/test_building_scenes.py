"""Issue 20's named building scenes (building_scenes.py): the port against ACE bit for bit on both
runtimes, what each scene shows, and every building branch reached by one of them.

data/ace_building_scenes.json holds the scenes and live ACE's outcomes (ACE 7b47913 on mono and on
.NET 10 through the live oracle); the fast lane replays them, the live lane (`live_oracle`) asks the
configured ACE again.
"""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

_HERE = Path(__file__).resolve().parent
if str(_HERE) not in sys.path:
    sys.path.insert(0, str(_HERE))

from acconform.compare import compare  # noqa: E402
from acconform.outcome import Outcome  # noqa: E402
from acconform.port.run import run_scene  # noqa: E402
from acconform.port.transition.branches import (BRANCHES, NOT_YET_REACHED, REACHED_BY_BUILDING_SCENES,  # noqa: E402
                                                REACHED_BY_INDOOR_SCENES, REACHED_BY_OBJECT_SCENES,
                                                REACHED_BY_PLACEMENT_SCENES, Trace)
from building_scenes import DATA, RULES, load  # noqa: E402

RUNTIMES = ("mono", "coreclr")
if not DATA.exists():  # pragma: no cover - the data is committed
    pytest.fail(f"no recorded building scenes at {DATA}: record them (building_scenes.py --record)", pytrace=False)
SCENES, OUTCOMES = load()


def port(name: str, runtime: str = "mono") -> tuple[Outcome, Trace]:
    trace = Trace()
    return run_scene(SCENES[name], trace=trace, runtime=runtime), trace


def ace(name: str, runtime: str = "mono") -> Outcome:
    return Outcome.from_json(OUTCOMES[runtime][name])


@pytest.mark.anchor("CBuildingObj::find_building_collisions")
@pytest.mark.parametrize("runtime", RUNTIMES)
@pytest.mark.parametrize("name", sorted(SCENES))
def test_named_building_scene_matches_recorded_ace_bit_for_bit(name, runtime):
    assert set(OUTCOMES[runtime]) == set(SCENES)
    assert compare(port(name, runtime)[0], ace(name, runtime), "exact") == [], name


@pytest.mark.live_oracle
@pytest.mark.anchor("CBuildingObj::find_building_collisions")
@pytest.mark.parametrize("name", sorted(SCENES))
def test_named_building_scene_matches_live_ace(live, name):
    assert compare(port(name, live.location.runtime)[0], live.run(SCENES[name]), "exact") == [], name


def test_every_rule_picked_a_scene_and_both_portal_sides_are_there():
    assert set(RULES) | {"portal-side-on", "portal-side-off"} == set(SCENES)


# ---------------------------------------------------------------- what each scene shows


@pytest.mark.anchor("CEnvCell::check_building_transit")
def test_walking_in_through_the_door_ends_in_the_vestibule_and_walking_out_ends_outdoors():
    inside, t_in = port("in-through-door")
    outside, _ = port("out-through-door")
    assert inside.cell & 0xFFFF >= 0x100 and t_in["building:transit_cell"] > 0
    assert outside.cell & 0xFFFF < 0x100 and SCENES["out-through-door"].mover.begin.cell & 0xFFFF >= 0x100


@pytest.mark.anchor("CBuildingObj::find_building_collisions")
def test_the_shell_stops_a_mover_along_it_and_into_the_wall_beside_the_door():
    for name in ("along-shell", "into-wall-beside-door"):
        out, trace = port(name)
        assert trace["building:collided"] > 0 and out.collision_normal.valid, name


@pytest.mark.anchor("CEnvCell::find_transit_cells")
def test_down_the_cellar_stairs_ends_lower_on_the_stairs_or_in_the_cellar():
    out, _ = port("down-cellar-stairs")
    assert out.cell & 0xFFFF in (0x0102, 0x0103) and out.origin[2] < SCENES["down-cellar-stairs"].mover.begin.frame.origin[2]


@pytest.mark.anchor("CObjCell::find_cell_list")
def test_a_placement_under_an_outdoor_id_inside_the_house_ends_in_the_buildings_cell():
    out, _ = port("placement-into-building")
    assert SCENES["placement-into-building"].mover.begin.cell & 0xFFFF < 0x100
    assert out.placement.cur_cell & 0xFFFF >= 0x100


@pytest.mark.anchor("CEnvCell::check_building_transit")
def test_a_static_in_the_doorway_is_registered_in_the_vestibule_through_the_parts_overload():
    out, _ = port("static-in-doorway")
    assert any(c & 0xFFFF >= 0x100 for c in out.static_cells[0])


@pytest.mark.anchor("CBldPortal::CBldPortal")
def test_ace_reads_no_buildings_portal_side_so_both_sides_answer_the_same():
    """BldPortal.PortalSide (and ExactMatch) is copied from the DAT and never read by ACE's physics:
    check_building_transit's parts overload reads the EnvCell's own CellPortal.PortalSide."""
    for runtime in RUNTIMES:
        assert ace("portal-side-on", runtime) == ace("portal-side-off", runtime) == ace("in-through-door", runtime)


# ---------------------------------------------------------------- the branches


def test_building_branch_list_is_documented_and_disjoint_from_the_others():
    assert set(REACHED_BY_BUILDING_SCENES) <= set(BRANCHES)
    assert not set(REACHED_BY_BUILDING_SCENES) & (set(NOT_YET_REACHED) | set(REACHED_BY_OBJECT_SCENES)
                                                  | set(REACHED_BY_INDOOR_SCENES) | set(REACHED_BY_PLACEMENT_SCENES))


@pytest.mark.anchor("CBuildingObj::find_building_collisions")
@pytest.mark.parametrize("branch", sorted(REACHED_BY_BUILDING_SCENES))
def test_branch_is_reached_by_a_named_building_scene_where_the_port_matches_ace(branch):
    names = []
    for name in sorted(SCENES):
        out, trace = port(name)
        if trace[branch]:
            assert compare(out, ace(name), "exact") == [], name
            names.append(name)
    assert names, f"no named building scene reaches {branch}"
