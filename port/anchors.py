"""The anchor registry: every public port routine tied to its retail function and ACE method.

Use as a decorator; it registers and returns the function unchanged (no call overhead):

    @anchor("CTransition::edge_slide", "Transition.cs:EdgeSlide")
    def edge_slide(self): ...

`retail` is the retail client's name (``None`` where ACE has no retail counterpart, e.g. a
server-only helper); `ace` is ``File.cs:Method``. Coverage per anchor and the registry audit
(tests/port/test_anchors.py) read `REGISTRY`.
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


def anchor(retail: str | None, ace: str, note: str = ""):
    if ":" not in ace or not ace.split(":", 1)[0].endswith(".cs"):
        raise ValueError(f"ACE anchor {ace!r} must read 'File.cs:Method'")

    def register(fn):
        key = f"{fn.__module__}.{fn.__qualname__}"
        if key in REGISTRY:
            raise ValueError(f"{key} is anchored twice")
        REGISTRY[key] = Anchor(key, retail, ace, note)
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
