"""Named building scenes (issue 20's acceptance): a house from strategies/buildings.py for each thing it shows.

The scenes are data: data/ace_building_scenes.json holds each scene (picked once from the building
strategy's draws by `pick`, the rule named beside it) and live ACE's outcome for it on mono and on
.NET 10. Re-pick and re-record with

    ACE_ASSEMBLY=/path/to/ACE.Server.dll python tests/port/cell/building_scenes.py --record

once with a mono build and once with a .NET 10 build (the second run keeps the scenes the first
picked and adds its runtime's outcomes).
"""

from __future__ import annotations

import json
import sys
from dataclasses import replace
from pathlib import Path

from acconform.scene import PORTAL_SIDE_BIT, Scene

DATA = Path(__file__).resolve().parent / "data" / "ace_building_scenes.json"
SEED, DRAWS = 7, 900


def _first(scenes, outcomes, traces, want):
    for s, o, t in zip(scenes, outcomes, traces):
        if want(s, o, t):
            return s
    return None


# what each named scene is picked for: (scene, port outcome, port trace) -> bool
RULES = {
    "in-through-door": lambda s, o, t: s.name == "building:in" and o.cell & 0xFFFF >= 0x100 and not o.error,
    "out-through-door": lambda s, o, t: s.name.startswith("building:out") and o.cell & 0xFFFF < 0x100 and not o.error,
    "along-shell": lambda s, o, t: s.name.startswith("building:along") and t["building:collided"] > 0,
    "into-wall-beside-door": lambda s, o, t: s.name.startswith("building:wall") and t["building:collided"] > 0
    and o.cell & 0xFFFF < 0x100,
    "down-cellar-stairs": lambda s, o, t: s.name.startswith("building:cellar") and o.cell & 0xFFFF in (0x102, 0x103)
    and not o.error and o.origin[2] < s.mover.begin.frame.origin[2] - 0.1,
    "border-from-neighbour": lambda s, o, t: s.name.startswith("building:border")
    and s.mover.begin.cell >> 16 != s.buildings[0].landblock >> 16 and t["building:transit_cell"] > 0,
    "placement-into-building": lambda s, o, t: s.name.startswith("building:placement") and o.placement is not None
    and o.placement.cur_cell & 0xFFFF >= 0x100,
    "static-in-doorway": lambda s, o, t: s.name.startswith("building:static")
    and any(c & 0xFFFF >= 0x100 for c in o.static_cells[0]),
    "porch-edge": lambda s, o, t: s.name.startswith("building:porch") and o.cell & 0xFFFF < 0x100 and not o.error,
}


def with_portal_side(scene: Scene, on: bool) -> Scene:
    """The scene with its building portal's PortalSide on (flag bit clear) or off (bit set)."""
    b = scene.buildings[0]
    p = b.portals[0]
    flags = (p.flags & ~PORTAL_SIDE_BIT) | (0 if on else PORTAL_SIDE_BIT)
    return replace(scene, buildings=(replace(b, portals=(replace(p, flags=flags),)),))


def pick() -> dict[str, Scene]:
    from acconform.port.run import run_scene
    from acconform.port.transition.branches import Trace
    from acconform.strategies import sample_scenes

    scenes = list(sample_scenes(("buildings",), DRAWS, SEED))
    traces = [Trace() for _ in scenes]
    outcomes = [run_scene(s, trace=t) for s, t in zip(scenes, traces)]
    named = {name: replace(_first(scenes, outcomes, traces, rule), name=f"named:{name}") for name, rule in RULES.items()}
    for on in (True, False):
        named[f"portal-side-{'on' if on else 'off'}"] = replace(
            with_portal_side(named["in-through-door"], on), name=f"named:portal-side-{'on' if on else 'off'}")
    return named


def load() -> tuple[dict[str, Scene], dict[str, dict]]:
    """(scenes by name, {runtime: {name: outcome JSON}})."""
    doc = json.loads(DATA.read_text())
    return {k: Scene.from_json(v) for k, v in doc["scenes"].items()}, doc["outcomes"]


def _record() -> None:
    from acconform.oracle.live import LiveOracle

    if DATA.exists():
        doc = json.loads(DATA.read_text())
        scenes = {k: Scene.from_json(v) for k, v in doc["scenes"].items()}
    else:
        scenes = pick()
        doc = {"ace": "7b47913, live oracle", "scenes": {k: s.to_json() for k, s in sorted(scenes.items())},
               "outcomes": {}}
    oracle = LiveOracle()
    doc["outcomes"][oracle.location.runtime] = {k: oracle.run(s).to_json() for k, s in sorted(scenes.items())}
    DATA.write_text(json.dumps(doc, indent=None, sort_keys=True) + "\n")
    print(f"{len(scenes)} {oracle.location.runtime} outcomes -> {DATA}")


if __name__ == "__main__":
    if sys.argv[1:] != ["--record"]:
        sys.exit("usage: python tests/port/cell/building_scenes.py --record")
    _record()
