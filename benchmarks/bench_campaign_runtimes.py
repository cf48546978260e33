"""Live campaigns on mono and on .NET 10 side by side: cases/s, same seed, one run each.

    python benchmarks/bench_campaign_runtimes.py --mono mono/ACE.Server.dll --coreclr net10/ACE.Server.dll \
        [-n 4000] [-j 2] [--seeds 101,102,103] [--kinds ...]

For each seed, `acconform check -n N -j J --seed S` runs once against each build, one after the
other in a fresh process (as a user runs it: worker start-up, ACE's load and facade, Hypothesis'
draw, the port, ACE and the comparison all counted); the order alternates from seed to seed, so
a busy spell on the shared machine does not always fall on the same runtime. Prints each pair's
cases/s (the campaign's own figure, from --json), their ratio, the seconds the workers spent in the
port and in ACE (summed over workers), and each side's differences; the medians close the table. Every pair is printed: the machine is noisy, and one pair proves little.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

RUNTIMES = ("mono", "coreclr")


def campaign(ace: str, n: int, workers: int, seed: int, kinds: str | None) -> dict:
    out = Path(tempfile.mkdtemp(prefix="acconform-bench-")) / "summary.json"
    cmd = [sys.executable, "-m", "acconform.cli", "check", "-n", str(n), "-j", str(workers), "--seed", str(seed),
           "--no-progress", "--no-database", "--keep-going", "--failures", str(out.parent / "failures"), "--json", str(out)]
    if kinds:
        cmd += ["--kinds", kinds]
    env = dict(os.environ, ACE_ASSEMBLY=ace)
    r = subprocess.run(cmd, env=env, capture_output=True, text=True)
    if r.returncode not in (0, 1) or not out.exists():
        sys.exit(f"bench_campaign_runtimes: acconform check on {ace} exited {r.returncode}: "
                 f"{(r.stderr.strip().splitlines() or ['no output'])[-1]}")
    s = json.loads(out.read_text())
    if s["oracle"] != "live":
        sys.exit(f"bench_campaign_runtimes: {ace} did not run live (oracle {s['oracle']!r})")
    t = s["timings"]
    return {"rate": t["cases_per_s"], "cases": s["cases"]["run"], "differences": s["differences"]["total"],
            "port": t.get("port_s", 0.0), "oracle": t.get("oracle_s", 0.0)}


def main() -> None:
    p = argparse.ArgumentParser()
    p.add_argument("--mono", required=True, help="ACE.Server.dll built for mono")
    p.add_argument("--coreclr", required=True, help="ACE.Server.dll built for .NET 10")
    p.add_argument("-n", type=int, default=4000)
    p.add_argument("-j", type=int, default=2)
    p.add_argument("--seeds", default="101,102,103")
    p.add_argument("--kinds", default=None)
    a = p.parse_args()
    builds = {"mono": a.mono, "coreclr": a.coreclr}
    print(f"acconform check -n {a.n} -j {a.j} per run, live ACE; cases/s as the campaign reports it")
    print(f"{'seed':>6s} {'first':>8s} {'mono':>9s} {'coreclr':>9s} {'coreclr/mono':>13s}  "
          f"port s (mono, coreclr)  ACE s (mono, coreclr)  differences (mono, coreclr)")
    ratios, rates = [], {rt: [] for rt in RUNTIMES}
    for i, seed in enumerate(int(s) for s in a.seeds.split(",")):
        order = RUNTIMES if i % 2 == 0 else RUNTIMES[::-1]
        r = {rt: campaign(builds[rt], a.n, a.j, seed, a.kinds) for rt in order}
        ratio = r["coreclr"]["rate"] / r["mono"]["rate"]
        ratios.append(ratio)
        for rt in RUNTIMES:
            rates[rt].append(r[rt]["rate"])
        m, c = r["mono"], r["coreclr"]
        print(f"{seed:6d} {order[0]:>8s} {m['rate']:9.1f} {c['rate']:9.1f} {ratio:12.2f}x  "
              f"{m['port']:10.1f}, {c['port']:<10.1f} {m['oracle']:9.1f}, {c['oracle']:<10.1f} "
              f"{m['differences']}, {c['differences']}")
    print(f"{'median':>6s} {'':>8s} {statistics.median(rates['mono']):9.1f} {statistics.median(rates['coreclr']):9.1f} "
          f"{statistics.median(ratios):12.2f}x  ({sum(x >= 1 for x in ratios)} of {len(ratios)} pairs CoreCLR >= mono)")


if __name__ == "__main__":
    main()
