"""acconform record: run scenes through the live oracle (ACE) and append records to a corpus.

    acconform record SCENE.json ...                 scenes from files (scene, case or record files)
    acconform record tests/data/corpus/mono/*.jsonl.gz   the scenes of another corpus's shards
    acconform record -n 1000 --kinds terrain,bsp    scenes drawn from the strategies (sample_scenes)

Records go to gzip'd JSON-lines shards <kind>-NNNN.jsonl.gz in --out (default: the committed
corpus of the runtime ACE ran on, tests/data/corpus/<mono|coreclr>). Scenes already in the
corpus are skipped. Needs a live ACE: without one it
exits 2 saying how to configure it.
"""

from __future__ import annotations

import sys
import time


def add_arguments(p) -> None:
    p.add_argument("files", nargs="*", metavar="FILE", help="scene, case or record files, or corpus shards (.jsonl.gz), whose scenes to record")
    p.add_argument("-n", type=int, default=0, help="also record N scenes drawn from the strategies")
    p.add_argument("--kinds", default=None, help="scene kinds to draw, comma-separated (default: the strategies' defaults)")
    p.add_argument("--seed", type=int, default=0, help="seed for drawn scenes (default 0)")
    p.add_argument("--out", default=None, metavar="DIR", help="corpus directory (default: the committed "
                   "corpus of the runtime ACE runs on, tests/data/corpus/<runtime>)")
    p.add_argument("--ace", default=None, metavar="PATH", help="ACE.Server.dll or its directory (else ACE_ASSEMBLY, else the config file)")
    p.add_argument("--runtime", choices=("mono", "coreclr"), default=None, help="force the .NET runtime (default: from the build)")
    p.add_argument("--batch", type=int, default=256, help="scenes per call into ACE (default 256)")
    p.add_argument("-q", "--quiet", action="store_true", help="print only the summary")


def _scenes(args):
    from ..case import iter_documents
    from ..scene import Scene

    for path in args.files:
        for where, doc in iter_documents(path):
            scene = doc if isinstance(doc, Scene) else getattr(doc, "scene", None)
            if scene is None:
                from ..errors import InvalidScene

                raise InvalidScene("", "an outcome file holds no scene to record", where)
            yield scene
    if args.n > 0:
        from acconform.strategies import sample_scenes

        kinds = tuple(k for k in args.kinds.split(",") if k) if args.kinds else None
        yield from sample_scenes(kinds, args.n, args.seed)


def run(args) -> int:
    from ..case import Record
    from ..errors import AcconformError
    from ..numerics import runtime_named
    from ..oracle import default_corpus, require_live
    from ..oracle.recorded import CorpusWriter, RecordedOracle, scene_key

    if not args.files and args.n <= 0:
        raise AcconformError("nothing to record: give scene files and/or -n N")
    oracle = require_live(args.ace, args.runtime)
    out = args.out or default_corpus(runtime_named(oracle.versions.runtime))
    try:
        known = set(RecordedOracle(out)._lines)
    except AcconformError:
        known = set()
    t0 = time.perf_counter()
    done = skipped = errors = 0
    with CorpusWriter(out) as writer:
        batch = []

        def flush():
            nonlocal done, errors
            for scene, (outcome, _us) in zip(batch, oracle.run_many(batch)):
                writer.add(Record(scene, outcome, oracle.versions))
                done += 1
                errors += outcome.error is not None
            batch.clear()

        for scene in _scenes(args):
            key = scene_key(scene)
            if key in known:
                skipped += 1
                continue
            known.add(key)
            batch.append(scene)
            if len(batch) >= args.batch:
                flush()
                if not args.quiet:
                    print(f"recorded {done} ...", file=sys.stderr)
        if batch:
            flush()
    dt = time.perf_counter() - t0
    kinds = ", ".join(f"{k} {n}" for k, n in sorted(writer.written.items())) or "none"
    print(f"recorded {done} scenes ({kinds}; {errors} ACE exceptions as verdicts), skipped {skipped} already "
          f"recorded, into {out} in {dt:.1f}s with {oracle.versions.ace} on {oracle.versions.runtime}")
    return 0
