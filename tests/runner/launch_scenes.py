"""Missile scenes with a launch arm (strategies/missiles.py draw_launch_scene: the trajectory_alt_solver, a
target out of range, straight above or below, outrunning or creeping, a spell that times out, movers that report
collisions), for `acconform record` (issue 41's shard ticks-0051).

    python tests/runner/launch_scenes.py OUT_DIR [-n 600] [--seed 51] [--arms A,B] [--timeouts K] [--only ARM]

Writes one scene file per drawn scene (strategies.fast_draw, as a campaign draws), `s<seed>-<i>.json`, keeping
only the scenes of `--arms` when given and the first K of arm `timeout` (310 ticks each: a shard's replay time);
`--only ARM` draws that arm alone (`across`, which draw_launch_scene never draws, is drawn so); `--border` draws
draw_border_scene's launches across a cell line, a landblock's edge or the world's (issue 41's
shard ticks-0068); `--relocate` draws draw_relocation_scene's spells flying into the next landblock (shard ticks-0071).
The missiles kind draws the launch arms too, as a share of its scenes (strategies/scenes.py MISSILE_WAYS); this draws
them alone, or one arm alone.
"""

from __future__ import annotations

from scene_writer import scene_arguments, write_scenes


def main(argv=None) -> int:
    from acconform.strategies.missiles import draw_border_scene, draw_launch_scene, draw_missile_scene, draw_relocation_scene

    ap = scene_arguments(__doc__, n=600, seed=51)
    ap.add_argument("--arms", default=None, help="comma-separated arms to keep (default: every arm)")
    ap.add_argument("--timeouts", type=int, default=None, help="keep at most this many timeout scenes")
    ap.add_argument("--only", default=None, help="draw this arm alone (draw_missile_scene(draw, ARM))")
    ap.add_argument("--border", action="store_true", help="draw draw_border_scene's arms (with --only: that one)")
    ap.add_argument("--relocate", action="store_true", help="draw draw_relocation_scene's spells flying into the next landblock")
    a = ap.parse_args(argv)
    arms = None if a.arms is None else set(a.arms.split(","))
    draw = draw_launch_scene if a.only is None else (lambda d: draw_missile_scene(d, a.only))
    if a.border:
        draw = lambda d: draw_border_scene(d, a.only)  # noqa: E731
    if a.relocate:
        draw = draw_relocation_scene
    timeouts = 0

    def keep(scene) -> bool:
        nonlocal timeouts
        arm = scene.name.split(":")[1]
        if arms is not None and arm not in arms:
            return False
        if arm == "timeout":
            if a.timeouts is not None and timeouts >= a.timeouts:
                return False
            timeouts += 1
        return True

    return write_scenes(a.out, a.n, a.seed, draw, keep)


if __name__ == "__main__":
    raise SystemExit(main())
