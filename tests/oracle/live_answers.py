"""Recording live ACE's answers to a set of named scenes: the configured ACE (one runtime per
process) answers each, and its outcomes go into the data file under its runtime, beside the other
runtime's. Run once with a mono build and once with a .NET 10 build."""

from __future__ import annotations

import json
from pathlib import Path


def record_outcomes(scenes: dict, data: Path, what: str) -> None:
    from acconform.oracle.live import LiveOracle

    oracle = LiveOracle()
    runtime = oracle.location.runtime
    doc = json.loads(data.read_text()) if data.exists() else {"ace": "7b47913, live oracle", "outcomes": {}}
    doc["outcomes"][runtime] = {name: oracle.run(scene).to_json() for name, scene in scenes.items()}
    data.parent.mkdir(parents=True, exist_ok=True)
    data.write_text(json.dumps(doc, indent=1, sort_keys=True) + "\n")
    print(f"{len(scenes)} {what} outcomes from ACE on {runtime} -> {data}")
