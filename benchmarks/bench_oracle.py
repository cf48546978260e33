"""Oracle cost per case beside ACE's own in-runtime time, per scene kind.

    ACE_ASSEMBLY=/path/to/ACE.Server.dll python benchmarks/bench_oracle.py [-n 300]
    ACE_ASSEMBLY=... python benchmarks/bench_oracle.py --against HEAD~1   # before/after in one run
    python benchmarks/bench_oracle.py --ace mono/ACE.Server.dll --ace net10/ACE.Server.dll   # runtimes side by side

Columns, per case (medians; landblocks cached across scenes, the default):
  run() us    the oracle's wall time from Python for one `run` call (pack, cross, unpack)
  batch us    the same per scene through `run_many`, BATCH scenes a call
  .NET us     the facade's whole case inside .NET: what ACE's runtime spends on the case (reset,
              build the scene's world and objects, the transition, read back)
  trans us    PhysicsObj.transition's own work (MakeTransition .. FindValidPosition .. CleanupTransition)
  FVP us      ACE's Transition.FindValidPosition alone
  /.NET /trans /FVP   run() divided by each
  built       landblocks the facade had to build per case (the rest came from its cache)
  us/lb       .NET time per landblock built (CellLandblock.Unpack, new Landblock, PostInit)
The strategies' kinds are fresh scenes (warm-up on other seeds, so nothing measured was seen
before) and also get campaign totals: sum of run() over sum of each in-runtime time, which is
what a campaign pays. "after the port" measures it as a campaign runs a case (runner.run_case):
on other fresh scenes, each run by the built-in port just before ACE, so the scene's DAT records,
written once per scene for both sides (acconform.dat.scene_records), are already written.

--ace PATH, given more than once, measures each ACE build in its own subprocess (pythonnet loads
one runtime per process; the runtime is chosen from each build) on the same scenes and prints
them side by side, e.g. a mono build beside a .NET build on CoreCLR, with whether their outcomes
are identical.

--against REV checks REV out into a temporary git worktree and runs this script there in a
subprocess (imports resolve to the worktree through a shim on sys.path), on the same scenes
(passed as JSON), first; then this tree. It prints both and whether the outcomes are identical.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from revision import ROOT, revision_env  # noqa: E402 (benchmarks run as scripts)
BATCH = 50  # scenes per run_many call


def scene_groups(n: int) -> dict:
    from acconform.strategies import sample_scenes
    from tests.oracle.scenes import PROBE, flat, walk, wall

    groups = {name: [s] * n for name, s in PROBE.items()}
    groups["BSP wall (slide)"] = [walk(flat, (12.0, 12.0, 20.0), (17.0, 12.0, 20.0), 20.0, objects=(wall(),))] * n
    for kind in ("terrain", "bsp", "obstacles", "indoor", "buildings", "ticks"):
        groups[f"strategies: {kind}"] = list(sample_scenes((kind,), n, 7))
        groups[f"warm-up: {kind}"] = list(sample_scenes((kind,), 50, 8))
        groups[f"batch: {kind}"] = list(sample_scenes((kind,), n, 9))
        groups[f"campaign: {kind}"] = list(sample_scenes((kind,), n, 10))
    return groups


def measure(groups: dict) -> dict:
    from acconform.oracle.live import LiveOracle

    from acconform.impl import BuiltinPort
    from acconform.oracle import port_runtime

    oracle = LiveOracle()
    port = BuiltinPort("exact", port_runtime(oracle))
    res = {"oracle": f"{oracle!r}: {oracle.versions.ace} on {oracle.versions.runtime}", "kinds": {}}
    for name, scenes in groups.items():
        if name.startswith(("warm-up: ", "batch: ", "campaign: ")):
            continue
        fresh = name.startswith("strategies: ")
        kind = name.split(": ", 1)[-1]
        for s in (groups[f"warm-up: {kind}"] if fresh else scenes[:50]):
            oracle.run(s)  # warm-up: JIT (and, for a repeated scene, its landblock)
        singles, ace, trans, case, built, build_us = [], [], [], [], [], []
        digest = hashlib.sha256()
        for s in scenes:
            t = time.perf_counter()
            o, us = oracle.run_timed(s)
            singles.append((time.perf_counter() - t) * 1e6)
            ace.append(us)
            trans.append(getattr(oracle, "last_transition_micros", float("nan")))  # absent before b340fad
            case.append(oracle.last_case_micros)
            built.append(oracle.last_landblocks_built)
            build_us.append(oracle.last_build_micros)
            digest.update(json.dumps(o.to_json(), sort_keys=True).encode())
        batch_scenes = groups[f"batch: {kind}"] if fresh else scenes
        oracle.run_many(batch_scenes[:BATCH])  # warm-up: the batch buffers grow once
        if fresh:
            batch_scenes = batch_scenes[BATCH:]
        batch, t = [], time.perf_counter()
        for i in range(0, len(batch_scenes), BATCH):
            batch += oracle.run_many(batch_scenes[i:i + BATCH])
        batch_us = (time.perf_counter() - t) * 1e6 / max(len(batch_scenes), 1)
        same = all(b[0].to_json() == oracle.run(s).to_json() for b, s in zip(batch[:20], batch_scenes[:20]))
        after = after_net = 0.0  # run() as a campaign pays it: the port ran the scene just before (runner.run_case)
        for s in groups.get(f"campaign: {kind}", ()) if fresh else ():
            port(s)
            t = time.perf_counter()
            oracle.run(s)
            after += (time.perf_counter() - t) * 1e6
            after_net += oracle.last_case_micros
        res["kinds"][name] = {"run": statistics.median(singles), "batch": batch_us, "net": statistics.median(case),
                              "sum_after": after, "sum_after_net": after_net,
                              "trans": statistics.median(trans), "fvp": statistics.median(ace),
                              "built": statistics.mean(built),
                              "lb_us": sum(build_us) / sum(built) if sum(built) else float("nan"),
                              "sum_run": sum(singles), "sum_net": sum(case), "sum_trans": sum(trans),
                              "sum_fvp": sum(ace), "fresh": fresh,
                              "outcomes": digest.hexdigest()[:16], "batch_agrees": same}
    return res


def _ratio(a, b) -> str:
    return f"{a / b:6.1f}" if b else "   nan"


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("-n", type=int, default=300)
    ap.add_argument("--against", metavar="REV", help="also run REV (a git revision) first and print before/after")
    ap.add_argument("--ace", action="append", metavar="PATH",
                    help="an ACE build to measure (else ACE_ASSEMBLY); give several to print them side by side")
    ap.add_argument("--json", action="store_true", help=argparse.SUPPRESS)
    ap.add_argument("--scenes", help=argparse.SUPPRESS)  # the parent's scenes as JSON
    args = ap.parse_args()
    if args.scenes:
        from acconform.case import parse_document

        groups = {k: [parse_document(d) for d in v] for k, v in json.loads(Path(args.scenes).read_text()).items()}
    else:
        sys.path.insert(0, str(ROOT))
        groups = scene_groups(args.n)
    if args.json:
        print(json.dumps(measure(groups)))
        return 0
    if args.ace and len(args.ace) > 1:
        if args.against:
            raise SystemExit("bench_oracle: --against compares revisions on one build; give one --ace with it")
        return _side_by_side(args, groups)
    if args.ace:
        os.environ["ACE_ASSEMBLY"] = args.ace[0]

    old = None
    if args.against:
        with revision_env(args.against) as env:  # REV gets no "campaign:" scenes: it would time them as a kind
            old = _measure_in_subprocess(args, {k: v for k, v in groups.items() if not k.startswith("campaign: ")},
                                         env, args.against)
    new = measure(groups)

    print(new["oracle"])
    if old:
        print(f"before = {args.against}, after = this tree; same scenes, one run (before first)")
        print(f"{'scene kind':28} {'run() us':>17} {'batch us':>15} {'.NET us':>13} {'trans':>6} {'FVP us':>6} "
              f"{'/.NET':>6} {'/trans':>6} {'/FVP':>6} {'built':>5} {'us/lb':>5}  outcomes")
        for name, b in new["kinds"].items():
            a = old["kinds"][name]
            print(f"{name:28} {a['run']:7.1f} -> {b['run']:6.1f} {a['batch']:6.1f} -> {b['batch']:5.1f} "
                  f"{a['net']:5.1f} -> {b['net']:5.1f} {b.get('trans', float('nan')):6.1f} {b['fvp']:6.1f} "
                  f"{_ratio(b['run'], b['net'])} {_ratio(b['run'], b.get('trans', 0))} {_ratio(b['run'], b['fvp'])} "
                  f"{b['built']:5.2f} {b['lb_us']:5.0f}  "
                  f"{'identical' if a['outcomes'] == b['outcomes'] else 'DIFFER'}{'' if b['batch_agrees'] else ' (batch DIFFERS)'}")
        _totals(new, groups)
        return 0 if all(old["kinds"][k]["outcomes"] == v["outcomes"] for k, v in new["kinds"].items()) else 1
    print(f"{'scene kind':28} {'run() us':>9} {'batch us':>9} {'.NET us':>8} {'trans us':>8} {'FVP us':>7} "
          f"{'/.NET':>6} {'/trans':>6} {'/FVP':>6} {'built':>5} {'us/lb':>5}")
    for name, b in new["kinds"].items():
        print(f"{name:28} {b['run']:9.1f} {b['batch']:9.1f} {b['net']:8.1f} {b['trans']:8.1f} {b['fvp']:7.1f} "
              f"{_ratio(b['run'], b['net'])} {_ratio(b['run'], b['trans'])} {_ratio(b['run'], b['fvp'])} "
              f"{b['built']:5.2f} {b['lb_us']:5.0f}")
    _totals(new, groups)
    return 0


def _measure_in_subprocess(args, groups: dict, env: dict, what: str) -> dict:
    scenes = Path(tempfile.mkdtemp(prefix="acconform-scenes-")) / "scenes.json"
    scenes.write_text(json.dumps({k: [s.to_json() for s in v] for k, v in groups.items()}))
    cmd = [sys.executable, str(Path(__file__).resolve()), "--json", "--scenes", str(scenes)]
    done = subprocess.run(cmd, env=env, capture_output=True, text=True)
    if done.returncode != 0:
        sys.stderr.write(done.stderr)
        raise SystemExit(f"bench_oracle: measuring {what} failed (its stderr is above)")
    return json.loads(done.stdout.strip().splitlines()[-1])


def _side_by_side(args, groups: dict) -> int:
    """Each build in its own process (one .NET runtime per process), one after the other, same scenes."""
    runs = []
    for ace in args.ace:
        env = {k: v for k, v in os.environ.items() if k != "ACE_RUNTIME"}
        env["ACE_ASSEMBLY"] = ace
        runs.append(_measure_in_subprocess(args, groups, env, ace))
    for i, r in enumerate(runs):
        print(f"[{i}] {r['oracle']}")
    head = "".join(f" | [{i}] {'run()':>6} {'.NET':>6} {'trans':>6} {'FVP':>6} {'/.NET':>5}" for i in range(len(runs)))
    print(f"{'scene kind (us per case)':28}{head} | outcomes")
    for name in runs[0]["kinds"]:
        row = "".join(f" |     {r['kinds'][name]['run']:6.1f} {r['kinds'][name]['net']:6.1f} {r['kinds'][name]['trans']:6.1f} "
                      f"{r['kinds'][name]['fvp']:6.1f} {_ratio(r['kinds'][name]['run'], r['kinds'][name]['net']):>5}"
                      for r in runs)
        same = len({r["kinds"][name]["outcomes"] for r in runs}) == 1
        print(f"{name:28}{row} | {'identical' if same else 'differ'}")
    print("campaign totals on fresh scenes (sum of run() / sum of the whole case inside .NET):")
    for name in runs[0]["kinds"]:
        if runs[0]["kinds"][name]["fresh"]:
            cells = "   ".join(f"[{i}] {r['kinds'][name]['sum_run'] / len(groups[name]):6.1f} us a case, "
                               f"/.NET {r['kinds'][name]['sum_run'] / r['kinds'][name]['sum_net']:4.2f}"
                               for i, r in enumerate(runs))
            print(f"  {name:26} {cells}")
    return 0


def _totals(res: dict, groups: dict) -> None:
    print("campaign totals on fresh scenes, this tree (sum of run() / sum of each):")
    for name, b in res["kinds"].items():
        if b["fresh"]:
            print(f"  {name:26} run() {b['sum_run'] / len(groups[name]):7.1f} us a case:"
                  f"  /.NET {_over(b['sum_run'], b['sum_net'])}  /trans {_over(b['sum_run'], b['sum_trans'])}"
                  f"  /FVP {_over(b['sum_run'], b['sum_fvp'])}"
                  + (f"   after the port: run() {b['sum_after'] / len(groups[name]):7.1f} us a case"
                     f"  /.NET {_over(b['sum_after'], b['sum_after_net'])}" if b.get("sum_after_net") else ""))


def _over(a: float, b: float) -> str:
    return f"{a / b:5.2f}" if b else "  n/a"  # a tick scene's transitions run inside update_object, not timed apart


if __name__ == "__main__":
    sys.exit(main())
