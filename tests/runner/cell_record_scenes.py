"""Buildings scenes whose cell DAT records carry housing barriers or low-word visible cells and building portals
(strategies/cell_records.py draw_cell_records_scene: scene/8 env_cells[].restriction_obj, landblocks[].restrictions,
visible cells and building portals below 0x0100, cell structures without a drawing BSP, cell-tree PORT nodes, keys
the physics misses), for `acconform record` (shard buildings-0018: -n 380 --seed 52).

    python tests/runner/cell_record_scenes.py OUT_DIR [-n 380] [--seed 52]

Writes one scene file per drawn scene (strategies.fast_draw, as a campaign draws), `s<seed>-<i>.json`.
The draw is no campaign kind: a draw added to a kind would move every seeded sample the tests pin.
"""

from __future__ import annotations

from scene_writer import scene_arguments, write_scenes


def main(argv=None) -> int:
    from acconform.strategies.cell_records import draw_cell_records_scene

    a = scene_arguments(__doc__, n=380, seed=52).parse_args(argv)
    return write_scenes(a.out, a.n, a.seed, draw_cell_records_scene)


if __name__ == "__main__":
    raise SystemExit(main())
