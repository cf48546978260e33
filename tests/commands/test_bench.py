"""acconform bench: prints run time against error per kind; --json writes the same figures."""

from __future__ import annotations

import json
import math

from acconform.cli import main
from acconform.commands.bench import ErrorStats, distance
from acconform.outcome import Outcome


def test_bench_on_five_scenes_prints_timings_and_the_field_table_and_writes_json(no_ace, tmp_path, capsys):
    out_file = tmp_path / "bench.json"
    assert main(["bench", "-n", "5", "--kinds", "terrain", "--no-oracle", "--json", str(out_file)]) == 0
    out = capsys.readouterr().out
    assert "terrain: 5 scenes; ms/scene exact" in out and "exact/fast" in out
    assert "discrete outcome differs: fast vs exact" in out
    assert "origin[2]" in out and "ulp max" in out
    assert "fast mode's disagreement with ACE is not measured" in out  # said, not silently dropped
    doc = json.loads(out_file.read_text())
    t = doc["kinds"]["terrain"]
    assert t["scenes"] == 5 and t["ms_exact"] > 0 and t["ms_fast"] > 0
    assert "origin[0]" in t["fast_vs_exact"]["fields"]


def test_bench_against_a_recorded_corpus_adds_the_oracle_columns(no_ace, tmp_path, capsys):
    from acconform.case import Record, Versions
    from acconform.oracle.recorded import CorpusWriter
    from acconform.port.run import run_scene
    from acconform.strategies import sample_scenes

    with CorpusWriter(tmp_path) as w:  # the port's own answers stand in for ACE's
        for s in sample_scenes(("terrain",), 3, 5):
            w.add(Record(s, run_scene(s), Versions("0.1.0", "test", "")))
    assert main(["bench", "-n", "3", "--kinds", "terrain", "--corpus", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    assert "fast vs oracle" in out and "exact vs oracle 0/3" in out
    assert "differences from ACE as check counts them: fast mode (ULP tolerance) " in out
    assert "exact mode (bits) 0/3" in out and "exact mode on 0." in out


def test_bench_without_ace_measures_fast_mode_against_the_recorded_answers_of_the_runtime_asked_for(no_ace, capsys):
    from acconform.oracle import default_corpus

    assert main(["bench", "-n", "4", "--kinds", "bsp", "--runtime", "mono"]) == 0
    out = capsys.readouterr().out
    assert f"recorded corpus {default_corpus('mono')}" in out and "on mono 6.8" in out
    assert "fast mode disagrees with ACE (mono 6.8.0.105) on " in out and "exact mode on 0." in out


def test_error_stats_count_a_discrete_flip_once_and_keep_it_out_of_the_float_columns():
    s = ErrorStats()
    s.add(Outcome(ok=True, origin=(1.0, 2.0, 3.0)), Outcome(ok=True, origin=(1.0, 2.0, 3.0000002)))
    s.add(Outcome(ok=True, origin=(1.0, 2.0, 9.0)), Outcome(ok=False, origin=(1.0, 2.0, 3.0)))
    f = s.fields()
    assert s.discrete == 1 and s.scenes == 2
    assert f["origin[2]"]["ulp_max"] == 1 and f["origin[0]"]["ulp_max"] == 0


def test_distance_treats_nan_pairs_as_equal_and_other_nonfinite_mismatches_as_infinite():
    assert distance(math.nan, math.nan) == (0.0, 0.0)
    assert distance(math.inf, 1.0) == (math.inf, math.inf)
    assert distance(1.0, 1.0000001192092896) == (1.0, 1.1920928955078125e-07)


def test_bench_on_a_corpus_without_the_oracle_names_the_corpus_and_measures_no_disagreement(no_ace, tmp_path, capsys):
    from acconform.case import Record, Versions
    from acconform.oracle.recorded import CorpusWriter
    from acconform.port.run import run_scene
    from acconform.strategies import sample_scenes

    with CorpusWriter(tmp_path) as w:
        for s in sample_scenes(("terrain",), 3, 5):
            w.add(Record(s, run_scene(s), Versions("0.1.0", "test", "")))
    assert main(["bench", "-n", "3", "--kinds", "terrain", "--corpus", str(tmp_path), "--no-oracle"]) == 0
    out = capsys.readouterr().out
    assert f"recorded corpus {tmp_path}" in out and "oracle none" in out and "--no-oracle" in out
