"""Differences a live campaign against ACE on .NET 10 shrank, kept once fixed: each case file
(data/net10_cases/, acconform.case/1 from `acconform check`) holds the scene and ACE-on-.NET 10's
outcome; the port computing .NET 10's arithmetic must reproduce it bit for bit."""

from __future__ import annotations

from pathlib import Path

import pytest

from acconform.case import load_document
from acconform.compare import compare
from acconform.numerics import runtime_named
from acconform.port.run import run_scene

CASES = sorted((Path(__file__).parent / "data" / "net10_cases").glob("case-*.json"))


def test_the_dotnet10_regression_cases_are_there():
    assert len(CASES) >= 2


@pytest.mark.anchor("CSphere::slide_sphere")
@pytest.mark.parametrize("path", CASES, ids=[p.stem for p in CASES])
def test_a_collision_normal_negated_on_dotnet10_keeps_its_negative_zeros(path):
    """Sphere.SlideSphere's ``-gDelta``: .NET 10 negates by flipping sign bits, so a zero
    component of the pushed-back normal comes out -0 where mono's ``Zero - v`` gives +0."""
    case = load_document(path)
    assert runtime_named(case.versions.runtime) == "coreclr"
    assert compare(run_scene(case.scene, runtime="coreclr"), case.oracle, "exact") == []
    mono = compare(run_scene(case.scene, runtime="mono"), case.oracle, "exact")
    assert mono and all("normal" in str(d) for d in mono)
