"""acconform coverage --branches: how often each port branch fires on generated scenes.

Draws scenes with acconform.strategies.sample_scenes, runs each through the port with a branch
counter, and prints per branch: scenes (per 1,000) in which it fired at least once, and total
fires per 1,000 scenes. Key branches (EdgeSlide, CliffSlide, PrecipiceSlide, StepUp, StepDown)
are marked; one that never fired is listed with 0 so a silent skip cannot pass for coverage.

Beside it, the boundary table: per exact boundary (port/transition/branches.py BOUNDARIES: a
normal.z bit-equal to FloorZ or LandingZ, exact sphere and cylsphere tangency, walkable polygons on
both sides of a BSP split, moves ending on a cell or landblock border), the scenes per 1,000 that
hit it exactly, and those that came within 4 ulps of it.

It takes no --impl: branches and anchors are counted inside the built-in port, in process; an
implementation behind the protocol is a black box (its own tools must count its branches).

A scene on which the port raises (an ACE exception the port reproduces, or a port bug) is written
as a scene file under --errors (made only then) and listed on stderr with the exception's message,
so `acconform run FILE` replays it.
"""

from __future__ import annotations

import sys
import time
from collections import Counter

KEY_PREFIXES = ("edge_slide", "cliff_slide", "precipice_slide", "step_up", "step_down")
NEAR_ULPS = 4
DEFAULT_ERRORS = "coverage-errors"


def add_arguments(p) -> None:
    p.add_argument("--branches", action="store_true", help="print the branch table (the default report)")
    p.add_argument("--anchors", action="store_true", help="print calls per retail anchor and the anchors never reached "
                   "(with --branches, both tables)")
    p.add_argument("-n", "--cases", type=int, default=1000, help="scenes to draw (default 1000)")
    p.add_argument("--seed", type=int, default=0)
    from ..protocol import CAMPAIGN_KINDS  # strategies.DEFAULT_KINDS, what check_kinds(None) runs

    p.add_argument("--kinds", default=None, help=f"comma-separated scene kinds (default: all, {','.join(CAMPAIGN_KINDS)})")
    p.add_argument("--mode", choices=("exact", "fast"), default="exact")
    p.add_argument("--errors", default=DEFAULT_ERRORS, metavar="DIR", help="where a scene the port raises on is "
                   f"written, to replay with `acconform run` (default ./{DEFAULT_ERRORS}, made only then)")
    from . import add_runtime_argument

    add_runtime_argument(p, "whose System.Numerics arithmetic the port computes (branches can fire differently)")


def known_branches() -> list[str]:
    from ..port.transition.branches import BRANCHES

    return sorted(BRANCHES)


def measure(kinds, n: int, seed: int, mode: str = "exact", runtime: str | None = None):
    """(per-scene branch presence Counter, total fires Counter, generation s, port s, errors).
    A boundary hit counts as "boundary:<name>"; one within NEAR_ULPS of it as "near:<name>".
    `errors`: (index of the scene among the n drawn, the scene, the outcome's error) per scene the
    port raised on. `runtime`: the arithmetic computed (commands.runtime_or_default)."""
    from ..port.run import run_scene
    from . import runtime_or_default

    runtime = runtime_or_default(runtime)
    from ..port.transition.branches import Trace
    from ..strategies import check_kinds, sample_scenes

    t0 = time.perf_counter()
    scenes = list(sample_scenes(check_kinds(kinds), n, seed))
    gen = time.perf_counter() - t0
    present: Counter = Counter()
    total: Counter = Counter()
    errors = []
    t1 = time.perf_counter()
    for i, s in enumerate(scenes):
        trace = Trace()
        o = run_scene(s, mode=mode, trace=trace, runtime=runtime)
        if o.error:
            errors.append((i, s, o.error))
        total.update(trace)
        present.update(trace.keys())
        present.update(f"near:{b}" for b, ulps in trace.closest.items() if ulps <= NEAR_ULPS)
    return present, total, gen, time.perf_counter() - t1, errors


def run(args) -> int:
    import warnings

    from ..strategies import check_kinds

    kinds = check_kinds(args.kinds)
    if args.cases < 1:
        from ..errors import AcconformError

        raise AcconformError(f"--cases must be at least 1, got {args.cases}")
    from ..runner import check_failures_dir

    check_failures_dir(args.errors, "--errors")
    warnings.simplefilter("ignore", RuntimeWarning)
    from contextlib import nullcontext

    from ..anchor_coverage import counting_anchors, render_table

    with counting_anchors() if args.anchors else nullcontext() as counted:
        present, total, gen, port, errors = measure(kinds, args.cases, args.seed, args.mode, args.runtime)
    if args.anchors and not args.branches:
        print(f"kinds {','.join(kinds)}, {args.cases} scenes, seed {args.seed}, mode {args.mode}")
        print("\n".join(render_table(counted.calls, counted.unwrapped)))
        return 0
    n = args.cases
    names = sorted((set(known_branches()) | set(total)) - {k for k in total if k.startswith("boundary:")})
    print(f"kinds {','.join(kinds)}, {n} scenes, seed {args.seed}: generation {n / gen:.0f} scenes/s, "
          f"port {n / port:.0f} scenes/s")
    print(f"{'branch':48} {'scenes/1000':>12} {'fires/1000':>11}")
    for name in names:
        key = "*" if name.startswith(KEY_PREFIXES) or name.endswith(KEY_PREFIXES) or ":" + name.split(":")[-1] in (
            ":cliff_slide", ":precipice_slide") else " "
        print(f"{key}{name:47} {present[name] * 1000 / n:12.1f} {total[name] * 1000 / n:11.1f}")
    from ..port.transition.branches import MEASURED_IN_ULPS

    print(f"\n{'boundary (hit exactly)':48} {'scenes/1000':>12} {'within ' + str(NEAR_ULPS) + ' ulps':>14}")
    for name in boundary_names():
        near = f"{present['near:' + name] * 1000 / n:14.1f}" if name in MEASURED_IN_ULPS else f"{'-':>14}"
        print(f" {name:47} {present['boundary:' + name] * 1000 / n:12.1f} {near}")
    if args.anchors:
        print("\n".join(render_table(counted.calls, counted.unwrapped)))
    if errors:
        options = "".join(f" --{k} {v}" for k, v in (("mode", args.mode), ("runtime", args.runtime))
                          if v is not None and v != "exact")
        for line in report_errors(errors, args.errors, args.seed, n, options):
            print(line, file=sys.stderr)
    return 0


def report_errors(errors, directory, seed: int, n: int, options: str = "") -> list[str]:
    """Each scene the port raised on written under `directory` (a temporary directory when that
    cannot be written, said so), and the lines naming them: the count by exception type, then each
    distinct message with its first scene's file and how many more scenes raised it. `options`: the
    `run` options that replay it as coverage ran it (" --runtime mono")."""
    import tempfile
    from pathlib import Path

    from ..case import write_document
    from ..runner import scene_hash

    by_type = Counter(e.split(":", 1)[0] for _, _, e in errors)
    out = ["port errors: " + ", ".join(f"{k} x{v}" for k, v in by_type.most_common())]
    target, fallback = Path(directory), None
    by_message: dict[str, list] = {}
    for i, scene, error in errors:
        path = target / f"scene-{scene_hash(scene)[:12]}.json"
        try:
            write_document(path, scene)
        except OSError as e:
            if fallback is not None:
                raise
            fallback = f"could not write to {target} ({e.strerror or e}); the scenes are in "
            target = Path(tempfile.mkdtemp(prefix="acconform-coverage-errors-"))
            fallback += str(target)
            path = write_document(target / path.name, scene)
        by_message.setdefault(error, []).append((i, scene, path))
    for error, found in by_message.items():
        i, scene, path = found[0]
        more = f"; {len(found) - 1} more scene{'s' if len(found) > 2 else ''} raised it" if len(found) > 1 else ""
        out.append(f"  {error}")
        out.append(f"    scene {i + 1} of {n} (seed {seed}, {scene.name or 'unnamed'}): {path} -- replay it with "
                   f"`acconform run {path}{options}`{more}")
    if fallback:
        out.append(f"warning: {fallback}")
    return out


def boundary_names() -> list[str]:
    """Every exact boundary the port counts (a boundary never hit is printed with 0)."""
    from ..port.transition.branches import BOUNDARIES

    return list(BOUNDARIES)
