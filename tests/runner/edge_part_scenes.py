"""Scenes of a multi-part static standing at the world's west edge with a part past it (issue 41), for
`acconform record` (shard bsp-0018).

    python tests/runner/edge_part_scenes.py OUT_DIR [-n 120] [--seed 77]

The recorded corpus holds outdoor scenes with a static made from a Setup of several parts (setup.multipart,
strategies/objects.py `multipart`), but none at the world's edge; cell_variant_scenes.py's statics on the edge have
one part, at their own position. So no record took LandCell.add_all_outside_cells' parts overload for a part whose
position AdjustToOutside refuses (a part of a static placed in the world whose frame puts it west of x 0). Each
scene here is such a record (of the coreclr corpus, drawn with `--seed` from those that apply) moved west by whole
landblocks until its west-most landblock is the world's first column (x 0x00, as cell_variant_scenes.py's
`to_the_world_edge`), with its first multi-part static in that landblock put at half the west-most part's offset
from the edge: its origin inside the world (column 0 of cells, its row kept), that part past it. The static's
calc_cross_cells_static then walks the parts (find_bbox_cell_list: HasPhysicsBSP, or no cylspheres).
"""

from __future__ import annotations

import gzip
import json
import math
import random
from dataclasses import replace
from pathlib import Path

from scene_writer import scene_arguments

CORPUS = Path(__file__).resolve().parents[1] / "data" / "corpus" / "coreclr"


def _rotate(q, v):
    """v turned by the unit quaternion q = (w, x, y, z), in double (only to choose a position)."""
    w, x, y, z = q
    vx, vy, vz = v
    # t = 2 (q.xyz x v); v' = v + w t + q.xyz x t
    tx, ty, tz = 2 * (y * vz - z * vy), 2 * (z * vx - x * vz), 2 * (x * vy - y * vx)
    return (vx + w * tx + (y * tz - z * ty), vy + w * ty + (z * tx - x * tz), vz + w * tz + (x * ty - y * tx))


def west_most_part(o) -> float:
    """The least x offset of a part's origin from the static's (its orientation and scale applied)."""
    return min(_rotate(o.position.frame.orientation, tuple(c * o.scale for c in p.frame.origin))[0]
               for p in o.setup.parts)


def to_the_world_edge(s):
    """The scene moved west by whole landblocks until its west-most one is the world's first column (x 0x00): ids
    change, coordinates within a landblock do not."""
    xs = [lb.id >> 24 for lb in s.landblocks]
    dx = -min(xs) << 24
    listed = {lb.id >> 16 for lb in s.landblocks}

    def cell(c):
        return c + dx if c >> 16 in listed else c
    m = s.mover
    mover = replace(m, begin=replace(m.begin, cell=cell(m.begin.cell)),
                    end=None if m.end is None else replace(m.end, cell=cell(m.end.cell)),
                    contact_plane=None if m.contact_plane is None else replace(m.contact_plane,
                                                                              cell=cell(m.contact_plane.cell)))
    return replace(s, landblocks=tuple(replace(lb, id=cell(lb.id)) for lb in s.landblocks), mover=mover,
                   objects=tuple(replace(o, position=replace(o.position, cell=cell(o.position.cell)))
                                 for o in s.objects))


def candidate(s):
    """The index of the scene's first multi-part static in its west-most landblock whose parts reach at least
    0.2 m west of its origin, or None (outdoor scenes only: no ticks, cells or buildings)."""
    if s.ticks is not None or s.buildings or s.env_cells or not s.landblocks:
        return None
    west = min(lb.id >> 24 for lb in s.landblocks)
    for i, o in enumerate(s.objects):
        if (o.setup is not None and len(o.setup.parts) >= 2 and o.position.cell >> 24 == west
                and (o.position.cell & 0xFFFF) < 0x100 and west_most_part(o) < -0.2):
            return i
    return None


def part_past_the_edge(s, i):
    """The scene at the world's edge, static `i` at half its west-most part's offset from it."""
    s = to_the_world_edge(s)
    o = s.objects[i]
    x = -west_most_part(o) / 2
    y = o.position.frame.origin[1]
    low = int(y // 24) + 1  # column 0 of cells, the static's row
    pos = replace(o.position, cell=(o.position.cell & 0xFFFF0000) | low,
                  frame=replace(o.position.frame, origin=(float(x),) + tuple(o.position.frame.origin[1:])))
    objects = list(s.objects)
    objects[i] = replace(o, position=pos)
    return replace(s, objects=tuple(objects))


def main(argv=None) -> int:
    from acconform.scene import Scene

    a = scene_arguments(__doc__, n=120, seed=77).parse_args(argv)
    a.out.mkdir(parents=True, exist_ok=True)
    pool = []
    for f in sorted(CORPUS.glob("bsp-*.jsonl.gz")):
        with gzip.open(f, "rt") as fh:
            for k, line in enumerate(fh):
                if '"setup"' not in line:
                    continue
                s = Scene.from_json(json.loads(line)["scene"])
                i = candidate(s)
                if i is not None:
                    pool.append((f"{f.name.split('.')[0]}-{k:05d}", s, i))
    rng = random.Random(a.seed)
    chosen = rng.sample(pool, min(a.n, len(pool)))
    for key, s, i in chosen:
        v = part_past_the_edge(s, i)
        (a.out / f"{key}-part_past_the_edge.json").write_text(
            json.dumps(replace(v, name=f"{s.name}:part_past_the_edge").to_json()))
    print(f"{len(chosen)} of {len(pool)} scenes in {a.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
