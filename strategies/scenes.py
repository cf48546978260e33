"""Scene strategies: a mover path over terrain, with BSP objects or obstacles near the path.

Generation order (so that every feature matters): home landblock -> mover start -> terrain
features placed around the start -> path aimed at a feature edge, an object, a block border or
anywhere -> objects placed along the path -> every landblock the path (plus a margin of the
spheres' reach) can touch, sliced from one height field so shared edges agree.
"""

from __future__ import annotations

import math
from dataclasses import replace

from hypothesis import strategies as st

from acconform.flags import PhysicsState, TransientState
from acconform.numerics import to_f32
from acconform.scene import (IDENTITY, ContactPlane, CylSphereShape, Frame, Mover, PlaneRec, Position, Scene, SetupRec,
                             SphereRec, SphereShape, StaticObject)


from . import boundaries as bd
from . import buildings as bl
from . import draws as dr
from . import dungeon as dg
from . import objects as ob
from . import shapes as sh
from . import terrain as tr
from .terrain import BLOCK, CELL, cell_of, split_global
from .set_position import with_placement


# Typical Setup spheres: humans 0.35-0.5 m; the 2-sphere form stacks a head sphere above.
# the missiles kind's draws (scenes_of): the policies alone, a launch arm, or one of the arms draw_launch_scene leaves
# to be named (all but `across`, a launch both sides refuse over a landblock border)
MISSILE_WAYS = st.sampled_from(("policy", "policy", "policy", "policy", "launch", "named"))
NAMED_LAUNCH_ARMS = st.sampled_from(("run_into", "spin", "trap", "thrown", "untargeted", "spells", "quiet", "sphereless"))
RADII = tuple(to_f32(r) for r in (0.3, 0.35, 0.4, 0.48, 0.5, 1.0))
STEP_HEIGHTS = tuple(to_f32(h) for h in (0.0, 0.01, 0.04, 0.1, 0.2, 0.25, 0.3, 0.4, 0.5, 0.6, 0.75, 1.0, 1.5, 2.0))


def position(gx: float, gy: float, z: float, orientation=IDENTITY) -> Position:
    bx, by, lx, ly = split_global(gx, gy)
    return Position(cell_of(bx, by, lx, ly), Frame((lx, ly, to_f32(z)), orientation))


def yaw(deg: float):
    h = math.radians(deg) / 2
    return (to_f32(math.cos(h)), 0.0, 0.0, to_f32(math.sin(h)))


class _World:
    """The height field plus a cache of sliced landblocks, for ground queries during a draw."""

    def __init__(self, field: tr.Field):
        self.field = field
        self.blocks = {}

    def block(self, bx, by):
        lb = self.blocks.get((bx, by))
        if lb is None:
            lb = self.blocks[(bx, by)] = self.field.landblock(bx, by)
        return lb

    def ground(self, gx, gy):
        bx, by, lx, ly = split_global(gx, gy)
        return self.block(bx, by), tr.ground(self.block(bx, by), lx, ly)

    def water(self, gx, gy) -> bool:
        bx, by, lx, ly = split_global(gx, gy)
        lb = self.block(bx, by)
        cx, cy = min(int(lx // CELL), 7), min(int(ly // CELL), 7)
        return any(tr.is_water_word(lb.terrain[(cx + i) * 9 + cy + j]) for i in (0, 1) for j in (0, 1))


SPHERE_RADII = dr.OneOf(st.sampled_from(RADII), dr.f32(0.1, 1.5))
HEAD_HEIGHTS = st.sampled_from((1.0, 1.6, 2.0, 0.5))


@st.composite
def movers_spheres(draw):
    r = dr.take(draw, SPHERE_RADII)
    spheres = [SphereRec((0.0, 0.0, r), r)]
    if draw(dr.BOOLEANS):
        h = to_f32(r + r * draw(HEAD_HEIGHTS))
        spheres.append(SphereRec((0.0, 0.0, h), r))
    return tuple(spheres)


MOVER_SPHERES = dr.eager(movers_spheres())
COMMON_STEPS = st.sampled_from(STEP_HEIGHTS)
ANY_STEP = dr.f32(0.0, 2.5)
STEP_UP_SITE, STEP_DOWN_SITE = dr.Site("step-up height"), dr.Site("step-down height")


def step_heights(geometry_steps=()) -> tuple:
    """Step heights, as one_of branches (draws.one_of): values just around the geometry's own
    step sizes (built only when that branch is drawn), common values, anything."""
    if not geometry_steps or max(geometry_steps) + 0.01 < 0:  # nothing around them is a height
        return (COMMON_STEPS, ANY_STEP)

    def around(draw):
        return draw(st.sampled_from([to_f32(s + d) for s in geometry_steps for d in (-0.01, 0.0, 0.01) if s + d >= 0]))

    return around, COMMON_STEPS, ANY_STEP


HEADINGS = dr.OneOf(st.sampled_from((0, 90, 180, 270, 45)), dr.ints(0, 359))
# the plainest choice first in every sampled_from / one_of: Hypothesis shrinks toward it
AIMS = st.sampled_from(("any", "feature", "feature", "border"))
AIMS_WITH_OBJECTS = st.sampled_from(("any", "object", "object", "feature", "border"))
JITTER = st.sampled_from((0, 0, 0, 5, -5, 30, -30, 60))
BORDER_JITTER = st.sampled_from((0, 0, 20, -20, 45, -45))
FINE_JITTER = st.sampled_from((0.0, 0.0, 0.5, 1.0))
# how far before an edge the path starts, in sphere radii: on it, within a step, a few steps
GAPS = dr.OneOf(st.sampled_from((0.0, 0.5, 1.0)), dr.f32(0.0, 1.0), dr.f32(1.0, 6.0))

PATH_FACTORS = dr.OneOf(
    dr.f32(0.05, 1.0),  # a fraction of one step (one step = sphere radius)
    dr.f32(0.001, 0.05),  # a sliver: a step-down from barely above gentle ground overshoots (interp in [-0.1, 0))
    st.sampled_from((0.0, 1.0, 2.0, 30.0, 31.0, 45.0)),  # standing still; exactly whole steps; past the step cap
    dr.f32(1.0, 4.0),
    dr.f32(4.0, 25.0),
)
CROSSING_FACTORS = dr.OneOf(st.sampled_from((0.5, 1.0, 2.0)), dr.f32(0.05, 4.0))


HOME = dr.eager(tr.landblock_coords(0x02, 0xFC))
CENTRED = dr.f32(-95.9, 95.9)
WHERE = st.sampled_from(("any", "any", "border", "corner"))
CROSSING_WHERE = st.sampled_from(("border", "corner"))
NEAR_BORDER = dr.OneOf(dr.f32(0.0, 3.0), dr.f32(189.0, 191.99))
QUARTERS = dr.ints(0, 3)
OBJECT_COUNTS = dr.ints(1, 3)


BSP_POLICIES = st.sampled_from(("ledge", "ledge", "ledge", "stairs", "stairs", "wall", "wall", "scatter", "scatter",
                                "straddle", "straddle", "slope", "slope", "seam", "touch", "multipart", "multipart",
                                "multipart"))
# "multipart": a static made from a Setup of several parts (strategies/objects.py, MULTIPART_VARIANTS)
# "touch": a box face, top edge or corner exactly touching the mover's sphere at its end
# (boundaries.TOUCH_RADS / TOUCH_CORNERS: plane_tangent, polygon_edge, polygon_vertex)
# obstacles: scattered along a free path, one across a cell or landblock border or corner
# ("straddle_round"), or "tangent": one exactly tangent to the mover's end
# or "sphere_contact": stepping up onto, or falling past, a sphere whose contact normal's z is
# FloorZ or LandingZ exactly (boundaries.SPHERE_CONTACTS)
OBSTACLE_POLICIES = st.sampled_from(("scatter", "scatter", "scatter", "straddle_round", "tangent", "sphere_contact"))
# terrain: a free path, or "border_slope": grounded on tilted terrain, a few metres from a block
# border, walking across it (AdjustOffset keeps the old block's sloped contact plane a step)
# "exact_slope": a one-cell rise whose normal.z is a walkable/landing threshold exactly (the land
# height table solved, strategies/boundaries.py), walked off from the flat top onto the slope
TERRAIN_POLICIES = st.sampled_from(("free", "free", "free", "border_slope", "exact_slope"))
SNAP_END = st.sampled_from((None, None, None, None, "cell", "block"))
STARTS = st.sampled_from(("ground", "ground", "ground", "air"))
PLATFORM_OFFSETS = dr.f32(-3.0, 3.0)
PLATFORM_ANGLES = st.sampled_from((0, 0, 30, 45, 90))
AIR_HEIGHTS = dr.OneOf(dr.f32(0.001, 0.1), dr.f32(0.1, 6.0))
END_Z = st.sampled_from(("level", "ground", "fall", "rise"))
FALLS, RISES, POLICY_FALLS = dr.f32(0.0, 3.0), dr.f32(0.0, 1.0), dr.f32(0.0, 2.0)
ALONG_PATH = st.sampled_from((0.5, 1.0, 1.0, 1.2))
SIDEWAYS = st.sampled_from((0.0, 0.0, 0.5, -0.5, 1.0))
CLEARANCE = st.sampled_from((0.0, 0.5, 1.0))
OBJECT_ANGLES = st.sampled_from((0, 0, 90, 45, 10, -30))


@st.composite
def scenes_of(draw, kind: str):
    if kind == "doors":  # the ticks policy door only (strategies/doors.py)
        from .ticks import draw_tick_scene

        return draw_tick_scene(draw, None, "door")
    if kind == "movers":  # the ticks policy movers only (strategies/movers.py)
        from .ticks import draw_tick_scene

        return draw_tick_scene(draw, None, "movers")
    if kind == "missiles":  # a projectile launched at a tick (strategies/missiles.py)
        from .missiles import draw_launch_scene, draw_missile_scene

        # one scene in six a launch arm (draw_launch_scene: the alternate solver, misfires, out of range, ...), one in
        # six an arm drawn by name (a spin, a trap, a thrown weapon, ...): else the policies alone
        way = draw(MISSILE_WAYS)
        if way == "launch":
            return draw_launch_scene(draw)
        return draw_missile_scene(draw, draw(NAMED_LAUNCH_ARMS) if way == "named" else None)
    if kind == "targets":  # a MoveTo, sticky follow, turn or stick_to at another mover (strategies/motion.py)
        from .motion import draw_managed_chase
        from .ticks import _clock

        scene = draw_managed_chase(draw, _clock)
        mode = draw(dr.ENGINE_MODES)
        # the legacy player path is the server's (a client-mode PhysicsObj has no RequestPos to set)
        return scene.replace(engine_mode="server" if scene.ticks.driver == "request_pos" else mode)
    if kind == "motion":  # the ticks policy motion only (strategies/motion.py)
        from .ticks import draw_tick_scene

        return draw_tick_scene(draw, None, "motion")
    if kind == "ticks" or kind.startswith("ticks:"):  # tick scenes, over any world or one
        from .ticks import draw_tick_scene

        return draw_tick_scene(draw, kind.partition(":")[2] or None)
    return with_placement(draw, draw_scene(draw, kind))


def draw_scene(draw, kind: str, policy: str | None = None) -> Scene:
    """A scene of `kind`, with its policy drawn (or the one given: a TERRAIN_POLICIES, BSP_POLICIES,
    OBSTACLE_POLICIES, dungeon.POLICIES or buildings.POLICIES entry; strategies/ticks.py asks for ledges,
    stairs, walls, porches, cellars)."""
    if kind == "indoor":
        return dg.draw_indoor(draw, draw(MOVER_SPHERES), step_heights, policy)
    if kind == "buildings":
        return bl.draw_building(draw, draw(MOVER_SPHERES), step_heights, policy)
    bx, by = draw(HOME)
    terrain_policy = (policy or draw(TERRAIN_POLICIES)) if kind == "terrain" else "free"
    if terrain_policy == "exact_slope":
        return _exact_slope_scene(draw, bx, by, draw(MOVER_SPHERES))
    crossing = terrain_policy == "border_slope"
    # start: anywhere in the block, or hugging a border (the neighbour must be defined)
    where = draw(CROSSING_WHERE) if crossing else draw(WHERE)
    if where == "any":
        lx, ly = to_f32(96.0 + draw(CENTRED)), to_f32(96.0 + draw(CENTRED))
    else:
        lx = dr.take(draw, NEAR_BORDER)
        ly = dr.take(draw, NEAR_BORDER) if where == "corner" else to_f32(96.0 + draw(CENTRED))
        if draw(dr.BOOLEANS):
            lx, ly = ly, lx
    gx0, gy0 = bx * BLOCK + lx, by * BLOCK + ly
    vx, vy = round(gx0 / CELL), round(gy0 / CELL)
    if kind == "terrain" or policy is None:
        policy = draw(BSP_POLICIES) if kind == "bsp" else draw(OBSTACLE_POLICIES) if kind == "obstacles" else "scatter"
    flat = kind != "terrain" and (policy != "scatter" or draw(QUARTERS) < 3)
    field = tr.field_near(draw, vx, vy, flat=flat, tilt=crossing)
    world = _World(field)

    spheres = draw(MOVER_SPHERES)
    r = spheres[0].radius
    reach = max(s.center[2] + s.radius for s in spheres)
    if policy == "tangent":
        return _tangent_scene(draw, world, bx, by, spheres)
    if policy == "sphere_contact":
        return _sphere_contact_scene(draw, bx, by)
    if policy == "touch":
        return _touch_scene(draw, bx, by)
    if policy != "scatter":
        return _policy_scene(draw, kind, policy, world, bx, by, lx, ly, spheres)

    # objects go in first (the path may aim at one)
    objects_spec = []
    if kind == "bsp":
        for _ in range(draw(OBJECT_COUNTS)):
            objects_spec.append(draw(sh.BSP_SHAPES))
    elif kind == "obstacles":
        for _ in range(draw(OBJECT_COUNTS)):
            objects_spec.append(("obstacle", dr.take(draw, sh.OBSTACLE_SHAPES), 0.0))

    # path
    aim = "border" if crossing else draw(AIMS_WITH_OBJECTS if objects_spec else AIMS)
    if aim == "feature" and field.features:
        # aim at a feature's edge from a short gap before it, so the path crosses it
        f = field.features[dr.index(draw, len(field.features))]
        tx, ty = _feature_target(f, vx, vy, draw(dr.BOOLEANS))
        tx, ty = tx * CELL, ty * CELL
        heading = math.degrees(math.atan2(ty - gy0, tx - gx0)) + draw(JITTER)
        gap = dr.take(draw, GAPS) * r
        hr = math.radians(heading)
        gx0 = min(max(tx - gap * math.cos(hr), (bx - 1) * BLOCK + 1.0), (bx + 2) * BLOCK - 1.0)
        gy0 = min(max(ty - gap * math.sin(hr), (by - 1) * BLOCK + 1.0), (by + 2) * BLOCK - 1.0)
        bx, by, lx, ly = split_global(gx0, gy0)
        gx0, gy0 = bx * BLOCK + lx, by * BLOCK + ly
        length = to_f32(gap + r * dr.take(draw, PATH_FACTORS))
    else:
        if aim == "border":
            dists = {0: BLOCK - lx, 180: lx, 90: BLOCK - ly, 270: ly}
            heading = min(dists, key=dists.get) + draw(BORDER_JITTER)
        else:
            heading = dr.take(draw, HEADINGS)
        if crossing:
            # far enough to cross the border (aim "border": it is within NEAR_BORDER's 3 m)
            gap = min(dists.values()) / max(math.cos(math.radians(heading - min(dists, key=dists.get))), 0.3)
            length = to_f32(gap + r * dr.take(draw, CROSSING_FACTORS))
        else:
            length = to_f32(r * dr.take(draw, PATH_FACTORS))
    heading += draw(FINE_JITTER)

    # start height: on the ground (contact), a little above it, or well up in the air
    lb0, (z0, n0, d0) = world.ground(gx0, gy0)
    start = "ground" if crossing else draw(STARTS)
    state = int(PhysicsState.Gravity)
    if draw(QUARTERS) > 0:  # shrinks to 0: EdgeSlide off
        state |= int(PhysicsState.EdgeSlide)
    begin_cell = cell_of(bx, by, lx, ly)
    contact = None
    transient = 0
    platform = None
    geometry_steps = [abs(f.k) * 2.0 for f in field.features if f.kind in ("step", "box") and abs(f.k) < 4]

    # BSP objects: maybe one is a platform under the mover (a ledge to walk off)
    placed = []
    if objects_spec and objects_spec[0][0] in ("platform", "ledge", "step", "floor") and draw(dr.BOOLEANS):
        label, shape, top = objects_spec.pop(0)
        ox = gx0 + draw(PLATFORM_OFFSETS)
        oy = gy0 + draw(PLATFORM_OFFSETS)
        angle = draw(PLATFORM_ANGLES)
        platform = (label, shape, top, ox, oy, angle)
        geometry_steps.append(top)
    for label, shape, top in objects_spec:
        geometry_steps.append(top)

    obj_state = (lambda: draw(ob.BSP_STATES)) if kind == "bsp" else (lambda: int(PhysicsState.Static))
    if platform is not None:
        label, shape, top, ox, oy, angle = platform
        _, (gz, _, _) = world.ground(ox, oy)
        z0 = to_f32(gz + top)
        n0, d0 = (0.0, 0.0, 1.0), to_f32(-z0)
        placed.append((shape, ox, oy, gz, yaw(angle), obj_state()))
    if start == "ground":
        walkable = n0[2] >= tr.FLOOR_Z
        transient = int(TransientState.Contact) | (int(TransientState.OnWalkable) if walkable else 0)
        if world.water(gx0, gy0) and platform is None:
            transient |= int(TransientState.WaterContact)
        contact = ContactPlane(begin_cell, PlaneRec(n0, d0))
        bz = to_f32(z0 + dr.take(draw, ob.PLANE_DZ))  # on the plane, or EPSILON either side of it
    else:
        bz = to_f32(z0 + dr.take(draw, AIR_HEIGHTS))

    rad = math.radians(heading)
    gx1, gy1 = _snap(draw, gx0 + length * math.cos(rad), gy0 + length * math.sin(rad))
    end_z = draw(END_Z)
    if end_z == "ground" and platform is None:
        _, (ez, _, _) = world.ground(gx1, gy1)
        ez = to_f32(ez + dr.take(draw, ob.PLANE_DZ))
    elif end_z == "fall" or start == "air":
        ez = bz - draw(FALLS)
    elif end_z == "rise":
        ez = bz + draw(RISES)
    else:
        ez = bz

    # the other objects: along the path, a little past its end, or to the side
    for shape_i, (label, shape, top) in enumerate(objects_spec):
        t = draw(ALONG_PATH)
        side = draw(SIDEWAYS)
        clearance = shape.sphere.radius if hasattr(shape, "sphere") and label not in ("wall",) else 0.3
        dist = length * t + r + clearance * draw(CLEARANCE)
        ox = gx0 + dist * math.cos(rad) - side * r * math.sin(rad)
        oy = gy0 + dist * math.sin(rad) + side * r * math.cos(rad)
        angle = heading + draw(OBJECT_ANGLES)
        _, (gz, _, _) = world.ground(ox, oy)
        placed.append((shape, ox, oy, gz, yaw(angle), obj_state()))

    steps = step_heights(geometry_steps + [r * t for t in (0.5, 1.0, 1.25, 1.5, 2.0)])
    up = dr.one_of(draw, STEP_UP_SITE, *steps)
    # step-down in [r, 2r] reaches a cliff's face within one step (and stays whole: above 2r a
    # one-sphere mover halves it), which is what EdgeSlide's CliffSlide branch needs
    down = dr.one_of(draw, STEP_DOWN_SITE, ob.radius_to_diameter(r), *steps)
    mover = Mover(
        spheres=spheres,
        begin=Position(begin_cell, Frame((lx, ly, bz))),
        end=position(gx1, gy1, ez),
        step_up_height=up,
        step_down_height=down,
        state=state,
        transient_state=transient,
        contact_plane=contact,
        velocity=draw(ob.VELOCITIES),
    )
    name = f"{kind}:{start}:{aim}" + (":platform" if platform else "") + (":slope" if crossing else "")
    return _scene(world, bx, by, (gx0, gy0), (gx1, gy1), reach, placed, mover, name)


def _snap(draw, gx: float, gy: float) -> tuple[float, float]:
    """Maybe move a path's end exactly onto the nearest cell or landblock border (a decision boundary)."""
    how = draw(SNAP_END)
    if how is None:
        return gx, gy
    unit = CELL if how == "cell" else BLOCK
    sx, sy = round(gx / unit) * unit, round(gy / unit) * unit
    if abs(sx - gx) <= abs(sy - gy) or draw(dr.BOOLEANS):
        return float(sx), gy
    return gx, float(sy)


def _policy_scene(draw, kind, policy, world, bx, by, lx, ly, spheres):
    """A BSP scene from one of strategies.objects' policies (the mover placed with the objects)."""
    r = spheres[0].radius
    reach = max(s.center[2] + s.radius for s in spheres)
    gx0, gy0 = bx * BLOCK + lx, by * BLOCK + ly
    plan = draw(ob.POLICIES[policy](gx0, gy0, r))
    if plan.spheres is not None:  # the policy set the mover's spheres (multipart's tangent variant)
        spheres = plan.spheres
        r, reach = spheres[0].radius, max(s.center[2] + s.radius for s in spheres)
    if plan.moved_begin is not None:  # the policy moved the start (straddle: beside a landblock border)
        bx, by, lx, ly = split_global(*plan.moved_begin)
        gx0, gy0 = bx * BLOCK + lx, by * BLOCK + ly
    placed = []
    for shape, ox, oy, angle, st_ in plan.objects:
        _, (gz, _, _) = world.ground(ox, oy)
        placed.append((shape, ox, oy, gz, yaw(angle), st_))
    _, (z0, n0, d0) = world.ground(gx0, gy0)
    begin_cell = cell_of(bx, by, lx, ly)
    state, transient = ob.mover_flags(plan)
    if plan.stand_on is not None:
        _, (pz, _, _) = world.ground(plan.objects[0][1], plan.objects[0][2])
        z0, n0, d0 = to_f32(pz + plan.stand_on), (0.0, 0.0, 1.0), to_f32(-to_f32(pz + plan.stand_on))
        if plan.stand_normal is not None:
            n0 = plan.stand_normal
            d0 = to_f32(-(n0[0] * lx + n0[1] * ly + n0[2] * (z0 - plan.stand_lift)))
    contact = None
    if plan.airborne:
        bz = to_f32(z0 + plan.airborne)
    else:
        contact = ContactPlane(begin_cell, PlaneRec(n0, d0))
        bz = to_f32(z0 + (plan.plane_dz if plan.plane_dz is not None else dr.take(draw, ob.PLANE_DZ)))
        if n0[2] < tr.FLOOR_Z:
            transient &= ~int(TransientState.OnWalkable)
    rad = math.radians(plan.heading)
    gx1, gy1 = gx0 + plan.length * math.cos(rad), gy0 + plan.length * math.sin(rad)
    ez = bz if not plan.airborne else to_f32(bz - draw(POLICY_FALLS))
    steps = step_heights(plan.steps + [r * t for t in (0.5, 1.0, 1.5)])
    up = plan.step_up if plan.step_up is not None else dr.one_of(draw, STEP_UP_SITE, *steps)
    down = plan.step_down if plan.step_down is not None else dr.one_of(draw, STEP_DOWN_SITE, ob.radius_to_diameter(r),
                                                                       *steps)
    mover = Mover(spheres=spheres, begin=Position(begin_cell, Frame((lx, ly, bz))), end=position(gx1, gy1, ez),
                  step_up_height=up, step_down_height=down, state=state, transient_state=transient,
                  contact_plane=contact, velocity=plan.velocity if plan.velocity is not None else draw(ob.VELOCITIES))
    name = f"{kind}:{plan.label}" + (":air" if plan.airborne else "") + ("" if plan.edge_slide else ":no-edge-slide")
    return _scene(world, bx, by, (gx0, gy0), (gx1, gy1), reach, placed, mover, name)


TANGENT_STARTS = dr.f32(70.0, 118.0)  # block-local, inside boundaries.GRID_LO..GRID_HI with room to move
AXES = st.sampled_from(((1, 0), (-1, 0), (0, 1), (0, -1)))
TANGENT_STEPS = dr.f32(0.25, 1.0)  # of the mover's radius: one step, so the check position is the end
TANGENT_KINDS = st.sampled_from(("sphere", "cylsphere"))
TANGENT_RADII = dr.f32(0.1, 2.0)
TANGENT_HEIGHTS = dr.f32(0.5, 4.0)
EXACT_STEP_UP = st.sampled_from((False, True))
TOUCHES = st.sampled_from(("face", "edge", "vertex"))
TOUCH_RADS = st.sampled_from(bd.TOUCH_RADS)
TOUCH_CORNERS = st.sampled_from(bd.TOUCH_CORNERS)
TOUCH_SIZES = st.sampled_from(bd.TOUCH_SIZES)
TOUCH_TALL = st.sampled_from((2.0, 4.0))
TOUCH_SIDE = st.sampled_from((0.0, 0.25, -0.25))  # of the box's width: where along the face it is met
SIGNS = st.sampled_from((1, -1))


def _tangent_scene(draw, world, bx, by, spheres) -> Scene:
    """An obstacle exactly tangent to the mover's sphere at the end of a one-step move along an
    axis (strategies/boundaries.py: every coordinate and the radius sum sit on GRID, so the
    check position is the end and disp is (radsum, 0, 0) bit for bit)."""
    r = bd.grid_floor(spheres[0].radius)
    spheres = tuple(SphereRec((0.0, 0.0, r if i == 0 else s.center[2]), r) for i, s in enumerate(spheres))
    lx, ly = draw(TANGENT_STARTS), draw(TANGENT_STARTS)
    ax, ay = draw(AXES)
    step = bd.grid_floor(r * draw(TANGENT_STEPS))
    gx0, gy0 = bx * BLOCK + lx, by * BLOCK + ly
    gx1, gy1 = gx0 + step * ax, gy0 + step * ay
    _, (z0, n0, d0) = world.ground(gx0, gy0)
    kind = draw(TANGENT_KINDS)
    radius, radsum = bd.tangent_radius(kind, r, draw(TANGENT_RADII))
    ox, oy = gx1 + radsum * ax, gy1 + radsum * ay
    height = 0.0
    if kind == "sphere":
        shape, oz = SphereShape(SphereRec((0.0, 0.0, 0.0), radius)), to_f32(to_f32(z0) + r)
    else:
        height = draw(TANGENT_HEIGHTS)
        shape, oz = CylSphereShape((0.0, 0.0, 0.0), radius, height), z0
    begin_cell = cell_of(bx, by, lx, ly)
    state = int(PhysicsState.Gravity) | (int(PhysicsState.EdgeSlide) if draw(dr.BOOLEANS) else 0)
    steps = step_heights([r * t for t in (0.5, 1.0, 1.5)])
    # maybe the step-up height is the rise StepSphereUp computes there, bit for bit (step_up_height)
    up = dr.one_of(draw, STEP_UP_SITE, *steps)
    if draw(EXACT_STEP_UP):
        up = bd.tangent_step_up(kind, r, radius, height, z0)
    mover = Mover(spheres=spheres, begin=Position(begin_cell, Frame((lx, ly, z0))), end=position(gx1, gy1, z0),
                  step_up_height=up,
                  step_down_height=dr.one_of(draw, STEP_DOWN_SITE, ob.radius_to_diameter(r), *steps),
                  state=state, transient_state=int(TransientState.Contact | TransientState.OnWalkable),
                  contact_plane=ContactPlane(begin_cell, PlaneRec(n0, d0)), velocity=(0.0, 0.0, 0.0))
    reach = max(s.center[2] + s.radius for s in spheres)
    placed = [(shape, ox, oy, oz, IDENTITY, int(PhysicsState.Static))]
    return _scene(world, bx, by, (gx0, gy0), (gx1, gy1), reach, placed, mover, f"obstacles:tangent-{kind}")


def _touch_scene(draw, bx, by) -> Scene:
    """A box (dyadic sizes, on flat ground at z 0) exactly touching the mover's sphere at the end
    of a one-step move along an axis (strategies/boundaries.py: rad = r - EPSILON on GRID, every
    coordinate on GRID): "face", a side face rad ahead (plane_tangent); "edge", the box's top at
    the sphere centre's height with its edge rad ahead (polygon_edge, and plane_tangent on the
    side face); "vertex", a top corner (a, b) off the centre with a^2 + b^2 == rad^2 (polygon_vertex)."""
    how = draw(TOUCHES)
    if how == "vertex":
        rad, a, b = draw(TOUCH_CORNERS)
    else:
        rad, a, b = draw(TOUCH_RADS), None, None
    r = bd.touch_radius(rad)
    lx, ly = draw(TANGENT_STARTS), draw(TANGENT_STARTS)
    ax, ay = draw(AXES)
    step = bd.grid_floor(r * draw(TANGENT_STEPS))
    gx0, gy0 = bx * BLOCK + lx, by * BLOCK + ly
    gx1, gy1 = gx0 + step * ax, gy0 + step * ay
    along, across = draw(TOUCH_SIZES), draw(TOUCH_SIZES)
    px, py = -ay, ax  # across the move
    if how == "vertex":
        side = draw(SIGNS)
        ahead, off = a + along / 2, side * (b + across / 2)
    else:
        ahead, off = rad + along / 2, draw(TOUCH_SIDE) * across
    ox, oy = gx1 + ahead * ax + off * px, gy1 + ahead * ay + off * py
    height = to_f32(r) if how != "face" else draw(TOUCH_TALL)  # the top at the sphere centre's height
    shape = sh.box(along if ax else across, across if ax else along, height)
    if how != "vertex":  # a face's own node would turn the sphere away at dist == reach
        shape = sh.one_leaf_above_ground(shape)
    world = _World(tr.Field(0, (), 0, 0, draw(tr.LAND)))
    begin_cell = cell_of(bx, by, lx, ly)
    spheres = (SphereRec((0.0, 0.0, r), r),)
    state = int(PhysicsState.Gravity) | (int(PhysicsState.EdgeSlide) if draw(dr.BOOLEANS) else 0)
    steps = step_heights([r * t for t in (0.5, 1.0, 1.5)])
    mover = Mover(spheres=spheres, begin=Position(begin_cell, Frame((lx, ly, 0.0))), end=position(gx1, gy1, 0.0),
                  step_up_height=dr.one_of(draw, STEP_UP_SITE, *steps),
                  step_down_height=dr.one_of(draw, STEP_DOWN_SITE, ob.radius_to_diameter(r), *steps),
                  state=state, transient_state=int(TransientState.Contact | TransientState.OnWalkable),
                  contact_plane=ContactPlane(begin_cell, PlaneRec((0.0, 0.0, 1.0), 0.0)), velocity=(0.0, 0.0, 0.0))
    placed = [(shape, ox, oy, 0.0, IDENTITY, draw(ob.BSP_STATES))]  # mostly a plain physics BSP
    return _scene(world, bx, by, (gx0, gy0), (gx1, gy1), 2 * r, placed, mover, f"bsp:touch-{how}")


EXACT_SLOPE_TARGETS = st.sampled_from(bd.exact_terrain_targets())
SLOPE_GAPS = dr.OneOf(st.sampled_from((0.0, 0.5, 1.0)), dr.f32(0.0, 2.0))  # of r, the start behind the top edge
SLOPE_JITTER = st.sampled_from((0.0, 0.0, 10.0, -10.0, 30.0, -30.0, 60.0))
SLOPE_PAST = dr.OneOf(st.sampled_from((0.5, 1.0, 2.0)), dr.f32(0.05, 3.0))  # of r, how far past the edge
SLOPE_STARTS = st.sampled_from(("top", "top", "top", "air"))
# a LandingZ slope is 85 degrees: a 0.04 m step-down probe meets it only within 3.5 mm of the top
# edge, so that walk starts on the edge and stops a sliver past it (metres; above EPSILON)
SLOPE_SLIVERS = dr.f32(0.0005, 0.0035)
# maybe a step-down height of exactly 2r: walking off the top, TransitionalInsert compares them (step_down_height)
EXACT_STEP_DOWN = st.sampled_from((False, True))


def _exact_slope_scene(draw, bx, by, spheres) -> Scene:
    """Terrain with one cell-wide rise whose make_plane normal.z is exactly FloorZ or LandingZ or an
    ulp off (the land height table's entry 1 solved, entry 0 = 0: boundaries.terrain_rise_for); the
    mover starts on the flat top a little behind the edge and walks (or falls) off it toward the
    slope, so StepDown and the landing tests meet the slope's plane. A FloorZ-side target walks
    on walkable ground (StepDown compares with FloorZ), a LandingZ one with Contact only
    (StepDown compares with LandingZ)."""
    name, rise = draw(EXACT_SLOPE_TARGETS)
    table = bd.exact_slope_table(rise)
    r = spheres[0].radius
    lx, ly = draw(TANGENT_STARTS), draw(TANGENT_STARTS)
    gx, gy = bx * BLOCK + lx, by * BLOCK + ly
    ax, ay = draw(AXES)  # the slope descends toward (ax, ay): heights index 1 behind the edge, 0 past it
    vx, vy = round(gx / CELL), round(gy / CELL)
    # the top is a*gx' + b*gy' >= c with (a, b) = -(ax, ay); its edge at vertex line vx (or vy)
    edge = vx if ax else vy
    c = -(ax * vx + ay * vy)
    world = _World(tr.Field(0, (tr.Feature("step", a=-ax, b=-ay, c=c, k=1),), 0, 0, draw(tr.LAND)))
    walkable_side = name.startswith("floor_z")
    gap = dr.take(draw, SLOPE_GAPS) * r if walkable_side else 0.0
    if ax:
        gx = edge * CELL - ax * gap
    else:
        gy = edge * CELL - ay * gap
    bx, by, lx, ly = split_global(gx, gy)
    gx, gy = bx * BLOCK + lx, by * BLOCK + ly
    heading = math.degrees(math.atan2(ay, ax)) + draw(SLOPE_JITTER)
    length = to_f32(gap + (r * dr.take(draw, SLOPE_PAST) if walkable_side else draw(SLOPE_SLIVERS)))
    rad = math.radians(heading)
    gx1, gy1 = _snap(draw, gx + length * math.cos(rad), gy + length * math.sin(rad))
    top = to_f32(rise)
    begin_cell = cell_of(bx, by, lx, ly)
    state = int(PhysicsState.Gravity) | (int(PhysicsState.EdgeSlide) if draw(QUARTERS) > 0 else 0)
    if draw(SLOPE_STARTS) == "air":
        bz, contact, transient = to_f32(top + dr.take(draw, AIR_HEIGHTS)), None, 0
        ez = to_f32(bz - draw(FALLS))
    else:
        bz = to_f32(top + dr.take(draw, ob.PLANE_DZ))
        contact = ContactPlane(begin_cell, PlaneRec((0.0, 0.0, 1.0), to_f32(-top)))
        transient = int(TransientState.Contact) | (int(TransientState.OnWalkable) if walkable_side else 0)
        ez = bz
    steps = step_heights([r * t for t in (0.5, 1.0, 1.5)])
    down = dr.one_of(draw, STEP_DOWN_SITE, ob.radius_to_diameter(r), *steps)
    if draw(EXACT_STEP_DOWN):
        down = to_f32(2 * r)  # exact: doubling a float32
    mover = Mover(spheres=spheres, begin=Position(begin_cell, Frame((lx, ly, bz))), end=position(gx1, gy1, ez),
                  step_up_height=dr.one_of(draw, STEP_UP_SITE, *steps), step_down_height=down,
                  state=state, transient_state=transient, contact_plane=contact, velocity=draw(ob.VELOCITIES))
    reach = max(s.center[2] + s.radius for s in spheres)
    scene = _scene(world, bx, by, (gx, gy), (gx1, gy1), reach, [], mover, f"terrain:exact-slope-{name}")
    return Scene(scene.landblocks, scene.mover, scene.objects, land_height_table=table, name=scene.name)


SPHERE_CONTACTS = st.sampled_from(bd.SPHERE_CONTACTS)


def _sphere_contact_scene(draw, bx, by) -> Scene:
    """A solved geometry of boundaries.SPHERE_CONTACTS over flat ground, moved on GRID and turned
    to an axis: a walkable mover stepping up onto a sphere (StepSphereDown compares FloorZ bit
    for bit) or an airborne one dropping past its side (IsWalkableAllowable compares LandingZ)."""
    how, r, radius, dx = draw(SPHERE_CONTACTS)
    x0, y0 = draw(TANGENT_STARTS), draw(TANGENT_STARTS)
    ax, ay = draw(AXES)
    (x0, y0, zb), (x1, y1, ze), (ox, oy, oz) = bd.sphere_contact_layout(how, r, radius, dx, x0, y0, ax, ay)
    world = _World(tr.Field(bd.SPHERE_CONTACT_GROUND_INDEX, (), 0, 0, draw(tr.LAND)))
    cell = cell_of(bx, by, x0, y0)
    gz = bd.SPHERE_CONTACT_GROUND_Z
    walk = how == "walk"
    up = bd.SPHERE_CONTACT_STEP_UP
    mover = Mover(spheres=(SphereRec((0.0, 0.0, r), r),), begin=Position(cell, Frame((x0, y0, zb))),
                  end=Position(cell_of(bx, by, x1, y1), Frame((x1, y1, ze))), step_up_height=up, step_down_height=up,
                  state=int(PhysicsState.Gravity) | (int(PhysicsState.EdgeSlide) if draw(dr.BOOLEANS) else 0),
                  transient_state=int(TransientState.Contact | TransientState.OnWalkable) if walk else 0,
                  contact_plane=ContactPlane(cell, PlaneRec((0.0, 0.0, 1.0), -gz)) if walk else None,
                  velocity=(0.0, 0.0, 0.0))
    gx0, gy0, gx1, gy1 = bx * BLOCK + x0, by * BLOCK + y0, bx * BLOCK + x1, by * BLOCK + y1
    placed = [(SphereShape(SphereRec((0.0, 0.0, 0.0), radius)), bx * BLOCK + ox, by * BLOCK + oy, oz, IDENTITY,
               int(PhysicsState.Static))]
    return _scene(world, bx, by, (gx0, gy0), (gx1, gy1), r, placed, mover, f"obstacles:sphere-contact-{how}")


def _scene(world, bx, by, p0, p1, reach, placed, mover, name) -> Scene:
    objects = []
    for i, (shape, ox, oy, gz, q, state) in enumerate(placed):
        if isinstance(shape, SetupRec):  # a Setup of several parts (scene/7)
            objects.append(StaticObject(0x70000000 + i, position(ox, oy, gz, q), None, state, setup=shape))
        else:
            objects.append(StaticObject(0x70000000 + i, position(ox, oy, gz, q), shape, state))
    landblocks = tuple(world.block(ix, iy) for ix, iy in sorted(_blocks_in_reach(bx, by, p0, p1, reach, objects)))
    return Scene(landblocks, mover, tuple(objects), name=name)


def _blocks_in_reach(bx, by, p0, p1, reach, objects) -> set[tuple[int, int]]:
    """Every landblock the mover's path (plus the spheres' reach and REACH_SLACK) or any object's
    bounding sphere (plus REACH_SLACK) can touch: a function of the path and the objects only, so
    as Hypothesis shrinks them the landblock set shrinks too (a short path inside one block and no
    object across a border is a one-landblock scene)."""
    margin = reach + sh.REACH_SLACK
    x0, y0 = min(p0[0], p1[0]) - margin, min(p0[1], p1[1]) - margin
    x1, y1 = max(p0[0], p1[0]) + margin, max(p0[1], p1[1]) + margin
    ix0, ix1, iy0, iy1 = int(x0 // BLOCK), int(x1 // BLOCK), int(y0 // BLOCK), int(y1 // BLOCK)
    # a sphere stepping down just across a border looks one landblock further on along the
    # crossing (check_pos keeps the old block's frame a moment: add_all_outside_cells reaches the
    # cell beyond), so a path spanning a border takes the next block ahead
    if ix1 > ix0:
        ix0, ix1 = (ix0 - 1, ix1) if p1[0] < p0[0] else (ix0, ix1 + 1)
    if iy1 > iy0:
        iy0, iy1 = (iy0 - 1, iy1) if p1[1] < p0[1] else (iy0, iy1 + 1)
    blocks = {(bx, by)} | {(ix, iy) for ix in range(ix0, ix1 + 1) for iy in range(iy0, iy1 + 1)
                           if 0 <= ix <= 0xFE and 0 <= iy <= 0xFE}
    for o in objects:
        blocks |= sh.object_blocks(o)
    return blocks


def _feature_target(f: tr.Feature, vx: int, vy: int, top: bool) -> tuple[float, float]:
    """A global vertex point on the feature's edge nearest the start vertex (vx, vy).

    A step's slope spans the cells between the lines a*x + b*y = c - 1 and = c; `top` picks the
    first (where the ground starts to change, seen from the base side), else the second.
    """
    if f.kind == "step":
        c = f.c - 1 if top else f.c
        if f.a == 0:
            return vx, c / f.b
        if f.b == 0:
            return c / f.a, vy
        # diagonal line a*x + b*y = c: project the start onto it
        t = (c - f.a * vx - f.b * vy) / 2
        return vx + f.a * t, vy + f.b * t
    cx = min(max(vx, f.x0), f.x1)
    cy = min(max(vy, f.y0), f.y1)
    if (cx, cy) == (vx, vy):  # inside: aim at the nearest edge
        d = {(f.x0, vy): vx - f.x0, (f.x1, vy): f.x1 - vx, (vx, f.y0): vy - f.y0, (vx, f.y1): f.y1 - vy}
        return min(d, key=d.get)
    return cx, cy


# scene/8 mover.free_heading: the transition kinds a free-heading mover may be drawn over (a shard holds one kind:
# bsp-0017's scenes are bsp), and its end's heading
FREE_HEADING_KINDS = ("terrain", "bsp", "obstacles", "indoor")
FREE_HEADING_TURNS = st.sampled_from((0.0, 30.0, 90.0, 180.0, -135.0))
FREE_HEADING_IN_PLACE = st.sampled_from((False, False, False, True))


def draw_free_heading_scene(draw, kinds=FREE_HEADING_KINDS) -> Scene:
    """A transition scene (one of `kinds`, placed or not, as `scenes_of` draws it) whose mover's Setup has
    the flag AllowFreeHeading (scene/8 mover.free_heading): PhysicsObj.get_object_info sets ObjectInfoState.FreeRotate,
    so Transition.FindTransitionalPosition gives the current position the end's orientation before the first step (a
    placement's transition has no step: its other FreeRotate arm) and never turns the check position by steps. The end
    is turned by a drawn yaw (0 keeps its heading) so the orientation the transition carries differs; a quarter of the
    scenes turn in place (the end at the begin).
    No campaign kind draws it: a draw added to a kind would move every seeded sample the tests pin."""
    kind = draw(st.sampled_from(kinds))
    scene = with_placement(draw, draw_scene(draw, kind))
    m = scene.mover
    turn = draw(FREE_HEADING_TURNS)
    # a quarter turn in place (the end at the begin's origin): CalcNumSteps gives no step, so the transition takes
    # FindTransitionalPosition's numSteps <= 0 arm with FreeRotate set
    # (a begin no cell holds, a placement's, keeps its end)
    low = m.begin.cell & 0xFFFF
    in_place = draw(FREE_HEADING_IN_PLACE) and (1 <= low <= 0x40 or 0x100 <= low <= 0xFFFD)
    end = Position(m.begin.cell, Frame(m.begin.frame.origin, m.begin.frame.orientation)) if in_place else m.end
    if turn:
        w, x, y, z = end.frame.orientation
        tw, _, _, tz = yaw(turn)  # the turn about +z, composed on the left: q' = t * q
        q = tuple(to_f32(v) for v in (tw * w - tz * z, tw * x - tz * y, tw * y + tz * x, tw * z + tz * w))
        end = Position(end.cell, Frame(end.frame.origin, q))
    return scene.replace(mover=replace(m, end=end, free_heading=True), name=f"{scene.name}:free-heading")


# scene/8 `drawing`: the kinds whose DAT records have something drawn (BSP statics' GfxObjs, Environments and EnvCells,
# buildings' shells)
DRAWING_KINDS = ("bsp", "indoor", "buildings")


def draw_drawing_scene(draw, kinds=DRAWING_KINDS) -> Scene:
    """A transition scene (one of `kinds`, placed or not, as `scenes_of` draws it) whose DAT records carry what a
    client draws (scene/8 `drawing`; acconform/dat.py): every polygon its UV indices (a Clockwise one its negative
    ones too), a BSP GfxObj its drawing polygons, a drawing BSP (whose root sphere ACE's GfxObj makes its
    DrawingSphere), a surface and a degrade table, an EnvCell a surface; in the engine mode drawn as a placement's
    (a client-mode GfxObj makes its drawing polygons). No campaign kind draws it: a draw added to a kind would move
    every seeded sample the tests pin."""
    kind = draw(st.sampled_from(kinds))
    scene = with_placement(draw, draw_scene(draw, kind))
    return scene.replace(drawing=True, engine_mode=draw(dr.ENGINE_MODES), name=f"{scene.name}:drawing")


# a multipart static with more cylspheres than ObjCell.find_cell_list takes (it clamps numCylSphere to 10)
MANY_CYLSPHERE_COUNTS = st.sampled_from((11, 11, 12, 16))
MANY_CYLSPHERE_RADII = st.sampled_from((0.25, 0.5, 0.75, 1.0))
MANY_CYLSPHERE_OFFSETS = st.sampled_from((-2.0, -1.0, -0.5, 0.0, 0.5, 1.0, 2.0))


def draw_many_cylspheres_scene(draw) -> Scene:
    """A bsp scene of the multipart policy (a static made from a Setup of BSP parts, scene/7 `setup`) whose Setup has
    11 or more cylspheres, its state Static alone (no HasPhysicsBSP: the scene's state overwrites it, as WorldObject's
    does), so PhysicsObj.calc_cross_cells_static finds its cells by ObjCell.find_cell_list's cylsphere overload, which
    takes only the first 10 (numCylSphere > 10), and FindObjCollisions meets its cylspheres. No campaign kind draws it:
    a draw added to a kind would move every seeded sample the tests pin."""
    scene = with_placement(draw, draw_scene(draw, "bsp", "multipart"))
    objects = list(scene.objects)
    for i, o in enumerate(objects):
        if o.setup is None:
            continue
        n = draw(MANY_CYLSPHERE_COUNTS)
        cyls = tuple(CylSphereShape((draw(MANY_CYLSPHERE_OFFSETS), draw(MANY_CYLSPHERE_OFFSETS), 0.0),
                                    draw(MANY_CYLSPHERE_RADII), draw(MANY_CYLSPHERE_RADII) * 2) for _ in range(n))
        objects[i] = replace(o, setup=replace(o.setup, cylspheres=cyls), state=int(PhysicsState.Static))
        break
    return scene.replace(objects=tuple(objects), name=f"{scene.name}:many-cylspheres")
