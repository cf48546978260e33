"""Oracle cost per case beside ACE's own in-runtime time, per scene kind.

    ACE_ASSEMBLY=/path/to/ACE.Server.dll python benchmarks/bench_oracle.py [-n 300] [--path facade|direct]

Columns: per case, the oracle's wall time from Python (one `run` call; and per scene in a batch
`run_many`), the facade's whole case inside .NET, and ACE's FindValidPosition (a Stopwatch
inside the facade). Medians after a warm-up; landblocks cached across scenes (the default).
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("-n", type=int, default=300)
    ap.add_argument("--path", default=None)
    args = ap.parse_args()
    from acconform.oracle.live import LiveOracle
    from acconform.strategies import sample_scenes
    from tests.oracle.scenes import PROBE, flat, walk, wall

    oracle = LiveOracle(path=args.path)
    print(f"{oracle!r}: {oracle.versions.ace} on {oracle.versions.runtime}; facade: {oracle.facade_status}")
    groups = {name: [s] * args.n for name, s in PROBE.items()}
    groups["BSP wall (slide)"] = [walk(flat, (12.0, 12.0, 20.0), (17.0, 12.0, 20.0), 20.0, objects=(wall(),))] * args.n
    for kind in ("terrain", "bsp", "obstacles"):
        groups[f"strategies: {kind}"] = list(sample_scenes((kind,), args.n, 7))
    print(f"{'scene kind':32} {'run() us':>10} {'batch us':>10} {'in .NET us':>11} {'ACE FVP us':>11} {'ratio':>6}")
    for name, scenes in groups.items():
        for s in scenes[:50]:
            oracle.run(s)  # warm-up: JIT, landblock cache
        singles, ace, case = [], [], []
        for s in scenes:
            t = time.perf_counter()
            _, us = oracle.run_timed(s)
            singles.append((time.perf_counter() - t) * 1e6)
            ace.append(us)
            case.append(oracle.last_case_micros)
        t = time.perf_counter()
        oracle.run_many(scenes)
        batch = (time.perf_counter() - t) * 1e6 / len(scenes)
        a = statistics.median(ace)
        print(f"{name:32} {statistics.median(singles):10.1f} {batch:10.1f} {statistics.median(case):11.1f} {a:11.1f} "
              f"{batch / a if a else float('nan'):6.1f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
