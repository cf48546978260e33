"""The protocol's `trace` feature: a request with ``"trace": true`` answered with the outcome and the
run's trace records (acconform.trace/1), read back by the harness; docs/protocol.md's example is a
trace the harness reads."""

from __future__ import annotations

import json
import re
import sys
from pathlib import Path

import pytest

from acconform.case import load_document
from acconform.protocol import Implementation, handshake
from acconform.port.run import run_scene, traced_run
from acconform.trace import first_divergence, trace_from_json

ROOT = Path(__file__).resolve().parents[2]
PLANTED = Path(__file__).with_name("planted_impl.py")
DOC = ROOT / "docs" / "protocol.md"


def example(name):
    return load_document(ROOT / "examples" / f"{name}.json")


def test_the_built_in_port_lists_the_trace_feature_in_its_handshake():
    assert "trace" in handshake()["features"]


@pytest.mark.anchor("CTransition::find_transitional_position")
def test_acconform_serve_answers_a_traced_request_with_the_ports_outcome_and_trace():
    impl = Implementation(f"{sys.executable} -m acconform.cli serve", timeout=120)
    try:
        assert impl.traces
        scene = example("cliff_edge_slide")
        outcome, records, anchors = impl.run_traced(scene)
        want_outcome, want_records = traced_run(scene, runtime=impl.runtime)
        assert anchors == {r.anchor for r in records if r.event == "enter"} | anchors and len(anchors) > 400
        assert outcome == want_outcome == run_scene(scene, runtime=impl.runtime)
        assert records == want_records
        assert impl.run(example("flat_walk")) == run_scene(example("flat_walk"), runtime=impl.runtime)  # untraced again
    finally:
        impl.close()


@pytest.mark.anchor("CTransition::transitional_insert")
def test_a_planted_bug_traced_through_the_protocol_parts_from_the_port_in_the_mutated_routine():
    impl = Implementation(f"{sys.executable} {PLANTED} step_down_two_halves_made_thirds", timeout=120)
    try:
        from acconform.oracle.recorded import RecordedOracle
        from acconform.oracle import default_corpus

        scene = next(iter(_two_sphere_descent()))
        _, mutant, anchors = impl.run_traced(scene)
        _, port = traced_run(scene, runtime=impl.runtime)
        d = first_divergence(port, mutant, anchors)
        assert d is not None and d.routine == "Transition.cs:TransitionalInsert" and d.field == "args[1]"
    finally:
        impl.close()


def _two_sphere_descent():
    """A scene where the two half step-downs are taken: the first of the fast sample's records
    that fire that branch (the planted bug turns them into thirds)."""
    from acconform.oracle import default_corpus
    from acconform.oracle.recorded import RecordedOracle

    sample = json.loads((ROOT / "tests/data/corpus/coreclr/fast-sample.json").read_text())
    keys = {k for k, _, branches in sample["records"]
            if sample["branches"].index("transitional_insert:step_down_halves") in branches}
    oracle = RecordedOracle(default_corpus())
    for entry in oracle.select(runtime="coreclr"):
        if entry.key in keys:
            yield oracle._record(entry).scene


def test_an_implementation_without_the_feature_is_asked_without_it_and_gives_no_trace(tmp_path):
    script = tmp_path / "untraced.py"
    script.write_text(
        "import sys\n"
        "from acconform.port.run import run_scene\n"
        "from acconform.protocol import handshake, serve\n"
        "hello = handshake('untraced'); hello['features'].remove('trace')\n"
        "sys.exit(serve(lambda s, m, r: run_scene(s, mode=m, runtime=r), hello=hello))\n")
    impl = Implementation(f"{sys.executable} {script}")
    try:
        assert not impl.traces
        outcome, records, anchors = impl.run_traced(example("flat_walk"))
        assert records is None and anchors is None and outcome == run_scene(example("flat_walk"), runtime=impl.runtime)
    finally:
        impl.close()


def test_a_traced_answer_without_its_trace_is_a_protocol_error_verdict(tmp_path):
    script = tmp_path / "forgetful.py"
    script.write_text(
        "import sys\n"
        "from acconform.port.run import run_scene\n"
        "from acconform.protocol import serve\n"
        "sys.exit(serve(lambda s, m, r: run_scene(s, mode=m, runtime=r)))\n")  # lists trace, never sends one
    impl = Implementation(f"{sys.executable} {script}")
    try:
        outcome, records, _ = impl.run_traced(example("flat_walk"))
        assert records is None and outcome.error.startswith("ImplementationProtocolError")
        assert "trace" in outcome.error
    finally:
        impl.close()


def test_the_protocol_docs_example_trace_is_one_the_harness_reads():
    text = DOC.read_text()
    section = text.split("## Traces (feature `trace`)", 1)[1].split("\n## ", 1)[0]
    answer = re.search(r'\{"id": 3, "outcome": \{\.\.\.\}, "trace": (\{.*?\]\})\}\n```', section, re.S).group(1)
    records = trace_from_json(json.loads(answer), exact=True)
    assert [(r.anchor, r.event, r.step) for r in records] == [("Transition.cs:FindTransitionalPosition", "step", 0)]
    assert records[0].path.contact_plane.normal == (0.0, 0.0, 1.0)
    # the example is the port's own first step record for the flat walk (written by the port, not by hand)
    _, port = traced_run(example("flat_walk"))
    assert first_divergence(port, records) is None


SLOW = """
import json, sys, time
from acconform.codec import dumps_compact
from acconform.outcome import Outcome
from acconform.protocol import handshake
from acconform.trace import trace_to_json
print(dumps_compact(handshake("slow", "1")), flush=True)
for line in sys.stdin:
    req = json.loads(line)
    time.sleep(float(sys.argv[1]))
    answer = {"id": req["id"], "outcome": Outcome(ok=True).to_json()}
    if req.get("trace"):
        answer["trace"] = trace_to_json([])
    print(dumps_compact(answer), flush=True)
"""


def test_a_traced_request_may_take_longer_than_the_time_limit_of_a_plain_one(tmp_path):
    # a trace costs 20-30x a plain run: a traced request held to the plain limit timed out under load,
    # and check's triage then grouped the case by fields where explain named its first divergence
    from acconform.protocol import TRACED_TIMEOUT

    script = tmp_path / "slow.py"
    script.write_text(SLOW)
    impl = Implementation(f"{sys.executable} {script} 1.5", timeout=1)  # answers each request after 1.5 s
    try:
        scene = getattr(example("flat_walk"), "scene", example("flat_walk"))
        assert TRACED_TIMEOUT * 1 > 1.5
        outcome, records, _ = impl.run_traced(scene)
        assert outcome.error is None and records == ()
        assert "ImplementationTimeout" in (impl.run(scene).error or "")
    finally:
        impl.close()
