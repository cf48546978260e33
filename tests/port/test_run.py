"""port/run.py's driver around a run: what a run leaves behind."""

from __future__ import annotations

import gc

import pytest

from acconform.port.run import run_scene
from acconform.runner import campaign_gc
from acconform.strategies import sample_scenes


@pytest.mark.anchor("PhysicsObj.cs:transition")
@pytest.mark.parametrize("kind", ["obstacles", "indoor", "buildings"])
def test_a_run_frees_its_world_as_it_ends_and_leaves_the_collector_nothing(kind):
    # a run's world holds cycles; freed young as the run ends, it is never walked by a later collection
    scene = next(iter(sample_scenes((kind,), 1, 2)))
    run_scene(scene, runtime="coreclr")  # the pools and caches a first run fills
    with campaign_gc():
        assert run_scene(scene, runtime="coreclr").error is None
        assert gc.collect() == 0
