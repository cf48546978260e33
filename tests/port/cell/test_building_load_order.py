"""A building scene's world is loaded in ACE's order: the landblock with the building built and PostInit'd (its
building placed) before the run, as the oracle's facade builds it, and the EnvCells behind the building's portal
loaded in the run, when get_landcell first reaches them, in the order ACE loads them (building_load_order.py; ACE's
order from the instrumented ACE's own trace on mono and on .NET 10, data/ace_building_load_order.json)."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest

_HERE = Path(__file__).resolve().parent
if str(_HERE) not in sys.path:
    sys.path.insert(0, str(_HERE))

from acconform.port.run import traced_run  # noqa: E402
from building_load_order import DATA, SCENES, load_order  # noqa: E402
from building_scenes import load  # noqa: E402

ACE = json.loads(DATA.read_text())["orders"]
NAMED, _ = load()


@pytest.mark.anchor("CLandBlock::init_buildings")
@pytest.mark.anchor("CSortCell::add_building")
@pytest.mark.anchor("EnvCell.cs:PostInit")
@pytest.mark.parametrize("runtime", sorted(ACE))
@pytest.mark.parametrize("name", SCENES)
def test_a_building_scenes_landblock_and_cells_load_in_aces_order_its_buildings_before_the_run(name, runtime):
    scene = NAMED[name]
    _, records = traced_run(scene, "exact", runtime)
    assert load_order(scene, records) == ACE[runtime][name]
