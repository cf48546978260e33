"""Print issue 21's figure for ACE's stepped trace: on how many corpus scenes the stepped run ends in
exactly ACE's own outcome, and agrees step by step with the port's trace.

    ACE_ASSEMBLY=/path/to/ACE.Server.dll python tests/oracle/stepped_check.py [-n 2000] [--port-every 1]

Takes N records of the runtime's recorded corpus, a sample stratified by kind (seed 0), tick scenes left out;
per scene, LiveOracle.stepped_trace (the facade drives FindTransitionalPosition's loop through ACE's
public methods and snapshots it at each pass) must not refuse, i.e. the stepped run ends in ACE's
unstepped outcome; where the port's outcome equals ACE's, the port's `step` records must equal ACE's
steps (acconform.trace.first_divergence at the step grain), checked on every --port-every'th scene
(a traced port run costs some 20x ACE's).
"""

from __future__ import annotations

import argparse
import sys
import time
import warnings


def main() -> int:
    p = argparse.ArgumentParser()
    p.add_argument("-n", type=int, default=2000)
    p.add_argument("--runtime", default=None, help="default: the configured ACE's")
    p.add_argument("--port-every", type=int, default=1, help="compare the port's steps on every k-th scene")
    args = p.parse_args()
    warnings.simplefilter("ignore")

    from acconform.compare import compare
    from acconform.oracle import default_corpus, require_live
    from acconform.oracle.live import SteppedTraceRefused
    from acconform.oracle.recorded import RecordedOracle
    from acconform.port.run import traced_run
    from acconform.trace import first_divergence

    ace = require_live(None, args.runtime)
    runtime = ace.location.runtime
    corpus = RecordedOracle(default_corpus(runtime))
    t0 = time.monotonic()
    n = held = refused = steps_agree = steps_differ = port_differs = 0
    total_steps = 0
    for entry in corpus.select(n=args.n, seed=0, runtime=runtime):  # a sample stratified by kind
        rec = corpus._record(entry)
        if rec.scene.ticks is not None:
            continue
        n += 1
        try:
            outcome, steps = ace.stepped_trace(rec.scene)
            held += 1
            total_steps += len(steps)
        except SteppedTraceRefused as e:
            refused += 1
            print(f"refused: {rec.scene.name}: {e}", flush=True)
            if n >= args.n:
                break
            continue
        if (n - 1) % args.port_every:
            if n >= args.n:
                break
            continue
        port_outcome, port_trace = traced_run(rec.scene, "exact", runtime)
        if compare(port_outcome, outcome):
            port_differs += 1
        elif first_divergence(port_trace, steps) is None:
            steps_agree += 1
        else:
            steps_differ += 1
            d = first_divergence(port_trace, steps)
            print(f"steps differ: {rec.scene.name}: step {d.step} {d.field}: port={d.a_value!r} ace={d.b_value!r}",
                  flush=True)
        if n >= args.n:
            break
    print(f"{runtime}: {n} corpus scenes, the stepped run ended in ACE's own outcome on {held} "
          f"({refused} refused; {total_steps} steps); of those compared with the port (every {args.port_every}) where the port's outcome is ACE's, the port's steps equal ACE's on "
          f"{steps_agree}, differ on {steps_differ} ({port_differs} where the port's outcome differs); "
          f"{time.monotonic() - t0:.0f} s")
    return 0 if refused == 0 and steps_differ == 0 and n >= args.n else 1


if __name__ == "__main__":
    sys.exit(main())
