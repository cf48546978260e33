"""Port cost per scene, by scene kind and mode, and its share in landblock construction.

    python benchmarks/bench_port.py [--n 60] [--generated 40] [--repeat 3]
    python benchmarks/bench_port.py --against HEAD~3      # old/new ratio, measured in one run

Scenes: the recorded corpus (tests/data/corpus/coreclr/{terrain,bsp,obstacles,indoor,buildings,ticks}-*.jsonl.gz,
the first --n of each kind; a revision that cannot read a kind's records shows none of them) and
--generated scenes from acconform.strategies.sample_scenes (seed 1); a revision that cannot read
them all (an older scene format) shows none.
Each scene set runs --repeat times through run_scene in exact and fast mode, and in exact mode with
a branches.Trace as a campaign runs the built-in port ("exact+trace"), computing as .NET 10 does;
the best pass is reported as ms/scene (process CPU time, see CLOCK), with the garbage collector
tuned as `check` runs the port (runner.campaign_gc; --gc default: Python's own, where collections
of the benchmark's heap cost about as much as the port). "build%" is the share of that pass spent constructing landblocks
(Landblock.__init__ and post_init, plus any lazy cell building the port does on first access),
measured in a separate instrumented pass so the timing pass carries no wrapper cost.

--against REV checks REV out into a temporary git worktree, runs this same script there in a
subprocess (imports resolve to the worktree through a shim on sys.path) and prints old, new and
old/new side by side. Both runs see the same scenes (the corpus of this tree, and this tree's
generated draw passed to both runs as JSON); each side runs in a fresh subprocess, the new one
second; --rounds R runs each side R times, alternately, and keeps the best of each.
"""

from __future__ import annotations

import argparse
import gzip
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from revision import ROOT, revision_env  # noqa: E402 (benchmarks run as scripts)
KINDS = ("terrain", "bsp", "obstacles", "indoor", "buildings", "ticks")
# CPU time of this process, not wall time: the port is single-threaded, and the machine is shared
# (tests and oracles run beside a benchmark), so wall time mostly measured the neighbours.
CLOCK = time.process_time


def load_corpus(kind: str, n: int):
    """The first n records of the kind that this revision can read (an older one reads no building or
    tick records)."""
    from acconform.case import parse_document
    from acconform.oracle import default_corpus

    out = []
    for path in sorted(default_corpus().glob(f"{kind}-*.jsonl.gz")):
        with gzip.open(path, "rt", encoding="utf-8") as f:
            for line in f:
                try:
                    rec = parse_document(json.loads(line))
                except Exception:  # a record format this revision does not know
                    continue
                out.append(getattr(rec, "scene", rec))
                if len(out) >= n:
                    return out
    return out


def _run(scene, mode: str, trace_class) -> None:
    from acconform.port.run import run_scene

    if trace_class is None:
        run_scene(scene, mode, runtime="coreclr")
    else:
        run_scene(scene, "exact", trace_class(), runtime="coreclr")


def _trace_class():
    from acconform.port.transition.branches import Trace

    return Trace


def _build_functions():
    """(owner, attribute) pairs that construct landblocks, whichever of them this tree has."""
    from acconform.port.land import landblock, lscape

    names = [(landblock.Landblock, "__init__"), (landblock.Landblock, "post_init"),
             (lscape.LScape, "build_landblock")]
    return [(o, a) for o, a in names if a in vars(o)]


class BuildTimer:
    """Wraps the construction functions; counts outermost time only (they nest)."""

    def __init__(self):
        self.total = 0.0
        self.depth = 0
        self.saved = []

    def __enter__(self):
        for owner, attr in _build_functions():
            fn = vars(owner)[attr]
            self.saved.append((owner, attr, fn))
            setattr(owner, attr, self._wrap(fn))
        return self

    def _wrap(self, fn):
        timer = self

        def wrapped(*a, **k):
            if timer.depth:
                return fn(*a, **k)
            timer.depth += 1
            t0 = CLOCK()
            try:
                return fn(*a, **k)
            finally:
                timer.total += CLOCK() - t0
                timer.depth -= 1
        return wrapped

    def __exit__(self, *exc):
        for owner, attr, fn in self.saved:
            setattr(owner, attr, fn)


def _clear_caches():
    """Empty what the port remembers across runs (whichever of it this tree has): landblocks,
    GfxObjs, Environments and CellStructs. Each pass then builds what a campaign's new scenes build
    (a corpus replay meets each scene once)."""
    import importlib

    for module, name in (("land.lscape", "clear_landblock_cache"), ("gfx_obj_cache", "clear_built"),
                         ("db_obj", "clear_environments"), ("cell.cell_struct", "clear_built")):
        try:
            clear = getattr(importlib.import_module(f"acconform.port.{module}"), name, None)
        except ImportError:
            continue
        if clear is not None:
            clear()


def _collector(gc_setting: str):
    """The garbage collector as `check` runs the port (runner.campaign_gc: frozen heap, rare
    collections), or Python's default ("default")."""
    import contextlib

    if gc_setting == "default":
        return contextlib.nullcontext()
    from acconform.runner import campaign_gc

    return campaign_gc()


def measure(scenes, mode: str, repeat: int, gc_setting: str = "campaign") -> dict:
    with _collector(gc_setting):
        return _measure(scenes, mode, repeat)


def _measure(scenes, mode: str, repeat: int) -> dict:
    trace_class = _trace_class() if mode == "exact+trace" else None
    best = float("inf")
    for _ in range(repeat):
        _clear_caches()  # every pass starts cold: the memories' gain is within a pass
        t0 = CLOCK()
        for s in scenes:
            _run(s, mode, trace_class)
        best = min(best, CLOCK() - t0)
    _clear_caches()
    with BuildTimer() as bt:
        t0 = CLOCK()
        for s in scenes:
            _run(s, mode, trace_class)
        total = CLOCK() - t0
    return {"ms": best / len(scenes) * 1e3, "build": bt.total / total if total else 0.0}


def generated_scenes(args) -> list:
    """sample_scenes(None, --generated, seed 1) of this tree, or the --scenes file the parent wrote."""
    if args.scenes:
        from acconform.case import parse_document

        try:
            return [parse_document(d) for d in json.loads(Path(args.scenes).read_text())]
        except Exception:  # an older revision reading today's draw: it shows none, as for a kind it cannot read
            return []
    from acconform.strategies import sample_scenes

    return list(sample_scenes(None, args.generated, 1))


def run(args) -> dict:
    sets = {k: load_corpus(k, args.n) for k in KINDS}
    if args.generated:
        sets["generated"] = generated_scenes(args)
    results = {}
    for name, scenes in sets.items():
        if not scenes:
            continue
        for mode in ("exact", "fast", "exact+trace"):
            results[f"{name}/{mode}"] = measure(scenes, mode, args.repeat, args.gc) | {"scenes": len(scenes)}
    return results


def _best(a: dict, b: dict) -> dict:
    """Per scene set and mode, the faster of two runs' figures."""
    return {k: min((r for r in (a.get(k), v) if r is not None), key=lambda r: r["ms"]) for k, v in b.items()}


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=60, help="corpus scenes per kind")
    ap.add_argument("--generated", type=int, default=40)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--against", metavar="REV", help="also run REV (a git revision) and print old/new")
    ap.add_argument("--rounds", type=int, default=1, help="with --against: runs of each side, alternately (the best of each)")
    ap.add_argument("--gc", choices=("campaign", "default"), default="campaign",
                    help="the collector as check runs the port (runner.campaign_gc; default) or Python's default")
    ap.add_argument("--json", action="store_true", help=argparse.SUPPRESS)
    ap.add_argument("--scenes", help=argparse.SUPPRESS)  # generated scenes as JSON (the parent's draw)
    args = ap.parse_args()

    old = None
    if args.against:
        with revision_env(args.against) as env:
            scenes = Path(tempfile.mkdtemp(prefix="acconform-scenes-")) / "generated.json"
            scenes.write_text(json.dumps([s.to_json() for s in generated_scenes(args)] if args.generated else []))
            args.scenes = str(scenes)  # both runs time the same draw (strategies change between revisions)
            cmd = [sys.executable, str(Path(__file__).resolve()), "--json", "--n", str(args.n),
                   "--generated", str(args.generated), "--repeat", str(args.repeat), "--scenes", str(scenes), "--gc", args.gc]
            old, new = {}, {}
            for _ in range(args.rounds):  # alternately: a neighbour's burst falls on both sides
                old = _best(old, json.loads(subprocess.run(cmd, env=env, check=True, capture_output=True, text=True).stdout))
                # this tree in a fresh process too: the parent holds the strategies' draw (hypothesis and
                # all), whose heap made every collection slower and the new side look ~15% slower
                new = _best(new, json.loads(subprocess.run(cmd, check=True, capture_output=True, text=True).stdout))
    else:
        new = run(args)
    if args.json:
        print(json.dumps(new))
        return
    print(f"load average {' '.join(f'{x:.2f}' for x in os.getloadavg())} (1, 5, 15 min) before the runs; "
          f"collector: {'as check runs the port (campaign_gc)' if args.gc == 'campaign' else 'Python default'}")
    if old is None:
        print(f"{'scenes/mode':20s} {'n':>4s} {'ms/scene':>9s} {'build%':>7s}")
        for key, r in new.items():
            print(f"{key:20s} {r['scenes']:4d} {r['ms']:9.2f} {r['build'] * 100:6.1f}%")
        return
    print(f"{'scenes/mode':20s} {'n':>4s} {'old ms':>8s} {'build%':>7s} {'new ms':>8s} {'build%':>7s} {'old/new':>8s}")
    for key, r in new.items():
        o = old.get(key)
        if o is None:
            print(f"{key:20s} {r['scenes']:4d} {'-':>8s} {'':7s} {r['ms']:8.2f} {r['build'] * 100:6.1f}%")
            continue
        print(f"{key:20s} {r['scenes']:4d} {o['ms']:8.2f} {o['build'] * 100:6.1f}% {r['ms']:8.2f} "
              f"{r['build'] * 100:6.1f}% {o['ms'] / r['ms']:7.2f}x")


if __name__ == "__main__":
    main()
