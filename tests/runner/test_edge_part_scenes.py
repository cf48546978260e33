"""tests/runner/edge_part_scenes.py: a multi-part static at the world's west edge with a part past it (shard
bsp-0018, LandCell.add_all_outside_cells' parts overload refusing a part AdjustToOutside cannot place)."""

import gzip
import json
from pathlib import Path

from edge_part_scenes import candidate, part_past_the_edge, west_most_part

from acconform.scene import Scene

SHARD = Path(__file__).resolve().parents[1] / "data" / "corpus" / "coreclr" / "bsp-0016.jsonl.gz"


def _first_candidate():
    with gzip.open(SHARD, "rt") as fh:
        for line in fh:
            if '"setup"' in line:
                s = Scene.from_json(json.loads(line)["scene"])
                i = candidate(s)
                if i is not None:
                    return s, i
    raise AssertionError("no multi-part static in bsp-0016")


def test_the_static_stands_inside_the_world_with_a_part_past_its_west_edge():
    s, i = _first_candidate()
    v = part_past_the_edge(s, i)
    o = v.objects[i]
    x = o.position.frame.origin[0]
    assert min(lb.id >> 24 for lb in v.landblocks) == 0
    assert o.position.cell >> 24 == 0 and 1 <= (o.position.cell & 0xFFFF) <= 8  # column 0 of the first landblock
    assert 0 < x < 24
    assert x + west_most_part(o) < 0  # that part's origin is west of x 0: off the world
