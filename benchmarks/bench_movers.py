"""Cost per tick scene by the number of movers (issue 41), side by side: the port, and ACE from Python
beside ACE's own in-runtime time.

    ACE_ASSEMBLY=/path/to/ACE.Server.dll python benchmarks/bench_movers.py [--rounds 5] [--ticks 60]
    python benchmarks/bench_movers.py --port-only

One scene per count of other movers (0 to 3): the player walking at 3 m/s on flat land, the others (monsters,
one a PK player) walking at it from the four sides and meeting it, every velocity held every tick, 30 fps.
The scenes are run in turn, round after round (interleaved, so a machine's load falls on all alike), and the
medians printed:
  port ms     the built-in port's run_scene (exact mode)
  ACE ms      the live oracle's run() from Python (pack, the facade's whole case, unpack)
  .NET ms     the facade's whole case inside ACE's runtime (build the world, the movers, the ticks, read back)
  ACE/.NET    ACE's share over its in-runtime time (issue 41 asks at most 2x)
  port/ACE    the port's time over ACE's
and per column the ratio to the one-mover scene.

Measured (2-core machine shared with other jobs, load average 4-6; stop 49: oracle/pack.py's faster unpack and
step packing), one run of --rounds 5 on each runtime, ACE/.NET for 1, 2, 3, 4 movers:
  mono 6.8   1.61  1.83  1.72  1.67   (.NET ms 0.40  0.66  0.95  1.26)
  .NET 10    1.67  1.88  1.71  1.62   (.NET ms 0.52  0.70  1.02  1.43)
  before     1.96  2.35  2.46  2.64   (the last figures before stop 49)
At that load other runs had rows several times over 2x where the scheduler preempted the timed call (a median of
5 samples), and once 2.02 (one mover, .NET 10). With more rounds .NET 10's tiered JIT recompiles the facade and ACE
(.NET ms 0.26, 0.34, 0.54, 0.63 at --rounds 25) and the same Python cost is then 2.5-4x: about 1.5-2.5 us of Python
per TickState (making its objects, with caches cold after the port's run) against 1-2.5 us of optimised .NET.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from dataclasses import replace
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))


def scenes(ticks: int) -> dict:
    from acconform.scene import Frame, OtherInputs, OtherMover, Position, TickStep
    from oracle.mover_scenes import BODY, DT, GROUND, WALKING, _player, cell_at, land, scene

    sides = [((60.0, 64.0), (0.0, -2.0, 0.0), 0x80000001, "monster"), ((64.0, 60.0), (-2.0, 0.0, 0.0), 0x80000002, "monster"),
             ((56.0, 60.0), (2.0, 0.0, 0.0), 0x50000002, "player"), ((60.0, 56.0), (0.0, 2.0, 0.0), 0x80000003, "monster")]
    out = {}
    for k in range(0, 4):
        others = tuple(OtherMover(i, w, BODY, Position(cell_at(*xy), Frame((*xy, GROUND))), 0.4, 0.4, transient_state=WALKING,
                                  player_killer_status=4 if w == "player" else 2) for xy, _, i, w in sides[:k])
        steps = tuple(TickStep(DT, velocity=(0.0, 1.0, 0.0), others=tuple(OtherInputs(i, velocity=v) for _, v, i, _ in sides[:k]))
                      for _ in range(ticks))
        out[k] = scene(f"{k} other movers", [land()], _player((60.0, 60.0, GROUND), "PK"), steps, others=others)
    return out


def main() -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--rounds", type=int, default=5)
    p.add_argument("--ticks", type=int, default=60)
    p.add_argument("--port-only", action="store_true", help="time the port alone (no ACE)")
    args = p.parse_args()

    from acconform.port.run import run_scene

    oracle = None
    runtime = "mono"
    if not args.port_only:
        from acconform.oracle.live import LiveOracle

        oracle = LiveOracle()
        runtime = oracle.location.runtime
    by_k = scenes(args.ticks)
    times = {k: {"port": [], "ace": [], "net": []} for k in by_k}
    for k, s in by_k.items():  # warm-up: the facade's caches, the port's imports
        run_scene(s, runtime=runtime)
        if oracle is not None:
            oracle.run(s)
    for _ in range(args.rounds):
        for k, s in by_k.items():
            t = time.perf_counter()
            run_scene(s, runtime=runtime)
            times[k]["port"].append((time.perf_counter() - t) * 1e3)
            if oracle is not None:
                t = time.perf_counter()
                oracle.run(s)
                times[k]["ace"].append((time.perf_counter() - t) * 1e3)
                times[k]["net"].append(oracle.last_case_micros / 1e3)
    med = {k: {c: statistics.median(v) if v else float("nan") for c, v in t.items()} for k, t in times.items()}
    print(f"{args.ticks} ticks a scene, {args.rounds} rounds interleaved, medians; runtime {runtime}")
    print(f"{'movers':>7} {'port ms':>9} {'ACE ms':>9} {'.NET ms':>9} {'ACE/.NET':>9} {'port/ACE':>9}   vs one mover: port, ACE")
    for k, m in med.items():
        base = med[0]
        print(f"{k + 1:>7} {m['port']:>9.1f} {m['ace']:>9.2f} {m['net']:>9.2f} {m['ace'] / m['net']:>9.2f} "
              f"{m['port'] / m['ace']:>9.1f}   {m['port'] / base['port']:.2f}x, {m['ace'] / base['ace']:.2f}x")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
