"""The instrumented ACE against the plain one over a whole corpus: how many scenes it answers exactly as
the plain ACE does (recorder on), and how many of them its trace agrees with the port's at the grain both
write (trace.against_ace; only scenes the port answers as ACE does).

    ACE_ASSEMBLY=<build> python benchmarks/instrumented_corpus.py [--runtime mono|coreclr] [-n N]
        [--answers-only] [--shards GLOB,...] [--per-shard N] [--progress N] [--seconds S]
        [--ledger FILE] [--fresh] [--status] [--stop]

The plain ACE runs in this process, the instrumented copy in its worker (oracle/instrumented.py). Prints
the counts, and the first few scenes that differ.

The whole corpus takes hours a runtime, so a run is resumable: each scene answered exactly as the plain ACE is
entered in a ledger (--ledger FILE, default $XDG_CACHE_HOME/acconform/instrumented-verified.json), keyed by the
plain ACE build's hash (the assemblies the instrumenter rewrites) with the instrumentation's (instrumenter, recorder,
anchors), the runtime and the shard's SHA-256; a later run skips what the ledger holds for the same build, runtime
and shard (a changed shard, build or instrumentation starts over), --fresh ignores it (and replaces what it checks).
A scene that differs is entered as such and run again next time. Two runs, one a runtime, can share the ledger. At
the end (and with --status, which runs nothing) it prints how much of the corpus is verified, by shard."""

from __future__ import annotations

import argparse
import fcntl
import fnmatch
import hashlib
import json
import os
import sys
import time
from pathlib import Path

LEDGER_VERSION = 1


def build_hash(assembly: Path) -> str:
    """The plain ACE build's hash (the assemblies the instrumenter rewrites) with the instrumentation's own (the
    instrumenter's and recorder's source and the anchors): a change of either is another instrumented ACE to verify."""
    from acconform.oracle.instrumented import REWRITTEN, instrumentation_hash

    h = hashlib.sha256()
    for name in REWRITTEN:
        h.update((assembly.parent / name).read_bytes())
    h.update(instrumentation_hash().encode())
    return h.hexdigest()[:20]


def shard_digest(path: Path, _seen: dict = {}) -> str:  # noqa: B006 (a per-process memo)
    d = _seen.get(path)
    if d is None:
        d = _seen[path] = hashlib.sha256(path.read_bytes()).hexdigest()[:20]
    return d


class Ledger:
    """The scenes verified so far: {key: {"shard": name, "verified": [line numbers], "differ": [line numbers]}},
    key "<build hash>/<runtime>/<shard digest>". Saved whole, atomically; a save merges what another run saved
    meanwhile."""

    def __init__(self, path: Path, fresh: bool):
        self.path = path
        self.fresh = fresh
        self.entries: dict[str, dict] = {} if fresh else self._read()
        self.touched: set[str] = set()

    def _read(self) -> dict:
        try:
            doc = json.loads(self.path.read_text())
        except FileNotFoundError:
            return {}
        except (OSError, ValueError) as e:
            raise SystemExit(f"--ledger {self.path}: not a ledger ({e}); --fresh starts a new one") from None
        if not isinstance(doc, dict) or doc.get("version") != LEDGER_VERSION:
            raise SystemExit(f"--ledger {self.path}: not a version-{LEDGER_VERSION} ledger; --fresh starts a new one")
        return {k: {"shard": v["shard"], "verified": set(v["verified"]), "differ": set(v.get("differ", ()))}
                for k, v in doc["entries"].items()}

    def _entry(self, key: str, shard: str) -> dict:
        return self.entries.setdefault(key, {"shard": shard, "verified": set(), "differ": set()})

    def verified(self, key: str) -> set:
        e = self.entries.get(key)
        return e["verified"] if e else set()

    def differs(self, key: str) -> set:
        e = self.entries.get(key)
        return e["differ"] if e else set()

    def enter(self, key: str, shard: str, lineno: int, same: bool) -> None:
        e = self._entry(key, shard)
        (e["verified"] if same else e["differ"]).add(lineno)
        (e["differ"] if same else e["verified"]).discard(lineno)
        self.touched.add(key)

    def save(self) -> None:
        """Merge with the file and write it, under a lock: two runs (one a runtime) share the ledger. A key this run
        has not touched takes the file's version (another run's progress); a touched one is the union, this run's
        verdicts winning."""
        self.path.parent.mkdir(parents=True, exist_ok=True)
        with open(self.path.with_name(self.path.name + ".lock"), "w") as lock:
            fcntl.flock(lock, fcntl.LOCK_EX)
            entries = self.entries
            if not self.fresh:
                for k, v in self._read().items():
                    mine = entries.get(k)
                    if mine is None or k not in self.touched:
                        entries[k] = v
                    else:
                        mine["verified"] |= v["verified"] - mine["differ"]
                        mine["differ"] |= v["differ"] - mine["verified"]
            self.fresh = False  # from now on a save merges with what this run wrote
            doc = {"version": LEDGER_VERSION, "entries": {
                k: {"shard": v["shard"], "verified": sorted(v["verified"]), "differ": sorted(v["differ"])}
                for k, v in sorted(entries.items())}}
            tmp = self.path.with_name(self.path.name + f".tmp-{os.getpid()}")
            tmp.write_text(json.dumps(doc, separators=(",", ":")) + "\n")
            tmp.replace(self.path)


def status(ledger: Ledger, prefix: str, entries, corpus_dir: Path) -> tuple[int, int, int]:
    """Print the verified share of each shard of the corpus, and the totals; -> (verified, differ, scenes)."""
    total: dict[Path, int] = {}
    for e in entries:
        total[e.shard.path] = total.get(e.shard.path, 0) + 1
    done = bad = n = 0
    rows = []
    for path, count in total.items():
        key = prefix + shard_digest(path)
        v, d = len(ledger.verified(key)), len(ledger.differs(key))
        done, bad, n = done + v, bad + d, n + count
        rows.append(f"{path.name} {v}/{count}" + (f" ({d} differ)" if d else ""))
    full = [r for r in rows if r.split()[1].split("/")[0] == r.split()[1].split("/")[1]]
    print(f"verified by shard ({corpus_dir}): " + ", ".join(rows))
    print(f"verified: {done} of {n} scenes ({100 * done / max(n, 1):.1f} %), {len(full)} of {len(rows)} shards "
          f"whole; {bad} differ")
    return done, bad, n


def main() -> int:
    p = argparse.ArgumentParser()
    p.add_argument("--runtime", default=None)
    p.add_argument("-n", type=int, default=None, help="a stratified sample of N scenes (default: all)")
    p.add_argument("--answers-only", action="store_true", help="compare the answers only (recorder on, its records "
                   "counted, not compared with the port's trace): the whole corpus in minutes")
    p.add_argument("--shards", default=None, help="only the shards whose file name matches one of these "
                   "comma-separated globs (e.g. 'ticks-005*,ticks-006*,*': those first, then the rest), in the order given")
    p.add_argument("--per-shard", type=int, default=None, help="only the first N scenes of each shard (every shard "
                   "represented when the whole corpus cannot run in the time there is)")
    p.add_argument("--progress", type=int, default=1000, help="print the counts so far every N scenes (0: never)")
    p.add_argument("--seconds", type=float, default=None, help="stop after S seconds and print how far it got")
    p.add_argument("--ledger", default=None, help="the ledger of verified scenes (default: "
                   "$XDG_CACHE_HOME/acconform/instrumented-verified.json)")
    p.add_argument("--fresh", action="store_true", help="ignore the ledger's verified scenes (check them again)")
    p.add_argument("--status", action="store_true", help="print what the ledger holds for this build and corpus; run nothing")
    p.add_argument("--stop", action="store_true", help="stop at the first scene that differs")
    args = p.parse_args()
    from acconform.compare import compare
    from acconform.oracle import default_corpus
    from acconform.oracle.config import cache_dir, resolve
    from acconform.oracle.recorded import RecordedOracle, scene_kind

    location = resolve(None, args.runtime)
    if location is None:
        print("no ACE assembly configured (ACE_ASSEMBLY or --ace)", file=sys.stderr)
        return 2
    runtime = location.runtime
    ledger = Ledger(Path(args.ledger) if args.ledger else cache_dir() / "instrumented-verified.json", args.fresh)
    prefix = f"{build_hash(location.assembly)}/{runtime.split(' ', 1)[0]}/"
    corpus = RecordedOracle(default_corpus(runtime))
    if args.status:
        status(ledger, prefix, corpus.entries, corpus.corpus_dir)
        return 0
    entries = corpus.select(n=args.n, seed=0) if args.n else corpus.entries
    if args.shards:
        globs = [g.strip() for g in args.shards.split(",") if g.strip()]
        picked = {}  # id -> entry, in the globs' order, each once ('ticks-006*,*': the newest first, then the rest)
        for g in globs:
            picked.update((id(e), e) for e in entries if id(e) not in picked and fnmatch.fnmatch(e.shard.path.name, g))
        entries = list(picked.values())
        if not entries:
            print(f"--shards {args.shards}: no shard of {corpus.corpus_dir} matches", file=sys.stderr)
            return 2
    if args.per_shard is not None:
        taken: dict[str, int] = {}
        kept = []
        for e in entries:
            name = e.shard.path.name
            if taken.get(name, 0) < args.per_shard:
                taken[name] = taken.get(name, 0) + 1
                kept.append(e)
        entries = kept
    selected = len(entries)
    if not args.fresh:
        entries = [e for e in entries if e.lineno not in ledger.verified(prefix + shard_digest(e.shard.path))]
    print(f"{runtime}: {selected} scenes selected, {selected - len(entries)} verified before (the ledger {ledger.path}), "
          f"{len(entries)} to run", flush=True)

    from acconform.oracle.instrumented import TracedAce
    from acconform.oracle.live import LiveOracle

    plain = LiveOracle(location.assembly, runtime, say=None)
    traced = TracedAce(plain.location.assembly, runtime, say=None)
    done = 0
    shards_done: dict[str, int] = {}
    same = traces_agree = port_agrees = 0
    shown = 0
    stopped = False
    t0 = last_save = time.monotonic()
    try:
        for e in entries:
            if args.seconds is not None and time.monotonic() - t0 > args.seconds:
                print(f"stopped after {args.seconds:.0f} s", flush=True)
                break
            if args.progress and done and done % args.progress == 0:
                print(f"{done} of {len(entries)} scenes: {same} answered as the plain ACE, {done - same} differ "
                      f"({time.monotonic() - t0:.0f} s; now {e.shard.path.name})", flush=True)
            if time.monotonic() - last_save > 60:
                ledger.save()
                last_save = time.monotonic()
            name = e.shard.path.name
            scene = corpus._record(e).scene
            answer = plain.run(scene)
            if args.answers_only:
                outcome, _count = traced.counted(scene)
                records = None
            else:
                outcome, records = traced.trace(scene)
            done += 1
            shards_done[name] = shards_done.get(name, 0) + 1
            key = prefix + shard_digest(e.shard.path)
            if compare(outcome, answer, "exact"):
                ledger.enter(key, name, e.lineno, False)
                if shown < 5 or args.stop:
                    print(f"differs: {scene_kind(scene)} {e.where}: "
                          f"{'; '.join(str(d) for d in compare(outcome, answer, 'exact')[:3])}", flush=True)
                    shown += 1
                if args.stop:
                    stopped = True
                    break
                continue
            ledger.enter(key, name, e.lineno, True)
            same += 1
            if records is None:
                continue
            from acconform.port.run import traced_run
            from acconform.trace import against_ace

            port_outcome, port = traced_run(scene, "exact", runtime)
            if not compare(port_outcome, answer, "exact"):
                port_agrees += 1
                if against_ace(records, port, traced.kinds, scene.ticks is not None, traced.overloaded) is None:
                    traces_agree += 1
    except KeyboardInterrupt:
        print("interrupted", flush=True)
        stopped = True
    finally:
        ledger.save()
        traced.close()
    seconds = time.monotonic() - t0
    print(f"shards run: {', '.join(f'{k} ({v})' for k, v in shards_done.items())}")
    print(f"{runtime}: {same} of {done} scenes run (of {len(entries)} to run) answered exactly as the plain ACE "
          f"(recorder on), {done - same} differ ({seconds:.0f} s, {seconds / max(done, 1):.2f} s a scene)"
          + ("" if args.answers_only else f"; ACE's trace agrees with the port's on {traces_agree} of the "
             f"{port_agrees} the port answers as ACE"))
    status(ledger, prefix, corpus.entries, corpus.corpus_dir)
    return 0 if same == done == len(entries) and not stopped else 1


if __name__ == "__main__":
    sys.exit(main())
