"""The tick scenes of shard ticks-0065: MotionInterp's rarer arms (issue 40, stop 50).

    python benchmarks/motion_layer_scenes.py N OUT.jsonl.gz

Draws a motion policy world (strategies/ticks.py's SITES["motion"]) and `draw_motion_layer_ticks` on it (a mover
whose Gravity is cleared among MoveToState keys, combat refusals of DoMotion, keys pressed and released by
DoMotion / StopMotion, a mover without a motion table, a table's modifier that is no substate), in either engine mode, from seed 65 (strategies.fast_draw); writes N scenes as JSON lines
for `acconform record` (docs/corpus-coverage.md, stop 50).
"""

from __future__ import annotations

import gzip
import json
import sys


def main(argv) -> int:
    if len(argv) != 2 or not argv[0].isdigit() or int(argv[0]) < 1:
        print("usage: motion_layer_scenes.py N OUT.jsonl.gz (N a positive count)", file=sys.stderr)
        return 2
    from hypothesis import strategies as st

    from strategies import draws as dr
    from strategies.determinism import pinned_constants
    from strategies.fast_draw import FastDrawer
    from strategies.motion import draw_motion_layer_ticks
    from strategies.scenes import draw_scene
    from strategies.ticks import SITES, _clock

    @st.composite
    def layer_ticks(draw):
        kind, sub = draw(st.sampled_from(SITES["motion"]))
        base = draw_scene(draw, kind, sub)
        return draw_motion_layer_ticks(draw, base, _clock).replace(engine_mode=draw(dr.ENGINE_MODES))

    want = int(argv[0])
    drawer = FastDrawer(layer_ticks(), 65 * 1000003)
    with pinned_constants():
        kept = [drawer.draw()[0] for _ in range(want)]
    with gzip.open(argv[1], "wt", encoding="utf-8") as f:
        for s in kept:
            f.write(json.dumps(s.to_json(), separators=(",", ":")) + "\n")
    print(f"{len(kept)} scenes drawn into {argv[1]}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
