"""The tick scenes of shard ticks-0063 past a multipart static whose Setup names a DefaultAnimation.

    python benchmarks/default_animation_scenes.py N OUT.jsonl.gz

Draws `draw_scene(draw, "bsp", "multipart")` then a walk (`_walk`) or a motion table's keys (`draw_motion_ticks`),
in either engine mode, from seed 63 (strategies.fast_draw), and keeps the first N scenes with a static whose Setup
has a `default_animation` (strategies/objects.py `_default_animation`); writes them as JSON lines for
`acconform record` (docs/corpus-coverage.md, stop 50).
"""

from __future__ import annotations

import sys

from scene_lines import arguments_ok, write_lines


def main(argv) -> int:
    if not arguments_ok(argv, "default_animation_scenes.py N OUT.jsonl.gz (N a positive count)"):
        return 2
    from hypothesis import strategies as st

    from strategies import draws as dr
    from strategies.determinism import pinned_constants
    from strategies.fast_draw import FastDrawer
    from strategies.motion import draw_motion_ticks
    from strategies.scenes import draw_scene
    from strategies.ticks import _clock, _walk

    @st.composite
    def anim_ticks(draw):
        base = draw_scene(draw, "bsp", "multipart")
        s = _walk(draw, base, "walk") if draw(st.booleans()) else draw_motion_ticks(draw, base, _clock)
        return s.replace(engine_mode=draw(dr.ENGINE_MODES))

    want = int(argv[0])
    drawer = FastDrawer(anim_ticks(), 63 * 1000003)
    kept, tried = [], 0
    with pinned_constants():
        while len(kept) < want and tried < 40 * want:
            tried += 1
            s = drawer.draw()[0]
            if any(o.setup is not None and o.setup.default_animation is not None for o in s.objects):
                kept.append(s)
    write_lines(argv[1], kept)
    print(f"{len(kept)} scenes of {tried} drawn into {argv[1]}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
