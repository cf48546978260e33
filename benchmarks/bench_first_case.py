"""Time to the first case of `check`, for one or more acconform installs side by side.

    python benchmarks/bench_first_case.py [--rounds 2] [--live] [LABEL=PYTHON ...]

For each install (a Python whose `acconform` is the one measured; default: this one) and each
round, alternating installs so drift in machine load hits them alike, measures:

- `check -n 1 -j 1`: the wall time of a whole one-case campaign (start, loading, one case, exit);
- the seconds until the campaign's start line ("... vs recorded corpus ..." / "... vs live oracle
  ...") is printed, after which the first case runs (the whole-corpus replay, or the one-case live
  campaign), and the longest silence on stderr before it: what a user waits without a word;
- live, the seconds until the first case is done (the one-case campaign's progress line "1/1
  cases"): **the seconds to the first live case**, the figure issue 44 bounds (5 s warm).

Without --live, ACE is not used (ACE_ASSEMBLY and ACE_RUNTIME are unset), so both replay the
committed .NET 10 corpus. With --live, ACE is found as `check` finds it (ACE_ASSEMBLY, ACE_RUNTIME,
the config file) and each measure runs twice: **cold**, with an empty facade cache
(XDG_CACHE_HOME a fresh directory, so the C# facade is compiled), and **warm**, with the facade
compiled before. Each figure is wall seconds and, less sensitive to other jobs on the machine, the
CPU seconds (user + system) the acconform process and its children spent. Prints which ACE was
found (the oracle's "ACE: ..." line), the median per install and measure, and the load average.
"""

from __future__ import annotations

import argparse
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time


def _env(live: bool, cache: str | None) -> dict:
    """The environment of a run: live, its facade cache in `cache`; replaying, no ACE (and the
    user's own cache, which holds the corpus's keys)."""
    env = dict(os.environ)
    if live:
        env["XDG_CACHE_HOME"] = cache
    else:
        env.pop("ACE_ASSEMBLY", None)
        env.pop("ACE_RUNTIME", None)
    return env


def _children_cpu() -> float:
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def one_case(python: str, cwd: str, live: bool, cache: str | None) -> tuple[float, float]:
    before = _children_cpu()
    t0 = time.monotonic()
    subprocess.run([python, "-m", "acconform.cli", "check", "-n", "1", "-j", "1", "--no-progress", "--no-database",
                    "--failures", os.path.join(cwd, "f")], cwd=cwd, env=_env(live, cache), capture_output=True,
                   check=False)
    return time.monotonic() - t0, _children_cpu() - before


def to_campaign_start(python: str, cwd: str, live: bool, cache: str | None) -> tuple[float, ...]:
    """(wall seconds to the start line, CPU seconds of the whole run, the longest silence on stderr
    before the start line[, live: wall seconds to the first case done]). Live, the one-case
    campaign runs to its end; replaying, the whole corpus is stopped once the line is out."""
    cmd = [python, "-m", "acconform.cli", "check", "-j", "1", "--no-database", "--failures", os.path.join(cwd, "f")]
    cmd += ["-n", "1"] if live else []
    before = _children_cpu()
    t0 = time.monotonic()
    p = subprocess.Popen(cmd, cwd=cwd, env=_env(live, cache), stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                         text=True, start_new_session=True)
    started = silence = first = float("nan")
    last = t0
    try:
        for line in p.stderr:
            now = time.monotonic()
            if started != started:
                silence = max(0.0 if silence != silence else silence, now - last)
            last = now
            if line.startswith("acconform check: ACE: ") and line not in SEEN_ACE:
                SEEN_ACE.append(line)
                print(f"  {line.strip()}", flush=True)
            if " vs recorded corpus " in line or " vs live oracle," in line:
                started = now - t0
                if not live:
                    break
            if live and " 1/1 cases" in line:
                first = now - t0
        if not live:
            p.kill()  # the rest of the corpus is not measured
    finally:
        p.stderr.close()
        p.wait()
    return (started, _children_cpu() - before, silence) + ((first,) if live else ())


SEEN_ACE: list[str] = []  # the oracle's "ACE: ..." lines, printed once each


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("installs", nargs="*", metavar="LABEL=PYTHON")
    ap.add_argument("--rounds", type=int, default=2)
    ap.add_argument("--live", action="store_true", help="live ACE (as check finds it), cold and warm facade cache")
    a = ap.parse_args()
    installs = [i.split("=", 1) for i in a.installs] or [["this", sys.executable]]
    if a.live and not os.environ.get("ACE_ASSEMBLY"):
        print("--live: set ACE_ASSEMBLY to the ACE.Server.dll to measure", file=sys.stderr)
        return 2
    figures: dict[tuple[str, str], list[tuple[float, ...]]] = {}
    print(f"load average before: {os.getloadavg()[0]:.1f}; {'live ACE ' + os.environ['ACE_ASSEMBLY'] if a.live else 'recorded corpus'}")
    with tempfile.TemporaryDirectory() as cwd:
        warm = os.path.join(cwd, "warm-cache")
        if a.live:  # the warm cache holds the facade compiled once beforehand
            one_case(installs[0][1], cwd, True, warm)
        caches = [("warm", warm), ("cold", "")] if a.live else [("", None)]
        for r in range(a.rounds):
            for label, python in installs:
                for temp, cache in caches:
                    for name, fn in (("check -n 1", one_case), ("to the start line", to_campaign_start)):
                        # cold: each run a cache of its own, empty
                        here = tempfile.mkdtemp(dir=cwd, prefix="cold-cache-") if cache == "" else cache
                        got = fn(python, cwd, a.live, here)
                        key = f"{temp} {name}".strip()
                        figures.setdefault((label, key), []).append(got)
                        silence = f", longest silence {got[2]:.1f} s" if len(got) > 2 else ""
                        first = f", first live case at {got[3]:.1f} s" if len(got) > 3 else ""
                        print(f"round {r + 1} {label:>8}: {key} {got[0]:.1f} wall, {got[1]:.1f} CPU{silence}{first}",
                              flush=True)
    print(f"load average after: {os.getloadavg()[0]:.1f}")
    for (label, name), ts in figures.items():
        cols = list(zip(*ts))
        text = (f"{label:>8}  {name:28} median {statistics.median(cols[0]):6.1f} s wall "
                f"({', '.join(f'{t:.1f}' for t in cols[0])}), {statistics.median(cols[1]):6.1f} s CPU")
        if len(cols) > 2:
            text += f", longest silence {statistics.median(cols[2]):.1f} s ({', '.join(f'{t:.1f}' for t in cols[2])})"
        if len(cols) > 3:
            text += f", first live case at {statistics.median(cols[3]):.1f} s ({', '.join(f'{t:.1f}' for t in cols[3])})"
        print(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
