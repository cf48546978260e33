"""The cost of tracing a port run (port/tracing.py): the same scenes untraced and traced, side by side.

    python benchmarks/bench_trace.py [--n 40] [--repeat 3]

Scenes: the first --n recorded corpus scenes of each kind (terrain, bsp, obstacles; coreclr). Each set
runs --repeat times untraced (run_scene) and traced (traced_run: every anchored routine wrapped, a
snapshot at each entry and exit), alternating, computing as coreclr; the best pass of each is
reported as ms/scene of process CPU time, with traced/untraced and the records written per scene.
Tracing off costs nothing to measure here: benchmarks/bench_port.py --against REV compares the
untraced port with an older revision.
"""

from __future__ import annotations

import argparse
import time

from bench_port import KINDS, load_corpus  # noqa: E402 (benchmarks run as scripts)

CLOCK = time.process_time


def main() -> int:
    p = argparse.ArgumentParser()
    p.add_argument("--n", type=int, default=40)
    p.add_argument("--repeat", type=int, default=3)
    args = p.parse_args()
    import warnings

    warnings.simplefilter("ignore")
    from acconform.port.run import run_scene, traced_run

    print(f"{'kind':<10} {'untraced ms':>12} {'traced ms':>10} {'ratio':>7} {'records/scene':>14}")
    for kind in KINDS:
        scenes = load_corpus(kind, args.n)
        best = {"off": float("inf"), "on": float("inf")}
        records = 0
        for _ in range(args.repeat):
            t = CLOCK()
            for s in scenes:
                run_scene(s, runtime="coreclr")
            best["off"] = min(best["off"], CLOCK() - t)
            t = CLOCK()
            records = 0
            for s in scenes:
                records += len(traced_run(s, runtime="coreclr")[1])
            best["on"] = min(best["on"], CLOCK() - t)
        off, on = (best[k] * 1000 / len(scenes) for k in ("off", "on"))
        print(f"{kind:<10} {off:>12.2f} {on:>10.1f} {on / off:>6.0f}x {records / len(scenes):>14.0f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
