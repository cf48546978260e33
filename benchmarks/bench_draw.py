"""Draw cost side by side: ms per drawn scene, per kind, for this tree and for another revision.

    python benchmarks/bench_draw.py [--against 298b4e3] [--kinds terrain,bsp,obstacles,indoor,buildings] [-n 300]
                                    [--rounds 3] [--seed 0]

Each measurement is its own subprocess (one revision's `acconform` imported per process: this
tree's, or REV's through benchmarks/revision.py's shim), drawing n scenes of one kind with
`sample_scenes` (as a campaign draws its fresh scenes: strategies.fast_draw in this tree, Hypothesis' engine
before it) after a warm-up draw of 20. The two
revisions alternate round by round so that load from other processes falls on both; the figure
is the fastest round (the least disturbed), with the slowest beside it.
"""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from revision import child_ms, revision_env  # noqa: E402

CHILD = """
import json, sys, time, warnings
warnings.simplefilter("ignore", RuntimeWarning)
from acconform.strategies import sample_scenes
kind, n, seed = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
list(sample_scenes((kind,), 20, seed + 1))
t = time.perf_counter()
got = list(sample_scenes((kind,), n, seed))
print(json.dumps({"ms": (time.perf_counter() - t) * 1000 / len(got)}))
"""


def _time(env, kind: str, n: int, seed: int) -> float:
    return child_ms(env, CHILD, kind, str(n), str(seed), what=f"bench_draw: drawing {kind}")


def main() -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--against", default="298b4e3")  # issue 22's baseline
    p.add_argument("--kinds", default="terrain,bsp,obstacles,indoor,buildings",
                   help="kinds drawn (a kind the other revision cannot draw fails with its own error line)")
    p.add_argument("-n", type=int, default=300)
    p.add_argument("--rounds", type=int, default=3)
    p.add_argument("--seed", type=int, default=0)
    a = p.parse_args()
    kinds = a.kinds.split(",")
    here = dict(os.environ)
    here.pop("PYTHONPATH", None)
    times = {(rev, k): [] for rev in ("this", a.against) for k in kinds}
    with revision_env(a.against) as old:
        for _ in range(a.rounds):
            for k in kinds:
                times[("this", k)].append(_time(here, k, a.n, a.seed))
                times[(a.against, k)].append(_time(old, k, a.n, a.seed))
    print(f"ms per drawn scene ({a.n} scenes, fastest of {a.rounds} rounds; slowest in brackets); "
          f"load average {os.getloadavg()[0]:.1f}; ratio = {a.against} / this tree")
    print(f"{'kind':10} {'this tree':>18} {a.against:>18} {'ratio':>7}")
    for k in kinds:
        t, o = times[("this", k)], times[(a.against, k)]
        print(f"{k:10} {min(t):8.2f} ({max(t):6.2f}) {min(o):8.2f} ({max(o):6.2f}) {min(o) / min(t):7.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
