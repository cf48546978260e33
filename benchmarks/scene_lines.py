"""The part every tick-scene writer in benchmarks/ shares (motion_layer_scenes.py, modifier_substate_scenes.py,
motion_objects_scenes.py, default_animation_scenes.py, motion_query_scenes.py, target_aim_scenes.py): the check of
`N [SEED] OUT.jsonl.gz`, the scenes written as the JSON lines `acconform record` reads, and the loop that draws N
scenes as a campaign draws them (strategies.fast_draw, seeded `seed * 1000003`, under the pinned constants), and
the motion policy world the MotionInterp writers draw their ticks on.
"""

from __future__ import annotations

import gzip
import json
import sys


def arguments_ok(argv, usage: str, seeded: bool = False) -> bool:
    """Whether argv is `N OUT` (or `N SEED OUT` if `seeded`), N a positive count and SEED digits; if not, print
    `usage: <usage>` to stderr."""
    ok = (len(argv) == 2 + seeded and argv[0].isdigit() and int(argv[0]) >= 1
          and (not seeded or argv[1].isdigit()))
    if not ok:
        print(f"usage: {usage}", file=sys.stderr)
    return ok


def write_lines(path: str, scenes) -> None:
    """The scenes as gzip'd JSON lines, one scene's to_json() a line."""
    with gzip.open(path, "wt", encoding="utf-8") as f:
        for s in scenes:
            f.write(json.dumps(s.to_json(), separators=(",", ":")) + "\n")


def draw_all(argv, name: str, seed: int, draw) -> int:
    """The main() of a writer `name N OUT.jsonl.gz` that keeps every one of N scenes of `draw` (a function of
    Hypothesis' `draw`) drawn from `seed`; 2 on bad arguments."""
    if not arguments_ok(argv, f"{name} N OUT.jsonl.gz (N a positive count)"):
        return 2
    from hypothesis import strategies as st

    from strategies.determinism import pinned_constants
    from strategies.fast_draw import FastDrawer

    drawer = FastDrawer(st.composite(draw)(), seed * 1000003)
    with pinned_constants():
        kept = [drawer.draw()[0] for _ in range(int(argv[0]))]
    write_lines(argv[1], kept)
    print(f"{len(kept)} scenes drawn into {argv[1]}")
    return 0


def on_a_motion_site(draw, ticks):
    """A motion policy world (strategies/ticks.py's SITES["motion"]) with `ticks(draw, base, clock)` drawn on it, in
    either engine mode."""
    from hypothesis import strategies as st

    from strategies import draws as dr
    from strategies.scenes import draw_scene
    from strategies.ticks import SITES, _clock

    kind, sub = draw(st.sampled_from(SITES["motion"]))
    base = draw_scene(draw, kind, sub)
    return ticks(draw, base, _clock).replace(engine_mode=draw(dr.ENGINE_MODES))
