"""Fixtures shared across the test folders."""

import gc

import pytest
from hypothesis import settings

# Speed is measured by benchmarks that print figures, never by a test: Hypothesis's per-example
# deadline is a timed test that fails on a loaded machine, so it is off for every suite here.
settings.register_profile("acconform", deadline=None)
settings.load_profile("acconform")


def pytest_collection_finish(session):
    """The collector as a campaign tunes it (runner.campaign_gc): what the suite has built once
    its tests are collected (modules, Hypothesis' caches) frozen, and collections less often. The
    port's and the strategies' tests ran 20-30% faster (alternating, one run); each xdist worker
    does the same."""
    from acconform.runner import GC_THRESHOLDS

    gc.collect()
    gc.freeze()
    gc.set_threshold(*GC_THRESHOLDS)


@pytest.fixture
def no_ace(monkeypatch, tmp_path):
    """No ACE from the environment or the user's config file: the machine CI starts with."""
    monkeypatch.delenv("ACE_ASSEMBLY", raising=False)
    monkeypatch.delenv("ACE_RUNTIME", raising=False)
    monkeypatch.setenv("XDG_CONFIG_HOME", str(tmp_path / "config"))
    monkeypatch.setenv("HOME", str(tmp_path / "home"))


@pytest.fixture(scope="session")
def live():
    """The live oracle on the configured ACE (ACE_ASSEMBLY / --ace / config), or a visible skip."""
    from acconform.errors import OracleUnavailable
    from acconform.oracle import live_configured
    from acconform.oracle.live import LiveOracle

    if not live_configured():
        pytest.skip("no ACE configured: set ACE_ASSEMBLY=/path/to/ACE.Server.dll to run the live-oracle lane")
    try:
        return LiveOracle()
    except OracleUnavailable as e:
        pytest.fail(f"ACE is configured but the live oracle cannot load: {e}")
