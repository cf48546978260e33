"""The oracle: ACE's answer to a scene, live (ACE through pythonnet) or recorded (a corpus).

`get_oracle(ace=None, runtime=None, corpus=None)` returns the live oracle when an ACE assembly
is configured (``--ace``, ``ACE_ASSEMBLY``, or the user config file; see oracle/config.py) and
otherwise the recorded oracle replaying `corpus` (default: `default_corpus(runtime)`, the committed
corpus of that runtime; DEFAULT_RUNTIME, .NET 10 on CoreCLR, when none is asked for).
This package is the only one that imports pythonnet, and only when the live oracle is made.
"""

from __future__ import annotations

from pathlib import Path
from typing import Protocol, runtime_checkable

from ..case import Versions
from ..errors import OracleUnavailable
from ..outcome import Outcome
from ..scene import Scene
from .loading import to_stderr

_ROOT = Path(__file__).resolve().parent.parent  # a checkout's root, or the installed acconform package
# The recorded corpora: tests/data/corpus in a checkout (and an editable install); an installed
# acconform carries the same files as package data, acconform/corpus (pyproject.toml). One
# directory per runtime ACE ran on, named by its runtime key: CORPUS_ROOT/mono, CORPUS_ROOT/coreclr.
# The one definition: every command, test and script that needs a default corpus calls default_corpus.
CORPUS_ROOT = next((p for p in (_ROOT / "tests" / "data" / "corpus", _ROOT / "corpus") if p.is_dir()),
                   _ROOT / "corpus")
# What users run: ACE ships for .NET 10 (ACE.Server.csproj targets net10.0), so on CoreCLR.
DEFAULT_RUNTIME = "coreclr"


def default_corpus(runtime: str | None = None) -> Path:
    """The committed corpus of `runtime` ("mono" or "coreclr"; None: DEFAULT_RUNTIME)."""
    from ..errors import AcconformError
    from ..numerics import RUNTIMES

    runtime = runtime or DEFAULT_RUNTIME
    if runtime not in RUNTIMES:
        raise AcconformError(f"unknown runtime {runtime!r}: choose one of {', '.join(sorted(RUNTIMES))}")
    return CORPUS_ROOT / runtime


@runtime_checkable
class Oracle(Protocol):
    name: str  # "live" or "recorded"
    versions: Versions  # ACE version and runtime the answers come from

    def run(self, scene: Scene) -> Outcome: ...


def live_configured(ace=None) -> bool:
    from .config import configured_setting

    return configured_setting(ace) is not None


def get_oracle(ace=None, runtime: str | None = None, corpus=None, say=to_stderr) -> Oracle:
    """Live when ACE is configured (misconfiguration raises OracleUnavailable), else recorded.
    `say`: where loading ACE says what it is doing (oracle/loading.py; None: silent)."""
    if live_configured(ace):
        from .live import LiveOracle

        return LiveOracle(ace, runtime, say)
    from .recorded import RecordedOracle

    path = Path(corpus) if corpus is not None else default_corpus(runtime)
    return RecordedOracle(path)


class PerProcessOracle:
    """The live oracle, loaded in the process that first uses it.

    A .NET runtime (mono or CoreCLR) does not survive fork(), and pythonnet allows one runtime per
    process, so a campaign on several worker processes gives each worker its own ACE. The location
    is checked on disk up front (`config.resolve`) so a missing or wrong file still fails at once,
    in the parent; the runtime itself is started on the first `run` or `versions` in each process.
    """

    name = "live"
    per_process = True

    def __init__(self, ace=None, runtime: str | None = None, say=to_stderr):
        from .config import resolve

        self.location = resolve(ace, runtime)  # the build and the runtime it runs on, checked on disk
        if self.location is None:
            from .config import HOW_TO_SET

            raise OracleUnavailable(f"no ACE assembly configured for the live oracle; {HOW_TO_SET}")
        self._args = (ace, runtime, say)
        self._pid = None
        self._oracle = None

    def _live(self):
        import os

        if self._oracle is None or self._pid != os.getpid():
            from .live import LiveOracle

            self._oracle, self._pid = LiveOracle(*self._args), os.getpid()
        return self._oracle

    @property
    def versions(self) -> Versions:
        return self._live().versions

    @property
    def ace_note(self) -> str | None:
        """The live oracle's note when its ACE is not the one the port follows (oracle/identity.py)."""
        return self._live().ace_note

    def unsupported(self, scene: Scene) -> str | None:
        """Why this process's ACE cannot run `scene`, or None (LiveOracle.unsupported)."""
        return self._live().unsupported(scene)

    def run(self, scene: Scene) -> Outcome:
        return self._live().run(scene)


def port_runtime(oracle, runtime: str | None = None) -> str:
    """The runtime key ("mono" or "coreclr") whose arithmetic the port computes to be compared with
    `oracle`: a live oracle's, the runtime its build runs on (read from the build on disk: a
    PerProcessOracle's parent loads no runtime); a recorded one's, the runtime its records come
    from (`runtime`, --runtime, picks among a corpus's). `check` and the benchmarks ask here."""
    location = getattr(oracle, "location", None)  # LiveOracle and PerProcessOracle
    if location is not None:
        return location.runtime
    from ..numerics import runtime_named

    return runtime_named(runtime or oracle.versions.runtime)


def require_live(ace=None, runtime: str | None = None, say=to_stderr):
    """The live oracle, or OracleUnavailable saying that no ACE is configured (commands exit 2)."""
    from .config import HOW_TO_SET

    if not live_configured(ace):
        raise OracleUnavailable(f"this command needs the live oracle (ACE's physics) and no ACE assembly is configured; {HOW_TO_SET}")
    from .live import LiveOracle

    return LiveOracle(ace, runtime, say)


__all__ = ["Oracle", "PerProcessOracle", "get_oracle", "port_runtime", "require_live", "live_configured", "CORPUS_ROOT",
           "DEFAULT_RUNTIME", "default_corpus"]
