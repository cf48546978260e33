"""coverage --anchors: calls per retail anchor, counted by wrapping registry functions only while a run lasts."""

from __future__ import annotations

import pytest

from acconform.anchor_coverage import counting_anchors, render_table
from acconform.cli import main
from acconform.port.anchors import load_all
from acconform.strategies import sample_scenes


@pytest.fixture(scope="module")
def terrain_scene():
    return next(iter(sample_scenes(("terrain",), 1, 0)))


@pytest.mark.anchor("CTransition::find_valid_position")
def test_a_terrain_scene_reaches_find_valid_position(terrain_scene):
    from acconform.port import run

    with counting_anchors() as cov:
        run.run_scene(terrain_scene)
    calls = {a.retail: n for key, a in load_all().items() if (n := cov.calls.get(key))}
    assert calls.get("CTransition::find_valid_position", 0) >= 1
    assert cov.unwrapped == []  # every anchor had a reference to wrap


def test_unreached_anchors_are_listed_with_zero_calls_and_a_summary(terrain_scene):
    from acconform.port import run

    with counting_anchors() as cov:
        run.run_scene(terrain_scene)
    lines = render_table(cov.calls)
    total = len(load_all())
    summary = next(line for line in lines if line.endswith(f"of {total} anchors reached"))
    reached = int(summary.split()[0])
    assert 0 < reached < total
    never = next(line for line in lines if line.startswith("never reached"))
    assert "CCylSphere::collides_with_sphere" in never  # no cylsphere in a terrain scene
    assert any(line.startswith("CCylSphere::collides_with_sphere") and line.endswith(" 0") for line in lines)


def test_counting_restores_every_wrapped_function_afterwards(terrain_scene):
    from acconform.port.cell import land_cell, obj_cell
    from acconform.port.cell.land_cell import LandCell
    from acconform.port.transition.transition import Transition

    before = (Transition.__dict__["find_valid_position"], LandCell.__dict__["find_collisions"],
              land_cell.__dict__["add_all_outside_cells"], obj_cell.ObjCell.__dict__["find_collisions"])
    with counting_anchors():
        assert Transition.__dict__["find_valid_position"] is not before[0]
    after = (Transition.__dict__["find_valid_position"], LandCell.__dict__["find_collisions"],
             land_cell.__dict__["add_all_outside_cells"], obj_cell.ObjCell.__dict__["find_collisions"])
    assert all(a is b for a, b in zip(before, after))


def test_coverage_anchors_prints_the_table_and_the_summary_line(capsys):
    assert main(["coverage", "--anchors", "-n", "2", "--kinds", "terrain"]) == 0
    out = capsys.readouterr().out
    assert "retail anchor" in out and "Transition.cs:FindValidPosition" in out
    assert f"of {len(load_all())} anchors reached" in out
