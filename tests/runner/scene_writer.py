"""The part every drawn-scene writer for `acconform record` shares (tests/runner/world_scenes.py,
multipart_scenes.py, launch_scenes.py, world_exit_scenes.py, cell_record_scenes.py, free_heading_scenes.py; the
arguments alone: lead_scenes.py, edge_part_scenes.py): the OUT_DIR / -n / --seed arguments, and the loop that draws
`-n` scenes as a campaign draws them (strategies.fast_draw, seeded `seed * 1000003`, under the pinned
constants) and writes the kept ones as `<prefix><seed>-<i>.json`, `i` the draw's index (so a file's
name says which draw made it, whatever was left out before it).
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path


def scene_arguments(doc: str, n: int, seed: int, n_help: str | None = None) -> argparse.ArgumentParser:
    """A parser for OUT_DIR [-n N] [--seed S], described by the first line of the writer's docstring; a bad
    argument is one line and exit 2, as acconform's own commands answer it."""
    from acconform.cli import _Parser

    ap = _Parser(description=doc.splitlines()[0])
    ap.add_argument("out", type=Path)
    ap.add_argument("-n", type=int, default=n, help=n_help)
    ap.add_argument("--seed", type=int, default=seed)
    return ap


def write_scenes(out: Path, n: int, seed: int, draw, keep=None, prefix: str = "s") -> int:
    """Draw `n` scenes of `draw` (a function of Hypothesis' `draw`), write those `keep` accepts (asked once per
    scene, in draw order; every one without `keep`), print how many, and return 0."""
    from hypothesis import strategies as st

    from acconform.strategies.determinism import pinned_constants
    from acconform.strategies.fast_draw import FastDrawer

    out.mkdir(parents=True, exist_ok=True)
    drawer = FastDrawer(st.composite(draw)(), seed * 1000003)
    kept = 0
    with pinned_constants():
        for i in range(n):
            scene = drawer.draw()[0]
            if keep is not None and not keep(scene):
                continue
            (out / f"{prefix}{seed}-{i:04d}.json").write_text(json.dumps(scene.to_json()))
            kept += 1
    print(f"{kept} of {n} scenes in {out}" if keep is not None else f"{n} scenes in {out}")
    return 0
