"""Small indoor worlds for the cell tests: rooms as scene records, and the run's LScape and DATs over
them (acconform/dat.py's records, read by port/dat/), as a run builds them.

Rooms are boxes in their own frame: x and y in [-5, 5], floor z = 0, ceiling z = 4. The cell
BSP is a chain of front nodes on the six inward planes; the physics BSP holds the floor (and,
in a "closed" room, the wall at x = -5). Portal polygon 0 is the wall x = +5 (toward +x),
portal polygon 1 the wall x = -5.
"""

from __future__ import annotations

from acconform.flags import CullMode
from acconform.numerics import to_f32
from acconform.scene import (BSPLeaf, BSPNode, CellBSPNode, CellPortalRec, CellStructRec, ContactPlane,
                             Environment, EnvCell, Frame, Landblock, Mover, PlaneRec, PolygonRec, Position, Scene,
                             SphereRec)
from acconform.port.land.lscape import LScape
from acconform.port import run

LB = 0xA9B40000
ENV_ID = 0x0D000001
HALF = 5.0
HEIGHT = 4.0
ROOM_Z = 20.0  # room floors sit at this z in the landblock (the terrain below is at 0)

def tag(name: str) -> bytes:
    """A node tag as the DAT holds it: ReadNode reverses the four ASCII bytes it reads."""
    return name[::-1].encode("ascii")


# ---------------------------------------------------------------- rooms


def _plane(n, d) -> PlaneRec:
    return PlaneRec(tuple(to_f32(x) for x in n), to_f32(d))


def _quad(*v) -> PolygonRec:
    return PolygonRec(tuple(tuple(to_f32(c) for c in p) for p in v), int(CullMode.None_))


def room_cell_bsp(floor: float = 0.0) -> CellBSPNode:
    """The inward planes, innermost last: x >= -5, x <= 5, y >= -5, y <= 5, z >= floor, z <= 4."""
    planes = [((1, 0, 0), HALF), ((-1, 0, 0), HALF), ((0, 1, 0), HALF), ((0, -1, 0), HALF),
              ((0, 0, 1), -floor), ((0, 0, -1), HEIGHT)]
    node = None
    for n, d in reversed(planes):
        node = CellBSPNode(_plane(n, d), node, None)
    return node


def room_struct(floor: float = 0.0, back_wall: bool = False, rise: float = 0.0) -> CellStructRec:
    """`rise`: the floor climbs that much from x = -5 to x = +5 (a ramp)."""
    h, z = HALF, floor
    portal_east = _quad((h, -h, 0.0), (h, h, 0.0), (h, h, HEIGHT), (h, -h, HEIGHT))
    portal_west = _quad((-h, h, 0.0), (-h, -h, 0.0), (-h, -h, HEIGHT), (-h, h, HEIGHT))
    floor_poly = _quad((-h, -h, z), (h, -h, z + rise), (h, h, z + rise), (-h, h, z))  # CCW from above: normal up
    physics = [floor_poly]
    if back_wall:
        physics.append(_quad((-h, -h, z), (-h, h, z), (-h, h, HEIGHT), (-h, -h, HEIGHT)))  # normal +x
    sphere = SphereRec((0.0, 0.0, to_f32(HEIGHT / 2)), to_f32(10.0))
    root = BSPNode(_plane((0, 0, -1), 50.0), sphere, BSPLeaf(tuple(range(len(physics))), False, sphere),
                   BSPLeaf((), False, sphere))
    return CellStructRec((portal_east, portal_west), (0, 1), tuple(physics), root, room_cell_bsp(floor))


def room(low: int, x: float, y: float = 60.0, z: float = ROOM_Z, struct_index: int = 0, portals=(), visible=(),
         seen_outside=False) -> EnvCell:
    return EnvCell(LB | low, Frame((to_f32(x), to_f32(y), to_f32(z))), ENV_ID, struct_index, tuple(portals),
                   tuple(visible), seen_outside)


def portal(polygon: int, other: int, flags: int = 0) -> CellPortalRec:
    return CellPortalRec(polygon, other, 0, flags)


def two_rooms(struct_b: CellStructRec | None = None, z_b: float = ROOM_Z) -> tuple[Environment, tuple[EnvCell, ...]]:
    """Room A (0x0100, x = 60) with a back wall; room B (0x0101, x = 70) east of it, joined by
    A's east wall and B's west wall."""
    env = Environment(ENV_ID, (room_struct(back_wall=True), struct_b or room_struct()))
    a = room(0x0100, 60.0, portals=(portal(0, 0x0101),), visible=(0x0101,))
    b = room(0x0101, 70.0, z=z_b, struct_index=1, portals=(portal(1, 0x0100),), visible=(0x0100,))
    return env, (a, b)


ONE_SPHERE = (SphereRec((0.0, 0.0, 0.48), 0.48),)


def indoor_scene(env: Environment, cells, start, end, *, state: int, transient: int, begin_cell: int,
                 end_cell: int, step_down: float = 0.4, floor_z: float = ROOM_Z, objects=()) -> Scene:
    start = tuple(to_f32(c) for c in start)
    end = tuple(to_f32(c) for c in end)
    cp = ContactPlane(begin_cell, PlaneRec((0.0, 0.0, 1.0), to_f32(-floor_z)))
    mover = Mover(ONE_SPHERE, Position(begin_cell, Frame(start)), Position(end_cell, Frame(end)), to_f32(0.4),
                  to_f32(step_down), state=state, transient_state=transient, contact_plane=cp)
    return Scene((Landblock(LB | 0xFFFF, (0,) * 81, (0,) * 81),), mover, tuple(objects), environments=(env,),
                 env_cells=tuple(cells))


def world(scene: Scene, mode):
    """The run's LScape with its portal and cell DATs (acconform/dat.py's records), as port/run.py
    builds a run's world; returns (lscape, portal_dat)."""
    portal_dat, _dids = run.portal_dat_for(scene, mode)
    lscape = LScape(scene, mode)
    lscape.portal_dat = portal_dat
    lscape.cell_dat = run.cell_dat_for(scene, mode)
    return lscape, portal_dat


# ---------------------------------------------------------------- named scenes (ACE's answers in data/)


def _named() -> dict[str, tuple[Scene, str]]:
    from acconform.flags import PhysicsState, TransientState
    from acconform.scene import CylSphereShape, SphereShape, StaticObject, validate_scene
    from object_scenes import box

    walk_state = int(PhysicsState.EdgeSlide | PhysicsState.Gravity)
    no_edge_slide = int(PhysicsState.Gravity)
    grounded = int(TransientState.Contact | TransientState.OnWalkable)
    a_id = LB | 0x0100

    def scene(env, cells, start, end, state=walk_state, objects=()):
        return validate_scene(indoor_scene(env, cells, start, end, state=state, transient=grounded, begin_cell=a_id,
                                           end_cell=a_id, objects=objects))

    env, cells = two_rooms()
    low_env, low_cells = two_rooms(z_b=19.8)
    step_env, step_cells = two_rooms(z_b=20.3)
    ramp_env, ramp_cells = two_rooms(struct_b=room_struct(rise=2.0))
    cliff_env, cliff_cells = two_rooms(z_b=17.0)
    outside = (room(0x0100, 60.0, portals=(portal(0, 0xFFFF),), seen_outside=True), cells[1])
    unloaded = (room(0x0100, 60.0, portals=(portal(0, 0x0105),)), cells[1])
    boulder = StaticObject(0x70000000, Position(a_id, Frame((64.5, 60.0, 20.0))), box(2.0, 2.0, 2.0))
    pillar = StaticObject(0x70000001, Position(a_id, Frame((64.8, 60.0, 20.0))),
                          CylSphereShape((0.0, 0.0, 0.0), to_f32(0.5), to_f32(2.0)))
    ball = StaticObject(0x70000002, Position(a_id, Frame((62.0, 60.2, 20.5))), SphereShape(SphereRec((0.0, 0.0, 0.0), 0.5)))
    return {
        "across-portal": (scene(env, cells, (63, 60, 20), (67, 60, 20)), "walk from room A through its east portal into B"),
        "portal-diagonal": (scene(env, cells, (63, 58, 20), (67.5, 61.3, 20)), "cross the portal at an angle"),
        "back-wall": (scene(env, cells, (57, 60, 20), (53, 60, 20)), "walk into room A's back wall (physics BSP)"),
        "small-ledge": (scene(low_env, low_cells, (63, 60, 20), (67, 60, 20)), "step down 0.2 m onto B's floor"),
        "tall-ledge-edge-slide": (scene(cliff_env, cliff_cells, (63, 60, 20), (67, 60, 20)),
                                  "a 3 m drop with EdgeSlide: precipice slide off A's floor"),
        "tall-ledge-no-edge-slide": (scene(cliff_env, cliff_cells, (63, 60, 20), (67, 60, 20), state=no_edge_slide),
                                     "a 3 m drop without EdgeSlide: walk off and lose contact"),
        "tall-ledge-angle": (scene(cliff_env, cliff_cells, (63, 58, 20), (67, 62, 20)), "the drop at an angle, with EdgeSlide"),
        "outside-portal": (scene(env, outside, (63, 60, 20), (66, 60, 20)), "out through a portal to 0xFFFF onto terrain cells"),
        "unloaded-neighbour": (scene(env, unloaded, (63, 60, 20), (66, 60, 20)),
                               "toward a portal whose cell is not visible: its short id, no cell"),
        "static-straddling": (scene(env, cells, (61, 60, 20), (66, 60, 20), objects=(boulder,)),
                              "a static in A straddling the portal, registered in A and B; walk into it"),
        "step-up": (scene(step_env, step_cells, (63, 60, 20), (67, 60, 20.3)), "step up 0.3 m onto B's floor"),
        "ramp-up": (scene(ramp_env, ramp_cells, (63, 60, 20), (68, 60, 21)), "walk from A onto a ramp rising 2 m in B"),
        "cylsphere-and-sphere-statics": (scene(env, cells, (61, 60, 20), (67, 60, 20), objects=(pillar, ball)),
                                         "a cylsphere static on the portal (find_cell_list's indoor branch places it) "
                                         "and a sphere static in A; walk past them"),
    }


SCENES = _named()
