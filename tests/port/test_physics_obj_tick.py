"""PhysicsObj's tick (port/physics_obj.py): update_object's quantum split, UpdatePhysicsInternal,
calc_friction, UpdatePositionInternal, the velocity setters, GetBlockDist, handle_all_collisions'
bounce, the collision records' clock.

Every expected value is worked out from ACE's code (PhysicsObj.cs at 7b47913) in the comments:
the double arithmetic of update_object written as the same Python double operations, float32
arithmetic as numpy float32 operations, never by calling the port routine under test.
"""

from __future__ import annotations

import math
from collections import Counter

import numpy as np
import pytest

from acconform.flags import PhysicsState, TransientState
from acconform.numerics import EXACT, Plane, f32_bits, f32_from_bits
from acconform.port import constants as k
from acconform.port.cell.obj_cell import ObjCell
from acconform.port.frame import AFrame, Position
from acconform.port.part_array import PartArray
from acconform.port.physics_obj import PhysicsObj
from acconform.port.physics_timer import PhysicsTimer
from acconform.port.transition.branches import Trace
from acconform.port.transition.collision_info import CollisionInfo

F = np.float32
MAXQ = 0.10000000149011612  # (double)0.1f
MINQ = 0.03333333507180214  # (double)(1.0f / 30.0f), also TickRate


def v(x, y, z):
    return EXACT.vec(x, y, z)


def mover(start: float = 0.0, transient: int = 0) -> PhysicsObj:
    """A PhysicsObj made at clock `start`, in a cell, without Active unless asked: each
    UpdateObjectInternal sub-step then returns at once and is only counted."""
    obj = PhysicsObj.create(EXACT, PhysicsTimer(start))
    obj.cur_cell = ObjCell(0xA9B40001, EXACT)
    obj.transient_state = transient
    return obj


def tick(obj: PhysicsObj, time: float) -> tuple[bool, Counter]:
    obj.timer.set(time)
    trace = Trace()
    return obj.update_object(None, trace), trace


def steps(trace) -> tuple[int, int, int]:
    return (trace["update_object:max_quantum_step"], trace["update_object:remainder_step"],
            trace["update_object_internal:inactive"])


def up(x: float) -> float:
    return math.nextafter(x, math.inf)


def down(x: float) -> float:
    return math.nextafter(x, -math.inf)


# ---------------------------------------------------------------- update_object: the quantum split


@pytest.mark.anchor("CPhysicsObj::update_object")
def test_the_constructor_takes_update_time_from_the_clock():
    obj = mover(1234.5)
    assert obj.update_time == 1234.5 and obj.physics_timer_current_time == 1234.5


@pytest.mark.anchor("CPhysicsObj::update_object")
def test_less_than_tick_rate_since_the_last_update_runs_nothing_and_keeps_the_time():
    obj = mover()
    updated, trace = tick(obj, down(MINQ))  # deltaTime < TickRate (widened to double)
    assert not updated and trace["update_object:tick_rate_gate"] == 1 and steps(trace) == (0, 0, 0)
    assert obj.update_time == 0.0


@pytest.mark.anchor("CPhysicsObj::update_object")
def test_exactly_tick_rate_passes_the_gate_but_keeps_the_remainder_as_it_is_not_over_min_quantum():
    # deltaTime == TickRate == MinQuantum: not `< TickRate`, not `> MinQuantum`: nothing runs,
    # UpdateTime = PhysicsTimer_CurrentTime = the old UpdateTime, and update_object answers true
    obj = mover()
    updated, trace = tick(obj, MINQ)
    assert updated and steps(trace) == (0, 0, 0) and trace["update_object:remainder_kept"] == 1
    assert trace["boundary:tick_rate"] == 1 and trace["boundary:min_quantum"] == 1
    assert obj.update_time == 0.0


@pytest.mark.anchor("CPhysicsObj::update_object")
def test_one_ulp_over_min_quantum_runs_one_sub_step_of_the_whole_time():
    obj = mover()
    updated, trace = tick(obj, up(MINQ))
    assert updated and steps(trace) == (0, 1, 1)
    assert obj.update_time == 0.0 + up(MINQ)


@pytest.mark.anchor("CPhysicsObj::update_object")
def test_exactly_max_quantum_is_one_remainder_sub_step_not_a_max_quantum_one():
    obj = mover()
    updated, trace = tick(obj, MAXQ)  # not `> MaxQuantum`; `> MinQuantum`
    assert updated and steps(trace) == (0, 1, 1) and trace["boundary:max_quantum"] == 1
    assert obj.update_time == MAXQ


@pytest.mark.anchor("CPhysicsObj::update_object")
def test_one_ulp_under_max_quantum_is_one_remainder_sub_step():
    obj = mover()
    updated, trace = tick(obj, down(MAXQ))
    assert updated and steps(trace) == (0, 1, 1) and obj.update_time == down(MAXQ)


@pytest.mark.anchor("CPhysicsObj::update_object")
def test_one_ulp_over_max_quantum_is_one_max_step_and_a_kept_remainder_of_one_ulp():
    obj = mover()
    updated, trace = tick(obj, up(MAXQ))
    # one MaxQuantum sub-step; deltaTime - 0.1f is one double ulp, not over MinQuantum: kept
    assert updated and steps(trace) == (1, 0, 1) and trace["update_object:remainder_kept"] == 1
    assert obj.update_time == MAXQ


@pytest.mark.anchor("CPhysicsObj::update_object")
def test_exactly_huge_quantum_is_simulated_in_nineteen_max_steps_and_a_remainder():
    # 2.0 / 0.1f = 19.9999997...: after 19 sub-steps 2.0 - 19 * 0.1f (exact in double) is
    # 0.0999999716877937, under 0.1f and over MinQuantum: a last sub-step; the clock adds up to 2.0
    obj = mover()
    updated, trace = tick(obj, 2.0)
    assert updated and steps(trace) == (19, 1, 20) and trace["boundary:huge_quantum"] == 1
    assert obj.update_time == 2.0


@pytest.mark.anchor("CPhysicsObj::update_object")
def test_one_ulp_over_huge_quantum_is_skipped_and_the_time_consumed():
    obj = mover()
    updated, trace = tick(obj, up(2.0))
    assert not updated and trace["update_object:huge_quantum_skip"] == 1 and steps(trace) == (0, 0, 0)
    assert obj.update_time == up(2.0)


@pytest.mark.anchor("CPhysicsObj::update_object")
def test_one_ulp_under_huge_quantum_is_simulated():
    obj = mover()
    updated, trace = tick(obj, down(2.0))
    assert updated and trace["update_object:huge_quantum_skip"] == 0 and steps(trace)[0] == 19


@pytest.mark.anchor("CPhysicsObj::update_object")
def test_a_tick_of_0_15_s_is_two_sub_steps_as_aces_max_quantum_is_0_1_not_retails_0_2():
    obj = mover()
    updated, trace = tick(obj, 0.15)  # 0.15 > 0.1f: one MaxQuantum step, then 0.0499999985 > MinQuantum
    assert updated and steps(trace) == (1, 1, 2) and obj.update_time == MAXQ + (0.15 - MAXQ)


@pytest.mark.anchor("CPhysicsObj::update_object")
def test_a_kept_remainder_is_carried_into_the_next_tick():
    obj = mover(1000.0)
    updated, trace = tick(obj, 1000.12)
    # deltaTime = 1000.12 - 1000.0; one 0.1f sub-step; the rest (about 0.02) is not over MinQuantum
    assert updated and steps(trace) == (1, 0, 1)
    assert obj.update_time == 1000.0 + MAXQ
    updated, trace = tick(obj, 1000.15)
    # deltaTime = 1000.15 - (1000.0 + 0.1f), about 0.05: over TickRate, under MaxQuantum: one sub-step
    assert updated and steps(trace) == (0, 1, 1)
    assert obj.update_time == (1000.0 + MAXQ) + (1000.15 - (1000.0 + MAXQ))


@pytest.mark.anchor("CPhysicsObj::update_object")
def test_an_object_in_no_cell_is_made_inactive_and_not_updated():
    obj = mover(transient=int(TransientState.Active))
    obj.cur_cell = None
    updated, trace = tick(obj, 1.0)
    assert not updated and trace["update_object:not_in_world"] == 1
    assert not obj.transient_state & TransientState.Active and obj.update_time == 0.0


# ---------------------------------------------------------------- UpdatePhysicsInternal and calc_friction


def physics(obj: PhysicsObj, quantum, trace=None) -> AFrame:
    frame = AFrame.identity(EXACT)
    obj.update_physics_internal(F(quantum), frame, trace)
    return frame


@pytest.mark.anchor("CPhysicsObj::UpdatePhysicsInternal")
def test_a_mover_at_rest_gains_gravity_but_does_not_move_in_its_first_sub_step():
    obj = mover()
    obj.acceleration = v(0, 0, k.GRAVITY)
    frame = physics(obj, MAXQ)
    # velocity_mag2 == 0: no movement; then Velocity += Acceleration * quantum
    assert frame.origin == v(0, 0, 0)
    assert f32_bits(obj.velocity.z) == f32_bits(F(k.GRAVITY) * F(0.1))


@pytest.mark.anchor("CPhysicsObj::UpdatePhysicsInternal")
def test_a_falling_mover_moves_by_half_a_t_squared_plus_v_t_in_float32():
    obj = mover()
    obj.acceleration = v(0, 0, k.GRAVITY)
    obj.velocity = v(0, 0, -3.0)
    frame = physics(obj, MAXQ)
    q = F(0.1)
    want = F(k.GRAVITY) * F(0.5) * q * q + F(-3.0) * q  # Acceleration * 0.5f * quantum * quantum + Velocity * quantum
    assert f32_bits(frame.origin.z) == f32_bits(F(0.0) + want)
    assert f32_bits(obj.velocity.z) == f32_bits(F(-3.0) + F(k.GRAVITY) * q)


@pytest.mark.anchor("CPhysicsObj::UpdatePhysicsInternal")
def test_a_speed_over_max_velocity_is_clamped_to_it():
    obj = mover()
    obj.velocity = v(60.0, 0, 0)
    trace = Trace()
    frame = physics(obj, 0.05, trace)
    assert obj.velocity == v(50.0, 0, 0) and trace["update_physics:velocity_clamped"] == 1
    assert f32_bits(frame.origin.x) == f32_bits(F(50.0) * F(0.05))


@pytest.mark.anchor("CPhysicsObj::UpdatePhysicsInternal")
def test_exactly_max_velocity_is_not_clamped():
    obj = mover()
    obj.velocity = v(0, 50.0, 0)
    trace = Trace()
    physics(obj, 0.05, trace)
    assert trace["update_physics:velocity_clamped"] == 0 and trace["boundary:max_velocity"] == 1
    assert obj.velocity == v(0, 50.0, 0)


@pytest.mark.anchor("CPhysicsObj::UpdatePhysicsInternal")
def test_exactly_small_velocity_is_zeroed_before_the_move():
    obj = mover()
    obj.velocity = v(0.25, 0, 0)  # 0.0625f - 0.0625f = 0 < EPSILON
    trace = Trace()
    frame = physics(obj, 0.05, trace)
    assert obj.velocity == v(0, 0, 0) and frame.origin == v(0, 0, 0)
    assert trace["update_physics:small_velocity_zeroed"] == 1


@pytest.mark.anchor("CPhysicsObj::UpdatePhysicsInternal")
def test_a_speed_whose_square_is_epsilon_over_small_velocitys_is_kept():
    # velocity_mag2 - 0.0625f < 0.0002f decides; 0.26 m/s: 0.0676f - 0.0625f = 0.0051 > EPSILON
    obj = mover()
    obj.velocity = v(0.26, 0, 0)
    frame = physics(obj, 0.05)
    assert obj.velocity == v(0.26, 0, 0)
    assert f32_bits(frame.origin.x) == f32_bits(F(0.26) * F(0.05))


@pytest.mark.anchor("CPhysicsObj::UpdatePhysicsInternal")
def test_a_mover_at_rest_on_walkable_ground_without_a_movement_manager_goes_inactive():
    obj = mover(transient=int(TransientState.Active | TransientState.OnWalkable | TransientState.Contact))
    physics(obj, 0.05)
    assert not obj.transient_state & TransientState.Active


@pytest.mark.anchor("CPhysicsObj::UpdatePhysicsInternal")
def test_omega_turns_the_offset_frame_by_omega_times_quantum():
    obj = mover()
    obj.omega = v(0, 0, 2.0)
    frame = physics(obj, 0.05)
    rt = EXACT.runtime
    want = rt.quat_normalize(rt.quat_multiply(EXACT.quat(0, 0, 0, 1),
                                              rt.quat_create_from_yaw_pitch_roll(F(0), F(0), F(2.0) * F(0.05))))
    assert frame.orientation == want


def walking(velocity, normal=(0.0, 0.0, 1.0), state: int = 0) -> PhysicsObj:
    obj = mover(transient=int(TransientState.OnWalkable | TransientState.Contact))
    obj.velocity = v(*velocity)
    obj.contact_plane = Plane(v(*normal), F(0.0))
    obj.state = state
    return obj


def friction_scalar(friction, quantum: float):
    return F(math.pow(float(F(1.0) - F(friction)), quantum))  # (float)Math.Pow(1.0f - friction, quantum)


@pytest.mark.anchor("CPhysicsObj::calc_friction")
def test_friction_scales_a_walkers_velocity_by_one_less_friction_to_the_power_of_quantum_in_double():
    obj = walking((2.0, 0.0, 0.0))
    obj.calc_friction(MAXQ, obj.velocity.length_squared())
    assert f32_bits(obj.velocity.x) == f32_bits(F(2.0) * friction_scalar(k.DEFAULT_FRICTION, MAXQ))


@pytest.mark.anchor("CPhysicsObj::calc_friction")
def test_friction_first_removes_the_velocity_into_the_contact_plane():
    obj = walking((2.0, 0.0, -1.0))  # angle = -1: Velocity -= Normal * angle -> (2, 0, 0)
    obj.calc_friction(MAXQ, obj.velocity.length_squared())
    s = friction_scalar(k.DEFAULT_FRICTION, MAXQ)
    assert obj.velocity == v(F(2.0) * s, 0.0, F(0.0) * s)


@pytest.mark.anchor("CPhysicsObj::calc_friction")
def test_no_friction_off_walkable_ground_or_when_leaving_the_plane_at_a_quarter():
    obj = walking((2.0, 0.0, 0.0))
    obj.transient_state = 0
    obj.calc_friction(MAXQ, F(4.0))
    assert obj.velocity == v(2.0, 0.0, 0.0)
    obj = walking((2.0, 0.0, 0.25))  # Dot(Velocity, Normal) == 0.25f: `>= 0.25f` returns
    trace = Trace()
    obj.calc_friction(MAXQ, obj.velocity.length_squared(), trace)
    assert obj.velocity == v(2.0, 0.0, 0.25) and trace["calc_friction:leaving_plane"] == 1


@pytest.mark.anchor("CPhysicsObj::calc_friction")
def test_a_slow_sled_stops_dead_and_exactly_at_the_stop_speed_slides_on():
    sled = int(PhysicsState.Sledding)
    obj = walking((1.2, 0.0, 0.0), state=sled)
    obj.calc_friction(MAXQ, F(1.44))  # < 1.5625f: friction 1.0f, Math.Pow(0, q) == 0
    assert obj.velocity == v(0.0, 0.0, 0.0)
    obj = walking((1.25, 0.0, 0.0), state=sled)
    trace = Trace()
    obj.calc_friction(MAXQ, F(1.5625), trace)  # not < 1.5625f, not >= 6.25f: DefaultFriction
    assert trace["boundary:sledding_stop_speed"] == 1 and trace["calc_friction:sledding_stop"] == 0
    assert f32_bits(obj.velocity.x) == f32_bits(F(1.25) * friction_scalar(k.DEFAULT_FRICTION, MAXQ))


@pytest.mark.anchor("CPhysicsObj::calc_friction")
def test_a_fast_sled_glides_only_on_a_plane_flatter_than_aces_threshold():
    sled = int(PhysicsState.Sledding)
    at = f32_from_bits(0x3F7FFFB2)  # 0.99999536f
    glide = friction_scalar(k.SLEDDING_GLIDE_FRICTION, MAXQ)
    drag = friction_scalar(k.DEFAULT_FRICTION, MAXQ)
    for z, scalar in ((1.0, glide), (f32_from_bits(0x3F7FFFB3), glide), (at, drag), (f32_from_bits(0x3F7FFFB1), drag)):
        obj = walking((2.5, 0.0, 0.0), normal=(0.0, 0.0, z), state=sled)
        obj.calc_friction(MAXQ, F(6.25))  # >= 6.25f
        assert f32_bits(obj.velocity.x) == f32_bits(F(2.5) * scalar), z


@pytest.mark.anchor("CPhysicsObj::calc_friction")
def test_a_sled_just_under_the_glide_speed_drags():
    obj = walking((2.4, 0.0, 0.0), state=int(PhysicsState.Sledding))
    obj.calc_friction(MAXQ, f32_from_bits(f32_bits(6.25) - 1))
    assert f32_bits(obj.velocity.x) == f32_bits(F(2.4) * friction_scalar(k.DEFAULT_FRICTION, MAXQ))


# ---------------------------------------------------------------- UpdatePositionInternal, root motion


def root_motion(transient: int, scale=1.0) -> PhysicsObj:
    obj = mover(transient=transient)
    obj.part_array = PartArray.create(EXACT)
    obj.part_array.sequence.set_velocity(v(1.0, -2.0, 0.0))
    obj.scale = F(scale)
    obj.position = Position(0xA9B40001, AFrame(v(10.0, 10.0, 5.0), EXACT.quat(0, 0, 0, 1)))
    return obj


@pytest.mark.anchor("CPhysicsObj::UpdatePositionInternal")
def test_root_motion_moves_a_walker_by_sequence_velocity_times_quantum_times_scale():
    obj = root_motion(int(TransientState.OnWalkable | TransientState.Contact), scale=2.0)
    frame = obj.update_position_internal(MAXQ, None, EXACT)
    q = F(0.1)  # PartArray.Update: (float)quantum
    assert frame.origin == v(F(10.0) + F(1.0) * q * F(2.0), F(10.0) + F(-2.0) * q * F(2.0), 5.0)


@pytest.mark.anchor("CPhysicsObj::UpdatePositionInternal")
def test_root_motion_is_dropped_in_the_air():
    obj = root_motion(0)
    frame = obj.update_position_internal(MAXQ, None, EXACT)
    assert frame.origin == v(10.0, 10.0, 5.0)


@pytest.mark.anchor("CPhysicsObj::UpdatePositionInternal")
def test_a_hidden_object_neither_animates_nor_integrates():
    obj = root_motion(int(TransientState.OnWalkable))
    obj.state = int(PhysicsState.Hidden)
    obj.velocity = v(3.0, 0.0, 0.0)
    frame = obj.update_position_internal(MAXQ, None, EXACT)
    assert frame.origin == v(10.0, 10.0, 5.0) and obj.velocity == v(3.0, 0.0, 0.0)


# ---------------------------------------------------------------- the setters


@pytest.mark.anchor("CPhysicsObj::set_velocity")
def test_set_velocity_clamps_to_max_velocity_marks_the_jump_and_wakes_the_object_at_the_clock():
    obj = mover(5.0)
    obj.timer.set(7.0)
    obj.set_velocity(v(0.0, 80.0, 0.0), False)
    assert obj.velocity == v(0.0, 50.0, 0.0) and obj.jumped_this_frame
    assert obj.transient_state & TransientState.Active and obj.update_time == 7.0
    obj.timer.set(8.0)
    obj.set_velocity(v(0.0, 1.0, 0.0), False)  # already Active: UpdateTime stays
    assert obj.update_time == 7.0


@pytest.mark.anchor("CPhysicsObj::set_velocity")
def test_set_velocity_leaves_a_static_object_asleep():
    obj = mover()
    obj.state = int(PhysicsState.Static)
    obj.set_velocity(v(1.0, 0.0, 0.0), False)
    assert not obj.transient_state & TransientState.Active


@pytest.mark.anchor("CPhysicsObj::set_local_velocity")
def test_set_local_velocity_turns_the_velocity_by_the_objects_orientation():
    obj = mover()
    h = F(math.sqrt(0.5))
    obj.position.frame.orientation = EXACT.quat(0, 0, h, h)
    obj.set_local_velocity(v(0.0, 4.0, 1.0), False)
    assert obj.velocity == EXACT.runtime.transform_by_quaternion(v(0.0, 4.0, 1.0), obj.position.frame.orientation)


@pytest.mark.anchor("CPhysicsObj::set_omega")
def test_set_omega_sets_omega_only():
    obj = mover()
    obj.set_omega(v(0.0, 0.0, 1.5), False)
    assert obj.omega == v(0.0, 0.0, 1.5) and not obj.transient_state & TransientState.Active


@pytest.mark.anchor("CPhysicsObj::set_active")
def test_set_active_stamps_update_time_only_when_waking():
    obj = mover(3.0)
    obj.timer.set(4.0)
    assert obj.set_active(True) and obj.update_time == 4.0
    obj.timer.set(5.0)
    assert obj.set_active(True) and obj.update_time == 4.0
    assert obj.set_active(False) and not obj.transient_state & TransientState.Active


# ---------------------------------------------------------------- GetBlockDist


@pytest.mark.anchor("PhysicsObj.cs:GetBlockDist(uint, uint)")
def test_block_distance_is_the_larger_landblock_step_in_x_or_y():
    d = PhysicsObj.get_block_dist_ids
    assert d(0xA9B40001, 0xA9B4FFFF) == 0
    assert d(0xA9B40001, 0xAAB50001) == 1
    assert d(0xA9B40001, 0xABB30001) == 2
    assert d(0x00000001, 0xFF000001) == 255 and d(0xFF000001, 0x00FF0001) == 255  # no uint wraparound


@pytest.mark.anchor("PhysicsObj.cs:GetBlockDist(Position, Position)")
def test_block_distance_to_no_position_is_zero():
    assert PhysicsObj.get_block_dist(None, Position(0xA9B40001, AFrame.identity(EXACT))) == 0


@pytest.mark.anchor("PhysicsObj.cs:UpdateObjectInternalServer")
def test_the_legacy_path_refuses_a_request_two_landblocks_away_before_any_transition():
    obj = mover()
    obj.position = Position(0xA9B40001, AFrame.identity(EXACT))
    obj.request_pos = Position(0xABB40001, AFrame.identity(EXACT))
    obj.cached_velocity = v(1.0, 0.0, 0.0)
    trace = Trace()
    assert obj.update_object_internal_server(MAXQ, None, trace) is False
    assert trace["update_object_internal_server:block_dist_refused"] == 1 and obj.cached_velocity == v(1.0, 0.0, 0.0)


# ---------------------------------------------------------------- handle_all_collisions, hooks, collision records


def collided(normal) -> CollisionInfo:
    ci = CollisionInfo.create(F(0.0))
    ci.collision_normal_valid = True
    ci.collision_normal = v(*normal)
    return ci


@pytest.mark.anchor("CPhysicsObj::handle_all_collisions")
def test_a_collision_bounces_the_velocity_by_one_plus_elasticity():
    obj = mover()
    obj.velocity = v(1.0, 0.0, -10.0)
    trace = Trace()
    obj.handle_all_collisions(collided((0.0, 0.0, 1.0)), False, False, trace)
    angle = F(-10.0)  # Dot(Velocity, Normal)
    elastic = -(angle * (F(0.05) + F(1.0)))
    assert obj.velocity == v(1.0, 0.0, F(-10.0) + F(1.0) * elastic) and trace["handle_all_collisions:elastic_bounce"] == 1


@pytest.mark.anchor("CPhysicsObj::handle_all_collisions")
def test_an_inelastic_collision_stops_the_object():
    obj = mover()
    obj.state |= PhysicsState.Inelastic
    obj.velocity = v(1.0, 0.0, -10.0)
    obj.handle_all_collisions(collided((0.0, 0.0, 1.0)), False, False)
    assert obj.velocity == v(0.0, 0.0, 0.0)


@pytest.mark.anchor("CPhysicsObj::handle_all_collisions")
def test_no_bounce_while_staying_on_walkable_ground_unless_sledding():
    obj = mover(transient=int(TransientState.OnWalkable))
    obj.velocity = v(1.0, 0.0, -10.0)
    obj.handle_all_collisions(collided((0.0, 0.0, 1.0)), True, True)
    assert obj.velocity == v(1.0, 0.0, -10.0)
    obj.state |= PhysicsState.Sledding
    obj.handle_all_collisions(collided((0.0, 0.0, 1.0)), True, True)
    assert obj.velocity != v(1.0, 0.0, -10.0)


@pytest.mark.anchor("CPhysicsObj::process_hooks")
def test_process_hooks_with_no_hooks_leaves_both_lists_empty():
    obj = mover()
    obj.process_hooks()
    assert obj.hooks == [] and obj.anim_hooks == []


@pytest.mark.anchor("CPhysicsObj::report_collision_end")
def test_a_collision_record_ends_a_second_after_its_touch_or_at_once_if_ethereal():
    obj = mover(10.0)
    solid, ghost = mover(), mover()
    solid.id, ghost.id = 0x7000_0001, 0x7000_0002
    ghost.state |= PhysicsState.Ethereal
    obj.track_object_collision(solid, False)
    obj.track_object_collision(ghost, False)
    obj.report_collision_end(False)
    assert obj.collision_table.keys() == [solid.id, ghost.id]  # touched now: deltaTime 0
    obj.timer.set(10.5)
    obj.report_collision_end(False)
    assert obj.collision_table.keys() == [solid.id]  # the ethereal one, deltaTime > 0
    obj.timer.set(11.0)
    obj.report_collision_end(False)
    assert obj.collision_table.keys() == [solid.id]  # deltaTime == 1.0 is not > 1.0f
    obj.timer.set(up(11.0))
    obj.report_collision_end(False)
    assert len(obj.collision_table) == 0


@pytest.mark.anchor("CPhysicsObj::add_particle_shadow_to_cell")
@pytest.mark.anchor("CPhysicsObj::add_shadows_to_cell")
def test_a_particle_emitter_shadows_its_cell_under_key_1_outside_the_cells_list_and_a_second_add_throws():
    # PhysicsObj.cs add_particle_shadow_to_cell: NumShadowObjects = 1; ShadowObjects.Add(1, new
    # ShadowObj(this, CurCell)) -- the cell's ShadowObjectList is not touched, so no transition meets
    # it -- and Dictionary.Add throws ArgumentException for key 1 the second time (remove_shadows_from_cells
    # keeps the keys)
    from acconform.port.errors import ArgumentException
    from acconform.port.transition.cell_array import CellArray

    obj = mover()
    obj.state = int(PhysicsState.ParticleEmitter)
    cells = CellArray()
    cells.add_cell(0xA9B40002, ObjCell(0xA9B40002, EXACT))
    obj.add_shadows_to_cell(cells)
    assert list(obj.shadow_objects) == [1] and obj.num_shadow_objects == 1
    assert obj.shadow_objects[1].cell is obj.cur_cell and obj.cur_cell.shadow_object_list == []
    obj.remove_shadows_from_cells()
    with pytest.raises(ArgumentException):
        obj.add_shadows_to_cell(cells)
