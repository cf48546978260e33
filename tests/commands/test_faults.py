"""Faults and bad input as a new user meets them: each one clear line and exit 2, losing nothing."""

from __future__ import annotations

import gzip
import json
import os
import shutil
import signal
import subprocess
import sys
import time
from collections import Counter
from pathlib import Path

import pytest

from acconform.oracle import default_corpus
from acconform.oracle.recorded import RecordedOracle, shards

ROOT = Path(__file__).resolve().parents[2]


def cli(*args, cwd=None, **kw):
    return subprocess.run([sys.executable, "-m", "acconform.cli", *args], capture_output=True, text=True,
                          cwd=cwd or ROOT, **kw)


def one_line_exit_2(r, *words):
    assert r.returncode == 2, r.stdout + r.stderr
    assert "Traceback" not in r.stderr
    last = r.stderr.strip().splitlines()[-1]
    for w in words:
        assert w in last, last
    return last


@pytest.fixture
def small_corpus(tmp_path):
    """Two shards: 40 good terrain records, and a bsp shard whose 3rd line is broken."""
    d = tmp_path / "corpus"
    d.mkdir()
    terrain = [line for _, line in zip(range(40), gzip.open(next(s for s in shards(default_corpus()) if s.name.startswith("terrain")), "rt"))]
    with gzip.open(d / "terrain-0000.jsonl.gz", "wt") as f:
        f.writelines(terrain)
    bsp = [line for _, line in zip(range(5), gzip.open(shards(default_corpus())[0], "rt"))]
    bsp[2] = '{"format": "acconform.record/1", "scene": \n'
    with gzip.open(d / "bsp-0000.jsonl.gz", "wt") as f:
        f.writelines(bsp)
    return d


def test_a_bad_json_line_in_a_shard_names_shard_and_line_and_keep_going_skips_and_counts_it(small_corpus, tmp_path, no_ace):
    r = cli("check", "--corpus", str(small_corpus), "--no-progress", "--failures", str(tmp_path / "f"))
    last = one_line_exit_2(r, "bsp-0000.jsonl.gz line 3", "not JSON")
    assert "no ACE assembly" not in last
    r = cli("check", "--corpus", str(small_corpus), "--no-progress", "--keep-going", "--failures", str(tmp_path / "f"))
    assert r.returncode == 0, r.stderr
    assert "44 cases" in r.stdout and "skipped 1 unreadable corpus record" in r.stdout and "line 3" in r.stdout


def test_a_truncated_shard_is_named_with_the_last_line_read(small_corpus, tmp_path, no_ace):
    (small_corpus / "bsp-0000.jsonl.gz").unlink()
    shard = small_corpus / "terrain-0000.jsonl.gz"
    shard.write_bytes(shard.read_bytes()[: shard.stat().st_size // 2])
    r = cli("check", "--corpus", str(small_corpus), "--no-progress", "--failures", str(tmp_path / "f"))
    one_line_exit_2(r, "terrain-0000.jsonl.gz", "truncated after line")
    r = cli("validate", str(shard))
    one_line_exit_2(r, "terrain-0000.jsonl.gz", "truncated")


def test_validate_and_show_read_corpus_shards():
    shard = shards(default_corpus())[0]
    r = cli("validate", str(shard))
    assert r.returncode == 0 and r.stdout.startswith(f"ok {shard}: ") and "records" in r.stdout
    r = cli("show", str(shard))
    assert r.returncode == 0 and f"# {shard} line 2" in r.stdout and "ACE:" in r.stdout


def test_show_into_a_closed_pipe_stops_quietly():
    shard = shards(default_corpus())[0]
    p = subprocess.run(f"{sys.executable} -m acconform.cli show {shard} | head -1", shell=True, capture_output=True,
                       text=True, cwd=ROOT)
    assert p.stdout.startswith("# ") and p.stderr == ""


def test_an_unwritable_failures_directory_is_refused_before_the_campaign(tmp_path, no_ace):
    blocker = tmp_path / "file"
    blocker.write_text("")
    r = cli("check", "-n", "5", "--seed", "1", "--no-progress", "--failures", str(blocker / "sub"))
    one_line_exit_2(r, "--failures", "cannot write there")
    assert "cases in" not in r.stdout


def test_a_case_that_cannot_be_written_where_asked_goes_to_a_temporary_directory(tmp_path):
    from acconform.outcome import Outcome
    from acconform.runner import Result, save_cases
    from acconform.strategies import sample_scenes
    from acconform.runner import Found, make_case
    from acconform.case import Versions

    scene = next(iter(sample_scenes(("terrain",), 1, 0)))
    result = Result(found=[Found(make_case(scene, Outcome(ok=True), Outcome(), [], 0, "exact", Versions()))])
    blocker = tmp_path / "file"
    blocker.write_text("")
    save_cases(result, blocker / "sub")  # the directory became unwritable during the campaign
    path = result.found[0].path
    assert path.is_file() and str(path.parent) in result.failures_fallback and str(blocker / "sub") in result.failures_fallback


def test_bench_json_to_a_bad_path_is_refused_before_the_run():
    r = cli("bench", "-n", "1", "--json", "/nonexistent-dir/figures.json")
    one_line_exit_2(r, "--json", "no directory /nonexistent-dir")
    assert "ms/scene" not in r.stdout


def test_coverage_with_no_cases_is_refused():
    one_line_exit_2(cli("coverage", "-n", "0"), "--cases must be at least 1")


def test_negative_worker_counts_are_refused(no_ace):
    one_line_exit_2(cli("check", "-j", "-3"), "--workers", "-3")


def test_replay_refuses_options_it_would_ignore(no_ace):
    one_line_exit_2(cli("check", "--database", "db"), "--database", "replaying")
    one_line_exit_2(cli("check", "--seed", "4"), "--seed", "-n")
    one_line_exit_2(cli("check", "--runtime", "mono", "--corpus", str(default_corpus("coreclr")), "--no-progress"),
                    "--runtime mono", "coreclr .NET 10")
    one_line_exit_2(cli("check", "--runtime", "wasm", "--no-progress"), "unknown runtime 'wasm'", "coreclr, mono")


def test_replay_samples_n_cases_stratified_by_kind_with_the_seed():
    oracle = RecordedOracle(default_corpus())
    every = Counter(e.kind for e in oracle.select())
    a = oracle.select(n=300, seed=1)
    assert len(a) == 300 and a == oracle.select(n=300, seed=1) and a != oracle.select(n=300, seed=2)
    got = Counter(e.kind for e in a)
    for kind, n in every.items():
        assert abs(got[kind] - 300 * n / len(oracle)) <= 1, (got, every)
    assert Counter(e.kind for e in oracle.select(n=2, seed=0)).total() == 2
    assert set(oracle.select(runtime="coreclr")) == set(oracle.select()) and not oracle.select(runtime="mono")


def test_progress_is_printed_while_the_corpus_loads(tmp_path, no_ace):
    r = cli("check", "-n", "3", "--seed", "1", "--failures", str(tmp_path / "f"))
    assert r.returncode == 0, r.stderr
    lines = r.stderr.splitlines()
    assert lines[0].startswith("acconform check: recorded corpus: loading ")


def test_ctrl_c_prints_a_partial_summary_and_no_worker_lines(tmp_path, no_ace):
    p = subprocess.Popen([sys.executable, "-m", "acconform.cli", "check", "-j", "2", "--failures", str(tmp_path / "f")],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=ROOT, start_new_session=True)
    for line in p.stderr:  # wait until the campaign runs
        if "cases/s" in line:
            break
    os.killpg(p.pid, signal.SIGINT)  # what Ctrl-C in a terminal does: the whole process group
    out, err = p.communicate(timeout=120)
    assert p.returncode == 130, out + err
    assert out.startswith("interrupted: ") and " cases in " in out
    assert "Traceback" not in err and "KeyboardInterrupt" not in err


def test_stress_without_ace_does_not_speak_of_ace_not_raising():
    from acconform.commands.stress import KindStats, render

    s = KindStats()
    s.raised_alone["ZeroDivisionError"] = 1
    text = "\n".join(render({"ulp_nudge": s}, with_oracle=False))
    assert "port raised (no ACE to compare with)" in text and "ACE did not" not in text


def test_coverage_anchors_names_every_anchor_once_and_never_reached_agrees_with_the_table():
    r = cli("coverage", "--anchors", "-n", "20")
    assert r.returncode == 0, r.stderr
    lines = r.stdout.splitlines()
    start = next(i for i, l in enumerate(lines) if l.startswith("retail anchor"))
    end = next(i for i, l in enumerate(lines) if l.endswith("anchors reached"))
    table = {}
    for l in lines[start + 1:end]:
        name, calls = l.split("  ", 1)[0], int(l.split()[-1])
        assert name not in table, f"{name} listed twice"
        table[name] = calls
    never = next(l for l in lines if l.startswith("never reached"))
    unreached = [n for n, c in table.items() if c == 0]
    assert unreached and never == f"never reached ({len(unreached)}): " + ", ".join(unreached)


def test_repro_gives_no_verdict_when_the_implementation_a_case_names_does_not_start(tmp_path, no_ace):
    from acconform.case import Case, ImplementationRun, write_document
    from acconform.impl import BuiltinPort
    from acconform.strategies import sample_scenes

    scene = next(iter(sample_scenes(("terrain",), 1, 1)))
    answer = BuiltinPort()(scene)
    gone = ImplementationRun(f"{sys.executable} {tmp_path / 'no-such-port.py'}", str(tmp_path), {"name": "js-port"})
    write_document(tmp_path / "case.json", Case(scene, answer, answer, implementation=gone))
    r = cli("repro", str(tmp_path / "case.json"))
    last = one_line_exit_2(r, "no verdict", "'js-port'", "no-such-port.py", "--impl")
    assert "no longer fails" not in r.stdout and "still fails" not in r.stdout, last


def test_stress_refuses_a_time_limit_that_is_not_positive():
    one_line_exit_2(cli("stress", "-n", "1", "--scene-timeout", "0"), "--scene-timeout must be positive")
