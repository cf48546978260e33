"""The motion layer's named scenes (issue 40): a player's MotionTable in the scene (scene/6,
protocol feature mover.motion) and MoveToState inputs (the tick input ``motion``).

MOTION is the list (name, behaviour, builder). ACE's answers for them, on mono and on .NET 10, are in
tests/oracle/data/ace_motion_outcomes.json, recorded by

    ACE_ASSEMBLY=/path/to/ACE.Server.dll python tests/oracle/motion_scenes.py --record

once with a mono build and once with a .NET 10 build; tests/oracle/test_motion_scenes.py checks the
port against them (fast lane) and asks live ACE again (live lane).

The player-like table has the shapes retail's human table has, small: the NonCombat style whose
default substate is Ready, cycles for Ready, WalkForward, RunForward and TurnRight (each an animation
with root motion PosFrames, WalkForward and RunForward with a Velocity, TurnRight with an Omega),
links Ready -> WalkForward and WalkForward -> Ready, and a TurnRight modifier.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

from acconform.motion_enums import HoldKey, MotionCommand as MC
from acconform.motion_scene import AnimationSpec, AnimRef, MotionDataSpec, MotionEntry, MotionInput, MotionTableSpec
from dataclasses import replace

from acconform.scene import Frame, TickStep

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from oracle.named_scenes import A9B4, START, land, mover, scene  # noqa: E402

DATA = Path(__file__).resolve().parent / "data" / "ace_motion_outcomes.json"
FPS30 = 1.0 / 30.0
NC = int(MC.NonCombat)


def _yaw(deg: float):
    h = math.radians(deg) / 2
    return (math.cos(h), 0.0, 0.0, math.sin(h))


def player_like_table() -> MotionTableSpec:
    animations = (
        AnimationSpec((Frame((0.0, 0.0, 0.0)),)),  # 0: Ready, one still frame
        AnimationSpec(tuple(Frame((0.0, 0.05 * i, 0.0)) for i in range(6))),  # 1: WalkForward, root motion forward
        AnimationSpec(tuple(Frame((0.0, 0.1 * i, 0.0)) for i in range(4))),  # 2: RunForward
        AnimationSpec(tuple(Frame((0.0, 0.0, 0.0), _yaw(-3.0 * i)) for i in range(5))),  # 3: TurnRight
        AnimationSpec((Frame((0.0, 0.0, 0.0)), Frame((0.0, 0.02, 0.0)), Frame((0.0, 0.04, 0.0)))),  # 4: a link
    )

    def data(anim: int, framerate: float, velocity=None, omega=None, bitfield: int = 0) -> MotionDataSpec:
        return MotionDataSpec((AnimRef(anim, framerate),), velocity, omega, bitfield)

    return MotionTableSpec(
        default_style=NC,
        style_defaults=((NC, int(MC.Ready)),),
        animations=animations,
        cycles=(MotionEntry(NC, int(MC.Ready), data(0, 30.0)),
                MotionEntry(NC, int(MC.WalkForward), data(1, 30.0, velocity=(0.0, 3.12, 0.0))),
                MotionEntry(NC, int(MC.RunForward), data(2, 30.0, velocity=(0.0, 4.0, 0.0))),
                MotionEntry(NC, int(MC.TurnRight), data(3, 30.0, omega=(0.0, 0.0, -1.5)))),
        links=(MotionEntry(NC, int(MC.Ready), data(4, 30.0), to=int(MC.WalkForward)),
               MotionEntry(NC, int(MC.WalkForward), data(4, 30.0), to=int(MC.Ready))),
        modifiers=(MotionEntry(NC, int(MC.TurnRight), data(3, 30.0, omega=(0.0, 0.0, -1.5))),),
    )


def walk_turn_stop():
    """Walk forward (held, hold key None) for 12 ticks at 30 fps, turn right while walking for 12, then
    release both keys and stand for 12."""
    walk = MotionInput(hold_key=int(HoldKey.None_), forward=int(MC.WalkForward), forward_hold_key=int(HoldKey.None_),
                       forward_speed=1.0)
    turn = replace(walk, turn=int(MC.TurnRight), turn_hold_key=int(HoldKey.None_), turn_speed=1.0)
    stop = MotionInput(hold_key=int(HoldKey.None_))
    steps = ((TickStep(FPS30, motion=walk),) + tuple(TickStep(FPS30) for _ in range(11))
             + (TickStep(FPS30, motion=turn),) + tuple(TickStep(FPS30) for _ in range(11))
             + (TickStep(FPS30, motion=stop),) + tuple(TickStep(FPS30) for _ in range(11)))
    m = replace(mover((60.0, 60.0, 20.0)), motion_table=player_like_table())
    return scene("a player walks forward, turns, and stops with a player-like table", [land(A9B4)], m, steps)


def strafing_table() -> MotionTableSpec:
    """player_like_table with a SideStepRight cycle (root motion sideways and a Velocity), allowed only from
    the style's default substate (Bitfield 2), and a SideStepRight modifier, as retail's human table has them."""
    t = player_like_table()
    side = AnimationSpec(tuple(Frame((0.04 * i, 0.0, 0.0)) for i in range(5)))
    cycle = MotionEntry(NC, int(MC.SideStepRight), MotionDataSpec((AnimRef(len(t.animations), 30.0),),
                                                                  (1.25, 0.0, 0.0), None, 2))
    modifier = MotionEntry(NC, int(MC.SideStepRight), MotionDataSpec((AnimRef(len(t.animations), 30.0),),
                                                                     (1.25, 0.0, 0.0), None, 0))
    return replace(t, animations=t.animations + (side,), cycles=t.cycles + (cycle,), modifiers=t.modifiers + (modifier,))


def _keys(forward=0, sidestep=0, turn=0, hold=HoldKey.None_, speed=1.0) -> MotionInput:
    """A MoveToState's keys: each command given with the hold key and speed, the state's hold key too."""
    return MotionInput(hold_key=int(hold),
                       forward=int(forward), forward_hold_key=int(hold) if forward else 0, forward_speed=speed if forward else 0.0,
                       sidestep=int(sidestep), sidestep_hold_key=int(hold) if sidestep else 0,
                       sidestep_speed=speed if sidestep else 0.0,
                       turn=int(turn), turn_hold_key=int(hold) if turn else 0, turn_speed=speed if turn else 0.0)


def _held(dt: float, n: int, keys: MotionInput | None) -> tuple[TickStep, ...]:
    """n ticks of dt, the first pressing `keys` (None: the keys stay as they are)."""
    return (TickStep(dt, motion=keys),) + tuple(TickStep(dt) for _ in range(n - 1))


RELEASE = MotionInput(hold_key=int(HoldKey.None_))
FPS60 = 1.0 / 60.0


def _jump_while_running(name: str, status: str):
    """Run forward (hold key Run) for 16 ticks at 60 fps (update_object steps every third tick here, so the
    16th tick passes without an update and UpdateTime lags the clock), jump with the local velocity
    (0, 4, 5) on the 17th, keep running and land; the Player's PlayerKillerStatus picks
    HandleActionJump's branch: FastTick keeps the lagging UpdateTime while the mover moves, the other
    branch sets it to the clock."""
    from acconform.flags import PlayerKillerStatus

    run = _keys(forward=MC.RunForward, hold=HoldKey.Run)
    steps = (_held(FPS60, 16, run) + (TickStep(FPS60, jump=(0.0, 4.0, 5.0)),)
             + tuple(TickStep(FPS60) for _ in range(83)))
    m = replace(mover((40.0, 60.0, 20.0)), motion_table=player_like_table(),
                player_killer_status=int(PlayerKillerStatus[status]))
    return scene(name, [land(A9B4)], m, steps)


def pk_player_jumps_while_running():
    return _jump_while_running("a PK player jumps while running (HandleActionJump's FastTick branch)", "PK")


def ordinary_player_jumps_while_running():
    return _jump_while_running("an ordinary (NPK) player jumps while running (HandleActionJump's other branch)", "NPK")


def _turn_in_place(name: str, fps: int):
    """Turn right in place with the Run hold key (RunTurnFactor) for a second at `fps`, then release."""
    dt = 1.0 / fps
    steps = _held(dt, fps, _keys(turn=MC.TurnRight, hold=HoldKey.Run, speed=1.4)) + _held(dt, fps // 4, RELEASE)
    m = replace(mover((60.0, 60.0, 20.0)), motion_table=player_like_table())
    return scene(name, [land(A9B4)], m, steps)


def turn_in_place_at_30fps():
    return _turn_in_place("a player turns about 180 degrees in place at 30 fps", 30)


def turn_in_place_at_250fps():
    return _turn_in_place("a player turns about 180 degrees in place at 250 fps", 250)


def strafe_run_diagonal():
    """Run forward and sidestep right at once (hold key Run) for 30 ticks at 30 fps, then release."""
    steps = _held(FPS30, 30, _keys(forward=MC.RunForward, sidestep=MC.SideStepRight, hold=HoldKey.Run)) + \
        _held(FPS30, 12, RELEASE)
    m = replace(mover((60.0, 60.0, 20.0)), motion_table=strafing_table())
    return scene("a player runs and strafes right at once, then stops", [land(A9B4)], m, steps)


def stop_on_release():
    """Run forward for 20 ticks at 60 fps, release every key on the 21st, stand for 30."""
    steps = _held(FPS60, 20, _keys(forward=MC.RunForward, hold=HoldKey.Run)) + _held(FPS60, 30, RELEASE)
    m = replace(mover((60.0, 60.0, 20.0)), motion_table=player_like_table())
    return scene("a running player stops when the keys are released", [land(A9B4)], m, steps)


def run_up_48_degree_slope_by_key():
    """The 48 degree ramp of walk_up_48_degree_slope (x = 13 to 19), run up by the RunForward key at 30 fps,
    the mover turned to face +x."""
    from oracle.named_scenes import GROUND, slope, static

    ramp = static(0x70000001, (16.0, 12.0, GROUND), slope(48.0, 6.0))
    m = mover((10.0, 12.0, GROUND))
    m = replace(m, motion_table=player_like_table(),
                begin=replace(m.begin, frame=Frame(m.begin.frame.origin, _yaw(-90.0))))
    steps = _held(FPS30, 60, _keys(forward=MC.RunForward, hold=HoldKey.Run))
    return scene("a player runs up a 48 degree slope by key", [land()], m, steps, [ramp])


def run_jump_onto_lip():
    """A 2 x 4 m slab 0.6 m high (over the step-up height 0.4) from x = 15 to 17; the player runs at it along +x
    from x = 10 at 60 fps and, a PK player, jumps with the local velocity (0, 4, 5) 30 ticks in."""
    from acconform.flags import PlayerKillerStatus
    from acconform.strategies.shapes import box
    from oracle.named_scenes import GROUND, static

    slab = static(0x70000001, (16.0, 12.0, GROUND), box(2.0, 4.0, 0.6))
    m = mover((10.0, 12.0, GROUND))
    m = replace(m, motion_table=player_like_table(), player_killer_status=int(PlayerKillerStatus.PK),
                begin=replace(m.begin, frame=Frame(m.begin.frame.origin, _yaw(-90.0))))
    steps = (_held(FPS60, 30, _keys(forward=MC.RunForward, hold=HoldKey.Run)) + (TickStep(FPS60, jump=(0.0, 4.0, 5.0)),)
             + tuple(TickStep(FPS60) for _ in range(69)))
    return scene("a player runs and jumps onto a lip above its step-up height", [land()], m, steps, [slab])


def run_with_run_skill_300():
    """Walk forward with the Run hold key for 30 ticks at 30 fps, then release for 12: a Player whose run skill
    is 300 (GetCreatureSkill(Skill.Run).Current). apply_run_to_command makes the key RunForward at the speed
    InqRunRate answers, GetRunRate(0, 300, 1) = 2.65, not the database-free Player's 1."""
    from acconform.scene import MoverSkills

    steps = _held(FPS30, 30, _keys(forward=MC.WalkForward, hold=HoldKey.Run)) + _held(FPS30, 12, RELEASE)
    m = replace(mover((60.0, 40.0, 20.0)), motion_table=player_like_table(), skills=MoverSkills(run=300))
    return scene("a player with a run skill of 300 runs, then stops", [land(A9B4)], m, steps)


def skilled_player_jumps_while_running():
    """An ordinary player with a run skill of 300, a jump skill of 250, no stamina, Strength 100 and a load
    of 20,000 (burden 4/3 of its capacity 15,000 + 1 carrying-capacity augmentation's 3,000) runs (the
    WalkForward key held with Run: RunForward at the run rate 2.65) for 16 ticks at 60 fps, jumps with
    the local velocity (0, 4, 5) and lands: HandleActionJump's physics sets the JumpPack's velocity;
    leaving the ground asks get_state_velocity, capped at the run rate's speed."""
    from acconform.scene import MoverSkills

    steps = (_held(FPS60, 16, _keys(forward=MC.WalkForward, hold=HoldKey.Run)) + (TickStep(FPS60, jump=(0.0, 4.0, 5.0)),)
             + tuple(TickStep(FPS60) for _ in range(83)))
    skills = MoverSkills(run=300, jump=250, stamina=0, strength=100, encumbrance_val=20000,
                         augmentation_increased_carrying_capacity=1)
    m = replace(mover((40.0, 40.0, 20.0)), motion_table=player_like_table(), skills=skills)
    return scene("a skilled, loaded player without stamina jumps while running", [land(A9B4)], m, steps)


MOTION = (
    ("player_walks_turns_and_stops", "the MoveToState keys become interpreted motions, the table's cycles, links and "
     "modifier play, and update_object moves the mover by root motion and get_state_velocity", walk_turn_stop),
    ("pk_player_jumps_while_running", "a PK player's jump (FastTick) keeps UpdateTime while the mover moves: the "
     "time since the last update is stepped", pk_player_jumps_while_running),
    ("ordinary_player_jumps_while_running", "an ordinary player's jump sets UpdateTime to the clock: the time since "
     "the last update is dropped", ordinary_player_jumps_while_running),
    ("turn_in_place_at_30fps", "a turn in place by key at 30 fps, then released", turn_in_place_at_30fps),
    ("turn_in_place_at_250fps", "the same turn at 250 fps: ticks under MinQuantum carry their time", turn_in_place_at_250fps),
    ("strafe_run_diagonal", "forward and sidestep keys at once: the sidestep is allowed only from the default "
     "substate (Bitfield 2)", strafe_run_diagonal),
    ("stop_on_release", "releasing every key stops the run cycle and the mover", stop_on_release),
    ("run_up_48_degree_slope_by_key", "root motion and the run cycle's velocity carry the mover up a walkable slope",
     run_up_48_degree_slope_by_key),
    ("run_jump_onto_lip", "a running PK player's jump clears a lip it cannot step up", run_jump_onto_lip),
    ("run_with_run_skill_300", "the Player's run skill sets the run rate (InqRunRate): the run cycle's speed and "
     "get_state_velocity's cap", run_with_run_skill_300),
    ("skilled_player_jumps_while_running", "a Player's run and jump skills, stamina, strength and burden (scene/8 "
     "mover.skills) under a running jump", skilled_player_jumps_while_running),
)


def scenes() -> dict:
    return {name: build() for name, _, build in MOTION}


if __name__ == "__main__" and "--record" in sys.argv:
    from oracle.live_answers import record_outcomes

    record_outcomes(scenes(), DATA, "motion scene")
