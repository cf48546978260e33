"""Tracing a port run: a snapshot at each anchored routine's entry and exit (acconform.trace records).

Off (the default), nothing here runs: the port's routines are the plain functions, and the few
per-step points (each pass of FindTransitionalPosition's loop, each TransitionalInsert attempt,
each tick of run_ticks) test ``trace is not None and trace.recorder is not None`` once.

On (`run.traced_run`: run_scene given a branches.Trace carrying a `Recorder`), `installed` puts a wrapper around
every routine of the anchor registry (anchors.FUNCTIONS) for the length of that run only: in the
class that holds it (a method) and in every port module whose globals call it by name; it puts the
originals back afterwards. What a wrapper writes depends on the routine's ACE file:

- a transition routine (`PATH_FILES`, and `PATH_ROUTINES` outside them): ``enter`` and ``exit`` records with a `PathState` of the
  run's current Transition (the last one a routine was handed) and, at the exit, the result;
- a PhysicsObj routine on the mover, or a server routine of `MOVER_ROUTINES` (Player.HandleActionJump): ``enter``
  and ``exit`` with the mover as a TickState;
- any other routine: one ``call`` record at its exit, with its result only.

Records carry the tick (run_ticks' step index) and the FindTransitionalPosition step they ran in, and,
while a static object is placed (PhysicsObj.add_obj_to_cell on an object other than the mover: the
world's statics as the run builds it, an EnvCell's stabs as the cell loads), that object's ID
(`placing`): the statics' placement is part of the traced run, as ACE's instrumented facade records it.
A traced run starts cold (the memories of GfxObjs and landblocks across runs emptied first), and a
routine that remembers answers ACE computes every time (anchors.remembers) runs its twin computing
every time, so its trace is a function of the scene alone: it does not depend on what the process
ran before.
"""

from __future__ import annotations

import sys
from collections import Counter
import threading
from contextlib import contextmanager
from enum import IntEnum

import numpy as np

from acconform.codec import write_f32
from acconform.outcome import ContactPlaneState, NormalState, PlaneState
from acconform.staging import MOVER_ID
from acconform.trace import PathState, TraceRecord

from .anchors import FUNCTIONS, REGISTRY, REMEMBERING, harness, load_all

# routines whose entry and exit snapshot the transition (the rest of the registry writes a `call`)
PATH_FILES = frozenset({"Transition.cs", "SpherePath.cs", "ObjectInfo.cs", "BSPTree.cs", "BSPNode.cs", "BSPLeaf.cs",
                        "Sphere.cs", "CylSphere.cs", "ObjCell.cs", "LandCell.cs", "EnvCell.cs", "SortCell.cs"})
# routines outside those files that are handed the transition and hand it on: a building's or a part's collision test
# (what a building sets in the path, BuildingCheck, is seen at the part's entry, in find_building_collisions' body)
PATH_ROUTINES = frozenset({"BuildingObj.cs:find_building_collisions", "PartArray.cs:FindObjCollisions",
                           "PhysicsPart.cs:FindObjCollisions"})
MOVER_FILE = "PhysicsObj.cs"
# routines of the server's WorldObjects whose first argument is the mover, traced as PhysicsObj's are (the mover's
# state at entry and exit): what they change of the mover (a jump's UpdateTime) is named there, not a tick later
MOVER_ROUTINES = frozenset({"ACE.Server/WorldObjects/Player.cs:HandleActionJump"})
FTP = "Transition.cs:FindTransitionalPosition"
TI = "Transition.cs:TransitionalInsert"
TICK = "PhysicsObj.cs:update_object"
PLACE = "PhysicsObj.cs:add_obj_to_cell"  # a static object's placement: the records it writes are labelled `placing`
_ZERO = (0.0, 0.0, 0.0)
_lock = threading.Lock()  # one traced run at a time in a process: the wrappers are the classes' own


@harness("whether a traced routine's records snapshot the transition (a transition file's routine, or PATH_ROUTINES)")
def writes_path(ace: str) -> bool:
    """Whether a routine's records snapshot the transition (enter and exit with a PathState)."""
    return ace.split(":", 1)[0] in PATH_FILES or ace in PATH_ROUTINES


def _vec(v) -> tuple[float, float, float]:
    return _ZERO if v is None else (float(v.x), float(v.y), float(v.z))


def _contact(valid, cell, water, plane) -> ContactPlaneState:
    if plane is None:
        return ContactPlaneState(bool(valid), int(cell), bool(water))
    return ContactPlaneState(bool(valid), int(cell), bool(water), _vec(plane.normal), float(plane.d))


def _id(cell) -> int:
    return int(cell.id) if cell is not None else 0


@harness("a transition as a trace's PathState: SpherePath's positions, cells and flags, CollisionInfo's planes and normals")
def path_state(t) -> PathState | None:
    sp, ci, oi = getattr(t, "sphere_path", None), getattr(t, "collision_info", None), getattr(t, "object_info", None)
    if sp is None or ci is None:
        return None
    walkable = sp.walkable.plane if sp.walkable is not None else None
    return PathState(
        _id(sp.check_cell), _vec(sp.check_pos.frame.origin) if sp.check_pos is not None else _ZERO,
        _id(sp.cur_cell), _vec(sp.cur_pos.frame.origin) if sp.cur_pos is not None else _ZERO,
        _vec(sp.global_offset),
        _contact(ci.contact_plane_valid, ci.contact_plane_cell_id, ci.contact_plane_is_water, ci.contact_plane),
        _contact(ci.last_known_contact_plane_valid, ci.last_known_contact_plane_cell_id,
                 ci.last_known_contact_plane_is_water, ci.last_known_contact_plane),
        NormalState(bool(ci.collision_normal_valid), _vec(ci.collision_normal)),
        NormalState(bool(ci.sliding_normal_valid), _vec(ci.sliding_normal)),
        PlaneState(_vec(walkable.normal), float(walkable.d)) if walkable is not None else None,
        bool(sp.step_up), bool(sp.step_down), bool(sp.collide), bool(sp.neg_poly_hit),
        int(ci.frames_stationary_fall), int(oi.state) if oi is not None else 0,
        bool(sp.placement_allows_sliding), bool(sp.building_check), bool(sp.hits_interior_cell))


def _num(x):
    if isinstance(x, np.floating):
        return write_f32(x) if x.dtype == np.float32 else float(x)
    return float(x) if isinstance(x, float) else x


def _vec_list(v) -> list:
    return [_num(v.x), _num(v.y), _num(v.z)]


@harness("a routine's answer as plain JSON for a trace record: numbers, vectors as lists, objects by id or type")
def plain(v, depth: int = 0):
    if v is None or isinstance(v, (bool, str)):
        return v
    if isinstance(v, np.bool_):
        return bool(v)
    if isinstance(v, IntEnum):
        return int(v)
    if isinstance(v, (int, np.integer)):
        return int(v)
    if isinstance(v, (float, np.floating)):
        return _num(v)
    if hasattr(v, "w") and hasattr(v, "x"):  # a Quaternion: [w, x, y, z]
        return [_num(v.w)] + _vec_list(v)
    if hasattr(v, "x") and hasattr(v, "y") and hasattr(v, "z"):  # a Vector3
        return _vec_list(v)
    if hasattr(v, "center") and hasattr(v, "radius") and hasattr(v.center, "x"):  # a Sphere
        return _vec_list(v.center) + [_num(v.radius)]
    if hasattr(v, "normal") and hasattr(v, "d") and hasattr(v.normal, "x"):  # a Plane
        return _vec_list(v.normal) + [_num(v.d)]
    if hasattr(v, "origin") and hasattr(v, "orientation") and hasattr(v.origin, "x"):  # an AFrame: origin, [w, x, y, z]
        q = v.orientation
        return _vec_list(v.origin) + [_num(q.w), _num(q.x), _num(q.y), _num(q.z)]
    if hasattr(v, "min") and hasattr(v, "max") and hasattr(v.min, "x"):  # a BBox: its corners, min then max
        return _vec_list(v.min) + _vec_list(v.max)
    if hasattr(v, "obj_cell_id") and hasattr(v, "frame"):  # a Position: [cell, origin]
        return [int(v.obj_cell_id)] + _vec_list(v.frame.origin)
    if isinstance(v, (tuple, list)):
        return [plain(x, depth + 1) for x in v[:16]] if depth < 3 else f"{len(v)} items"
    for name in ("id", "poly_id", "leaf_idx"):  # a cell or object, a polygon, a BSP leaf: by its number
        if isinstance(getattr(v, name, None), (int, np.integer)):
            return int(getattr(v, name))
    if getattr(v, "splitting_plane", None) is not None:  # a BSP node: by its plane
        return plain(v.splitting_plane, depth + 1)
    # a DAT motion table's MotionData and AnimData, by what they hold: by their type only, a link looked up
    # from the wrong state (MotionTable.get_link) showed first where the animation it named was unpacked
    if hasattr(v, "anims") and hasattr(v, "bitfield"):  # a MotionData: bitfield, flags, its anims, velocity, omega
        return [int(v.bitfield), int(v.flags), [plain(a, depth + 2) for a in v.anims[:16]],
                plain(v.velocity, depth + 1), plain(v.omega, depth + 1)]
    if hasattr(v, "anim_id") and hasattr(v, "framerate") and hasattr(v, "low_frame"):  # an AnimData
        return [int(v.anim_id), int(v.low_frame), int(v.high_frame), _num(v.framerate)]
    return type(v).__name__


class Recorder:
    """The records of one traced run, and where the run is: its tick, its step, its transition."""

    def __init__(self):
        self.records: list[TraceRecord] = []
        self.tick: int | None = None
        self.step: int | None = None
        self.transition = None
        self.placing: int | None = None  # the static object being placed (add_obj_to_cell), its ID
        self.running: list[str] = []  # the anchors of the routines running now, outermost first

    def _add(self, anchor: str, event: str, args=None, result=None, path=None, mover=None) -> None:
        within = self.running[-1] if self.running else None
        self.records.append(TraceRecord(anchor, event, self.tick, self.step, within, args, result, path, mover,
                                        self.placing))

    # ---- the per-step points (one guarded line each in the port)

    @harness("a pass of FindTransitionalPosition's loop: its step number and the transition as it starts")
    def at_step(self, transition, step: int) -> None:
        self.transition = transition
        self.step = step
        self._add(FTP, "step", path=path_state(transition))

    @harness("a TransitionalInsert attempt: the transition as it starts")
    def at_insert(self, transition) -> None:
        self.transition = transition
        self._add(TI, "insert", path=path_state(transition))

    @harness("a tick of run_ticks: its index while it runs (start) and the mover after it (done)")
    def at_tick(self, index: int, state=None) -> None:
        if state is None:
            self.tick = index
        else:
            self._add(TICK, "tick", mover=state)

    @harness("forgets the records (a run retried on a deep stack starts again)")
    def clear(self) -> None:
        self.records.clear()
        self.tick = self.step = self.transition = self.placing = None
        self.running.clear()


def _args(args, kw) -> list:
    """A call's arguments as plain JSON, keyword ones last, in their order; the branch counter
    (harness state, not ACE's) left out."""
    return [plain(a) for a in args if not isinstance(a, Counter)] + [plain(v) for k, v in kw.items() if k != "trace"]


def _mover_state(obj):
    from .run import tick_state

    return tick_state(obj, False)


def _run(recorder: Recorder, ace: str, fn, args, kw):
    running = recorder.running
    running.append(ace)
    try:
        return fn(*args, **kw)
    finally:
        running.pop()


def _wrap(fn, anchor, recorder: Recorder, transition_type):
    ace = anchor.ace
    file = ace.split(":", 1)[0]
    if writes_path(ace):
        resets_step = ace == FTP

        def traced(*args, **kw):
            for x in args:
                if isinstance(x, transition_type):
                    recorder.transition = x
                    break
            t = recorder.transition
            if resets_step:
                recorder.step = None
            recorder._add(ace, "enter", _args(args, kw), path=path_state(t) if t is not None else None)
            r = _run(recorder, ace, fn, args, kw)
            if resets_step:
                recorder.step = None
            t = recorder.transition
            recorder._add(ace, "exit", None, plain(r), path=path_state(t) if t is not None else None)
            return r
    elif file == MOVER_FILE or ace in MOVER_ROUTINES:
        any_object = ace in MOVER_ROUTINES  # a server routine snapshots the object it acts on: another mover's jump too

        def traced(*args, **kw):
            obj = args[0] if args else None
            if (getattr(obj, "id", None) != MOVER_ID and not any_object) or getattr(obj, "position", None) is None:
                a = _args(args, kw)
                r = _run(recorder, ace, fn, args, kw)
                recorder._add(ace, "call", a, plain(r))
                return r
            recorder._add(ace, "enter", _args(args, kw), mover=_mover_state(obj))
            r = _run(recorder, ace, fn, args, kw)
            recorder._add(ace, "exit", None, plain(r), mover=_mover_state(obj))
            return r
        if ace == PLACE:
            traced = _placing(traced, recorder)
    else:
        def traced(*args, **kw):
            a = _args(args, kw)
            r = _run(recorder, ace, fn, args, kw)
            recorder._add(ace, "call", a, plain(r))
            return r
    traced.__wrapped__ = fn
    traced.__name__ = fn.__name__
    traced.__qualname__ = fn.__qualname__
    return traced


def _placing(traced, recorder: Recorder):
    """add_obj_to_cell's wrapper `traced`, labelling what it records with the static object it places."""
    def placing(*args, **kw):
        obj = args[0] if args else None
        if getattr(obj, "id", None) == MOVER_ID:
            return traced(*args, **kw)
        outer, recorder.placing = recorder.placing, int(getattr(obj, "id", 0))
        try:
            return traced(*args, **kw)
        finally:
            recorder.placing = outer
    return placing


@harness("every (anchor, event) kind of record a traced run of this port can write: its grain")
def record_kinds() -> frozenset:
    kinds = {(FTP, "step"), (TI, "insert"), (TICK, "tick")}
    for a in load_all().values():
        file = a.ace.split(":", 1)[0]
        events = ("enter", "exit") if writes_path(a.ace) else ("enter", "exit", "call") if file == MOVER_FILE \
            or a.ace in MOVER_ROUTINES \
            else ("call",)
        kinds.update((a.ace, e) for e in events)
    return frozenset(kinds)


@contextmanager
@harness("wraps every anchored routine of this port for one traced run, and puts the originals back")
def installed(recorder: Recorder):
    package = __name__.rsplit(".", 1)[0]
    load_all()
    from .transition.transition import Transition

    # the routines replaced for the run: every anchored one (by a wrapper writing its records) and every
    # one that remembers answers (by its twin computing every time, wrapped when anchored)
    originals = dict(FUNCTIONS)
    originals.update((key, fn) for key, (fn, _) in REMEMBERING.items())
    by_id = {id(fn): key for key, fn in originals.items()}
    wrappers: dict[int, object] = {}
    patched: list[tuple[object, str, object]] = []

    def wrapper(fn):
        w = wrappers.get(id(fn))
        if w is None:
            key = by_id[id(fn)]
            body = REMEMBERING[key][1] if key in REMEMBERING else fn
            w = wrappers[id(fn)] = _wrap(body, REGISTRY[key], recorder, Transition) if key in REGISTRY else body
        return w

    with _lock:
        # a traced run starts cold: what the harness remembers across runs (GfxObjs, Environments and CellStructs
        # built from the same bytes, pooled landblocks) would leave out the records of building them, and a trace must not
        # depend on what the process ran before
        from .cell.cell_struct import clear_built as clear_cell_structs
        from .db_obj import clear_environments
        from .gfx_obj_cache import clear_built
        from .land.lscape import clear_landblock_cache

        clear_built()
        clear_cell_structs()
        clear_environments()
        clear_landblock_cache()
        try:
            for name, module in list(sys.modules.items()):
                if module is None or not (name == package or name.startswith(package + ".")):
                    continue
                for attr, value in list(vars(module).items()):
                    if id(value) in by_id and originals[by_id[id(value)]] is value:
                        patched.append((module, attr, value))
                        setattr(module, attr, wrapper(value))
                    elif isinstance(value, type) and value.__module__ == name:
                        for cattr, cvalue in list(vars(value).items()):
                            raw = cvalue.__func__ if isinstance(cvalue, (staticmethod, classmethod)) else cvalue
                            if id(raw) in by_id and originals[by_id[id(raw)]] is raw:
                                w = wrapper(raw)
                                patched.append((value, cattr, cvalue))
                                setattr(value, cattr, type(cvalue)(w) if raw is not cvalue else w)
            yield recorder
        finally:
            for owner, attr, value in reversed(patched):
                setattr(owner, attr, value)
