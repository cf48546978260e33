"""A live campaign on several worker processes: each worker loads its own .NET runtime."""

import os
import subprocess
import sys

import pytest

from acconform.oracle import PerProcessOracle, default_corpus, live_configured, port_runtime
from acconform.port.run import run_scene
from acconform.runner import run_campaign


@pytest.mark.live_oracle
def test_a_live_campaign_on_two_workers_loads_ace_in_each_worker_and_finishes():
    if not live_configured():
        pytest.skip("no ACE configured: set ACE_ASSEMBLY=/path/to/ACE.Server.dll to run the live-oracle lane")
    # in a fresh process: a live test before this one may have loaded a runtime into pytest's
    code = """
from acconform.oracle import PerProcessOracle, port_runtime
from acconform.port.run import run_scene
from acconform.runner import run_campaign
oracle = PerProcessOracle()
runtime = port_runtime(oracle)
result = run_campaign(lambda s: run_scene(s, runtime=runtime), oracle.run, n=20, seed=5, workers=2, failures_dir=None,
                      database=None)
assert result.cases == 20 and not result.found, (result.cases, len(result.found))
assert oracle._oracle is None, "the parent must not start a runtime it would then fork"
"""
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=600)
    assert out.returncode == 0, out.stderr[-2000:]


@pytest.mark.live_oracle
def test_a_process_that_has_loaded_ace_refuses_to_fork_live_workers_with_one_line():
    if not live_configured():
        pytest.skip("no ACE configured: set ACE_ASSEMBLY=/path/to/ACE.Server.dll to run the live-oracle lane")
    from acconform.errors import AcconformError
    from acconform.oracle import get_oracle

    get_oracle().versions  # noqa: B018 - ACE loaded into this process
    with pytest.raises(AcconformError, match="already loaded a .NET runtime"):
        run_campaign(run_scene, PerProcessOracle().run, n=4, seed=5, workers=2, failures_dir=None, database=None)


def test_a_per_process_oracle_refuses_a_missing_assembly_before_any_fork(tmp_path, monkeypatch):
    from acconform.errors import OracleUnavailable

    monkeypatch.setenv("XDG_CONFIG_HOME", str(tmp_path))
    monkeypatch.delenv("ACE_ASSEMBLY", raising=False)
    with pytest.raises(OracleUnavailable, match="no such file|not found|does not exist|no ACE"):
        PerProcessOracle(ace=os.fspath(tmp_path / "nope" / "ACE.Server.dll"))


@pytest.mark.live_oracle
def test_the_port_computes_as_the_runtime_a_live_build_runs_on_without_the_parent_loading_it():
    if not live_configured():
        pytest.skip("no ACE configured: set ACE_ASSEMBLY=/path/to/ACE.Server.dll to run the live-oracle lane")
    from acconform.oracle.config import resolve

    oracle = PerProcessOracle()
    assert port_runtime(oracle) == resolve().runtime
    assert oracle._oracle is None, "asking the runtime must not start one in the parent"


@pytest.mark.parametrize("runtime", ["mono", "coreclr"])
def test_the_port_computes_as_the_runtime_a_recorded_corpus_comes_from(runtime):
    from acconform.oracle.recorded import RecordedOracle

    assert port_runtime(RecordedOracle(default_corpus(runtime))) == runtime
