"""Scene -> packed bytes for the facade, packed bytes -> Outcome. Pure Python (no .NET).

The layout is read by oracle/facade/Facade.cs (BuildScene / WriteOutcome); both sides change
together and carry PACK_VERSION. All floats travel as float32, so the facade sees exactly the
scene's values. The conventions both sides apply when staging a scene live in acconform.staging.
"""

from __future__ import annotations

import struct
from dataclasses import fields, replace

from ..outcome import (AttackFrameState, CollisionState, CommandState, ContactPlaneState, MotionAnswerState,
                       MotionTickState, NormalState, Outcome, PlacementState, PlaneState, TickState)
from ..dat import cell_landblock, has_objects, scene_records
from ..motion_scene import MOTION_TABLE_ID, STOPS
from ..scene import MOTION_QUERY_FUNCTIONS, SPELL_KINDS, DRIVERS, OTHER_INPUTS, TICK_INPUTS, WEENIE_CLASSES, Position, Frame, Scene, Ticks
from ..staging import MOVER_ID

PACK_VERSION = 18

_f = struct.Struct("<f")
_DOOR = struct.Struct("<IB")  # the door input: the static's id, 1 opens (ethereal) / 0 closes
_4f = struct.Struct("<4f")
_3f = struct.Struct("<3f")


_last_table: list = [None, b""]  # the last land height table and its bytes (scenes mostly share one)


def _table_bytes(table) -> bytes:
    if table is not _last_table[0] and table != _last_table[0]:
        _last_table[:] = [table, struct.pack("<256f", *table)]
    return _last_table[1]


def _pos(p) -> tuple:
    return (p.cell, *p.frame.origin, *p.frame.orientation)


_POS = "I3f4f"


# the DatLoader FileType the facade unpacks each record as; 0-2 go to the portal DAT, 3-4 to the cell DAT
_RECORD_KIND = {"GfxObj": 0, "SetupModel": 1, "Environment": 2, "EnvCell": 3, "LandblockInfo": 4, "MotionTable": 5,
                "Animation": 6}


def _record_list(records) -> list[bytes]:
    """DAT records (acconform.dat) the facade unpacks with ACE's own Unpack: count, then each one's
    kind, id, length and bytes."""
    out = [struct.pack("<i", len(records))]
    for rec in records:
        out.append(struct.pack("<BIi", _RECORD_KIND[rec.kind], rec.id, len(rec.data)))
        out.append(rec.data)
    return out


def _records(recs) -> list[bytes]:
    return _record_list(recs.records)


def _object(o, recs) -> bytes:
    """A static object: its scene id, position, state and scale (applied as WorldObject.InitPhysicsObj
    does), the DAT id `PhysicsObj.makeObject` takes and its DAT records (`recs`)."""
    head = struct.pack("<I" + _POS + "IfI", o.id, *_pos(o.position), o.state, o.scale, recs.did)
    return b"".join([head] + _records(recs))


_HEAD = struct.Struct("<iB")
_NO_END = Position(0, Frame((0.0, 0.0, 0.0)))  # a tick scene's mover has no end: the facade reads none
_TICKS_HEAD = struct.Struct("<BBdi")
_STEP_HEAD = struct.Struct("<dI")
_U32 = struct.Struct("<I")
_POS_S = struct.Struct("<" + "I3f4f")
# a motion input: the RawMotionState's CurrentHoldKey, CurrentStyle, then forward, sidestep and turn (command, hold key, speed)
_MOTION = struct.Struct("<IIIIfIIfIIf")
# a MovementParameters: Flags, DistanceToObject, MinDistance, FailDistance, Speed, WalkRunThreshold, DesiredHeading,
# HoldKeyToApply
_PARAMS = struct.Struct("<I6fI")
_COMMAND = struct.Struct("<II")  # do_motion / stop_motion: the motion, the HoldKeyToApply
_INDEX_MASK = struct.Struct("<iI")  # another mover's index in the scene's `others`, its inputs' mask


def _params(p) -> bytes:
    return _PARAMS.pack(p.flags, p.distance_to_object, p.min_distance, p.fail_distance, p.speed, p.walk_run_threshold,
                        p.desired_heading, p.hold_key_to_apply)


# how each input's value is packed (`v`; the rest: a vector, 3 floats), as the facade reads it
_INPUT_BYTES = {
    "state": "_U32.pack(v)", "transient_state": "_U32.pack(v)", "request_pos": "_POS_S.pack(*_pos(v))",
    "motion": "_MOTION.pack(v.hold_key, v.style, v.forward, v.forward_hold_key, v.forward_speed, v.sidestep, "
              "v.sidestep_hold_key, v.sidestep_speed, v.turn, v.turn_hold_key, v.turn_speed)",
    "stop": "_U32.pack(STOPS.index(v))", "do_motion": "_COMMAND.pack(v.motion, v.hold_key)",
    "stop_motion": "_COMMAND.pack(v.motion, v.hold_key)", "move_to": "_POS_S.pack(*_pos(v.position)) + _params(v.params)",
    "turn_to_heading": "_params(v.params)", "move_to_object": "_U32.pack(v.object) + _params(v.params)",
    "turn_to_object": "_U32.pack(v.object) + _params(v.params)", "door": "_DOOR.pack(v.object, 1 if v.ethereal else 0)",
    "stick_to": "_U32.pack(v)"}


def _inputs_packer(names: tuple, head: str, after: str = ""):
    """A function (r, out, key) of a TickStep or an OtherInputs `r`: appends to `out` `head`.pack(key, a mask of its
    inputs present, bit i: names[i]) and their values' bytes in that order (`after`: more lines, which may set mask
    bits and append values). Written out per input, straight into the scene's one list (a tick scene packs a
    TickStep, and an OtherInputs per other mover, per tick, and most of their inputs are None). A plain loop over
    (bit, packer) pairs measured about 3x slower on the inputs (stop 50, side by side in one process: attrgetter and
    zip, or compress over the present ones), and pack_scene 2.1-2.2x slower on benchmarks/bench_movers.py's scenes
    (1.0-1.4x on drawn motion, targets and missile scenes, whose DAT records weigh more): the straight-line code
    stays. The head goes in last, where its place was kept (stop 51: no list of values and no tuple per input set)."""
    body = "".join(f"    v = r.{name}\n    if v is not None:\n        mask |= {1 << bit}\n"
                   f"        out.append({_INPUT_BYTES.get(name, '_3f.pack(*v)')})\n" for bit, name in enumerate(names))
    ns: dict = {}
    exec(f"def inputs(r, out, key):\n    at = len(out)\n    out.append(None)\n    mask = 0\n{body}{after}"
         f"    out[at] = {head}.pack(key, mask)\n", globals(), ns)
    return ns["inputs"]


# a step's clock value and the mask of its inputs present (bit i: TICK_INPUTS[i])
_tick_inputs = _inputs_packer(TICK_INPUTS, "_STEP_HEAD")
# another mover's index in the scene's `others` and the mask of its inputs present (bit i: OTHER_INPUTS[i], then bit 8
# destroy, bit 9 unparent, bit 10 parent and (pack 18) bit 11 execute_motion)
_other_mover_inputs = _inputs_packer(OTHER_INPUTS, "_INDEX_MASK", (
    f"    if r.destroy:\n        mask |= {1 << len(OTHER_INPUTS)}\n"  # no value: destroyed after the setters and the parenting inputs
    f"    if r.unparent:\n        mask |= {2 << len(OTHER_INPUTS)}\n"  # unset_parent (no value)
    f"    v = r.parent\n    if v is not None:\n        mask |= {4 << len(OTHER_INPUTS)}\n"  # held anew, as a child's record says it
    f"        out.append(_child_of(v))\n"
    f"    v = r.execute_motion\n    if v is not None:\n        mask |= {8 << len(OTHER_INPUTS)}\n"  # WorldObject.ExecuteMotion's physics: its command
    f"        out.append(_U32.pack(v))\n"))


def _other_inputs(step, index: dict, out: list | None = None) -> list[bytes]:
    """int n, then per other mover's inputs (`_other_mover_inputs`; `index`: an id's index in the scene's `others`),
    appended to `out` (a new list when None), which is returned."""
    out = [] if out is None else out
    out.append(_I32.pack(len(step.others)))
    for r in step.others:
        _other_mover_inputs(r, out, index[r.id])
    return out


def _ticks(ticks: Ticks | None, others=(), queries=()) -> bytes:
    """byte 0 (not a tick scene), or 1 (2: with motion queries, `_queries` after the steps), the driver (its index in scene.DRIVERS), the start clock (double), the
    number of steps, and per step: its absolute clock value from `Ticks.times()` (double, computed once by the
    record), a mask of the inputs present (bit i: TICK_INPUTS[i]) and their values in that order, then int n and per
    other mover's inputs its index in the scene's `others`, their mask and values (`_other_inputs`; `others`: the
    scene's)."""
    if ticks is None:
        return b"\0"
    index = {o.id: k for k, o in enumerate(others)}
    out = [_TICKS_HEAD.pack(2 if queries else 1, DRIVERS.index(ticks.driver), ticks.start, len(ticks.steps))]
    tick_inputs = _tick_inputs
    for step, time in zip(ticks.steps, ticks.times()):
        tick_inputs(step, out, time)
        if step.others:
            _other_inputs(step, index, out)
        else:
            out.append(_NO_OTHERS)
    if queries:  # byte 2 above: the scene's motion_queries (scene/8) after the steps
        out += _queries(queries)
    return b"".join(out)


_NO_OTHERS = struct.pack("<i", 0)
# another mover (scene/8): its Setup id, id, weenie class (index in WEENIE_CLASSES), PlayerKillerStatus, scale, State,
# TransientState, Velocity, begin position
_OTHER = struct.Struct("<IIBIfII3f" + _POS)
# then (scene/8 children) whether it is a child (1) and its parent's id, ParentLocation and Placement (a child's begin is
# written as zeros: it enters the world with its parent)
_CHILD = struct.Struct("<BIii")
_NOT_A_CHILD = _CHILD.pack(0, 0, 0, 0)
# the frame form (ChildOf.part and .frame): byte 2, the parent's id, the part, 0, then the frame's origin and
# orientation (w x y z)
_FRAME = struct.Struct("<3f4f")


def _child_of(p) -> bytes:
    if p.part is not None:
        return _CHILD.pack(2, p.id, p.part, 0) + _FRAME.pack(*p.frame.origin, *p.frame.orientation)
    return _CHILD.pack(1, p.id, p.location, p.placement)
# ... then the Player's skills (acconform.scene.MoverSkills): Run, Jump, Stamina, Strength (u32), EncumbranceVal and
# AugmentationIncreasedCarryingCapacity (i32)
_MOVER = struct.Struct("<IIfII3fBI4fB3f" + _POS + _POS + "BiBII" + "IIIIii")
# then byte 0, or a projectile's launch (pack 14): byte 1, tick, launcher id, target id (0: none, an untargeted spell), speed, origin, orientation
# (w x y z), lead_target, arc, tracking, alt_solver, rotation_speed (the projectile's RotationSpeed; 0: none), the spell's kind
# (byte: its index in acconform.scene.SPELL_KINDS); then the WorldObject's ReportCollisions property (byte: 0 unset,
# 1 false, 2 true); then (pack 18) its WorldObject's MotionTableId (uint: MOTION_TABLE_ID, or 0)
_NO_LAUNCH = b"\0"
_LAUNCH = struct.Struct("<BiIIf3f4fBBBBfB")


def pack_scene(scene: Scene) -> bytes:
    out = [_HEAD.pack(PACK_VERSION, 1 if scene.engine_mode == "server" else 0),
           _ticks(scene.ticks, scene.others, scene.motion_queries),
           _table_bytes(scene.land_height_table),
           struct.pack("<i", len(scene.landblocks))]
    for lb in scene.landblocks:
        out.append(b"\xfc\0\0\0")  # 252: the length of every CellLandblock (acconform.dat.cell_landblock)
        out.append(cell_landblock(lb, has_objects(scene, lb.id | 0xFFFF)))
    written = scene_records(scene)
    out += _record_list(written.portal + written.cell)
    out.append(struct.pack("<i", len(scene.objects)))
    for o, recs in zip(scene.objects, written.statics):
        out.append(_object(o, recs))
    m = scene.mover
    recs = written.mover
    out += _records(recs)
    cp = m.contact_plane
    cpv = (0, 0, 0.0, 0.0, 0.0, 0.0) if cp is None else (1, cp.cell, *cp.plane.normal, cp.plane.d)
    sn = m.sliding_normal
    snv = (0, 0.0, 0.0, 0.0) if sn is None else (1, *sn)
    pl = m.placement
    plv = (0, 0, 0) if pl is None else (2 if pl.via == "enter_world" else 1, pl.flags, 1 if pl.get_cell else 0)
    sk = m.skills
    out.append(_MOVER.pack(recs.did, MOVER_ID, m.scale, m.state, m.transient_state,
                           *m.velocity, *cpv, *snv, *_pos(m.begin), *_pos(m.end if m.end is not None else _NO_END),
                           *plv, MOTION_TABLE_ID if m.motion_table is not None else 0, m.player_killer_status,
                           sk.run, sk.jump, sk.stamina, sk.strength, sk.encumbrance_val,
                           sk.augmentation_increased_carrying_capacity))
    out.append(_I32.pack(len(scene.others)))
    for o, recs in zip(scene.others, written.others):
        out += _records(recs)
        out.append(_OTHER.pack(recs.did, o.id, WEENIE_CLASSES.index(o.weenie), o.player_killer_status, o.scale, o.state,
                               o.transient_state, *o.velocity, *_pos(o.begin if o.begin is not None else _NO_END)))
        p = o.parent
        out.append(_NOT_A_CHILD if p is None else _child_of(p))
        la = o.launch
        out.append(_NO_LAUNCH if la is None else
                   _LAUNCH.pack(1, la.tick, la.launcher, la.target or 0, la.speed, *la.origin, *la.orientation,
                                1 if la.lead_target else 0, 1 if la.arc else 0, 1 if la.tracking else 0,
                                1 if la.alt_solver else 0, la.rotation_speed,
                                SPELL_KINDS.index(la.spell)))
        out.append(bytes((0 if o.report_collisions is None else 2 if o.report_collisions else 1,)))
        out.append(_U32.pack(o.motion_table_id))  # pack 18: its WorldObject's MotionTableId
    return b"".join(out)


def _queries(queries) -> list[bytes]:
    """int n, then per motion query its function, stance, motion, current motion, whether that is given, speed."""
    out = [_I32.pack(len(queries))]
    for q in queries:
        out.append(_QUERY.pack(MOTION_QUERY_FUNCTIONS.index(q.function), q.stance, q.motion, q.current_motion or 0,
                               0 if q.current_motion is None else 1, 1.0 if q.speed is None else q.speed))
    return out


# pack 17, a tick scene's first byte 2 instead of 1, and after its steps: int n, then per motion query (scene/8 motion_queries) its function (byte: its index in
# acconform.scene.MOTION_QUERY_FUNCTIONS), stance, motion, current motion (uint; 0 when none), whether the current
# motion is given (byte), the speed (float; 1.0f, C#'s default, when the scene gives none)
_QUERY = struct.Struct("<BIIIBf")


def _frozen_maker(cls, params: str | None = None, values: dict | None = None, names: dict | None = None):
    """A constructor for a frozen, slotted dataclass that fills its slots directly: positional, one
    argument per field, or with `params` (its parameters) and `values` (a field -> the expression of
    them it is set to, which may use `names`; a field not named there is set to the parameter of its name).

    The generated ``__init__`` of a frozen dataclass goes through ``object.__setattr__`` by name for
    every field (about 3.6 us for Outcome's 17). The maker fills an object of a plain class with the
    same slots (a plain attribute store is the interpreter's fastest write) and then makes it a `cls`:
    Python lets ``__class__`` be assigned between classes of one layout (it checks; a class whose layout
    differs fails here, at import). The object is the constructor's (equal, same hash:
    tests/oracle/test_pack.py) in about a quarter of the time of setting each slot through its
    descriptor, which counts in a tick scene's outcome (a TickState per mover and tick)."""
    fields_ = [f.name for f in fields(cls)]
    shell = type(f"{cls.__name__}Shell", (), {"__slots__": tuple(fields_), "__module__": __name__})
    probe = object.__new__(shell)
    probe.__class__ = cls  # the layouts agree, or a TypeError now
    values = values or {}
    ns = {"_new": object.__new__, "_shell": shell, "_cls": cls, **(names or {})}
    body = "".join(f"    o.{n} = {values.get(n, n)}\n" for n in fields_)
    exec(f"def make({params if params is not None else ', '.join(fields_)}):\n    o = _new(_shell)\n{body}"
         f"    o.__class__ = _cls\n    return o\n", ns)
    return ns["make"]


_make_outcome = _frozen_maker(Outcome)
_make_plane = _frozen_maker(PlaneState)
_make_cps = _frozen_maker(ContactPlaneState)
_make_ns = _frozen_maker(NormalState)
_parts: dict = {}  # (valid, cell, water, nx, ny, nz, d) / (valid, x, y, z) -> the shared immutable record
_PARTS_LIMIT = 8192

# tag 1, then the outcome fields, ACE's FindValidPosition time and the whole case (doubles), then
# the facade's counters: landblocks built, landblocks reused (ints), building time, and the time of
# PhysicsObj.transition's own work, MakeTransition to CleanupTransition (doubles); then the statics'
# cells (`_static_cells`)
_OUT = struct.Struct("<BBI3f4fI" + "BIB3ff" * 2 + "B3f" * 2 + "Bi3fIBBBdd" + "iidd")
_TAIL = struct.Struct("<ddiidd")  # after an error message: FVP time, whole case, counters
_I32 = struct.Struct("<i")


def _static_cells(data, pos: int):
    """int count (-1: none read), then per static: int n and the n cell ids of its PhysicsObj.ShadowObjects.
    Returns (the cells or None, the offset after them)."""
    (n,) = _I32.unpack_from(data, pos)
    pos += 4
    if n < 0:
        return None, pos
    cells = []
    for _ in range(n):
        (k,) = _I32.unpack_from(data, pos)
        cells.append(struct.unpack_from(f"<{k}I", data, pos + 4))
        pos += 4 + 4 * k
    return tuple(cells), pos


_PLACED = struct.Struct("<iI3f4fIIi")
_make_placement = _frozen_maker(PlacementState)
# a tick scene's Outcome: the transition's fields at their defaults (Outcome's first 17, through `error`), then its own
_TRANSITION_DEFAULTS = tuple(getattr(Outcome(), f.name) for f in fields(Outcome))[:17]


def _placement_at(data, pos: int):
    """(`_placement`, the offset after it)."""
    if data[pos] in (0, b"\0"):
        return None, pos + 1
    v = _PLACED.unpack_from(data, pos + 1)
    at = pos + 1 + _PLACED.size
    shadows = struct.unpack_from(f"<{v[11]}I", data, at)
    return _make_placement(v[0], v[1], v[2:5], v[5:9], v[9], v[10], shadows), at + 4 * v[11]


# a MotionInterpreter (byte) and its InterpretedState's and RawState's commands, a CurrAnim's Anim (byte) and its ID,
# Sequence.FrameNumber, Velocity, Omega, a MoveToManager (byte) and its MovementType, IsMovingTo()
_MOTION_STATE = struct.Struct("<B" + "IIfIfIf" * 2 + "BIf3f3fBBB")
_make_command = _frozen_maker(CommandState)
_make_motion = _frozen_maker(MotionTickState)


def _motion(v) -> MotionTickState:
    """A tick's MotionTickState from its `_MOTION_STATE` values."""
    interpreted, raw = (_make_command(*v[1:8]), _make_command(*v[8:15])) if v[0] else (None, None)
    return _make_motion(interpreted, raw, v[16] if v[15] else None, v[17], v[18:21], v[21:24],
                        v[25] if v[24] else None, bool(v[26]))


_COLLISION = struct.Struct("<IdB")  # a CollisionTable record: the id, TouchedTime (double), Ethereal (byte)
_make_collision = _frozen_maker(CollisionState)

# A tick scene's states (pack 18: oracle/facade/Ticks.cs) come as fixed-size records, one per mover and tick, read in
# one iter_unpack: updated, UpdateTime, Position.ObjCellID, CurCell id, origin, the indices of the orientation,
# Velocity, Acceleration, Omega and CachedVelocity, State, TransientState, ContactPlaneCellID, the ContactPlane's
# index, SlidingNormal's index, JumpedThisFrame, the indices of its ShadowObjects cell list and of its CollisionTable,
# and its id (another mover's; 0 for the mover). The indices are into the scene's tables of the distinct ones (by
# bits), each made into its tuple or record once; every TickState shares them. So a TickState costs one record's
# unpack and its slots filled (about 0.6 us against 1.5 us for pack 17's unpack and call per state, stop 51).
_STATE_RECORD = struct.Struct("<?dII3f5iIIIii?iiI")
_TICK_BLOCK = struct.Struct("<Bi")  # byte 1: a scene with other movers; their count k (per tick)
_FLAGS = struct.Struct("<BBi")  # the mover's motion layers follow (1), the last tick threw (1), the records' count


def _state_maker(var: str, values: str) -> list[str]:
    """The lines that make the TickState `var` from its record `values` (`_STATE_RECORD`; S: the scene's cell lists,
    V, Q, P its vectors, orientations and planes), its CollisionTable, motion, others, id and error not set:
    `_tick_builder` sets them and makes it a TickState."""
    v = values
    exprs = {"updated": f"{v}[0]", "update_time": f"{v}[1]", "cell": f"{v}[2]", "cur_cell": f"{v}[3]",
             "origin": f"{v}[4:7]", "orientation": f"Q[{v}[7]]", "velocity": f"V[{v}[8]]",
             "acceleration": f"V[{v}[9]]", "omega": f"V[{v}[10]]", "cached_velocity": f"V[{v}[11]]",
             "state": f"{v}[12]", "transient_state": f"{v}[13]", "contact_plane_cell": f"{v}[14]",
             "contact_plane": f"P[{v}[15]]", "sliding_normal": f"V[{v}[16]]", "jumped_this_frame": f"{v}[17]"}
    lines = [f"{var} = _new(_shell)"] + [f"{var}.{name} = {e}" for name, e in exprs.items()]
    lines.append(f"{var}.shadow_cells = S[{v}[18]]")
    return lines


def _tick_builder():
    """build(records, S, T, motions, V, Q, P, k, n): the n ticks' TickStates from the state records (an
    iterator; S, T: the scene's cell lists and CollisionTables), written out straight (no call per TickState: the records' fields go into its slots as
    `_frozen_maker` does). k: the other movers a tick carries (None: a scene without them, whose mover has no
    CollisionTable and no others)."""
    names = [f.name for f in fields(TickState)]
    shell = type("TickStateShell", (), {"__slots__": tuple(names), "__module__": __name__})
    probe = object.__new__(shell)
    probe.__class__ = TickState  # the layouts agree, or a TypeError now
    mover = _state_maker("o", "v")
    other = _state_maker("p", "u") + ["p.collisions = T[u[19]]", "p.motion = None",
                                      "p.others = None", "p.id = u[20]", "p.error = None", "p.__class__ = _cls",
                                      "others.append(p)"]
    set_here = {"updated", "update_time", "cell", "cur_cell", "origin", "orientation", "velocity", "acceleration",
                "omega", "cached_velocity", "state", "transient_state", "contact_plane_cell", "contact_plane",
                "sliding_normal", "jumped_this_frame", "shadow_cells", "motion", "collisions", "others", "id", "error"}
    assert set_here == set(names), "every TickState field is set"
    body = "\n".join(["def build(records, S, T, motions, V, Q, P, k, n):",
                      "    out = []",
                      "    for i in range(n):",
                      "        v = next(records)"]
                     + ["        " + line for line in mover]
                     + ["        o.motion = None if motions is None else motions[i]",
                        "        if k is None:",
                        "            o.collisions = None",
                        "            o.others = None",
                        "        else:",
                        "            o.collisions = T[v[19]]",
                        "            others = []",
                        "            for _ in range(k):",
                        "                u = next(records)"]
                     + ["                " + line for line in other]
                     + ["            o.others = tuple(others)",
                        "        o.id = None",
                        "        o.error = None",
                        "        o.__class__ = _cls",
                        "        out.append(o)",
                        "    return out", ""])
    ns = {"_new": object.__new__, "_shell": shell, "_cls": TickState}
    exec(body, ns)
    return ns["build"]


_build_ticks = _tick_builder()


def _array(data, pos: int, record, count: int):
    """`count` records of the Struct `record` at `pos` in the byte view `data`: (their values' tuples, the end)."""
    end = pos + count * record.size
    return list(record.iter_unpack(data[pos:end])), end


def _lists(data, pos: int, kind: str):
    """int n, then n lists, each int m and m values of the struct format `kind`: (their tuples, the end)."""
    (n,) = _I32.unpack_from(data, pos)
    pos += 4
    out = []
    for _ in range(n):
        (m,) = _I32.unpack_from(data, pos)
        out.append(struct.unpack_from(f"<{m}{kind}", data, pos + 4))
        pos += 4 + 4 * m
    return out, pos


def _ticks_at(data, pos: int):
    return _ticks_and_end(data, pos)[0]


def _ticks_and_end(data, pos: int):
    """int n (-1: not a tick scene), then when n > 0 the tick block (oracle/facade/Ticks.cs, WriteTicks): byte 1 (a
    scene with other movers) or 0, int k (the other movers each tick carries), byte 1 (the mover's motion layers
    follow) or 0, byte 1 (the last tick threw: it ended the scene) or 0, int n and the n state records
    (`_STATE_RECORD`; per tick the mover's, then each other mover's), the scene's distinct ShadowObjects cell lists
    (`_lists`), its distinct CollisionTables (`_lists` of indices into the records after them), int n and the n
    distinct CollisionTable records (`_COLLISION`), a motion layer per tick that did not throw (`_MOTION_STATE`), int n
    and the n distinct vectors (x y z), int n and the n distinct orientations (w x y z), int n and the n distinct
    planes (normal, d), and when the last tick threw, int length and its message. Returns (the TickStates or None,
    the offset after them)."""
    (n,) = _I32.unpack_from(data, pos)
    pos += 4
    if n < 0:
        return None, pos
    if n == 0:
        return (), pos
    data = memoryview(data).cast("B")  # ints, whatever the buffer (a ctypes char array's items are bytes)
    with_others, k = _TICK_BLOCK.unpack_from(data, pos)
    pos += _TICK_BLOCK.size
    k = k if with_others else None
    with_motion, threw, count = _FLAGS.unpack_from(data, pos)
    pos += _FLAGS.size
    end = pos + count * _STATE_RECORD.size
    records = _STATE_RECORD.iter_unpack(data[pos:end])
    cells, pos = _lists(data, end, "I")
    tables, pos = _lists(data, pos, "i")
    (m,) = _I32.unpack_from(data, pos)
    distinct, pos = _array(data, pos + 4, _COLLISION, m)
    distinct = [_make_collision(i, t, e != 0) for i, t, e in distinct]
    tables = [tuple([distinct[i] for i in t]) for t in tables]
    ticks = n - threw
    motions = None
    if with_motion:
        motions, pos = _array(data, pos, _MOTION_STATE, ticks)
        motions = [_motion(v) for v in motions]
    (m,) = _I32.unpack_from(data, pos)
    vectors, pos = _array(data, pos + 4, _3f, m)
    (m,) = _I32.unpack_from(data, pos)
    orientations, pos = _array(data, pos + 4, _4f, m)
    (m,) = _I32.unpack_from(data, pos)
    planes, pos = _array(data, pos + 4, _4f, m)
    planes = [_make_plane((x, y, z), d) for x, y, z, d in planes]
    out = _build_ticks(records, cells, tables, motions, vectors, orientations, planes, k, ticks)
    if threw:
        (m,) = _I32.unpack_from(data, pos)
        out.append(TickState(error=bytes(data[pos + 4:pos + 4 + m]).decode("utf-8", "replace")))
        pos += 4 + m
    return tuple(out), pos


_ATTACK = struct.Struct("<fiI6f")


def _answers_at(data, pos: int):
    """int n (-1: no queries asked), then per motion query its answer (Facade.AskMotionQueries): byte 0 and a float,
    byte 1, int n and n attack frames (time, Direction, PartIndex, LeftX, LeftY, RightX, RightY, Radius, Height), or
    byte 0xEE, int length and the error message."""
    (n,) = _I32.unpack_from(data, pos)
    pos += 4
    if n < 0:
        return None
    out = []
    for _ in range(n):
        tag = data[pos]
        if type(tag) is bytes:  # a ctypes char array's item (the live oracle's output array)
            tag = tag[0]
        pos += 1
        if tag == 0:
            (v,) = _f.unpack_from(data, pos)
            pos += 4
            out.append(MotionAnswerState(value=v))
        elif tag == 1:
            (k,) = _I32.unpack_from(data, pos)
            pos += 4
            frames = []
            for _ in range(k):
                frames.append(AttackFrameState(*_ATTACK.unpack_from(data, pos)))
                pos += _ATTACK.size
            out.append(MotionAnswerState(attack_frames=tuple(frames)))
        else:
            (k,) = _I32.unpack_from(data, pos)
            out.append(MotionAnswerState(error=bytes(data[pos + 4:pos + 4 + k]).decode("utf-8", "replace")))
            pos += 4 + k
    return tuple(out)


def _other_placements_at(data, pos: int):
    """int -1 (none), or n and per other mover its placement (`_placement_at` without the leading byte)."""
    (n,) = _I32.unpack_from(data, pos)
    pos += 4
    if n < 0:
        return None, pos
    out = []
    for _ in range(n):
        v = _PLACED.unpack_from(data, pos)
        pos += _PLACED.size
        shadows = struct.unpack_from(f"<{v[11]}I", data, pos)
        pos += 4 * v[11]
        out.append(_make_placement(v[0], v[1], v[2:5], v[5:9], v[9], v[10], shadows))
    return tuple(out), pos


_NO_TRANSITION = struct.Struct("<B3fd")  # tag 2 (placed in no cell): the mover's velocity, FVP time 0
_AFTER = struct.Struct("<diidd")  # the whole case, then the counters
_TICK_SCENE = struct.Struct("<Bd")  # tag 3 (a tick scene: no single transition; 4: with motion answers): FVP time 0


_RAW = struct.Struct("<38x22s22s13s13s")  # the same four records' bytes: exact (bitwise) cache keys


def _cps(key, valid, cell, water, x, y, z, d):
    v = _parts.get(key)
    if v is None:
        if len(_parts) >= _PARTS_LIMIT:
            _parts.clear()
        v = _parts[key] = _make_cps(bool(valid), cell, bool(water), (x, y, z), d)
    return v


def _ns(key, valid, x, y, z):
    v = _parts.get(key)
    if v is None:
        if len(_parts) >= _PARTS_LIMIT:
            _parts.clear()
        v = _parts[key] = _make_ns(bool(valid), (x, y, z))
    return v


def unpack_outcome(data, offset: int = 0) -> tuple[Outcome, float, float, tuple[int, int, float, float]]:
    """(Outcome, ACE's in-runtime FindValidPosition time, the facade's whole-case time, (landblocks
    built, landblocks reused from the facade's cache, microseconds building them, PhysicsObj.transition's
    own time: MakeTransition to CleanupTransition)), times in
    microseconds, from the facade's bytes (`data` is any buffer; the outcome starts at `offset`)."""
    tag = data[offset]
    if tag == 0xEE or tag == b"\xee":
        (n,) = struct.unpack_from("<i", data, offset + 1)
        msg = bytes(data[offset + 5:offset + 5 + n]).decode("utf-8", "replace")
        us, case_us, built, reused, build_us, trans_us = _TAIL.unpack_from(data, offset + 5 + n)
        return Outcome(error=msg), us, case_us, (built, reused, build_us, trans_us)
    if tag in (3, 4, b"\x03", b"\x04"):  # 4: the motion queries' answers after the ticks
        _tag, us = _TICK_SCENE.unpack_from(data, offset)
        at = offset + _TICK_SCENE.size
        case_us, built, reused, build_us, trans_us = _AFTER.unpack_from(data, at)
        cells, at = _static_cells(data, at + _AFTER.size)
        placement, at = _placement_at(data, at)
        others, at = _other_placements_at(data, at)
        ticks, at = _ticks_and_end(data, at)
        answers = _answers_at(data, at) if tag in (4, b"\x04") else None
        return (_make_outcome(*_TRANSITION_DEFAULTS, cells, placement, ticks, others, answers),
                us, case_us, (built, reused, build_us, trans_us))
    if tag == 2 or tag == b"\x02":
        _tag, vx, vy, vz, us = _NO_TRANSITION.unpack_from(data, offset)
        at = offset + _NO_TRANSITION.size
        case_us, built, reused, build_us, trans_us = _AFTER.unpack_from(data, at)
        cells, at = _static_cells(data, at + _AFTER.size)
        placement, at = _placement_at(data, at)
        others, _ = _other_placements_at(data, at)
        return (Outcome(velocity=(vx, vy, vz), static_cells=cells, placement=placement, other_placements=others),
                us, case_us, (built, reused, build_us, trans_us))
    v = _OUT.unpack_from(data, offset)
    if v[0] != 1:
        raise ValueError(f"unknown outcome tag {v[0]}")
    kc, kl, kn, ks = _RAW.unpack_from(data, offset)  # keyed by bits: 0.0 and -0.0 stay apart
    cp = _cps(kc, *v[11:18])
    lk = cp if kl == kc else _cps(kl, *v[18:25])
    cells, at = _static_cells(data, offset + _OUT.size)
    placement, at = _placement_at(data, at)
    others, _ = _other_placements_at(data, at)
    return (_make_outcome(bool(v[1]), v[2], v[3:6], v[6:10], v[10], cp, lk, _ns(kn, *v[25:29]), _ns(ks, *v[29:33]),
                          bool(v[33]), v[34], v[35:38], v[38], bool(v[39]), bool(v[40]), bool(v[41]), None,
                          cells, placement, None, others, None),
            v[42], v[43], (v[44], v[45], v[46], v[47]))
