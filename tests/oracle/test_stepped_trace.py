"""ACE's stepped trace (LiveOracle.stepped_trace): the facade drives FindTransitionalPosition's loop
through ACE's public methods and snapshots each pass; the stepped run must end in ACE's own outcome,
its steps are the port's where the port's outcome is ACE's, and explain uses them as the reference
where the port itself differs from ACE. tests/oracle/stepped_check.py prints the corpus figure."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import pytest

from acconform.case import load_document
from acconform.compare import compare
from acconform.explain import explain, render
from acconform.impl import BuiltinPort
from acconform.oracle.live import SteppedTraceRefused
from acconform.port.run import traced_run
from acconform.trace import first_divergence

ROOT = Path(__file__).resolve().parents[2]
pytestmark = pytest.mark.live_oracle


def example(name):
    return load_document(ROOT / "examples" / f"{name}.json")


@pytest.mark.anchor("CTransition::find_transitional_position")
@pytest.mark.parametrize("name", ["cliff_edge_slide", "flat_walk", "two_rooms", "placement_wall_push"])
def test_aces_stepped_run_ends_in_its_own_outcome_and_its_steps_are_the_ports(live, name):
    scene = example(name)
    outcome, steps = live.stepped_trace(scene)
    assert compare(outcome, live.run(scene)) == []
    assert steps and [r.step for r in steps] == list(range(len(steps)))
    port_outcome, port_trace = traced_run(scene, "exact", live.location.runtime)
    assert compare(port_outcome, outcome) == []
    assert first_divergence(port_trace, steps) is None
    assert len([r for r in port_trace if r.event == "step"]) == len(steps)


def test_a_tick_scene_has_no_stepped_trace_and_says_why(live):
    with pytest.raises(SteppedTraceRefused, match="tick scene"):
        live.stepped_trace(example("tick_walk"))


def test_a_stepped_run_that_ends_elsewhere_is_refused_naming_the_field(live, monkeypatch):
    scene = example("cliff_edge_slide")
    real = live.run
    calls = {"n": 0}

    def second_run_moved(s):  # the stepped run (the second) as if it ended elsewhere
        calls["n"] += 1
        o = real(s)
        return replace(o, origin=(o.origin[0] + 1.0, o.origin[1], o.origin[2])) if calls["n"] == 2 else o

    monkeypatch.setattr(live, "run", second_run_moved)
    with pytest.raises(SteppedTraceRefused, match=r"does not end in ACE's own outcome \(origin\[0\]"):
        live.stepped_trace(scene)


@pytest.mark.anchor("CTransition::find_transitional_position")
def test_where_the_port_differs_from_ace_explain_takes_aces_steps_as_the_reference(live):
    scene = example("cliff_edge_slide")
    ace = live.run(scene)
    wrong = replace(ace, origin=(ace.origin[0] + 1.0, ace.origin[1], ace.origin[2]))  # as if ACE had answered so
    e = explain(scene, wrong, "a doctored answer", BuiltinPort("exact", live.location.runtime), "exact",
                live.location.runtime, live)
    assert e.reference_name == "ACE" and e.reference.startswith("ACE's stepped trace (checked")
    assert e.divergence is None and "after the last step" in e.note  # the port's steps are ACE's own
    assert any(line.startswith("reference: ACE's stepped trace") for line in render(e))
