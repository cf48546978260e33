"""Rough edges a porter met on the first day (issue 42): what check, repro, show, stress, bench and
the shrinking print, each said once, named one way, and never a stress bug passing as a clean run."""

from __future__ import annotations

import dataclasses
import gzip
import io
import json
import subprocess
import sys
from pathlib import Path

import pytest

from acconform.case import CASE_FORMAT, Case, ImplementationRun, Versions, parse_document
from acconform.compare import Difference, compare
from acconform.impl import BuiltinPort
from acconform.oracle import default_corpus
from acconform.oracle.recorded import shards
from acconform.outcome import Outcome, TickState
from acconform.protocol import CRASH, KINDS
from acconform.runner import Found, Result, Status, make_case, run_campaign
from acconform.strategies import check_kinds, sample_scenes

ROOT = Path(__file__).resolve().parents[2]
SERVE = f"{sys.executable} -m acconform.cli serve"


def cli(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "acconform.cli", *args], capture_output=True, text=True,
                          cwd=cwd or ROOT)


@pytest.fixture(scope="module")
def scene():
    return next(s for s in sample_scenes(("terrain",), 10, 2) if s.mover.end.cell != s.mover.begin.cell)


# ---------------------------------------------------------------- 4: loading the corpus is one line


@pytest.fixture
def two_shard_corpus(tmp_path):
    d = tmp_path / "corpus"
    d.mkdir()
    for prefix in ("terrain", "bsp"):
        shard = next(s for s in shards(default_corpus()) if s.name.startswith(prefix))
        with gzip.open(shard, "rt") as f, gzip.open(d / f"{prefix}-0000.jsonl.gz", "wt") as out:
            out.writelines(line for _, line in zip(range(10), f))
    return d


def test_check_says_in_one_line_what_it_read_of_the_corpus_when_piped(two_shard_corpus, tmp_path, no_ace):
    r = cli("check", "--corpus", str(two_shard_corpus), "-n", "4", "-j", "1", "--failures", str(tmp_path / "f"))
    assert r.returncode == 0, r.stderr
    said = [line for line in r.stderr.splitlines() if "recorded corpus:" in line]
    assert said == [f"acconform check: recorded corpus: 20 records from 2 shards of {two_shard_corpus} read in "
                    + said[0].rsplit(" in ", 1)[1]] and said[0].endswith(" s")
    assert "loading" not in r.stderr


class _Terminal(io.StringIO):
    def isatty(self):
        return True


def test_the_loading_line_is_redrawn_in_place_on_a_terminal_and_ends_in_its_summary():
    out = _Terminal()
    status = Status(True, out, prefix="recorded corpus: ")
    for i in range(61):
        status.say(f"loading shard {i}")
    status.done("30004 records from 61 shards read in 1.5 s")
    text = out.getvalue()
    assert text.count("\n") == 1 and text.endswith("\rrecorded corpus: 30004 records from 61 shards read in 1.5 s\033[K\n")
    assert text.startswith("\rrecorded corpus: loading shard 0\033[K")  # each redraw returns to the line's start


def test_no_progress_says_nothing_of_the_loading():
    out = _Terminal()
    status = Status(False, out)
    status.say("loading")
    status.done("read")
    assert out.getvalue() == ""


# ---------------------------------------------------------------- 5: an implementation's values are impl=


def test_an_implementation_s_values_are_labelled_impl_and_the_built_in_port_s_port(scene):
    a, b = Outcome(ok=True), Outcome(ok=False)
    diffs = compare(a, b)
    made = ImplementationRun("./my-port", "/tmp", {"name": "mine"})
    assert make_case(scene, a, b, diffs, 0, "exact", Versions(), made).differences == ("ok: impl=True oracle=False",)
    assert make_case(scene, a, b, diffs, 0, "exact", Versions()).differences == ("ok: port=True oracle=False",)


def test_check_s_summary_and_junit_list_an_implementation_s_values_as_impl(scene):
    from acconform.commands.check import console_summary
    from acconform.report import Campaign, junit

    a, b = Outcome(ok=True), Outcome(ok=False)
    case = make_case(scene, a, b, compare(a, b), 0, "exact", Versions(), ImplementationRun("./my-port"))
    result = Result(cases=1, found=[Found(case, Path("case.json"), ("ok",))])
    assert "      ok: impl=True oracle=False" in console_summary(result, [], keep_going=False)
    campaign = Campaign("recorded", "exact", None, ("terrain",), {"name": "mine"}, "failures")
    assert "  ok: impl=True oracle=False" in junit(result, campaign).find("testsuite/testcase/failure").text


def test_a_case_file_keeps_the_tested_side_under_impl_and_a_case_2_file_still_reads(scene):
    case = Case(scene, Outcome(ok=True), Outcome(ok=False), ("ok: port=True oracle=False",))
    doc = case.to_json()
    assert doc["format"] == CASE_FORMAT == "acconform.case/3" and "port" not in doc and doc["impl"]["ok"] is True
    assert parse_document(doc) == case
    old = dict(doc, format="acconform.case/2")
    old["port"] = old.pop("impl")
    read = parse_document(old)
    assert read.port == case.port and read.format == "acconform.case/2"
    doc["port"] = doc["impl"]  # a case/3 file with the old key too is refused, naming it
    with pytest.raises(Exception, match="port"):
        parse_document(doc)


def test_repro_and_show_label_an_implementation_s_values_impl(scene, tmp_path, no_ace):
    answer = BuiltinPort("exact", "coreclr")(scene)
    ace = dataclasses.replace(answer, ok=not answer.ok)
    made = ImplementationRun(SERVE, str(ROOT), {"name": "acconform"})
    case = make_case(scene, answer, ace, compare(answer, ace), 0, "exact", Versions("0", "ace", "coreclr 10.0.0"), made)
    path = tmp_path / "case.json"
    path.write_text(json.dumps(case.to_json()))
    r = cli("repro", str(path))
    assert r.returncode == 1, r.stdout + r.stderr
    listed = r.stdout.split("still fails: 1 field differ\n", 1)[1]
    assert listed == f"  ok: impl={answer.ok} oracle={ace.ok}\n"
    # "port" still means the built-in port: the reference the explanation on top checks against ACE
    assert f"differs from the oracle outcome recorded in the case (no ACE configured) (ok: port={answer.ok} " in r.stdout
    shown = cli("show", str(path)).stdout
    assert f"ok: impl={answer.ok}" in shown and "\nimpl:" in shown and "\nport:" not in shown


# ---------------------------------------------------------------- 6: a verdict first, and alone


def test_a_crash_verdict_is_the_one_difference_not_listed_after_the_fields_it_left_at_zero(scene):
    ace = BuiltinPort("exact", "coreclr")(scene)
    crash = Outcome(error=f"{CRASH}: the implementation exited with code 1")
    assert compare(crash, ace) == [Difference("error", crash.error, None)]
    assert compare(ace, crash, "fast") == [Difference("error", None, crash.error)]
    case = make_case(scene, crash, ace, compare(crash, ace), 0, "exact", Versions(), ImplementationRun("./p"))
    assert case.differences == (f"error: impl={crash.error!r} oracle=None",)


def test_two_errors_of_different_types_list_the_error_first():
    a = Outcome(ok=True, error="NullReferenceException: x")
    b = Outcome(error="InvalidOperationException: y")
    assert [d.field for d in compare(a, b)] == ["error", "ok"]


def test_a_tick_that_raised_on_one_side_only_is_its_error_and_nothing_after_it():
    ran = Outcome(ticks=(TickState(updated=True), TickState(updated=True, cell=5), TickState(updated=True)))
    raised = Outcome(ticks=(TickState(updated=True), TickState(error="NullReferenceException: boom")))
    assert [d.field for d in compare(ran, raised)] == ["ticks[1].error"]


# ---------------------------------------------------------------- 8: one naming of a scene's kind


def test_the_case_line_names_the_kind_that_differences_by_kind_counts(scene):
    from acconform.commands.check import console_summary

    named = dataclasses.replace(scene, name="obstacles:ground:feature", objects=())  # shrinking took its obstacles
    case = make_case(named, Outcome(ok=True), Outcome(), compare(Outcome(ok=True), Outcome()), 0, "exact", Versions())
    found = Found(case, Path("failures/case-x.json"), ("ok",))
    lines = console_summary(Result(cases=1, found=[found]), [], keep_going=False)
    assert "differences by kind:  terrain x1" in lines
    assert "    failures/case-x.json (not shrunk; kind terrain, scene 'obstacles:ground:feature')" in lines


# ---------------------------------------------------------------- shrinking says what it does


def fake_port(scene):
    """A cheap deterministic backend (as tests/runner/test_runner.py's)."""
    end = scene.mover.end or scene.mover.begin
    return Outcome(ok=True, cell=end.cell, origin=end.frame.origin)


def buggy_when_long(scene):
    """Wrong whenever the path leaves its start cell: a difference that shrinks."""
    o = fake_port(scene)
    return dataclasses.replace(o, ok=False) if (scene.mover.end or scene.mover.begin).cell != scene.mover.begin.cell else o


def test_shrinking_a_replayed_difference_says_on_stderr_what_it_runs(scene, capsys):
    r = run_campaign(buggy_when_long, fake_port, replay=[scene], failures_dir=None, stand_in=fake_port,
                     shrink_budget=40, progress=True)
    assert r.found and r.shrink_runs > 1
    err = capsys.readouterr().err
    assert "shrinking a difference against the built-in port standing in for ACE: 1 of up to 40 smaller scenes run" in err


def test_shrinking_a_drawn_difference_says_on_stderr_what_it_runs(capsys):
    r = run_campaign(buggy_when_long, fake_port, n=300, seed=2, failures_dir=None, database=None, progress=True)
    assert r.found and r.shrink_runs > 1
    assert "shrinking a difference against live ACE: 1 smaller scene run" in capsys.readouterr().err


def test_no_progress_says_nothing_while_shrinking(scene, capsys):
    run_campaign(buggy_when_long, fake_port, replay=[scene], failures_dir=None, stand_in=fake_port, shrink_budget=5)
    assert "shrinking" not in capsys.readouterr().err


# ---------------------------------------------------------------- 9: stress derives valid scenes, or fails


def test_stress_moves_a_building_with_its_landblock_to_the_world_s_edge():
    from acconform.commands.stress import derive
    from acconform.scene import validate_scene

    base = next(iter(sample_scenes(("buildings",), 1, 0)))
    derived = [s for v, twin in derive("world_edge", base, 2) for s in (v, twin) if s is not None]
    assert derived
    for s in derived:
        validate_scene(s)
        assert {b.landblock for b in s.buildings} <= {lb.id for lb in s.landblocks}


def test_stress_fails_naming_a_derived_scene_that_does_not_validate(monkeypatch, capsys, tmp_path, no_ace):
    from acconform.cli import main
    from acconform.commands import stress

    def broken(kind, scene, k=2):  # a derivation that forgets to move the landblocks with the mover
        return [(dataclasses.replace(scene, landblocks=(), name="broken"), None)]

    monkeypatch.setattr(stress, "derive", broken)
    code = main(["stress", "-n", "1", "--kinds", "terrain", "--only", "tiny_sphere", "--failures", str(tmp_path)])
    out = capsys.readouterr().out
    assert code == 1
    assert out.rstrip().splitlines()[-1].startswith("error: 1 derived scene did not validate (a bug in stress, not in "
                                                    "the port; not run); first: terrain tiny_sphere: broken")


# ---------------------------------------------------------------- 10: help from the constants the code runs


def test_bench_check_and_coverage_help_name_the_kinds_they_run_by_default():
    from acconform.cli import build_parser

    parser = build_parser()
    sub = next(a for a in parser._actions if a.dest == "command").choices
    default = ",".join(check_kinds(None))  # what bench, check and coverage run without --kinds
    for command in ("bench", "check", "coverage"):
        kinds = next(a for a in sub[command]._actions if a.dest == "kinds")
        assert f"default: all, {default}" in kinds.help, command
    stress = next(a for a in sub["stress"]._actions if a.dest == "kinds")
    assert f"every world kind, {','.join(KINDS)};" in stress.help


def test_stress_runs_the_world_kinds_its_help_names(monkeypatch, no_ace):
    from acconform.cli import main
    from acconform.commands import stress

    seen = []
    monkeypatch.setattr(stress, "_run", lambda args, kinds, *rest: seen.append(kinds) or 0)
    assert main(["stress", "-n", "1"]) == 0
    assert seen == [KINDS]


def test_the_readme_does_not_count_the_world_kinds_stress_takes():
    readme = (ROOT / "README.md").read_text()
    assert "four world kinds" not in readme and "stress` takes the world kinds only, every kind but `ticks`" in readme
