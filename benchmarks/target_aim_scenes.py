"""The scenes of shard ticks-0066: targets scenes that take one of stop 50's later aims.

    python benchmarks/target_aim_scenes.py N SEED OUT.jsonl.gz

Draws N scenes of the campaign kind targets (`scenes_of("targets")`, strategies.fast_draw from SEED, as
`acconform record --kinds targets` draws them) and keeps those whose name says they aim at the mover itself
(`self_move_to_object`, `self_turn_to_object`, `self_stick`, `self_first`), turn at a destroyed target
(`turn_at_gone`), chase without a motion table (`tableless_*`) or switch to a second target (`switch`) (strategies/motion.py LATER_AIMS,
TABLELESS_CHASES); writes them as JSON lines for `acconform record` (docs/corpus-coverage.md, stop 50).
"""

from __future__ import annotations

import gzip
import json
import re
import sys

AIMS = re.compile(r":(self_move_to_object|self_turn_to_object|self_stick|self_first|turn_at_gone|tableless_\w+|switch)@?")


def main(argv) -> int:
    if len(argv) != 3 or not argv[0].isdigit() or int(argv[0]) < 1 or not argv[1].isdigit():
        print("usage: target_aim_scenes.py N SEED OUT.jsonl.gz (N a positive count, SEED a number)", file=sys.stderr)
        return 2
    from strategies.determinism import pinned_constants
    from strategies.fast_draw import FastDrawer
    from strategies.scenes import scenes_of

    with pinned_constants():
        drawer = FastDrawer(scenes_of("targets"), int(argv[1]))
        drawn = [drawer.draw()[0] for _ in range(int(argv[0]))]
    kept = [s for s in drawn if AIMS.search(s.name)]
    with gzip.open(argv[2], "wt", encoding="utf-8") as f:
        for s in kept:
            f.write(json.dumps(s.to_json(), separators=(",", ":")) + "\n")
    print(f"{len(kept)} scenes of {len(drawn)} drawn into {argv[2]}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
