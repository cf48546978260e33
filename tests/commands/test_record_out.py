"""`acconform record` without --out writes into ./corpus/<runtime> under the working directory (never
into the installed package), and its summary line says where."""

from __future__ import annotations

import gzip
from pathlib import Path

import acconform
import acconform.oracle
from acconform.cli import main
from acconform.commands.record import default_out
from acconform.oracle import default_corpus
from acconform.oracle.recorded import RecordedOracle, shards


def test_the_default_output_is_a_corpus_folder_per_runtime_under_the_working_directory(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert default_out("coreclr") == tmp_path / "corpus" / "coreclr"
    assert default_out("mono") == tmp_path / "corpus" / "mono"
    assert Path(acconform.__file__).parent not in default_out("mono").parents


def test_record_without_out_writes_into_the_working_directory_and_says_where(tmp_path, monkeypatch, capsys):
    # three recorded scenes are the scenes given, and their recorded answers stand in for live ACE
    source = tmp_path / "in"
    source.mkdir()
    with gzip.open(shards(default_corpus("coreclr"))[0], "rt") as f:
        lines = [f.readline() for _ in range(3)]
    with gzip.open(source / "bsp-0000.jsonl.gz", "wt") as f:
        f.writelines(lines)
    recorded = RecordedOracle(source)

    class LiveStandIn:
        name = "live"
        versions = recorded.versions

        def run_many(self, scenes):
            return [(recorded.run(s), 0) for s in scenes]

    monkeypatch.setattr(acconform.oracle, "require_live", lambda ace=None, runtime=None, say=None: LiveStandIn())
    work = tmp_path / "work"
    work.mkdir()
    monkeypatch.chdir(work)
    assert main(["record", "-q", str(source / "bsp-0000.jsonl.gz")]) == 0
    written = work / "corpus" / "coreclr"
    out = capsys.readouterr().out
    assert f"recorded 3 scenes (bsp 3; 0 ACE exceptions as verdicts), skipped 0 already recorded, into {written} in" in out
    assert len(RecordedOracle(written)) == 3
    assert main(["record", "-q", str(source / "bsp-0000.jsonl.gz")]) == 0  # again: every scene already there
    assert f"recorded 0 scenes (none; 0 ACE exceptions as verdicts), skipped 3 already recorded, into {written}" in capsys.readouterr().out
