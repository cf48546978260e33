"""The instrumented ACE against the plain one over a whole corpus: how many scenes it answers exactly as
the plain ACE does (recorder on), and how many of them its trace agrees with the port's at the grain both
write (trace.against_ace; only scenes the port answers as ACE does).

    ACE_ASSEMBLY=<build> python benchmarks/instrumented_corpus.py [--runtime mono|coreclr] [-n N]
        [--answers-only] [--shards GLOB,...] [--per-shard N] [--progress N] [--seconds S]

The plain ACE runs in this process, the instrumented copy in its worker (oracle/instrumented.py). Prints
the counts, and the first few scenes that differ."""

from __future__ import annotations

import argparse
import fnmatch
import sys
import time


def main() -> int:
    p = argparse.ArgumentParser()
    p.add_argument("--runtime", default=None)
    p.add_argument("-n", type=int, default=None, help="a stratified sample of N scenes (default: all)")
    p.add_argument("--answers-only", action="store_true", help="compare the answers only (recorder on, its records "
                   "counted, not compared with the port's trace): the whole corpus in minutes")
    p.add_argument("--shards", default=None, help="only the shards whose file name matches one of these "
                   "comma-separated globs (e.g. 'ticks-005*,ticks-006*,*': those first, then the rest), in the order given")
    p.add_argument("--per-shard", type=int, default=None, help="only the first N scenes of each shard (every shard "
                   "represented when the whole corpus cannot run in the time there is)")
    p.add_argument("--progress", type=int, default=1000, help="print the counts so far every N scenes (0: never)")
    p.add_argument("--seconds", type=float, default=None, help="stop after S seconds and print how far it got")
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
    if args.shards:
        globs = [g.strip() for g in args.shards.split(",") if g.strip()]
        picked = {}  # id -> entry, in the globs' order, each once ('ticks-006*,*': the newest first, then the rest)
        for g in globs:
            picked.update((id(e), e) for e in entries if id(e) not in picked and fnmatch.fnmatch(e.shard.path.name, g))
        entries = list(picked.values())
        if not entries:
            print(f"--shards {args.shards}: no shard of {corpus.corpus_dir} matches", file=sys.stderr)
            return 2
    if args.per_shard is not None:
        taken: dict[str, int] = {}
        kept = []
        for e in entries:
            name = e.shard.path.name
            if taken.get(name, 0) < args.per_shard:
                taken[name] = taken.get(name, 0) + 1
                kept.append(e)
        entries = kept
    done = 0
    shards_done: dict[str, int] = {}
    same = traces_agree = port_agrees = 0
    shown = 0
    t0 = time.monotonic()
    for e in entries:
        if args.seconds is not None and time.monotonic() - t0 > args.seconds:
            print(f"stopped after {args.seconds:.0f} s", flush=True)
            break
        if args.progress and done and done % args.progress == 0:
            print(f"{done} of {len(entries)} scenes: {same} answered as the plain ACE, {done - same} differ "
                  f"({time.monotonic() - t0:.0f} s; now {e.shard.path.name})", flush=True)
        done += 1
        name = e.shard.path.name
        shards_done[name] = shards_done.get(name, 0) + 1
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
    print(f"shards run: {', '.join(f'{k} ({v})' for k, v in shards_done.items())}")
    print(f"{runtime}: {same} of {done} scenes (of {len(entries)} selected) answered exactly as the plain ACE (recorder on); "
          f"ACE's trace agrees with the port's on {traces_agree} of the {port_agrees} the port answers as ACE "
          f"({time.monotonic() - t0:.0f} s)")
    return 0 if same == done == len(entries) else 1


if __name__ == "__main__":
    sys.exit(main())
