"""End-to-end differential throughput on 2 cores, and where the time goes.

    python benchmarks/bench_runner.py [-n 2000] [--workers 2] [--kinds K,..] [--oracle port|recorded|live]

Oracle "live" is the real thing: ACE through pythonnet (ACE_ASSEMBLY or --ace), one runtime per
worker. "port" runs the port against itself -- it isolates the harness's own cost; "recorded"
replays the corpus (the oracle is then a lookup).
Prints cases/s for the whole campaign and the split: generation (Hypothesis drawing scenes,
measured separately), port, oracle, comparison.
"""

from __future__ import annotations

import argparse
import time
import warnings

from acconform.runner import run_campaign
from acconform.strategies import sample_scenes


def main() -> None:
    p = argparse.ArgumentParser()
    p.add_argument("-n", type=int, default=2000)
    p.add_argument("--workers", type=int, default=2)
    p.add_argument("--kinds", default="terrain,bsp,obstacles")
    p.add_argument("--oracle", choices=("port", "recorded", "live"), default="port")
    p.add_argument("--ace", default=None, help="ACE assembly for --oracle live (else ACE_ASSEMBLY)")
    a = p.parse_args()
    warnings.simplefilter("ignore", RuntimeWarning)
    from acconform.port.run import run_scene

    kinds = tuple(a.kinds.split(","))
    t = time.perf_counter()
    list(sample_scenes(kinds, min(a.n, 500), 1))
    gen_rate = min(a.n, 500) / (time.perf_counter() - t)

    if a.oracle == "recorded":
        from acconform.oracle import get_oracle

        oracle = get_oracle()
        replay = list(oracle.scenes())[: a.n]
        r = run_campaign(run_scene, oracle.run, replay=replay, failures_dir=None, workers=a.workers, keep_going=True)
    elif a.oracle == "live":
        from acconform.oracle import PerProcessOracle

        oracle = PerProcessOracle(a.ace)
        r = run_campaign(run_scene, oracle.run, kinds=kinds, n=a.n, seed=0, failures_dir=None, database=None,
                         workers=a.workers, keep_going=True)
    else:
        r = run_campaign(run_scene, run_scene, kinds=kinds, n=a.n, seed=0, failures_dir=None, database=None,
                         workers=a.workers, keep_going=True)
    rate = r.cases / r.elapsed
    busy = r.elapsed * a.workers
    t = r.timings
    gen = busy - sum(t.values()) if r.source == "generative" else 0.0
    print(f"{r.cases} cases in {r.elapsed:.1f} s on {a.workers} workers: {rate:.0f} cases/s end to end "
          f"(oracle={a.oracle}, {len(r.found)} differences)")
    print(f"  generation alone: {gen_rate:.0f} scenes/s on one core")
    for name, secs in (("generation+hypothesis", gen), ("port", t["port"]), ("oracle", t["oracle"]),
                       ("comparison", t["compare"])):
        print(f"  {name:22} {secs:7.2f} worker-s  {100 * secs / busy:5.1f}%  {1000 * secs / max(r.cases, 1):6.2f} ms/case")


if __name__ == "__main__":
    main()
