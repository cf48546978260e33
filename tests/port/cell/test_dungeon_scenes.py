"""The named indoor scenes (dungeon_scenes.SCENES): the port against ACE bit for bit, and what each
scene is built to show.

data/ace_dungeon_outcomes.json holds live ACE's outcomes for them (ACE 7b47913 on mono and on
.NET 10 through the live oracle); the fast lane replays them bit for bit, the live lane
(`live_oracle`) asks the configured ACE again. Record anew with

    ACE_ASSEMBLY=/path/to/ACE.Server.dll python tests/port/cell/test_dungeon_scenes.py --record

once with a mono build and once with a .NET 10 build (each is recorded under its runtime).
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest

_HERE = Path(__file__).resolve().parent
if str(_HERE) not in sys.path:
    sys.path.insert(0, str(_HERE))

from acconform.compare import compare  # noqa: E402
from acconform.outcome import Outcome  # noqa: E402
from acconform.port.run import run_scene  # noqa: E402
from acconform.port.transition.branches import Trace  # noqa: E402
from dungeon_scenes import R, SCENES  # noqa: E402

DATA = _HERE / "data" / "ace_dungeon_outcomes.json"


def recorded(runtime: str) -> dict:
    if not DATA.exists():
        pytest.fail(f"no recorded ACE answers at {DATA}: record them with the live oracle (see the module note)")
    return json.loads(DATA.read_text())["outcomes"][runtime]


def scene(name):
    return SCENES[name][0]


def port(name: str) -> tuple[Outcome, Trace]:
    trace = Trace()
    return run_scene(scene(name), trace=trace), trace


# ---------------------------------------------------------------- against ACE


@pytest.mark.anchor("CEnvCell::find_env_collisions")
@pytest.mark.parametrize("runtime", ["mono", "coreclr"])
@pytest.mark.parametrize("name", sorted(SCENES))
def test_named_indoor_scene_matches_recorded_ace_bit_for_bit(name, runtime):
    answers = recorded(runtime)
    assert set(answers) == set(SCENES)
    assert compare(port(name)[0], Outcome.from_json(answers[name]), "exact") == [], name


@pytest.mark.live_oracle
@pytest.mark.anchor("CEnvCell::find_env_collisions")
@pytest.mark.parametrize("name", sorted(SCENES))
def test_named_indoor_scene_matches_live_ace(live, name):
    assert compare(port(name)[0], live.run(scene(name)), "exact") == [], name


# ---------------------------------------------------------------- what each scene shows


def _reached_end(out, name):
    end = scene(name).mover.end.frame.origin
    return all(abs(a - b) < 1e-4 for a, b in zip(out.origin[:2], end[:2]))


@pytest.mark.anchor("CEnvCell::find_transit_cells")
def test_a_mover_walks_through_a_doorway_barely_wider_than_itself_into_the_corridor():
    out, trace = port("doorway")
    begin = scene("doorway").mover.begin.cell
    assert out.error is None and out.cell == begin + 1 and _reached_end(out, "doorway")
    assert trace["env_cell:other_cell"] > 0


@pytest.mark.anchor("CEnvCell::find_transit_cells")
def test_a_mover_walks_along_a_whole_wall_seam_between_two_cells_with_both_in_its_cell_list():
    out, trace = port("corridor-seam")
    s = scene("corridor-seam")
    assert out.error is None and _reached_end(out, "corridor-seam")
    assert out.origin[0] == s.mover.begin.frame.origin[0]  # it keeps its line along the seam
    assert out.cell in {c.id for c in s.env_cells} and trace["env_cell:other_cell"] > 0


@pytest.mark.anchor("CEnvCell::find_env_collisions")
def test_a_mover_walks_from_a_flat_floor_up_a_ramp_in_the_ramps_cell():
    out, _ = port("ramp")
    s = scene("ramp")
    end = s.mover.end.frame.origin
    assert out.error is None and out.cell == s.mover.begin.cell + 1
    assert abs(out.origin[0] - end[0]) < 0.1 and out.origin[2] > s.mover.begin.frame.origin[2] + 0.5  # up the slope
    assert out.contact_plane.valid and 0.9 < out.contact_plane.normal[2] < 0.99  # on the 20-degree slope


@pytest.mark.anchor("CEnvCell::find_env_collisions")
def test_a_mover_steps_up_a_stair_onto_the_steps():
    out, trace = port("stair")
    s = scene("stair")
    rise = out.origin[2] - s.mover.begin.frame.origin[2]
    assert out.error is None and out.cell == s.mover.begin.cell + 1
    assert rise > 0 and abs(rise / 0.25 - round(rise / 0.25)) < 1e-4  # on a step: a whole number of 0.25 m steps
    assert trace["step_up:ok"] > 0


@pytest.mark.anchor("CEnvCell::find_env_collisions")
def test_edge_slide_holds_a_mover_on_an_indoor_ledge():
    out, trace = port("ledge-edge-slide")
    s = scene("ledge-edge-slide")
    edge_x = s.env_cells[0].frame.origin[0]  # the ledge's edge is at the room's centre
    assert out.error is None and out.contact_plane.valid
    assert out.origin[2] == s.mover.begin.frame.origin[2]
    assert edge_x <= out.origin[0] < edge_x + R  # its centre over the lower floor by less than a radius
    assert trace["edge_slide:precipice_slide"] + trace["edge_slide:back_probe_precipice_slide"] > 0


@pytest.mark.anchor("CEnvCell::find_env_collisions")
def test_without_edge_slide_a_mover_walks_off_an_indoor_ledge_and_loses_the_floor():
    out, trace = port("ledge-no-edge-slide")
    assert out.error is None and _reached_end(out, "ledge-no-edge-slide")
    assert not out.contact_plane.valid and trace["step_down:fail"] > 0


@pytest.mark.anchor("CEnvCell::find_env_collisions")
def test_a_mover_walking_into_the_wall_beside_a_doorway_stops_at_the_wall_in_its_cell():
    out, _ = port("wall-beside-portal")
    s = scene("wall-beside-portal")
    wall_x = s.env_cells[0].frame.origin[0] + 3.0
    assert out.error is None and out.cell == s.mover.begin.cell
    assert s.mover.begin.frame.origin[0] < out.origin[0] <= wall_x - R


@pytest.mark.anchor("CEnvCell::point_in_cell")
def test_a_mover_crosses_a_portal_at_an_angle_into_a_cell_whose_frame_is_turned():
    out, _ = port("portal-at-an-angle")
    s = scene("portal-at-an-angle")
    assert s.env_cells[0].frame.orientation != s.env_cells[1].frame.orientation
    assert out.error is None and out.cell == s.env_cells[1].id and _reached_end(out, "portal-at-an-angle")


@pytest.mark.anchor("CEnvCell::init_static_objects")
def test_a_static_straddling_two_cells_is_registered_in_both_and_stops_the_mover():
    out, _ = port("static-straddling-cells")
    s = scene("static-straddling-cells")
    assert out.static_cells == (tuple(c.id for c in s.env_cells),)
    box_face = s.objects[0].position.frame.origin[0] - 0.5
    assert out.error is None and out.origin[0] <= box_face - R


def _record() -> None:
    """Record the configured ACE's answers under its runtime (one runtime per process: run once per build)."""
    from acconform.oracle.live import LiveOracle

    live = LiveOracle()
    runtime = live.ace.location.runtime
    old = json.loads(DATA.read_text())["outcomes"] if DATA.exists() else {}
    old[runtime] = {name: live.run(s).to_json() for name, (s, _) in sorted(SCENES.items())}
    source = "ACE 7b47913 via the live oracle (acconform.oracle, Facade.cs path), on mono 6.8 and on .NET 10"
    DATA.write_text(json.dumps({"source": source, "outcomes": old}, indent=1, sort_keys=True) + "\n")
    print(f"recorded {len(old[runtime])} {runtime} outcomes to {DATA}")


if __name__ == "__main__":
    if sys.argv[1:] != ["--record"]:
        sys.exit("usage: ACE_ASSEMBLY=/path/to/ACE.Server.dll python tests/port/cell/test_dungeon_scenes.py --record")
    _record()
