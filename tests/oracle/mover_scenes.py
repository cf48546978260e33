"""Several movers (issue 41; scene/8 `others`, feature objects.moving): named scenes of a player and the
other moving objects it meets, each answered by ACE on both runtimes and kept in
tests/oracle/data/ace_mover_outcomes.json, recorded by

    ACE_ASSEMBLY=/path/to/ACE.Server.dll python tests/oracle/mover_scenes.py --record

once with a mono build and once with a .NET 10 build. Each scene is the hand-written player (sphere r 0.48,
entered into the world by enter_world) on flat land at z = 20 and one or two other movers of the same body,
pushed by velocities held every tick (30 fps).
"""

from __future__ import annotations

import sys
from dataclasses import replace
from pathlib import Path

from acconform.flags import PhysicsState, PlayerKillerStatus
from acconform.strategies.shapes import box
from acconform.scene import Frame, OtherInputs, OtherMover, Placement, Position, SphereRec, TickStep

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from oracle.named_scenes import EDGE_SLIDE, GROUND, WALKING, cell_at, land, mover, scene, static  # noqa: E402

DATA = Path(__file__).resolve().parent / "data" / "ace_mover_outcomes.json"
DT = 1 / 30
PLAYER_2 = 0x50000002
MONSTER = 0x80000001
NPC = 0x80000002
THING = 0x80000003
BODY = (SphereRec((0.0, 0.0, 0.48), 0.48),)


def other(ident: int, weenie: str, origin, pks: str = "NPK", state: int = EDGE_SLIDE) -> OtherMover:
    return OtherMover(ident, weenie, BODY, Position(cell_at(origin[0], origin[1]), Frame(tuple(origin))), 0.4, 0.4,
                      state=state, transient_state=WALKING, player_killer_status=int(PlayerKillerStatus[pks]))


def _player(origin, pks: str = "NPK"):
    return replace(mover(origin), placement=Placement(via="enter_world"),
                   player_killer_status=int(PlayerKillerStatus[pks]))


def _steps(n: int, mine, theirs: dict, **extra) -> tuple[TickStep, ...]:
    """n ticks: the player's velocity `mine` and each other mover's velocity in `theirs` held every tick."""
    others = tuple(OtherInputs(i, velocity=v) for i, v in theirs.items())
    return tuple(TickStep(DT, velocity=mine, others=others, **extra) for _ in range(n))


def _head_on(name: str, weenie: str, ident: int, pks: tuple[str, str] = ("NPK", "NPK")):
    return scene(name, [land()], _player((60.0, 60.0, GROUND), pks[0]),
                 _steps(40, (0.0, 3.0, 0.0), {ident: (0.0, -3.0, 0.0)}),
                 others=(other(ident, weenie, (60.0, 64.0, GROUND), pks[1]),))


def collide_with_a_moving_object():
    """dereth's required scenario: the player walks into a monster walking at it; they meet half way and stop,
    each with the other in its CollisionTable."""
    return _head_on("collide_with_a_moving_object", "monster", MONSTER)


def two_players_run_through_each_other():
    """Two NPK players head-on: FindObjCollisions' PK exemption (neither is PK) lets each pass through the other."""
    return _head_on("two_players_run_through_each_other", "player", PLAYER_2)


def pk_players_run_into_each_other():
    """Two PK players head-on: no exemption (both IsPK), so they collide and stop."""
    return _head_on("pk_players_run_into_each_other", "player", PLAYER_2, ("PK", "PK"))


def pk_and_npk_players_pass_through_each_other():
    """A PK player and an NPK one head-on: the exemption holds (not both PK), they pass."""
    return _head_on("pk_and_npk_players_pass_through_each_other", "player", PLAYER_2, ("PK", "NPK"))


def player_walks_into_a_moving_object():
    """The player and a GenericObject (no creature) walking at each other."""
    return _head_on("player_walks_into_a_moving_object", "object", THING)


def player_walks_into_a_standing_npc_side_on():
    """An NPC (a Creature, not a monster) stands; the player walks across its path and grazes its side."""
    return scene("player_walks_into_a_standing_npc_side_on", [land()], _player((56.0, 60.3, GROUND)),
                 _steps(60, (3.0, 0.0, 0.0), {}), others=(other(NPC, "creature", (60.0, 60.0, GROUND)),))


def creature_pushes_along_a_wall():
    """A monster pushed diagonally into a wall slides along it (EdgeSlide off, Gravity) towards the player
    standing against the same wall, and stops short of it (the wall, a static, is an environment collision and
    never a CollisionTable record)."""
    wall = static(0x70000001, (60.0, 66.0, GROUND), box(12.0, 0.4, 3.0))
    return scene("creature_pushes_along_a_wall", [land()], _player((60.5, 65.3, GROUND)),
                 _steps(80, (0.0, 0.0, 0.0), {MONSTER: (2.0, 2.0, 0.0)}), [wall],
                 others=(other(MONSTER, "monster", (56.0, 64.0, GROUND), state=int(PhysicsState.Gravity)),))


def monster_turns_ethereal_and_is_passed():
    """The player walks at a standing monster, which turns Ethereal (its State set at a tick) before the player
    reaches it: the player walks on through it (an ethereal object's spheres are passed)."""
    steps = list(_steps(40, (0.0, 3.0, 0.0), {MONSTER: (0.0, 0.0, 0.0)}))
    steps[8] = TickStep(DT, velocity=(0.0, 3.0, 0.0),
                         others=(OtherInputs(MONSTER, state=int(EDGE_SLIDE | PhysicsState.Ethereal)),))
    return scene("monster_turns_ethereal_and_is_passed", [land()], _player((60.0, 60.0, GROUND)), steps,
                 others=(other(MONSTER, "monster", (60.0, 62.5, GROUND)),))


def a_monster_and_a_player_meet_the_player():
    """Two others, a monster and a PK player, walk at the standing PK player from either side and stop at it: their
    tables hold the player; the standing player, never stepped into them, has none."""
    return scene("a_monster_and_a_player_meet_the_player", [land()], _player((60.0, 60.0, GROUND), "PK"),
                 _steps(50, (0.0, 0.0, 0.0), {MONSTER: (0.0, -2.0, 0.0), PLAYER_2: (0.0, 2.0, 0.0)}),
                 others=(other(MONSTER, "monster", (60.0, 63.0, GROUND)), other(PLAYER_2, "player", (60.0, 57.0, GROUND), "PK")))


def player_runs_into_a_slow_monster():
    """The player runs (3 m/s) at a monster walking at it (1 m/s): the tick they meet, the player is stepped first
    (it entered the world first) and takes the gap; the monster, stepped after it, stays where it was."""
    return scene("player_runs_into_a_slow_monster", [land()], _player((60.0, 60.0, GROUND)),
                 _steps(40, (0.0, 3.0, 0.0), {MONSTER: (0.0, -1.0, 0.0)}),
                 others=(other(MONSTER, "monster", (60.0, 64.0, GROUND)),))


def monster_bumps_the_player_and_backs_off():
    """A monster walks into the standing player, then backs off: more than a second after they last touched, each
    one's CollisionTable record of the other ends (report_collision_end: CollisionRecord lifetime)."""
    steps = _steps(25, (0.0, 0.0, 0.0), {MONSTER: (0.0, -2.0, 0.0)}) + _steps(45, (0.0, 0.0, 0.0), {MONSTER: (0.0, 2.0, 0.0)})
    return scene("monster_bumps_the_player_and_backs_off", [land()], _player((60.0, 60.0, GROUND)), steps,
                 others=(other(MONSTER, "monster", (60.0, 61.5, GROUND)),))


NAMED = (collide_with_a_moving_object, two_players_run_through_each_other, pk_players_run_into_each_other,
         pk_and_npk_players_pass_through_each_other, player_walks_into_a_moving_object,
         player_walks_into_a_standing_npc_side_on, creature_pushes_along_a_wall, monster_turns_ethereal_and_is_passed,
         a_monster_and_a_player_meet_the_player, monster_bumps_the_player_and_backs_off, player_runs_into_a_slow_monster)


def scenes() -> dict:
    return {f.__name__: f() for f in NAMED}


if __name__ == "__main__" and "--record" in sys.argv:
    from oracle.live_answers import record_outcomes

    record_outcomes(scenes(), DATA, "mover scene")
