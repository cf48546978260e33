"""Verdicts a porter can act on, and long runs that say what they are doing (issue 23).

A case names the implementation that made it and keeps its stderr; `repro` replays on it (or
gives no verdict); replayed differences are shrunk against the built-in port standing in for
ACE, and say so; every scene is counted once; the console summarises by field and kind;
in-process runs have a time limit per scene; progress lines come with an ETA, also when piped;
the corpus loads without parsing a scene.
"""

from __future__ import annotations

import dataclasses
import io
import json
import subprocess
import sys
import time
import warnings
from collections import Counter
from functools import partial
from pathlib import Path

import pytest

from acconform.case import STDERR_LIMIT, Case, Shrink, Versions, load_document
from acconform.compare import compare
from acconform.impl import BuiltinPort
from acconform.outcome import Outcome
from acconform.protocol import CRASH, Implementation
from acconform.runner import Found, Progress, Result, make_case, run_campaign, signature
from acconform.strategies import sample_scenes
from test_runner import buggy_when_long, fake_port

warnings.simplefilter("ignore", RuntimeWarning)

ROOT = Path(__file__).resolve().parents[2]
PLANTED = ROOT / "tests" / "impl" / "planted_impl.py"
BUG = "step_down_two_halves_made_thirds"  # tests/runner/mutants.py


def cli(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "acconform.cli", *args], capture_output=True, text=True,
                          cwd=cwd or ROOT)


@pytest.fixture(scope="module")
def corpus():
    from acconform.oracle import default_corpus
    from acconform.oracle.recorded import RecordedOracle

    return RecordedOracle(default_corpus())


@pytest.fixture(scope="module")
def mutant():
    from mutants import MUTATIONS, load_mutant

    return partial(load_mutant([m.name for m in MUTATIONS].index(BUG)), runtime="coreclr")


# ---------------------------------------------------------------- the implementation, in the case


def test_a_case_made_by_an_implementation_names_it_and_repro_replays_on_it(corpus, tmp_path, no_ace):
    command = f"{sys.executable} {PLANTED} {BUG}"
    impl = Implementation(command)
    impl.runtime = "coreclr"  # as the corpus's ACE (check sets it so)
    try:
        r = run_campaign(impl, corpus.run, replay=corpus.scenes(corpus.select(n=300, seed=1)), failures_dir=tmp_path,
                         stand_in=BuiltinPort("exact", "coreclr"))
    finally:
        impl.close()
    path = r.found[0].path
    case = load_document(path)
    assert case.implementation.command == command and case.implementation.handshake["name"] == "planted"
    assert case.implementation.cwd and json.loads(path.read_text())["format"] == "acconform.case/3"
    out = cli("repro", str(path))
    assert out.returncode == 1, out.stdout + out.stderr
    assert f"replaying on the implementation the case names: {command!r}" in out.stdout
    assert "implementation 'planted'" in out.stdout and "still fails" in out.stdout
    # --impl replays on another, and says the case was made by a different one
    out = cli("repro", str(path), "--impl", f"{sys.executable} -m acconform.cli serve")
    assert out.returncode == 0 and "the case was made by implementation 'planted'" in out.stdout


def test_a_case_1_file_replays_on_the_port_saying_it_cannot_know_which_implementation_made_it(tmp_path, no_ace):
    scene = next(iter(sample_scenes(("terrain",), 1, 2)))
    answer = BuiltinPort()(scene)  # mono's arithmetic, as the case's versions say
    doc = Case(scene, dataclasses.replace(answer, ok=not answer.ok), answer, ("ok: differs",),
               versions=Versions("0.1.0", "test", "mono 6.8.0.105")).to_json()
    doc["format"] = "acconform.case/1"
    doc["port"] = doc.pop("impl")  # before case/3 the tested side's outcome was "port"
    del doc["shrunk"]
    (tmp_path / "old.json").write_text(json.dumps(doc))
    out = cli("repro", str(tmp_path / "old.json"))
    assert out.returncode == 0 and "does not say which implementation made it" in out.stdout


CRASHER = r'''
import json, sys
print(json.dumps({"protocol": "acconform.protocol/1", "name": "crasher", "version": "1", "kinds": ["terrain", "bsp",
      "obstacles", "indoor"], "features": [], "modes": ["exact"]}), flush=True)
sys.stdin.readline()
sys.stderr.write("crasher v1 starting\n" + "x" * int(sys.argv[1]) + "\nError: boom in step_down\n"
                 "    at stepDown (port.js:12:3)\nNode.js v20.11.0\n")
sys.exit(1)
'''


@pytest.mark.parametrize("filler", [0, 200_000])
def test_a_crashing_implementation_s_whole_stderr_is_kept_in_the_case_up_to_a_bound(tmp_path, filler):
    script = tmp_path / "crasher.py"
    script.write_text(CRASHER)
    impl = Implementation(f"{sys.executable} {script} {filler}")
    scene = next(s for s in sample_scenes(("terrain",), 20, 4) if len(s.mover.spheres) == 1)  # no features asked
    try:
        r = run_campaign(impl, fake_port, replay=[scene], failures_dir=tmp_path / "f")
    finally:
        impl.close()
    case = load_document(r.found[0].path)
    assert case.port.error.startswith(CRASH) and "Error: boom in step_down" in case.port.error  # the error line, not the banner
    kept = case.implementation.stderr
    assert kept.startswith("crasher v1 starting\n") and kept.rstrip().endswith("Node.js v20.11.0")
    assert "at stepDown (port.js:12:3)" in kept
    if filler:
        assert len(kept) < STDERR_LIMIT + 200 and "characters left out" in kept
    else:
        assert "left out" not in kept


# ---------------------------------------------------------------- shrinking without ACE


def test_replayed_differences_are_shrunk_against_the_port_when_it_agrees_with_the_recorded_answer(corpus, mutant,
                                                                                                   tmp_path):
    port = BuiltinPort("exact", "coreclr")
    r = run_campaign(mutant, corpus.run, replay=corpus.scenes(corpus.select(n=300, seed=1)), failures_dir=tmp_path,
                     keep_going=True, stand_in=port)
    kinds = Counter(f.signature for f in r.found)
    assert r.found and r.shrink_runs > 0
    shrunk = [f for f in r.found if f.case.shrink.against == "port"]
    assert len(shrunk) == len(kinds)  # the first of each kind of difference
    assert any(f.case.shrink.bytes_after < f.case.shrink.bytes_before for f in shrunk)
    for f in shrunk:  # still the same kind of difference, and the oracle side is the port's answer
        assert signature(compare(mutant(f.case.scene), port(f.case.scene), "exact")) == f.signature
        assert f.case.oracle == port(f.case.scene)
    rest = [f for f in r.found if f not in shrunk]
    assert all(f.case.shrink.against == "none" and "the first case of this kind" in f.case.shrink.note for f in rest)
    assert load_document(shrunk[0].path).shrink == shrunk[0].case.shrink


def test_a_replayed_difference_is_written_as_recorded_when_the_port_disagrees_with_the_recorded_answer(tmp_path):
    scenes = list(sample_scenes(("terrain",), 3, 5))
    port = BuiltinPort()

    def recorded(scene):  # an "ACE" the port does not reproduce
        return dataclasses.replace(port(scene), ok=not port(scene).ok)

    r = run_campaign(port, recorded, replay=scenes, failures_dir=tmp_path, stand_in=port)
    (f,) = r.found
    assert f.case.shrink.against == "none" and "the built-in port differs from ACE's recorded answer" in f.case.shrink.note
    assert f.case.scene == scenes[0]


def test_the_built_in_port_replays_recorded_text_and_reads_only_an_answer_that_differs(tmp_path):
    """Exact mode: a record whose answer, written as the corpus writes it, is the recorded text
    agrees unread (run_text answers None); one whose recorded outcome was altered is read,
    compared and written as a case holding the recorded outcome. Fast mode reads every answer."""
    import gzip

    from acconform.oracle import default_corpus
    from acconform.oracle.recorded import RecordedOracle

    shard = default_corpus("coreclr") / "terrain-0000.jsonl.gz"
    with gzip.open(shard, "rt", encoding="utf-8") as f:
        lines = [next(f) for _ in range(6)]
    altered = lines[3].replace('"ok":true', '"ok":false', 1) if '"ok":true' in lines[3] \
        else lines[3].replace('"ok":false', '"ok":true', 1)
    assert altered != lines[3]
    corpus_dir = tmp_path / "corpus"
    corpus_dir.mkdir()
    with gzip.open(corpus_dir / "terrain-0000.jsonl.gz", "wt", encoding="utf-8") as f:
        f.writelines(lines[:3] + [altered] + lines[4:])
    corpus = RecordedOracle(corpus_dir)
    port = BuiltinPort("exact", "coreclr")
    assert port.runs_every_scene and not BuiltinPort("fast", "coreclr").runs_every_scene
    answers = [port.run_text(e.text()) for e in corpus.entries]
    assert [a is None for a in answers] == [True, True, True, False, True, True]
    r = run_campaign(port, corpus.run, replay=corpus.scenes(), failures_dir=tmp_path / "f", keep_going=True)
    (f,) = r.found
    assert r.cases == 6 and f.signature == ("ok",)
    assert f.case.oracle == Outcome.from_json(json.loads(altered)["outcome"]) and f.case.port == answers[3]


# ---------------------------------------------------------------- counting, each once


def test_n_counts_the_scenes_compared_and_shrinking_is_counted_apart(tmp_path):
    r = run_campaign(buggy_when_long, fake_port, n=60, seed=3, failures_dir=None, database=None, keep_going=True)
    assert r.found and r.shrink_runs > 0
    assert r.compared == 60 and r.cases == 60 and not r.skipped


class TwoSpheresUnsupported:
    """A port whose handshake leaves out two-sphere movers."""

    def __call__(self, scene):
        return fake_port(scene)

    def unsupported(self, scene):
        return "feature mover.two_spheres" if len(scene.mover.spheres) == 2 else None


def test_scenes_the_implementation_cannot_run_do_not_count_toward_n():
    r = run_campaign(TwoSpheresUnsupported(), fake_port, n=50, seed=1, failures_dir=None, database=None)
    assert r.compared == 50 and r.skipped["feature mover.two_spheres"] > 0
    assert r.cases == r.compared + sum(r.skipped.values())


def test_a_corpus_sample_passes_over_scenes_the_implementation_cannot_run(corpus):
    skipped: Counter = Counter()
    picked = corpus.select(n=40, seed=2, unsupported=TwoSpheresUnsupported().unsupported, skipped=skipped)
    assert len(picked) == 40 and skipped["feature mover.two_spheres"] > 0
    assert all(len(s.mover.spheres) == 1 for s in corpus.scenes(picked))


def test_workers_report_each_kind_of_difference_once(tmp_path):
    r = run_campaign(buggy_when_long, fake_port, n=200, seed=4, failures_dir=tmp_path, database=tmp_path / "db",
                     workers=2, keep_going=True)
    assert r.found
    assert len({f.signature for f in r.found}) == len(r.found) == len({f.path for f in r.found})
    assert len(list(tmp_path.glob("case-*.json"))) == len(r.found)


def test_the_console_summary_counts_differences_by_field_and_by_kind():
    from acconform.commands.check import console_summary

    scenes = list(sample_scenes(("terrain",), 2, 1)) + list(sample_scenes(("bsp",), 1, 1))
    found = []
    for s, fields in zip(scenes, [("walkable",), ("walkable",), ("cell", "walkable")]):
        a = dataclasses.replace(fake_port(s), walkable=not fake_port(s).walkable,
                                cell=fake_port(s).cell + (1 if "cell" in fields else 0))
        diffs = compare(a, fake_port(s), "exact")
        found.append(Found(make_case(s, a, fake_port(s), diffs, 0, "exact", None, shrink=Shrink()), Path("c.json"),
                           signature(diffs)))
    r = Result(cases=12, found=found, elapsed=1.0, skipped=Counter({"kind indoor": 2}), shrink_runs=7)
    lines = console_summary(r, [], keep_going=True)
    assert lines[0] == "12 cases in 1.0 s (12 cases/s): 10 compared, 2 skipped, 3 differences"
    assert "shrinking ran 7 more scenes (not counted above)" in lines
    assert "differences by field: walkable x3, cell x1" in lines
    assert "differences by kind:  terrain x2, bsp x1" in lines
    assert "3 differences, 2 distinct sets of differing fields (the implementation gives no trace)" in lines
    assert "  differs in walkable" in lines and "  differs in cell, walkable" in lines
    assert any("+ 1 more case in this group" in l for l in lines)


def test_the_console_summary_groups_differences_by_their_first_divergence_and_labels_a_known_one():
    from acconform.commands.check import console_summary

    scenes = list(sample_scenes(("terrain",), 3, 1))
    found = []
    for s, group, known in zip(scenes, ("Transition.cs:StepDown path.check_pos", "Transition.cs:StepDown path.check_pos",
                                        "PhysicsObj.cs:calc_friction mover.velocity"), ("", "", "sledding_threshold")):
        a = dataclasses.replace(fake_port(s), walkable=not fake_port(s).walkable)
        diffs = compare(a, fake_port(s), "exact")
        found.append(Found(make_case(s, a, fake_port(s), diffs, 0, "exact", None, shrink=Shrink()), Path("c.json"),
                           signature(diffs), "first divergence: " + group, known))
    lines = console_summary(Result(cases=3, found=found, elapsed=1.0), [], keep_going=True)
    assert "3 differences, 2 distinct first divergences" in lines
    assert "  first divergence: Transition.cs:StepDown path.check_pos" in lines
    assert ("  first divergence: PhysicsObj.cs:calc_friction mover.velocity -- known: ACE differs from retail here "
            "(sledding_threshold)") in lines


# ---------------------------------------------------------------- time limits and progress


def _slow_when_named(scene):
    if scene.name.startswith("slow"):
        time.sleep(30)
    return fake_port(scene)


def test_a_scene_past_the_time_limit_is_a_verdict_and_the_next_scene_runs():
    from acconform.commands.stress import stress
    from acconform.timed import SCENE_TIMEOUT, TimedBackend

    fast, slow = [s.replace(name=n) for s, n in zip(sample_scenes(("terrain",), 2, 6), ("quick", "slow"))]
    port = TimedBackend(lambda: _slow_when_named, 1.0, "port")
    try:
        t0 = time.monotonic()
        late = port(slow)
        assert late.error.startswith(SCENE_TIMEOUT) and time.monotonic() - t0 < 10 and port.timeouts == 1
        assert port(fast) == fake_port(fast)
        stats = stress([slow], ["nudge_end"], port, fake_port, fake_port, k=1)["nudge_end"]
    finally:
        port.close()
    assert stats.timed_out == {"port exact": stats.scenes} and stats.diff_exact == 0 and stats.pairs == 0


def test_piped_progress_writes_a_line_every_few_seconds_with_an_eta(monkeypatch):
    import acconform.runner as runner

    now = [1000.0]
    monkeypatch.setattr(runner.time, "monotonic", lambda: now[0])
    out = io.StringIO()
    bar = Progress(100, True, stream=out)
    for done in range(1, 101):
        now[0] += 0.5  # a case every half second: 50 s in all
        bar.update(done, 0)
    bar.close(100, 0)
    lines = out.getvalue().splitlines()
    assert 9 <= len(lines) <= 12  # every PIPE_EVERY (5) seconds, and the last
    assert "10/100 cases" in lines[0] and "ETA 45 s" in lines[0]
    assert lines[-1].startswith("[##############################] 100/100 cases") and "took 50 s" in lines[-1]


def test_bench_shows_progress_with_an_eta_on_stderr(no_ace):
    out = cli("bench", "-n", "2", "--kinds", "terrain")
    assert out.returncode == 0, out.stderr
    assert "acconform bench: reading 2 scenes per kind" in out.stderr
    assert "acconform bench: measuring [" in out.stderr and "took" in out.stderr


# ---------------------------------------------------------------- the corpus loads without parsing


def test_the_corpus_loads_without_parsing_a_scene_and_a_replay_parses_only_what_it_runs(monkeypatch):
    from acconform.case import Record
    from acconform.oracle import default_corpus
    from acconform.oracle.recorded import RecordedOracle
    from acconform.scene import Scene

    parsed = [0]
    from_json = Scene.from_json

    def counting(doc, path=""):
        parsed[0] += 1
        return from_json(doc, path)

    monkeypatch.setattr(Scene, "from_json", staticmethod(counting))
    oracle = RecordedOracle(default_corpus())
    assert len(oracle) > 20_000 and parsed[0] == 0 and oracle._index is None
    picked = oracle.select(n=5, seed=1)
    scenes = oracle.scenes(picked)
    assert len(scenes) == 5 and parsed[0] == 0
    scene = scenes[3]
    assert parsed[0] == 1
    assert oracle.run(scene) == Record.from_json(picked[3].doc()).outcome
    assert oracle._index is None  # answered from the record it came from, no key index built
