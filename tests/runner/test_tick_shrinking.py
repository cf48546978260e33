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
    assert len(json.dumps(small.ticks.to_json())) < len(json.dumps(big.ticks.to_json())) / 10


def test_the_shrinker_simplifies_time_steps_that_do_not_matter():
    scene = next(s for s in sample_scenes(("ticks",), 200, 8)
                 if ":irregular" in s.name and len(s.ticks.steps) >= 5 and s.ticks.driver == "update_object")

    def three_ticks(s):  # fails while the scene keeps three ticks or more, whatever their steps
        return s.ticks is not None and len(s.ticks.steps) >= 3

    small, _ = shrink_scene(scene, three_ticks)
    assert len(small.ticks.steps) == 3
    assert all(s.dt == SIMPLE_DT for s in small.ticks.steps) and inputs(small) == 0
