"""BSP object policies: scenes built around one behaviour a static object makes possible.

Each policy places BSP objects and the mover together, so the mover meets the object the way
the branch it aims at needs (the scatter policy in scenes.py places objects along a free path):

- ``ledge``: the mover stands on a platform's top near one of its edges (contact plane = the top,
  OnWalkable) and walks off it at an angle to the edge, EdgeSlide on or off; sometimes a second
  platform shares the edge (same height, a little lower or higher), so the path crosses a
  polygon edge between two walkable tops. Reaches PrecipiceSlide and the back-probe.
- ``stairs``: the mover walks at a stair (1-3 steps) whose rise is drawn around its step-up
  height (0.5x .. 2x, dense around 1.5x, where ACE's reach ends: it climbs ~0.6 m with step-up
  0.4 and radius 0.48). Reaches StepUp ok/fail and the neg-poly step-up.
- ``wall``: a wall approached head-on to grazing (89.5 degrees), or the inside corner of two walls;
  sometimes airborne (SetCollide). Reaches slides, the collide paths, AdjustOffset's crease.
- ``slope``: a ramp whose slope's normal.z is exactly FloorZ or LandingZ, or one ulp either side
  (strategies/boundaries.py solves its rise); the mover walks up onto it from its foot, stands on
  it (its contact plane the slope's) walking up, down or across, or lands on it from above.
  Reaches the walkable and landing tests at exactly their thresholds.
- ``seam``: two floor halves under one BSP node split between them (shapes.split_floor), level or
  a little apart in height; the mover stands on the seam, within reach of both, and walks across
  it, along it or aslant, or lands on it. find_walkable then finds a walkable polygon on each
  side of the split, and the order it visits them decides which one it keeps.
- ``straddle``: one static across a cell border, a landblock border or a landblock corner next to
  the mover (a BSP box, a sphere or a cylsphere, small or large, often turned; now and then a
  BSP tree whose root is a leaf or whose empty leaves have radius-0 spheres), owned by the cell
  on either side, and the mover walking into it: so it comes from the object's own cell or
  landblock or from the neighbour. Reaches ACE's placement (find_bbox_cell_list's own-landblock
  skip, find_cell_list for cylspheres) where it decides what the mover meets.

BSP objects get ``Static|HasPhysicsBSP`` (what ACE's makeObject leaves via CacheHasPhysicsBSP),
now and then with Ethereal (and IgnoreCollisions), or ``Static`` alone (walked through).

What a policy draws from is a module constant (strategies/draws.py says why); a one_of with a
branch that depends on the mover or the ledge (a ledge r or 2r high, a step-down around the
drop) is drawn with draws.one_of, its dependent branch built only when it is chosen.
"""

from __future__ import annotations

import math
from dataclasses import replace

from hypothesis import strategies as st

from acconform.flags import PhysicsState, TransientState
from acconform.numerics import to_f32
from acconform.scene import CylSphereShape, SphereRec, SphereShape

from . import boundaries as bd
from . import draws as dr
from . import shapes as sh

BSP_STATE = int(PhysicsState.Static | PhysicsState.HasPhysicsBSP)
BSP_STATES = st.sampled_from(
    (BSP_STATE,) * 12
    + (int(PhysicsState.Static),  # no physics BSP flag: ACE passes through
       BSP_STATE | int(PhysicsState.Ethereal),  # a static ethereal object still blocks
       BSP_STATE | int(PhysicsState.Ethereal | PhysicsState.IgnoreCollisions)))  # ignored entirely

EPS = to_f32(0.0002)  # PhysicsGlobals.EPSILON
# how far above a plane the mover's sphere starts: exactly on it, EPSILON either side, an ulp
PLANE_DZ = dr.OneOf(st.just(0.0), st.just(0.0), st.sampled_from((EPS, -EPS, EPS / 2, -EPS / 2, 2 * EPS, 1e-6, -1e-6)))

EDGE_ANGLES = dr.OneOf(st.sampled_from((0.0, 0.0, 15.0, -15.0, 30.0, -30.0, 45.0, -45.0, 60.0, -60.0, 80.0, -80.0,
                                        89.0, -89.0, 90.0)), dr.floats(-89.9, 89.9))
WALL_ANGLES = dr.OneOf(st.sampled_from((0.0, 20.0, 45.0, 70.0, 80.0, 85.0, 88.0, 89.0, 89.5)), dr.floats(0.0, 89.5))
YAWS = dr.OneOf(st.sampled_from((0.0, 0.0, 90.0, 30.0, 45.0, 180.0)), dr.floats(0.0, 359.0))
LIP_FACTORS = dr.OneOf(st.sampled_from((0.5, 0.9, 1.0, 1.001, 1.25, 1.4, 1.5, 1.6, 2.0)), dr.floats(1.2, 1.8))
# the mover's velocity: at rest first (shrinking goes there); now and then falling (keeps contact),
# rising (leaves the contact plane: get_object_info's leaving_contact) or anything. Drawn by
# sampled_from, whose generation is close to uniform over its entries (one_of's is not).
VELOCITY_KINDS = st.sampled_from(("rest",) * 16 + ("falling", "rising", "any"))
FALLING = st.sampled_from((-1.0, -10.0))
RISING = st.sampled_from((0.5, 4.0, to_f32(1e-3)))
ANY_VELOCITY = dr.eager(st.tuples(sh.f32s(-5.0, 5.0), sh.f32s(-5.0, 5.0), sh.f32s(-5.0, 5.0)))


@st.composite
def velocities(draw):
    how = draw(VELOCITY_KINDS)
    if how == "rest":
        return (0.0, 0.0, 0.0)
    if how == "falling":
        return (0.0, 0.0, draw(FALLING))
    if how == "rising":
        return (0.0, 0.0, draw(RISING))
    return draw(ANY_VELOCITY)


VELOCITIES = dr.eager(velocities())
STEP_UPS = dr.OneOf(st.sampled_from((0.4, 0.4, 0.4, 0.25, 0.3, 0.5, 0.6, 1.0)), dr.f32(0.1, 1.2))


def radius_to_diameter(r: float):
    """A one_of branch (draws.one_of): a float32 in [r, 2r], its strategy built only when chosen."""
    return lambda draw: draw(sh.f32s(r, 2 * r))


def _rot(theta_deg: float, x: float, y: float) -> tuple[float, float]:
    t = math.radians(theta_deg)
    return x * math.cos(t) - y * math.sin(t), x * math.sin(t) + y * math.cos(t)


class Plan:
    """What a policy decided: objects (shape, global x, y, yaw, state, top), and the mover."""

    def __init__(self):
        self.objects: list[tuple] = []  # (shape, gx, gy, yaw_deg, state)
        self.begin = (0.0, 0.0)  # global x, y
        self.heading = 0.0
        self.length = 0.0
        self.stand_on: float | None = None  # height of a platform top the mover stands on, over the ground
        self.airborne = 0.0
        self.edge_slide = True
        self.step_up = None
        self.step_down = None
        self.label = ""
        self.steps: list[float] = []
        self.velocity = None  # None: drawn from VELOCITIES
        self.plane_dz = None  # the start's height over its contact plane; None: drawn from PLANE_DZ
        self.stand_normal = None  # the contact plane's global normal where the mover stands; None: (0, 0, 1)
        self.stand_lift = 0.0  # the origin's height over the contact plane beneath it (a sphere on a slope)
        self.moved_begin = None  # global x, y the policy moved the mover's start to (None: where it was drawn)
        self.spheres = None  # the mover's spheres, when the policy sets them (None: as drawn)


# what a ledge scene is for (the first is the plainest, where shrinking goes):
# - walk_off: walk off the top at an angle to the edge, any step-down, EdgeSlide on or off;
# - back_probe: the walkable polygon is lost before EdgeSlide (the step's sphere centre is past the
#   edge and the step-down cannot reach the ground), so EdgeSlide's back-probe steps down from the
#   current centre, finds the top again and precipice-slides (edge_slide:back_probe_precipice_slide):
#   EdgeSlide on, at rest, step-down short of the drop, the path crossing the edge within two steps;
# - shared_edge: a second platform shares the edge (same height, a little lower or higher);
# - drop: step-down a little more than the drop (drop in (2/3, 1] of it), which a two-sphere mover
#   takes as two half step-downs (transitional_insert:step_down_halves).
LEDGE_VARIANTS = st.sampled_from(("walk_off", "back_probe", "back_probe", "shared_edge", "drop"))
PROBE_ANGLES = dr.OneOf(st.sampled_from((0.0, 15.0, -15.0, 30.0, -30.0, 45.0, -45.0)), dr.floats(-50.0, 50.0))
LEDGE_HEIGHTS = dr.OneOf(sh.STEPS, dr.f32(0.05, 3.0))
PROBE_HEIGHTS = dr.f32(0.5, 3.0)
DROP_FACTORS = dr.OneOf(st.sampled_from((1.25, 1.5, 2.0)), dr.f32(1.05, 3.0))
TOP_SIDES = dr.f32(1.0, 10.0)
ONE_IN_FOUR = st.sampled_from((False, False, False, True))
# a Setup's DefaultScript (scene/8; 0 none) now and then: InitDefaults plays it, making the object's ScriptManager
# (and, a static, setting HasDefaultScript), one Setup in two; PhysicsScript ids are portal DAT 0x33xxxxxx, which ACE never reads
DEFAULT_SCRIPTS = st.sampled_from((0, 0, 0, 0x33000001, 0x33000002, 0x3300FFFF))
EDGES = st.sampled_from(((1, 0), (-1, 0), (0, 1), (0, -1)))
ALONG_EDGE = dr.OneOf(dr.floats(-0.9, 0.9), st.sampled_from((0.0, 1.0, -1.0, 0.99, -0.99)))
PROBE_INSIDE = dr.OneOf(st.sampled_from((0.5, 0.9, 1.2)), dr.floats(0.4, 1.5))
INSIDE = dr.OneOf(st.sampled_from((0.0, 0.0, 0.5, 1.0, 0.01)), dr.floats(0.0, 2.0))
SECOND_WIDTHS = dr.f32(0.5, 6.0)
PROBE_STEPS = dr.OneOf(st.sampled_from((1.0, 1.5, 2.0)), dr.f32(0.8, 2.5))
ON_TOP = st.sampled_from((0.0, 0.0, EPS / 2))
PROBE_DOWN = dr.OneOf(st.sampled_from((0.5, 0.25, 0.9)), dr.f32(0.05, 0.95))
WALK_STEPS = dr.OneOf(st.sampled_from((0.2, 0.5, 1.0, 1.5, 2.0, 3.0)), dr.f32(0.05, 6.0))
EDGE_SLIDE = st.sampled_from((True, True, False, True))
DROP_DOWN = dr.OneOf(st.sampled_from((1.2, 1.01, 1.45)), dr.f32(1.0, 1.49))
COMMON_DOWN = st.sampled_from((to_f32(0.4), to_f32(1.0), to_f32(2.0)))
# one_ofs with a branch that depends on the mover or the ledge (draws.one_of)
LEDGE_HEIGHT_SITE, PROBE_HEIGHT_SITE = dr.Site("ledge height"), dr.Site("back-probe ledge height")
LEDGE_DOWN_SITE = dr.Site("ledge step-down")


@st.composite
def ledge(draw, gx: float, gy: float, r: float) -> Plan:
    p = Plan()
    variant = draw(LEDGE_VARIANTS)
    sx, sy = draw(TOP_SIDES), draw(TOP_SIDES)
    if variant == "walk_off" or variant == "shared_edge":
        h = dr.one_of(draw, LEDGE_HEIGHT_SITE, LEDGE_HEIGHTS, lambda d: d(st.sampled_from((to_f32(r), to_f32(2 * r)))))
    elif variant == "back_probe":
        h = dr.one_of(draw, PROBE_HEIGHT_SITE, lambda d: d(st.sampled_from((to_f32(1.0), to_f32(0.5), to_f32(2 * r)))),
                      PROBE_HEIGHTS)
    else:  # drop: above 2r, so a two-sphere mover halves its step-down
        h = to_f32(2 * r * dr.take(draw, DROP_FACTORS))
    yaw = dr.take(draw, YAWS)
    if variant != "back_probe" and draw(ONE_IN_FOUR):
        # the top as one two-sided polygon, wound either way (a crossed edge's normal may point in)
        quad = [(-sx / 2, -sy / 2, h), (sx / 2, -sy / 2, h), (sx / 2, sy / 2, h), (-sx / 2, sy / 2, h)]
        if draw(dr.BOOLEANS):
            quad.reverse()
        top = sh.polygon_shape(quad)
    else:
        top = sh.box(sx, sy, h)
    # the edge to walk off (local outward normal), where along it, and how far inside it to start
    ex, ey = draw(EDGES)
    half_n, half_t = (sx / 2, sy / 2) if ex else (sy / 2, sx / 2)
    along = dr.take(draw, ALONG_EDGE) * half_t
    if variant == "back_probe":
        # a step on the top first (step_down:ok), then the next one's centre is past the edge
        inside = dr.take(draw, PROBE_INSIDE) * r
    else:
        inside = dr.take(draw, INSIDE) * r
    inside = min(inside, half_n * 2 * 0.95)
    d = half_n - inside  # local distance of the start from the centre, along the outward normal
    lx, ly = (ex * d, along) if ex else (along, ey * d)
    ox, oy = _rot(yaw, lx, ly)
    state = BSP_STATE if variant == "back_probe" else draw(BSP_STATES)
    p.objects.append((top, gx - ox, gy - oy, yaw, state))
    if variant == "shared_edge":
        # a second platform sharing the edge: the path crosses a polygon edge between two tops
        h2 = draw(st.sampled_from((h, h, to_f32(h - 0.01), to_f32(h * 0.5), to_f32(h + 0.1),
                                   to_f32(max(h - 0.2, 0.05)))))
        h2 = max(h2, to_f32(0.02))
        w2 = draw(SECOND_WIDTHS)
        cx, cy = (ex * (half_n + w2 / 2), 0.0) if ex else (0.0, ey * (half_n + w2 / 2))
        b2 = sh.box(w2, 2 * half_t, h2) if ex else sh.box(2 * half_t, w2, h2)
        c2x, c2y = _rot(yaw, cx, cy)
        p.objects.append((b2, gx - ox + c2x, gy - oy + c2y, yaw, BSP_STATE))
        p.steps.append(h2)
    out = math.degrees(math.atan2(ey, ex)) + yaw
    p.heading = out + dr.take(draw, PROBE_ANGLES if variant == "back_probe" else EDGE_ANGLES)
    p.begin = (gx, gy)
    if variant == "back_probe":
        # past the edge within one or two steps (a step is one radius)
        p.length = to_f32(inside + r * dr.take(draw, PROBE_STEPS))
        p.edge_slide = True
        p.velocity = (0.0, 0.0, 0.0)
        # on the top or just above it: a sphere sunk into the top keeps the polygon as walkable
        # (edge_slide:precipice_slide at once) and a lone two-sided polygon top is never found again
        p.plane_dz = draw(ON_TOP)
        p.step_down = to_f32(h * dr.take(draw, PROBE_DOWN))
    else:
        p.length = to_f32(inside + r * dr.take(draw, WALK_STEPS))
        p.edge_slide = draw(EDGE_SLIDE)
        if variant == "drop":
            p.step_down = to_f32(h * dr.take(draw, DROP_DOWN))
        else:
            around_h = (to_f32(h - 0.01), h, to_f32(h + 0.01))
            p.step_down = dr.one_of(draw, LEDGE_DOWN_SITE, lambda d: d(st.sampled_from(around_h)),
                                    radius_to_diameter(r), COMMON_DOWN)
    p.step_down = max(p.step_down, 0.0)
    p.stand_on = h
    p.steps.append(h)
    p.label = "ledge" if variant in ("walk_off", "shared_edge") else f"ledge-{variant.replace('_', '-')}"
    return p


STAIR_COUNTS = st.sampled_from((1, 1, 2, 3))
TREADS = dr.OneOf(st.sampled_from((0.3, 0.5, 1.0, 2.0)), dr.f32(0.2, 3.0))
STAIR_WIDTHS = dr.f32(1.5, 8.0)
STAIR_GAPS = dr.OneOf(st.sampled_from((0.0, 0.001, 0.5, 1.0)), dr.floats(0.0, 3.0))
ACROSS = dr.floats(-0.8, 0.8)
STAIR_HEADINGS = st.sampled_from((0.0, 0.0, 10.0, -10.0, 30.0, -30.0, 45.0, 60.0, -70.0))
STAIR_PATHS = st.sampled_from((0.5, 1.0, 1.0, 1.5))


@st.composite
def stairs(draw, gx: float, gy: float, r: float) -> Plan:
    p = Plan()
    up = dr.take(draw, STEP_UPS)
    rise = to_f32(up * dr.take(draw, LIP_FACTORS))
    n = draw(STAIR_COUNTS)
    w = dr.take(draw, TREADS)
    wy = draw(STAIR_WIDTHS)
    yaw = dr.take(draw, YAWS)
    gap = dr.take(draw, STAIR_GAPS) * r
    # stair frame: the first riser at x = 0 facing -x; the mover starts at x = -(r + gap)
    across = draw(ACROSS) * wy / 2
    sx0, sy0 = -(r + gap), across
    for k in range(n):
        shape = sh.box(w, wy, to_f32(rise * (k + 1)))
        cx, cy = _rot(yaw, k * w + w / 2 - sx0, -sy0)
        p.objects.append((shape, gx + cx, gy + cy, yaw, draw(BSP_STATES) if k == 0 else BSP_STATE))
    p.heading = yaw + draw(STAIR_HEADINGS)
    p.begin = (gx, gy)
    p.length = to_f32(gap + r + w * n * draw(STAIR_PATHS))
    p.step_up = to_f32(up)
    p.edge_slide = draw(EDGE_SLIDE)
    p.steps += [rise, to_f32(up)]
    p.label = "stairs"
    return p


WALL_THICKNESS, WALL_LENGTHS = dr.f32(0.1, 1.0), dr.f32(2.0, 12.0)
WALL_HEIGHTS = dr.OneOf(dr.f32(1.0, 6.0), dr.f32(0.2, 1.0))
WALL_GAPS = dr.OneOf(st.sampled_from((0.0, 0.001, 0.5)), dr.floats(0.0, 3.0))
SIGNS = st.sampled_from((1, -1))
WALL_ALONG = dr.floats(-0.45, 0.45)
CORNER_ALONG = dr.floats(0.5, 3.0)
CORNERS = st.sampled_from((False, False, True, False))
ONE_IN_THREE = st.sampled_from((False, False, True))
SECOND_WALLS = dr.f32(2.0, 8.0)
WALL_PATHS = st.sampled_from((0.5, 1.0, 2.0, 4.0))
AIRBORNE = st.sampled_from((0.0, 0.0, 0.0, 0.5, 2.0))


@st.composite
def wall(draw, gx: float, gy: float, r: float) -> Plan:
    p = Plan()
    t = draw(WALL_THICKNESS)
    length = draw(WALL_LENGTHS)
    height = dr.take(draw, WALL_HEIGHTS)
    yaw = dr.take(draw, YAWS)
    gap = dr.take(draw, WALL_GAPS) * r
    inc = dr.take(draw, WALL_ANGLES) * draw(SIGNS)
    corner = draw(CORNERS)
    # wall frame: the wall's face at x = 0 facing -x, centre at x = t/2; the mover at x = -(r + gap)
    along = draw(WALL_ALONG) * length
    if corner:
        along = length / 2 - draw(CORNER_ALONG) * r  # near the far end, where a second wall closes it
        inc = abs(inc) * 0.5 + 20.0
    sx0, sy0 = -(r + gap), along
    cx, cy = _rot(yaw, t / 2 - sx0, -sy0)
    state = draw(BSP_STATES)
    if draw(ONE_IN_THREE):
        # a lone two-sided polygon (sides None), faced either way: hit from behind it is a neg-poly hit
        y0, y1 = -length / 2, length / 2
        quad = [(0.0, y0, 0.0), (0.0, y1, 0.0), (0.0, y1, height), (0.0, y0, height)]
        if draw(dr.BOOLEANS):
            quad.reverse()
        cx, cy = _rot(yaw, -sx0, -sy0)
        p.objects.append((sh.polygon_shape(quad), gx + cx, gy + cy, yaw, state))
    else:
        p.objects.append((sh.box(t, length, height), gx + cx, gy + cy, yaw, state))
    if corner:
        # the second wall along x at y = length/2, facing -y, reaching back past the mover
        l2 = draw(SECOND_WALLS)
        c2x, c2y = _rot(yaw, -l2 / 2 + t - sx0, length / 2 + t / 2 - sy0)
        p.objects.append((sh.box(l2, t, height), gx + c2x, gy + c2y, yaw, BSP_STATE))
    p.heading = yaw + inc
    p.begin = (gx, gy)
    cos = max(math.cos(math.radians(inc)), 0.05)
    p.length = to_f32(min((gap + r * draw(WALL_PATHS)) / cos, 40 * r))
    p.airborne = draw(AIRBORNE)
    p.edge_slide = draw(EDGE_SLIDE)
    p.steps.append(height)
    p.label = "corner" if corner else "wall"
    return p


SLOPE_TARGETS = st.sampled_from(tuple(bd.Z_BOUNDARIES))
SLOPE_WEDGES = {name: st.sampled_from(bd.exact_wedges(bits)) for name, bits in bd.Z_BOUNDARIES.items()}
SLOPE_VARIANTS = st.sampled_from(("on_slope", "on_slope", "walk_up", "land"))
SLOPE_YAWS = st.sampled_from((0.0, 90.0, 180.0, 270.0, 30.0, 45.0))  # a yaw leaves normal.z's bits as they are
SLOPE_HEADINGS = st.sampled_from((0.0, 180.0, 90.0, -90.0, 20.0, 160.0))  # up, down, across, slanted
SLOPE_ALONG = dr.floats(-0.3, 0.3)
SLOPE_GAPS = st.sampled_from((0.0, 0.1, 0.5))


@st.composite
def slope(draw, gx: float, gy: float, r: float) -> Plan:
    p = Plan()
    target = draw(SLOPE_TARGETS)
    sx, sy, sz = draw(SLOPE_WEDGES[target])
    yaw = draw(SLOPE_YAWS)
    variant = draw(SLOPE_VARIANTS)
    along = draw(SLOPE_ALONG) * sy
    nx, _, nz = bd.slope_normal(sx, sy, sz)
    if variant == "walk_up":
        # on the ground before the foot, walking up the slope
        gap = draw(SLOPE_GAPS)
        u = -sx / 2 - r - gap
        p.heading = yaw
        p.length = to_f32(r + gap + sx / 2)  # to the middle of the slope
    else:
        u = sx * draw(SLOPE_ALONG)  # over the middle part of the slope
        rise = (u + sx / 2) * sz / sx
        p.stand_lift = r / nz - r if variant == "on_slope" else 0.0
        p.stand_on = to_f32(rise + p.stand_lift)
        c, s_ = math.cos(math.radians(yaw)), math.sin(math.radians(yaw))
        p.stand_normal = (to_f32(nx * c), to_f32(nx * s_), nz)
        p.heading = yaw + draw(SLOPE_HEADINGS)
        p.length = to_f32(r * dr.take(draw, WALK_STEPS))
        if variant == "land":
            p.airborne = to_f32(r * draw(SLOPE_DROPS))
            p.stand_normal = None
    ox, oy = _rot(yaw, u, along)
    p.objects.append((sh.wedge(sx, sy, sz), gx - ox, gy - oy, yaw, BSP_STATE))
    p.begin = (gx, gy)
    p.edge_slide = draw(EDGE_SLIDE)
    p.steps.append(sz)
    p.label = f"slope-{target.replace('_', '-')}-{variant.replace('_', '-')}"
    return p


SLED_TARGETS = st.sampled_from(tuple(bd.SLED_Z_BOUNDARIES))
SLED_WEDGES = {name: st.sampled_from(w) for name, w in bd.SLED_WEDGES.items()}
SLED_HEADINGS = st.sampled_from((180.0, 180.0, 0.0, 90.0, 160.0))  # down, up, across, slanted


@st.composite
def sled_slope(draw, gx: float, gy: float, r: float) -> Plan:
    """On a wedge whose slope's normal.z is the sledding threshold or an ulp either side
    (boundaries.SLED_WEDGES), over its middle part (strategies/ticks.py sleds down it)."""
    p = Plan()
    target = draw(SLED_TARGETS)
    sx, sy, sz = draw(SLED_WEDGES[target])
    yaw = draw(SLOPE_YAWS)
    along = draw(SLOPE_ALONG) * sy
    nx, _, nz = bd.slope_normal(sx, sy, sz)
    u = sx * draw(SLOPE_ALONG)
    p.stand_lift = r / nz - r
    p.stand_on = to_f32((u + sx / 2) * sz / sx + p.stand_lift)
    c, s_ = math.cos(math.radians(yaw)), math.sin(math.radians(yaw))
    p.stand_normal = (to_f32(nx * c), to_f32(nx * s_), nz)
    p.heading = yaw + draw(SLED_HEADINGS)
    p.length = to_f32(sx)
    ox, oy = _rot(yaw, u, along)
    p.objects.append((sh.wedge(sx, sy, sz), gx - ox, gy - oy, yaw, BSP_STATE))
    p.begin = (gx, gy)
    p.edge_slide = draw(EDGE_SLIDE)
    p.steps.append(sz)
    p.velocity = (0.0, 0.0, 0.0)
    p.label = f"sled-{target.replace('_', '-')}"
    return p


SLOPE_DROPS = st.sampled_from((0.05, 0.5, 2.0))

SEAM_DROPS = st.sampled_from((0.01, 0.01, EPS, 0.1, 0.0, -0.01, -EPS))  # the negative half is higher: both sides adjust
SEAM_ACROSS = dr.floats(-0.5, 0.5)  # the start's distance from the seam, in radii
SEAM_HEADINGS = st.sampled_from((0.0, 180.0, 90.0, 45.0, -30.0, 170.0))
SEAM_VARIANTS = st.sampled_from(("stand", "stand", "land"))


@st.composite
def seam(draw, gx: float, gy: float, r: float) -> Plan:
    p = Plan()
    sx, sy = draw(TOP_SIDES), draw(TOP_SIDES)
    h = draw(sh.STEPS)
    dh = draw(SEAM_DROPS)
    h_neg = to_f32(max(h + dh, 0.02))
    yaw = dr.take(draw, YAWS)
    u = to_f32(draw(SEAM_ACROSS) * r)
    along = draw(SLOPE_ALONG) * sy
    ox, oy = _rot(yaw, u, along)
    p.objects.append((sh.split_floor(sx, sy, h, h_neg), gx - ox, gy - oy, yaw, BSP_STATE))
    p.begin = (gx, gy)
    p.stand_on = max(h, h_neg)
    if draw(SEAM_VARIANTS) == "land":
        p.airborne = to_f32(r * draw(SLOPE_DROPS))
    p.heading = yaw + draw(SEAM_HEADINGS)
    p.length = to_f32(r * dr.take(draw, WALK_STEPS))
    p.edge_slide = draw(EDGE_SLIDE)
    p.steps += [h, h_neg]
    p.label = "seam" + ("-land" if p.airborne else "")
    return p


# straddle: which border, how far the object's origin sits past it (signed: which side owns it),
# what the object is, and the walk into it (at its origin, or beside it; short of it or through)
STRADDLE_BORDERS = st.sampled_from(("cell", "block", "block", "corner", "corner"))
# within this of a landblock border the start counts as beside it (scenes.NEAR_BORDER draws 3 m)
NEAR_BLOCK = 6.0
# what straddles: BSP shapes in a bsp campaign, spheres and cylspheres in an obstacles one (a
# campaign's kinds say which objects it draws)
STRADDLE_KINDS = {"bsp": st.sampled_from(("bsp", "leaf_root", "zero_radius_leaves", "bsp", "zero_radius_leaves", "bsp")),
                  "obstacles": st.sampled_from(("sphere", "cylsphere"))}
SMALL_SIDES, LARGE_SIDES = dr.f32(0.3, 1.5), dr.f32(3.0, 12.0)
SMALL_RADII, LARGE_RADII = dr.f32(0.2, 0.8), dr.f32(2.0, 6.0)
STRADDLE_HEIGHTS = dr.f32(0.3, 4.0)
SIZES = st.sampled_from(("small", "large"))
STRADDLE_YAWS = dr.OneOf(st.sampled_from((0.0, 45.0, 90.0, 30.0, 180.0)), dr.floats(0.0, 359.0))
PAST_BORDER = dr.OneOf(st.sampled_from((0.0, 0.25, 0.5)), dr.floats(0.0, 0.9))  # of the object's half size
OFF_AXIS = dr.OneOf(st.just(0.0), dr.floats(-0.8, 0.8))  # of the object's half size, beside the walk
THROUGH = st.sampled_from((1.0, 2.0, 2.0, 0.5))  # path length in units of the start's distance to the object
START_OFF_BORDER = dr.f32(0.5, 5.0)  # where a start far from a landblock border moves to, from the border


def _straddle_shape(draw, scene_kind: str) -> tuple:
    """(shape, state, half size across the border) for one straddling object."""
    kind = draw(STRADDLE_KINDS[scene_kind])
    large = draw(SIZES) == "large"
    if kind in ("bsp", "leaf_root", "zero_radius_leaves"):
        sides = LARGE_SIDES if large else SMALL_SIDES
        sx, sy = draw(sides), draw(sides)
        shape = sh.box(sx, sy, draw(STRADDLE_HEIGHTS))
        if kind == "leaf_root":
            shape = sh.leaf_root(shape)
        elif kind == "zero_radius_leaves":
            shape = sh.zero_radius_empty_leaves(shape)
        return kind, shape, BSP_STATE, max(sx, sy) / 2
    r = draw(LARGE_RADII if large else SMALL_RADII)
    if kind == "sphere":
        return kind, SphereShape(SphereRec((0.0, 0.0, to_f32(r / 2)), r)), int(PhysicsState.Static), r
    return kind, CylSphereShape((0.0, 0.0, 0.0), r, draw(STRADDLE_HEIGHTS)), int(PhysicsState.Static), r


@st.composite
def straddle(draw, gx: float, gy: float, r: float, scene_kind: str = "bsp") -> Plan:
    border = draw(STRADDLE_BORDERS)
    bxl, byl = round(gx / 192.0) * 192.0, round(gy / 192.0) * 192.0
    near_x, near_y = abs(gx - bxl) < NEAR_BLOCK, abs(gy - byl) < NEAR_BLOCK
    moved = None
    if border != "cell" and not (near_x or near_y) or border == "corner" and not (near_x and near_y):
        # move the start beside the nearest landblock border (both, for a corner), on either side
        if border == "corner" or abs(gx - bxl) <= abs(gy - byl):
            gx, near_x = bxl + draw(SIGNS) * draw(START_OFF_BORDER), True
        if border == "corner" or not near_x:
            gy, near_y = byl + draw(SIGNS) * draw(START_OFF_BORDER), True
        moved = (gx, gy)
    kind, shape, state, half = _straddle_shape(draw, scene_kind)
    past = half * dr.take(draw, PAST_BORDER)
    sx, sy = draw(SIGNS), draw(SIGNS)  # which side of each border the origin (the owner) is on
    if border == "corner" and near_x and near_y:
        ox, oy, where = bxl + sx * past, byl + sy * past, "corner"
    elif border != "cell" and (near_x or near_y):
        if near_x:
            ox, oy, where = bxl + sx * past, gy + half * dr.take(draw, OFF_AXIS), "block"
        else:
            ox, oy, where = gx + half * dr.take(draw, OFF_AXIS), byl + sy * past, "block"
    else:  # the nearer cell border line
        cxl, cyl = round(gx / 24.0) * 24.0, round(gy / 24.0) * 24.0
        if abs(gx - cxl) <= abs(gy - cyl):
            ox, oy = cxl + sx * past, gy + half * dr.take(draw, OFF_AXIS)
        else:
            ox, oy = gx + half * dr.take(draw, OFF_AXIS), cyl + sy * past
        where = "cell"
    p = Plan()
    p.objects.append((shape, ox, oy, dr.take(draw, STRADDLE_YAWS), state))
    dist = math.hypot(ox - gx, oy - gy)
    p.heading = math.degrees(math.atan2(oy - gy, ox - gx)) if dist > 0 else 0.0
    p.begin = (gx, gy)
    p.moved_begin = moved
    p.length = to_f32(min(max(dist, r) * draw(THROUGH), 40 * r))
    p.edge_slide = draw(EDGE_SLIDE)
    p.label = f"straddle-{where}-{kind}"
    return p


# multipart: a static made from a Setup of two to four BSP parts (scene/7 `setup`), each a box at its own
# offset and turn, sometimes with per-part scales (Setup.DefaultScale: ACE's PhysicsPart collides with its
# BSP scaled by the part's scale.z alone), with the Setup's own spheres and cylspheres (ACE's
# FindObjCollisions: the parts' BSPs under HasPhysicsBSP, else the cylspheres if any, else the spheres).
# - corner: the mover walks at a corner of one part (top or bottom, so stepping up it too);
# - spheres: several spheres and cylspheres beside the parts, the state picking which ACE collides with;
# - touching: two of the Setup's spheres touching (the centres' distance their radius sum, or one ulp
#   either side), the mover walking at the point where they meet;
# - tangent: the mover's sphere at the end of a one-step move along an axis exactly tangent to one of
#   the Setup's spheres (or cylspheres), or one ulp of its radius either side: every coordinate and
#   the radius sum on boundaries.GRID, as the obstacles' tangent policy builds it.
MULTIPART_VARIANTS = st.sampled_from(("corner", "corner", "corner", "spheres", "touching", "tangent", "tangent"))
PART_COUNTS = dr.ints(2, 4)
PART_SIDES = dr.f32(0.3, 2.0)
PART_HEIGHTS = dr.OneOf(st.sampled_from((0.5, 1.0, 2.0)), dr.f32(0.2, 3.0))
PART_OFFSETS = dr.OneOf(st.sampled_from((0.0, 0.5, -0.5, 1.0, -1.0)), dr.f32(-2.0, 2.0))
PART_LIFTS = dr.OneOf(st.sampled_from((0.0, 0.0, 0.25, 0.5)), dr.f32(-0.5, 1.0))
PART_YAWS = dr.OneOf(st.sampled_from((0.0, 0.0, 30.0, 45.0, 90.0)), dr.floats(0.0, 359.0))
PART_SCALES = dr.OneOf(st.sampled_from(((1.0, 1.0, 1.0), (1.0, 1.0, 2.0), (0.5, 0.5, 0.5), (2.0, 2.0, 1.0),
                                        (1.5, 1.5, 1.5), (1.0, 1.0, 0.5))),
                       dr.eager(st.tuples(sh.f32s(0.5, 2.0), sh.f32s(0.5, 2.0), sh.f32s(0.5, 2.0))))
SCALED_PARTS = st.sampled_from((False, False, True))
SETUP_SPHERE_COUNTS, SETUP_CYL_COUNTS = dr.ints(0, 3), dr.ints(0, 2)
SETUP_RADII = dr.f32(0.2, 1.2)
MULTIPART_STATES = st.sampled_from((BSP_STATE,) * 6 + (int(PhysicsState.Static),) * 3
                                   + (BSP_STATE | int(PhysicsState.Ethereal),))
CORNER_DISTANCES = dr.f32(0.2, 3.0)  # of the mover's radius, from the corner to the start
CORNER_THROUGH = st.sampled_from((1.0, 1.5, 2.0, 3.0))
# touching spheres: radii on a 1/16 grid so their sum is exact; the centres' distance that sum or an ulp off
TOUCH_SPHERE_RADII = st.sampled_from(tuple(k / 16 for k in range(3, 17)))
ULP_OFFSETS = st.sampled_from((0, 0, 1, -1))
TANGENT_SETUP_KINDS = st.sampled_from(("sphere", "sphere", "cylsphere"))
TANGENT_SETUP_STARTS = dr.f32(70.0, 118.0)  # block-local, on GRID once floored
MULTIPART_AXES = st.sampled_from(((1, 0, 0.0), (-1, 0, 180.0), (0, 1, 90.0), (0, -1, 270.0)))
SETUP_TANGENT_STEPS = dr.f32(0.25, 1.0)  # of the mover's radius
# the Setup's ParentIndex (scene/8 setup.parent_index: SetupFlags.HasParent), which ACE's physics never reads: none
# mostly, each part the root's child (0xFFFFFFFF the root: retail's "no parent"), or a chain of parts
PARENT_INDEX_WAYS = (None, None, None, "flat", "chain")
# the Setup's DefaultAnimation (scene/8 setup.default_animation: one frame, a frame per part), whose frame places the
# parts in place of the placement frames (PartArray.InitDefaults -> Sequence.append_animation; UpdateParts): none
# mostly, the parts' own frames, each turned a quarter about the Setup's z axis, or each raised half a metre
DEFAULT_ANIMATION_WAYS = (None, None, None, None, "same", "turned", "raised")


def _yaw_quat(deg: float):
    """A turn about z as a float32 quaternion (w, x, y, z)."""
    t = math.radians(deg) / 2
    return (to_f32(math.cos(t)), 0.0, 0.0, to_f32(math.sin(t)))


def _ulps(x: float, k: int) -> float:
    from acconform.numerics import f32_next_up

    for _ in range(abs(k)):
        x = f32_next_up(x) if k > 0 else -f32_next_up(-x)
    return x


def _parts(draw) -> tuple:
    from acconform.scene import Frame, PartRec

    scaled = draw(SCALED_PARTS)
    parts = []
    for _ in range(draw(PART_COUNTS)):
        shape = sh.box(draw(PART_SIDES), draw(PART_SIDES), dr.take(draw, PART_HEIGHTS))
        frame = Frame((dr.take(draw, PART_OFFSETS), dr.take(draw, PART_OFFSETS), dr.take(draw, PART_LIFTS)),
                      _yaw_quat(dr.take(draw, PART_YAWS)))
        parts.append(PartRec(shape, frame, tuple(map(to_f32, dr.take(draw, PART_SCALES))) if scaled else None))
    return tuple(parts)


def _round_spheres(draw) -> tuple[tuple, tuple]:
    spheres = tuple(SphereRec((dr.take(draw, PART_OFFSETS), dr.take(draw, PART_OFFSETS), draw(SETUP_RADII)),
                              draw(SETUP_RADII)) for _ in range(draw(SETUP_SPHERE_COUNTS)))
    cyls = tuple(CylSphereShape((dr.take(draw, PART_OFFSETS), dr.take(draw, PART_OFFSETS), 0.0), draw(SETUP_RADII),
                                dr.take(draw, PART_HEIGHTS)) for _ in range(draw(SETUP_CYL_COUNTS)))
    return spheres, cyls


def _part_corner(part, yaw_deg: float, corner: int) -> tuple[float, float]:
    """Where a part's box corner (0..3, its top and bottom alike) lies about the object's origin,
    in doubles: the box's x, y extent scaled by the part's scale.z (what ACE's collision scales its
    BSP by), turned by the part's frame and then the object's yaw."""
    xs = [v[0] for p in part.shape.polygons for v in p.vertices]
    ys = [v[1] for p in part.shape.polygons for v in p.vertices]
    k = part.scale[2] if part.scale is not None else 1.0
    x, y = (max(xs) if corner & 1 else min(xs)) * k, (max(ys) if corner & 2 else min(ys)) * k
    w, _, _, z = part.frame.orientation
    x, y = _rot(math.degrees(2 * math.atan2(z, w)), x, y)
    return _rot(yaw_deg, x + part.frame.origin[0], y + part.frame.origin[1])


@st.composite
def multipart(draw, gx: float, gy: float, r: float) -> Plan:
    from acconform.scene import SetupRec

    variant = draw(MULTIPART_VARIANTS)
    p = Plan()
    p.edge_slide = draw(EDGE_SLIDE)
    parts = _parts(draw)
    if variant == "tangent":
        return _setup_tangent(draw, p, parts, gx, gy, r)
    spheres, cyls = _round_spheres(draw) if variant != "corner" or draw(ONE_IN_FOUR) else ((), ())
    state = draw(MULTIPART_STATES)
    yaw = dr.take(draw, YAWS)
    if variant == "touching":
        r1, r2 = draw(TOUCH_SPHERE_RADII), draw(TOUCH_SPHERE_RADII)
        z = max(r1, r2)
        dist = _ulps(to_f32(r1 + r2), draw(ULP_OFFSETS))
        spheres = (SphereRec((0.0, 0.0, z), r1), SphereRec((dist, 0.0, z), r2)) + spheres
        cyls, state = (), int(PhysicsState.Static)
        ax, ay = _rot(yaw, r1, 0.0)  # where they meet, about the object's origin
    else:
        ax, ay = _part_corner(parts[dr.index(draw, len(parts))], yaw, dr.index(draw, 4))
    heading = dr.take(draw, YAWS)
    d = r * draw(CORNER_DISTANCES) + r
    ox, oy = gx - ax + d * math.cos(math.radians(heading)), gy - ay + d * math.sin(math.radians(heading))
    p.objects.append((SetupRec(parts, spheres, cyls, default_script=draw(DEFAULT_SCRIPTS)), ox, oy, yaw, state))
    p.begin = (gx, gy)
    p.heading = heading + dr.take(draw, EDGE_ANGLES) / 8
    p.length = to_f32(d * draw(CORNER_THROUGH))
    p.label = f"multipart-{variant}-{len(parts)}" + _parent_index(draw, p) + _default_animation(p)
    return p


def _parent_index(draw, p: Plan) -> str:
    """The last static's Setup given a ParentIndex (PARENT_INDEX_WAYS); returns the label's suffix. Picked by the
    static's drawn place, not drawn itself: a draw here would shift every later scene of a seeded sample (the
    policies' tests pin some), and ACE's physics never reads the index."""
    rec, ox, oy, *rest = p.objects[-1]
    how = PARENT_INDEX_WAYS[(len(rec.parts) + int(abs(ox) * 1000) + int(abs(oy) * 1000)) % len(PARENT_INDEX_WAYS)]
    if how is None:
        return ""
    rest = [ox, oy, *rest]
    n = len(rec.parts)
    index = tuple(0xFFFFFFFF if k == 0 else (0 if how == "flat" else k - 1) for k in range(n))
    p.objects[-1] = (replace(rec, parent_index=index), *rest)
    return f"-parent-{how}"


def _default_animation(p: Plan) -> str:
    """The last static's Setup given a DefaultAnimation (DEFAULT_ANIMATION_WAYS); returns the label's suffix. Picked,
    as _parent_index picks, by the static's drawn place, not drawn (a draw would shift later scenes of a seed)."""
    from acconform.scene import Frame

    rec, ox, oy, *rest = p.objects[-1]
    k = len(rec.parts) * 7 + int(abs(ox) * 997) + int(abs(oy) * 991)
    how = DEFAULT_ANIMATION_WAYS[k % len(DEFAULT_ANIMATION_WAYS)]
    if how is None:
        return ""
    frames = []
    for part in rec.parts:
        (x, y, z), q = part.frame.origin, part.frame.orientation
        if how == "turned":  # a quarter turn about z: (x, y) -> (-y, x), the orientation premultiplied by it
            h = math.sqrt(0.5)
            w, qx, qy, qz = q
            q = (h * (w - qz), h * (qx - qy), h * (qy + qx), h * (qz + w))
            x, y = -y, x
        elif how == "raised":
            z = z + 0.5
        frames.append(Frame((float(to_f32(x)), float(to_f32(y)), float(to_f32(z))),
                            tuple(float(to_f32(c)) for c in q)))
    p.objects[-1] = (replace(rec, default_animation=tuple(frames)), ox, oy, *rest)
    return f"-anim-{how}"


def _setup_tangent(draw, p: Plan, parts, gx: float, gy: float, r: float) -> Plan:
    """The tangent variant (see MULTIPART_VARIANTS): the mover's first sphere (centre (0, 0, r), on flat
    ground, plane_dz 0) ends one step along an axis exactly its radius sum (as ACE computes it) from
    a Setup sphere at the same height, or a cylsphere standing on the ground; the start on GRID."""
    from acconform.scene import SetupRec

    kind = draw(TANGENT_SETUP_KINDS)
    r = bd.grid_floor(r)  # the mover's one sphere, its radius on GRID (as the obstacles' tangent policy makes it)
    p.spheres = (SphereRec((0.0, 0.0, r), r),)
    bx, by = math.floor(gx / 192.0) * 192.0, math.floor(gy / 192.0) * 192.0
    lx, ly = bd.grid_floor(draw(TANGENT_SETUP_STARTS)), bd.grid_floor(draw(TANGENT_SETUP_STARTS))
    ax, ay, heading = draw(MULTIPART_AXES)
    step = bd.grid_floor(r * draw(SETUP_TANGENT_STEPS))
    radius, radsum = bd.tangent_radius(kind, r, draw(SETUP_RADII))
    radius = _ulps(radius, draw(ULP_OFFSETS))
    ex, ey = lx + step * ax, ly + step * ay
    if kind == "sphere":
        spheres, cyls = (SphereRec((0.0, 0.0, r), radius),), ()
    else:
        spheres, cyls = (), (CylSphereShape((0.0, 0.0, 0.0), radius, dr.take(draw, PART_HEIGHTS)),)
    p.moved_begin = (bx + lx, by + ly)
    p.begin = p.moved_begin
    p.objects.append((SetupRec(parts, spheres, cyls, default_script=draw(DEFAULT_SCRIPTS)), bx + ex + radsum * ax, by + ey + radsum * ay, 0.0,
                      int(PhysicsState.Static)))
    p.heading, p.length, p.plane_dz, p.velocity = heading, step, 0.0, (0.0, 0.0, 0.0)
    p.label = f"multipart-tangent-{kind}" + _parent_index(draw, p) + _default_animation(p)
    return p


# a policy: (global x, global y, mover radius) -> a strategy of Plans (built per scene: a policy
# depends on the mover; it costs little next to the span of its own it gives the shrinker)
POLICIES = {"ledge": ledge, "stairs": stairs, "wall": wall, "straddle": straddle, "slope": slope, "seam": seam,
            "multipart": multipart,
            "straddle_round": lambda gx, gy, r: straddle(gx, gy, r, "obstacles"), "sled_slope": sled_slope}


def mover_flags(plan: Plan) -> tuple[int, int]:
    state = int(PhysicsState.Gravity) | (int(PhysicsState.EdgeSlide) if plan.edge_slide else 0)
    transient = 0 if plan.airborne else int(TransientState.Contact | TransientState.OnWalkable)
    return state, transient
