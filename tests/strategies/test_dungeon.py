"""Dungeons are built the way the DAT's cells are (strategies/dungeon.py): both sides of every
portal agree, cell BSPs hold their cells, physics BSPs reach every polygon a sphere can touch,
polygons face into the cell, and the indoor policies all get drawn."""

from __future__ import annotations

import math
from collections import Counter

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from acconform.scene import validate_scene
from acconform.scene import BSPLeaf, CellBSPLeaf, OUTSIDE_CELL, PORTAL_SIDE_BIT, newell_normal
from acconform.strategies import sample_scenes
from acconform.strategies import dungeon as dg


@pytest.fixture(scope="module")
def indoor_scenes():
    return list(sample_scenes(("indoor",), 400, 12))


def _structs(scene):
    env = {e.id: e for e in scene.environments}
    return {c.id: env[c.environment].cell_structs[c.cell_structure] for c in scene.env_cells}


def _to_global(cell, p):
    q = cell.frame.orientation
    ang = 2 * math.atan2(q[3], q[0])
    c, s = math.cos(ang), math.sin(ang)
    o = cell.frame.origin
    return (o[0] + p[0] * c - p[1] * s, o[1] + p[0] * s + p[1] * c, o[2] + p[2])


def _unit(v):
    n = math.sqrt(sum(c * c for c in v))
    return tuple(c / n for c in v)


def test_both_sides_of_every_portal_name_each_other_and_share_the_doorway(indoor_scenes):
    crossed = 0
    for scene in indoor_scenes:
        cells = {c.id & 0xFFFF: c for c in scene.env_cells}
        structs = _structs(scene)
        for cell in scene.env_cells:
            st = structs[cell.id]
            assert [p.polygon for p in cell.portals] == list(st.portals)
            for k, portal in enumerate(cell.portals):
                if portal.other_cell == OUTSIDE_CELL:
                    continue
                other = cells[portal.other_cell]
                back = other.portals[portal.other_portal]
                assert back.other_cell == cell.id & 0xFFFF and back.other_portal == k
                assert back.flags & PORTAL_SIDE_BIT == portal.flags & PORTAL_SIDE_BIT
                mine = [_to_global(cell, v) for v in st.polygons[portal.polygon].vertices]
                theirs = [_to_global(other, v) for v in structs[other.id].polygons[back.polygon].vertices]
                for v in mine:  # the same doorway, bar a seam's step (dungeon.SEAM_DZ) and float32 frames
                    assert min(max(math.hypot(v[0] - w[0], v[1] - w[1]) / 2e-3, abs(v[2] - w[2]) / 0.011)
                               for w in theirs) < 1, (scene.name, v, theirs)
                n1 = _unit(newell_normal(mine))
                n2 = _unit(newell_normal(theirs))
                assert sum(a * b for a, b in zip(n1, n2)) < -0.999  # each faces its own way
                crossed += 1
    assert crossed >= len(indoor_scenes)


def test_a_portal_faces_the_neighbour_exactly_when_its_portal_side_bit_is_clear(indoor_scenes):
    sides = Counter()
    for scene in indoor_scenes:
        structs = _structs(scene)
        for cell in scene.env_cells:
            st = structs[cell.id]
            inside = (0.0, 0.0, 0.5)  # over the entry floor, in every piece
            for portal in cell.portals:
                poly = st.polygons[portal.polygon]
                plane = dg.plane_of(poly.vertices)
                faces_out = dg.plane_distance(plane, inside) < 0
                assert faces_out == (not portal.flags & PORTAL_SIDE_BIT)
                sides[faces_out] += 1
    assert sides[True] and sides[False]


def test_the_mover_starts_inside_its_cell_by_the_cell_bsp(indoor_scenes):
    for scene in (s for s in indoor_scenes if s.mover.placement is None):  # a placement moves the begin on purpose
        built_cells = {c.id: c for c in scene.env_cells}
        structs = _structs(scene)
        m = scene.mover
        cell = built_cells[m.begin.cell]
        q = cell.frame.orientation
        ang = -2 * math.atan2(q[3], q[0])
        o = m.begin.frame.origin
        dx, dy = o[0] - cell.frame.origin[0], o[1] - cell.frame.origin[1]
        local = (dx * math.cos(ang) - dy * math.sin(ang), dx * math.sin(ang) + dy * math.cos(ang),
                 o[2] + m.spheres[0].radius - cell.frame.origin[2])
        assert dg.point_inside(structs[cell.id].cell_bsp, local), scene.name


def test_a_cell_bsp_is_a_chain_of_inward_planes_with_no_leaf_on_it(indoor_scenes):
    for scene in indoor_scenes:
        for st in _structs(scene).values():
            node, depth = st.cell_bsp, 0
            while node is not None:
                assert not isinstance(node, CellBSPLeaf)
                assert dg.plane_distance(node.plane, (0.0, 0.0, 0.01)) > 0 or st.physics_polygons  # entry floor's centre
                node, depth = node.front, depth + 1
            assert depth == 6


def _sphere_touches(poly, c, r):
    """Brute force (doubles): does a sphere reach a convex polygon?"""
    verts = poly.vertices
    n = _unit(newell_normal(verts))
    d = sum(a * b for a, b in zip(n, c)) - sum(a * b for a, b in zip(n, verts[0]))
    if abs(d) > r:
        return False
    foot = tuple(ci - d * ni for ci, ni in zip(c, n))
    inside = True
    for i in range(len(verts)):
        a, b = verts[i], verts[(i + 1) % len(verts)]
        e = tuple(y - x for x, y in zip(a, b))
        w = tuple(y - x for x, y in zip(a, foot))
        cr = (e[1] * w[2] - e[2] * w[1], e[2] * w[0] - e[0] * w[2], e[0] * w[1] - e[1] * w[0])
        if sum(x * y for x, y in zip(cr, n)) < 0:
            inside = False
    if inside:
        return True
    best = math.inf
    for i in range(len(verts)):
        a, b = verts[i], verts[(i + 1) % len(verts)]
        e = tuple(y - x for x, y in zip(a, b))
        t = max(0.0, min(1.0, sum((ci - ai) * ei for ci, ai, ei in zip(c, a, e)) / sum(x * x for x in e)))
        best = min(best, math.dist(c, tuple(ai + t * ei for ai, ei in zip(a, e))))
    return best <= r


def _reached(node, c, r, out):
    """The polygons a physics BSP's sphere walk (BSPNode.sphere_intersects_poly) can visit."""
    if isinstance(node, BSPLeaf):
        out.update(node.polygons)
        return
    dist = sum(a * b for a, b in zip(node.plane.normal, c)) + node.plane.d
    reach = r - 0.0002
    if dist >= reach:
        _reached(node.front, c, r, out)
    elif dist <= -reach:
        _reached(node.back, c, r, out)
    else:
        _reached(node.front, c, r, out)
        _reached(node.back, c, r, out)


def test_the_physics_bsp_sends_every_sphere_to_every_polygon_it_touches(indoor_scenes):
    import random

    rnd = random.Random(5)
    touched = 0
    for scene in indoor_scenes[:60]:
        for st in _structs(scene).values():
            pts = [v for p in st.physics_polygons for v in p.vertices]
            lo = [min(p[i] for p in pts) for i in range(3)]
            hi = [max(p[i] for p in pts) for i in range(3)]
            for _ in range(30):
                c = tuple(rnd.uniform(a - 0.5, b + 0.5) for a, b in zip(lo, hi))
                r = rnd.choice((0.1, 0.3, 0.5, 1.0))
                out = set()
                _reached(st.physics_bsp, c, r, out)
                for i, poly in enumerate(st.physics_polygons):
                    if _sphere_touches(poly, c, r):
                        touched += 1
                        assert i in out, (scene.name, i, c, r)
    assert touched > 100


def test_every_physics_wall_faces_into_the_cell(indoor_scenes):
    for scene in indoor_scenes[:60]:
        for st in _structs(scene).values():
            for poly in st.physics_polygons:
                n = newell_normal(poly.vertices)
                if abs(n[2]) < 1e-9 * math.hypot(*n):  # a vertical wall, riser or ledge face
                    continue
                # floors face up, ceilings down: a horizontal polygon's normal is +-z
                assert abs(abs(_unit(n)[2]) - 1) < 1e-6 or n[2] > 0


def test_visible_cells_name_cells_of_the_dungeon_and_the_portal_neighbours_unless_left_out(indoor_scenes):
    missing = 0
    for scene in indoor_scenes:
        ids = {c.id & 0xFFFF for c in scene.env_cells}
        for cell in scene.env_cells:
            assert set(cell.visible_cells) <= ids - {cell.id & 0xFFFF}
            neighbours = {p.other_cell for p in cell.portals if p.other_cell != OUTSIDE_CELL}
            if not neighbours <= set(cell.visible_cells):
                missing += 1
            assert cell.seen_outside == any(p.other_cell == OUTSIDE_CELL for p in cell.portals)
    assert missing > 0


POLICY_NAMES = sorted(set(dg.POLICIES.elements))


@st.composite
def _policy_scenes(draw, policy):
    from acconform.strategies.scenes import MOVER_SPHERES, step_heights

    return dg.draw_indoor(draw, draw(MOVER_SPHERES), step_heights, policy)


@pytest.mark.parametrize("policy", POLICY_NAMES)
def test_every_indoor_policy_draws_valid_scenes_named_after_it(policy):
    @settings(max_examples=8, deadline=None, database=None, suppress_health_check=list(HealthCheck))
    @given(_policy_scenes(policy))
    def check(scene):
        assert scene.name.split(":")[1] == policy
        assert validate_scene(scene) == scene

    check()


def test_a_sample_draws_most_policies(indoor_scenes):
    policies = Counter(s.name.split(":")[1] for s in indoor_scenes)
    assert len(policies) >= len(POLICY_NAMES) - 3, policies


def test_exact_ramps_put_the_slope_on_floor_z_and_landing_z_bit_for_bit():
    from acconform.numerics import f32_bits
    from acconform.strategies import boundaries as bd

    names = {name for name, _ in dg.EXACT_RAMPS}
    assert {"floor_z", "landing_z"} <= names
    for name, (sx, sy, sz) in dg.EXACT_RAMPS:
        g = dg.cell_geometry(dg.Piece("ramp", sx, sy, 3.0, "ramp", sz), None, None, None)
        ramp = g.physics[0][0]
        assert bd.plane_normal_z_bits(ramp) == bd.Z_BOUNDARIES[name], (name, sx, sy, sz)
