"""The scenes of shard ticks-0066: targets scenes that take one of stop 50's later aims.

    python benchmarks/target_aim_scenes.py N SEED OUT.jsonl.gz

Draws N scenes of the campaign kind targets (`scenes_of("targets")`, strategies.fast_draw from SEED, as
`acconform record --kinds targets` draws them) and keeps those whose name says they aim at the mover itself
(`self_move_to_object`, `self_turn_to_object`, `self_stick`, `self_first`), turn at a destroyed target
(`turn_at_gone`), chase without a motion table (`tableless_*`) or switch to a second target (`switch`) (strategies/motion.py LATER_AIMS,
TABLELESS_CHASES); writes them as JSON lines for `acconform record` (docs/corpus-coverage.md, stop 50).
"""

from __future__ import annotations

import re
import sys

from scene_lines import arguments_ok, write_lines

AIMS = re.compile(r":(self_move_to_object|self_turn_to_object|self_stick|self_first|turn_at_gone|tableless_\w+|switch)@?")


def main(argv) -> int:
    if not arguments_ok(argv, "target_aim_scenes.py N SEED OUT.jsonl.gz (N a positive count, SEED a number)",
                        seeded=True):
        return 2
    from strategies.determinism import pinned_constants
    from strategies.fast_draw import FastDrawer
    from strategies.scenes import scenes_of

    with pinned_constants():
        drawer = FastDrawer(scenes_of("targets"), int(argv[1]))
        drawn = [drawer.draw()[0] for _ in range(int(argv[0]))]
    kept = [s for s in drawn if AIMS.search(s.name)]
    write_lines(argv[2], kept)
    print(f"{len(kept)} scenes of {len(drawn)} drawn into {argv[2]}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
