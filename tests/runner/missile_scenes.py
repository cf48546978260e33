"""Missile movers on scenes of the recorded corpus (issue 24), for `acconform record`.

    python tests/runner/missile_scenes.py OUT_DIR [-n 300] [--seed 24]

Writes one scene file per record of the coreclr corpus's coverage kernel and of a stratified
sample of N records, each with its mover made a missile (PhysicsState.Missile: ACE's
PhysicsObj.get_object_info then sets ObjectInfoState.PathClipped, and ObjectInfo takes no
StepDown); outdoors, one scene in three makes its statics missiles too (ObjectInfo.MissileIgnore's
arms; an EnvCell's statics are DAT stabs, which carry no state). No strategy draws a missile: a
draw added to every scene would move every seeded sample the tests pin.
"""

from __future__ import annotations

import argparse
import json
import random
from dataclasses import replace
from pathlib import Path


def main(argv=None) -> int:
    from acconform.flags import PhysicsState
    from acconform.oracle import default_corpus
    from acconform.oracle.recorded import RecordedOracle
    from acconform.scene import Scene

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out", type=Path)
    ap.add_argument("-n", type=int, default=300)
    ap.add_argument("--seed", type=int, default=24)
    a = ap.parse_args(argv)
    a.out.mkdir(parents=True, exist_ok=True)
    corpus = default_corpus("coreclr")
    oracle = RecordedOracle(corpus)
    index = oracle.index()
    kernel = json.loads((corpus / "coverage-kernel.json").read_text())["keys"]
    rng = random.Random(a.seed)
    seen: set[str] = set()
    for e in [index[k] for k in kernel] + oracle.select(n=a.n, seed=a.seed):
        if e.key in seen:
            continue
        seen.add(e.key)
        s = Scene.from_json(e.doc()["scene"])
        if s.ticks is not None or s.mover.state & PhysicsState.Missile:
            continue
        objects, tag = s.objects, ":missile"
        if objects and not s.env_cells and rng.random() < 1 / 3:
            objects = tuple(replace(o, state=o.state | int(PhysicsState.Missile)) for o in objects)
            tag = ":missile:missile_statics"
        mover = replace(s.mover, state=s.mover.state | int(PhysicsState.Missile))
        (a.out / f"{e.key[:16]}.json").write_text(json.dumps(replace(s, mover=mover, objects=objects,
                                                                     name=s.name + tag).to_json()))
    print(f"{len(seen)} scenes in {a.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
