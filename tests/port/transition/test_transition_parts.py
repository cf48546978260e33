"""Unit behaviour of the transition's records: CellArray order, CollisionInfo normals, CalcNumSteps."""

from __future__ import annotations

import pytest

from acconform.numerics import EXACT, f32_bits
from acconform.port.transition.cell_array import CellArray
from acconform.port.transition.collision_info import CollisionInfo
from acconform.port.transition.transition import Transition
from acconform.port.frame import AFrame, Position


class _Cell:
    def __init__(self, i):
        self.id = i


@pytest.mark.anchor("CELLARRAY::add_cell")
def test_cell_array_reuses_a_removed_slot_for_the_next_cell_like_a_net_dictionary():
    ca = CellArray()
    for i in (1, 2, 3):
        ca.add_cell(i, _Cell(i))
    ca.remove_cell(_Cell(2))
    ca.add_cell(9, _Cell(9))
    ca.add_cell(1, _Cell(1))  # already present: ignored
    assert [c.id for c in ca.cells.values()] == [1, 9, 3]
    assert ca.cells.value_at(1).id == 9 and ca.num_cells == 3


@pytest.mark.anchor("COLLISIONINFO::set_collision_normal")
def test_collision_normal_is_stored_unnormalised():
    ci = CollisionInfo.create(EXACT.scalar(0.0))
    ci.set_collision_normal(EXACT.vec(0, 3, 4))
    assert ci.collision_normal_valid and ci.collision_normal == EXACT.vec(0, 3, 4)


@pytest.mark.anchor("COLLISIONINFO::set_sliding_normal")
def test_sliding_normal_drops_z_and_is_zero_for_a_tiny_normal():
    ci = CollisionInfo.create(EXACT.scalar(0.0))
    ci.set_sliding_normal(EXACT.vec(0, 0, 1))
    assert ci.sliding_normal_valid and ci.sliding_normal == EXACT.vec(0, 0, 0)
    ci.set_sliding_normal(EXACT.vec(3, 0, 4))
    assert ci.sliding_normal == EXACT.vec(3, 0, 0)
    ci.set_sliding_normal(EXACT.vec(1e-5, 0, 0))
    assert ci.sliding_normal == EXACT.vec(0, 0, 0)


@pytest.mark.anchor("CTransition::calc_num_steps")
def test_calc_num_steps_takes_the_ceiling_and_multiplies_by_the_reciprocal():
    t = Transition(EXACT, lscape=None)
    from acconform.port.geom.sphere import Sphere

    t.init_sphere(1, [Sphere(EXACT.vec(0, 0, 0.48), EXACT.scalar(0.48))], EXACT.scalar(1.0))
    begin = Position(0xA9B40001, AFrame(EXACT.vec(12, 12, 20), EXACT.quat(0, 0, 0, 1)))
    end = Position(0xA9B40001, AFrame(EXACT.vec(17, 12, 20), EXACT.quat(0, 0, 0, 1)))
    t.sphere_path.begin_pos, t.sphere_path.end_pos = begin, end
    offset, per_step, n = t.calc_num_steps()
    assert n == 11  # ceil(5 / 0.48) = ceil(10.42)
    expected = EXACT.scalar(5.0) * (EXACT.scalar(1.0) / EXACT.scalar(11))
    assert f32_bits(per_step.x) == f32_bits(expected)


@pytest.mark.anchor("CTransition::find_transitional_position")
def test_fast_mode_runs_the_same_walk_within_a_few_ulps():
    import sys
    from pathlib import Path

    sys.path.insert(0, str(Path(__file__).parent))
    from terrain_scenes import SCENES
    from acconform.port.run import run_scene

    exact = run_scene(SCENES["ramp-uphill"][0], "exact")
    fast = run_scene(SCENES["ramp-uphill"][0], "fast")
    assert fast.error is None and fast.cell == exact.cell
    assert fast.origin == pytest.approx(exact.origin, abs=1e-4)


@pytest.mark.anchor("CTransition::find_transitional_position")
def test_a_port_exception_becomes_an_error_verdict():
    import dataclasses
    import sys
    from pathlib import Path

    from acconform.scene import Frame, Position as PosRec

    sys.path.insert(0, str(Path(__file__).parent))
    from terrain_scenes import SCENES
    from acconform.port.run import run_scene

    scene = SCENES["flat-short"][0]
    # walk west out of landblock A9B4 into A8B4, which the scene does not list: ACE reads its DAT, which lacks it
    end = PosRec(scene.mover.end.cell, Frame((-1.0, 12.0, 20.0)))
    out = run_scene(scene.replace(mover=dataclasses.replace(scene.mover, end=end)))
    assert out.error == "ArgumentOutOfRangeException: Height[0] of 0 heights"
    assert out.ok is False and out.cell == 0
