"""Print the mutation check's figures: per planted bug, caught or not, scenes to find it, shrunk size.

    python tests/runner/mutation_report.py [-j 2] [--budget 1500] [--seed 0] [--only NAME,...] [--json FILE]
    python tests/runner/mutation_report.py --corpus DIR [--runtime mono] [--kernel] [-j 2] [--only ...]
    ACE_ASSEMBLY=... python tests/runner/mutation_report.py --live 4000 [--only ...]
    python tests/runner/mutation_report.py --ticks [--runtime coreclr] [--only ...]
    python tests/runner/mutation_report.py --fast-lane 600 [--lane-tests tests/port,...] [--lane-workers 1 -j 2] [--only ...]

Runs the same hunt as test_mutations.py (mutants.hunt: one worker per mutant, no example
database), mutants spread over -j processes. With --corpus, generates nothing: replays the
recorded corpus through each mutant against ACE's recorded answers (mutants.corpus_kill) and
says which mutants the corpus alone kills (--kernel: the corpus's coverage kernel first,
benchmarks/corpus_coverage.py's, and the whole corpus only for the mutants it leaves). With --live N, each mutant is the implementation
under test (tests/impl/planted_impl.py, --impl) in `acconform check -n N` against live ACE (the
configured ACE_ASSEMBLY), one worker, no example database, stopping at its first difference.
With --fast-sample, each mutant replays only the fast lane's differential sample
(tests/runner/test_differential.py's records of both runtimes, in-process, as --corpus does):
the part of the every-push lane that compares with ACE's answers, without pytest's start-up
per mutant; a kill there fails the fast lane (the lane's other tests can only add kills).
With --fast-lane S, each mutant is applied to a checkout of HEAD (benchmarks/revision.py's
shim puts it on PYTHONPATH) whose every-push lane (`pytest -x -m "not slow"`) runs for at most S
seconds: a failing test kills the mutant; running out of time says nothing either way.
--lane-tests narrows the lane to some of its paths (comma-separated, under tests/) and
--lane-workers sets its xdist workers (0: in one process); with 0 or 1, -j lanes run at once.
With --ticks, the tick-loop mutants (kinds ("ticks",)) replay the tick records (mutants.tick_kill: the
corpus's ticks-* shards when present, then the example, hand-written and named tick scenes) against
ACE's recorded answers, and the killing scene is shrunk; the hunt has no tick kind and skips them.
"""

from __future__ import annotations

import argparse
import json
import multiprocessing
import sys
from contextlib import nullcontext
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from mutants import BUDGET, MUTATIONS, SEED, TICKS, corpus_kill, hunt, tick_kill  # noqa: E402


def _one(args):
    i, budget, seed = args
    return hunt(i, budget, seed)


def _replay(args):
    i, corpus, runtime, seed = args[:4]
    return corpus_kill(i, corpus, runtime, seed, only=args[4] if len(args) > 4 else None)


def _sample_replay(args):
    """The fast lane's differential sample (test_differential's records, both runtimes) through the mutant."""
    from acconform.oracle import default_corpus
    from corpus_sample import load_sample

    i, seed = args
    out = {"name": MUTATIONS[i].name, "killed": False}
    for runtime in ("mono", "coreclr"):
        keys = [key for key, _kind, _branches in load_sample(runtime)["records"]]
        r = corpus_kill(i, default_corpus(runtime), runtime, seed, only=keys)
        out[runtime] = r["records_to_kill"]
        out["killed"] = out["killed"] or r["killed"]
        out["records"] = r["records"]
    return out


def _rows(fn, jobs, a, pooled: bool = True) -> list[dict]:
    """Each job's row (printed as a JSON line as it comes, and written to --json at the end);
    pooled over -j processes, or one at a time (a job that runs workers of its own)."""
    rows = []
    with multiprocessing.get_context("fork").Pool(a.j) if pooled else nullcontext() as pool:
        for row in pool.imap(fn, jobs) if pooled else map(fn, jobs):
            rows.append(row)
            print(json.dumps(row), flush=True)
    if a.json:
        Path(a.json).write_text(json.dumps(rows, indent=1))
    return rows


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("-j", type=int, default=2)
    p.add_argument("--budget", type=int, default=BUDGET)
    p.add_argument("--seed", type=int, default=SEED)
    p.add_argument("--only", default="")
    p.add_argument("--json", default=None)
    p.add_argument("--corpus", default=None, metavar="DIR", help="replay this recorded corpus instead of hunting")
    p.add_argument("--fast-lane", type=int, default=0, metavar="S",
                   help="run the fast test lane (at most S seconds) on a checkout with each mutant applied instead")
    p.add_argument("--fast-sample", action="store_true",
                   help="replay only the fast lane's differential sample (both runtimes) through each mutant")
    p.add_argument("--lane-tests", default="tests", help="with --fast-lane: the test paths to run (comma-separated)")
    p.add_argument("--lane-workers", type=int, default=2, help="with --fast-lane: pytest-xdist workers per lane")
    p.add_argument("--live", type=int, default=0, metavar="N", help="a live campaign of N cases per mutant instead")
    p.add_argument("--runtime", default="mono", help="with --corpus or --ticks: the records' runtime (mono or coreclr)")
    p.add_argument("--ticks", action="store_true", help="replay the tick records through the tick-loop mutants")
    p.add_argument("--kernel", action="store_true",
                   help="with --corpus: the corpus's coverage-kernel.json records first, the whole corpus for their survivors")
    a = p.parse_args(argv)
    names = [m.name for m in MUTATIONS]
    unknown = [n for n in a.only.split(",") if n and n not in names]
    if unknown:
        print(f"mutation_report: unknown mutant {unknown[0]!r}", file=sys.stderr)
        return 2
    picked = [names.index(n) for n in a.only.split(",") if n] or list(range(len(MUTATIONS)))
    if a.ticks:
        return _ticks_report([i for i in picked if MUTATIONS[i].kinds == TICKS], a)
    if a.live:
        return _live_report(picked, a)
    if a.fast_lane:
        return _fast_lane_report(picked, a)
    if a.fast_sample:
        rows = _rows(_sample_replay, [(i, a.seed) for i in picked], a)
        print(f"{sum(r['killed'] for r in rows)}/{len(rows)} killed by the fast lane's differential sample")
        print(f"{'mutant':42} {'killed':>6} {'mono at':>8} {'coreclr at':>10}")
        for r in rows:
            print(f"{r['name']:42} {'yes' if r['killed'] else 'no':>6} {r['mono'] or '-':>8} {r['coreclr'] or '-':>10}")
        return 0
    if a.corpus is not None:
        if not Path(a.corpus).is_dir():
            print(f"mutation_report: no corpus directory at {a.corpus}", file=sys.stderr)
            return 2
        return _corpus_report(picked, a)
    picked = [i for i in picked if MUTATIONS[i].kinds != TICKS]  # no tick kind to hunt on: --ticks
    rows = _rows(_one, [(i, a.budget, a.seed) for i in picked], a)
    caught = [r for r in rows if r["caught"]]
    print(f"{len(caught)}/{len(rows)} caught")
    print(f"{'mutant':42} {'caught':>6} {'scenes':>6} {'lbs':>4} {'objs':>4} {'path m':>7}")
    for r in rows:
        print(f"{r['name']:42} {'yes' if r['caught'] else 'no':>6} {r['scenes_to_find'] or '-':>6} "
              f"{r.get('landblocks', '-'):>4} {r.get('objects', '-'):>4} {r.get('path', '-'):>7}")
    return 0


def _live(args):
    import shlex
    import subprocess
    import tempfile
    import time

    i, n, seed = args
    name = MUTATIONS[i].name
    impl = f"{shlex.quote(sys.executable)} {shlex.quote(str(Path(__file__).resolve().parents[1] / 'impl' / 'planted_impl.py'))} {name}"
    with tempfile.TemporaryDirectory(prefix="acconform-live-") as tmp:
        summary = Path(tmp) / "summary.json"
        t0 = time.monotonic()
        r = subprocess.run([str(Path(sys.executable).parent / "acconform"), "check", "--impl", impl, "-n", str(n), "--seed", str(seed),
                            "-j", "1", "--no-database", "--no-progress", "--failures", str(Path(tmp) / "failures"),
                            "--json", str(summary)], capture_output=True, text=True)
        out = {"name": name, "exit": r.returncode, "seconds": round(time.monotonic() - t0, 1)}
        if summary.exists():
            doc = json.loads(summary.read_text())
            out["cases"] = (doc.get("cases") or {}).get("run")  # generated plus shrinking runs
        out["killed"] = r.returncode == 1
        if r.returncode not in (0, 1):
            out["stderr"] = r.stderr[-400:]
    return out


def _fast_lane(args):
    import subprocess
    import time

    sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "benchmarks"))
    from revision import revision_env

    i, limit, tests, workers = args
    m = MUTATIONS[i]
    with revision_env("HEAD") as env:
        tree = Path(env["PYTHONPATH"]) / "acconform" / "port"
        target = tree.resolve() / m.file
        text = target.read_text()
        target.write_text(text.replace(m.old, m.new))
        root = tree.resolve().parent
        t0 = time.monotonic()
        try:
            r = subprocess.run([sys.executable, "-m", "pytest", "-x", "-q", "-m", "not slow", "-p", "no:cacheprovider",
                                "-n", str(workers), *tests], cwd=root, env=env, capture_output=True, text=True,
                               timeout=limit)
            failed = [ln for ln in r.stdout.splitlines() if ln.startswith(("FAILED", "ERROR"))][:1]
            # -x under xdist ends a failing lane as interrupted (exit 2): a FAILED line decides
            verdict = "killed" if failed else {0: "survived"}.get(r.returncode, f"exit {r.returncode}")
        except subprocess.TimeoutExpired:
            verdict, failed = "timed out", []
    return {"name": m.name, "fast_lane": verdict, "seconds": round(time.monotonic() - t0, 1),
            "first_failure": failed[0][7:] if failed else None}


def _fast_lane_report(picked, a) -> int:
    # a lane of two workers runs alone; lanes of one process run -j at once
    tests = a.lane_tests.split(",")
    rows = _rows(_fast_lane, [(i, a.fast_lane, tests, a.lane_workers) for i in picked], a, pooled=a.lane_workers <= 1)
    print(f"{sum(r['fast_lane'] == 'killed' for r in rows)}/{len(rows)} killed by the fast lane ({' '.join(tests)}; "
          f"{sum(r['fast_lane'] == 'timed out' for r in rows)} ran out of its {a.fast_lane} s)")
    for r in rows:
        print(f"{r['name']:42} {r['fast_lane']:>10} {r['seconds']:7.1f} s  {r['first_failure'] or ''}")
    return 0


def _live_report(picked, a) -> int:
    rows = _rows(_live, [(i, a.live, a.seed) for i in picked], a)
    print(f"{sum(r['killed'] for r in rows)}/{len(rows)} killed by a live campaign of at most {a.live} cases")
    for r in rows:
        print(f"{r['name']:42} {'yes' if r['killed'] else 'no':>6} {r.get('cases')}")
    return 0


def _tick(args):
    i, runtime = args
    return tick_kill(i, runtime)


def _ticks_report(picked, a) -> int:
    rows = _rows(_tick, [(i, a.runtime) for i in picked], a)
    print(f"{sum(r['killed'] for r in rows)}/{len(rows)} tick-loop mutants killed by the tick records ({a.runtime})")
    print(f"{'mutant':42} {'killed':>6} {'after':>6} {'ticks':>5} {'shrunk':>6} {'objs':>4} {'lbs':>3} {'bytes':>6}  record")
    for r in rows:
        print(f"{r['name']:42} {'yes' if r['killed'] else 'no':>6} {r['records_to_kill'] or '-':>6} {r.get('ticks', '-'):>5} "
              f"{r.get('shrunk_ticks', '-'):>6} {r.get('shrunk_objects', '-'):>4} {r.get('shrunk_landblocks', '-'):>3} "
              f"{r.get('shrunk_bytes', '-'):>6}  {r.get('record', '')}")
    return 0


def _corpus_report(picked, a) -> int:
    if a.kernel:
        # the corpus's coverage kernel first (a few hundred records taking the branches the corpus takes):
        # what it kills the corpus kills; only its survivors replay every record
        kernel = json.loads((Path(a.corpus) / "coverage-kernel.json").read_text())["keys"]
        first = {r["name"]: r for r in _rows(_replay, [(i, a.corpus, a.runtime, a.seed, kernel) for i in picked], a)}
        left = [i for i in picked if not first[MUTATIONS[i].name]["killed"]]
        print(f"{len(picked) - len(left)}/{len(picked)} killed by the coverage kernel's {len(kernel)} records; "
              f"the other {len(left)} replay the whole corpus", flush=True)
        rest = {r["name"]: r for r in _rows(_replay, [(i, a.corpus, a.runtime, a.seed) for i in left], a)}
        rows = [rest.get(MUTATIONS[i].name) or {**first[MUTATIONS[i].name], "records_to_kill": "kernel"} for i in picked]
        if a.json:
            Path(a.json).write_text(json.dumps(rows, indent=1))
    else:
        rows = _rows(_replay, [(i, a.corpus, a.runtime, a.seed) for i in picked], a)
    print(f"{sum(r['killed'] for r in rows)}/{len(rows)} killed by the corpus replay alone ({a.corpus}, {a.runtime})")
    print(f"{'mutant':42} {'killed':>6} {'after':>6}")
    for r in rows:
        print(f"{r['name']:42} {'yes' if r['killed'] else 'no':>6} {r['records_to_kill'] or '-':>6}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
