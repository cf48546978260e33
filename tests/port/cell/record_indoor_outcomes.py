"""Records live ACE's outcomes for indoor_rooms.SCENES into data/ace_indoor_outcomes.json.

Run with an ACE build: ACE_ASSEMBLY=/path/to/ACE.Server.dll python tests/port/cell/record_indoor_outcomes.py
(ACE on mono; the fast lane replays the file against the port).
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path[:0] = [str(HERE), str(HERE.parent / "objects")]


def main() -> None:
    from acconform.oracle.live import LiveOracle
    from indoor_rooms import SCENES

    oracle = LiveOracle()
    outcomes = {name: oracle.run(scene).to_json() for name, (scene, _) in sorted(SCENES.items())}
    path = HERE / "data" / "ace_indoor_outcomes.json"
    path.write_text(json.dumps({"ace": "7b47913 on mono, live oracle", "outcomes": outcomes}, indent=1, sort_keys=True) + "\n")
    print(f"{len(outcomes)} outcomes -> {path}")


if __name__ == "__main__":
    main()
