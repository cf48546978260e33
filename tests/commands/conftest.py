"""Fixtures for the bench / stress / coverage --anchors command tests: no ACE unless a test asks."""

from __future__ import annotations

import warnings


warnings.simplefilter("ignore", RuntimeWarning)
