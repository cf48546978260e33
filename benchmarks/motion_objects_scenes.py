"""The tick scenes of shard ticks-0072: objects with a motion table and the server's ExecuteMotion (issue 40, stop 51).

    python benchmarks/motion_objects_scenes.py N OUT.jsonl.gz

Draws `draw_motion_objects` (strategies/motion.py: a player beside GenericObjects and creatures that have the scene's
motion table, the server executing motions on them (EmoteManager's Motion emote: IsMovingTo, ExecuteMotion), scene/8 others[].motion_table and execute_motion, feature
objects.motion_tables) in either engine mode from seed 72 (strategies.fast_draw); writes N scenes as JSON lines for
`acconform record` (docs/corpus-coverage.md, stop 51).
"""

from __future__ import annotations

import sys

from scene_lines import draw_all


def objects(draw):
    from strategies import draws as dr
    from strategies.motion import draw_motion_objects
    from strategies.ticks import _clock

    return draw_motion_objects(draw, _clock).replace(engine_mode=draw(dr.ENGINE_MODES))


def main(argv) -> int:
    return draw_all(argv, "motion_objects_scenes.py", 72, objects)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
