"""acconform check: a differential campaign, the port (or --impl) against ACE (live, or the recorded corpus).

Exit 0 when no difference was found, 1 when one was (each written as a case file under
--failures), 2 for bad input or when there is nothing to check against (no ACE configured and
no corpus), 130 when interrupted (after printing what the campaign found so far).

Replaying the corpus: ``--runtime`` picks the committed corpus of that runtime (default coreclr,
.NET 10, what users run; ``--runtime mono`` replays mono's), or with ``--corpus DIR`` only the
records of that runtime; ``-n`` replays a sample stratified by kind, drawn with ``--seed``; a tick-policy kind (motion, doors,
movers, missiles, targets) replays the ``ticks`` records whose scene needs its feature;
``--database`` (the campaign's saved failing scenes) has no use there and is refused.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

GENERATIVE_CASES = 1000


def add_arguments(p) -> None:
    from ..impl import add_arguments as impl_arguments

    p.add_argument("-n", "--cases", type=int, default=None,
                   help=f"scenes to draw (live; default {GENERATIVE_CASES}), or to sample from the corpus (default: all of it)")
    p.add_argument("--seed", type=int, default=None, help="campaign seed: the same seed draws the same scenes "
                   "(or the same corpus sample); default 0")
    from ..protocol import CAMPAIGN_KINDS  # strategies.DEFAULT_KINDS, what check_kinds(None) runs

    p.add_argument("--kinds", default=None, help=f"comma-separated scene kinds (default: all, {','.join(CAMPAIGN_KINDS)}; "
                   "ticks:<world> draws tick scenes over one world; motion, doors, movers, missiles, targets "
                   "draw one policy's tick scenes, only when named; replayed, the tick records that need its feature)")
    p.add_argument("--mode", choices=("exact", "fast"), default="exact", help="exact: float32 bit for bit; fast: port in doubles, ULP tolerance")
    p.add_argument("--keep-going", action="store_true", help="go on after a difference (each new kind of difference is "
                   "shrunk and saved); skip and count unreadable corpus records")
    p.add_argument("--shrink-budget", type=int, default=None, metavar="N", help="at most N smaller scenes run "
                   "per kind of difference while shrinking it (each runs both sides; a hang costs --timeout); 0: "
                   "write differences as found (default: Hypothesis' own limits live, 300 replaying)")
    p.add_argument("--failures", default="failures", metavar="DIR", help="where case files go (default ./failures)")
    p.add_argument("--database", default=None, metavar="DIR", help="the Hypothesis example database where a live campaign "
                   "keeps its failing scenes and retries them first next run, shared by the shards and runs that "
                   "name it: a directory (default .hypothesis/acconform), or github:OWNER/REPO[/ARTIFACT], the ones "
                   "a GitHub Actions artifact holds (read-only) beside the default directory")
    p.add_argument("--no-database", action="store_true", help="do not read or write the saved failing scenes")
    from . import positive_int

    p.add_argument("-j", "--workers", type=positive_int, default=None, help="worker processes (default: all cores)")
    p.add_argument("--ace", default=None, help="ACE assembly for the live oracle (else ACE_ASSEMBLY or the config file)")
    from . import add_runtime_argument

    add_runtime_argument(p, "the ACE compared with: live, the runtime the build is loaded on; replaying, the "
                         "committed corpus of that runtime. The port computes its arithmetic")
    p.add_argument("--corpus", default=None, metavar="DIR", help="recorded corpus to replay when no ACE is configured "
                   "(default: the committed corpus of --runtime)")
    impl_arguments(p)
    p.add_argument("--shard", default=None, metavar="K/N", help="run part K of N disjoint parts of the campaign (a "
                   "replay's records, or a live campaign's seeds as N x workers streams); `acconform merge` joins "
                   "the parts' --json summaries and --failures directories")
    p.add_argument("--json", default=None, metavar="FILE", help="write a JSON summary (cases, differences by field and kind, seed, versions, timings)")
    p.add_argument("--junit", default=None, metavar="FILE", help="write JUnit XML: one testcase per class of difference")
    p.add_argument("--no-progress", action="store_true", help="no progress bar")


def _say(msg: str) -> None:
    print(f"acconform check: {msg}", file=sys.stderr, flush=True)


def run(args) -> int:
    from ..errors import AcconformError
    from ..impl import make_backend
    from ..runner import check_failures_dir, check_output_file, default_workers
    from ..strategies import check_kinds

    kinds = check_kinds(args.kinds)
    from ..runner import parse_shard

    args.shard = parse_shard(args.shard) if args.shard is not None else (1, 1)
    if args.cases is not None and args.cases < 1:
        raise AcconformError(f"--cases must be at least 1, got {args.cases}")
    if args.shrink_budget is not None and args.shrink_budget < 0:
        raise AcconformError(f"--shrink-budget must be 0 (no shrinking) or more, got {args.shrink_budget}")
    if args.workers is not None and args.workers > default_workers():
        # each worker is a process (with its own ACE, live): more than the cores only slow the
        # campaign and multiply its memory, and the scenes a seed draws depend on the count
        raise AcconformError(f"--workers {args.workers}: this machine has {default_workers()} cores; more workers "
                             f"than cores only slow a campaign down (use -j {default_workers()} or fewer; "
                             "leave -j out for all cores)")
    # everything that could stop a finished campaign from being saved is checked before it starts
    # (the case directory itself is made only when a difference is written)
    check_failures_dir(args.failures)
    for path, option in ((args.json, "--json"), (args.junit, "--junit")):
        if path is not None:
            check_output_file(path, option)
    from ..oracle import default_corpus
    from ..paths import refuse_output_over_input

    # a report never lands on the corpus a replay reads (case files are named case-<hash>.json, never a shard's name)
    corpus = args.corpus if args.corpus is not None else default_corpus(args.runtime)
    for path, option in ((args.json, "--json"), (args.junit, "--junit")):
        refuse_output_over_input(path, [corpus], option)
    workers = args.workers or default_workers()
    port = make_backend(args.impl, args.mode, args.timeout)
    try:
        return _campaign(args, port, kinds, workers)
    finally:
        getattr(port, "close", lambda: None)()


def _campaign(args, port, kinds, workers) -> int:
    from collections import Counter

    from ..errors import AcconformError
    from ..impl import BuiltinPort
    from ..report import Campaign, junit, summary, write_json, write_junit
    from ..oracle import port_runtime
    from ..runner import DEFAULT_DATABASE, example_database, run_campaign

    impl_info = {"name": port.name, "version": (port.hello or {}).get("version", ""), "command": args.impl or ""}
    from ..protocol import CAMPAIGN_KINDS
    from ..strategies import kind_supported

    unsupported_kinds = [k for k in kinds if not kind_supported(k, getattr(port, "kinds", CAMPAIGN_KINDS))]
    run_kinds = tuple(k for k in kinds if k not in unsupported_kinds)
    if unsupported_kinds:
        if not run_kinds:
            raise AcconformError(f"implementation {port.name!r} supports none of the kinds asked for "
                                 f"({','.join(kinds)}); its handshake lists {','.join(port.kinds)}")
    presampled: Counter = Counter()  # corpus scenes passed over before the campaign (never sent)
    oracle, replay, bad = _oracle(args, workers, kinds, run_kinds, port, presampled)
    port.runtime = runtime = port_runtime(oracle, args.runtime)
    database = None if args.no_database else example_database(args.database or DEFAULT_DATABASE)
    seed = args.seed if args.seed is not None else 0
    who = f"implementation {port.name!r} ({args.impl})" if args.impl else "port"
    part, parts = args.shard
    if parts > 1:
        who += f", shard {part}/{parts}"
        # the scenes passed over before the campaign are counted once over the parts: in their part
        presampled_all = dict(presampled)
        presampled.clear()
        for why, count in presampled_all.items():
            presampled[why] = len(range(part - 1, count, parts))
    if replay is not None:
        source = f"recorded corpus ({len(range(part - 1, len(replay), parts))} of {len(replay)} scenes" \
            if parts > 1 else f"recorded corpus ({len(replay)} scenes"
        source += (f", a sample by kind, seed {seed}" if args.cases else "") + ")"
        _say(f"{who} vs {source}, mode {args.mode}, {runtime} arithmetic, {workers} worker{'s' if workers != 1 else ''}")
    else:
        from ..runner import shard_cases

        n = args.cases or GENERATIVE_CASES
        cases = f"{shard_cases(n, args.shard, workers)} of {n} cases" if parts > 1 else f"{n} cases"
        _say(f"{who} vs {getattr(oracle, 'name', 'oracle')} oracle, mode {args.mode}, {runtime} arithmetic, "
             f"kinds {','.join(run_kinds)}, "
             f"{cases}, seed {seed}, {workers} worker{'s' if workers != 1 else ''}")
    if unsupported_kinds:
        _say(f"skipping kinds {','.join(unsupported_kinds)}: the implementation's handshake does not list them")
    # replayed differences are shrunk against the built-in port standing in for ACE (where it
    # agrees with ACE's recorded answer), computing as the runtime the records come from
    stand_in = BuiltinPort("exact", runtime) if replay is not None else None
    result = run_campaign(port, oracle.run, kinds=run_kinds, n=args.cases or GENERATIVE_CASES, seed=seed,
                          mode=args.mode, keep_going=args.keep_going, failures_dir=args.failures,
                          database=database, workers=workers, progress=not args.no_progress, replay=replay,
                          stand_in=stand_in, shard=args.shard, shrink_budget=args.shrink_budget)
    campaign_started = time.monotonic() - result.elapsed
    result.skipped.update(presampled)
    result.cases += sum(presampled.values())
    if result.found and not result.interrupted:  # group the differences by their first divergence
        try:
            from ..explain import triage

            triage(result.found, port, args.mode, runtime, None if args.no_progress else _say,
                   _traced_ace(args, oracle, None if args.no_progress else _say))
        except KeyboardInterrupt:  # the cases are written: the summary says what was found, ungrouped
            result.interrupted = True
    bad = bad + result.unreadable
    lines = console_summary(result, bad, keep_going=args.keep_going)
    wall = time_spent(result, getattr(oracle, "load_seconds", {}), campaign_started)
    if wall is not None:  # where the wall time went, under the first line
        lines[1:1] = [wall_line(result, workers, "implementation" if args.impl else "port",
                                "the corpus" if replay is not None else "ACE")]
    for line in lines:
        print(line, flush=True)
    sampled = replay is None or args.cases is not None  # replaying the whole corpus draws nothing
    campaign = Campaign("recorded" if replay is not None else "live", args.mode, seed if sampled else None, run_kinds,
                        impl_info, str(args.failures), bad, tuple(unsupported_kinds))
    from ..runner import save_output

    # a report whose directory went away during the run goes to a temporary file, named here
    if args.json:
        doc = summary(result, campaign)
        if parts > 1:  # what `acconform merge` needs to join the parts
            doc["shard"] = {"part": part, "parts": parts, "cases_asked": None if replay is not None else
                            (args.cases or GENERATIVE_CASES), "workers": workers}
        warned = save_output(args.json, "--json", lambda p: write_json(p, doc))
        if warned:
            print(f"warning: {warned}")
    if args.junit:
        root = junit(result, campaign)
        warned = save_output(args.junit, "--junit", lambda p: write_junit(p, root))
        if warned:
            print(f"warning: {warned}")
    if result.interrupted:
        return 130
    if result.unreadable and not args.keep_going:
        raise AcconformError(f"{result.unreadable[0]} (--keep-going skips unreadable records)")
    return 1 if result.found else 0


def time_spent(result, loaded: dict, campaign_started: float) -> float | None:
    """Add to `result.timings` what came before and after the campaign: "startup" (the process's
    start to the campaign's, less ACE's loading), "ace_load" (`loaded`: the seconds of each step of
    loading ACE in this process, oracle/loading.py), "after" (the campaign's end to now) and "wall"
    (the process's start to now). Returns the wall seconds, or None where the process's start time
    cannot be read (timed.process_age)."""
    from ..timed import process_age

    age = process_age()
    if age is None:
        return None
    now = time.monotonic()
    t = result.timings
    t["ace_load"] += sum(loaded.values())
    t["startup"] = max(campaign_started - (now - age) - sum(loaded.values()), 0.0)
    t["after"] = max(now - campaign_started - result.elapsed, 0.0)
    t["wall"] = age
    return age


def wall_line(result, workers: int, tested: str, reference: str) -> str:
    """Where the wall time went (`time_spent`'s figures and the campaign's own: drawing, each side,
    comparing, shrinking; what never ran, as a replay's drawing, is left out). On several workers
    the campaign's figures are worker-seconds, summed."""
    t = result.timings
    loading = [("ACE loading", t["ace_load"])] if t["ace_load"] > 0 else []
    inside = [(what, t[k]) for what, k in (("drawing", "draw"), (tested, "port"), (reference, "oracle"),
                                           ("comparing", "compare"), ("shrinking", "shrink")) if t[k] > 0]
    if workers == 1:
        parts = [("start-up", t["startup"])] + loading + inside
        parts += [("the runner", result.elapsed - sum(x for _, x in inside)), ("after the campaign", t["after"])]
        return f"where the {t['wall']:.1f} s went: " + ", ".join(f"{what} {x:.1f} s" for what, x in parts)
    spent = loading + inside
    spent.append(("the runner and waiting", workers * result.elapsed - sum(x for _, x in spent)))
    return (f"where the {t['wall']:.1f} s went: start-up {t['startup']:.1f} s, the campaign {result.elapsed:.1f} s on "
            f"{workers} workers (worker-seconds: " + ", ".join(f"{what} {x:.1f} s" for what, x in spent)
            + f"), after the campaign {t['after']:.1f} s")


def _plural(n: int, word: str) -> str:
    return f"{n} {word}{'' if n == 1 else 's'}"


def console_summary(result, bad, keep_going: bool) -> list[str]:
    """What `check` prints at the end: what was run, compared, skipped and found (each once), the
    differences by outcome field and by scene kind, then each kind of difference with its case."""
    from collections import Counter

    from ..oracle.recorded import scene_kind

    skipped = sum(result.skipped.values())
    rate = result.cases / max(result.elapsed, 1e-9)
    head = "interrupted: " if result.interrupted else ""
    out = [f"{head}{result.cases} cases in {result.elapsed:.1f} s ({rate:.0f} cases/s): {result.compared} compared, "
           f"{skipped} skipped, {_plural(len(result.found), 'difference')}"]
    if result.skipped:
        ace = [why.startswith("this ACE ") for why in result.skipped]  # LiveOracle.unsupported's reasons
        who = "this ACE" if all(ace) else "the implementation or this ACE" if any(ace) else "the implementation"
        out.append(f"skipped {_plural(skipped, 'scene')} {who} cannot run: "
                   + ", ".join(f"{why} x{n}" for why, n in result.skipped.most_common()))
    if result.shrink_runs:
        out.append(f"shrinking ran {_plural(result.shrink_runs, 'more scene')} (not counted above)")
    if bad:
        how = "(--keep-going)" if keep_going else "(the campaign stopped there)"
        out.append(f"skipped {_plural(len(bad), 'unreadable corpus record')} {how}; first: {bad[0]}")
    if result.failures_fallback:
        out.append(f"warning: {result.failures_fallback}")
    if not result.found:
        return out
    by_field: Counter = Counter()
    by_kind: Counter = Counter()
    groups: dict[str, list] = {}
    for f in result.found:
        by_field.update(f.signature)
        by_kind[scene_kind(f.case.scene)] += 1
        groups.setdefault(f.group_key, []).append(f)
    traced = any(f.group for f in result.found)
    if result.ace_note:  # the ACE found is not the one the port follows: its own changes show here too
        out.append(result.ace_note)
    out.append(f"{_plural(len(result.found), 'difference')}, {len(groups)} distinct "
               + ("first divergence" + ("s" if len(groups) != 1 else "") if traced else
                  "set" + ("s" if len(groups) != 1 else "") + " of differing fields (the implementation gives no trace)"))
    out.append("differences by field: " + ", ".join(f"{k} x{n}" for k, n in sorted(by_field.items(), key=lambda kv: (-kv[1], kv[0]))))
    out.append("differences by kind:  " + ", ".join(f"{k} x{n}" for k, n in sorted(by_kind.items(), key=lambda kv: (-kv[1], kv[0]))))
    for key, found in groups.items():
        f = next((x for x in found if x.shrunk), found[0])  # one shrunk case per group
        known = f" -- known: ACE differs from retail here ({f.known})" if f.known else ""
        out.append(f"  {key}{known}")
        # its kind as "differences by kind" counts it: what the (shrunk) scene holds; its name is the
        # strategy that drew it, and shrinking can take away what made it that kind
        named = f", scene {f.case.scene.name!r}" if f.case.scene.name else ""
        out.append(f"    {f.path} ({shrink_label(f.case.shrink)}; kind {scene_kind(f.case.scene)}{named})")
        out += [f"      {line}" for line in f.case.differences]
        if len(found) > 1:
            out.append(f"    + {_plural(len(found) - 1, 'more case')} in this group (listed in --json)")
    return out


def shrink_label(shrink) -> str:
    sizes = ""
    if shrink.bytes_before and shrink.bytes_after:
        sizes = f", {shrink.bytes_before:,} -> {shrink.bytes_after:,} bytes"
    if shrink.against == "ace":
        return f"shrunk against ACE{sizes}"
    if shrink.against == "port":
        return f"shrunk against the built-in port standing in for ACE{sizes}"
    return shrink.note or "not shrunk"


def _oracle(args, workers: int, kinds, run_kinds, port, presampled):
    """(oracle, scenes to replay or None, unreadable records skipped). Exit 2 when there is nothing to compare against.

    Replaying, the scenes are a lazy sequence (each record parsed when its case runs). The kinds
    the implementation does not list are left out (a whole-corpus replay counts their records as
    skipped); a sample of -n N is drawn among the scenes the implementation can run, the ones it
    passes over counted in `presampled`."""
    from ..errors import AcconformError, OracleUnavailable
    from ..oracle import PerProcessOracle, default_corpus, get_oracle, live_configured
    from ..oracle.recorded import CorpusMissing, RecordedOracle, shards
    from ..runner import Status, scene_filter

    if live_configured(args.ace):
        say = None if args.no_progress else _say  # what loading ACE is doing (oracle/loading.py)
        if workers > 1:
            return PerProcessOracle(args.ace, args.runtime, say), None, []
        return get_oracle(args.ace, args.runtime, say=say), None, []
    # replaying: options that only a generative campaign uses are refused, not ignored
    one_world = [k for k in kinds if ":" in k]
    if one_world:
        raise AcconformError(f"--kinds {one_world[0]}: draws tick scenes over one world in a live campaign; a recorded "
                             "corpus is replayed by its shards' kinds (--kinds ticks)")
    if args.database is not None:
        raise AcconformError("--database keeps the failing scenes of live campaigns; replaying the "
                             "recorded corpus uses none (no ACE is configured)")
    if args.seed is not None and args.cases is None:
        raise AcconformError("--seed draws the corpus sample of -n; replaying the whole corpus uses no seed "
                             "(add -n N, or drop --seed)")
    corpus = Path(args.corpus) if args.corpus is not None else default_corpus(args.runtime)
    # one line while the shards load (redrawn on a terminal), then one saying what was read
    status = Status(not args.no_progress, prefix="acconform check: recorded corpus: ")
    t0 = time.monotonic()
    try:
        oracle = RecordedOracle(corpus, keep_going=args.keep_going, progress=status.say)
    except CorpusMissing as e:
        raise OracleUnavailable(f"nothing to check against: no ACE assembly is configured (pass --ace, set "
                                f"ACE_ASSEMBLY or the config file) and {e}") from None
    status.done(f"{len(oracle)} records from {len(shards(corpus))} shards of {corpus} read in "
                f"{time.monotonic() - t0:.1f} s")
    if args.runtime is not None and not oracle.select(runtime=args.runtime):
        raise AcconformError(f"--runtime {args.runtime}: the recorded corpus {corpus} holds no records of that "
                             f"runtime (it holds {', '.join(oracle.runtimes()) or 'none'})")
    # the sample's scenes are read to be weighed only when the port may pass one over (else each is
    # read once, when it is replayed)
    unsupported = scene_filter(port)
    entries = oracle.select(n=args.cases, seed=args.seed or 0, kinds=set(run_kinds), runtime=args.runtime,
                            unsupported=unsupported if args.cases is not None else None, skipped=presampled)
    if args.cases is None:
        for kind in set(kinds) - set(run_kinds):  # a tick-policy kind's records are filed as "ticks": named by its kind
            presampled[f"kind {kind}"] += len(oracle.select(kinds={kind}, runtime=args.runtime))
    if not entries:
        raise OracleUnavailable(f"nothing to check against: no ACE assembly is configured and the recorded corpus "
                                f"{corpus} holds no scenes of kinds {','.join(run_kinds)} (record some with `acconform "
                                f"record` where ACE is available)")
    return oracle, oracle.scenes(entries), oracle.bad


def _traced_ace(args, oracle, say):
    """The instrumented ACE (oracle/instrumented.py) when the campaign ran against a live ACE: the triage
    then compares with ACE's own trace; None when ACE is not live or cannot be instrumented here (the
    triage then uses the port's trace, as without ACE)."""
    if getattr(oracle, "name", None) != "live":
        return None
    from ..errors import OracleUnavailable
    from ..oracle.instrumented import TracedAce

    try:
        return TracedAce(args.ace, args.runtime, say)
    except OracleUnavailable as e:
        if say is not None:
            say(f"triage against the port's trace: no instrumented ACE ({e})")
        return None
