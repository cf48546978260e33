"""Scene generation speed and how often each key port branch fires per 1,000 scenes.

    python benchmarks/bench_strategies.py [-n 1000] [--seed 0] [--kinds terrain]

Prints scenes/s for sample_scenes per kind, how often the drawn scenes put a static across a
cell border, a landblock border or a landblock corner (strategies/placement.py, per 1,000 scenes
of each object kind, with the port's registered cells), and the branch table of `acconform coverage`.
"""

from __future__ import annotations

import argparse
import time
import warnings

from acconform.strategies import ALL_KINDS, sample_scenes


def main() -> None:
    p = argparse.ArgumentParser()
    p.add_argument("-n", type=int, default=1000)
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--kinds", default="terrain")
    a = p.parse_args()
    warnings.simplefilter("ignore", RuntimeWarning)
    drawn = {}
    for kind in ALL_KINDS:
        t = time.perf_counter()
        scenes = drawn[kind] = list(sample_scenes((kind,), a.n, a.seed))
        dt = time.perf_counter() - t
        blocks = sum(len(s.landblocks) for s in scenes) / len(scenes)
        print(f"generation {kind:10} {a.n / dt:7.0f} scenes/s  ({blocks:.2f} landblocks a scene)")
    try:
        from acconform.strategies.placement import placement_table
    except ImportError:  # a revision before the placement table (bench --against)
        placement_table = None
    if placement_table is not None:
        from acconform.port.run import run_scene

        for kind in ("bsp", "obstacles"):
            outcomes = [run_scene(s) for s in drawn[kind]]
            print(f"placement per 1,000 {kind} scenes")
            for tag, per in placement_table(drawn[kind], outcomes):
                print(f"  {tag:58} {per:7.1f}")
    from acconform.cli import main as cli

    cli(["coverage", "--branches", "-n", str(a.n), "--seed", str(a.seed), "--kinds", a.kinds])


if __name__ == "__main__":
    main()
