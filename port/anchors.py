"""The anchor registry: every public port routine tied to its retail function and ACE method.

Use as a decorator; it registers and returns the function unchanged (no call overhead):

    @anchor("CTransition::edge_slide", "Transition.cs:EdgeSlide")
    def edge_slide(self): ...

`retail` is the retail client's name (``None`` where ACE has no retail counterpart, e.g. a
server-only helper); `ace` is ``File.cs:Method``. Coverage per anchor and the registry audit
(tests/port/test_anchors.py) read `REGISTRY`.

Harness glue -- public port functions with no ACE counterpart (building port objects from
scene records, .NET library behaviour such as Dictionary order or ``Nullable.Value``, the
landblock pool) -- is registered apart with ``@harness("what it does")`` in `HARNESS`, so the
ACE registry holds only ACE. The audit requires every public port function to be in one of
the two; ``acconform coverage --anchors`` lists the harness functions separately.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True, slots=True)
class Anchor:
    qualname: str  # module-qualified Python name of the port routine
    retail: str | None
    ace: str
    note: str = ""


REGISTRY: dict[str, Anchor] = {}
# the registered functions themselves, by the same key (port/tracing.py wraps them for a traced run)
FUNCTIONS: dict[str, object] = {}


# a routine that remembers answers ACE computes every time (docs/port-conventions.md "Remembered
# answers"), by its key -> (the routine, its twin computing every time); a traced run runs the twin in
# its place (port/tracing.py), so a trace holds the records of computing the answer, whatever ran before
REMEMBERING: dict[str, tuple[object, object]] = {}


def remembers(computed):
    """Register the decorated routine as one that remembers answers, and `computed` as the same routine
    without the memory (ACE's body, called the same way), which a traced run runs instead. Place it
    under @anchor or @harness."""

    def register(fn):
        REMEMBERING[f"{fn.__module__}.{fn.__qualname__}"] = (fn, computed)
        return fn

    return register


def anchor(retail: str | None, ace: str, note: str = ""):
    if ":" not in ace or not ace.split(":", 1)[0].endswith(".cs"):
        raise ValueError(f"ACE anchor {ace!r} must read 'File.cs:Method'")

    def register(fn):
        key = f"{fn.__module__}.{fn.__qualname__}"
        if key in REGISTRY or key in HARNESS:
            raise ValueError(f"{key} is anchored twice")
        REGISTRY[key] = Anchor(key, retail, ace, note)
        FUNCTIONS[key] = fn
        return fn

    return register


@dataclass(frozen=True, slots=True)
class Harness:
    qualname: str  # module-qualified Python name of the harness function
    what: str  # what it does instead of an ACE routine


HARNESS: dict[str, Harness] = {}


def harness(what: str):
    """Register a public port function that is harness glue, not ACE (see the module note)."""
    if not what:
        raise ValueError("a harness function says what it does")

    def register(fn):
        key = f"{fn.__module__}.{fn.__qualname__}"
        if key in HARNESS or key in REGISTRY:
            raise ValueError(f"{key} is registered twice")
        HARNESS[key] = Harness(key, what)
        return fn

    return register


def load_all() -> dict[str, Anchor]:
    """Import every port module so the registry is complete, and return it."""
    import importlib
    import pkgutil

    import acconform.port as pkg

    for info in pkgutil.walk_packages(pkg.__path__, pkg.__name__ + "."):
        importlib.import_module(info.name)
    return REGISTRY
