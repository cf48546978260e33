"""Dungeons: EnvCells joined by portals, built the way the DAT's cells are, and the strategies that draw them.

A dungeon here is a chain of pieces laid along +x of a *dungeon frame* (a yaw and an origin in
the landblock): rooms, corridors, T-junctions (a side corridor off +y), ramps, stairs, ledges and
floors with a pit. Each piece is one EnvCell; consecutive pieces share a doorway, the portal.

Every cell's geometry is what a DAT cell structure holds, in the cell's own frame (origin at the
piece's centre, z = 0 at its entry floor; x along the chain, y across):

- `polygons`: the drawing polygons, floors, walls, ceilings and the portal polygons; a wall with a
  doorway is cut into convex pieces (jambs and lintel) around the door, as a DAT wall is.
- `portals`: the indices of the portal polygons, in the order of the EnvCell's portal list.
- `physics_polygons`: the same minus the portals, each facing into the cell's free space
  (counter-clockwise seen from inside); `physics_bsp` a tree over them (`physics_bsp`).
- `cell_bsp`: the cell's volume, a chain of planes facing inward linked by front children; a point
  is inside when it is in front of every plane down the chain (BSPNode.point_inside_cell_bsp). A
  DAT cell BSP has no leaf on that chain (ACE's leaf has no plane); a back child may be a leaf.
- a portal's `flags`: PortalSide (bit 0x2 clear) when the portal polygon faces out of the cell,
  toward the neighbour; EnvCell.find_transit_cells then adds the neighbour when a sphere reaches
  in front of it. Both sides of a portal name each other (other_cell, other_portal) and lie on
  the same plane in the landblock (exactly when the frames' yaws are multiples of 90 degrees).

A portal to 0xFFFF leads outside (the landblock's land cells). The dungeon's landblock is flat
ground below the cells: a landblock without terrain, as a dungeon's is.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from hypothesis import strategies as st

from acconform.flags import CullMode, PhysicsState, TransientState
from acconform.numerics import to_f32, to_f32s
from acconform.port.constants import FLOOR_Z
from acconform.scene import (CellBSPLeaf, CellBSPNode, CellPortalRec, CellStructRec, ContactPlane, EnvCell,
                             Environment, Frame, Landblock, Mover, PlaneRec, PolygonRec, Position, Scene, SphereRec,
                             StaticObject, BSPLeaf, BSPNode, OUTSIDE_CELL, PORTAL_SIDE_BIT, newell_normal)

from . import boundaries as bd
from . import draws as dr
from . import shapes as sh

FIRST_CELL = 0x0100
ENVIRONMENT_ID = 0x0D000100

# a polygon whose vertices lie within SPLIT_TOL of a splitting plane's back goes to its front
# child as well (and the other way round): a sphere the BSP sends one way only (dist >= radius -
# EPSILON) still reaches polygons that close behind the plane
SPLIT_TOL = 0.05


# ---------------------------------------------------------------- geometry in a cell's frame

_v = to_f32s  # a point's coordinates rounded to float32


def facing(verts, normal) -> tuple:
    """The vertices ordered so that their Newell normal points along `normal` (CCW seen from there)."""
    verts = [_v(p) for p in verts]
    n = newell_normal(verts)
    if n[0] * normal[0] + n[1] * normal[1] + n[2] * normal[2] < 0:
        verts.reverse()
    return tuple(verts)


def rect_x(x, y0, y1, z0, z1, normal_x):
    """A rectangle on the plane x = const, facing +x (normal_x = 1) or -x (-1)."""
    return facing([(x, y0, z0), (x, y1, z0), (x, y1, z1), (x, y0, z1)], (normal_x, 0.0, 0.0))


def rect_y(y, x0, x1, z0, z1, normal_y):
    return facing([(x0, y, z0), (x1, y, z0), (x1, y, z1), (x0, y, z1)], (0.0, normal_y, 0.0))


def quad_z(x0, x1, y0, y1, z0, z1, normal_z):
    """A floor or ceiling over [x0, x1] x [y0, y1], at height z0 at x0 and z1 at x1 (a ramp when they differ)."""
    return facing([(x0, y0, z0), (x1, y0, z1), (x1, y1, z1), (x0, y1, z0)], (0.0, 0.0, normal_z))


@dataclass(frozen=True)
class Door:
    """A doorway in an end or side wall: width and height, the lateral centre (y for an end wall,
    x for a side wall), and where it leads (a piece index, or OUTSIDE_CELL)."""

    width: float
    height: float
    centre: float = 0.0
    leads_to: int = OUTSIDE_CELL
    faces_out: bool = True  # the portal polygon faces the neighbour (PortalSide)


@dataclass(frozen=True)
class Piece:
    """One EnvCell of the chain. `profile`: flat, ramp, stairs, ledge or pit; `rise` the exit
    floor's height over the entry's (ramp, stairs: > 0 or < 0; ledge: the drop, < 0)."""

    kind: str
    length: float
    width: float
    height: float
    profile: str = "flat"
    rise: float = 0.0
    steps: int = 1           # stairs: how many
    feature_at: float = 0.0  # ledge: the edge's x; pit: its near edge's x
    pit_length: float = 0.0
    pit_depth: float = 0.0
    turn: int = 0            # the cell frame's yaw relative to the dungeon frame: 0, 90, 180 or 270
    floor_cull: int = int(CullMode.Clockwise)
    seam_dz: float = 0.0     # the entry floor's height over the previous piece's exit floor (a seam's step)
    lip: float = 0.0         # a flat floor reaching this far back past the entry wall, under the previous cell


@dataclass
class CellGeometry:
    polygons: list = field(default_factory=list)
    physics: list = field(default_factory=list)     # (PolygonRec, on the cell's boundary)
    portals: list = field(default_factory=list)     # polygon indices, in the EnvCell's portal order
    portal_doors: list = field(default_factory=list)  # (which wall, Door) per portal
    zmin: float = 0.0
    ztop: float = 0.0


def floor_at(p: Piece, x: float) -> float:
    """The floor's height at local x (entry floor = 0)."""
    x0 = -p.length / 2
    if p.profile == "ramp":
        return p.rise * (x - x0) / p.length
    if p.profile == "stairs":
        run = p.length / p.steps
        k = min(int((x - x0) // run), p.steps - 1)
        return to_f32(p.rise * k / (p.steps - 1)) if p.steps > 1 else 0.0
    if p.profile == "ledge":
        return 0.0 if x < p.feature_at else p.rise
    return 0.0


def exit_floor(p: Piece) -> float:
    return to_f32(p.rise) if p.profile in ("ramp", "stairs", "ledge") else 0.0


def _wall_with_door(make, span0, span1, zb, zt, door: Door | None, normal):
    """A wall's convex pieces around an optional door: [(PolygonRec vertices, is_portal)]."""
    out = []
    if door is None:
        return [(make(span0, span1, zb, zt, normal), False)]
    d0, d1 = to_f32(door.centre - door.width / 2), to_f32(door.centre + door.width / 2)
    dt = to_f32(min(zb + door.height, zt))
    if d0 > span0:
        out.append((make(span0, d0, zb, zt, normal), False))
    if span1 > d1:
        out.append((make(d1, span1, zb, zt, normal), False))
    if zt > dt:
        out.append((make(d0, d1, dt, zt, normal), False))
    out.append((make(d0, d1, zb, dt, normal), True))
    return out


def cell_geometry(p: Piece, entry: Door | None, exit_: Door | None, side: Door | None) -> CellGeometry:
    """The cell's polygons in its own (dungeon-aligned) frame; doors: on the -x wall, the +x wall, the +y wall."""
    g = CellGeometry()
    hl, hw = to_f32(p.length / 2), to_f32(p.width / 2)
    x0, x1, y0, y1 = -hl, hl, -hw, hw
    z_out = exit_floor(p)
    floors = [min(0.0, z_out)]
    top = to_f32(max(0.0, z_out) + p.height)
    strips = []  # (xa, xb, floor za at xa, floor zb at xb): the floor under side walls, left to right

    # a floor is the cell's boundary (all below it solid) only when it is the whole floor or a ramp
    floor_bounds = p.profile in ("flat", "ramp")

    def add(verts, boundary=True, cull=int(CullMode.Clockwise), portal=None):
        rec = PolygonRec(verts, cull)
        g.polygons.append(rec)
        if portal is None:
            g.physics.append((rec, boundary))
        else:
            g.portals.append(len(g.polygons) - 1)
            g.portal_doors.append(portal)

    if p.profile == "ramp":
        add(quad_z(x0, x1, y0, y1, 0.0, z_out, 1.0), cull=p.floor_cull, boundary=floor_bounds)
        strips.append((x0, x1, 0.0, z_out))
    elif p.profile == "stairs":
        run = p.length / p.steps
        prev = None
        for k in range(p.steps):
            xa, xb = to_f32(x0 + run * k), (to_f32(x0 + run * (k + 1)) if k < p.steps - 1 else x1)
            z = floor_at(p, (xa + xb) / 2)
            add(quad_z(xa, xb, y0, y1, z, z, 1.0), cull=p.floor_cull, boundary=floor_bounds)
            if prev is not None and z != prev:  # a riser facing the lower step
                add(rect_x(xa, y0, y1, min(z, prev), max(z, prev), -1.0 if z > prev else 1.0), boundary=False)
            strips.append((xa, xb, z, z))
            prev = z
    elif p.profile == "ledge":
        xe = to_f32(p.feature_at)
        add(quad_z(x0, xe, y0, y1, 0.0, 0.0, 1.0), cull=p.floor_cull, boundary=floor_bounds)
        add(quad_z(xe, x1, y0, y1, z_out, z_out, 1.0), cull=p.floor_cull, boundary=floor_bounds)
        add(rect_x(xe, y0, y1, z_out, 0.0, 1.0), boundary=False)  # the ledge's face, toward the low floor
        strips += [(x0, xe, 0.0, 0.0), (xe, x1, z_out, z_out)]
    elif p.profile == "pit":
        xa, xb = to_f32(p.feature_at), to_f32(p.feature_at + p.pit_length)
        zp = to_f32(-p.pit_depth)
        floors.append(zp)
        add(quad_z(x0, xa, y0, y1, 0.0, 0.0, 1.0), cull=p.floor_cull, boundary=floor_bounds)
        add(quad_z(xa, xb, y0, y1, zp, zp, 1.0), cull=p.floor_cull, boundary=floor_bounds)
        add(quad_z(xb, x1, y0, y1, 0.0, 0.0, 1.0), cull=p.floor_cull, boundary=floor_bounds)
        add(rect_x(xa, y0, y1, zp, 0.0, 1.0), boundary=False)
        add(rect_x(xb, y0, y1, zp, 0.0, -1.0), boundary=False)
        strips += [(x0, xa, 0.0, 0.0), (xa, xb, zp, zp), (xb, x1, 0.0, 0.0)]
    else:
        add(quad_z(to_f32(x0 - p.lip), x1, y0, y1, 0.0, 0.0, 1.0), cull=p.floor_cull, boundary=floor_bounds)
        strips.append((x0, x1, 0.0, 0.0))
    add(quad_z(x0, x1, y0, y1, top, top, -1.0))  # ceiling, facing down

    # side walls (y = -hw facing +y, y = +hw facing -y), one convex strip per floor strip
    for y, ny in ((y0, 1.0), (y1, -1.0)):
        door = side if ny < 0 else None
        for xa, xb, za, zb in strips:
            if door is not None and xa <= door.centre - door.width / 2 and door.centre + door.width / 2 <= xb and za == zb:
                for verts, is_portal in _wall_with_door(lambda s0, s1, b, t, n, y=y: rect_y(y, s0, s1, b, t, n),
                                                        xa, xb, za, top, door, ny):
                    add(verts, portal=("side", door) if is_portal else None)
                door = None
            else:
                add(facing([(xa, y, za), (xb, y, zb), (xb, y, top), (xa, y, top)], (0.0, ny, 0.0)))
    # end walls
    for x, nx, zb, door, which in ((x0, 1.0, 0.0 if p.profile != "pit" else 0.0, entry, "entry"),
                                   (x1, -1.0, z_out if p.profile != "pit" else 0.0, exit_, "exit")):
        for verts, is_portal in _wall_with_door(lambda s0, s1, b, t, n, x=x: rect_x(x, s0, s1, b, t, n),
                                                y0, y1, zb, top, door, nx):
            add(verts, portal=(which, door) if is_portal else None)
    g.zmin = min(floors)
    g.ztop = top
    # a wall with a doorway in it bounds nothing: the space beyond its plane is the neighbour's
    doorways = [plane_of(g.polygons[k].vertices) for k in g.portals]
    g.physics = [(rec, boundary and not _in_a_doorway(plane_of(rec.vertices), doorways)) for rec, boundary in g.physics]
    # a portal polygon faces the neighbour when its door says so (PortalSide), else into the cell
    for k, (which, door) in zip(g.portals, g.portal_doors):
        if door.faces_out:
            rec = g.polygons[k]
            g.polygons[k] = PolygonRec(tuple(reversed(rec.vertices)), rec.sides_type)
    return g


def plane_of(verts) -> PlaneRec:
    return sh._plane(verts)


def _coplanar(a: PlaneRec, b: PlaneRec) -> bool:
    """The same plane, facing either way."""
    dot = sum(x * y for x, y in zip(a.normal, b.normal))
    return abs(abs(dot) - 1) < 1e-6 and abs(a.d - (b.d if dot > 0 else -b.d)) < 1e-4


def _in_a_doorway(plane: PlaneRec, doorways) -> bool:
    return any(_coplanar(plane, d) for d in doorways)


def plane_distance(plane: PlaneRec, p) -> float:
    """The signed distance of point p from the plane (positive in front)."""
    n = plane.normal
    return n[0] * p[0] + n[1] * p[1] + n[2] * p[2] + plane.d


def physics_bsp(physics: list, max_depth: int = 4) -> BSPNode | BSPLeaf:
    """A physics BSP over the cell's physics polygons: each node splits on one polygon's plane; a
    polygon goes to each side it reaches within SPLIT_TOL, so every sphere the tree sends one way
    finds every polygon it can touch there. A leaf behind a boundary polygon's plane (outside the
    cell) is solid. Node and leaf spheres bound the polygons below them. Below `max_depth` nodes
    a leaf holds what is left (a deeper tree costs both sides more per scene, and the corpus more
    bytes, for the same polygons)."""
    verts = [rec.vertices for rec, _ in physics]
    planes = [plane_of(vs) for vs in verts]
    boundary = [b for _, b in physics]
    # polygon sets are bit masks (bit i: polygon i), so a split costs two ANDs per candidate plane
    spheres = {0: SphereRec((0.0, 0.0, 0.0), 0.0)}  # a set -> its sphere: both sides of a split often keep the same polygons

    def sphere_of(ids: int):
        s = spheres.get(ids)
        if s is None:
            # a vertex shared by polygons counts once (the set's order picks the sign of a zero bound)
            s = spheres[ids] = sh.bounding_sphere({v for i in _members(ids) for v in verts[i]})
        return s

    # which polygons reach each side of each plane, once per plane (a node only picks among them);
    # a plane is named by its first polygon, so the tree's candidates are those polygons
    firsts = {}
    for k, pl in enumerate(planes):
        firsts.setdefault(pl, k)
    reach = {}
    for k in firsts.values():
        front = back = 0
        for i, vs in enumerate(verts):
            ds = [plane_distance(planes[k], v) for v in vs]
            if max(ds) > -SPLIT_TOL:
                front |= 1 << i
            if min(ds) < SPLIT_TOL:
                back |= 1 << i
        reach[k] = (front, back)

    def build(ids: int, candidates, solid, depth):
        # the plane that splits best (the larger side smallest, the first such); a leaf when none splits
        best = None
        if depth < max_depth:
            for k in candidates:
                in_front, behind = reach[k]
                front, back = ids & in_front, ids & behind
                size = max(front.bit_count(), back.bit_count())
                if (front != ids or back != ids) and (best is None or size < best[0]):
                    best = (size, k, front, back)
        if best is None:
            return BSPLeaf(_members(ids), solid, sphere_of(ids))
        _, k, front, back = best
        rest = [c for c in candidates if c != k]
        return BSPNode(planes[k], sphere_of(ids), build(front, rest, solid, depth + 1),
                       build(back, rest, solid or boundary[k], depth + 1))

    return build((1 << len(verts)) - 1, sorted(firsts.values()), False, 0)


def _members(mask: int) -> tuple[int, ...]:
    """The set bits of a mask, lowest first."""
    out = []
    while mask:
        low = mask & -mask
        out.append(low.bit_length() - 1)
        mask ^= low
    return tuple(out)


def cell_bsp(p: Piece, g: CellGeometry, order: tuple[int, ...], back_leaves: bool, ramp_floor: bool):
    """The cell's volume as a chain of inward planes (front children), in `order` (a permutation of
    the six faces: -x, +x, -y, +y, floor, ceiling); back children empty or leaves."""
    hl, hw = to_f32(p.length / 2), to_f32(p.width / 2)
    faces = [PlaneRec((1.0, 0.0, 0.0), hl), PlaneRec((-1.0, 0.0, 0.0), hl),
             PlaneRec((0.0, 1.0, 0.0), hw), PlaneRec((0.0, -1.0, 0.0), hw),
             PlaneRec((0.0, 0.0, 1.0), to_f32(-g.zmin)), PlaneRec((0.0, 0.0, -1.0), g.ztop)]
    if ramp_floor and p.profile == "ramp":
        faces[4] = plane_of(g.physics[0][0].vertices)  # the ramp itself (its first physics polygon)
    node = None
    for k in reversed(order):
        node = CellBSPNode(faces[k], node, CellBSPLeaf() if back_leaves else None)
    return node


def point_inside(bsp: CellBSPNode | None, point) -> bool:
    """BSPNode.point_inside_cell_bsp in doubles (for the strategies' own checks; the port is float32)."""
    node = bsp
    while node is not None:
        if plane_distance(node.plane, point) < -0.0002:
            return False
        node = node.front
    return True


# ---------------------------------------------------------------- frames

def yaw_quat(deg: float):
    h = math.radians(deg) / 2
    return (to_f32(math.cos(h)), 0.0, 0.0, to_f32(math.sin(h)))


def _rot(deg, x, y):
    if deg % 90 == 0:
        c, s = [(1, 0), (0, 1), (-1, 0), (0, -1)][int(deg // 90) % 4]
    else:
        c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return x * c - y * s, x * s + y * c


@dataclass(frozen=True)
class Dungeon:
    """A laid-out chain: the pieces, the dungeon frame, and what the scene records need."""

    block: int
    pieces: tuple[Piece, ...]
    doors: tuple[Door, ...]         # doors[i]: between pieces i and i + 1
    entry: Door | None              # piece 0's -x door (to outside) or None
    side: tuple                     # (piece index, Door, side corridor Piece) or ()
    yaw: float
    origin: tuple[float, float, float]
    starts: tuple[float, ...]       # each piece's entry x along the chain
    bases: tuple[float, ...]        # each piece's entry floor z (dungeon frame)

    def cell_id(self, i: int) -> int:
        return (self.block << 16) | (FIRST_CELL + i)

    def centre(self, i: int) -> tuple[float, float, float]:
        """Piece i's frame origin in the dungeon frame (the side corridor is index len(pieces))."""
        if i < len(self.pieces):
            p = self.pieces[i]
            return (self.starts[i] + p.length / 2, 0.0, self.bases[i])
        j, door, corr = self.side
        p = self.pieces[j]
        return (self.starts[j] + p.length / 2 + door.centre, p.width / 2 + corr.length / 2, self.bases[j])

    def frame(self, i: int) -> Frame:
        p = self.pieces[i] if i < len(self.pieces) else self.side[2]
        cx, cy, cz = self.centre(i)
        ox, oy = _rot(self.yaw, cx, cy)
        origin = (to_f32(self.origin[0] + ox), to_f32(self.origin[1] + oy), to_f32(self.origin[2] + cz))
        # the side corridor runs along +y: its own +x is the dungeon's +y (turn 90 on top of its own)
        extra = 90 if i >= len(self.pieces) else 0
        return Frame(origin, yaw_quat(self.yaw + p.turn + extra))

    def global_point(self, i: int, local) -> tuple[float, float, float]:
        """A point in cell i's own frame -> landblock coordinates, through the cell's float32 frame."""
        f = self.frame(i)
        q = f.orientation
        ang = 2 * math.atan2(q[3], q[0])
        c, s = math.cos(ang), math.sin(ang)
        x, y, z = local
        return (f.origin[0] + x * c - y * s, f.origin[1] + x * s + y * c, f.origin[2] + z)


def _turned(p: Piece, verts):
    """Vertices in the dungeon-aligned piece frame -> the cell's own frame (turned by -p.turn)."""
    turned = [(_rot(-p.turn, x, y), z) for x, y, z in verts]
    return tuple((to_f32(x), to_f32(y), z) for (x, y), z in turned)


@dataclass(frozen=True)
class Built:
    dungeon: Dungeon
    environment: Environment
    env_cells: tuple[EnvCell, ...]
    geometry: tuple[CellGeometry, ...]


def build(d: Dungeon, visible: str = "all", bsp_order=(0, 1, 2, 3, 4, 5), back_leaves=False, ramp_floor=False,
          missing_visible: int | None = None, bsp_depth: int = 4) -> Built:
    """The Environment and EnvCells of a laid-out dungeon. `visible`: "all" (every cell sees every
    other) or "neighbours" (the portal neighbours only); `missing_visible`: a cell whose portal
    neighbours are left out of its visible list (find_transit_cells then adds the id alone)."""
    n = len(d.pieces)
    cells = list(range(n)) + ([n] if d.side else [])
    structs, struct_index, geoms, portals_of = [], {}, [], {}
    for i in cells:
        if i < n:
            p = d.pieces[i]
            entry = d.doors[i - 1] if i > 0 else d.entry
            exit_ = d.doors[i] if i < n - 1 else None
            side = d.side[1] if d.side and d.side[0] == i else None
        else:
            p, entry, exit_, side = d.side[2], d.side[1], None, None
            entry = Door(entry.width, entry.height, 0.0, d.side[0], entry.faces_out)
        g = cell_geometry(p, entry, exit_, side)
        if p.turn:
            g.polygons = [PolygonRec(_turned(p, r.vertices), r.sides_type) for r in g.polygons]
            g.physics = [(PolygonRec(_turned(p, r.vertices), r.sides_type), b) for r, b in g.physics]
        geoms.append(g)
        bsp = cell_bsp(p, g, bsp_order, back_leaves, ramp_floor and not p.turn)
        if p.turn:
            bsp = _turn_bsp(bsp, p.turn)
        physics = [r for r, _ in g.physics]
        rec = CellStructRec(tuple(g.polygons), tuple(g.portals), tuple(physics),
                            physics_bsp(g.physics, bsp_depth), bsp)
        # pieces of one shape share a structure: equal records, found by their polygons first (hashing
        # a whole record walks both of its trees)
        same = struct_index.setdefault((rec.polygons, rec.portals, rec.physics_polygons), [])
        index = next((k for k in same if structs[k] == rec), None)
        if index is None:
            index = len(structs)
            same.append(index)
            structs.append(rec)
        portals_of[i] = (index, g)
    env = Environment(ENVIRONMENT_ID, tuple(structs))
    # portals: entry (-x), exit (+x), side (+y) as cell_geometry listed them
    env_cells = []
    for i in cells:
        s, g = portals_of[i]
        recs = []
        for k, (which, door) in zip(g.portals, g.portal_doors):
            other, other_portal = _neighbour(d, i, which, door, portals_of)
            flags = 0 if door.faces_out else PORTAL_SIDE_BIT
            recs.append(CellPortalRec(k, other, other_portal, flags))
        neighbours = [r.other_cell for r in recs if r.other_cell != OUTSIDE_CELL]
        if visible == "all":
            vis = [FIRST_CELL + j for j in cells if j != i]
        else:
            vis = neighbours
        if missing_visible == i:
            vis = [c for c in vis if c not in neighbours]
        seen_out = any(r.other_cell == OUTSIDE_CELL for r in recs)
        env_cells.append(EnvCell(d.cell_id(i), d.frame(i), ENVIRONMENT_ID, s, tuple(recs), tuple(vis), seen_out))
    return Built(d, env, tuple(env_cells), tuple(geoms))


def _turn_bsp(node, turn):
    if node is None or isinstance(node, CellBSPLeaf):
        return node
    nx, ny = _rot(-turn, node.plane.normal[0], node.plane.normal[1])
    plane = PlaneRec((to_f32(nx), to_f32(ny), node.plane.normal[2]), node.plane.d)
    return CellBSPNode(plane, _turn_bsp(node.front, turn), node.back)


def _neighbour(d: Dungeon, i: int, which: str, door: Door, portals_of) -> tuple[int, int]:
    n = len(d.pieces)
    if which == "entry":
        j = door.leads_to if i >= n else i - 1
        if i == 0:
            return OUTSIDE_CELL, 0
        want = "side" if i >= n else "exit"
    elif which == "exit":
        j, want = i + 1, "entry"
    else:
        j, want = n, "entry"
    _, g = portals_of[j]
    k = next(m for m, (w, _) in enumerate(g.portal_doors) if w == want)
    return FIRST_CELL + j, k


def lay_out(block: int, pieces, doors, entry=None, side=(), yaw: float = 0.0,
            origin=(96.0, 96.0, 20.0)) -> Dungeon:
    """A Dungeon for pieces in a chain: each piece's entry x and entry floor along the chain."""
    starts, bases = [], []
    x, z = 0.0, 0.0
    for p in pieces:
        z = to_f32(z + p.seam_dz)
        starts.append(x)
        bases.append(z)
        x, z = x + p.length, to_f32(z + exit_floor(p))
    return Dungeon(block, tuple(pieces), tuple(doors), entry, tuple(side), yaw, tuple(origin), tuple(starts),
                   tuple(bases))


def dungeon_point(d: Dungeon, i: int, x: float, y: float, z: float) -> tuple[float, float, float]:
    """A point given in piece i's dungeon-aligned frame (x along the chain, z over its entry floor)
    -> landblock coordinates, as float32s (through the cell's frame, its turn undone)."""
    p = d.pieces[i] if i < len(d.pieces) else d.side[2]
    lx, ly = _rot(-p.turn, x, y)
    if i >= len(d.pieces):
        lx, ly = _rot(-90, lx, ly)
    return tuple(to_f32(c) for c in d.global_point(i, (lx, ly, z)))


def cell_containing(built: Built, point) -> int | None:
    """The first cell (in cell order) whose cell BSP holds a landblock point (doubles)."""
    for cell in built.env_cells:
        q = cell.frame.orientation
        ang = -2 * math.atan2(q[3], q[0])
        dx, dy = point[0] - cell.frame.origin[0], point[1] - cell.frame.origin[1]
        local = (dx * math.cos(ang) - dy * math.sin(ang), dx * math.sin(ang) + dy * math.cos(ang),
                 point[2] - cell.frame.origin[2])
        if point_inside(built.environment.cell_structs[cell.cell_structure].cell_bsp, local):
            return cell.id
    return None


def dungeon_landblock(block: int) -> Landblock:
    """The dungeon's landblock: no terrain (ACE reads 81 zero heights: flat ground at z = 0, below
    every cell, reached only through a portal to 0xFFFF)."""
    return Landblock((block << 16) | 0xFFFF, has_terrain=False)


def dungeon_scene(built: Built, spheres, begin, end, begin_cell: int, step_up: float, step_down: float,
                  state: int, airborne: bool = False, statics=(), name: str = "indoor",
                  contact_normal=(0.0, 0.0, 1.0), velocity=(0.0, 0.0, 0.0)) -> Scene:
    """A scene: the dungeon's landblock, Environment and EnvCells, statics and a mover from
    `begin` (landblock coordinates, in begin_cell) to `end`; grounded movers stand on a floor whose
    normal is `contact_normal` through `begin`."""
    d = built.dungeon
    # each end in the cell whose cell BSP holds its first sphere's centre (as find_cell_list picks)
    begin_cell = cell_containing(built, (begin[0], begin[1], begin[2] + spheres[0].radius)) or begin_cell
    end_cell = cell_containing(built, (end[0], end[1], end[2] + spheres[0].radius)) or begin_cell
    contact, transient = None, 0
    if not airborne:
        n = contact_normal
        contact = ContactPlane(begin_cell, PlaneRec(n, to_f32(-(n[0] * begin[0] + n[1] * begin[1] + n[2] * begin[2]))))
        transient = int(TransientState.Contact) | (int(TransientState.OnWalkable) if n[2] >= FLOOR_Z else 0)
    mover = Mover(spheres=tuple(spheres), begin=Position(begin_cell, Frame(tuple(begin))),
                  end=Position(end_cell, Frame(tuple(end))), step_up_height=step_up, step_down_height=step_down,
                  state=state, transient_state=transient, contact_plane=contact, velocity=velocity)
    return Scene((dungeon_landblock(d.block),), mover, tuple(statics), name=name,
                 environments=(built.environment,), env_cells=built.env_cells)


def static_in(built: Built, i: int, ident: int, shape, x: float, y: float, z: float = 0.0, angle: float = 0.0,
              state: int = int(PhysicsState.Static)) -> StaticObject:
    """A static object in piece i's cell at (x, y, z) of the piece's dungeon-aligned frame."""
    d = built.dungeon
    origin = dungeon_point(d, i, x, y, z)
    extra = 90 if i >= len(d.pieces) else 0
    return StaticObject(ident, Position(d.cell_id(i), Frame(origin, yaw_quat(d.yaw + angle + extra))), shape, state)


# ---------------------------------------------------------------- strategies

DUNGEON_BLOCKS = st.sampled_from((0x01D9, 0x8A02, 0x0007, 0xF9FE))
YAWS = dr.OneOf(st.sampled_from((0.0, 90.0, 180.0, 270.0)), st.sampled_from((37.0, 45.0, 12.5, 300.0)),
                dr.ints(0, 359))
TURNS = st.sampled_from((0, 0, 0, 90, 180, 270))
ORIGIN_XY = dr.f32(60.0, 130.0)
ORIGIN_Z = dr.OneOf(st.sampled_from((20.0, 100.0, 0.5)), dr.f32(1.0, 200.0))
# how much wider than the mover a doorway is: barely (a hair to a centimetre), some, lots
DOOR_SLACK = dr.OneOf(st.sampled_from((0.0005, 0.001, 0.01, 0.02)), dr.f32(0.001, 0.1), dr.f32(0.1, 3.0))
HEADROOM = dr.OneOf(st.sampled_from((0.05, 0.5)), dr.f32(0.01, 2.0))
ROOM_EXTRA_WIDTH, ROOM_LENGTHS, CORRIDOR_LENGTHS = dr.f32(0.3, 8.0), dr.f32(1.0, 12.0), dr.f32(0.5, 10.0)
EXTRA_HEIGHT = st.sampled_from((0.0, 0.0, 0.5, 2.0))
ROOM_OR_CORRIDOR = st.sampled_from(("room", "corridor"))
FACES_OUT = st.sampled_from((True, True, False))
RAMP_ANGLES = st.sampled_from((48.0, 48.3, 48.5, 49.0, 10.0, 30.0, 45.0, 60.0))
EXACT_RAMPS = tuple((name, w) for name, bits in bd.Z_BOUNDARIES.items() for w in bd.exact_wedges(bits))
RAMP_KINDS = st.sampled_from(("exact", "exact", "angle"))
EXACT_RAMP_PICK = dr.ints(0, max(len(EXACT_RAMPS) - 1, 0))
DOWNHILL = st.sampled_from((False, False, True))
STAIR_COUNTS = dr.ints(2, 6)
STAIR_RUNS = dr.f32(0.3, 2.0)
LEDGE_DROPS = dr.OneOf(st.sampled_from((0.1, 0.25, 0.5, 1.0, 3.0)), dr.f32(0.01, 6.0))
PIT_LENGTHS = dr.OneOf(st.sampled_from((0.1, 0.5, 1.0)), dr.f32(0.05, 4.0))
PIT_DEPTHS = dr.f32(0.2, 5.0)
FLOOR_CULLS = st.sampled_from((int(CullMode.Clockwise), int(CullMode.Clockwise), int(CullMode.None_)))
VISIBLE = st.sampled_from(("all", "all", "all", "neighbours", "missing"))
BSP_DEPTHS = st.sampled_from((3, 3, 4, 6, 1))
BSP_ORDERS = st.sampled_from(((0, 1, 2, 3, 4, 5), (4, 5, 0, 1, 2, 3), (5, 3, 1, 4, 2, 0), (2, 0, 4, 1, 5, 3)))
# a seam's step between two cells' floors, and a floor reaching under the previous cell
SEAM_DZ = st.sampled_from((0.0, 0.0, 0.0, 0.0, 0.001, -0.001, 0.0005, 0.01, -0.01))
LIPS = st.sampled_from((0.0, 0.0, 0.0, 0.001, 0.01, 0.05))
# a doorway cell: a frame thinner than the mover, between two cells (its neighbours reached through it)
FRAME_LENGTHS = dr.OneOf(st.sampled_from((0.05, 0.1, 0.2)), dr.f32(0.02, 1.0))
# a dungeon with a way out: on the ground, just above it, or sunk a little below it (a cellar: the
# land cells the outside portal adds reach into the cell, where the visible-cell pruning drops them)
OUTSIDE_Z = st.sampled_from((0.0, -0.1, 0.01, -0.3, 0.3, 0.02, -0.05))
POLICIES = st.sampled_from(("cross", "cross", "doorway", "wall", "ramp", "ramp", "stairs", "ledge", "ledge", "pit",
                            "tee", "static", "straddle", "seam", "outside", "fall"))
# path lengths in mover radii past the target (a portal, an edge, a wall): within one step, or many
PAST = dr.OneOf(dr.f32(0.05, 1.0), st.sampled_from((0.0, 0.5, 1.0, 2.0)), dr.f32(1.0, 8.0))
# how far before the target the mover starts, in radii: on it, a step, a few steps
BEFORE = dr.OneOf(st.sampled_from((0.0, 0.25, 1.0)), dr.f32(0.0, 1.0), dr.f32(1.0, 6.0))
HEADING_JITTER = dr.OneOf(st.sampled_from((0.0, 0.0, 10.0, -10.0, 30.0, -45.0, 60.0, 89.0)), dr.floats(-80.0, 80.0))
LATERAL = st.sampled_from((0.0, 0.0, 0.5, -0.5, 0.9, -0.9, 1.0, -1.0))  # of the door's free half-width
AIR = dr.OneOf(st.sampled_from((0.01, 0.5)), dr.f32(0.001, 4.0))
QUARTERS = dr.ints(0, 3)
STATIC_SIZES = dr.f32(0.2, 2.0)
STATIC_ANGLES = st.sampled_from((0.0, 0.0, 45.0, 30.0))
STEP_UP_SITE, STEP_DOWN_SITE = dr.Site("indoor step-up height"), dr.Site("indoor step-down height")


def _door(draw, r, head, leads_to) -> Door:
    width = to_f32(2 * r + dr.take(draw, DOOR_SLACK))
    height = to_f32(head + dr.take(draw, HEADROOM))
    return Door(width, height, 0.0, leads_to, draw(FACES_OUT))


def _plain(draw, kind, door_in: Door, r: float) -> Piece:
    """A flat room (wider than its door) or corridor (the door's width), at least a mover long."""
    wd, hd = door_in.width, door_in.height
    if kind == "corridor":
        return Piece("corridor", max(draw(CORRIDOR_LENGTHS), to_f32(2 * r + 0.1)), wd, to_f32(hd + draw(EXTRA_HEIGHT)),
                     floor_cull=draw(FLOOR_CULLS), turn=draw(TURNS))
    return Piece("room", max(draw(ROOM_LENGTHS), to_f32(2 * r + 0.1)), to_f32(wd + draw(ROOM_EXTRA_WIDTH)), to_f32(hd + draw(EXTRA_HEIGHT)),
                 floor_cull=draw(FLOOR_CULLS), turn=draw(TURNS))


def _ramp(draw, door: Door) -> tuple[Piece, list]:
    """A ramp piece: exactly at or an ulp either side of FloorZ / LandingZ (boundaries' solved
    wedges, frame not turned: the slope's plane is the solved one), or at a drawn angle."""
    if draw(RAMP_KINDS) == "exact" and EXACT_RAMPS:
        name, (sx, sy, sz) = EXACT_RAMPS[draw(EXACT_RAMP_PICK)]
        if sy >= door.width:
            return Piece("ramp", sx, sy, to_f32(door.height + 0.5), "ramp", sz), [abs(sz)]
    length = draw(ROOM_LENGTHS)
    rise = to_f32(length * math.tan(math.radians(draw(RAMP_ANGLES))))
    if draw(DOWNHILL):
        rise = -rise
    return Piece("ramp", length, to_f32(door.width + draw(ROOM_EXTRA_WIDTH)), to_f32(door.height + 0.5), "ramp",
                 rise, turn=draw(TURNS)), [abs(rise)]


def _stairs(draw, door: Door, r: float) -> tuple[Piece, list]:
    n = draw(STAIR_COUNTS)
    h = draw(st.sampled_from(sh.STEP_SIZES + (to_f32(r / 2), to_f32(r))))
    rise = to_f32(h * (n - 1)) * (-1 if draw(DOWNHILL) else 1)
    return Piece("stairs", to_f32(n * draw(STAIR_RUNS)), to_f32(door.width + draw(ROOM_EXTRA_WIDTH)),
                 to_f32(door.height + 0.5), "stairs", rise, steps=n, turn=draw(TURNS)), [h]


def draw_indoor(draw, spheres, step_heights, policy: str | None = None) -> Scene:
    """An indoor scene: a dungeon chain built for one policy (drawn, or the one given) and a mover
    across its feature. `step_heights(geometry_steps)` gives the one_of branches for step heights
    (strategies/scenes.py)."""
    policy = policy or draw(POLICIES)
    block = draw(DUNGEON_BLOCKS)
    r = spheres[0].radius
    head = max(s.center[2] + s.radius for s in spheres)
    d0 = _door(draw, r, head, 1)
    geometry_steps = [r * t for t in (0.5, 1.0, 1.5)]
    side, entry = (), None
    first = draw(ROOM_OR_CORRIDOR)
    pieces = [_plain(draw, first, d0, r)]
    doors = [d0]
    feature = 1  # the piece whose entry (or feature) the mover heads for
    if policy == "ramp":
        p, s = _ramp(draw, d0)
        pieces.append(p)
        geometry_steps += s
    elif policy == "stairs":
        p, s = _stairs(draw, d0, r)
        pieces.append(p)
        geometry_steps += s
    elif policy in ("ledge", "pit"):
        base = _plain(draw, "room", d0, r)
        x0 = -base.length / 2
        if policy == "ledge":
            drop = -dr.take(draw, LEDGE_DROPS)
            # the edge anywhere along the room, or at its exit wall (a precipice at the portal)
            at = to_f32(x0 + base.length * draw(st.sampled_from((0.3, 0.5, 0.99, 1.0))))
            at = min(at, to_f32(-x0 - 0.01))
            p = Piece("ledge", base.length, base.width, to_f32(base.height - drop), "ledge", to_f32(drop),
                      feature_at=at, floor_cull=base.floor_cull, turn=base.turn)
            geometry_steps.append(-drop)
        else:
            pl = min(dr.take(draw, PIT_LENGTHS), base.length * 0.5)
            at = to_f32(x0 + base.length * 0.25)
            p = Piece("pit", base.length, base.width, base.height, "pit", feature_at=at, pit_length=to_f32(pl),
                      pit_depth=draw(PIT_DEPTHS), floor_cull=base.floor_cull, turn=base.turn)
        pieces.append(p)
    elif policy == "seam":
        # two cells of one width and height meeting at a whole-wall portal
        pieces[0] = Piece(pieces[0].kind, pieces[0].length, d0.width, d0.height, turn=pieces[0].turn)
        pieces.append(Piece("corridor", max(draw(CORRIDOR_LENGTHS), to_f32(2 * r + 0.1)), d0.width, d0.height,
                            turn=draw(TURNS)))
    elif policy == "tee":
        tee = _plain(draw, "room", d0, r)
        sd = _door(draw, r, head, 1)
        sd = Door(sd.width, sd.height, 0.0, 1, sd.faces_out)
        tee = Piece("tee", max(tee.length, to_f32(sd.width + 0.2)), tee.width, max(tee.height, sd.height),
                    floor_cull=tee.floor_cull)
        pieces.append(tee)
        side = (1, sd, Piece("corridor", draw(CORRIDOR_LENGTHS), sd.width, sd.height, turn=draw(TURNS)))
    else:
        if draw(QUARTERS) == 0:  # a thin doorway cell first: the next cell is reached through it
            frame = Piece("frame", min(dr.take(draw, FRAME_LENGTHS), r), d0.width, d0.height, turn=draw(TURNS))
            pieces.append(frame)
            doors.append(Door(d0.width, d0.height, 0.0, 2, d0.faces_out))
        nxt = _plain(draw, draw(ROOM_OR_CORRIDOR), d0, r)
        pieces.append(Piece(nxt.kind, nxt.length, nxt.width, nxt.height, floor_cull=nxt.floor_cull, turn=nxt.turn,
                            seam_dz=draw(SEAM_DZ), lip=draw(LIPS)))
    if draw(QUARTERS) == 0:  # a third cell beyond
        d1 = _door(draw, r, head, 2)
        d1 = Door(min(d1.width, pieces[-1].width), min(d1.height, pieces[-1].height), 0.0, 2, d1.faces_out)
        doors.append(d1)
        pieces.append(_plain(draw, draw(ROOM_OR_CORRIDOR), d1, r))
    if policy == "outside" or draw(QUARTERS) == 0:
        entry = Door(min(d0.width, pieces[0].width), min(d0.height, pieces[0].height), 0.0, OUTSIDE_CELL,
                     draw(FACES_OUT))
    yaw = dr.take(draw, YAWS)
    origin = (draw(ORIGIN_XY), draw(ORIGIN_XY), draw(OUTSIDE_Z) if entry is not None else dr.take(draw, ORIGIN_Z))
    d = lay_out(block, pieces, doors, entry, side, yaw, origin)
    vis = draw(VISIBLE)
    built = build(d, "all" if vis == "missing" else vis, draw(BSP_ORDERS), draw(dr.BOOLEANS), draw(dr.BOOLEANS),
                  missing_visible=0 if vis == "missing" else None, bsp_depth=draw(BSP_DEPTHS))

    # the mover: in piece 0 (or the feature piece), heading for the feature
    p0 = pieces[0]
    free = max((d0.width - 2 * r) / 2, 0.0)
    lateral = draw(LATERAL) * free
    heading = 0.0
    start_piece = 0
    statics = []
    airborne = policy == "fall"
    state = int(PhysicsState.Gravity) | (int(PhysicsState.EdgeSlide) if draw(QUARTERS) > 0 else 0)
    before = dr.take(draw, BEFORE) * r
    past = dr.take(draw, PAST) * r
    target_x = p0.length / 2  # the exit portal of piece 0
    if policy == "wall":
        # beside the door: the jamb, a radius or less from the door's edge
        side_sign = 1 if draw(dr.BOOLEANS) else -1
        lateral = side_sign * to_f32(d0.width / 2 + r * draw(st.sampled_from((0.0, 0.5, 1.0, 0.99))))
        lateral = max(min(lateral, p0.width / 2 - r - 0.01), -(p0.width / 2 - r - 0.01))
    elif policy == "doorway":
        lateral = draw(st.sampled_from((1.0, -1.0, 0.999, -0.999))) * free
    elif policy == "seam":
        # along the seam: sphere centred on the shared wall, walking across the corridor's width
        target_x = p0.length / 2 - r * draw(st.sampled_from((0.0, 0.5, 0.9, -0.5)))
        heading = draw(st.sampled_from((90.0, -90.0, 80.0, 100.0)))
        before = 0.0
    elif policy in ("ledge", "pit"):
        start_piece = 1
        p1 = pieces[1]
        target_x = p1.feature_at
        lateral = draw(LATERAL) * max(p1.width / 2 - r - 0.01, 0.0)
    elif policy == "tee":
        start_piece = 1
        tee = pieces[1]
        target_x = draw(st.sampled_from((0.0, 0.1, -0.1))) * tee.length
        heading = draw(st.sampled_from((90.0, 90.0, 60.0, 0.0)))
    elif policy == "outside":
        target_x = -p0.length / 2
        heading = 180.0
    elif policy == "static":
        size = draw(STATIC_SIZES)
        statics.append(static_in(built, 0, 0x70000000, sh.box(size, size, size), to_f32(p0.length / 2 - size / 2 - r),
                                 lateral, 0.0, draw(STATIC_ANGLES)))
        target_x = p0.length / 2 - size - r
    elif policy == "straddle":
        # a static across the portal between pieces 0 and 1 (at the jamb side or in the doorway)
        size = draw(STATIC_SIZES)
        statics.append(static_in(built, 0, 0x70000000, sh.box(size, size, size), to_f32(p0.length / 2),
                                 draw(st.sampled_from((0.0, 0.5, -0.5))) * p0.width, 0.0, draw(STATIC_ANGLES)))
    heading += dr.take(draw, HEADING_JITTER) if policy not in ("seam", "tee", "wall", "doorway") else 0.0
    ps = pieces[start_piece]
    rad = math.radians(heading)
    sx = max(min(target_x - before * math.cos(rad), ps.length / 2 - r - 0.01), -ps.length / 2 + r + 0.01)
    sy = max(min(lateral - before * math.sin(rad), ps.width / 2 - r - 0.01), -ps.width / 2 + r + 0.01)
    if policy == "seam":
        sx = target_x
    floor = floor_at(ps, sx)
    if policy in ("ledge", "pit") and sx >= ps.feature_at:
        sx = to_f32(ps.feature_at - 0.01)
        floor = 0.0
    z0 = to_f32(floor + (min(dr.take(draw, AIR), max(ps.height - head - 0.05, 0.0)) if airborne else 0.0))
    length = math.hypot(target_x - sx, lateral - sy) + past
    ex, ey = sx + length * math.cos(rad), sy + length * math.sin(rad)
    ez = z0 if not airborne else to_f32(z0 - draw(st.sampled_from((0.0, 0.5, 2.0))))
    begin = dungeon_point(d, start_piece, sx, sy, z0)
    end = dungeon_point(d, start_piece, ex, ey, ez)
    steps = step_heights(geometry_steps)
    up = dr.one_of(draw, STEP_UP_SITE, *steps)
    down = dr.one_of(draw, STEP_DOWN_SITE, lambda draw: draw(sh.f32s(r, 2 * r)), *steps)
    name = f"indoor:{policy}" + ("" if state & int(PhysicsState.EdgeSlide) else ":no-edge-slide")
    return dungeon_scene(built, spheres, begin, end, d.cell_id(start_piece), up, down, state, airborne, statics, name)
