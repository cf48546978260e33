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


MOTION = (
    ("player_walks_turns_and_stops", "the MoveToState keys become interpreted motions, the table's cycles, links and "
     "modifier play, and update_object moves the mover by root motion and get_state_velocity", walk_turn_stop),
)


def scenes() -> dict:
    return {name: build() for name, _, build in MOTION}


if __name__ == "__main__" and "--record" in sys.argv:
    from oracle.live_answers import record_outcomes

    record_outcomes(scenes(), DATA, "motion scene")
