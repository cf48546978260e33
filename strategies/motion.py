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
import zlib
from dataclasses import replace

from hypothesis import strategies as st

from acconform.flags import PlayerKillerStatus as PKS, TransientState
from acconform.motion_enums import HoldKey, MotionCommand as MC
from acconform.motion_enums import MovementParamFlags as MPF
from acconform.motion_scene import (DEFAULT_MOVEMENT_FLAGS, STOPS, AnimationSpec, AnimRef, CommandInput, HookSpec, MotionDataSpec,
                                    MotionEntry, MotionInput, MotionTableSpec, MovementParams, MoveToInput,
                                    ObjectMoveInput)
from acconform.numerics import to_f32
from acconform.scene import DEFAULT_SKILLS, ENV_CELL_FIRST, Frame, MoverSkills, Position, Scene, SphereRec, SphereShape, StaticObject

from . import draws as dr

NC = int(MC.NonCombat)
READY, WALK, RUN = int(MC.Ready), int(MC.WalkForward), int(MC.RunForward)
SIDE, TURN = int(MC.SideStepRight), int(MC.TurnRight)
HC, SC = int(MC.HandCombat), int(MC.SwordCombat)
RICH_ACTIONS = (int(MC.Twitch1), int(MC.Twitch2))

_RATES = (30.0, 30.0, 15.0, 60.0, 10.0, 24.0, 7.5, -30.0, -15.0, -30.0)  # negative: played backward
# one animation in 41 is still (0, +-0.0001: under AnimSequenceNode's EPSILON, a frame that never ends and
# Sequence's arms that skip apply_physics), so most tables still walk by their root motion
FRAMERATES = st.sampled_from(tuple(float(to_f32(r)) for r in _RATES * 12 + (0.0, 0.0001, -0.0001)))
FRAME_COUNTS = st.integers(1, 8)
FRAME_RANGES = st.sampled_from(("all", "all", "all", "low1", "first3", "high_past_end", "one", "low_past_high",
                                "low_past_end"))
# one animation in 40 played from a low frame below 0 (an AnimData's LowFrame is an int the DAT may give negative:
# set_animation_id clamps only a low frame past the end): the frames before 0 have no PartFrame (get_part_frame's
# range test, execute_hooks' null) and no PosFrame (get_pos_frame's identity)
NEGATIVE_LOW = st.sampled_from((False,) * 39 + (True,))
NEGATIVE_LOWS = st.sampled_from((-1, -2, -5))
ROOT_MOTION = st.sampled_from((True,) * 59 + (False,))  # False: an Animation without PosFrames (one in 60)
HOOKED = st.sampled_from((False,) * 29 + (True,))  # an animation with hooks (one in 30)
HOOK_NAMES = st.sampled_from(("AnimationDone", "AnimationDone", "DefaultScript", "Ethereal", "Sound"))
HOOK_DIRS = st.sampled_from((0, 0, 1, -1))
BITFIELDS = st.sampled_from((0, 0, 0, 0, 1, 2, 3))
MOSTLY = st.sampled_from((True, True, True, False))
RICH = st.sampled_from((False, True))  # a second style, actions, more animations (_rich_entries)
# a table that leaves the mover without a state now and then: the default style without a default substate,
# or its default substate without a cycle (SetDefaultState fails: style and substate stay 0)
STATELESS = st.sampled_from((None,) * 10 + ("no_default", "no_cycle"))
DEFAULT_ANIMATIONS = st.sampled_from((False, False, False, True))  # the Setup's DefaultAnimation (a table animation)
EMPTY_LINKS = st.sampled_from((False, False, False, True))
ACTION_LINKS = st.sampled_from(("ready", "ready", "walk", "any", "none"))
STYLES = st.sampled_from((0,) * 8 + (HC, NC, SC, int(MC.Magic)))  # a MoveToState's style (0: unflagged, NonCombat)
ACTION_INPUTS = st.sampled_from((False, False, True))  # a key scene's DoMotion of an action at a drawn tick
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
SIDESTEPS = st.sampled_from((0, 0, 0, SIDE, int(MC.SideStepLeft)))
TURNS = st.sampled_from((0, 0, TURN, int(MC.TurnLeft)))
HOLD_KEYS = st.sampled_from((int(HoldKey.None_), int(HoldKey.Run), 0))
# speeds under MotionTable's EPSILON (change_cycle_speed's arms) and negative ones (a command played backward)
INPUT_SPEEDS = dr.OneOf(st.sampled_from((1.0, 1.0, 1.0, 0.5, 1.5, 2.0, 1.0, 0.5, 0.0001, 0.00001, -1.0, -0.5)),
                        dr.f32(0.1, 3.0))
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
                                         int(MC.Cheer), int(MC.Twitch1), int(MC.Twitch2), HC, NC, SC,
                                         int(MC.Dead), int(MC.Falling))))
READY_ACTIONS = (int(MC.Twitch1), int(MC.Cheer))  # the table's actions (links from Ready), when it has them
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
        frames = tuple(Frame((0.0, 0.0, 0.0), _yaw(step * i)) for i in range(n))
    else:
        stride = float(dr.take(draw, STRIDES))
        axis = 0 if move == "side" else 1
        frames = tuple(Frame(tuple(to_f32(stride * i) if k == axis else 0.0 for k in range(3))) for i in range(n))
    hooks = ()
    if draw(HOOKED):
        hooks = tuple(HookSpec(draw(st.integers(0, n - 1)), draw(HOOK_NAMES), draw(HOOK_DIRS))
                      for _ in range(draw(st.integers(1, 3))))
    return AnimationSpec(frames, draw(ROOT_MOTION), hooks)


def _anim_ref(draw, index: int, frames: int) -> AnimRef:
    fr = draw(FRAMERATES)
    if draw(NEGATIVE_LOW):  # kept as it is: played from a frame before the first
        return AnimRef(index, fr, draw(NEGATIVE_LOWS), -1)
    how = draw(FRAME_RANGES)
    if how == "low1" and frames > 1:
        return AnimRef(index, fr, 1, -1)
    if how == "first3" and frames > 3:
        return AnimRef(index, fr, 0, 2)
    if how == "high_past_end":  # AnimSequenceNode clamps a high frame past the last
        return AnimRef(index, fr, 0, frames + 2)
    if how == "one":  # a single frame: low == high
        return AnimRef(index, fr, frames - 1, frames - 1)
    if how == "low_past_high" and frames > 2:  # set_animation_id raises the high frame to the low
        return AnimRef(index, fr, 2, 1)
    if how == "low_past_end":  # set_animation_id lowers the low frame to the last
        return AnimRef(index, fr, frames + 1, -1)
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
        for action in READY_ACTIONS:
            links.append(MotionEntry(NC, READY, data("still"), to=action))
        label += "a"
    label += (f"l{len(links)}" if links else "") + (f"m{len(modifiers)}" if modifiers else "")
    style_defaults = ((NC, READY),)
    if draw(RICH):
        style_defaults, more = _rich_entries(draw, cycles, links, modifiers, data)
        label += ":" + more
    default_animation = draw(st.integers(0, len(animations) - 1)) if draw(DEFAULT_ANIMATIONS) else None
    # the Ready actions and a richer table's may both link Ready to Twitch1: one MotionData per link key, the first
    firsts: dict = {}
    for e in links:
        firsts.setdefault((e.style, e.motion, e.to), e)
    links = list(firsts.values())
    table = MotionTableSpec(NC, style_defaults, tuple(animations), tuple(cycles), tuple(links), tuple(modifiers),
                            default_animation)
    return table, label or "ready"


def _rich_entries(draw, cycles: list, links: list, modifiers: list, data) -> tuple[tuple, str]:
    """What a richer table adds (one table in two; `cycles`, `links` and `modifiers` grow in place): a
    second style, HandCombat, its default substate Ready (or, now and then, WalkForward: a style change
    then ends in a cycle of the other style's walk), its own Ready cycle (Bitfield 1 now and then: it clears
    the modifiers) and the links between the styles' Readys each mostly there (without, GetObjectSequence
    links through the default style); the Ready cycle played by two or three animations; the action
    commands Twitch1 and Twitch2 (links from Ready, from WalkForward, or from any substate: a link keyed by
    the style alone, get_link's last lookup); a modifier keyed by its motion alone (no style: the modifiers'
    second lookup); and a link from any substate to Ready. Returns (the style defaults, a label)."""
    tags = []
    hc_default = draw(st.sampled_from((READY, READY, READY, WALK)))
    if hc_default == WALK and not any(c.motion == WALK for c in cycles):
        hc_default = READY
    cycles.append(MotionEntry(HC, READY, replace(data("still"), bitfield=draw(st.sampled_from((0, 0, 1))))))
    if hc_default == WALK or draw(HALF):
        cycles.append(MotionEntry(HC, WALK, data("walk", velocity=(0.0, to_f32(dr.take(draw, WALK_VELOCITIES)), 0.0))))
        tags.append("hw")
    for style, frm, to in dict.fromkeys(((NC, READY, HC), (HC, hc_default, NC), (HC, READY, NC))):
        if draw(MOSTLY):
            links.append(MotionEntry(style, frm, data("walk"), to=to))
    if draw(HALF):  # the Ready cycle with more animations
        ready = cycles[0]
        extra = tuple(data("still").anims[0] for _ in range(draw(st.integers(1, 2))))
        cycles[0] = replace(ready, data=replace(ready.data, anims=ready.data.anims + extra))
        tags.append(f"a{1 + len(extra)}")
    for action in RICH_ACTIONS:
        where = draw(ACTION_LINKS)
        if where == "none":
            continue
        frm = {"ready": READY, "walk": WALK, "any": 0}[where]
        link = data("walk")
        if draw(EMPTY_LINKS):  # no animation: its pending motion has 0 animations (CheckForCompletedMotions ends it)
            link = replace(link, anims=())
            tags.append("e")
        links.append(MotionEntry(NC, frm, link, to=action))
        if draw(HALF):
            links.append(MotionEntry(HC, READY, data("walk"), to=action))
        tags.append(f"{action & 0xFF:x}{where[0]}")
    if draw(HALF):  # a link from any substate to Ready
        links.append(MotionEntry(NC, 0, data("walk"), to=READY))
        tags.append("anyR")
    if draw(HALF) and not any(m.motion == TURN for m in modifiers):  # a modifier of no style
        modifiers.append(MotionEntry(0, TURN, data("turn", None, (0.0, 0.0, to_f32(dr.take(draw, OMEGAS))))))
        tags.append("m0")
    if draw(HALF):  # a style with a cycle and no default substate (its link lookups find no default)
        cycles.append(MotionEntry(SC, READY, data("still")))
        tags.append("sc")
    defaults = ((NC, READY), (HC, hc_default))
    stateless = draw(STATELESS)
    if stateless == "no_default":
        defaults = ((HC, hc_default),)
    elif stateless == "no_cycle":
        defaults = ((NC, int(MC.Sleeping)), (HC, hc_default))
    if stateless:
        tags.append(stateless)
    return defaults, "hc" + ("-walk" if hc_default == WALK else "") + "".join(f".{t}" for t in tags)


def _speed(draw) -> float:
    return float(to_f32(dr.take(draw, INPUT_SPEEDS)))


def draw_motion_input(draw) -> tuple[MotionInput, str]:
    if draw(INPUT_KINDS) == "stop":
        return MotionInput(hold_key=int(HoldKey.None_)), "stop"
    kw = {"hold_key": draw(HOLD_KEYS), "style": draw(STYLES)}
    tag = {0: "", HC: "hc", NC: "nc", SC: "sc", int(MC.Magic): "mg"}[kw["style"]]
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
    if n > 1 and draw(ACTION_INPUTS):  # an action's DoMotion (Player.OnMoveToState's path for one key)
        at = draw(st.integers(0, n - 1))
        inputs[at]["do_motion"] = CommandInput(draw(st.sampled_from(RICH_ACTIONS + RICH_ACTIONS + (HC, SC))), draw(HOLD_TO_APPLY))
        tags.append(f"do{inputs[at]['do_motion'].motion & 0xFF:x}@{at}")
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
        first["do_motion"] = CommandInput(draw(st.sampled_from(READY_ACTIONS)), draw(HOLD_TO_APPLY))
    else:
        first["do_motion"] = CommandInput(dr.take(draw, KEY_COMMANDS), draw(HOLD_TO_APPLY))
    tags = [goal]
    later = []
    if goal == "actions":
        k = min(draw(BURSTS), n) - 1
        later = [(at, {"do_motion": CommandInput(draw(st.sampled_from(READY_ACTIONS)), draw(HOLD_TO_APPLY))})
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


# ---------------------------------------------------------------- a MoveTo, sticky follow or turn at a moving mover

# how the target (another mover, scene/8 others) moves: standing, walking away (the mover follows), toward the
# mover, across its line, or stop-and-go (away, stopped, back toward the mover, stopped again)
TARGET_MOVES = st.sampled_from(("stand", "away", "away", "toward", "across", "stop_and_go", "stop_and_go", "stop_and_go"))
TARGET_WEENIES = st.sampled_from(("player", "player", "monster", "creature"))
TARGET_GAPS = dr.OneOf(st.sampled_from((3.0, 1.0, 6.0, 0.5, 12.0, 20.0)), dr.f32(0.2, 16.0))
TARGET_MOVE_SPEEDS = dr.OneOf(st.sampled_from((1.0, 2.5, 4.0, 0.5, 6.0)), dr.f32(0.2, 7.0))
CHASE_GOALS = st.sampled_from(("move_to_object", "move_to_object", "sticky", "sticky", "sticky", "turn_to_object",
                               "stick", "stick", "wrap_turn"))
# wrap_turn: a TurnToHeading at tick 0 of a mover facing north (heading exactly 0) to a heading within EPSILON short
# of 360, where BeginTurnToHeading's `heading_diff + EPSILON <= 360` fails by float32 rounding (359.9998 still
# passes: 359.9998f + 0.0002f rounds to 360) and the turn ends at once; the target meanwhile has no voyeur
STICK_AFTER_GONE = st.sampled_from((False, True))  # of a scene whose target is destroyed
# the driver: update_object (a creature's or a FastTick player's physics), or request_pos, the legacy player path
# (Player.UpdatePlayerPosition -> update_object_server -> UpdateObjectInternalServer, which runs the mover's
# TargetManager and PositionManager too), the client reporting the mover walking toward the target at a speed;
# picked by the scene's drawn name, not drawn (a draw would shift every later scene of a seeded sample)
CHASE_DRIVERS = ("update_object", "update_object", "update_object", "request_pos")
REPORTED_SPEEDS = (0.0, 1.0, 2.5, 4.0, 4.0)
WRAP_HEADINGS = st.sampled_from((359.9999, 359.99985, 359.99982, 359.9998, 0.0001))
TARGET_FATES = st.sampled_from(("stays", "stays", "stays", "destroyed"))  # the server destroys the target at a tick
NO_TABLE = st.sampled_from((False, False, False, True))  # a stick_to scene's mover without a motion table (no MotionInterp)
# the MovementParameters the server's callers build (ACE 7b47913): Monster_Navigation.GetMovementParameters (CanWalk
# off; a melee monster adds FailWalk, UseFinalHeading, Sticky and MoveAway; a ranged one turns with the rest),
# Player_Move.GetChargeParameters (the melee charge: CanCharge too, HoldKey Run, FailDistance 15, Speed 1.5),
# Monster_Navigation's MoveTo home (DistanceToObject 0.6, a DesiredHeading), or drawn flags (each flag flipped)
# or backoff: MoveAway with a MinDistance past the target's gap, so BeginMoveForward walks away from it (the
# desired heading 180 plus the heading to the target wraps past 360 in HandleMoveToPosition when that heading is
# 180 or more)
CHASE_PARAMS = st.sampled_from(("monster", "monster", "charge", "charge", "ranged", "drawn", "drawn", "drawn", "backoff"))
BACKOFF_MARGINS = st.sampled_from((2.0, 5.0, 0.5))
FLIP_COUNTS = dr.ints(0, 3)
FLAG_FLIPS = (st.sampled_from((MPF.CanWalk, MPF.CanRun, MPF.CanSidestep, MPF.CanWalkBackwards, MPF.CanCharge,
                                       MPF.FailWalk, MPF.UseFinalHeading, MPF.MoveAway, MPF.MoveTowards, MPF.UseSpheres,
                                       MPF.SetHoldKey, MPF.StopCompletely, MPF.CancelMoveTo)))
CHASE_DISTANCES = dr.OneOf(st.sampled_from((0.6, 0.0, 1.0, 2.0, 4.0, 0.1)), dr.f32(0.0, 6.0))
CHASE_MIN_DISTANCES = dr.OneOf(st.sampled_from((0.0, 0.0, 0.0, 1.0, 3.0, 8.0)), dr.f32(0.0, 10.0))
CHASE_FAIL_DISTANCES = st.sampled_from((None, None, 15.0, 5.0, 2.0, 0.5))
CHASE_LATER = dr.ints(0, 4)
CHASE_LATER_KINDS = st.sampled_from(("stop", "stop", "again", "turn_to_object", "sticky", "do_motion", "move_to",
                                     "turn_to_heading", "stick"))


def _chase_params(draw, goal: str, gap: float = 3.0) -> tuple[MovementParams, str]:
    how = draw(CHASE_PARAMS)
    melee = int(MPF.FailWalk | MPF.UseFinalHeading | MPF.Sticky | MPF.MoveAway)
    if how == "monster":
        p = MovementParams(flags=(DEFAULT_MOVEMENT_FLAGS & ~int(MPF.CanWalk)) | melee)
    elif how == "charge":
        p = MovementParams(flags=(DEFAULT_MOVEMENT_FLAGS & ~int(MPF.CanWalk)) | melee | int(MPF.CanCharge),
                           hold_key_to_apply=int(HoldKey.Run), fail_distance=15.0, speed=1.5)
    elif how == "ranged":
        p = MovementParams(flags=DEFAULT_MOVEMENT_FLAGS & ~int(MPF.CanWalk))
    elif how == "backoff":  # MoveAway alone walks forward, away (heading 180); with MoveTowards it backs off
        towards = int(MPF.MoveTowards) if draw(HALF) else 0
        p = MovementParams(flags=(DEFAULT_MOVEMENT_FLAGS & ~int(MPF.MoveTowards)) | int(MPF.MoveAway) | towards,
                           min_distance=float(to_f32(gap + draw(BACKOFF_MARGINS))))  # DistanceToObject 0.6f, the default
    else:
        flags = DEFAULT_MOVEMENT_FLAGS
        for _ in range(dr.take(draw, FLIP_COUNTS)):
            flags ^= int(draw(FLAG_FLIPS))
        fail = draw(CHASE_FAIL_DISTANCES)
        p = MovementParams(flags=flags, distance_to_object=float(to_f32(dr.take(draw, CHASE_DISTANCES))),
                           min_distance=float(to_f32(dr.take(draw, CHASE_MIN_DISTANCES))),
                           fail_distance=MovementParams().fail_distance if fail is None else fail,
                           speed=float(to_f32(dr.take(draw, MOVE_SPEEDS))),
                           walk_run_threshold=float(to_f32(dr.take(draw, WALK_RUN))),
                           desired_heading=float(to_f32(dr.take(draw, HEADINGS))), hold_key_to_apply=draw(HOLD_TO_APPLY))
    if goal == "sticky":
        p = replace(p, flags=p.flags | int(MPF.Sticky))
    elif goal == "move_to_object" and how == "drawn" and draw(HALF):
        p = replace(p, flags=p.flags & ~int(MPF.Sticky))
    return p, how


def _target_walk(draw, rows: list[dict], dts: list[float], ux: float, uy: float, how: str) -> str:
    """The target's held velocities (OtherInputs.velocity each tick) for `how`; (ux, uy) points from the mover to it."""
    from .movers import _vec

    n = len(dts)
    speed = float(dr.take(draw, TARGET_MOVE_SPEEDS))
    if how == "stand":
        return how
    if how in ("away", "toward", "across"):
        dx, dy = {"away": (ux, uy), "toward": (-ux, -uy), "across": (-uy, ux)}[how]
        stop = n if draw(HALF) else draw(st.integers(0, n - 1))
        for i in range(min(stop, n)):
            rows[i]["velocity"] = _vec(dx * speed, dy * speed, 0.0)
        if stop < n:
            rows[stop]["velocity"] = (0.0, 0.0, 0.0)
        return f"{how}{speed:g}" + ("" if stop >= n else f"-stop@{stop}")
    # stop-and-go: away from 0, stopped at a, toward the mover from b, stopped at c
    cuts = sorted(draw(st.integers(1, max(n - 1, 1))) for _ in range(3))
    a, b, c = cuts
    for i in range(n):
        if i < a:
            v = _vec(ux * speed, uy * speed, 0.0)
        elif i < b:
            v = (0.0, 0.0, 0.0)
        elif i < c:
            v = _vec(-ux * speed, -uy * speed, 0.0)
        else:
            v = (0.0, 0.0, 0.0)
        if i == 0 or v != rows[i - 1].get("velocity") or v != (0.0, 0.0, 0.0):
            rows[i]["velocity"] = v
    return f"stopgo{speed:g}@{a}/{b}/{c}"


def draw_managed_chase(draw, clock) -> Scene:
    """The server's MoveToObject, sticky MoveToObject (StickTo on arrival) or TurnToObject at another mover that
    moves (a creature chasing a player, a player's melee charge at a monster): the mover (a player with a drawn
    motion table) on flat ground, the target (scene/8 others: a player, a monster or an NPC) a gap away, standing,
    walking away, toward it, across its line or stop-and-go; the parameters the server's callers build or drawn
    flags; then at drawn ticks a stop (each of the server's), the MoveTo again, a turn or a sticky MoveTo at the
    target, a key, a MoveTo to a point or a turn in place. The target's TargetManager answers the mover's voyeur
    requests as it moves (HandleTargetting each update_object)."""
    from .movers import _Flat, _Ids, _Timeline, _finish, _mover, _other, _pks, _spheres
    from .ticks import _unit

    world = _Flat(draw, False)
    mx, my = 96.0 + float(draw(st.sampled_from((0.0, 0.5, -3.0)))), 96.0 + float(draw(st.sampled_from((0.0, 0.25, 2.0))))
    rad = math.radians(dr.take(draw, HEADINGS))
    ux, uy = math.cos(rad), math.sin(rad)
    n = dr.take(draw, TICK_COUNTS)
    start, dts, clabel = clock(draw, n)
    tl, ids = _Timeline(dts), _Ids()
    table, tlabel = draw_motion_table(draw)
    goal = draw(CHASE_GOALS)
    if goal == "wrap_turn" and n < 2:
        goal = "move_to_object"  # the target is aimed at from tick 1
    facing = math.degrees(math.atan2(-ux, uy)) + float(draw(st.sampled_from((0.0, 0.0, 90.0, 180.0, -45.0))))
    if goal == "wrap_turn":
        facing = 0.0  # _yaw(0) is the identity: get_heading answers exactly 0
    mover = _mover(draw, _spheres(draw), world.position(mx, my, _yaw(facing)), world.z, _pks(draw, "player"))
    gap = float(dr.take(draw, TARGET_GAPS))
    weenie = draw(TARGET_WEENIES)
    target = _other(draw, ids, weenie, _spheres(draw), world.position(mx + ux * gap, my + uy * gap))
    moves = _target_walk(draw, tl.of(target.id), dts, ux, uy, draw(TARGET_MOVES))
    gone = n  # the tick the server destroys the target at (WorldObject.Destroy), n: never
    if n > 1 and draw(TARGET_FATES) == "destroyed":
        gone = draw(st.integers(1, n - 1))
        rows = tl.of(target.id)
        rows[gone] = {"destroy": True}
        for i in range(gone + 1, n):
            rows[i].clear()
        moves += f":destroyed@{gone}"
    first = tl.mover[0]
    no_table = goal == "stick" and draw(NO_TABLE)
    if goal == "stick":  # a melee swing's stick_to_object (Monster_Melee / Player_Melee), the mover beside the target
        first["stick_to"] = target.id
        tags = ["stick" + (":no-table" if no_table else "")]
    elif goal == "wrap_turn":
        heading = draw(WRAP_HEADINGS)
        first["turn_to_heading"] = MoveToInput(_params(draw, heading=float(to_f32(heading))))
        tags = [f"wrap_turn{heading:g}"]
        if gone > 1:  # then a MoveToObject at the target (a target destroyed at tick 1 needs objects.targets already)
            tl.mover[1]["move_to_object"] = ObjectMoveInput(target.id, _chase_params(draw, "move_to_object", gap)[0])
            tags.append("again@1")
    else:
        params, how = _chase_params(draw, goal, gap)
        first["turn_to_object" if goal == "turn_to_object" else "move_to_object"] = ObjectMoveInput(target.id, params)
        tags = [f"{goal}:{how}"]
    for _ in range(min(dr.take(draw, CHASE_LATER), n - 1)):
        at = draw(st.integers(1, n - 1))
        kind = "stick" if no_table else draw(CHASE_LATER_KINDS)
        if at >= gone and kind in ("stick", "again", "turn_to_object", "sticky"):
            continue  # the server aims nothing at a destroyed object
        row = tl.mover[at]
        if kind == "stick":
            row["stick_to"] = target.id
        elif kind == "stop":
            kind = draw(st.sampled_from(STOPS))
            row["stop"] = kind
        elif kind in ("again", "sticky"):
            row["move_to_object"] = ObjectMoveInput(target.id, _chase_params(draw, "sticky" if kind == "sticky" else "move_to_object", gap)[0])
        elif kind == "turn_to_object":
            row["turn_to_object"] = ObjectMoveInput(target.id, _chase_params(draw, kind)[0])
        elif kind == "do_motion":
            row["do_motion"] = CommandInput(dr.take(draw, KEY_COMMANDS), draw(HOLD_TO_APPLY))
        elif kind == "move_to":
            row["move_to"] = MoveToInput(_params(draw), world.position(mx - ux * 3.0, my - uy * 3.0))
        else:
            row["turn_to_heading"] = MoveToInput(_params(draw))
        tags.append(f"{kind}@{at}")
    stuck_gone = None  # the tick of the stick_to at the gone target
    if gone < n - 1 and draw(STICK_AFTER_GONE):
        # a melee swing's stick_to at the target the server has destroyed (the swing's AttackTarget outlives it):
        # stick_to_object makes the PositionManager, finds no object and returns, so the mover keeps a
        # PositionManager without a StickyManager
        at = draw(st.integers(gone + 1, n - 1))
        tl.mover[at]["stick_to"] = target.id
        tags.append(f"stick_gone@{at}")
        stuck_gone = at
    skills = draw_skills(draw)
    name = f"targets:{weenie}:{moves}:gap{gap:g}:{'+'.join(tags)}:{tlabel}:{clabel}"
    scene = _finish(draw, start, dts, tl, world.landblocks, mover, (target,), (), name, ethereal=False)
    pick = zlib.crc32(scene.name.encode())
    if CHASE_DRIVERS[pick % len(CHASE_DRIVERS)] == "request_pos":
        speed = REPORTED_SPEEDS[(pick // len(CHASE_DRIVERS)) % len(REPORTED_SPEEDS)]
        reach = max(gap - 1.0, 0.0)  # the client stops a metre short of the target's starting point
        requests, t = [], 0.0
        for dt in dts:
            t += dt
            d = min(speed * t, reach)
            requests.append(world.position(mx + ux * d, my + uy * d, _yaw(facing)))
        steps = tuple(replace(step, request_pos=r) for step, r in zip(scene.ticks.steps, requests))
        scene = scene.replace(ticks=replace(scene.ticks, driver="request_pos", steps=steps),
                              name=scene.name + f":request_pos{speed:g}")
    m = scene.mover
    if no_table:
        scene = scene.replace(mover=replace(m, transient_state=m.transient_state | int(TransientState.Active)))
        scene = _chase_without_table(scene, target.id, pick)
    else:
        scene = scene.replace(mover=replace(m, motion_table=table, skills=skills,
                                            transient_state=m.transient_state | int(TransientState.Active)))
    scene = _aim_at_self_or_gone(scene, target.id, gone, no_table, pick)
    if stuck_gone is not None and stuck_gone < n - 1 and (pick >> 28) % 2 == 0:
        # the next target (a monster's new AttackTarget after the first died): a second mover standing opposite
        # the first, and a MoveToObject at it after the stick at the gone one, whose voyeur update reaches a
        # PositionManager without a StickyManager (picked by the name, not drawn)
        (bx, by, _), (tx, ty, _) = scene.mover.begin.frame.origin, target.begin.frame.origin
        second = replace(target, id=ids.take(weenie), begin=world.position(2 * bx - tx, 2 * by - ty))
        steps = list(scene.ticks.steps)
        at = stuck_gone + 1 + (pick >> 29) % (n - 1 - stuck_gone)
        if steps[at].move_to_object is None:
            steps[at] = replace(steps[at], move_to_object=ObjectMoveInput(second.id, _params_of_first(steps)))
            scene = scene.replace(others=scene.others + (second,), ticks=replace(scene.ticks, steps=tuple(steps)),
                                  name=scene.name + f":switch@{at}")
    return scene


# a mover without a motion table (a creature whose weenie has no MotionTableId) that the server sends after its target
# first: MoveToObject / TurnToObject make the MovementManager themselves (ACE's "refactor into common method" block)
# and clear Active, so the swing's stick_to after makes a PositionManager that sets Active and UpdateTime again
TABLELESS_CHASES = (None, "move_to_object", "turn_to_object")


def _chase_without_table(scene: Scene, target_id: int, pick: int) -> Scene:
    how = TABLELESS_CHASES[(pick >> 24) % len(TABLELESS_CHASES)]
    steps = list(scene.ticks.steps)
    if how is None or getattr(steps[0], how) is not None:
        return scene
    steps[0] = replace(steps[0], **{how: ObjectMoveInput(target_id, MovementParams())})
    return scene.replace(ticks=replace(scene.ticks, steps=tuple(steps)), name=scene.name + f":tableless_{how}")


# a later aim of the chase, picked by the scene's drawn name (not drawn: a draw would shift every later scene of a
# seeded sample): at the mover itself -- a MoveToObject, a TurnToObject (ACE's CreateTurnToChain2 at a spell's
# target.Wielder, the caster's own wielded item) or a melee swing's stick_to (a client's targeted attack at its own
# guid: Player_Melee finds the player, a Creature it can damage, and DoSwingMotion sticks to it) -- which
# MoveToObject/TurnToObject end at once (PhysicsObj.ID == topLevelID: CleanUp, StopCompletely) and StickTo makes
# the mover its own voyeur; or, of a scene whose target the server destroyed, a TurnToObject at it after (the
# facade's GetObjectA finds none: TurnToObject(null) answers false)
# (self_first: a MoveToObject at itself in the first tick, before the chase's turn or stick_to there, so the mover has
# no TargetManager yet when the MoveTo's CleanUp calls clear_target)
LATER_AIMS = (None, None, None, "self_move_to_object", "self_turn_to_object", "self_stick", "turn_at_gone", "self_first")


def _aim_at_self_or_gone(scene: Scene, target_id: int, gone: int, no_table: bool, pick: int) -> Scene:
    from acconform.staging import MOVER_ID

    steps = list(scene.ticks.steps)
    n = len(steps)
    aim = LATER_AIMS[(pick >> 16) % len(LATER_AIMS)]
    if aim is None or n < 2:
        return scene
    if aim == "self_first":
        if no_table:
            return scene
        at, field, value = 0, "move_to_object", ObjectMoveInput(MOVER_ID, _params_of_first(steps))
    elif aim == "turn_at_gone":
        if gone >= n - 1 or no_table:
            return scene
        at = gone + 1 + (pick >> 20) % (n - 1 - gone)
        field, value = "turn_to_object", ObjectMoveInput(target_id, _params_of_first(steps))
    else:
        at = 1 + (pick >> 20) % (n - 1)
        if no_table and aim != "self_stick":
            aim = "self_stick"  # a motion input needs the motion table
        field = aim[len("self_"):]
        field = "stick_to" if field == "stick" else field
        value = MOVER_ID if field == "stick_to" else ObjectMoveInput(MOVER_ID, _params_of_first(steps))
    if getattr(steps[at], field) is not None:
        return scene
    steps[at] = replace(steps[at], **{field: value})
    return scene.replace(ticks=replace(scene.ticks, steps=tuple(steps)), name=scene.name + f":{aim}@{at}")


def _params_of_first(steps) -> MovementParams:
    """The parameters of the chase's first MoveToObject or TurnToObject (the server's caller builds the same), else
    the defaults."""
    for s in steps:
        for move in (s.move_to_object, s.turn_to_object):
            if move is not None:
                return move.params
    return MovementParams()


# ---------------------------------------------------------------- the motion layer's rarer arms (issue 40, stop 50)

# which of MotionInterp's rarer arms a layer scene aims at: "float" clears the mover's Gravity at a drawn tick (a
# creature whose GravityStatus is off: contact_allows_move's, LeaveGround's and HitGround's Gravity tests), now and
# then giving it back later; "refusal" sets a combat style by a MoveToState, then asks DoMotion for Crouch,
# Sitting, Sleeping or an emote (DoMotion's combat refusals); "keys" presses and releases turns and sidesteps by
# DoMotion / StopMotion with a StopCompletely among them
# DoMotion / StopMotion with a StopCompletely among them; "tableless" gives a mover without a motion table the calls a
# server makes of any WorldObject (get_minterp's MovementManager, made Static or not; DoMotion, StopMotion and
# StopCompletely before it: NoAnimationTable)
# "modifier" gives the table a modifier that is no substate (Jump, StopTurning: MotionTable's modifier arm), then
# presses and releases it by DoMotion / StopMotion (InterpretedMotionState's and RawMotionState's ApplyMotion of a
# command neither substate, style nor action)
LAYER_ARMS = st.sampled_from(("float", "float", "float", "refusal", "keys", "keys", "tableless", "tableless", "modifier"))
PURE_MODIFIERS = st.sampled_from((int(MC.Jump), int(MC.StopTurning)))
TABLELESS_STOPS = st.sampled_from(("stop_completely", "cancel_moveto"))
STATIC = 0x00000001  # PhysicsState.Static
REFUSED = st.sampled_from((int(MC.Sleeping), int(MC.Sleeping), int(MC.Crouch), int(MC.Sitting), int(MC.Cheer)))
COMBAT_STYLES = st.sampled_from((HC, SC, int(MC.Magic)))
LAYER_KEYS = st.sampled_from((TURN, int(MC.TurnLeft), SIDE, int(MC.SideStepLeft), WALK, int(MC.WalkBackwards), RUN))
GRAVITY = 0x00000400  # PhysicsState.Gravity


def draw_motion_layer_ticks(draw, base: Scene, clock) -> Scene:
    """A motion tick scene (draw_motion_ticks's table, world and clock) aimed at one of MotionInterp's rarer arms
    (LAYER_ARMS): the mover's Gravity cleared at a drawn tick among MoveToState keys (and a jump now and then),
    a combat style then DoMotion of what combat refuses, or keys pressed and released by DoMotion / StopMotion."""
    from .ticks import _path, _unit

    table, tlabel = draw_motion_table(draw)
    n = max(3, dr.take(draw, TICK_COUNTS))
    start, dts, clabel = clock(draw, n)
    inputs = [{} for _ in range(n)]
    g0, g1 = _path(base)
    arm = draw(LAYER_ARMS)
    tags = [arm]
    if arm == "float":
        first, tag = draw_motion_input(draw)
        inputs[0]["motion"] = first
        at = draw(st.integers(0, n - 1))
        inputs[at]["state"] = base.mover.state & ~GRAVITY
        tags.append(f"{tag}-grav@{at}")
        for _ in range(min(dr.take(draw, SEGMENTS), n - 1)):
            k = draw(st.integers(1, n - 1))
            inputs[k]["motion"], t = draw_motion_input(draw)
            tags.append(f"{t}@{k}")
        if draw(HALF):
            from .ticks import JUMP_FORWARD, JUMP_UPS

            k = draw(st.integers(0, n - 1))
            inputs[k]["jump"] = (0.0, to_f32(dr.take(draw, JUMP_FORWARD)), to_f32(dr.take(draw, JUMP_UPS)))
            tags.append(f"jump@{k}")
        if at < n - 1 and draw(HALF):  # Gravity given back: the mover falls again and lands
            k = draw(st.integers(at + 1, n - 1))
            inputs[k]["state"] = base.mover.state | GRAVITY
            tags.append(f"grav@{k}")
    elif arm == "refusal":
        inputs[0]["motion"] = MotionInput(hold_key=draw(HOLD_KEYS), style=draw(COMBAT_STYLES),
                                          forward=draw(st.sampled_from((0, WALK, READY))))
        for _ in range(draw(st.integers(1, 3))):
            k = draw(st.integers(1, n - 1))
            inputs[k]["do_motion"] = CommandInput(draw(REFUSED), draw(HOLD_TO_APPLY))
            tags.append(f"do{inputs[k]['do_motion'].motion & 0xFF:x}@{k}")
    elif arm == "modifier":
        modifier = draw(PURE_MODIFIERS)
        still = table.cycles[0].data.anims  # the Ready cycle's animation
        table = replace(table, modifiers=table.modifiers + (MotionEntry(NC, modifier, MotionDataSpec(still)),))
        first, tag = draw_motion_input(draw)
        inputs[0]["motion"] = first
        tags.append(f"{modifier & 0xFF:x}+{tag}")
        for _ in range(draw(st.integers(1, 3))):
            k = draw(st.integers(0, n - 1))
            key = "do_motion" if draw(MOSTLY) else "stop_motion"
            inputs[k][key] = CommandInput(modifier, draw(HOLD_TO_APPLY))
            tags.append(f"{key[:2]}@{k}")
    elif arm == "tableless":
        table = None
        k = draw(st.integers(0, n - 1))  # the first MoveToState (get_minterp); before it, keys and stops find no manager
        inputs[k]["motion"], tag = draw_motion_input(draw)
        tags.append(f"{tag}@{k}")
        if draw(HALF):  # Static (get_minterp's arm for it), Active kept or cleared
            inputs[k]["state"] = base.mover.state | STATIC
            tags.append("static")
        if draw(HALF):
            inputs[k]["transient_state"] = base.mover.transient_state & ~int(TransientState.Active)
            tags.append("inactive")
        for _ in range(draw(st.integers(1, 4))):
            j = draw(st.integers(0, n - 1))
            key = draw(st.sampled_from(("do_motion", "stop_motion", "stop")))
            inputs[j][key] = draw(TABLELESS_STOPS) if key == "stop" else CommandInput(draw(LAYER_KEYS), draw(HOLD_TO_APPLY))
            tags.append(f"{key[:6]}@{j}")
        # moving (a velocity given at the tick, mostly): IsMovingOrAnimating, which Player.OnMoveToState and its keys
        # ask before their calls, is true before it reaches the absent MovementManager (which throws)
        ux, uy = _unit(g1[0] - g0[0], g1[1] - g0[1])
        for j, inp in enumerate(inputs):
            if any(key in inp for key in ("motion", "do_motion", "stop_motion")) and draw(MOSTLY):
                v = draw(st.sampled_from((0.5, 1.0, 2.0)))
                inp["velocity"] = (to_f32(ux * v), to_f32(uy * v), 0.0)
    else:
        first, tag = draw_motion_input(draw)
        inputs[0]["motion"] = first
        tags.append(tag)
        for _ in range(draw(st.integers(1, 4))):
            k = draw(st.integers(0, n - 1))
            key = "do_motion" if draw(HALF) else "stop_motion"
            inputs[k][key] = CommandInput(draw(LAYER_KEYS), draw(HOLD_TO_APPLY))
            tags.append(f"{key[:2]}{inputs[k][key].motion & 0xFF:x}@{k}")
        if draw(HALF):
            k = draw(st.integers(0, n - 1))
            inputs[k]["stop"] = "stop_completely"
            tags.append(f"stop@{k}")
    status = draw(PLAYER_KILLER_STATUSES)
    skills = draw_skills(draw)
    return _motion_scene(base, table, start, dts, inputs, g0, g1,
                         f"{tlabel}:layer:{'+'.join(tags)}:{status.name}:run{skills.run}:{clabel}", status, skills)


# ---------------------------------------------------------------- the server's motion-table queries (scene/8)

# one motion scene in three asks the server's questions of its motion table after the ticks (motion_queries)
QUERIED = st.sampled_from((True, False, False))
QUERY_COUNTS = dr.ints(1, 12)
QUERY_FUNCTIONS = st.sampled_from(("GetAttackFrames", "GetAttackFrames", "GetAnimationLength", "GetAnimationLength",
                                   "GetAnimationLength", "GetRunSpeed", "GetTurnSpeed", "Dat.GetAnimationLength",
                                   "Dat.GetAnimationLength"))
# stances the table has (NonCombat, HandCombat; SwordCombat now and then, with a cycle and no default) and lacks
QUERY_STANCES = st.sampled_from((NC, NC, NC, HC, HC, SC, int(MC.Magic), 0))
# motions the table links from Ready (its cycles, its actions), a style (the five-argument overload's Ready arm),
# Ready itself and ones it lacks (Dead, an unlisted command)
QUERY_MOTIONS = st.sampled_from((WALK, RUN, SIDE, TURN, READY, int(MC.Twitch1), int(MC.Twitch2), int(MC.Cheer),
                                 int(MC.Twitch1), int(MC.Cheer), HC, NC, SC, int(MC.Dead), 0x10000123))
QUERY_CURRENTS = st.sampled_from((None, None, READY, READY, WALK, RUN, int(MC.Dead), 0))
# speeds as the server passes them (a swing's animSpeed, a cast's, an emote's): 1, 0, negative, one ulp from 1
QUERY_SPEEDS = dr.OneOf(st.sampled_from((None, None, 1.0, 0.0, -0.0, -1.0, -1.5, 2.5, 0.5, 0.99999994, 1.0000001)),
                        dr.f32(0.1, 4.0))
# a queried scene's mover without a motion table now and then (its MotionTableId 0: the statics' early answers)
TABLELESS = st.sampled_from((False,) * 9 + (True,))
# the queried table's animations with AttackHooks (one in two), among its other hooks: GetAttackFrames finds them
ATTACKS = st.sampled_from((True, False))


def draw_motion_queries(draw, scene: Scene) -> Scene:
    """A share of motion scenes (QUERIED) with the server's queries on the mover's motion table after the ticks
    (scene/8 motion_queries): GetAttackFrames, GetAnimationLength (both overloads), GetRunSpeed, GetTurnSpeed and the
    DatLoader's GetAnimationLength, with stances and motions the table has and lacks and the speeds the server passes;
    a query may repeat an earlier one (ACE's static RunSpeed, TurnSpeed and attack-frame caches answer it). Now and
    then the table gains AttackHooks, or the mover loses its table and its motion inputs (a MotionTableId of 0)."""
    from acconform.scene import MOTION_INPUTS, MotionQuery

    if not draw(QUERIED):
        return scene
    m = scene.mover
    tags = []
    if draw(TABLELESS):
        steps = tuple(replace(s, **{n: None for n in MOTION_INPUTS}) for s in scene.ticks.steps)
        scene = scene.replace(mover=replace(m, motion_table=None), ticks=replace(scene.ticks, steps=steps))
        tags.append("tableless")
    elif draw(ATTACKS):
        table = m.motion_table
        animations = list(table.animations)
        # mostly the animations links play (what GetAttackFrames' GetAnimData finds), else any of the table's
        linked = sorted({r.animation for e in table.links for r in e.data.anims})
        for _ in range(draw(st.integers(1, 4))):
            i = draw(st.sampled_from(linked)) if linked and draw(MOSTLY) else draw(st.integers(0, len(animations) - 1))
            a = animations[i]
            hook = HookSpec(draw(st.integers(0, len(a.pos_frames) - 1)), "Attack", draw(HOOK_DIRS))
            animations[i] = replace(a, hooks=a.hooks + (hook,))
        scene = scene.replace(mover=replace(m, motion_table=replace(table, animations=tuple(animations))))
        tags.append("attacks")
    table = scene.mover.motion_table
    # a link's style and target (the link GetAnimData looks up, when it starts from the style's default or from any
    # substate), asked one query in two: the others mostly find no link
    links = [(e.style, e.to) for e in table.links] if table is not None else []

    def stance_motion():
        if links and draw(HALF):
            return draw(st.sampled_from(links))
        return draw(QUERY_STANCES), draw(QUERY_MOTIONS)

    queries: list = []
    for _ in range(dr.take(draw, QUERY_COUNTS)):
        if queries and draw(st.sampled_from((False,) * 4 + (True,))):  # asked again: the caches' second answer
            queries.append(queries[draw(st.integers(0, len(queries) - 1))])
            continue
        f = draw(QUERY_FUNCTIONS)
        if f in ("GetRunSpeed", "GetTurnSpeed"):
            queries.append(MotionQuery(f))
        elif f == "GetAttackFrames":
            queries.append(MotionQuery(f, *stance_motion()))
        elif f == "GetAnimationLength":
            speed = dr.take(draw, QUERY_SPEEDS)
            stance, motion = stance_motion()
            queries.append(MotionQuery(f, stance, motion, draw(QUERY_CURRENTS), None if speed is None else float(to_f32(speed))))
        elif table is not None:  # Dat.GetAnimationLength reads the table's record
            current = draw(QUERY_CURRENTS)
            stance, motion = stance_motion()
            queries.append(MotionQuery(f, stance if current is not None else 0, motion, current))
    tags.append(f"q{len(queries)}")
    return scene.replace(motion_queries=tuple(queries), name=scene.name + ":" + ".".join(tags))


# ---------------------------------------------------------------- objects with a motion table (issue 40, stop 51)

# the other movers of a motion-objects scene: mostly GenericObjects (a Chest: no creature, so MotionInterp's
# non-creature arms), else a creature; each with the scene's motion table mostly (its WorldObject's MotionTableId). None
# is of no parts: its enter_world fails, and WorldObject.AddPhysicsObj then destroys its PhysicsObj and sets it null,
# so no ExecuteMotion or melee swing reaches it
OBJECT_WEENIES = st.sampled_from(("object", "object", "object", "creature", "monster"))
OBJECT_COUNTS = st.integers(1, 3)
OBJECT_TABLES = st.sampled_from((True, True, True, False))
# how high above the ground it begins (0: on it; else it falls and lands: HitGround), and its state
OBJECT_DROPS = st.sampled_from((0.0, 0.0, 0.5, 2.0))
# the commands the server executes on it: a Chest's On and Off (Chest.motionOpen / motionClosed), an emote's motion
# (an action the table links from Ready, one it lacks, a style), a creature's death (Dead), a sleep (Sleeping), and
# moves a Motion may carry (WalkForward, TurnRight, Falling)
EXECUTED = st.sampled_from((int(MC.On), int(MC.Off), int(MC.On), int(MC.Twitch1), int(MC.Cheer), HC, NC,
                            int(MC.Dead), int(MC.Sleeping), WALK, TURN, int(MC.Falling), READY_ACTIONS[0]))
EXECUTE_COUNTS = st.integers(1, 4)
OBJECT_LATER = st.sampled_from(("none", "none", "gravity", "velocity", "drop", "stick", "stick", "chase"))
# the mover without a motion table now and then (a creature whose weenie has none: its others have none either, the
# table being the scene's), so a MoveToObject or TurnToObject at an object makes its MovementManager
MOVER_TABLELESS = st.sampled_from((False, False, False, True))
# the mover's flags at a stick_to or a chase's tick: kept (Active), Active cleared (an object at rest: update_object
# cleared it), that and its Gravity too (enter_default_state's LeaveGround then sets no velocity, so Active stays
# clear), or Static (MakePositionManager's and the MoveTo block's arms for each)
MOVER_FLAGS = st.sampled_from(("kept", "inactive", "inactive", "floating", "static"))


def draw_motion_objects(draw, clock) -> Scene:
    """The server's ExecuteMotion on objects that are not the player (scene/8 others[].motion_table and
    execute_motion, feature objects.motion_tables): the mover (a player with a drawn motion table) on flat ground, and
    one to three others beside it -- GenericObjects mostly (a Chest opening and closing: no creature), a creature now
    and then -- each with the scene's motion table mostly (a Setup of no parts now and then), standing or falling
    onto the ground; at drawn ticks the server executes motions on them (WorldObject.ExecuteMotion's physics), and
    now and then one loses its Gravity, is given a velocity (it slides and stops), is lifted and falls again, or the
    player's melee swing sticks to it (stick_to_object)."""
    from .movers import _Flat, _Ids, _Timeline, _finish, _mover, _other, _pks, _spheres

    world = _Flat(draw, False)
    mx, my = 96.0, 96.0
    n = max(3, dr.take(draw, TICK_COUNTS))
    start, dts, clabel = clock(draw, n)
    tl, ids = _Timeline(dts), _Ids()
    table, tlabel = draw_motion_table(draw)
    mover = _mover(draw, _spheres(draw), world.position(mx, my), world.z, _pks(draw, "player"))
    tableless = draw(MOVER_TABLELESS)
    if tableless:
        table, tlabel = None, "tableless"
    mover = replace(mover, motion_table=table, transient_state=mover.transient_state | int(TransientState.Active))
    others, tags = [], []
    for k in range(draw(OBJECT_COUNTS)):
        weenie = draw(OBJECT_WEENIES)
        drop = draw(OBJECT_DROPS)
        at = world.position(mx + 2.0 + 2.5 * k, my + float(draw(st.sampled_from((0.0, 1.0, -1.5)))))
        at = replace(at, frame=Frame((at.frame.origin[0], at.frame.origin[1], to_f32(at.frame.origin[2] + drop))))
        o = _other(draw, ids, weenie, _spheres(draw), at)
        o = replace(o, state=o.state | GRAVITY, motion_table=draw(OBJECT_TABLES) and not tableless,
                    transient_state=o.transient_state if drop == 0.0 else int(TransientState.Active))
        tag = f"{weenie[0]}{'t' if o.motion_table else ''}{f'^{drop:g}' if drop else ''}"
        rows = tl.of(o.id)
        for _ in range(draw(EXECUTE_COUNTS)):
            i = draw(st.integers(0, n - 1))
            rows[i]["execute_motion"] = draw(EXECUTED)
            tag += f".x{rows[i]['execute_motion'] & 0xFFFF:x}@{i}"
        later = draw(OBJECT_LATER)
        i = draw(st.integers(0, n - 1))
        if later == "gravity":
            rows[i]["state"] = o.state & ~GRAVITY
        elif later == "velocity":
            rows[i]["velocity"] = (to_f32(draw(st.sampled_from((0.5, -1.0, 2.0)))), 0.0, 0.0)
        elif later == "drop":  # lifted off the ground (its contact flags cleared): it falls and lands
            rows[i]["transient_state"] = int(TransientState.Active)
            rows[i]["velocity"] = (0.0, 0.0, to_f32(draw(st.sampled_from((1.0, 3.0)))))
        elif later == "stick":
            tl.mover[i]["stick_to"] = o.id
        elif later == "chase":  # the mover sent after it (Monster_Navigation.StartTurn's calls), or turned to it
            field = draw(st.sampled_from(("move_to_object", "turn_to_object")))
            tl.mover[i].setdefault(field, ObjectMoveInput(o.id, MovementParams()))
        if later in ("stick", "chase"):
            flags = draw(MOVER_FLAGS)
            if flags in ("inactive", "floating"):
                tl.mover[i]["transient_state"] = mover.transient_state & ~int(TransientState.Active)
            if flags == "floating":
                tl.mover[i]["state"] = mover.state & ~GRAVITY
            elif flags == "static":
                tl.mover[i]["state"] = mover.state | STATIC
            later += "" if flags == "kept" else f"-{flags}"
        if later != "none":
            tag += f".{later}@{i}"
        others.append(o)
        tags.append(tag)
    name = f"motion_objects:{'+'.join(tags)}:{tlabel}:{clabel}"
    return _finish(draw, start, dts, tl, world.landblocks, mover, tuple(others), (), name, ethereal=False)


# stop 51 (shard ticks-0076): a style whose default substate is a command that is a modifier and no substate
# (StopTurning, Jump: a table's StyleDefaults may name any command), with cycles and modifiers of it in NonCombat and
# HandCombat. A MoveToState to HandCombat runs GetObjectSequence's style arm, which makes the old style's default
# (that command) the Substate; that MoveToState's forward key or a DoMotion of the command then reaches the modifier
# arm: add_modifier refuses it (MotionState.add_modifier: it is the Substate), StopSequenceMotion finds no modifier
# to stop and add_modifier refuses it again (48 of the shard's 150 scenes: style_forward 29 of 37, style_do 18 of
# 44, forward_do 1 of 33, style 0 of 36)
MODIFIER_SUBSTATES = st.sampled_from((int(MC.StopTurning), int(MC.Jump)))
MODIFIER_ASKS = st.sampled_from(("style", "style_forward", "style_do", "forward_do"))


def draw_modifier_substate_ticks(draw, base: Scene, clock) -> Scene:
    """A motion tick scene (draw_motion_ticks) whose table's NonCombat style defaults to a modifier-only command that
    HandCombat has a cycle and both styles a modifier of, the first tick a MoveToState to HandCombat mostly."""
    scene = draw_motion_ticks(draw, base, clock)
    x = draw(MODIFIER_SUBSTATES)
    table = scene.mover.motion_table
    ready = next(c for c in table.cycles if c.style == NC and c.motion == READY).data
    style_defaults = tuple((s, x if s == NC else m) for s, m in table.style_defaults)
    if HC not in (s for s, _ in style_defaults):
        style_defaults += ((HC, READY),)
    keep = lambda es: tuple(e for e in es if e.motion != x and not (e.style == HC and e.motion == READY))  # noqa: E731
    cycles = (*keep(table.cycles), MotionEntry(NC, x, ready), MotionEntry(HC, x, ready), MotionEntry(HC, READY, ready))
    modifiers = (*keep(table.modifiers), MotionEntry(NC, x, ready), MotionEntry(HC, x, ready))
    table = replace(table, style_defaults=style_defaults, cycles=cycles, modifiers=modifiers)
    ask = draw(MODIFIER_ASKS)
    steps = list(scene.ticks.steps)
    kw = {"hold_key": int(HoldKey.None_)}
    if ask != "forward_do":
        kw["style"] = HC
    if ask in ("style_forward", "forward_do"):
        kw.update(forward=x, forward_hold_key=int(HoldKey.None_), forward_speed=1.0)
    steps[0] = replace(steps[0], motion=MotionInput(**kw))
    if ask in ("style_do", "forward_do"):
        at = draw(st.integers(0, len(steps) - 1))
        steps[at] = replace(steps[at], do_motion=CommandInput(x))
    mover = replace(scene.mover, motion_table=table)
    return scene.replace(mover=mover, ticks=replace(scene.ticks, steps=tuple(steps)),
                         name=f"{scene.name}:modsub{x & 0xFF:x}:{ask}")
