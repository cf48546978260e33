"""A campaign in parts (`check --shard K/N`): the parts together run exactly the unsharded run's
cases, each once, and `acconform merge` joins their summaries and case files into one; bad input to
merge is one line, exit 2."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import warnings
from pathlib import Path

import pytest

from acconform.outcome import Outcome
from acconform.runner import run_campaign, scene_hash

warnings.simplefilter("ignore", RuntimeWarning)


def recording(log: Path):
    """A backend answering a fixed outcome that appends each scene's hash to `log` (forked workers too)."""
    def backend(scene):
        with open(log, "a") as f:
            f.write(f"{os.getpid()} {scene_hash(scene)}\n")
        return Outcome(ok=True)
    return backend


def hashes(log: Path) -> list[str]:
    return sorted(line.split()[1] for line in log.read_text().splitlines()) if log.exists() else []


def test_the_parts_of_a_live_campaign_draw_exactly_the_scenes_of_the_unsharded_run(tmp_path):
    whole = tmp_path / "whole.log"
    r = run_campaign(recording(whole), lambda s: Outcome(ok=True), n=30, seed=4, failures_dir=None, database=None,
                     workers=2, kinds=("terrain", "obstacles"))
    assert r.ok and r.cases == 30
    parts = []
    for k in (1, 2):
        log = tmp_path / f"part{k}.log"
        p = run_campaign(recording(log), lambda s: Outcome(ok=True), n=30, seed=4, failures_dir=None, database=None,
                         workers=1, kinds=("terrain", "obstacles"), shard=(k, 2))
        assert p.cases == 15
        parts.append(hashes(log))
    # the same streams, so the same scenes, as many times (Hypothesis may draw one simple scene in two streams,
    # as it does for two workers of one run)
    assert sorted(parts[0] + parts[1]) == hashes(whole)


def test_the_parts_of_a_replay_take_every_record_once(tmp_path):
    from acconform.oracle import default_corpus
    from acconform.oracle.recorded import RecordedOracle

    oracle = RecordedOracle(default_corpus())
    replay = oracle.scenes(oracle.select(n=50, seed=2))
    whole = tmp_path / "whole.log"
    run_campaign(recording(whole), lambda s: Outcome(ok=True), replay=replay, failures_dir=None)
    parts = []
    for k in (1, 2, 3):
        log = tmp_path / f"part{k}.log"
        r = run_campaign(recording(log), lambda s: Outcome(ok=True), replay=replay, failures_dir=None, workers=2 if k == 2 else 1,
                         shard=(k, 3))
        assert r.cases == len(range(k - 1, 50, 3))
        parts.append(hashes(log))
    assert sorted(sum(parts, [])) == hashes(whole) and len(hashes(whole)) == 50


def acconform(*args, cwd):
    return subprocess.run([sys.executable, "-m", "acconform.cli", *args], capture_output=True, text=True, cwd=cwd)


def test_merge_joins_the_parts_summaries_into_the_unsharded_runs_counts(tmp_path, no_ace):
    common = ("check", "--no-progress", "-n", "40", "--seed", "1", "-j", "1")
    whole = acconform(*common, "--json", "whole.json", cwd=tmp_path)
    assert whole.returncode == 0, whole.stderr
    for k in (1, 2):
        r = acconform(*common, "--shard", f"{k}/2", "--json", f"p{k}.json", "--failures", f"f{k}", cwd=tmp_path)
        assert r.returncode == 0, r.stderr
    m = acconform("merge", "p2.json", "p1.json", "--json", "m.json", cwd=tmp_path)
    assert m.returncode == 0, m.stderr
    merged, unsharded = (json.loads((tmp_path / f).read_text()) for f in ("m.json", "whole.json"))
    assert merged["cases"] == unsharded["cases"] and merged["ok"] and "shard" not in merged
    assert {k: merged[k] for k in ("oracle", "mode", "seed", "kinds")} == {k: unsharded[k] for k in ("oracle", "mode", "seed", "kinds")}


def test_merge_copies_each_parts_case_files_once(tmp_path):
    from acconform.commands.merge import merge

    docs = []
    for k in (1, 2):
        d = tmp_path / f"f{k}"
        d.mkdir()
        (d / "case-aaa.json").write_text("{}")  # the same scene found by both parts
        (d / f"case-{k}.json").write_text("{}")
        cases = [{"file": str(d / name), "kind": "bsp", "fields": ["origin"], "group": "differs in origin",
                  "shrunk": False} for name in ("case-aaa.json", f"case-{k}.json")]
        docs.append((tmp_path / f"p{k}.json", {
            "format": "acconform.summary/1", "ok": False, "interrupted": False, "oracle": "recorded", "mode": "exact",
            "seed": None, "kinds": ["bsp"], "implementation": {}, "versions": {"runtime": "coreclr"},
            "shard": {"part": k, "parts": 2, "cases_asked": None, "workers": 1},
            "cases": {"run": 10, "compared": 10, "skipped": {}}, "differences": {"cases": cases},
            "timings": {"elapsed_s": 1.0 * k, "port_s": 0.5}}))
    out = merge(docs, tmp_path / "merged")
    assert sorted(p.name for p in (tmp_path / "merged").iterdir()) == ["case-1.json", "case-2.json", "case-aaa.json"]
    assert out["differences"]["total"] == 3 and out["cases"]["run"] == 20 and not out["ok"]
    assert out["timings"] == {"elapsed_s": 2.0, "cases_per_s": 10.0, "port_s": 1.0}


@pytest.mark.parametrize("setup, says", [
    ("missing", "no such summary"),
    ("not json", "not JSON"),
    ("unsharded", "not the summary of a part"),
    ("twice", "parts overlap: part 1/2 is given twice"),
    ("one of two", "parts missing: 2/2"),
    ("other seed", "its seed is 9, not 1"),
])
def test_bad_input_to_merge_is_one_line_and_exit_2(tmp_path, setup, says):
    part = {"format": "acconform.summary/1", "ok": True, "interrupted": False, "oracle": "recorded", "mode": "exact",
            "seed": 1, "kinds": ["bsp"], "implementation": {}, "versions": {"runtime": "coreclr"},
            "shard": {"part": 1, "parts": 2, "cases_asked": None, "workers": 1},
            "cases": {"run": 1, "compared": 1, "skipped": {}}, "differences": {"cases": []}, "timings": {}}
    (tmp_path / "p1.json").write_text(json.dumps(part))
    other = dict(part, shard=dict(part["shard"], part=2))
    args = {"missing": ["p1.json", "gone.json"], "twice": ["p1.json", "p1.json"], "one of two": ["p1.json"],
            "not json": ["p1.json", "bad.json"], "unsharded": ["p1.json", "plain.json"],
            "other seed": ["p1.json", "p2.json"]}[setup]
    (tmp_path / "bad.json").write_text("{")
    (tmp_path / "plain.json").write_text(json.dumps({k: v for k, v in part.items() if k != "shard"}))
    (tmp_path / "p2.json").write_text(json.dumps(dict(other, seed=9)))
    r = acconform("merge", *args, cwd=tmp_path)
    assert r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1 and says in r.stderr, r.stderr
    assert not (tmp_path / "failures").exists()


def test_merge_finds_a_parts_case_files_beside_its_summary(tmp_path):
    """As CI artifacts keep them: each part's summary and its failures/ folder in a folder of their own."""
    from acconform.commands.merge import merge

    docs = []
    for k in (1, 2):
        d = tmp_path / f"part-{k}" / "failures"
        d.mkdir(parents=True)
        (d / f"case-{k}.json").write_text("{}")
        docs.append((tmp_path / f"part-{k}" / "s.json", {
            "format": "acconform.summary/1", "ok": False, "oracle": "recorded", "mode": "exact", "seed": None,
            "kinds": ["bsp"], "implementation": {}, "versions": {"runtime": "coreclr"},
            "shard": {"part": k, "parts": 2, "cases_asked": None, "workers": 1},
            "cases": {"run": 1, "compared": 1, "skipped": {}},
            "differences": {"cases": [{"file": f"failures/case-{k}.json", "fields": [f"f{k}"], "group": "g"}]},
            "timings": {"elapsed_s": 1.0}}))
    out = merge(docs, tmp_path / "merged")
    assert sorted(p.name for p in (tmp_path / "merged").iterdir()) == ["case-1.json", "case-2.json"]
    assert out["differences"]["total"] == 2
