"""The port against ACE's recorded answers on the static-object scenes, bit for bit.

data/ace_object_outcomes.json holds real ACE's outcomes (ACE 7b47913 on mono, live oracle) for
the scenes in object_scenes.py. Floats are compared by float32 bits; an error is compared by its
.NET type (the text before ": "), since the port words its own message.
"""

from __future__ import annotations

import json
from collections import Counter
from pathlib import Path

import pytest

from acconform.flags import PhysicsState
from acconform.compare import compare
from acconform.outcome import Outcome
from acconform.port.run import run_scene
from acconform.port.transition.branches import BRANCHES, NOT_YET_REACHED, REACHED_BY_OBJECT_SCENES
from object_scenes import SCENES

RECORDED = json.loads((Path(__file__).parent / "data" / "ace_object_outcomes.json").read_text())["outcomes"]


def ace_outcome(name: str) -> Outcome:
    return Outcome.from_json(RECORDED[name])


def run(name: str) -> tuple[Outcome, Counter]:
    trace = Counter()
    return run_scene(SCENES[name][0], trace=trace), trace


def matches_ace(name: str) -> tuple[Outcome, Counter]:
    out, trace = run(name)
    assert compare(out, ace_outcome(name), "exact") == [], name
    return out, trace


# ---------------------------------------------------------------- every scene, every branch


@pytest.mark.anchor("CPhysicsObj::FindObjCollisions")
def test_every_object_scene_has_a_recorded_ace_answer():
    assert set(SCENES) == set(RECORDED)


@pytest.mark.anchor("CPhysicsObj::FindObjCollisions")
@pytest.mark.parametrize("name", sorted(SCENES))
def test_object_scene_matches_ace_bit_for_bit(name):
    out, _ = run(name)
    assert compare(out, ace_outcome(name), "exact") == []


@pytest.mark.anchor("CTransition::edge_slide")
def test_object_branch_lists_are_documented_and_disjoint():
    assert set(REACHED_BY_OBJECT_SCENES) <= set(BRANCHES)
    assert not set(REACHED_BY_OBJECT_SCENES) & set(NOT_YET_REACHED)


@pytest.mark.anchor("CTransition::edge_slide")
@pytest.mark.parametrize("branch", sorted(REACHED_BY_OBJECT_SCENES))
def test_branch_is_reached_by_an_object_scene_where_the_port_matches_ace(branch):
    names = [name for name in sorted(SCENES) if run(name)[1][branch]]
    assert names, f"no object scene reaches {branch}"
    for name in names:
        matches_ace(name)


# ---------------------------------------------------------------- behaviours, by name


@pytest.mark.anchor("CBSPTree::find_collisions")
def test_a_bsp_wall_stops_the_mover_after_a_failed_step_up():
    out, trace = matches_ace("wall-head-on")
    assert trace["step_up:fail"] and out.collision_normal.valid and out.collision_normal.vector == (-1.0, 0.0, 0.0)
    assert out.origin[0] < 100.0 - 0.25


@pytest.mark.anchor("CPhysicsObj::FindObjCollisions")
def test_a_bsp_object_without_has_physics_bsp_is_passed_through():
    scene = SCENES["wall-without-bsp-flag"][0]
    assert not scene.objects[0].state & PhysicsState.HasPhysicsBSP
    out, _ = matches_ace("wall-without-bsp-flag")
    assert out.origin[0] == pytest.approx(102.0, abs=1e-4) and not out.collision_normal.valid


@pytest.mark.anchor("CPhysicsObj::FindObjCollisions_Inner")
def test_an_ethereal_static_wall_still_blocks():
    out, _ = matches_ace("wall-ethereal")
    assert out.origin == run("wall-head-on")[0].origin


@pytest.mark.anchor("CTransition::step_up")
def test_step_up_onto_a_stair_lower_than_the_step_height():
    out, trace = matches_ace("stair-step-up")
    assert trace["step_up:ok"] and out.origin[2] == pytest.approx(20.3, abs=1e-4) and out.origin[0] == pytest.approx(100.0, abs=1e-4)


@pytest.mark.anchor("CTransition::step_up")
def test_lip_1mm_over_the_step_height_is_climbed_but_1mm_over_the_reach_is_not():
    over_height, t1 = matches_ace("lip-1mm-over-step-height")
    assert t1["step_up:ok"] and over_height.origin[0] == pytest.approx(100.0, abs=1e-4)
    over_reach, t2 = matches_ace("lip-1mm-over-step-reach")
    assert t2["step_up:fail"] and not t2["step_up:ok"] and over_reach.origin[0] < 98.0
    under_reach, t3 = matches_ace("lip-1mm-under-step-reach")
    assert t3["step_up:ok"] and under_reach.origin[0] == pytest.approx(100.0, abs=1e-4)


@pytest.mark.anchor("SPHEREPATH::precipice_slide")
def test_precipice_slide_off_a_bsp_ledge_keeps_the_mover_on_top_through_the_back_probe():
    out, trace = matches_ace("platform-edge-precipice-slide")
    assert trace["edge_slide:back_probe"] and trace["edge_slide:back_probe_precipice_slide"]
    assert trace["precipice_slide:normal_kept"]
    assert out.origin[2] == 20.5 and out.origin[0] < 102.5 and out.origin[1] == pytest.approx(97.0, abs=1e-4)  # slid along the edge


@pytest.mark.anchor("SPHEREPATH::precipice_slide")
def test_precipice_slide_on_the_crossed_edge_of_a_rotated_ledge():
    out, trace = matches_ace("ledge-rotated")
    assert trace["edge_slide:precipice_slide"] and trace["check_walkable:probe_fell"]
    assert out.origin[2] == 22.0


@pytest.mark.anchor("SPHEREPATH::precipice_slide")
def test_precipice_slide_turns_the_edge_normal_to_oppose_the_movement():
    _, trace = matches_ace("sampled-precipice-slide-normal-flipped")
    assert trace["precipice_slide:normal_flipped"]


@pytest.mark.anchor("SPHEREPATH::precipice_slide")
def test_precipice_slide_without_a_crossed_edge_collides():
    _, trace = matches_ace("sampled-precipice-slide-no-crossed-edge")
    assert trace["precipice_slide:no_crossed_edge"]


@pytest.mark.anchor("CTransition::edge_slide")
def test_without_edge_slide_the_mover_walks_off_the_platform():
    out, trace = matches_ace("platform-edge-no-edge-slide")
    assert not trace["edge_slide:precipice_slide"] and out.origin[0] == pytest.approx(103.0, abs=1e-4)


@pytest.mark.anchor("CTransition::check_walkable")
def test_check_walkable_probe_meets_ground():
    _, trace = matches_ace("sampled-check-walkable-probe-blocked")
    assert trace["check_walkable:probe_blocked"]


@pytest.mark.anchor("CTransition::edge_slide")
def test_edge_slide_with_a_walkable_contact_plane_still_valid():
    _, trace = matches_ace("sampled-edge-slide-contact-plane-still-valid")
    assert trace["edge_slide:contact_plane_valid"]


@pytest.mark.anchor("CTransition::transitional_insert")
def test_neg_poly_hit_slides_or_steps_up():
    _, slide = matches_ace("sampled-neg-poly-slide")
    assert slide["transitional_insert:neg_poly_slide"]
    _, step = matches_ace("sampled-neg-poly-step-up")
    assert step["transitional_insert:neg_poly_step_up"]


@pytest.mark.anchor("CTransition::transitional_insert")
def test_collide_path_lands_on_a_platform_from_the_air():
    out, trace = matches_ace("platform-landing")
    assert trace["transitional_insert:collide_landed"] and out.contact_plane.valid and out.origin[2] == 20.5


@pytest.mark.anchor("CTransition::transitional_insert")
def test_collide_path_resets_against_a_wall_in_the_air():
    out, trace = matches_ace("wall-airborne")
    assert trace["transitional_insert:collide_reset"] and out.collision_normal.valid


@pytest.mark.anchor("CTransition::step_down")
def test_step_down_placement_blocked_by_an_obstacle():
    _, trace = matches_ace("sampled-step-down-placement-blocked")
    assert trace["step_down:placement_blocked"]


@pytest.mark.anchor("CSphere::intersects_sphere")
def test_sphere_and_cylsphere_obstacles_stop_the_mover():
    for name in ("sphere-obstacle", "sphere-obstacle-glance", "cylsphere-obstacle", "sphere-airborne"):
        out, _ = matches_ace(name)
        assert out.origin[0] < 99.5, name


@pytest.mark.anchor("CObjCell::find_obj_collisions")
def test_a_wall_across_a_cell_border_blocks_from_the_neighbouring_cell():
    out, _ = matches_ace("objects-in-two-cells")
    assert out.origin[0] < 121.0 - 0.25


@pytest.mark.anchor("LScape::get_landblock")
def test_walking_into_a_landblock_the_scene_lacks_throws_building_the_empty_one_aces_dat_read_gives():
    out, _ = matches_ace("landblock-missing")
    assert out.error == "ArgumentOutOfRangeException: Height[0] of 0 heights"
    assert ace_outcome("landblock-missing").error.startswith("ArgumentOutOfRangeException: ")
