"""Cost per tick scene by the number of movers (issue 41): ACE run from Python, in its parts, beside ACE's own
in-runtime time (and with --port the port's time).

    ACE_ASSEMBLY=/path/to/ACE.Server.dll python benchmarks/bench_movers.py [--rounds 15] [--warmup 5] [--ticks 60]
    ACE_ASSEMBLY=... python benchmarks/bench_movers.py --movers 2 8 --port
    python benchmarks/bench_movers.py --port-only

One scene per number of movers (1, 2, 4, 8): the player walking at 3 m/s on flat land, the others (monsters, one a
PK player) walking at it from four sides and the diagonals and meeting it, every velocity held every tick, 30 fps.
The scenes run in turn, round after round (interleaved, so a machine's load falls on all alike); the warm-up rounds
are not timed (steady state: the facade's caches, .NET 10's tiered JIT). Before each ACE run the scene's DAT records
are written (untimed), as a campaign's port run leaves them for both sides. Medians per scene, in ms:
  pack      oracle/pack.py's pack_scene
  call      the native entry point: the copy in, the facade's RunPinned, the copy out
  in-rt     the facade's whole case inside ACE's runtime (build the world and movers, the ticks, write them)
  unpack    unpack_outcome into the Outcome and its TickStates (one per mover and tick)
  ACE       pack + call + unpack, run() from Python
  ratio     ACE / in-rt, per run, then the median (issue 41 asks at most 2x)
  port      the built-in port's run_scene, exact mode (--port), and port/ACE

Measured side by side (2-core machine shared with other jobs, load average 9; stop 51): main 7e03fac ("before")
and pack 18 alternately, 3 runs each per runtime of --rounds 60 --warmup 20, medians of the runs (ratio: median, and
the runs' range):

  mono 6.8   movers  pack  call in-rt unpack  ratio (runs)       before: unpack  ratio (runs)
             1       0.10  0.66  0.60  0.10   1.36 (1.35-1.39)           0.16   1.44 (1.44-1.49)
             2       0.13  0.65  0.63  0.18   1.44 (1.39-1.49)           0.39   1.72 (1.71-1.73)
             4       0.17  1.69  1.66  0.35   1.37 (1.31-1.39)           0.68   1.65 (1.59-1.65)
             8       0.32 10.32 10.27  0.66   1.11 (1.08-1.17)           1.19   1.17 (1.16-1.19)
  .NET 10    1       0.08  0.30  0.28  0.07   1.69 (1.65-1.89)           0.14   1.91 (1.76-1.93)
             2       0.12  0.31  0.30  0.13   1.87 (1.85-2.33)           0.31   2.69 (2.61-2.91)
             4       0.16  0.59  0.58  0.26   1.69 (1.69-2.19)           0.55   2.58 (2.38-2.74)
             8       0.29  5.16  5.14  0.54   1.15 (1.14-1.69)           1.21   2.37 (2.22-2.61)

pack 18 (oracle/facade/Ticks.cs, oracle/pack.py `_ticks_and_end`): a tick's states come as fixed records read in
one iter_unpack, their vectors, planes, cell lists and CollisionTables as indices into the scene's tables of the
distinct ones, each TickState filled by straight-line code; unpacking is 1.7-2x faster alone (best of 40, one
process: 1 mover 0.089 -> 0.052 ms, 8 movers 0.72 -> 0.38 ms). The in-rt time is a tailed distribution on this
machine (8 movers: 0.7-1.0 ms at best, medians 1.5-13 ms from run to run, on either facade; runs with a fast
median, 1.3-1.8 ms, had 8 movers at 1.7-2.0). The 2-mover scene on .NET 10 stays the tightest: about 1.1 us of
Python per mover and tick (pack and unpack; run cold after the .NET call they take about 1.6x their time run twice
in a row) against 2-3 us of optimised .NET. docs/oracle.md has the discussion.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))


MOVERS = (1, 2, 4, 8)  # movers a scene (the player and the others), the table's rows

# the others: (x, y) start, velocity, id, weenie; each walks at the player (at (60, 60), walking +y) and meets it
SIDES = [((60.0, 64.0), (0.0, -2.0, 0.0), 0x80000001, "monster"), ((64.0, 60.0), (-2.0, 0.0, 0.0), 0x80000002, "monster"),
         ((56.0, 60.0), (2.0, 0.0, 0.0), 0x50000002, "player"), ((60.0, 56.0), (0.0, 2.0, 0.0), 0x80000003, "monster"),
         ((64.0, 64.0), (-1.5, -1.5, 0.0), 0x80000004, "monster"), ((56.0, 64.0), (1.5, -1.5, 0.0), 0x80000005, "monster"),
         ((64.0, 56.0), (-1.5, 1.5, 0.0), 0x80000006, "monster")]


def scenes(ticks: int, movers=MOVERS) -> dict:
    """movers -> the scene of that many movers (the player and movers - 1 others from SIDES)."""
    from acconform.scene import Frame, OtherInputs, OtherMover, Position, TickStep
    from oracle.mover_scenes import BODY, DT, GROUND, WALKING, _player, cell_at, land, scene

    out = {}
    for n in movers:
        sides = SIDES[:n - 1]
        others = tuple(OtherMover(i, w, BODY, Position(cell_at(*xy), Frame((*xy, GROUND))), 0.4, 0.4, transient_state=WALKING,
                                  player_killer_status=4 if w == "player" else 2) for xy, _, i, w in sides)
        steps = tuple(TickStep(DT, velocity=(0.0, 1.0, 0.0), others=tuple(OtherInputs(i, velocity=v) for _, v, i, _ in sides))
                      for _ in range(ticks))
        out[n] = scene(f"{n - 1} other movers", [land()], _player((60.0, 60.0, GROUND), "PK"), steps, others=others)
    return out


def ace_run_split(oracle, s) -> tuple[float, float, float, float]:
    """oracle.run_timed(s) in its three parts, timed apart: (pack ms, call ms, unpack ms, the facade's whole case ms).
    The call is the native entry point (the copy in, the facade's RunPinned, its copy out)."""
    from acconform import deep
    from acconform.oracle.pack import pack_scene, unpack_outcome

    t0 = time.perf_counter()
    data = deep.retrying(pack_scene, s)
    t1 = time.perf_counter()
    n = oracle._call(oracle._run_pinned, data)
    t2 = time.perf_counter()
    _outcome, _us, case_us, _counts = unpack_outcome(oracle._out, 0) if n <= oracle._out_cap else oracle._overflow(n)
    t3 = time.perf_counter()
    return (t1 - t0) * 1e3, (t2 - t1) * 1e3, (t3 - t2) * 1e3, case_us / 1e3


def main() -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--rounds", type=int, default=15)
    p.add_argument("--ticks", type=int, default=60)
    p.add_argument("--warmup", type=int, default=5, help="untimed rounds first (the JIT's tiers, the caches)")
    p.add_argument("--movers", type=int, nargs="+", default=list(MOVERS))
    p.add_argument("--port", action="store_true", help="also time the port's run_scene (exact mode) before each ACE run")
    p.add_argument("--port-only", action="store_true", help="time the port alone (no ACE)")
    args = p.parse_args()

    from acconform.dat import scene_records
    from acconform.port.run import run_scene

    with_port = args.port or args.port_only

    oracle = None
    runtime = "mono"
    if not args.port_only:
        from acconform.oracle.live import LiveOracle

        oracle = LiveOracle(say=None)
        runtime = oracle.location.runtime
    by_n = scenes(args.ticks, args.movers)
    cols = ("port", "pack", "call", "net", "unpack", "ace", "ratio")
    times = {n: {c: [] for c in cols} for n in by_n}
    for r in range(args.warmup + args.rounds):
        for n, s in by_n.items():
            if with_port:
                t = time.perf_counter()
                run_scene(s, runtime=runtime)
                port_ms = (time.perf_counter() - t) * 1e3
            if oracle is not None:
                scene_records(s)  # as a campaign's port run leaves them: written once for both sides
                pack, call, unpack, net = ace_run_split(oracle, s)
            if r < args.warmup:
                continue
            if with_port:
                times[n]["port"].append(port_ms)
            if oracle is not None:
                for c, v in zip(("pack", "call", "unpack", "net"), (pack, call, unpack, net)):
                    times[n][c].append(v)
                times[n]["ace"].append(pack + call + unpack)
                times[n]["ratio"].append((pack + call + unpack) / net)
    med = {n: {c: statistics.median(v) if v else float("nan") for c, v in t.items()} for n, t in times.items()}
    print(f"{args.ticks} ticks a scene, {args.warmup} + {args.rounds} rounds interleaved, medians (ms); runtime {runtime}")
    print(f"{'movers':>6} {'pack':>7} {'call':>7} {'in-rt':>7} {'unpack':>7} {'ACE':>7} {'ratio':>6} {'port':>8} {'port/ACE':>8}")
    for n, m in med.items():
        print(f"{n:>6} {m['pack']:>7.3f} {m['call']:>7.3f} {m['net']:>7.3f} {m['unpack']:>7.3f} {m['ace']:>7.3f} "
              f"{m['ratio']:>6.2f} {m['port']:>8.1f} {m['port'] / m['ace']:>8.1f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
