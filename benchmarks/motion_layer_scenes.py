"""The tick scenes of shard ticks-0065: MotionInterp's rarer arms (issue 40, stop 50).

    python benchmarks/motion_layer_scenes.py N OUT.jsonl.gz

Draws a motion policy world (strategies/ticks.py's SITES["motion"]) and `draw_motion_layer_ticks` on it (a mover
whose Gravity is cleared among MoveToState keys, combat refusals of DoMotion, keys pressed and released by
DoMotion / StopMotion, a mover without a motion table, a table's modifier that is no substate), in either engine mode, from seed 65 (strategies.fast_draw); writes N scenes as JSON lines
for `acconform record` (docs/corpus-coverage.md, stop 50).
"""

from __future__ import annotations

import sys

from scene_lines import draw_all, on_a_motion_site


def layer_ticks(draw):
    from strategies.motion import draw_motion_layer_ticks

    return on_a_motion_site(draw, draw_motion_layer_ticks)


def main(argv) -> int:
    return draw_all(argv, "motion_layer_scenes.py", 65, layer_ticks)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
