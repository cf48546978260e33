"""Protocol overhead: cases/s of the same corpus sample through the in-process port and through
`acconform serve` as a separate process (acconform.protocol/1), in one run, one worker each.

    python benchmarks/bench_protocol.py [-n 1500] [--seed 0] [--rounds 3]

Alternates the two for --rounds rounds and prints each rate, then the medians and their ratio
(the issue's target: the protocol at most 1.3x slower). The process start and handshake are
outside the timed part (once per campaign, not per case).
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time


def _cpu_of(impl) -> float:
    """CPU seconds the implementation's process has used so far (Linux /proc; 0 elsewhere)."""
    import os

    try:
        fields = open(f"/proc/{impl._proc.pid}/stat").read().rsplit(")", 1)[1].split()
    except (OSError, AttributeError):
        return 0.0
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def main() -> int:
    p = argparse.ArgumentParser()
    p.add_argument("-n", type=int, default=1500)
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--rounds", type=int, default=3)
    args = p.parse_args()

    from acconform.impl import BuiltinPort
    from acconform.numerics import runtime_named
    from acconform.oracle import default_corpus
    from acconform.oracle.recorded import RecordedOracle
    from acconform.protocol import Implementation
    from acconform.runner import run_campaign

    oracle = RecordedOracle(default_corpus())
    runtime = runtime_named(oracle.versions.runtime)
    scenes = list(oracle.scenes(oracle.select(n=args.n, seed=args.seed)))
    serve = Implementation(f"{sys.executable} -m acconform.cli serve")
    rates: dict[str, list[float]] = {"in-process port": [], "acconform serve": []}
    cpu: dict[str, list[float]] = {"in-process port": [], "acconform serve": []}
    try:
        for round_ in range(args.rounds):  # alternated, so a change in the machine's load hits both
            for name, port in (("in-process port", BuiltinPort()), ("acconform serve", serve)):
                port.runtime = runtime  # the port computes as the ACE whose answers it is compared with
                t0, c0, s0 = time.perf_counter(), time.process_time(), _cpu_of(serve)
                r = run_campaign(port, oracle.run, replay=scenes, failures_dir=None, workers=1, keep_going=True)
                rates[name].append(r.cases / (time.perf_counter() - t0))
                cpu[name].append((time.process_time() - c0 + _cpu_of(serve) - s0) / r.cases * 1e3)
                print(f"round {round_ + 1}: {name:16} {r.cases} cases, {len(r.found)} differences: "
                      f"{rates[name][-1]:.0f} cases/s, {cpu[name][-1]:.2f} ms CPU per case (both processes)")
    finally:
        serve.close()
    port, served = statistics.median(rates["in-process port"]), statistics.median(rates["acconform serve"])
    cport, cserved = statistics.median(cpu["in-process port"]), statistics.median(cpu["acconform serve"])
    print(f"median of {args.rounds} rounds: in-process {port:.0f} cases/s, serve {served:.0f} cases/s; "
          f"protocol overhead {port / served:.2f}x in cases/s, {cserved / cport:.2f}x in CPU per case")
    return 0


if __name__ == "__main__":
    sys.exit(main())
