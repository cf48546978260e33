"""The port's cost per scene computing as mono and as .NET 10 (CoreCLR), on the same campaign scenes.

    python benchmarks/bench_runtimes.py [--n 600] [--seed 515] [--repeat 3]
    python benchmarks/bench_runtimes.py --against HEAD~3      # old and new side by side, one run

The scenes are the ones a live campaign runs: a generative campaign of the port against itself
(`run_campaign`, all kinds, one worker, no example database) with the port tracing its boundaries,
so the campaign's climb toward exact boundaries steers the draw as `acconform check` does; the scenes it ran are kept.
Each pass runs them all, traced as in a campaign, through `run_scene` on one runtime; the
runtimes alternate pass by pass (the machine is shared: a neighbour's burst hits both) and the
best of --repeat passes is reported as ms/scene (process CPU time), with coreclr/mono.
Every pass starts with an empty landblock pool and runs under the campaign's collector settings
(`runner.campaign_gc`), as a campaign worker does.

--against REV runs this script of this tree against REV's acconform (a temporary worktree, see
revision.py) in a subprocess on the same scenes (drawn by this tree), then this tree in a fresh
subprocess, --rounds times alternately (one pass per runtime each), and prints the best of each.
"""

from __future__ import annotations

import argparse
import contextlib
import json
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from revision import revision_env  # noqa: E402 (benchmarks run as scripts)

RUNTIMES = ("mono", "coreclr")
CLOCK = time.process_time  # CPU time of this process: the port is single-threaded, the machine shared


def campaign_scenes(n: int, seed: int) -> list:
    """The scenes a traced generative campaign of `n` cases at `seed` runs (port against port)."""
    from acconform.impl import BuiltinPort
    from acconform.runner import run_campaign

    ran = []
    port = BuiltinPort("exact", "mono")

    def keep(scene):
        ran.append(scene)
        return port(scene)

    class Recorder:  # the port as run_campaign sees it (trace_boundaries set, last_trace read)
        def __call__(self, scene):
            port.trace_boundaries = self.trace_boundaries
            outcome = keep(scene)
            self.last_trace = port.last_trace
            return outcome

        trace_boundaries = False
        last_trace = None

    run_campaign(Recorder(), BuiltinPort("exact", "mono"), n=n, seed=seed, failures_dir=None, database=None,
                 workers=1, keep_going=True)
    return ran


def measure(scenes: list, repeat: int) -> dict:
    from acconform.port.land.lscape import clear_landblock_cache
    from acconform.port.run import run_scene
    from acconform.port.transition.branches import Trace

    from acconform import runner

    # the collector as a campaign worker tunes it: with Python's default thresholds a full collection
    # over the drawn scenes costs ~0.25 s and lands on whichever runtime's pass happens to trigger it
    # (measured: ~40% of a pass), drowning the arithmetic this benchmark compares
    tuned_gc = getattr(runner, "campaign_gc", contextlib.nullcontext)  # --against: an older tree may lack it
    best = {rt: float("inf") for rt in RUNTIMES}
    with tuned_gc():
        for _ in range(repeat):
            for rt in RUNTIMES:
                clear_landblock_cache()
                t0 = CLOCK()
                for s in scenes:
                    run_scene(s, "exact", Trace(), rt)
                best[rt] = min(best[rt], CLOCK() - t0)
    return {rt: best[rt] / len(scenes) * 1e3 for rt in RUNTIMES}


def load(path: str) -> list:
    from acconform.case import parse_document

    return [parse_document(d) for d in json.loads(Path(path).read_text())]


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=600, help="campaign cases drawn")
    ap.add_argument("--seed", type=int, default=515)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--against", metavar="REV", help="also run REV (a git revision) on the same scenes")
    ap.add_argument("--rounds", type=int, default=3, help="with --against: old and new runs, alternated")
    ap.add_argument("--json", action="store_true", help=argparse.SUPPRESS)
    ap.add_argument("--scenes", help=argparse.SUPPRESS)  # the parent's draw, as JSON
    args = ap.parse_args()

    if args.scenes:
        result = measure(load(args.scenes), args.repeat)
        print(json.dumps(result) if args.json else result)
        return
    scenes = campaign_scenes(args.n, args.seed)
    path = Path(tempfile.mkdtemp(prefix="acconform-scenes-")) / "campaign.json"
    path.write_text(json.dumps([s.to_json() for s in scenes]))
    cmd = [sys.executable, str(Path(__file__).resolve()), "--json", "--repeat", str(args.repeat), "--scenes", str(path)]

    def best(runs: list) -> dict:
        return {rt: min(r[rt] for r in runs) for rt in RUNTIMES}

    def run(env=None) -> dict:
        return json.loads(subprocess.run(cmd, env=env, check=True, capture_output=True, text=True).stdout)

    # this tree in a fresh process too (the parent holds Hypothesis' draw, which slows collections)
    if args.against:
        cmd[cmd.index("--repeat") + 1] = "1"
        with revision_env(args.against) as env:
            runs = [(run(env), run()) for _ in range(args.rounds)]  # alternated: a busy spell hits both
        rows = [(args.against, best([o for o, _ in runs])), ("this tree", best([n for _, n in runs]))]
        args.repeat = args.rounds
    else:
        rows = [("this tree", run())]
    print(f"{len(scenes)} campaign scenes (seed {args.seed}), traced, best of {args.repeat}, ms/scene CPU")
    print(f"{'revision':12s} {'mono':>8s} {'coreclr':>8s} {'coreclr/mono':>13s}")
    for name, r in rows:
        print(f"{name:12s} {r['mono']:8.2f} {r['coreclr']:8.2f} {r['coreclr'] / r['mono']:12.2f}x")
    if len(rows) == 2:
        (_, o), (_, n) = rows
        print(f"{'old/new':12s} {o['mono'] / n['mono']:7.2f}x {o['coreclr'] / n['coreclr']:7.2f}x")


if __name__ == "__main__":
    main()
