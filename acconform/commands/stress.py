"""acconform stress: numerical stability on scenes pushed to the edges where one ULP decides.

For N base scenes per kind (acconform.strategies.sample_scenes) derives stressed variants
(PERTURBATIONS: ULP nudges of the begin and end positions, moves ending exactly on a cell or
landblock border, a contact plane one ULP either side of FloorZ, very long and very short moves,
the same scene at the edges of the world, a near-degenerate polygon, tiny and huge spheres),
checks each with acconform.scene.validate_scene, and runs it through the port in exact and fast
mode and through the live oracle when ACE is configured (without one, the oracle half is
skipped with a note). Reports per perturbation kind:

- port/oracle differences: exact mode bit for bit (each written as a case file with
  acconform.runner's writer; these decide the exit code) and fast mode within its tolerance
  (a figure only: the double-precision port is expected to part from float32 at these edges);
- outcome sensitivity: of the pairs (stressed scene, the same scene one ULP away), how many
  have a different discrete outcome in the exact port;
- fast/exact discrete flips, non-finite values in any outcome field, and exceptions the port
  raised (split into those where ACE raised too, a verdict, and the rest);
- scenes over the time limit (--scene-timeout, per scene and side): each side runs in a child
  process (acconform.timed), so a scene that would run for minutes (a 187 m move of a 0.35 mm
  sphere) becomes a "SceneTimeout" verdict, counted apart and never compared.

A derived scene that does not validate is a bug in stress, not in the port: it is not run, each is
named, and the run fails.

Exit 1 when port (exact) and oracle differ on any stressed scene, or when a derived scene is
invalid; else 0; 2 for bad options.
"""

from __future__ import annotations

import sys

# name -> the behaviour it stresses (the derivations live in derive())
PERTURBATIONS: dict[str, str] = {
    "nudge_begin": "begin origin moved +-1..k float32 ULPs (all three coordinates)",
    "nudge_end": "end origin moved +-1..k float32 ULPs (all three coordinates)",
    "cell_border": "the move ends exactly on the nearest cell line (24 m grid) of its main axis",
    "landblock_border": "the move ends exactly on a landblock border (x or y a multiple of 192 m)",
    "floor_z": "the mover's contact plane has normal.z one ULP below / above FloorZ",
    "long_move": "the move is stretched to 60 m",
    "short_move": "the move is shrunk to a fraction (1/2, 1/100) of PhysicsGlobals.EPSILON",
    "world_edge": "the landblocks relabelled to the world's edge columns/rows 0x00 and 0xFE",
    "degenerate_polygon": "one BSP polygon squashed to a sliver (one vertex 1/1000 from its opposite edge)",
    "tiny_sphere": "the mover's spheres scaled by 1/1000",
    "huge_sphere": "the mover's spheres scaled by 20",
}


def add_arguments(p) -> None:
    p.add_argument("-n", "--cases", type=int, default=50, help="base scenes per kind (default 50)")
    p.add_argument("--seed", type=int, default=0, help="seed for the base scenes (default 0)")
    from ..protocol import KINDS

    p.add_argument("--kinds", default=None, help=f"comma-separated scene kinds (default: every world kind, "
                   f"{','.join(KINDS)}; a tick scene has no path to nudge)")
    p.add_argument("-k", "--ulps", type=int, default=2, help="nudges go from 1 to K ULPs each way (default 2)")
    p.add_argument("--only", default=None, help=f"comma-separated perturbation kinds (default all: {', '.join(PERTURBATIONS)})")
    p.add_argument("--failures", default="failures", metavar="DIR", help="where case files go (default ./failures)")
    p.add_argument("--no-oracle", action="store_true", help="port only, even when ACE is configured")
    p.add_argument("--ace", default=None, help="ACE assembly for the live oracle (else ACE_ASSEMBLY or the config file)")
    from . import add_runtime_argument

    add_runtime_argument(p, "the .NET runtime to load the live build on; the port computes its arithmetic")
    from ..timed import DEFAULT_LIMIT

    from . import positive_seconds

    p.add_argument("--scene-timeout", type=positive_seconds, default=DEFAULT_LIMIT, metavar="S",
                   help=f"seconds the port (each mode) or ACE may take for one scene before it is a timeout verdict "
                        f"(default {DEFAULT_LIMIT:g})")


# ---------------------------------------------------------------- float32 steps and positions


def step(x: float, n: int) -> float:
    """x moved n float32 ULPs (n < 0: down), through zero as the float32 line does."""
    import numpy as np

    f = np.float32(x)
    toward = np.float32(np.inf if n > 0 else -np.inf)
    for _ in range(abs(n)):
        f = np.nextafter(f, toward)
    return float(f)


def _relocated(pos, lx: float, ly: float, z: float):
    """`pos` moved to landblock-local (lx, ly, z) of its landblock (a global point when outside it)."""
    from ..numerics import to_f32
    from ..scene import Frame, Position
    from ..strategies.terrain import BLOCK, cell_of, split_global

    bx, by = pos.cell >> 24, (pos.cell >> 16) & 0xFF
    if 0.0 <= lx < BLOCK and 0.0 <= ly < BLOCK:
        return Position(cell_of(bx, by, lx, ly), Frame((to_f32(lx), to_f32(ly), to_f32(z)), pos.frame.orientation))
    nbx, nby, nlx, nly = split_global(bx * BLOCK + lx, by * BLOCK + ly)
    return Position(cell_of(nbx & 0xFF, nby & 0xFF, nlx, nly), Frame((nlx, nly, to_f32(z)), pos.frame.orientation))


def _global(pos) -> tuple[float, float, float]:
    from ..strategies.terrain import BLOCK

    x, y, z = pos.frame.origin
    return (pos.cell >> 24) * BLOCK + x, ((pos.cell >> 16) & 0xFF) * BLOCK + y, z


def _with_end(scene, end, tag):
    from dataclasses import replace

    return replace(scene, mover=replace(scene.mover, end=end), name=f"{scene.name or 'scene'} [stress {tag}]")


def _nudge(scene, which: str, n: int, tag: str):
    from dataclasses import replace

    pos = getattr(scene.mover, which)
    x, y, z = (step(c, n) for c in pos.frame.origin)
    moved = _relocated(pos, x, y, z)
    if which == "begin" and moved.cell >> 16 != pos.cell >> 16:
        moved = pos.__class__(pos.cell, moved.frame)  # begin stays in its (defined) landblock
    return replace(scene, mover=replace(scene.mover, **{which: moved}), name=f"{scene.name or 'scene'} [stress {tag}]")


def _end_at_global(scene, gx: float, gy: float, z: float, tag: str):
    b = scene.mover.begin
    bx, by = b.cell >> 24, (b.cell >> 16) & 0xFF
    from ..strategies.terrain import BLOCK

    return _with_end(scene, _relocated(b, gx - bx * BLOCK, gy - by * BLOCK, z), tag)


def _twin(scene):
    """The same scene with its end one ULP further along +x, +y, +z: the 1-ULP neighbour."""
    return _nudge(scene, "end", 1, "+1ulp")


# ---------------------------------------------------------------- derivations


def derive(kind: str, scene, k: int = 2) -> list[tuple[object, object | None]]:
    """Stressed variants of `scene` for one perturbation kind, each with its 1-ULP neighbour (or None).

    For the nudges the neighbour is the base scene itself (a 1-ULP nudge is the pair)."""
    import math
    from dataclasses import replace

    from ..numerics import f32_from_bits, f32_bits, to_f32
    from ..port.constants import EPSILON, FLOOR_Z
    from ..scene import ContactPlane, PlaneRec, SphereRec
    from ..strategies.terrain import BLOCK, CELL

    m = scene.mover
    bx0, by0, bz0 = _global(m.begin)
    ex0, ey0, ez0 = _global(m.end)
    dx, dy, dz = ex0 - bx0, ey0 - by0, ez0 - bz0
    out: list = []
    if kind in ("nudge_begin", "nudge_end"):
        which = kind.split("_")[1]
        for n in range(1, k + 1):
            for sign in (1, -1):
                v = _nudge(scene, which, sign * n, f"{which}{sign * n:+d}ulp")
                out.append((v, scene if n == 1 else None))
    elif kind in ("cell_border", "landblock_border"):
        grid = CELL if kind == "cell_border" else BLOCK
        axis = 0 if abs(dx) >= abs(dy) else 1
        e = (ex0, ey0)[axis]
        line = math.floor(e / grid + 0.5) * grid if kind == "cell_border" else (
            math.ceil(e / grid) * grid if (dx, dy)[axis] >= 0 else math.floor(e / grid) * grid)
        if abs(line - e) <= 24.0 and line != e:
            gx, gy = (line, ey0) if axis == 0 else (ex0, line)
            v = _end_at_global(scene, gx, gy, ez0, f"{kind} {'xy'[axis]}={line:g}")
            out.append((v, _twin(v)))
    elif kind == "floor_z":
        if m.placement is not None:  # the placement finds the contact plane, and its begin's cell id may be any
            return out
        h = math.hypot(dx, dy)
        ux, uy = (dx / h, dy / h) if h > 0 else (1.0, 0.0)
        for n in (-1, 1):
            nz = f32_from_bits(f32_bits(FLOOR_Z) + n)
            s = math.sqrt(max(0.0, 1.0 - nz * nz))
            normal = (to_f32(-ux * s), to_f32(-uy * s), nz)  # the plane rises along the move
            bo = m.begin.frame.origin
            d = to_f32(-(normal[0] * bo[0] + normal[1] * bo[1] + normal[2] * bo[2]))
            cp = ContactPlane(m.begin.cell, PlaneRec(normal, d))
            v = replace(scene, mover=replace(m, contact_plane=cp),
                        name=f"{scene.name or 'scene'} [stress floor_z {n:+d}ulp]")
            out.append(v)
        out = [(out[0], out[1])]  # the pair is the two sides of FloorZ
        out.append((out[0][1], None))
    elif kind in ("long_move", "short_move"):
        length = math.sqrt(dx * dx + dy * dy + dz * dz)
        u = (dx / length, dy / length, dz / length) if length > 0 else (1.0, 0.0, 0.0)
        for target in ((60.0,) if kind == "long_move" else (EPSILON * 0.5, EPSILON * 0.01)):
            v = _end_at_global(scene, bx0 + u[0] * target, by0 + u[1] * target, bz0 + u[2] * target,
                               f"{kind} {target:.3g} m")
            out.append((v, _twin(v)))
    elif kind == "world_edge":
        xs = [lb.id >> 24 for lb in scene.landblocks]
        ys = [(lb.id >> 16) & 0xFF for lb in scene.landblocks]
        for axis, edge in ((0, 0x00), (0, 0xFE), (1, 0x00), (1, 0xFE)):
            vals = xs if axis == 0 else ys
            shift = edge - (min(vals) if edge == 0 else max(vals))
            if shift == 0 and edge != 0:
                continue
            v = _shift_landblocks(scene, shift if axis == 0 else 0, shift if axis == 1 else 0,
                                  f"world_edge {'xy'[axis]}=0x{edge:02X}")
            out.append((v, _twin(v)))
    elif kind == "degenerate_polygon":
        v = _squash_polygon(scene)
        if v is not None:
            out.append((v, _twin(v)))
    elif kind in ("tiny_sphere", "huge_sphere"):
        f = 1e-3 if kind == "tiny_sphere" else 20.0
        spheres = tuple(SphereRec(tuple(to_f32(c * f) for c in sp.center), to_f32(sp.radius * f)) for sp in m.spheres)
        v = replace(scene, mover=replace(m, spheres=spheres), name=f"{scene.name or 'scene'} [stress {kind}]")
        out.append((v, _twin(v)))
    else:
        from ..errors import AcconformError

        raise AcconformError(f"unknown perturbation kind {kind!r} (known: {', '.join(PERTURBATIONS)})")
    return out


def _shift_landblocks(scene, sx: int, sy: int, tag: str):
    """The scene moved by (sx, sy) landblocks: every id that names a landblock or a cell in one (the
    landblocks, the buildings', the EnvCells', the statics' and the mover's cells) moves with it."""
    from dataclasses import replace

    def cell(c: int) -> int:
        return ((((c >> 24) + sx) & 0xFF) << 24) | (((((c >> 16) & 0xFF) + sy) & 0xFF) << 16) | (c & 0xFFFF)

    def pos(p):
        return replace(p, cell=cell(p.cell))

    m = scene.mover
    mover = replace(m, begin=pos(m.begin), end=pos(m.end),
                    contact_plane=None if m.contact_plane is None else replace(m.contact_plane, cell=cell(m.contact_plane.cell)))
    return replace(scene, landblocks=tuple(replace(lb, id=cell(lb.id)) for lb in scene.landblocks),
                   objects=tuple(replace(o, position=pos(o.position)) for o in scene.objects), mover=mover,
                   env_cells=tuple(replace(c, id=cell(c.id)) for c in scene.env_cells),
                   buildings=tuple(replace(b, landblock=cell(b.landblock)) for b in scene.buildings),
                   name=f"{scene.name or 'scene'} [stress {tag}]")


def _squash_polygon(scene):
    """The scene with the first BSP triangle-or-more polygon's last vertex pulled to 1/1000 of its
    distance from the midpoint of the first two (it stays in the polygon's plane), or None."""
    from dataclasses import replace

    from ..numerics import to_f32

    for i, o in enumerate(scene.objects):
        if o.shape is None or o.shape.kind != "bsp":
            continue
        polys = list(o.shape.polygons)
        for j, p in enumerate(polys):
            v0, v1, v2 = p.vertices[0], p.vertices[1], p.vertices[-1]
            mid = tuple((a + b) / 2 for a, b in zip(v0, v1))
            new = tuple(to_f32(c + (d - c) * 1e-3) for c, d in zip(mid, v2))
            verts = p.vertices[:-1] + (new,)
            polys[j] = replace(p, vertices=verts)
            shape = replace(o.shape, polygons=tuple(polys))
            objects = list(scene.objects)
            objects[i] = replace(o, shape=shape)
            return replace(scene, objects=tuple(objects), name=f"{scene.name or 'scene'} [stress degenerate_polygon]")
    return None


# ---------------------------------------------------------------- the run


class KindStats:
    def __init__(self):
        self.scenes = 0
        self.invalid: list[str] = []
        self.not_applicable = 0
        self.diff_exact = 0
        self.diff_fast = 0
        self.pairs = 0
        self.flips = 0
        self.fast_flips = 0
        self.nonfinite = 0
        self.raised_alone: dict[str, int] = {}
        self.raised_both = 0
        self.timed_out: dict[str, int] = {}  # side ("port exact", "port fast", "ACE") -> scenes over the limit

    def to_json(self):
        return {k: getattr(self, k) for k in ("scenes", "not_applicable", "diff_exact", "diff_fast", "pairs", "flips",
                                              "fast_flips", "nonfinite", "raised_alone", "raised_both",
                                              "timed_out")} | {
            "invalid": len(self.invalid)}


def stress(bases, kinds_of_perturbation, port_exact, port_fast, oracle=None, *, k: int = 2, failures_dir=None,
           seed=0, versions=None, on_case=None) -> dict[str, KindStats]:
    """Run every stressed variant of every base scene; returns stats per perturbation kind.
    `oracle` is a callable scene -> Outcome (or an object with run_many) or None."""
    from ..compare import compare
    from ..errors import InvalidScene
    from ..runner import guarded, make_case, versions_of, write_case
    from ..scene import validate_scene
    from ..timed import SCENE_TIMEOUT
    from .bench import discrete_part, nonfinite_fields

    if versions is None and oracle is not None:
        versions = versions_of(port_exact, oracle)
    stats = {p: KindStats() for p in kinds_of_perturbation}
    memo: dict[int, object] = {}

    def exact_of(s):
        if id(s) not in memo:
            memo[id(s)] = (s, guarded(port_exact, s))
        return memo[id(s)][1]

    for base in bases:
        memo.clear()
        exact_of(base)
        for pk in kinds_of_perturbation:
            st = stats[pk]
            pairs = derive(pk, base, k)
            if not pairs:
                st.not_applicable += 1
                continue
            runs: list = []
            seen: set[int] = set()
            for v, twin in pairs:
                for s in (v, twin):
                    if s is None or s is base or id(s) in seen:
                        continue
                    seen.add(id(s))
                    try:
                        validate_scene(s)
                    except InvalidScene as e:
                        st.invalid.append(f"{s.name}: {e}")
                        continue
                    runs.append(s)
            answers = _oracle_many(oracle, runs)
            valid = {id(s) for s in runs}
            for s, o in zip(runs, answers):
                st.scenes += 1
                e = exact_of(s)
                f = guarded(port_fast, s)
                late = [side for side, x in (("port exact", e), ("port fast", f), ("ACE", o))
                        if x is not None and (x.error or "").startswith(SCENE_TIMEOUT)]
                for side in late:
                    st.timed_out[side] = st.timed_out.get(side, 0) + 1
                if late:  # no outcome to judge on one side: a verdict of its own, not a difference
                    continue
                if discrete_part(e) != discrete_part(f):
                    st.fast_flips += 1
                if nonfinite_fields(e) or nonfinite_fields(f):
                    st.nonfinite += 1
                if e.error is not None:
                    if o is not None and o.error is not None:
                        st.raised_both += 1
                    else:
                        t = e.error.split(":", 1)[0]
                        st.raised_alone[t] = st.raised_alone.get(t, 0) + 1
                if o is None:
                    continue
                diffs = compare(e, o, "exact")
                if diffs:
                    st.diff_exact += 1
                    case = make_case(s, e, o, diffs, seed, "exact", versions)
                    path = write_case(case, failures_dir) if failures_dir is not None else None
                    if on_case is not None:
                        on_case(pk, case, path)
                if compare(f, o, "fast"):
                    st.diff_fast += 1
            for v, twin in pairs:
                if twin is None or id(v) not in valid or (twin is not base and id(twin) not in valid):
                    continue
                ev, et = exact_of(v), exact_of(twin)
                if any((x.error or "").startswith(SCENE_TIMEOUT) for x in (ev, et)):
                    continue
                st.pairs += 1
                st.flips += discrete_part(ev) != discrete_part(et)
    return stats


def _oracle_many(oracle, scenes):
    if oracle is None:
        return [None] * len(scenes)
    from ..outcome import Outcome

    if hasattr(oracle, "run_many"):
        try:
            return [o for o, _us in oracle.run_many(scenes)]
        except Exception as e:  # noqa: BLE001 - the bridge failing on one batch becomes a verdict per scene
            return [Outcome(error=f"{type(e).__name__}: {e}") for _ in scenes]
    from ..runner import guarded

    return [guarded(oracle, s) for s in scenes]


def render(stats: dict[str, KindStats], with_oracle: bool) -> list[str]:
    def pct(a, b):
        return f"{a}/{b} ({100 * a / b:.1f}%)" if b else "-"

    out = [(f"{'perturbation':20} {'scenes':>7} {'port/ACE exact':>15} {'fast/ACE':>9} {'1-ULP flips':>19} "
            f"{'fast/exact flips':>17} {'non-finite':>10} {'exceptions (alone / both)':>26}")]
    for name, s in stats.items():
        alone = sum(s.raised_alone.values())
        out.append(f"{name:20} {s.scenes:7d} {s.diff_exact if with_oracle else '-':>15} "
                   f"{s.diff_fast if with_oracle else '-':>9} {pct(s.flips, s.pairs):>19} {s.fast_flips:17d} "
                   f"{s.nonfinite:10d} {f'{alone} / {s.raised_both}':>26}")
        if s.not_applicable:
            out.append(f"  {name}: not applicable to {s.not_applicable} base scene{'s' if s.not_applicable != 1 else ''}")
        if s.raised_alone:
            what = "port raised where ACE did not" if with_oracle else "port raised (no ACE to compare with)"
            out.append(f"  {name}: {what}: "
                       + ", ".join(f"{t} x{n}" for t, n in sorted(s.raised_alone.items())))
        if s.timed_out:
            out.append(f"  {name}: over the time limit for a scene (not compared): "
                       + ", ".join(f"{side} x{n}" for side, n in sorted(s.timed_out.items())))
        for msg in s.invalid[:3]:
            out.append(f"  {name}: INVALID derived scene (a stress bug): {msg}")
    return out


def run(args) -> int:
    import warnings

    from ..errors import AcconformError
    from ..port.run import run_scene
    from ..strategies import check_kinds

    warnings.simplefilter("ignore", RuntimeWarning)
    from ..protocol import KINDS

    kinds = check_kinds(args.kinds if args.kinds is not None else KINDS)  # the default --help names
    ticked = next((k for k in kinds if k.partition(":")[0] == "ticks"), None)
    if ticked:
        raise AcconformError(f"--kinds {ticked}: stress nudges a transition's begin and end, and a tick scene has no end "
                             "(check --kinds ticks runs tick scenes)")
    if args.cases < 1 or args.ulps < 1:
        raise AcconformError(f"--cases and --ulps must be at least 1, got {args.cases} and {args.ulps}")
    perturbations = only_perturbations(args.only)
    from functools import partial

    from ..timed import TimedBackend

    oracle = None
    if args.no_oracle:
        print("oracle half skipped: --no-oracle")
    else:
        from ..oracle import PerProcessOracle, live_configured

        if live_configured(args.ace):
            # ACE loads in a child process, which a scene past the time limit stops
            oracle = TimedBackend(lambda: PerProcessOracle(args.ace, args.runtime).run, args.scene_timeout, "ACE")
        else:
            print("oracle half skipped: no ACE is configured (pass --ace or set ACE_ASSEMBLY); the recorded corpus "
                  "cannot answer stressed scenes. Port-only figures follow.")

    from . import runtime_or_default

    rt = runtime_or_default(args.runtime, oracle)  # as the ACE compared with
    exact = TimedBackend(partial(partial, run_scene, mode="exact", runtime=rt), args.scene_timeout, "port (exact)")
    fast = TimedBackend(partial(partial, run_scene, mode="fast", runtime=rt), args.scene_timeout, "port (fast)")
    try:
        return _run(args, kinds, perturbations, exact, fast, oracle)
    finally:
        for b in (exact, fast, oracle):
            if b is not None:
                b.close()


def only_perturbations(only: str | None) -> tuple[str, ...]:
    """--only's perturbation kinds (None: all of them); an empty, unknown or repeated name is exit 2."""
    from ..errors import AcconformError

    if only is None:
        return tuple(PERTURBATIONS)
    names = tuple(p.strip() for p in only.split(","))
    for p in names:
        if not p:
            raise AcconformError(f"--only {only!r}: an empty perturbation kind (known: {', '.join(PERTURBATIONS)}; "
                                 "leave --only out for all of them)")
        if p not in PERTURBATIONS:
            raise AcconformError(f"--only {only!r}: unknown perturbation kind {p!r} (known: {', '.join(PERTURBATIONS)})")
        if names.count(p) > 1:
            raise AcconformError(f"--only {only!r}: {p!r} is named twice")
    return names


def _run(args, kinds, perturbations, exact, fast, oracle) -> int:
    from ..runner import versions_of
    from ..strategies import sample_scenes

    found: list[str] = []

    def on_case(pk, case, path):
        found.append(f"  {pk}: {path} ({len(case.differences)} field{'s' if len(case.differences) != 1 else ''}: "
                     f"{case.differences[0]})")

    total_diff = 0
    invalid: list[str] = []
    print(f"acconform stress: {', '.join(kinds)}; {args.cases} base scenes per kind (seed {args.seed}); nudges 1..{args.ulps} "
          f"ULP; oracle " + (f"live ({oracle.versions.ace} on {oracle.versions.runtime})" if oracle else "none")
          + f"; at most {args.scene_timeout:g} s a scene", flush=True)
    versions = versions_of(exact, oracle) if oracle is not None else None
    for kind in kinds:
        bases = list(sample_scenes((kind,), args.cases, args.seed))
        stats = stress(bases, perturbations, exact, fast, oracle, k=args.ulps, failures_dir=args.failures,
                       seed=args.seed, versions=versions, on_case=on_case)
        print(f"\n{kind}:")
        print("\n".join(render(stats, oracle is not None)), flush=True)
        total_diff += sum(s.diff_exact for s in stats.values())
        invalid += [f"{kind} {pk}: {msg}" for pk, s in stats.items() for msg in s.invalid]
    if found:
        print(f"\n{len(found)} stressed scene{'s' if len(found) != 1 else ''} where port and ACE differ (case files):")
        print("\n".join(found[:50]) + (f"\n  ... and {len(found) - 50} more" if len(found) > 50 else ""))
    elif oracle is not None:
        print("\nport and ACE agree bit for bit on every stressed scene")
    print("1-ULP flips: pairs (stressed scene, the same one ULP away) whose discrete outcome differs in the exact port",
          file=sys.stderr)
    if invalid:  # a stress bug: those scenes were not run, so the figures above miss them
        print(f"\nerror: {len(invalid)} derived scene{'s' if len(invalid) != 1 else ''} did not validate (a bug in "
              f"stress, not in the port; not run); first: {invalid[0]}")
    return 1 if total_diff or invalid else 0
