"""Transition and placement scenes of the recorded corpus with one thing varied (issue 24), for
`acconform record`.

    python tests/runner/transition_variant_scenes.py OUT_DIR [-n 100] [--seed 2425] [--only NAMES]

The placement strategies (strategies/set_position.py) place a mover that is neither Static nor
Active, so PhysicsObj.prepare_to_enter_world's arms for those flags were never taken; the obstacle
strategies never make a sphere or cylsphere static both non-static and ethereal beside a
two-sphere mover, so the second sphere's test in the ethereal-obstruction arm of
Sphere.IntersectsSphere / CylSphere.IntersectsSphere was never reached. Each variant below is
applied to N records of the coreclr corpus drawn with `--seed` from its pool, one scene file each,
named after the record with the variant appended (the tick scenes have tick_variant_scenes.py).
"""

from __future__ import annotations

import argparse
import json
import random
from dataclasses import replace
from pathlib import Path


def variants():
    """(name, pool, scene -> scene): "placement" draws from the placement records, "statics" from
    the transition records with statics outdoors and a one-sphere mover."""
    from acconform.flags import PhysicsState as P, TransientState as T
    from acconform.numerics import to_f32

    def mover(**kw):
        return lambda s: replace(s, mover=replace(s.mover, **{k: f(s.mover) for k, f in kw.items()}))

    def head_sphere(m):
        """A second sphere of the same radius stacked above the first (strategies/scenes.py's form)."""
        low = m.spheres[0]
        return (low, replace(low, center=(0.0, 0.0, to_f32(low.radius * 2.6))))

    def ethereal_obstacles(s):
        return replace(s, objects=tuple(replace(o, state=(o.state & ~P.Static) | P.Ethereal) for o in s.objects))

    return [
        ("placement_active", "placement", mover(transient_state=lambda m: m.transient_state | T.Active)),
        ("placement_static", "placement", mover(state=lambda m: m.state | P.Static)),
        ("two_spheres_ethereal_obstacles", "statics", lambda s: ethereal_obstacles(mover(spheres=head_sphere)(s))),
    ]


def main(argv=None) -> int:
    from acconform.oracle import default_corpus
    from acconform.oracle.recorded import RecordedOracle
    from acconform.scene import Scene

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out", type=Path)
    ap.add_argument("-n", type=int, default=100, help="records per variant")
    ap.add_argument("--seed", type=int, default=2425)
    ap.add_argument("--only", default=None, help="comma-separated variant names to write (the draws stay those of all)")
    a = ap.parse_args(argv)
    a.out.mkdir(parents=True, exist_ok=True)
    oracle = RecordedOracle(default_corpus("coreclr"))
    records = sorted((e for e in oracle.entries if "/ticks-" not in e.where), key=lambda e: e.key)
    scenes = [(e.key, Scene.from_json(e.doc()["scene"])) for e in records]
    pools = {
        "placement": [(k, s) for k, s in scenes if s.mover.placement is not None],
        # an EnvCell's statics are DAT stabs, which carry no state: the obstacle variant is outdoors
        "statics": [(k, s) for k, s in scenes if s.objects and not s.env_cells and s.mover.placement is None
                    and len(s.mover.spheres) == 1],
    }
    only = set(a.only.split(",")) if a.only else None
    rng = random.Random(a.seed)
    written = 0
    for name, pool_name, make in variants():
        pool = pools[pool_name]
        drawn = rng.sample(pool, min(a.n, len(pool)))
        if only is not None and name not in only:
            continue
        for key, s in drawn:
            (a.out / f"{key[:16]}-{name}.json").write_text(json.dumps(replace(make(s), name=f"{s.name}:{name}").to_json()))
            written += 1
    print(f"{written} scenes in {a.out} ({', '.join(f'{len(p)} {k}' for k, p in pools.items())} records)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
