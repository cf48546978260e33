"""Buildings scenes whose cell DAT records carry housing barriers or low-word visible cells and building portals
(strategies/cell_records.py draw_cell_records_scene: scene/8 env_cells[].restriction_obj, landblocks[].restrictions,
visible cells and building portals below 0x0100, cell structures without a drawing BSP, cell-tree PORT nodes, keys
the physics misses), for `acconform record` (shard buildings-0018: -n 380 --seed 52).

    python tests/runner/cell_record_scenes.py OUT_DIR [-n 380] [--seed 52]

Writes one scene file per drawn scene (strategies.fast_draw, as a campaign draws), `s<seed>-<i>.json`.
The draw is no campaign kind: a draw added to a kind would move every seeded sample the tests pin.
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path


def main(argv=None) -> int:
    from hypothesis import strategies as st

    from acconform.strategies.cell_records import draw_cell_records_scene
    from acconform.strategies.determinism import pinned_constants
    from acconform.strategies.fast_draw import FastDrawer

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out", type=Path)
    ap.add_argument("-n", type=int, default=380)
    ap.add_argument("--seed", type=int, default=52)
    a = ap.parse_args(argv)
    a.out.mkdir(parents=True, exist_ok=True)
    drawer = FastDrawer(st.composite(draw_cell_records_scene)(), a.seed * 1000003)
    with pinned_constants():
        for i in range(a.n):
            scene = drawer.draw()[0]
            (a.out / f"s{a.seed}-{i:04d}.json").write_text(json.dumps(scene.to_json()))
    print(f"{a.n} scenes in {a.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
