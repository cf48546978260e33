"""Small indoor worlds for the cell tests: DatLoader bytes for EnvCells and Environments (a test-side
byte builder in ACE.DatLoader's layout: FileTypes/EnvCell.cs, FileTypes/Environment.cs,
Entity/CellStruct.cs, Entity/CellPortal.cs, Entity/Stab.cs, Entity/BSPNode.cs with BSPType.Cell), and
the run's LScape and DATs over them, as a run builds them.

Rooms are boxes in their own frame: x and y in [-5, 5], floor z = 0, ceiling z = 4. The cell
BSP is a chain of front nodes on the six inward planes; the physics BSP holds the floor (and,
in a "closed" room, the wall at x = -5). Portal polygon 0 is the wall x = +5 (toward +x),
portal polygon 1 the wall x = -5.
"""

from __future__ import annotations

import struct

from acconform import dat
from acconform.flags import CullMode
from acconform.numerics import to_f32
from acconform.scene import (BSPLeaf, BSPNode, CellBSPLeaf, CellBSPNode, CellPortalRec, CellStructRec, ContactPlane,
                             Environment, EnvCell, Frame, Landblock, Mover, PlaneRec, PolygonRec, Position, Scene,
                             SphereRec)
from acconform.port.dat.portal_dat import PortalDat
from acconform.port.land.lscape import LScape
from acconform.port import run

LB = 0xA9B40000
ENV_ID = 0x0D000001
HALF = 5.0
HEIGHT = 4.0
ROOM_Z = 20.0  # room floors sit at this z in the landblock (the terrain below is at 0)

_u16, _u32, _i32 = struct.Struct("<H"), struct.Struct("<I"), struct.Struct("<i")
_4f = struct.Struct("<4f")


def tag(name: str) -> bytes:
    """A node tag as the DAT holds it: ReadNode reverses the four ASCII bytes it reads."""
    return name[::-1].encode("ascii")


def cell_bsp(node, out: list, leaves: list) -> None:
    """A cell BSP in DatLoader's BSPType.Cell layout: a node is its tag (which children follow),
    its plane and its children; a leaf its tag and LeafIndex."""
    if isinstance(node, CellBSPLeaf):
        out.append(tag("LEAF") + _i32.pack(len(leaves)))
        leaves.append(node)
        return
    name = {(True, True): "BPIN", (True, False): "BPIn", (False, True): "BpIN", (False, False): "BpIn"}[
        (node.front is not None, node.back is not None)]
    out.append(tag(name) + _4f.pack(*node.plane.normal, node.plane.d))
    if node.front is not None:
        cell_bsp(node.front, out, leaves)
    if node.back is not None:
        cell_bsp(node.back, out, leaves)


def _align(out: list) -> None:
    n = sum(len(b) for b in out) % 4
    if n:
        out.append(b"\0" * (4 - n))


def cell_struct_bytes(c: CellStructRec, base: int) -> bytes:
    """DatLoader CellStruct; `base` is the stream position it starts at (AlignBoundary counts from the record's start)."""
    index: dict[tuple, int] = {}
    vertices = []

    def ids(poly):
        out = []
        for v in poly.vertices:
            if v not in index:
                index[v] = len(vertices)
                vertices.append(v)
            out.append(index[v])
        return out

    poly_ids = [ids(p) for p in c.polygons]
    phys_ids = [ids(p) for p in c.physics_polygons]
    out = [b"\0" * base, _u32.pack(len(c.polygons)), _u32.pack(len(c.physics_polygons)), _u32.pack(len(c.portals)),
           dat.vertex_array(vertices)]
    for k, (p, i) in enumerate(zip(c.polygons, poly_ids)):
        out.append(_u16.pack(k) + dat.polygon(p, i))
    for portal in c.portals:
        out.append(_u16.pack(portal))
    _align(out)
    cell_bsp(c.cell_bsp, out, [])
    for k, (p, i) in enumerate(zip(c.physics_polygons, phys_ids)):
        out.append(_u16.pack(k) + dat.polygon(p, i))
    dat.bsp_node(c.physics_bsp, out, [])
    out.append(_u32.pack(0))  # no drawing BSP
    _align(out)
    return b"".join(out)[base:]


def environment_bytes(e: Environment) -> bytes:
    out = _u32.pack(e.id) + _u32.pack(len(e.cell_structs))
    for k, c in enumerate(e.cell_structs):
        out += _u32.pack(k)
        out += cell_struct_bytes(c, len(out))
    return out


def env_cell_bytes(c: EnvCell, stabs=(), flags_extra: int = 0) -> bytes:
    """DatLoader EnvCell; `stabs` are (did, ((x, y, z), (w, x, y, z))) pairs."""
    flags = (0x1 if c.seen_outside else 0) | (0x2 if stabs else 0) | flags_extra
    out = [_u32.pack(c.id), _u32.pack(flags), _u32.pack(c.id), bytes((0, len(c.portals))), _u16.pack(len(c.visible_cells)),
           _u16.pack(c.environment & 0xFFFF), _u16.pack(c.cell_structure),
           struct.pack("<7f", *c.frame.origin, *c.frame.orientation)]
    for p in c.portals:
        out.append(struct.pack("<4H", p.flags, p.polygon, p.other_cell, p.other_portal))
    for v in c.visible_cells:
        out.append(_u16.pack(v))
    if stabs:
        out.append(_u32.pack(len(stabs)))
        for did, (origin, q) in stabs:
            out.append(_u32.pack(did) + struct.pack("<7f", *origin, *q))
    return b"".join(out)


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


def room_struct(floor: float = 0.0, back_wall: bool = False) -> CellStructRec:
    h, z = HALF, floor
    portal_east = _quad((h, -h, 0.0), (h, h, 0.0), (h, h, HEIGHT), (h, -h, HEIGHT))
    portal_west = _quad((-h, h, 0.0), (-h, -h, 0.0), (-h, -h, HEIGHT), (-h, h, HEIGHT))
    floor_poly = _quad((-h, -h, z), (h, -h, z), (h, h, z), (-h, h, z))  # CCW from above: normal +z
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
                 end_cell: int, step_down: float = 0.4, floor_z: float = ROOM_Z) -> Scene:
    start = tuple(to_f32(c) for c in start)
    end = tuple(to_f32(c) for c in end)
    cp = ContactPlane(begin_cell, PlaneRec((0.0, 0.0, 1.0), to_f32(-floor_z)))
    mover = Mover(ONE_SPHERE, Position(begin_cell, Frame(start)), Position(end_cell, Frame(end)), to_f32(0.4),
                  to_f32(step_down), state=state, transient_state=transient, contact_plane=cp)
    return Scene((Landblock(LB | 0xFFFF, (0,) * 81, (0,) * 81),), mover, environments=(env,), env_cells=tuple(cells))


def landblock_info_bytes(block_id: int, num_cells: int) -> bytes:
    """DatLoader LandblockInfo (0xXXYYFFFE): NumCells, no objects, no buildings, PackMask 0."""
    return _u32.pack(block_id | 0xFFFE) + _u32.pack(num_cells) + _u32.pack(0) + _u16.pack(0) + _u16.pack(0)


def world(scene: Scene, mode, stabs: dict | None = None):
    """The run's LScape with its cell DAT (the scene's EnvCells) and portal DAT (the mover's records,
    the Environments, and `extra` records), as port/run.py builds a run's world; returns
    (lscape, portal_dat)."""
    portal_dat, _dids = run.portal_dat_for(scene, mode)
    for e in scene.environments:
        portal_dat.records[e.id] = environment_bytes(e)
    stabs = stabs or {}
    cell_records = {c.id: env_cell_bytes(c, stabs.get(c.id, ())) for c in scene.env_cells}
    for block in {c.id & 0xFFFF0000 for c in scene.env_cells}:
        cell_records[block | 0xFFFE] = landblock_info_bytes(block, sum(1 for c in scene.env_cells if c.id & 0xFFFF0000 == block))
    lscape = LScape(scene, mode)
    lscape.cell_dat = PortalDat(cell_records, mode, scene.engine_mode == "server")
    lscape.portal_dat = portal_dat
    return lscape, portal_dat


def walk(scene: Scene, mode, trace=None):
    """The mover's transition from begin to end, as run_scene makes it; returns (transition, ok, lscape)."""
    from acconform.port.frame import Position as PortPosition

    lscape, portal_dat = world(scene, mode)
    mover = run.build_mover(scene, portal_dat, lscape)
    old_pos = mover.position.copy()
    new_pos = PortPosition.from_record(scene.mover.end, mode)
    trans, ok = mover.transition(old_pos, new_pos, False, lscape, trace)
    return trans, ok, lscape
