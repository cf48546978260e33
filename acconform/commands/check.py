"""acconform check: a differential campaign, port against ACE (live, or the recorded corpus).

Exit 0 when no difference was found, 1 when one was (each written as a case file under
--failures), 2 when there is nothing to check against (no ACE configured and no corpus).
"""

from __future__ import annotations

import sys


def add_arguments(p) -> None:
    p.add_argument("-n", "--cases", type=int, default=1000, help="scenes to draw (generative campaigns; default 1000)")
    p.add_argument("--seed", type=int, default=0, help="campaign seed: the same seed draws the same scenes (default 0)")
    p.add_argument("--kinds", default=None, help="comma-separated scene kinds: terrain, bsp, obstacles (default: what the port supports)")
    p.add_argument("--mode", choices=("exact", "fast"), default="exact", help="exact: float32 bit for bit; fast: port in doubles, ULP tolerance")
    p.add_argument("--keep-going", action="store_true", help="go on after a difference (each new kind of difference is shrunk and saved)")
    p.add_argument("--failures", default="failures", metavar="DIR", help="where case files go (default ./failures)")
    p.add_argument("--database", default=None, metavar="DIR", help="Hypothesis example database (default .hypothesis/acconform)")
    p.add_argument("--no-database", action="store_true", help="do not read or write the example database")
    p.add_argument("-j", "--workers", type=int, default=0, help="worker processes (default: all cores)")
    p.add_argument("--ace", default=None, help="ACE assembly for the live oracle (else ACE_ASSEMBLY or the config file)")
    p.add_argument("--runtime", default=None, help="runtime for the live oracle (mono or coreclr)")
    p.add_argument("--corpus", default=None, metavar="DIR", help="recorded corpus to replay when no ACE is configured")
    p.add_argument("--no-progress", action="store_true", help="no progress bar")


def run(args) -> int:
    from ..errors import AcconformError
    from ..runner import DEFAULT_DATABASE, default_workers, run_campaign
    from ..strategies import check_kinds

    kinds = check_kinds(args.kinds)
    if args.cases < 1:
        raise AcconformError(f"--cases must be at least 1, got {args.cases}")
    workers = args.workers or default_workers()
    oracle, replay = _oracle(args, workers)
    from ..port.run import run_scene

    mode = args.mode
    runtime = _port_runtime(args, oracle)

    def port(scene):
        return run_scene(scene, mode=mode, runtime=runtime)

    database = None if args.no_database else (args.database or DEFAULT_DATABASE)
    source = f"recorded corpus ({len(replay)} scenes)" if replay is not None else f"{getattr(oracle, 'name', 'oracle')} oracle"
    print(f"acconform check: port vs {source}, mode {mode}, {runtime} arithmetic, "
          + (f"kinds {','.join(kinds)}, {args.cases} cases, seed {args.seed}, " if replay is None else "")
          + f"{workers} worker{'s' if workers != 1 else ''}", file=sys.stderr)
    result = run_campaign(port, oracle.run, kinds=kinds, n=args.cases, seed=args.seed, mode=mode,
                          keep_going=args.keep_going, failures_dir=args.failures, database=database,
                          workers=workers, progress=not args.no_progress, replay=replay)
    rate = result.cases / max(result.elapsed, 1e-9)
    print(f"{result.cases} cases in {result.elapsed:.1f} s ({rate:.0f} cases/s): "
          f"{len(result.found)} difference{'s' if len(result.found) != 1 else ''}")
    for f in result.found:
        how = "shrunk" if f.shrunk else "as recorded, not shrunk"
        print(f"  {f.path} ({how}; {f.case.scene.name or 'scene'})")
        for line in f.case.differences:
            print(f"    {line}")
    return 1 if result.found else 0


def _port_runtime(args, oracle) -> str:
    """The runtime whose arithmetic the port computes: the live oracle's (from the build, or
    --runtime), else the one the corpus was recorded on."""
    from ..numerics import runtime_named

    if getattr(oracle, "name", "") == "live":
        from ..oracle.config import resolve

        return resolve(args.ace, args.runtime).runtime
    return runtime_named(oracle.versions.runtime)


def _oracle(args, workers: int):
    """(oracle, scenes to replay or None). Exit-2 errors when there is nothing to compare against."""
    from ..errors import AcconformError, OracleUnavailable
    from ..oracle import PerProcessOracle, get_oracle, live_configured

    live = live_configured(args.ace)
    if live and workers > 1:
        return PerProcessOracle(args.ace, args.runtime), None
    try:
        oracle = get_oracle(args.ace, args.runtime, args.corpus)
        if getattr(oracle, "name", "") == "live":
            return oracle, None
        scenes = list(oracle.scenes()) if hasattr(oracle, "scenes") else []
    except AcconformError as e:
        if live:
            raise
        raise OracleUnavailable(f"nothing to check against: no ACE assembly is configured (pass --ace, set "
                                f"ACE_ASSEMBLY or the config file) and {e}") from None
    if args.kinds is not None:
        scenes = [s for s in scenes if _kind(s) in set(args.kinds.split(","))]
    if not scenes:
        raise OracleUnavailable(
            "nothing to check against: no ACE assembly is configured (pass --ace, set ACE_ASSEMBLY or the "
            "config file) and the recorded corpus" + (f" {args.corpus}" if args.corpus else "")
            + " holds no scenes" + (f" of kinds {args.kinds}" if args.kinds else "")
            + " (record one with `acconform record` where ACE is available)")
    return oracle, scenes


def _kind(scene) -> str:
    try:
        from ..oracle.recorded import scene_kind

        return scene_kind(scene)
    except ImportError:
        pass
    if not scene.objects:
        return "terrain"
    return "bsp" if any(o.shape.kind == "bsp" for o in scene.objects) else "obstacles"
