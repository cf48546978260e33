"""acconform record: run scenes through the live oracle (ACE) and append records to a corpus.

    acconform record SCENE.json ...                 scenes from files (scene, case or record files)
    acconform record tests/data/corpus/mono/*.jsonl.gz   the scenes of another corpus's shards
    acconform record -n 1000 --kinds terrain,bsp    scenes drawn from the strategies (sample_scenes)
    acconform record -n 500 --boundaries            keep only scenes whose port run hits an exact boundary

Records go to gzip'd JSON-lines shards <kind>-NNNN.jsonl.gz in --out (default: ./corpus/<runtime>
under the working directory, <runtime> being the one ACE ran on, mono or coreclr -- never into the
installed package, where the next install would lose them; the summary line says where they went).
To grow a checkout's committed corpus, give it: --out tests/data/corpus/<runtime>. Scenes already
in the output corpus are skipped. Needs a live ACE: without one it exits 2 saying how to configure it.

--boundaries keeps only scenes where the built-in port, traced (port/transition/branches.py),
compares two bit-equal values at an exact boundary other than a cell or landblock border (those
a plain campaign already ends on): a walkable or landing test at FloorZ/LandingZ, a tangency, a
BSP split with walkable polygons on both sides. With -n it draws until N such scenes are kept
(rounds of N draws, at most BOUNDARY_ROUNDS), so a corpus grows where bugs hide.
"""

from __future__ import annotations

import sys
import time

# rounds of N draws --boundaries may spend to keep N scenes (about 1 in 8 drawn scenes hits a
# boundary with the default kinds)
BOUNDARY_ROUNDS = 50
# boundaries a scene must hit for --boundaries: every one but the borders
BORDERS = ("cell_border", "landblock_border")
# where records go without --out: DEFAULT_OUT/<runtime> under the working directory
DEFAULT_OUT = "corpus"


def default_out(runtime: str):
    """The corpus `record` writes without --out: ./corpus/<runtime>, under the working directory."""
    from pathlib import Path

    return Path.cwd() / DEFAULT_OUT / runtime


def add_arguments(p) -> None:
    p.add_argument("files", nargs="*", metavar="FILE", help="scene, case or record files, or corpus shards (.jsonl.gz), whose scenes to record")
    p.add_argument("-n", type=int, default=0, help="also record N scenes drawn from the strategies")
    p.add_argument("--kinds", default=None, help="scene kinds to draw, comma-separated (default: the strategies' defaults; motion, doors, movers, "
                   "missiles, targets: one policy's tick scenes, recorded as ticks)")
    p.add_argument("--seed", type=int, default=0, help="seed for drawn scenes (default 0)")
    p.add_argument("--out", default=None, metavar="DIR", help=f"corpus directory (default: ./{DEFAULT_OUT}/<runtime> "
                   "under the working directory, <runtime> the one ACE runs on; a checkout's committed corpus is "
                   "tests/data/corpus/<runtime>)")
    p.add_argument("--ace", default=None, metavar="PATH", help="ACE.Server.dll or its directory (else ACE_ASSEMBLY, else the config file)")
    from . import add_runtime_argument, positive_int

    add_runtime_argument(p, "the .NET runtime to load the build on")
    p.add_argument("--batch", type=positive_int, default=256, help="scenes per call into ACE (default 256)")
    p.add_argument("--boundaries", action="store_true",
                   help="keep only scenes whose port run hits an exact boundary (not a cell/landblock border)")
    p.add_argument("-q", "--quiet", action="store_true", help="print only the summary")


def hits_boundary(scene, runtime: str = "mono") -> bool:
    """Whether the built-in port's run of `scene` compares bit-equal values at a boundary other
    than a cell or landblock border (branches.BOUNDARIES)."""
    import warnings

    from acconform.port.run import run_scene
    from acconform.port.transition.branches import BOUNDARIES, Trace

    trace = Trace()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        run_scene(scene, trace=trace, runtime=runtime)
    return any(trace["boundary:" + b] for b in BOUNDARIES if b not in BORDERS)


def _scenes(args, runtime: str):
    from ..case import iter_documents
    from ..scene import Scene

    for path in args.files:
        for where, doc in iter_documents(path):
            scene = doc if isinstance(doc, Scene) else getattr(doc, "scene", None)
            if scene is None:
                from ..errors import InvalidScene

                raise InvalidScene("", "an outcome file holds no scene to record", where)
            if not args.boundaries or hits_boundary(scene, runtime):
                yield scene
    if args.n > 0:
        from acconform.strategies import check_kinds

        kinds = check_kinds(args.kinds)
        if not args.boundaries:
            yield from spread_over_kinds(kinds, args.n, args.seed)
            return
        kept = 0
        for round_ in range(BOUNDARY_ROUNDS):
            # rounds of N draws, each seeded apart, until N boundary scenes are kept
            for scene in spread_over_kinds(kinds, args.n, args.seed * 1009 + round_):
                if hits_boundary(scene, runtime):
                    yield scene
                    kept += 1
                    if kept >= args.n:
                        return


def spread_over_kinds(kinds: tuple[str, ...], n: int, seed: int):
    """`n` scenes spread evenly over `kinds` (the first n % len(kinds) kinds one more), interleaved;
    each kind's drawn with sample_scenes((kind,), its share, seed), as bench and stress draw per kind.
    A draw across the kinds at once (scenes(kinds), one choice of kind per scene) can give a small
    -n none of a kind named."""
    from itertools import chain, zip_longest

    from acconform.strategies import sample_scenes

    per_kind = [list(sample_scenes((k,), n // len(kinds) + (i < n % len(kinds)), seed)) for i, k in enumerate(kinds)]
    return [s for s in chain.from_iterable(zip_longest(*per_kind)) if s is not None]


def run(args) -> int:
    from pathlib import Path

    from ..case import Record
    from ..errors import AcconformError
    from ..numerics import runtime_named
    from ..oracle import require_live
    from ..oracle.recorded import CorpusWriter, RecordedOracle, scene_key

    if not args.files and args.n <= 0:
        raise AcconformError("nothing to record: give scene files and/or -n N")
    # what can be checked before ACE starts is checked first: a bad option costs no wait for ACE
    if args.kinds is not None:
        from ..strategies import check_kinds

        check_kinds(args.kinds)
    if args.out is not None:
        from ..paths import refuse_output_over_input
        from ..runner import check_writable

        refuse_output_over_input(args.out, args.files, "--out")
        check_writable(args.out, "--out")
    from ..oracle.loading import to_stderr

    oracle = require_live(args.ace, args.runtime, say=None if args.quiet else to_stderr)
    out = Path(args.out) if args.out else default_out(runtime_named(oracle.versions.runtime))
    try:
        known = set(RecordedOracle(out).index())
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

        for scene in _scenes(args, runtime_named(oracle.versions.runtime)):
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
          f"recorded, into {out.resolve()} in {dt:.1f}s with {oracle.versions.ace} on {oracle.versions.runtime}")
    return 0
