"""tests/port: makes the shared helpers here (numerics_replay, dat_shapes) and the scene data in objects/ importable from every subdirectory."""

import sys
from pathlib import Path

_HERE = str(Path(__file__).resolve().parent)
for _p in (_HERE, str(Path(_HERE) / "objects")):
    if _p not in sys.path:
        sys.path.insert(0, _p)


import pytest  # noqa: E402


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
