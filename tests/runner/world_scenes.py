"""Scenes of PhysicsObj's world side (strategies/movers.py draw_world_arm: a Hidden holder dropping its child, a
child holding a child and held anew, a Static other entering the world, the frame form at part -1 and before a
missile's launch), for `acconform record` (issue 41's shard ticks-0067).

    python tests/runner/world_scenes.py OUT_DIR [-n 600] [--seed 67] [--only ARM]

Writes one scene file per drawn scene (strategies.fast_draw, as a campaign draws), `s<seed>-<i>.json`, leaving out
the draws that found nothing to change (`world:<arm>:none:`). The arms are no campaign kind: a draw added to the
movers kind would move every seeded sample the tests pin.
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path


def main(argv=None) -> int:
    from hypothesis import strategies as st

    from acconform.strategies.determinism import pinned_constants
    from acconform.strategies.fast_draw import FastDrawer
    from acconform.strategies.movers import draw_world_arm
    from acconform.strategies.ticks import _clock

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out", type=Path)
    ap.add_argument("-n", type=int, default=600)
    ap.add_argument("--seed", type=int, default=67)
    ap.add_argument("--only", default=None, help="draw this arm alone")
    a = ap.parse_args(argv)
    a.out.mkdir(parents=True, exist_ok=True)
    drawer = FastDrawer(st.composite(lambda d: draw_world_arm(d, _clock, a.only))(), a.seed * 1000003)
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
