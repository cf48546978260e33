"""The differential lane: the port against ACE, driven by the same runner as `acconform check`.

Live ACE when configured (a generative, shrinking campaign); otherwise the recorded corpus is
replayed. Shards are separate tests so `pytest -n auto` (pytest-xdist) spreads them over all
cores. A differential lane with neither an oracle nor recorded data fails: it must not pass
by checking nothing.
"""

from __future__ import annotations

import os
import warnings

import pytest

SHARDS = 4
CASES = int(os.environ.get("ACCONFORM_CASES", "200"))  # generative scenes per shard (live oracle)
SEED = int(os.environ.get("ACCONFORM_SEED", "0"))

warnings.simplefilter("ignore", RuntimeWarning)


@pytest.fixture(scope="module")
def backends():
    port = pytest.importorskip("acconform.port.run", reason="the port has not landed")
    oracle_pkg = pytest.importorskip("acconform.oracle")
    if not hasattr(oracle_pkg, "get_oracle"):
        pytest.skip("the oracle package has not landed get_oracle yet")
    oracle = oracle_pkg.get_oracle()  # an empty corpus raises: the lane fails, as it must
    replay = None
    if getattr(oracle, "name", "") != "live":
        replay = list(oracle.scenes())
        assert replay, "no live ACE and no recorded scenes: the differential lane has nothing to check"
    return port.run_scene, oracle, replay


@pytest.mark.parametrize("shard", range(SHARDS))
def test_port_agrees_with_ace(shard, backends, tmp_path):
    from acconform.runner import run_campaign

    run_scene, oracle, replay = backends
    mine = None if replay is None else replay[shard::SHARDS]
    r = run_campaign(run_scene, oracle.run, n=CASES, seed=SEED * SHARDS + shard, failures_dir=tmp_path,
                     database=None, replay=mine, keep_going=True)
    assert r.cases > 0
    assert r.ok, "\n".join(f"{f.path}: " + "; ".join(f.case.differences) for f in r.found)
