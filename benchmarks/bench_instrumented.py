"""The cost of the instrumented ACE (oracle/instrumented.py) beside the plain one, side by side in one run.

    ACE_ASSEMBLY=<build> python benchmarks/bench_instrumented.py [--runtime mono|coreclr] [-n 40] [--repeat 2]
        [--dump FILE]

Scenes: a sample of -n corpus scenes stratified by kind (seed 0). Each pass runs every scene, in turn, on the plain
ACE (this process), on the instrumented copy with its recorder off (`run`), with it on and its records counted in
the worker (`count`: the .NET recorder's cost alone), and traced: the run with its trace handed over to this process
as the recorder wrote it (`handed`), then read into acconform.trace records (`read`; both together, `trace`, are
what explain pays). The best of --repeat passes of each is printed as ms a scene (wall clock: the worker is another
process), with its ratio to the plain run and the records a scene. The worker starts cold (the landblock cache off,
as a traced run must), so its `run` column includes loading each scene's landblocks from the DATs, which the plain
ACE keeps. --dump FILE writes each scene's raw recorder lines (a change to the recorder's speed alone must leave
them byte-identical: `cmp` two dumps)."""

from __future__ import annotations

import argparse
import hashlib
import json
import sys
import time

CLOCK = time.perf_counter


def main() -> int:
    p = argparse.ArgumentParser()
    p.add_argument("--runtime", default=None)
    p.add_argument("-n", type=int, default=40)
    p.add_argument("--repeat", type=int, default=2)
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--dump", default=None, help="write each scene's recorder lines to this file")
    args = p.parse_args()
    import warnings

    warnings.simplefilter("ignore")
    from acconform.oracle import default_corpus
    from acconform.oracle.instrumented import TracedAce, records_from
    from acconform.oracle.live import LiveOracle
    from acconform.oracle.recorded import RecordedOracle, scene_kind

    plain = LiveOracle(None, args.runtime, say=None)
    runtime = plain.location.runtime
    traced = TracedAce(plain.location.assembly, runtime, say=None)
    corpus = RecordedOracle(default_corpus(runtime))
    scenes = [corpus._record(e).scene for e in corpus.select(n=args.n, seed=args.seed)]
    for s in scenes[:3]:  # warm both sides (JIT, the worker's start)
        plain.run(s)
        traced.run(s)
        traced.counted(s)
    best = {k: float("inf") for k in ("plain", "run", "count", "trace", "read")}
    records = 0
    dump = []
    for rep in range(args.repeat):
        spent = dict.fromkeys(best, 0.0)
        records = 0
        for s in scenes:
            t = CLOCK()
            plain.run(s)
            spent["plain"] += CLOCK() - t
            t = CLOCK()
            traced.run(s)
            spent["run"] += CLOCK() - t
            t = CLOCK()
            _, n = traced.counted(s)
            spent["count"] += CLOCK() - t
            records += n
            t = CLOCK()
            if hasattr(traced, "trace_text"):
                outcome, text = traced.trace_text(s)
            else:  # before the lines followed the answer as they are (main 7e03fac)
                from acconform.outcome import Outcome

                doc = traced._ask("trace", s)
                outcome, text = Outcome.from_json(doc["outcome"], "outcome"), doc["records"]
            t1 = CLOCK()
            records_from(text, traced.ids, outcome)
            t2 = CLOCK()
            spent["trace"] += t2 - t
            spent["read"] += t2 - t1
            if rep == 0 and args.dump:
                key = hashlib.sha256(json.dumps(s.to_json(), sort_keys=True).encode()).hexdigest()[:12]
                dump.append(f"# {scene_kind(s)} {key}\n")
                dump.append(text)
        for k in best:
            best[k] = min(best[k], spent[k])
    traced.close()
    if args.dump:
        with open(args.dump, "w") as f:
            f.writelines(dump)
    ms = {k: v * 1000 / len(scenes) for k, v in best.items()}
    print(f"{runtime}: {len(scenes)} scenes ({', '.join(sorted({scene_kind(s) for s in scenes}))}), best of {args.repeat}, "
          f"{records / len(scenes):.0f} records a scene")
    ms["handed"] = ms["trace"] - ms["read"]
    print(f"{'run':<46} {'ms/scene':>9} {'x plain':>8}")
    for k, label in (("plain", "plain ACE"), ("run", "instrumented, recorder off"),
                     ("count", "instrumented, recorder on (count)"), ("handed", "instrumented, traced (the trace handed over)"),
                     ("read", "reading it into trace records (Python)"), ("trace", "traced and read (what explain pays)")):
        print(f"{label:<46} {ms[k]:>9.1f} {ms[k] / ms['plain']:>7.1f}x")
    return 0


if __name__ == "__main__":
    sys.exit(main())
