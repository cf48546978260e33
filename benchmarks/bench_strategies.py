"""Scene generation speed and how often each key port branch fires per 1,000 scenes.

    python benchmarks/bench_strategies.py [-n 1000] [--seed 0] [--kinds terrain]

Prints scenes/s for sample_scenes per kind and the branch table of `acconform coverage`.
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
    for kind in ALL_KINDS:
        t = time.perf_counter()
        scenes = list(sample_scenes((kind,), a.n, a.seed))
        dt = time.perf_counter() - t
        blocks = sum(len(s.landblocks) for s in scenes) / len(scenes)
        print(f"generation {kind:10} {a.n / dt:7.0f} scenes/s  ({blocks:.2f} landblocks a scene)")
    from acconform.cli import main as cli

    cli(["coverage", "--branches", "-n", str(a.n), "--seed", str(a.seed), "--kinds", a.kinds])


if __name__ == "__main__":
    main()
