"""Buildings: a house on terrain -- a shell with a doorway over EnvCells entered from outside -- and the strategies that draw it.

A house is a dungeon chain (strategies/dungeon.py) whose first piece, the vestibule, has a door
at its -x end to outside (a CellPortal to 0xFFFF), then a room, and sometimes stairs down to a
cellar. Its EnvCells are in the landblock it stands on (0xXXYY0100 up), which has terrain. The
shell is a building (scene `buildings`, written as the landblock's LandblockInfo BuildInfo): a
GfxObj whose physics BSP is the house's outer walls, a wall thickness `wall` outside the cells,
facing outward, the -x wall cut around the doorway, and a roof; its frame is the house's frame
(the dungeon frame: an origin in the landblock and a yaw). Its one portal leads into the vestibule
through the vestibule's door portal (OtherPortalId), with PortalSide and ExactMatch flags drawn
both ways and the stab list of every cell.

Policies (the scene's name is ``building:<policy>``):

- "in": from outside toward the door, straight, at an angle, or grazing a jamb (the mover's
  lateral offset up to the door's free half-width and past it);
- "out": from inside the vestibule out through the door;
- "wall": into the shell beside the door; "along": parallel to an outer wall, a hair from it;
- "porch": the house floor raised above the ground, its floor reaching out past the door (a lip):
  from inside out onto the porch and off its edge;
- "cellar": from the room down the stairs to the cellar;
- "hatch": the room's floor open over a cellar pit below it (a pit piece: strategies/dungeon.py),
  the mover walking from the room's near end over the hatch (drawn by the tick strategies, which
  let it fall in over ticks: strategies/ticks.py; the `buildings` kind's own draws leave it out);
- "border": the house across a cell border, a landblock border or a landblock corner (its origin
  a little inside its landblock, the rest in the neighbours), approached from the neighbour;
- "static": a static box in the doorway, half inside (placed by init_static_objs' chain, its cells
  found through the building: the parts overloads), and the mover walking in toward it;
- "placement": the mover placed (mover.placement, engine client) at a point inside the house
  under the id of the outdoor cell holding it.

Doors are barely wider than the mover (strategies/dungeon.DOOR_SLACK).
"""

from __future__ import annotations

import math

from hypothesis import strategies as st

from acconform.flags import CullMode, PhysicsState, SetPositionFlags, TransientState
from acconform.numerics import to_f32
from acconform.scene import (OUTSIDE_CELL, PORTAL_EXACT_MATCH, PORTAL_SIDE_BIT, BSPShape, Building, BuildingPortalRec,
                             ContactPlane, Frame, Landblock, Mover, Placement, PlaneRec, PolygonRec, Position, Scene,
                             StaticObject)

from . import draws as dr
from . import dungeon as dg
from . import shapes as sh
from .dungeon import Door, Piece, quad_z, rect_x, rect_y
from .terrain import BLOCK, CELL, cell_of, split_global

POLICIES = st.sampled_from(("in", "in", "in", "out", "out", "wall", "along", "porch", "cellar", "border", "border",
                            "placement", "static"))
# a static box standing in the doorway, half in, half out (its placement reaches the building's cells
# through the parts overloads): its size and how far in it stands
STATIC_SIZES = dr.f32(0.2, 1.5)
STATIC_DEPTHS = st.sampled_from((0.0, 0.0, 0.3, -0.3, 1.0))
HOME_BLOCKS = st.sampled_from(((0xA9, 0xB4), (0x12, 0x34), (0x7F, 0x80)))
GROUND_INDEX = dr.ints(0, 60)
WALLS = dr.OneOf(st.sampled_from((0.1, 0.2, 0.3, 0.05)), dr.f32(0.02, 0.6))
FLOOR_OFFSETS = st.sampled_from((0.0, 0.0, 0.0, 0.01, -0.01, 0.05, -0.05, 0.2))
PORCH_HEIGHTS = dr.OneOf(st.sampled_from((0.2, 0.3, 0.5, 1.0)), dr.f32(0.05, 2.0))
PORCH_LIPS = dr.OneOf(st.sampled_from((0.5, 1.0, 2.0)), dr.f32(0.1, 3.0))
ROOF_GAPS = st.sampled_from((0.0, 0.2, 1.0))
SHELL_SIDES = st.sampled_from((int(CullMode.Clockwise), int(CullMode.Clockwise), int(CullMode.None_)))
BLD_FLAGS = st.sampled_from((0, PORTAL_SIDE_BIT, PORTAL_EXACT_MATCH, PORTAL_EXACT_MATCH | PORTAL_SIDE_BIT))
# where a "border" house's origin sits: metres inside its landblock (or cell) past the border
BORDER_INSET = dr.OneOf(st.sampled_from((0.5, 1.0, 2.0, 3.0)), dr.f32(0.1, 6.0))
BORDERS = st.sampled_from(("cell", "landblock x", "landblock y", "corner"))
# lateral offset of the path at the door, in units of the door's free half-width (1: grazing a jamb)
LATERAL = dr.OneOf(st.sampled_from((0.0, 0.0, 0.5, -0.5, 1.0, -1.0, 0.999, -0.999, 1.2, -1.2)),
                   dr.floats(-1.5, 1.5))
HEADINGS = dr.OneOf(st.sampled_from((0.0, 0.0, 10.0, -10.0, 30.0, -45.0, 60.0)), dr.floats(-75.0, 75.0))
ALONG_GAPS = st.sampled_from((0.0, 0.001, 0.01, 0.05, -0.01, 0.2))
EDGE_SLIDE = st.sampled_from((True, True, True, False))
# a cellar hatch: the opening's length along the room past the mover's diameter (under it: the mover
# bridges it), and the cellar's depth below the floor
HATCH_SLACK = dr.OneOf(st.sampled_from((0.5, 1.0, 0.2, 0.05, -0.1)), dr.f32(0.0, 2.0))
HATCH_DEPTHS = dr.OneOf(st.sampled_from((2.0, 2.5, 3.0)), dr.f32(0.5, 4.0))
SPHERE_STEP_SITE, STEP_DOWN_SITE = dr.Site("building step-up height"), dr.Site("building step-down height")


def _rot(deg, x, y):
    a = math.radians(deg)
    return x * math.cos(a) - y * math.sin(a), x * math.sin(a) + y * math.cos(a)


def shell(d: dg.Dungeon, built: dg.Built, door: Door, wall: float, roof_gap: float, sides: int,
          bottom: float) -> BSPShape:
    """The house's outer walls in the house frame: a box `wall` outside every cell, from `bottom`
    (house-frame z) to the highest ceiling plus `roof_gap`, facing outward; the -x wall cut
    around `door` (its doorway left open), and a roof."""
    x0 = to_f32(-wall)
    x1 = to_f32(max(s + p.length for s, p in zip(d.starts, d.pieces)) + wall)
    hw = max(p.width for p in d.pieces) / 2
    y0, y1 = to_f32(-hw - wall), to_f32(hw + wall)
    top = to_f32(max(b + g.ztop for b, g in zip(d.bases, built.geometry)) + roof_gap)
    bottom = to_f32(bottom)
    polys = []
    for verts, is_door in dg._wall_with_door(lambda s0, s1, b, t, n: rect_x(x0, s0, s1, b, t, n), y0, y1, 0.0, top,
                                             door, -1.0):
        if not is_door:
            polys.append(verts)
    if bottom < 0:  # below the doorway's sill: the wall goes on down to the bottom
        polys.append(rect_x(x0, y0, y1, bottom, 0.0, -1.0))
    polys.append(rect_x(x1, y0, y1, bottom, top, 1.0))
    polys.append(rect_y(y0, x0, x1, bottom, top, -1.0))
    polys.append(rect_y(y1, x0, x1, bottom, top, 1.0))
    polys.append(quad_z(x0, x1, y0, y1, top, top, 1.0))
    recs = [PolygonRec(v, sides) for v in polys]
    root = dg.physics_bsp([(r, False) for r in recs], 3)
    return BSPShape(tuple(recs), root, sh.bounding_sphere([v for r in recs for v in r.vertices]))


def house_point(d: dg.Dungeon, x: float, y: float, z: float) -> tuple[float, float, float]:
    """A point in the house frame -> landblock coordinates (doubles)."""
    rx, ry = _rot(d.yaw, x, y)
    return (d.origin[0] + rx, d.origin[1] + ry, d.origin[2] + z)


def _landblocks(home: tuple[int, int], ground: int, neighbours: bool) -> tuple[Landblock, ...]:
    """The home landblock, and with `neighbours` the three toward -x and -y (a "border" house reaches
    back into them), all flat at height index `ground`."""
    bx, by = home
    reach = ((0, 0), (-1, 0), (0, -1), (-1, -1)) if neighbours else ((0, 0),)
    return tuple(Landblock(((bx + dx) << 24) | ((by + dy) << 16) | 0xFFFF, (ground,) * 81, (0,) * 81)
                 for dx, dy in reach)


def _outdoor_position(home, p, orientation=(1.0, 0.0, 0.0, 0.0)) -> Position:
    """A landblock point of the home block (possibly past its edges) as a Position in the block holding it."""
    bx, by, lx, ly = split_global(home[0] * BLOCK + p[0], home[1] * BLOCK + p[1])
    return Position(cell_of(bx, by, lx, ly), Frame((lx, ly, to_f32(p[2])), orientation))


def draw_building(draw, spheres, step_heights, policy: str | None = None) -> Scene:
    """A building scene for one policy (drawn, or the one given); `step_heights` as in strategies/scenes.py."""
    policy = policy or draw(POLICIES)
    home = draw(HOME_BLOCKS)
    block = (home[0] << 8) | home[1]
    ground_index = draw(GROUND_INDEX)
    ground = 2.0 * ground_index  # DEFAULT_LAND_HEIGHT_TABLE
    r = spheres[0].radius
    head = max(s.center[2] + s.radius for s in spheres)

    # the pieces: vestibule, room, and for a cellar stairs down and a room below
    door = dg._door(draw, r, head, OUTSIDE_CELL)
    inner = dg._door(draw, r, head, 1)
    vest = dg._plain(draw, "room", door, r)
    vest = Piece("room", vest.length, max(vest.width, inner.width), max(vest.height, inner.height),
                 floor_cull=vest.floor_cull, lip=to_f32(dr.take(draw, PORCH_LIPS)) if policy == "porch" else 0.0)
    room = dg._plain(draw, "room", inner, r)
    room = Piece("room", room.length, room.width, room.height, floor_cull=room.floor_cull)
    if policy == "hatch":  # the hatch from the room's middle on: the room at least twice its length
        hatch = to_f32(max(2 * r + dr.take(draw, HATCH_SLACK), 0.2))
        length = max(room.length, to_f32(2 * hatch + 0.2))
        room = Piece("pit", length, room.width, room.height, "pit", feature_at=0.0, pit_length=hatch,
                     pit_depth=to_f32(dr.take(draw, HATCH_DEPTHS)), floor_cull=room.floor_cull)
    inner = Door(min(inner.width, vest.width, room.width), min(inner.height, vest.height, room.height), 0.0, 1,
                 inner.faces_out)
    pieces, doors = [vest, room], [inner]
    if policy == "cellar" or (policy in ("in", "out") and draw(dg.QUARTERS) == 0):
        down = dg._door(draw, r, head, 2)
        down = Door(min(down.width, room.width), min(down.height, room.height), 0.0, 2, down.faces_out)
        n = draw(dg.STAIR_COUNTS)
        h = draw(st.sampled_from(sh.STEP_SIZES + (to_f32(r / 2),)))
        stairs = Piece("stairs", to_f32(n * draw(dg.STAIR_RUNS)), to_f32(down.width + 0.5), to_f32(down.height + 0.5),
                       "stairs", to_f32(-h * (n - 1)), steps=n)
        below = dg._door(draw, r, head, 3)
        below = Door(min(below.width, stairs.width), min(below.height, stairs.height), 0.0, 3, below.faces_out)
        cellar = dg._plain(draw, "room", below, r)
        pieces += [stairs, Piece("room", cellar.length, cellar.width, cellar.height, floor_cull=cellar.floor_cull)]
        doors += [down, below]
    entry = Door(min(door.width, vest.width), min(door.height, vest.height), 0.0, OUTSIDE_CELL, door.faces_out)

    wall = dr.take(draw, WALLS)
    yaw = dr.take(draw, dg.YAWS)
    lift = to_f32(dr.take(draw, PORCH_HEIGHTS)) if policy == "porch" else draw(FLOOR_OFFSETS)
    border = None
    if policy == "border":
        border = draw(BORDERS)
        inset = dr.take(draw, BORDER_INSET)
        ox = to_f32(inset) if border in ("landblock x", "corner") else to_f32(BLOCK / 2 + inset)
        oy = to_f32(inset) if border in ("landblock y", "corner") else to_f32(BLOCK / 2)
        if border == "cell":
            ox = to_f32(4 * CELL + inset)
        # a house yawed toward -x / -y reaches back over the border into the neighbour; one yawed
        # 0 / 90 has its door toward the neighbour, so the mover comes from there
        yaw = draw(st.sampled_from((0.0, 0.0, 90.0, 10.0, 180.0, 225.0, 200.0, 270.0, 135.0)))
    else:
        ox, oy = draw(dg.ORIGIN_XY), draw(dg.ORIGIN_XY)
    origin = (ox, oy, to_f32(ground + lift))
    d = dg.lay_out(block, pieces, doors, entry, (), yaw, origin)
    built = dg.build(d, "all", draw(dg.BSP_ORDERS), bsp_depth=draw(dg.BSP_DEPTHS))
    g0 = built.geometry[0]
    entry_portal = next(k for k, (which, _) in enumerate(g0.portal_doors) if which == "entry")
    # the shell: down to the ground (a porch's sill is above it), or to the cellar's floor
    bottom = min(-lift - 0.5, min(d.bases) - 0.5, -room.pit_depth - 0.5)
    shell_shape = shell(d, built, entry, wall, draw(ROOF_GAPS), draw(SHELL_SIDES), bottom)
    cells = tuple(c.id & 0xFFFF for c in built.env_cells)
    portal = BuildingPortalRec(dg.FIRST_CELL, entry_portal, draw(BLD_FLAGS), cells)
    building = Building((home[0] << 24) | (home[1] << 16) | 0xFFFF, Frame(tuple(d.origin), dg.yaw_quat(yaw)),
                        shell_shape, (portal,))

    # the mover, in the house frame: x into the house, the door at x = 0 (outer face at -wall)
    free = max((entry.width - 2 * r) / 2, 0.0)
    state = int(PhysicsState.Gravity) | (int(PhysicsState.EdgeSlide) if draw(EDGE_SLIDE) else 0)
    before = dr.take(draw, dg.BEFORE) * r
    past = dr.take(draw, dg.PAST) * r
    heading = dr.take(draw, HEADINGS)
    lateral = dr.take(draw, LATERAL) * free
    floor_z = 0.0  # house-frame z of the vestibule's floor
    out_z = to_f32(-lift)  # the ground outside, in the house frame
    start_inside = policy in ("out", "porch", "cellar", "hatch")
    if policy == "wall":
        lateral = draw(st.sampled_from((1.0, -1.0))) * to_f32(entry.width / 2 + r * draw(st.sampled_from((0.0, 0.5, 1.0, 2.0))))
    if policy == "along":
        side = draw(st.sampled_from((1.0, -1.0)))
        hw = max(p.width for p in d.pieces) / 2 + wall
        sx, sy = to_f32(-wall - r - before), side * to_f32(hw + r + draw(ALONG_GAPS))
        heading = draw(st.sampled_from((0.0, 0.0, 2.0, -2.0, 5.0)))
        sz = out_z
    elif start_inside:
        if policy == "cellar":
            i = 1
            sx = d.starts[1] + d.pieces[1].length / 2 - before - r
            sx = max(sx, d.starts[1] + r + 0.01)
            heading = draw(st.sampled_from((0.0, 0.0, 5.0, -5.0)))
            sy = draw(dg.LATERAL) * max(d.pieces[1].width / 2 - r - 0.01, 0.0)
        elif policy == "hatch":  # in the room, short of the hatch (its near edge at the room's middle)
            i = 1
            edge = d.starts[1] + room.length / 2
            sx = max(edge - before - 0.01, d.starts[1] + r + 0.01)
            heading = draw(st.sampled_from((0.0, 0.0, 5.0, -5.0, 20.0)))
            sy = draw(dg.LATERAL) * max(room.width / 2 - r - 0.01, 0.0)
        else:
            i = 0
            sx = max(min(to_f32(before + r), vest.length - r - 0.01), r + 0.01)
            heading = 180.0 + heading
            sy = max(min(lateral, vest.width / 2 - r - 0.01), -vest.width / 2 + r + 0.01)
        sz = floor_z
    else:
        rad = math.radians(heading)
        sx = -wall - r - before - 0.01
        sy = lateral - (wall + r + before) * math.tan(rad) if abs(heading) < 80 else lateral
        sz = out_z
    rad = math.radians(heading)
    if policy == "hatch":  # to the hatch's middle and on
        length = d.starts[1] + room.length / 2 + room.pit_length / 2 - sx + past
    elif policy == "cellar":
        length = sum(p.length for p in d.pieces[1:]) - (sx - d.starts[1]) + past
    elif start_inside:
        # a porch's path goes past its edge (the vestibule's floor reaching `lip` out of the door)
        length = sx + wall + r + past + (max(dr.take(draw, PORCH_LIPS), vest.lip) if policy == "porch" else 0.0)
    elif policy == "along":
        length = vest.length + room.length + 2 * wall + past
    else:
        length = (abs(sx) + past) / max(math.cos(rad), 0.2)
    ex, ey = sx + length * math.cos(rad), sy + length * math.sin(rad)
    begin = tuple(to_f32(c) for c in house_point(d, sx, sy, sz))
    end = tuple(to_f32(c) for c in house_point(d, ex, ey, sz))
    if start_inside:
        cell = dg.cell_containing(built, (begin[0], begin[1], begin[2] + r)) or d.cell_id(i)
        begin_pos = Position(cell, Frame(begin))
    else:
        begin_pos = _outdoor_position(home, begin)
    end_cell = dg.cell_containing(built, (end[0], end[1], end[2] + r))
    end_pos = Position(end_cell, Frame(end)) if end_cell else _outdoor_position(home, end)

    # grounded on the floor or the flat ground (normal +z) where it starts
    contact = ContactPlane(begin_pos.cell, PlaneRec((0.0, 0.0, 1.0), to_f32(-begin_pos.frame.origin[2])))
    steps = step_heights([lift, abs(pieces[-1].rise) if policy == "cellar" else room.pit_depth if policy == "hatch"
                          else r / 2, r / 2])
    up = dr.one_of(draw, SPHERE_STEP_SITE, *steps)
    down = dr.one_of(draw, STEP_DOWN_SITE, lambda draw: draw(sh.f32s(r, 2 * r)), *steps)
    placement = None
    mode = "server"
    if policy == "placement":
        # a point inside the vestibule, under the id of the outdoor cell holding it
        px = to_f32(draw(st.sampled_from((0.5, 0.25, 0.9))) * vest.length)
        p = tuple(to_f32(c) for c in house_point(d, px, 0.0, 0.0))
        begin_pos = _outdoor_position(home, p)
        if draw(dr.PLACEMENT_VIAS) == "enter_world":
            placement = Placement(0, draw(dr.BOOLEANS), "enter_world")
        else:
            placement = Placement(draw(st.sampled_from((0, int(SetPositionFlags.Slide)))), draw(dr.BOOLEANS))
        mode = draw(dr.ENGINE_MODES)
        contact = None
    mover = Mover(spheres=tuple(spheres), begin=begin_pos, end=end_pos, step_up_height=up, step_down_height=down,
                  state=state,
                  transient_state=(int(TransientState.Contact) | int(TransientState.OnWalkable)) if contact else 0,
                  contact_plane=contact, placement=placement)
    objects = ()
    if policy == "static":
        size = draw(STATIC_SIZES)
        at = tuple(to_f32(c) for c in house_point(d, to_f32(draw(STATIC_DEPTHS)), 0.0, 0.0))
        where = _outdoor_position(home, at, dg.yaw_quat(yaw))
        objects = (StaticObject(0x70000000, where, sh.box(size, size, size)),)
    name = f"building:{policy}" + ("" if state & int(PhysicsState.EdgeSlide) else ":no-edge-slide")
    return Scene(_landblocks(home, ground_index, border not in (None, "cell")), mover, objects, engine_mode=mode, name=name,
                 environments=(built.environment,), env_cells=built.env_cells, buildings=(building,))
