
import pytest

from acconform.errors import OracleUnavailable


@pytest.fixture(scope="session")
def live():
    """The live oracle on the configured ACE (ACE_ASSEMBLY / --ace / config), or a visible skip."""
    from acconform.oracle import live_configured
    from acconform.oracle.live import LiveOracle

    if not live_configured():
        pytest.skip("no ACE configured: set ACE_ASSEMBLY=/path/to/ACE.Server.dll to run the live-oracle lane")
    try:
        return LiveOracle()
    except OracleUnavailable as e:
        pytest.fail(f"ACE is configured but the live oracle cannot load: {e}")


@pytest.fixture
def isolated_config(no_ace, tmp_path):
    """No ACE setting from the environment or the user's config file (tests/conftest.py no_ace)."""
    return tmp_path
