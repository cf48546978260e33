"""The instrumented ACE against the plain one over a whole corpus: how many scenes it answers exactly as
the plain ACE does (recorder on), and how many of them its trace agrees with the port's at the grain both
write (trace.against_ace; only scenes the port answers as ACE does).

    ACE_ASSEMBLY=<build> python benchmarks/instrumented_corpus.py [--runtime mono|coreclr] [-n N]

The plain ACE runs in this process, the instrumented copy in its worker (oracle/instrumented.py). Prints
the counts, and the first few scenes that differ."""

from __future__ import annotations

import argparse
import sys
import time


def main() -> int:
    p = argparse.ArgumentParser()
    p.add_argument("--runtime", default=None)
    p.add_argument("-n", type=int, default=None, help="a stratified sample of N scenes (default: all)")
    p.add_argument("--answers-only", action="store_true", help="compare the answers only (recorder on, its records "
                   "counted, not compared with the port's trace): the whole corpus in minutes")
    args = p.parse_args()
    from acconform.compare import compare
    from acconform.oracle import default_corpus
    from acconform.oracle.instrumented import TracedAce
    from acconform.oracle.live import LiveOracle
    from acconform.oracle.recorded import RecordedOracle, scene_kind
    from acconform.port.run import traced_run
    from acconform.trace import against_ace

    plain = LiveOracle(None, args.runtime, say=None)
    runtime = plain.location.runtime
    traced = TracedAce(plain.location.assembly, runtime, say=None)
    corpus = RecordedOracle(default_corpus(runtime))
    entries = corpus.select(n=args.n, seed=0) if args.n else corpus.entries
    same = traces_agree = port_agrees = 0
    shown = 0
    t0 = time.monotonic()
    for e in entries:
        scene = corpus._record(e).scene
        answer = plain.run(scene)
        if args.answers_only:
            outcome, _count = traced.counted(scene)
            records = None
        else:
            outcome, records = traced.trace(scene)
        if compare(outcome, answer, "exact"):
            if shown < 5:
                print(f"differs: {scene_kind(scene)} {e.where}", flush=True)
                shown += 1
            continue
        same += 1
        if records is None:
            continue
        port_outcome, port = traced_run(scene, "exact", runtime)
        if not compare(port_outcome, answer, "exact"):
            port_agrees += 1
            if against_ace(records, port, traced.kinds, scene.ticks is not None, traced.overloaded) is None:
                traces_agree += 1
    traced.close()
    print(f"{runtime}: {same} of {len(entries)} scenes answered exactly as the plain ACE (recorder on); "
          f"ACE's trace agrees with the port's on {traces_agree} of the {port_agrees} the port answers as ACE "
          f"({time.monotonic() - t0:.0f} s)")
    return 0 if same == len(entries) else 1


if __name__ == "__main__":
    sys.exit(main())
