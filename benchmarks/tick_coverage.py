"""Hit rates of the tick strategies (issue 19): per 1,000 tick scenes, how often each policy, clock,
driver and threshold velocity is drawn, and how often the port's tick branches and exact tick
boundaries fire (port/transition/branches.py), plus the ticks that end in ACE's errors as the port
reproduces them.

    python benchmarks/tick_coverage.py [-n 1000] [--seed 0] [--runtime coreclr] [--kinds ticks:buildings]

Scenes come from `sample_scenes(("ticks",), n, seed)` (strategies/ticks.py; `--kinds ticks:<world>`:
tick scenes over that world only, e.g. through houses) and run through the
built-in port with a branch Trace, in process; nothing is timed. A boundary is "hit" when a compared
value is bit-equal to its threshold, "near" within 4 float32 ulps (the ulps are measured for the
float boundaries only; the clock's are compared in double and counted when equal). Scenes through a
house get the building branches too (port/transition/branches.py: the shell, the building's portal
cells, the EnvCells), and how many of them fell over their ticks: a drop of more than 5 cm below
where the mover began (off a porch, down a cellar's stairs or through its hatch).
"""

from __future__ import annotations

import argparse
import re
import sys
import time
from collections import Counter
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

TICK_BRANCH_PREFIXES = ("update_object", "update_object_internal", "update_object_internal_server", "update_physics",
                        "calc_friction", "handle_all_collisions")
TICK_BOUNDARIES = ("tick_rate", "huge_quantum", "max_quantum", "min_quantum", "max_velocity", "small_velocity",
                   "sledding_stop_speed", "sledding_glide_speed", "sledding_flat_z")
NEAR_ULPS = 4
# branches of the world a tick scene through a house goes through: its shell, its portal, its cells
BUILDING_BRANCH_PREFIXES = ("building", "env_cell", "find_cell_list")
FELL = 0.05  # metres below the start: the mover fell


def labels(scene) -> list[str]:
    """What the strategy drew for a scene, from its name and its timeline."""
    name = scene.name
    parts = name.split(":")
    out = [f"policy {parts[1].split('-')[0]}", f"driver {scene.ticks.driver}"]
    if parts[1].startswith("velocity-"):
        speed = parts[1][len("velocity-"):]
        for how in ("-down", "--x", "-x", "-y", "-345"):  # the direction drawn, last in the label
            if speed.endswith(how):
                speed = speed[: -len(how)]
                break
        out.append(f"velocity {speed}")
    m = re.search(r":(\d+fps|irregular|quanta-[^:]+)", name)
    if m:
        clock = m.group(1)
        out.append("clock " + ("quanta" if clock.startswith("quanta") else clock))
        if clock.startswith("quanta"):
            out.append("quantum step " + clock.split("-", 1)[1].rsplit("-", 1)[0])
    for sub in ("sled-sledding-flat-z-1ulp", "sled-sledding-flat-z+1ulp", "sled-sledding-flat-z", "sled-flat"):
        if sub in name:
            out.append(f"sled slope {sub[5:]}" + (" (terrain)" if "terrain:sled" in name else " (wedge)"
                                                    if "bsp:" in name else ""))
            break
    m = re.search(r"exact-slope-([a-z_]+(?:[+-]1ulp)?)", name)
    if m and parts[1] == "slide":
        out.append(f"slide slope {m.group(1)}")
    kind = parts[2] if len(parts) > 2 else "?"
    out.append(f"world {kind}")
    if kind == "building":
        out.append(f"house {parts[1]} {parts[3]}" + (" (no EdgeSlide)" if ":no-edge-slide" in name else ""))
    if scene.env_cells and any(o.position.cell & 0xFFFF >= 0x100 for o in scene.objects):
        out.append("world indoor with statics in EnvCells")
    return out


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("-n", type=int, default=1000)
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--runtime", choices=("mono", "coreclr"), default="coreclr")
    p.add_argument("--kinds", default="ticks", help="ticks (default), or ticks:<world> for tick scenes over one world")
    a = p.parse_args(argv)

    from acconform.port.run import run_scene
    from acconform.port.transition.branches import BRANCHES, MEASURED_IN_ULPS, Trace
    from acconform.strategies import check_kinds, sample_scenes

    t0 = time.perf_counter()
    scenes = list(sample_scenes(check_kinds(a.kinds), a.n, a.seed))
    gen = time.perf_counter() - t0
    drawn: Counter = Counter()
    present: Counter = Counter()
    errors: Counter = Counter()
    in_house: Counter = Counter()  # branches in the scenes through a house
    ticks = 0
    t1 = time.perf_counter()
    for s in scenes:
        drawn.update(labels(s))
        ticks += len(s.ticks.steps)
        trace = Trace()
        o = run_scene(s, trace=trace, runtime=a.runtime)
        present.update(trace.keys())
        present.update(f"near:{b}" for b, ulps in trace.closest.items() if ulps <= NEAR_ULPS)
        if s.buildings:
            in_house.update(trace.keys())
            zs = [t.origin[2] for t in o.ticks if t.cell]
            if zs and min(zs) < s.mover.begin.frame.origin[2] - FELL:
                drawn[f"house {s.name.split(':')[1]} {s.name.split(':')[3]}: fell"] += 1
        err = next((t.error for t in o.ticks if t.error), o.error)
        if err:
            errors[f"{s.ticks.driver}: {err.split(':', 1)[0]}"] += 1
    run = time.perf_counter() - t1
    per = 1000.0 / len(scenes)

    print(f"tick strategies ({a.kinds}): {len(scenes)} scenes (seed {a.seed}), {ticks / len(scenes):.1f} ticks each on average; "
          f"{a.runtime} arithmetic; drawn in {gen:.1f} s, run through the port in {run:.1f} s")
    print("\n| drawn | per 1,000 scenes |\n|---|---:|")
    for k in sorted(drawn):
        print(f"| {k} | {drawn[k] * per:.0f} |")
    print("\n| tick branch | scenes per 1,000 |\n|---|---:|")
    for b in sorted(BRANCHES):
        if b.split(":")[0] in TICK_BRANCH_PREFIXES:
            print(f"| {b} | {present.get(b, 0) * per:.1f} |")
    if any(s.buildings for s in scenes):
        houses = sum(1 for s in scenes if s.buildings)
        print(f"\n| building branch, in the {houses} scenes through a house | per 1,000 of them |\n|---|---:|")
        for b in sorted(BRANCHES):
            if b.split(":")[0] in BUILDING_BRANCH_PREFIXES:
                print(f"| {b} | {in_house.get(b, 0) * 1000.0 / houses:.1f} |")
    print("\n| tick boundary | hit per 1,000 | within 4 ulps per 1,000 |\n|---|---:|---:|")
    for b in TICK_BOUNDARIES:
        near = f"{present.get(f'near:{b}', 0) * per:.1f}" if b in MEASURED_IN_ULPS else "(compared in double)"
        print(f"| {b} | {present.get(f'boundary:{b}', 0) * per:.1f} | {near} |")
    others = sorted(k for k in present if k.startswith("boundary:") and k[9:] not in TICK_BOUNDARIES)
    if others:
        print("\n| transition boundary reached in tick scenes | hit per 1,000 |\n|---|---:|")
        for k in others:
            print(f"| {k[9:]} | {present[k] * per:.1f} |")
    print("\n| a tick ends in an error (ACE's, reproduced by the port) | per 1,000 |\n|---|---:|")
    for k in sorted(errors) or ["none"]:
        print(f"| {k} | {errors.get(k, 0) * per:.1f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
