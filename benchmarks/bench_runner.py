"""End-to-end differential throughput on 2 cores, and where the time goes.

    python benchmarks/bench_runner.py [-n 2000] [--workers 2] [--kinds K,..] [--oracle port|recorded|live]
    python benchmarks/bench_runner.py --impl CMD [--corpus DIR] [--workers 2] [LABEL=PYTHON ...]

Oracle "live" is the real thing: ACE through pythonnet (ACE_ASSEMBLY or --ace), one runtime per
worker. Against ACE, live or recorded, the port computes as the runtime ACE runs (ran) on, as `check`
does (`acconform.oracle.port_runtime`). "port" runs the port against itself -- it isolates the harness's own cost; "recorded"
replays the corpus (the oracle is then a lookup).
Prints cases/s for the whole campaign and the split of the workers' time: drawing the scenes,
start-up (ACE's loading), the runner's own work and idling at the end (what no step timed), port,
oracle, comparison; then the harness and ACE alone (the workers' time less the port's, as issue
22 counts it), and the generation rate of one core drawing alone.

With --impl, a corpus replay through an implementation process, as a user runs it (`acconform
check --impl CMD --corpus DIR -j W`), for one or more installs side by side (a Python whose
`acconform` is measured; default this one), each in a fresh process, no ACE configured. CMD may
name {python}, {root} (the install's source tree) and {corpus}: e.g. an implementation that
answers each scene at once with ACE's recorded outcome, which runs with any install:
`--impl "{python} benchmarks/instant_impl.py {corpus}"` (an absolute path), or
`--impl "node {root}/tests/impl/recorded_answers.js {corpus}"`. Prints per install: seconds from
launch to the first case, the campaign's cases/s (as `check` reports it), the harness's worker
milliseconds per case (the workers' time not spent waiting for the implementation), and the wall
time of the whole command, with the load average.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
import warnings

from acconform.runner import run_campaign
from acconform.strategies import sample_scenes


def replay_through(python: str, impl: str, corpus: str | None, workers: int) -> dict:
    """One `check --impl` replay by the acconform of `python`: its figures."""
    root = subprocess.run([python, "-c", "import acconform, os; print(os.path.dirname(os.path.dirname(acconform.__file__)))"],
                          capture_output=True, text=True, check=True).stdout.strip()
    corpus = corpus or os.path.join(root, "tests", "data", "corpus", "coreclr")
    env = {k: v for k, v in os.environ.items() if k not in ("ACE_ASSEMBLY", "ACE_RUNTIME")}
    with tempfile.TemporaryDirectory() as d:
        t0 = time.monotonic()
        p = subprocess.Popen([python, "-m", "acconform.cli", "check", "--no-progress", "-j", str(workers), "--corpus", corpus,
                              "--impl", impl.format(root=root, corpus=corpus, python=python), "--json", os.path.join(d, "s.json"),
                              "--failures", os.path.join(d, "f")], cwd=d, env=env, stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True)
        first = float("nan")
        for line in p.stderr:
            if " vs recorded corpus " in line:
                first = time.monotonic() - t0
        out = p.stdout.read()
        p.wait()
        wall = time.monotonic() - t0
        if p.returncode != 0:
            raise SystemExit(f"{python}: check exited {p.returncode}: {out[-500:]}")
        s = json.load(open(os.path.join(d, "s.json")))
    t, cases = s["timings"], s["cases"]["run"]
    return {"cases": cases, "differences": s["differences"]["total"], "first_case_s": first, "wall_s": wall,
            "cases_per_s": t["cases_per_s"],
            "harness_ms": 1000 * (t["elapsed_s"] * workers - t.get("port_s", 0.0)) / max(cases, 1)}


def main_impl(a) -> None:
    installs = [i.split("=", 1) for i in a.installs] or [["this", sys.executable]]
    print(f"load average before: {os.getloadavg()[0]:.1f}; {a.workers} workers; impl {a.impl!r}")
    for r in range(a.rounds):
        for label, python in installs:
            f = replay_through(python, a.impl, a.corpus, a.workers)
            print(f"round {r + 1} {label:>8}: {f['cases']} cases ({f['differences']} differences): first case at "
                  f"{f['first_case_s']:.1f} s, {f['cases_per_s']:.0f} cases/s, harness {f['harness_ms']:.2f} worker-ms/case, "
                  f"{f['wall_s']:.1f} s wall in all; load {os.getloadavg()[0]:.1f}", flush=True)


def main() -> None:
    p = argparse.ArgumentParser()
    p.add_argument("-n", type=int, default=2000)
    p.add_argument("--workers", type=int, default=2)
    p.add_argument("--kinds", default="terrain,bsp,obstacles")
    p.add_argument("--oracle", choices=("port", "recorded", "live"), default="port")
    p.add_argument("--ace", default=None, help="ACE assembly for --oracle live (else ACE_ASSEMBLY)")
    p.add_argument("--impl", default=None, help="replay the corpus through this implementation command (see above)")
    p.add_argument("--corpus", default=None, help="with --impl: the corpus replayed (default each install's coreclr corpus)")
    p.add_argument("--rounds", type=int, default=1, help="with --impl: rounds, alternating installs")
    p.add_argument("installs", nargs="*", metavar="LABEL=PYTHON", help="with --impl: the installs compared")
    a = p.parse_args()
    if a.impl is not None:
        return main_impl(a)
    warnings.simplefilter("ignore", RuntimeWarning)
    from acconform.port.run import run_scene

    kinds = tuple(a.kinds.split(","))
    t = time.perf_counter()
    list(sample_scenes(kinds, min(a.n, 500), 1))
    gen_rate = min(a.n, 500) / (time.perf_counter() - t)

    from acconform.impl import BuiltinPort
    from acconform.oracle import port_runtime

    if a.oracle == "recorded":
        from acconform.oracle import default_corpus
        from acconform.oracle.recorded import RecordedOracle

        oracle = RecordedOracle(default_corpus())
        replay = list(oracle.scenes())[: a.n]
        # the port computes as the ACE it is compared with, as `check` does
        port = BuiltinPort("exact", port_runtime(oracle))
        r = run_campaign(port, oracle.run, replay=replay, failures_dir=None, workers=a.workers, keep_going=True)
    elif a.oracle == "live":
        from acconform.oracle import PerProcessOracle

        oracle = PerProcessOracle(a.ace)
        port = BuiltinPort("exact", port_runtime(oracle))
        r = run_campaign(port, oracle.run, kinds=kinds, n=a.n, seed=0, failures_dir=None, database=None,
                         workers=a.workers, keep_going=True)
    else:
        port = BuiltinPort("exact")
        r = run_campaign(run_scene, run_scene, kinds=kinds, n=a.n, seed=0, failures_dir=None, database=None,
                         workers=a.workers, keep_going=True)
    rate = r.cases / r.elapsed
    busy = r.elapsed * a.workers
    t = r.timings
    rest = busy - sum(t.values())  # the workers' start-up (ACE's loading), the runner's own work, idling at the end
    print(f"{r.cases} cases in {r.elapsed:.1f} s on {a.workers} workers: {rate:.0f} cases/s end to end "
          f"(oracle={a.oracle}, port computing as {port.runtime}, {len(r.found)} differences)")
    print(f"  generation alone: {gen_rate:.0f} scenes/s on one core")
    for name, secs in (("drawing", t["draw"]), ("start-up, runner, idle", rest), ("port", t["port"]),
                       ("oracle", t["oracle"]), ("comparison", t["compare"])):
        print(f"  {name:22} {secs:7.2f} worker-s  {100 * secs / busy:5.1f}%  {1000 * secs / max(r.cases, 1):6.2f} ms/case")
    harness = busy - t["port"]
    print(f"  the harness and ACE alone (all but the port): {1000 * harness / max(r.cases, 1):.2f} worker-ms per case, "
          f"{a.workers * r.cases / harness:.0f} cases/s on {a.workers} workers")


if __name__ == "__main__":
    main()
