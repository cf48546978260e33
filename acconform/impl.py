"""The implementation under test: the built-in port in process, or an external one (--impl CMD).

`make_backend(impl, mode, timeout)` is what every command that runs scenes on "the port" calls,
so `check`, `run`, `repro` and `bench` choose it one way. `add_arguments` adds the shared
``--impl CMD`` and ``--timeout S`` options.
"""

from __future__ import annotations

from .outcome import Outcome
from .scene import Scene

DEFAULT_TIMEOUT = 10.0
# the least time an implementation gets to write its handshake (a process starting an interpreter or
# a JVM on a loaded machine); --timeout above it is the handshake's time limit too
HANDSHAKE_TIMEOUT_MIN = 10.0


def add_arguments(p) -> None:
    p.add_argument("--impl", default=None, metavar="CMD",
                   help="the implementation under test: a command speaking acconform.protocol/1 "
                        "(docs/protocol.md); default: the built-in port, in process")
    from .commands import positive_seconds

    p.add_argument("--timeout", type=positive_seconds, default=DEFAULT_TIMEOUT, metavar="S",
                   help=f"seconds --impl may take for one scene before it is a hang verdict (default {DEFAULT_TIMEOUT:g}), "
                        f"and to start and write its handshake (at least {HANDSHAKE_TIMEOUT_MIN:g})")


class BuiltinPort:
    """The built-in port in this process (acconform.port.run.run_scene) in one mode, computing as
    ACE on `runtime` does ("mono" or "coreclr"; set it to the runtime of the ACE compared with)."""

    name = "acconform port"
    hello = None
    # every campaign kind, "motion" (motion tick scenes: the port has the motion layer), "doors", "movers", "missiles" and "targets"
    kinds = ("terrain", "bsp", "obstacles", "indoor", "buildings", "ticks", "motion", "doors", "movers", "missiles", "targets")

    def __init__(self, mode: str = "exact", runtime: str = "mono"):
        from .port.run import run_scene

        self.mode = mode
        self.runtime = runtime
        self._run = run_scene
        # a generative campaign sets this: each run then keeps its boundaries (a branches.Trace)
        # in last_trace, for the campaign's climb toward exact boundaries (runner.boundary_scores)
        self.trace_boundaries = False
        self.last_trace = None

    def __call__(self, scene: Scene) -> Outcome:
        if not self.trace_boundaries:
            return self._run(scene, mode=self.mode, runtime=self.runtime)
        from .port.transition.branches import Trace

        self.last_trace = Trace()
        return self._run(scene, mode=self.mode, runtime=self.runtime, trace=self.last_trace)

    @property
    def runs_every_scene(self) -> bool:
        """Exact mode: a replay hands it recorded scenes as their text (`run_text`). Fast mode
        answers in other digits than ACE's, so its answers are always read and compared."""
        return self.mode == "exact"

    def run_text(self, recorded) -> Outcome | None:
        """The outcome for a recorded scene given as its JSON text (an `oracle.recorded.RecordedText`);
        None when the outcome, written as the corpus writes it, is the recorded outcome's text
        (ACE's answer: nothing to read or compare). Only the scene's part of the record is parsed."""
        from . import deep
        from .codec import dumps_compact

        outcome = self(deep.retrying(Scene.loads, recorded.scene))  # a deep BSP's on a deep stack
        return None if dumps_compact(outcome.to_json()) == recorded.outcome else outcome

    def unsupported(self, scene: Scene) -> None:
        return None


def make_backend(impl: str | None, mode: str = "exact", timeout: float = DEFAULT_TIMEOUT):
    """The built-in port, or `impl` started as an acconform.protocol/1 process (handshake checked)."""
    if impl is None:
        return BuiltinPort(mode)
    from .errors import AcconformError
    from .protocol import Implementation

    if not timeout > 0:
        raise AcconformError(f"--timeout must be positive, got {timeout:g}")
    return Implementation(impl, mode=mode, timeout=timeout, start_timeout=max(timeout, HANDSHAKE_TIMEOUT_MIN))
