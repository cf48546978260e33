"""The motion layer against live ACE (lane `live_oracle`): the same RawMotionState,
InterpretedMotionState, MovementParameters and MotionInterp built in ACE (through pythonnet, on
ACE's own types) and in the port, the same routine run on both, compared bit for bit.

ACE's MotionInterp is made with its parameterless constructor and given its states by hand (as the
port's is with `motion_helpers.interp(default_state=False)`), so no PhysicsObj or motion table is
needed for the routines that read only the states and the WeenieObject. The WeenieObject is null,
ACE's DummyObject (not a creature), or a creature with no WorldObject (DummyObject's private
constructor, IsCreature set by reflection): InqRunRate's run skill is then 0, so its rate is 1.
"""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from acconform.motion_enums import HoldKey, MotionCommand as M
from acconform.numerics import EXACT, RUNTIMES, f32_bits
from acconform.port.animation import movement_system as ms
from acconform.port.animation.interpreted_motion_state import InterpretedMotionState
from acconform.port.animation.movement_parameters import MovementParameters
from acconform.port.animation.raw_motion_state import RawMotionState

from motion_helpers import CreatureWeenie, ItemWeenie, interp

pytestmark = pytest.mark.live_oracle

f = np.float32
MOTIONS = [M.Ready, M.WalkForward, M.WalkBackwards, M.RunForward, M.TurnRight, M.TurnLeft, M.SideStepRight,
           M.SideStepLeft, M.Falling, M.Crouch, M.Twitch1, M.SwordCombat, M.NonCombat, M.Dead, 0]
SPEEDS = [0.0, -0.0, 1.0, -1.0, 0.5, 1.5, 2.999, 3.0, 4.75, -7.25, 1e-7, 123456.0, 0.1]
HOLD_KEYS = [HoldKey.Invalid, HoldKey.None_, HoldKey.Run]
WEENIES = ["null", "dummy", "creature"]


def _bits_equal(a, b) -> bool:
    return f32_bits(a) == f32_bits(b)


@pytest.fixture(scope="module")
def ace(live):
    import System  # type: ignore[import-not-found]
    from ACE.Server.Physics import Animation  # type: ignore[import-not-found]
    from ACE.Server.Physics.Common import WeenieObject  # type: ignore[import-not-found]

    wt = System.Type.GetType("ACE.Server.Physics.Common.WeenieObject, ACE.Server")
    creature = System.Activator.CreateInstance(wt, True)
    wt.GetField("IsCreature").SetValue(creature, True)
    assert creature.IsCreature and not WeenieObject.DummyObject.IsCreature
    return Animation, {"null": None, "dummy": WeenieObject.DummyObject, "creature": creature}


def _ace_interp(ace, weenie, my_run_rate=1.0):
    Animation, weenies = ace
    mi = Animation.MotionInterp()
    mi.RawState = Animation.RawMotionState()
    mi.InterpretedState = Animation.InterpretedMotionState()
    mi.MyRunRate = my_run_rate
    mi.CurrentSpeedFactor = 1.0
    mi.WeenieObj = weenies[weenie]
    return mi


def _port_interp(weenie, my_run_rate=1.0):
    mi = interp({"null": None, "dummy": ItemWeenie(), "creature": CreatureWeenie(run_skill=0)}[weenie],
                default_state=False)
    mi.raw_state = RawMotionState.create(EXACT)
    mi.interpreted_state = InterpretedMotionState.create(EXACT)
    mi.my_run_rate = f(my_run_rate)
    return mi


@pytest.mark.anchor("CMotionInterp::adjust_motion")
def test_adjust_motion_matches_ace_for_every_motion_speed_hold_key_and_weenie(ace):
    from ACE.Entity.Enum import HoldKey as AceHoldKey  # type: ignore[import-not-found]

    cases = 0
    for weenie, raw_key, run_rate in itertools.product(WEENIES, (HoldKey.None_, HoldKey.Run), (1.0, 2.5)):
        a, p = _ace_interp(ace, weenie, run_rate), _port_interp(weenie, run_rate)
        a.RawState.CurrentHoldKey = AceHoldKey(int(raw_key))
        p.raw_state.current_hold_key = raw_key
        for motion, speed, key in itertools.product(MOTIONS, SPEEDS, HOLD_KEYS):
            am, aspeed = a.adjust_motion(int(motion), float(f(speed)), AceHoldKey(int(key)))
            pm, pspeed = p.adjust_motion(motion, f(speed), key)
            assert (am, f32_bits(aspeed)) == (int(pm), f32_bits(pspeed)), (weenie, raw_key, motion, speed, key)
            cases += 1
    assert cases == 3 * 2 * 2 * len(MOTIONS) * len(SPEEDS) * len(HOLD_KEYS)


@pytest.mark.anchor("CMotionInterp::get_state_velocity")
def test_state_velocity_and_max_speeds_match_ace(ace):
    sides, forwards = [0, M.SideStepRight, M.SideStepLeft], [M.Ready, M.WalkForward, M.RunForward, M.WalkBackwards]
    for weenie, run_rate in itertools.product(WEENIES, (1.0, 0.75, 3.5)):
        a, p = _ace_interp(ace, weenie, run_rate), _port_interp(weenie, run_rate)
        for side, fwd, sspeed, fspeed in itertools.product(sides, forwards, SPEEDS[::2], SPEEDS[1::2]):
            a.InterpretedState.SideStepCommand, p.interpreted_state.side_step_command = int(side), side
            a.InterpretedState.ForwardCommand, p.interpreted_state.forward_command = int(fwd), fwd
            a.InterpretedState.SideStepSpeed, p.interpreted_state.side_step_speed = float(f(sspeed)), f(sspeed)
            a.InterpretedState.ForwardSpeed, p.interpreted_state.forward_speed = float(f(fspeed)), f(fspeed)
            av, pv = a.get_state_velocity(), p.get_state_velocity()
            assert [f32_bits(c) for c in (av.X, av.Y, av.Z)] == [f32_bits(c) for c in pv], (weenie, side, fwd, sspeed, fspeed)
            assert _bits_equal(a.get_max_speed(), p.get_max_speed())
            assert _bits_equal(a.get_adjusted_max_speed(), p.get_adjusted_max_speed())


@pytest.mark.anchor("CMotionInterp::motion_allows_jump")
def test_motion_allows_jump_and_jump_charge_is_allowed_match_ace_for_every_motion_command(ace):
    a, p = _ace_interp(ace, "creature"), _port_interp("creature")
    for motion in M:
        assert int(a.motion_allows_jump(int(motion))) == int(p.motion_allows_jump(motion)), motion.name
        a.InterpretedState.ForwardCommand = int(motion)
        p.interpreted_state.forward_command = motion
        assert int(a.jump_charge_is_allowed()) == int(p.jump_charge_is_allowed()), motion.name


def _ace_params(ace, speed, set_hold_key, key, stamp=0, autonomous=False):
    from ACE.Entity.Enum import HoldKey as AceHoldKey  # type: ignore[import-not-found]

    mp = ace[0].MovementParameters()
    mp.Speed, mp.SetHoldKey, mp.HoldKeyToApply = float(f(speed)), set_hold_key, AceHoldKey(int(key))
    mp.ActionStamp, mp.Autonomous = stamp, autonomous
    return mp


def _port_params(speed, set_hold_key, key, stamp=0, autonomous=False):
    mp = MovementParameters.create(EXACT)
    mp.speed, mp.set_hold_key, mp.hold_key_to_apply = f(speed), set_hold_key, key
    mp.action_stamp, mp.autonomous = stamp, autonomous
    return mp


def _raw_fields(s, ace: bool):
    if ace:
        return (int(s.CurrentHoldKey), s.CurrentStyle, s.ForwardCommand, int(s.ForwardHoldKey), f32_bits(s.ForwardSpeed), s.SideStepCommand,
                int(s.SideStepHoldKey), f32_bits(s.SideStepSpeed), s.TurnCommand, int(s.TurnHoldKey), f32_bits(s.TurnSpeed),
                [(n.Action, f32_bits(n.Speed), n.Stamp, n.Autonomous) for n in s.Actions])
    return (int(s.current_hold_key), int(s.current_style), int(s.forward_command), int(s.forward_hold_key),
            f32_bits(s.forward_speed), int(s.side_step_command), int(s.side_step_hold_key), f32_bits(s.side_step_speed),
            int(s.turn_command), int(s.turn_hold_key), f32_bits(s.turn_speed),
            [(int(n.action), f32_bits(n.speed), n.stamp, n.autonomous) for n in s.actions])


def _interpreted_fields(s, ace: bool):
    if ace:
        return (s.CurrentStyle, s.ForwardCommand, f32_bits(s.ForwardSpeed), s.SideStepCommand, f32_bits(s.SideStepSpeed),
                s.TurnCommand, f32_bits(s.TurnSpeed), [(n.Action, f32_bits(n.Speed), n.Stamp, n.Autonomous) for n in s.Actions])
    return (int(s.current_style), int(s.forward_command), f32_bits(s.forward_speed), int(s.side_step_command),
            f32_bits(s.side_step_speed), int(s.turn_command), f32_bits(s.turn_speed),
            [(int(n.action), f32_bits(n.speed), n.stamp, n.autonomous) for n in s.actions])


@pytest.mark.anchor("RawMotionState::ApplyMotion")
@pytest.mark.parametrize("seed", range(4))
def test_motion_states_apply_and_remove_the_same_random_motions_as_ace(ace, seed):
    Animation = ace[0]
    rng = np.random.default_rng(seed)
    ar, pr = Animation.RawMotionState(), RawMotionState.create(EXACT)
    ai, pi = Animation.InterpretedMotionState(), InterpretedMotionState.create(EXACT)
    copy_a, copy_p = Animation.InterpretedMotionState(), InterpretedMotionState.create(EXACT)
    for step in range(200):
        motion = MOTIONS[rng.integers(len(MOTIONS))]
        speed = SPEEDS[rng.integers(len(SPEEDS))]
        key = HOLD_KEYS[rng.integers(3)]
        set_key, stamp, auto = bool(rng.integers(2)), int(rng.integers(-5, 70000)), bool(rng.integers(2))
        if rng.integers(3) == 0:
            ar.RemoveMotion(int(motion)); pr.remove_motion(motion)
            ai.RemoveMotion(int(motion)); pi.remove_motion(motion)
        elif rng.integers(6) == 0:
            assert ar.RemoveAction() == pr.remove_action() and ai.RemoveAction() == pi.remove_action()
        else:
            amp, pmp = _ace_params(ace, speed, set_key, key, stamp, auto), _port_params(speed, set_key, key, stamp, auto)
            ar.ApplyMotion(int(motion), amp); pr.apply_motion(motion, pmp)
            ai.ApplyMotion(int(motion), amp); pi.apply_motion(motion, pmp)
        assert _raw_fields(ar, True) == _raw_fields(pr, False), step
        assert _interpreted_fields(ai, True) == _interpreted_fields(pi, False), step
        assert ai.GetNumActions() == pi.get_num_actions() and ai.HasCommands() == pi.has_commands()
    copy_a.copy_movement_from(ai); copy_p.copy_movement_from(pi)
    assert _interpreted_fields(copy_a, True) == _interpreted_fields(copy_p, False)


@pytest.mark.anchor("MovementParameters::get_command")
def test_movement_parameters_commands_and_flags_match_ace(ace):
    from ACE.Entity.Enum import HoldKey as AceHoldKey  # type: ignore[import-not-found]

    Animation = ace[0]
    a, p = Animation.MovementParameters(), MovementParameters.create(EXACT)
    assert int(a.Flags) == p.flags
    dists = [0.0, 0.0001, 0.3, 0.6, 0.61, 1.6, 1.61, 5.0]
    for towards, away, can_run, can_walk in itertools.product((True, False), repeat=4):
        a.MoveTowards, a.MoveAway, a.CanRun, a.CanWalk = towards, away, can_run, can_walk
        p.move_towards, p.move_away, p.can_run, p.can_walk = towards, away, can_run, can_walk
        a.MinDistance, p.min_distance = 0.3, f(0.3)
        assert int(a.Flags) == p.flags
        for dist in dists:
            ar = a.get_command(float(f(dist)), 0.0, 7, AceHoldKey.Invalid, True)
            pr = p.get_command(f(dist), f(0.0), 7, HoldKey.Invalid, True)
            assert (ar[0], int(ar[1]), ar[2]) == (int(pr[0]), int(pr[1]), pr[2]), (towards, away, can_run, can_walk, dist)
            for motion in (M.WalkForward, M.RunForward, M.WalkBackwards, M.Ready):
                for moving_away in (True, False):
                    assert _bits_equal(a.get_desired_heading(int(motion), moving_away), p.get_desired_heading(motion, moving_away))
    copy = Animation.MovementParameters(a, True)
    assert int(copy.Flags) == MovementParameters.create_copy(p, True).flags and copy.Speed == 0.0


@pytest.mark.anchor("MovementSystem.cs:GetRunRate")
def test_movement_system_matches_ace_over_skills_burdens_and_powers(ace, live):
    System = ace[0].MovementSystem
    runtime = RUNTIMES[live.location.runtime]
    burdens = [0.0, 0.5, 0.999, 1.0, 1.3, 1.999, 2.0, 2.7]
    for burden, skill in itertools.product(burdens, [0, 1, 10, 100, 199, 200, 299, 300, 500, 799, 800, 1200]):
        for scaling in (1.0, 0.75):
            assert System.GetRunRate(float(f(burden)), skill, scaling) == ms.get_run_rate(f(burden), skill, f(scaling))
        for power in (-0.5, 0.0, 0.1, 0.5, 0.999, 1.0, 1.5):
            assert _bits_equal(System.GetJumpHeight(float(f(burden)), skill, float(f(power)), 1.0),
                               ms.get_jump_height(f(burden), skill, f(power), f(1.0)))
            for pk in (True, False):
                assert System.JumpStaminaCost(float(f(power)), float(f(burden)), pk) == ms.jump_stamina_cost(
                    f(power), f(burden), pk, runtime), (power, burden, pk)
        for pk in (True, False):
            assert _bits_equal(System.GetJumpPower(skill, float(f(burden)), pk), ms.get_jump_power(skill, f(burden), pk))


def _objects(ace, live, state, transient, orientation, velocity):
    """ACE's `new PhysicsObj()` and the port's PhysicsObj.create, given the same flags, orientation
    and (global) velocity."""
    from System.Numerics import Quaternion, Vector3  # type: ignore[import-not-found]
    from ACE.Server.Physics import PhysicsObj as AcePhysicsObj  # type: ignore[import-not-found]
    from ACE.Server.Physics.Common import Position as AcePosition  # type: ignore[import-not-found]

    from acconform.numerics import get_mode
    from acconform.port.frame import AFrame, Position
    from acconform.port.physics_obj import PhysicsObj
    from acconform.port.physics_timer import PhysicsTimer

    mode = get_mode("exact", live.location.runtime)
    a = AcePhysicsObj()
    a.State = a.State.__class__(state)
    a.TransientState = a.TransientState.__class__(transient)
    a.Position = AcePosition(0xA9B40001)
    a.Position.Frame.Orientation = Quaternion(*[float(f(c)) for c in orientation])
    a.Velocity = Vector3(*[float(f(c)) for c in velocity])
    p = PhysicsObj.create(mode, PhysicsTimer())
    p.state, p.transient_state = state, transient
    p.position = Position(0xA9B40001, AFrame(mode.vec(0, 0, 0), mode.quat(*orientation)))
    p.velocity = mode.vec(*velocity)
    return a, p


@pytest.mark.anchor("CMotionInterp::get_leave_ground_velocity")
def test_contact_rules_and_the_leave_ground_velocity_on_a_physics_obj_match_ace(ace, live):
    from acconform.flags import PhysicsState, TransientState

    c, w = TransientState.Contact, TransientState.OnWalkable
    orientations = [(0, 0, 0, 1), (0, 0, 0.38268343, 0.9238795), (0.1, -0.2, 0.7, 0.67823300)]
    checked = 0
    for weenie, state, transient, orientation in itertools.product(
            WEENIES, (PhysicsState.Gravity, 0), (0, c, c | w, w), orientations):
        a_obj, p_obj = _objects(ace, live, state, transient, orientation, (1.5, -2.25, 0.75))
        a, p = _ace_interp(ace, weenie, 1.25), _port_interp(weenie, 1.25)
        a.PhysicsObj, p.physics_obj = a_obj, p_obj
        for motion in MOTIONS:
            assert a.contact_allows_move(int(motion)) == p.contact_allows_move(motion), (weenie, state, transient, motion)
        assert a.is_standing_still() == p.is_standing_still()
        for fwd, extent in itertools.product((M.Ready, M.WalkForward, M.RunForward), (0.0, 0.0001, 0.5, 1.0, 2.0)):
            a.InterpretedState.ForwardCommand, p.interpreted_state.forward_command = int(fwd), fwd
            a.JumpExtent, p.jump_extent = float(f(extent)), f(extent)
            av, pv = a.get_leave_ground_velocity(), p.get_leave_ground_velocity()
            assert [f32_bits(x) for x in (av.X, av.Y, av.Z)] == [f32_bits(x) for x in pv], (weenie, orientation, fwd, extent)
            checked += 1
    assert checked == 3 * 2 * 4 * 3 * 15
