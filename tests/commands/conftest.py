"""Fixtures for the bench / stress / coverage --anchors command tests: no ACE unless a test asks."""

from __future__ import annotations

import warnings

import pytest

warnings.simplefilter("ignore", RuntimeWarning)


@pytest.fixture
def no_ace(monkeypatch, tmp_path):
    monkeypatch.delenv("ACE_ASSEMBLY", raising=False)
    monkeypatch.setenv("XDG_CONFIG_HOME", str(tmp_path / "config"))
    monkeypatch.setenv("HOME", str(tmp_path / "home"))
