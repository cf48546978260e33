"""acconform bench: the port's run time against its error, exact (float32) mode vs fast (double) mode.

For N scenes per kind (drawn with acconform.strategies.sample_scenes when ACE is configured or
with --no-oracle; else taken from a recorded corpus: --corpus DIR, by default the committed corpus
of --runtime, .NET 10's unless --runtime mono) runs the port in both modes and prints per kind: milliseconds per scene
in each mode and their ratio; how many scenes' discrete outcome (ok, cells, flags, validity
bits, water, SpherePath bits, error presence) differs; and, per float field of the outcome,
the max and median float32 ULP distance and absolute error of fast mode against exact mode,
and against the oracle when there is one (live ACE, or the corpus's recorded answers). Float
figures are taken over the scenes whose discrete outcome agrees (a scene that took another
branch is counted once, in the discrete column, instead of swamping the float columns).

Fast mode is no workaround for a runtime's arithmetic: against an oracle, bench ends with how
many scenes fast mode gets wrong as `check --mode fast` judges it (the comparator's ULP
tolerance), beside exact mode's count (bit for bit).

A benchmark that prints figures, not a test: it always exits 0 (2 for bad options).
`--json FILE` also writes every figure.
"""

from __future__ import annotations

import sys


def add_arguments(p) -> None:
    p.add_argument("-n", "--cases", type=int, default=200, help="scenes per kind (default 200)")
    p.add_argument("--seed", type=int, default=0, help="seed for drawn scenes (default 0)")
    from ..protocol import CAMPAIGN_KINDS  # strategies.DEFAULT_KINDS, what check_kinds(None) runs

    p.add_argument("--kinds", default=None, help=f"comma-separated scene kinds (default: all, {','.join(CAMPAIGN_KINDS)})")
    p.add_argument("--corpus", nargs="?", const="", default=None, metavar="DIR",
                   help="take the scenes (and the oracle's answers) from a recorded corpus (default: the committed "
                   "corpus of --runtime; what bench does when no ACE is configured)")
    p.add_argument("--no-oracle", action="store_true", help="do not compare against an oracle even when ACE is configured")
    p.add_argument("--ace", default=None, help="ACE assembly for the live oracle (else ACE_ASSEMBLY or the config file)")
    from . import add_runtime_argument

    add_runtime_argument(p, "the ACE compared with (the live oracle's runtime, or the committed corpus --corpus "
                         "takes); the port computes its arithmetic, also with --no-oracle")
    p.add_argument("--json", default=None, metavar="FILE", help="also write the figures as JSON")
    p.add_argument("--no-progress", action="store_true", help="no progress lines (with an ETA) on stderr")
    from ..impl import add_arguments as impl_arguments

    impl_arguments(p)


# ---------------------------------------------------------------- outcome leaves (shared with stress)


def leaves(outcome, prefix: str = ""):
    """(path, value) for every leaf of an Outcome, vectors split into components (path[i])."""
    from dataclasses import fields, is_dataclass

    for f in fields(outcome):
        v = getattr(outcome, f.name)
        path = prefix + f.name
        if is_dataclass(v):
            yield from leaves(v, path + ".")
        elif isinstance(v, tuple):
            for i, c in enumerate(v):
                yield f"{path}[{i}]", c
        else:
            yield path, v


def float_part(outcome) -> dict[str, float]:
    return {p: v for p, v in leaves(outcome) if isinstance(v, float)}


def discrete_part(outcome) -> tuple:
    """Every non-float leaf; an error counts by its presence (its message is free text)."""
    return tuple((p, (v is not None) if p == "error" else v) for p, v in leaves(outcome) if not isinstance(v, float))


def nonfinite_fields(outcome) -> list[str]:
    import math

    return [p for p, v in float_part(outcome).items() if not math.isfinite(v)]


def distance(a: float, b: float) -> tuple[float, float]:
    """(float32 ULPs, absolute error) between a and b; NaN~NaN is 0 apart, any other non-finite pair inf."""
    import math

    from ..compare import ulp_distance

    if math.isnan(a) and math.isnan(b):
        return 0.0, 0.0
    if not (math.isfinite(a) and math.isfinite(b)):
        return (0.0, 0.0) if a == b else (math.inf, math.inf)
    return float(ulp_distance(a, b)), abs(a - b)


class ErrorStats:
    """One comparison (e.g. fast against exact) over a kind's scenes."""

    def __init__(self):
        self.scenes = 0
        self.discrete = 0  # scenes whose discrete outcome differs
        self.ulps: dict[str, list[float]] = {}
        self.abs: dict[str, list[float]] = {}

    def add(self, a, b) -> None:
        self.scenes += 1
        if discrete_part(a) != discrete_part(b):
            self.discrete += 1
            return
        if a.error is not None:  # both raised: no floats to compare
            return
        fb = float_part(b)
        for path, va in float_part(a).items():
            u, e = distance(va, fb[path])
            self.ulps.setdefault(path, []).append(u)
            self.abs.setdefault(path, []).append(e)

    def fields(self) -> dict[str, dict[str, float]]:
        from statistics import median

        return {p: {"ulp_max": max(us), "ulp_median": median(us), "abs_max": max(self.abs[p]),
                    "abs_median": median(self.abs[p])} for p, us in self.ulps.items()}

    def to_json(self):
        return {"scenes": self.scenes, "discrete_differs": self.discrete,
                "float_scenes": len(next(iter(self.ulps.values()), [])), "fields": self.fields()}


# ---------------------------------------------------------------- the run


def _scenes(args, kinds):
    """{kind: scenes}, and the recorded oracle when the scenes come from a corpus."""
    from ..runner import Progress
    from ..strategies import sample_scenes

    bar = Progress(len(kinds), not args.no_progress, unit="kinds",
                   label=f"acconform bench: {'drawing' if args.corpus is None else 'reading'} {args.cases} scenes per kind ")
    bar.update(0, force=True)
    if args.corpus is None:
        out = {}
        for i, k in enumerate(kinds):
            out[k] = list(sample_scenes((k,), args.cases, args.seed))
            bar.update(i + 1)
        bar.close(len(kinds))
        return out, None
    from ..errors import AcconformError
    from ..oracle import default_corpus
    from ..oracle.recorded import RecordedOracle

    oracle = RecordedOracle(args.corpus or default_corpus(args.runtime))
    # the first records of each kind, parsed only once taken (a tick-policy kind's, filed as "ticks", by its own select)
    entries: dict[str, list] = {k: oracle.select(kinds={k})[:args.cases] for k in kinds}
    out = {}
    for i, k in enumerate(kinds):
        out[k] = list(oracle.scenes(entries[k]))
        bar.update(i + 1)
    bar.close(len(kinds))
    empty = [k for k, ss in out.items() if not ss]
    if empty:
        raise AcconformError(f"the corpus {oracle.corpus_dir} holds no scenes of kind {', '.join(empty)} "
                             f"(choose others with --kinds)")
    return out, oracle


def measure_kind(scenes, oracle=None, run_scene=None, runtime: str | None = None, tick=None) -> dict:
    """Every figure for one kind's scenes: timings and the three comparisons.

    `run_scene(scene, mode=...)` is the implementation measured (default: the built-in port).
    `runtime` (--runtime): the arithmetic computed without an oracle (commands.runtime_or_default).
    `tick()` (optional) hears each scene run in both modes, and each the oracle answers.
    """
    tick = tick or (lambda: None)
    import time

    from ..compare import compare
    from . import runtime_or_default

    if run_scene is None:
        from ..port.run import run_scene

    # the port computes as the ACE it is compared with (whose answers the figures use), else as --runtime
    rt = runtime_or_default(None, oracle) if oracle is not None else runtime_or_default(runtime)
    t_exact = t_fast = 0.0
    fast_exact, fast_oracle, exact_oracle = ErrorStats(), ErrorStats(), ErrorStats()
    errors = {"exact": 0, "fast": 0, "oracle": 0}

    run_scene(scenes[0], mode="exact", runtime=rt), run_scene(scenes[0], mode="fast", runtime=rt)  # warm caches and imports
    exact, fast = [], []
    for s in scenes:  # modes alternate scene by scene, so drift in machine load hits both alike
        t0 = time.perf_counter()
        e = run_scene(s, mode="exact", runtime=rt)
        t1 = time.perf_counter()
        f = run_scene(s, mode="fast", runtime=rt)
        t2 = time.perf_counter()
        t_exact += t1 - t0
        t_fast += t2 - t1
        exact.append(e)
        fast.append(f)
        tick()
        fast_exact.add(f, e)
        errors["exact"] += e.error is not None
        errors["fast"] += f.error is not None
    n = len(scenes)
    out = {"scenes": n, "ms_exact": 1000 * t_exact / n, "ms_fast": 1000 * t_fast / n,
           "exact_over_fast": t_exact / max(t_fast, 1e-12), "errors": errors,
           "fast_vs_exact": fast_exact.to_json()}
    if oracle is not None:
        t0 = time.perf_counter()
        if hasattr(oracle, "run_many"):
            answers = []
            ace_us = 0.0
            for i in range(0, n, 256):
                for o, us in oracle.run_many(scenes[i:i + 256]):
                    answers.append(o)
                    ace_us += us
                    tick()
            out["ms_oracle_ace"] = ace_us / 1000 / n
        else:
            answers = []
            for s in scenes:
                answers.append(oracle.run(s))
                tick()
        out["ms_oracle_wall"] = 1000 * (time.perf_counter() - t0) / n
        # what a campaign reports: scenes the comparator finds different (fast: within its ULP tolerance)
        out["check_differs"] = {"fast": 0, "exact": 0}
        for e, f, o in zip(exact, fast, answers):
            fast_oracle.add(f, o)
            exact_oracle.add(e, o)
            errors["oracle"] += o.error is not None
            out["check_differs"]["fast"] += bool(compare(f, o, "fast"))
            out["check_differs"]["exact"] += bool(compare(e, o, "exact"))
        out["fast_vs_oracle"] = fast_oracle.to_json()
        out["exact_vs_oracle"] = exact_oracle.to_json()
    return out


def _g(x: float) -> str:
    return "inf" if x == float("inf") else (f"{x:.0f}" if x == int(x) and abs(x) < 1e9 else f"{x:.3g}")


def render_kind(kind: str, r: dict, oracle_name: str | None) -> list[str]:
    fe = r["fast_vs_exact"]
    head = (f"{kind}: {r['scenes']} scenes; ms/scene exact {r['ms_exact']:.2f}, fast {r['ms_fast']:.2f}, "
            f"exact/fast {r['exact_over_fast']:.2f}")
    if "ms_oracle_wall" in r:
        head += f"; {oracle_name} oracle {r['ms_oracle_wall']:.2f}"
        if "ms_oracle_ace" in r:
            head += f" (ACE's FindValidPosition {r['ms_oracle_ace']:.3f})"
    lines = [head]
    disc = f"  discrete outcome differs: fast vs exact {fe['discrete_differs']}/{fe['scenes']}"
    if "fast_vs_oracle" in r:
        disc += (f", fast vs oracle {r['fast_vs_oracle']['discrete_differs']}/{r['scenes']}"
                 f", exact vs oracle {r['exact_vs_oracle']['discrete_differs']}/{r['scenes']}")
    errs = r["errors"]
    lines.append(disc + f"; exceptions as verdicts: exact {errs['exact']}, fast {errs['fast']}"
                 + (f", oracle {errs['oracle']}" if "fast_vs_oracle" in r else ""))
    if "check_differs" in r:
        cd = r["check_differs"]
        lines.append(f"  differences from ACE as check counts them: fast mode (ULP tolerance) {cd['fast']}/{r['scenes']}, "
                     f"exact mode (bits) {cd['exact']}/{r['scenes']}")
    cols = [("fast vs exact", fe)] + ([("fast vs oracle", r["fast_vs_oracle"])] if "fast_vs_oracle" in r else [])
    width = 36
    titles = [f"{name} ({c['float_scenes']} scenes)" for name, c in cols]
    lines.append(f"  {'':{width}}" + "".join(f" | {t:^39}" for t in titles))
    lines.append(f"  {'float field':{width}}" + " | ulp max  ulp med    abs max    abs med" * len(cols))
    for path in fe["fields"]:
        row = f"  {path:{width}}"
        for _, c in cols:
            s = c["fields"].get(path)
            row += (" | " + f"{_g(s['ulp_max']):>7}  {_g(s['ulp_median']):>7}  {s['abs_max']:9.3g}  {s['abs_median']:9.3g}"
                    if s else " | " + f"{'-':>7}  {'-':>7}  {'-':>9}  {'-':>9}")
        lines.append(row)
    return lines


def run(args) -> int:
    import json
    import warnings

    from ..errors import AcconformError
    from ..strategies import check_kinds

    warnings.simplefilter("ignore", RuntimeWarning)
    kinds = check_kinds(args.kinds)
    if args.cases < 1:
        raise AcconformError(f"--cases must be at least 1, got {args.cases}")
    if args.json:
        from ..paths import refuse_output_over_input
        from ..runner import check_output_file

        refuse_output_over_input(args.json, [args.corpus] if args.corpus else [], "--json")
        check_output_file(args.json, "--json")  # before the run, not after it
    run, impls = _implementation(args, kinds)
    if impls:
        from ..strategies import kind_supported

        kinds = tuple(k for k in kinds if kind_supported(k, impls["exact"].kinds))
        if not kinds:
            raise AcconformError(f"implementation {impls['exact'].name!r} supports none of the kinds asked for")
    try:
        return _bench(args, kinds, run, json, AcconformError)
    finally:
        for impl in impls.values():
            impl.close()


def _implementation(args, kinds):
    """(run_scene for the scenes measured, {mode: Implementation} to close): the port, or --impl in both modes."""
    if args.impl is None:
        return None, {}
    from ..impl import make_backend

    impls = {}
    try:
        for mode in ("exact", "fast"):  # bench sets the modes side by side: the implementation needs both
            impls[mode] = make_backend(args.impl, mode, args.timeout)
    except Exception:
        for impl in impls.values():
            impl.close()
        raise

    def run(scene, mode="exact", runtime="mono"):
        impls[mode].runtime = runtime
        return impls[mode](scene)

    return run, impls


def _bench(args, kinds, run, json, AcconformError) -> int:
    from ..oracle import live_configured, require_live

    if args.corpus is None and not args.no_oracle and not live_configured(args.ace):
        args.corpus = ""  # no ACE: ACE's recorded answers (the committed corpus of --runtime)
    by_kind, oracle = _scenes(args, kinds)
    source = f"recorded corpus {oracle.corpus_dir}" if oracle is not None else f"sample_scenes seed {args.seed}"
    note = None
    if args.no_oracle:
        oracle, note = None, "oracle columns off (--no-oracle): fast mode's disagreement with ACE is not measured"
    elif oracle is None:
        oracle = require_live(args.ace, args.runtime)
    oracle_name = getattr(oracle, "name", None)
    who = f"implementation {args.impl!r}" if args.impl else "the port"
    print(f"acconform bench: {who}; {', '.join(kinds)}; up to {args.cases} scenes per kind from {source}; oracle "
          + (f"{oracle_name} ({oracle.versions.ace} on {oracle.versions.runtime})" if oracle is not None else "none"),
          flush=True)
    if note:
        print(note)
    from ..runner import Progress

    results = {}
    per_scene = 2 if oracle is not None else 1  # both modes, then the oracle
    bar = Progress(sum(len(by_kind[k]) for k in kinds) * per_scene, not args.no_progress, unit="steps",
                   label="acconform bench: measuring ")
    done = [0]

    def tick():
        done[0] += 1
        bar.update(done[0])

    for k in kinds:
        results[k] = measure_kind(by_kind[k], oracle, run, args.runtime, tick)
        print()
        print("\n".join(render_kind(k, results[k], oracle_name)), flush=True)
    bar.close(done[0])
    if oracle is not None:
        n = sum(r["scenes"] for r in results.values())
        fast = sum(r["check_differs"]["fast"] for r in results.values())
        exact = sum(r["check_differs"]["exact"] for r in results.values())
        print(f"\nfast mode disagrees with ACE ({oracle.versions.runtime}) on {fast} of {n} scenes "
              f"({100 * fast / n:.1f}%) even within its ULP tolerance; exact mode on {exact}. Fast mode is a "
              f"run-time/error measurement, not a way to check a port.")
    if args.json:
        doc = {"format": "acconform.bench/1", "source": source, "seed": args.seed, "implementation": args.impl or "",
               "oracle": None if oracle is None else {"name": oracle_name, "ace": oracle.versions.ace,
                                                      "runtime": oracle.versions.runtime},
               "kinds": results}
        from ..runner import save_output

        def write(path):
            with open(path, "w", encoding="utf-8") as f:
                json.dump(_finite(doc), f, indent=1, allow_nan=False)
                f.write("\n")

        warned = save_output(args.json, "--json", write)  # its directory may have gone during the run
        print(f"\nwarning: {warned}" if warned else f"\nfigures written to {args.json}", file=sys.stderr)
    return 0


def _finite(x):
    """JSON has no inf or NaN: such figures are written as the strings "inf", "-inf", "nan"."""
    import math

    if isinstance(x, dict):
        return {k: _finite(v) for k, v in x.items()}
    if isinstance(x, float) and not math.isfinite(x):
        return str(x)
    return x
