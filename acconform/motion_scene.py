"""The motion layer's scene data (scene/6, protocol feature ``mover.motion``): the mover's motion table
and the tick input ``motion``.

A mover's ``motion_table`` is a small inline MotionTable: its default style, the style defaults, the
cycles, links and modifiers (each a MotionData: its animations with framerate and frame range, an
optional velocity and omega), and the animations they play, each a list of root-motion frames
(PosFrames). acconform/dat.py writes it as ACE's DAT records (MotionTable ``MOTION_TABLE_ID``,
Animation ``ANIMATION_BASE + index``, one part frame per frame for the Setup's one part, no hooks),
named by the mover's Setup (DefaultMotionTable); the mover is then made as WorldObject.InitPhysicsObj
makes a player with that MotionTableId. Motions and styles are MotionCommand names
(acconform/motion_enums.py); hold keys are HoldKey names (``None`` for HoldKey.None).

A tick's ``motion`` is the RawMotionState of a player's MoveToState, applied with the physics calls
of Player.OnMoveToState's FastTick path and OnMoveToState_ServerMethod (ACE's default,
client_movement_formula off): UpdateTime when not moving or animating, RawState.SetState, then
apply_raw_movement(true, motion_allows_jump(the interpreted forward command) == None).
"""

from __future__ import annotations

from dataclasses import dataclass

from .codec import Reader, write_f32, write_id, write_vec
from .errors import InvalidScene
from .motion_enums import HoldKey, MotionCommand

MOTION_TABLE_ID = 0x09000000  # the mover's MotionTable (portal DAT type 0x09)
ANIMATION_BASE = 0x03000000  # animation i of the mover's table (portal DAT type 0x03)
MAX_ANIMATIONS = 0xFFFF


def _command(r: Reader) -> int:
    name = r.str_()
    try:
        return int(MotionCommand[name])
    except KeyError:
        r.fail(f"unknown motion command {name!r} (a MotionCommand name, e.g. Ready, WalkForward, NonCombat)")


def _command_name(v: int) -> str:
    return MotionCommand(v).name


def _hold_key(r: Reader) -> int:
    name = r.str_()
    key = "None_" if name == "None" else name
    if key not in HoldKey.__members__:
        r.fail(f"unknown hold key {name!r} (known: Invalid, None, Run)")
    return int(HoldKey[key])


def _hold_key_name(v: int) -> str:
    return "None" if v == HoldKey.None_ else HoldKey(v).name


@dataclass(frozen=True, slots=True)
class AnimRef:
    """An AnimData: the table's animation `animation` (an index into its animations) played at
    `framerate` frames per second from `low_frame` to `high_frame` (-1: the last frame)."""

    animation: int
    framerate: float
    low_frame: int = 0
    high_frame: int = -1

    def to_json(self):
        return {"animation": self.animation, "framerate": write_f32(self.framerate), "low_frame": self.low_frame,
                "high_frame": self.high_frame}

    @staticmethod
    def from_json(r: Reader, n_animations: int) -> "AnimRef":
        r.obj({"animation", "framerate", "low_frame", "high_frame"})
        index = r["animation"].int_(0, n_animations - 1) if n_animations else r["animation"].fail(
            "the table has no animations to play")
        return AnimRef(index, r["framerate"].f32(), r["low_frame"].int_(-(2 ** 31), 2 ** 31 - 1) if r.given("low_frame") else 0,
                       r["high_frame"].int_(-(2 ** 31), 2 ** 31 - 1) if r.given("high_frame") else -1)


@dataclass(frozen=True, slots=True)
class MotionDataSpec:
    """A MotionData: its animations, Bitfield, and Velocity / Omega when given."""

    anims: tuple[AnimRef, ...]
    velocity: tuple | None = None
    omega: tuple | None = None
    bitfield: int = 0

    def json_into(self, d: dict) -> dict:
        d["anims"] = [a.to_json() for a in self.anims]
        if self.velocity is not None:
            d["velocity"] = write_vec(self.velocity)
        if self.omega is not None:
            d["omega"] = write_vec(self.omega)
        if self.bitfield:
            d["bitfield"] = self.bitfield
        return d

    @staticmethod
    def read(r: Reader, n_animations: int) -> "MotionDataSpec":
        return MotionDataSpec(tuple(AnimRef.from_json(a, n_animations) for a in r["anims"].list(max_count=255)),
                              r["velocity"].vec3() if r.given("velocity") else None,
                              r["omega"].vec3() if r.given("omega") else None,
                              r["bitfield"].int_(0, 255) if r.given("bitfield") else 0)


_DATA_FIELDS = {"anims", "velocity", "omega", "bitfield"}


@dataclass(frozen=True, slots=True)
class MotionEntry:
    """A cycle or modifier (`style`, `motion`), or a link (`style`, from `motion` to `to`)."""

    style: int
    motion: int
    data: MotionDataSpec
    to: int | None = None

    def to_json(self):
        d = {"style": _command_name(self.style), ("from" if self.to is not None else "motion"): _command_name(self.motion)}
        if self.to is not None:
            d["to"] = _command_name(self.to)
        return self.data.json_into(d)

    @staticmethod
    def from_json(r: Reader, n_animations: int, link: bool) -> "MotionEntry":
        r.obj({"style", "from", "to", *_DATA_FIELDS} if link else {"style", "motion", *_DATA_FIELDS})
        style = _command(r["style"])
        if link:
            return MotionEntry(style, _command(r["from"]), MotionDataSpec.read(r, n_animations), _command(r["to"]))
        return MotionEntry(style, _command(r["motion"]), MotionDataSpec.read(r, n_animations))


# the hooks a scene's animation may carry (ACE.Entity.Enum.AnimationHookType names), with the bytes
# DatLoader's hook class reads after type and direction: AnimHook.Execute acts on AnimationDone only
# (PhysicsObj.Hook_AnimDone); ACE's server physics ignores the others (their Execute arms are the client's,
# Ethereal's is commented out)
HOOKS = {"AnimationDone": (4, b""), "DefaultScript": (17, b""), "Ethereal": (6, b"\x01\x00\x00\x00"),
         "Sound": (1, b"\x00\x00\x00\x00"),
         # scene/8 motion_queries: an AttackHook (ignored by the server's physics) for GetAttackFrames to find, with one
         # AttackCone: PartIndex 0, Left (-0.5, 1), Right (0.5, 1), Radius 2, Height 1.5
         "Attack": (3, bytes.fromhex("00000000" "000000bf" "0000803f" "0000003f" "0000803f" "00000040" "0000c03f"))}
# name: (AnimationHookType, the fields' bytes)
HOOK_DIRECTIONS = {"Backward": -1, "Both": 0, "Forward": 1}


@dataclass(frozen=True, slots=True)
class HookSpec:
    """An AnimationHook on frame `frame` of an animation: its type (a HOOKS name) and direction
    (AnimationHookDir: Backward -1, Both 0, Forward 1: Sequence.execute_hooks runs a hook when its
    direction is Both or the way the frame is crossed)."""

    frame: int
    hook: str
    direction: int = 0

    def to_json(self):
        d = {"frame": self.frame, "hook": self.hook}
        if self.direction:
            d["direction"] = {v: k for k, v in HOOK_DIRECTIONS.items()}[self.direction]
        return d

    @staticmethod
    def from_json(r: Reader, n_frames: int) -> "HookSpec":
        r.obj({"frame", "hook", "direction"})
        hook = r["hook"].str_()
        if hook not in HOOKS:
            r["hook"].fail(f"unknown hook {hook!r} (known: {', '.join(HOOKS)})")
        direction = 0
        if r.given("direction"):
            name = r["direction"].str_()
            if name not in HOOK_DIRECTIONS:
                r["direction"].fail(f"unknown hook direction {name!r} (known: {', '.join(HOOK_DIRECTIONS)})")
            direction = HOOK_DIRECTIONS[name]
        return HookSpec(r["frame"].int_(0, n_frames - 1), hook, direction)


@dataclass(frozen=True, slots=True)
class AnimationSpec:
    """An Animation: its root motion, one PosFrame (a Frame) per frame (`root_motion` false: the
    Animation has as many frames but no PosFrames, its Flags without them), and its hooks."""

    pos_frames: tuple  # of scene.Frame
    root_motion: bool = True
    hooks: tuple = ()  # of HookSpec

    def to_json(self):
        d = {"pos_frames": [f.to_json() for f in self.pos_frames]}
        if not self.root_motion:
            d["root_motion"] = False
        if self.hooks:
            d["hooks"] = [h.to_json() for h in self.hooks]
        return d

    @staticmethod
    def from_json(r: Reader) -> "AnimationSpec":
        from .scene import Frame

        r.obj({"pos_frames", "root_motion", "hooks"})
        frames = tuple(Frame.from_json(f) for f in r["pos_frames"].list(min_count=1))
        return AnimationSpec(frames, r["root_motion"].bool_() if r.given("root_motion") else True,
                             tuple(HookSpec.from_json(h, len(frames)) for h in r["hooks"].list(max_count=64))
                             if r.given("hooks") else ())


@dataclass(frozen=True, slots=True)
class MotionTableSpec:
    default_style: int
    style_defaults: tuple  # ((style, substate), ...), in order
    animations: tuple[AnimationSpec, ...]
    cycles: tuple[MotionEntry, ...]
    links: tuple[MotionEntry, ...] = ()
    modifiers: tuple[MotionEntry, ...] = ()
    # scene/8: the mover's Setup's DefaultAnimation, animation `default_animation` of this table (None: 0,
    # none): PartArray.InitDefaults plays it before SetMotionTableID's default state replaces it
    default_animation: int | None = None

    @property
    def needs_v8(self) -> bool:
        """Whether the table uses a scene/8 field: the Setup's default_animation, an animation's hooks or
        its root_motion off."""
        return self.default_animation is not None or any(a.hooks or not a.root_motion for a in self.animations)

    def to_json(self):
        d = {"default_style": _command_name(self.default_style),
             "style_defaults": [[_command_name(s), _command_name(m)] for s, m in self.style_defaults],
             "animations": [a.to_json() for a in self.animations],
             "cycles": [c.to_json() for c in self.cycles]}
        if self.links:
            d["links"] = [c.to_json() for c in self.links]
        if self.modifiers:
            d["modifiers"] = [c.to_json() for c in self.modifiers]
        if self.default_animation is not None:
            d["default_animation"] = self.default_animation
        return d

    @staticmethod
    def from_json(r: Reader) -> "MotionTableSpec":
        r.obj({"default_style", "style_defaults", "animations", "cycles", "links", "modifiers", "default_animation"})
        animations = tuple(AnimationSpec.from_json(a) for a in r["animations"].list(max_count=MAX_ANIMATIONS))
        n = len(animations)
        pairs = []
        for p in r["style_defaults"].list():
            style, substate = p.list(count=2)
            pairs.append((_command(style), _command(substate)))
        keys = [s for s, _ in pairs]
        if len(set(keys)) != len(keys):
            r["style_defaults"].fail("a style has one default substate: a style is listed twice")
        table = MotionTableSpec(
            _command(r["default_style"]), tuple(pairs), animations,
            tuple(MotionEntry.from_json(c, n, False) for c in r["cycles"].list()),
            tuple(MotionEntry.from_json(c, n, True) for c in r["links"].list()) if r.given("links") else (),
            tuple(MotionEntry.from_json(c, n, False) for c in r["modifiers"].list()) if r.given("modifiers") else (),
            (r["default_animation"].int_(0, n - 1) if n else r["default_animation"].fail("the table has no animations"))
            if r.given("default_animation") else None)
        for name, entries in (("cycles", table.cycles), ("modifiers", table.modifiers)):
            seen = set()
            for i, e in enumerate(entries):
                key = cycle_key(e.style, e.motion)
                if key in seen:
                    raise InvalidScene(r[name][i].path, "the same style and motion as an earlier entry (one MotionData per key)")
                seen.add(key)
        seen = set()
        for i, e in enumerate(table.links):
            key = (cycle_key(e.style, e.motion), e.to)
            if key in seen:
                raise InvalidScene(r["links"][i].path, "the same style, from and to as an earlier link")
            seen.add(key)
        return table


def cycle_key(style: int, motion: int) -> int:
    """The key of MotionTable.Cycles, Modifiers and Links: ``style << 16 | (motion & 0xFFFFFF)`` (uint)."""
    return ((style << 16) | (motion & 0xFFFFFF)) & 0xFFFFFFFF


@dataclass(frozen=True, slots=True)
class MotionInput:
    """A MoveToState's RawMotionState: the current hold key and style, then forward, sidestep and turn
    commands, each with its hold key and speed. 0 (Invalid) where not given, as the client's packed
    state leaves an unflagged field (RawMotionState.SetState then makes style NonCombat, forward
    Ready and each speed 0 into 1)."""

    hold_key: int = 0
    style: int = 0
    forward: int = 0
    forward_hold_key: int = 0
    forward_speed: float = 0.0
    sidestep: int = 0
    sidestep_hold_key: int = 0
    sidestep_speed: float = 0.0
    turn: int = 0
    turn_hold_key: int = 0
    turn_speed: float = 0.0

    _COMMANDS = ("style", "forward", "sidestep", "turn")
    _KEYS = ("hold_key", "forward_hold_key", "sidestep_hold_key", "turn_hold_key")
    _SPEEDS = ("forward_speed", "sidestep_speed", "turn_speed")

    def to_json(self):
        d = {}
        for name in ("hold_key", "style", "forward", "forward_hold_key", "forward_speed", "sidestep",
                     "sidestep_hold_key", "sidestep_speed", "turn", "turn_hold_key", "turn_speed"):
            v = getattr(self, name)
            if not v:
                continue
            if name in self._COMMANDS:
                d[name] = _command_name(v)
            elif name in self._KEYS:
                d[name] = _hold_key_name(v)
            else:
                d[name] = write_f32(v)
        return d

    @staticmethod
    def from_json(r: Reader) -> "MotionInput":
        r.obj({"hold_key", "style", "forward", "forward_hold_key", "forward_speed", "sidestep", "sidestep_hold_key",
               "sidestep_speed", "turn", "turn_hold_key", "turn_speed"})
        kw = {}
        for name in MotionInput._COMMANDS:
            if r.given(name):
                kw[name] = _command(r[name])
        for name in MotionInput._KEYS:
            if r.given(name):
                kw[name] = _hold_key(r[name])
        for name in MotionInput._SPEEDS:
            if r.given(name):
                kw[name] = r[name].f32()
        return MotionInput(**kw)


# ACE's MovementParameters() constructor: its flags (CanWalk .. CanCharge, MoveTowards, UseSpheres,
# SetHoldKey, ModifyRawState, ModifyInterpretedState, CancelMoveTo, StopCompletely) and float defaults
DEFAULT_MOVEMENT_FLAGS = 0x1EE1F
_DEFAULT_FAIL_DISTANCE = 3.4028234663852886e38  # float.MaxValue (Default_FailDistance)


@dataclass(frozen=True, slots=True)
class MovementParams:
    """A MovementParameters as ``new MovementParameters()`` makes it, then each field the scene gives
    set (both sides build it with their own class: the oracle with ACE's, the port with
    port/animation/movement_parameters.py). ``flags`` are MovementParamFlags names (all of them: the
    listed set replaces the constructor's); hold_key_to_apply a HoldKey name."""

    flags: int = DEFAULT_MOVEMENT_FLAGS
    distance_to_object: float = 0.6000000238418579  # Default_DistanceToObject = 0.6f
    min_distance: float = 0.0
    fail_distance: float = _DEFAULT_FAIL_DISTANCE
    speed: float = 1.0
    walk_run_threshold: float = 1.0  # Default_WalkRunThreshold = 1.0f
    desired_heading: float = 0.0
    hold_key_to_apply: int = 0  # HoldKey.Invalid

    _FLOATS = ("distance_to_object", "min_distance", "fail_distance", "speed", "walk_run_threshold", "desired_heading")
    _FIELDS = frozenset(("flags", "hold_key_to_apply") + _FLOATS)

    def to_json(self):
        from .flags import flag_names
        from .motion_enums import MovementParamFlags

        d = {}
        if self.flags != DEFAULT_MOVEMENT_FLAGS:
            d["flags"] = flag_names(MovementParamFlags, self.flags)
        default = MovementParams()
        for name in self._FLOATS:
            v = getattr(self, name)
            if v != getattr(default, name):
                d[name] = write_f32(v)
        if self.hold_key_to_apply:
            d["hold_key_to_apply"] = _hold_key_name(self.hold_key_to_apply)
        return d

    @staticmethod
    def from_json(r: Reader) -> "MovementParams":
        from .motion_enums import MovementParamFlags

        r.obj(MovementParams._FIELDS)
        kw = {}
        if r.given("flags"):
            kw["flags"] = r["flags"].flags(MovementParamFlags)
        for name in MovementParams._FLOATS:
            if r.given(name):
                kw[name] = r[name].f32()
        if r.given("hold_key_to_apply"):
            kw["hold_key_to_apply"] = _hold_key(r["hold_key_to_apply"])
        return MovementParams(**kw)


def _params(r: Reader) -> MovementParams:
    """The step's ``params`` (the constructor's MovementParameters when left out)."""
    return MovementParams.from_json(r["params"]) if r.given("params") else MovementParams()


@dataclass(frozen=True, slots=True)
class MoveToInput:
    """``move_to``: Creature.MoveTo(Position)'s physics calls (UpdateTime when not moving or animating,
    then PhysicsObj.MoveToPosition(the position, the parameters)); ``turn_to_heading`` has no position
    (PhysicsObj.TurnToHeading with the parameters' DesiredHeading)."""

    params: MovementParams = MovementParams()
    position: object = None  # scene.Position (move_to only)

    def to_json(self):
        d = {}
        if self.position is not None:
            d["position"] = self.position.to_json()
        p = self.params.to_json()
        if p:
            d["params"] = p
        return d

    @staticmethod
    def from_json(r: Reader, with_position: bool) -> "MoveToInput":
        from .scene import Position

        r.obj({"position", "params"} if with_position else {"params"})
        return MoveToInput(_params(r),
                           Position.from_json(r["position"]) if with_position else None)


@dataclass(frozen=True, slots=True)
class ObjectMoveInput:
    """``move_to_object`` / ``turn_to_object``: the target is the scene's static object `object` (its
    id), found as ACE's server finds it (the id ServerObjectManager filed it under); the physics calls
    of Monster_Navigation.StartTurn: PhysicsObj.MoveToObject / TurnToObject(its PhysicsObj, the
    parameters), then UpdateTime = CurrentTime."""

    object: int
    params: MovementParams = MovementParams()

    def to_json(self):
        d = {"object": write_id(self.object)}
        p = self.params.to_json()
        if p:
            d["params"] = p
        return d

    @staticmethod
    def from_json(r: Reader) -> "ObjectMoveInput":
        r.obj({"object", "params"})
        return ObjectMoveInput(r["object"].id_(), _params(r))


# ``stop``: the server's ways to stop a movement (WorldObjects' callers, ACE 7b47913):
#   stop_completely       PhysicsObj.StopCompletely (Creature_Death, Player_Tick's PK logout, Player_Magic)
#   cancel_moveto         PhysicsObj.cancel_moveto (Player_Move2.StopExistingMoveToChains2, Player_Melee)
#   move_to_manager_cancel  MovementManager.MoveToManager.CancelMoveTo(ActionCancelled) and
#                         FailProgressCount = 0 (Monster_Navigation.CancelMoveTo, Creature_Navigation's MoveTo tick)
STOPS = ("stop_completely", "cancel_moveto", "move_to_manager_cancel")


@dataclass(frozen=True, slots=True)
class CommandInput:
    """``do_motion`` / ``stop_motion``: Player.OnMoveToState_ClientMethod's physics calls for one key
    (a MovementParameters() with HoldKeyToApply the current hold key; UpdateTime when not moving or
    animating; PhysicsObj.DoMotion(motion, mvp) / StopMotion(motion, mvp, true))."""

    motion: int
    hold_key: int = 0

    def to_json(self):
        d = {"motion": _command_name(self.motion)}
        if self.hold_key:
            d["hold_key"] = _hold_key_name(self.hold_key)
        return d

    @staticmethod
    def from_json(r: Reader) -> "CommandInput":
        r.obj({"motion", "hold_key"})
        return CommandInput(_command(r["motion"]), _hold_key(r["hold_key"]) if r.given("hold_key") else 0)


def read_stop(r: Reader) -> str:
    name = r.str_()
    if name not in STOPS:
        r.fail(f"unknown stop {name!r} (known: {', '.join(STOPS)})")
    return name
