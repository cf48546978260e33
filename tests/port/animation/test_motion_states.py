"""RawMotionState, InterpretedMotionState, MovementParameters, MovementParamFlags, MovementStruct:
the records the motion interpreter keeps and hands around, on small hand-built states."""

import numpy as np
import pytest

from acconform.motion_enums import HoldKey, MotionCommand as M, MovementType
from acconform.numerics import EXACT, f32_bits
from acconform.port import constants as k
from acconform.port.animation.interpreted_motion_state import InterpretedMotionState
from acconform.port.animation.movement_param_flags import MovementParamFlags
from acconform.port.animation.movement_parameters import MovementParameters
from acconform.port.animation.movement_struct import MovementStruct
from acconform.port.animation.raw_motion_state import RawMotionState


def params(speed=1.0, set_hold_key=False, hold_key=HoldKey.Invalid):
    p = MovementParameters.create(EXACT)
    p.speed = np.float32(speed)
    p.set_hold_key = set_hold_key
    p.hold_key_to_apply = hold_key
    return p


@pytest.mark.parametrize("name, value, bits", [
    ("BACKWARDS_FACTOR", k.BACKWARDS_FACTOR, 0x3F266666),
    ("MAX_SIDESTEP_ANIM_RATE", k.MAX_SIDESTEP_ANIM_RATE, 0x40400000),
    ("RUN_ANIM_SPEED", k.RUN_ANIM_SPEED, 0x40800000),
    ("RUN_TURN_FACTOR", k.RUN_TURN_FACTOR, 0x3FC00000),
    ("SIDESTEP_ANIM_SPEED", k.SIDESTEP_ANIM_SPEED, 0x3FA00000),
    ("SIDESTEP_FACTOR", k.SIDESTEP_FACTOR, 0x3F000000),
    ("WALK_ANIM_SPEED", k.WALK_ANIM_SPEED, 0x4047AE14),
    ("SIDESTEP_SPEED_SCALE", k.SIDESTEP_SPEED_SCALE, 0x3F9FBE76),
    ("DEFAULT_DISTANCE_TO_OBJECT", k.DEFAULT_DISTANCE_TO_OBJECT, 0x3F19999A),
    ("DEFAULT_WALK_RUN_THRESHOLD", k.DEFAULT_WALK_RUN_THRESHOLD, 0x3F800000),
    ("JUMP_SKILL_HEIGHT", k.JUMP_SKILL_HEIGHT, 0x41B1999A),
    ("JUMP_BASE_HEIGHT", k.JUMP_BASE_HEIGHT, 0x3D4CCCCD),
    ("MIN_JUMP_HEIGHT", k.MIN_JUMP_HEIGHT, 0x3EB33333),
    ("MAX_RUN_RATE", k.MAX_RUN_RATE, 0x40900000),
    ("RUN_SKILL_FOR_MAX_RATE", k.RUN_SKILL_FOR_MAX_RATE, 0x44480000),
])
def test_motion_constants_are_pinned_by_their_float32_bit_patterns(name, value, bits):
    assert f32_bits(value) == bits
    assert float(np.float32(value)) == value, f"{name} must be an exact float32"


def test_motion_constants_match_the_csharp_literals_and_folds_they_come_from():
    f = np.float32
    assert f32_bits(k.BACKWARDS_FACTOR) == f32_bits(6.4999998e-1)
    assert f32_bits(k.WALK_ANIM_SPEED) == f32_bits(3.1199999)
    assert k.SIDESTEP_SPEED_SCALE == f(0.5) * (f(3.1199999) / f(1.25))
    assert k.MAX_RUN_RATE == f(18.0) / f(4.0)
    assert f32_bits(k.JUMP_SKILL_HEIGHT) == f32_bits(22.2) and f32_bits(k.MIN_JUMP_HEIGHT) == f32_bits(0.35)


@pytest.mark.anchor("RawMotionState::RawMotionState")
def test_a_new_raw_state_stands_ready_out_of_combat_with_no_hold_key_and_float32_speeds():
    raw = RawMotionState.create(EXACT)
    assert (raw.current_style, raw.forward_command, raw.side_step_command, raw.turn_command) == (M.NonCombat, M.Ready, 0, 0)
    assert raw.current_hold_key == HoldKey.None_ and raw.forward_hold_key == HoldKey.Invalid
    assert type(raw.forward_speed) is np.float32 and raw.forward_speed == 1.0 and raw.actions == []


@pytest.mark.anchor("RawMotionState::ApplyMotion")
def test_the_raw_state_keeps_a_left_turn_as_sent_with_the_parameters_hold_key_unless_they_set_it():
    raw = RawMotionState.create(EXACT)
    raw.apply_motion(M.TurnLeft, params(0.5, set_hold_key=False, hold_key=HoldKey.Run))
    assert raw.turn_command == M.TurnLeft and raw.turn_hold_key == HoldKey.Run and raw.turn_speed == np.float32(0.5)
    raw.apply_motion(M.SideStepLeft, params(2.0, set_hold_key=True, hold_key=HoldKey.Run))
    assert raw.side_step_command == M.SideStepLeft and raw.side_step_hold_key == HoldKey.Invalid


@pytest.mark.anchor("RawMotionState::ApplyMotion")
def test_the_raw_state_never_records_run_forward_and_a_new_style_resets_forward_to_ready():
    raw = RawMotionState.create(EXACT)
    raw.apply_motion(M.WalkBackwards, params(1.0))
    raw.apply_motion(M.RunForward, params(3.0))
    assert raw.forward_command == M.WalkBackwards and raw.forward_speed == 1.0
    raw.apply_motion(M.SwordCombat, params())
    assert raw.current_style == M.SwordCombat and raw.forward_command == M.Ready
    raw.apply_motion(M.Twitch1, params(2.0))  # an action
    assert [(a.action, a.speed) for a in raw.actions] == [(M.Twitch1, 2.0)]
    assert raw.remove_action() == M.Twitch1 and raw.remove_action() == 0


@pytest.mark.anchor("RawMotionState::RemoveMotion")
def test_removing_a_forward_motion_other_than_the_current_one_leaves_the_raw_state_alone():
    raw = RawMotionState.create(EXACT)
    raw.apply_motion(M.WalkForward, params(2.0))
    raw.remove_motion(M.WalkBackwards)
    assert raw.forward_command == M.WalkForward and raw.forward_speed == 2.0
    raw.remove_motion(M.WalkForward)
    assert raw.forward_command == M.Ready and raw.forward_speed == 1.0 and type(raw.forward_speed) is np.float32
    raw.apply_motion(M.TurnRight, params())
    raw.remove_motion(M.TurnLeft)  # either turn clears the turn
    assert raw.turn_command == 0


@pytest.mark.anchor("InterpretedMotionState::ApplyMotion")
def test_the_interpreted_state_takes_a_left_turn_as_a_forward_substate_since_only_right_is_a_turn_there():
    state = InterpretedMotionState.create(EXACT)
    state.apply_motion(M.TurnLeft, params(1.5))
    assert state.turn_command == 0 and state.forward_command == M.TurnLeft and state.forward_speed == np.float32(1.5)
    state.apply_motion(M.TurnRight, params(-1.0))
    assert state.turn_command == M.TurnRight and state.turn_speed == -1.0


@pytest.mark.anchor("InterpretedMotionState::ApplyMotion")
def test_the_interpreted_state_takes_any_style_as_new_and_resets_forward_to_ready():
    state = InterpretedMotionState.create(EXACT)
    state.apply_motion(M.WalkForward, params(1.0))
    state.apply_motion(M.NonCombat, params())  # the same style: still resets (RawMotionState would not)
    assert state.forward_command == M.Ready and state.current_style == M.NonCombat


@pytest.mark.anchor("InterpretedMotionState::RemoveMotion")
def test_the_interpreted_state_forgets_a_style_back_to_non_combat_and_a_sidestep_right_only():
    state = InterpretedMotionState.create(EXACT)
    state.apply_motion(M.SwordCombat, params())
    state.apply_motion(M.SideStepRight, params(2.0))
    state.remove_motion(M.SideStepLeft)  # a SubState bit: not the forward command, nothing happens
    assert state.side_step_command == M.SideStepRight
    state.remove_motion(M.SideStepRight)
    state.remove_motion(M.SwordCombat)
    assert state.side_step_command == 0 and state.current_style == M.NonCombat
    assert not state.has_commands()


@pytest.mark.anchor("InterpretedMotionState::copy_movement_from")
def test_copying_movement_copies_commands_and_speeds_but_not_actions():
    a, b = InterpretedMotionState.create(EXACT), InterpretedMotionState.create(EXACT)
    a.apply_motion(M.RunForward, params(2.5))
    a.apply_motion(M.Twitch1, params())
    b.copy_movement_from(a)
    assert b.forward_command == M.RunForward and b.forward_speed == 2.5 and b.actions == []


@pytest.mark.anchor("MovementParamFlags.cs:MovementParamFlagsHelper.Get")
def test_default_movement_parameters_set_can_charge_too_so_their_flags_are_0x1ee1f_not_the_commented_0x1ee0f():
    p = MovementParameters.create(EXACT)
    assert p.flags == 0x1EE1F  # ACE's constructor sets CanCharge; its commented-out `Flags = 0x1EE0F` does not
    assert f32_bits(p.distance_to_object) == 0x3F19999A and f32_bits(p.fail_distance) == 0x7F7FFFFF
    assert type(p.speed) is np.float32 and p.hold_key_to_apply == HoldKey.Invalid


@pytest.mark.anchor("MovementParamFlags.cs:MovementParamFlagsHelper.Set")
def test_flags_written_are_read_back_bool_by_bool():
    p = MovementParameters.create(EXACT)
    p.flags = MovementParamFlags.Sticky | MovementParamFlags.DisableJumpDuringLink
    assert p.sticky and p.disable_jump_during_link and not p.can_walk and p.flags == 0x20080


@pytest.mark.anchor("MovementParameters.cs:CopySome")
def test_copy_some_leaves_out_autonomous_context_and_disable_jump_during_link():
    src = params(2.0, hold_key=HoldKey.Run)
    src.autonomous, src.context_id, src.disable_jump_during_link, src.can_run = True, 7, True, False
    dst = MovementParameters.create(EXACT)
    dst.copy_some(src)
    assert dst.speed == 2.0 and dst.hold_key_to_apply == HoldKey.Run and not dst.can_run
    assert not dst.autonomous and dst.context_id == 0 and not dst.disable_jump_during_link


@pytest.mark.anchor("MovementParameters.cs:MovementParameters(MovementParameters, bool)")
def test_a_copy_of_only_the_bits_leaves_every_float_at_csharps_default_zero():
    src = params(2.0)
    copy = MovementParameters.create_copy(src, only_bits=True)
    assert copy.flags == src.flags and copy.speed == 0.0 and copy.distance_to_object == 0.0
    assert MovementParameters.create_copy(src).speed == 2.0


@pytest.mark.anchor("MovementParameters::get_command")
def test_get_command_walks_toward_a_far_object_and_runs_past_the_threshold():
    p = MovementParameters.create(EXACT)
    f = np.float32
    assert p.get_command(f(1.0), f(0.0), 0, HoldKey.Invalid, True) == (M.WalkForward, HoldKey.None_, False)
    assert p.get_command(f(1.7), f(0.0), 0, HoldKey.Invalid, True) == (M.WalkForward, HoldKey.Run, False)
    assert p.get_command(f(0.5), f(0.0), 9, HoldKey.Invalid, True) == (0, HoldKey.None_, True)
    p.move_away, p.move_towards, p.min_distance = True, False, f(2.0)
    assert p.get_command(f(1.0), f(0.0), 0, HoldKey.Invalid, False) == (M.WalkForward, HoldKey.None_, True)


@pytest.mark.anchor("MovementParameters::towards_and_away")
def test_towards_and_away_backs_off_within_the_minimum_distance():
    p = MovementParameters.create(EXACT)
    f = np.float32
    assert p.towards_and_away(f(0.0), f(0.0), 0, False) == (M.WalkBackwards, True)
    assert p.towards_and_away(f(0.3), f(0.0), 5, False) == (0, False)
    assert p.get_desired_heading(M.WalkBackwards, False) == 180.0


@pytest.mark.anchor("MovementStruct.cs:MovementStruct(MovementType, uint, MovementParameters)")
def test_a_movement_struct_keeps_the_parameters_it_is_given():
    p = params()
    mvs = MovementStruct.create(MovementType.RawCommand, M.WalkForward, p)
    assert mvs.params is p and mvs.type == MovementType.RawCommand
    assert MovementStruct.create(MovementType.StopCompletely).params is None


@pytest.mark.anchor("MotionState::add_modifier")
def test_a_modifier_that_is_the_substate_is_refused_and_not_listed():
    from acconform.port.animation.motion_state import MotionState

    state = MotionState.create(EXACT)
    state.substate = int(M.StopTurning)  # a style's default may be a modifier-only command (shard ticks-0076)
    assert state.add_modifier(int(M.StopTurning), np.float32(1)) is False
    assert state.modifiers.count == 0
    assert state.add_modifier(int(M.Jump), np.float32(1)) is True
    assert [m.id for m in state.modifiers] == [int(M.Jump)]
