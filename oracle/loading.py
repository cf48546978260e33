"""Saying what loading the live oracle is doing while it does it, and how long each step took.

Loading ACE is several waits: starting the .NET runtime, referencing ACE's assemblies, checking
the members the oracle uses, compiling the C# facade (1-2 s with csc, 6-15 s where the SDK must
build a project; once per ACE build; a cached one is only loaded). `Loading` runs each as a step: it says the step when it
starts, again every TICK seconds while it lasts (from a thread, since the step itself is a child
process or a call into .NET), and keeps each step's seconds (`LiveOracle.load_seconds`) so a
campaign can say where its wall time went. `say` is where the lines go (a command's own
stderr printer); None keeps it silent (--no-progress) and still times the steps.
"""

from __future__ import annotations

import contextlib
import sys
import threading
import time
from typing import Callable

Say = Callable[[str], None]
TICK = 2.0  # seconds between a long step's "N s so far" lines: nobody waits longer than this without a word


def to_stderr(message: str) -> None:
    """The default `say`: one line on stderr, flushed (it interleaves with a progress bar's)."""
    print(f"acconform: {message}", file=sys.stderr, flush=True)


class Loading:
    """The steps of one load, each said and timed (see the module doc)."""

    def __init__(self, say: Say | None):
        self.say = say
        self.seconds: dict[str, float] = {}  # step name -> seconds, in the order they ran
        self.start = time.monotonic()

    @contextlib.contextmanager
    def step(self, name: str, doing: str):
        """Time the block as step `name`; say `doing` when it starts and every TICK s while it runs."""
        t0 = time.monotonic()
        done = threading.Event()
        ticker = None
        if self.say is not None:
            self.say(doing)
            ticker = threading.Thread(target=self._tick, args=(name, t0, done), daemon=True)
            ticker.start()
        try:
            yield
        finally:
            done.set()
            if ticker is not None:
                ticker.join()
            self.seconds[name] = self.seconds.get(name, 0.0) + time.monotonic() - t0

    def _tick(self, name: str, t0: float, done: threading.Event) -> None:
        while not done.wait(TICK):
            self.say(f"  {name}: {time.monotonic() - t0:.0f} s so far")

    def total(self) -> float:
        return time.monotonic() - self.start

    def summary(self) -> str:
        """"ACE ready in 5.4 s (runtime 0.8 s, assemblies 1.9 s, ...)"."""
        parts = ", ".join(f"{name} {s:.1f} s" for name, s in self.seconds.items())
        return f"ACE ready in {self.total():.1f} s ({parts})"
