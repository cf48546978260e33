"""Pins for docs/divergences.md: where ACE differs from retail, the port follows ACE."""

from __future__ import annotations

import json
from collections import Counter
from pathlib import Path

import pytest

from acconform.compare import compare
from acconform.outcome import Outcome
from acconform.port.run import run_scene
from terrain_scenes import SCENES

RECORDED = json.loads((Path(__file__).parent / "data" / "ace_terrain_outcomes.json").read_text())["outcomes"]
EDGE_WALKS = ["cliff-edge-slide", "cliff-diagonal", "two-spheres-cliff", "big-step-down-halves"]


@pytest.mark.anchor("CTransition::edge_slide")
@pytest.mark.parametrize("name", EDGE_WALKS)
def test_terrain_never_sets_the_walkable_polygon_so_its_edges_never_precipice_slide(name):
    # Retail (and acdream's port) keeps the terrain polygon as the walkable one and precipice-slides
    # along its crossed edge; ACE's LandCell.find_env_collisions never calls set_walkable, so a
    # terrain edge goes through cliff slide or the back-probe instead.
    scene, _ = SCENES[name]
    ace = Outcome.from_json(RECORDED[name])
    trace = Counter()
    port = run_scene(scene, trace=trace)
    assert not ace.walkable and not port.walkable
    assert not any(b.startswith("precipice_slide") for b in trace), trace
    assert trace["edge_slide:cliff_slide"] + trace["edge_slide:back_probe"] > 0, trace
    assert compare(port, ace, "exact") == []
