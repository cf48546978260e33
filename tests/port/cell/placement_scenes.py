"""Named placement scenes: the mover placed by ACE's PhysicsObj.SetPosition (a scene's mover.placement)
in indoor_rooms' two rooms and on the flat landblock around them, then walked as the base scene walks.

Room A is cell 0x0100 (x 55..65, floor z 20, a back wall at x = 55), room B 0x0101 east of it
(x 65..75); the landblock's terrain is flat at z 0. Each scene names what it shows; the ACE answers
(both runtimes) are in data/ace_placement_outcomes.json, recorded by test_placement_scenes.py --record.
"""

from __future__ import annotations

from dataclasses import replace

from acconform.flags import PhysicsState, SetPositionFlags
from acconform.numerics import to_f32
from acconform.scene import EnvCell, Frame, Placement, Position, SphereRec, StaticObject, validate_scene

from indoor_rooms import ENV_ID, LB, SCENES as ROOM_SCENES, portal, room, two_rooms
from object_scenes import box


def cells_with_outside_room():
    """Room A SeenOutside, its east portal to 0xFFFF (the outside); room B as before."""
    return (room(0x0100, 60.0, portals=(portal(0, 0xFFFF),), seen_outside=True), two_rooms()[1][1])

A, B = LB | 0x0100, LB | 0x0101
SLIDE = int(SetPositionFlags.Slide)
# a box static in room A: faces at x 63.5 .. 65.5, y 59 .. 61, z 20 .. 22
BOULDER = StaticObject(0x70000000, Position(A, Frame((64.5, 60.0, 20.0))), box(2.0, 2.0, 2.0))
# a slab 12 x 12 x 2 m over room A and beyond: no free spot within the spiral search's 4 m
SLAB = StaticObject(0x70000000, Position(A, Frame((62.0, 60.0, 20.0))), box(12.0, 12.0, 2.0))


def turned_room():
    """Room A alone, turned 180 degrees about z: its back wall at x = 65 faces -x."""
    return (EnvCell(LB | 0x0100, Frame((60.0, 60.0, 20.0), (0.0, 0.0, 0.0, 1.0)), ENV_ID, 0, (), (), False),)


def placed(begin_cell: int, origin, flags: int = 0, get_cell: bool = False, objects=(), base: str = "across-portal",
           state: int | None = None, cells=None, radius: float | None = None):
    """The base room scene with its mover placed at (begin_cell, origin) first, in client mode
    (its one sphere `radius` big, when given)."""
    scene = ROOM_SCENES[base][0]
    mover = replace(scene.mover, begin=Position(begin_cell, Frame(tuple(to_f32(c) for c in origin))),
                    placement=Placement(flags, get_cell))
    if state is not None:
        mover = replace(mover, state=state)
    if radius is not None:
        mover = replace(mover, spheres=(SphereRec((0.0, 0.0, to_f32(radius)), to_f32(radius)),))
    return validate_scene(replace(scene, mover=mover, engine_mode="client", objects=tuple(objects) or scene.objects,
                                  env_cells=cells if cells is not None else scene.env_cells))


def _named() -> dict:
    reporting = int(PhysicsState.EdgeSlide | PhysicsState.Gravity | PhysicsState.ReportCollisions)
    return {
        "indoor-neighbour-child": (placed(A, (66.0, 60.0, 20.0)),
                                   "cell id A, point in B: find_visible_child_cell finds B among A's visible cells"),
        "indoor-in-place": (placed(A, (63.0, 60.0, 20.0)), "cell id A, point in A: placed where it is"),
        "seen-outside-fall-out": (placed(A, (40.0, 60.0, 0.0), cells=cells_with_outside_room()),
                                  "a SeenOutside cell's id, the point in no cell: adjust_to_outside, placed on terrain"),
        "no-cell": (placed(A, (63.0, 90.0, 20.0)),
                    "cell id A (not SeenOutside), the point in no cell: AdjustPosition finds none, no transition"),
        "outdoor-wrong-cell-id": (placed(LB | 0x0001, (30.0, 30.0, 0.0)),
                                  "land cell 1's id, the point in cell 0x0A: AdjustToOutside fixes the id"),
        "id-out-of-range": (placed(LB | 0x0050, (30.0, 30.0, 0.0)),
                            "cell id 0x0050: outside AdjustPosition's ranges, no cell, the position stored"),
        "wall-push-small": (placed(A, (55.45, 60.0, 20.0)),
                            "overlapping the back wall by 0.03: pushed +x less than 0.05, kept"),
        "wall-push-large": (placed(A, (55.2, 60.0, 20.0)),
                            "overlapping the back wall by 0.28 without Slide: pushed +x too far, NoValidPosition"),
        "wall-push-large-slide": (placed(A, (55.2, 60.0, 20.0), SLIDE),
                                  "the same with Slide: kept where FindValidPosition pushed it"),
        "wall-push-negative": (placed(A, (64.8, 60.0, 20.0), cells=turned_room()),
                               "overlapping a wall facing -x by 0.28 without Slide: pushed -x, kept (no Math.Abs)"),
        "box-overlap": (placed(A, (63.3, 60.0, 20.0), objects=(BOULDER,)),
                        "overlapping a box's -x face without Slide: a static's BSP does not push a placement out"),
        "inside-box": (placed(A, (64.5, 60.0, 21.0), objects=(BOULDER,)),
                       "inside a box without Slide: blocked, no sliding"),
        "inside-box-reporting": (placed(A, (64.5, 60.0, 21.0), objects=(BOULDER,), state=reporting),
                                 "inside a box, ReportCollisions: handle_all_collisions reports it, Collided"),
        "inside-box-slide": (placed(A, (64.5, 60.0, 21.0), SLIDE, objects=(BOULDER,)),
                             "inside a box with Slide: the spiral search finds a free spot"),
        "inside-slab-slide": (placed(A, (62.0, 60.0, 20.5), SLIDE, objects=(SLAB,)),
                              "inside a 12 m slab with Slide: the spiral search finds no free spot within 4 m"),
        "lifted-out-of-the-cell": (placed(A, (60.0, 60.0, 18.5), radius=4.5),
                                   "a 4.5 m sphere sunk 1.5 m into the floor: placement_insert lifts its centre above "
                                   "the 4 m ceiling, into no cell; the initial placement fails"),
        "get-cell-indoor": (placed(A, (66.0, 60.0, 20.0), get_cell=True),
                            "Position.GetCell first: AdjustCell (LandblockInfo) finds B for the point"),
        "get-cell-outdoor": (placed(LB | 0x0001, (30.0, 30.0, 0.0), get_cell=True),
                             "Position.GetCell first: GetOutdoorCell gives the point's land cell"),
        "get-cell-indoor-no-cell": (placed(A, (63.0, 90.0, 20.0), get_cell=True),
                                    "GetIndoorCell finds no cell for the point: the id kept, then no cell"),
        "dont-create-cells-teleport": (placed(A, (66.0, 60.0, 20.0), int(SetPositionFlags.Teleport
                                                                         | SetPositionFlags.DontCreateCells)),
                                       "Teleport | DontCreateCells (AdjustPosition ignores the latter)"),
    }


SCENES = _named()
