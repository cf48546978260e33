"""Missile tick scenes (issue 41; campaign kind ``missiles``, feature missiles): an arrow or a spell launched at a
drawn tick from a player or a monster at a creature standing at a wall, through a door, past a cylsphere post, at a
moving target, or at a wall.

    draw_missile_scene(draw)     a tick scene of flat land with one projectile and its site

The site lies on one landblock of flat land (its height drawn), away from its borders (a launch across landblocks
is refused: ACE.Entity.Position.ToGlobal is not modelled). The launcher stands at a drawn point facing a drawn
heading; the target 3-25 m along it. Policies:

- ``creature_at_wall``: a monster target stands with a wall (a BSP slab across the line) just behind it;
- ``through_door``: a door slab across the line part way (open: Ethereal; closed; Static one time in eight),
  a monster or the wall behind it the target;
- ``graze_cylsphere``: a cylsphere post whose edge lies within a few centimetres of the projectile's line
  (either side, or touching exactly), the target beyond;
- ``moving_target``: a monster walking toward, away from or across the line, held every tick (the arrow
  leads it: the moving-target solver; a tracking spell leads it too);
- ``wall``: the wall itself is the target (a static);
- ``bystander``: a player (the mover, or another player: NPK, PK or PKLite, a body of two spheres reaching above
  the projectile's line) crosses the line of flight (across it, or along it toward or away from the launcher, a
  slow walk) timed to reach it as the projectile passes (a lag of up to 0.3 s either way). The projectile is
  launched at a monster or another player by a monster or another player (the mover crossing), or by the mover
  (another player crossing): a player's transition meets a Missile whose ProjectileTarget is someone else, which
  it ignores (ObjectInfo.MissileIgnore); sometimes the crossing player is the target instead.

Outside ``bystander``, the launcher is the player (the mover) three times in four, else a monster launching at the player. The
projectile: an arrow (an Ammunition, one sphere of 2-10 cm, Gravity) two times in three, else a spell (a
SpellProjectile, 10-30 cm; an arc one time in three, tracking half the time); it spawns 0.8 m ahead at eye height
(1-1.5 m), is made at the start and listed before or after the monsters (which the server steps in the order
they entered), and launches at tick 0-5 of 20-60 ticks.
"""

from __future__ import annotations

import math
from dataclasses import replace

from hypothesis import strategies as st

from acconform.flags import ParentLocation, PhysicsState, PlayerKillerStatus, TransientState
from acconform.numerics import to_f32
from acconform.scene import SPELL_KINDS
from acconform.scene import (ChildOf, CylSphereShape, ContactPlane, Frame, HoldingLocation, Landblock, Launch, Mover, OtherInputs, OtherMover,
                             Placement, PlaneRec, Position, Scene, SphereRec, StaticObject, Ticks, TickStep, validate_scene)
from acconform.strategies.shapes import box

from . import draws as dr

PLAYER = 0x50000001
OTHER = 0x50000002  # another player (bystander)
MONSTER = 0x80000001
CASTER = 0x80000002
PROJECTILE = 0x80000010
CARRIED_ID = 0x80000020  # a child the projectile holds (CARRIED)
# a child held by the projectile (a missile's attached object, as the client parents one): none mostly, held in the
# projectile's Position (past its one part) or by its part
CARRIED = st.sampled_from(("none", "none", "none", "none", "none", "position", "position", "by-part"))
CARRY_OFFSETS = st.sampled_from((0.0, 0.0, -0.3, 0.2, -1.0))
CARRIED_RADII = st.sampled_from((0.05, 0.1, 0.2))
CRATE = 0x80000021  # report / run_into: a GenericObject the projectile meets (not CARRIED_ID: both may be drawn)
WALL = 0x70000001
DOOR = 0x70000002
POST = 0x70000003
WALKING = int(TransientState.Contact | TransientState.OnWalkable | TransientState.Active)
EDGE_SLIDE = int(PhysicsState.Gravity | PhysicsState.EdgeSlide)
BODY = (SphereRec((0.0, 0.0, 0.48), 0.48),)
TALL = (SphereRec((0.0, 0.0, 0.48), 0.48), SphereRec((0.0, 0.0, 1.44), 0.48))  # up to 1.92 m: across a 1-1.5 m flight

POLICIES = st.sampled_from(("creature_at_wall", "through_door", "graze_cylsphere", "moving_target", "wall", "bystander"))
BLOCKS = st.sampled_from((0xA9B4, 0x7F7F, 0x2B10, 0xC6A0))
HEIGHTS = dr.ints(5, 60)  # the land height index: z = 2 m per index
SPOTS = dr.f32(60.0, 132.0)
HEADINGS = dr.OneOf(st.sampled_from((0.0, 90.0, 45.0, 180.0)), dr.f32(0.0, 360.0))
DISTANCES = dr.OneOf(st.sampled_from((8.0, 5.0, 12.0)), dr.f32(3.0, 25.0))
ARROW_RADII = dr.OneOf(st.sampled_from((0.05, 0.03)), dr.f32(0.02, 0.1))
SPELL_RADII = dr.f32(0.1, 0.3)
ARROW_SPEEDS = dr.OneOf(st.sampled_from((20.0, 12.0, 30.0)), dr.f32(6.0, 40.0))
SPELL_SPEEDS = dr.OneOf(st.sampled_from((15.0, 10.0)), dr.f32(5.0, 25.0))
EYES = dr.f32(1.0, 1.5)
WALL_GAPS = dr.OneOf(st.sampled_from((0.0, 0.02)), dr.f32(0.0, 0.4))
DOOR_AT = dr.f32(0.25, 0.75)
DOOR_WIDTHS = dr.f32(1.2, 3.0)
THICKNESS = dr.OneOf(st.sampled_from((0.2, 0.4)), dr.f32(0.05, 0.6))
POST_RADII = dr.f32(0.1, 0.6)
GRAZES = dr.OneOf(st.sampled_from((0.0, -0.01, 0.01)), dr.f32(-0.08, 0.08))  # the gap between post and projectile
WAYS = st.sampled_from(("toward", "away", "across", "across"))
WALK_SPEEDS = dr.OneOf(st.sampled_from((3.0, 1.0, 6.0)), dr.f32(0.5, 8.0))
LAUNCH_TICKS = dr.ints(0, 5)
TICK_COUNTS = dr.OneOf(dr.ints(20, 40), dr.ints(40, 60))
ROLES = st.sampled_from(("mover_crosses", "mover_crosses", "other_crosses", "mover_is_target", "other_is_target"))
BY_LAUNCHERS = st.sampled_from((CASTER, CASTER, OTHER))
BY_TARGETS = st.sampled_from((MONSTER, MONSTER, OTHER))
CROSSINGS = st.sampled_from(("across", "across", "toward", "away"))
CROSS_AT = dr.f32(0.0, 1.0)
MEET_LAGS = dr.OneOf(st.sampled_from((0.0,)), dr.f32(-0.3, 0.3))  # seconds the player reaches the line after the projectile
PLAYER_PKS = st.sampled_from(tuple(int(s) for s in (PlayerKillerStatus.NPK, PlayerKillerStatus.NPK, PlayerKillerStatus.PK,
                                                    PlayerKillerStatus.PKLite)))
PK_NAMES = {int(s): s.name.lower() for s in PlayerKillerStatus}
DTS = st.sampled_from((1 / 30, 1 / 30, 1 / 30, 1 / 60, 1 / 10))

# The launch arms (draw_launch_scene): what no missile scene above says, each a change to one draw of
# draw_missile_scene (which draws as before without an arm)
ARMS = st.sampled_from(("alt_solver", "alt_solver", "out_of_range", "overhead", "overhead", "fast_target", "fast_target",
                        "tiny_target", "report", "report", "report", "timeout"))
ARM_POLICIES = {"alt_solver": ("moving_target", "moving_target", "moving_target", "creature_at_wall", "wall", "bystander"),
                "out_of_range": ("creature_at_wall", "moving_target", "wall"), "overhead": ("creature_at_wall", "moving_target"),
                "fast_target": ("moving_target",), "tiny_target": ("moving_target",), "timeout": ("moving_target",),
                "across": ("moving_target",), "run_into": ("moving_target",),
                "report": ("bystander", "bystander", "bystander", "moving_target", "creature_at_wall"),
                "trap": ("moving_target", "moving_target", "creature_at_wall", "wall"),
                "quiet": ("moving_target", "creature_at_wall", "moving_target"),
                "sphereless": ("moving_target", "creature_at_wall", "moving_target"),
                "spells": ("moving_target", "creature_at_wall", "wall", "through_door"),
                "untargeted": ("moving_target", "creature_at_wall", "wall", "graze_cylsphere", "through_door")}
SLOW_ARROW_SPEEDS = dr.f32(2.0, 7.0)  # 45 degrees carries 7 m/s 5 m: a target 10-25 m off is out of range
FAR = dr.f32(10.0, 25.0)
FAST_SPEEDS = dr.OneOf(st.sampled_from((12.0, 20.0)), dr.f32(8.0, 30.0))  # outrunning a spell of 3-10 m/s
SLOW_SPELL_SPEEDS = dr.f32(3.0, 10.0)
TINY_SPEEDS = dr.OneOf(st.sampled_from((0.0001,)), dr.f32(0.00001, 0.001))  # Trajectory2's normalize_check_small
# overhead: the projectile straight above its target (a mover's Setup has Height 0: the aim point is its origin), at
# that very point (no offset: the solvers' first test), or under the ground beneath it (straight up)
OVERHEAD = st.sampled_from(("above", "above", "at", "below"))
DROPS = dr.f32(0.05, 6.0)
SINKS = dr.f32(0.1, 1.0)
CRAWL_SPEEDS = dr.f32(0.2, 0.99)  # under 1 m/s: Trajectory2's quadratic (a unit target direction) turns positive
TIMEOUT_SPEEDS = dr.f32(0.5, 4.0)  # 30 s carries it at most 120 m: it stays on the landblock
REPORT_ROLES = st.sampled_from(("mover_is_target", "mover_is_target", "mover_crosses"))
PUSHES = dr.f32(1.0, 4.0)  # report: a crate (weenie object) pushed into the target
RUN_SPEEDS = dr.f32(6.0, 12.0)  # run_into: the player runs at the arrow about as fast as it flies, so his own
RUN_ARROW_SPEEDS = dr.f32(6.0, 9.0)  # step meets it about one time in two
# spin: a projectile's RotationSpeed (revolutions a second; ACE's weenies give some arrows, bolts, thrown weapons and
# spells one, of either sign): Omega about its x axis, AlignPath cleared
ROTATION_SPEEDS = dr.OneOf(st.sampled_from((1.0, 0.5, 2.0, -1.0)), dr.f32(-4.0, 4.0))


def _carrying(draw, others: tuple, projectile: OtherMover, carried: str) -> tuple:
    """The projectile with a holding location (past its one part: in its Position, or by the part) and a small
    GenericObject held there (scene/8 others[].parent), parented at the start, while the projectile is out of the
    world (set_parent finds no cell to change to); it follows the projectile's entry (prepare_to_enter_world walks
    the children) and flight (UpdateChild)."""
    part = 0 if carried == "by-part" else 1
    frame = Frame((0.0, float(dr.take(draw, CARRY_OFFSETS)), 0.0))
    holder = replace(projectile, holding_locations=(HoldingLocation(int(ParentLocation.RightHand), part, frame),))
    radius = to_f32(dr.take(draw, CARRIED_RADII))
    child = OtherMover(CARRIED_ID, "object", (SphereRec((0.0, 0.0, 0.0), radius),), None, 0.0, 0.0,
                       sorting_sphere=SphereRec((0.0, 0.0, 0.0), radius) if draw(dr.BOOLEANS) else None,
                       parent=ChildOf(PROJECTILE, int(ParentLocation.RightHand)))
    return tuple(holder if o is projectile else o for o in others) + (child,)


def _cell(lb: int, x: float, y: float) -> int:
    return lb << 16 | (int(x // 24) * 8 + int(y // 24) + 1)


def _heading(ux: float, uy: float):
    """The quaternion (w x y z) turning +y onto (ux, uy), in float32."""
    theta = math.atan2(-ux, uy)
    return (to_f32(math.cos(theta / 2)), 0.0, 0.0, to_f32(math.sin(theta / 2)))


def _slab(ident: int, lb: int, x: float, y: float, z: float, ux: float, uy: float, width: float, thickness: float,
          height: float, state: int) -> StaticObject:
    """A BSP slab across the line (its thin axis along (ux, uy)), centred at (x, y) on the ground z."""
    x, y = to_f32(x), to_f32(y)
    return StaticObject(ident, Position(_cell(lb, x, y), Frame((x, y, to_f32(z)), _heading(ux, uy))),
                        box(width, thickness, height), state)


def _monster(ident: int, lb: int, x: float, y: float, z: float, state: int = EDGE_SLIDE) -> OtherMover:
    x, y = to_f32(x), to_f32(y)
    return OtherMover(ident, "monster", BODY, Position(_cell(lb, x, y), Frame((x, y, to_f32(z)))), 0.4, 0.4,
                      state=state, transient_state=WALKING)


def _player(ident: int, body, lb: int, x: float, y: float, z: float, ux: float, uy: float, pks: int,
            state: int = EDGE_SLIDE) -> OtherMover:
    x, y = to_f32(x), to_f32(y)
    return OtherMover(ident, "player", body, Position(_cell(lb, x, y), Frame((x, y, to_f32(z)), _heading(ux, uy))), 0.4, 0.4,
                      state=state, transient_state=WALKING, player_killer_status=pks)


def _crossing(draw, x0: float, y0: float, ux: float, uy: float, d: float, dt: float, n: int, launch_tick: int,
              speed: float, arm: str | None = None):
    """A bystander's walk: it reaches the line of flight at a point 1.8 m or more from the launcher (at least 1.2 m
    short of the target) when the projectile passes it, give or take a lag (the projectile's first step is the tick
    after its launch; gravity and the target's lead ignored). Across the line it walks as far again, then stops;
    along it (toward the launcher, or away ahead of the projectile) it walks slowly from no nearer the target or the
    launcher than a body's width, and stops 0.3 s after. Returns its velocity per tick and (way, where it starts, its
    heading)."""
    way = draw(CROSSINGS) if arm != "report" else draw(st.sampled_from(("toward", "toward", "across")))
    v = float(dr.take(draw, WALK_SPEEDS))
    dc = 1.8 + max(d - 3.6, 0.0) * float(dr.take(draw, CROSS_AT))
    t_meet = max(dt, (launch_tick + 1) * dt + max(dc - 0.8, 0.0) / speed + float(dr.take(draw, MEET_LAGS)))
    side = 1.0 if draw(dr.BOOLEANS) else -1.0
    wx, wy = {"across": (side * uy, -side * ux), "toward": (-ux, -uy), "away": (ux, uy)}[way]
    room = {"across": 15.0, "toward": max(d - dc - 1.0, 0.05), "away": dc - 1.3}[way]
    v = min(v, room / t_meet)
    cx, cy = x0 + ux * dc, y0 + uy * dc
    start = (cx - wx * v * t_meet, cy - wy * v * t_meet)
    walking = t_meet + (t_meet if way == "across" else 0.3)
    vel = (to_f32(wx * v), to_f32(wy * v), 0.0)
    walk = [vel if k * dt < walking else (0.0, 0.0, 0.0) for k in range(n)]
    return walk, (way, start, (wx, wy))


def draw_launch_scene(draw) -> Scene:
    """A missile scene with one launch arm (ARMS): `alt_solver` (the server's trajectory_alt_solver: Trajectory2);
    `out_of_range` (an arrow too slow to reach a target 10-25 m off: the solvers' no-solution arms); `overhead`
    (the projectile spawned straight above its target, or at its feet: no ground distance, the solvers'
    degenerate arms and a misfire's NaN velocity); `fast_target` (a target of 8-30 m/s a slow spell or arrow
    cannot catch, or meets head on: the lead solvers' no-root and two-root arms); `tiny_target` (a target
    creeping at under 1 mm/s); `timeout` (a straight spell at 3-4.5 m/s that misses a target crossing and flies
    on over the landblock for 31 s at 10 ticks a second: the missile timeout); `report` (the mover and the
    monsters report collisions, PhysicsState.ReportCollisions as ACE's creatures do: the player's and a
    creature's OnCollideObject). Any arm but timeout runs under trajectory_alt_solver one time in four.
    One more arm, `across` (the player at a monster just over the landblock's north border: a launch both sides
    refuse, ACE.Entity.Position.ToGlobal not being modelled), and `run_into` (a monster 3-6 m off shoots a 6-9 m/s arrow
    at the player, who reports collisions and runs at it at 6-12 m/s: his own step meets the arrow aimed at him, the
    player's OnCollideObject and the helper's hit) are drawn only by name: draw_missile_scene(draw, ARM). So are
    `spin` (the projectile has a RotationSpeed, scene/8 launch.rotation_speed: SetProjectilePhysicsState or
    SpellProjectile.Setup clears AlignPath and sets Omega, and it tumbles as it flies) and `trap` (a GenericObject
    casts the spell at the player, as ACE's EmoteManager casts a trap's or any non-creature emoter's spell,
    WorldObject.TryCastSpell_WithRedirects: IsProjectileVisible's launcher that is no Creature) and `thrown` (a
    thrown weapon, weenie missile, ACE's Missile: launched as an arrow, it runs WorldObject's OnCollideObject and
    OnCollideEnvironment, the helper's with its ProjectileTarget; half the time spinning, as thrown weapons do), and
    `untargeted` (a spell cast at no one, scene/8 a launch without target: along its caster's forward vector, with
    no ProjectileTarget; the caster the player, a monster or, half the time a monster would, an object), and `spells`
    (scene/8 launch.spell: Rolling Death, made Ethereal half the time, which its Setup leaves; a wall spell, a Ring
    spell or Ring spell 3818, whose Setup clears or sets ScriptedCollision; a Ring spell at no target half the time),
    and `quiet` (as `report`, with the crate always pushed into the target, its WorldObject carrying ReportCollisions
    false, scene/8 others[].report_collisions: the target's OnCollideObject returns at once), and `sphereless` (as
    `quiet`, the crate's Setup with no spheres, scene/8 others[].spheres []: ACE's items, chests and doors of BSP parts;
    enter_world's SetPosition runs on a dummy sphere and UpdateObjectInternal keeps it where it is, clearing Active on
    walkable ground, or, half the time, in the air, Active and never on walkable ground)."""
    arm = draw(ARMS)
    return draw_missile_scene(draw, arm)


def draw_missile_scene(draw, arm: str | None = None) -> Scene:
    lb = draw(BLOCKS)
    h = dr.take(draw, HEIGHTS)
    ground = 2.0 * h
    x0, y0 = float(dr.take(draw, SPOTS)), float(dr.take(draw, SPOTS))
    phi = math.radians(float(dr.take(draw, HEADINGS)))
    if arm == "across":  # north from near the landblock's north edge at a monster over the border (ToGlobal: refused)
        phi, y0 = 0.0, 186.0
    if arm == "timeout":  # from near an edge, inward along an axis: 135 m of flight stays on the landblock
        phi = math.radians(draw(st.sampled_from((0.0, 90.0, 180.0, 270.0))))
        ux, uy = -math.sin(phi), math.cos(phi)
        x0 = 12.0 if ux > 0.5 else 180.0 if ux < -0.5 else x0
        y0 = 12.0 if uy > 0.5 else 180.0 if uy < -0.5 else y0
    ux, uy = -math.sin(phi), math.cos(phi)
    d = float(dr.take(draw, FAR if arm == "out_of_range" else DISTANCES))
    d = 8.0 if arm == "across" else min(6.0 if arm == "run_into" else d, max(3.0, min((x0 - 8.0) / -ux if ux < -1e-6 else 1e9, (184.0 - x0) / ux if ux > 1e-6 else 1e9,
                            (y0 - 8.0) / -uy if uy < -1e-6 else 1e9, (184.0 - y0) / uy if uy > 1e-6 else 1e9) - 2.0))
    tx, ty = x0 + ux * d, y0 + uy * d
    policy = draw(POLICIES) if arm not in ARM_POLICIES else draw(st.sampled_from(ARM_POLICIES[arm]))
    player_launches = draw(st.sampled_from((True, True, True, False)))
    arrow = draw(st.sampled_from((True, True, False))) if arm not in ("out_of_range", "timeout") else arm == "out_of_range"
    n = dr.take(draw, TICK_COUNTS)
    dt = draw(DTS)
    if arm == "across":
        player_launches = True
    if arm == "run_into":  # a monster shoots a slow arrow at the player, who runs at it
        player_launches, arrow = False, True
    if arm == "thrown":
        arrow = True
    if arm in ("untargeted", "spells"):
        arrow = False
    if arm == "trap":  # an object casts a spell at the player (only a Creature launches an arrow: LaunchProjectile)
        player_launches, arrow = False, False
    if arm == "timeout":  # the player launches at a monster hovering 2-5 m up (no Gravity), which moves out of the way
        n, dt = 310, 0.1
        player_launches = True
    launch_tick = min(dr.take(draw, LAUNCH_TICKS), n - 1)

    body = EDGE_SLIDE | int(PhysicsState.ReportCollisions) if arm in ("report", "run_into", "quiet") else EDGE_SLIDE
    walk_for = 1.0 if arm in ("fast_target", "timeout") else math.inf  # seconds a fast target walks: 30 m at most
    objects, monsters = [], []
    mover_inputs = [{} for _ in range(n)]
    monster_velocity = None
    crosser = None  # bystander: the player who crosses the line of flight
    if policy == "bystander":
        role = draw(ROLES) if arm != "report" else draw(REPORT_ROLES)
        crosser = PLAYER if role.startswith("mover") else OTHER
        if role == "mover_crosses":
            launcher = draw(BY_LAUNCHERS)
            target = MONSTER if launcher == OTHER else draw(BY_TARGETS)
        elif role == "mover_is_target":
            launcher, target = draw(BY_LAUNCHERS), PLAYER
        else:  # the mover launches: at a monster another player crosses in front of, or at that player
            launcher, target = PLAYER, MONSTER if role == "other_crosses" else OTHER
        player_launches = launcher != CASTER
        launcher_at = mover_at = (x0, y0)
        mover_pks, other_pks = draw(PLAYER_PKS), draw(PLAYER_PKS)
        for who, (wx, wy) in ((launcher, (x0, y0)), (target, (tx, ty))):  # those who stand
            if who in (CASTER, MONSTER):
                monsters.append(_monster(who, lb, wx, wy, ground, body))
            elif who == OTHER and crosser != OTHER:
                monsters.append(_player(OTHER, BODY, lb, wx, wy, ground, ux, uy, other_pks, body))
    elif player_launches:
        launcher_at, launcher = (x0, y0), PLAYER
        mover_at = (x0, y0)
    else:
        launcher_at, launcher = (x0, y0), CASTER
        mover_at = (tx, ty)
        caster = _monster(CASTER, lb, x0, y0, ground, body)
        trap = arm == "trap" or (arm == "untargeted" and draw(dr.BOOLEANS))
        monsters.append(replace(caster, weenie="object") if trap else caster)
    if crosser is None:
        target = MONSTER
    if policy == "wall":
        target = WALL
    monster_at = (tx, ty)
    if policy == "creature_at_wall" or policy == "wall":
        t = float(dr.take(draw, THICKNESS))
        back = (0.0 if policy == "wall" else 0.48) + t / 2 + float(dr.take(draw, WALL_GAPS))
        objects.append(_slab(WALL, lb, tx + ux * back, ty + uy * back, ground, ux, uy, 8.0, t, 4.0,
                             int(PhysicsState.Static | PhysicsState.HasPhysicsBSP)))
    elif policy == "through_door":
        at = float(dr.take(draw, DOOR_AT))
        state = int(PhysicsState.HasPhysicsBSP)
        if draw(dr.BOOLEANS):
            state |= int(PhysicsState.Ethereal)
        if draw(st.sampled_from((False,) * 7 + (True,))):
            state |= int(PhysicsState.Static)
        objects.append(_slab(DOOR, lb, x0 + ux * d * at, y0 + uy * d * at, ground, ux, uy, float(dr.take(draw, DOOR_WIDTHS)),
                             float(dr.take(draw, THICKNESS)), 3.0, state))
        if draw(dr.BOOLEANS):  # the wall behind is the target
            objects.append(_slab(WALL, lb, tx, ty, ground, ux, uy, 8.0, 0.4, 4.0,
                                 int(PhysicsState.Static | PhysicsState.HasPhysicsBSP)))
            target = WALL
    elif policy == "graze_cylsphere":
        at = float(dr.take(draw, DOOR_AT))
        r = float(dr.take(draw, POST_RADII))
        side = 1.0 if draw(dr.BOOLEANS) else -1.0
        reach = (0.05 if arrow else 0.2) + r + float(dr.take(draw, GRAZES))
        px, py = x0 + ux * d * at + side * uy * reach, y0 + uy * d * at - side * ux * reach
        px, py = to_f32(px), to_f32(py)
        objects.append(StaticObject(POST, Position(_cell(lb, px, py), Frame((px, py, to_f32(ground)))),
                                    CylSphereShape((0.0, 0.0, 0.0), to_f32(r), 4.0), int(PhysicsState.Static)))
    elif policy == "moving_target":
        way = draw(WAYS) if arm not in ("timeout", "run_into") else "across" if arm == "timeout" else "toward"
        speeds = {"fast_target": FAST_SPEEDS, "tiny_target": TINY_SPEEDS, "timeout": FAST_SPEEDS,
                  "run_into": RUN_SPEEDS}.get(arm, WALK_SPEEDS)
        speed = float(dr.take(draw, speeds))
        vx, vy = {"toward": (-ux, -uy), "away": (ux, uy), "across": (uy, -ux)}[way]
        monster_velocity = (to_f32(vx * speed), to_f32(vy * speed), 0.0)
    if target == MONSTER and policy != "bystander":
        if player_launches and arm == "timeout":
            hover = to_f32(ground + float(dr.take(draw, dr.f32(2.0, 5.0))))
            monsters.append(replace(_monster(MONSTER, lb, *monster_at, hover, body), state=int(PhysicsState.EdgeSlide),
                                    transient_state=int(TransientState.Active)))
        elif player_launches and arm == "across":
            monsters.append(_monster(MONSTER, lb + 1, monster_at[0], monster_at[1] - 192.0, ground, body))
        elif player_launches:
            monsters.append(_monster(MONSTER, lb, *monster_at, ground, body))
        else:
            target = PLAYER  # a monster launches at the player
            if monster_velocity is not None:
                for k in range(n):
                    mover_inputs[k]["velocity"] = monster_velocity if k * dt < walk_for else (0.0, 0.0, 0.0)
                monster_velocity = None

    eye = float(dr.take(draw, EYES))
    lx, ly = launcher_at
    origin = (to_f32(lx + ux * 0.8), to_f32(ly + uy * 0.8), to_f32(ground + eye))
    if arm == "overhead":
        where = draw(OVERHEAD)
        dz = {"above": lambda: float(dr.take(draw, DROPS)), "at": lambda: 0.0, "below": lambda: -float(dr.take(draw, SINKS))}[where]()
        origin = (to_f32(tx), to_f32(ty), to_f32(ground + dz))
    if arm == "timeout":
        launch_tick = 0
    alt_solver = arm not in (None, "timeout") and (arm == "alt_solver" or draw(st.sampled_from((False, False, False, True))))
    if arrow:
        radius = float(dr.take(draw, ARROW_RADII))
        speeds = SLOW_ARROW_SPEEDS if arm == "out_of_range" else RUN_ARROW_SPEEDS if arm == "run_into" else ARROW_SPEEDS
        if arm == "alt_solver" and draw(st.sampled_from((False, False, True))):
            speeds = CRAWL_SPEEDS
        launch = Launch(launch_tick, launcher, target, to_f32(dr.take(draw, speeds)), origin, _heading(ux, uy),
                        lead_target=draw(dr.BOOLEANS), alt_solver=alt_solver)
        projectile = OtherMover(PROJECTILE, "missile" if arm == "thrown" else "ammunition", (SphereRec((0.0, 0.0, 0.0), to_f32(radius)),),
                                Position(_cell(lb, lx, ly), Frame((to_f32(lx), to_f32(ly), to_f32(ground)))), 0.0, 0.0,
                                state=int(PhysicsState.Gravity), transient_state=0, launch=launch)
    else:
        radius = float(dr.take(draw, SPELL_RADII))
        kind = draw(st.sampled_from(SPELL_KINDS[1:])) if arm == "spells" else "plain"
        arc = draw(st.sampled_from((False, False, True))) if arm != "timeout" and kind in ("plain", "rolling_death") else False
        speeds = {"fast_target": SLOW_SPELL_SPEEDS, "timeout": TIMEOUT_SPEEDS}.get(arm, SPELL_SPEEDS)
        if arm == "alt_solver" and draw(st.sampled_from((False, False, True))):
            speeds = CRAWL_SPEEDS
        launch = Launch(launch_tick, launcher, target, to_f32(dr.take(draw, speeds)), origin, arc=arc,
                        tracking=draw(dr.BOOLEANS) if arm != "timeout" else False, alt_solver=alt_solver, spell=kind)
        projectile = OtherMover(PROJECTILE, "spell_projectile", (SphereRec((0.0, 0.0, 0.0), to_f32(radius)),),
                                Position(_cell(lb, lx, ly), Frame((to_f32(lx), to_f32(ly), to_f32(ground)))), 0.0, 0.0,
                                state=int(PhysicsState.Ethereal) if kind == "rolling_death" and draw(dr.BOOLEANS) else 0,
                                transient_state=0, launch=launch)
    if arm == "untargeted" or (not arrow and launch.spell.startswith("ring") and draw(dr.BOOLEANS)):
        launch = replace(launch, target=None)
        projectile = replace(projectile, launch=launch)
    if arm == "spin" or (arm == "thrown" and draw(dr.BOOLEANS)):
        launch = replace(launch, rotation_speed=to_f32(dr.take(draw, ROTATION_SPEEDS)))
        projectile = replace(projectile, launch=launch)
    walkers = {}  # id -> velocity, per tick
    if crosser is not None:
        walk, walker = _crossing(draw, x0, y0, ux, uy, d, dt, n, launch_tick, float(launch.speed), arm)
        way = walker[0]
        if crosser == PLAYER:
            mover_at = walker[1]
            for k in range(n):
                mover_inputs[k]["velocity"] = walk[k]
        else:
            walkers[OTHER] = walk
            monsters.append(_player(OTHER, TALL, lb, *walker[1], ground, *walker[2], other_pks, body))
    if arm in ("quiet", "sphereless") or (arm == "report" and draw(dr.BOOLEANS)):  # a crate (a GenericObject) pushed into the target from beside it
        side = 1.0 if draw(dr.BOOLEANS) else -1.0
        cx, cy = tx + side * uy * 1.5, ty - side * ux * 1.5
        push = float(dr.take(draw, PUSHES))
        walkers[CRATE] = [(to_f32(-side * uy * push), to_f32(side * ux * push), 0.0)] * n
        crate = OtherMover(CRATE, "object", BODY, Position(_cell(lb, cx, cy), Frame((to_f32(cx), to_f32(cy), to_f32(ground)))),
                           0.4, 0.4, state=body, transient_state=WALKING)
        if arm == "quiet":  # a weenie with ReportCollisions false (InitPhysicsObj clears the bit with it)
            crate = replace(crate, state=body & ~int(PhysicsState.ReportCollisions), report_collisions=False)
        if arm == "sphereless":  # a GenericObject of BSP parts: no spheres
            crate = replace(crate, spheres=())
            if draw(dr.BOOLEANS):  # in the air: Active, never on walkable ground
                crate = replace(crate, transient_state=int(TransientState.Active),
                                begin=replace(crate.begin, frame=Frame((crate.begin.frame.origin[0], crate.begin.frame.origin[1],
                                                                        to_f32(ground + 1.5)))))
        monsters.append(crate)
    elif arm == "run_into" and draw(dr.BOOLEANS):  # a crate standing half way: the arrow hits what it is not aimed at
        cx, cy = (x0 + tx) / 2, (y0 + ty) / 2
        monsters.append(OtherMover(CRATE, "object", BODY, Position(_cell(lb, cx, cy), Frame((to_f32(cx), to_f32(cy), to_f32(ground)))),
                                   0.4, 0.4, state=body, transient_state=WALKING))
    others = tuple(monsters) + (projectile,)
    if monsters and draw(dr.BOOLEANS):  # the projectile entered first: stepped before the monsters
        others = (projectile,) + tuple(monsters)
    carried = draw(CARRIED)
    if carried != "none":  # a child held by the projectile before its launch: the launch's enter_world takes it along
        others = _carrying(draw, others, projectile, carried)

    mx, my = mover_at
    cell = _cell(lb, mx, my)
    facing = walker[2] if crosser == PLAYER else (ux, uy)
    mover = Mover(spheres=TALL if crosser == PLAYER else BODY,
                  begin=Position(cell, Frame((to_f32(mx), to_f32(my), to_f32(ground)), _heading(*facing))),
                  end=None, step_up_height=0.4, step_down_height=0.4, state=body, transient_state=WALKING,
                  contact_plane=ContactPlane(cell, PlaneRec((0.0, 0.0, 1.0), -ground)), placement=Placement(via="enter_world"),
                  player_killer_status=mover_pks if crosser is not None else int(PlayerKillerStatus.NPK))
    steps = []
    for k in range(n):
        theirs = ((OtherInputs(MONSTER, velocity=monster_velocity if k * dt < walk_for else (0.0, 0.0, 0.0)),)
                  if monster_velocity is not None else ())
        theirs += tuple(OtherInputs(i, velocity=v[k]) for i, v in walkers.items())
        steps.append(TickStep(dt, others=theirs, **mover_inputs[k]))
    land = (Landblock(lb << 16 | 0xFFFF, (h,) * 81, (0,) * 81),)
    if arm == "across":
        land += (Landblock((lb + 1) << 16 | 0xFFFF, (h,) * 81, (0,) * 81),)
    name = f"missiles:{policy}:{'arrow' if arrow else 'spell'}:{'player' if player_launches else 'monster'}"
    if arm is not None:
        name = f"missiles:{arm}:{name[9:]}" + (":alt_solver" if launch.alt_solver and arm != "alt_solver" else "")
    if crosser is not None:  # who crosses (or is the target), how, and the players' PlayerKillerStatus
        name += f":{role}:{way}:{PK_NAMES[mover_pks]}:{PK_NAMES[other_pks]}"
    if carried != "none":
        name += f":carries-{carried}"
    return validate_scene(Scene(land, mover, tuple(objects), engine_mode="server", name=name,
                                ticks=Ticks("update_object", 1000.0, tuple(steps)), others=others))


# ------------------------------------------------------------------ a launch at a border (issue 41, stop 50)
# The projectile's Location is its launcher's with Pos moved to the spawn point, whose setter (ACE.Entity.Position
# .SetPosition) finds the outdoor landblock and cell of the spawn point anew: these arms spawn it across a line.
BORDER_ARMS = st.sampled_from(("cell_border", "cell_border", "cell_border", "block_border", "block_border", "world_edge",
                               "world_edge"))
BORDER_GAPS = dr.OneOf(st.sampled_from((0.8, 0.4, 0.05)), dr.f32(0.01, 0.79))  # how far short of the line the launcher stands
CELL_LINES = dr.ints(2, 6)  # the cell line crossed: x or y = 24 k
AXES = st.sampled_from(((0.0, 1.0), (1.0, 0.0), (0.0, -1.0), (-1.0, 0.0)))  # north, east, south, west
EDGE_BLOCKS = {(1.0, 0.0): 0xFE40, (0.0, 1.0): 0x40FE, (-1.0, 0.0): 0x0040, (0.0, -1.0): 0x4000}  # the world's edges
INNER_BLOCKS = {(1.0, 0.0): 0xA9B4, (0.0, 1.0): 0x7F7F, (-1.0, 0.0): 0x2B10, (0.0, -1.0): 0xC6A0}


def _step_block(lb: int, ux: float, uy: float) -> int:
    """The landblock next to `lb` along an axis (x the high byte, y the low)."""
    return lb + (int(ux) << 8) + int(uy)


def _spell_projectile(draw, launch_tick: int, launcher: int, target: int | None, origin, lb: int, x0: float, y0: float,
                      ground: float) -> OtherMover:
    """An edge scene's spell projectile (a SpellProjectile of 10-30 cm, made at its launcher's feet): its speed, an
    arc one time in three when it has a target, tracking half the time, its radius, drawn in that order."""
    launch = Launch(launch_tick, launcher, target, to_f32(dr.take(draw, SPELL_SPEEDS)), origin,
                    arc=target is not None and draw(st.sampled_from((False, False, True))),
                    tracking=draw(dr.BOOLEANS))
    return OtherMover(PROJECTILE, "spell_projectile", (SphereRec((0.0, 0.0, 0.0), to_f32(dr.take(draw, SPELL_RADII))),),
                      Position(_cell(lb, x0, y0), Frame((to_f32(x0), to_f32(y0), to_f32(ground)))), 0.0, 0.0,
                      state=0, transient_state=0, launch=launch)


def _edge_scene(land_ids, h: int, lb: int, mover_at, ux: float, uy: float, monsters: list, projectile: OtherMover,
                dt: float, n: int, name: str) -> Scene:
    """An edge scene from its parts (draw_border_scene's, draw_relocation_scene's; nothing drawn here): the player
    (the mover) entering the world at `mover_at` on landblock `lb`'s flat land facing along (ux, uy), standing
    for `n` plain ticks of `dt`; the monsters, then the projectile; flat landblocks of height index `h`."""
    ground = 2.0 * h
    others = tuple(monsters) + (projectile,)
    mx, my = mover_at
    cell = _cell(lb, mx, my)
    mover = Mover(spheres=BODY, begin=Position(cell, Frame((to_f32(mx), to_f32(my), to_f32(ground)), _heading(ux, uy))),
                  end=None, step_up_height=0.4, step_down_height=0.4, state=EDGE_SLIDE, transient_state=WALKING,
                  contact_plane=ContactPlane(cell, PlaneRec((0.0, 0.0, 1.0), -ground)), placement=Placement(via="enter_world"))
    steps = [TickStep(dt) for _ in range(n)]
    land = tuple(Landblock(b << 16 | 0xFFFF, (h,) * 81, (0,) * 81) for b in land_ids)
    return validate_scene(Scene(land, mover, (), engine_mode="server", name=name,
                                ticks=Ticks("update_object", 1000.0, tuple(steps)), others=others))


def draw_border_scene(draw, arm: str | None = None) -> Scene:
    """A launch whose spawn point lies across a line from its launcher (BORDER_ARMS, or `arm`), on flat land:

    - ``cell_border``: the launcher stands 0.01-0.8 m short of a cell line (x or y = 24 k), facing across it along an
      axis or at a slant; an arrow or a spell at a monster 3-12 m on (or from a monster at the player): the Location's
      cell is the next one, where enter_world starts;
    - ``block_border``: an untargeted spell (along the caster's forward vector) from the landblock's edge, out over
      it: the Location moves onto the next landblock (its Pos 192 m back), which the scene holds, or, one time in
      five, lacks (refused by both: NotSupportedException);
    - ``world_edge``: the same at the edge of the world (landblock x or y 0xFE, east or north: X or Y clamped to 192,
      the cell id past the landblock's 64, which get_landcell refuses: AddPhysicsObj fails and the spell is
      destroyed; 0x00, west or south: clamped to 0, a cell of the landblock)."""
    arm = arm or draw(BORDER_ARMS)
    h = dr.take(draw, HEIGHTS)
    ground = 2.0 * h
    n = dr.take(draw, dr.ints(20, 40))
    dt = draw(DTS)
    launch_tick = min(dr.take(draw, LAUNCH_TICKS), n - 1)
    eye = float(dr.take(draw, EYES))
    gap = float(dr.take(draw, BORDER_GAPS))
    ux, uy = draw(AXES)
    lb = draw(BLOCKS)
    land_ids = [lb]
    player_launches = draw(st.sampled_from((True, True, False)))
    arrow = arm == "cell_border" and draw(st.sampled_from((True, True, False)))
    target: int | None = MONSTER
    monsters = []
    if arm == "cell_border":
        k = dr.take(draw, CELL_LINES)
        along = 24.0 * k - gap if (ux + uy) > 0 else 24.0 * k + gap  # the coordinate along the axis, short of the line
        across = float(dr.take(draw, SPOTS))
        x0, y0 = (along, across) if ux != 0.0 else (across, along)
        if draw(st.sampled_from((False, False, True))):  # at a slant: 10-80 degrees off the axis
            t = math.radians(float(dr.take(draw, dr.f32(10.0, 80.0))) * (1.0 if draw(dr.BOOLEANS) else -1.0))
            ux, uy = ux * math.cos(t) - uy * math.sin(t), ux * math.sin(t) + uy * math.cos(t)
        d = float(dr.take(draw, dr.f32(3.0, 12.0)))
        tx, ty = x0 + ux * d, y0 + uy * d
    else:
        if arm == "world_edge":
            lb = EDGE_BLOCKS[(ux, uy)]
            land_ids = [lb]
        elif draw(st.sampled_from((True, True, True, True, False))):  # the next landblock is the scene's
            lb = INNER_BLOCKS[(ux, uy)]
            land_ids = [lb, _step_block(lb, ux, uy)]
        else:
            lb = INNER_BLOCKS[(ux, uy)]
            land_ids = [lb]
        edge = 192.0 - gap if (ux + uy) > 0 else gap
        across = float(dr.take(draw, SPOTS))
        x0, y0 = (edge, across) if ux != 0.0 else (across, edge)
        tx, ty = x0 - ux * 4.0 + uy * 3.0, y0 - uy * 4.0 - ux * 3.0  # a monster standing by, inside
    if arm == "cell_border" and not player_launches:  # a monster launches at the player
        launcher, target = CASTER, PLAYER
        mover_at = (tx, ty)
        monsters.append(_monster(CASTER, lb, x0, y0, ground))
    elif player_launches:
        launcher, mover_at = PLAYER, (x0, y0)
        monsters.append(_monster(MONSTER, lb, tx, ty, ground))
    else:
        launcher, mover_at = CASTER, (tx, ty)
        monsters.append(_monster(CASTER, lb, x0, y0, ground))
        target = PLAYER
    if arm in ("block_border", "world_edge"):
        target = None
    origin = (to_f32(x0 + ux * 0.8), to_f32(y0 + uy * 0.8), to_f32(ground + eye))
    if arrow:
        launch = Launch(launch_tick, launcher, target, to_f32(dr.take(draw, ARROW_SPEEDS)), origin, _heading(ux, uy),
                        lead_target=draw(dr.BOOLEANS))
        projectile = OtherMover(PROJECTILE, "ammunition", (SphereRec((0.0, 0.0, 0.0), to_f32(dr.take(draw, ARROW_RADII))),),
                                Position(_cell(lb, x0, y0), Frame((to_f32(x0), to_f32(y0), to_f32(ground)))), 0.0, 0.0,
                                state=int(PhysicsState.Gravity), transient_state=0, launch=launch)
    else:
        projectile = _spell_projectile(draw, launch_tick, launcher, target, origin, lb, x0, y0, ground)
    name = (f"missiles:{arm}:{'arrow' if arrow else 'spell'}:{'player' if launcher == PLAYER else 'monster'}"
            f":{'north' if uy > 0.5 else 'south' if uy < -0.5 else 'east' if ux > 0.5 else 'west' if ux < -0.5 else 'slant'}")
    if arm == "block_border" and len(land_ids) == 1:
        name += ":unloaded"
    return _edge_scene(land_ids, h, lb, mover_at, ux, uy, monsters, projectile, dt, n, name)


# ------------------------------------------------------------------ a projectile flying into the next landblock (issue 41)
# After a tick's physics, LandblockManager.RelocateObjectForPhysics moves each object whose landblock changed to its
# new landblock (the old one's RemoveWorldObjectForPhysics with adjacencyMove, the new one's AddWorldObjectForPhysics,
# GetLandblock(id, true)'s SetAdjacents): these spells are launched inside their launcher's landblock and fly across
# its edge into the next one, which the scene holds.
RELOCATION_GAPS = dr.OneOf(st.sampled_from((1.0, 2.0, 4.0)), dr.f32(0.9, 8.0))  # how far short of the edge the caster stands


def draw_relocation_scene(draw) -> Scene:
    """An untargeted spell (along its caster's forward vector: the player's, or a monster's) cast 0.9-8 m short of a
    landblock's edge, out across it, on flat land of two landblocks side by side (north, east, south or west): it
    flies into the next landblock, where, one time in two, a monster stands in its path 2-8 m past the edge (some
    spells strike it there: ProjectileImpact leaves them inert in the landblock they were moved to). Both sides relocate it
    after the tick it crosses in (port: missile_launch.relocate_object_for_physics; Facade.RelocateObjectForPhysics)."""
    h = dr.take(draw, HEIGHTS)
    ground = 2.0 * h
    n = dr.take(draw, dr.ints(20, 40))
    dt = draw(DTS)
    launch_tick = min(dr.take(draw, LAUNCH_TICKS), n - 1)
    eye = float(dr.take(draw, EYES))
    gap = float(dr.take(draw, RELOCATION_GAPS))
    ux, uy = draw(AXES)
    lb = INNER_BLOCKS[(ux, uy)]
    nb = _step_block(lb, ux, uy)
    edge = 192.0 - gap if (ux + uy) > 0 else gap
    across = float(dr.take(draw, SPOTS))
    x0, y0 = (edge, across) if ux != 0.0 else (across, edge)
    tx, ty = x0 - ux * 4.0 + uy * 3.0, y0 - uy * 4.0 - ux * 3.0  # a monster standing by, inside
    player_launches = draw(st.sampled_from((True, True, False)))
    monsters = []
    if player_launches:
        launcher, mover_at = PLAYER, (x0, y0)
        monsters.append(_monster(MONSTER, lb, tx, ty, ground))
    else:
        launcher, mover_at = CASTER, (tx, ty)
        monsters.append(_monster(CASTER, lb, x0, y0, ground))
    blocked = draw(dr.BOOLEANS)
    if blocked:  # a monster in the spell's path, past the edge (in the next landblock's frame)
        past = float(dr.take(draw, dr.f32(2.0, 8.0)))
        bx, by = x0 + ux * (gap + past), y0 + uy * (gap + past)
        bx, by = bx - 192.0 * ux if abs(ux) > 0.5 else bx, by - 192.0 * uy if abs(uy) > 0.5 else by
        monsters.append(_monster(MONSTER + 2, nb, bx, by, ground))
    origin = (to_f32(x0 + ux * 0.8), to_f32(y0 + uy * 0.8), to_f32(ground + eye))
    projectile = _spell_projectile(draw, launch_tick, launcher, None, origin, lb, x0, y0, ground)
    name = (f"missiles:relocate:spell:{'player' if launcher == PLAYER else 'monster'}"
            f":{'north' if uy > 0.5 else 'south' if uy < -0.5 else 'east' if ux > 0.5 else 'west'}"
            + (":blocked" if blocked else ""))
    return _edge_scene((lb, nb), h, lb, mover_at, ux, uy, monsters, projectile, dt, n, name)
