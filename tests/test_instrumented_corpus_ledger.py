"""benchmarks/instrumented_corpus.py's ledger (fast lane): two runs, one a runtime, share one file."""

import sys
from pathlib import Path

SCRIPT = Path(__file__).resolve().parent.parent / "benchmarks" / "instrumented_corpus.py"
sys.path.insert(0, str(SCRIPT.parent))

import instrumented_corpus  # noqa: E402


def test_a_save_keeps_what_another_run_saved_meanwhile_under_a_key_this_run_never_touched(tmp_path):
    path = tmp_path / "ledger.json"
    first = instrumented_corpus.Ledger(path, fresh=False)
    first.enter("b/coreclr/s", "s.jsonl.gz", 1, True)
    first.save()
    mono = instrumented_corpus.Ledger(path, fresh=False)  # read the coreclr key, then never touches it
    coreclr = instrumented_corpus.Ledger(path, fresh=False)
    coreclr.enter("b/coreclr/s", "s.jsonl.gz", 2, True)
    coreclr.save()
    mono.enter("b/mono/s", "s.jsonl.gz", 7, True)
    mono.save()
    after = instrumented_corpus.Ledger(path, fresh=False)
    assert after.verified("b/coreclr/s") == {1, 2} and after.verified("b/mono/s") == {7}


def test_a_runs_own_verdict_on_a_scene_wins_over_the_files(tmp_path):
    path = tmp_path / "ledger.json"
    other = instrumented_corpus.Ledger(path, fresh=False)
    other.enter("b/mono/s", "s.jsonl.gz", 3, True)
    other.save()
    this = instrumented_corpus.Ledger(path, fresh=False)
    this.enter("b/mono/s", "s.jsonl.gz", 3, False)
    this.save()
    after = instrumented_corpus.Ledger(path, fresh=False)
    assert after.differs("b/mono/s") == {3} and after.verified("b/mono/s") == set()
