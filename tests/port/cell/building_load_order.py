"""The order in which a building scene's world is loaded, read from a trace: its landblocks' PostInit and the
buildings it places (init_buildings, BuildingObj.add_to_cell, SortCell.add_building), its EnvCells' PostInit and
their stabs (init_static_objects), each said as before the run (the world's building) or in it, and which static
was being placed. ACE's order, from the instrumented ACE's own trace (docs/oracle.md, "The instrumented ACE"), is
kept in data/ace_building_load_order.json for three of issue 20's named building scenes (building_scenes.py) whose
run reaches the building's landblock first; re-record with an ACE build (once with mono, once with .NET 10):

    ACE_ASSEMBLY=/path/to/ACE.Server.dll python tests/port/cell/building_load_order.py --record
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
if str(HERE) not in sys.path:
    sys.path.insert(0, str(HERE))

DATA = HERE / "data" / "ace_building_load_order.json"
# the named building scenes whose traces parted from ACE's, before the port built a landblock with buildings up front
SCENES = ("border-from-neighbour", "down-cellar-stairs", "placement-into-building")
LANDBLOCK = ("Landblock.cs:PostInit", "Landblock.cs:init_buildings")
LOADING = frozenset(LANDBLOCK + ("BuildingObj.cs:add_to_cell", "SortCell.cs:add_building", "EnvCell.cs:PostInit",
                                 "EnvCell.cs:init_static_objects"))


def load_order(scene, records) -> list[list]:
    """[routine, its `this` (a landblock's, building's, cell's ID), "world" or "run", the static being placed] for
    each call of a loading routine (LOADING; a landblock's only for one with buildings: the port builds the others
    on first use, which writes nothing the comparison with ACE's reads), in the trace's order."""
    from acconform.trace import run_start

    start = run_start(records)
    with_buildings = {b.landblock for b in scene.buildings}
    out = []
    for i, r in enumerate(records):
        if r.anchor not in LOADING or r.event == "exit":
            continue
        this = r.args[0] if r.args else None
        if r.anchor in LANDBLOCK and this not in with_buildings:
            continue
        out.append([r.anchor, this, "world" if i < start else "run", r.placing])
    return out


def _record() -> None:
    from building_scenes import load

    from acconform.oracle.instrumented import TracedAce

    scenes, _ = load()
    traced = TracedAce(say=None)
    try:
        runtime = traced.location.runtime
        orders = {name: load_order(scenes[name], traced.trace(scenes[name])[1]) for name in SCENES}
    finally:
        traced.close()
    doc = json.loads(DATA.read_text()) if DATA.exists() else {"ace": "7b47913, the instrumented ACE", "orders": {}}
    doc["orders"][runtime] = orders
    DATA.write_text(json.dumps(doc, indent=None, sort_keys=True) + "\n")
    print(f"{len(orders)} {runtime} load orders -> {DATA}")


if __name__ == "__main__":
    if sys.argv[1:] != ["--record"]:
        sys.exit("usage: python tests/port/cell/building_load_order.py --record")
    _record()
