"""Fixtures shared across the test folders."""

import pytest


@pytest.fixture
def no_ace(monkeypatch, tmp_path):
    """No ACE from the environment or the user's config file: the machine CI starts with."""
    monkeypatch.delenv("ACE_ASSEMBLY", raising=False)
    monkeypatch.delenv("ACE_RUNTIME", raising=False)
    monkeypatch.setenv("XDG_CONFIG_HOME", str(tmp_path / "config"))
    monkeypatch.setenv("HOME", str(tmp_path / "home"))
