"""The branch-name list (port/transition/branches.py) is complete and each name is real."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

import acconform.port as port_pkg
from acconform.port.transition.branches import BRANCHES, NOT_YET_REACHED

_NAME = re.compile(r'"([a-z_]+:[a-z_0-9]+)"')


def _emitted() -> set[str]:
    names = set()
    for path in Path(port_pkg.__file__).parent.rglob("*.py"):
        if path.name == "branches.py":
            continue
        for line in path.read_text().splitlines():
            if "_hit(" in line or "trace[" in line:
                names.update(_NAME.findall(line))
    return names


@pytest.mark.anchor("CTransition::edge_slide")
def test_every_branch_the_port_counts_is_documented():
    assert _emitted() - set(BRANCHES) == set()


@pytest.mark.anchor("CTransition::edge_slide")
def test_every_documented_branch_is_counted_somewhere_in_the_port():
    assert set(BRANCHES) - _emitted() == set()


@pytest.mark.anchor("CTransition::edge_slide")
def test_not_yet_reached_names_only_documented_branches_with_a_reason():
    assert set(NOT_YET_REACHED) <= set(BRANCHES)
    assert all(reason for reason in NOT_YET_REACHED.values())
