"""Protocol overhead: cases/s of the same corpus sample through the in-process port and through
`acconform serve` as a separate process (acconform.protocol/1), in one run, one worker each.

    python benchmarks/bench_protocol.py [-n 1500] [--seed 0]

Prints both rates and their ratio (the issue's target: the protocol at most 1.3x slower). The
process start and handshake are outside the timed part (once per campaign, not per case).
"""

from __future__ import annotations

import argparse
import sys
import time


def main() -> int:
    p = argparse.ArgumentParser()
    p.add_argument("-n", type=int, default=1500)
    p.add_argument("--seed", type=int, default=0)
    args = p.parse_args()

    from acconform.impl import BuiltinPort
    from acconform.oracle import DEFAULT_CORPUS
    from acconform.oracle.recorded import RecordedOracle
    from acconform.protocol import Implementation
    from acconform.runner import run_campaign

    oracle = RecordedOracle(DEFAULT_CORPUS)
    scenes = list(oracle.scenes(oracle.select(n=args.n, seed=args.seed)))
    serve = Implementation(f"{sys.executable} -m acconform.cli serve")
    rates = {}
    try:
        for name, port in (("in-process port", BuiltinPort()), ("acconform serve", serve),
                           ("in-process port again", BuiltinPort())):
            t0 = time.perf_counter()
            r = run_campaign(port, oracle.run, replay=scenes, failures_dir=None, workers=1, keep_going=True)
            rates[name] = r.cases / (time.perf_counter() - t0)
            print(f"{name:22} {r.cases} cases, {len(r.found)} differences: {rates[name]:.0f} cases/s")
    finally:
        serve.close()
    base = (rates["in-process port"] + rates["in-process port again"]) / 2
    print(f"protocol overhead: {base / rates['acconform serve']:.2f}x (in-process {base:.0f} cases/s, "
          f"serve {rates['acconform serve']:.0f} cases/s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
