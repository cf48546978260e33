"""Scenes of PhysicsObj's world side (strategies/movers.py draw_world_arm: a Hidden holder dropping its child, a
child holding a child and held anew, a Static other entering the world, the frame form at part -1 and before a
missile's launch), for `acconform record` (issue 41's shard ticks-0067).

    python tests/runner/world_scenes.py OUT_DIR [-n 600] [--seed 67] [--only ARM]

Writes one scene file per drawn scene (strategies.fast_draw, as a campaign draws), `s<seed>-<i>.json`, leaving out
the draws that found nothing to change (`world:<arm>:none:`). The arms are no campaign kind: a draw added to the
movers kind would move every seeded sample the tests pin.
"""

from __future__ import annotations

from scene_writer import scene_arguments, write_scenes


def main(argv=None) -> int:
    from acconform.strategies.movers import draw_world_arm
    from acconform.strategies.ticks import _clock

    ap = scene_arguments(__doc__, n=600, seed=67)
    ap.add_argument("--only", default=None, help="draw this arm alone")
    a = ap.parse_args(argv)
    return write_scenes(a.out, a.n, a.seed, lambda d: draw_world_arm(d, _clock, a.only),
                        keep=lambda scene: scene.name.split(":")[2] != "none")


if __name__ == "__main__":
    raise SystemExit(main())
