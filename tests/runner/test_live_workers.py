"""A live campaign on several worker processes: each worker loads its own .NET runtime."""

import os

import pytest

from acconform.oracle import PerProcessOracle, live_configured
from acconform.port.run import run_scene
from acconform.runner import run_campaign


@pytest.mark.live_oracle
def test_a_live_campaign_on_two_workers_loads_ace_in_each_worker_and_finishes():
    if not live_configured():
        pytest.skip("no ACE configured: set ACE_ASSEMBLY=/path/to/ACE.Server.dll to run the live-oracle lane")
    oracle = PerProcessOracle()
    result = run_campaign(lambda s: run_scene(s), oracle.run, n=20, seed=5, workers=2, failures_dir=None,
                          database=None)
    assert result.cases == 20 and not result.found
    assert oracle._oracle is None, "the parent must not start a runtime it would then fork"


def test_a_per_process_oracle_refuses_a_missing_assembly_before_any_fork(tmp_path, monkeypatch):
    from acconform.errors import OracleUnavailable

    monkeypatch.setenv("XDG_CONFIG_HOME", str(tmp_path))
    monkeypatch.delenv("ACE_ASSEMBLY", raising=False)
    with pytest.raises(OracleUnavailable, match="no such file|not found|does not exist|no ACE"):
        PerProcessOracle(ace=os.fspath(tmp_path / "nope" / "ACE.Server.dll"))
