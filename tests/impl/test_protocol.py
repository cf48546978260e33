"""A second implementation, caught through the protocol: the port with a planted bug as a process.

tests/impl/planted_impl.py speaks acconform.protocol/1; the harness sees it only through the
protocol. It must be found wrong, shrunk and reported (JSON and JUnit written); a crash, a hang
and a malformed answer each come out as a verdict for that case, and the process is restarted.
The built-in port runs the differential suite through `acconform serve` the same way.
"""

from __future__ import annotations

import json
import re
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from acconform.impl import BuiltinPort
from acconform.oracle.recorded import scene_kind
from acconform.protocol import CRASH, PROTOCOL_ERROR, TIMEOUT, Implementation, ImplementationError
from acconform.report import Campaign, junit, summary, write_json, write_junit
from acconform.runner import run_campaign

ROOT = Path(__file__).resolve().parents[2]
PLANTED = Path(__file__).with_name("planted_impl.py")
BUG = "step_down_two_halves_made_thirds"  # tests/runner/mutants.py: the two half step-downs are thirds


def planted(*args: str) -> str:
    return " ".join([sys.executable, str(PLANTED), *args])


def check(*args, cwd):
    return subprocess.run([sys.executable, "-m", "acconform.cli", "check", "--no-progress", *args],
                          capture_output=True, text=True, cwd=cwd)


@pytest.fixture(scope="module")
def corpus_scenes():
    from acconform.oracle import default_corpus
    from acconform.oracle.recorded import RecordedOracle

    oracle = RecordedOracle(default_corpus())
    keys = oracle.select(n=30, seed=5)
    return {scene_kind(s): s for s in oracle.scenes(keys)}


def test_the_builtin_port_runs_the_differential_suite_through_serve_as_a_process(tmp_path, no_ace):
    r = check("--impl", f"{sys.executable} -m acconform.cli serve", "-n", "150", "--seed", "2", "-j", "2",
              "--failures", str(tmp_path / "f"), "--json", str(tmp_path / "s.json"), cwd=tmp_path)
    assert r.returncode == 0, r.stdout + r.stderr
    s = json.loads((tmp_path / "s.json").read_text())
    assert s["cases"]["compared"] == 150 and s["differences"]["total"] == 0
    assert s["implementation"]["name"] == "acconform"


def test_a_planted_bug_is_found_in_the_corpus_and_reported_as_json_and_junit(tmp_path, no_ace):
    r = check("--impl", planted(BUG), "-n", "300", "--seed", "1", "--keep-going", "--failures", str(tmp_path / "f"),
              "--json", str(tmp_path / "s.json"), "--junit", str(tmp_path / "j.xml"), cwd=tmp_path)
    assert r.returncode == 1, r.stdout + r.stderr
    s = json.loads((tmp_path / "s.json").read_text())
    assert not s["ok"] and s["differences"]["total"] >= 1 and s["seed"] == 1
    assert s["implementation"]["version"] == f"0.0+{BUG}"
    assert s["differences"]["by_field"] and sum(s["differences"]["by_kind"].values()) == s["differences"]["total"]
    files = [c["file"] for c in s["differences"]["cases"]]
    assert all(Path(f).is_file() for f in files)
    suite = ET.parse(tmp_path / "j.xml").getroot().find("testsuite")
    failures = suite.findall("testcase/failure")
    # one planted bug, one group (its first divergence), one testcase, however many fields it spoils
    assert len(failures) == len(s["differences"]["groups"]) == len({c["group"] for c in s["differences"]["cases"]}) == 1
    assert s["differences"]["groups"][0]["group"] == "first divergence: Transition.cs:TransitionalInsert args"
    assert set(files) <= {f for fl in failures for f in fl.get("message").split(": ", 1)[1].split(", ")}


def test_a_planted_bug_is_found_and_shrunk_in_a_generative_campaign(tmp_path):
    impl = Implementation(planted(BUG))
    try:
        # seed 1 finds it in the 9th scene and shrinks it in 37 runs; seed 0 takes 183 and 397, to the same end
        r = run_campaign(impl, BuiltinPort(), kinds=("terrain",), n=400, seed=1, failures_dir=tmp_path, database=None)
    finally:
        impl.close()
    assert r.found and r.found[0].shrunk and r.found[0].path.is_file()
    assert r.found[0].case.differences
    c = Campaign("live", "exact", 1, ("terrain",), {"name": "planted", "version": "", "command": impl.command}, str(tmp_path))
    write_json(tmp_path / "s.json", summary(r, c))
    write_junit(tmp_path / "j.xml", junit(r, c))
    s = json.loads((tmp_path / "s.json").read_text())
    assert s["differences"]["cases"][0]["shrunk"] and s["differences"]["cases"][0]["file"] == str(r.found[0].path)
    assert str(r.found[0].path) in (tmp_path / "j.xml").read_text()


def test_a_shrink_budget_bounds_the_smaller_scenes_a_live_campaign_runs_and_keeps_the_smallest_failing_one(tmp_path):
    impl = Implementation(planted(BUG))
    try:
        r = run_campaign(impl, BuiltinPort(), kinds=("terrain",), n=400, seed=1, failures_dir=tmp_path, database=None,
                         shrink_budget=3)
        assert r.shrink_runs == 3 and len(r.found) == 1
        shrink = r.found[0].case.shrink
        assert shrink.bytes_after < shrink.bytes_before  # one of the three smaller scenes still failed
        case = r.found[0].case
        assert impl(case.scene) == case.port and BuiltinPort()(case.scene) == case.oracle  # the case as written replays
        r0 = run_campaign(impl, BuiltinPort(), kinds=("terrain",), n=400, seed=1, failures_dir=None, database=None,
                          shrink_budget=0)
        assert r0.shrink_runs == 0 and r0.found[0].case.shrink.bytes_after == shrink.bytes_before
    finally:
        impl.close()


def test_a_crash_is_a_verdict_and_the_process_is_restarted(corpus_scenes):
    impl = Implementation(planted("none", "--crash-on", "bsp"))
    try:
        crashed = impl(corpus_scenes["bsp"])
        assert crashed.error.startswith(f"{CRASH}: the process exited with code 3")
        after = impl(corpus_scenes["terrain"])
        assert after.error is None and impl.restarts == 1
        assert after == BuiltinPort()(corpus_scenes["terrain"])
    finally:
        impl.close()


def test_a_hang_past_the_time_limit_is_a_verdict_and_the_process_is_restarted(corpus_scenes):
    impl = Implementation(planted("none", "--hang-on", "obstacles"), timeout=1.0)
    try:
        hung = impl(corpus_scenes["obstacles"])
        assert hung.error.startswith(f"{TIMEOUT}: no answer within 1 s")
        assert impl(corpus_scenes["terrain"]).error is None and impl.restarts == 1
    finally:
        impl.close()


def test_a_malformed_answer_is_a_verdict_and_the_process_is_restarted(corpus_scenes):
    impl = Implementation(planted("none", "--garble-on", "terrain"))
    try:
        bad = impl(corpus_scenes["terrain"])
        assert bad.error.startswith(PROTOCOL_ERROR) and "this is not JSON" in bad.error
        assert impl(corpus_scenes["bsp"]).error is None and impl.restarts == 1
    finally:
        impl.close()


def test_crashes_and_hangs_in_a_campaign_come_out_as_differences_never_a_harness_crash(tmp_path, no_ace):
    """Shrinking included: a few smaller scenes each (--shrink-budget), every one that still crashes or
    hangs costing a restart (and the time limit)."""
    r = check("--impl", planted("none", "--crash-on", "bsp", "--hang-on", "obstacles"), "--timeout", "1",
              "-n", "6", "--seed", "3", "-j", "1", "--keep-going", "--shrink-budget", "5", "--failures", str(tmp_path / "f"),
              "--json", str(tmp_path / "s.json"), cwd=tmp_path)
    assert r.returncode == 1, r.stdout + r.stderr
    assert "Traceback" not in r.stderr
    cases = json.loads((tmp_path / "s.json").read_text())["differences"]["cases"]
    errors = [d for c in cases for d in c["differences"]]
    assert any(CRASH in d for d in errors) and any(TIMEOUT in d for d in errors)
    # (a scene slow past the time limit on a loaded machine is a timeout of its own kind, written unshrunk
    # as another kind's repeat, or not shrinkable: not every case says how many it tried)
    tried = [int(m[1]) for c in cases if (m := re.search(r"(\d+) smaller scenes tried", c["shrink_note"]))]
    assert tried and max(tried) <= 5, [c["shrink_note"] for c in cases]


def test_kinds_missing_from_the_handshake_are_skipped_and_do_not_count_toward_n(tmp_path, no_ace):
    r = check("--impl", planted("none", "--kinds", "terrain"), "-n", "30", "--seed", "1",
              "--failures", str(tmp_path / "f"), "--json", str(tmp_path / "s.json"), cwd=tmp_path)
    assert r.returncode == 0, r.stdout + r.stderr
    s = json.loads((tmp_path / "s.json").read_text())
    assert s["cases"]["compared"] == 30 and s["kinds_skipped"] == ["bsp", "obstacles", "indoor", "buildings"]
    assert s["cases"]["run"] == s["cases"]["compared"] + s["cases"]["skipped_total"]
    assert "skipping kinds bsp,obstacles,indoor,buildings" in r.stderr and "30 compared" in r.stdout


def test_tick_scenes_over_one_world_need_the_ticks_feature_and_that_world_in_the_handshake(tmp_path, no_ace):
    """--kinds ticks:buildings: an implementation without the kind buildings supports none of it; one with
    it gets past the gate, and then, ACE not configured, the replay says a corpus has no such shards."""
    r = check("--impl", planted("none", "--kinds", "terrain"), "--kinds", "ticks:buildings", "-n", "5", "--seed", "1",
              cwd=tmp_path)
    assert r.returncode == 2 and "supports none of the kinds asked for (ticks:buildings)" in r.stderr, r.stderr
    r = check("--impl", planted("none", "--kinds", "terrain,buildings"), "--kinds", "ticks:buildings", "-n", "5",
              "--seed", "1", cwd=tmp_path)
    assert r.returncode == 2 and "Traceback" not in r.stderr, r.stderr
    assert "--kinds ticks:buildings: draws tick scenes over one world in a live campaign" in r.stderr.splitlines()[-1]


def test_an_implementation_that_sends_no_handshake_is_one_line_and_exit_2(tmp_path, no_ace):
    r = check("--impl", f"{sys.executable} -c pass", "-n", "5", "--seed", "1", cwd=tmp_path)
    assert r.returncode == 2
    assert r.stderr.strip().splitlines()[-1].startswith("acconform check: error: implementation")
    assert "sent no handshake" in r.stderr and "Traceback" not in r.stderr
    with pytest.raises(ImplementationError, match="cannot start"):
        Implementation("/nonexistent/port --serve")


def test_bench_measures_an_implementation_in_both_modes(tmp_path):
    r = subprocess.run([sys.executable, "-m", "acconform.cli", "bench", "-n", "3", "--kinds", "terrain", "--impl",
                        planted("none"), "--json", str(tmp_path / "b.json")], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    doc = json.loads((tmp_path / "b.json").read_text())
    assert doc["implementation"] == planted("none") and doc["kinds"]["terrain"]["scenes"] == 3


def test_run_prints_one_scene_outcome_from_the_port_or_an_implementation(tmp_path):
    scene = ROOT / "examples" / "flat_walk.json"
    outs = []
    for extra in ([], ["--impl", planted("none")]):
        r = subprocess.run([sys.executable, "-m", "acconform.cli", "run", str(scene), *extra],
                           capture_output=True, text=True)
        assert r.returncode == 0, r.stderr
        outs.append(json.loads(r.stdout))
    from acconform.outcome import FORMAT_V2

    assert outs[0] == outs[1] and outs[0]["format"] == FORMAT_V2  # a scene without a placement: outcome/2


def test_a_scene_sent_ahead_of_a_crash_is_sent_again_to_the_restarted_process(corpus_scenes):
    impl = Implementation(planted("none", "--crash-on", "bsp"))
    try:
        impl.prefetch(corpus_scenes["bsp"])
        impl.prefetch(corpus_scenes["terrain"])  # in the pipe behind the scene that crashes the process
        assert impl(corpus_scenes["bsp"]).error.startswith(CRASH)
        assert impl(corpus_scenes["terrain"]) == BuiltinPort()(corpus_scenes["terrain"])
        assert impl.restarts == 1
    finally:
        impl.close()


def test_indoor_scenes_are_the_kind_indoor_and_statics_inside_env_cells_a_feature():
    from acconform.protocol import FEATURES, KINDS, handshake, scene_features
    from oracle.indoor_scenes import room_with_static, two_rooms

    assert "indoor" in KINDS and "indoor" in handshake()["kinds"] and "indoor.statics" in FEATURES
    assert scene_kind(two_rooms()) == scene_kind(room_with_static()) == "indoor"
    assert scene_features(two_rooms()) == [] and scene_features(room_with_static()) == ["indoor.statics"]
    from types import SimpleNamespace

    impl = SimpleNamespace(hello={"kinds": ["terrain", "indoor"], "features": []})  # what its handshake listed
    assert Implementation.unsupported(impl, two_rooms()) is None
    assert Implementation.unsupported(impl, room_with_static()) == "feature indoor.statics"
    impl.hello["kinds"] = ["terrain"]
    assert Implementation.unsupported(impl, two_rooms()) == "kind indoor"


@pytest.mark.parametrize("runtime", ["coreclr", "mono"])
def test_a_recorded_scene_sent_as_its_text_is_what_the_harness_writes_for_the_scene(runtime):
    """A replay through an implementation sends a record's scene text unread (RecordedText): the
    committed records hold their scenes exactly as the harness writes them, so an implementation
    receives the same request either way."""
    from acconform.codec import dumps_compact
    from acconform.oracle import default_corpus
    from acconform.oracle.recorded import RecordedOracle
    from acconform.scene import Scene

    oracle = RecordedOracle(default_corpus(runtime))
    by_shard: dict[str, list] = {}
    for e in oracle.entries:
        by_shard.setdefault(e.where.rsplit(" line ", 1)[0], []).append(e)
    assert len(by_shard) >= 20
    for entries in by_shard.values():
        for e in entries[:: max(1, len(entries) // 8)]:
            text = e.text()
            assert text is not None, e.where
            assert dumps_compact(Scene.from_json(json.loads(text.scene)).to_json()) == text.scene, e.where
            assert json.loads(text.outcome) == e.doc()["outcome"], e.where


# answers Outcome(ok=True) to every request; its first process (no file at sys.argv[2] yet) waits
# sys.argv[1] seconds before its first answer, reading nothing meanwhile
SLOW_FIRST = """
import json, os, sys, time
from acconform.codec import dumps_compact
from acconform.outcome import Outcome
from acconform.protocol import handshake
print(dumps_compact(handshake("slow-first", "1")), flush=True)
first = not os.path.exists(sys.argv[2])
open(sys.argv[2], "w").close()
for n, line in enumerate(sys.stdin):
    if n == 0 and first:
        time.sleep(float(sys.argv[1]))
    print(dumps_compact({"id": json.loads(line)["id"], "outcome": Outcome(ok=True).to_json()}), flush=True)
"""


def test_a_request_longer_than_the_pipe_sent_ahead_to_a_stalled_process_is_never_cut_off(tmp_path):
    """The harness sends the next scene while the process works on the one before. A scene longer
    than the pipe holds waits, whole, until the process reads it: when the process stalls past the
    time limit, the scene it stalled on is the timeout and the one behind it goes whole to the
    restarted process. (It was written in part and given up on, and the next request's text then
    followed the half-written one.)"""
    from acconform.case import jsonl_lines
    from acconform.oracle import default_corpus
    from acconform.outcome import Outcome
    from acconform.scene import Scene

    big = next(Scene.from_json(json.loads(line)["scene"]) for shard in sorted(default_corpus().glob("ticks-*.jsonl.gz"))
               for _, line in jsonl_lines(shard) if len(line) > 140_000)
    small = Scene.from_json(json.loads(next(jsonl_lines(default_corpus() / "terrain-0000.jsonl.gz"))[1])["scene"])
    impl = Implementation(f"{sys.executable} -c '{SLOW_FIRST}' 1.6 {tmp_path / 'started'}", timeout=1)
    try:
        impl.prefetch(small)
        impl.prefetch(big)  # more than the pipe takes, while the process sleeps on `small`
        assert impl(small).error.startswith(TIMEOUT)
        assert impl(big) == Outcome(ok=True)
        assert impl(small.replace(name="after the big one")) == Outcome(ok=True)
        assert impl.restarts == 1
    finally:
        impl.close()
