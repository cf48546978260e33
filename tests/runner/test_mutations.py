"""Proof that the harness catches bugs: planted bugs in copies of the port, found and shrunk.

Each mutant (tests/runner/mutants.py) runs as the port against the real port as the oracle,
through the same runner `acconform check` uses, on the default kinds (terrain, BSP objects,
obstacles). A caught mutant must shrink to a small scene (a few landblocks, at most two
objects). Mutants the campaign may miss within its budget are listed with the reason; they are
run all the same and pass when caught.
"""

from __future__ import annotations

import warnings

import pytest

from acconform.runner import run_campaign

from mutants import MUTATIONS, load_mutant

warnings.simplefilter("ignore", RuntimeWarning)

BUDGET = 1500  # scenes per mutant before we call it missed
MAX_LANDBLOCKS = 9  # a 3x3 neighbourhood: near a corner, the path and the next block ahead
MAX_OBJECTS = 2

# Mutants the default kinds may miss within BUDGET at seed 0; each is still run, and passes when caught.
EXPECTED_MISSES = {
    # dist == -EPSILON exactly cannot be drawn on purpose: a sphere's bottom (center.z - r) lies on
    # the float32 grid of r, and EPSILON's low bits are finer than that grid
    "validate_walkable_contact_test_strict": "boundary (dist == -EPSILON exactly) is unreachable by construction",
    "step_down_interp_floor_raised": "a step-down overshoot in [-0.1, 0) needs gentle slopes and a sliver step",
    "adjust_offset_block_offset_dropped": "needs a sloped contact plane kept across a block border",
}


@pytest.mark.slow
@pytest.mark.parametrize("index", range(len(MUTATIONS)), ids=[m.name for m in MUTATIONS])
def test_the_runner_finds_and_shrinks_a_planted_bug(index, tmp_path):
    pytest.importorskip("acconform.port.run")
    from acconform.port.run import run_scene

    m = MUTATIONS[index]
    mutant = load_mutant(index)
    r = run_campaign(mutant, run_scene, kinds=None, n=BUDGET, seed=0, failures_dir=tmp_path,
                     database=None, workers=2)
    if not r.found and m.name in EXPECTED_MISSES:
        pytest.xfail(EXPECTED_MISSES[m.name])
    assert r.found, f"{m.name} ({m.what}) went unnoticed for {r.cases} scenes"
    case = r.found[0].case
    assert r.found[0].shrunk and r.found[0].path.exists()
    assert len(case.scene.landblocks) <= MAX_LANDBLOCKS and len(case.scene.objects) <= MAX_OBJECTS


def test_every_mutation_still_applies_to_the_port_exactly_once():
    pytest.importorskip("acconform.port.run")
    from mutants import PORT_DIR

    assert len(MUTATIONS) >= 10
    for m in MUTATIONS:
        assert (PORT_DIR / m.file).read_text().count(m.old) == 1, m.name
