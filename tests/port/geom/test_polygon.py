"""Polygon.cs (port/geom/polygon.py): hand-checked planes, edge tests and the distinctions ACE's
code makes (a point on an edge is inside, a sphere tangent at radius - EPSILON touches, zero-length
edges are skipped, the -0.5 walk interpolation limit, pos_hits_sphere's hit polygon on a miss)."""

from __future__ import annotations

import numpy as np
import pytest

from acconform.flags import CullMode
from acconform.numerics import EXACT, FAST, D, f32_bits
from acconform.port.constants import EPSILON, FLOOR_Z
from acconform.port.geom.polygon import ADJUST_TO_PLANE_INTERP_LIMIT, Polygon, Sidedness, Vertex
from acconform.port.geom.sphere import Sphere
from acconform.scene import PolygonRec

F = np.float32
SQUARE = ((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (1.0, 1.0, 0.0), (0.0, 1.0, 0.0))  # CCW seen from +z


def v(x, y, z):
    return EXACT.vec(x, y, z)


def poly(points=SQUARE, mode=EXACT):
    return Polygon.from_rec(PolygonRec(tuple(points)), mode)


def sphere(x, y, z, r):
    return Sphere(v(x, y, z), F(r))


class Path:
    def __init__(self, walk_interp=1.0, walkable_allowance=FLOOR_Z):
        self.walk_interp = F(walk_interp)
        self.walkable_allowance = F(walkable_allowance)
        self.trace = None


@pytest.mark.anchor("CPolygon::make_plane")
def test_make_plane_of_a_counter_clockwise_square_faces_up_through_its_vertices():
    p = poly([(x, y, 2.0) for x, y, _ in SQUARE])
    assert p.plane.normal == v(0, 0, 1)
    assert p.plane.d == -2.0 and type(p.plane.d) is np.float32


@pytest.mark.anchor("CPolygon::make_plane")
def test_terrain_constructor_then_make_plane_matches_the_record_constructor():
    p = Polygon(7, 3, CullMode.Landblock)
    assert p.poly_id == 7 and p.vertex_ids == [-1, -1, -1] and p.vertices == [None, None, None]
    for i, pt in enumerate([(0, 0, 0), (24, 0, 4), (24, 24, 8)]):
        p.vertices[i] = Vertex(v(*pt), index=i)
        p.vertex_ids[i] = i
    p.make_plane()
    q = poly([(0, 0, 0), (24, 0, 4), (24, 24, 8)])
    assert p.plane == q.plane
    # normal of (24,0,4) x (24,24,8) = (-96, -96, 576), normalised by its length sqrt(350208)
    n = [F(x) / F(np.sqrt(F(350208))) for x in (-96, -96, 576)]
    assert [f32_bits(c) for c in p.plane.normal] == [f32_bits(c) for c in n]


@pytest.mark.anchor("CPolygon::make_plane")
def test_make_plane_in_fast_mode_computes_in_double():
    p = poly(mode=FAST)
    assert type(p.plane.d) is np.float64 and p.plane.normal == FAST.vec(0, 0, 1)


@pytest.mark.anchor("CPolygon::find_crossed_edge")
def test_find_crossed_edge_counts_a_point_on_an_edge_as_inside():
    found, normal = poly().find_crossed_edge(sphere(0.0, 0.5, 3.0, 0.5), v(0, 0, 1), v(9, 9, 9))
    assert not found and normal == v(9, 9, 9)  # the ref normal is left untouched


@pytest.mark.anchor("CPolygon::find_crossed_edge")
def test_find_crossed_edge_returns_the_inward_unit_normal_of_the_edge_crossed():
    # the edge (0,1)->(0,0): cross((0,0,1), (0,-1,0)) = (1,0,0)
    found, normal = poly().find_crossed_edge(sphere(-0.5, 0.5, 3.0, 0.5), v(0, 0, 1), v(0, 0, 0))
    assert found and normal == v(1, 0, 0)


@pytest.mark.anchor("CPolygon::find_crossed_edge")
def test_find_crossed_edge_is_false_for_an_up_vector_parallel_to_the_plane():
    found, _ = poly().find_crossed_edge(sphere(-5, 0.5, 0, 0.5), v(1, 0, 0), v(0, 0, 0))
    assert not found


@pytest.mark.anchor("CPolygon::find_crossed_edge")
def test_zero_length_edges_are_skipped_by_every_edge_walk():
    dup = poly([SQUARE[0], SQUARE[1], SQUARE[1], SQUARE[2], SQUARE[3]])
    ref = poly()
    assert dup.plane == ref.plane
    for pt in [(0.5, 0.5), (1.0, 0.5), (1.2, 0.5), (0.5, -0.3)]:
        s = sphere(pt[0], pt[1], 0.2, 0.5)
        assert dup.find_crossed_edge(s, v(0, 0, 1), v(0, 0, 0)) == ref.find_crossed_edge(s, v(0, 0, 1), v(0, 0, 0))
        assert dup.polygon_hits_sphere_precise(s, v(0, 0, 0)) == ref.polygon_hits_sphere_precise(s, v(0, 0, 0))
        assert dup.point_in_polygon(v(pt[0], pt[1], 0)) == ref.point_in_polygon(v(pt[0], pt[1], 0))


@pytest.mark.anchor("CPolygon::point_in_polygon")
def test_point_in_polygon_counts_edges_and_corners_as_inside():
    p = poly()
    assert p.point_in_polygon(v(1.0, 0.5, 0)) and p.point_in_polygon(v(1, 1, 0))
    assert not p.point_in_polygon(v(1.0001, 0.5, 0))


@pytest.mark.anchor("CPolygon::point_in_poly2D")
def test_point_in_poly2d_sides_are_mirror_images():
    p = poly()
    # counter-clockwise (as terrain polygons are): inside for the Positive side, which
    # LandCell.find_terrain_poly asks; edge (0,0)->(0,1) gives 1*0 - 0 + 0 - 1*0.5 = -0.5 <= 0
    assert p.point_in_poly2D(v(0.5, 0.5, 0), Sidedness.Positive)
    assert not p.point_in_poly2D(v(0.5, 0.5, 0), Sidedness.Negative)
    assert p.point_in_poly2D(v(0.0, 0.5, 0), Sidedness.Positive)  # on an edge: 0, not > 0
    assert not p.point_in_poly2D(v(-0.01, 0.5, 0), Sidedness.Positive)
    cw = poly(list(reversed(SQUARE)))
    assert cw.point_in_poly2D(v(0.5, 0.5, 0), Sidedness.Negative)
    assert not cw.point_in_poly2D(v(0.5, 0.5, 0), Sidedness.Positive)


@pytest.mark.anchor("CPolygon::polygon_hits_sphere_precise")
def test_sphere_reaching_the_plane_at_radius_minus_epsilon_touches_and_one_ulp_further_does_not():
    p = poly()
    rad = F(0.5) - F(EPSILON)  # what the routine compares against
    hit, contact = p.polygon_hits_sphere_precise(sphere(0.5, 0.5, rad, 0.5), v(0, 0, 0))
    assert hit and contact == v(0.5, 0.5, 0)
    further = np.nextafter(rad, F(1))
    hit, contact = p.polygon_hits_sphere_precise(sphere(0.5, 0.5, further, 0.5), v(7, 7, 7))
    assert not hit and contact == v(7, 7, 7)  # untouched when the plane is out of reach


@pytest.mark.anchor("CPolygon::polygon_hits_sphere_precise")
def test_sphere_exactly_tangent_to_the_plane_does_not_touch():
    hit, _ = poly().polygon_hits_sphere_precise(sphere(0.5, 0.5, 0.5, 0.5), v(0, 0, 0))
    assert not hit


@pytest.mark.anchor("CPolygon::polygon_hits_sphere_precise")
def test_sphere_beside_an_edge_touches_within_reach_of_it_and_misses_beyond():
    p = poly()
    # contact point (1.3, 0.5, 0): 0.3 outside the edge x = 1, inside the disc of radius
    # sqrt((0.5 - eps)^2 - 0.1^2) ~ 0.4898
    assert p.polygon_hits_sphere_precise(sphere(1.3, 0.5, 0.1, 0.5), v(0, 0, 0))[0]
    assert not p.polygon_hits_sphere_precise(sphere(1.5, 0.5, 0.1, 0.5), v(0, 0, 0))[0]
    # the corner region: (1.3, 1.3) is 0.42 from the corner (1, 1)
    assert p.polygon_hits_sphere_precise(sphere(1.3, 1.3, 0.1, 0.5), v(0, 0, 0))[0]
    assert not p.polygon_hits_sphere_precise(sphere(1.4, 1.4, 0.1, 0.5), v(0, 0, 0))[0]


@pytest.mark.anchor("CPolygon::polygon_hits_sphere")
def test_polygon_hits_sphere_agrees_with_the_precise_test_on_simple_cases():
    p = poly()
    for c in [(0.5, 0.5, 0.1), (1.3, 0.5, 0.1), (1.5, 0.5, 0.1), (1.3, 1.3, 0.1), (1.4, 1.4, 0.1), (0.5, 0.5, 0.6)]:
        s = sphere(*c, 0.5)
        assert p.polygon_hits_sphere(s, v(0, 0, 0)) == p.polygon_hits_sphere_precise(s, v(0, 0, 0))


@pytest.mark.anchor("CPolygon::pos_hits_sphere")
def test_pos_hits_sphere_sets_the_hit_polygon_even_when_moving_away_returns_false():
    p = poly()
    s = sphere(0.5, 0.5, 0.2, 0.5)
    hit, contact, hit_poly = p.pos_hits_sphere(s, v(0, 0, 1), v(0, 0, 0), None)
    assert not hit and hit_poly is p and contact == v(0.5, 0.5, 0)
    hit, _, hit_poly = p.pos_hits_sphere(s, v(0, 0, 0), v(0, 0, 0), None)  # no movement: dot 0 >= 0
    assert not hit and hit_poly is p


@pytest.mark.anchor("CPolygon::pos_hits_sphere")
def test_pos_hits_sphere_hits_when_moving_into_the_front_face_and_keeps_an_earlier_polygon_on_a_miss():
    p = poly()
    hit, _, hit_poly = p.pos_hits_sphere(sphere(0.5, 0.5, 0.2, 0.5), v(0, 0, -1), v(0, 0, 0), None)
    assert hit and hit_poly is p
    earlier = poly()
    hit, _, hit_poly = p.pos_hits_sphere(sphere(5, 5, 0.2, 0.5), v(0, 0, -1), v(0, 0, 0), earlier)
    assert not hit and hit_poly is earlier


@pytest.mark.anchor("CPolygon::walkable_hits_sphere")
def test_walkable_hits_sphere_needs_the_slope_strictly_above_the_allowance():
    flat = poly()
    s = sphere(0.5, 0.5, 0.2, 0.5)
    assert flat.walkable_hits_sphere(Path(), s, v(0, 0, 1))
    assert not flat.walkable_hits_sphere(Path(walkable_allowance=1.0), s, v(0, 0, 1))  # dp == allowance


@pytest.mark.anchor("CPolygon::adjust_sphere_to_plane")
def test_adjust_sphere_to_plane_accepts_interp_at_exactly_minus_one_half():
    assert f32_bits(ADJUST_TO_PLANE_INTERP_LIMIT) == 0xBF000000
    p = poly()
    path = Path()
    s = sphere(0.5, 0.5, 0.5, 2.0)  # dist = 0.5 - 2 = -1.5, iDist = 1.5, interp = -0.5
    assert p.adjust_sphere_to_plane(path, s, v(0, 0, -1))
    assert path.walk_interp == -0.5 and s.center == v(0.5, 0.5, 2.0)


@pytest.mark.anchor("CPolygon::adjust_sphere_to_plane")
def test_adjust_sphere_to_plane_rejects_interp_below_minus_one_half_and_leaves_the_sphere():
    p = poly()
    path = Path()
    s = sphere(0.5, 0.5, 0.25, 2.0)  # iDist = 1.75, interp = -0.75
    assert not p.adjust_sphere_to_plane(path, s, v(0, 0, -1))
    assert path.walk_interp == 1.0 and s.center == v(0.5, 0.5, 0.25)


@pytest.mark.anchor("CPolygon::adjust_sphere_to_plane")
def test_adjust_sphere_to_plane_refuses_movement_along_the_plane_and_no_progress():
    p = poly()
    assert not p.adjust_sphere_to_plane(Path(), sphere(0.5, 0.5, 0.2, 0.5), v(1, 0, 0))  # |dpMove| <= EPSILON
    # sphere above its reach: dist = 0.7 - 0.5 > 0, iDist < 0, interp > walk_interp
    assert not p.adjust_sphere_to_plane(Path(), sphere(0.5, 0.5, 0.7, 0.5), v(0, 0, -1))


@pytest.mark.anchor("CPolygon::adjust_sphere_to_plane")
def test_adjust_sphere_to_plane_moves_a_sinking_sphere_back_to_rest_on_the_plane():
    p = poly()
    path = Path()
    s = sphere(0.5, 0.5, 0.4, 0.5)
    assert p.adjust_sphere_to_plane(path, s, v(0, 0, -0.5))
    i_dist = (F(0.4) - F(0.5)) / F(-0.5)
    assert path.walk_interp == (F(1) - i_dist) * F(1)
    assert s.center == v(0.5, 0.5, F(0.4) - F(-0.5) * i_dist)


@pytest.mark.anchor("CPolygon::adjust_sphere_to_poly")
def test_adjust_sphere_to_poly_returns_a_double_one_when_already_touching():
    p = poly()
    t = p.adjust_sphere_to_poly(sphere(0, 0, 0, 0.5), v(0.5, 0.5, 0.3), v(0, 0, -1))
    assert t == 1.0 and type(t) is np.float64
    t = p.adjust_sphere_to_poly(sphere(0, 0, 0, 0.5), v(0.5, 0.5, 2.0), v(0, 0, -4))
    assert type(t) is np.float64 and t == D((F(0.5) - F(2.0)) / F(-4))
    # a short move (|m|^2 <= r^2) flips the target distance to the back face
    t = p.adjust_sphere_to_poly(sphere(0, 0, 0, 0.5), v(0.5, 0.5, 2.0), v(0, 0, -0.25))
    assert t == D((F(-0.5) - F(2.0)) / F(-0.25))


@pytest.mark.anchor("CPolygon::adjust_to_placement_poly")
def test_adjust_to_placement_poly_pushes_both_spheres_out_the_front_or_through_the_back():
    p = poly()
    a, b = sphere(0.5, 0.5, 0.2, 0.5), sphere(0.5, 0.5, 1.0, 0.5)
    p.adjust_to_placement_poly(a, b, F(0.5), False, True)
    assert a.center == v(0.5, 0.5, 0.5) and b.center == v(0.5, 0.5, F(1.0) + (F(0.5) - F(0.2)))
    c = sphere(0.5, 0.5, 0.2, 0.5)
    p.adjust_to_placement_poly(c, None, F(0.5), True, True)  # center solid: radius flips
    assert c.center == v(0.5, 0.5, -0.5)


@pytest.mark.anchor("CPolygon::check_walkable")
def test_check_small_walkable_quarters_the_squared_radius():
    p = poly()
    s = sphere(1.4, 0.5, 0.0, 0.5)  # 0.4 outside the edge x = 1
    assert p.check_walkable(s, v(0, 0, 1))
    assert not p.check_small_walkable(s, v(0, 0, 1))  # reach 0.25
    assert p.check_small_walkable(sphere(1.2, 0.5, 0.0, 0.5), v(0, 0, 1))
    assert not p.check_walkable(s, v(0, 0, -1))  # facing away from up


@pytest.mark.anchor("CPolygon::hits_sphere")
def test_hits_sphere_ignores_the_side_the_sphere_is_on():
    p = poly()
    assert p.hits_sphere(sphere(0.5, 0.5, 0.2, 0.5)) and p.hits_sphere(sphere(0.5, 0.5, -0.2, 0.5))
    assert not p.hits_sphere(sphere(0.5, 0.5, 0.6, 0.5))
