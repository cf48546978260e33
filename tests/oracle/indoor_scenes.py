"""Small hand-made indoor scenes the staging and oracle tests share: a box room, two rooms joined by
a portal, a room with a static. One Environment (0x0D000001) holds three cell structures, each an
8 x 8 m room 3 m high in its own frame, floor at z = 0: a closed box (0), one whose +x wall is a
portal (1), one whose -x wall is a portal (2). The rooms stand in a landblock without terrain."""

from acconform.scene import (BSPLeaf, BSPNode, CellBSPNode, CellPortalRec, CellStructRec, ContactPlane, EnvCell,
                             Environment, Frame, Landblock, Mover, PlaneRec, PolygonRec, Position, Scene, SphereRec,
                             SphereShape, StaticObject, validate_scene)

BLOCK = 0x01D90000
ENV = 0x0D000001
HALF, HEIGHT = 4.0, 3.0
FLOOR_Z = -10.0  # the rooms' floors, in landblock coordinates
ROOM_A = (48.0, 48.0, FLOOR_Z)
ROOM_B = (56.0, 48.0, FLOOR_Z)  # east of A: A's +x wall is B's -x wall

h, t = HALF, HEIGHT
FLOOR = PolygonRec(((-h, -h, 0.0), (h, -h, 0.0), (h, h, 0.0), (-h, h, 0.0)))
EAST = PolygonRec(((h, -h, 0.0), (h, -h, t), (h, h, t), (h, h, 0.0)))      # x = +h, facing -x
WEST = PolygonRec(((-h, -h, 0.0), (-h, h, 0.0), (-h, h, t), (-h, -h, t)))  # x = -h, facing +x
NORTH = PolygonRec(((-h, h, 0.0), (h, h, 0.0), (h, h, t), (-h, h, t)))     # y = +h, facing -y
SOUTH = PolygonRec(((-h, -h, 0.0), (-h, -h, t), (h, -h, t), (h, -h, 0.0)))  # y = -h, facing +y

# the cell's inside: in front of every inward plane (a chain of front children, the last with none)
INSIDE = ((0.0, 0.0, 1.0, 0.0), (-1.0, 0.0, 0.0, h), (1.0, 0.0, 0.0, h), (0.0, -1.0, 0.0, h), (0.0, 1.0, 0.0, h),
          (0.0, 0.0, -1.0, t))
BOUND = SphereRec((0.0, 0.0, t / 2), 7.0)


def cell_bsp():
    node = None
    for x, y, z, d in reversed(INSIDE):
        node = CellBSPNode(PlaneRec((x, y, z), d), node, None)
    return node


def physics_bsp(n: int):
    """Every physics polygon in the front leaf of a root whose plane (z = -100) has everything in front."""
    return BSPNode(PlaneRec((0.0, 0.0, 1.0), 100.0), BOUND, BSPLeaf(tuple(range(n)), False, BOUND),
                   BSPLeaf((), False, BOUND))


def structure(portal_wall=None):
    walls = [w for w in (EAST, WEST, NORTH, SOUTH) if w is not portal_wall]
    physics = (FLOOR, *walls)
    polygons = (portal_wall,) if portal_wall is not None else ()
    return CellStructRec(polygons, (0,) if polygons else (), physics, physics_bsp(len(physics)), cell_bsp())


ENVIRONMENT = Environment(ENV, (structure(), structure(EAST), structure(WEST)))
DUNGEON = Landblock(BLOCK | 0xFFFF, has_terrain=False)


def mover(begin, end, cell_begin, cell_end, ground_z=FLOOR_Z):
    return Mover(spheres=(SphereRec((0.0, 0.0, 0.48), 0.48),), begin=Position(cell_begin, Frame(begin)),
                 end=Position(cell_end, Frame(end)), step_up_height=0.4, step_down_height=0.4,
                 contact_plane=ContactPlane(cell_begin, PlaneRec((0.0, 0.0, 1.0), -ground_z)))


def box_room(end=(49.0, 48.0, FLOOR_Z), name="box room: one step"):
    cell = EnvCell(BLOCK | 0x0100, Frame(ROOM_A), ENV, 0)
    m = mover((47.0, 48.0, FLOOR_Z), end, cell.id, cell.id)
    return validate_scene(Scene((DUNGEON,), m, environments=(ENVIRONMENT,), env_cells=(cell,), name=name))


def two_rooms(end=(55.0, 48.0, FLOOR_Z), name="two rooms: through the portal"):
    a = EnvCell(BLOCK | 0x0100, Frame(ROOM_A), ENV, 1, (CellPortalRec(0, 0x0101, 0),), (0x0101,))
    b = EnvCell(BLOCK | 0x0101, Frame(ROOM_B), ENV, 2, (CellPortalRec(0, 0x0100, 0),), (0x0100,))
    m = mover((50.0, 48.0, FLOOR_Z), end, a.id, a.id)
    return validate_scene(Scene((DUNGEON,), m, environments=(ENVIRONMENT,), env_cells=(a, b), name=name))


def room_with_static(name="box room: walk into a boulder"):
    cell = EnvCell(BLOCK | 0x0100, Frame(ROOM_A), ENV, 0)
    boulder = StaticObject(0x70000001, Position(cell.id, Frame((50.0, 48.0, FLOOR_Z + 0.5))),
                           SphereShape(SphereRec((0.0, 0.0, 0.0), 0.5)))
    m = mover((47.0, 48.0, FLOOR_Z), (51.0, 48.0, FLOOR_Z), cell.id, cell.id)
    return validate_scene(Scene((DUNGEON,), m, (boulder,), environments=(ENVIRONMENT,), env_cells=(cell,), name=name))


SCENES = {
    "box room: one step": box_room(),
    "box room: into the east wall": box_room((53.0, 48.0, FLOOR_Z), "box room: into the east wall"),
    "two rooms: through the portal": two_rooms(),
    "two rooms: stop in the doorway": two_rooms((52.0, 48.0, FLOOR_Z), "two rooms: stop in the doorway"),
    "box room: walk into a boulder": room_with_static(),
}
