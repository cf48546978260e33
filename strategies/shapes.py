"""BSP shapes and obstacles: convex solids and polygons with valid physics BSP trees.

Every solid is convex and its polygons are listed counter-clockwise seen from outside (so the
plane normal made from the vertices points out). Its physics BSP is a chain with one internal
node per face plane: the front child is an empty leaf (a sphere wholly in front of any face of
a convex solid cannot touch it), the back child the next node, and the last back child a solid
leaf holding every polygon. Every node and leaf carries the solid's bounding sphere (centre the
vertex box's middle, radius the farthest vertex, rounded up to a float32 that still covers it),
so `sphere.intersects` never prunes a polygon it should reach. A lone polygon ("a convex polygon")
gets one node on its plane with the polygon in the back leaf.

All coordinates are exact float32s (rounded with to_f32); shapes are built in the object's
local frame with z = 0 at the object's base.
"""

from __future__ import annotations

import math
from itertools import repeat

from hypothesis import strategies as st

from acconform.flags import CullMode
from acconform.numerics import f32_next_up, to_f32, to_f32s
from acconform.scene import (BSPLeaf, BSPNode, BSPShape, CylSphereShape, PlaneRec, PolygonRec, SphereRec, newell_normal,
                             SphereShape)

from . import draws as dr
from .terrain import BLOCK


def f32s(lo: float, hi: float):
    """Exact float32s in [lo, hi] (Hypothesis draws binary32 values directly); draws.f32: the same, unwrapped."""
    return st.floats(to_f32(lo), to_f32(hi), width=32, allow_nan=False, allow_infinity=False)


_v = to_f32s  # a point's coordinates rounded to float32


def _plane(verts) -> PlaneRec:
    # Newell's normal (robust for any planar convex polygon), unit length, through vertex 0
    nx, ny, nz = newell_normal(verts)
    ln = math.sqrt(nx * nx + ny * ny + nz * nz)
    nx, ny, nz = nx / ln, ny / ln, nz / ln
    x0, y0, z0 = verts[0]
    return PlaneRec(_v((nx, ny, nz)), to_f32(-(nx * x0 + ny * y0 + nz * z0)))


MIN_RADIUS = to_f32(0.01)  # a bounding sphere's floor (a point or a degenerate polygon still gets one)


def bounding_sphere(points) -> SphereRec:
    xs, ys, zs = zip(*points)
    c = ((min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2, (min(zs) + max(zs)) / 2)
    c = _v(c)
    r = max(map(math.dist, repeat(c), points))
    rf = to_f32(r)
    if rf < r:
        rf = f32_next_up(rf)
    rf = f32_next_up(rf)  # one ulp of slack for float32 distance rounding
    return SphereRec(c, max(rf, MIN_RADIUS))


def solid(faces: list[list[tuple[float, float, float]]], sides: int = int(CullMode.Clockwise)) -> BSPShape:
    """A BSPShape for a convex solid given its faces (each CCW from outside)."""
    polys = tuple(PolygonRec(tuple(_v(p) for p in f), sides) for f in faces)
    sphere = bounding_sphere([p for poly in polys for p in poly.vertices])
    node = BSPLeaf(tuple(range(len(polys))), True, sphere)
    for poly in reversed(polys):
        node = BSPNode(_plane(poly.vertices), sphere, BSPLeaf((), False, sphere), node)
    return BSPShape(polys, node, sphere)


def box(sx: float, sy: float, sz: float, z0: float = 0.0) -> BSPShape:
    """An axis-aligned box [-sx/2, sx/2] x [-sy/2, sy/2] x [z0, z0 + sz]."""
    x0, x1, y0, y1, z1 = -sx / 2, sx / 2, -sy / 2, sy / 2, z0 + sz
    return solid(_box_faces(x0, x1, y0, y1, z0, z1))


def _box_faces(x0, x1, y0, y1, z0, z1):
    return [
        [(x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)],  # top (+z)
        [(x0, y0, z0), (x0, y1, z0), (x1, y1, z0), (x1, y0, z0)],  # bottom (-z)
        [(x1, y0, z0), (x1, y1, z0), (x1, y1, z1), (x1, y0, z1)],  # +x
        [(x0, y0, z0), (x0, y0, z1), (x0, y1, z1), (x0, y1, z0)],  # -x
        [(x0, y1, z0), (x0, y1, z1), (x1, y1, z1), (x1, y1, z0)],  # +y
        [(x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1)],  # -y
    ]


def wedge(sx: float, sy: float, sz: float) -> BSPShape:
    """A ramp: rises along +x from height 0 at x = -sx/2 to sz at x = +sx/2."""
    x0, x1, y0, y1 = -sx / 2, sx / 2, -sy / 2, sy / 2
    faces = [
        [(x0, y0, 0.0), (x1, y0, sz), (x1, y1, sz), (x0, y1, 0.0)],  # slope
        [(x0, y0, 0.0), (x0, y1, 0.0), (x1, y1, 0.0), (x1, y0, 0.0)],  # bottom
        [(x1, y0, 0.0), (x1, y1, 0.0), (x1, y1, sz), (x1, y0, sz)],  # back wall +x
        [(x0, y1, 0.0), (x1, y1, sz), (x1, y1, 0.0)],  # +y side
        [(x0, y0, 0.0), (x1, y0, 0.0), (x1, y0, sz)],  # -y side
    ]
    return solid(faces)


def prism(n: int, radius: float, height: float, phase: float = 0.0) -> BSPShape:
    """A regular n-gon prism (thin posts with small radius)."""
    ring = [(radius * math.cos(phase + 2 * math.pi * k / n), radius * math.sin(phase + 2 * math.pi * k / n)) for k in range(n)]
    ring = [(to_f32(x), to_f32(y)) for x, y in ring]
    faces = [[(x, y, height) for x, y in ring], [(x, y, 0.0) for x, y in reversed(ring)]]
    for k in range(n):
        (ax, ay), (bx, by) = ring[k], ring[(k + 1) % n]
        faces.append([(ax, ay, 0.0), (bx, by, 0.0), (bx, by, height), (ax, ay, height)])
    return solid(faces)


def split_floor(sx: float, sy: float, h_pos: float, h_neg: float) -> BSPShape:
    """Two floor halves (two-sided) meeting at x = 0, at heights h_pos (x >= 0) and h_neg (x <= 0),
    under one BSP node whose splitting plane is x = 0: a sphere on the seam reaches a walkable
    polygon on each side, and which one find_walkable keeps depends on the order it visits them."""
    x0, x1, y0, y1 = to_f32(-sx / 2), to_f32(sx / 2), to_f32(-sy / 2), to_f32(sy / 2)
    pos = PolygonRec(tuple(_v(p) for p in [(0.0, y0, h_pos), (x1, y0, h_pos), (x1, y1, h_pos), (0.0, y1, h_pos)]),
                     int(CullMode.None_))
    neg = PolygonRec(tuple(_v(p) for p in [(x0, y0, h_neg), (0.0, y0, h_neg), (0.0, y1, h_neg), (x0, y1, h_neg)]),
                     int(CullMode.None_))
    sphere = bounding_sphere(pos.vertices + neg.vertices)
    root = BSPNode(PlaneRec((1.0, 0.0, 0.0), 0.0), sphere,
                   BSPLeaf((0,), False, bounding_sphere(pos.vertices)), BSPLeaf((1,), False, bounding_sphere(neg.vertices)))
    return BSPShape((pos, neg), root, sphere)


def polygon_shape(verts) -> BSPShape:
    """One convex polygon (two-sided), its BSP a single node on its plane."""
    poly = PolygonRec(tuple(_v(p) for p in verts), int(CullMode.None_))
    sphere = bounding_sphere(poly.vertices)
    root = BSPNode(_plane(poly.vertices), sphere, BSPLeaf((), False, sphere), BSPLeaf((0,), False, sphere))
    return BSPShape((poly,), root, sphere)


# ---------------------------------------------------------------- strategies
#
# Module constants throughout (strategies/draws.py says why); the composites take no arguments,
# so each is built once, and every object still draws inside a span of its own.

STEP_SIZES = tuple(to_f32(h) for h in (0.1, 0.2, 0.25, 0.3, 0.4, 0.5, 0.6, 1.0))
STEPS = st.sampled_from(STEP_SIZES)

VERTEX_COUNTS = dr.ints(3, 8)
# a polygon's vertex angles: n distinct multiples of 15 degrees, one list strategy per n
ANGLES = {n: dr.eager(st.lists(st.sampled_from(range(0, 360, 15)), min_size=n, max_size=n, unique=True))
          for n in range(3, 9)}
SEMI_AXES = dr.f32(0.5, 6.0)
TILTS = st.sampled_from((0, 0, 10, 30, 45, 50, 60, 90))
LIFTS = dr.f32(0.0, 3.0)


@st.composite
def convex_polygons(draw):
    """A convex polygon: points on an ellipse at increasing angles, tilted, CCW from +z before tilting."""
    n = draw(VERTEX_COUNTS)
    angles = sorted(draw(ANGLES[n]))
    rx, ry = draw(SEMI_AXES), draw(SEMI_AXES)
    tilt = math.radians(draw(TILTS))
    z = draw(LIFTS)
    pts = []
    for a in angles:
        x, y = rx * math.cos(math.radians(a)), ry * math.sin(math.radians(a))
        pts.append((x, y * math.cos(tilt), z + y * math.sin(tilt)))
    return polygon_shape(pts)


CONVEX_POLYGONS = dr.eager(convex_polygons())
SHAPE_KINDS = st.sampled_from(("wall", "floor", "ramp", "ledge", "platform", "post", "box", "polygon", "step"))
WALL_THICKNESS, WALL_LENGTHS, WALL_HEIGHTS = dr.f32(0.1, 1.0), dr.f32(2.0, 12.0), dr.f32(1.0, 6.0)
TOP_HEIGHTS, TOP_SIDES, FLOOR_HEIGHTS = dr.f32(0.05, 3.0), dr.f32(1.0, 10.0), dr.f32(0.02, 0.3)
RAMP_LENGTHS, RAMP_WIDTHS = dr.f32(2.0, 12.0), dr.f32(1.0, 6.0)
RAMP_ANGLES = st.sampled_from((20.0, 45.0, 48.0, 48.4, 48.5, 49.0, 60.0))
POST_SIDES, POST_RADII, POST_HEIGHTS = dr.ints(3, 8), dr.f32(0.05, 0.4), dr.f32(1.0, 5.0)
BOX_SIDES = dr.f32(0.5, 4.0)


@st.composite
def bsp_shapes(draw):
    """(label, shape, top height) for one BSP object (label says what it is)."""
    kind = draw(SHAPE_KINDS)
    if kind == "wall":
        shape = box(draw(WALL_THICKNESS), draw(WALL_LENGTHS), draw(WALL_HEIGHTS))
    elif kind in ("floor", "platform", "ledge", "step"):
        height = draw(STEPS) if kind == "step" else draw(TOP_HEIGHTS)
        sx, sy = draw(TOP_SIDES), draw(TOP_SIDES)
        shape = box(sx, sy, height if kind != "floor" else draw(FLOOR_HEIGHTS))
    elif kind == "ramp":
        length = draw(RAMP_LENGTHS)
        angle = draw(RAMP_ANGLES)
        shape = wedge(length, draw(RAMP_WIDTHS), to_f32(length * math.tan(math.radians(angle))))
    elif kind == "post":
        shape = prism(draw(POST_SIDES), draw(POST_RADII), draw(POST_HEIGHTS))
    elif kind == "box":
        shape = box(draw(BOX_SIDES), draw(BOX_SIDES), draw(BOX_SIDES))
    else:
        shape = draw(CONVEX_POLYGONS)
    zs = [p[2] for poly in shape.polygons for p in poly.vertices]
    return kind, shape, max(zs)


BSP_SHAPES = dr.eager(bsp_shapes())


def spheres_shapes():
    return st.builds(lambda c, r: SphereShape(SphereRec((0.0, 0.0, c), r)), f32s(0.0, 2.0), f32s(0.1, 3.0))


def cylsphere_shapes():
    return st.builds(lambda r, h: CylSphereShape((0.0, 0.0, 0.0), r, h), f32s(0.1, 2.0), f32s(0.2, 5.0))


OBSTACLE_SHAPES = dr.OneOf(dr.eager(spheres_shapes()), dr.eager(cylsphere_shapes()))


def leaf_root(shape: BSPShape) -> BSPShape:
    """The same polygons under a tree that is one solid leaf (ACE makes its root a childless node)."""
    return BSPShape(shape.polygons, BSPLeaf(tuple(range(len(shape.polygons))), True, shape.sphere), shape.sphere)


def one_leaf_above_ground(shape: BSPShape) -> BSPShape:
    """The same polygons in one solid leaf in front of a root split by the plane z = 0 (an empty
    leaf behind it). No splitting plane lies on a face, so a sphere exactly touching a face
    reaches the polygon test (a face's own node sends it to the empty side at dist == reach)."""
    leaf = BSPLeaf(tuple(range(len(shape.polygons))), True, shape.sphere)
    root = BSPNode(PlaneRec((0.0, 0.0, 1.0), 0.0), shape.sphere, leaf, BSPLeaf((), False, shape.sphere))
    return BSPShape(shape.polygons, root, shape.sphere)


def zero_radius_empty_leaves(shape: BSPShape) -> BSPShape:
    """The same tree with every empty leaf's bounding sphere shrunk to radius 0 (at the origin)."""
    def walk(node):
        if isinstance(node, BSPLeaf):
            return node if node.polygons else BSPLeaf((), node.solid, SphereRec((0.0, 0.0, 0.0), 0.0))
        return BSPNode(node.plane, node.sphere, walk(node.front), walk(node.back))
    return BSPShape(shape.polygons, walk(shape.root), shape.sphere)


def rotate(q, v):
    """v turned by the quaternion q = (w, x, y, z) (normalised first), in doubles."""
    w, x, y, z = q
    n = math.sqrt(w * w + x * x + y * y + z * z) or 1.0
    w, x, y, z = w / n, x / n, y / n, z / n
    vx, vy, vz = v
    # v + 2w(q x v) + 2 q x (q x v)
    cx, cy, cz = y * vz - z * vy, z * vx - x * vz, x * vy - y * vx
    cx2, cy2, cz2 = y * cz - z * cy, z * cx - x * cz, x * cy - y * cx
    return (vx + 2 * (w * cx + cx2), vy + 2 * (w * cy + cy2), vz + 2 * (w * cz + cz2))


def object_reach(obj) -> tuple[tuple[float, float, float], float]:
    """A sphere (centre in the object's landblock, radius) holding all of a static object: what the
    strategies use to pick the landblocks a scene lists. Only the drawing uses it; where ACE
    registers the object is ACE's own placement code, run on each side."""
    shape = obj.shape
    if obj.setup is not None:
        c, r = (0.0, 0.0, 0.0), setup_reach(obj.setup)
    elif isinstance(shape, SphereShape):
        c, r = shape.sphere.center, shape.sphere.radius
    elif isinstance(shape, CylSphereShape):
        lx, ly, lz = shape.low_point
        c, r = (lx, ly, lz + shape.height / 2), shape.radius + shape.height / 2
    else:  # the shape's bounding sphere, which the strategies draw to cover every vertex
        c, r = shape.sphere.center, shape.sphere.radius
    s = obj.scale
    rc = rotate(obj.position.frame.orientation, (c[0] * s, c[1] * s, c[2] * s))
    o = obj.position.frame.origin
    return (o[0] + rc[0], o[1] + rc[1], o[2] + rc[2]), r * s


def setup_reach(setup) -> float:
    """The radius of a sphere about a Setup's origin holding its parts (each part's bounding sphere
    moved by its frame, grown by its largest scale component), its spheres and its cylspheres."""
    reach = 0.0
    for p in setup.parts:
        c, r = p.shape.sphere.center, p.shape.sphere.radius
        k = max(p.scale) if p.scale is not None else 1.0
        reach = max(reach, math.dist((0.0, 0.0, 0.0), p.frame.origin) + (math.dist((0.0, 0.0, 0.0), c) + r) * k)
    for s in setup.spheres:
        reach = max(reach, math.dist((0.0, 0.0, 0.0), s.center) + s.radius)
    for cyl in setup.cylspheres:
        reach = max(reach, math.dist((0.0, 0.0, 0.0), cyl.low_point) + cyl.radius + cyl.height)
    return reach


# metres beyond the spheres' reach: float rounding, a step-up's lift, a slide's last epsilon. The
# mover never ends farther from its path than its spheres reach (slides and steps only shorten
# the move), and cells are gathered from the spheres (add_all_outside_cells), so a metre is ample.
REACH_SLACK = 1.0


def object_blocks(obj) -> set[tuple[int, int]]:
    """The landblocks (x, y) a scene lists for a static object: every one its reach sphere (plus
    REACH_SLACK) touches, off the map's edge left out."""
    (cx, cy, _), rad = object_reach(obj)
    gx = (obj.position.cell >> 24) * BLOCK + cx
    gy = ((obj.position.cell >> 16) & 0xFF) * BLOCK + cy
    m = rad + REACH_SLACK
    return {(ix, iy) for ix in range(int((gx - m) // BLOCK), int((gx + m) // BLOCK) + 1)
            for iy in range(int((gy - m) // BLOCK), int((gy + m) // BLOCK) + 1) if 0 <= ix <= 0xFE and 0 <= iy <= 0xFE}
