"""The tick scenes of shard ticks-0076: a style defaulting to a modifier (issue 40, stop 51).

    python benchmarks/modifier_substate_scenes.py N OUT.jsonl.gz

Draws a motion policy world (strategies/ticks.py's SITES["motion"]) and `draw_modifier_substate_ticks` on it (a
player's table whose NonCombat style defaults to StopTurning or Jump, a modifier and no substate, then asked for
it), in either engine mode, from seed 76 (strategies.fast_draw); writes N scenes as JSON lines for
`acconform record` (docs/corpus-coverage.md, stop 51).
"""

from __future__ import annotations

import gzip
import json
import sys


def main(argv) -> int:
    if len(argv) != 2 or not argv[0].isdigit() or int(argv[0]) < 1:
        print("usage: modifier_substate_scenes.py N OUT.jsonl.gz (N a positive count)", file=sys.stderr)
        return 2
    from hypothesis import strategies as st

    from strategies import draws as dr
    from strategies.determinism import pinned_constants
    from strategies.fast_draw import FastDrawer
    from strategies.motion import draw_modifier_substate_ticks
    from strategies.scenes import draw_scene
    from strategies.ticks import SITES, _clock

    @st.composite
    def modsub_ticks(draw):
        kind, sub = draw(st.sampled_from(SITES["motion"]))
        base = draw_scene(draw, kind, sub)
        return draw_modifier_substate_ticks(draw, base, _clock).replace(engine_mode=draw(dr.ENGINE_MODES))

    want = int(argv[0])
    drawer = FastDrawer(modsub_ticks(), 76 * 1000003)
    with pinned_constants():
        kept = [drawer.draw()[0] for _ in range(want)]
    with gzip.open(argv[1], "wt", encoding="utf-8") as f:
        for s in kept:
            f.write(json.dumps(s.to_json(), separators=(",", ":")) + "\n")
    print(f"{len(kept)} scenes drawn into {argv[1]}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
