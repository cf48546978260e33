"""The tick strategies (strategies/ticks.py): valid tick scenes of every policy, every world, both
drivers, quantum-exact clocks and threshold velocities, solved sledding slopes."""

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
    return list(sample_scenes(("ticks",), N, 19))


def test_tick_scenes_are_their_own_kind_in_every_default_campaign():
    assert "ticks" in ALL_KINDS and "ticks" in DEFAULT_KINDS


def test_every_tick_scene_validates_runs_in_client_mode_and_has_no_end(tick_scenes):
    for s in tick_scenes:
        assert validate_scene(s) == s
        assert s.engine_mode == "client" and s.mover.end is None and s.ticks.steps
        assert scene_kind(s) == "ticks" and geometry_kind(s) in ("terrain", "bsp", "obstacles", "indoor")


def test_tick_scenes_average_twenty_ticks_or_more(tick_scenes):
    assert sum(len(s.ticks.steps) for s in tick_scenes) / len(tick_scenes) >= 20


def test_every_policy_world_and_driver_is_drawn(tick_scenes):
    policies = Counter(s.name.split(":")[1].split("-")[0] for s in tick_scenes)
    assert set(policies) >= {"walk", "fall", "jump", "slide", "sled", "press", "cross", "portal", "velocity"}
    assert {geometry_kind(s) for s in tick_scenes} == {"terrain", "bsp", "obstacles", "indoor"}
    assert {s.ticks.driver for s in tick_scenes} == {"update_object", "request_pos"}


def test_indoor_tick_scenes_hold_env_cells_and_statics(tick_scenes):
    indoor = [s for s in tick_scenes if s.env_cells]
    assert indoor and any(any(o.position.cell & 0xFFFF >= 0x100 for o in s.objects) for s in indoor)


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
