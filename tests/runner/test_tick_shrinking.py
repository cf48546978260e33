"""Shrinking over ticks: a planted tick bug -- a port that splits a step longer than MaxQuantum
wrongly (here: answers a wrong walkable flag whenever a tick's dt exceeds MaxQuantum) -- is shrunk
to a small tick scene, by Hypothesis in a live campaign (the strategy's shape: fewer ticks, the
plainest policy, no inputs) and by acconform/shrink.py for a recorded scene (fewer ticks, fewer
inputs, simpler time steps)."""

from __future__ import annotations

import dataclasses
import json

from acconform.outcome import Outcome
from acconform.port.constants import MAX_QUANTUM
from acconform.runner import run_campaign
from acconform.shrink import SIMPLE_DT, SIMPLE_START, shrink_scene
from acconform.strategies import sample_scenes


def fake_port(scene):
    """A stand-in backend: a cheap deterministic function of the scene."""
    m = scene.mover
    return Outcome(ok=True, cell=m.begin.cell, origin=m.begin.frame.origin, walkable=bool(m.contact_plane),
                   object_info_state=m.transient_state)


def long_step(scene) -> bool:
    return scene.ticks is not None and any(s.dt > float(MAX_QUANTUM) for s in scene.ticks.steps)


def planted(scene):
    """The planted tick bug: wrong whenever a tick is longer than MaxQuantum (update_object's split)."""
    o = fake_port(scene)
    return dataclasses.replace(o, walkable=not o.walkable) if long_step(scene) else o


def inputs(scene) -> int:
    return sum(getattr(s, name) is not None for s in scene.ticks.steps
               for name in ("state", "transient_state", "velocity", "local_velocity", "omega", "jump",
                            "sequence_velocity", "sequence_omega"))


def test_hypothesis_shrinks_a_planted_tick_bug_to_one_tick(tmp_path):
    r = run_campaign(planted, fake_port, kinds=("ticks",), n=200, seed=19, failures_dir=tmp_path, database=None)
    assert r.found, "the planted tick bug is found"
    scene = r.found[0].case.scene
    assert long_step(scene)
    assert len(scene.ticks.steps) == 1, scene.ticks


def test_the_shrinker_cuts_a_recorded_tick_scene_to_one_plain_tick():
    big = next(s for s in sample_scenes(("ticks",), 200, 7)
               if long_step(s) and len(s.ticks.steps) >= 30 and inputs(s) >= 1 and s.ticks.driver == "update_object"
               and s.ticks.steps[-1].dt <= float(MAX_QUANTUM))
    small, tried = shrink_scene(big, long_step, budget=400)
    assert long_step(small) and tried <= 400
    assert len(small.ticks.steps) == 1 and inputs(small) == 0
    assert small.ticks.start == SIMPLE_START
    # one plain step: its dt (the long one that fails) and nothing else
    assert small.ticks.to_json() == {"driver": "update_object", "start": SIMPLE_START, "steps": [{"dt": small.ticks.steps[0].dt}]}
    assert len(json.dumps(small.ticks.to_json())) < len(json.dumps(big.ticks.to_json())) / 5


def test_the_shrinker_simplifies_time_steps_that_do_not_matter():
    scene = next(s for s in sample_scenes(("ticks",), 200, 8)
                 if ":irregular" in s.name and len(s.ticks.steps) >= 5 and s.ticks.driver == "update_object")

    def three_ticks(s):  # fails while the scene keeps three ticks or more, whatever their steps
        return s.ticks is not None and len(s.ticks.steps) >= 3

    small, _ = shrink_scene(scene, three_ticks)
    assert len(small.ticks.steps) == 3
    assert all(s.dt == SIMPLE_DT for s in small.ticks.steps) and inputs(small) == 0


def test_the_shrinker_cuts_a_motion_table_to_the_entry_and_the_frame_that_matter():
    import sys
    from pathlib import Path

    sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
    from acconform.motion_enums import MotionCommand as MC
    from acconform.shrink import size
    from oracle.motion_scenes import scenes

    scene = scenes()["strafe_run_diagonal"]
    table = scene.mover.motion_table

    def still_fails(s):  # "the bug" needs the sidestep cycle's root motion to move along x
        t = s.mover.motion_table
        return t is not None and any(c.motion == int(MC.SideStepRight) and t.animations[c.data.anims[0].animation]
                                     .pos_frames[0].origin == (0.0, 0.0, 0.0) for c in t.cycles)

    small, tried = shrink_scene(scene, still_fails, 400)
    t = small.mover.motion_table
    assert still_fails(small) and not size(small).exceeds(size(scene))
    assert [c.motion for c in t.cycles] == [int(MC.SideStepRight)] and t.links == () and t.modifiers == ()
    assert len(t.animations) == 1 and len(t.animations[0].pos_frames) == 1 < len(table.animations[-1].pos_frames)
