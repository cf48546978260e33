"""The tick scenes of shard ticks-0072: objects with a motion table and the server's ExecuteMotion (issue 40, stop 51).

    python benchmarks/motion_objects_scenes.py N OUT.jsonl.gz

Draws `draw_motion_objects` (strategies/motion.py: a player beside GenericObjects and creatures that have the scene's
motion table, the server executing motions on them (EmoteManager's Motion emote: IsMovingTo, ExecuteMotion), scene/8 others[].motion_table and execute_motion, feature
objects.motion_tables) in either engine mode from seed 72 (strategies.fast_draw); writes N scenes as JSON lines for
`acconform record` (docs/corpus-coverage.md, stop 51).
"""

from __future__ import annotations

import gzip
import json
import sys


def main(argv) -> int:
    if len(argv) != 2 or not argv[0].isdigit() or int(argv[0]) < 1:
        print("usage: motion_objects_scenes.py N OUT.jsonl.gz (N a positive count)", file=sys.stderr)
        return 2
    from hypothesis import strategies as st

    from strategies import draws as dr
    from strategies.determinism import pinned_constants
    from strategies.fast_draw import FastDrawer
    from strategies.motion import draw_motion_objects
    from strategies.ticks import _clock

    @st.composite
    def objects(draw):
        return draw_motion_objects(draw, _clock).replace(engine_mode=draw(dr.ENGINE_MODES))

    want = int(argv[0])
    drawer = FastDrawer(objects(), 72 * 1000003)
    with pinned_constants():
        kept = [drawer.draw()[0] for _ in range(want)]
    with gzip.open(argv[1], "wt", encoding="utf-8") as f:
        for s in kept:
            f.write(json.dumps(s.to_json(), separators=(",", ":")) + "\n")
    print(f"{len(kept)} scenes drawn into {argv[1]}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
