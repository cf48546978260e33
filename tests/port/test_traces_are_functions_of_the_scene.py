"""A trace is a function of the scene alone (issue 43): no answer a routine remembers, no cache and no
scene the process ran before changes what a traced run records. A sample of corpus scenes is traced
in corpus order, again in a shuffled order after untraced runs of all of them in another order, and
in a fresh process in reverse order; every trace is the same, record for record."""

from __future__ import annotations

import hashlib
import json
import random
import subprocess
import sys

import pytest

from acconform.port.run import run_scene, traced_run
from acconform.trace import trace_to_json

KINDS = ["terrain", "bsp", "obstacles", "indoor", "buildings"]
RUNTIME = "coreclr"
N = 16


def sample(kind=None):
    from acconform.oracle import default_corpus
    from acconform.oracle.recorded import RecordedOracle

    oracle = RecordedOracle(default_corpus(RUNTIME))
    entries = oracle.select(n=N, seed=3, runtime=RUNTIME, kinds=KINDS)
    return [oracle._record(e).scene for e in entries if kind is None or e.kind == kind]


def digest(scene) -> str:
    records = traced_run(scene, "exact", RUNTIME)[1]
    return hashlib.sha256(json.dumps(trace_to_json(records), sort_keys=True).encode()).hexdigest()


FRESH = """
import json, sys
sys.path.insert(0, {here!r})
from test_traces_are_functions_of_the_scene import digest, sample
scenes = sample()
print(json.dumps({{i: digest(scenes[i]) for i in reversed(range(len(scenes)))}}))
"""


@pytest.mark.anchor("LandDefs::get_block_offset")
def test_a_trace_is_the_same_whatever_the_process_ran_before_and_in_a_fresh_process():
    from pathlib import Path

    scenes = sample()
    assert len(scenes) == N
    first = [digest(s) for s in scenes]
    order = list(range(N))
    random.Random(1).shuffle(order)
    for i in reversed(order):  # untraced runs fill every memory the port keeps across runs
        run_scene(scenes[i], "exact", None, RUNTIME)
    shuffled = {i: digest(scenes[i]) for i in order}
    assert [i for i in range(N) if shuffled[i] != first[i]] == []
    out = subprocess.run([sys.executable, "-c", FRESH.format(here=str(Path(__file__).parent))],
                         capture_output=True, text=True, check=True).stdout
    fresh = {int(k): v for k, v in json.loads(out.strip().splitlines()[-1]).items()}
    assert [i for i in range(N) if fresh[i] != first[i]] == []


@pytest.mark.anchor("LandDefs::get_block_offset")
def test_a_traced_run_records_block_offsets_computed_even_after_untraced_runs_remembered_them():
    from acconform.port import land_defs

    scene = next(s for s in sample("terrain") if len(s.landblocks) > 1)
    run_scene(scene, "exact", None, RUNTIME)
    records = traced_run(scene, "exact", RUNTIME)[1]
    offsets = [k for k, r in enumerate(records) if r.anchor == "LandDefs.cs:GetBlockOffset"]
    crossing = [k for k in offsets if records[k].result != [0.0, 0.0, 0.0]]
    assert crossing, "the scene's transition crosses no landblock border"
    for k in crossing:  # each offset between two landblocks computed: its two blockid_to_lcoord calls just before
        assert [r.anchor for r in records[k - 2:k]] == ["LandDefs.cs:blockid_to_lcoord"] * 2
    assert land_defs._BLOCK_OFFSETS  # the untraced run's memory is still there, only the traced run bypassed it
