"""The harness's own cost per generated case, per kind, side by side with another revision.

    python benchmarks/bench_harness.py [--against 93f11f8] [--kinds terrain,bsp,...] [-n 600] [--rounds 2]

What a live campaign spends on a case besides the implementation and ACE: drawing the scene (and
Hypothesis' bookkeeping, where a revision draws through its engine), the protocol, the comparison,
the runner. Both sides answer at once with the same fixed outcome, so nothing else is left:

  in-process  `run_campaign` with two backends that return at once (drawing, runner, comparison)
  protocol    the implementation under test is a process speaking acconform.protocol/1 that
              answers every scene at once with that outcome (benchmarks/instant_impl.py --fixed):
              the scene packed and sent, the answer read and checked, as `check --impl` does
  busy MS     the same process working MS ms of CPU on each scene first (--busy MS): wall time
              per case against MS shows how much of the harness happens while it works

One worker, no example database, `-n` cases per kind, seed 0. Each measurement is its own
subprocess (this tree's acconform, or REV's through benchmarks/revision.py's shim); the revisions
alternate round by round so load from other processes falls on both, and the figure is the
fastest round's ms per case (wall time of the campaign), with the slowest beside it. The issue's
goals (22): at most 1 ms outdoors and 2 ms indoors, with the protocol.
"""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from revision import child_ms, revision_env  # noqa: E402

INSTANT = Path(__file__).resolve().parent / "instant_impl.py"

CHILD = """
import json, sys, time, warnings
warnings.simplefilter("ignore", RuntimeWarning)
from acconform.outcome import Outcome
from acconform.protocol import Implementation
from acconform.runner import run_campaign
kind, n, how, instant = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4]
fixed = Outcome(ok=True)
def at_once(scene):
    return fixed
busy = f" --busy {how.split()[1]}" if how.startswith("busy") else ""
port = Implementation(f"{sys.executable} {instant} --fixed{busy}") if how != "in-process" else at_once
try:
    run_campaign(port, at_once, kinds=(kind,), n=20, seed=1, failures_dir=None, database=None, workers=1)  # warm-up
    t = time.perf_counter()
    r = run_campaign(port, at_once, kinds=(kind,), n=n, seed=0, failures_dir=None, database=None, workers=1)
    ms = (time.perf_counter() - t) * 1000 / r.cases
finally:
    if how != "in-process":
        port.close()
assert not r.found, "both sides answer the same outcome"
print(json.dumps({"ms": ms}))
"""


def _time(env, kind: str, n: int, how: str) -> float:
    return child_ms(env, CHILD, kind, str(n), how, str(INSTANT), what=f"bench_harness: {kind} ({how})")


def main() -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--against", default="93f11f8", help="the revision measured beside this tree")
    p.add_argument("--kinds", default="terrain,bsp,obstacles,indoor,buildings,ticks")
    p.add_argument("-n", type=int, default=600)
    p.add_argument("--rounds", type=int, default=2)
    p.add_argument("--busy", type=float, default=None, metavar="MS",
                   help="also through the protocol to an implementation that works MS ms on each scene")
    a = p.parse_args()
    kinds = a.kinds.split(",")
    hows = ("in-process", "protocol") + ((f"busy {a.busy:g}",) if a.busy else ())
    here = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    revs = ("this", a.against)
    times = {(rev, k, how): [] for rev in revs for k in kinds for how in hows}
    with revision_env(a.against) as old:
        for _ in range(a.rounds):
            for k in kinds:
                for how in hows:
                    for rev, env in (("this", here), (a.against, old)):
                        times[rev, k, how].append(_time(env, k, a.n, how))
    load = os.getloadavg()[0]
    print(f"harness ms per generated case (fastest of {a.rounds} rounds, slowest in brackets), "
          f"n={a.n}, load {load:.1f}")
    print(f"{'kind':10} {'how':11} {'this':>16} {a.against:>16} {'ratio':>7}")
    for k in kinds:
        for how in hows:
            t, o = times["this", k, how], times[a.against, k, how]
            print(f"{k:10} {how:11} {min(t):7.2f} ({max(t):6.2f}) {min(o):7.2f} ({max(o):6.2f}) "
                  f"{min(o) / min(t):6.2f}x")
    return 0


if __name__ == "__main__":
    sys.exit(main())
