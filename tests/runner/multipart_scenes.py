"""Scenes of other movers made from a Setup of several parts (strategies/movers.py draw_multipart_movers: a movers
scene whose first other in the world has 2-16 BSP parts at their frames, per-part scales, cylspheres or its parts'
BSPs to collide with), for `acconform record` (issue 41's shard ticks-0070).

    python tests/runner/multipart_scenes.py OUT_DIR [-n 400] [--seed 70] [--children]

`--children` draws `draw_no_part_child` instead: a carry whose first child has a Setup of no parts.

Writes one scene file per drawn scene (strategies.fast_draw, as a campaign draws), `s<seed>-<i>.json`, leaving out
the draws with no other to change (`multipart:none:`). No campaign kind draws them: a draw added to the movers kind
would move every seeded sample the tests pin.
"""

from __future__ import annotations

from scene_writer import scene_arguments, write_scenes


def main(argv=None) -> int:
    from acconform.strategies.movers import draw_multipart_movers, draw_no_part_child
    from acconform.strategies.ticks import _clock

    ap = scene_arguments(__doc__, n=400, seed=70)
    ap.add_argument("--children", action="store_true", help="a carry whose first child has a Setup of no parts")
    a = ap.parse_args(argv)
    draw_scene = draw_no_part_child if a.children else draw_multipart_movers
    return write_scenes(a.out, a.n, a.seed, lambda d: draw_scene(d, _clock),
                        keep=lambda scene: scene.name.split(":")[1] != "none", prefix="c" if a.children else "s")


if __name__ == "__main__":
    raise SystemExit(main())
