"""The one comparator: two outcomes in, a list of field-by-field differences out.

    compare(a, b, mode="exact") -> list[Difference]

Discrete fields (ok, cell ids, flags, validity bits, is_water, frames_stationary_fall, the
SpherePath bits, error presence) must be equal in every mode. Floats:

- ``exact``: bit-equal as float32 (so -0.0 differs from +0.0, and NaN equals NaN only when its
  bit pattern does).
- ``fast`` (the port run in doubles): equal within ``FAST_ULPS`` float32 ULPs *or* within
  ``FAST_ABS`` absolute (for values near zero, where ULPs are tiny); NaN matches NaN of any
  payload, infinities only themselves.

`placement` (the mover's placement, scenes with one) is compared field by field like the rest;
one side with it and the other without is a difference.

`static_cells` (the cells each static is registered in, in order) must be equal in every mode,
unless either side has None ("not recorded": an ``acconform.outcome/1`` record); then it is
not compared.

Errors: their presence must match in every mode, and in exact mode also the exception type
(the text before the first colon); the messages are free text (ACE's come from .NET, the
port's name the missing piece) and are shown but never compared. An outcome's `error` is compared
first, so a verdict (an exception, an implementation's crash, timeout or protocol error) heads the
list. When only one side has an error, that side gave no answer: its other fields are defaults,
not values, so the error is the one difference listed (likewise a tick with an error on one side
only: later ticks do not exist on that side).

`ticks` (a tick scene's outcome) is compared tick by tick, each `TickState` field by field
(``ticks[7].origin[0]``), right after `placement` and before `static_cells` (which are read after
the last tick), so the first difference of a tick scene is its first differing tick and field:
`first_tick_difference` picks it, and the case file and ``acconform show`` put it on top. A tick's
``update_time`` is a double (ACE's clock arithmetic) and must be bit-equal in every mode; a tick's
``error`` follows the rule for errors below; when one side ran fewer ticks (an error ended it), the
first missing tick is a difference (``ticks[n]``, one value None); one side with ticks and the other
without is a difference (``ticks``).

A tick's `motion` (a mover with a motion table) is compared like the rest, after the tick's other
fields: ``ticks[3].motion.interpreted.forward_command``, ``ticks[3].motion.frame_number``,
``ticks[3].motion.sequence_velocity[1]``; one side with it (or with a part of it: `interpreted`, `raw`,
`animation`, `movement_type`) and the other without is a difference naming that field. The
commands and the animation id are compared as ids, the speeds, the frame number and the sequence's
velocity and omega as floats, `movement_type` and `is_moving_to` as discrete values.

Other movers (scene/8, outcome/6): `other_placements` right after `placement`, each other mover's
placement field by field (``other_placements[1].cell``); per tick, after the mover's fields, its
`collisions` (its CollisionTable: ``ticks[4].collisions[0].id``, ``.touched_time`` bit-equal as a double,
``.ethereal``; a table of another length is one difference naming the table, both sides' ids shown) and
then each other mover's state, named by its id: ``ticks[4].others[0x80000002].origin[0]``,
``ticks[4].others[0x80000002].collisions[0].id``. So the first difference names the tick, the mover
and the field.

Motion queries (scene/8 motion_queries, outcome/6 motion_answers): after the ticks, each answer by the
query's index and field: ``motion_answers[2].value`` (a float), ``motion_answers[0].attack_frames[1].time``,
``.part_index``; an answer list or an attack-frame list of another length is one difference naming it; an
answer's `error` follows the rule for errors.

A Difference names the field by path (``contact_plane.normal[2]``) and carries both values.
"""

from __future__ import annotations

import math
import struct
from dataclasses import dataclass, fields
from typing import Any

import numpy as np

from .flags import ObjectInfoState, PhysicsState, TransientState, flag_names
from .outcome import (CollisionState, CommandState, ContactPlaneState,
                      MotionTickState, NormalState, Outcome, PlacementState, PlaneState, TickState)
from .numerics import f32_bits

MODES = ("exact", "fast")
FAST_ULPS = 64  # float32 ULPs allowed between a double run and ACE's float32 run
FAST_ABS = 1e-4  # metres / unit-vector components; below PhysicsGlobals.EPSILON (2e-4)

_ID_FIELDS = frozenset({"cell", "check_cell", "cur_cell", "contact_plane_cell", "current_style", "forward_command",
                        "side_step_command", "turn_command", "animation", "id"})
_FLAG_FIELDS = {"object_info_state": ObjectInfoState, "state": PhysicsState, "transient_state": TransientState}
_VEC_FIELDS = frozenset({"origin", "orientation", "velocity", "normal", "vector", "acceleration", "omega",
                         "cached_velocity", "sliding_normal", "sequence_velocity", "sequence_omega"})
_DOUBLE_FIELDS = frozenset({"update_time", "touched_time"})
_FLOAT_FIELDS = frozenset({"d", "forward_speed", "side_step_speed", "turn_speed", "frame_number", "value", "time",
                           "left_x", "left_y", "right_x", "right_y", "radius", "height"})


@dataclass(frozen=True, slots=True)
class Difference:
    field: str
    a: Any
    b: Any

    def render(self, a_name: str = "port", b_name: str = "oracle") -> str:
        return f"{self.field}: {a_name}={_show(self.field, self.a)} {b_name}={_show(self.field, self.b)}"

    def __str__(self) -> str:
        return self.render()


def _show(path: str, v) -> str:
    leaf = path.rsplit(".", 1)[-1].split("[", 1)[0]
    if isinstance(v, bool) or v is None:
        return repr(v)
    if isinstance(v, int) and leaf in _ID_FIELDS:
        return f"0x{v:08X}"
    if isinstance(v, tuple) and leaf == "static_cells":
        return "[" + ", ".join("[" + ", ".join(f"0x{c:08X}" for c in cells) + "]" for cells in v) + "]"
    if isinstance(v, int) and leaf in _FLAG_FIELDS:
        return "|".join(flag_names(_FLAG_FIELDS[leaf], v)) or "0"
    if isinstance(v, float) and leaf in _DOUBLE_FIELDS:
        return f"{v!r} (0x{_double_bits(v):016x})"
    if isinstance(v, tuple) and leaf == "shadow_cells":
        return "[" + ", ".join(f"0x{c:08X}" for c in v) + "]"
    if isinstance(v, int) and leaf == "movement_type":
        from .motion_enums import MovementType

        return MovementType(v).name if v in MovementType._value2member_map_ else repr(v)
    if isinstance(v, (CommandState, MotionTickState)):
        return "a " + type(v).__name__
    if isinstance(v, tuple) and leaf == "ticks":
        return f"{len(v)} ticks"
    if isinstance(v, tuple) and leaf == "collisions":
        return "[" + ", ".join(f"0x{c.id:08X}" for c in v) + "]"
    if isinstance(v, tuple) and leaf in ("motion_answers", "attack_frames"):
        return f"{len(v)} {'answers' if leaf == 'motion_answers' else 'attack frames'}"
    if isinstance(v, tuple) and leaf in ("others", "other_placements"):
        return f"{len(v)} other movers"
    if isinstance(v, TickState):
        return "TickState(error=" + repr(v.error) + ")" if v.error is not None else "a TickState"
    if isinstance(v, float):
        f = np.float32(v)
        return f"{f!r}"[len("np.float32("):-1] + f" (0x{f32_bits(v):08x})" if math.isfinite(v) else f"{v} (0x{f32_bits(v):08x})"
    return repr(v)


def float_equal(a: float, b: float, mode: str = "exact") -> bool:
    """Whether two float32 values count as equal under `mode` (see the module docstring)."""
    if mode == "exact":
        if a == b:  # one value, so one float32 rounding: only the sign of a zero can tell them apart
            return a != 0.0 or math.copysign(1.0, a) == math.copysign(1.0, b)
        return f32_bits(a) == f32_bits(b)  # NaNs, or two doubles that round to one float32
    fa, fb = np.float32(a), np.float32(b)
    if np.isnan(fa) or np.isnan(fb):
        return bool(np.isnan(fa) and np.isnan(fb))
    if np.isinf(fa) or np.isinf(fb):
        return bool(fa == fb)
    if abs(float(fa) - float(fb)) <= FAST_ABS:
        return True
    return ulp_distance(a, b) <= FAST_ULPS


def ulp_distance(a: float, b: float) -> int:
    """How many float32 values lie between a and b (0 when equal; +0 and -0 are 0 apart)."""

    def ordered(x):
        i = f32_bits(x)
        return i if i < 0x80000000 else 0x80000000 - i  # monotone map of the float32 line to ints

    return abs(ordered(a) - ordered(b))


def compare(a: Outcome, b: Outcome, mode: str = "exact") -> list["Difference"]:
    """Every field where a and b differ under `mode`, in field order."""
    if mode not in MODES:
        from .errors import AcconformError

        raise AcconformError(f"unknown comparison mode {mode!r}: choose one of {', '.join(MODES)}")
    if (a.error is None) != (b.error is None):  # one side's fields are defaults, not an answer
        return [Difference("error", a.error, b.error)]
    out: list[Difference] = []
    _compare_record(a, b, "", mode, out)
    return out


def _double_bits(x: float) -> int:
    return struct.unpack("<Q", struct.pack("<d", x))[0]


def _order(record) -> list[str]:
    """The fields of `record` in comparison order: an Outcome's `error` first (a verdict heads the
    list), its `placement` and `ticks` before `static_cells` (read after the transition or the last
    tick); every other record in field order."""
    names = [f.name for f in fields(record)]
    if isinstance(record, Outcome):
        names.remove("error")
        names.insert(0, "error")
        names.remove("static_cells")
        names.append("static_cells")
        names.remove("other_placements")
        names.insert(names.index("placement") + 1, "other_placements")
    return names


def first_tick_difference(diffs: list["Difference"]) -> "Difference | None":
    """The first difference in a tick (``ticks[...]``, the first differing tick and field), or None."""
    return next((d for d in diffs if d.field.startswith("ticks")), None)


def _compare_ticks(va, vb, mode: str, out: list) -> None:
    if (va is None) != (vb is None):
        out.append(Difference("ticks", va, vb))
        return
    if va is None:
        return
    for i in range(max(len(va), len(vb))):
        if i >= len(va) or i >= len(vb):
            out.append(Difference(f"ticks[{i}]", va[i] if i < len(va) else None, vb[i] if i < len(vb) else None))
            return
        if (va[i].error is None) != (vb[i].error is None):  # that tick's fields are defaults on one side
            out.append(Difference(f"ticks[{i}].error", va[i].error, vb[i].error))
            return
        _compare_record(va[i], vb[i], f"ticks[{i}].", mode, out)


def _compare_collisions(va, vb, path: str, mode: str, out: list) -> None:
    if (va is None) != (vb is None) or (va is not None and len(va) != len(vb)):
        out.append(Difference(path, va, vb))
        return
    for k, (ca, cb) in enumerate(zip(va or (), vb or ())):
        _compare_record(ca, cb, f"{path}[{k}].", mode, out)


def _compare_others(va, vb, path: str, mode: str, out: list) -> None:
    """Each other mover's tick, named by its id (`others[0x80000002]`)."""
    if (va is None) != (vb is None) or (va is not None and [o.id for o in va] != [o.id for o in vb]):
        out.append(Difference(path, va, vb))
        return
    for oa, ob in zip(va or (), vb or ()):
        _compare_record(oa, ob, f"{path}[0x{oa.id:08X}].", mode, out)


def _compare_answers(va, vb, path: str, mode: str, out: list) -> None:
    """The motion queries' answers, by index and field; an answer's value or attack frames on one side only (or an
    attack-frame list of another length) is a difference naming it."""
    if (va is None) != (vb is None) or (va is not None and len(va) != len(vb)):
        out.append(Difference(path, va, vb))
        return
    for k, (a, b) in enumerate(zip(va or (), vb or ())):
        at = f"{path}[{k}]"
        if (a.error is None) != (b.error is None) or (mode == "exact" and a.error is not None and _etype(a.error) != _etype(b.error)):
            out.append(Difference(f"{at}.error", a.error, b.error))
            continue
        if (a.value is None) != (b.value is None) or (a.value is not None and not float_equal(a.value, b.value, mode)):
            out.append(Difference(f"{at}.value", a.value, b.value))
        fa, fb = a.attack_frames, b.attack_frames
        if (fa is None) != (fb is None) or (fa is not None and len(fa) != len(fb)):
            out.append(Difference(f"{at}.attack_frames", fa, fb))
            continue
        for j, (x, y) in enumerate(zip(fa or (), fb or ())):
            _compare_record(x, y, f"{at}.attack_frames[{j}].", mode, out)


def _compare_placements(va, vb, path: str, mode: str, out: list) -> None:
    if (va is None) != (vb is None) or (va is not None and len(va) != len(vb)):
        out.append(Difference(path, va, vb))
        return
    for k, (pa, pb) in enumerate(zip(va or (), vb or ())):
        _compare_record(pa, pb, f"{path}[{k}].", mode, out)


_TICKS, _DOUBLE, _SHADOW, _PLACEMENT, _STATIC, _ERROR, _VEC, _FLOAT, _OTHER, _COLLISIONS, _OTHERS, _PLACEMENTS, _ANSWERS = range(13)
_RECORDS = (ContactPlaneState, NormalState, PlaneState)
_OPTIONAL_RECORDS = (MotionTickState, CommandState)  # None on a side that has none: compared when both have one
_PLANS: dict[type, tuple] = {}  # a record type -> its fields in `_order`, each with how it is compared


def _plan(record) -> tuple:
    plan = _PLANS.get(type(record))
    if plan is None:
        def how(name):
            if name == "ticks" and isinstance(record, Outcome):
                return _TICKS
            if name in _DOUBLE_FIELDS:
                return _DOUBLE
            if name == "shadow_cells":
                return _SHADOW
            if isinstance(record, TickState) and name in ("collisions", "others"):
                return _COLLISIONS if name == "collisions" else _OTHERS
            if name == "other_placements":
                return _PLACEMENTS
            if name == "motion_answers":
                return _ANSWERS
            return {"placement": _PLACEMENT, "static_cells": _STATIC, "error": _ERROR}.get(
                name, _VEC if name in _VEC_FIELDS else _FLOAT if name in _FLOAT_FIELDS else _OTHER)
        plan = _PLANS[type(record)] = tuple((name, how(name)) for name in _order(record))
    return plan


def _compare_record(a, b, prefix: str, mode: str, out: list) -> None:
    for name, how in _plan(a):
        va, vb = getattr(a, name), getattr(b, name)
        if how == _VEC and mode == "exact" and type(va) is tuple and va == vb and 0.0 not in va:
            continue  # equal nonzero values round to one float32 each (the common case, decided at once)
        path = prefix + name
        if how == _TICKS:
            _compare_ticks(va, vb, mode, out)
        elif how == _COLLISIONS:
            _compare_collisions(va, vb, path, mode, out)
        elif how == _OTHERS:
            _compare_others(va, vb, path, mode, out)
        elif how == _PLACEMENTS:
            _compare_placements(va, vb, path, mode, out)
        elif how == _ANSWERS:
            _compare_answers(va, vb, path, mode, out)
        elif how == _DOUBLE:
            if _double_bits(va) != _double_bits(vb):
                out.append(Difference(path, va, vb))
        elif how == _SHADOW:
            if va != vb:
                out.append(Difference(path, va, vb))
        elif isinstance(va, _RECORDS) or (isinstance(va, PlacementState) and isinstance(vb, PlacementState)):
            _compare_record(va, vb, path + ".", mode, out)
        elif isinstance(va, _OPTIONAL_RECORDS) or isinstance(vb, _OPTIONAL_RECORDS):
            if type(va) is type(vb):
                _compare_record(va, vb, path + ".", mode, out)
            else:  # one side has none (no motion table, no motion interpreter)
                out.append(Difference(path, va, vb))
        elif how == _PLACEMENT and (va is None) != (vb is None):
            out.append(Difference(path, va, vb))
        elif how == _STATIC:
            if va is not None and vb is not None and va != vb:
                out.append(Difference(path, va, vb))
        elif how == _ERROR:
            if (va is None) != (vb is None) or (mode == "exact" and va is not None and _etype(va) != _etype(vb)):
                out.append(Difference(path, va, vb))
        elif how == _VEC:
            for i, (x, y) in enumerate(zip(va, vb)):
                if not float_equal(x, y, mode):
                    out.append(Difference(f"{path}[{i}]", x, y))
        elif how == _FLOAT:
            if not float_equal(va, vb, mode):
                out.append(Difference(path, va, vb))
        elif va != vb or type(va) is not type(vb):
            out.append(Difference(path, va, vb))


def _etype(error: str) -> str:
    """An error's exception type ("NullReferenceException: ..." -> "NullReferenceException")."""
    return error.split(":", 1)[0].strip()


def render(diffs: list[Difference], a_name: str = "port", b_name: str = "oracle") -> list[str]:
    return [d.render(a_name, b_name) for d in diffs]
