"""Time to the first case of a corpus replay, for one or more acconform installs side by side.

    python benchmarks/bench_first_case.py [--rounds 2] [LABEL=PYTHON ...]

For each install (a Python whose `acconform` is the one measured; default: this one) and each
round, alternating installs so drift in machine load hits them alike, measures:

- `check -n 1 -j 1`: the wall time of a whole one-case replay (start, corpus load, one case, exit);
- `check -j 1` (the whole corpus): the seconds until the campaign's start line ("... vs recorded
  corpus ...") is printed, after which the first case runs; the replay is then stopped.

No ACE is used (ACE_ASSEMBLY is unset), so both replay the committed .NET 10 corpus. Each figure
is wall seconds and, less sensitive to other jobs on the machine, the CPU seconds (user + system)
the acconform process spent. Prints the median per install and measure, and the load average.
"""

from __future__ import annotations

import argparse
import os
import signal
import statistics
import subprocess
import sys
import tempfile
import time


def _env() -> dict:
    env = dict(os.environ)
    env.pop("ACE_ASSEMBLY", None)
    env.pop("ACE_RUNTIME", None)
    return env


def _cpu(pid: int) -> float:
    """utime + stime of a running process, in seconds (/proc)."""
    fields = open(f"/proc/{pid}/stat").read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def one_case(python: str, cwd: str) -> tuple[float, float]:
    import resource

    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.monotonic()
    subprocess.run([python, "-m", "acconform.cli", "check", "-n", "1", "-j", "1", "--no-progress", "--failures",
                    os.path.join(cwd, "f")], cwd=cwd, env=_env(), capture_output=True, check=False)
    wall = time.monotonic() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def to_campaign_start(python: str, cwd: str) -> tuple[float, float]:
    t0 = time.monotonic()
    p = subprocess.Popen([python, "-m", "acconform.cli", "check", "-j", "1", "--failures", os.path.join(cwd, "f")],
                         cwd=cwd, env=_env(), stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                         start_new_session=True)
    try:
        for line in p.stderr:
            if " vs recorded corpus " in line:
                return time.monotonic() - t0, _cpu(p.pid)
        return float("nan"), float("nan")
    finally:
        os.killpg(p.pid, signal.SIGKILL)
        p.wait()


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("installs", nargs="*", metavar="LABEL=PYTHON")
    ap.add_argument("--rounds", type=int, default=2)
    a = ap.parse_args()
    installs = [i.split("=", 1) for i in a.installs] or [["this", sys.executable]]
    figures: dict[tuple[str, str], list[tuple[float, float]]] = {}
    print(f"load average before: {os.getloadavg()[0]:.1f}")
    with tempfile.TemporaryDirectory() as cwd:
        for r in range(a.rounds):
            for label, python in installs:
                for name, fn in (("check -n 1", one_case), ("whole corpus: to the first case", to_campaign_start)):
                    wall, cpu = fn(python, cwd)
                    figures.setdefault((label, name), []).append((wall, cpu))
                    print(f"round {r + 1} {label:>8}: {name} {wall:.1f} wall, {cpu:.1f} CPU", flush=True)
    print(f"load average after: {os.getloadavg()[0]:.1f}")
    for (label, name), ts in figures.items():
        walls, cpus = [w for w, _ in ts], [c for _, c in ts]
        print(f"{label:>8}  {name:32} median {statistics.median(walls):6.1f} s wall ({', '.join(f'{t:.1f}' for t in walls)}), "
              f"{statistics.median(cpus):6.1f} s CPU ({', '.join(f'{t:.1f}' for t in cpus)})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
