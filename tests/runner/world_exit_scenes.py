"""Scenes of a target gone from the world and of a RequestPos into no cell (strategies/world_exit.py
draw_world_exit: a MoveToObject at a destroyed other, a RequestPos whose cell get_landcell cannot find), for
`acconform record` (issue 40's shard ticks-0073).

    python tests/runner/world_exit_scenes.py OUT_DIR [-n 300] [--seed 73] [--only ARM]

Writes one scene file per drawn scene (strategies.fast_draw, as a campaign draws), `s<seed>-<i>.json`, leaving out
the draws that found nothing to change (`world:<arm>:none:`). The arms are no campaign kind: a draw added to the
targets kind would move every seeded sample the tests pin.
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path


def main(argv=None) -> int:
    from hypothesis import strategies as st

    from acconform.strategies.determinism import pinned_constants
    from acconform.strategies.fast_draw import FastDrawer
    from acconform.strategies.world_exit import draw_world_exit
    from acconform.strategies.ticks import _clock

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out", type=Path)
    ap.add_argument("-n", type=int, default=300)
    ap.add_argument("--seed", type=int, default=73)
    ap.add_argument("--only", default=None, help="draw this arm alone")
    a = ap.parse_args(argv)
    a.out.mkdir(parents=True, exist_ok=True)
    drawer = FastDrawer(st.composite(lambda d: draw_world_exit(d, _clock, a.only))(), a.seed * 1000003)
    kept = 0
    with pinned_constants():
        for i in range(a.n):
            scene = drawer.draw()[0]
            if scene.name.split(":")[2] == "none":
                continue
            (a.out / f"s{a.seed}-{i:04d}.json").write_text(json.dumps(scene.to_json()))
            kept += 1
    print(f"{kept} of {a.n} scenes in {a.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
