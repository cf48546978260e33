"""Calls per anchor: every registered port routine wrapped with a counter for the length of a run.

    with counting_anchors() as calls:      # calls: Counter, anchor qualname -> calls
        run_scene(scene)
    for row in anchor_rows(calls): ...     # (Anchor, calls), every registered anchor, registry order
    for row in harness_rows(calls): ...    # (Harness, calls), the harness glue (port/anchors.py HARNESS)

`counting_anchors` imports every port module (acconform.port.anchors.load_all), finds each
anchored function by its qualname and replaces it -- and every other reference to the same
function object held in a port module's globals or a port class's dict (``from .x import f``,
LandCell's borrowed ObjCell methods) -- with a counting wrapper. On exit every slot is put back
to the very object it held, so nothing stays wrapped and no global flag is left set.

Python 3.11 has no sys.monitoring; wrapping touches only the anchored routines, where a profile
hook would slow every call in the process. What wrapping cannot see is a reference kept outside
those dicts (a closure, a default argument, a dispatch table); `Coverage.unwrapped` lists any
anchor for which not one slot was found, so a silent miss cannot read as "never reached".
"""

from __future__ import annotations

import functools
import importlib
import sys
from collections import Counter
from contextlib import contextmanager
from dataclasses import dataclass, field

PORT_PACKAGE = "acconform.port"


@dataclass(slots=True)
class Coverage:
    calls: Counter = field(default_factory=Counter)  # anchor qualname -> calls
    slots: Counter = field(default_factory=Counter)  # anchor qualname -> references wrapped
    unwrapped: list[str] = field(default_factory=list)  # anchors whose function was not found anywhere


def _resolve(qualname: str):
    """The object registered under `qualname` (a function, or the classmethod/staticmethod holding it)."""
    parts = qualname.split(".")
    for i in range(len(parts) - 1, 0, -1):
        try:
            obj = importlib.import_module(".".join(parts[:i]))
        except ImportError:
            continue
        for p in parts[i:]:
            d = getattr(obj, "__dict__", {})
            obj = d[p] if p in d else getattr(obj, p)
        return obj
    raise LookupError(qualname)


def _plain(obj):
    return obj.__func__ if isinstance(obj, (classmethod, staticmethod)) else obj


def _owners():
    """Every namespace that can hold a port routine: port modules and the classes they define."""
    seen: set[int] = set()
    for name, mod in list(sys.modules.items()):
        if mod is None or not (name == PORT_PACKAGE or name.startswith(PORT_PACKAGE + ".")):
            continue
        yield mod
        for v in list(vars(mod).values()):
            if isinstance(v, type) and id(v) not in seen and (v.__module__ or "").startswith(PORT_PACKAGE):
                seen.add(id(v))
                yield v


def _counting(fn, key: str, calls: Counter):
    @functools.wraps(fn)
    def wrapper(*args, **kwargs):
        calls[key] += 1
        return fn(*args, **kwargs)

    wrapper.__acconform_counted__ = fn
    return wrapper


@contextmanager
def counting_anchors():
    """Count calls to every registered anchor inside the block; yields a Coverage (filled live)."""
    from .port.anchors import HARNESS, load_all

    registry = list(load_all()) + list(HARNESS)  # harness glue is counted too, and listed apart
    cov = Coverage()
    by_func: dict[int, str] = {}
    for key in registry:
        fn = _plain(_resolve(key))
        if getattr(fn, "__acconform_counted__", None) is not None:
            raise RuntimeError("counting_anchors is already active (it does not nest)")
        by_func[id(fn)] = key
    replaced: list[tuple[object, str, object]] = []  # (owner, attribute, original value)
    wrappers: dict[int, object] = {}
    try:
        for owner in _owners():
            for attr, value in list(vars(owner).items()):
                fn = _plain(value)
                key = by_func.get(id(fn))
                if key is None:
                    continue
                w = wrappers.get(id(fn))
                if w is None:
                    w = wrappers[id(fn)] = _counting(fn, key, cov.calls)
                new = type(value)(w) if isinstance(value, (classmethod, staticmethod)) else w
                setattr(owner, attr, new)
                replaced.append((owner, attr, value))
                cov.slots[key] += 1
        cov.unwrapped = [k for k in registry if not cov.slots[k]]
        yield cov
    finally:
        for owner, attr, value in reversed(replaced):
            setattr(owner, attr, value)


def anchor_rows(calls: Counter):
    """(Anchor, calls) for every registered anchor, in registry order."""
    from .port.anchors import load_all

    return [(a, calls.get(key, 0)) for key, a in load_all().items()]


def harness_rows(calls: Counter):
    """(Harness, calls) for every harness function (glue with no ACE counterpart), in registry order."""
    from .port.anchors import HARNESS, load_all

    load_all()
    return [(h, calls.get(key, 0)) for key, h in HARNESS.items()]


def anchor_labels(anchors) -> dict[str, str]:
    """qualname -> a name for each anchor that no other anchor shares: the retail name (else the
    ACE method), with the port routine's Class.method added where overloads share it."""
    def base(a):
        return a.retail or a.ace

    seen = Counter(base(a) for a in anchors)
    labels = {}
    for a in anchors:
        label = base(a)
        if seen[label] > 1:
            label = f"{label} [{'.'.join(a.qualname.split('.')[-2:])}]"
        labels[a.qualname] = label
    counts = Counter(labels.values())
    return {q: (f"{lab} [{q}]" if counts[lab] > 1 else lab) for q, lab in labels.items()}


def render_table(calls: Counter, unwrapped=()) -> list[str]:
    """The `coverage --anchors` table: one row per anchor (a name no other row shares), its ACE
    File.cs:Method and calls; then the summary, naming the anchors never reached the same way."""
    rows = anchor_rows(calls)
    labels = anchor_labels([a for a, _ in rows])
    width = max([len(labels[a.qualname]) for a, _ in rows] + [len("retail anchor")])
    ace_w = max([len(a.ace) for a, _ in rows] + [len("ACE")])
    out = [f"{'retail anchor':{width}}  {'ACE':{ace_w}}  {'calls':>9}"]
    for a, n in rows:
        out.append(f"{labels[a.qualname]:{width}}  {a.ace:{ace_w}}  {n:9d}")
    reached = sum(1 for _, n in rows if n)
    never = [a for a, n in rows if not n]
    out.append(f"{reached} of {len(rows)} anchors reached")
    if never:
        out.append(f"never reached ({len(never)}): " + ", ".join(labels[a.qualname] for a in never))
    glue = harness_rows(calls)
    if glue:
        name_w = max(len(h.qualname) for h, _ in glue)
        out.append("")
        out.append(f"harness glue (no ACE counterpart, {len(glue)}):")
        for h, n in glue:
            out.append(f"  {h.qualname:{name_w}}  {n:9d}  {h.what}")
    if unwrapped:
        out.append(f"not counted (no reference found to wrap, {len(unwrapped)}): " + ", ".join(unwrapped))
    return out
