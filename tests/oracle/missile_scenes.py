"""Missiles and spell projectiles (issue 41; scene/8 `others[].launch`, feature missiles): named scenes of an arrow
or a spell launched at a tick, each answered by ACE on both runtimes and kept in
tests/oracle/data/ace_missile_outcomes.json, recorded by

    ACE_ASSEMBLY=/path/to/ACE.Server.dll python tests/oracle/missile_scenes.py --record

once with a mono build and once with a .NET 10 build. Each scene is the hand-written player (sphere r 0.48, entered
by enter_world) on flat land at z = 20, facing +y, an arrow (an Ammunition: one 0.05 m sphere, Gravity) or a
spell (a SpellProjectile: one 0.15 m sphere, no gravity unless an arc) made at the start and launched at tick 2
from 0.8 m in front of its launcher's centre at 1.2 m, at 30 fps.
"""

from __future__ import annotations

import sys
from dataclasses import replace
from pathlib import Path

from acconform.flags import PhysicsState
from acconform.strategies.shapes import box
from acconform.scene import (CylSphereShape, Frame, Launch, OtherInputs, OtherMover, Placement, Position, SphereRec,
                             StaticObject, TickStep)

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from oracle.named_scenes import EDGE_SLIDE, GROUND, WALKING, cell_at, land, mover, scene, static  # noqa: E402

DATA = Path(__file__).resolve().parent / "data" / "ace_missile_outcomes.json"
DT = 1 / 30
PLAYER = 0x50000001  # the mover (acconform.staging.MOVER_ID)
MONSTER = 0x80000001
ARROW = 0x80000010
SPELL = 0x80000011
WALL = 0x70000001
DOOR = 0x70000002
POST = 0x70000003
BODY = (SphereRec((0.0, 0.0, 0.48), 0.48),)
ARROW_BODY = (SphereRec((0.0, 0.0, 0.0), 0.05),)
SPELL_BODY = (SphereRec((0.0, 0.0, 0.0), 0.15),)
LAUNCH_TICK = 2
EYE = 1.2


def _player(origin):
    return replace(mover(origin), placement=Placement(via="enter_world"))


def monster(origin) -> OtherMover:
    return OtherMover(MONSTER, "monster", BODY, Position(cell_at(origin[0], origin[1]), Frame(tuple(origin))), 0.4, 0.4,
                      state=EDGE_SLIDE, transient_state=WALKING)


def arrow(launcher_at, target: int, speed: float = 20.0, launcher: int = PLAYER) -> OtherMover:
    """An arrow made where its launcher stands and launched at tick 2 from 0.8 m ahead (+y) at eye level."""
    x, y, z = launcher_at
    return OtherMover(ARROW, "ammunition", ARROW_BODY, Position(cell_at(x, y), Frame((x, y, z))), 0.0, 0.0,
                      state=int(PhysicsState.Gravity), transient_state=0,
                      launch=Launch(LAUNCH_TICK, launcher, target, speed, (x, y + 0.8, z + EYE)))


def spell(launcher_at, target: int, launcher: int, direction: float = 1.0, speed: float = 15.0, arc: bool = False) -> OtherMover:
    x, y, z = launcher_at
    return OtherMover(SPELL, "spell_projectile", SPELL_BODY, Position(cell_at(x, y), Frame((x, y, z))), 0.0, 0.0,
                      state=int(PhysicsState.Gravity) if arc else 0, transient_state=0,
                      launch=Launch(LAUNCH_TICK, launcher, target, speed, (x, y + 0.8 * direction, z + EYE), arc=arc))


def _steps(n: int, theirs: dict | None = None) -> tuple[TickStep, ...]:
    others = tuple(OtherInputs(i, velocity=v) for i, v in (theirs or {}).items())
    return tuple(TickStep(DT, velocity=(0.0, 0.0, 0.0), others=others) for _ in range(n))


def _wall(y: float = 70.0):
    return static(WALL, (60.0, y, GROUND), box(12.0, 0.4, 4.0))


def _door(ethereal: bool):
    """A door: a BSP slab 2 m wide, 0.2 m thick, 3 m tall across the flight at y = 65, no Static flag (a server's
    door is a WorldObject); open, it is Ethereal."""
    state = int(PhysicsState.HasPhysicsBSP) | (int(PhysicsState.Ethereal) if ethereal else 0)
    return StaticObject(DOOR, Position(cell_at(60.0, 65.0), Frame((60.0, 65.0, GROUND))), box(2.0, 0.2, 3.0), state)


def arrow_into_a_wall():
    """The player shoots the wall 10 m ahead: the static reports an environment collision (Missile cleared), and
    Ammunition.OnCollideEnvironment's helper removes the arrow from its landblock (DestroyObject)."""
    return scene("arrow_into_a_wall", [land()], _player((60.0, 60.0, GROUND)), _steps(30), [_wall()],
                 others=(arrow((60.0, 60.0, GROUND), WALL),))


def arrow_through_an_open_door():
    """An open door (Ethereal, no WorldObject) between the player and the wall: MissileIgnore passes it, the arrow
    strikes the wall behind."""
    return scene("arrow_through_an_open_door", [land()], _player((60.0, 60.0, GROUND)), _steps(30), [_wall(), _door(True)],
                 others=(arrow((60.0, 60.0, GROUND), WALL),))


def arrow_into_a_closed_door():
    """The same door closed: the arrow strikes it (an object collision with a static that has no WorldObject: no
    OnCollideObject, the missile bits cleared) and falls."""
    return scene("arrow_into_a_closed_door", [land()], _player((60.0, 60.0, GROUND)), _steps(30), [_wall(), _door(False)],
                 others=(arrow((60.0, 60.0, GROUND), WALL),))


def arrow_at_a_monster_standing_at_a_wall():
    """A monster stands against the wall; the arrow strikes it: ProjectileCollisionHelper's hit on its target
    (RemoveWorldObject, set_active(false))."""
    return scene("arrow_at_a_monster_standing_at_a_wall", [land()], _player((60.0, 60.0, GROUND)), _steps(30),
                 [_wall()], others=(monster((60.0, 69.3, GROUND)), arrow((60.0, 60.0, GROUND), MONSTER)))


def monster_runs_into_an_arrow_at_it():
    """A monster runs (6 m/s) at the player; the arrow (12 m/s), launched at it, leads it (the moving target's
    CachedVelocity: the quartic solver). The monster is stepped before the arrow (it entered first): a mover that is
    no player ignores a missile (ObjectInfo.MissileIgnore), so it runs into the arrow's sphere unhindered and the
    arrow's own step strikes it."""
    return scene("monster_runs_into_an_arrow_at_it", [land()], _player((60.0, 60.0, GROUND)),
                 _steps(45, {MONSTER: (0.0, -6.0, 0.0)}), [_wall()],
                 others=(monster((60.0, 66.0, GROUND)), arrow((60.0, 60.0, GROUND), MONSTER, speed=12.0)))


def arrow_grazing_a_cylsphere_post():
    """A post (a static cylsphere, r 0.3) whose edge lies 0.045 m off the arrow's line: the arrow's 0.05 m sphere
    grazes it on the way to the wall."""
    post = StaticObject(POST, Position(cell_at(60.345, 65.0), Frame((60.345, 65.0, GROUND))),
                        CylSphereShape((0.0, 0.0, 0.0), 0.3, 3.0), int(PhysicsState.Static))
    return scene("arrow_grazing_a_cylsphere_post", [land()], _player((60.0, 60.0, GROUND)), _steps(30), [_wall(), post],
                 others=(arrow((60.0, 60.0, GROUND), WALL),))


def spell_projectile_hits_a_player():
    """A monster 8 m ahead casts a bolt back at the player: the SpellProjectile's OnCollideObject(player) is
    ProjectileImpact (ethereal, inert, still), and it stays in the world, inactive."""
    return scene("spell_projectile_hits_a_player", [land()], _player((60.0, 60.0, GROUND)), _steps(30),
                 others=(monster((60.0, 68.0, GROUND)), spell((60.0, 68.0, GROUND), PLAYER, MONSTER, direction=-1.0)))


def arc_spell_at_a_monster():
    """The player casts an arc spell (gravity, the lateral solver) at a monster 8 m ahead."""
    return scene("arc_spell_at_a_monster", [land()], _player((60.0, 60.0, GROUND)), _steps(30),
                 others=(monster((60.0, 68.0, GROUND)), spell((60.0, 60.0, GROUND), MONSTER, PLAYER, arc=True)))


NAMED = (arrow_into_a_wall, arrow_through_an_open_door, arrow_into_a_closed_door, arrow_at_a_monster_standing_at_a_wall,
         monster_runs_into_an_arrow_at_it, arrow_grazing_a_cylsphere_post, spell_projectile_hits_a_player,
         arc_spell_at_a_monster)


def scenes() -> dict:
    return {f.__name__: f() for f in NAMED}


if __name__ == "__main__" and "--record" in sys.argv:
    from oracle.live_answers import record_outcomes

    record_outcomes(scenes(), DATA, "missile scene")
