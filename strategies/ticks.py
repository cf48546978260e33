"""Tick scenes: every kind's geometry with a timeline of ticks (issue 19; kind "ticks").

    draw_tick_scene(draw, world=None, policy=None)     a tick scene: a policy's geometry, a motion, a clock and a driver

A tick scene is one of the other kinds' scenes (strategies/scenes.py, strategies/dungeon.py,
strategies/buildings.py: the same terrain, BSP objects, obstacles, dungeons of EnvCells with statics
and houses) whose mover, instead of one transition from `begin` to `end`, is moved by ACE's per-tick update along that path. The
policy picks the geometry and what the ticks do there (`draw_tick_scene(draw, world)`: only the
policies and sites on one world, campaign kind ``ticks:<world>``):

- ``walk``: any kind's path, walked (a held velocity for as many ticks as the path takes, then
  coasting; root motion through the Sequence; or one push);
- ``fall``: off a ledge onto the floor below (BSP ledges outdoors, ledges, pits and drops indoors),
  or from the air;
- ``jump``: a jump arc (the `jump` input: HandleActionJump's physics) onto stairs, steps and lips;
- ``slide``: onto a terrain slope whose normal.z is FloorZ or LandingZ exactly or an ulp either side
  (boundaries.exact_terrain_targets), held there by gravity for many ticks;
- ``sled``: Sledding on a terrain slope whose normal.z is ACE's sledding threshold (0.99999536,
  calc_friction's `normal.z > SleddingFlatZ`) exactly or an ulp either side, at the sledding
  speeds (1.25 and 2.5 m/s exactly, and around);
- ``press``: into walls and corners (BSP walls, indoor walls, jambs and doorways), held for many ticks;
- ``cross``: a diagonal walk across a landblock corner (four landblocks);
- ``portal``: out of a dungeon through its portal to the outside, and back in through it;
- ``motion``: any world's path walked by the motion layer: the mover given a small motion table
  (cycles with root motion, links, modifiers, several framerates and speeds) and MoveToState keys
  (the tick input ``motion``: forward, backward, sidestep, turn, hold keys Run / None, speeds,
  stops), strategies/motion.py;
- ``velocity``: velocities at MaxVelocity and SmallVelocity exactly and an ulp either side, and
  at the squared speed nearest SmallVelocity's EPSILON test;
- through a house (strategies/buildings.py; ``walk`` walks any of its paths but a placement too):
  ``enter``, in at its door from outside (straight, at an angle, grazing a jamb, from across a
  border, past a static in the doorway; or out of it), by a held velocity, the Sequence's
  velocity or a push; ``porch``, out onto the porch and off its edge; ``cellar``, down the cellar
  stairs or over a hatch in the room's floor into the cellar below; ``shell``, along the outer
  walls and into the wall beside the door, the velocity held every tick. A porch or cellar walk
  has ticks enough for its whole path at the drawn speed and a second's fall (REACH_FALL), no
  root motion (its ground flags, kept each tick, would hold the mover up) and EdgeSlide mostly off.

Clocks (orthogonal to the policy): fixed steps of 30, 250, 60, 10 or 4 fps; irregular steps; or
steps exactly at MinQuantum (= TickRate), MaxQuantum and HugeQuantum and one double ulp either
side (also one float32 ulp either side, and sums the sub-step loop leaves exact). The clock's
arithmetic is the harness's (`Ticks.times()`: start + dt in double), so a quantum step is exact only
where the sum is: a double-ulp step is the first tick from a clock at 0, where ``deltaTime`` is dt
itself; float32-valued steps stay exact from a clock at 1000.

Drivers: `update_object` (the object path), or `request_pos` (the legacy player path) with a
RequestPos per tick along the path, in the cell that holds it. ACE throws NullReferenceException
when a RequestPos's cell differs from the one the transition leaves the mover in (set_current_pos
-> change_cell_server); such a scene is kept: ACE's error is its recorded answer.

Shrinking: the tick count, each irregular dt and each input are draws of their own that shrink
toward fewer ticks, a fixed 30 fps clock, no inputs after the first tick and the plainest policy
(``walk``); acconform/shrink.py shrinks a recorded tick scene likewise.
"""

from __future__ import annotations

import math
from dataclasses import replace

from hypothesis import strategies as st

from acconform.flags import PhysicsState, TransientState
from acconform.numerics import f32_bits, f32_from_bits, to_f32
from acconform.port.constants import (EPSILON, HUGE_QUANTUM, MAX_QUANTUM, MAX_VELOCITY, MIN_QUANTUM, SLEDDING_FLAT_Z,
                                      SMALL_VELOCITY, SMALL_VELOCITY_SQUARED)
from acconform.scene import IDENTITY, ContactPlane, Frame, Mover, PlaneRec, Position, Scene, TickStep, Ticks

from . import boundaries as bd
from . import draws as dr
from . import dungeon as dg
from . import terrain as tr
from .terrain import BLOCK, CELL, cell_of, split_global

# the plainest first: Hypothesis shrinks toward it
POLICY_NAMES = ("walk", "walk", "fall", "fall", "jump", "jump", "slide", "sled", "sled", "press", "press", "cross",
                "portal", "velocity", "velocity", "enter", "porch", "cellar", "shell", "motion", "motion")
POLICIES = st.sampled_from(POLICY_NAMES)
WALK_SITES = (("terrain", None), ("bsp", None), ("obstacles", None), ("indoor", None), ("buildings", None))
FALL_SITES = (("bsp", "ledge"), ("bsp", "ledge"), ("indoor", "ledge"), ("indoor", "pit"), ("indoor", "fall"),
              ("terrain", None), ("bsp", "slope"))
JUMP_SITES = (("bsp", "stairs"), ("bsp", "stairs"), ("indoor", "stairs"), ("indoor", "cross"), ("bsp", "ledge"),
              ("bsp", "seam"), ("obstacles", "sphere_contact"))
PRESS_SITES = (("bsp", "wall"), ("bsp", "wall"), ("indoor", "wall"), ("indoor", "doorway"), ("bsp", "touch"),
               ("obstacles", "tangent"), ("indoor", "static"))
# through a house (strategies/buildings.py): in at its door from outside (straight, at an angle,
# grazing a jamb; across a border; past a static in the doorway) or out of it; out onto its porch
# and off the edge; down its cellar (the stairs, or through a hatch in the room's floor); along
# its shell and into the wall beside the door
ENTER_SITES = (("buildings", "in"), ("buildings", "in"), ("buildings", "in"), ("buildings", "border"),
               ("buildings", "static"), ("buildings", "out"))
PORCH_SITES = (("buildings", "porch"),)
CELLAR_SITES = (("buildings", "hatch"), ("buildings", "hatch"), ("buildings", "cellar"))
SHELL_SITES = (("buildings", "along"), ("buildings", "along"), ("buildings", "wall"))
DOOR_SITES = (("obstacles", None), ("obstacles", None), ("terrain", None))  # strategies/doors.py
SITES = {"door": DOOR_SITES, "walk": WALK_SITES, "motion": WALK_SITES + FALL_SITES + JUMP_SITES, "fall": FALL_SITES, "jump": JUMP_SITES, "press": PRESS_SITES, "enter": ENTER_SITES,
         "porch": PORCH_SITES, "cellar": CELLAR_SITES, "shell": SHELL_SITES,
         # the policies drawing their own worlds: the worlds they draw on
         "slide": (("terrain", None),), "sled": (("terrain", None), ("bsp", None)), "cross": (("terrain", None),),
         "portal": (("indoor", None),), "velocity": (("terrain", None),)}
WORLDS = ("terrain", "bsp", "obstacles", "indoor", "buildings")
# off a porch's edge or into a cellar hatch: EdgeSlide (which stops the mover at the edge) mostly off
EDGE_SLIDE_KEPT = st.sampled_from(("off", "off", "off", "kept"))
# a walk through a house: any of its policies but a placement (a tick scene's mover starts where it is)
HOUSE_WALKS = st.sampled_from(("in", "out", "wall", "along", "porch", "cellar", "hatch", "border", "static"))


def _sites_over(world: str | None):
    """{policy: a strategy of its (world kind, world policy) sites}, all of them or those on `world`."""
    return {p: st.sampled_from(tuple(s for s in sites if world is None or s[0] == world)) for p, sites in SITES.items()
            if world is None or any(s[0] == world for s in sites)}


# per world (None: every world): the policies drawing on it, and each one's sites there
SITES_OVER = {w: _sites_over(w) for w in (None,) + WORLDS}
POLICIES_OVER = {None: POLICIES} | {w: st.sampled_from(tuple(p for p in POLICY_NAMES if p in SITES_OVER[w]))
                                    for w in WORLDS}

# ticks per scene: a few, a second or so, or two; mean about 27 (issue 19 asks for 20 or more)
TICK_COUNTS = dr.OneOf(dr.ints(1, 10), dr.ints(10, 40), dr.ints(20, 60), dr.ints(20, 60))
LONG_TICK_COUNTS = dr.OneOf(dr.ints(20, 40), dr.ints(40, 90))  # pressing and sliding: many ticks
REACH_FALL, REACH_MAX_TICKS = 1.0, 150  # off a porch, into a cellar: the path walked and a second to fall

# clocks
CLOCKS = st.sampled_from(("fps", "fps", "fps", "irregular", "quanta"))
FPS = st.sampled_from((30, 250, 60, 10, 4))
STARTS = st.sampled_from((1000.0, 0.0, 5000.0, 86400.0, 123456789.0))  # Timers.PortalYearTicks when made
IRREGULAR_DTS = dr.OneOf(st.sampled_from((1 / 30, 0.05, 0.1, 0.0, 0.02, 0.2, 0.5, 1 / 60, 0.25, 2.5)),
                         dr.floats(0.0, 0.3))


def _double_ulps(x: float) -> tuple[float, float, float]:
    x = float(x)
    return (x, math.nextafter(x, -math.inf), math.nextafter(x, math.inf))


def _f32_ulps(x: float) -> tuple[float, float]:
    b = f32_bits(x)
    return (float(f32_from_bits(b - 1)), float(f32_from_bits(b + 1)))


# (label, dt): the quanta as doubles, exactly and one double ulp either side (exact as the first
# tick's deltaTime from a clock at 0), one float32 ulp either side, and sums the sub-step loop
# leaves at a quantum (two and three MaxQuanta: the loop leaves exactly MaxQuantum; MaxQuantum plus
# MinQuantum: the remainder is exactly MinQuantum)
QUANTA: tuple[tuple[str, float], ...] = tuple(
    [(f"{name}{tag}", v) for name, c in (("min_quantum", MIN_QUANTUM), ("max_quantum", MAX_QUANTUM),
                                         ("huge_quantum", HUGE_QUANTUM))
     for tag, v in zip(("", "-1ulp", "+1ulp"), _double_ulps(c))]
    + [(f"{name}{tag}:f32", v) for name, c in (("min_quantum", MIN_QUANTUM), ("max_quantum", MAX_QUANTUM),
                                               ("huge_quantum", HUGE_QUANTUM))
       for tag, v in zip(("-1ulp", "+1ulp"), _f32_ulps(c))]
    + [("2max_quantum", 2 * float(MAX_QUANTUM)), ("3max_quantum", 3 * float(MAX_QUANTUM)),
       ("max_plus_min_quantum", float(MAX_QUANTUM) + float(MIN_QUANTUM))])
QUANTUM_PICK = dr.ints(0, len(QUANTA) - 1)
QUANTUM_AT = st.sampled_from(("first", "first", "every", "some"))

# the mover's Setup's DefaultScript (scene/8; 0 none), one scene in eight (strategies/objects.py DEFAULT_SCRIPTS)
DEFAULT_SCRIPTS = st.sampled_from((False,) * 7 + (True,))
SCRIPT_IDS = st.integers(0x33000001, 0x3300FFFF)  # PhysicsScript ids (portal DAT 0x33xxxxxx), which ACE never reads
# the mover's Setup's placement frame Resting (scene/8 `mover.resting_frame`; None: no placement frames), one
# scene in eight: PartArray.CreateSetup's SetPlacementFrame(0x65) finds it; its part then sits at that frame from the object's
_HALF_TURN_Z = (float(to_f32(0.70710677)), 0.0, 0.0, float(to_f32(0.70710677)))  # 90 degrees about z
RESTING_FRAMES = st.sampled_from((None,) * 14 + (Frame((0.0, 0.0, 0.0)), Frame((0.25, -0.125, 0.5), _HALF_TURN_Z)))
# the driver: the object path, now and then the legacy player path
DRIVERS = st.sampled_from(("update_object", "update_object", "update_object", "request_pos"))

# motion along a path
MOTIONS = st.sampled_from(("held", "held", "root", "push"))
# walking off an edge to fall: no root motion (its ground flags, kept each tick, hold the mover up)
FALL_MOTIONS = st.sampled_from(("held", "held", "held", "push"))
SPEEDS = dr.OneOf(st.sampled_from((3.0, 1.0, 4.0, 2.5, 1.25, 6.0, 11.0)), dr.f32(0.05, 12.0))
JUMP_UPS = dr.OneOf(st.sampled_from((6.0, 4.0, 2.0, 8.0, 10.0)), dr.f32(0.5, 12.0))
JUMP_FORWARD = dr.OneOf(st.sampled_from((2.0, 0.0, 4.0, 1.0)), dr.f32(0.0, 6.0))
JUMP_AT = dr.ints(0, 5)
OMEGAS = st.sampled_from((None, None, None, (0.0, 0.0, 1.0), (0.0, 0.0, -2.5)))

# slopes
SLIDE_TARGETS = st.sampled_from(bd.exact_terrain_targets())
SLED_SPEEDS = dr.OneOf(st.sampled_from((2.5, 1.25, 3.0, 2.0, 5.0)), st.sampled_from((
    float(f32_from_bits(f32_bits(2.5) - 1)), float(f32_from_bits(f32_bits(2.5) + 1)),
    float(f32_from_bits(f32_bits(1.25) - 1)), float(f32_from_bits(f32_bits(1.25) + 1)))), dr.f32(0.5, 8.0))
SLED_HEADINGS = st.sampled_from((0.0, 0.0, 180.0, 90.0, 45.0, 30.0))  # from down the slope
SLED_STATES = st.sampled_from(("sledding", "sledding", "sledding", "plain"))
SLOPE_STARTS = dr.f32(72.0, 120.0)
SIGNS = st.sampled_from((1, -1))
AXES = st.sampled_from(((1, 0), (-1, 0), (0, 1), (0, -1)))

# velocities at the tick's thresholds
_SV = float(SMALL_VELOCITY)
_EPS_SPEED = math.sqrt(float(SMALL_VELOCITY_SQUARED) + float(EPSILON))
VELOCITY_SPEEDS: tuple[tuple[str, float], ...] = (
    ("max_velocity", float(MAX_VELOCITY)),
    ("max_velocity-1ulp", float(f32_from_bits(f32_bits(MAX_VELOCITY) - 1))),
    ("max_velocity+1ulp", float(f32_from_bits(f32_bits(MAX_VELOCITY) + 1))),
    ("small_velocity", _SV),
    ("small_velocity-1ulp", float(f32_from_bits(f32_bits(_SV) - 1))),
    ("small_velocity+1ulp", float(f32_from_bits(f32_bits(_SV) + 1))),
) + tuple((f"small_velocity_epsilon{k:+d}", float(f32_from_bits(f32_bits(_EPS_SPEED) + k))) for k in (-1, 0, 1))
VELOCITY_PICK = dr.ints(0, len(VELOCITY_SPEEDS) - 1)
# a speed as a vector with the same squared length: along an axis, or (3, 4, 0) / 5 (exact in float32
# for the round speeds: 30-40-50)
VELOCITY_DIRECTIONS = st.sampled_from(("down", "x", "y", "345", "-x"))
VELOCITY_TICKS = dr.OneOf(dr.ints(1, 4), dr.ints(20, 40))


# ---------------------------------------------------------------- the clock

def _clock(draw, n: int) -> tuple[float, list[float], str]:
    """(start, n dts, label)."""
    how = draw(CLOCKS)
    if how == "fps":
        fps = draw(FPS)
        return draw(STARTS), [1.0 / fps] * n, f"{fps}fps"
    if how == "irregular":
        return draw(STARTS), [float(dr.take(draw, IRREGULAR_DTS)) for _ in range(n)], "irregular"
    name, q = QUANTA[draw(QUANTUM_PICK)]
    base = 1.0 / draw(FPS)
    at = draw(QUANTUM_AT)
    if at == "first":
        dts = [q] + [base] * (n - 1)
    elif at == "every":
        dts = [q] * n
    else:
        dts = [q if draw(dr.BOOLEANS) else base for _ in range(n)]
    # a double-ulp step is exact only near 0; a float32-valued one from 1000 too
    start = 0.0 if at == "first" or "ulp" in name and ":f32" not in name else draw(st.sampled_from((0.0, 1000.0)))
    return start, dts, f"quanta-{name}-{at}"


# ---------------------------------------------------------------- paths

def _global(scene: Scene, pos: Position) -> tuple[float, float, float]:
    b = pos.cell >> 16
    bx, by = b >> 8, b & 0xFF
    x, y, z = pos.frame.origin
    return bx * BLOCK + x, by * BLOCK + y, z


def _path(scene: Scene) -> tuple[tuple[float, float, float], tuple[float, float, float]]:
    """The base scene's path in global metres (begin, end)."""
    return _global(scene, scene.mover.begin), _global(scene, scene.mover.end)


def _unit(dx: float, dy: float) -> tuple[float, float]:
    h = math.hypot(dx, dy)
    return (dx / h, dy / h) if h > 0 else (1.0, 0.0)


def _vec(*v) -> tuple[float, float, float]:
    return tuple(to_f32(c) for c in v)


def _cell_at(scene: Scene, g) -> int | None:
    """The cell that holds a global point: an EnvCell whose cell BSP holds it, else the outdoor
    cell of a landblock the scene defines (None when there is none)."""
    bx, by, lx, ly = split_global(g[0], g[1])
    if scene.env_cells:
        envs = {e.id: e for e in scene.environments}
        for c in scene.env_cells:
            if c.id >> 16 != (bx << 8 | by):
                continue
            q, o = c.frame.orientation, c.frame.origin
            ang = -2 * math.atan2(q[3], q[0])
            dx, dy = lx - o[0], ly - o[1]
            local = (dx * math.cos(ang) - dy * math.sin(ang), dx * math.sin(ang) + dy * math.cos(ang), g[2] - o[2])
            if dg.point_inside(envs[c.environment].cell_structs[c.cell_structure].cell_bsp, local):
                return c.id
    block = (bx << 8 | by) << 16 | 0xFFFF
    if not any(lb.id == block for lb in scene.landblocks):
        return None
    return cell_of(bx, by, lx, ly)


def _request_positions(scene: Scene, n: int, g0, g1) -> list[Position]:
    """RequestPos per tick: evenly along the path (the last at its end), each in the cell that
    holds it (a point outside every defined landblock repeats the one before)."""
    out = []
    last = scene.mover.begin
    for i in range(n):
        t = (i + 1) / n
        g = tuple(a + (b - a) * t for a, b in zip(g0, g1))
        bx, by, lx, ly = split_global(g[0], g[1])
        cell = _cell_at(scene, (g[0], g[1], g[2]))
        if cell is not None:
            last = Position(cell, Frame((to_f32(lx), to_f32(ly), to_f32(g[2])), IDENTITY))
        out.append(last)
    return out


def _tick_scene(scene: Scene, start: float, dts: list[float], inputs: list[dict], driver: str,
                requests: list[Position] | None, name: str) -> Scene:
    steps = tuple(TickStep(dt, **inp, **({"request_pos": requests[i]} if requests else {}))
                  for i, (dt, inp) in enumerate(zip(dts, inputs)))
    m = scene.mover
    mover = replace(m, end=None, placement=None, transient_state=m.transient_state | int(TransientState.Active))
    return scene.replace(mover=mover, ticks=Ticks(driver, float(start), steps), name=name)


def _walk_inputs(draw, n: int, dts: list[float], g0, g1, motion: str,
                 speed: float | None = None) -> tuple[list[dict], str]:
    """Inputs moving the mover from g0 toward g1: a held velocity for the ticks the path takes at the
    drawn speed (then nothing: it coasts, falls, slides), root motion (a Sequence velocity, Active
    and the ground flags kept by the scene each tick, as a MovementManager would), or one push."""
    inputs = [{} for _ in range(n)]
    dx, dy, dz = (b - a for a, b in zip(g0, g1))
    ux, uy = _unit(dx, dy)
    length = math.hypot(dx, dy)
    speed = float(dr.take(draw, SPEEDS)) if speed is None else speed
    v = _vec(ux * speed, uy * speed, 0.0)
    if motion == "push" or length == 0.0:
        inputs[0]["velocity"] = v
        return inputs, "push"
    if motion == "root":
        inputs[0]["sequence_velocity"] = _vec(ux * speed, uy * speed, 0.0)
        omega = draw(OMEGAS)
        if omega is not None:
            inputs[0]["sequence_omega"] = omega
        keep = int(TransientState.Contact | TransientState.OnWalkable | TransientState.Active)
        for i in range(1, n):
            inputs[i]["transient_state"] = keep
        return inputs, "root"
    t, k = 0.0, 0
    while k < n and (t * speed < length or k == 0):
        inputs[k]["velocity"] = v
        t += dts[k]
        k += 1
    return inputs, f"held{k}"


def _driver_for(draw, scene: Scene, n: int, g0, g1) -> tuple[str, list[Position] | None]:
    driver = draw(DRIVERS)
    if driver == "update_object":
        return driver, None
    return driver, _request_positions(scene, n, g0, g1)


# ---------------------------------------------------------------- policies

def draw_tick_scene(draw, world: str | None = None, policy: str | None = None) -> Scene:
    """A tick scene; over `world` (a geometry kind: campaign kind ``ticks:<world>``) when given, of
    `policy` when given (one drawing on that world); in ACE's server mode three times in four, else
    client mode (dr.ENGINE_MODES)."""
    scene = _draw_tick_scene(draw, world, policy)
    script = draw(SCRIPT_IDS) if draw(DEFAULT_SCRIPTS) else 0
    if script:  # the mover's Setup's DefaultScript: a ScriptManager each update steps (UpdateScripts)
        scene = scene.replace(mover=replace(scene.mover, default_script=script))
    resting = draw(RESTING_FRAMES)
    if resting is not None:
        scene = scene.replace(mover=replace(scene.mover, resting_frame=resting))
    return scene.replace(engine_mode=draw(dr.ENGINE_MODES))


def _draw_tick_scene(draw, world: str | None, policy: str | None) -> Scene:
    from .scenes import draw_scene

    policy = policy or draw(POLICIES_OVER[world])
    if policy == "movers":  # other movers beside the mover, on their own flat ground or a house (strategies/movers.py)
        from .movers import draw_movers_ticks

        return draw_movers_ticks(draw, _clock)
    sites = SITES_OVER[world][policy]
    if policy == "sled":
        return _sled(draw, draw(sites)[0])
    if policy == "velocity":
        return _velocity(draw, draw_scene)
    if policy == "cross":
        return _walk(draw, _diagonal(draw), "cross", long=False)
    if policy == "slide":
        return _walk(draw, draw_scene(draw, "terrain", "exact_slope"), "slide", long=True)
    if policy == "portal":
        return _portal(draw, draw_scene(draw, "indoor", "outside"))
    kind, sub = draw(sites)
    if kind == "buildings" and sub is None:
        sub = draw(HOUSE_WALKS)
    base = draw_scene(draw, kind, sub)
    if policy in ("walk", "enter"):
        return _walk(draw, base, policy)
    if policy == "door":  # a door on the path opens or closes at a tick (strategies/doors.py)
        from .doors import draw_door_ticks

        return draw_door_ticks(draw, base, _clock)
    if policy == "motion":  # a motion table and MoveToState keys (strategies/motion.py)
        from .motion import draw_motion_queries, draw_motion_ticks

        return draw_motion_queries(draw, draw_motion_ticks(draw, base, _clock))
    if policy in ("porch", "cellar"):  # off the edge (EdgeSlide mostly off), long enough to fall and land
        m = base.mover
        if m.state & int(PhysicsState.EdgeSlide) and draw(EDGE_SLIDE_KEPT) == "off":
            base = base.replace(mover=replace(m, state=m.state & ~int(PhysicsState.EdgeSlide)),
                                name=base.name + ":no-edge-slide")
        return _walk(draw, base, policy, long=True, reach=True)
    if policy == "fall":
        return _walk(draw, base, policy)
    if policy in ("press", "shell"):
        return _walk(draw, base, policy, long=True, held_all=True)
    return _jump(draw, base)


def _walk(draw, base: Scene, label: str, long: bool = False, held_all: bool = False, reach: bool = False) -> Scene:
    """`reach`: ticks enough to walk the whole path at the drawn speed and fall for REACH_FALL seconds
    after it (the clock's last step repeated, up to REACH_MAX_TICKS ticks in all)."""
    n = dr.take(draw, LONG_TICK_COUNTS if long else TICK_COUNTS)
    start, dts, clock = _clock(draw, n)
    g0, g1 = _path(base)
    speed = None
    if reach:
        speed = float(dr.take(draw, SPEEDS))
        need = math.hypot(g1[0] - g0[0], g1[1] - g0[1]) / speed + REACH_FALL
        step = dts[-1] if dts[-1] > 0 else 1 / 30
        while sum(dts) < need and len(dts) < REACH_MAX_TICKS:
            dts.append(step)
        n = len(dts)
    if held_all:  # pressing: the velocity held every tick
        dx, dy = g1[0] - g0[0], g1[1] - g0[1]
        ux, uy = _unit(dx, dy)
        speed = float(dr.take(draw, SPEEDS))
        inputs = [{"velocity": _vec(ux * speed, uy * speed, 0.0)} for _ in range(n)]
        motion = "held-all"
    else:
        inputs, motion = _walk_inputs(draw, n, dts, g0, g1, draw(FALL_MOTIONS if reach else MOTIONS), speed)
    driver, requests = _driver_for(draw, base, n, g0, g1)
    name = f"ticks:{label}:{base.name}:{motion}:{clock}:{driver}"
    return _tick_scene(base, start, dts, inputs, driver, requests, name)


def _jump(draw, base: Scene) -> Scene:
    n = dr.take(draw, TICK_COUNTS)
    start, dts, clock = _clock(draw, n)
    g0, g1 = _path(base)
    ux, uy = _unit(g1[0] - g0[0], g1[1] - g0[1])
    fwd, up = float(dr.take(draw, JUMP_FORWARD)), float(dr.take(draw, JUMP_UPS))
    inputs = [{} for _ in range(n)]
    at = min(draw(JUMP_AT), n - 1)
    # the mover's orientation is the identity: its local frame is the landblock's
    inputs[at]["jump"] = _vec(ux * fwd, uy * fwd, up)
    driver, requests = "update_object", None
    return _tick_scene(base, start, dts, inputs, driver, requests, f"ticks:jump:{base.name}:at{at}:{clock}")


def _portal(draw, base: Scene) -> Scene:
    """Out of the dungeon through its portal to the outside, then back in the way it came."""
    n = dr.take(draw, LONG_TICK_COUNTS)
    start, dts, clock = _clock(draw, n)
    g0, g1 = _path(base)
    dx, dy = g1[0] - g0[0], g1[1] - g0[1]
    ux, uy = _unit(dx, dy)
    speed = float(dr.take(draw, SPEEDS))
    half = n // 2
    inputs = [{"velocity": _vec(ux * speed, uy * speed, 0.0)} if i < half else
              {"velocity": _vec(-ux * speed, -uy * speed, 0.0)} for i in range(n)]
    driver, requests = _driver_for(draw, base, n, g0, g1)
    if requests:
        back = list(reversed(requests[:half])) + [base.mover.begin] * (n - 2 * half)
        requests = requests[:half] + back[: n - half]
    return _tick_scene(base, start, dts, inputs, driver, requests, f"ticks:portal:{base.name}:{clock}:{driver}")


def _velocity(draw, draw_scene) -> Scene:
    """A velocity at a tick threshold, set on the first tick: down onto the ground from the air,
    or along the ground; a few ticks at 50 m/s along it (to stay on the scene's landblocks)."""
    base = draw_scene(draw, "terrain", "free")
    label, speed = VELOCITY_SPEEDS[draw(VELOCITY_PICK)]
    how = draw(VELOCITY_DIRECTIONS)
    f = to_f32
    if how == "down":
        v = (0.0, 0.0, -speed)
    elif how == "x":
        v = (speed, 0.0, 0.0)
    elif how == "-x":
        v = (-speed, 0.0, 0.0)
    elif how == "y":
        v = (0.0, speed, 0.0)
    else:  # 3-4-5: exact for 50 (30, 40) and 0.25 (0.15, 0.2 round, but the sum is what ACE squares)
        v = (f(speed * 0.6), f(speed * 0.8), 0.0)
    fast = speed > 1.0 and how != "down"
    if fast:  # 50 m/s along the ground: a few ticks of at most MaxQuantum (5 m a tick)
        n = min(dr.take(draw, VELOCITY_TICKS), 3)
        fps = max(draw(FPS), 10)
        start, dts, clock = draw(STARTS), [1.0 / fps] * n, f"{fps}fps"
    else:
        n = dr.take(draw, TICK_COUNTS)
        start, dts, clock = _clock(draw, n)
    inputs = [{} for _ in range(n)]
    inputs[0]["velocity"] = tuple(float(f(c)) for c in v)
    return _tick_scene(base, start, dts, inputs, "update_object", None,
                       f"ticks:velocity-{label}-{how}:{base.name}:{clock}")


def _diagonal(draw) -> Scene:
    """Terrain around a landblock corner, the mover a few metres from it heading across it
    diagonally (four landblocks)."""
    from .scenes import HOME, MOVER_SPHERES, _World, _scene, step_heights, STEP_UP_SITE, STEP_DOWN_SITE
    from . import objects as ob

    bx, by = draw(HOME)
    # the corner at (bx + 1, by + 1) * BLOCK, approached from inside the home block
    back = dr.take(draw, CROSS_BACK)
    heading = 45.0 + draw(CROSS_JITTER)
    rad = math.radians(heading)
    gc = ((bx + 1) * BLOCK, (by + 1) * BLOCK)
    gx0, gy0 = gc[0] - back * math.cos(rad), gc[1] - back * math.sin(rad)
    field = tr.field_near(draw, round(gx0 / CELL), round(gy0 / CELL))
    world = _World(field)
    spheres = draw(MOVER_SPHERES)
    r = spheres[0].radius
    past = dr.take(draw, CROSS_PAST)
    gx1, gy1 = gc[0] + past * math.cos(rad), gc[1] + past * math.sin(rad)
    hbx, hby, lx, ly = split_global(gx0, gy0)
    lx, ly = to_f32(lx), to_f32(ly)
    _, (z0, n0, d0) = world.ground(hbx * BLOCK + lx, hby * BLOCK + ly)
    cell = cell_of(hbx, hby, lx, ly)
    walkable = n0[2] >= tr.FLOOR_Z
    transient = int(TransientState.Contact) | (int(TransientState.OnWalkable) if walkable else 0)
    _, (z1, _, _) = world.ground(gx1, gy1)
    ebx, eby, elx, ely = split_global(gx1, gy1)
    steps = step_heights([r * t for t in (0.5, 1.0, 1.5)])
    mover = Mover(spheres=spheres, begin=Position(cell, Frame((lx, ly, to_f32(z0)))),
                  end=Position(cell_of(ebx, eby, elx, ely), Frame((to_f32(elx), to_f32(ely), to_f32(z1)))),
                  step_up_height=dr.one_of(draw, STEP_UP_SITE, *steps),
                  step_down_height=dr.one_of(draw, STEP_DOWN_SITE, ob.radius_to_diameter(r), *steps),
                  state=int(PhysicsState.Gravity) | (int(PhysicsState.EdgeSlide) if draw(dr.BOOLEANS) else 0),
                  transient_state=transient, contact_plane=ContactPlane(cell, PlaneRec(n0, d0)))
    reach = max(s.center[2] + s.radius for s in spheres)
    return _scene(world, hbx, hby, (gx0, gy0), (gx1, gy1), reach, [], mover, "terrain:diagonal")


CROSS_BACK = dr.OneOf(st.sampled_from((2.0, 1.0, 4.0)), dr.f32(0.2, 6.0))
CROSS_PAST = dr.OneOf(st.sampled_from((2.0, 1.0, 4.0)), dr.f32(0.2, 6.0))
CROSS_JITTER = st.sampled_from((0.0, 0.0, 0.0, 10.0, -10.0, 30.0, -30.0))


def _sled(draw, world: str = "terrain") -> Scene:
    """Sledding (or a plain mover, for comparison) down a slope whose normal.z is ACE's sledding
    threshold exactly or an ulp either side -- a BSP wedge (boundaries.SLED_WEDGES), or a one-cell
    terrain rise at the threshold itself (boundaries.SLED_TERRAIN_RISE) -- or over flat ground
    (normal.z 1: glides), pushed at a sledding speed (1.25 and 2.5 m/s exactly and an ulp either
    side, and around) on the first tick, for many ticks."""
    from .scenes import draw_scene

    where = "wedge" if world == "bsp" else draw(SLED_WHERE)
    if where == "wedge":
        base = draw_scene(draw, "bsp", "sled_slope")
    else:
        base = _sled_terrain(draw, where == "terrain")
    g0, g1 = _path(base)
    ux, uy = _unit(g1[0] - g0[0], g1[1] - g0[1])
    speed = float(dr.take(draw, SLED_SPEEDS))
    n = dr.take(draw, LONG_TICK_COUNTS)
    start, dts, clock = _clock(draw, n)
    sledding = draw(SLED_STATES) == "sledding"
    m = base.mover
    state = (m.state | int(PhysicsState.Sledding)) if sledding else m.state
    base = base.replace(mover=replace(m, state=state))
    inputs = [{} for _ in range(n)]
    inputs[0]["velocity"] = _vec(ux * speed, uy * speed, 0.0)
    label = "sled" if sledding else "slope"
    return _tick_scene(base, start, dts, inputs, "update_object", None, f"ticks:{label}:{base.name}:{clock}")


SLED_WHERE = st.sampled_from(("terrain", "flat"))  # on a BSP wedge: the world bsp


def _sled_terrain(draw, sloped: bool) -> Scene:
    """Terrain flat, or with one cell rising by boundaries.SLED_TERRAIN_RISE (normal.z exactly the
    sledding threshold); the mover on it, heading down (or across) it."""
    from .scenes import HOME, MOVER_SPHERES, _World, _scene

    bx, by = draw(HOME)
    ax, ay = draw(AXES)  # the slope descends toward (ax, ay)
    lx, ly = draw(SLOPE_STARTS), draw(SLOPE_STARTS)
    gx, gy = bx * BLOCK + lx, by * BLOCK + ly
    table = bd.exact_slope_table(bd.SLED_TERRAIN_RISE) if sloped else None
    features = ()
    if sloped:
        # the slope is the cell between vertex lines a*x + b*y = c - 1 and c, (a, b) = -(ax, ay): the mover's
        vx, vy = math.floor(gx / CELL), math.floor(gy / CELL)
        c = -(ax * (vx + max(-ax, 0)) + ay * (vy + max(-ay, 0)))
        features = (tr.Feature("step", a=-ax, b=-ay, c=c, k=1),)
    world = _World(tr.Field(0, features, 0, 0, draw(tr.LAND)))
    spheres = draw(MOVER_SPHERES)
    cell = cell_of(bx, by, lx, ly)
    lb = world.block(bx, by)
    z0, n0, d0 = tr.ground(lb, lx, ly, table) if table else tr.ground(lb, lx, ly)
    heading = math.degrees(math.atan2(ay, ax)) + draw(SLED_HEADINGS)
    rad = math.radians(heading)
    travel = 40.0
    gx1, gy1 = gx + travel * math.cos(rad), gy + travel * math.sin(rad)
    ebx, eby, elx, ely = split_global(gx1, gy1)
    mover = Mover(spheres=spheres, begin=Position(cell, Frame((lx, ly, to_f32(z0)))),
                  end=Position(cell_of(ebx, eby, elx, ely), Frame((to_f32(elx), to_f32(ely), to_f32(z0)))),
                  step_up_height=to_f32(0.4), step_down_height=to_f32(0.4), state=int(PhysicsState.Gravity),
                  transient_state=int(TransientState.Contact | TransientState.OnWalkable),
                  contact_plane=ContactPlane(cell, PlaneRec(n0, d0)))
    reach = max(s.center[2] + s.radius for s in spheres)
    scene = _scene(world, bx, by, (gx, gy), (gx1, gy1), reach, [], mover,
                   "terrain:sled-" + ("sledding-flat-z" if sloped else "flat"))
    return scene.replace(land_height_table=table) if table else scene
