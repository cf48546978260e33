"""Cost of a motion tick scene beside the same ticks driven by velocities, in the port, side by side.

    python benchmarks/bench_motion.py [-n 200] [--seed 0] [-r 3] [--runtime coreclr]

Issue 40 asks that a motion tick scene (a motion table and MoveToState keys: MotionInterp, the
MotionTable, the Sequence's frames and root motion) cost the port at most 1.5x the same ticks driven
by velocities. The scenes are the `motion` tick policy's (strategies/motion.py, FastDrawer from
--seed). Each is run once to learn its path; its velocity twin is the same scene without the motion
table and without the key inputs, every tick instead setting the world velocity that carries the
mover over the motion scene's displacement in that tick (so both run the same ticks, with transitions
over about the same path). Printed per side: the scenes, the ticks, the median over -r repetitions of the total time,
the time per tick, and the ratio motion / velocities.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from dataclasses import replace
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))


def motion_scenes(n: int, seed: int):
    from hypothesis import strategies as st

    from strategies.fast_draw import FastDrawer
    from strategies.ticks import draw_tick_scene

    drawer = FastDrawer(st.composite(lambda draw: draw_tick_scene(draw, policy="motion"))(), seed)
    return [drawer.draw()[0] for _ in range(n)]


def _global(cell: int, origin) -> tuple[float, float, float]:
    return ((cell >> 24) * 192.0 + origin[0], ((cell >> 16) & 0xFF) * 192.0 + origin[1], origin[2])


def velocity_twin(scene, outcome):
    """The same ticks with no motion table and no keys: each tick sets the world velocity that carries
    the mover from where the motion scene's mover began the tick to where it ended it (root motion and
    all) in the tick's time; a tick that did not move it sets the velocity it had."""
    steps = []
    times = scene.ticks.times()
    before = _global(scene.mover.begin.cell, scene.mover.begin.frame.origin)
    velocity = scene.mover.velocity
    t_prev = float(scene.ticks.start)
    for step, t, after in zip(scene.ticks.steps, times, outcome.ticks or ()):
        if after.error is not None:
            steps.append(replace(step, motion=None))
            break
        here = _global(after.cell, after.origin)
        dt = t - t_prev
        if after.updated and dt > 0:
            velocity = tuple((b - a) / dt for a, b in zip(before, here))
        steps.append(replace(step, motion=None, velocity=velocity))
        before, t_prev = here, t
    mover = replace(scene.mover, motion_table=None)
    return scene.replace(mover=mover, ticks=replace(scene.ticks, steps=tuple(steps)))


def timed(scenes, runtime: str, reps: int) -> float:
    from acconform.port.run import run_scene

    times = []
    for _ in range(reps):
        t0 = time.perf_counter()
        for s in scenes:
            run_scene(s, runtime=runtime)
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("-n", type=int, default=200, help="motion scenes (default 200)")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("-r", "--reps", type=int, default=3, help="repetitions; the median is printed")
    ap.add_argument("--runtime", choices=("coreclr", "mono"), default="coreclr",
                    help="whose arithmetic the port computes in (default coreclr)")
    a = ap.parse_args(argv)

    import warnings

    from acconform.port.run import run_scene

    warnings.simplefilter("ignore", RuntimeWarning)
    scenes = motion_scenes(a.n, a.seed)
    twins = []
    for s in scenes:
        twins.append(velocity_twin(s, run_scene(s, runtime=a.runtime)))
    ticks_m = sum(len(s.ticks.steps) for s in scenes)
    ticks_v = sum(len(s.ticks.steps) for s in twins)
    timed(scenes[:20], a.runtime, 1)  # warm both paths
    timed(twins[:20], a.runtime, 1)
    # interleaved, so a change of load on the machine falls on both
    tm, tv = [], []
    for _ in range(a.reps):
        tm.append(timed(scenes, a.runtime, 1))
        tv.append(timed(twins, a.runtime, 1))
    m, v = statistics.median(tm), statistics.median(tv)
    print(f"port ({a.runtime}), {a.n} motion scenes (seed {a.seed}), median of {a.reps}:")
    print(f"  motion      {ticks_m:6d} ticks  {m:7.2f} s  {1e3 * m / ticks_m:6.3f} ms/tick")
    print(f"  velocities  {ticks_v:6d} ticks  {v:7.2f} s  {1e3 * v / ticks_v:6.3f} ms/tick")
    print(f"  ratio motion / velocities: {m / v:.2f} (per tick {(m / ticks_m) / (v / ticks_v):.2f}; issue 40 asks <= 1.5)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
