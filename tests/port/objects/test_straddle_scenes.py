"""Statics straddling cell and landblock borders: the port against ACE, registered cells included.

The scenes are straddle_scenes.SCENES. data/ace_straddle_outcomes.json holds live ACE's outcomes
for them (ACE 7b47913 on mono through the live oracle), static_cells included; the fast lane
replays them bit for bit, the live lane (`live_oracle`) asks ACE again. Record anew with

    ACE_ASSEMBLY=/path/to/ACE.Server.dll python tests/port/objects/test_straddle_scenes.py --record
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest

_HERE = Path(__file__).resolve().parent
for _p in (str(_HERE), str(_HERE.parent)):
    if _p not in sys.path:
        sys.path.insert(0, _p)

from acconform.compare import compare  # noqa: E402
from acconform.outcome import Outcome  # noqa: E402
from acconform.port.run import run_scene  # noqa: E402
from straddle_scenes import SCENES  # noqa: E402

DATA = _HERE / "data" / "ace_straddle_outcomes.json"
SOURCE = "ACE 7b47913 on mono via the live oracle (acconform.oracle, Facade.cs path)"


def recorded() -> dict:
    if not DATA.exists():
        pytest.fail(f"no recorded ACE answers at {DATA}: record them with the live oracle (see the module note)")
    return json.loads(DATA.read_text())["outcomes"]


def port(name: str, runtime: str = "mono") -> Outcome:
    """The port's outcome computing as `runtime` does (the recorded answers are mono's)."""
    return run_scene(SCENES[name][0], runtime=runtime)


def cells(name: str) -> tuple[tuple[int, ...], ...]:
    return port(name).static_cells


def landblocks(cell_ids) -> set[int]:
    return {c >> 16 for c in cell_ids}


# ---------------------------------------------------------------- against ACE's recorded answers


@pytest.mark.anchor("CPhysicsObj::add_obj_to_cell")
def test_every_straddle_scene_has_a_recorded_ace_answer_with_its_registered_cells():
    answers = recorded()
    assert set(answers) == set(SCENES)
    outcomes = [Outcome.from_json(o) for o in answers.values()]
    assert all(o.static_cells is not None for o in outcomes if o.error is None)


@pytest.mark.anchor("CPhysicsObj::add_obj_to_cell")
@pytest.mark.parametrize("name", sorted(SCENES))
def test_straddle_scene_matches_ace_bit_for_bit_registered_cells_included(name):
    assert compare(port(name), Outcome.from_json(recorded()[name]), "exact") == [], name


@pytest.mark.live_oracle
@pytest.mark.anchor("CPhysicsObj::add_obj_to_cell")
@pytest.mark.parametrize("name", sorted(SCENES))
def test_straddle_scene_matches_live_ace(live, name):
    assert compare(port(name, live.location.runtime), live.run(SCENES[name][0]), "exact") == [], name


# ---------------------------------------------------------------- what ACE's placement does (named cases)


@pytest.mark.anchor("CLandCell::add_cell_block")
@pytest.mark.parametrize("shape", ["bsp-small", "bsp-large", "sphere-small", "sphere-large", "bsp-large-rotated"])
def test_a_bbox_placed_object_across_a_landblock_border_is_registered_only_in_its_own_landblock(shape):
    for border in ("block-border", "block-corner"):
        (registered,) = cells(f"{shape}-{border}-from-own")
        assert landblocks(registered) == {0xA9B4}, (shape, border, [hex(c) for c in registered])


@pytest.mark.anchor("CObjCell::find_cell_list")
def test_a_cylsphere_across_a_landblock_corner_is_registered_in_every_landblock_its_sphere_reaches():
    (registered,) = cells("cylsphere-large-block-corner-from-own")
    assert registered[0] == 0xA9B40040  # its own cell first
    assert landblocks(registered) == {0xA9B4, 0xAAB4, 0xA9B5, 0xAAB5}


@pytest.mark.anchor("CPhysicsObj::find_bbox_cell_list")
def test_an_object_across_a_cell_border_is_registered_in_its_own_cell_then_the_neighbour():
    assert cells("bsp-large-cell-border-from-own") == ((0xA9B40023, 0xA9B4001B),)


@pytest.mark.anchor("CLandCell::add_all_outside_cells")
def test_a_large_box_across_a_landblock_border_lets_a_mover_from_the_neighbour_walk_through_it():
    """Registered only on its own side, the box is met only once the mover's spheres reach that
    landblock: coming from the east the mover is already inside it, and walks on out the west."""
    out = port("bsp-large-block-border-from-neighbour")
    assert out.cell >> 16 == 0xA9B4 and out.origin[0] < 188.4 - 0.48


@pytest.mark.anchor("BSPNODE::sphere_intersects_poly")
def test_a_bsp_whose_root_is_a_leaf_is_walked_through():
    out = port("leaf-root-walk-through")
    assert out.error is None and out.ok and abs(out.origin[0] - 104.0) < 1e-4  # the whole way, float32 steps


@pytest.mark.anchor("BSPNODE::find_walkable")
def test_stepping_down_onto_a_leaf_root_bsp_is_a_null_reference_exception_as_in_ace():
    assert port("leaf-root-step-down").error.startswith("NullReferenceException:")


@pytest.mark.anchor("BSPLEAF::sphere_intersects_poly")
def test_empty_leaves_with_zero_radius_spheres_still_stop_the_mover():
    out = port("zero-radius-empty-leaves")
    assert out.error is None and out.origin[0] < 99.0 - 0.48


def _record() -> None:
    from acconform.oracle.live import LiveOracle

    live = LiveOracle()
    outcomes = {name: live.run(scene).to_json() for name, (scene, _) in sorted(SCENES.items())}
    DATA.write_text(json.dumps({"source": SOURCE, "outcomes": outcomes}, indent=1, sort_keys=True) + "\n")
    print(f"recorded {len(outcomes)} outcomes to {DATA}")


if __name__ == "__main__":
    if sys.argv[1:] != ["--record"]:
        sys.exit("usage: python tests/port/objects/test_straddle_scenes.py --record")
    _record()
