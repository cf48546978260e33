"""The server's calls into the motion layer's managers (issue 40): one named scene per tick input --
move_to, turn_to_heading, move_to_object (sticky), turn_to_object, the three stops, do_motion and
stop_motion -- each a player with tests/oracle/motion_scenes.py's player-like table on flat land, and
a 1 m sphere (a static the server files by id) to move or turn to.

tests/oracle/test_manager_inputs.py compares the port with ACE's answers recorded on mono and .NET 10 in
tests/oracle/data/ace_manager_outcomes.json (fast lane), recorded by

    ACE_ASSEMBLY=/path/to/ACE.Server.dll python tests/oracle/manager_scenes.py --record

once with a mono build and once with a .NET 10 build, and asks live ACE again (live lane).
"""

from __future__ import annotations

import sys
from dataclasses import replace
from pathlib import Path

from acconform.motion_enums import MotionCommand as MC, MovementParamFlags as MPF
from acconform.motion_scene import DEFAULT_MOVEMENT_FLAGS, CommandInput, MovementParams, MoveToInput, ObjectMoveInput
from acconform.flags import PhysicsState
from acconform.scene import Frame, OtherInputs, Placement, Position, SphereRec, SphereShape, StaticObject, TickStep

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from oracle.motion_scenes import FPS30, player_like_table  # noqa: E402
from oracle.named_scenes import GROUND, cell_at, land, mover, scene  # noqa: E402

BALL = 0x70000002
BOX = 0x70000003
DATA = Path(__file__).resolve().parent / "data" / "ace_manager_outcomes.json"


def _scene(name: str, steps, objects=()):
    m = replace(mover((60.0, 60.0, GROUND)), motion_table=player_like_table())
    return scene(name, [land()], m, tuple(steps), objects)


def _idle(n: int, dt: float = FPS30):
    return tuple(TickStep(dt) for _ in range(n))


def _ball():
    return StaticObject(BALL, Position(cell_at(70.0, 66.0), Frame((70.0, 66.0, GROUND))),
                        SphereShape(SphereRec((0.0, 0.0, 0.5), 1.0)))


def _box():
    """A 2 x 2 x 2 m box standing between the player at (60, 60) and the point (66, 66): a MoveTo walks
    straight at its target (ACE's MoveToManager does not find a way round) and slides along the box."""
    from acconform.strategies.shapes import box

    return StaticObject(BOX, Position(cell_at(63.0, 63.0), Frame((63.0, 63.0, GROUND))), box(2.0, 2.0, 2.0),
                        int(PhysicsState.Static | PhysicsState.HasPhysicsBSP))


def _to(x: float, y: float, params=MovementParams()) -> MoveToInput:
    return MoveToInput(params, Position(cell_at(x, y), Frame((x, y, GROUND))))


def scenes() -> dict:
    out = {
        "move_to_a_point": _scene("move_to_a_point", (TickStep(FPS30, move_to=_to(66.0, 64.0)),) + _idle(60)),
        "move_to_at_4fps_overshoots": _scene("move_to_at_4fps_overshoots",
                                             (TickStep(0.25, move_to=_to(62.0, 63.0, MovementParams(distance_to_object=0.1))),)
                                             + _idle(12, 0.25)),
        "move_to_around_a_box": _scene("move_to_around_a_box", (TickStep(FPS30, move_to=_to(66.0, 66.0)),) + _idle(90),
                                       [_box()]),
        "turn_to_heading_in_place": _scene("turn_to_heading_in_place", (TickStep(FPS30, turn_to_heading=MoveToInput(
            MovementParams(desired_heading=135.0))),) + _idle(30)),
        "sticky_move_to_a_static": _scene("sticky_move_to_a_static", (TickStep(FPS30, move_to_object=ObjectMoveInput(
            BALL, MovementParams(flags=DEFAULT_MOVEMENT_FLAGS | MPF.Sticky))),) + _idle(80), [_ball()]),
        "turn_to_a_static": _scene("turn_to_a_static", (TickStep(FPS30, turn_to_object=ObjectMoveInput(BALL)),) + _idle(30),
                                   [_ball()]),
        "keys_do_and_stop_motion": _scene("keys_do_and_stop_motion", (
            TickStep(FPS30, do_motion=CommandInput(int(MC.Ready), 1)),
            TickStep(FPS30, do_motion=CommandInput(int(MC.WalkForward), 1))) + _idle(10)
            + (TickStep(FPS30, stop_motion=CommandInput(int(MC.WalkForward), 1)),) + _idle(10)),
    }
    for stop in ("stop_completely", "cancel_moveto", "move_to_manager_cancel"):
        out[f"move_to_then_{stop}"] = _scene(f"move_to_then_{stop}", (TickStep(FPS30, move_to=_to(66.0, 64.0)),)
                                             + _idle(8) + (TickStep(FPS30, stop=stop),) + _idle(8))
    out["sticky_follow_of_a_moving_target"] = sticky_follow_of_a_moving_target()
    return out


def sticky_follow_of_a_moving_target():
    """A monster's melee chase (scene/8, feature objects.targets): the player makes the sticky MoveToObject a
    melee monster makes (Monster_Navigation.GetMovementParameters: CanWalk off; FailWalk, UseFinalHeading,
    Sticky, MoveAway) at another player 4 m ahead, who walks away along +x at 2 m/s for a second, stands for
    two thirds of one, walks back toward it for a second and stands for two: the MoveTo follows the target's
    voyeur updates (TargetManager.HandleTargetting, ReceiveUpdate), arrives, sticks to it (StickyManager)
    and is drawn along as the target walks on and back (stop-and-go)."""
    from oracle.mover_scenes import PLAYER_2, other

    flags = (DEFAULT_MOVEMENT_FLAGS & ~int(MPF.CanWalk)) | int(MPF.FailWalk | MPF.UseFinalHeading | MPF.Sticky
                                                                | MPF.MoveAway)
    m = replace(mover((60.0, 60.0, GROUND)), motion_table=player_like_table(), placement=Placement(via="enter_world"))

    def walk(n: int, vx: float) -> tuple:
        return tuple(TickStep(FPS30, others=(OtherInputs(PLAYER_2, velocity=(vx, 0.0, 0.0)),)) for _ in range(n))

    steps = ((TickStep(FPS30, move_to_object=ObjectMoveInput(PLAYER_2, MovementParams(flags=flags)),
                       others=(OtherInputs(PLAYER_2, velocity=(2.0, 0.0, 0.0)),)),)
             + walk(29, 2.0) + walk(20, 0.0) + walk(30, -2.0) + walk(1, 0.0) + _idle(59))
    target = other(PLAYER_2, "player", (64.0, 60.0, GROUND))
    return scene("sticky_follow_of_a_moving_target", [land()], m, steps, (), others=(target,))


if __name__ == "__main__" and "--record" in sys.argv:
    from oracle.live_answers import record_outcomes

    record_outcomes(scenes(), DATA, "manager scene")
