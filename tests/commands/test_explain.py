"""acconform explain, repro's first divergence, check's triage and report: a planted bug run as an
external implementation is named where it parts from the port, one bug is one group, and bad input
is one line and exit 2."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from acconform.case import ImplementationRun, write_document
from acconform.compare import compare
from acconform.protocol import Implementation
from acconform.runner import Found, make_case, signature

ROOT = Path(__file__).resolve().parents[2]
PLANTED = ROOT / "tests" / "impl" / "planted_impl.py"
BUG = "step_down_two_halves_made_thirds"
sys.path.insert(0, str(ROOT / "tests" / "runner"))


def cli(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "acconform.cli", *args], capture_output=True, text=True, cwd=cwd)


@pytest.fixture(scope="module")
def planted_cases(tmp_path_factory):
    folder = tmp_path_factory.mktemp("failures")
    command = f"{sys.executable} {PLANTED} {BUG}"
    hello = Implementation(command).hello
    cases = []
    from mutants import killing_records

    for i, (rec, got) in enumerate(killing_records(BUG, 2, branch="transitional_insert:step_down_halves")):
        diffs = compare(got, rec.outcome)
        case = make_case(rec.scene, got, rec.outcome, diffs, 0, "exact", rec.versions,
                         ImplementationRun(command, str(ROOT), hello))
        path = folder / f"case-{i:012d}.json"
        write_document(path, case)
        cases.append((path, case, diffs))
    assert len(cases) == 2
    return folder, cases


@pytest.mark.anchor("CTransition::transitional_insert")
def test_explain_names_the_planted_bugs_routine_field_values_and_ulps_after_checking_the_reference(planted_cases):
    _, cases = planted_cases
    r = cli("explain", str(cases[0][0]))
    assert r.returncode == 1, r.stderr
    out = r.stdout
    assert "reference: the port's trace (checked: the port's outcome for this case equals" in out
    assert "  in: Transition.cs:TransitionalInsert (retail CTransition::transitional_insert)" in out
    assert "  field: args[1]: port=" in out and "ulps apart" in out
    assert "enter of Transition.cs:StepDown" in out
    assert out.count(">") >= 2  # the diverging record marked on both sides


@pytest.mark.anchor("CTransition::transitional_insert")
def test_repro_puts_the_first_divergence_on_top(planted_cases):
    _, cases = planted_cases
    r = cli("repro", str(cases[0][0]))
    assert r.returncode == 1, r.stderr
    lines = r.stdout.splitlines()
    first = next(i for i, l in enumerate(lines) if l.startswith("first divergence:"))
    still = next(i for i, l in enumerate(lines) if l.startswith("still fails"))
    assert first < still and "Transition.cs:TransitionalInsert" in r.stdout


def test_one_planted_bug_is_one_group_however_many_differences(planted_cases):
    from acconform.explain import triage

    _, cases = planted_cases
    found = [Found(case, path, signature(diffs)) for path, case, diffs in cases]
    impl = Implementation(f"{sys.executable} {PLANTED} {BUG}", timeout=60)
    impl.runtime = "coreclr"
    try:
        triage(found, impl, "exact", "coreclr")
    finally:
        impl.close()
    assert {f.group for f in found} == {"first divergence: Transition.cs:TransitionalInsert args"}


def _terrain_scenes_across_landblocks(n):
    from acconform.oracle import default_corpus
    from acconform.oracle.recorded import RecordedOracle

    oracle = RecordedOracle(default_corpus("coreclr"))
    records = (oracle._record(e) for e in oracle.select(n=40, seed=3, runtime="coreclr", kinds=["terrain"]))
    return [r for r in records if len(r.scene.landblocks) > 1][:n]


@pytest.mark.anchor("LandDefs::get_block_offset")
def test_explain_names_no_divergence_for_an_implementation_that_agrees_after_it_ran_the_scene_untraced():
    # issue 43: an implementation that had remembered GetBlockOffset's answers wrote no inner call, and
    # explain named a divergence "before the steps" on a case whose outcome agrees
    from acconform.explain import explain_case
    from acconform.runner import guarded

    rec = _terrain_scenes_across_landblocks(1)[0]
    impl = Implementation(f"{sys.executable} {PLANTED} none", timeout=120)
    impl.runtime = "coreclr"
    try:
        assert not compare(guarded(impl, rec.scene), rec.outcome)  # an untraced run first, as check and repro do
        e = explain_case(rec, impl, "exact", "coreclr", rec.outcome)
    finally:
        impl.close()
    assert e.divergence is None and e.note == "the traces agree at the implementation's grain"


@pytest.mark.anchor("CTransition::cliff_slide")
def test_check_and_explain_name_the_same_first_divergence_whatever_the_implementation_ran_before(tmp_path):
    from acconform.explain import triage
    from acconform.runner import guarded
    from mutants import killing_records

    bug = "cliff_slide_sign_flipped"
    command = f"{sys.executable} {PLANTED} {bug}"
    (rec, got), = killing_records(bug, 1)
    diffs = compare(got, rec.outcome)
    case = make_case(rec.scene, got, rec.outcome, diffs, 0, "exact", rec.versions,
                     ImplementationRun(command, str(ROOT), Implementation(command).hello))
    path = tmp_path / "case-cliff.json"
    write_document(path, case)
    found = [Found(case, path, signature(diffs))]
    impl = Implementation(command, timeout=120)
    impl.runtime = "coreclr"
    try:  # check's implementation has run the campaign's scenes before it traces the difference
        for other in _terrain_scenes_across_landblocks(3) + [rec]:
            guarded(impl, other.scene)
        triage(found, impl, "exact", "coreclr")
    finally:
        impl.close()
    r = cli("explain", str(path), "--timeout", "120")  # a fresh process, a fresh implementation
    assert r.returncode == 1, r.stderr
    line = next(x for x in r.stdout.splitlines() if x.startswith("first divergence:"))
    assert found[0].group.startswith("first divergence: Transition.cs:CliffSlide")
    assert line.startswith(found[0].group + " (")


def test_report_indexes_a_failures_directory_by_first_divergence_with_a_page_per_case(planted_cases, tmp_path):
    folder, cases = planted_cases
    r = cli("report", str(folder), "--html", str(tmp_path / "index.html"))
    assert r.returncode == 0, r.stderr
    assert "(2 cases, 1 groups)" in r.stdout
    index = (tmp_path / "index.html").read_text()
    assert index.count('<section class="group">') == 1 and index.count('<li class="case">') == 2
    assert "first divergence: Transition.cs:TransitionalInsert args" in index
    for path, _, _ in cases:
        page = tmp_path / f"index-{path.stem}.html"
        assert f'href="{page.name}"' in index and "<svg" in page.read_text()


@pytest.mark.parametrize("args, message", [
    (("explain", "no-such-case.json"), "no such file"),
    (("explain", "examples/flat_walk.json"), "expected a case file"),
    (("report", "no-such-dir", "--html", "x.html"), "no such directory"),
    (("report", "examples", "--html", "x.html"), "holds no case files"),
])
def test_bad_input_to_explain_and_report_is_one_line_and_exit_2(args, message):
    r = cli(*args, cwd=ROOT)
    assert r.returncode == 2 and message in r.stderr and len(r.stderr.strip().splitlines()) == 1, r.stderr


def test_explain_html_to_a_missing_directory_is_one_line_and_exit_2_before_running(planted_cases):
    _, cases = planted_cases
    r = cli("explain", str(cases[0][0]), "--html", "/no/such/dir/page.html")
    assert r.returncode == 2 and "does not exist" in r.stderr and len(r.stderr.strip().splitlines()) == 1


@pytest.mark.anchor("CLandBlock::init_buildings")
def test_explain_html_draws_a_case_among_buildings_with_the_terrain_the_landblock_builds(tmp_path):
    """A landblock with buildings reads the scene's DATs as it is built: the page's terrain is built so."""
    import gzip
    import json

    from acconform.case import Record
    from acconform.oracle import default_corpus
    from acconform.runner import guarded
    from mutants import MUTATIONS, load_mutant

    name = "building_check_ignored"  # killed by buildings-0005 (test_mutations' KILLED_IN_SHARD)
    mutant = load_mutant([m.name for m in MUTATIONS].index(name))
    command = f"{sys.executable} {PLANTED} {name}"
    with gzip.open(default_corpus("coreclr") / "buildings-0005.jsonl.gz", "rt") as f:
        recs = [Record.from_json(json.loads(line)) for line in f]
    rec, got = next((r, g) for r in recs if compare(g := guarded(lambda s: mutant(s, runtime="coreclr"), r.scene), r.outcome))
    assert rec.scene.buildings
    case = make_case(rec.scene, got, rec.outcome, compare(got, rec.outcome), 0, "exact", rec.versions,
                     ImplementationRun(command, str(ROOT), Implementation(command).hello))
    write_document(tmp_path / "case.json", case)
    r = cli("explain", str(tmp_path / "case.json"), "--html", str(tmp_path / "page.html"))
    assert r.returncode == 1 and "Traceback" not in r.stderr, r.stderr
    page = (tmp_path / "page.html").read_text()
    assert page.count('class="terrain"') > 2  # the two views' groups, and triangles in them
