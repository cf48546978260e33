"""The oracle: ACE's answer to a scene, live (ACE through pythonnet) or recorded (a corpus).

`get_oracle(ace=None, runtime=None, corpus=None)` returns the live oracle when an ACE assembly
is configured (``--ace``, ``ACE_ASSEMBLY``, or the user config file; see oracle/config.py) and
otherwise the recorded oracle replaying `corpus` (default: the repository's tests/data/corpus).
This package is the only one that imports pythonnet, and only when the live oracle is made.
"""

from __future__ import annotations

from pathlib import Path
from typing import Protocol, runtime_checkable

from ..case import Versions
from ..errors import OracleUnavailable
from ..outcome import Outcome
from ..scene import Scene

DEFAULT_CORPUS = Path(__file__).resolve().parent.parent / "tests" / "data" / "corpus"


@runtime_checkable
class Oracle(Protocol):
    name: str  # "live" or "recorded"
    versions: Versions  # ACE version and runtime the answers come from

    def run(self, scene: Scene) -> Outcome: ...


def live_configured(ace=None) -> bool:
    from .config import configured_setting

    return configured_setting(ace) is not None


def get_oracle(ace=None, runtime: str | None = None, corpus=None) -> Oracle:
    """Live when ACE is configured (misconfiguration raises OracleUnavailable), else recorded."""
    if live_configured(ace):
        from .live import LiveOracle

        return LiveOracle(ace, runtime)
    from .recorded import RecordedOracle

    path = Path(corpus) if corpus is not None else DEFAULT_CORPUS
    return RecordedOracle(path)


def require_live(ace=None, runtime: str | None = None):
    """The live oracle, or OracleUnavailable saying that no ACE is configured (commands exit 2)."""
    from .config import HOW_TO_SET

    if not live_configured(ace):
        raise OracleUnavailable(f"this command needs the live oracle (ACE's physics) and no ACE assembly is configured; {HOW_TO_SET}")
    from .live import LiveOracle

    return LiveOracle(ace, runtime)


__all__ = ["Oracle", "get_oracle", "require_live", "live_configured", "DEFAULT_CORPUS"]
