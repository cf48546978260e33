"""Indoor scenes of the recorded corpus with a static moved so that its part's box touches a portal
plane (issue 24, the fifth round), for `acconform record`.

    python tests/runner/portal_box_scenes.py OUT_DIR [--seed 24] [--records 150]

PlaneExtensions.intersect_box answers Crossing at once when the box's min corner lies within
EPSILON of the plane: no record's static had its bounding box there, so that arm of port/vec.py's
intersect_box was never taken. For each static of an indoor (non-tick) record standing in an
EnvCell whose frame has no rotation, the port is run with that static alone and the first three
intersect_box calls are measured (the min corner's signed distance d from the portal's plane, and
the plane's normal n); each gives a scene with the static moved by -d n, which puts the corner on
the plane (translation moves every corner alike, and the cell's frame has no rotation). The records
are drawn from the coreclr corpus's indoor-000N shards with `--seed`, the first `--records` of the
shuffle, until more than 60 scenes are written.
"""

from __future__ import annotations

import argparse
import gzip
import json
import random
from dataclasses import replace
from pathlib import Path


VARIANT_SHARDS = ("indoor-0014",)  # the corpus shards this script's scenes were recorded into


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out", type=Path)
    ap.add_argument("--seed", type=int, default=24)
    ap.add_argument("--records", type=int, default=150)
    a = ap.parse_args(argv)
    a.out.mkdir(parents=True, exist_ok=True)

    from acconform.oracle import default_corpus
    from acconform.port.cell import env_cell
    from acconform.port.run import run_scene
    from acconform.scene import Scene

    calls: list[tuple[float, tuple[float, float, float]]] = []
    intersect_box = env_cell.intersect_box

    def measured(p, box):
        n = (float(p.normal.x), float(p.normal.y), float(p.normal.z))
        calls.append((n[0] * float(box.min.x) + n[1] * float(box.min.y) + n[2] * float(box.min.z) + float(p.d), n))
        return intersect_box(p, box)

    env_cell.intersect_box = measured  # this process only: a measurement, the scenes are what it writes
    records = []
    for shard in sorted(default_corpus("coreclr").glob("indoor-000*.jsonl.gz")):
        with gzip.open(shard, "rt") as f:
            for line in f:
                s = json.loads(line)["scene"]
                if s.get("objects"):
                    records.append(s)
    random.Random(a.seed).shuffle(records)
    written = 0
    for doc in records[:a.records]:
        s = Scene.from_json(doc)
        if s.ticks is not None:
            continue
        for i, o in enumerate(s.objects):
            if o.position.cell & 0xFFFF < 0x100:
                continue
            cell = next((c for c in s.env_cells if c.id == o.position.cell), None)
            if cell is None or tuple(cell.frame.orientation) != (1.0, 0.0, 0.0, 0.0):
                continue
            calls.clear()
            run_scene(replace(s, objects=(o,)), runtime="coreclr")
            for dist, n in calls[:3]:
                f = o.position.frame
                origin = tuple(f.origin[j] - dist * n[j] for j in range(3))
                moved = replace(o, position=replace(o.position, frame=replace(f, origin=origin)))
                v = replace(s, objects=s.objects[:i] + (moved,) + s.objects[i + 1:], name=f"{s.name}:static_box_on_portal")
                (a.out / f"box-{written:04d}.json").write_text(json.dumps(v.to_json()))
                written += 1
        if written > 60:
            break
    print(f"{written} scenes in {a.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
