"""Several movers (issue 41; campaign kind ``movers``, the ticks policy ``movers``): tick scenes with one to
three other moving objects (scene/8 ``others``) beside the mover, entered into the world after it
(enter_world) and stepped after it each tick.

    draw_movers_ticks(draw, clock)     a tick scene of a drawn MOVER_POLICIES entry

The world is flat ground (strategies/buildings.py's flat landblocks: the home block, and for a meeting at a
landblock border its neighbours toward -x and -y), or a house of strategies/buildings.py. The policies:

- ``head_on``: the mover and another walk into each other along one line; ``side_on``: the other crosses the
  mover's path at right angles, timed to reach the crossing when the mover does (or a little off);
- ``corner``: both walk along the two faces of a BSP box toward the corner they share, out of each other's
  sight, or the mover waits at a house's corner (buildings "along") while the other comes along its front;
- ``chase``: a monster (or an NPC) chases the mover, its velocity aimed each tick at where the mover's held
  velocity puts it; ``doorway``: the same through a doorway of two static slabs with a gap between them;
- ``touch``: the mover and another at rest, their spheres exactly touching (the centre distance the radius
  sum as float32, or ACE's radsum, the sum less EPSILON; or one ulp either side), placed on a 2^-16 grid
  so the distance is exact; ``approach``: one walks by root motion on an exact grid (dt 1/16, 3/32, 5/64 s,
  a speed whose step is exact) toward the other standing where that distance is met exactly at a drawn tick;
- ``jump``: a player (the mover, or another player) jumps onto or over another standing ahead;
- ``carry``: the mover, or another mover (a monster, a player, an NPC), carries one or two children (scene/8
  ``others[].parent``: small objects, a sorting sphere or none) at holding locations of its Setup -- past its
  parts (in its Position, the common case), by part 0, or at a location it lacks (set_parent refuses it) -- and
  walks, turns, jumps, crosses a cell or landblock border, walks into a wall or into another mover.

Across policies: the pair's weenies (player/player in every PlayerKillerStatus combination: two players
whose statuses exempt them pass through each other, FindObjCollisions; player/monster, player/creature,
player/object), one or two spheres, scaled others, velocity / local_velocity / root-motion inputs, an other
(or the mover) turning Ethereal at a tick (`state`) and back, bystanders (up to three others in all), the
ticks strategies' clocks (strategies/ticks.py _clock) but where the policy needs an exact grid, and
ACE's server mode three times in four. Players' ids from 0x50000002 (0x50000001 is the mover's), the
others' from 0x80000001.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
from hypothesis import strategies as st

from acconform.flags import ParentLocation, PhysicsState, PlayerKillerStatus, TransientState
from acconform.numerics import f32_bits, f32_from_bits, to_f32
from acconform.port.constants import EPSILON
from acconform.scene import (IDENTITY, ChildOf, ContactPlane, Frame, HoldingLocation, Mover, OtherInputs, OtherMover,
                             Placement, PlaneRec, Position, Scene, SphereRec, StaticObject)

from . import buildings as bl
from . import draws as dr
from . import shapes as sh
from .terrain import BLOCK, CELL

POLICY_NAMES = ("head_on", "head_on", "side_on", "side_on", "corner", "chase", "chase", "doorway", "touch", "touch",
                "approach", "approach", "jump", "jump", "carry", "carry")
POLICIES = st.sampled_from(POLICY_NAMES)

FIRST_PLAYER, FIRST_OBJECT = 0x50000002, 0x80000001
WALKING = int(TransientState.Contact | TransientState.OnWalkable | TransientState.Active)
STATIC_BSP = int(PhysicsState.Static | PhysicsState.HasPhysicsBSP)
NPK = int(PlayerKillerStatus.NPK)

# the pair: who the other is, and the players' PlayerKillerStatus (every member of ACE's enum, the
# ones FindObjCollisions reads -- NPK, PK, PKLite, Free -- most often)
WEENIES = st.sampled_from(("player", "player", "player", "monster", "monster", "creature", "object"))
PKS = dr.OneOf(st.sampled_from(tuple(int(s) for s in (PlayerKillerStatus.NPK, PlayerKillerStatus.NPK, PlayerKillerStatus.PK,
                                                      PlayerKillerStatus.PKLite, PlayerKillerStatus.Free))),
               st.sampled_from(tuple(int(s) for s in PlayerKillerStatus)))
CREATURE_PKS = st.sampled_from(("npk", "npk", "npk", "drawn"))

# bodies
RADII = dr.OneOf(st.sampled_from((0.48, 0.35, 0.5, 0.3, 1.0)), dr.f32(0.2, 1.2))
TWO_SPHERES = st.sampled_from((False, False, True))
HEAD_HEIGHTS = st.sampled_from((1.0, 1.6, 2.0, 0.5))
SCALES = st.sampled_from(tuple(to_f32(x) for x in (1.0, 1.0, 1.0, 1.0, 1.0, 0.5, 2.0, 1.5, 0.8)))
EXACT_SCALES = st.sampled_from((1.0, 1.0, 1.0, 1.0, 0.5, 2.0))  # powers of two: a scaled radius stays exact
STEPS = st.sampled_from(tuple(to_f32(x) for x in (0.4, 0.4, 0.2, 0.6, 1.0, 0.0)))

# motion
SPEEDS = dr.OneOf(st.sampled_from((3.0, 1.0, 4.0, 2.5, 6.0)), dr.f32(0.5, 8.0))
INPUT_KINDS = st.sampled_from(("velocity", "velocity", "velocity", "local", "root"))
HOLDS = st.sampled_from(("all", "all", "all", "stop"))
WALK_LIMIT = 40.0  # metres a walk holds its velocity for: from 30 m off a block's middle it stays in the block
TICK_COUNTS = dr.OneOf(dr.ints(20, 40), dr.ints(40, 90), dr.ints(5, 20))
GAPS = dr.OneOf(st.sampled_from((2.0, 4.0, 1.0, 6.0)), dr.f32(0.2, 10.0))
TIMING = st.sampled_from((0.0, 0.0, 0.0, 0.5, -0.5, 1.5, -1.5))  # metres off a timed meeting
MAX_LEAD = 20.0  # the other starts at most this far from the meeting (a slow mover's is not waited for)
WHERE = st.sampled_from(("middle", "middle", "middle", "middle", "cell", "cell", "block", "corner"))
HEADINGS = dr.OneOf(st.sampled_from((0.0, 90.0, 180.0, 270.0, 45.0)), dr.ints(0, 359))
NEAR = dr.f32(-3.0, 3.0)
EXTRAS = st.sampled_from((0, 0, 0, 1, 1, 2))
EXTRA_KINDS = st.sampled_from(("stand", "stand", "cross", "follow"))
EXTRA_GAPS = st.sampled_from((0.0, 0.1, 0.5, 1.0, 2.0))
ETHEREAL_AT = st.sampled_from((None, None, None, None, "other", "other", "mover"))

# corners
BOX_SIDES = dr.OneOf(st.sampled_from((2.0, 4.0, 1.0)), dr.f32(0.5, 6.0))
BOX_YAWS = st.sampled_from((0.0, 0.0, 90.0, 45.0, 30.0, 200.0))
LANE_GAPS = st.sampled_from((0.0, 0.01, 0.1, 0.3, 1.0))
CORNER_SITES = st.sampled_from(("box", "box", "box", "house"))
HOUSE_WAITS = st.sampled_from(("all", "all", "some", "none"))

# chases
CHASE_LEADS = dr.OneOf(st.sampled_from((3.0, 5.0, 1.5)), dr.f32(0.5, 10.0))
CHASE_LATERAL = st.sampled_from((0.0, 0.0, 1.0, -1.0, 2.5, -2.5))
CHASE_FASTER = st.sampled_from((1.5, 1.2, 2.0, 1.0))
TARGET_SPEEDS = st.sampled_from((2.0, 3.0, 1.0, 0.0, 4.0))
CHASERS = st.sampled_from(("monster", "monster", "monster", "creature"))
DOOR_SLACK = dr.OneOf(st.sampled_from((0.2, 0.05, 0.5, 1.0, 0.01)), dr.f32(0.0, 2.0))
DOOR_AHEAD = dr.OneOf(st.sampled_from((2.0, 4.0, 1.0)), dr.f32(0.5, 6.0))
SLAB_WIDTHS = st.sampled_from((2.0, 3.0, 1.0))
SLAB_THICKNESS = st.sampled_from((0.2, 0.5, 0.1))
DOORWAY_ID = 0x7D000011

# exact touches
GRID = 2.0 ** -16  # coordinates and radii on it: a sum of two stays exact below 256
TOUCHES = st.sampled_from(("sum", "sum", "sum-1ulp", "sum+1ulp", "ace", "ace", "ace-1ulp", "ace+1ulp"))
EXACT_RADII = st.sampled_from((0.48, 0.5, 0.35, 0.3, 0.75, 1.0, 0.4375))
AXES = st.sampled_from(((1, 0), (-1, 0), (0, 1), (0, -1)))
HALF_TURN = (0.0, 0.0, 0.0, 1.0)
EXACT_DTS = st.sampled_from((1 / 16, 3 / 32, 5 / 64))  # binary fractions in [MinQuantum, MaxQuantum]
EXACT_SPEEDS = st.sampled_from((2.0, 3.0, 1.0, 1.5, 4.0, 2.5))
EXACT_STARTS = st.sampled_from((1000.0, 0.0, 5000.0))
MEET_AT = dr.ints(1, 20)
APPROACHERS = st.sampled_from(("mover", "mover", "other"))

# jumps
JUMP_UPS = dr.OneOf(st.sampled_from((6.0, 8.0, 4.0, 10.0)), dr.f32(2.0, 12.0))
JUMP_FORWARD = dr.OneOf(st.sampled_from((2.0, 3.0, 4.0, 1.0)), dr.f32(0.0, 6.0))
JUMP_AHEAD = dr.OneOf(st.sampled_from((1.0, 1.5, 0.5, 2.0)), dr.f32(0.0, 4.0))
JUMP_AT = dr.ints(0, 4)
JUMPERS = st.sampled_from(("mover", "mover", "other"))

# carries: who holds, what it does, where; each child's holding location: past the holder's parts (the frame in its
# Position: the common case), by part 0 (a server never moves it: the frame is in landblock coordinates), or one
# the holder's Setup lacks (set_parent refuses it: GeneralFailure)
CARRIERS = st.sampled_from(("mover", "mover", "mover", "monster", "monster", "player", "creature"))
CARRY_MOVES = st.sampled_from(("walk", "walk", "walk", "turn", "turn", "jump", "wall", "bump", "bump", "stand"))
CARRY_WHERE = st.sampled_from(("middle", "middle", "middle", "cell", "cell", "block"))
CROSS_HEADINGS = st.sampled_from((0.0, 180.0, 0.0, 180.0, 10.0, 190.0, 165.0, -20.0))  # across x = const borders
CHILD_COUNTS = st.sampled_from((1, 1, 1, 2))
HOLDS_AT = st.sampled_from(("position", "position", "position", "position", "position", "part0", "missing"))
SECOND_HOLDER = st.sampled_from(("same", "same", "same", "mover"))  # a second child of another holder: the mover's
PAST_PARTS = st.sampled_from((1, 1, 1, 1, 2, 5, 255))  # the Setup has one part: any of these is past it
LOCATIONS = st.sampled_from(tuple(int(p) for p in ParentLocation if p) + (1, 1, 2, 3, 0, 12, 40, 255))
PLACEMENTS = st.sampled_from((0, 0, 0, 0, 0, 1, 2, 3, 13, 101))
HOLD_XY = dr.OneOf(st.sampled_from((0.4, 0.0, -0.4, 0.1, 0.25, -0.3, 1.0)), dr.f32(-1.5, 1.5))
HOLD_Z = dr.OneOf(st.sampled_from((1.0, 0.5, 1.2, 0.0, -0.2)), dr.f32(-0.5, 2.0))
HOLD_TURNS = st.sampled_from(((1.0, 0.0, 0.0, 0.0), (1.0, 0.0, 0.0, 0.0), (0.70710677, 0.0, 0.0, 0.70710677),
                              (0.0, 0.0, 0.0, 1.0), (0.70710677, 0.70710677, 0.0, 0.0), (0.5, 0.5, 0.5, 0.5),
                              (0.9238795, 0.0, 0.38268343, 0.0), "drawn"))
QUAT_PARTS = dr.f32(-1.0, 1.0)
PART_FRAMES = st.sampled_from(("origin", "origin", "origin", "start"))  # by part 0: near its landblock's origin, or the start
EXTRA_LOCATION = st.sampled_from((False, False, True))  # a holding location no child is held at
CHILD_WEENIES = st.sampled_from(("object", "object", "object", "object", "object", "creature", "monster"))
CHILD_RADII = st.sampled_from((0.1, 0.05, 0.2, 0.3))
SORTING = st.sampled_from(((0.0, 0.5, 0.6), (0.0, 0.5, 0.6), (0.0, 0.0, 0.3), (0.2, 0.3, 1.0), (0.0, 0.0, 0.0), None))
CARRY_OMEGAS = st.sampled_from((1.5, -1.0, 3.0, 0.5, -2.5))
CARRY_SPEEDS = st.sampled_from((0.0, 0.5, 1.0))  # a turning holder's walk
CARRY_WALL_ID = 0x7D000031
# a held child moved at a tick, as the client does when the server moves a wielded item (scene/8 tick inputs
# others[].unparent / .parent): none, dropped (unset_parent), dropped and picked up again, moved to another
# location of its holder, handed to the other holder; the old holder stands from then on, or moves on (a holder that
# lost a child throws at its next move within a cell: ChildList.RemoveChild leaves NumObjects one too high)
# a child held by part 0 or at a missing location whose drawn Placement is one of these is attached by the frame
# form instead, set_parent(holder, part, frame) (the client's call for an object attached to a part,
# ParticleEmitter.SetParenting; no placement frame): part 0 with the holding frame drawn for it, or part 1, past
# the Setup's one part, which add_child refuses. Picked from a draw made already: no draw of its own.
FRAME_FORM_PLACEMENTS = (13, 101)
HANDINGS = st.sampled_from(("none", "none", "drop", "drop-pick", "other-hand", "hand-over", "hand-over"))
HANDING_STOPS = st.sampled_from((True, True, True, False))
HIDDEN_TAKERS = st.sampled_from((False, False, False, True))  # the new holder is Hidden (set_parent: NoDraw)


# ---------------------------------------------------------------- bodies, ids, the world

class _Ids:
    def __init__(self):
        self.player, self.object = FIRST_PLAYER, FIRST_OBJECT

    def take(self, weenie: str) -> int:
        if weenie == "player":
            self.player += 1
            return self.player - 1
        self.object += 1
        return self.object - 1


def _spheres(draw, r: float | None = None) -> tuple[SphereRec, ...]:
    r = to_f32(r if r is not None else dr.take(draw, RADII))
    out = [SphereRec((0.0, 0.0, r), r)]
    if draw(TWO_SPHERES):
        out.append(SphereRec((0.0, 0.0, to_f32(r + r * draw(HEAD_HEIGHTS))), r))
    return tuple(out)


def _pks(draw, weenie: str) -> int:
    if weenie == "player" or (weenie in ("monster", "creature") and draw(CREATURE_PKS) == "drawn"):
        return int(dr.take(draw, PKS))
    return NPK


def _heading_quat(ux: float, uy: float):
    """The yaw that turns the local +y (an object's forward) onto (ux, uy)."""
    h = math.atan2(-ux, uy) / 2
    return (to_f32(math.cos(h)), 0.0, 0.0, to_f32(math.sin(h)))


def _unit(dx: float, dy: float) -> tuple[float, float]:
    h = math.hypot(dx, dy)
    return (dx / h, dy / h) if h > 0 else (1.0, 0.0)


def _vec(*v):
    return tuple(to_f32(c) for c in v)


class _Flat:
    """Flat ground at a height index of the default table: the home block (and its -x, -y neighbours)."""

    def __init__(self, draw, neighbours: bool):
        self.home = draw(bl.HOME_BLOCKS)
        index = draw(bl.GROUND_INDEX)
        self.z = to_f32(2.0 * index)
        self.landblocks = bl._landblocks(self.home, index, neighbours)

    def position(self, x: float, y: float, q=IDENTITY) -> Position:
        """A point of the home block's frame (past its -x / -y edges: the neighbours) on the ground."""
        return bl._outdoor_position(self.home, (to_f32(x), to_f32(y), self.z), q)


def _meeting_point(draw, world_where: str) -> tuple[float, float]:
    if world_where == "cell":
        return 4 * CELL + draw(st.sampled_from((0.0, 0.5, -0.5, 1.0))), 96.0 + float(draw(NEAR))
    if world_where == "block":
        return draw(st.sampled_from((0.0, 0.5, -0.5, 1.5))), 96.0 + float(draw(NEAR))
    if world_where == "corner":
        return draw(st.sampled_from((0.0, 0.5, -0.5))), draw(st.sampled_from((0.0, 0.5, -0.5)))
    return 96.0 + float(draw(NEAR)) * 10, 96.0 + float(draw(NEAR)) * 10


def _mover(draw, spheres, begin: Position, z: float, pks: int, scale: float = 1.0) -> Mover:
    plane = ContactPlane(begin.cell, PlaneRec((0.0, 0.0, 1.0), to_f32(-z)))
    return Mover(spheres=spheres, begin=begin, end=None, step_up_height=to_f32(draw(STEPS)),
                 step_down_height=to_f32(draw(STEPS)), scale=scale,
                 state=int(PhysicsState.Gravity) | (int(PhysicsState.EdgeSlide) if draw(dr.BOOLEANS) else 0),
                 transient_state=WALKING, contact_plane=plane, placement=Placement(via="enter_world"),
                 player_killer_status=pks)


def _other(draw, ids: _Ids, weenie: str, spheres, begin: Position, scale: float = 1.0, pks: int | None = None) -> OtherMover:
    return OtherMover(ids.take(weenie), weenie, spheres, begin, to_f32(draw(STEPS)), to_f32(draw(STEPS)), scale=scale,
                      transient_state=WALKING, player_killer_status=_pks(draw, weenie) if pks is None else pks)


# ---------------------------------------------------------------- inputs

class _Timeline:
    """Per-tick inputs of the mover (dicts of TickStep fields) and of each other mover (dicts of OtherInputs fields)."""

    def __init__(self, dts: list[float]):
        self.n = n = len(dts)
        self.dts = dts
        self.mover = [{} for _ in range(n)]
        self.others: dict[int, list[dict]] = {}

    def of(self, oid: int) -> list[dict]:
        return self.others.setdefault(oid, [{} for _ in range(self.n)])

    def walk(self, draw, inputs: list[dict], ux: float, uy: float, speed: float, kind: str | None = None,
             hold: str | None = None, first: int = 0, limit: float = WALK_LIMIT) -> str:
        """Walk toward (ux, uy) at `speed` from tick `first`: a held velocity, a held local velocity (the body faces
        its heading: see `facing`), or root motion (the Sequence's velocity, set once; the ground flags kept);
        held every tick, or stopped at a drawn tick, and stopped once `limit` metres are walked (the scene's
        landblocks end). Returns the kind."""
        kind = kind or draw(INPUT_KINDS)
        hold = hold or draw(HOLDS)
        stop = self.n if hold == "all" else draw(st.integers(first, self.n - 1))
        walked = 0.0
        for i in range(first, stop):
            walked += speed * self.dts[i]
            if walked > limit:
                stop = i + 1
                break
        for i in range(first, stop):
            if kind == "velocity":
                inputs[i]["velocity"] = _vec(ux * speed, uy * speed, 0.0)
            elif kind == "local":
                inputs[i]["local_velocity"] = _vec(0.0, speed, 0.0)
            else:
                if i == first:
                    inputs[i]["sequence_velocity"] = _vec(0.0, speed, 0.0)
                inputs[i]["transient_state"] = WALKING
        if stop < self.n:
            if kind == "root":
                inputs[stop]["sequence_velocity"] = (0.0, 0.0, 0.0)
            else:
                inputs[stop]["velocity"] = (0.0, 0.0, 0.0)
        return kind if hold == "all" else f"{kind}-stop"

    def steps_inputs(self, others: tuple[OtherMover, ...]) -> list[dict]:
        out = []
        for i in range(self.n):
            inp = dict(self.mover[i])
            row = tuple(OtherInputs(o.id, **self.others[o.id][i]) for o in others
                        if o.id in self.others and self.others[o.id][i])
            if row:
                inp["others"] = row
            out.append(inp)
        return out


def facing(kind: str, ux: float, uy: float):
    """The orientation a body walking toward (ux, uy) starts with: its heading for local and root inputs."""
    return _heading_quat(ux, uy) if kind in ("local", "root") else IDENTITY


def _ethereal(draw, tl: _Timeline, scene_mover: Mover, others: tuple[OtherMover, ...]) -> str:
    """Maybe an other (or the mover) turns Ethereal at a drawn tick, and half the time back later."""
    who = draw(ETHEREAL_AT)
    if who is None or (who == "other" and not others) or tl.n < 2:
        return ""
    k = draw(st.integers(0, tl.n - 1))
    back = draw(st.integers(k + 1, tl.n - 1)) if k + 1 < tl.n and draw(dr.BOOLEANS) else None
    if who == "mover":
        rows, state = tl.mover, scene_mover.state
    else:
        o = others[dr.index(draw, len(others))]
        rows, state = tl.of(o.id), o.state
    rows[k]["state"] = state | int(PhysicsState.Ethereal)
    if back is not None:
        rows[back]["state"] = state
    return f":ethereal-{who}" + ("-back" if back is not None else "")


# ---------------------------------------------------------------- the scene

def _finish(draw, clock_start, dts, tl: _Timeline, world_landblocks, mover: Mover, others, objects, name,
            buildings=(), environments=(), env_cells=(), ethereal: bool = True) -> Scene:
    from .ticks import _tick_scene

    others = tuple(others)
    blocks = {lb.id >> 16 for lb in world_landblocks}
    in_world = tuple(o for o in others if o.parent is None)  # a child enters with its parent and takes no input
    assert all(p.cell >> 16 in blocks for p in (mover.begin,) + tuple(o.begin for o in in_world)), name  # stays on them
    if ethereal:
        name += _ethereal(draw, tl, mover, in_world)
    base = Scene(tuple(world_landblocks), mover, tuple(objects), name=name, buildings=tuple(buildings),
                 environments=tuple(environments), env_cells=tuple(env_cells))
    scene = _tick_scene(base, clock_start, dts, tl.steps_inputs(others), "update_object", None, name)
    return scene.replace(mover=replace(scene.mover, placement=Placement(via="enter_world")), others=others)


def _extras(draw, world: _Flat, ids: _Ids, tl: _Timeline, mx: float, my: float, ux: float, uy: float,
            reach: float, count: int) -> list[OtherMover]:
    """Bystanders near the meeting point (mx, my): standing beside the line, crossing it, or following the other."""
    out = []
    for j in range(count):
        weenie = draw(WEENIES)
        spheres = _spheres(draw)
        r = spheres[0].radius
        side = draw(st.sampled_from((1.0, -1.0)))
        px, py = -uy * side, ux * side
        how = draw(EXTRA_KINDS)
        gap = draw(EXTRA_GAPS)
        off = reach + r + gap + j * (2 * r + gap)
        if how == "follow":  # behind the other, on its line
            bx, by = mx + ux * (off + 2.0), my + uy * (off + 2.0)
            dx, dy = -ux, -uy
        else:
            bx, by = mx + px * off, my + py * off
            dx, dy = -px, -py
        kind = draw(INPUT_KINDS)
        o = _other(draw, ids, weenie, spheres, world.position(bx, by, facing(kind, dx, dy)), scale=draw(SCALES))
        if how != "stand":
            tl.walk(draw, tl.of(o.id), dx, dy, float(dr.take(draw, SPEEDS)), kind)
        out.append(o)
    return out


def _within(distance: float, speed: float, dts: list[float]) -> float:
    """`distance`, or less: what `speed` covers in 0.6 of the scene's time (so the meeting falls within the
    ticks), but at least a metre."""
    return min(distance, max(0.6 * speed * sum(dts), 1.0))


def draw_movers_ticks(draw, clock, policy: str | None = None) -> Scene:
    """A movers tick scene; `clock(draw, n)` is strategies.ticks._clock (start, dts, label)."""
    policy = policy or draw(POLICIES)
    if policy in ("head_on", "side_on"):
        return _crossing(draw, clock, policy)
    if policy == "corner":
        return _house_corner(draw, clock) if draw(CORNER_SITES) == "house" else _box_corner(draw, clock)
    if policy in ("chase", "doorway"):
        return _chase(draw, clock, policy == "doorway")
    if policy == "touch":
        return _touch(draw, clock)
    if policy == "approach":
        return _approach(draw)
    if policy == "carry":
        return _carry(draw, clock)
    return _jump(draw, clock)


def _crossing(draw, clock, policy: str) -> Scene:
    """Head-on (the other on the mover's line, walking back along it) or side-on (across it at right angles,
    timed to reach the crossing when the mover does, or a little off)."""
    where = draw(WHERE)
    world = _Flat(draw, where in ("block", "corner"))
    mx, my = _meeting_point(draw, where)
    rad = math.radians(dr.take(draw, HEADINGS))
    ux, uy = math.cos(rad), math.sin(rad)
    vm, vo = float(dr.take(draw, SPEEDS)), float(dr.take(draw, SPEEDS))
    n = dr.take(draw, TICK_COUNTS)
    start, dts, label = clock(draw, n)
    lm = _within(float(dr.take(draw, GAPS)), vm, dts)  # the mover's distance to the meeting point
    tl = _Timeline(dts)
    ids = _Ids()
    weenie = draw(WEENIES)
    sm, so = _spheres(draw), _spheres(draw)
    mkind = draw(INPUT_KINDS)
    begin = world.position(mx - ux * lm, my - uy * lm, facing(mkind, ux, uy))
    mover = _mover(draw, sm, begin, world.z, _pks(draw, "player"), scale=1.0 if draw(dr.BOOLEANS) else draw(SCALES))
    mlabel = tl.walk(draw, tl.mover, ux, uy, vm, mkind)
    if policy == "head_on":
        dx, dy = -ux, -uy
        lo = vo / vm * lm + draw(TIMING)
    else:
        side = draw(st.sampled_from((1.0, -1.0)))
        dx, dy = uy * side, -ux * side  # toward the line, at right angles
        lo = vo / vm * lm + draw(TIMING)
    lo = min(max(lo, 0.0), MAX_LEAD)
    okind = draw(INPUT_KINDS)
    other = _other(draw, ids, weenie, so, world.position(mx - dx * lo, my - dy * lo, facing(okind, dx, dy)),
                   scale=draw(SCALES))
    olabel = tl.walk(draw, tl.of(other.id), dx, dy, vo, okind)
    reach = max(s.radius for s in sm)
    others = [other] + _extras(draw, world, ids, tl, mx, my, ux, uy, reach, draw(EXTRAS))
    name = f"movers:{policy}:{weenie}:{where}:{mlabel}/{olabel}:{len(others)}others:{label}"
    return _finish(draw, start, dts, tl, world.landblocks, mover, others, (), name)


def _box_corner(draw, clock) -> Scene:
    """A BSP box; the mover walks along its +y face toward its (+x, +y) corner, the other along its +x face
    toward the same corner, each a lane gap off its face, timed to cross just outside the corner."""
    world = _Flat(draw, False)
    cx, cy = 96.0 + float(draw(NEAR)) * 10, 96.0 + float(draw(NEAR)) * 10
    w, d = float(dr.take(draw, BOX_SIDES)), float(dr.take(draw, BOX_SIDES))
    yaw = draw(BOX_YAWS)
    cs, sn = math.cos(math.radians(yaw)), math.sin(math.radians(yaw))

    def at(x, y):  # box frame -> the home block's frame
        return cx + x * cs - y * sn, cy + x * sn + y * cs

    sm, so = _spheres(draw), _spheres(draw)
    rm, ro = sm[0].radius, so[0].radius
    gm, go = draw(LANE_GAPS), draw(LANE_GAPS)
    vm, vo = float(dr.take(draw, SPEEDS)), float(dr.take(draw, SPEEDS))
    n = dr.take(draw, TICK_COUNTS)
    start, dts, label = clock(draw, n)
    a = _within(float(dr.take(draw, GAPS)), vm, dts)
    b = min(max(vo / vm * (a + ro + go) - rm - gm + draw(TIMING), 0.1), MAX_LEAD)
    tl, ids = _Timeline(dts), _Ids()
    mu, ou = (cs, sn), (-sn, cs)  # the box's +x and +y in the block frame
    mkind, okind = draw(INPUT_KINDS), draw(INPUT_KINDS)
    mover = _mover(draw, sm, world.position(*at(w / 2 - a, d / 2 + rm + gm), facing(mkind, *mu)), world.z,
                   _pks(draw, "player"))
    weenie = draw(WEENIES)
    other = _other(draw, ids, weenie, so, world.position(*at(w / 2 + ro + go, d / 2 - b), facing(okind, *ou)),
                   scale=1.0)
    mlabel = tl.walk(draw, tl.mover, *mu, vm, mkind)
    olabel = tl.walk(draw, tl.of(other.id), *ou, vo, okind)
    box = StaticObject(0x7D000021, world.position(cx, cy, bl.dg.yaw_quat(yaw)), sh.box(w, d, 3.0), STATIC_BSP)
    name = f"movers:corner:box:{weenie}:{mlabel}/{olabel}:{label}"
    return _finish(draw, start, dts, tl, world.landblocks, mover, [other], (box,), name)


def _house_corner(draw, clock) -> Scene:
    """A house (buildings "along": the mover outside its front corner, beside its side wall); the mover waits
    there (all the ticks, some, or none) then walks along the side, while the other comes along the front
    face toward the corner."""
    from .scenes import step_heights

    base = bl.draw_building(draw, _spheres(draw), step_heights, "along")
    b = base.buildings[0]
    (ox, oy, _), q = b.frame.origin, b.frame.orientation
    yaw = 2 * math.atan2(q[3], q[0])
    cs, sn = math.cos(yaw), math.sin(yaw)
    m = base.mover
    home_x = (m.begin.cell >> 24) - (b.landblock >> 24)
    home_y = ((m.begin.cell >> 16) & 0xFF) - ((b.landblock >> 16) & 0xFF)
    gx, gy, gz = m.begin.frame.origin
    gx, gy = gx + home_x * BLOCK, gy + home_y * BLOCK
    # the mover in the house frame (x into the house, y across it)
    hx, hy = (gx - ox) * cs + (gy - oy) * sn, -(gx - ox) * sn + (gy - oy) * cs
    side = 1.0 if hy >= 0 else -1.0
    so = _spheres(draw)
    rm, ro = m.spheres[0].radius, so[0].radius
    lead = float(dr.take(draw, GAPS))
    x = hx - max(ro - rm, 0.0) - draw(LANE_GAPS)
    y = hy - side * (lead + rm + ro)

    def at(px, py):
        return ox + px * cs - py * sn, oy + px * sn + py * cs

    home = (b.landblock >> 24, (b.landblock >> 16) & 0xFF)
    ux, uy = -sn * side, cs * side  # along the front, toward the corner
    n = dr.take(draw, TICK_COUNTS)
    start, dts, label = clock(draw, n)
    tl, ids = _Timeline(dts), _Ids()
    okind = draw(INPUT_KINDS)
    weenie = draw(WEENIES)
    px, py = at(x, y)
    other = _other(draw, ids, weenie, so, bl._outdoor_position(home, (to_f32(px), to_f32(py), gz), facing(okind, ux, uy)))
    olabel = tl.walk(draw, tl.of(other.id), ux, uy, float(dr.take(draw, SPEEDS)), okind)
    wait = draw(HOUSE_WAITS)
    first = n if wait == "all" else 0 if wait == "none" else draw(st.integers(0, n - 1))
    if first < n:
        tl.walk(draw, tl.mover, cs, sn, float(dr.take(draw, SPEEDS)), "velocity", "all", first)
    mover = replace(m, placement=Placement(via="enter_world"), transient_state=WALKING,
                    player_killer_status=_pks(draw, "player"))
    name = f"movers:corner:house:{weenie}:wait-{wait}:{olabel}:{label}"
    return _finish(draw, start, dts, tl, base.landblocks, mover, [other], base.objects, name,
                   base.buildings, base.environments, base.env_cells)


def _chase(draw, clock, doorway: bool) -> Scene:
    """A monster (or an NPC) behind the mover chases it: each tick its velocity points at where the mover's held
    velocity puts the mover then (from where its own chase put it), at a speed a little above the mover's; in
    a doorway scene the mover walks through the gap between two static slabs ahead of it."""
    where = draw(WHERE) if not doorway else "middle"
    world = _Flat(draw, where in ("block", "corner"))
    mx, my = _meeting_point(draw, where)
    rad = math.radians(dr.take(draw, HEADINGS))
    ux, uy = math.cos(rad), math.sin(rad)
    px, py = -uy, ux
    vm = draw(TARGET_SPEEDS)
    sm = _spheres(draw)
    n = dr.take(draw, TICK_COUNTS)
    start, dts, label = clock(draw, n)
    tl, ids = _Timeline(dts), _Ids()
    mover = _mover(draw, sm, world.position(mx, my), world.z, _pks(draw, "player"))
    if vm > 0:
        tl.walk(draw, tl.mover, ux, uy, vm, "velocity", "all")
    chasers = []
    count = draw(st.sampled_from((1, 1, 1, 2)))
    for c in range(count):
        weenie = draw(CHASERS)
        so = _spheres(draw)
        speed = max(vm, 1.0) * draw(CHASE_FASTER)
        lead = _within(float(dr.take(draw, CHASE_LEADS)), max(speed - vm, 0.5), dts)
        lat = draw(CHASE_LATERAL)
        cx, cy = mx - ux * lead + px * lat, my - uy * lead + py * lat
        o = _other(draw, ids, weenie, so, world.position(cx, cy), scale=draw(SCALES))
        rows = tl.of(o.id)
        t, x, y = 0.0, cx, cy
        for i, dt in enumerate(dts):  # the mover where its held velocity puts it at the tick's start
            tx, ty = mx + ux * vm * t, my + uy * vm * t
            dx, dy = tx - x, ty - y
            h = math.hypot(dx, dy)
            v = (0.0, 0.0, 0.0) if h < 0.05 else _vec(dx / h * speed, dy / h * speed, 0.0)
            rows[i]["velocity"] = v
            step = min(dt, h / speed) if h > 0 else 0.0
            x, y = x + v[0] * step, y + v[1] * step
            t += dt
        chasers.append(o)
    objects = ()
    name = f"movers:{'doorway' if doorway else 'chase'}:{'/'.join(o.weenie for o in chasers)}:{where}:v{vm}:{label}"
    if doorway:
        reach = max(max(s.radius for s in sm), max(o.spheres[0].radius * o.scale for o in chasers))
        gap = 2 * reach + float(dr.take(draw, DOOR_SLACK))
        ahead = float(dr.take(draw, DOOR_AHEAD))
        w, t = draw(SLAB_WIDTHS), draw(SLAB_THICKNESS)
        q = bl.dg.yaw_quat(math.degrees(math.atan2(py, px)))  # the slab's x along the doorway
        dx0, dy0 = mx + ux * ahead, my + uy * ahead
        objects = tuple(StaticObject(DOORWAY_ID + k, world.position(dx0 + s * px * (gap + w) / 2, dy0 + s * py * (gap + w) / 2, q),
                                     sh.box(w, t, 3.0), STATIC_BSP) for k, s in enumerate((1.0, -1.0)))
    return _finish(draw, start, dts, tl, world.landblocks, mover, chasers, objects, name)


# ---------------------------------------------------------------- exact touches

def _on_grid(x: float) -> float:
    return round(x / GRID) * GRID


def touch_radius(rm: float, touch: str) -> tuple[float, float] | None:
    """(the other's radius, the centre distance) for a mover of radius `rm` (on GRID): the distance on GRID
    and the other's radius such that in float32 the radius sum (``sum``) or ACE's radsum, the sum less
    EPSILON (``ace``), is exactly the distance, or one ulp of it above or below (``-1ulp``: the sum an ulp
    short of the distance; ``+1ulp``: an ulp past it). None when no float32 radius does it."""
    kind = "ace" if touch.startswith("ace") else "sum"
    shift = -1 if touch.endswith("-1ulp") else 1 if touch.endswith("+1ulp") else 0
    f = np.float32
    rm32 = f(rm)
    dist = _on_grid(2 * rm - (float(EPSILON) if kind == "ace" else 0.0))
    target = f32_from_bits(f32_bits(dist) + shift)

    def value(ro):
        s = rm32 + f(ro)
        return s - f(EPSILON) if kind == "ace" else s

    guess = f(float(target) - float(rm) + (float(EPSILON) if kind == "ace" else 0.0))
    bits = f32_bits(float(guess))
    for k in sorted(range(-24, 25), key=abs):
        ro = f32_from_bits(bits + k)
        if value(ro) == f(target):
            return float(ro), dist
    return None


def _touch_pair(draw):
    """The mover's and the other's spheres (the same centres; the other's radius solved by touch_radius, its
    scale a power of two with its spheres divided by it), the other's weenie and the touch label."""
    rm = _on_grid(draw(EXACT_RADII))
    touch = draw(TOUCHES)
    solved = touch_radius(rm, touch)
    if solved is None:
        touch, solved = "sum", touch_radius(rm, "sum")
    ro, dist = solved
    two = draw(TWO_SPHERES)
    # both bodies' spheres at the same heights, the larger radius's (the smaller floats a few ulps above the
    # ground: a sphere dipping into it would be lifted by the placement, and the distance no longer axial)
    low = max(rm, ro)
    head = to_f32(low + rm * draw(HEAD_HEIGHTS))
    centres = (low, head) if two else (low,)
    scale = draw(EXACT_SCALES)
    sm = tuple(SphereRec((0.0, 0.0, c), rm) for c in centres)
    so = tuple(SphereRec((0.0, 0.0, to_f32(c / scale)), to_f32(ro / scale)) for c in centres)
    return sm, so, scale, dist, touch


def _touch(draw, clock) -> Scene:
    """The mover and another at rest (velocity 0), their centres `dist` apart along an axis on GRID: touching
    exactly (touch_radius), or an ulp apart or into each other, for a few ticks of any clock."""
    world = _Flat(draw, False)
    sm, so, scale, dist, touch = _touch_pair(draw)
    ax, ay = draw(AXES)
    x0, y0 = _on_grid(96.0 + float(draw(NEAR)) * 10), _on_grid(96.0 + float(draw(NEAR)) * 10)
    n = dr.take(draw, TICK_COUNTS)
    start, dts, label = clock(draw, n)
    tl, ids = _Timeline(dts), _Ids()
    weenie = draw(WEENIES)
    mover = _mover(draw, sm, world.position(x0, y0), world.z, _pks(draw, "player"))
    other = _other(draw, ids, weenie, so, world.position(x0 + ax * dist, y0 + ay * dist), scale=scale)
    name = f"movers:touch:{touch}:{weenie}:x{scale}:{label}"
    return _finish(draw, start, dts, tl, world.landblocks, mover, [other], (), name, ethereal=False)


def _approach(draw) -> Scene:
    """One of the pair (the mover or the other) walks by root motion along an axis, at a speed whose step
    (speed x dt, dt a binary fraction between MinQuantum and MaxQuantum) is exact, so its k-th tick puts it
    exactly k steps on; the other stands where, at a drawn tick, the centre distance is the touch's."""
    world = _Flat(draw, False)
    sm, so, scale, dist, touch = _touch_pair(draw)
    # along +y or -y, facing it: the identity or a half turn, whose float32 quaternions rotate the root
    # motion's local +y exactly (a quarter turn's do not: cos 45 degrees is not a float32)
    ay = draw(st.sampled_from((1, -1)))
    ax, q = 0, (IDENTITY if ay > 0 else HALF_TURN)
    dt = draw(EXACT_DTS)
    speed = draw(EXACT_SPEEDS)
    while speed * dt > 1.9 * sm[0].radius:  # at most two transition steps: halves stay exact
        speed /= 2
    step = speed * dt
    k = draw(MEET_AT)
    n = k + dr.take(draw, dr.ints(2, 20))
    x0, y0 = _on_grid(96.0 + float(draw(NEAR)) * 10), _on_grid(96.0 + float(draw(NEAR)) * 10)
    walker = draw(APPROACHERS)
    dts = [dt] * n
    tl, ids = _Timeline(dts), _Ids()
    weenie = draw(WEENIES)
    # the walker at (x0, y0) + k steps meets the stander `dist` further on
    wx, wy = x0, y0
    sx, sy = x0 + ax * (k * step + dist), y0 + ay * (k * step + dist)
    if walker == "mover":
        mover = _mover(draw, sm, world.position(wx, wy, q), world.z, _pks(draw, "player"))
        other = _other(draw, ids, weenie, so, world.position(sx, sy), scale=scale)
        tl.walk(draw, tl.mover, ax, ay, speed, "root", "all")
    else:  # the other walks (its spheres scaled: its step is speed x dt x scale on the ground)
        mover = _mover(draw, sm, world.position(sx, sy), world.z, _pks(draw, "player"))
        other = _other(draw, ids, weenie, so, world.position(wx, wy, q), scale=scale)
        tl.walk(draw, tl.of(other.id), ax, ay, speed / scale, "root", "all")
    start = draw(EXACT_STARTS)
    name = f"movers:approach:{walker}:{touch}:{weenie}:x{scale}:at{k}:dt{dt}:v{speed}"
    return _finish(draw, start, dts, tl, world.landblocks, mover, [other], (), name, ethereal=False)


def _jump(draw, clock) -> Scene:
    """A player (the mover, or another player) jumps toward another standing ahead of it: onto it, over it,
    or short of it."""
    world = _Flat(draw, False)
    mx, my = _meeting_point(draw, "middle")
    rad = math.radians(dr.take(draw, HEADINGS))
    ux, uy = math.cos(rad), math.sin(rad)
    n = dr.take(draw, TICK_COUNTS)
    start, dts, label = clock(draw, n)
    tl, ids = _Timeline(dts), _Ids()
    jumper = draw(JUMPERS)
    sj, ss = _spheres(draw), _spheres(draw)
    ahead = sj[0].radius + ss[0].radius + float(dr.take(draw, JUMP_AHEAD))
    at = min(dr.take(draw, JUMP_AT), n - 1)
    fwd = float(dr.take(draw, JUMP_FORWARD))
    jump = _vec(ux * fwd, uy * fwd, float(dr.take(draw, JUMP_UPS)))
    standing = draw(WEENIES)
    if jumper == "mover":
        mover = _mover(draw, sj, world.position(mx, my), world.z, _pks(draw, "player"))
        others = [_other(draw, ids, standing, ss, world.position(mx + ux * ahead, my + uy * ahead), scale=draw(SCALES))]
        tl.mover[at]["jump"] = jump
    else:  # another player jumps over the mover (or over a third)
        over_mover = draw(dr.BOOLEANS)
        jp = _other(draw, ids, "player", sj, world.position(mx, my))
        if over_mover:
            mover = _mover(draw, ss, world.position(mx + ux * ahead, my + uy * ahead), world.z, _pks(draw, "player"))
            others = [jp]
        else:
            mover = _mover(draw, _spheres(draw), world.position(mx - uy * 5.0, my + ux * 5.0), world.z,
                           _pks(draw, "player"))
            others = [jp, _other(draw, ids, standing, ss, world.position(mx + ux * ahead, my + uy * ahead))]
        tl.of(jp.id)[at]["jump"] = jump
    name = f"movers:jump:{jumper}:{standing}:at{at}:{label}"
    return _finish(draw, start, dts, tl, world.landblocks, mover, others, (), name)


# ---------------------------------------------------------------- carries

def _holding_frame(draw, holder_origin, by_part: bool) -> Frame:
    """A child's frame in its holding part: an offset and a turn (exact float32s). Part 0 of a server's object
    without a physics BSP is where makeAnimObject put it, the origin of its landblock (until a set_frame of its
    PartArray makes it the holder's Position itself), so a frame by part 0 is in landblock coordinates: a
    metre or more into the landblock (a child's sorting sphere at its -x or -y edge would reach a landblock the
    scene lacks: ACE's empty CellLandblock throws), or one time in four near the holder's start."""
    x, y, z = (float(dr.take(draw, HOLD_XY)), float(dr.take(draw, HOLD_XY)), float(dr.take(draw, HOLD_Z)))
    if by_part:
        if draw(PART_FRAMES) == "start":
            x, y, z = x + holder_origin[0], y + holder_origin[1], z + holder_origin[2]
        else:
            x, y = abs(x) + 1.25, abs(y) + 1.25
    q = draw(HOLD_TURNS)
    if q == "drawn":
        v = [float(draw(QUAT_PARTS)) for _ in range(4)]
        h = math.sqrt(sum(c * c for c in v))
        q = tuple(c / h for c in v) if h > 1e-3 else (1.0, 0.0, 0.0, 0.0)
    return Frame(_vec(x, y, z), _vec(*q))


def _child(draw, ids: _Ids, parent: int, location: int) -> OtherMover:
    """A small held object (a GenericObject mostly), with a sorting sphere or none."""
    weenie = draw(CHILD_WEENIES)
    r = to_f32(draw(CHILD_RADII))
    spheres = (SphereRec((0.0, 0.0, r), r),)
    sorting = draw(SORTING)
    sphere = None if sorting is None else SphereRec(_vec(sorting[0], 0.0, sorting[1]), to_f32(sorting[2]))
    return OtherMover(ids.take(weenie), weenie, spheres, None, 0.0, 0.0, scale=to_f32(draw(SCALES)) if draw(dr.BOOLEANS) else 1.0,
                      sorting_sphere=sphere, parent=ChildOf(parent, location, draw(PLACEMENTS)))


def _carry(draw, clock) -> Scene:
    """The mover or another mover (a monster, a player, an NPC) carries one or two children at holding locations of
    its Setup, and walks (velocity, local_velocity, root motion), turns (omega, walking slowly), jumps (a player),
    walks into a wall or into another mover walking at it, or stands; across a cell or landblock border or
    mid-block. A second child may be the mover's while another holds the first."""
    from acconform.staging import MOVER_ID

    where = draw(CARRY_WHERE)
    world = _Flat(draw, where == "block")
    mx, my = _meeting_point(draw, where)
    rad = math.radians(dr.take(draw, HEADINGS) if where == "middle" else draw(CROSS_HEADINGS))
    ux, uy = math.cos(rad), math.sin(rad)
    n = dr.take(draw, TICK_COUNTS)
    start, dts, label = clock(draw, n)
    tl, ids = _Timeline(dts), _Ids()
    carrier = draw(CARRIERS)
    move = draw(CARRY_MOVES)
    if move == "jump" and carrier in ("monster", "creature"):
        move = "walk"
    speed = float(dr.take(draw, SPEEDS))
    lead = _within(float(dr.take(draw, GAPS)), speed, dts)  # to the border, the wall, the meeting
    kind = draw(INPUT_KINDS) if move in ("walk", "wall", "bump") else "velocity"
    sh_ = _spheres(draw)
    hx, hy = mx - ux * lead, my - uy * lead
    hq = facing(kind, ux, uy) if move != "turn" else IDENTITY
    objects, others = (), []
    if carrier == "mover":
        mover = _mover(draw, sh_, world.position(hx, hy, hq), world.z, _pks(draw, "player"))
        rows, holder_id, holder_begin = tl.mover, MOVER_ID, mover.begin
        holder = None
    else:
        holder = _other(draw, ids, carrier, sh_, world.position(hx, hy, hq), scale=draw(SCALES))
        rows, holder_id, holder_begin = tl.of(holder.id), holder.id, holder.begin
        others.append(holder)
        if move == "bump":  # the mover walks at it
            mover = _mover(draw, _spheres(draw), world.position(mx + ux * lead, my + uy * lead, facing(kind, -ux, -uy)),
                           world.z, _pks(draw, "player"))
        else:  # the mover stands aside
            mover = _mover(draw, _spheres(draw), world.position(mx - uy * 5.0, my + ux * 5.0), world.z, _pks(draw, "player"))
    # the motion
    label_move = move
    if move in ("walk", "wall", "bump"):
        label_move += "-" + tl.walk(draw, rows, ux, uy, speed, kind)
    elif move == "turn":
        w, v = draw(CARRY_OMEGAS), draw(CARRY_SPEEDS)
        local = draw(dr.BOOLEANS)
        for i in range(n):
            rows[i]["omega"] = _vec(0.0, 0.0, w)
            if v:
                rows[i]["local_velocity" if local else "velocity"] = _vec(0.0, v, 0.0) if local else _vec(ux * v, uy * v, 0.0)
        label_move += f"-w{w}-v{v}" + ("-local" if local and v else "")
    elif move == "jump":
        at = min(dr.take(draw, JUMP_AT), n - 1)
        label_move += "-" + tl.walk(draw, rows, ux, uy, min(speed, 4.0), "velocity")
        fwd = float(dr.take(draw, JUMP_FORWARD))
        rows[at]["jump"] = _vec(ux * fwd, uy * fwd, float(dr.take(draw, JUMP_UPS)))
    if move == "wall":
        ahead = max(s.radius for s in sh_) + float(draw(LANE_GAPS)) + lead
        q = bl.dg.yaw_quat(math.degrees(rad) + 90.0)  # the box's x across the walk
        objects = (StaticObject(CARRY_WALL_ID, world.position(hx + ux * (ahead + 0.2), hy + uy * (ahead + 0.2), q),
                                sh.box(draw(SLAB_WIDTHS) * 2, 0.4, 3.0), STATIC_BSP),)
    # the children and their holding locations
    locations: dict[int, list[HoldingLocation]] = {holder_id: []}
    begins = {holder_id: holder_begin, MOVER_ID: mover.begin}
    held, kinds = [], []
    for c in range(draw(CHILD_COUNTS)):
        who = holder_id
        if c == 1 and holder_id != MOVER_ID and draw(SECOND_HOLDER) == "mover":
            who = MOVER_ID
        taken = locations.setdefault(who, [])
        at_kind = draw(HOLDS_AT)
        location = draw(LOCATIONS)
        for k in range(12):  # a location of its own (a Setup keys each once), or one not given
            if location not in {h.location for h in taken} and location not in {ch.parent.location for ch in held
                                                                               if ch.parent.id == who}:
                break
            location = draw(LOCATIONS) if k < 11 else 1000 + c
        if at_kind != "missing":
            part = 0 if at_kind == "part0" else draw(PAST_PARTS)
            taken.append(HoldingLocation(location, part, _holding_frame(draw, begins[who].frame.origin, part == 0)))
        ch = _child(draw, ids, who, location)
        frame_form = ch.parent.placement in FRAME_FORM_PLACEMENTS and at_kind != "position"
        if frame_form:  # attached by its part and a frame instead (part 0 the holding frame's, else part 1: refused)
            part, f = (0, taken[-1].frame) if at_kind == "part0" else (1, Frame(_vec(0.0, 0.0, 1.0)))
            ch = replace(ch, parent=ChildOf(who, 0, 0, part, f))
        held.append(ch)
        kinds.append(at_kind + ("-frame" if frame_form else "") + ("-mover" if who != holder_id else ""))
    for who, taken in locations.items():
        if draw(EXTRA_LOCATION):
            used = {h.location for h in taken} | {ch.parent.location for ch in held if ch.parent.id == who}
            spare = next(l for l in (9, 8, 7, 6, 500) if l not in used)
            taken.append(HoldingLocation(spare, draw(PAST_PARTS), _holding_frame(draw, begins[who].frame.origin, False)))
    if locations.get(MOVER_ID):
        mover = replace(mover, holding_locations=tuple(locations[MOVER_ID]))
    if holder is not None and locations[holder_id]:
        others[0] = replace(holder, holding_locations=tuple(locations[holder_id]))
    others += held
    if move == "bump" and carrier == "mover":  # another mover walks at the holder
        weenie = draw(WEENIES)
        okind = draw(INPUT_KINDS)
        bumper = _other(draw, ids, weenie, _spheres(draw), world.position(mx + ux * lead, my + uy * lead,
                                                                          facing(okind, -ux, -uy)), scale=draw(SCALES))
        tl.walk(draw, tl.of(bumper.id), -ux, -uy, float(dr.take(draw, SPEEDS)), okind)
        others.append(bumper)
    label += _handing(draw, tl, rows, held, holder_id, mover, others)
    name = f"movers:carry:{carrier}:{label_move}:{where}:{len(held)}c:{'/'.join(kinds)}:{label}"
    return _finish(draw, start, dts, tl, world.landblocks, mover, others, objects, name)


def _handing(draw, tl: _Timeline, rows: list[dict], held: list[OtherMover], holder_id: int, mover: Mover,
             others: list[OtherMover]) -> str:
    """The first child moved at a drawn tick (HANDINGS): its input row gets `unparent` and/or `parent`; the old
    holder stands from that tick on (HANDING_STOPS), and a new holder may be made Hidden at tick 0 (HIDDEN_TAKERS).
    Returns the name's suffix."""
    from acconform.staging import MOVER_ID

    how = draw(HANDINGS)
    if how == "none" or tl.n < 3:
        return ""
    first = held[0]
    at = draw(st.integers(1, tl.n - 2))
    row = tl.of(first.id)
    old = first.parent.id
    new = old
    if how == "hand-over":
        new = MOVER_ID if old != MOVER_ID else (holder_id if holder_id != MOVER_ID else MOVER_ID)
    holders = {MOVER_ID: mover, **{o.id: o for o in others}}
    places = [h.location for h in holders[new].holding_locations] or [first.parent.location]
    location = draw(st.sampled_from(places))
    if how in ("drop", "drop-pick"):
        row[at]["unparent"] = True
    if how == "drop-pick":
        later = draw(st.integers(at + 1, tl.n - 1))
        tl.of(first.id)[later]["parent"] = first.parent  # held again as it was
    elif how in ("other-hand", "hand-over"):
        row[at]["parent"] = ChildOf(new, location, draw(PLACEMENTS))
    suffix = f":{how}@{at}"
    if draw(HANDING_STOPS):
        old_rows = rows if old == holder_id else tl.mover
        for i in range(at, tl.n):
            for key in ("velocity", "local_velocity", "omega", "sequence_velocity", "jump"):
                old_rows[i].pop(key, None)
        old_rows[at].update(velocity=(0.0, 0.0, 0.0), omega=(0.0, 0.0, 0.0))
        suffix += "-stop"
    if new != old and draw(HIDDEN_TAKERS):
        new_rows = tl.mover if new == MOVER_ID else tl.of(new)
        state = (mover.state if new == MOVER_ID else holders[new].state) | int(PhysicsState.Hidden)
        new_rows[0]["state"] = state
        suffix += "-hidden"
    return suffix


# ---------------------------------------------------------------- issue 41: the world side of PhysicsObj (stop 50)
# Arms drawn by name (tests/runner/world_scenes.py, shard ticks-0067), each a scene of the policies above changed
# after the draw, so that no seeded sample of the movers kind moves:
# - ``hidden-holder``: a carry whose first child's holder is Hidden from the start (set_parent: NoDraw), and the
#   child dropped (unset_parent: a hidden parent clears the child's Hidden, PartArray.SetNoDrawInternal(false))
# - ``static-other``: a movers scene with another mover Static from its entry (prepare_to_enter_world and
#   enter_world(bool) leave it inactive)
# - ``frame-minus-one``: a carry whose first child is attached by the frame form at part -1 (add_child takes it:
#   the holder's Position; UpdateChild indexes Parts[-1] and throws)
# - ``frame-unlaunched``: a missile carrying a child attached by the frame form before its launch (set_parent's
#   frame form with a holder out of the world: no cell to change to)
# - ``emitter-child``: a carry whose first child is a ParticleEmitter (a weenie's PhysicsState may carry it:
#   WorldObject_Networking.cs CalculatedPhysicsState): SetPlacementFrame, leave_world and SetPositionInternal leave
#   its parts alone
# - ``off-cell``: a player's RequestPos (driver request_pos) that from a drawn tick names the land cell beside the one
#   its origin is in (a client's position is the client's word): set_current_pos's find_terrain_poly finds no
#   triangle of the named cell under it and keeps the contact plane
# - ``static-mover``: a motion scene (a motion table, keys) whose mover is Static from the start: MovementManager's
#   PerformMovement calls set_active(true), which a Static object refuses
WORLD_ARMS = ("hidden-holder", "hidden-holder", "static-other", "frame-minus-one", "frame-unlaunched", "emitter-child",
              "off-cell", "static-mover")


def _other_input(scene: Scene, k: int, oid: int, **kw) -> Scene:
    """`scene` with tick k's inputs to other `oid` given `kw` (made when it has none), in `others` order."""
    steps = list(scene.ticks.steps)
    theirs = {o.id: o for o in steps[k].others}
    theirs[oid] = replace(theirs[oid], **kw) if oid in theirs else OtherInputs(oid, **kw)
    order = [o.id for o in scene.others]
    steps[k] = replace(steps[k], others=tuple(sorted(theirs.values(), key=lambda o: order.index(o.id))))
    return scene.replace(ticks=replace(scene.ticks, steps=tuple(steps)))


def _untouched_child(scene: Scene):
    """The first child no tick unparents or parents anew (None: none)."""
    moved = {o.id for s in scene.ticks.steps for o in s.others if o.unparent or o.parent is not None}
    return next((o for o in scene.others if o.parent is not None and o.id not in moved), None)


def _replace_other(scene: Scene, new: OtherMover) -> Scene:
    return scene.replace(others=tuple(new if o.id == new.id else o for o in scene.others))


def draw_world_arm(draw, clock, arm: str | None = None) -> Scene:
    """A scene of one WORLD_ARMS arm (drawn when `arm` is None); its name begins ``world:<arm>:``."""
    from acconform.staging import MOVER_ID

    from .missiles import draw_missile_scene

    arm = arm or draw(st.sampled_from(WORLD_ARMS))
    if arm == "frame-unlaunched":
        for _ in range(12):
            scene = draw_missile_scene(draw)
            child = next((o for o in scene.others if o.parent is not None), None)
            if child is not None:
                break
        else:
            return scene.replace(name="world:frame-unlaunched:none:" + scene.name)
        holder = next(o for o in scene.others if o.id == child.parent.id)
        loc = holder.holding_locations[0]
        part = draw(st.sampled_from((0, -1, loc.part)))
        scene = _replace_other(scene, replace(child, parent=ChildOf(holder.id, 0, 0, part, loc.frame)))
        return validate_world(scene.replace(name=f"world:{arm}:part{part}:" + scene.name))
    if arm == "static-other":
        scene = draw_movers_ticks(draw, clock, draw(st.sampled_from(("head_on", "side_on", "chase", "touch", "jump"))))
        free = [o for o in scene.others if o.parent is None and o.launch is None]
        if not free:
            return scene.replace(name="world:static-other:none:" + scene.name)
        o = draw(st.sampled_from(free))
        scene = _replace_other(scene, replace(o, state=o.state | int(PhysicsState.Static)))
        return validate_world(scene.replace(name=f"world:{arm}:{o.weenie}:" + scene.name))
    if arm == "off-cell":
        return _off_cell(draw, clock)
    if arm == "static-mover":
        from .ticks import draw_tick_scene

        scene = draw_tick_scene(draw, None, "motion")
        scene = scene.replace(mover=replace(scene.mover, state=scene.mover.state | int(PhysicsState.Static)))
        return validate_world(scene.replace(name=f"world:{arm}:" + scene.name))
    scene = _carry(draw, clock)
    child = _untouched_child(scene)
    n = len(scene.ticks.steps)
    if child is None or n < 3:
        return scene.replace(name=f"world:{arm}:none:" + scene.name)
    if arm == "hidden-holder":
        hid = child.parent.id
        if hid == MOVER_ID:
            scene = scene.replace(mover=replace(scene.mover, state=scene.mover.state | int(PhysicsState.Hidden)))
        else:
            h = next(o for o in scene.others if o.id == hid)
            scene = _replace_other(scene, replace(h, state=h.state | int(PhysicsState.Hidden)))
        at = draw(st.integers(1, n - 2))
        how = draw(st.sampled_from(("drop", "drop", "again", "drop-pick")))
        if how == "again":  # held anew where it is: set_parent's unset_parent from the hidden holder
            scene = _other_input(scene, at, child.id, parent=child.parent)
        else:
            scene = _other_input(scene, at, child.id, unparent=True)
            if how == "drop-pick":
                scene = _other_input(scene, draw(st.integers(at + 1, n - 1)), child.id, parent=child.parent)
        return validate_world(scene.replace(name=f"world:{arm}:{how}@{at}:" + scene.name))
    if arm == "emitter-child":
        scene = _replace_other(scene, replace(child, state=child.state | int(PhysicsState.ParticleEmitter)))
        return validate_world(scene.replace(name=f"world:{arm}:" + scene.name))
    # frame-minus-one
    f = Frame(_vec(float(dr.take(draw, HOLD_XY)), 0.0, float(dr.take(draw, HOLD_Z))))
    scene = _replace_other(scene, replace(child, parent=ChildOf(child.parent.id, 0, 0, -1, f)))
    return validate_world(scene.replace(name=f"world:{arm}:" + scene.name))


def _off_cell(draw, clock) -> Scene:
    scene = draw_movers_ticks(draw, clock, draw(st.sampled_from(("head_on", "side_on", "chase"))))
    begin = scene.mover.begin
    low = begin.cell & 0xFFFF
    n = len(scene.ticks.steps)
    if not 1 <= low <= 64 or n < 2:
        return scene.replace(name="world:off-cell:none:" + scene.name)
    col, row = divmod(low - 1, 8)
    row += 1 if row < 7 else -1
    wrong = (begin.cell & 0xFFFF0000) | (col * 8 + row + 1)
    at = draw(st.integers(0, n - 1))
    x, y, z = begin.frame.origin
    drift = float(draw(st.sampled_from((0.0, 0.05, 0.2))))
    steps = []
    for i, step in enumerate(scene.ticks.steps):
        origin = (float(to_f32(x + drift * i)), y, z)
        pos = replace(begin, cell=wrong if i >= at else begin.cell, frame=replace(begin.frame, origin=origin))
        steps.append(replace(step, request_pos=pos, velocity=None, local_velocity=None, sequence_velocity=None))
    scene = scene.replace(ticks=replace(scene.ticks, driver="request_pos", steps=tuple(steps)))
    return validate_world(scene.replace(name=f"world:off-cell:{wrong & 0xFFFF:#x}@{at}:" + scene.name))


def validate_world(scene: Scene) -> Scene:
    from acconform.scene import validate_scene

    return validate_scene(scene)


# ---------------------------------------------------------------- multi-part movers (issue 41)

# another mover made from a Setup of several parts (scene/8 others[].setup, feature setup.multipart_movers)
MULTIPART_PART_COUNTS = st.sampled_from((2, 2, 3, 4, 5, 8, 12, 16))
# how the other collides: its spheres (as before), its Setup's cylspheres, or its parts' BSPs (HasPhysicsBSP set and,
# for a GenericObject, no spheres: FindObjCollisions tries the parts only when the State has HasPhysicsBSP)
MULTIPART_BODIES = st.sampled_from(("spheres", "cylspheres", "bsp", "bsp", "bsp-sphereless"))
MULTIPART_POLICIES = st.sampled_from(("head_on", "side_on", "chase", "doorway", "touch", "approach", "house"))
# the Setup's layout: its parts at their placement frames; "bare", no placement frames (UpdateParts then leaves the
# parts where PhysicsPart made them); "empty", no parts at all (InitParts fails: makeObject's PhysicsObj has no PartArray)
MULTIPART_LAYOUTS = st.sampled_from(("placed",) * 6 + ("bare", "bare", "empty", "empty"))
# a static of a Setup with no parts beside them, at the other's start, Static (with HasPhysicsBSP or not)
EMPTY_STATICS = st.sampled_from((False, False, False, True))
EMPTY_STATIC_STATES = st.sampled_from((STATIC_BSP, int(PhysicsState.Static)))


def _multipart_setup(draw, cylspheres: bool):
    """A Setup of 2-16 BSP box parts, each at its own frame (an offset, a lift and a yaw), with or without a
    DefaultScale entry per part, and 0-2 cylspheres."""
    from acconform.scene import CylSphereShape, PartRec, SetupRec

    from . import objects as ob

    scaled = draw(ob.SCALED_PARTS)
    parts = []
    for _ in range(draw(MULTIPART_PART_COUNTS)):
        shape = sh.box(draw(ob.PART_SIDES), draw(ob.PART_SIDES), dr.take(draw, ob.PART_HEIGHTS))
        frame = Frame((dr.take(draw, ob.PART_OFFSETS), dr.take(draw, ob.PART_OFFSETS), dr.take(draw, ob.PART_LIFTS)),
                      ob._yaw_quat(dr.take(draw, ob.PART_YAWS)))
        parts.append(PartRec(shape, frame, tuple(map(to_f32, dr.take(draw, ob.PART_SCALES))) if scaled else None))
    cyls = ()
    if cylspheres:
        cyls = tuple(CylSphereShape((dr.take(draw, ob.PART_OFFSETS), dr.take(draw, ob.PART_OFFSETS), 0.0),
                                       draw(ob.SETUP_RADII), dr.take(draw, ob.PART_HEIGHTS))
                     for _ in range(draw(st.integers(1, 2))))
    return SetupRec(tuple(parts), (), cyls)


def draw_multipart_movers(draw, clock) -> Scene:
    """A movers scene (head-on, side-on, a chase, through a doorway, a touch, an approach or at a house's corner, whose
    EnvCells may hold the static of no parts) whose first other mover in the world is made
    from a Setup of several parts (`_multipart_setup`): the mover meets its spheres, its cylspheres or its parts' BSPs
    (`MULTIPART_BODIES`), each part placed at its frame by UpdateParts every tick."""
    policy = draw(MULTIPART_POLICIES)
    scene = _house_corner(draw, clock) if policy == "house" else draw_movers_ticks(draw, clock, policy)
    body = draw(MULTIPART_BODIES)
    for k, o in enumerate(scene.others):
        if o.begin is not None and o.launch is None and o.parent is None:
            break
    else:
        return scene.replace(name="multipart:none:" + scene.name)
    setup = _multipart_setup(draw, body == "cylspheres")
    layout = draw(MULTIPART_LAYOUTS)
    if layout == "bare":
        setup = replace(setup, parts=tuple(replace(p, frame=Frame((0.0, 0.0, 0.0))) for p in setup.parts), placement=False)
    elif layout == "empty":
        setup = replace(setup, parts=())
    state, spheres = o.state, o.spheres
    if body.startswith("bsp"):
        state |= int(PhysicsState.HasPhysicsBSP)
    if body == "bsp-sphereless" and o.weenie == "object":  # a GenericObject's Setup may have none (objects.sphereless)
        spheres = ()
    other = replace(o, setup=setup, state=state, spheres=spheres)
    scene = _replace_other(scene, other)
    name = f"multipart:{body}:{layout}-{len(setup.parts)}:"
    if draw(EMPTY_STATICS):  # a static of no parts: no PartArray, so add_obj_to_cell's enter_cell puts it in no cell
        at = replace(o.begin, frame=Frame(o.begin.frame.origin))
        if scene.env_cells and draw(dr.BOOLEANS):  # a stab of an EnvCell: init_static_objects destroys it
            cell = scene.env_cells[0]
            at = Position(cell.id, Frame(cell.frame.origin))
        indoor = at.cell & 0xFFFF >= 0x100  # a stab: init_static_objects sets no state
        static = StaticObject(0x7D0000F0, at, None, int(PhysicsState.Static) if indoor else draw(EMPTY_STATIC_STATES),
                              setup=replace(setup, parts=(), cylspheres=(), placement=True))
        scene = scene.replace(objects=scene.objects + (static,))
        name += "empty-stab:" if indoor else "empty-static:"
    return validate_world(scene.replace(name=name + scene.name))


def draw_no_part_child(draw, clock) -> Scene:
    """A carry (`_carry`) whose first child is made from a Setup of no parts (scene/8 setup.parts [], feature
    setup.no_parts): makeObject gives it no PartArray, and set_parent, UpdateChild and unset_parent meet a child
    without one."""
    from acconform.scene import SetupRec

    scene = _carry(draw, clock)
    for child in scene.others:
        if child.parent is not None:
            break
    else:
        return scene.replace(name="multipart:none:" + scene.name)
    scene = _replace_other(scene, replace(child, setup=SetupRec(())))
    return validate_world(scene.replace(name="multipart:child:empty-0:" + scene.name))
