"""Door tick scenes (issue 41; campaign kind ``doors``, the ticks policy ``door``): a door on the mover's
path that opens or closes at a drawn tick (the tick input ``door``: ACE's server Door.Open /
FinalizeClose physics, scene/7).

    draw_door_ticks(draw, base, clock)     a tick scene: `base`'s path walked through a door

The site is any outdoor path of the obstacles or terrain kinds (strategies/scenes.py): a door, a BSP
slab 0.1-0.3 m thick, 1-3 m wide and 3 m tall, stands across the path at a drawn fraction of it
(0: the mover starts inside it), its thin axis along the path. It starts open (ethereal) and closes,
or starts closed and opens; at a drawn tick, at the tick the mover's centre reaches the door's plane
(the mover inside it: a close that ethereal_check_for_collisions holds) or one tick either side.
A held close is followed, half the time, by a second close later (the server's one-second poll). The
door's State has no Static flag (an ACE door is a WorldObject), one time in eight it has (a Static
object stops a mover whether ethereal or not). The mover enters the world (enter_world) so it is in
its cell's object list, where a closing door looks, from the first tick; it walks by a velocity held
every tick (forward, or back once past the door), and an opening door clears its Sliding state half
the time (the sliding normal a closed door left holds the mover at its face).
"""

from __future__ import annotations

import math
from dataclasses import replace

from hypothesis import strategies as st

from acconform.flags import PhysicsState, TransientState
from acconform.numerics import to_f32
from acconform.scene import DoorInput, Frame, Placement, Position, StaticObject
from acconform.strategies.shapes import box

from . import draws as dr
from .terrain import split_global

DOOR_ID = 0x7D000001
DOOR_HEIGHT = 3.0
DOOR_WIDTHS = dr.OneOf(st.sampled_from((2.0, 1.2, 3.0)), dr.f32(1.0, 3.0))
DOOR_THICKNESS = dr.OneOf(st.sampled_from((0.2, 0.1, 0.3)), dr.f32(0.05, 0.4))
DOOR_AT = dr.OneOf(st.sampled_from((0.5, 0.0, 0.3)), dr.f32(0.0, 1.0))  # the fraction of the path
DOOR_WAYS = st.sampled_from(("closes", "closes", "opens"))
DOOR_WHEN = st.sampled_from(("inside", "inside", "before", "after", "drawn"))
STATIC_DOOR = st.sampled_from((False, False, False, False, False, False, False, True))
DOOR_SPEEDS = dr.OneOf(st.sampled_from((3.0, 1.0, 4.0, 2.5)), dr.f32(0.5, 6.0))
DOOR_TICKS = dr.OneOf(dr.ints(20, 40), dr.ints(40, 90))
WALKING = int(TransientState.Contact | TransientState.OnWalkable | TransientState.Active)


def _door(scene, g, ux: float, uy: float, width: float, thickness: float, state: int) -> StaticObject | None:
    bx, by, lx, ly = split_global(g[0], g[1])
    block = (bx << 8 | by) << 16
    if not any(lb.id == block | 0xFFFF for lb in scene.landblocks):
        return None
    from .terrain import cell_of

    theta = math.atan2(-ux, uy)  # the slab's y axis (its thickness) along the path
    q = (to_f32(math.cos(theta / 2)), 0.0, 0.0, to_f32(math.sin(theta / 2)))
    pos = Position(cell_of(bx, by, lx, ly), Frame((lx, ly, to_f32(g[2])), q))
    return StaticObject(DOOR_ID, pos, box(width, thickness, DOOR_HEIGHT), state)


def draw_door_ticks(draw, base, clock):
    """`clock(draw, n)`: strategies.ticks._clock (start, dts, label)."""
    from .ticks import _global, _tick_scene, _unit, _vec

    g0, g1 = _global(base, base.mover.begin), _global(base, base.mover.end)
    ux, uy = _unit(g1[0] - g0[0], g1[1] - g0[1])
    at = float(dr.take(draw, DOOR_AT))
    length = math.hypot(g1[0] - g0[0], g1[1] - g0[1])
    gd = (g0[0] + ux * length * at, g0[1] + uy * length * at, g0[2])
    way = draw(DOOR_WAYS)
    state = int(PhysicsState.HasPhysicsBSP) | (int(PhysicsState.Static) if draw(STATIC_DOOR) else 0)
    if way == "closes":
        state |= int(PhysicsState.Ethereal)
    door = _door(base, gd, ux, uy, float(dr.take(draw, DOOR_WIDTHS)), float(dr.take(draw, DOOR_THICKNESS)), state)
    n = dr.take(draw, DOOR_TICKS)
    start, dts, label = clock(draw, n)
    speed = float(dr.take(draw, DOOR_SPEEDS))
    v = _vec(ux * speed, uy * speed, 0.0)
    inputs = [{"velocity": v} for _ in range(n)]
    # the tick the mover's centre reaches the door's plane at this speed
    reach, t = n - 1, 0.0
    for k, dt in enumerate(dts):
        if t * speed >= length * at:
            reach = k
            break
        t += dt
    when = draw(DOOR_WHEN)
    k = {"inside": reach, "before": reach - 1, "after": reach + 1}.get(when)
    if k is None:
        k = draw(st.integers(0, n - 1))
    k = min(max(k, 0), n - 1)
    name = f"ticks:door:{way}:{when}:{base.name}:{label}"
    if door is None:  # the door's point lies outside the scene's landblocks: a plain walk
        return _tick_scene(base, start, dts, inputs, "update_object", None, name + ":no-door")
    inputs[k]["door"] = DoorInput(DOOR_ID, way == "opens")
    if way == "opens" and draw(st.booleans()):
        inputs[k]["transient_state"] = WALKING
    if way == "closes" and k + 1 < n and draw(st.booleans()):
        k2 = draw(st.integers(k + 1, n - 1))
        inputs[k2]["door"] = DoorInput(DOOR_ID, False)
        if draw(st.booleans()):  # back the way it came from the second close on
            for i in range(k2, n):
                inputs[i]["velocity"] = _vec(-ux * speed, -uy * speed, 0.0)
    scene = base.replace(objects=tuple(o for o in base.objects if o.id != DOOR_ID) + (door,))
    scene = _tick_scene(scene, start, dts, inputs, "update_object", None, name)
    return scene.replace(mover=replace(scene.mover, placement=Placement(via="enter_world")))
