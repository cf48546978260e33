"""The tick scenes of shard ticks-0076: a style defaulting to a modifier (issue 40, stop 51).

    python benchmarks/modifier_substate_scenes.py N OUT.jsonl.gz

Draws a motion policy world (strategies/ticks.py's SITES["motion"]) and `draw_modifier_substate_ticks` on it (a
player's table whose NonCombat style defaults to StopTurning or Jump, a modifier and no substate, then asked for
it), in either engine mode, from seed 76 (strategies.fast_draw); writes N scenes as JSON lines for
`acconform record` (docs/corpus-coverage.md, stop 51).
"""

from __future__ import annotations

import sys

from scene_lines import draw_all, on_a_motion_site


def modsub_ticks(draw):
    from strategies.motion import draw_modifier_substate_ticks

    return on_a_motion_site(draw, draw_modifier_substate_ticks)


def main(argv) -> int:
    return draw_all(argv, "modifier_substate_scenes.py", 76, modsub_ticks)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
