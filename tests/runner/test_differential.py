"""The differential lane: the port against ACE, driven by the same runner as `acconform check`.

Live ACE when configured (a generative, shrinking campaign, on the runtime the build runs on);
otherwise each runtime's recorded corpus is replayed, the port computing as that runtime does.
The fast lane replays a fixed, stratified sample of each corpus
(tests/data/corpus/<runtime>/fast-sample.json, built by corpus_sample.py: every kind, every branch
the corpus reaches, ~1,500 records); the whole corpora are the slow lane (and CI's `acconform check`).
Shards are separate tests so `pytest -n auto` (pytest-xdist) spreads them over all cores. A
differential lane with neither an oracle nor recorded data fails: it must not pass by checking
nothing.
"""

from __future__ import annotations

import os
import warnings
from collections import Counter
from functools import partial

import pytest

from acconform.numerics import RUNTIMES, runtime_named
from acconform.oracle import get_oracle, live_configured
from acconform.port.run import run_scene
from corpus_sample import SAMPLE_NAME, load_sample

SHARDS = 4
CASES = int(os.environ.get("ACCONFORM_CASES", "200"))  # generative scenes per shard (live oracle)
SEED = int(os.environ.get("ACCONFORM_SEED", "0"))

warnings.simplefilter("ignore", RuntimeWarning)


@pytest.fixture(scope="module", params=sorted(RUNTIMES))
def backends(request):
    """(the port computing as `runtime`, ACE on it, runtime): live ACE when configured, else the runtime's corpus."""
    runtime = request.param
    if live_configured():
        oracle = get_oracle()
        if runtime_named(oracle.versions.runtime) != runtime:
            pytest.skip(f"live ACE runs on {oracle.versions.runtime}; the {runtime} corpus replays without a live ACE")
    else:
        oracle = get_oracle(runtime=runtime)  # a missing or empty corpus raises: the lane fails, as it must
    return partial(run_scene, runtime=runtime), oracle, runtime


def _live(oracle) -> bool:
    return getattr(oracle, "name", "") == "live"


def _sample_scenes(oracle, runtime, shard):
    """This shard's sample records as (their scenes, the branches each fires, where each is). The
    scenes are the recorded oracle's, parsed as the replay asks for them (so the oracle answers each
    from the record it handed out, without keying the scene again)."""
    doc = load_sample(runtime)
    names = doc["branches"]
    index = oracle.index()
    entries, fired = [], []
    for key, _kind, branches in doc["records"][shard::SHARDS]:
        entry = index.get(key)
        assert entry is not None, f"{runtime}/{SAMPLE_NAME} names record {key[:16]}, which the corpus lacks: rebuild it"
        entries.append(entry)
        fired.append({names[i] for i in branches})
    return oracle.scenes(entries), fired, [e.where for e in entries]


def _run(run_scene, oracle, tmp_path, shard, replay):
    from acconform.runner import run_campaign

    r = run_campaign(run_scene, oracle.run, n=CASES, seed=SEED * SHARDS + shard, failures_dir=tmp_path,
                     database=None, replay=replay, keep_going=True)
    assert r.cases > 0
    assert r.ok, "\n".join(f"{f.path}: " + "; ".join(f.case.differences) for f in r.found)
    return r


@pytest.mark.parametrize("shard", range(SHARDS))
def test_port_agrees_with_ace_on_the_stratified_sample(shard, backends, tmp_path):
    run_scene, oracle, runtime = backends
    if _live(oracle):
        _run(run_scene, oracle, tmp_path, shard, None)
        return
    scenes, fired, where = _sample_scenes(oracle, runtime, shard)
    traces = []

    def traced(scene):
        trace: Counter = Counter()
        traces.append(trace)
        return run_scene(scene, trace=trace)

    r = _run(traced, oracle, tmp_path, shard, scenes)
    assert r.cases == len(traces) == len(fired)
    # the sample file's branch lists are what the port really fires (so its coverage claim holds)
    wrong = [w for w, want, got in zip(where, fired, traces) if set(got) != want]
    assert not wrong, f"{len(wrong)} sample records fire other branches than {runtime}/{SAMPLE_NAME} says: rebuild it"


@pytest.mark.parametrize("runtime", sorted(RUNTIMES))
def test_the_sample_spans_every_kind_and_every_branch_the_corpus_reaches(runtime):
    from acconform.port.transition.branches import BRANCHES, NOT_YET_REACHED

    doc = load_sample(runtime)
    assert 1000 <= len(doc["records"]) <= 2500
    assert {r[1] for r in doc["records"]} >= {"terrain", "bsp", "obstacles"}
    reached = {doc["branches"][i] for r in doc["records"] for i in r[2]}
    assert reached == set(doc["corpus_branches"])
    unreached = set(BRANCHES) - set(NOT_YET_REACHED) - reached
    assert unreached <= set(CORPUS_MISSES), f"branches no corpus record reaches: {sorted(unreached - set(CORPUS_MISSES))}"
    assert not reached & set(CORPUS_MISSES), f"reached now, take them out of CORPUS_MISSES: {sorted(reached & set(CORPUS_MISSES))}"


# Branches the generated corpus does not reach (hand-made scenes in tests/port reach them), and why.
# (The tick corpus, the tick variants and the house ticks reach every tick branch, the blocked
# slide, the parallel cliff planes and the stationary falls, which were listed here before.)
CORPUS_MISSES = {
    "land_cell:entirely_water_block": "strategies keep water smaller than a landblock (a whole-water block collides all)",
}


@pytest.mark.slow
@pytest.mark.parametrize("shard", range(SHARDS))
def test_port_agrees_with_ace_on_the_whole_corpus(shard, backends, tmp_path):
    run_scene, oracle, _ = backends
    if _live(oracle):
        pytest.skip("live ACE: the fast lane's generative campaign is the live check")
    scenes = list(oracle.scenes())
    assert scenes, "no live ACE and no recorded scenes: the differential lane has nothing to check"
    _run(run_scene, oracle, tmp_path, shard, scenes[shard::SHARDS])
