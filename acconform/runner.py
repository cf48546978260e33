"""The differential runner: scenes through two backends, compared, differences shrunk and saved.

A backend is any callable ``scene -> Outcome``; the port (acconform.port.run.run_scene) and the
oracle (acconform.oracle.get_oracle().run) are the default pair, and tests pass plain callables
(e.g. a mutated port against the real one).

Two kinds of campaign:

- generative (a live oracle, or any callable pair): scenes are drawn from
  acconform.strategies.scenes(kinds) outside Hypothesis' engine (strategies.fast_draw), a few
  times cheaper per scene, each with the choice sequence that drew it; in the second half of a
  round some are the scene that came closest to an exact boundary with one choice moved. A
  difference is handed to Hypothesis as its choice sequence, Hypothesis shrinks it as one of its
  own, acconform.shrink then shrinks the scene itself, and the minimal scene is written as a case
  file. The campaign's database (a Hypothesis example database: a directory, or one shared through
  GitHub Actions artifacts; `SavedFailures`) remembers each shrunk failing scene, so the next run
  of the same kinds and mode -- on this machine or, sharing the database, another shard's -- runs
  them first; one that no longer fails is forgotten.
- replay (a recorded oracle): Hypothesis cannot ask a recording about scenes it never saw, so
  the recorded scenes are replayed as they are. The first difference of each kind is then shrunk
  (acconform.shrink) with a *stand-in* for ACE -- the built-in port, computing as the recorded
  runtime -- provided the stand-in agrees bit for bit with ACE's recorded answer on the original
  scene; otherwise, and for the other differences of that kind, the case is written as recorded.
  Each case says which (`Case.shrink`: against "ace", "port" or "none", and why).

Deterministic for a seed (and a worker count): worker w draws with seed (seed, w). With
``keep_going`` a campaign goes on after a difference, ignoring differences with the same
*signature* (the set of differing field paths) so each shrink finds a new kind of failure.

A port backend may name scenes it cannot run (``port.unsupported(scene) -> reason or None``, as
an implementation under test does from its handshake): those are skipped and counted by reason
in `Result.skipped`, never compared, and never count toward `n`: `n` is the number of scenes
compared. Each scene is counted once: `Result.cases` = compared + skipped; the extra runs
shrinking takes are `Result.shrink_runs`; each kind of difference is found once (a live campaign
on several workers keeps the first worker's case of each kind). Ctrl-C ends a campaign early with what it has found so far
(`Result.interrupted`); worker processes ignore SIGINT and stop when the parent tells them to.
"""

from __future__ import annotations

import contextlib
import gc
import hashlib
import math
import multiprocessing
import os
import signal
import sys
import tempfile
import threading
import time
from collections import Counter
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Callable, Iterable, Sequence

from . import __version__
from .case import Case, Shrink, Versions, write_document
from .compare import Difference, compare, first_tick_difference, render
from .errors import AcconformError
from .outcome import Outcome
from .scene import Scene

Backend = Callable[[Scene], Outcome]

DEFAULT_DATABASE = Path(".hypothesis") / "acconform"


def example_database(spec):
    """The Hypothesis example database (hypothesis.database) a live campaign keeps its failing scenes
    in, named by `spec` (--database): an ExampleDatabase as it is; ``github:OWNER/REPO[/ARTIFACT]``
    the scenes a GitHub Actions artifact holds (the latest of that name, default Hypothesis'
    "hypothesis-example-db"; read-only, a GitHubArtifactDatabase; GITHUB_TOKEN for a private
    repository) beside DEFAULT_DATABASE, the directory this run keeps its own in; anything else a
    directory (DirectoryBasedExampleDatabase)."""
    from hypothesis.database import (DirectoryBasedExampleDatabase, ExampleDatabase, GitHubArtifactDatabase,
                                     MultiplexedDatabase, ReadOnlyDatabase)

    if isinstance(spec, ExampleDatabase):
        return spec
    text = os.fspath(spec)
    if text.startswith("github:"):
        owner, _, rest = text[len("github:"):].partition("/")
        repo, _, artifact = rest.partition("/")
        if not owner or not repo or "/" in artifact:
            raise AcconformError(f"--database {text!r}: expected github:OWNER/REPO or github:OWNER/REPO/ARTIFACT")
        shared = GitHubArtifactDatabase(owner, repo, *([artifact] if artifact else []))
        return MultiplexedDatabase(DirectoryBasedExampleDatabase(DEFAULT_DATABASE), ReadOnlyDatabase(shared))
    return DirectoryBasedExampleDatabase(text)


def failure_key(kinds, mode: str) -> bytes:
    """The key a campaign's failing scenes are kept under in the database: one per campaign shape
    (kinds and mode), so runs of other kinds or modes do not mix."""
    return f"acconform:{','.join(kinds)}:{mode}".encode()


class SavedFailures:
    """Failing scenes kept across campaigns, and shared between shards and machines, in a Hypothesis
    example database (`example_database`): under the campaign's `failure_key`, one value per
    shrunk scene, its JSON.

    The values are scenes, not Hypothesis' choice sequences: the campaign runs them first, as they
    are, so they replay whatever the strategies draw today. A directory database writes each
    value whole then renames it, so workers and shards sharing one never read half a scene; a
    value that does not read as a scene (another version) is skipped."""

    def __init__(self, database, key: bytes):
        self.db = example_database(database)
        self.key = key

    def scenes(self) -> list[Scene]:
        found = []
        for value in sorted(self.db.fetch(self.key)):  # sorted: the same order whoever wrote them
            try:
                found.append(Scene.loads(value.decode()))
            except (UnicodeDecodeError, ValueError, AcconformError):
                continue
        return found

    def save(self, scene: Scene) -> None:
        value = scene.dumps().encode()
        self.db.save(self.key, value)
        if value not in set(self.db.fetch(self.key)):  # Hypothesis' databases drop a failed write silently
            # the difference is still reported and written as a case file
            print(f"acconform: cannot keep the failing scene in {self.db!r}", file=sys.stderr)

    def forget(self, scene: Scene) -> None:
        self.db.delete(self.key, scene.dumps().encode())


@dataclass(slots=True)
class Found:
    """One difference found (and shrunk where the campaign can shrink)."""

    case: Case
    path: Path | None = None
    signature: tuple[str, ...] = ()
    # its first divergence (`check` fills it after the campaign: acconform.explain.triage): the group it
    # is counted in, and the known ACE-versus-retail divergence it matches, if any
    group: str = ""
    known: str = ""

    @property
    def group_key(self) -> str:
        return self.group or "differs in " + ", ".join(self.signature)

    @property
    def shrunk(self) -> bool:
        return self.case.shrink.against != "none"


@dataclass(slots=True)
class Result:
    cases: int = 0  # scenes taken: compared + skipped (each once; shrinking's runs are not cases)
    found: list[Found] = field(default_factory=list)
    elapsed: float = 0.0
    source: str = "generative"
    timings: Counter = field(default_factory=Counter)  # seconds in "draw" (a campaign's scenes), "port", "oracle", "compare"
    skipped: Counter = field(default_factory=Counter)  # scenes the port cannot run, by reason
    interrupted: bool = False  # Ctrl-C ended the campaign early
    failures_fallback: str | None = None  # why case files went to a temporary directory instead
    versions: Versions | None = None  # of the oracle (None: per-process oracle, not asked in this process)
    shrink_runs: int = 0  # scenes run while shrinking (not counted in cases)
    unreadable: list[str] = field(default_factory=list)  # replayed items that did not load, each naming where
    ace_note: str | None = None  # the live oracle's ACE is not the one the port follows (oracle/identity.py)

    @property
    def ok(self) -> bool:
        return not self.found

    @property
    def compared(self) -> int:
        return self.cases - sum(self.skipped.values())


def scene_hash(scene: Scene) -> str:
    from . import deep
    from .codec import compact

    return hashlib.sha256(deep.retrying(compact, scene.to_json).encode()).hexdigest()


def signature(diffs: list[Difference]) -> tuple[str, ...]:
    """What kind of failure: the differing fields, vector indices dropped."""
    return tuple(sorted({d.field.split("[", 1)[0] for d in diffs}))


def guarded(backend: Backend, scene: Scene) -> Outcome:
    """A backend's outcome; an exception escaping it becomes the outcome's error (a verdict)."""
    try:
        return backend(scene)
    except Exception as e:  # noqa: BLE001 - a crash on one side is a difference, not a runner crash
        return Outcome(error=f"{type(e).__name__}: {e}")


def ace_note_of(oracle: Backend) -> str | None:
    """The oracle's note when its ACE is not the one the port follows (a live oracle's; None otherwise)."""
    owner = getattr(oracle, "__self__", oracle)
    try:
        note = getattr(owner, "ace_note", None)
    except Exception:  # noqa: BLE001 - a per-process oracle that cannot load has said why already
        return None
    return note if isinstance(note, str) else None


def versions_of(port: Backend, oracle: Backend) -> Versions:
    owner = getattr(oracle, "__self__", oracle)  # a bound `oracle.run` carries its oracle
    v = getattr(owner, "versions", None)
    if isinstance(v, Versions):
        return Versions(__version__, v.ace, v.runtime)
    if isinstance(v, dict):
        return Versions(__version__, str(v.get("ace", "")), str(v.get("runtime", "")))
    return Versions(__version__, str(getattr(owner, "name", "") or ""), "")


def run_case(port: Backend, oracle: Backend, scene: Scene, mode: str, timings: Counter):
    """One scene through both backends and the comparator, adding each step's time to `timings`."""
    t0 = time.perf_counter()
    a = guarded(port, scene)
    t1 = time.perf_counter()
    b = guarded(oracle, scene)
    t2 = time.perf_counter()
    diffs = compare(a, b, mode)
    timings["port"] += t1 - t0
    timings["oracle"] += t2 - t1
    timings["compare"] += time.perf_counter() - t2
    return a, b, diffs


def make_case(scene, a: Outcome, b: Outcome, diffs, seed, mode, versions, implementation=None,
              shrink: Shrink | None = None) -> Case:
    """The case of a difference; a tick scene's first differing tick and field is its first line. The
    values of an implementation under test (--impl) are labelled `impl=`, the built-in port's `port=`."""
    first = first_tick_difference(diffs)
    if first is not None:
        diffs = [first] + [d for d in diffs if d is not first]
    lines = render(diffs, tested_label(implementation))
    return Case(scene=scene, port=a, oracle=b, differences=tuple(lines), seed=str(seed), mode=mode,
                versions=versions, implementation=implementation, shrink=shrink or Shrink())


def tested_label(implementation) -> str:
    """How the tested side's values are labelled where a human reads them: "impl" for an
    implementation under test (an `ImplementationRun`, or a backend with a command), "port" for
    the built-in port, which is what "port" means everywhere else."""
    return "port" if implementation is None or getattr(implementation, "command", None) is None else "impl"


def implementation_run(port: Backend):
    """What a case records of the implementation under test (None: the built-in port)."""
    info = getattr(port, "case_implementation", None)
    return info() if info is not None else None


def shrunk_against(oracle: Backend) -> str:
    """The label of a case Hypothesis shrank against `oracle`: "port" when the built-in port
    stands in for ACE, else "ace"."""
    from .impl import BuiltinPort

    owner = getattr(oracle, "__self__", oracle)
    return "port" if isinstance(owner, BuiltinPort) else "ace"


def write_case(case: Case, failures_dir: str | Path) -> Path:
    path = Path(failures_dir) / f"case-{scene_hash(case.scene)[:12]}.json"
    return write_document(path, case)


def check_writable(directory: str | Path, what: str = "--failures") -> Path:
    """`directory`, created if need be, after writing and removing a probe file in it; else exit 2."""
    d = Path(directory)
    _no_file_in_the_way(d, what)
    try:
        d.mkdir(parents=True, exist_ok=True)
        with tempfile.NamedTemporaryFile(dir=d, prefix=".acconform-probe-", buffering=0) as probe:
            probe.write(b"\n")  # a full disk takes a new empty file, not a byte
    except OSError as e:
        raise AcconformError(f"{what} {d}: cannot write there ({e.strerror or e}); choose a writable directory") from None
    return d


def _no_file_in_the_way(d: Path, what: str) -> None:
    """Exit 2 when `d`, or the folder it would be made in, is a file: it can never be a directory."""
    for p in (d, *d.parents):
        if p.exists():
            if not p.is_dir():
                raise AcconformError(f"{what} {d}: cannot write there ({p} is a file, not a directory); "
                                     "choose a writable directory")
            return


def check_failures_dir(directory: str | Path, what: str = "--failures") -> Path:
    """The directory case files will go to, checked before a campaign without creating anything: it is
    made when the first difference is written (a clean campaign in a read-only folder writes nothing).
    Exit 2 only when it can never be a directory; one that cannot be written when a difference is
    found sends the cases to a temporary directory the summary names (`save_cases`)."""
    d = Path(directory)
    _no_file_in_the_way(d, what)
    return d


def save_output(path: str | Path, option: str, write) -> str | None:
    """`write(path)` for a report a job writes when it ends (--json, --junit); when that fails (its
    directory went away during the run), the report goes to a temporary file instead. Returns a
    warning naming where it went, or None."""
    try:
        write(path)
        return None
    except OSError as e:
        fd, fallback = tempfile.mkstemp(prefix="acconform-", suffix=Path(path).suffix or ".out")
        os.close(fd)
        write(fallback)
        return f"could not write {option} {path} ({e.strerror or e}); it is in {fallback}"


def check_output_file(path: str | Path, option: str) -> Path:
    """A file a job will write when it ends, checked before it starts: not a directory, in a writable one."""
    p = Path(path)
    if p.is_dir():
        raise AcconformError(f"{option} {p}: is a directory; give a file name")
    if not p.parent.is_dir():
        raise AcconformError(f"{option} {p}: no directory {p.parent}")
    check_writable(p.parent, f"{option} {p}:")
    return p


def save_cases(result: "Result", failures_dir: str | Path) -> None:
    """Write every found case; if `failures_dir` fails, fall back to a temporary directory (never lose one)."""
    target = Path(failures_dir)
    for f in result.found:
        try:
            f.path = write_case(f.case, target)
        except OSError as e:
            if result.failures_fallback is not None:
                raise
            fallback = Path(tempfile.mkdtemp(prefix="acconform-failures-"))
            result.failures_fallback = f"could not write to {target} ({e.strerror or e}); case files are in {fallback}"
            target = fallback
            f.path = write_case(f.case, target)


class _Stop(BaseException):
    """Ends a Hypothesis run at once (not an Exception, so Hypothesis neither catches nor shrinks it)."""


class _Mismatch(Exception):
    pass


def _duration(seconds: float) -> str:
    seconds = max(int(round(seconds)), 0)
    if seconds < 60:
        return f"{seconds} s"
    m, sec = divmod(seconds, 60)
    if m < 60:
        return f"{m} min {sec:02d} s"
    h, m = divmod(m, 60)
    return f"{h} h {m:02d} min"


class Progress:
    """A plain-text progress line on stderr, with the rate and an ETA: redrawn in place on a
    terminal (at most 5 times a second); otherwise (piped, a log file) a line every
    `PIPE_EVERY` seconds and one at the end. `check`, `bench` and `runtime-diff` use it.

    `update(done, found)`: `found` (differences so far) is shown when not None; `doing` (e.g. what
    shrinking a difference has run so far) is shown in place of the rate and ETA while it lasts."""

    PIPE_EVERY = 5.0

    def __init__(self, total: int, enabled: bool, stream=None, unit: str = "cases", label: str = ""):
        self.total = max(total, 1)
        self.enabled = enabled
        self.stream = stream or sys.stderr
        self.tty = hasattr(self.stream, "isatty") and self.stream.isatty()
        self.unit = unit
        self.label = label
        self.start = time.monotonic()
        self.last = 0.0
        self.last_line = self.start  # when a piped line was last written

    def line(self, done: int, found: int | None = None, now: float | None = None, doing: str = "") -> str:
        now = time.monotonic() if now is None else now
        elapsed = max(now - self.start, 1e-9)
        frac = min(done / self.total, 1.0)
        rate = done / elapsed
        width = 30
        bar = "#" * int(frac * width) + "-" * (width - int(frac * width))
        text = f"{self.label}[{bar}] {done}/{self.total} {self.unit}"
        if found is not None:
            text += f"  {found} difference{'s' if found != 1 else ''}"
        if doing:
            return f"{text}  {doing}"
        text += f"  {rate:.1f} {self.unit}/s" if rate < 10 else f"  {rate:.0f} {self.unit}/s"
        if done >= self.total:
            text += f"  took {_duration(elapsed)}"
        elif done > 0:
            text += f"  ETA {_duration((self.total - done) / rate)}"
        return text

    def update(self, done: int, found: int | None = None, force: bool = False, doing: str = "") -> None:
        if not self.enabled:
            return
        now = time.monotonic()
        if not force and now - self.last < 0.2:
            return
        self.last = now
        if self.tty:
            self.stream.write("\r" + self.line(done, found, now, doing) + "\033[K")
            self.stream.flush()
        elif force or now - self.last_line >= self.PIPE_EVERY:
            self.last_line = now
            self.stream.write(self.line(done, found, now, doing) + "\n")
            self.stream.flush()

    def close(self, done: int, found: int | None = None) -> None:
        self.update(done, found, force=True)
        if self.enabled and self.tty:
            self.stream.write("\n")
            self.stream.flush()


class Status:
    """One line saying what a job is doing before its cases start (loading a corpus, ...): on a
    terminal `say` redraws it in place (at most 5 times a second) and `done` leaves its summary; piped
    (a log file), nothing until `done`'s one line, unless a wait goes on past `Progress.PIPE_EVERY`
    seconds: then one line every so often says what it is still doing."""

    def __init__(self, enabled: bool, stream=None, prefix: str = ""):
        self.enabled = enabled
        self.stream = stream or sys.stderr
        self.tty = hasattr(self.stream, "isatty") and self.stream.isatty()
        self.prefix = prefix
        self.last = 0.0
        self.last_line = time.monotonic()

    def say(self, text: str) -> None:
        if not self.enabled:
            return
        now = time.monotonic()
        if self.tty and now - self.last >= 0.2:
            self.last = now
            self.stream.write(f"\r{self.prefix}{text}\033[K")
            self.stream.flush()
        elif not self.tty and now - self.last_line >= Progress.PIPE_EVERY:
            self.last_line = now
            self.stream.write(f"{self.prefix}{text}\n")
            self.stream.flush()

    def done(self, text: str) -> None:
        if not self.enabled:
            return
        self.stream.write(("\r" if self.tty else "") + f"{self.prefix}{text}" + ("\033[K\n" if self.tty else "\n"))
        self.stream.flush()


# ---------------------------------------------------------------- one worker's campaign

# The port's objects hold reference cycles (a PhysicsObj and its PartArray, a cell and its
# landblock), so every case leaves cyclic garbage, and Hypothesis allocates heavily while it
# draws. With CPython's default thresholds (700, 10, 10) the collector runs every few hundred
# microseconds and keeps re-walking the long-lived objects (modules, Hypothesis' caches, the
# pythonnet bridge). Freezing what exists before the campaign and collecting less often made
# the port 12% faster per case (5.85 -> 5.10 ms, one run) with no visible memory cost.
GC_THRESHOLDS = (20000, 20, 20)


@contextlib.contextmanager
def campaign_gc():
    """The collector tuned for a campaign (see GC_THRESHOLDS); restored afterwards."""
    old = gc.get_threshold()
    gc.collect()
    gc.freeze()
    gc.set_threshold(*GC_THRESHOLDS)
    try:
        yield
    finally:
        gc.set_threshold(*old)
        gc.unfreeze()


def boundary_scores(trace) -> dict[str, float]:
    """How close the run came to each exact boundary, as a score to raise: -log2(1 + ulps), so
    the last few ulps weigh as much as the first thousands."""
    if trace is None:
        return {}
    return {name: -math.log2(1 + ulps) for name, ulps in trace.closest.items()}


# After this share of a round's budget, half the scenes are the closest scene yet to a boundary with
# one choice moved (Hypothesis' own targeting starts at half its budget too).
TARGET_AFTER = 0.5
HANDOFF_KEY = b"acconform:handoff"  # the in-memory database that hands a found difference to Hypothesis


def _nudged(choices: tuple, rng) -> tuple:
    """`choices` with one changed a little: an integer by 1 or a power of 2, a float by a relative
    power of 2 (down to float32's last bits), a boolean flipped."""
    if not choices:
        return choices
    i = rng.randrange(len(choices))
    v = choices[i]
    if type(v) is bool:
        v = not v
    elif type(v) is int:
        v += rng.choice((-1, 1)) * (1 << rng.randrange(0, 9) if rng.random() < 0.5 else 1)
    else:
        v += rng.choice((-1.0, 1.0)) * (abs(v) or 1.0) * 2.0 ** -rng.randrange(1, 26)
    return choices[:i] + (v,) + choices[i + 1:]


def _generative(port: Backend, oracle: Backend, r: Result, *, kinds, n: int, seed: int, mode: str,
                keep_going: bool, database, tick, should_stop, versions: Versions,
                shrink_budget: int | None = None, shrinking=None) -> None:
    """Compare up to `n` drawn scenes; add each new kind of difference (shrunk) to `r.found`.

    Scenes are drawn outside Hypothesis' engine (strategies.fast_draw: the strategies and
    Hypothesis' own choice distribution, without its per-choice bookkeeping), from a Random
    seeded by `seed` and the round; past TARGET_AFTER of the budget half of them are the scene
    that came closest to some exact boundary with one choice moved (hill climbing on
    `boundary_scores`). Hypothesis' generation mutator (a span's choices copied over another's)
    is left out: with it 5 of 6 scenes were mutations, and the project's mutants took 3x the
    scenes to find (tests/runner/mutation_report.py: median 138 against 40). A difference is
    handed to Hypothesis as the choice sequence that drew it, and Hypothesis shrinks it as one of
    its own; acconform.shrink then shrinks the scene itself. Scenes the port cannot run are skipped (another
    is drawn: they do not count toward `n`) and counted in `r.skipped`; the scenes shrinking runs
    go to `r.shrink_runs`, and each is told to `shrinking(1)` (the progress line; `shrinking(-k)` when a
    shrink of k runs ends). `shrink_budget`: at most that many smaller scenes are run per
    difference (None: Hypothesis' own limits); past it every candidate passes unrun, so
    Hypothesis' shrinker soon ends with the smallest failing scene it ran; 0: differences are
    written as drawn."""
    import random

    from .shrink import scene_bytes
    from .strategies import check_kinds, scenes
    from .strategies.determinism import pinned_constants
    from .strategies.fast_draw import FastDrawer

    kinds = check_kinds(kinds)
    strategy = scenes(kinds)
    saved = SavedFailures(database, failure_key(kinds, mode)) if database else None
    known: set[tuple[str, ...]] = set()
    if hasattr(port, "trace_boundaries"):  # the built-in port: aim the search at exact boundaries
        port.trace_boundaries = True
    unsupported = either_unsupported(getattr(port, "unsupported", None), oracle_filter(oracle))
    # a process (acconform.protocol.Implementation) is sent the next scene before the current one runs;
    # the built-in port climbs on each scene's trace, so it draws after each case
    ahead_of = getattr(port, "prefetch", None) if not hasattr(port, "trace_boundaries") else None
    against = shrunk_against(oracle)
    what = "live ACE" if against == "ace" else "the built-in port"

    def found(scene, ran_case, impl, shrink: Shrink) -> None:
        """A difference, with what the implementation said of the run that made it (`impl`)."""
        a, b, diffs = ran_case
        sig = signature(diffs)
        known.add(sig)
        if saved is not None:
            saved.save(scene)
        r.found.append(Found(make_case(scene, a, b, diffs, seed, mode, versions, impl, shrink), None, sig))

    def compared_case(scene):
        """The scene's case (port, ACE, differences), or None when the port cannot run it (skipped)."""
        if should_stop():
            raise _Stop
        why = unsupported(scene) if unsupported is not None else None
        if why:
            r.skipped[why] += 1
            r.cases += 1
            return None
        ran_case = run_case(port, oracle, scene, mode, r.timings)
        r.cases += 1
        tick(1)
        return ran_case

    try:
        compared = 0
        # the database's failing scenes first, as they are (each was shrunk when it was found)
        for scene in saved.scenes()[:n] if saved is not None else ():
            ran_case = compared_case(scene)
            if ran_case is None:
                continue
            compared += 1
            if ran_case[2] and signature(ran_case[2]) not in known:
                found(scene, ran_case, implementation_run(port),
                      Shrink(against, f"the example database's scene, shrunk by Hypothesis against {what}",
                             scene_bytes(scene), scene_bytes(scene)))
                if not keep_going:
                    return
            elif not ran_case[2]:
                saved.forget(scene)

        round_ = 0
        with pinned_constants():
            while compared < n:
                rng = random.Random(seed * 7919 + round_)
                drawer = FastDrawer(strategy, rng.getrandbits(64))
                best: dict[str, tuple[float, tuple]] = {}  # boundary -> (closest score, the choices that drew it)
                budget = n - compared
                climb_from = int(budget * TARGET_AFTER)
                ran = skipped = 0
                hit = None

                def draw():
                    prefix = ()
                    if ran >= climb_from and best and rng.random() < 0.5:
                        prefix = _nudged(best[rng.choice(sorted(best))][1], rng)
                    t0 = time.perf_counter()
                    drawn = drawer.draw(prefix)
                    r.timings["draw"] += time.perf_counter() - t0
                    if ahead_of is not None:
                        ahead_of(drawn[0])
                    return drawn

                nxt = None
                while ran < budget and skipped < 10 * budget + 100:  # Hypothesis' bound on invalid draws too
                    scene, choices = nxt if nxt is not None else draw()
                    # an implementation that takes scenes ahead works on this one while the next is drawn
                    nxt = draw() if ahead_of is not None and ran + 1 < budget else None
                    ran_case = compared_case(scene)
                    if ran_case is None:
                        skipped += 1
                        continue
                    ran += 1
                    for name, score in boundary_scores(getattr(port, "last_trace", None)).items():
                        if name not in best or score > best[name][0]:
                            best[name] = (score, choices)
                    if ran_case[2] and signature(ran_case[2]) not in known:
                        hit = (scene, choices, ran_case, implementation_run(port))
                        break
                compared += ran
                round_ += 1
                if hit is None:  # the budget is spent, or the port can run none of the scenes drawn
                    break
                _shrink_found(port, oracle, r, hit, strategy=strategy, mode=mode, known=known, found=found,
                              shrink_budget=shrink_budget, should_stop=should_stop, what=what, against=against,
                              seed=seed * 7919 + round_, shrinking=shrinking or (lambda k: None))
                if not keep_going:
                    break
    except _Stop:
        return


def _shrink_found(port: Backend, oracle: Backend, r: Result, hit, *, shrinking, **how) -> None:
    """`_shrink_hit`, telling `shrinking(1)` of each scene it runs and `shrinking(-k)` when its k runs end
    (however it ends: a Ctrl-C, a stop): the progress line shows a shrink while it lasts."""
    ran = [0]

    def counted(k: int) -> None:
        ran[0] += k
        shrinking(k)

    kept = len(r.found)
    # shrinking's runs are timed as shrinking, not as the cases' port and ACE time
    t0, cases_time = time.perf_counter(), {k: r.timings[k] for k in ("port", "oracle", "compare")}
    try:
        _shrink_hit(port, oracle, r, hit, shrinking=counted, **how)
    except (_Stop, KeyboardInterrupt):  # stopped mid-shrink (Ctrl-C): the difference is kept, as drawn
        if len(r.found) == kept:
            from .shrink import scene_bytes

            scene0, _choices, case0, impl0 = hit
            size = scene_bytes(scene0)
            how["found"](scene0, case0, impl0, Shrink("none", "not shrunk: the campaign was stopped while it was "
                                                      "being shrunk", size, size))
        raise
    finally:
        shrinking(-ran[0])
        for k, v in cases_time.items():
            r.timings[k] = v
        r.timings["shrink"] += time.perf_counter() - t0


def _shrink_hit(port: Backend, oracle: Backend, r: Result, hit, *, strategy, mode: str, known, found,
                shrink_budget, should_stop, what: str, against: str, seed: int, shrinking) -> None:
    """Hand a difference to Hypothesis as the choices that drew it: Hypothesis replays them from an
    in-memory example database and shrinks the scene as one of its own, and `found` gets the case."""
    from hypothesis import HealthCheck, Phase, Verbosity, given, settings
    from hypothesis import seed as hseed
    from hypothesis.database import InMemoryExampleDatabase, choices_to_bytes

    from .shrink import DEFAULT_BUDGET, no_larger, scene_bytes, shrink_scene, size

    scene0, choices, case0, impl0 = hit
    size0 = scene_bytes(scene0)
    sig0 = signature(case0[2])
    if shrink_budget == 0:
        found(scene0, case0, impl0, Shrink("none", "written as drawn, not shrunk: the shrink budget is 0", size0, size0))
        return
    last: list = []
    failing: dict[str, list] = {}  # scene_hash -> [scene, case, impl] of every failing scene run while shrinking
    runs = [0]
    unsupported = either_unsupported(getattr(port, "unsupported", None), oracle_filter(oracle))

    def differential(scene):
        if should_stop():
            raise _Stop
        if unsupported is not None and unsupported(scene):
            return
        if shrink_budget is not None and runs[0] >= shrink_budget:
            # Hypothesis runs its smallest failing scene once more, to report it: that is not always the
            # last one that failed (passing it then made Hypothesis raise FlakyFailure out of the campaign)
            seen = failing.get(scene_hash(scene))
            if seen is not None:
                last[:] = seen
                mismatch(seen[1][2])
            return
        ran_case = run_case(port, oracle, scene, mode, r.timings)
        r.shrink_runs += 1
        runs[0] += 1
        shrinking(1)
        diffs = ran_case[2]
        if diffs and signature(diffs) not in known:
            last[:] = [scene, ran_case, implementation_run(port)]
            failing[scene_hash(scene)] = list(last)
            mismatch(diffs)

    def mismatch(diffs):
        """The one place a failing scene is reported to Hypothesis: it tells failures apart by where
        they were raised, and a replay raising from another line is "inconsistent" (FlakyFailure)."""
        raise _Mismatch(signature(diffs))

    db = InMemoryExampleDatabase()
    db.save(HANDOFF_KEY + b".secondary", choices_to_bytes(choices))
    test = given(strategy)(differential)
    test._hypothesis_internal_database_key = HANDOFF_KEY
    test = settings(max_examples=1, database=db, deadline=None, verbosity=Verbosity.quiet,
                    suppress_health_check=list(HealthCheck), report_multiple_bugs=False,
                    phases=[Phase.reuse, Phase.shrink])(hseed(seed)(test))
    try:
        test()
    except _Mismatch:
        scene, ran_case, impl = last
        shrink = Shrink(against, f"shrunk by Hypothesis against {what}", size0)
    else:  # Hypothesis' replay of the choices did not fail as the draw did
        scene, ran_case, impl = scene0, case0, impl0
        shrink = Shrink("none", f"not shrunk: Hypothesis' replay of the drawn scene did not differ ({', '.join(sig0)})",
                        size0)
    # Hypothesis shrinks the choices, and fewer choices can still draw a larger scene: one larger than the
    # drawn scene in any measure is dropped (acconform.shrink.no_larger), and the drawn scene shrunk instead
    if not no_larger(scene0, scene):
        grew = ", ".join(size(scene).exceeds(size(scene0)))
        scene, ran_case, impl = scene0, case0, impl0
        shrink = Shrink("none", f"not shrunk by Hypothesis: its smallest failing scene was larger than the drawn one ({grew})",
                        size0)
    # then the scene itself (acconform.shrink: fewer objects and cells, a shorter path, ...), never larger
    sig = signature(ran_case[2])
    smaller: list = []

    def still_fails(s: Scene) -> bool:
        if should_stop():
            raise _Stop
        if unsupported is not None and unsupported(s):
            return False
        c = run_case(port, oracle, s, mode, r.timings)
        r.shrink_runs += 1
        runs[0] += 1
        shrinking(1)
        if c[2] and signature(c[2]) == sig:
            smaller[:] = [s, c, implementation_run(port)]
            return True
        return False

    left = DEFAULT_BUDGET if shrink_budget is None else shrink_budget - runs[0]
    if left > 0:
        _, tried = shrink_scene(scene, still_fails, left)
        if smaller:
            scene, ran_case, impl = smaller
            shrink = Shrink(against, f"{shrink.note if shrink.against != 'none' else 'drawn'}, then its scene by "
                                     f"acconform.shrink against {what} ({tried} smaller scenes tried)", size0)
    found(scene, ran_case, impl, replace(shrink, bytes_after=scene_bytes(scene)))


REPLAYED = Shrink("none", "replayed as recorded: not shrunk")


def scene_filter(port: Backend, oracle: Backend | None = None):
    """The port's `unsupported(scene)`, or None for a port that `runs_every_scene` (the built-in port
    in exact mode, an implementation whose handshake lists every kind and feature): it passes no
    scene over, so no scene need be read to be weighed. With `oracle`, the oracle's too (a live ACE
    that cannot run some scenes: LiveOracle.unsupported)."""
    mine = None if getattr(port, "runs_every_scene", False) else getattr(port, "unsupported", None)
    return either_unsupported(mine, oracle_filter(oracle))


def oracle_filter(oracle: Backend | None):
    """The oracle's `unsupported(scene)` (a bound `oracle.run` carries its oracle), or None."""
    owner = getattr(oracle, "__self__", oracle)
    f = getattr(owner, "unsupported", None) if owner is not None else None
    return f if callable(f) else None


def either_unsupported(a, b):
    """One `unsupported(scene)` from two (either may be None): the first reason given."""
    if a is None or b is None:
        return a or b
    return lambda scene: a(scene) or b(scene)


def _replay(port: Backend, oracle: Backend, r: Result, items: Sequence, indices: Iterable[int], *, mode: str,
            keep_going: bool, tick, should_stop, versions: Versions, seed) -> None:
    """Replay `items[i]` for i in `indices` as they are; add each difference (unshrunk) to `r.found`.

    `items` may load lazily (a corpus sample parses each record when asked): one that does not
    load (an AcconformError naming where) is listed in `r.unreadable` and skipped with
    `keep_going`, else the replay stops. A port that can take a scene ahead (`port.prefetch`, an
    implementation process) is sent the next scene before the current answer is read, so it
    computes while this process compares.

    Recorded scenes (`items.text(i)`) through an implementation process that runs every scene are
    sent as their recorded JSON text, unparsed; an answer that is the recorded outcome's text is
    counted as agreeing without reading either. Only a scene whose answer differs in its text is
    read, run through the oracle and compared, so its case is what the slower path would write.
    """
    indices = iter(indices)
    stop = [False]
    texts = getattr(items, "text", None) if getattr(port, "runs_every_scene", False) else None

    def unreadable(e: AcconformError) -> None:
        r.unreadable.append(str(e))
        if not keep_going:
            stop[0] = True

    def load(i):
        try:
            return items[i]
        except AcconformError as e:
            unreadable(e)
            return None

    def take():
        """(index, what to send: the recorded text or the scene), or None at the end."""
        for i in indices:
            if texts is not None:
                try:
                    text = texts(i)  # read from its shard now: a shard cut short since loading fails here
                except AcconformError as e:
                    unreadable(e)
                    if stop[0]:
                        return None
                    continue
                if text is not None:
                    return i, text
            scene = load(i)
            if scene is not None:
                return i, scene
            if stop[0]:
                return None
        return None

    prefetch = getattr(port, "prefetch", None)
    unsupported = scene_filter(port, oracle)
    cur = take()
    if prefetch is not None and cur is not None:
        prefetch(cur[1])
    while cur is not None and not should_stop():
        nxt = None if stop[0] else take()
        if prefetch is not None and nxt is not None:
            prefetch(nxt[1])
        i, scene = cur
        cur = nxt
        if not isinstance(scene, Scene):  # a recorded text: compared as text first
            t0 = time.perf_counter()
            a = guarded(port.run_text, scene)
            r.timings["port"] += time.perf_counter() - t0
            if a is None:
                r.cases += 1
                tick(1)
                continue
            scene = load(i)
            if scene is None:
                if stop[0]:
                    break
                continue
            t1 = time.perf_counter()
            b = guarded(oracle, scene)
            t2 = time.perf_counter()
            diffs = compare(a, b, mode)
            r.timings["oracle"] += t2 - t1
            r.timings["compare"] += time.perf_counter() - t2
        elif unsupported is not None and (why := unsupported(scene)):
            r.skipped[why] += 1
            r.cases += 1
            tick(1)
            continue
        else:
            a, b, diffs = run_case(port, oracle, scene, mode, r.timings)
        r.cases += 1
        tick(1)
        if diffs:
            case = make_case(scene, a, b, diffs, seed, mode, versions, implementation_run(port), REPLAYED)
            r.found.append(Found(case, None, signature(diffs)))
            if not keep_going:
                break


def _shrink_replayed(r: Result, port: Backend, stand_in: Backend | None, mode: str, budget: int,
                     shrinking=lambda k: None) -> None:
    """Shrink the first replayed difference of each kind against `stand_in` (the built-in port
    standing in for ACE), when it agrees bit for bit with ACE's recorded answer on that scene;
    `shrinking` hears of each scene run (1) and of each shrink's end (-its runs), as in `_shrink_found`."""

    from .shrink import scene_bytes, shrink_scene

    unsupported = getattr(port, "unsupported", None)
    first: dict[tuple[str, ...], str] = {}
    for f in r.found:
        c = f.case
        if f.signature in first:
            f.case = replace(c, shrink=Shrink("none", f"not shrunk: the first case of this kind ({first[f.signature]}) was"))
            continue
        first[f.signature] = scene_hash(c.scene)[:12]
        if stand_in is None:
            continue
        if budget == 0:
            f.case = replace(c, shrink=Shrink("none", "written as recorded, not shrunk: the shrink budget is 0"))
            continue
        ref = guarded(stand_in, c.scene)
        r.shrink_runs += 1
        off = compare(ref, c.oracle, "exact")
        if off:
            f.case = replace(c, shrink=Shrink("none", "written as recorded, not shrunk: the built-in port differs from "
                                              f"ACE's recorded answer on this scene (in {', '.join(signature(off))}), "
                                              "so it cannot stand in for ACE"))
            continue
        before = scene_bytes(c.scene)
        last: list = []
        runs = [0]

        def still_fails(s: Scene) -> bool:
            if unsupported is not None and unsupported(s):
                return False
            r.shrink_runs += 1
            runs[0] += 1
            shrinking(1)
            a, b = guarded(port, s), guarded(stand_in, s)
            d = compare(a, b, mode)
            if d and signature(d) == f.signature:
                last[:] = [s, a, b, d, implementation_run(port)]
                return True
            return False

        try:
            small, tried = shrink_scene(c.scene, still_fails, budget)
        finally:
            shrinking(-runs[0])
        what = ("shrunk against the built-in port standing in for ACE (it agrees with ACE's recorded answer on "
                f"the original scene; the oracle outcome here is the port's); {tried} smaller scenes tried")
        if not last:
            f.case = replace(c, shrink=Shrink("port", what + ", none still differs in the same fields", before, before))
            continue
        s, a, b, d, impl = last
        f.case = make_case(s, a, b, d, c.seed, c.mode, c.versions, impl, Shrink("port", what, before, scene_bytes(s)))


# ---------------------------------------------------------------- workers

_SHARED: dict = {}


def _ignore_sigint() -> None:
    """Pool initializer: Ctrl-C is the parent's to handle (it tells the workers to stop)."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)


# After Ctrl-C, how long the parent waits for its workers to return what they found: a worker
# checks the stop between scenes (milliseconds apart), but one loading ACE (seconds; a facade
# build, 10-30 s) or inside one long scene cannot, and is ended with nothing found yet.
STOP_GRACE = 1.0


@contextlib.contextmanager
def _ctrl_c_as_a_flag():
    """While the parent waits for its workers, the first Ctrl-C appends to the list it yields
    instead of raising KeyboardInterrupt; a second one raises it (stop at once, no summary).

    A KeyboardInterrupt raised at an arbitrary point of the waiting loop can land between a lock's
    acquire and its release -- the shared counter's (then every worker blocks on its next tick) or
    the pool's result condition (then the result never arrives) -- and the campaign hangs. Set
    before the pool forks, so a worker that takes the signal before its initializer ignores it
    only sets its own copy of the flag."""
    if threading.current_thread() is not threading.main_thread():  # signal handlers are the main thread's
        yield []
        return
    pressed: list = []

    def on_sigint(signum, frame):
        if pressed:
            raise KeyboardInterrupt
        pressed.append(signum)

    previous = signal.signal(signal.SIGINT, on_sigint)
    try:
        yield pressed
    finally:
        signal.signal(signal.SIGINT, previous)


def _worker(w: int) -> dict:
    s = _SHARED
    counter, stop = s["counter"], s["stop"]

    def tick(k):
        with counter.get_lock():
            counter.value += k

    def shrinking(k):  # the scenes the workers' shrinks in progress have run, for the parent's progress line
        with s["shrinking"].get_lock():
            s["shrinking"].value += k

    r = Result()
    if s["versions"] is None:  # a per-process oracle: this worker loads its own runtime
        t0 = time.perf_counter()
        s["versions"] = versions_of(s["port"], s["oracle"])
        r.timings["ace_load"] += time.perf_counter() - t0
    with campaign_gc():
        _worker_campaign(w, s, r, tick, shrinking)
    if (r.found or r.unreadable) and not s["keep_going"]:
        stop.set()
    close = getattr(s["port"], "close", None)
    if close is not None:
        close()  # this worker's implementation process
    return {"cases": r.cases, "found": [f.case.to_json() for f in r.found], "timings": dict(r.timings),
            "skipped": dict(r.skipped), "shrink_runs": r.shrink_runs, "unreadable": r.unreadable,
            "ace_note": ace_note_of(s["oracle"])}


def _worker_campaign(w: int, s: dict, r: Result, tick, shrinking) -> None:
    stop = s["stop"]
    if s["replay"] is not None:
        _replay(s["port"], s["oracle"], r, s["replay"], range(w, len(s["replay"]), s["workers"]), mode=s["mode"],
                keep_going=s["keep_going"], tick=tick, should_stop=lambda: stop.is_set(), versions=s["versions"],
                seed=s["seed"])
        return
    stream = s["first_stream"] + w
    _generative(s["port"], s["oracle"], r, kinds=s["kinds"], n=_stream_cases(s["n"], stream, s["streams"]),
                seed=s["seed"] * 1000 + stream, mode=s["mode"],
                keep_going=s["keep_going"], database=s["database"], tick=tick, should_stop=lambda: stop.is_set(),
                versions=s["versions"], shrink_budget=s["shrink_budget"], shrinking=shrinking)


def _stream_cases(n: int, stream: int, streams: int) -> int:
    """The cases of one stream of a live campaign of `n` cases drawn as `streams` streams."""
    return n // streams + (1 if stream < n % streams else 0)


def shard_cases(n: int, shard: tuple[int, int], workers: int) -> int:
    """The cases part K of N (`shard`) of a live campaign of `n` cases on `workers` workers runs."""
    part, parts = shard
    return sum(_stream_cases(n, s, parts * workers) for s in range((part - 1) * workers, part * workers))


def parse_shard(text: str) -> tuple[int, int]:
    """`--shard K/N` as (K, N), 1 <= K <= N; AcconformError (one line, exit 2) otherwise."""
    k, slash, n = text.partition("/")
    if not slash or not k.isdigit() or not n.isdigit() or not 1 <= int(k) <= int(n):
        raise AcconformError(f"--shard {text!r}: expected K/N with 1 <= K <= N, e.g. --shard 2/4")
    return int(k), int(n)


def _merge(result: Result, outs: list[dict], mode: str, generative: bool) -> None:
    """The workers' results as one: counts added; each difference once (a scene two workers both
    found, e.g. a saved failing scene each replayed, is one case; a live campaign keeps one case
    per kind of difference, the first worker's)."""
    seen_scenes: set[str] = set()
    seen_kinds: set[tuple[str, ...]] = set()
    for out in outs:
        result.cases += out["cases"]
        result.timings.update(out["timings"])
        result.skipped.update(out["skipped"])
        result.shrink_runs += out["shrink_runs"]
        result.unreadable.extend(out["unreadable"])
        result.ace_note = result.ace_note or out.get("ace_note")
        for doc in out["found"]:
            case = Case.from_json(doc)
            sig = signature(compare(case.port, case.oracle, mode))
            h = scene_hash(case.scene)
            if h in seen_scenes or (generative and sig in seen_kinds):
                continue
            seen_scenes.add(h)
            seen_kinds.add(sig)
            result.found.append(Found(case, None, sig))


def run_campaign(port: Backend, oracle: Backend, *, kinds=None, n: int = 1000, seed: int = 0, mode: str = "exact",
                 keep_going: bool = False, failures_dir: str | Path | None = "failures",
                 database: str | Path | None = DEFAULT_DATABASE, workers: int = 1, progress: bool = False,
                 replay: Sequence[Scene] | Iterable[Scene] | None = None, stand_in: Backend | None = None,
                 shrink_budget: int | None = None, shard: tuple[int, int] = (1, 1)) -> Result:
    """Compare `n` scenes (or replay `replay`) through port and oracle; see the module doc.

    `shard` (K, N): this run is part K of N disjoint parts of the campaign. Replaying, it takes
    the items K-1, K-1+N, K-1+2N, ...; live, the campaign is drawn as N x `workers` streams
    (worker w of part K draws stream (K-1) x workers + w, with seed x 1000 + its stream), so the N
    parts together draw exactly what one run with N x `workers` workers draws.

    `replay` is a sequence of scenes (or an iterable, listed first); a lazy one (a corpus sample)
    is loaded item by item in the worker that replays it. `stand_in` is what replayed differences
    are shrunk against (the built-in port standing in for ACE; None: not shrunk). Found
    differences are written to `failures_dir` (None: not written). `workers` > 1 forks worker
    processes (the backends are inherited, so any callable works); an oracle marked
    `per_process` (a .NET runtime cannot be forked) is first touched inside each worker.
    """
    from .shrink import DEFAULT_BUDGET

    if mode not in ("exact", "fast"):
        raise AcconformError(f"unknown mode {mode!r}: choose exact or fast")
    per_process = getattr(getattr(oracle, "__self__", oracle), "per_process", False)
    if per_process and workers > 1:
        from .oracle.runtime import loaded_runtime

        if loaded_runtime() is not None:  # a forked worker would start ACE on the parent's runtime and crash
            raise AcconformError(f"this process has already loaded a .NET runtime ({loaded_runtime()}), which forked "
                                 f"workers cannot use: run the live campaign with one worker, or from a process "
                                 f"that has not loaded ACE")
    versions = None if per_process and workers > 1 else versions_of(port, oracle)
    items = None if replay is None else replay if isinstance(replay, Sequence) else list(replay)
    part, parts = shard
    if items is not None and parts > 1:
        items = items[part - 1::parts]
    total = len(items) if items is not None else n
    if items is None and parts > 1:
        total = shard_cases(n, shard, workers)
    bar = Progress(total, progress)
    start = time.monotonic()
    streams, first_stream = workers * parts, (part - 1) * workers  # a sharded live campaign's streams
    workers = max(1, min(workers, total or 1))
    result = Result(source="replay" if items is not None else "generative", versions=versions)
    if versions is not None:  # this process has its oracle loaded already
        result.ace_note = ace_note_of(oracle)
    budget = DEFAULT_BUDGET if items is not None and shrink_budget is None else shrink_budget
    against = ("the built-in port standing in for ACE" if items is not None else
               "live ACE" if shrunk_against(oracle) == "ace" else "the built-in port")
    limit = f" of up to {budget}" if budget is not None else ""
    shrink_runs = [0]  # of the shrinks in progress (one process; the workers' add up in a shared value)

    def shrinking_now(runs: int) -> str:
        """What the progress line says while a difference is shrunk (nothing between shrinks)."""
        scenes = "scene" if runs == 1 and not limit else "scenes"
        return f"shrinking a difference against {against}: {runs}{limit} smaller {scenes} run" if runs > 0 else ""

    def shrinking(k):
        shrink_runs[0] += k
        # the first run of a shrink is shown at once, also piped; then as the bar's cadence allows
        bar.update(count[0], len(result.found), force=k > 0 and shrink_runs[0] == 1,
                   doing=shrinking_now(shrink_runs[0]))

    count = [0]
    if workers == 1:
        def tick(k):
            count[0] += k
            bar.update(count[0], len(result.found), doing=shrinking_now(shrink_runs[0]))

        try:
            with campaign_gc():
                if items is not None:
                    _replay(port, oracle, result, items, range(len(items)), mode=mode, keep_going=keep_going,
                            tick=tick, should_stop=lambda: False, versions=versions, seed=seed)
                elif parts == 1:
                    _generative(port, oracle, result, kinds=kinds, n=n, seed=seed, mode=mode, keep_going=keep_going,
                                database=database, tick=tick, should_stop=lambda: False, versions=versions,
                                shrink_budget=shrink_budget, shrinking=shrinking)
                else:  # part K of a sharded campaign on one worker: its first stream (its only one with cases)
                    _generative(port, oracle, result, kinds=kinds, n=_stream_cases(n, first_stream, streams),
                                seed=seed * 1000 + first_stream, mode=mode,
                                keep_going=keep_going, database=database, tick=tick, should_stop=lambda: False,
                                versions=versions, shrink_budget=shrink_budget, shrinking=shrinking)
        except KeyboardInterrupt:
            result.interrupted = True
    else:
        ctx = multiprocessing.get_context("fork")
        counter = ctx.Value("q", 0)
        shrinking_value = ctx.Value("q", 0)
        stop = ctx.Event()
        _SHARED.update(port=port, oracle=oracle, kinds=kinds, n=n, seed=seed, mode=mode, keep_going=keep_going,
                       database=database, versions=versions, replay=items, workers=workers, counter=counter,
                       stop=stop, first_stream=first_stream, streams=streams if parts > 1 else workers,
                       shrink_budget=shrink_budget, shrinking=shrinking_value)
        try:
            with _ctrl_c_as_a_flag() as ctrl_c, ctx.Pool(workers, initializer=_ignore_sigint) as pool:
                pending = [pool.apply_async(_worker, (w,)) for w in range(workers)]
                stop_by = math.inf
                while not all(p.ready() for p in pending) and time.monotonic() < stop_by:
                    next(p for p in pending if not p.ready()).wait(0.2)
                    if ctrl_c and not result.interrupted:
                        # tell the workers to stop; they return what they have so far
                        result.interrupted = True
                        stop.set()
                        stop_by = time.monotonic() + STOP_GRACE
                    count[0] = counter.value
                    bar.update(count[0], None, doing=shrinking_now(shrinking_value.value))
                outs = [p.get() for p in pending if p.ready()]
                if len(outs) < workers:  # the pool's exit ends them
                    print(f"{chr(10) if bar.enabled and bar.tty else ''}acconform: {workers - len(outs)} of {workers} workers had not stopped {STOP_GRACE:g} s "
                          "after Ctrl-C (loading ACE, or inside one scene): ended", file=sys.stderr, flush=True)
        finally:
            _SHARED.clear()
        _merge(result, outs, mode, generative=items is None)
        if not keep_going:
            result.found = result.found[:1]
    if items is not None and result.found and not result.interrupted:
        t0 = time.perf_counter()
        _shrink_replayed(result, port, stand_in, mode, budget, shrinking)
        result.timings["shrink"] += time.perf_counter() - t0
    if failures_dir is not None:
        save_cases(result, failures_dir)
    result.elapsed = time.monotonic() - start
    bar.close(result.cases, len(result.found))
    return result


def default_workers() -> int:
    return os.cpu_count() or 1
