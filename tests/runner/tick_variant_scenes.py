"""Tick scenes of the recorded corpus with the mover's flags and a tick's inputs varied (issue 24), for
`acconform record`.

    python tests/runner/tick_variant_scenes.py OUT_DIR [-n 12] [--seed 2424]

strategies/ticks.py draws movers with Gravity and the default transient flags, statics that are
Static, and steps that set the velocity, the transient flags, a jump or root motion: the tick loop's
arms for the other flags and inputs (PhysicsObj.UpdateObjectInternal's Hidden and AlignPath arms,
calc_acceleration without Gravity, handle_all_collisions' Inelastic stop, CheckEthereal's
set_ethereal, StationaryStuck, report_object_collision and the collision table of a non-static
obstacle, a step's state / local_velocity / omega, a Frozen or Static mover, a step that clears
Active) no recorded scene took. Each variant below is
applied to N tick records of the coreclr corpus drawn with `--seed` (for the obstacle variants,
those with statics outdoors), one scene file each, named after the record with the variant appended.
"""

from __future__ import annotations

import argparse
import json
import random
from dataclasses import replace
from pathlib import Path


def variants():
    """(name, needs statics, scene -> scene): each one flag or input the tick strategies never draw."""
    from acconform.flags import PhysicsState as P, TransientState as T

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
    ]


def main(argv=None) -> int:
    from acconform.oracle import default_corpus
    from acconform.oracle.recorded import RecordedOracle
    from acconform.scene import Scene

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out", type=Path)
    ap.add_argument("-n", type=int, default=12, help="tick records per variant")
    ap.add_argument("--seed", type=int, default=2424)
    a = ap.parse_args(argv)
    a.out.mkdir(parents=True, exist_ok=True)
    oracle = RecordedOracle(default_corpus("coreclr"))
    ticks = sorted((e for e in oracle.entries if "/ticks-" in e.where), key=lambda e: e.key)
    scenes = [(e.key, Scene.from_json(e.doc()["scene"])) for e in ticks]
    # an EnvCell's statics are DAT stabs, which carry no state: the obstacle variants are outdoors
    with_statics = [(k, s) for k, s in scenes if s.objects and not s.env_cells]
    rng = random.Random(a.seed)
    written = 0
    for name, needs_statics, make in variants():
        pool = with_statics if needs_statics else scenes
        for key, s in rng.sample(pool, min(a.n, len(pool))):
            v = make(s)
            (a.out / f"{key[:16]}-{name}.json").write_text(json.dumps(replace(v, name=f"{s.name}:{name}").to_json()))
            written += 1
    print(f"{written} scenes in {a.out} ({len(with_statics)} of {len(scenes)} tick records have statics outdoors)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
