"""Scenes of a target gone from the world and of a RequestPos into no cell (strategies/world_exit.py
draw_world_exit: a MoveToObject at a destroyed other, a RequestPos whose cell get_landcell cannot find), for
`acconform record` (issue 40's shard ticks-0073).

    python tests/runner/world_exit_scenes.py OUT_DIR [-n 300] [--seed 73] [--only ARM]

Writes one scene file per drawn scene (strategies.fast_draw, as a campaign draws), `s<seed>-<i>.json`, leaving out
the draws that found nothing to change (`world:<arm>:none:`). The arms are no campaign kind: a draw added to the
targets kind would move every seeded sample the tests pin.
"""

from __future__ import annotations

from scene_writer import scene_arguments, write_scenes


def main(argv=None) -> int:
    from acconform.strategies.ticks import _clock
    from acconform.strategies.world_exit import draw_world_exit

    ap = scene_arguments(__doc__, n=300, seed=73)
    ap.add_argument("--only", default=None, help="draw this arm alone")
    a = ap.parse_args(argv)
    return write_scenes(a.out, a.n, a.seed, lambda d: draw_world_exit(d, _clock, a.only),
                        keep=lambda scene: scene.name.split(":")[2] != "none")


if __name__ == "__main__":
    raise SystemExit(main())
