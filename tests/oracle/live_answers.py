"""Live ACE's answers to a set of named scenes, kept in a data file under each runtime: recording
them (the configured ACE, one runtime per process, answers each; run once with a mono build and
once with a .NET 10 build) and reading one runtime's back."""

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


def recorded_outcomes(data: Path, runtime: str) -> dict:
    """{name: Outcome} of ACE on `runtime` from `data`; a missing file or runtime fails the test, saying how to record."""
    import pytest

    from acconform.outcome import Outcome

    if not data.exists():
        pytest.fail(f"no recorded ACE answers at {data}: record them with the live oracle (see the module note)")
    doc = json.loads(data.read_text())
    if runtime not in doc["outcomes"]:
        pytest.fail(f"{data} has no answers from ACE on {runtime}: record them (see the module note)")
    return {name: Outcome.from_json(o) for name, o in doc["outcomes"][runtime].items()}
