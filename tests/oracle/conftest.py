"""tests/oracle fixtures (the live oracle fixture, `live`, is in tests/conftest.py)."""

import pytest


@pytest.fixture
def isolated_config(no_ace, tmp_path):
    """No ACE setting from the environment or the user's config file (tests/conftest.py no_ace)."""
    return tmp_path
