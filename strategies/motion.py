"""Motion tick scenes (issue 40; tick policy ``motion``): a player's motion table and MoveToState keys.

    draw_motion_ticks(draw, base)     a tick scene on `base`'s world: the mover given a drawn motion
                                      table, the ticks given a sequence of `motion` inputs

The table (acconform/motion_scene.py's MotionTableSpec, scene/6 ``mover.motion_table``) has the shapes
retail's human table has, small and varied: the NonCombat style defaulting to Ready; cycles for Ready
(always), WalkForward, RunForward, SideStepRight and TurnRight (each mostly there; MotionInterp's
adjust_motion makes WalkBackwards, SideStepLeft and TurnLeft into them with negative speeds), each an
animation with root motion (PosFrames moving along y, x or turning about z), at a framerate of 30, 15,
60, 10, 24 or 7.5 fps or played backward at -30 or -15, now and then a frame range (low/high frame), a Velocity or Omega mostly given,
and a Bitfield (bits 1 and 2: MotionTable.GetObjectSequence's and is_allowed's tests) now and then\n(bit 2 always on the turn and sidestep cycles: see draw_motion_table);
links between Ready and the others both ways (each mostly there, with an animation of its own),
and TurnRight and SideStepRight modifiers.

The inputs: the first tick a MoveToState (forward WalkForward, WalkBackwards or RunForward or none;
sidestep SideStepRight or SideStepLeft or none; turn TurnRight or TurnLeft or none; hold keys Run,
None or unset (Invalid), speeds 1 mostly, else 0.5, 1.5, 2 or any), then at drawn ticks more of them
or a stop (every key released, hold key None), mostly ending in a stop; one scene in four jumps
(the tick input jump, a local velocity up and forward) at a drawn tick. The worlds are the walk,
fall and jump policies' sites. The mover faces along its
world's path (a yaw about z), so a forward walk goes the way the other policies walk. Driver
update_object (MoveToState is the server's player path: its own position comes from ticks).

Shrinking: the inputs shrink toward one walk forward at speed 1 and no later input, the table toward
its first entries and plainest values.
"""

from __future__ import annotations

import math
from dataclasses import replace

from hypothesis import strategies as st

from acconform.flags import PlayerKillerStatus as PKS, TransientState
from acconform.motion_enums import HoldKey, MotionCommand as MC
from acconform.motion_enums import MovementParamFlags as MPF
from acconform.motion_scene import (DEFAULT_MOVEMENT_FLAGS, STOPS, AnimationSpec, AnimRef, CommandInput, MotionDataSpec,
                                    MotionEntry, MotionInput, MotionTableSpec, MovementParams, MoveToInput,
                                    ObjectMoveInput)
from acconform.numerics import to_f32
from acconform.scene import DEFAULT_SKILLS, ENV_CELL_FIRST, Frame, MoverSkills, Position, Scene, SphereRec, SphereShape, StaticObject

from . import draws as dr

NC = int(MC.NonCombat)
READY, WALK, RUN = int(MC.Ready), int(MC.WalkForward), int(MC.RunForward)
SIDE, TURN = int(MC.SideStepRight), int(MC.TurnRight)

FRAMERATES = st.sampled_from((30.0, 30.0, 15.0, 60.0, 10.0, 24.0, 7.5, -30.0, -15.0))  # negative: played backward
FRAME_COUNTS = st.integers(1, 8)
FRAME_RANGES = st.sampled_from(("all", "all", "all", "low1", "first3", "high_past_end", "one"))
BITFIELDS = st.sampled_from((0, 0, 0, 0, 1, 2, 3))
MOSTLY = st.sampled_from((True, True, True, False))
HALF = st.sampled_from((True, False))
# root motion per frame (metres or degrees)
STRIDES = dr.OneOf(st.sampled_from((0.05, 0.1, 0.02, 0.2)), dr.f32(0.0, 0.3))
TURN_STEPS = dr.OneOf(st.sampled_from((-3.0, -6.0, 3.0)), dr.f32(-10.0, 10.0))
WALK_VELOCITIES = dr.OneOf(st.sampled_from((3.12, 2.5, 1.0)), dr.f32(0.1, 6.0))
RUN_VELOCITIES = dr.OneOf(st.sampled_from((4.0, 11.0, 6.0)), dr.f32(1.0, 12.0))
SIDE_VELOCITIES = dr.OneOf(st.sampled_from((1.25, 2.0, -1.25)), dr.f32(-3.0, 3.0))
OMEGAS = dr.OneOf(st.sampled_from((-1.5, -0.5, 1.5, -3.0)), dr.f32(-4.0, 4.0))

FORWARDS = st.sampled_from((WALK, WALK, 0, int(MC.WalkBackwards), RUN))
# now and then a forward command that is no walk (one input in 8): the substates a client's RawMotionState
# may carry (Crouch, Sitting, Sleeping: motion_allows_jump's and DoMotion's combat refusals; Dead and Falling:
# contact_allows_move's first test; Reload: an action-like substate) and an action or emote (Cheer, Twitch1)
ODD_FORWARDS = st.sampled_from((int(MC.Crouch), int(MC.Sitting), int(MC.Sleeping), int(MC.Dead), int(MC.Falling),
                                int(MC.Reload), int(MC.Cheer), int(MC.Twitch1)))
ODD = st.sampled_from((False,) * 7 + (True,))
# the RawMotionState's style: unset mostly (SetState makes it NonCombat), else NonCombat or a combat style the
# table lacks (MotionInterp.DoMotion's combat refusals, RawMotionState.ApplyMotion's and RemoveMotion's style arms)
STYLES = st.sampled_from((0,) * 13 + (int(MC.NonCombat), int(MC.HandCombat), int(MC.Magic)))
SIDESTEPS = st.sampled_from((0, 0, 0, SIDE, int(MC.SideStepLeft)))
TURNS = st.sampled_from((0, 0, TURN, int(MC.TurnLeft)))
HOLD_KEYS = st.sampled_from((int(HoldKey.None_), int(HoldKey.Run), 0))
INPUT_SPEEDS = dr.OneOf(st.sampled_from((1.0, 1.0, 1.0, 0.5, 1.5, 2.0)), dr.f32(0.1, 3.0))
INPUT_KINDS = st.sampled_from(("move", "move", "stop"))
SEGMENTS = dr.ints(0, 4)  # inputs after the first
LAST_STOP = st.sampled_from((True, True, False))
JUMPS = st.sampled_from((False, False, False, True))  # a jump (the tick input jump) among the keys
# the Player's PlayerKillerStatus: PK and PKLite jump by HandleActionJump's FastTick branch, Free is impenetrable
PLAYER_KILLER_STATUSES = st.sampled_from((PKS.NPK, PKS.NPK, PKS.NPK, PKS.NPK, PKS.PK, PKS.PK, PKS.PKLite, PKS.Free))
# the Player's skills, vitals, attributes and burden (scene/8 mover.skills): the database-free Player's one
# scene in two, else each drawn with the values where ACE's formulas change: GetRunRate's 800 (4.5 from there
# on), GetJumpHeight's floor 0.35 (a jump skill under 19), a stamina of 0 (no jump skill), EncumbranceCapacity's
# augmentation cap (6 and more count as 5) and negative bonus, its int wrap (150 * 14,316,558), GetBurden's
# negative load and GetBurdenMod's 1 and 2 (a load of 15,000 and 30,000 on Strength 100)
DEFAULT_PLAYER = st.sampled_from((True, False))
RUN_SKILLS = dr.OneOf(st.sampled_from((0, 300, 799, 800, 801, 100)), dr.ints(0, 1000))
JUMP_SKILLS = dr.OneOf(st.sampled_from((0, 250, 18, 19, 1300)), dr.ints(0, 1000))
STAMINAS = st.sampled_from((1, 100, 0, 0xFFFFFFFF))
STRENGTHS = st.sampled_from((100, 1, 10, 290, 14316557, 14316558))
ENCUMBRANCES = dr.OneOf(st.sampled_from((0, 15000, 30000, 14999, -1, 45000)), dr.ints(0, 50000))
CARRYING_AUGS = st.sampled_from((0, 1, 5, 6, -1))
TICK_COUNTS = dr.OneOf(dr.ints(10, 40), dr.ints(20, 60), dr.ints(1, 10))

# the server's calls into the managers (one scene in two): what drives the mover first
MANAGED = st.sampled_from((False, True))
GOALS = st.sampled_from(("move_to", "move_to", "move_to_exact", "move_to_object", "sticky", "sticky",
                         "turn_to_heading", "turn_to_object", "turn_to_object", "keys", "actions", "actions"))
HEADINGS = dr.OneOf(st.sampled_from((0.0, 90.0, 180.0, 270.0, 135.0, 359.0)), dr.f32(0.0, 360.0))
DISTANCES = dr.OneOf(st.sampled_from((0.6, 0.0, 1.0, 0.5, 2.0)), dr.f32(0.0, 4.0))
MIN_DISTANCES = dr.OneOf(st.sampled_from((0.0, 0.0, 0.0, 0.5)), dr.f32(0.0, 1.0))
FAIL_DISTANCES = st.sampled_from((None, None, None, 15.0, 2.0))  # None: float.MaxValue
MOVE_SPEEDS = dr.OneOf(st.sampled_from((1.0, 1.0, 1.5, 0.5)), dr.f32(0.25, 3.0))
WALK_RUN = dr.OneOf(st.sampled_from((1.0, 15.0, 0.0, 5.0)), dr.f32(0.0, 20.0))
FLAG_CHANGES = st.sampled_from((0, 0, MPF.UseFinalHeading, MPF.FailWalk, MPF.MoveAway, MPF.CanCharge,
                                MPF.CanRun | MPF.CanWalk, MPF.UseSpheres, MPF.StopCompletely | MPF.CancelMoveTo))
HOLD_TO_APPLY = st.sampled_from((0, 0, int(HoldKey.Run), int(HoldKey.None_)))
TARGET_TS = st.sampled_from((1.0, 1.0, 0.5, 1.5, 0.25))  # where along the path (1: its end, past its obstacles)
LATER = dr.ints(0, 3)  # stops, turns and keys after the first
LATER_KINDS = st.sampled_from(("stop", "stop", "turn_to_heading", "move_to", "do_motion", "stop_motion"))
KEY_COMMANDS = dr.OneOf(st.sampled_from((WALK, RUN, TURN, SIDE, int(MC.TurnLeft), int(MC.WalkBackwards), READY)),
                        st.sampled_from((int(MC.SideStepLeft), int(MC.Crouch), int(MC.Sitting), int(MC.Sleeping),
                                         int(MC.Cheer), int(MC.Twitch1), int(MC.HandCombat), int(MC.NonCombat),
                                         int(MC.Dead), int(MC.Falling))))
ACTIONS = (int(MC.Twitch1), int(MC.Cheer))  # the table's actions (links from Ready), when it has them
BURSTS = st.integers(1, 8)  # actions asked for on successive ticks: the 6 DoMotion allows pending, and more
STYLE_FIRST = st.sampled_from((False, False, False, True))  # a managed scene's MoveToState with a style first
TARGET_ID = 0x7F000001  # a sphere the scene gains to follow when its world has no outdoor static


def _yaw(deg: float) -> tuple:
    h = math.radians(deg) / 2
    return (to_f32(math.cos(h)), 0.0, 0.0, to_f32(math.sin(h)))


def _animation(draw, move: str) -> AnimationSpec:
    n = draw(FRAME_COUNTS)
    if move == "turn":
        step = float(dr.take(draw, TURN_STEPS))
        return AnimationSpec(tuple(Frame((0.0, 0.0, 0.0), _yaw(step * i)) for i in range(n)))
    stride = float(dr.take(draw, STRIDES))
    axis = 0 if move == "side" else 1
    return AnimationSpec(tuple(Frame(tuple(to_f32(stride * i) if k == axis else 0.0 for k in range(3)))
                               for i in range(n)))


def _anim_ref(draw, index: int, frames: int) -> AnimRef:
    fr = draw(FRAMERATES)
    how = draw(FRAME_RANGES)
    if how == "low1" and frames > 1:
        return AnimRef(index, fr, 1, -1)
    if how == "first3" and frames > 3:
        return AnimRef(index, fr, 0, 2)
    if how == "high_past_end":  # AnimSequenceNode clamps a high frame past the last
        return AnimRef(index, fr, 0, frames + 2)
    if how == "one":  # a single frame: low == high
        return AnimRef(index, fr, frames - 1, frames - 1)
    return AnimRef(index, fr)


def draw_motion_table(draw) -> tuple[MotionTableSpec, str]:
    """A table and a label naming what it has (W walk, R run, S sidestep, T turn; l links, m modifiers)."""
    animations: list[AnimationSpec] = []

    def anim(move: str) -> AnimRef:
        a = _animation(draw, move)
        animations.append(a)
        return _anim_ref(draw, len(animations) - 1, len(a.pos_frames))

    def data(move: str, velocity=None, omega=None, bitfield: int = 0) -> MotionDataSpec:
        return MotionDataSpec((anim(move),), velocity, omega, draw(BITFIELDS) | bitfield)

    cycles = [MotionEntry(NC, READY, MotionDataSpec((anim("still"),)))]
    label = ""
    for motion, move, tag, speeds in ((WALK, "walk", "W", WALK_VELOCITIES), (RUN, "walk", "R", RUN_VELOCITIES),
                                      (SIDE, "side", "S", SIDE_VELOCITIES), (TURN, "turn", "T", OMEGAS)):
        if not draw(MOSTLY):
            continue
        label += tag
        v = float(dr.take(draw, speeds)) if draw(MOSTLY) else None
        # a turn or sidestep cycle is allowed only from the style's default (Bitfield 2, as retail's tables
        # have it): without, a turn and a sidestep, each a substate and a modifier, make each other the
        # substate in turn (GetObjectSequence -> re_modify -> GetObjectSequence ...) until ACE's stack overflows
        bits = 2 if move in ("turn", "side") else 0
        if v is None:
            cycles.append(MotionEntry(NC, motion, data(move, bitfield=bits)))
        elif move == "turn":
            cycles.append(MotionEntry(NC, motion, data(move, omega=(0.0, 0.0, to_f32(v)), bitfield=bits)))
        elif move == "side":
            cycles.append(MotionEntry(NC, motion, data(move, velocity=(to_f32(v), 0.0, 0.0), bitfield=bits)))
        else:
            cycles.append(MotionEntry(NC, motion, data(move, velocity=(0.0, to_f32(v), 0.0))))
    links = []
    for c in cycles[1:]:
        for frm, to in ((READY, c.motion), (c.motion, READY)):
            if draw(MOSTLY):
                links.append(MotionEntry(NC, frm, data("walk" if c.motion != TURN else "turn"), to=to))
    modifiers = []
    for motion, move in ((TURN, "turn"), (SIDE, "side")):
        if draw(HALF):
            v = to_f32(dr.take(draw, OMEGAS if move == "turn" else SIDE_VELOCITIES))
            vel = (v, 0.0, 0.0) if move == "side" else None
            om = (0.0, 0.0, v) if move == "turn" else None
            modifiers.append(MotionEntry(NC, motion, data(move, vel, om)))
    if draw(HALF):  # actions (Twitch1, the emote Cheer) as retail's tables have them: links from Ready
        for action in ACTIONS:
            links.append(MotionEntry(NC, READY, data("still"), to=action))
        label += "a"
    label += (f"l{len(links)}" if links else "") + (f"m{len(modifiers)}" if modifiers else "")
    table = MotionTableSpec(NC, ((NC, READY),), tuple(animations), tuple(cycles), tuple(links), tuple(modifiers))
    return table, label or "ready"


def _speed(draw) -> float:
    return float(to_f32(dr.take(draw, INPUT_SPEEDS)))


def draw_motion_input(draw) -> tuple[MotionInput, str]:
    if draw(INPUT_KINDS) == "stop":
        return MotionInput(hold_key=int(HoldKey.None_)), "stop"
    kw = {"hold_key": draw(HOLD_KEYS)}
    tag = ""
    style = draw(STYLES)
    if style:
        kw["style"] = style
        tag += "y"
    for name, commands, short in (("forward", FORWARDS, "f"), ("sidestep", SIDESTEPS, "s"), ("turn", TURNS, "t")):
        c = draw(commands)
        if name == "forward" and draw(ODD):
            c = draw(ODD_FORWARDS)
            short = "o"
        if c:
            kw[name], kw[f"{name}_hold_key"], kw[f"{name}_speed"] = c, draw(HOLD_KEYS), _speed(draw)
            tag += short
    return MotionInput(**kw), tag or "none"


def draw_skills(draw) -> MoverSkills:
    if draw(DEFAULT_PLAYER):
        return DEFAULT_SKILLS
    return MoverSkills(run=dr.take(draw, RUN_SKILLS), jump=dr.take(draw, JUMP_SKILLS), stamina=draw(STAMINAS),
                       strength=draw(STRENGTHS), encumbrance_val=dr.take(draw, ENCUMBRANCES),
                       augmentation_increased_carrying_capacity=draw(CARRYING_AUGS))


def draw_motion_ticks(draw, base: Scene, clock) -> Scene:
    """`clock(draw, n)` -> (start, dts, label): strategies/ticks.py's clock."""
    from .ticks import _path, _tick_scene, _unit

    table, tlabel = draw_motion_table(draw)
    n = dr.take(draw, TICK_COUNTS)
    start, dts, clabel = clock(draw, n)
    inputs = [{} for _ in range(n)]
    g0, g1 = _path(base)
    if draw(MANAGED):  # the server's calls into the managers instead of a player's keys
        first_inputs, later, base, mlabel = draw_managed_inputs(draw, base, n, g0, g1)
        inputs[0].update(first_inputs)
        if draw(STYLE_FIRST):  # a MoveToState setting a style (and maybe a substate) before the server's calls
            inputs[0]["motion"] = MotionInput(hold_key=draw(HOLD_KEYS), style=draw(STYLES) or int(MC.HandCombat),
                                              forward=draw(ODD_FORWARDS) if draw(HALF) else 0)
            mlabel = "style+" + mlabel
        for at, inp in later:
            inputs[at].update(inp)
        skills = draw_skills(draw)
        return _motion_scene(base, table, start, dts, inputs, g0, g1, f"{tlabel}:managed:{mlabel}:run{skills.run}:{clabel}",
                             skills=skills)
    first, tag = draw_motion_input(draw)
    if tag == "stop":
        first, tag = MotionInput(hold_key=int(HoldKey.None_), forward=WALK, forward_hold_key=int(HoldKey.None_),
                                 forward_speed=1.0), "f"
    inputs[0]["motion"] = first
    tags = [tag]
    for _ in range(min(dr.take(draw, SEGMENTS), n - 1)):
        at = draw(st.integers(1, n - 1))
        inputs[at]["motion"], t = draw_motion_input(draw)
        tags.append(f"{t}@{at}")
    if n > 2 and draw(LAST_STOP):
        inputs[n - 1]["motion"] = MotionInput(hold_key=int(HoldKey.None_))
        tags.append("stop-last")
    if n > 1 and draw(JUMPS):  # HandleActionJump's physics with the motion layer: LeaveGround, then HitGround
        from .ticks import JUMP_FORWARD, JUMP_UPS

        at = draw(st.integers(0, n - 1))
        inputs[at]["jump"] = (0.0, to_f32(dr.take(draw, JUMP_FORWARD)), to_f32(dr.take(draw, JUMP_UPS)))
        tags.append(f"jump@{at}")
    status = draw(PLAYER_KILLER_STATUSES)
    skills = draw_skills(draw)
    return _motion_scene(base, table, start, dts, inputs, g0, g1,
                         f"{tlabel}:{'+'.join(tags)}:{status.name}:run{skills.run}:{clabel}", status, skills)


def _motion_scene(base: Scene, table, start, dts, inputs, g0, g1, label: str, status=PKS.NPK,
                  skills: MoverSkills = DEFAULT_SKILLS) -> Scene:
    from .ticks import _tick_scene, _unit

    ux, uy = _unit(g1[0] - g0[0], g1[1] - g0[1])
    heading = math.degrees(math.atan2(-ux, uy))  # local +y along the path (a yaw about z)
    m = base.mover
    begin = Position(m.begin.cell, Frame(m.begin.frame.origin, _yaw(heading)))
    base = base.replace(mover=replace(m, begin=begin, motion_table=table, player_killer_status=int(status), skills=skills,
                                      transient_state=m.transient_state | int(TransientState.Active)))
    return _tick_scene(base, start, dts, inputs, "update_object", None, f"ticks:motion:{base.name}:{label}")


def _params(draw, sticky: bool = False, heading=None) -> MovementParams:
    flags = (DEFAULT_MOVEMENT_FLAGS ^ int(draw(FLAG_CHANGES))) | (int(MPF.Sticky) if sticky else 0)
    fail = draw(FAIL_DISTANCES)
    return MovementParams(flags=flags, distance_to_object=float(to_f32(dr.take(draw, DISTANCES))),
                          min_distance=float(to_f32(dr.take(draw, MIN_DISTANCES))),
                          fail_distance=MovementParams().fail_distance if fail is None else fail,
                          speed=float(to_f32(dr.take(draw, MOVE_SPEEDS))),
                          walk_run_threshold=float(to_f32(dr.take(draw, WALK_RUN))),
                          desired_heading=float(to_f32(dr.take(draw, HEADINGS))) if heading is None else heading,
                          hold_key_to_apply=draw(HOLD_TO_APPLY))


def _point(base: Scene, g0, g1, t: float):
    """The point `t` along the path, as a Position in the cell that holds it (None: no defined cell)."""
    from .terrain import split_global
    from .ticks import _cell_at

    g = tuple(a + (b - a) * t for a, b in zip(g0, g1))
    cell = _cell_at(base, g)
    if cell is None:
        return None, g
    _, _, lx, ly = split_global(g[0], g[1])
    return Position(cell, Frame((to_f32(lx), to_f32(ly), to_f32(g[2])))), g


ULP_STEPS = st.sampled_from((0, 0, 0, -1, 1))  # the distance itself, or one float32 ulp either side


def _distance_to_go(begin: Position, target: Position, params: MovementParams, ulps: int) -> float:
    """The float32 distance from `begin` to `target` as ACE's MoveToManager.GetCurrentDistance measures
    it for these parameters (computed by the port's Position: Distance, or with UseSpheres the
    (float) CylinderDistance of the Setups' radius and height, 0 in every Setup acconform writes),
    `ulps` float32 steps away: the MoveTo's DistanceToObject at which its first arrival test
    `dist <= DistanceToObject` holds exactly (0), or just fails (-1)."""
    import numpy as np

    from acconform.numerics import get_mode
    from acconform.port.frame import Position as PortPosition

    mode = get_mode("exact")
    a, b = PortPosition.from_record(begin, mode), PortPosition.from_record(target, mode)
    zero = mode.scalar(0.0)
    d = mode.scalar(PortPosition.cylinder_distance(zero, zero, a, zero, zero, b)) if params.flags & int(MPF.UseSpheres) \
        else a.distance(b)
    for _ in range(abs(ulps)):
        d = np.nextafter(d, np.float32(np.inf if ulps > 0 else -np.inf), dtype=np.float32)
    return float(d)


def draw_managed_inputs(draw, base: Scene, n: int, g0, g1) -> tuple[dict, list, Scene, str]:
    """The server's calls into the managers (the tick inputs move_to, move_to_object, turn_to_heading,
    turn_to_object, stop, do_motion, stop_motion) for a scene of `n` ticks on `base`'s path: a first
    input at tick 0 (a MoveTo toward the path's end, past its walls and steps, or part way; a MoveTo
    whose DistanceToObject is exactly the distance to go, so it arrives at once; a MoveTo or a sticky
    MoveTo to a static, the world's own outdoor one or a sphere the scene gains on the path; a turn in
    place or to a static; a key's DoMotion), then a few stops, turns, MoveTos and keys at drawn ticks.
    Returns (the first inputs, [(tick, inputs)], the scene, a label)."""
    goal = draw(GOALS)
    first: dict = {}
    scene = base
    t = draw(TARGET_TS)
    pos, g = _point(base, g0, g1, t)
    if pos is None or (goal in ("move_to_object", "sticky", "turn_to_object") and pos.cell & 0xFFFF >= ENV_CELL_FIRST):
        goal = "turn_to_heading"  # no cell there, or a static there would be an EnvCell's (ACE files none)
    if goal in ("move_to", "move_to_exact"):
        params = _params(draw)
        if goal == "move_to_exact":  # DistanceToObject the distance to go: arrives on its first check
            params = replace(params, distance_to_object=_distance_to_go(base.mover.begin, pos, params,
                                                                        draw(ULP_STEPS)), min_distance=0.0)
        first["move_to"] = MoveToInput(params, pos)
    elif goal in ("move_to_object", "sticky", "turn_to_object"):
        targets = [o for o in base.objects if o.position.cell & 0xFFFF < ENV_CELL_FIRST]
        if targets and draw(HALF):
            target = targets[draw(st.integers(0, len(targets) - 1))].id
        else:
            target = TARGET_ID
            ball = StaticObject(TARGET_ID, pos, SphereShape(SphereRec((0.0, 0.0, 0.5), 0.5)))
            scene = base.replace(objects=base.objects + (ball,))
        move = ObjectMoveInput(target, _params(draw, sticky=goal == "sticky"))
        first["turn_to_object" if goal == "turn_to_object" else "move_to_object"] = move
    elif goal == "turn_to_heading":
        first["turn_to_heading"] = MoveToInput(_params(draw))
    elif goal == "actions":  # a client's emotes and actions, one DoMotion a tick (the table's, or none)
        first["do_motion"] = CommandInput(draw(st.sampled_from(ACTIONS)), draw(HOLD_TO_APPLY))
    else:
        first["do_motion"] = CommandInput(dr.take(draw, KEY_COMMANDS), draw(HOLD_TO_APPLY))
    tags = [goal]
    later = []
    if goal == "actions":
        k = min(draw(BURSTS), n) - 1
        later = [(at, {"do_motion": CommandInput(draw(st.sampled_from(ACTIONS)), draw(HOLD_TO_APPLY))})
                 for at in range(1, k + 1)]
        tags.append(f"x{k + 1}")
    for _ in range(min(dr.take(draw, LATER), n - 1)):
        at = draw(st.integers(1, n - 1))
        kind = draw(LATER_KINDS)
        if kind == "stop":
            stop = draw(st.sampled_from(STOPS))
            later.append((at, {"stop": stop}))
            tags.append(f"{stop}@{at}")
            continue
        if kind == "move_to" and pos is not None:
            later.append((at, {"move_to": MoveToInput(_params(draw), pos)}))
        elif kind in ("do_motion", "stop_motion"):
            later.append((at, {kind: CommandInput(dr.take(draw, KEY_COMMANDS), draw(HOLD_TO_APPLY))}))
        else:
            kind = "turn_to_heading"
            later.append((at, {kind: MoveToInput(_params(draw))}))
        tags.append(f"{kind}@{at}")
    return first, later, scene, "+".join(tags)
