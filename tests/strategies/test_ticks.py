"""The tick strategies (strategies/ticks.py): valid tick scenes of every policy, every world, both
drivers, quantum-exact clocks and threshold velocities, solved sledding slopes; tick scenes through
houses (campaign kind ticks:buildings): in at the door, off the porch, down the cellar, along the shell."""

from __future__ import annotations

import math
from collections import Counter

import pytest

from acconform.numerics import f32_bits
from acconform.port.constants import HUGE_QUANTUM, MAX_QUANTUM, MAX_VELOCITY, MIN_QUANTUM, SLEDDING_FLAT_Z, SMALL_VELOCITY
from acconform.port.run import run_scene
from acconform.port.transition.branches import Trace
from acconform.scene import validate_scene
from acconform.strategies import ALL_KINDS, DEFAULT_KINDS, sample_scenes
from acconform.strategies import boundaries as bd
from acconform.strategies import ticks as tk
from acconform.oracle.recorded import geometry_kind, scene_kind

N = 300


@pytest.fixture(scope="module")
def tick_scenes():
    return list(sample_scenes(("ticks",), N, 20))


def test_tick_scenes_are_their_own_kind_in_every_default_campaign():
    assert "ticks" in ALL_KINDS and "ticks" in DEFAULT_KINDS


def test_every_tick_scene_validates_and_has_no_end_and_most_run_in_aces_server_mode(tick_scenes):
    for s in tick_scenes:
        assert validate_scene(s) == s
        assert s.mover.end is None and s.ticks.steps
        assert scene_kind(s) == "ticks" and geometry_kind(s) in ("terrain", "bsp", "obstacles", "indoor", "buildings")
    modes = Counter(s.engine_mode for s in tick_scenes)
    assert set(modes) == {"server", "client"} and modes["server"] > 2 * modes["client"], modes


def test_some_tick_scenes_give_the_movers_setup_a_default_script_or_a_resting_frame_most_neither(tick_scenes):
    scripts = [s.mover.default_script for s in tick_scenes if s.mover.default_script]
    resting = [s.mover.resting_frame for s in tick_scenes if s.mover.resting_frame is not None]
    assert 0 < len(scripts) < len(tick_scenes) // 3 and all(0x33000001 <= x <= 0x3300FFFF for x in scripts)
    assert 0 < len(resting) < len(tick_scenes) // 3 and len({f.origin for f in resting}) == 2
    assert all(s.format == "acconform.scene/8" for s in tick_scenes if s.mover.default_script or s.mover.resting_frame)


def test_tick_scenes_average_twenty_ticks_or_more(tick_scenes):
    assert sum(len(s.ticks.steps) for s in tick_scenes) / len(tick_scenes) >= 20


def test_every_policy_world_and_driver_is_drawn(tick_scenes):
    policies = Counter(s.name.split(":")[1].split("-")[0] for s in tick_scenes)
    assert set(policies) >= {"walk", "fall", "jump", "slide", "sled", "press", "cross", "portal", "velocity"}
    assert set(policies) & {"enter", "porch", "cellar", "shell"}  # through houses: each one below
    assert {geometry_kind(s) for s in tick_scenes} == {"terrain", "bsp", "obstacles", "indoor", "buildings"}
    assert {s.ticks.driver for s in tick_scenes} == {"update_object", "request_pos"}


def test_indoor_tick_scenes_hold_env_cells_and_statics():
    indoor = list(sample_scenes(("ticks:indoor",), 80, 19))
    assert all(s.env_cells for s in indoor) and any(any(o.position.cell & 0xFFFF >= 0x100 for o in s.objects) for s in indoor)


def test_every_clock_is_drawn_fixed_steps_at_each_rate(tick_scenes):
    assert {1 / 250, 1 / 60, 1 / 30, 1 / 10, 1 / 4} <= {s.dt for t in tick_scenes for s in t.ticks.steps}
    assert any(":irregular" in s.name for s in tick_scenes) and any(":quanta-" in s.name for s in tick_scenes)


def test_the_quantum_steps_are_the_quanta_as_doubles_and_one_ulp_either_side():
    q = dict(tk.QUANTA)
    for name, c in (("min_quantum", MIN_QUANTUM), ("max_quantum", MAX_QUANTUM), ("huge_quantum", HUGE_QUANTUM)):
        assert q[name] == float(c)
        assert q[f"{name}-1ulp"] == math.nextafter(float(c), 0) and q[f"{name}+1ulp"] == math.nextafter(float(c), 9)
    assert q["2max_quantum"] - float(MAX_QUANTUM) == float(MAX_QUANTUM)  # the loop leaves exactly MaxQuantum
    assert q["max_plus_min_quantum"] - float(MAX_QUANTUM) == float(MIN_QUANTUM)


def test_threshold_speeds_are_max_and_small_velocity_exactly_and_an_ulp_either_side():
    v = dict(tk.VELOCITY_SPEEDS)
    assert v["max_velocity"] == float(MAX_VELOCITY) and v["small_velocity"] == float(SMALL_VELOCITY)
    assert f32_bits(v["max_velocity+1ulp"]) - f32_bits(MAX_VELOCITY) == 1
    assert f32_bits(SMALL_VELOCITY) - f32_bits(v["small_velocity-1ulp"]) == 1


@pytest.mark.parametrize("name", sorted(bd.SLED_Z_BOUNDARIES))
def test_each_sledding_wedge_lands_on_its_normal_z_bits(name):
    for sx, sy, sz in bd.SLED_WEDGES[name]:
        assert bd.plane_normal_z_bits(bd.slope_polygon(sx, sy, sz)) == bd.SLED_Z_BOUNDARIES[name]


def test_the_sledding_terrain_rise_lands_on_the_threshold():
    assert bd.plane_normal_z_bits(bd.terrain_polygon(bd.SLED_TERRAIN_RISE)) == f32_bits(SLEDDING_FLAT_Z)


@pytest.mark.anchor("CPhysicsObj::update_object")
def test_the_tick_scenes_reach_the_tick_loops_branches_and_its_exact_boundaries(tick_scenes):
    seen = Counter()
    for s in tick_scenes:
        t = Trace()
        run_scene(s, trace=t, runtime="coreclr")
        seen.update(t.keys())
    for b in ("update_object:tick_rate_gate", "update_object:huge_quantum_skip", "update_object:max_quantum_step",
              "update_object:remainder_step", "update_object:remainder_kept", "calc_friction:sledding_glide",
              "calc_friction:sledding_stop", "handle_all_collisions:elastic_bounce",
              "boundary:tick_rate", "boundary:min_quantum", "boundary:huge_quantum", "boundary:sledding_flat_z"):
        assert seen[b], b


# ---------------------------------------------------------------- through houses (ticks:buildings)


HOUSE_POLICIES = ("walk", "enter", "porch", "cellar", "shell")


def _house_draws(policy: str, n: int, seed: int) -> list:
    """n tick scenes through houses of one policy, drawn as sample_scenes draws (seeded, generation only)."""
    from hypothesis import HealthCheck, Phase, given, settings
    from hypothesis import seed as hseed
    from hypothesis import strategies as st

    from acconform.strategies.determinism import pinned_constants

    out = []

    @hseed(seed)
    @settings(max_examples=n, database=None, phases=[Phase.generate], deadline=None,
              suppress_health_check=list(HealthCheck))
    @given(st.composite(lambda draw: tk.draw_tick_scene(draw, "buildings", policy))())
    def collect(scene):
        out.append(scene)

    with pinned_constants():
        collect()
    return out


@pytest.fixture(scope="module")
def house_scenes():
    """40 of each policy through a house, and 60 as a ticks:buildings campaign draws them."""
    return [s for p in HOUSE_POLICIES for s in _house_draws(p, 40, 20)] + list(sample_scenes(("ticks:buildings",), 60, 20))


def test_a_ticks_world_campaign_kind_draws_tick_scenes_over_that_world_only(house_scenes):
    for s in house_scenes:
        assert validate_scene(s) == s and s.mover.end is None
        assert scene_kind(s) == "ticks" and geometry_kind(s) == "buildings" and s.buildings
        assert s.mover.placement is None
    from acconform.strategies.motion import TARGET_ID

    for world in ("terrain", "indoor"):
        # a motion scene may gain a sphere to follow (a MoveTo's target): not the world's, so set aside
        kinds = {geometry_kind(s.replace(objects=tuple(o for o in s.objects if o.id != TARGET_ID)))
                 for s in sample_scenes((f"ticks:{world}",), 15, 3)}
        assert kinds == {world}


def test_every_house_policy_and_house_walk_is_drawn_over_ticks(house_scenes):
    drawn = Counter((s.name.split(":")[1], s.name.split(":")[3]) for s in house_scenes)
    assert {("enter", "in"), ("porch", "porch"), ("cellar", "hatch"), ("cellar", "cellar"), ("shell", "along"),
            ("shell", "wall")} <= set(drawn)
    assert {p for p, _ in drawn} == {"walk", "enter", "porch", "cellar", "shell", "motion"}
    walks = [s for s in house_scenes if s.name.split(":")[1] == "enter"]
    assert any(st.sequence_velocity for s in walks for st in s.ticks.steps)  # root motion through the door
    assert any(st.velocity for s in walks for st in s.ticks.steps)  # a velocity set toward it


def test_a_house_fall_walks_its_whole_path_and_a_second_more_without_root_motion(house_scenes):
    """Off the porch and into the cellar: ticks for the path at the drawn speed and a fall (up to 150),
    held velocity or a push (root motion's ground flags would hold the mover up), EdgeSlide mostly off."""
    falls = [s for s in house_scenes if s.name.split(":")[1] in ("porch", "cellar")]
    assert falls and not any(st.sequence_velocity for s in falls for st in s.ticks.steps)
    assert all(len(s.ticks.steps) <= tk.REACH_MAX_TICKS for s in falls)
    assert sum(":no-edge-slide" in s.name for s in falls) > len(falls) / 2


def test_the_cellar_hatch_is_a_pit_in_the_rooms_floor_the_mover_starts_in_the_room_short_of_it(house_scenes):
    hatches = [s for s in house_scenes if ":hatch" in s.name]
    assert hatches
    for s in hatches:
        room = s.env_cells[1]
        struct = s.environments[0].cell_structs[room.cell_structure]
        assert min(v[2] for p in struct.physics_polygons for v in p.vertices) < -0.4  # the cellar below the floor
        assert s.mover.begin.cell == room.id


@pytest.mark.anchor("CBuildingObj::find_building_transit_cells")
def test_tick_scenes_through_houses_reach_the_building_branches_and_fall_in_the_cellar(house_scenes):
    seen, fell = Counter(), Counter()
    for s in house_scenes:
        t = Trace()
        o = run_scene(s, trace=t, runtime="coreclr")
        seen.update(t.keys())
        zs = [k.origin[2] for k in o.ticks if k.cell]
        if zs and min(zs) < s.mover.begin.frame.origin[2] - 0.05:
            fell[s.name.split(":")[3]] += 1
    for b in ("building:collisions", "building:collided", "building:transit_cell", "env_cell:outside_portal",
              "find_cell_list:indoor", "update_object:remainder_step"):
        assert seen[b], b
    assert fell["hatch"] and fell["porch"]


def test_a_ticks_world_kind_names_a_known_world_and_is_supported_with_ticks_and_that_world():
    from acconform.errors import AcconformError
    from acconform.strategies import check_kinds, kind_supported

    assert check_kinds("ticks:buildings,terrain") == ("ticks:buildings", "terrain")
    with pytest.raises(AcconformError, match=r"unknown scene kind 'ticks:walls' .*ticks:<world>.*buildings"):
        check_kinds("ticks:walls")
    assert kind_supported("ticks:buildings", ("terrain", "buildings", "ticks"))
    assert not kind_supported("ticks:buildings", ("terrain", "buildings"))
    assert not kind_supported("ticks:buildings", ("terrain", "ticks"))
