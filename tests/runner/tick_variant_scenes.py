"""Tick scenes of the recorded corpus with the mover's flags and a tick's inputs varied (issue 24), for
`acconform record`.

    python tests/runner/tick_variant_scenes.py OUT_DIR [-n 12] [--seed 2424]

strategies/ticks.py draws movers with Gravity and the default transient flags, statics that are
Static, and steps that set the velocity, the transient flags, a jump or root motion: the tick loop's
arms for the other flags and inputs (PhysicsObj.UpdateObjectInternal's Hidden and AlignPath arms,
calc_acceleration without Gravity, handle_all_collisions' Inelastic stop, CheckEthereal's
set_ethereal, StationaryStuck, report_object_collision and the collision table of a non-static
obstacle, a step's state / local_velocity / omega, a Frozen or Static mover, a step that clears
Active) no recorded scene took; then (ticks-0025) an ethereal mover asking CheckEthereal every step
beside obstacles (set_ethereal's collision search through the cells' shadows, check_collision of a
non-static obstacle), a RequestPos two landblocks away (GetBlockDist's refusal) or with a quaternion
of length 2 (set_frame's repair of an invalid heading). Each variant below is
applied to N tick records of the coreclr corpus drawn with `--seed` (for the obstacle variants,
those with statics outdoors), one scene file each, named after the record with the variant appended.
"""

from __future__ import annotations

import argparse
import json
import random
from dataclasses import replace
from pathlib import Path


VARIANT_SHARDS = ("ticks-0024", "ticks-0025")  # the corpus shards this script's scenes were recorded into


def _outdoors(request_pos) -> bool:
    return request_pos is not None and request_pos.cell & 0xFFFF < 0x100


def variants():
    """(name, pool, scene -> scene): each one flag or input the tick strategies never draw; the pool is
    True for the records with statics outdoors, "request_pos" for those of the legacy player path with
    a RequestPos outdoors."""
    from acconform.flags import PhysicsState as P, TransientState as T
    from acconform.scene import Landblock

    def mover(**kw):
        return lambda s: replace(s, mover=replace(s.mover, **{k: f(s.mover) for k, f in kw.items()}))

    def first_step(**kw):
        def apply(s):
            steps = list(s.ticks.steps)
            steps[0] = replace(steps[0], **{k: f(s, steps[0]) for k, f in kw.items()})
            return replace(s, ticks=replace(s.ticks, steps=tuple(steps)))
        return apply

    def every_other_step(**kw):
        def apply(s):
            steps = tuple(replace(st, **kw) if i % 2 else st for i, st in enumerate(s.ticks.steps))
            return replace(s, ticks=replace(s.ticks, steps=steps))
        return apply

    def statics(state):
        return lambda s: replace(s, objects=tuple(replace(o, state=state(o.state)) for o in s.objects))

    def every_step_ethereal(s):
        flags = int(T.Contact | T.OnWalkable | T.Active | T.CheckEthereal)
        s = mover(state=lambda m: m.state | P.Ethereal)(s)
        steps = tuple(replace(st, transient_state=flags) for st in s.ticks.steps)
        return replace(s, ticks=replace(s.ticks, steps=steps))

    def request_far(s):
        """The first RequestPos two landblocks east of the mover (a landblock the scene adds)."""
        steps = list(s.ticks.steps)
        i = next(i for i, st in enumerate(steps) if _outdoors(st.request_pos))
        cell = s.ticks.steps[i].request_pos.cell
        far = cell + (2 << 24)
        lbs = s.landblocks if any(lb.id == far | 0xFFFF for lb in s.landblocks) else (
            s.landblocks + (Landblock(far | 0xFFFF, has_terrain=False),))
        steps[i] = replace(steps[i], request_pos=replace(steps[i].request_pos, cell=far))
        return replace(s, landblocks=lbs, ticks=replace(s.ticks, steps=tuple(steps)))

    def request_orientation(q):
        def apply(s):
            steps = tuple(replace(st, request_pos=replace(st.request_pos, frame=replace(st.request_pos.frame, orientation=q)))
                          if st.request_pos is not None else st for st in s.ticks.steps)
            return replace(s, ticks=replace(s.ticks, steps=steps))
        return apply

    return [
        ("hidden", False, mover(state=lambda m: m.state | P.Hidden)),
        ("align_path", False, mover(state=lambda m: m.state | P.AlignPath)),
        ("no_gravity", False, mover(state=lambda m: m.state & ~P.Gravity)),
        ("inelastic", False, mover(state=lambda m: m.state | P.Inelastic)),
        ("check_ethereal", False, mover(state=lambda m: m.state | P.Ethereal,
                                        transient_state=lambda m: m.transient_state | T.CheckEthereal)),
        ("stationary_stuck", False, mover(transient_state=lambda m: m.transient_state | T.StationaryStuck)),
        ("inactive", False, mover(transient_state=lambda m: m.transient_state & ~T.Active)),
        ("step_state", False, first_step(state=lambda s, st: s.mover.state | P.Hidden | P.AlignPath)),
        ("local_velocity_omega", False, every_other_step(local_velocity=(0.5, 2.0, 0.0), omega=(0.0, 0.0, 1.5))),
        ("obstacles_not_static", True, statics(lambda st: st & ~P.Static)),
        ("obstacles_report", True, lambda s: statics(lambda st: (st & ~P.Static) | P.ReportCollisions)(
            replace(s, mover=replace(s.mover, state=s.mover.state | P.ReportCollisions)))),
        ("obstacles_as_environment", True, statics(lambda st: (st & ~P.Static) | P.ReportCollisionsAsEnvironment)),
        ("obstacles_ignored", True, statics(lambda st: (st & ~P.Static) | P.IgnoreCollisions)),
        ("obstacles_ethereal", True, statics(lambda st: (st & ~P.Static) | P.Ethereal)),
        ("missile_report", True, lambda s: statics(lambda st: st & ~P.Static)(
            replace(s, mover=replace(s.mover, state=s.mover.state | P.Missile | P.ReportCollisions)))),
        ("frozen", False, mover(state=lambda m: m.state | P.Frozen)),
        ("static_mover", False, mover(state=lambda m: m.state | P.Static)),
        ("ethereal_ignore", True, mover(state=lambda m: m.state | P.Ethereal | P.IgnoreCollisions)),
        ("step_inactive", False, every_other_step(transient_state=int(T.Contact | T.OnWalkable))),
        ("sled_align", False, mover(state=lambda m: m.state | P.Sledding | P.AlignPath)),
        # issue 24, second round (ticks-0025)
        # an ethereal mover asking CheckEthereal again every step (set_ethereal(false) looks for a collision
        # in the cells its shadows are in), beside obstacles static or not
        ("ethereal_recheck", True, every_step_ethereal),
        ("ethereal_recheck_not_static", True, lambda s: statics(lambda st: st & ~P.Static)(every_step_ethereal(s))),
        ("ethereal_recheck_bsp", True, lambda s: statics(lambda st: st & ~P.Static)(
            mover(state=lambda m: m.state | P.HasPhysicsBSP)(every_step_ethereal(s)))),
        ("request_far", "request_pos", request_far),
        ("request_unnormalized", "request_pos", request_orientation((0.0, 0.0, 0.0, 2.0))),
    ]


def arguments(doc: str, n: int, seed: int, argv=None):
    """A variant script's command line: the output directory, records per variant, the seed, --only."""
    ap = argparse.ArgumentParser(description=doc.splitlines()[0])
    ap.add_argument("out", type=Path)
    ap.add_argument("-n", type=int, default=n, help="records per variant")
    ap.add_argument("--seed", type=int, default=seed)
    ap.add_argument("--only", default=None, help="comma-separated variant names to write (the draws stay those of all)")
    a = ap.parse_args(argv)
    a.out.mkdir(parents=True, exist_ok=True)
    return a


def write_variants(a, variants, pools) -> int:
    """Each variant (name, pool, make) drawn from its pool in turn, -n records with one seeded
    generator, and its changed scenes written (only the --only ones; every variant still draws, so
    a variant's scenes do not depend on which are written); how many were written."""
    only = set(a.only.split(",")) if a.only else None
    rng = random.Random(a.seed)
    written = 0
    for name, pool_name, make in variants:
        pool = pools[pool_name]
        drawn = rng.sample(pool, min(a.n, len(pool)))
        if only is not None and name not in only:
            continue
        for key, s in drawn:
            (a.out / f"{key[:16]}-{name}.json").write_text(json.dumps(replace(make(s), name=f"{s.name}:{name}").to_json()))
            written += 1
    return written


def drawn_records(keep, excluded: tuple[str, ...]) -> list:
    """(scene key, scene) of the coreclr corpus's records whose place `keep` takes (e.g. "/ticks-" in
    it), but none of the `excluded` shards' (variants written before), in scene-key order: a variant
    script's pools, the same draw each time it runs over the same corpus."""
    from acconform.oracle import default_corpus
    from acconform.oracle.recorded import RecordedOracle
    from acconform.scene import Scene

    oracle = RecordedOracle(default_corpus("coreclr"))
    records = sorted((e for e in oracle.entries if keep(e.where)
                      and not any(f"/{shard}." in e.where for shard in excluded)), key=lambda e: e.key)
    return [(e.key, Scene.from_json(e.doc()["scene"])) for e in records]


def main(argv=None) -> int:
    a = arguments(__doc__, 12, 2424, argv)
    # the drawn tick records, not the variants of them written here before
    scenes = drawn_records(lambda where: "/ticks-" in where, VARIANT_SHARDS)
    # an EnvCell's statics are DAT stabs, which carry no state: the obstacle variants are outdoors
    with_statics = [(k, s) for k, s in scenes if s.objects and not s.env_cells]
    pools = {False: scenes, True: with_statics,
             "request_pos": [(k, s) for k, s in scenes if any(_outdoors(st.request_pos) for st in s.ticks.steps)]}
    written = write_variants(a, variants(), pools)
    print(f"{written} scenes in {a.out} ({len(with_statics)} of {len(scenes)} tick records have statics outdoors)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
