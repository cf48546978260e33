"""Doors (issue 41): a static that opens or closes at a tick, as ACE's server Door does it (the tick
input ``door``: Door.Open's and Door.FinalizeClose's physics, scene/7, feature doors). Each scene is
the hand-written player (sphere r 0.48) on flat land at z = 20 and a door: a BSP slab 2 m wide
(x), 0.2 m thick (y) and 3 m tall standing across the player's way at y = 62, pushed along +y by a
velocity held every tick.

tests/oracle/test_doors.py asks live ACE (mono and .NET 10) for each and compares the port's answer
bit for bit.
"""

from __future__ import annotations

import sys
from pathlib import Path

from acconform.flags import PhysicsState
from dataclasses import replace

from acconform.scene import DoorInput, Frame, Placement, Position, StaticObject, TickStep
from acconform.strategies.shapes import box

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from oracle.named_scenes import GROUND, WALKING, cell_at, land, mover, scene  # noqa: E402

DOOR = 0x70000001
DOOR_Y = 62.0
DT = 1 / 30
# an ACE door is a WorldObject, not a DAT static: its State has no Static flag (FindObjCollisions_Inner stops a
# mover at a Static object whether it is ethereal or not), so the door here is a BSP object without Static
CLOSED = int(PhysicsState.HasPhysicsBSP)
OPEN = int(CLOSED | PhysicsState.Ethereal)


def door(state: int) -> StaticObject:
    return StaticObject(DOOR, Position(cell_at(60.0, DOOR_Y), Frame((60.0, DOOR_Y, GROUND))), box(2.0, 0.2, 3.0), state)


def _push(vy: float, **kw) -> TickStep:
    return TickStep(DT, velocity=(0.0, vy, 0.0), **kw)


def _scene(name: str, y: float, steps, state: int):
    """The player enters the world (enter_world, as a server's Player does) before the ticks: it is in its
    cell's object list from the start, where a closing door's ethereal_check_for_collisions looks."""
    m = replace(mover((60.0, y, GROUND)), placement=Placement(via="enter_world"))
    return scene(name, [land()], m, tuple(steps), [door(state)])


def door_closes_on_a_player_in_the_doorway():
    """The player stands in the open doorway; the door closes on it (FinalizeClose: ethereal_check_for_collisions
    finds it, the door is held open, Ethereal again), the player walks on through and out, the door closes
    again (a second's poll: nothing in it now) and the player, pushed back, meets the closed door."""
    steps = ([TickStep(DT)] * 3 + [TickStep(DT, door=DoorInput(DOOR, False))] + [_push(3.0)] * 20
             + [TickStep(DT, door=DoorInput(DOOR, False))] + [_push(-3.0)] * 30)
    return _scene("door_closes_on_a_player_in_the_doorway", DOOR_Y, steps, OPEN)


def door_closes_behind_a_player():
    """The player walks through the open (ethereal) door; it closes behind it (nothing in it: Ethereal cleared),
    and the player, turned back, walks into the closed door and stops at it."""
    steps = [_push(3.0)] * 45 + [TickStep(DT, door=DoorInput(DOOR, False))] + [_push(-3.0)] * 40
    return _scene("door_closes_behind_a_player", 59.0, steps, OPEN)


def closed_door_opens_before_a_player():
    """The player walks into the closed door and presses against it; the door opens (Ethereal set) and the
    player walks on through."""
    steps = [_push(3.0)] * 40 + [_push(3.0, door=DoorInput(DOOR, True))] + [_push(3.0)] * 30
    return _scene("closed_door_opens_before_a_player", 59.0, steps, CLOSED)


def closed_door_opens_and_the_player_walks_through():
    """As closed_door_opens_before_a_player, but the opening tick also sets the player's TransientState to
    Contact|OnWalkable|Active: the Sliding flag and sliding normal the closed door left (which hold the
    player at the open door's face in the scene before) cleared, the player walks on through the open door."""
    steps = ([_push(3.0)] * 40 + [_push(3.0, door=DoorInput(DOOR, True), transient_state=WALKING)]
             + [_push(3.0)] * 30)
    return _scene("closed_door_opens_and_the_player_walks_through", 59.0, steps, CLOSED)


def door_closes_on_a_player_touching_it():
    """The player pressed against the open door's face (the door's slab is ethereal, the player walks into it
    and stops inside); a close while the player overlaps the slab by the push is held; then the player backs off
    and the next close shuts it."""
    steps = ([_push(3.0)] * 30 + [_push(3.0, door=DoorInput(DOOR, False))] + [_push(-3.0)] * 15
             + [TickStep(DT, door=DoorInput(DOOR, False))] + [_push(3.0)] * 30)
    return _scene("door_closes_on_a_player_touching_it", 60.0, steps, OPEN)


NAMED = (door_closes_on_a_player_in_the_doorway, door_closes_behind_a_player, closed_door_opens_before_a_player,
         closed_door_opens_and_the_player_walks_through, door_closes_on_a_player_touching_it)


def scenes() -> dict:
    return {f.__name__: f() for f in NAMED}
