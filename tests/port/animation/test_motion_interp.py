"""MotionInterp (CMotionInterp) on small hand-built states: the HoldKey/run-rate rules of
adjust_motion and apply_run_to_command, the state's velocity, the jump rules, the ground."""

import numpy as np
import pytest

from acconform.flags import PhysicsState, TransientState
from acconform.motion_enums import HoldKey, MotionCommand as M, WeenieError as E
from acconform.numerics import EXACT, f32_bits
from acconform.port.animation.movement_parameters import MovementParameters

from motion_helpers import CreatureWeenie, ItemWeenie, Obj, interp

f = np.float32


@pytest.mark.anchor("CMotionInterp::adjust_motion")
def test_walking_backward_becomes_walking_forward_at_minus_backwards_factor():
    mi = interp()
    motion, speed = mi.adjust_motion(M.WalkBackwards, f(1.0), HoldKey.None_)
    assert motion == M.WalkForward and f32_bits(speed) == f32_bits(f(-0.65))
    assert type(speed) is np.float32


@pytest.mark.anchor("CMotionInterp::adjust_motion")
def test_left_turn_and_left_sidestep_become_right_ones_at_negated_speed_the_sidestep_scaled_to_the_walk():
    mi = interp()
    assert mi.adjust_motion(M.TurnLeft, f(1.0), HoldKey.None_) == (M.TurnRight, f(-1.0))
    motion, speed = mi.adjust_motion(M.SideStepLeft, f(1.0), HoldKey.None_)
    assert motion == M.SideStepRight and speed == -(f(0.5) * (f(3.1199999) / f(1.25)))


@pytest.mark.anchor("CMotionInterp::adjust_motion")
def test_run_forward_is_left_alone_even_with_the_run_key():
    mi = interp(CreatureWeenie(run_skill=300))
    assert mi.adjust_motion(M.RunForward, f(1.0), HoldKey.Run) == (M.RunForward, f(1.0))


@pytest.mark.anchor("CMotionInterp::adjust_motion")
def test_an_object_that_is_not_a_creature_keeps_its_motions_as_given():
    mi = interp(ItemWeenie())
    assert mi.adjust_motion(M.WalkBackwards, f(1.0), HoldKey.Run) == (M.WalkBackwards, f(1.0))


@pytest.mark.anchor("CMotionInterp::adjust_motion")
def test_an_invalid_hold_key_takes_the_raw_states_so_holding_run_makes_a_walk_a_run():
    mi = interp(CreatureWeenie(run_skill=200))  # GetRunRate(0, 200, 1) = (200/400*11 + 4)/4 = 2.375
    assert mi.adjust_motion(M.WalkForward, f(1.0), HoldKey.Invalid) == (M.WalkForward, f(1.0))
    mi.raw_state.current_hold_key = HoldKey.Run
    assert mi.adjust_motion(M.WalkForward, f(1.0), HoldKey.Invalid) == (M.RunForward, f(2.375))
    assert mi.adjust_motion(M.WalkForward, f(1.0), HoldKey.None_) == (M.WalkForward, f(1.0))


@pytest.mark.anchor("CMotionInterp::apply_run_to_command")
def test_running_backward_stays_a_walk_at_the_negative_speed_times_the_run_rate():
    mi = interp(CreatureWeenie(run_skill=200))
    motion, speed = mi.adjust_motion(M.WalkBackwards, f(1.0), HoldKey.Run)
    assert motion == M.WalkForward and speed == f(-0.65) * f(2.375)


@pytest.mark.anchor("CMotionInterp::apply_run_to_command")
def test_a_run_turns_half_again_as_fast_and_a_run_sidestep_is_capped_at_three_either_way():
    mi = interp(CreatureWeenie(run_skill=800))  # rate 4.5
    assert mi.apply_run_to_command(M.TurnRight, f(-1.0)) == (M.TurnRight, f(-1.5))
    assert mi.apply_run_to_command(M.SideStepRight, f(1.0)) == (M.SideStepRight, f(3.0))
    assert mi.apply_run_to_command(M.SideStepRight, f(-1.0)) == (M.SideStepRight, f(-3.0))
    assert mi.apply_run_to_command(M.SideStepRight, f(0.5)) == (M.SideStepRight, f(2.25))


@pytest.mark.anchor("CMotionInterp::apply_run_to_command")
def test_with_no_weenie_object_the_run_rate_is_one_not_my_run_rate():
    mi = interp(None)
    mi.my_run_rate = f(3.0)
    assert mi.apply_run_to_command(M.WalkForward, f(2.0)) == (M.RunForward, f(2.0))


@pytest.mark.anchor("CMotionInterp::get_state_velocity")
def test_state_velocity_walks_at_walk_anim_speed_and_sidesteps_at_sidestep_anim_speed():
    mi = interp()
    mi.interpreted_state.forward_command = M.WalkForward
    mi.interpreted_state.forward_speed = f(0.5)
    mi.interpreted_state.side_step_command = M.SideStepRight
    mi.interpreted_state.side_step_speed = f(-1.0)
    v = mi.get_state_velocity()
    assert (v.x, v.y, v.z) == (f(-1.25), f(3.1199999) * f(0.5), f(0.0))


@pytest.mark.anchor("CMotionInterp::get_state_velocity")
def test_state_velocity_is_capped_at_run_anim_speed_times_the_run_rate():
    mi = interp(CreatureWeenie(run_skill=0))  # rate 1: at most 4 m/s
    mi.interpreted_state.forward_command = M.RunForward
    mi.interpreted_state.forward_speed = f(2.0)
    mi.interpreted_state.side_step_command = M.SideStepRight
    mi.interpreted_state.side_step_speed = f(1.0)
    v = mi.get_state_velocity()
    length = np.sqrt(f(1.25) ** 2 + f(8.0) ** 2, dtype=np.float32)
    assert v.x == f(1.25) / length * f(4.0) and v.y == f(8.0) / length * f(4.0)
    assert abs(float(v.length()) - 4.0) < 1e-6


@pytest.mark.anchor("CMotionInterp::get_max_speed")
def test_max_speed_is_run_anim_speed_times_the_weenies_run_rate():
    assert interp(CreatureWeenie(run_skill=800)).get_max_speed() == f(18.0)
    assert interp(None).get_max_speed() == f(4.0)


@pytest.mark.anchor("CMotionInterp::get_adjusted_max_speed")
def test_adjusted_max_speed_follows_a_running_states_speed_over_the_speed_factor():
    mi = interp(CreatureWeenie(run_skill=800))
    mi.interpreted_state.forward_command = M.RunForward
    mi.interpreted_state.forward_speed = f(2.0)
    assert mi.get_adjusted_max_speed() == f(8.0)


@pytest.mark.anchor("CMotionInterp::motion_allows_jump")
@pytest.mark.parametrize("motion, allowed", [
    (M.Ready, True), (M.WalkForward, True), (M.Falling, False), (M.Fallen, True), (M.Crouch, False),
    (M.Sleeping, False), (M.Reload, False), (M.Pickup, False), (M.AimLevel, False), (M.MagicPray, False),
    (M.MagicPowerUp01, False), (M.TripleThrustLow, False), (M.Dead, True),
])
def test_motion_allows_jump_refuses_the_ranges_ace_names(motion, allowed):
    assert (interp().motion_allows_jump(motion) == E.None_) == allowed


@pytest.mark.anchor("CMotionInterp::jump_charge_is_allowed")
@pytest.mark.parametrize("forward, error", [
    (M.Ready, E.None_), (M.Fallen, E.YouCantJumpFromThisPosition), (M.Falling, E.None_),
    (M.Crouch, E.YouCantJumpFromThisPosition), (M.Sleeping, E.YouCantJumpFromThisPosition),
])
def test_a_jump_charge_is_refused_when_fallen_or_crouching_to_sleeping_but_not_when_falling(forward, error):
    mi = interp()
    mi.interpreted_state.forward_command = forward
    assert mi.jump_charge_is_allowed() == error


@pytest.mark.anchor("CMotionInterp::charge_jump")
def test_charge_jump_refuses_falling_and_leaves_sleeping_out_and_marks_a_standing_long_jump():
    mi = interp()
    assert mi.charge_jump() == 0 and mi.standing_long_jump
    mi.interpreted_state.forward_command = M.Falling
    assert mi.charge_jump() == 0x48
    mi.interpreted_state.forward_command = M.Sleeping
    assert mi.charge_jump() == 0


@pytest.mark.anchor("CMotionInterp::contact_allows_move")
def test_in_the_air_a_creature_may_turn_but_not_walk_and_without_gravity_it_may_do_anything():
    mi = interp(obj=Obj(transient_state=0))
    assert mi.contact_allows_move(M.TurnLeft) and mi.contact_allows_move(M.Falling)
    assert not mi.contact_allows_move(M.WalkForward)
    mi.physics_obj.transient_state = TransientState.Contact  # on a slope too steep to walk
    assert not mi.contact_allows_move(M.WalkForward)
    mi.physics_obj.state = 0
    assert mi.contact_allows_move(M.WalkForward)


@pytest.mark.anchor("CMotionInterp::jump_is_allowed")
def test_aces_weenie_object_costs_no_stamina_so_a_creatures_jump_fails_as_a_general_movement_failure():
    mi = interp()
    assert mi.jump_is_allowed(f(0.5), 0) == E.GeneralMovementFailure
    assert interp(None).jump_is_allowed(f(0.5), 0) == E.None_


@pytest.mark.anchor("CMotionInterp::jump_is_allowed")
def test_a_creature_in_the_air_cannot_jump_and_a_pending_motions_jump_error_is_returned():
    assert interp(obj=Obj(transient_state=0)).jump_is_allowed(f(0.5), 0) == E.YouCantJumpWhileInTheAir
    mi = interp(None)
    mi.add_to_queue(0, M.Crouch, E.YouCantJumpFromThisPosition)
    assert len(mi.pending_motions) > 1
    assert mi.jump_is_allowed(f(0.5), 0) == mi.pending_motions.first.value.jump_error_code


@pytest.mark.anchor("CMotionInterp::jump")
def test_an_allowed_jump_takes_the_extent_and_leaves_the_walkable():
    mi = interp(None)
    assert mi.jump(f(0.75), 0) == E.None_
    assert mi.jump_extent == f(0.75) and ("set_on_walkable", False) in mi.physics_obj.calls
    mi.standing_long_jump = True
    mi.physics_obj.fully_constrained = True
    assert mi.jump(f(0.5), 0) == E.GeneralMovementFailure and not mi.standing_long_jump


@pytest.mark.anchor("CMotionInterp::get_jump_v_z")
def test_jump_velocity_is_zero_below_epsilon_ten_with_no_weenie_and_the_weenies_answer_otherwise():
    mi = interp(None)
    assert mi.get_jump_v_z() == 0.0
    mi.jump_extent = f(2.0)
    assert mi.get_jump_v_z() == f(10.0)
    mi = interp(CreatureWeenie())
    mi.jump_extent = f(1.0)
    assert mi.get_jump_v_z() == 0.0  # InqJumpVelocity false: no Player behind the weenie


@pytest.mark.anchor("CMotionInterp::get_leave_ground_velocity")
def test_leaving_the_ground_standing_still_keeps_the_objects_own_velocity_in_its_frame():
    obj = Obj(velocity=EXACT.vec(1.0, 2.0, 0.0))
    mi = interp(None, obj=obj)
    v = mi.get_leave_ground_velocity()
    assert v == obj.position.global_to_local_vec(obj.velocity)
    mi.interpreted_state.forward_command = M.WalkForward
    assert mi.get_leave_ground_velocity() == EXACT.vec(0.0, 3.1199999, 0.0)


@pytest.mark.anchor("CMotionInterp::LeaveGround")
def test_leave_ground_sets_the_leave_velocity_and_forgets_the_jump():
    mi = interp(None)
    mi.interpreted_state.forward_command = M.WalkForward
    mi.jump_extent = f(1.0)
    mi.standing_long_jump = True
    mi.leave_ground()
    assert mi.physics_obj.calls[0] == ("set_local_velocity", (0.0, float(f(3.1199999)), 10.0))
    assert mi.jump_extent == 0.0 and not mi.standing_long_jump


@pytest.mark.anchor("CMotionInterp::HitGround")
def test_hit_ground_reapplies_the_movement_for_a_creature_under_gravity_only():
    mi = interp(ItemWeenie())
    mi.hit_ground()
    assert mi.physics_obj.calls == []
    mi = interp()
    mi.hit_ground()
    assert mi.physics_obj.calls[0] == ("remove_link_animations",) and len(mi.physics_obj.calls) > 1


@pytest.mark.anchor("CMotionInterp::DoInterpretedMotion")
def test_in_the_air_an_action_cannot_start_and_a_walk_only_changes_the_interpreted_state():
    mi = interp(obj=Obj(transient_state=0))
    p = MovementParameters.create(EXACT)
    assert mi.do_interpreted_motion(M.Twitch1, p) == E.YouCantJumpWhileInTheAir
    p.speed = f(2.0)
    assert mi.do_interpreted_motion(M.WalkForward, p) == E.None_
    assert mi.interpreted_state.forward_command == M.WalkForward and mi.interpreted_state.forward_speed == 2.0
    assert not any(c[0] == "do" for c in mi.physics_obj.calls)


@pytest.mark.anchor("CMotionInterp::DoInterpretedMotion")
def test_on_the_ground_a_motion_goes_to_the_motion_table_and_is_queued_with_its_jump_error():
    mi = interp()
    p = MovementParameters.create(EXACT)
    assert mi.do_interpreted_motion(M.Crouch, p) == E.None_
    assert ("do", int(M.Crouch), f(1.0)) in mi.physics_obj.calls and mi.physics_obj.is_animating
    assert mi.pending_motions.last.value.jump_error_code == E.YouCantJumpFromThisPosition
    p.disable_jump_during_link = True
    mi.do_interpreted_motion(M.Ready, p)
    assert mi.pending_motions.last.value.jump_error_code == E.YouCantJumpFromThisPosition


@pytest.mark.anchor("CMotionInterp::DoMotion")
def test_do_motion_walking_backward_keeps_the_raw_command_and_interprets_it_as_a_slow_forward_walk():
    mi = interp()
    p = MovementParameters.create(EXACT)
    assert mi.do_motion(M.WalkBackwards, p) == E.None_
    assert mi.raw_state.forward_command == M.WalkBackwards and mi.raw_state.forward_speed == 1.0
    assert mi.interpreted_state.forward_command == M.WalkForward and mi.interpreted_state.forward_speed == f(-0.65)


@pytest.mark.anchor("CMotionInterp::DoMotion")
def test_in_combat_a_creature_cannot_crouch_sit_sleep_or_chat_emote():
    mi = interp()
    mi.interpreted_state.current_style = M.SwordCombat
    p = MovementParameters.create(EXACT)
    assert mi.do_motion(M.Crouch, p) == E.CantCrouchInCombat
    assert mi.do_motion(M.Sitting, p) == E.CantSitInCombat
    assert mi.do_motion(M.Sleeping, p) == E.CantLieDownInCombat


@pytest.mark.anchor("CMotionInterp::DoMotion")
def test_a_seventh_action_is_refused():
    mi = interp()
    for _ in range(6):
        mi.interpreted_state.add_action(M.Twitch1, f(1.0), 0, False)
    assert mi.do_motion(M.Twitch1, MovementParameters.create(EXACT)) == E.TooManyActions


@pytest.mark.anchor("CMotionInterp::SetHoldKey")
def test_releasing_run_reinterprets_the_raw_walk_as_a_walk():
    mi = interp(CreatureWeenie(run_skill=200))
    mi.set_hold_run(1, False)
    mi.raw_state.forward_command = M.WalkForward
    mi.apply_current_movement(False, True)
    assert mi.interpreted_state.forward_command == M.RunForward and mi.interpreted_state.forward_speed == f(2.375)
    mi.set_hold_key(HoldKey.None_, False)
    assert mi.raw_state.current_hold_key == HoldKey.None_
    assert mi.interpreted_state.forward_command == M.WalkForward and mi.interpreted_state.forward_speed == 1.0


@pytest.mark.anchor("CMotionInterp::apply_current_movement")
def test_a_non_autonomous_object_replays_its_interpreted_state_not_its_raw_one():
    mi = interp(obj=Obj(autonomous=False))
    mi.raw_state.forward_command = M.WalkBackwards
    mi.interpreted_state.forward_command = M.RunForward
    mi.interpreted_state.forward_speed = f(1.5)
    mi.apply_current_movement(False, True)
    assert mi.interpreted_state.forward_command == M.RunForward and mi.my_run_rate == f(1.5)


@pytest.mark.anchor("CMotionInterp::StopCompletely")
def test_stop_completely_readies_both_states_and_queues_a_ready():
    mi = interp()
    mi.do_motion(M.WalkBackwards, MovementParameters.create(EXACT))
    assert mi.stop_completely() == E.None_
    assert mi.raw_state.forward_command == M.Ready == mi.interpreted_state.forward_command
    assert mi.pending_motions.last.value.motion == M.Ready
    assert ("stop_completely_internal",) in mi.physics_obj.calls


@pytest.mark.anchor("CMotionInterp::StopMotion")
def test_stopping_a_backward_walk_stops_the_interpreted_forward_walk_and_forgets_the_raw_one():
    mi = interp()
    p = MovementParameters.create(EXACT)
    mi.do_motion(M.WalkBackwards, p)
    assert mi.stop_motion(M.WalkBackwards, p) == E.None_
    assert ("stop", int(M.WalkForward)) in mi.physics_obj.calls
    assert mi.raw_state.forward_command == M.Ready and mi.interpreted_state.forward_command == M.Ready


@pytest.mark.anchor("CMotionInterp::MotionDone")
def test_motion_done_pops_the_first_pending_motion_and_an_action_from_both_states():
    mi = interp()
    mi.pending_motions.clear()
    mi.add_to_queue(0, M.Twitch1, E.None_)
    mi.raw_state.add_action(M.Twitch1, f(1.0), 0, False)
    mi.interpreted_state.add_action(M.Twitch1, f(1.0), 0, False)
    mi.motion_done(True)
    assert len(mi.pending_motions) == 0 and not mi.physics_obj.is_animating
    assert mi.raw_state.actions == [] and mi.interpreted_state.actions == []


@pytest.mark.anchor("CMotionInterp::move_to_interpreted_state")
def test_moving_to_an_interpreted_state_plays_only_actions_newer_than_the_server_stamp():
    from acconform.port.animation.interpreted_motion_state import InterpretedMotionState

    mi = interp()
    target = InterpretedMotionState.create(EXACT)
    target.forward_command = M.WalkForward
    target.add_action(M.Twitch1, f(1.0), 5, False)
    target.add_action(M.Twitch2, f(1.0), 3, False)  # older than 5 by then: skipped
    assert mi.move_to_interpreted_state(target)
    assert mi.server_action_stamp == 5
    assert [c[1] for c in mi.physics_obj.calls if c[0] == "do" and c[1] in (M.Twitch1, M.Twitch2)] == [M.Twitch1]


@pytest.mark.anchor("CMotionInterp::enter_default_state")
def test_entering_the_default_state_queues_a_ready_and_leaves_the_ground():
    from motion_helpers import Obj as O
    from acconform.port.animation.motion_interp import MotionInterp

    obj = O()
    mi = MotionInterp.create(obj, None, EXACT)
    assert mi.raw_state is None and obj.calls == []  # not initted: apply_current_movement does nothing
    mi.enter_default_state()
    assert mi.initted and mi.pending_motions.first.value.motion == M.Ready
    assert obj.calls[0] == ("initialize_motion_tables",) and obj.calls[1][0] == "set_local_velocity"


@pytest.mark.anchor("CMotionInterp::PerformMovement")
def test_perform_movement_dispatches_on_the_type_and_refuses_a_move_to():
    from acconform.motion_enums import MovementType
    from acconform.port.animation.movement_struct import MovementStruct

    mi = interp()
    assert mi.perform_movement(MovementStruct.create(MovementType.MoveToObject)) == E.GeneralMovementFailure
    assert mi.perform_movement(MovementStruct.create(MovementType.StopCompletely)) == E.None_
    assert mi.physics_obj.calls[-1] == ("check_for_completed_motions",)
