"""The scenes of shard ticks-0069: the motion scenes with the server's motion-table queries (scene/8 motion_queries).

    python benchmarks/motion_query_scenes.py N SEED OUT.jsonl.gz

Keeps the scenes with `motion_queries` among `sample_scenes(("motion",), N, SEED)` (strategies/motion.py
`draw_motion_queries` gives one motion scene in three its queries) and writes them as JSON lines for `acconform record`
(docs/corpus-coverage.md, stop 50: N 1500, SEED 69, 479 scenes).
"""

from __future__ import annotations

import sys

from scene_lines import arguments_ok, write_lines


def main(argv) -> int:
    if not arguments_ok(argv, "motion_query_scenes.py N SEED OUT.jsonl.gz (N a positive count, SEED a non-negative "
                        "integer)", seeded=True):
        return 2
    from strategies import sample_scenes

    kept = [s for s in sample_scenes(("motion",), int(argv[0]), int(argv[1])) if s.motion_queries]
    write_lines(argv[2], kept)
    print(f"{len(kept)} scenes of {argv[0]} drawn into {argv[2]}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
