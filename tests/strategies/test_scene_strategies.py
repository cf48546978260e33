"""The scene strategies: valid by construction, float32-exact, deterministic, kind-restricted."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings

from acconform.errors import AcconformError
from acconform.scene import Scene, validate_scene
from acconform.strategies import ALL_KINDS, DEFAULT_KINDS, check_kinds, sample_scenes, scenes
from acconform.strategies import terrain as tr
from acconform.strategies.objects import EPS
from acconform.strategies.scenes import BLOCK
from strategy_records import floats_in

FAST = settings(max_examples=60, deadline=None, suppress_health_check=list(HealthCheck), database=None)


@FAST
@given(scenes(ALL_KINDS))
def test_generated_scenes_validate_and_round_trip_through_json_exactly(scene):
    again = validate_scene(scene)
    assert again == scene
    assert Scene.loads(scene.dumps()) == scene


@FAST
@given(scenes(ALL_KINDS))
def test_every_generated_float_is_an_exact_float32(scene):
    for x in floats_in(scene):
        assert float(np.float32(x)) == x


def test_sample_scenes_gives_the_same_scenes_for_the_same_seed():
    a = list(sample_scenes(None, 15, 7))
    b = list(sample_scenes(None, 15, 7))
    c = list(sample_scenes(None, 15, 8))
    assert len(a) == 15 and a == b
    assert a != c


def test_default_kinds_start_with_terrain_and_unknown_kinds_are_refused():
    assert DEFAULT_KINDS[0] == "terrain"
    assert check_kinds("bsp,obstacles") == ("bsp", "obstacles")
    with pytest.raises(AcconformError, match="unknown scene kind 'walls'"):
        check_kinds(["walls"])


def _shapes(o):
    """A static's shapes: its one shape, or each part's of its multi-part Setup."""
    return [o.shape] if o.shape is not None else [p.shape for p in o.setup.parts]


@pytest.mark.parametrize("kind,shape_kinds", [("terrain", set()), ("bsp", {"bsp"}), ("obstacles", {"sphere", "cylsphere"})])
def test_kinds_restrict_what_a_campaign_draws(kind, shape_kinds):
    for scene in sample_scenes((kind,), 25, 1):
        got = {shape.kind for o in scene.objects for shape in _shapes(o)}
        assert got <= shape_kinds
        if shape_kinds:
            assert got, "a bsp/obstacles scene has at least one object"


def test_floor_z_index_gradients_straddle_walkability_by_the_closest_margins():
    # i^2 + j^2 <= 182 is walkable with the default 2 m table; 181 and 185 are the nearest sums
    assert all(tr.walkable_index_gradient(i, j) for i, j in tr.STRADDLING_GRADIENTS[:6])
    assert not any(tr.walkable_index_gradient(i, j) for i, j in tr.STRADDLING_GRADIENTS[6:])
    for i in range(0, 20):
        for j in range(0, 20):
            assert tr.walkable_index_gradient(i, j) == (i * i + j * j <= 182)
    assert tr.walkable_index_gradient(13, 0) and not tr.walkable_index_gradient(14, 0)


def test_water_is_read_from_the_terrain_type_bits_like_surfchar():
    assert [t for t in range(32) if tr.is_water_word(t << 2)] == [0x10, 0x11, 0x12, 0x13, 0x14]
    assert tr.is_water_word((0x12 << 2) | 0x3 | (0x1F << 11))  # road and scenery bits ignored
    assert not tr.is_water_word(tr.GRASSLAND)


@pytest.mark.anchor("CLandBlockStruct::ConstructPolygons")
def test_split_direction_matches_the_ports_landblock_construction():
    from acconform.port.land import landblock as port_landblock
    from acconform.numerics import EXACT

    for bx, by in [(0x02, 0x03), (0xA9, 0xB4), (0x7F, 0x80), (0xFC, 0x11)]:
        rec = tr.Field(100, ()).landblock(bx, by)
        lb = port_landblock.Landblock(rec, tuple(2.0 * i for i in range(256)), EXACT)
        for cell in lb.land_cells.values():
            cell.polygons  # a land cell (and its SWtoNEcut entry) is built when first read
        ours = [tr.sw_to_ne_cut(bx, by, cx, cy) for cx in range(8) for cy in range(8)]
        assert ours == list(lb.sw_to_ne_cut)


@pytest.mark.anchor("CLandBlock::get_z")
def test_movers_on_the_ground_begin_at_the_ports_terrain_height():
    from acconform.numerics import EXACT
    from acconform.port.land.lscape import LScape

    checked = 0
    for scene in sample_scenes(("terrain",), 60, 3):
        m = scene.mover
        if m.contact_plane is None or m.placement is not None:  # a placement moves the begin on purpose
            continue
        ls = LScape(scene, EXACT)
        lb = ls.get_landblock(m.begin.cell)
        z = lb.get_z(ls, EXACT.vec(*m.begin.frame.origin))
        # on the ground, or a deliberate boundary offset (PLANE_DZ: up to 2 EPSILON either side)
        assert abs(float(z) - m.begin.frame.origin[2]) <= 1e-4 * max(1.0, abs(float(z))) + 2 * EPS
        checked += 1
    assert checked > 20


def test_a_mover_near_a_border_has_the_neighbouring_landblock():
    for scene in sample_scenes(("terrain",), 80, 4):
        defined = {lb.id >> 16 for lb in scene.landblocks}
        m = scene.mover
        reach = max(s.center[2] + s.radius for s in m.spheres) + 1.0
        bx, by = m.begin.cell >> 24, (m.begin.cell >> 16) & 0xFF
        x, y, _ = m.begin.frame.origin
        for dx in (-reach, 0.0, reach):
            for dy in (-reach, 0.0, reach):
                nbx, nby = bx + math.floor((x + dx) / BLOCK), by + math.floor((y + dy) / BLOCK)
                assert (nbx << 8 | nby) in defined
        assert m.end.cell >> 16 in defined


def test_bsp_shapes_have_outward_planes_and_covering_bounding_spheres():
    from acconform.scene import BSPLeaf, BSPNode

    seen = 0
    for scene in sample_scenes(("bsp",), 30, 2):
        for s in (shape for o in scene.objects for shape in _shapes(o)):
            if s.kind != "bsp":
                continue
            pts = [p for poly in s.polygons for p in poly.vertices]
            c, r = s.sphere.center, s.sphere.radius
            assert all(math.dist(c, p) <= r for p in pts)
            node = s.root

            def side(leaf):
                return [p for i in leaf.polygons for p in s.polygons[i].vertices]

            if isinstance(node, BSPNode) and isinstance(node.front, BSPLeaf) and node.front.polygons:
                # a split floor (shapes.split_floor): each leaf's polygons on its own side of the split
                n, d = node.plane.normal, node.plane.d
                assert all(n[0] * p[0] + n[1] * p[1] + n[2] * p[2] + d >= -1e-3 for p in side(node.front))
                assert all(n[0] * p[0] + n[1] * p[1] + n[2] * p[2] + d <= 1e-3 for p in side(node.back))
                seen += 1
                continue
            while not isinstance(node, BSPLeaf):
                n, d = node.plane.normal, node.plane.d
                assert all(n[0] * p[0] + n[1] * p[1] + n[2] * p[2] + d <= 1e-3 for p in pts)
                node = node.back
            assert node.polygons
            seen += 1
    assert seen > 10
