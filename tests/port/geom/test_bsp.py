"""BSP (port/geom/bsp.py) built from a scene BSPShape's DAT record (as a run builds it): a floor square
split by its own plane, exercised through find_collisions' branches on a stand-in transition."""

from __future__ import annotations

import numpy as np
import pytest

from acconform.flags import ObjectInfoState, TransitionState
from acconform.numerics import EXACT, Plane
from acconform.port.geom.bsp import BSPLeaf, BSPTree, CELL_BSP_SLACK
from acconform.port.geom.sphere import Sphere
from acconform.numerics import f32_bits
from acconform.scene import BSPLeaf as LeafRec, BSPNode as NodeRec, BSPShape, PlaneRec, PolygonRec, SphereRec

from dat_shapes import bsp_tree

F = np.float32
FLOOR = PolygonRec(((-1.0, -1.0, 0.0), (1.0, -1.0, 0.0), (1.0, 1.0, 0.0), (-1.0, 1.0, 0.0)))
BIG = SphereRec((0.0, 0.0, 0.0), 3.0)


def v(x, y, z):
    return EXACT.vec(x, y, z)


def floor_tree():
    root = NodeRec(PlaneRec((0.0, 0.0, 1.0), 0.0), BIG, LeafRec((0,), False, BIG), LeafRec((), True, BIG))
    return bsp_tree(BSPShape((FLOOR,), root, BIG), EXACT)


def floor_polygon(tree):
    """The floor polygon as the front leaf holds it (each node that names a polygon has its own)."""
    return tree.root_node.pos_node.polygons[0]


def transition_at(make_transition, z, curr_z=None, **fields):
    t = make_transition(**fields)
    p = t.sphere_path
    p.local_space_sphere = [Sphere(v(0, 0, z), F(0.5))]
    p.local_space_curr_center = [Sphere(v(0, 0, z if curr_z is None else curr_z), F(0.5))]
    return t


@pytest.mark.anchor("BSPTREE::UnPack")
def test_tree_from_a_dat_record_maps_front_back_to_pos_neg_with_the_roots_sphere():
    tree = floor_tree()
    assert isinstance(tree.root_node.pos_node, BSPLeaf) and tree.root_node.pos_node.num_polys == 1
    assert not isinstance(tree.root_node, BSPLeaf) and tree.get_sphere() == Sphere(v(0, 0, 0), F(3))
    assert tree.root_node.neg_node.solid and tree.root_node.neg_node.num_polys == 0
    assert tree.root_node.splitting_plane == Plane(v(0, 0, 1), F(0))
    assert f32_bits(CELL_BSP_SLACK) == 0x3C23D70A


@pytest.mark.anchor("BSPTREE::find_collisions")
def test_placement_collides_with_a_sphere_through_the_floor_and_clears_above(make_transition):
    tree = floor_tree()
    assert tree.find_collisions(transition_at(make_transition, 0.2, insert_type=1), F(1)) == TransitionState.Collided
    assert tree.find_collisions(transition_at(make_transition, 0.6, insert_type=1), F(1)) == TransitionState.OK


@pytest.mark.anchor("BSPTREE::find_collisions")
def test_moving_up_off_a_touched_floor_still_sets_collide_through_the_hit_polygon(make_transition):
    """pos_hits_sphere returns false (moving away) but sets the polygon; find_collisions tests it."""
    tree = floor_tree()
    t = transition_at(make_transition, 0.3, curr_z=0.2)
    assert tree.find_collisions(t, F(1)) == TransitionState.Adjusted
    assert t.sphere_path.collide and t.sphere_path.collide_normal == v(0, 0, 1)


@pytest.mark.anchor("BSPTREE::find_collisions")
def test_contact_path_steps_up_on_a_hit(make_transition):
    tree = floor_tree()
    t = transition_at(make_transition, 0.2, curr_z=0.3)
    t.object_info.state = ObjectInfoState.Contact
    normals = []
    t.step_up = lambda n: normals.append(n) or True
    assert tree.find_collisions(t, F(1)) == TransitionState.OK and normals == [v(0, 0, 1)]


@pytest.mark.anchor("BSPTREE::step_sphere_down")
def test_step_down_rests_a_sinking_sphere_on_the_floor(make_transition):
    tree = floor_tree()
    t = transition_at(make_transition, 0.4, step_down=True, step_down_amt=F(0.5))
    assert tree.find_collisions(t, F(1)) == TransitionState.Adjusted
    i_dist = (F(0.4) - F(0.5)) / F(-0.5)
    assert t.sphere_path.walk_interp == F(1) - i_dist
    assert t.sphere_path.check_pos.frame.origin == v(0, 0, F(-0.5) * i_dist * F(-1))
    assert t.collision_info.contact_plane_valid and t.collision_info.contact_plane.normal == v(0, 0, 1)
    assert t.sphere_path.walkable[1] is floor_polygon(tree)


@pytest.mark.anchor("BSPTREE::check_walkable")
def test_check_walkable_collides_only_when_a_small_walkable_is_under_the_sphere(make_transition):
    tree = floor_tree()
    assert tree.find_collisions(transition_at(make_transition, 0.2, check_walkable=True), F(1)) == TransitionState.Collided
    t = make_transition(check_walkable=True)
    t.sphere_path.local_space_sphere = [Sphere(v(1.4, 0, 0.2), F(0.5))]  # 0.4 past the edge, small reach 0.25
    t.sphere_path.local_space_curr_center = [Sphere(v(1.4, 0, 0.2), F(0.5))]
    assert tree.find_collisions(t, F(1)) == TransitionState.OK


@pytest.mark.anchor("BSPTREE::placement_insert")
def test_placement_insert_pushes_a_sphere_behind_the_floor_out_through_the_back(make_transition):
    tree = floor_tree()
    t = transition_at(make_transition, -0.2)
    assert tree.placement_insert(t) == TransitionState.Adjusted
    diff = F(-0.5) - F(-0.2)  # solid check with dp <= 0: the radius flips
    assert t.sphere_path.offsets == [v(0, 0, (F(-0.2) + diff) - F(-0.2))]


@pytest.mark.anchor("BSPNODE::sphere_intersects_solid_poly")
def test_placement_insert_accepts_a_sphere_through_the_front_when_its_center_is_not_solid(make_transition):
    """An internal node returns centerSolid, not the leaf's hit, once a polygon is found."""
    tree = floor_tree()
    assert tree.placement_insert(transition_at(make_transition, 0.2)) == TransitionState.OK
    hit, center_solid, hit_poly = tree.root_node.sphere_intersects_solid_poly(
        Sphere(v(0, 0, 0.2), F(0.5)), F(0.5), False, None, True)
    assert (hit, center_solid, hit_poly) == (False, False, floor_polygon(tree))


@pytest.mark.anchor("BSPTREE::adjust_to_plane")
def test_collide_with_pt_with_perfect_clip_collides_because_adjust_to_plane_gives_up(make_transition):
    tree = floor_tree()
    t = transition_at(make_transition, 0.2, curr_z=0.8)
    t.object_info.state = ObjectInfoState.PathClipped | ObjectInfoState.PerfectClip
    assert tree.find_collisions(t, F(1)) == TransitionState.Collided
    assert t.collision_info.collision_normal is None  # set only after a successful adjust
