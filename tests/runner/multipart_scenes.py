"""Scenes of other movers made from a Setup of several parts (strategies/movers.py draw_multipart_movers: a movers
scene whose first other in the world has 2-16 BSP parts at their frames, per-part scales, cylspheres or its parts'
BSPs to collide with), for `acconform record` (issue 41's shard ticks-0070).

    python tests/runner/multipart_scenes.py OUT_DIR [-n 400] [--seed 70] [--children]

`--children` draws `draw_no_part_child` instead: a carry whose first child has a Setup of no parts.

Writes one scene file per drawn scene (strategies.fast_draw, as a campaign draws), `s<seed>-<i>.json`, leaving out
the draws with no other to change (`multipart:none:`). No campaign kind draws them: a draw added to the movers kind
would move every seeded sample the tests pin.
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path


def main(argv=None) -> int:
    from hypothesis import strategies as st

    from acconform.strategies.determinism import pinned_constants
    from acconform.strategies.fast_draw import FastDrawer
    from acconform.strategies.movers import draw_multipart_movers, draw_no_part_child
    from acconform.strategies.ticks import _clock

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out", type=Path)
    ap.add_argument("-n", type=int, default=400)
    ap.add_argument("--seed", type=int, default=70)
    ap.add_argument("--children", action="store_true", help="a carry whose first child has a Setup of no parts")
    a = ap.parse_args(argv)
    draw_scene = draw_no_part_child if a.children else draw_multipart_movers
    a.out.mkdir(parents=True, exist_ok=True)
    drawer = FastDrawer(st.composite(lambda d: draw_scene(d, _clock))(), a.seed * 1000003)
    kept = 0
    with pinned_constants():
        for i in range(a.n):
            scene = drawer.draw()[0]
            if scene.name.split(":")[1] == "none":
                continue
            (a.out / f"{'c' if a.children else 's'}{a.seed}-{i:04d}.json").write_text(json.dumps(scene.to_json()))
            kept += 1
    print(f"{kept} of {a.n} scenes in {a.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
