"""Traces: what a run looked like inside, record by record, and where two traces first part.

Format ``acconform.trace/1``. A trace is the list of `TraceRecord`s one run wrote, in the order it
wrote them. A record names its place (`anchor`: ACE's ``File.cs:Method``; `event`: ``enter`` or
``exit`` of an anchored routine, ``call`` for the exit of a routine that keeps no transition
state, ``step`` for a pass of FindTransitionalPosition's loop, ``insert`` for a TransitionalInsert
attempt, ``tick`` after a tick scene's step), the tick and step it ran in (or the static object being
placed, `placing`, while the world is built), the routine's `result`
at its exit, and a snapshot: `path` (the transition: SpherePath and CollisionInfo) or `mover` (the
mover's PhysicsObj, a TickState). A field left None was not recorded; a comparison skips it.

The port writes traces (acconform.port.tracing); an implementation answers a request with
``"trace": true`` with one (docs/protocol.md). `first_divergence(reference, other)` is the first
record where the two part, at the grain of `other`: only the (anchor, event) kinds `other`
writes are compared, so an implementation that records only steps or ticks still gets the first
step or tick that differs.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, fields, replace
from typing import Any

import numpy as np

from .codec import Reader, write_f32, write_id, write_vec
from .errors import InvalidScene
from .outcome import ContactPlaneState, NormalState, PlaneState, TickState, _vec_nf

FORMAT = "acconform.trace/1"
EVENTS = ("enter", "exit", "call", "step", "insert", "tick")
Vec3 = tuple[float, float, float]
PARTS = ("args", "result", "path", "mover")  # a record's compared parts, in comparison order
OPTIONAL_PATH_FLAGS = frozenset({"placement_allows_sliding", "building_check", "hits_interior_cell"})


@dataclass(frozen=True, slots=True)
class PathState:
    """The transition between two of its routines: SpherePath's positions, cells and flags, and
    CollisionInfo's planes and normals."""

    check_cell: int
    check_pos: Vec3  # SpherePath.CheckPos.Frame.Origin
    cur_cell: int
    cur_pos: Vec3  # SpherePath.CurPos.Frame.Origin
    global_offset: Vec3
    contact_plane: ContactPlaneState
    last_known_contact_plane: ContactPlaneState
    collision_normal: NormalState
    sliding_normal: NormalState
    walkable: PlaneState | None  # the walkable polygon's plane, None when there is none
    step_up: bool
    step_down: bool
    collide: bool
    neg_poly_hit: bool
    frames_stationary_fall: int
    object_info_state: int
    # SpherePath's flags that only a placement or a building sets; optional (None: not recorded), so a trace written
    # before they were added still reads, and a side that leaves them out is not compared on them
    placement_allows_sliding: bool | None = None
    building_check: bool | None = None
    hits_interior_cell: bool | None = None

    def to_json(self):
        d = {}
        for f in fields(self):
            v = getattr(self, f.name)
            if v is None and f.name in OPTIONAL_PATH_FLAGS:
                continue
            if f.name in ("check_cell", "cur_cell"):
                v = write_id(v)
            elif f.name in ("check_pos", "cur_pos", "global_offset"):
                v = write_vec(v)
            elif hasattr(v, "to_json"):
                v = v.to_json()
            d[f.name] = v
        return d

    @staticmethod
    def from_json(r: Reader) -> "PathState":
        names = [f.name for f in fields(PathState)]
        r.obj(set(names))
        kw = {}
        for name in names:
            if name in OPTIONAL_PATH_FLAGS:
                if r.given(name):
                    kw[name] = r[name].bool_()
                continue
            x = r[name]
            if name in ("check_cell", "cur_cell"):
                kw[name] = x.id_()
            elif name in ("check_pos", "cur_pos", "global_offset"):
                kw[name] = _vec_nf(x)
            elif name in ("contact_plane", "last_known_contact_plane"):
                kw[name] = ContactPlaneState.from_json(x)
            elif name in ("collision_normal", "sliding_normal"):
                kw[name] = NormalState.from_json(x)
            elif name == "walkable":
                kw[name] = None if x.value is None else PlaneState.from_json(x)
            elif name in ("frames_stationary_fall", "object_info_state"):
                kw[name] = x.int_()
            else:
                kw[name] = x.bool_()
        return PathState(**kw)


@dataclass(frozen=True, slots=True)
class TraceRecord:
    anchor: str  # ACE's File.cs:Method
    event: str  # one of EVENTS
    tick: int | None = None  # the tick scene's step index, None outside ticks
    step: int | None = None  # the FindTransitionalPosition step, None outside its loop
    within: str | None = None  # the anchor of the routine running when the record was written (the caller
    # at an enter, exit or call; FindTransitionalPosition at a step): whose body a divergence here is in
    args: Any = None  # at an enter or call: the routine's arguments as plain JSON (a list)
    result: Any = None  # at an exit or call: the routine's answer as plain JSON (a float32 as a number)
    path: PathState | None = None
    mover: TickState | None = None
    placing: int | None = None  # while a static object is placed (PhysicsObj.add_obj_to_cell on a static, as the
    # world is built or an EnvCell loads): that object's ID (0 for an EnvCell's stab, as ACE makes it); else None

    def to_json(self):
        d: dict = {"anchor": self.anchor, "event": self.event}
        for name in ("tick", "step", "placing", "within", "args", "result"):
            v = getattr(self, name)
            if v is not None:
                d[name] = v
        if self.path is not None:
            d["path"] = self.path.to_json()
        if self.mover is not None:
            d["mover"] = self.mover.to_json()
        return d

    @staticmethod
    def from_json(r: Reader) -> "TraceRecord":
        r.obj({"anchor", "event", "tick", "step", "placing", "within", "args", "result", "path", "mover"})
        event = r["event"].str_()
        if event not in EVENTS:
            r["event"].fail(f"unknown event {event!r} (known: {', '.join(EVENTS)})")
        return TraceRecord(
            r["anchor"].str_(), event,
            r["tick"].int_() if r.given("tick") else None,
            r["step"].int_() if r.given("step") else None,
            r["within"].str_() if r.given("within") else None,
            r["args"].value if r.given("args") else None,
            r["result"].value if r.given("result") else None,
            PathState.from_json(r["path"]) if r.given("path") else None,
            TickState.from_json(r["mover"]) if r.given("mover") else None,
            r["placing"].int_() if r.given("placing") else None)


def trace_to_json(records, anchors=None) -> dict:
    """A trace document; `anchors`: the routines (ACE methods) the implementation records at enter,
    exit or call, whether or not this run reached them (absent: those its records name)."""
    doc = {"format": FORMAT, "records": [r.to_json() for r in records]}
    if anchors is not None:
        doc["anchors"] = sorted(anchors)
    return doc


def trace_anchors(doc) -> frozenset | None:
    """The `anchors` a trace document declares (already read by trace_from_json), or None."""
    return frozenset(doc["anchors"]) if isinstance(doc, dict) and "anchors" in doc else None


def trace_from_json(doc, path: str = "trace", exact: bool = False) -> tuple[TraceRecord, ...]:
    r = Reader(doc, path, exact=exact)
    r.obj({"format", "records", "anchors"})
    if r["format"].str_() != FORMAT:
        r["format"].fail(f"expected {FORMAT!r}")
    if r.given("anchors"):
        for a in r["anchors"].list():
            a.str_()
    return tuple(TraceRecord.from_json(x) for x in r["records"].list())


# ---------------------------------------------------------------- comparing two traces


def _bits(x: float) -> int:
    return int(np.float32(x).view(np.uint32))


def ulps(a: float, b: float) -> int:
    """How many float32 values lie between a and b (0 when bit-equal; +0 and -0 are 0 apart)."""
    from .compare import ulp_distance

    return ulp_distance(a, b)


def _flat(value, prefix: str, out: list) -> None:
    """`value` as (field path, leaf) pairs: records by field, sequences by index."""
    if value is None:
        out.append((prefix, None))
    elif hasattr(value, "__dataclass_fields__"):
        for f in fields(value):
            _flat(getattr(value, f.name), f"{prefix}.{f.name}" if prefix else f.name, out)
    elif isinstance(value, (list, tuple)):
        if not value:
            out.append((prefix, ()))
        for i, x in enumerate(value):
            _flat(x, f"{prefix}[{i}]", out)
    else:
        out.append((prefix, value))


def record_fields(record: TraceRecord) -> list[tuple[str, Any]]:
    out: list = []
    for name in PARTS:
        v = getattr(record, name)
        if v is not None:
            _flat(v, name, out)
    return out


# a record's fields that are C# doubles (ACE's clock), compared bit for bit as doubles, as outcomes compare them
# (acconform/compare.py's _DOUBLE_FIELDS): as float32 a PhysicsTimer past 2^24 s hides whole quanta
DOUBLE_LEAVES = frozenset({"update_time", "touched_time"})


def _same_double(a, b) -> bool:
    import struct

    if not isinstance(a, (int, float)) or not isinstance(b, (int, float)) or isinstance(a, bool) or isinstance(b, bool):
        return a == b
    return struct.pack("<d", float(a)) == struct.pack("<d", float(b))


def _same(a, b) -> bool:
    if isinstance(a, bool) or isinstance(b, bool):
        return a is b or (isinstance(a, bool) and isinstance(b, bool) and a == b)
    if isinstance(a, float) or isinstance(b, float):
        if not isinstance(a, (int, float)) or not isinstance(b, (int, float)):
            return False
        if math.isnan(a) and math.isnan(b):
            return _bits(a) == _bits(b)
        return _bits(a) == _bits(b) if abs(a) < 3.5e38 and abs(b) < 3.5e38 else a == b
    return a == b


@dataclass(frozen=True, slots=True)
class Divergence:
    """Where two traces first part: the record index in each (after filtering to the shared grain),
    the record on each side (None past a trace's end), the field and both values, and `routine`:
    the anchor whose body the two part in -- the record's own routine when its result or the state
    it left differs; else the routine that was running (the reference record's `within`): the
    caller that handed different arguments, wrote different records, or changed the state before
    an enter or a step."""

    index: int
    a: TraceRecord | None
    b: TraceRecord | None
    field: str
    a_value: Any
    b_value: Any
    routine: str
    a_position: int  # the record's index in a's whole trace (for showing the records before it)
    b_position: int

    @property
    def ulps(self) -> int | None:
        x, y = self.a_value, self.b_value
        if isinstance(x, float) and isinstance(y, (int, float)) and not isinstance(y, bool):
            return ulps(x, float(y))
        return None

    @property
    def tick(self):
        return (self.a or self.b).tick

    @property
    def step(self):
        return (self.a or self.b).step

    @property
    def placing(self):
        """The static object being placed where the two part (its ID), or None outside a placement."""
        return (self.a or self.b).placing

    def key(self) -> str:
        """The group a difference falls in: routine and field, indices dropped (``path.cur_pos``)."""
        return f"{self.routine} {_INDEX.sub('', self.field)}"


_INDEX = re.compile(r"\[\d+\]")


def _grain(records) -> tuple[set, set]:
    kinds = {(r.anchor, r.event) for r in records}
    present = set()
    for r in records:
        for name in PARTS:
            if getattr(r, name) is not None:
                present.add((r.anchor, r.event, name))
    return kinds, present


def first_divergence(reference, other, anchors=None, reference_kinds=None, shapes: str = "strict") -> Divergence | None:
    """The first record where `other` parts from `reference`, compared at `other`'s grain: the
    (anchor, event) kinds it writes, and the enter, exit and call records of the routines it declares
    it records (`anchors`, its trace's "anchors": a routine it never reached is then a difference
    too), and the parts it fills; None when they agree throughout. `reference_kinds`: every kind the
    reference can write (the port's tracing.record_kinds()), not only those it wrote this run: a
    routine only `other` ran is then a difference too, where it was first entered, not later.
    `shapes`: "strict" compares every field of `other`'s parts; "ace" (against ACE's own trace, whose
    arguments and answers are C#'s: `this` in a constructor, ref and out parameters, a Dictionary)
    compares an argument or answer only where both sides hold one of the same shape (`comparable`)."""
    kinds, present = _grain(other)
    declared = anchors or frozenset()
    for r in reference:
        if r.anchor in declared and r.event in ("enter", "exit", "call"):
            present.update((r.anchor, r.event, name) for name in PARTS)
    ref = [(i, r) for i, r in enumerate(reference)
           if (r.anchor, r.event) in kinds or (r.anchor in declared and r.event in ("enter", "exit", "call"))]
    ref_kinds = {(r.anchor, r.event) for _, r in ref}
    if reference_kinds is not None:
        ref_kinds |= kinds & reference_kinds
    oth = [(i, r) for i, r in enumerate(other) if (r.anchor, r.event) in ref_kinds]  # the coarser grain of the two
    for n in range(max(len(ref), len(oth))):
        ia, a = ref[n] if n < len(ref) else (len(reference), None)
        ib, b = oth[n] if n < len(oth) else (len(other), None)
        inner = (a or b).within or (a or b).anchor
        if a is None or b is None or (a.anchor, a.event) != (b.anchor, b.event):
            if a is not None and b is not None:
                inner = _parted_in(reference, ia, other, ib, shapes) or inner
            return Divergence(n, a, b, "anchor", a and f"{a.anchor} {a.event}", b and f"{b.anchor} {b.event}",
                              inner, ia, ib)
        if a.tick != b.tick or a.step != b.step:
            field = "tick" if a.tick != b.tick else "step"
            return Divergence(n, a, b, field, getattr(a, field), getattr(b, field), inner, ia, ib)
        fa = dict(x for name in PARTS if (a.anchor, a.event, name) in present for x in _flat_part(a, name))
        fb = dict(x for name in PARTS for x in _flat_part(b, name))
        if shapes == "ace" and len(a.args or ()) != len(b.args or ()):  # C#'s parameters and the port's differ here
            fa = {k: v for k, v in fa.items() if not k.startswith("args")}
        for name, va in fa.items():
            vb = fb.get(name)
            if shapes == "ace" and not name.startswith(("path", "mover")) and not comparable(name in fb, va, vb):
                continue
            if (va is None or vb is None) and name.startswith("path.") and name[5:] in OPTIONAL_PATH_FLAGS:
                continue  # a side that does not record SpherePath's optional flags is not compared on them
            same = _same_double if name.rsplit(".", 1)[-1] in DOUBLE_LEAVES else _same
            if name not in fb or not same(va, vb):
                routine = a.anchor if a.event in ("exit", "call") and not name.startswith("args") else inner
                if name.startswith("args"):
                    routine = _caller_handed_them(ref, oth, n, routine, shapes)
                return Divergence(n, a, b, name, va, vb, routine, ia, ib)
    return None


def comparable(present: bool, a, b) -> bool:
    """Whether an argument or answer of ACE's (a) and of a port-grain trace (b) can be compared: both
    recorded, neither left empty, neither an object named by its type (a C# class's name is not a
    Python class's), and both numbers, both flags or both lists of the same length."""
    if not present or a is None or b is None or isinstance(a, str) or isinstance(b, str):
        return False
    if isinstance(a, bool) or isinstance(b, bool):
        return isinstance(a, bool) and isinstance(b, bool)
    return isinstance(a, (int, float)) and isinstance(b, (int, float))


# ---------------------------------------------------------------- the run, at the grain both ACE and the port write

# where a run starts after its world is built: the transition's (or the placement's) first calls, or a tick.
# Each side builds the scene's world in the harness's own order (the facade's BuildScene, the port's scene_world),
# so a comparison with ACE's own trace starts at the run.
RUN_STARTS = frozenset({"Transition.cs:MakeTransition", "Transition.cs:InitObject", "PhysicsObj.cs:get_object_info"})
RUN_ENDS = "Transition.cs:CleanupTransition"  # a transition scene's run ends with it (the placement's too)
TRANSITION = "PhysicsObj.cs:transition"
TICK_DRIVER = "PhysicsObj.cs:update_object"


def run_start(records) -> int:
    """The index of a trace's first record of the run (the first of RUN_STARTS, or the first tick): what comes
    before it is the world's building (its statics' placement among it), len(records) when the run never started."""
    return next((i for i, r in enumerate(records) if r.tick is not None or r.anchor in RUN_STARTS), len(records))


def run_part(records, ticks: bool) -> tuple:
    """The records of a trace that a comparison with ACE's own reads: the placement of the static objects
    (the records labelled `placing`, written while the world is built) and the run, from its start
    (RUN_STARTS, or the first tick), at the grain ACE's instrumented facade writes: in a transition scene, no
    PhysicsObj.transition records (the facade makes its calls one by one, as the port's run_scene does around
    the mover's transition); in a tick scene, no record of the port's tick driver (run_ticks, anchored to
    update_object, a call outside any routine). What either driver calls is called from outside any routine, as
    ACE's facade calls it (`within` None): at a tick, set_request_pos and update_object_server in server mode,
    update_object in client mode."""
    start = run_start(records)
    # what follows the last tick, or the transition's cleanup, is the harness's (the facade removes the statics)
    last = (lambda r: r.event == "tick") if ticks else (lambda r: r.anchor == RUN_ENDS)
    end = max((i + 1 for i, r in enumerate(records) if last(r)), default=len(records))
    out = []
    building = 0  # inside a constructor's enter .. exit
    updating = 0  # inside the mover's own update_object (a tick scene's client path), not the port's tick driver
    placing = [r for r in records[:start] if r.placing is not None]  # the world's statics placed, in order
    for r in placing + list(records[start:end]):
        updating -= ticks and r.anchor == TICK_DRIVER and r.event == "exit"
        by_driver = ticks and r.within == TICK_DRIVER and updating == 0  # the driver's own call, not the mover's routine's
        updating += ticks and r.anchor == TICK_DRIVER and r.event == "enter"
        if is_constructor(r.anchor) and r.event in ("enter", "exit"):
            building += 1 if r.event == "enter" else -1
            continue
        if building > 0 or (r.within is not None and is_constructor(r.within)):
            continue
        if not ticks and r.anchor == TRANSITION:
            continue
        if ticks and r.anchor == TICK_DRIVER and r.event == "call" and r.within is None:
            continue
        if is_constructor(r.anchor):
            continue
        if not ticks and r.mover is not None:  # outside a tick scene the mover's clock is the harness's (wall clock in ACE)
            r = replace(r, mover=replace(r.mover, update_time=0.0))
        # called by the port's driver, where ACE's facade calls it: run_scene (anchored PhysicsObj.transition) around a
        # transition scene and the statics' placement, run_ticks (anchored update_object) at each tick, whose
        # update_object_server (server mode) or update_object (client mode) ACE's facade calls itself
        if (r.within == TRANSITION and (not ticks or r.tick is None)) or by_driver:
            r = replace(r, within=None)
        out.append(r)
    return tuple(out)


STATE_EVENTS = ("enter", "exit", "step", "insert", "tick")


PLACEMENT_FILES = frozenset({"PhysicsObj.cs", "PartArray.cs", "CellArray.cs", "BBox.cs", "CellStruct.cs"})


def compared(r: TraceRecord) -> bool:
    """Whether against_ace compares a record of the run part: one that carries state (STATE_EVENTS), or, while a
    static is placed, the answer of a routine of the placement's own chain (PLACEMENT_FILES: add_obj_to_cell ..
    calc_cross_cells_static, the boxes carried between frames, the cells added): a placement carries no
    transition, its state is the cells and boxes those routines hand on."""
    return r.event in STATE_EVENTS or (r.placing is not None and r.anchor.split(":", 1)[0] in PLACEMENT_FILES)


def against_ace(ace, other, ace_kinds, ticks: bool, overloaded=frozenset()) -> Divergence | None:
    """The first record where `other` (the port's trace, or an implementation's at the port's grain)
    parts from ACE's own trace (oracle/instrumented.py), compared from the statics' placement and the run's
    start (`run_part`) on the records that carry state: the enter and exit records of the transition's routines
    (a PathState) and of the mover's (a TickState), each step, insert attempt and tick, and, while a static is
    placed, the calls of the placement's own chain (`compared`). Any other `call` record (a helper's answer, a
    getter) is not compared: ACE calls its helpers where its C# does (a property read twice, a check
    inlined), the port where its Python does, and their order differs without any state differing.
    Arguments and answers are compared where their shapes agree (first_divergence's shapes="ace").
    `overloaded`: the anchors that name several ACE overloads (one port routine for them all): ACE's
    record of one such overload inside another (AddOffsetToCheckPos(offset, radius) calling
    AddOffsetToCheckPos(offset)) is left out on both sides: the port writes one record for the pair, or two
    where it has a routine for each (CylSphere.IntersectsSphere's)."""
    def kept(records):
        return tuple(r for r in run_part(records, ticks) if compared(r)
                     and not (r.anchor in overloaded and r.within == r.anchor))

    a, b = kept(ace), kept(other)
    kinds = frozenset(k for k in ace_kinds if not is_constructor(k[0]))
    return first_divergence(a, b, None, kinds, shapes="ace")


def is_constructor(anchor: str) -> bool:
    """Whether an anchor names a constructor ("AFrame.cs:AFrame(AFrame)", "PlacementType.cs:PlacementType"):
    the port makes many objects inline or lazily where ACE news them (a landblock's cells, when first
    reached), so constructors and what they run are not compared with ACE's."""
    file, _, method = anchor.partition(":")
    return method.split("(", 1)[0] == file.rsplit("/", 1)[-1].removesuffix(".cs")


def _running(records, i: int) -> list[tuple[str, object]]:
    """The routines running at record i, outermost first, ending with the record's own, each with the
    arguments it was called with: each caller is the `within` of the record that ends the routine it
    called (its exit, or its call record, written at its exit); enter and exit records of a routine
    are paired, so recursion climbs right."""
    r = records[i]
    chain = [(r.anchor, r.args if r.event != "exit" else _entered_with(records, i))]
    routine, start = r.within, (i if r.event == "enter" else i + 1)
    while routine is not None:
        depth, end = 0, None
        for k in range(start, len(records)):
            x = records[k]
            if x.anchor != routine:
                continue
            if x.event == "enter":
                depth += 1
            elif x.event in ("exit", "call"):
                if depth == 0:
                    end = k
                    break
                if x.event == "exit":
                    depth -= 1
        if end is None:
            chain.append((routine, None))
            break
        x = records[end]
        chain.append((routine, x.args if x.event == "call" else _entered_with(records, end)))
        routine, start = x.within, end + 1
    return chain[::-1]


def _entered_with(records, exit_at: int):
    """The arguments of the enter record an exit record closes."""
    anchor, depth = records[exit_at].anchor, 0
    for k in range(exit_at - 1, -1, -1):
        x = records[k]
        if x.anchor == anchor:
            if x.event == "exit":
                depth += 1
            elif x.event == "enter":
                if depth == 0:
                    return x.args
                depth -= 1
    return None


def _parted_in(reference, ia: int, other, ib: int, shapes: str = "strict") -> str | None:
    """Where two traces that write different records at ia and ib part: the innermost routine both
    were still running (from both sides' `within`) that both sides called with the same arguments,
    whose body then went on differently (a routine handed different arguments went differently
    because its caller did); None when the other side records no `within` to tell."""
    if other[ib].within is None and reference[ia].within is not None:
        return None
    common = []
    for (x, xargs), (y, yargs) in zip(_running(reference, ia), _running(other, ib)):
        if x != y:
            break
        common.append((x, xargs is None or yargs is None or _same_args(xargs, yargs, shapes)))
    while len(common) > 1 and not common[-1][1]:
        common.pop()
    return common[-1][0] if common else None


def _caller_handed_them(ref, oth, n: int, routine: str, shapes: str = "strict") -> str:
    """Different arguments at record n were handed by `routine`; a `call` record is written at its
    routine's exit, after its callees' records, so when `routine`'s own call record (the next one of
    it) shows different arguments too, the values came from further up: climb to its caller."""
    while True:
        m = next((k for k in range(n + 1, len(ref)) if ref[k][1].anchor == routine and ref[k][1].event == "call"), None)
        if m is None or m >= len(oth):
            return routine
        a, b = ref[m][1], oth[m][1]
        if (b.anchor, b.event) != (a.anchor, a.event) or a.within is None or _same_args(a.args, b.args, shapes):
            return routine
        n, routine = m, a.within


def _same_args(x, y, shapes: str = "strict") -> bool:
    """Whether two calls were handed the same arguments; with shapes "ace" (C#'s against the port's), at the
    arguments first_divergence compares: where both pass as many, each both hold as a number or a flag."""
    fx, fy = [], []
    _flat(x, "args", fx)
    _flat(y, "args", fy)
    if shapes == "ace":
        if len(x or ()) != len(y or ()):
            return True
        dy = dict(fy)
        return all(_same(u, dy[p]) for p, u in fx if p in dy and comparable(True, u, dy[p]))
    return len(fx) == len(fy) and all(p == q and _same(u, v) for (p, u), (q, v) in zip(fx, fy))


def _flat_part(r: TraceRecord, name: str):
    out: list = []
    v = getattr(r, name)
    if v is not None:
        _flat(v, name, out)
    return out
