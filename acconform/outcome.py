"""The outcome: what one transition left behind, read the same way from the port and from ACE.

Format ``acconform.outcome/6``. Fields mirror ACE's objects after PhysicsObj.transition's
steps (FindValidPosition and its set-up): SpherePath.CurPos/CurCell, ObjectInfo.State, the
CollisionInfo fields, the mover's velocity (ObjectInfo.StopVelocity zeroes it), and a few
SpherePath fields that expose the transition's own state. `error` holds what a side raised
(ACE exception or port exception) as a verdict; the other fields are then defaults.

`static_cells` shows where the scene's statics were placed: for each static object, in scene
order, the ids of the cells its PhysicsObj is registered in as a shadow object, in the order of
`PhysicsObj.ShadowObjects` (a .NET Dictionary keyed by cell id: insertion order, since the
placement removes nothing). It is required in ``/2`` (``null`` when a side could not read it,
e.g. an error before placement); ``acconform.outcome/1`` documents still read, with
``static_cells = None``: "not recorded", which the comparator does not compare.

`placement` (``/3``; None for a scene without a placement, whose outcome is still written as
``/2``) is what ACE's placement of the mover left: SetPosition's answer and the mover's
Position, CurCell, TransientState and ShadowObjects cells afterwards. When the placement left
the mover in no cell, the transition is not run, and the transition's fields are the defaults
of this record (`velocity` and `static_cells` are still read): both sides write that record,
neither infers it.

`ticks` (``/4``; None for a scene without ticks, whose outcome is still written as ``/3`` or ``/2``)
holds, for a tick scene, one `TickState` per step: the mover's PhysicsObj read after the step's
driver returned. A tick scene's transition fields keep this record's defaults (no single
transition). An exception in a tick is that tick's `error` (its other fields the defaults) and
ends the scene: later steps have no TickState. An error before the first tick (building the
world) is the outcome's own `error`, with `ticks` None.

A tick's `motion` (``/5``; None for a mover without a motion table, whose outcome is still written as
``/4``, byte for byte as before) is the mover's motion layer after the tick, a `MotionTickState`:
its MotionInterp's InterpretedState and RawState, its Sequence's current animation, frame number,
Velocity and Omega, and its MoveToManager's MovementType and IsMovingTo. An ``/4`` record still
reads (its ticks with `motion` None); a `motion` there is refused, as a field the format lacks.

A scene with other movers (scene/8 ``others``) is answered as ``/6``: `other_placements` holds each
other mover after it entered the world (in the scene's `others` order), and each tick, beside the
mover's fields, its `collisions` (the mover's CollisionTable: the objects it touched, in the table's
.NET Dictionary order, with each record's TouchedTime and Ethereal) and `others` (each other mover's
`TickState`, with its own `collisions`, named by its id, in `others` order). Scenes without other
movers are written as before.

A scene with ``motion_queries`` (scene/8) is answered as ``/6`` too: `motion_answers` holds each query's answer, in
order (a `MotionAnswerState`: a float32 `value`, GetAttackFrames' `attack_frames` or an `error`).
"""

from __future__ import annotations

from dataclasses import dataclass, field, fields, replace

from .codec import Reader, write_f32, write_f64, write_id, write_vec
from .flags import ObjectInfoState, PhysicsState, SetPositionError, TransientState, flag_names
from .scene import Frame, IDENTITY, Vec3, check_format

FORMAT = "acconform.outcome/6"
FORMAT_V5 = "acconform.outcome/5"  # what an outcome with no other movers (scene/8 `others`) is written as
FORMAT_V4 = "acconform.outcome/4"  # what a tick outcome without a motion layer (no tick has `motion`) is written as
FORMAT_V3 = "acconform.outcome/3"  # what an outcome with a placement and no ticks is written as
FORMAT_V2 = "acconform.outcome/2"  # what an outcome without a placement is written as
FORMAT_V1 = "acconform.outcome/1"  # read (static_cells not recorded), never written
ZERO: Vec3 = (0.0, 0.0, 0.0)


def _field(default, unit: str, what: str):
    """A field with its unit ("" when it has none) and what it holds: docs/protocol.md's table of
    outcome fields is generated from these (acconform.schema.outcome_fields_markdown)."""
    return field(default=default, metadata={"unit": unit, "what": what})


def _vec_nf(r: Reader) -> Vec3:
    return r.f32s(3, allow_nonfinite=True)


def _quat_nf(r: Reader) -> tuple[float, float, float, float]:
    return r.f32s(4, allow_nonfinite=True)


@dataclass(frozen=True, slots=True)
class ContactPlaneState:
    valid: bool = _field(False, "", "whether the plane is set (CollisionInfo.ContactPlaneValid / LastKnownContactPlaneValid)")
    cell: int = _field(0, "", "the cell the plane was found in (ContactPlaneCellID)")
    is_water: bool = _field(False, "", "whether it is a water surface (ContactPlaneIsWater)")
    normal: Vec3 = _field(ZERO, "unit vector", "Plane.Normal")
    d: float = _field(0.0, "m", "Plane.D: the plane holds the points p with normal . p + d = 0")

    def to_json(self):
        return {"valid": self.valid, "cell": write_id(self.cell), "is_water": self.is_water,
                "normal": write_vec(self.normal), "d": write_f32(self.d)}

    @staticmethod
    def from_json(r: Reader) -> "ContactPlaneState":
        r.obj({"valid", "cell", "is_water", "normal", "d"})
        return ContactPlaneState(r["valid"].bool_(), r["cell"].id_(), r["is_water"].bool_(),
                                 _vec_nf(r["normal"]), r["d"].f32(allow_nonfinite=True))


@dataclass(frozen=True, slots=True)
class NormalState:
    valid: bool = _field(False, "", "whether the normal is set (CollisionNormalValid / SlidingNormalValid)")
    vector: Vec3 = _field(ZERO, "direction", "the normal, un-normalised as ACE stores it")

    def to_json(self):
        return {"valid": self.valid, "vector": write_vec(self.vector)}

    @staticmethod
    def from_json(r: Reader) -> "NormalState":
        r.obj({"valid", "vector"})
        return NormalState(r["valid"].bool_(), _vec_nf(r["vector"]))


@dataclass(frozen=True, slots=True)
class PlacementState:
    """The mover after PhysicsObj.SetPositionInternal(Position, SetPosition, Transition)."""

    result: int = _field(0, "", "SetPosition's answer: a SetPositionError name (OK, NoCell, Collided, ...)")
    cell: int = _field(0, "", "Position.ObjCellID")
    origin: Vec3 = _field(ZERO, "m", "Position.Frame.Origin, within the cell's landblock")
    orientation: tuple[float, float, float, float] = _field(IDENTITY, "quaternion [w, x, y, z]", "Position.Frame.Orientation")
    cur_cell: int = _field(0, "", "the mover's CurCell id (0x00000000 when none)")
    transient_state: int = _field(0, "", "TransientState flag names (Contact, OnWalkable, ...)")
    shadow_cells: tuple[int, ...] = _field((), "", "the cell ids of the mover's ShadowObjects, in their order")

    def to_json(self):
        return {"result": SetPositionError(self.result).name, "cell": write_id(self.cell), "origin": write_vec(self.origin),
                "orientation": write_vec(self.orientation), "cur_cell": write_id(self.cur_cell),
                "transient_state": flag_names(TransientState, self.transient_state),
                "shadow_cells": [write_id(c) for c in self.shadow_cells]}

    @staticmethod
    def from_json(r: Reader) -> "PlacementState":
        r.obj({"result", "cell", "origin", "orientation", "cur_cell", "transient_state", "shadow_cells"})
        name = r["result"].str_()
        if name not in SetPositionError.__members__:
            r["result"].fail(f"unknown SetPositionError {name!r} (known: {', '.join(SetPositionError.__members__)})")
        return PlacementState(int(SetPositionError[name]), r["cell"].id_(), _vec_nf(r["origin"]),
                              _quat_nf(r["orientation"]),
                              r["cur_cell"].id_(), r["transient_state"].flags(TransientState),
                              tuple(c.id_() for c in r["shadow_cells"].list()))


@dataclass(frozen=True, slots=True)
class PlaneState:
    """A System.Numerics Plane read back from ACE (PhysicsObj.ContactPlane): its normal and d."""

    normal: Vec3 = _field(ZERO, "unit vector", "Plane.Normal")
    d: float = _field(0.0, "m", "Plane.D: the plane holds the points p with normal . p + d = 0")

    def to_json(self):
        return {"normal": write_vec(self.normal), "d": write_f32(self.d)}

    @staticmethod
    def from_json(r: Reader) -> "PlaneState":
        r.obj({"normal", "d"})
        return PlaneState(_vec_nf(r["normal"]), r["d"].f32(allow_nonfinite=True))


Quat = tuple[float, float, float, float]


@dataclass(frozen=True, slots=True)
class CommandState:
    """The commands of a motion state (MotionInterp.InterpretedState, an InterpretedMotionState, or its
    RawState, a RawMotionState): the fields the two share; the raw one's hold keys and either's Actions
    are not read."""

    current_style: int = _field(0, "", "CurrentStyle: a MotionStance/MotionCommand id (0x8000003D NonCombat)")
    forward_command: int = _field(0, "", "ForwardCommand: a MotionCommand id (0x41000003 Ready, 0x45000005 WalkForward)")
    forward_speed: float = _field(0.0, "", "ForwardSpeed: the forward command's speed factor")
    side_step_command: int = _field(0, "", "SideStepCommand: a MotionCommand id (0 none)")
    side_step_speed: float = _field(0.0, "", "SideStepSpeed")
    turn_command: int = _field(0, "", "TurnCommand: a MotionCommand id (0 none)")
    turn_speed: float = _field(0.0, "", "TurnSpeed")

    def to_json(self):
        return {"current_style": write_id(self.current_style), "forward_command": write_id(self.forward_command),
                "forward_speed": write_f32(self.forward_speed), "side_step_command": write_id(self.side_step_command),
                "side_step_speed": write_f32(self.side_step_speed), "turn_command": write_id(self.turn_command),
                "turn_speed": write_f32(self.turn_speed)}

    @staticmethod
    def from_json(r: Reader) -> "CommandState":
        r.obj(_COMMAND_FIELDS)
        return CommandState(r["current_style"].id_(), r["forward_command"].id_(),
                            r["forward_speed"].f32(allow_nonfinite=True), r["side_step_command"].id_(),
                            r["side_step_speed"].f32(allow_nonfinite=True), r["turn_command"].id_(),
                            r["turn_speed"].f32(allow_nonfinite=True))


_COMMAND_FIELDS = frozenset({"current_style", "forward_command", "forward_speed", "side_step_command",
                             "side_step_speed", "turn_command", "turn_speed"})


@dataclass(frozen=True, slots=True)
class MotionTickState:
    """The mover's motion layer after a tick (a mover with a motion table): read from its
    MovementManager's MotionInterpreter and MoveToManager and its PartArray's Sequence, without a
    call that could change them (get_minterp would make a manager; get_state_velocity asks the
    WeenieObject for its run rate), so reading changes nothing the next tick sees."""

    interpreted: CommandState | None = _field(None, "", "MotionInterp.InterpretedState (null when the mover has no "
                                              "MovementManager or MotionInterpreter)")
    raw: CommandState | None = _field(None, "", "MotionInterp.RawState (null as `interpreted`)")
    animation: int | None = _field(None, "", "the animation id of the Sequence's CurrAnim (its AnimSequenceNode's "
                                   "Anim.ID, a 0x03... DAT id); null when CurrAnim is null")
    frame_number: float = _field(0.0, "frames", "Sequence.FrameNumber (a float in ACE: where in CurrAnim it is)")
    sequence_velocity: Vec3 = _field(ZERO, "m/s", "Sequence.Velocity: the velocity the motion layer asks for, "
                                     "what PartArray.Update applies to the mover each tick (in its own frame)")
    sequence_omega: Vec3 = _field(ZERO, "rad/s", "Sequence.Omega: the turn it asks for, applied likewise")
    movement_type: int | None = _field(None, "", "MoveToManager.MovementType, a MovementType name (Invalid when "
                                       "not moving to); null when there is no MoveToManager")
    is_moving_to: bool = _field(False, "", "PhysicsObj.IsMovingTo(): MovementManager.IsMovingTo(), false when there is no MovementManager")

    def to_json(self):
        from .motion_enums import MovementType

        return {"interpreted": None if self.interpreted is None else self.interpreted.to_json(),
                "raw": None if self.raw is None else self.raw.to_json(),
                "animation": None if self.animation is None else write_id(self.animation),
                "frame_number": write_f32(self.frame_number),
                "sequence_velocity": write_vec(self.sequence_velocity), "sequence_omega": write_vec(self.sequence_omega),
                "movement_type": None if self.movement_type is None else MovementType(self.movement_type).name,
                "is_moving_to": self.is_moving_to}

    @staticmethod
    def from_json(r: Reader) -> "MotionTickState":
        from .motion_enums import MovementType

        r.obj(_MOTION_ALLOWED)
        for name in _MOTION_FIELDS:
            r[name]  # every field is written (null where it has none): a missing one is named
        mt = None
        if r.has("movement_type"):
            mt = r["movement_type"].enum_(MovementType)
        return MotionTickState(
            CommandState.from_json(r["interpreted"]) if r.has("interpreted") else None,
            CommandState.from_json(r["raw"]) if r.has("raw") else None,
            r["animation"].id_() if r.has("animation") else None,
            r["frame_number"].f32(allow_nonfinite=True), _vec_nf(r["sequence_velocity"]), _vec_nf(r["sequence_omega"]),
            mt, r["is_moving_to"].bool_())


_MOTION_FIELDS = ("interpreted", "raw", "animation", "frame_number", "sequence_velocity", "sequence_omega",
                  "movement_type", "is_moving_to")  # in declaration order: a missing one is named the same every run
_MOTION_ALLOWED = frozenset(_MOTION_FIELDS)


@dataclass(frozen=True, slots=True)
class CollisionState:
    """One record of a PhysicsObj's CollisionTable (an object it collided with and has not ended)."""

    id: int = _field(0, "", "the other object's id (the table's key)")
    touched_time: float = _field(0.0, "s (double)", "CollisionRecord.TouchedTime: the clock when it last touched")
    ethereal: bool = _field(False, "", "CollisionRecord.Ethereal: the other object was ethereal then")

    def to_json(self):
        return {"id": write_id(self.id), "touched_time": _write_double(self.touched_time), "ethereal": self.ethereal}

    @staticmethod
    def from_json(r: Reader) -> "CollisionState":
        r.obj({"id", "touched_time", "ethereal"})
        return CollisionState(r["id"].id_(), _read_double(r["touched_time"]), r["ethereal"].bool_())


@dataclass(frozen=True, slots=True)
class TickState:
    """The mover's PhysicsObj after one tick's driver returned (update_object / the request_pos path)."""

    updated: bool = _field(False, "", "the driver's return value (update_object / update_object_server)")
    update_time: float = _field(0.0, "s (double)", "PhysicsObj.UpdateTime, the clock the next tick's quantum counts from")
    cell: int = _field(0, "", "Position.ObjCellID")
    cur_cell: int = _field(0, "", "CurCell's id (0x00000000 when none)")
    origin: Vec3 = _field(ZERO, "m", "Position.Frame.Origin, within the cell's landblock")
    orientation: Quat = _field(IDENTITY, "quaternion [w, x, y, z]", "Position.Frame.Orientation")
    velocity: Vec3 = _field(ZERO, "m/s", "PhysicsObj.Velocity")
    acceleration: Vec3 = _field(ZERO, "m/s^2", "PhysicsObj.Acceleration")
    omega: Vec3 = _field(ZERO, "rad/s", "PhysicsObj.Omega")
    cached_velocity: Vec3 = _field(ZERO, "m/s", "PhysicsObj.CachedVelocity")
    state: int = _field(0, "", "PhysicsState flag names")
    transient_state: int = _field(0, "", "TransientState flag names (Contact, OnWalkable, Active, ...)")
    contact_plane_cell: int = _field(0, "", "PhysicsObj.ContactPlaneCellID")
    contact_plane: PlaneState = _field(PlaneState(), "", "PhysicsObj.ContactPlane")
    sliding_normal: Vec3 = _field(ZERO, "direction", "PhysicsObj.SlidingNormal")
    jumped_this_frame: bool = _field(False, "", "PhysicsObj.JumpedThisFrame")
    shadow_cells: tuple[int, ...] = _field((), "", "the cell ids of the mover's ShadowObjects, in their order")
    motion: MotionTickState | None = _field(None, "", "the mover's motion layer after the step, only for a mover with "
                                            "a motion table (then the format is acconform.outcome/5); absent otherwise")
    collisions: tuple[CollisionState, ...] | None = _field(
        None, "", "the PhysicsObj's CollisionTable after the step, in its order, only in a scene with other movers "
        "(then the format is acconform.outcome/6); absent otherwise")
    others: tuple["TickState", ...] | None = _field(
        None, "", "each other mover's TickState after the step (with its `id`; no `motion`, `others` or `error` of "
        "its own), in the scene's `others` order, only in a scene with other movers (acconform.outcome/6); absent "
        "otherwise")
    id: int | None = _field(None, "", "the other mover's id, in an entry of a tick's `others` only (scene/8 "
                            "others[].id); absent otherwise")
    error: str | None = _field(None, "", "what this step threw (later steps are not run); absent when nothing was raised")

    def to_json(self):
        d = {name: write(getattr(self, name)) for name, write, _ in _TICK_CODECS}
        if self.id is not None:
            d = {"id": write_id(self.id), **d}
        if self.motion is not None:
            d["motion"] = self.motion.to_json()
        if self.collisions is not None:
            d["collisions"] = [c.to_json() for c in self.collisions]
        if self.others is not None:
            d["others"] = [o.to_json() for o in self.others]
        if self.error is not None:
            d["error"] = self.error
        return d

    @staticmethod
    def from_json(r: Reader, motion: bool = True, others: bool = True) -> "TickState":
        """`motion`: whether the record's format has the tick's `motion` (``/5``; ``/4`` has not); `others`:
        its `collisions` and `others` (``/6``)."""
        allowed = _TICK_ALLOWED if motion else _TICK_ALLOWED_V4
        r.obj(allowed if others else allowed - {"collisions", "others", "id"})
        kw = {name: read(r[name]) for name, _, read in _TICK_CODECS}  # a missing field: the first in declaration order
        if r.has("motion"):
            kw["motion"] = MotionTickState.from_json(r["motion"])
        if r.has("collisions"):
            kw["collisions"] = tuple(CollisionState.from_json(c) for c in r["collisions"].list())
        if r.has("others"):
            kw["others"] = tuple(TickState._other_from_json(o) for o in r["others"].list())
        if r.has("id"):
            r["id"].fail("only an entry of a tick's `others` names a mover by id")
        if r.has("error"):
            kw["error"] = r["error"].str_()
        return TickState(**kw)


_TICK_FIELDS = tuple(f.name for f in fields(TickState))  # in declaration order (an outcome holds one per tick)
_TICK_ALLOWED = frozenset(_TICK_FIELDS)
_TICK_ALLOWED_V4 = _TICK_ALLOWED - {"motion", "collisions", "others", "id"}
_TICK_ALLOWED_OTHER = _TICK_ALLOWED - {"motion", "others", "error"}


def _other_from_json(r: Reader) -> TickState:
    """An entry of a tick's `others`: its id and its TickState's fields."""
    oid = r.obj(_TICK_ALLOWED_OTHER)["id"].id_()
    body = Reader({k: v for k, v in r.value.items() if k != "id"}, r.path, exact=r.exact)
    return replace(TickState.from_json(body), id=oid)


TickState._other_from_json = staticmethod(_other_from_json)
_TICK_IDS = frozenset({"cell", "cur_cell", "contact_plane_cell"})
_TICK_VECS = frozenset({"origin", "orientation", "velocity", "acceleration", "omega", "cached_velocity", "sliding_normal"})


def _write_double(v: float):
    """A double read back from ACE: finite as its shortest round-trip decimal, else its bit pattern."""
    import math
    import struct

    if math.isfinite(v):
        return write_f64(v)
    return f"0x{struct.unpack('<Q', struct.pack('<d', v))[0]:016x}"


def _read_double(r: Reader) -> float:
    import struct

    v = r.value
    if isinstance(v, str) and v.lower().startswith("0x") and len(v) == 18:
        try:
            return struct.unpack("<d", struct.pack("<Q", int(v, 16)))[0]
        except ValueError:
            r.fail(f"expected a number or a double's bit pattern, got {v!r}")
    return r.f64()


def _tick_field_codec(name: str):
    """How a TickState's field `name` is written and read (all but `error`, which may be left out)."""
    if name in _TICK_IDS:
        return write_id, Reader.id_
    if name == "orientation":
        return write_vec, _quat_nf
    if name in _TICK_VECS:
        return write_vec, _vec_nf
    if name == "update_time":
        return _write_double, _read_double
    if name == "state":
        return lambda v: flag_names(PhysicsState, v), lambda x: x.flags(PhysicsState)
    if name == "transient_state":
        return lambda v: flag_names(TransientState, v), lambda x: x.flags(TransientState)
    if name == "shadow_cells":
        return lambda v: [write_id(c) for c in v], lambda x: tuple(c.id_() for c in x.list())
    if name == "contact_plane":
        return PlaneState.to_json, PlaneState.from_json
    return bool, Reader.bool_


# (name, write, read) per field, in declaration order, looked up once: an outcome holds a TickState
# per tick, and each one asked dataclasses.fields() and ran the field's if-chain (with flag_names
# remembering its answers, a 25-tick outcome is written in 0.37 ms, not 0.54, and read in 0.73, not 1.1)
_TICK_CODECS = tuple((name, *_tick_field_codec(name)) for name in _TICK_FIELDS
                     if name not in ("motion", "collisions", "others", "id", "error"))


@dataclass(frozen=True, slots=True)
class AttackFrameState:
    """One entry of GetAttackFrames' list: the frame's time and its AttackHook."""

    time: float = _field(0.0, "fraction of the animation", "the attack frame's number over the animation's frame count")
    direction: int = _field(0, "", "the AttackHook's Direction (AnimationHookDir: -1 Backward, 0 Both, 1 Forward)")
    part_index: int = _field(0, "", "its AttackCone.PartIndex")
    left_x: float = _field(0.0, "m", "AttackCone.Left.X")
    left_y: float = _field(0.0, "m", "AttackCone.Left.Y")
    right_x: float = _field(0.0, "m", "AttackCone.Right.X")
    right_y: float = _field(0.0, "m", "AttackCone.Right.Y")
    radius: float = _field(0.0, "m", "AttackCone.Radius")
    height: float = _field(0.0, "m", "AttackCone.Height")

    def to_json(self):
        return {name: (write_f32(v) if name in _ATTACK_FLOATS else v)
                for name in _ATTACK_FIELDS for v in (getattr(self, name),)}

    @staticmethod
    def from_json(r: Reader) -> "AttackFrameState":
        r.obj(set(_ATTACK_FIELDS))
        return AttackFrameState(**{name: (r[name].f32(allow_nonfinite=True) if name in _ATTACK_FLOATS
                                          else r[name].int_(-1, 1) if name == "direction" else r[name].int_(0, 0xFFFFFFFF))
                                   for name in _ATTACK_FIELDS})


_ATTACK_FIELDS = tuple(f.name for f in fields(AttackFrameState))
_ATTACK_FLOATS = frozenset(_ATTACK_FIELDS) - {"direction", "part_index"}


@dataclass(frozen=True, slots=True)
class MotionAnswerState:
    """The answer to one of the scene's motion_queries: a float (`value`: a length in seconds, a run speed, a turn
    speed) or GetAttackFrames' list (`attack_frames`), or what the query threw (`error`)."""

    value: float | None = _field(None, "s, m/s or rad/s", "GetAnimationLength's seconds, GetRunSpeed's metres per "
                                 "second or GetTurnSpeed's radians per second; absent for GetAttackFrames")
    attack_frames: tuple[AttackFrameState, ...] | None = _field(
        None, "", "GetAttackFrames' list, in its order: each attack hook's time and fields; absent for the others")
    error: str | None = _field(None, "", "what the query threw; absent when nothing was raised")

    def to_json(self):
        d = {}
        if self.value is not None:
            d["value"] = write_f32(self.value)
        if self.attack_frames is not None:
            d["attack_frames"] = [a.to_json() for a in self.attack_frames]
        if self.error is not None:
            d["error"] = self.error
        return d

    @staticmethod
    def from_json(r: Reader) -> "MotionAnswerState":
        r.obj({"value", "attack_frames", "error"})
        return MotionAnswerState(
            r["value"].f32(allow_nonfinite=True) if r.has("value") else None,
            tuple(AttackFrameState.from_json(a) for a in r["attack_frames"].list()) if r.has("attack_frames") else None,
            r["error"].str_() if r.has("error") else None)


@dataclass(frozen=True, slots=True)
class Outcome:
    ok: bool = _field(False, "", "FindValidPosition's answer (PhysicsObj.transition returns null when false)")
    cell: int = _field(0, "", "SpherePath.CurCell's id")
    origin: Vec3 = _field(ZERO, "m", "SpherePath.CurPos.Frame.Origin, within the cell's landblock")
    orientation: tuple[float, float, float, float] = _field(IDENTITY, "quaternion [w, x, y, z]", "SpherePath.CurPos.Frame.Orientation")
    object_info_state: int = _field(0, "", "ObjectInfo.State flag names (Contact, OnWalkable, EdgeSlide, ...)")
    contact_plane: ContactPlaneState = _field(ContactPlaneState(), "", "CollisionInfo's contact plane")
    last_known_contact_plane: ContactPlaneState = _field(ContactPlaneState(), "", "CollisionInfo's last known contact plane")
    collision_normal: NormalState = _field(NormalState(), "", "CollisionInfo.CollisionNormal")
    sliding_normal: NormalState = _field(NormalState(), "", "CollisionInfo.SlidingNormal")
    collided_with_environment: bool = _field(False, "", "CollisionInfo.CollidedWithEnvironment")
    frames_stationary_fall: int = _field(0, "frames (0-3)", "CollisionInfo.FramesStationaryFall")
    velocity: Vec3 = _field(ZERO, "m/s", "the mover's velocity afterwards (ObjectInfo.StopVelocity zeroes it)")
    check_cell: int = _field(0, "", "SpherePath.CheckCell's id (0x00000000 when none)")
    walkable: bool = _field(False, "", "whether SpherePath.Walkable is set")
    step_up: bool = _field(False, "", "SpherePath.StepUp")
    neg_poly_hit: bool = _field(False, "", "SpherePath.NegPolyHit")
    error: str | None = _field(None, "", "what a side raised, its .NET type first (\"NullReferenceException: ...\"), "
                               "or an implementation verdict; null when nothing was raised")
    static_cells: tuple[tuple[int, ...], ...] | None = _field(
        None, "", "for each static object, in scene order, the ids of the cells its PhysicsObj is registered in "
        "(PhysicsObj.ShadowObjects, in their order); null when it could not be read")
    placement: PlacementState | None = _field(None, "", "the mover after ACE's placement, only for a scene with "
                                              "mover.placement (then the format is acconform.outcome/3)")
    ticks: tuple[TickState, ...] | None = _field(None, "", "for a tick scene (then the format is acconform.outcome/4, "
                                                 "or /5 when its ticks carry `motion`), the mover's PhysicsObj after each "
                                                 "step's driver returned, in step order")
    other_placements: tuple[PlacementState, ...] | None = _field(
        None, "", "for a scene with other movers (then the format is acconform.outcome/6), each other mover after it "
        "entered the world (enter_world's answer OK or GeneralFailure, and where it is), in the scene's `others` order")
    motion_answers: tuple[MotionAnswerState, ...] | None = _field(
        None, "", "for a scene with motion_queries (then the format is acconform.outcome/6), each query's answer, in "
        "the scene's order, asked after the last tick")

    @property
    def frame(self) -> Frame:
        return Frame(self.origin, self.orientation)

    def to_json(self):
        d = {"format": FORMAT if self.other_placements is not None or self.motion_answers is not None
             else (FORMAT_V5 if any(t.motion is not None for t in self.ticks) else FORMAT_V4) if self.ticks is not None
             else FORMAT_V3 if self.placement is not None else FORMAT_V2}
        for f in fields(self):
            v = getattr(self, f.name)
            if f.name in ("placement", "ticks", "other_placements", "motion_answers") and v is None:
                continue
            if f.name == "motion_answers":
                d["motion_answers"] = [a.to_json() for a in v]
                continue
            if f.name == "ticks":
                d["ticks"] = [t.to_json() for t in v]
                continue
            if f.name == "other_placements":
                d["other_placements"] = [p.to_json() for p in v]
                continue
            if f.name in ("cell", "check_cell"):
                v = write_id(v)
            elif f.name in ("origin", "orientation", "velocity"):
                v = write_vec(v)
            elif f.name == "object_info_state":
                v = flag_names(ObjectInfoState, v)
            elif f.name == "static_cells":
                v = None if v is None else [[write_id(c) for c in cells] for cells in v]
            elif hasattr(v, "to_json"):
                v = v.to_json()
            d[f.name] = v
        return d

    @staticmethod
    def from_json(doc, path: str = "") -> "Outcome":
        """Every float must name a float32 (codec.Reader.f32), as every writer of an outcome writes
        it (the harness, an implementation): a double's digits there (0.30000000000000004) are a
        file acconform did not write, refused naming the field rather than rounded without a word."""
        r = Reader(doc, path, exact=True)
        names = _OUTCOME_FIELDS
        fmt = doc.get("format") if isinstance(doc, dict) else None
        v1 = fmt == FORMAT_V1
        allowed = _OUTCOME_ALLOWED - {"static_cells"} if v1 else _OUTCOME_ALLOWED
        if fmt not in (FORMAT, FORMAT_V5, FORMAT_V4, FORMAT_V3):
            allowed = allowed - {"placement"}
        if fmt not in (FORMAT, FORMAT_V5, FORMAT_V4):
            allowed = allowed - {"ticks"}
        if fmt != FORMAT:
            allowed = allowed - {"other_placements", "motion_answers"}
        r.obj(allowed | {"format"})
        if fmt not in (FORMAT_V1, FORMAT_V2, FORMAT_V3, FORMAT_V4, FORMAT_V5):
            check_format(r, FORMAT)
        kw = {}
        for name in names:
            if not r.has(name):
                if name in ("error", "placement", "ticks", "other_placements", "motion_answers") or (name == "static_cells" and (v1 or name in r.value)):
                    continue  # absent error/placement/ticks: none; static_cells: /1 never has it, /2 may write null
                r[name]  # raises InvalidScene: missing required field
            x = r[name]
            if name in ("cell", "check_cell"):
                kw[name] = x.id_()
            elif name in ("origin", "velocity"):
                kw[name] = _vec_nf(x)
            elif name == "orientation":
                kw[name] = _quat_nf(x)
            elif name == "object_info_state":
                kw[name] = x.flags(ObjectInfoState)
            elif name in ("contact_plane", "last_known_contact_plane"):
                kw[name] = ContactPlaneState.from_json(x)
            elif name in ("collision_normal", "sliding_normal"):
                kw[name] = NormalState.from_json(x)
            elif name == "frames_stationary_fall":
                kw[name] = x.int_(0, 3)
            elif name == "error":
                kw[name] = x.str_()
            elif name == "static_cells":
                kw[name] = tuple(tuple(c.id_() for c in cells.list()) for cells in x.list())
            elif name == "placement":
                kw[name] = PlacementState.from_json(x)
            elif name == "ticks":
                kw[name] = tuple(TickState.from_json(t, fmt in (FORMAT_V5, FORMAT), fmt == FORMAT) for t in x.list())
            elif name == "other_placements":
                kw[name] = tuple(PlacementState.from_json(p) for p in x.list())
            elif name == "motion_answers":
                kw[name] = tuple(MotionAnswerState.from_json(a) for a in x.list())
            else:
                kw[name] = x.bool_()
        return Outcome(**kw)


_OUTCOME_FIELDS = tuple(f.name for f in fields(Outcome))  # in declaration order: a missing field is named the same every run
_OUTCOME_ALLOWED = frozenset(_OUTCOME_FIELDS)
