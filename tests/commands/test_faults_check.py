"""Bad input to check, explain and stress (issue 42's catalogue): each refused by name in one line,
exit 2, no traceback, before anything runs, and nothing a user made or found is overwritten."""

from __future__ import annotations

import dataclasses
import gzip
import json
import subprocess
import sys
from pathlib import Path

import pytest

from acconform.case import Versions
from acconform.compare import compare
from acconform.impl import BuiltinPort
from acconform.oracle import default_corpus
from acconform.oracle.recorded import shards
from acconform.runner import make_case
from acconform.strategies import sample_scenes

ROOT = Path(__file__).resolve().parents[2]


def cli(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "acconform.cli", *map(str, args)], capture_output=True, text=True,
                          cwd=cwd or ROOT)


def refused(r, *words) -> str:
    assert r.returncode == 2, r.stdout + r.stderr
    assert "Traceback" not in r.stderr
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1, r.stderr
    for w in words:
        assert w in lines[0], lines[0]
    return lines[0]


@pytest.fixture
def corpus(tmp_path):
    d = tmp_path / "C"
    d.mkdir()
    shard = next(s for s in shards(default_corpus()) if s.name.startswith("terrain"))
    with gzip.open(shard, "rt") as f, gzip.open(d / "terrain-0000.jsonl.gz", "wt") as out:
        out.writelines(line for _, line in zip(range(10), f))
    return d


@pytest.mark.parametrize("workers", ["0", "-2"])
def test_check_refuses_fewer_than_one_worker_by_name(workers, tmp_path, no_ace):
    refused(cli("check", "-j", workers, "-n", "2", "--failures", tmp_path / "f"), "-j/--workers", f"got {workers}")
    assert not (tmp_path / "f").exists()


@pytest.mark.parametrize("seconds", ["0", "-1", "nan", "inf"])
def test_check_refuses_a_timeout_that_is_not_a_finite_number_of_seconds_above_zero(seconds, no_ace):
    refused(cli("check", "--timeout", seconds, "-n", "2"), "--timeout", f"got {seconds}")


@pytest.mark.parametrize("option", ["--json", "--junit"])
def test_check_refuses_a_report_over_a_shard_of_the_corpus_it_replays_and_leaves_the_shard(option, corpus, tmp_path,
                                                                                           no_ace):
    shard = corpus / "terrain-0000.jsonl.gz"
    before = shard.read_bytes()
    refused(cli("check", "--corpus", corpus, option, shard, "--failures", tmp_path / "f"), option, "input")
    assert shard.read_bytes() == before


def test_check_refuses_a_report_over_the_committed_corpus_it_would_replay(tmp_path, no_ace):
    shard = shards(default_corpus())[0]
    before = shard.stat().st_mtime_ns
    refused(cli("check", "--json", shard, "--failures", tmp_path / "f"), "--json", "input")
    assert shard.stat().st_mtime_ns == before


def test_explain_refuses_a_page_over_the_case_it_explains_and_leaves_the_case(tmp_path, no_ace):
    scene = next(iter(sample_scenes(("terrain",), 1, 3)))
    answer = BuiltinPort("exact", "coreclr")(scene)
    ace = dataclasses.replace(answer, ok=not answer.ok)
    path = tmp_path / "case.json"
    path.write_text(json.dumps(make_case(scene, answer, ace, compare(answer, ace), 0, "exact",
                                         Versions("0", "ace", "coreclr 10.0.0")).to_json()))
    before = path.read_bytes()
    refused(cli("explain", path, "--html", path), "--html", "input")
    refused(cli("explain", path, "--html", tmp_path / "." / "case.json"), "--html", "input")  # the same file, spelt otherwise
    assert path.read_bytes() == before


@pytest.mark.parametrize("only, words", [("", ["--only ''", "an empty perturbation kind"]),
                                         ("world_edge,,floor_z", ["an empty perturbation kind"]),
                                         ("world_edge,world_edge", ["'world_edge' is named twice"]),
                                         ("edges", ["unknown perturbation kind 'edges'"])])
def test_stress_refuses_an_only_that_names_no_perturbation_kind(only, words, no_ace):
    refused(cli("stress", "--only", only, "-n", "1", "--no-oracle"), *words)


@pytest.mark.parametrize("seconds", ["0", "nan", "inf"])
def test_stress_refuses_a_scene_timeout_that_is_not_a_finite_number_of_seconds_above_zero(seconds, no_ace):
    refused(cli("stress", "--scene-timeout", seconds, "-n", "1", "--no-oracle"), "--scene-timeout", f"got {seconds}")


def test_stress_refuses_empty_kinds_rather_than_running_the_default(no_ace):
    refused(cli("stress", "--kinds", "", "-n", "1", "--no-oracle"), "no scene kinds chosen")


@pytest.mark.skipif(not Path("/dev/full").exists(), reason="needs /dev/full (a device whose writes fail: disk full)")
def test_check_into_a_full_standard_output_ends_in_one_error_line_and_exit_2(corpus, tmp_path, no_ace):
    with open("/dev/full", "w") as full:
        r = subprocess.run([sys.executable, "-m", "acconform.cli", "check", "--corpus", str(corpus), "-n", "3",
                            "-j", "1", "--no-progress", "--failures", str(tmp_path / "f")], stdout=full,
                           stderr=subprocess.PIPE, text=True, cwd=ROOT)
    assert r.returncode == 2 and "Traceback" not in r.stderr
    assert r.stderr.strip().splitlines()[-1].startswith("acconform check: error: ")
