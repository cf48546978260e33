"""strategies/boundaries.py: solved geometry lands on its threshold's bits through the port's
make_plane, for the wedge shape the strategies really build."""

import pytest

from acconform.numerics import f32_bits
from acconform.port.constants import FLOOR_Z, LANDING_Z
from acconform.strategies import boundaries as bd
from acconform.strategies import shapes as sh


def test_boundary_table_holds_each_threshold_and_the_ulp_either_side():
    assert bd.Z_BOUNDARIES["floor_z"] == f32_bits(FLOOR_Z) == 0x3F2A0751
    assert bd.Z_BOUNDARIES["landing_z"] == f32_bits(LANDING_Z) == 0x3DB27EB0
    for name in ("floor_z", "landing_z"):
        assert bd.Z_BOUNDARIES[f"{name}-1ulp"] == bd.Z_BOUNDARIES[name] - 1
        assert bd.Z_BOUNDARIES[f"{name}+1ulp"] == bd.Z_BOUNDARIES[name] + 1


@pytest.mark.anchor("CPolygon::make_plane")
@pytest.mark.parametrize("name", sorted(bd.Z_BOUNDARIES))
def test_every_solved_wedge_slope_has_exactly_the_target_normal_z(name):
    target = bd.Z_BOUNDARIES[name]
    wedges = bd.exact_wedges(target)
    assert len(wedges) >= 10, f"too few ramp sizes reach {name}: {len(wedges)}"
    for sx, sy, sz in wedges:
        slope = sh.wedge(sx, sy, sz).polygons[0]
        assert slope.vertices == bd.slope_polygon(sx, sy, sz).vertices
        assert bd.plane_normal_z_bits(slope) == target, (name, sx, sy, sz)


@pytest.mark.anchor("CPolygon::make_plane")
def test_a_rise_one_ulp_off_the_solution_misses_the_floor_z_target():
    # the search finds a real knife edge, not a value that any nearby rise would give
    sx, sy, sz = bd.exact_wedges(bd.Z_BOUNDARIES["floor_z"])[0]
    from acconform.numerics import f32_from_bits
    misses = [bd.plane_normal_z_bits(bd.slope_polygon(sx, sy, f32_from_bits(f32_bits(sz) + k))) != bd.Z_BOUNDARIES["floor_z"]
              for k in (-8, 8)]
    assert all(misses)


@pytest.mark.anchor("CLandBlockStruct::ConstructPolygons")
@pytest.mark.parametrize("axis", [(1, 0), (-1, 0), (0, 1), (0, -1)])
def test_a_solved_land_height_table_gives_every_triangle_of_the_rise_the_target_normal_z(axis):
    # checked through the port's own landblock construction (both diagonal cuts occur along the rise)
    from acconform.numerics import EXACT
    from acconform.port.land.landblock import Landblock
    from acconform.strategies import terrain as tr

    ax, ay = axis
    targets = bd.exact_terrain_targets()
    assert {name for name, _ in targets} >= {"landing_z", "floor_z-1ulp", "floor_z+1ulp"}
    for name, rise in targets:
        field = tr.Field(0, (tr.Feature("step", a=-ax, b=-ay, c=-(ax * 4 + ay * 4), k=1),))
        rec = field.landblock(0, 0)
        lb = Landblock(rec, bd.exact_slope_table(rise), EXACT)
        for cell in lb.land_cells.values():
            cell.polygons  # a land cell (and its polygons) is built when first read
        sloped = [p for p in lb.polygons if len({float(v.origin.z) for v in p.vertices}) > 1]
        assert len(sloped) == 2 * 8, (name, len(sloped))  # one row of 8 cells, two triangles each
        assert {f32_bits(p.plane.normal.z) for p in sloped} == {bd.Z_BOUNDARIES[name]}, name


def test_floor_z_itself_is_out_of_reach_of_a_one_cell_terrain_rise():
    # normalize skips it: the rises one ulp apart give FloorZ - 1 ulp and FloorZ + 1 ulp
    assert "floor_z" not in dict(bd.exact_terrain_targets())


@pytest.mark.anchor("CTransition::step_down")
def test_an_exact_slope_scene_makes_step_down_compare_landing_z_bit_for_bit():
    import importlib

    from hypothesis import HealthCheck, find, settings
    from hypothesis import strategies as st

    from acconform.commands.record import hits_boundary
    from acconform.port.run import run_scene
    from acconform.port.transition.branches import Trace

    scenes = importlib.import_module("acconform.strategies.scenes")

    @st.composite
    def landing_slopes(draw):
        return scenes._exact_slope_scene(draw, 100, 100, draw(scenes.MOVER_SPHERES))

    def hits(scene):
        trace = Trace()
        run_scene(scene, trace=trace)
        return scene.name.endswith("landing_z") and trace["boundary:landing_z"] > 0

    scene = find(landing_slopes(), hits, settings=settings(database=None, max_examples=400, derandomize=True,
                                                           suppress_health_check=list(HealthCheck)))
    assert scene.land_height_table[1] == dict(bd.exact_terrain_targets())["landing_z"]
    assert hits_boundary(scene)


def test_a_level_walk_hits_no_boundary_for_record_boundaries():
    from acconform.commands.record import hits_boundary
    from acconform.scene import ContactPlane, Frame, Landblock, Mover, PlaneRec, Position, Scene, SphereRec

    cell = 0x64640000 | 1 + 3 * 8 + 3
    mover = Mover(spheres=(SphereRec((0.0, 0.0, 0.5), 0.5),), begin=Position(cell, Frame((80.0, 80.0, 20.0))),
                  end=Position(cell, Frame((81.0, 80.0, 20.0))), step_up_height=0.4, step_down_height=0.4, state=0x400,
                  transient_state=0x3, contact_plane=ContactPlane(cell, PlaneRec((0.0, 0.0, 1.0), -20.0)))
    scene = Scene((Landblock(0x6464FFFF, (10,) * 81, (4,) * 81),), mover)
    assert not hits_boundary(scene)


@pytest.mark.anchor("CSphere::step_sphere_down")
@pytest.mark.anchor("SPHEREPATH::is_walkable_allowable")
@pytest.mark.parametrize("entry", bd.SPHERE_CONTACTS, ids=lambda e: f"{e[0]}-r{e[1]}-R{e[2]:.4f}")
def test_every_solved_sphere_contact_hits_its_threshold_exactly_wherever_it_is_moved_on_the_grid(entry, monkeypatch):
    import importlib

    from hypothesis import HealthCheck, given, settings
    from hypothesis import strategies as st

    from acconform.port.run import run_scene
    from acconform.port.transition.branches import Trace

    scenes = importlib.import_module("acconform.strategies.scenes")
    boundary = "floor_z" if entry[0] == "walk" else "landing_z"

    @st.composite
    def moved(draw):
        return scenes._sphere_contact_scene(draw, 100, 100)

    @settings(max_examples=12, database=None, deadline=None, derandomize=True, suppress_health_check=list(HealthCheck))
    @given(moved())
    def check(scene):
        trace = Trace()
        run_scene(scene, trace=trace)
        assert trace["boundary:" + boundary] >= 1, scene.name

    monkeypatch.setattr(scenes, "SPHERE_CONTACTS", st.just(entry))
    check()


def _drawn(composite, n: int, seed: int):
    """n scenes drawn from a composite strategy (Hypothesis' engine, generation only)."""
    from hypothesis import HealthCheck, Phase, given, settings
    from hypothesis import seed as hseed

    out = []

    @hseed(seed)
    @settings(max_examples=n, database=None, phases=[Phase.generate], deadline=None,
              suppress_health_check=list(HealthCheck))
    @given(composite)
    def collect(scene):
        out.append(scene)

    collect()
    return out


def _traced(scene):
    from acconform.port.run import run_scene
    from acconform.port.transition.branches import Trace

    trace = Trace()
    run_scene(scene, trace=trace)
    return trace


@pytest.mark.parametrize("r", bd.TOUCH_RADS + tuple(c[0] for c in bd.TOUCH_CORNERS))
def test_a_touch_radius_less_epsilon_is_its_grid_value_in_float32(r):
    import numpy as np

    from acconform.port.constants import EPSILON

    radius = bd.touch_radius(r)
    assert float(np.float32(radius) - np.float32(EPSILON)) == r and bd.on_grid(r)


def test_every_touch_corner_is_a_float32_pythagorean_triple():
    import numpy as np

    f = np.float32
    for rad, a, b in bd.TOUCH_CORNERS:
        assert f(a) * f(a) + f(b) * f(b) == f(rad) * f(rad), (rad, a, b)


@pytest.mark.anchor("CPolygon::polygon_hits_sphere_precise")
def test_every_touch_scene_makes_the_polygon_test_compare_at_equality():
    import importlib

    from hypothesis import strategies as st

    scenes = importlib.import_module("acconform.strategies.scenes")
    drawn = _drawn(st.composite(lambda draw: scenes._touch_scene(draw, 0x20, 0x30))(), 45, 3)
    want = {"face": "plane_tangent", "edge": "polygon_edge", "vertex": "polygon_vertex"}
    seen = set()
    from acconform.strategies.objects import BSP_STATE

    for scene in drawn:
        if scene.objects[0].state != BSP_STATE:  # ethereal, ignored or without a physics BSP: no polygon test
            continue
        how = scene.name.rsplit("-", 1)[1]
        seen.add(how)
        assert _traced(scene)["boundary:" + want[how]] > 0, (scene.name, scene)
    assert seen == set(want)


@pytest.mark.anchor("CSphere::step_sphere_up")
@pytest.mark.anchor("CCylSphere::step_sphere_up")
def test_a_tangent_scene_with_the_exact_step_up_makes_step_sphere_up_compare_at_equality():
    import importlib

    from hypothesis import strategies as st

    scenes = importlib.import_module("acconform.strategies.scenes")
    world = scenes._World(scenes.tr.Field(30, (), 0, 0, 1))

    @st.composite
    def exact(draw):
        scene = scenes._tangent_scene(draw, world, 0x20, 0x30, draw(scenes.MOVER_SPHERES))
        o, m = scene.objects[0], scene.mover
        height = getattr(o.shape, "height", 0.0)
        kind = "sphere" if "sphere" == scene.name.rsplit("-", 1)[1] else "cylsphere"
        up = bd.tangent_step_up(kind, m.spheres[0].radius, o.shape.radius if kind == "cylsphere" else
                                o.shape.sphere.radius, height, m.begin.frame.origin[2])
        return scene, kind, up == m.step_up_height

    kinds = set()
    for scene, kind, is_exact in _drawn(exact(), 80, 4):
        if is_exact:
            kinds.add(kind)
            assert _traced(scene)["boundary:step_up_height"] > 0, scene
    assert kinds == {"sphere", "cylsphere"}


@pytest.mark.anchor("CTransition::transitional_insert")
def test_an_exact_slope_walk_with_a_step_down_of_exactly_2r_compares_them_at_equality():
    import importlib

    from hypothesis import strategies as st

    scenes = importlib.import_module("acconform.strategies.scenes")
    drawn = _drawn(st.composite(lambda draw: scenes._exact_slope_scene(draw, 0x20, 0x30, draw(scenes.MOVER_SPHERES)))(),
                   60, 5)
    exact = [s for s in drawn if s.mover.step_down_height == 2 * s.mover.spheres[0].radius
             and s.mover.contact_plane is not None and "floor_z" in s.name]
    assert exact, "no walkable-side exact slope walk with a step-down of 2r drawn"
    assert any(_traced(s)["boundary:step_down_height"] for s in exact)
