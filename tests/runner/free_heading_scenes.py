"""Transition scenes whose mover's Setup allows a free heading (strategies/scenes.py draw_free_heading_scene: scene/8
mover.free_heading, ObjectInfoState.FreeRotate in FindTransitionalPosition) or, with --drawing, whose DAT records
carry what a client draws (draw_drawing_scene: scene/8 drawing) or, with --many-cylspheres, with a multipart static
of 11 or more cylspheres (draw_many_cylspheres_scene), for `acconform record` (shards bsp-0017, buildings-0017).

    python tests/runner/free_heading_scenes.py OUT_DIR [-n 400] [--seed 17] [--kinds bsp] [--drawing | --many-cylspheres]

Writes one scene file per drawn scene (strategies.fast_draw, as a campaign draws), `s<seed>-<i>.json`.
The draw is no campaign kind: a draw added to a kind would move every seeded sample the tests pin.
"""

from __future__ import annotations

from scene_writer import scene_arguments, write_scenes


def main(argv=None) -> int:
    from acconform.strategies.scenes import draw_drawing_scene, draw_free_heading_scene, draw_many_cylspheres_scene

    ap = scene_arguments(__doc__, n=400, seed=17)
    ap.add_argument("--kinds", default="bsp", help="comma-separated transition kinds (a shard holds one kind)")
    ap.add_argument("--drawing", action="store_true", help="draw_drawing_scene in place of draw_free_heading_scene")
    ap.add_argument("--many-cylspheres", action="store_true", help="draw_many_cylspheres_scene (bsp only)")
    a = ap.parse_args(argv)
    kinds = tuple(a.kinds.split(","))
    draw = (draw_many_cylspheres_scene if a.many_cylspheres
            else lambda d: (draw_drawing_scene if a.drawing else draw_free_heading_scene)(d, kinds))
    return write_scenes(a.out, a.n, a.seed, draw)


if __name__ == "__main__":
    raise SystemExit(main())
