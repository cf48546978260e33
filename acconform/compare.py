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
port's name the missing piece) and are shown but never compared.

A Difference names the field by path (``contact_plane.normal[2]``) and carries both values.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields
from typing import Any

import numpy as np

from .flags import ObjectInfoState, flag_names
from .outcome import ContactPlaneState, NormalState, Outcome, PlacementState

MODES = ("exact", "fast")
FAST_ULPS = 64  # float32 ULPs allowed between a double run and ACE's float32 run
FAST_ABS = 1e-4  # metres / unit-vector components; below PhysicsGlobals.EPSILON (2e-4)

_ID_FIELDS = frozenset({"cell", "check_cell", "cur_cell"})
_FLAG_FIELDS = {"object_info_state": ObjectInfoState}
_VEC_FIELDS = frozenset({"origin", "orientation", "velocity", "normal", "vector"})
_FLOAT_FIELDS = frozenset({"d"})


@dataclass(frozen=True, slots=True)
class Difference:
    field: str
    a: Any
    b: Any

    def render(self, a_name: str = "port", b_name: str = "oracle") -> str:
        return f"{self.field}: {a_name}={_show(self.field, self.a)} {b_name}={_show(self.field, self.b)}"

    def __str__(self) -> str:
        return self.render()


def _bits(x: float) -> int:
    return int(np.float32(x).view(np.uint32))


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
    if isinstance(v, float):
        f = np.float32(v)
        return f"{f!r}"[len("np.float32("):-1] + f" (0x{_bits(v):08x})" if math.isfinite(v) else f"{v} (0x{_bits(v):08x})"
    return repr(v)


def float_equal(a: float, b: float, mode: str = "exact") -> bool:
    """Whether two float32 values count as equal under `mode` (see the module docstring)."""
    if mode == "exact":
        return _bits(a) == _bits(b)
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
        i = _bits(x)
        return i if i < 0x80000000 else 0x80000000 - i  # monotone map of the float32 line to ints

    return abs(ordered(a) - ordered(b))


def compare(a: Outcome, b: Outcome, mode: str = "exact") -> list["Difference"]:
    """Every field where a and b differ under `mode`, in field order."""
    if mode not in MODES:
        from .errors import AcconformError

        raise AcconformError(f"unknown comparison mode {mode!r}: choose one of {', '.join(MODES)}")
    out: list[Difference] = []
    _compare_record(a, b, "", mode, out)
    return out


def _compare_record(a, b, prefix: str, mode: str, out: list) -> None:
    for f in fields(a):
        name = f.name
        path = f"{prefix}{name}"
        va, vb = getattr(a, name), getattr(b, name)
        if isinstance(va, (ContactPlaneState, NormalState)) or (
                isinstance(va, PlacementState) and isinstance(vb, PlacementState)):
            _compare_record(va, vb, path + ".", mode, out)
        elif name == "placement" and (va is None) != (vb is None):
            out.append(Difference(path, va, vb))
        elif name == "static_cells":
            if va is not None and vb is not None and va != vb:
                out.append(Difference(path, va, vb))
        elif name == "error":
            if (va is None) != (vb is None) or (mode == "exact" and va is not None and _etype(va) != _etype(vb)):
                out.append(Difference(path, va, vb))
        elif name in _VEC_FIELDS:
            for i, (x, y) in enumerate(zip(va, vb)):
                if not float_equal(x, y, mode):
                    out.append(Difference(f"{path}[{i}]", x, y))
        elif name in _FLOAT_FIELDS:
            if not float_equal(va, vb, mode):
                out.append(Difference(path, va, vb))
        elif va != vb or type(va) is not type(vb):
            out.append(Difference(path, va, vb))


def _etype(error: str) -> str:
    """An error's exception type ("NullReferenceException: ..." -> "NullReferenceException")."""
    return error.split(":", 1)[0].strip()


def render(diffs: list[Difference], a_name: str = "port", b_name: str = "oracle") -> list[str]:
    return [d.render(a_name, b_name) for d in diffs]
