"""The server's MoveToObject, sticky MoveToObject and TurnToObject at a moving other mover (issue 40's managers;
strategies/motion.py draw_managed_chase), for `acconform record`.

    python tests/runner/managed_chase_scenes.py OUT_DIR [-n 600] [--seed 49]

Writes one scene file per distinct scene drawn. No campaign policy draws these: a policy added to the movers
policies would move every seeded sample the tests pin.
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path


def main(argv=None) -> int:
    from hypothesis import strategies as st

    from strategies import draws as dr
    from strategies.determinism import pinned_constants
    from strategies.fast_draw import FastDrawer
    from strategies.motion import draw_managed_chase
    from strategies.ticks import _clock

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out", type=Path)
    ap.add_argument("-n", type=int, default=600)
    ap.add_argument("--seed", type=int, default=49)
    a = ap.parse_args(argv)
    a.out.mkdir(parents=True, exist_ok=True)

    @st.composite
    def chase(draw):
        return draw_managed_chase(draw, _clock).replace(engine_mode=draw(dr.ENGINE_MODES))

    drawer = FastDrawer(chase(), a.seed * 1000003)
    seen = set()
    with pinned_constants():
        for _ in range(a.n):
            scene = drawer.draw()[0]
            text = json.dumps(scene.to_json())
            if text in seen:
                continue
            seen.add(text)
            (a.out / f"{len(seen):04d}.json").write_text(text)
    print(f"{len(seen)} scenes in {a.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
