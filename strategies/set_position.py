"""Placements: a share of drawn scenes of every kind has its mover placed by ACE's PhysicsObj.SetPosition.

`with_placement(draw, scene)` gives the scene a ``mover.placement`` one time in four, indoors one
time in two (in ACE's server mode three times in four, else client mode: dr.ENGINE_MODES). The begin
position is then biased toward where placement goes wrong:

- "as drawn": the begin position as the scene drew it (the cell holds the point);
- "at end": the end position (a wall, a ledge, an object the path ran into), so the placement
  overlaps geometry and FindValidPosition pushes the mover out -- by less or more than 0.05 in x
  or y, toward + or - (CheckPositionInternal's comparison has no Math.Abs);
- "backed off": the end position backed off toward the begin a little (a few centimetres to a third
  of a metre): overlaps small and large;
- "other cell": the point kept, the cell id another cell of its landblock: indoors another
  EnvCell (find_visible_child_cell finds the point's cell among its visible cells, or not; a
  SeenOutside cell falls out to the landblock), outdoors another land cell (AdjustToOutside
  fixes it);
- "nowhere": the point moved well away from its cell (into no EnvCell, or off the dungeon), half the
  time under a SeenOutside cell's id when the dungeon has one (AdjustPosition's adjust_to_outside);
- "bad id": a cell id outside AdjustPosition's ranges (0, 0x41..0xFF, 0xFFFE);
- "against a face": the first sphere sunk into a face by 0 to 0.35 m (around 0.05 often): an
  EnvCell's physics polygon (the begin in that cell), a BSP object's polygon or a sphere's or
  cylsphere's side (the begin in the land cell, or the static's EnvCell, holding it). Only an
  EnvCell's walls push a placement out (BSPTree.placement_insert; ObjCell.FindObjCollisions passes
  every object by in the initial placement): three times in four the face is a wall whose push
  goes toward -x or -y and that placement_insert does push (`_pushed_toward_minus`), so that
  CheckPositionInternal keeps a long push (no Math.Abs). A wall is met at the sphere's height.
  Into an object's face the placement collides where it stands: FindPlacementPos' spiral search
  with Slide, no valid position without it;
- "inside a solid": a static added around the first sphere's centre, in the begin's cell, of the
  scene's kind (a box of 1 to 20 m a side; among obstacles a cylsphere that wide; none where the
  scene has no object): narrower than the spiral search's reach (4 m each way) it finds a free
  spot at the side, wider it finds none.

Flags: Slide or not (the 0.05 check runs only without it; against an EnvCell's wall mostly not,
against an object's face or inside a solid mostly), sometimes DontCreateCells and the flags ACE ignores here (Placement,
Teleport, SendPositionEvent); get_cell true or false. One time in four the mover reports collisions
(PhysicsState.ReportCollisions): where no valid position is found, handle_all_collisions then
reports the environment collision (the mover's WeenieObj is WeenieObject.DummyObject, not null)
and SetPositionInternal answers Collided.
`placement_table(scenes)` counts the draws per 1,000 scenes (benchmarks/bench_strategies.py).
"""

from __future__ import annotations

from collections import Counter
from dataclasses import replace
from typing import NamedTuple

from hypothesis import strategies as st

from acconform.flags import PhysicsState, SetPositionFlags
from acconform.numerics import to_f32
from acconform.scene import (ENV_CELL_FIRST, IDENTITY, BSPNode, BSPShape, CylSphereShape, Frame, Placement, Position,
                             Scene, SphereShape, StaticObject, newell_normal)

from . import draws as dr
from .dungeon import plane_distance
from .objects import BSP_STATE
from .shapes import box, object_blocks, rotate
from .terrain import BLOCK, cell_of, split_global

PLACE = st.sampled_from((False, False, False, True))
# indoors, where placement inserts push a sphere out of the walls, one time in two
PLACE_INDOORS = st.sampled_from((False, True))
WHERE = st.sampled_from(("as drawn", "at end", "at end", "backed off", "backed off", "other cell", "other cell",
                         "nowhere", "nowhere", "bad id", "bad id") + ("against a face",) * 3 + ("inside a solid",) * 3)
# indoors the faces more often: only an EnvCell's walls push a placement (ObjCell.FindObjCollisions
# passes every object by in the initial placement)
WHERE_INDOORS = st.sampled_from(("as drawn", "at end", "backed off", "other cell", "other cell", "nowhere", "nowhere",
                                 "bad id", "bad id") + ("against a face",) * 8 + ("inside a solid",) * 3)
NUDGES = dr.OneOf(dr.f32(0.0, 0.06), dr.f32(0.0, 0.35))
SLIDE = st.sampled_from((False, True))
# against an EnvCell's wall the push is what CheckPositionInternal judges without Slide; against an
# object's face or inside a solid, Slide sends the placement on the spiral search
SLIDE_RARELY = st.sampled_from((False, False, False, True))
SLIDE_MOSTLY = st.sampled_from((False, True, True, True))
GET_CELL = st.sampled_from((False, True))

EXTRA_FLAGS = st.sampled_from((0, 0, int(SetPositionFlags.Placement), int(SetPositionFlags.Teleport),
                               int(SetPositionFlags.DontCreateCells),
                               int(SetPositionFlags.Placement | SetPositionFlags.SendPositionEvent)))
BAD_IDS = st.sampled_from((0x0000, 0x0041, 0x00FF, 0xFFFE))
AWAY = st.sampled_from(((0.0, 0.0, 30.0), (40.0, 0.0, 0.0), (0.0, -40.0, 0.0), (0.0, 0.0, -8.0)))
OTHER = dr.ints(0, 1 << 16)
# how deep the first sphere sinks into a face: around the 0.05 CheckPositionInternal compares a push
# with, a hair, up to a third of a metre
DEPTHS = dr.OneOf(st.sampled_from((0.05, 0.1, 0.3)), dr.f32(0.03, 0.07), dr.f32(0.05, 0.35), dr.f32(0.0, 0.35))
TOWARD_MINUS = st.sampled_from((False, True, True, True))
# where on a face: its centroid moved toward one of its vertices by this share of the way
BLENDS = dr.OneOf(st.sampled_from((0.0, 0.25, 0.5)), dr.f32(0.0, 0.95))
WALL_NZ = 0.1  # a face whose normal's z is smaller is a wall
ON_PLANE = 1e-3  # metres: a polygon this close to a splitting plane lies on it
# a solid's sides: inside the spiral search's 4 m reach from its middle (a free spot at its side),
# or wider than twice the reach (no free spot)
SOLID_SIDES = dr.OneOf(st.sampled_from((10.0, 9.0, 16.0)), dr.f32(9.0, 20.0), dr.f32(1.0, 9.0))
SOLID_HEIGHTS = dr.f32(0.5, 6.0)
REPORTS = st.sampled_from((False, False, False, True))


def _landblock_defined(scene: Scene, cell: int) -> bool:
    return any(lb.id >> 16 == cell >> 16 for lb in scene.landblocks)


def _to_block(origin, q, scale: float, v):
    """A point of an object's or a cell's frame in its landblock's coordinates."""
    x, y, z = rotate(q, (v[0] * scale, v[1] * scale, v[2] * scale))
    return origin[0] + x, origin[1] + y, origin[2] + z


def _unit(v):
    length = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) ** 0.5
    return None if length == 0.0 else (v[0] / length, v[1] / length, v[2] / length)


AXES = ((1.0, 0.0, 0.0), (-1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, -1.0, 0.0))


class Face(NamedTuple):
    """A face a placement can be put against."""

    cell: int | None        # the EnvCell holding it, or None outdoors (the point's land cell is taken)
    block: int              # its landblock's id (the high word)
    vertices: tuple         # in the landblock's coordinates
    normal: tuple           # unit, out of the solid
    cell_wall: bool         # an EnvCell's physics polygon: placement inserts push a sphere out of those alone
    split: bool             # its plane splits a node of its cell's physics BSP


def _splitting_planes(node) -> list:
    if isinstance(node, BSPNode):
        return [node.plane, *_splitting_planes(node.front), *_splitting_planes(node.back)]
    return []


def _on_plane(verts, plane) -> bool:
    return all(abs(plane_distance(plane, v)) < ON_PLANE for v in verts)


def _faces(scene: Scene) -> list[Face]:
    """Every EnvCell's physics polygons (they face into the cell's free space), every BSP object's
    polygons (counter-clockwise seen from outside), and a sphere's or cylsphere's sides toward +-x
    and +-y."""
    faces = []
    structs = {env.id: env.cell_structs for env in scene.environments}
    for c in scene.env_cells:
        struct = structs[c.environment][c.cell_structure]
        splits = _splitting_planes(struct.physics_bsp)
        for poly in struct.physics_polygons:
            verts = tuple(_to_block(c.frame.origin, c.frame.orientation, 1.0, v) for v in poly.vertices)
            normal = _unit(newell_normal(verts))
            if normal is not None:
                split = any(_on_plane(poly.vertices, plane) for plane in splits)
                faces.append(Face(c.id, c.id & 0xFFFF0000, verts, normal, True, split))
    for o in scene.objects:
        f, shape = o.position.frame, o.shape
        if o.setup is not None:  # a Setup of several parts: its faces are not gathered (a placement may meet it)
            continue
        cell = o.position.cell if o.position.cell & 0xFFFF >= ENV_CELL_FIRST else None
        block = o.position.cell & 0xFFFF0000
        if isinstance(shape, BSPShape):
            for poly in shape.polygons:
                verts = tuple(_to_block(f.origin, f.orientation, o.scale, v) for v in poly.vertices)
                normal = _unit(newell_normal(verts))
                if normal is not None:
                    faces.append(Face(cell, block, verts, normal, False, False))
            continue
        if isinstance(shape, SphereShape):
            centre, radius = shape.sphere.center, shape.sphere.radius * o.scale
        else:
            assert isinstance(shape, CylSphereShape)
            lx, ly, lz = shape.low_point
            centre, radius = (lx, ly, lz + shape.height / 2), shape.radius * o.scale
        cx, cy, cz = _to_block(f.origin, f.orientation, o.scale, centre)
        faces.extend(Face(cell, block, ((cx + radius * u[0], cy + radius * u[1], cz),), u, False, False) for u in AXES)
    return faces


def _pushed_toward_minus(face: Face, radius: float) -> bool:
    """An EnvCell's wall that FindValidPosition pushes a sphere out of toward -x or -y, and hardly
    toward +x or +y (CheckPositionInternal keeps such a push of any length: its comparison has no
    Math.Abs). Pushed: wide and high enough for the sphere, and its plane splits no node of the
    cell's physics BSP: ACE's BSPNode.sphere_intersects_solid_poly answers centerSolid, not true,
    for a polygon hit beyond a node whose plane the sphere straddles, so placement_insert leaves a
    sphere in such a wall where it is."""
    nx, ny, nz = face.normal
    if not face.cell_wall or face.split or abs(nz) >= WALL_NZ or not (nx < 0.1 and ny < 0.1 and min(nx, ny) < -0.5):
        return False
    verts = face.vertices
    width = max(abs((a[0] - b[0]) * ny - (a[1] - b[1]) * nx) for a in verts for b in verts)
    zs = [v[2] for v in verts]
    return min(width, max(zs) - min(zs)) >= 2 * radius


def _sphere_centre(m) -> tuple:
    """The mover's first sphere's centre, in its begin landblock's coordinates."""
    f = m.begin.frame
    return _to_block(f.origin, f.orientation, m.scale, m.spheres[0].center)


def _placed_at(scene: Scene, cell, block: int, origin, q) -> Position | None:
    """A begin at `origin` (its landblock's coordinates, maybe past its edge outdoors): in the
    EnvCell `cell`, or outdoors in the land cell holding it; None where that landblock is not listed."""
    x, y, z = origin
    if cell is not None:
        return Position(cell, Frame((to_f32(x), to_f32(y), to_f32(z)), q))
    bx, by, lx, ly = split_global((block >> 24) * BLOCK + x, ((block >> 16) & 0xFF) * BLOCK + y)
    new = cell_of(bx, by, lx, ly)
    return Position(new, Frame((lx, ly, to_f32(z)), q)) if _landblock_defined(scene, new) else None


def _against_a_face(draw, scene: Scene) -> tuple[Position, Face] | None:
    """The begin moved so that the first sphere sinks into one of the scene's faces (see the
    module), and the face; None where the scene has none, or the point's landblock is not listed."""
    m = scene.mover
    radius = m.spheres[0].radius * m.scale
    faces = _faces(scene)
    minus = [f for f in faces if _pushed_toward_minus(f, radius)]
    pool = minus if minus and draw(TOWARD_MINUS) else faces
    if not pool:
        return None
    face = pool[dr.index(draw, len(pool))]
    verts, normal = face.vertices, face.normal
    k = dr.index(draw, len(verts))
    t = dr.take(draw, BLENDS)
    centroid = tuple(sum(v[i] for v in verts) / len(verts) for i in range(3))
    point = tuple(c + t * (v - c) for c, v in zip(centroid, verts[k]))
    if abs(normal[2]) < WALL_NZ:
        # a wall is met at the height the sphere stands at, or the nearest height where the wall
        # covers the sphere (so it sinks into the wall alone, not into the floor or the ceiling)
        zs = [v[2] for v in verts]
        low, high = min(zs) + radius, max(zs) - radius
        z = _sphere_centre(m)[2]
        point = (point[0], point[1], min(max(z, low), high) if low <= high else (low + high) / 2)
    q = m.begin.frame.orientation
    out = radius - dr.take(draw, DEPTHS)
    offset = rotate(q, tuple(c * m.scale for c in m.spheres[0].center))
    origin = tuple(p + n * out - o for p, n, o in zip(point, normal, offset))
    begin = _placed_at(scene, face.cell, face.block, origin, q)
    return None if begin is None else (begin, face)


def _inside_a_solid(draw, scene: Scene) -> StaticObject | None:
    """A solid static around the first sphere's centre, in the begin's cell, of the scene's kind
    of object: a box (a stab indoors, a physics BSP outdoors) or a cylsphere among obstacles.
    None where the scene has no object (terrain draws none), the begin's cell is no EnvCell of
    the scene, or the solid would reach a landblock the scene does not list."""
    m = scene.mover
    if not scene.objects and not scene.env_cells:
        return None
    sx = dr.take(draw, SOLID_SIDES)
    sy = sx if draw(dr.BOOLEANS) else dr.take(draw, SOLID_SIDES)
    sz = draw(SOLID_HEIGHTS)
    indoors = m.begin.cell & 0xFFFF >= ENV_CELL_FIRST
    cell = m.begin.cell if indoors else None
    if indoors and cell not in {c.id for c in scene.env_cells}:
        return None
    at = _placed_at(scene, cell, m.begin.cell & 0xFFFF0000, _sphere_centre(m), IDENTITY)
    if at is None:
        return None
    ident = max((o.id for o in scene.objects), default=0x6FFFFFFF) + 1
    low = to_f32(-sz / 2)
    if indoors:  # a stab: EnvCell.init_static_objects caches HasPhysicsBSP itself
        solid = StaticObject(ident, at, box(sx, sy, sz, low))
    elif all(isinstance(o.shape, BSPShape) for o in scene.objects):
        solid = StaticObject(ident, at, box(sx, sy, sz, low), BSP_STATE)
    else:
        solid = StaticObject(ident, at, CylSphereShape((0.0, 0.0, low), to_f32(sx / 2), sz))
    if not indoors and not object_blocks(solid) <= {(lb.id >> 24, (lb.id >> 16) & 0xFF) for lb in scene.landblocks}:
        return None
    return solid


def with_placement(draw, scene: Scene) -> Scene:
    """The scene, or the scene with its mover placed by ACE (see the module)."""
    if not draw(PLACE_INDOORS if scene.env_cells else PLACE):
        return scene
    m = scene.mover
    where = draw(WHERE_INDOORS if scene.env_cells else WHERE)
    begin = m.begin
    objects = scene.objects
    slides = SLIDE
    block = begin.cell & 0xFFFF0000
    if where == "at end" and _landblock_defined(scene, m.end.cell):
        begin = Position(m.end.cell, Frame(m.end.frame.origin, begin.frame.orientation))
    elif where == "backed off" and _landblock_defined(scene, m.end.cell):
        dx, dy = (b - e for b, e in zip(begin.frame.origin[:2], m.end.frame.origin[:2]))
        length = (dx * dx + dy * dy) ** 0.5
        x, y, z = m.end.frame.origin
        if length > 0:
            step = dr.take(draw, NUDGES)
            x, y = to_f32(x + dx / length * step), to_f32(y + dy / length * step)
        begin = Position(m.end.cell, Frame((x, y, z), begin.frame.orientation))
    elif where == "other cell":
        if scene.env_cells:
            cells = [c.id for c in scene.env_cells if c.id >> 16 == begin.cell >> 16]
            cell = cells[draw(OTHER) % len(cells)] if cells else begin.cell
        else:
            cell = block | (1 + draw(OTHER) % 64)
        begin = Position(cell, begin.frame)
    elif where == "nowhere":
        ax, ay, az = draw(AWAY)
        x, y, z = begin.frame.origin
        seen_outside = [c.id for c in scene.env_cells if c.seen_outside and c.id >> 16 == begin.cell >> 16]
        cell = seen_outside[draw(OTHER) % len(seen_outside)] if seen_outside and draw(dr.BOOLEANS) else begin.cell
        begin = Position(cell, Frame((to_f32(x + ax), to_f32(y + ay), to_f32(z + az)), begin.frame.orientation))
    elif where == "bad id":
        begin = Position(block | draw(BAD_IDS), begin.frame)
    elif where == "against a face":
        against = _against_a_face(draw, scene)
        if against is not None:
            begin, face = against
            slides = SLIDE_RARELY if face.cell_wall else SLIDE_MOSTLY
    elif where == "inside a solid":
        solid = _inside_a_solid(draw, scene)
        if solid is not None:
            objects = scene.objects + (solid,)
            slides = SLIDE_MOSTLY
    if draw(dr.PLACEMENT_VIAS) == "enter_world":
        placement = Placement(0, draw(GET_CELL), "enter_world")
    else:
        flags = draw(EXTRA_FLAGS) | (int(SetPositionFlags.Slide) if draw(slides) else 0)
        placement = Placement(flags, draw(GET_CELL))
    state = m.state | (int(PhysicsState.ReportCollisions) if draw(REPORTS) else 0)
    return replace(scene, engine_mode=draw(dr.ENGINE_MODES), objects=objects,
                   mover=replace(m, begin=begin, placement=placement, state=state))


def placement_table(scenes) -> dict[str, float]:
    """Per 1,000 scenes: those with a placement, by Slide, get_cell, ReportCollisions, and an indoor or
    outdoor begin cell id."""
    scenes = list(scenes)
    counts: Counter = Counter()
    for s in scenes:
        p = s.mover.placement
        if p is None:
            continue
        counts["placed"] += 1
        if p.via == "enter_world":
            counts["placed, enter_world"] += 1
        else:
            counts["placed, Slide" if p.flags & SetPositionFlags.Slide else "placed, no Slide"] += 1
        counts["placed, get_cell" if p.get_cell else "placed, cell as given"] += 1
        if s.mover.state & PhysicsState.ReportCollisions:
            counts["placed, ReportCollisions"] += 1
        low = s.mover.begin.cell & 0xFFFF
        counts["placed, EnvCell id" if low >= ENV_CELL_FIRST and low != 0xFFFE else
               "placed, land cell id" if 1 <= low <= 64 else "placed, id out of AdjustPosition's ranges"] += 1
    n = max(len(scenes), 1)
    return {k: 1000.0 * v / n for k, v in sorted(counts.items())}
