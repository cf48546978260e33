"""Sphere.cs and CylSphere.cs (port/geom): the double-precision spots, the -0.1 step limits,
touching versus intersecting, and the slide/land/step responses on a stand-in transition."""

from __future__ import annotations

import math

import numpy as np
import pytest

from acconform.flags import TransitionState
from acconform.numerics import EXACT, Plane, f32_bits
from acconform.port.constants import EPSILON, LANDING_Z
from acconform.port.geom import sphere as sph
from acconform.port.geom.cyl_sphere import CylSphere
from acconform.port.geom.sphere import Sphere, collides_with_sphere, find_time_of_collision
from acconform.port.vec import normalize_check_small

F = np.float32


def v(x, y, z):
    return EXACT.vec(x, y, z)


@pytest.mark.anchor("CSphere::find_time_of_collision")
def test_find_time_of_collision_finishes_in_double_after_the_square_root():
    m, p, r = v(2.54, 0.99, -2.04), v(-0.35, -0.36, 0.79), F(0.7)
    t = find_time_of_collision(m, p, r)
    assert type(t) is np.float64
    # ACE by hand: float32 up to nonCollideB, then Math.Sqrt and the rest in double
    dist_sq = m.length_squared()
    similar = -(p.x * m.x + p.y * m.y + p.z * m.z)
    b = similar * similar - (p.length_squared() - r * r) * dist_sq
    c = math.sqrt(float(b))
    want = -1 * (float(similar) - c) / float(dist_sq) if float(similar) - c >= 0 else -1 * (c + float(similar)) / float(dist_sq)
    assert float(t) == want
    # an all-float32 evaluation lands on another float32: the double spot matters here
    c32 = F(math.sqrt(b))
    t32 = -1 * (c32 + similar) / dist_sq if similar - c32 < 0 else -1 * (similar - c32) / dist_sq
    assert f32_bits(F(t)) != f32_bits(t32)


@pytest.mark.anchor("CSphere::find_time_of_collision")
def test_find_time_of_collision_returns_minus_one_without_movement_or_when_overlapping():
    assert find_time_of_collision(v(0, 0, 0), v(5, 0, 0), F(1)) == -1.0
    assert find_time_of_collision(v(1, 0, 0), v(0.5, 0, 0), F(1)) == -1.0  # already inside
    assert find_time_of_collision(v(0, 1, 0), v(5, 0, 0), F(1)) == -1.0  # passes wide
    assert type(find_time_of_collision(v(0, 0, 0), v(5, 0, 0), F(1))) is np.float64


@pytest.mark.anchor("CSphere::collides_with_sphere")
def test_collides_with_sphere_counts_touching_but_intersects_does_not():
    assert collides_with_sphere(v(2, 0, 0), F(2))
    assert not collides_with_sphere(v(2, 0, 0), np.nextafter(F(2), F(0)))
    a, b = Sphere(v(0, 0, 0), F(1)), Sphere(v(2, 0, 0), F(1))
    assert not a.intersects(b)
    assert a.intersects(Sphere(v(np.nextafter(F(2), F(0)), 0, 0), F(1)))


@pytest.mark.anchor("CSphere::step_sphere_down")
def test_step_sphere_limit_constant_is_minus_one_tenth_as_float32():
    assert f32_bits(sph.STEP_INTERP_LIMIT) == 0xBDCCCCCD


def _step_down(make_transition, step_down_amt):
    t = make_transition(step_down_amt=F(step_down_amt), num_sphere=1)
    check = Sphere(v(0, 0, 1.5), F(1))
    t.sphere_path.global_sphere = [check]
    radsum = F(1) + F(1) - F(EPSILON)
    state, disp = sph.step_sphere_down(v(0, 0, 0), F(1), t, check, v(0, 0, 1.5), radsum)
    return t, state, disp, radsum


@pytest.mark.anchor("CSphere::step_sphere_down")
def test_step_sphere_down_lands_on_top_with_a_double_square_root(make_transition):
    t, state, disp, radsum = _step_down(make_transition, 0.5)
    assert state == TransitionState.Adjusted
    r = radsum + F(EPSILON)
    val = math.sqrt(float(r * r - F(0)))  # Math.Sqrt: double
    scaled = F(val - float(F(1.5))) / F(0.5)
    interp = F(0.5) * scaled
    assert t.sphere_path.walk_interp == (F(1) - scaled) * F(1)
    assert t.sphere_path.offsets == [v(0, 0, interp)]
    assert disp == v(0, 0, F(1.5) + interp) * (F(1) / r)
    assert t.collision_info.contact_plane_is_water is True
    assert t.collision_info.contact_plane.normal == disp


@pytest.mark.anchor("CSphere::step_sphere_down")
def test_step_sphere_down_refuses_a_step_past_the_minus_one_tenth_limit(make_transition):
    # timecheck = 1 - 0.5/step: step 0.46 -> -0.087 (allowed), step 0.44 -> -0.136 (refused)
    assert _step_down(make_transition, 0.46)[1] == TransitionState.Adjusted
    t, state, _, _ = _step_down(make_transition, 0.44)
    assert state == TransitionState.Collided and t.sphere_path.offsets == []


@pytest.mark.anchor("CSphere::land_on_sphere")
def test_land_on_sphere_sets_collide_and_the_landing_allowance(make_transition):
    t = make_transition()
    t.sphere_path.global_curr_center = [Sphere(v(0, 0, 3), F(0.5))]
    assert sph.land_on_sphere(v(0, 0, 1), t) == TransitionState.Adjusted
    assert t.sphere_path.collide_normal == v(0, 0, 1)
    assert t.sphere_path.walkable_allowance == LANDING_Z and type(t.sphere_path.walkable_allowance) is np.float32


@pytest.mark.anchor("CSphere::slide_sphere")
def test_slide_sphere_with_a_zero_normal_moves_half_way_back_even_for_negative_zero(make_transition):
    t = make_transition()
    s = Sphere(v(2, 0, 0), F(0.5))
    state, normal = s.slide_sphere(t, v(-0.0, 0.0, -0.0), v(0, 0, 0))
    assert state == TransitionState.Adjusted and t.sphere_path.offsets == [v(-1, 0, 0)]
    assert t.collision_info.collision_normal is None


@pytest.mark.anchor("CSphere::slide_sphere")
def test_slide_sphere_slides_along_the_contact_plane_without_the_normal_component(make_transition):
    t = make_transition()
    t.collision_info.contact_plane_valid = True
    t.collision_info.contact_plane = Plane(v(0, 0, 1), F(0))
    s = Sphere(v(1, 1, 0), F(0.5))  # moved (1, 1, 0) from the origin
    state, normal = s.slide_sphere(t, v(1, 0, 0), v(0, 0, 0))
    # direction = cross((1,0,0), (0,0,1)) = (0,-1,0); offset = dir * dot(dir, gDelta) / 1 - gDelta
    assert state == TransitionState.Slid and normal == v(1, 0, 0)
    assert t.sphere_path.offsets == [v(-1, 0, 0)]


@pytest.mark.anchor("CSphere::slide_sphere")
def test_slide_sphere_into_the_contact_plane_returns_ok_and_rewrites_the_ref_normal(make_transition):
    t = make_transition()
    s = Sphere(v(0, 0, -2), F(0.5))
    # the normal parallel to the (last known, +z) contact plane's normal but opposed
    state, normal = s.slide_sphere(t, v(0, 0, -1), v(0, 0, 0))
    assert state == TransitionState.OK and normal == v(0, 0, 1)  # -gDelta, normalised
    assert t.collision_info.collision_normals == [v(0, 0, -1), v(0, 0, 1)]


@pytest.mark.anchor("CSphere::collide_with_point")
def test_collide_with_point_without_perfect_clip_reports_the_normalised_offset(make_transition):
    t = make_transition()
    t.sphere_path.global_curr_center = [Sphere(v(0, 0, 4), F(0.5))]
    assert sph.collide_with_point(v(0, 0, 1), t, Sphere(v(0, 0, 2), F(0.5)), F(1), 0) == TransitionState.Collided
    assert t.collision_info.collision_normal == v(0, 0, 1)


@pytest.mark.anchor("CSphere::intersects_sphere")
def test_intersects_sphere_placement_collides_on_touch_and_creatures_skip_step_down(make_transition):
    t = make_transition(insert_type=1)
    t.sphere_path.global_sphere = [Sphere(v(0, 0, 1), F(0.5))]
    assert sph.intersects_sphere(v(0, 0, 0), F(0.5) + F(EPSILON), t, False) == TransitionState.Collided
    assert sph.intersects_sphere(v(0, 0, -1), F(0.5), t, False) == TransitionState.OK
    t2 = make_transition(step_down=True)
    t2.sphere_path.global_sphere = [Sphere(v(0, 0, 1), F(0.5))]
    assert sph.intersects_sphere(v(0, 0, 0.5), F(0.5), t2, True) == TransitionState.OK


@pytest.mark.anchor("Vec::NormalizeCheckSmall")
def test_normalize_check_small_leaves_a_tiny_vector_and_scales_by_the_reciprocal():
    tiny = v(1e-4, 1e-4, 0)
    assert normalize_check_small(tiny) == (True, tiny)
    x = v(3, 7, 11)
    small, n = normalize_check_small(x)
    inv = F(1) / x.length()
    assert not small and n == v(F(3) * inv, F(7) * inv, F(11) * inv)


@pytest.mark.anchor("CCylSphere::collides_with_sphere")
def test_cylsphere_collides_with_a_sphere_touching_its_side_or_top():
    c = CylSphere(v(0, 0, 0), F(2), F(0.5))
    s = Sphere(v(0, 0, 0), F(0.5))
    radsum = F(1)
    assert c.collides_with_sphere(s, v(1, 0, 1), radsum)  # side, touching counts
    assert not c.collides_with_sphere(s, v(1.01, 0, 1), radsum)
    # top: reach is r - eps + h/2 above the middle
    top = F(0.5) - F(EPSILON) + F(1)
    assert c.collides_with_sphere(s, v(0, 0, F(1) + top), radsum)
    assert not c.collides_with_sphere(s, v(0, 0, np.nextafter(F(1) + top, F(9))), radsum)


@pytest.mark.anchor("CCylSphere::step_sphere_down")
def test_cylsphere_step_down_rests_the_sphere_on_the_top_face(make_transition):
    c = CylSphere(v(0, 0, 0), F(2), F(0.5))
    t = make_transition(step_down_amt=F(0.5))
    check = Sphere(v(0, 0, 2.3), F(0.5))
    t.sphere_path.global_sphere = [check]
    state = c.step_sphere_down(t, check, v(0, 0, 2.3), F(1) - F(EPSILON))
    deltaz = F(2) + F(0.5) - F(2.3)
    assert state == TransitionState.Adjusted
    assert t.sphere_path.offsets == [v(0, 0, deltaz)]
    assert t.sphere_path.walk_interp == (F(1) - deltaz / F(0.5)) * F(1)
    assert t.collision_info.contact_plane == Plane(v(0, 0, 1), -(F(2.3) + (deltaz - F(0.5))))
