"""The named indoor scenes (issue 12's acceptance list), built with strategies/dungeon.py's pieces:
a walk through a doorway, along a corridor seam, up a ramp, up a stair, off a ledge with and
without EdgeSlide, into a wall beside a portal, through a portal into a neighbouring cell at an
angle, and into a static straddling two EnvCells. SCENES: name -> (scene, what it shows)."""

from __future__ import annotations

from acconform.flags import PhysicsState
from acconform.numerics import to_f32
from acconform.scene import SphereRec, validate_scene
from acconform.strategies import dungeon as dg
from acconform.strategies import shapes as sh

BLOCK = 0x01D9
R = 0.48
SPHERES = (SphereRec((0.0, 0.0, R), R),)
GRAVITY = int(PhysicsState.Gravity)
EDGE_SLIDE = int(PhysicsState.Gravity | PhysicsState.EdgeSlide)
ORIGIN = (96.0, 96.0, 20.0)


def _door(width=2.0, height=2.5):
    return dg.Door(to_f32(width), to_f32(height), 0.0, 1)


def _walk(built, piece, start, end, name, *, state=EDGE_SLIDE, up=0.4, down=0.4, statics=(), end_piece=None):
    d = built.dungeon
    begin = dg.dungeon_point(d, piece, *start)
    stop = dg.dungeon_point(d, piece if end_piece is None else end_piece, *end)
    return validate_scene(dg.dungeon_scene(built, SPHERES, begin, stop, d.cell_id(piece), to_f32(up), to_f32(down),
                                           state, statics=statics, name=name))


def doorway():
    """A room, then a corridor through a door only 2 cm wider than the mover: walked straight through."""
    door = _door(2 * R + 0.02)
    room = dg.Piece("room", 6.0, 4.0, 3.0)
    corridor = dg.Piece("corridor", 6.0, door.width, door.height)
    built = dg.build(dg.lay_out(BLOCK, (room, corridor), (door,), origin=ORIGIN))
    return _walk(built, 0, (1.0, 0.0, 0.0), (3.0 + 1.5, 0.0, 0.0), "indoor: through a doorway")


def corridor_seam():
    """Two rooms of one width meeting at a whole-wall portal; the mover walks along the seam."""
    door = _door(5.0, 3.0)
    a, b = dg.Piece("room", 6.0, 5.0, 3.0), dg.Piece("room", 6.0, 5.0, 3.0)
    built = dg.build(dg.lay_out(BLOCK, (a, b), (door,), origin=ORIGIN))
    return _walk(built, 0, (3.0, -2.0, 0.0), (3.0, 2.0, 0.0), "indoor: along a corridor seam")


def up_a_ramp():
    """A room, then a 20-degree ramp rising along the walk: the mover walks from the room onto it."""
    door = _door(2.0, 2.5)
    room = dg.Piece("room", 4.0, 3.0, 3.0)
    rise = to_f32(4.0 * 0.36397023)  # tan(20 degrees) over 4 m
    ramp = dg.Piece("ramp", 4.0, 3.0, 3.0, "ramp", rise)
    built = dg.build(dg.lay_out(BLOCK, (room, ramp), (door,), origin=ORIGIN))
    return _walk(built, 0, (1.0, 0.0, 0.0), (1.0, 0.0, dg.floor_at(ramp, 1.0)), "indoor: up a ramp", end_piece=1)


def up_a_stair():
    """A room, then four 0.25 m steps 0.75 m deep; step-up 0.4: the mover climbs the first steps."""
    door = _door(2.0, 2.5)
    room = dg.Piece("room", 4.0, 3.0, 3.0)
    stairs = dg.Piece("stairs", 3.0, 3.0, 3.0, "stairs", 0.75, steps=4)
    built = dg.build(dg.lay_out(BLOCK, (room, stairs), (door,), origin=ORIGIN))
    return _walk(built, 0, (1.0, 0.0, 0.0), (-0.2, 0.0, dg.floor_at(stairs, -0.2)), "indoor: up a stair", end_piece=1)


def off_a_ledge(edge_slide: bool):
    """A room whose floor drops 1.5 m (more than the step-down) at x = 0: walked off toward the drop."""
    room = dg.Piece("ledge", 6.0, 4.0, 4.0, "ledge", -1.5, feature_at=0.0)
    built = dg.build(dg.lay_out(BLOCK, (room,), (), origin=ORIGIN))
    name = "indoor: off a ledge " + ("with EdgeSlide" if edge_slide else "without EdgeSlide")
    return _walk(built, 0, (-1.0, 0.0, 0.0), (1.0, 0.0, 0.0), name, state=EDGE_SLIDE if edge_slide else GRAVITY)


def into_a_wall_beside_a_portal():
    """A room with a 1.2 m door in its +x wall; the mover walks at the wall 0.9 m beside the door."""
    door = _door(1.2, 2.5)
    room = dg.Piece("room", 6.0, 5.0, 3.0)
    corridor = dg.Piece("corridor", 4.0, door.width, door.height)
    built = dg.build(dg.lay_out(BLOCK, (room, corridor), (door,), origin=ORIGIN))
    return _walk(built, 0, (1.0, 1.5, 0.0), (4.0, 1.5, 0.0), "indoor: into a wall beside a portal")


def through_a_portal_at_an_angle():
    """Two rooms in a dungeon turned 37 degrees, the second cell's frame turned a further 90: the
    mover walks from the first through the doorway into the second."""
    door = _door(2.0, 2.5)
    a = dg.Piece("room", 5.0, 4.0, 3.0)
    b = dg.Piece("room", 5.0, 4.0, 3.0, turn=90)
    built = dg.build(dg.lay_out(BLOCK, (a, b), (door,), yaw=37.0, origin=ORIGIN))
    return _walk(built, 0, (1.0, 0.2, 0.0), (1.0, 0.2, 0.0), "indoor: through a portal at an angle", end_piece=1)


def static_straddling_two_cells():
    """A 1 m box standing across the whole-wall portal between two rooms, in the mover's way."""
    door = _door(4.0, 3.0)
    a, b = dg.Piece("room", 6.0, 4.0, 3.0), dg.Piece("room", 6.0, 4.0, 3.0)
    built = dg.build(dg.lay_out(BLOCK, (a, b), (door,), origin=ORIGIN))
    crate = dg.static_in(built, 0, 0x70000000, sh.box(1.0, 1.0, 1.0), 3.0, 0.0)
    return _walk(built, 0, (0.0, 0.0, 0.0), (5.0, 0.0, 0.0), "indoor: into a static straddling two cells",
                 statics=(crate,))


SCENES = {
    "doorway": (doorway(), "walks through a door 2 cm wider than itself into the corridor's cell"),
    "corridor-seam": (corridor_seam(), "walks along a whole-wall portal, its sphere in both cells"),
    "ramp": (up_a_ramp(), "walks from a flat floor onto a ramp and up it, in the ramp's cell"),
    "stair": (up_a_stair(), "steps up onto the stairs"),
    "ledge-edge-slide": (off_a_ledge(True), "EdgeSlide holds it on the ledge (precipice slide)"),
    "ledge-no-edge-slide": (off_a_ledge(False), "without EdgeSlide it walks off and drops"),
    "wall-beside-portal": (into_a_wall_beside_a_portal(), "stops at the wall beside the door"),
    "portal-at-an-angle": (through_a_portal_at_an_angle(), "crosses into the neighbour, whose frame is turned"),
    "static-straddling-cells": (static_straddling_two_cells(), "stops at a box registered in both cells"),
}
