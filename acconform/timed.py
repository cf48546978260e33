"""A per-scene time limit for backends that run in process: the built-in port and live ACE.

An --impl implementation already has one (acconform.protocol: a hang past --timeout is a
verdict and the process is restarted). A backend in this process cannot be stopped halfway --
pure Python could be interrupted by a signal, but a call into ACE through pythonnet holds the
interpreter until .NET returns -- so `TimedBackend` runs the backend in a child process forked
from this one (made there by `make()`, so a .NET runtime loads in the child, never here) and
waits at most `limit` seconds for each outcome. A scene past the limit gets an outcome whose
error is ``SceneTimeout: ...`` (a verdict for that scene); the child is killed and the next
scene starts a fresh one.

`process_age()`: how long this process has run, for a summary that says where its wall time went.
"""

from __future__ import annotations

import multiprocessing
import os
import signal
from typing import Callable

from .errors import AcconformError
from .outcome import Outcome

SCENE_TIMEOUT = "SceneTimeout"
DEFAULT_LIMIT = 10.0  # seconds for one scene: the port takes milliseconds on an ordinary one


def _serve(make: Callable, conn) -> None:
    """The child: make the backend, say it is ready (with its versions), answer scenes until None."""
    from .runner import guarded

    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C is the parent's
    try:
        backend = make()
        owner = getattr(backend, "__self__", backend)
        conn.send(("ready", getattr(owner, "versions", None)))
    except Exception as e:  # noqa: BLE001 - reported to the parent as one line
        conn.send(("error", f"{type(e).__name__}: {e}"))
        return
    while True:
        try:
            scene = conn.recv()
        except (EOFError, OSError):
            return
        if scene is None:
            return
        conn.send(guarded(backend, scene))


class TimedBackend:
    """``backend(scene) -> Outcome`` with a time limit per scene (see the module doc).

    `make()` builds the backend in the child; `what` names it in verdicts ("port", "ACE").
    `timeouts` counts the scenes that ran out of time, `versions` is the backend's (its
    oracle's) versions as the child reported them, or None."""

    def __init__(self, make: Callable, limit: float = DEFAULT_LIMIT, what: str = "backend",
                 start_limit: float = 300.0):
        if not limit > 0:
            raise AcconformError(f"the time limit for a scene must be positive, got {limit:g}")
        self.make = make
        self.limit = limit
        self.what = what
        self.start_limit = start_limit
        self.timeouts = 0
        self.versions = None
        self._proc = None
        self._conn = None
        self._start()

    def _start(self) -> None:
        ctx = multiprocessing.get_context("fork")
        self._conn, child = ctx.Pipe()
        self._proc = ctx.Process(target=_serve, args=(self.make, child), daemon=True)
        self._proc.start()
        child.close()
        if not self._conn.poll(self.start_limit):
            self._kill()
            raise AcconformError(f"the {self.what} did not start within {self.start_limit:g} s")
        try:
            state, detail = self._conn.recv()
        except (EOFError, OSError):
            self._kill()
            raise AcconformError(f"the {self.what} process exited while starting") from None
        if state != "ready":
            self._kill()
            raise AcconformError(f"the {self.what} cannot start: {detail}")
        self.versions = detail

    def _kill(self) -> None:
        p, self._proc = self._proc, None
        if self._conn is not None:
            self._conn.close()
            self._conn = None
        if p is not None:
            p.kill()
            p.join()

    def __call__(self, scene) -> Outcome:
        if self._proc is None:
            try:
                self._start()
            except AcconformError as e:
                return Outcome(error=f"{SCENE_TIMEOUT}: could not start the {self.what} again: {e}")
        try:
            self._conn.send(scene)
            if self._conn.poll(self.limit):
                return self._conn.recv()
        except (EOFError, OSError):
            self._kill()
            return Outcome(error=f"SceneCrash: the {self.what} process died on this scene")
        self._kill()
        self.timeouts += 1
        return Outcome(error=f"{SCENE_TIMEOUT}: no outcome within {self.limit:g} s; the {self.what} was "
                             f"stopped (a fresh one runs the next scene)")

    run = __call__

    def close(self) -> None:
        if self._conn is not None:
            try:
                self._conn.send(None)
            except OSError:
                pass
        if self._proc is not None:
            self._proc.join(2)
        self._kill()


def process_age() -> float | None:
    """Seconds since this process started, interpreter start-up included (the kernel's start time,
    /proc on Linux, in clock ticks); None where that cannot be read."""
    try:
        with open("/proc/self/stat") as f:
            started = int(f.read().rsplit(")", 1)[1].split()[19])  # field 22, starttime
        with open("/proc/uptime") as f:
            uptime = float(f.read().split()[0])
    except (OSError, ValueError, IndexError):
        return None
    return max(uptime - started / os.sysconf("SC_CLK_TCK"), 0.0)
