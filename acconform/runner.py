"""The differential runner: scenes through two backends, compared, differences shrunk and saved.

A backend is any callable ``scene -> Outcome``; the port (acconform.port.run.run_scene) and the
oracle (acconform.oracle.get_oracle().run) are the default pair, and tests pass plain callables
(e.g. a mutated port against the real one).

Two kinds of campaign:

- generative (a live oracle, or any callable pair): Hypothesis draws scenes from
  acconform.strategies.scenes(kinds); a difference fails the example, Hypothesis shrinks it to a
  minimal scene, and the minimal scene is written as a case file. The campaign's database (a
  directory, `SavedFailures`) remembers each shrunk failing scene, so the next run of the same
  kinds and mode tries them first, as explicit examples; one that no longer fails is forgotten.
  Hypothesis' own example database is not used: with one, Hypothesis keeps a Pareto front of every
  target() score, which cost 40-50% of a live campaign's time.
- replay (a recorded oracle): Hypothesis cannot ask a recording about scenes it never saw, so
  the recorded scenes are replayed as they are and a difference is saved unshrunk.

Deterministic for a seed (and a worker count): worker w draws with seed (seed, w). With
``keep_going`` a campaign goes on after a difference, ignoring differences with the same
*signature* (the set of differing field paths) so each shrink finds a new kind of failure.

A port backend may name scenes it cannot run (``port.unsupported(scene) -> reason or None``, as
an implementation under test does from its handshake): those are skipped and counted by reason
in `Result.skipped`, never compared. Ctrl-C ends a campaign early with what it has found so far
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
import time
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable, Iterable

from . import __version__
from .case import Case, Versions, write_document
from .compare import Difference, compare, render
from .errors import AcconformError
from .outcome import Outcome
from .scene import Scene

Backend = Callable[[Scene], Outcome]

DEFAULT_DATABASE = Path(".hypothesis") / "acconform"


class SavedFailures:
    """Failing scenes kept across campaigns: one JSON file per scene under DIR/<campaign shape>/.

    Each file is written whole then renamed, so workers sharing the directory never read half a
    scene; a file that does not read as a scene (another version, a partial copy) is skipped."""

    def __init__(self, root, shape: str):
        self.dir = Path(root) / hashlib.sha256(shape.encode()).hexdigest()[:16]

    @staticmethod
    def _name(scene: Scene) -> str:
        return hashlib.sha256(scene.dumps().encode()).hexdigest()[:24] + ".json"

    def scenes(self) -> list[Scene]:
        found = []
        for path in sorted(self.dir.glob("*.json")) if self.dir.is_dir() else ():
            try:
                found.append(Scene.loads(path.read_text()))
            except (OSError, ValueError, AcconformError):
                continue
        return found

    def save(self, scene: Scene) -> None:
        try:
            self.dir.mkdir(parents=True, exist_ok=True)
            tmp = self.dir / f".{os.getpid()}.tmp"
            tmp.write_text(scene.dumps())
            tmp.replace(self.dir / self._name(scene))
        except OSError as e:  # the difference is still reported and written as a case file
            print(f"acconform: cannot keep the failing scene in {self.dir}: {e.strerror or e}", file=sys.stderr)

    def forget(self, scene: Scene) -> None:
        try:
            (self.dir / self._name(scene)).unlink(missing_ok=True)
        except OSError:
            pass


@dataclass(slots=True)
class Found:
    """One difference found (and shrunk where the campaign can shrink)."""

    case: Case
    path: Path | None = None
    signature: tuple[str, ...] = ()
    shrunk: bool = False


@dataclass(slots=True)
class Result:
    cases: int = 0
    found: list[Found] = field(default_factory=list)
    elapsed: float = 0.0
    source: str = "generative"
    timings: Counter = field(default_factory=Counter)  # seconds in "port", "oracle", "compare"
    skipped: Counter = field(default_factory=Counter)  # scenes the port cannot run, by reason
    interrupted: bool = False  # Ctrl-C ended the campaign early
    failures_fallback: str | None = None  # why case files went to a temporary directory instead
    versions: Versions | None = None  # of the oracle (None: per-process oracle, not asked in this process)

    @property
    def ok(self) -> bool:
        return not self.found

    @property
    def compared(self) -> int:
        return self.cases - sum(self.skipped.values())


def scene_hash(scene: Scene) -> str:
    from .codec import dumps_compact

    from . import deep

    return hashlib.sha256(deep.retrying(lambda: dumps_compact(scene.to_json())).encode()).hexdigest()


def signature(diffs: list[Difference]) -> tuple[str, ...]:
    """What kind of failure: the differing fields, vector indices dropped."""
    return tuple(sorted({d.field.split("[", 1)[0] for d in diffs}))


def guarded(backend: Backend, scene: Scene) -> Outcome:
    """A backend's outcome; an exception escaping it becomes the outcome's error (a verdict)."""
    try:
        return backend(scene)
    except Exception as e:  # noqa: BLE001 - a crash on one side is a difference, not a runner crash
        return Outcome(error=f"{type(e).__name__}: {e}")


def versions_of(port: Backend, oracle: Backend) -> Versions:
    owner = getattr(oracle, "__self__", oracle)  # a bound `oracle.run` carries its oracle
    v = getattr(owner, "versions", None)
    if isinstance(v, Versions):
        return Versions(__version__, v.ace, v.runtime)
    if isinstance(v, dict):
        return Versions(__version__, str(v.get("ace", "")), str(v.get("runtime", "")))
    return Versions(__version__, str(getattr(owner, "name", "") or ""), "")


def run_case(port: Backend, oracle: Backend, scene: Scene, mode: str, timings: Counter,
             skipped: Counter | None = None):
    """One scene through both backends and the comparator, adding each step's time to `timings`.

    None (and the reason counted in `skipped`) when the port says it cannot run the scene.
    """
    unsupported = getattr(port, "unsupported", None)
    if unsupported is not None and skipped is not None:
        why = unsupported(scene)
        if why:
            skipped[why] += 1
            return None
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


def make_case(scene, a: Outcome, b: Outcome, diffs, seed, mode, versions) -> Case:
    return Case(scene=scene, port=a, oracle=b, differences=tuple(render(diffs)), seed=str(seed), mode=mode,
                versions=versions)


def write_case(case: Case, failures_dir: str | Path) -> Path:
    path = Path(failures_dir) / f"case-{scene_hash(case.scene)[:12]}.json"
    return write_document(path, case)


def check_writable(directory: str | Path, what: str = "--failures") -> Path:
    """`directory`, created if need be, after writing and removing a probe file in it; else exit 2."""
    d = Path(directory)
    _no_file_in_the_way(d, what)
    try:
        d.mkdir(parents=True, exist_ok=True)
        with tempfile.NamedTemporaryFile(dir=d, prefix=".acconform-probe-"):
            pass
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


class Progress:
    """A plain-text progress bar on stderr (redrawn in place on a terminal, a line per 10% otherwise)."""

    def __init__(self, total: int, enabled: bool, stream=None):
        self.total = max(total, 1)
        self.enabled = enabled
        self.stream = stream or sys.stderr
        self.tty = hasattr(self.stream, "isatty") and self.stream.isatty()
        self.start = time.monotonic()
        self.last = 0.0
        self.last_decile = -1

    def update(self, done: int, found: int, force: bool = False) -> None:
        if not self.enabled:
            return
        now = time.monotonic()
        if not force and now - self.last < 0.2:
            return
        self.last = now
        frac = min(done / self.total, 1.0)
        rate = done / max(now - self.start, 1e-9)
        width = 30
        bar = "#" * int(frac * width) + "-" * (width - int(frac * width))
        line = f"[{bar}] {done}/{self.total} cases  {found} difference{'s' if found != 1 else ''}  {rate:.0f} cases/s"
        if self.tty:
            self.stream.write("\r" + line)
            self.stream.flush()
        elif int(frac * 10) > self.last_decile or force:
            self.last_decile = int(frac * 10)
            self.stream.write(line + "\n")
            self.stream.flush()

    def close(self, done: int, found: int) -> None:
        self.update(done, found, force=True)
        if self.enabled and self.tty:
            self.stream.write("\n")
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


def aim_at_boundaries(trace) -> None:
    """Hypothesis target() on how close the run came to each exact boundary (in ulps, log-scaled
    so the last few ulps weigh as much as the first thousands) and event() per boundary hit."""
    if trace is None:
        return
    from hypothesis import event, target

    for name, ulps in trace.closest.items():
        target(-math.log2(1 + ulps), label=f"closeness to {name}")
    for key in trace:
        if key.startswith("boundary:"):
            event(key)


def _generative(port: Backend, oracle: Backend, *, kinds, n: int, seed: int, mode: str, keep_going: bool,
                database, tick, should_stop, timings: Counter, skipped: Counter, versions: Versions,
                found: list[Found]) -> int:
    """Draw up to `n` scenes; append each new kind of difference (shrunk) to `found`; return scenes run."""
    from hypothesis import HealthCheck, Phase, Verbosity, example, given, settings
    from hypothesis import seed as hseed

    from .strategies import check_kinds, scenes
    from .strategies.determinism import pinned_constants

    kinds = check_kinds(kinds)
    # one store per campaign shape, so runs of other kinds or modes do not mix
    saved = SavedFailures(database, f"acconform:{','.join(kinds)}:{mode}") if database else None
    known: set[tuple[str, ...]] = set()
    if hasattr(port, "trace_boundaries"):  # the built-in port: aim the search at exact boundaries
        port.trace_boundaries = True
    done = 0
    round_ = 0
    while done < n:
        last: list = []
        ran = [0]
        replayed = {id(s): s for s in saved.scenes()} if saved is not None else {}

        def differential(scene):
            if should_stop():
                raise _Stop
            ran[0] += 1
            tick(1)
            ran_case = run_case(port, oracle, scene, mode, timings, skipped)
            if ran_case is None:
                return
            aim_at_boundaries(getattr(port, "last_trace", None))
            a, b, diffs = ran_case
            if diffs:
                sig = signature(diffs)
                if sig not in known:
                    last[:] = [scene, a, b, diffs]
                    raise _Mismatch(sig)
            elif id(scene) in replayed:
                saved.forget(scene)

        for scene in replayed.values():
            differential = example(scene)(differential)
        differential = settings(max_examples=n - done, database=None, deadline=None, verbosity=Verbosity.quiet,
                                suppress_health_check=list(HealthCheck), report_multiple_bugs=False,
                                phases=[Phase.explicit, Phase.generate, Phase.target, Phase.shrink])(
            hseed(seed * 7919 + round_)(given(scenes(kinds))(differential)))

        new = False
        try:
            with pinned_constants():
                differential()
        except _Mismatch:
            scene, a, b, diffs = last
            sig = signature(diffs)
            known.add(sig)
            if saved is not None:
                saved.save(scene)
            found.append(Found(make_case(scene, a, b, diffs, seed, mode, versions), None, sig, True))
            new = True
        except _Stop:
            return done + ran[0]
        done += ran[0]
        round_ += 1
        # stop: first difference and not keep_going; or a clean round (the budget is spent or
        # Hypothesis ran out of scenes); or a round that ran nothing
        if (new and not keep_going) or not new or ran[0] == 0:
            break
    return done


def _replay(port: Backend, oracle: Backend, scenes: Iterable[Scene], *, mode: str, keep_going: bool, tick,
            should_stop, timings: Counter, skipped: Counter, versions: Versions, seed, found: list[Found]) -> int:
    """Replay `scenes` as they are; append each difference (unshrunk) to `found`; return scenes run.

    A port that can take a scene ahead (`port.prefetch`, an implementation process) is sent the
    next scene before the current answer is read, so it computes while this process compares.
    """
    done = 0
    scenes = list(scenes)
    prefetch = getattr(port, "prefetch", None)
    if prefetch is not None and scenes:
        prefetch(scenes[0])
    for i, scene in enumerate(scenes):
        if should_stop():
            break
        done += 1
        tick(1)
        if prefetch is not None and i + 1 < len(scenes):
            prefetch(scenes[i + 1])
        ran_case = run_case(port, oracle, scene, mode, timings, skipped)
        if ran_case is None:
            continue
        a, b, diffs = ran_case
        if diffs:
            found.append(Found(make_case(scene, a, b, diffs, seed, mode, versions), None, signature(diffs), False))
            if not keep_going:
                break
    return done


# ---------------------------------------------------------------- workers

_SHARED: dict = {}


def _ignore_sigint() -> None:
    """Pool initializer: Ctrl-C is the parent's to handle (it tells the workers to stop)."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)


def _worker(w: int) -> tuple[int, list[dict], dict, list[bool], dict]:
    s = _SHARED
    counter, stop = s["counter"], s["stop"]

    def tick(k):
        with counter.get_lock():
            counter.value += k

    timings: Counter = Counter()
    skipped: Counter = Counter()
    found: list[Found] = []
    if s["versions"] is None:  # a per-process oracle: this worker loads its own runtime
        s["versions"] = versions_of(s["port"], s["oracle"])
    with campaign_gc():
        done = _worker_campaign(w, s, tick, timings, skipped, found)
    if found and not s["keep_going"]:
        stop.set()
    close = getattr(s["port"], "close", None)
    if close is not None:
        close()  # this worker's implementation process
    return done, [f.case.to_json() for f in found], dict(timings), [f.shrunk for f in found], dict(skipped)


def _worker_campaign(w: int, s: dict, tick, timings: Counter, skipped: Counter, found: list[Found]) -> int:
    stop = s["stop"]
    if s["replay"] is not None:
        mine = [sc for i, sc in enumerate(s["replay"]) if i % s["workers"] == w]
        return _replay(s["port"], s["oracle"], mine, mode=s["mode"], keep_going=s["keep_going"], tick=tick,
                       should_stop=lambda: stop.is_set(), timings=timings, skipped=skipped, versions=s["versions"],
                       seed=s["seed"], found=found)
    n = s["n"] // s["workers"] + (1 if w < s["n"] % s["workers"] else 0)
    return _generative(s["port"], s["oracle"], kinds=s["kinds"], n=n, seed=s["seed"] * 1000 + w,
                       mode=s["mode"], keep_going=s["keep_going"], database=s["database"], tick=tick,
                       should_stop=lambda: stop.is_set(), timings=timings, skipped=skipped, versions=s["versions"],
                       found=found)


def run_campaign(port: Backend, oracle: Backend, *, kinds=None, n: int = 1000, seed: int = 0, mode: str = "exact",
                 keep_going: bool = False, failures_dir: str | Path | None = "failures",
                 database: str | Path | None = DEFAULT_DATABASE, workers: int = 1, progress: bool = False,
                 replay: Iterable[Scene] | None = None) -> Result:
    """Run a campaign of `n` scenes (or replay `replay`) through port and oracle; see the module doc.

    Found differences are written to `failures_dir` (None: not written). `workers` > 1 forks
    worker processes (the backends are inherited, so any callable works); an oracle marked
    `per_process` (a .NET runtime cannot be forked) is first touched inside each worker.
    """
    if mode not in ("exact", "fast"):
        raise AcconformError(f"unknown mode {mode!r}: choose exact or fast")
    per_process = getattr(getattr(oracle, "__self__", oracle), "per_process", False)
    versions = None if per_process and workers > 1 else versions_of(port, oracle)
    replay_list = list(replay) if replay is not None else None
    total = len(replay_list) if replay_list is not None else n
    bar = Progress(total, progress)
    start = time.monotonic()
    workers = max(1, min(workers, total or 1))
    result = Result(source="replay" if replay_list is not None else "generative", versions=versions)

    if workers == 1:
        count = [0]

        def tick(k):
            count[0] += k
            bar.update(count[0], len(result.found))

        try:
            with campaign_gc():
                if replay_list is not None:
                    result.cases = _replay(port, oracle, replay_list, mode=mode, keep_going=keep_going, tick=tick,
                                           should_stop=lambda: False, timings=result.timings, skipped=result.skipped,
                                           versions=versions, seed=seed, found=result.found)
                else:
                    result.cases = _generative(port, oracle, kinds=kinds, n=n, seed=seed, mode=mode,
                                               keep_going=keep_going, database=database, tick=tick,
                                               should_stop=lambda: False, timings=result.timings,
                                               skipped=result.skipped, versions=versions, found=result.found)
        except KeyboardInterrupt:
            result.interrupted = True
            result.cases = max(count[0] - 1, 0)  # the case Ctrl-C cut short was not compared
    else:
        ctx = multiprocessing.get_context("fork")
        counter = ctx.Value("q", 0)
        stop = ctx.Event()
        _SHARED.update(port=port, oracle=oracle, kinds=kinds, n=n, seed=seed, mode=mode, keep_going=keep_going,
                       database=database, versions=versions, replay=replay_list, workers=workers, counter=counter,
                       stop=stop)
        try:
            with ctx.Pool(workers, initializer=_ignore_sigint) as pool:
                pending = pool.map_async(_worker, range(workers))
                while True:
                    try:
                        while not pending.ready():
                            pending.wait(0.2)
                            bar.update(counter.value, 0)
                        outs = pending.get()
                        break
                    except KeyboardInterrupt:
                        # tell the workers to stop; they return what they have so far
                        result.interrupted = True
                        stop.set()
        finally:
            _SHARED.clear()
        for done, cases, timings, shrunk, skipped in outs:
            result.cases += done
            result.timings.update(timings)
            result.skipped.update(skipped)
            for doc, sh in zip(cases, shrunk):
                case = Case.from_json(doc)
                diffs = compare(case.port, case.oracle, mode)
                result.found.append(Found(case, None, signature(diffs), sh))
        if not keep_going:
            result.found = result.found[:1]
    if failures_dir is not None:
        save_cases(result, failures_dir)
    result.elapsed = time.monotonic() - start
    bar.close(result.cases, len(result.found))
    return result


def default_workers() -> int:
    return os.cpu_count() or 1
