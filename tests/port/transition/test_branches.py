"""The branch-name list (port/transition/branches.py) is complete and each name is real."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

import acconform.port as port_pkg
from acconform.port.transition.branches import BOUNDARIES, BRANCHES, NOT_YET_REACHED, Trace

_NAME = re.compile(r'"([a-z_]+:[a-z_0-9]+)"')


def _emitted() -> set[str]:
    names = set()
    for path in Path(port_pkg.__file__).parent.rglob("*.py"):
        if path.name == "branches.py":
            continue
        for line in path.read_text().splitlines():
            if "_hit(" in line or "trace[" in line:
                names.update(n for n in _NAME.findall(line) if not n.startswith("boundary:"))
    return names


def _boundaries_emitted() -> set[str]:
    names = set()
    for path in Path(port_pkg.__file__).parent.rglob("*.py"):
        if path.name == "branches.py":
            continue
        text = path.read_text()
        names.update(re.findall(r'trace\.boundary\("([a-z_]+)"', text))
        names.update(re.findall(r'trace\["boundary:([a-z_]+)"\]', text))
        if re.search(r"trace\.walkable\(", text):
            names.update(("floor_z", "landing_z"))
    return names


@pytest.mark.anchor("CTransition::step_down")
def test_every_boundary_the_port_counts_is_documented_and_every_documented_one_counted():
    assert _boundaries_emitted() == set(BOUNDARIES)


@pytest.mark.anchor("CTransition::step_down")
def test_a_trace_counts_only_bit_equal_values_as_boundary_hits_and_keeps_the_closest_ulps():
    from acconform.port.constants import FLOOR_Z, LANDING_Z
    from acconform.numerics import f32_from_bits, f32_bits

    t = Trace()
    t.walkable(f32_from_bits(f32_bits(FLOOR_Z) - 3), FLOOR_Z)
    assert t["boundary:floor_z"] == 0 and t.closest == {"floor_z": 3}
    t.walkable(FLOOR_Z, FLOOR_Z)
    t.walkable(f32_from_bits(f32_bits(LANDING_Z) + 1), LANDING_Z)
    t.walkable(0.5, 0.5)  # no boundary of ours
    assert t["boundary:floor_z"] == 1 and t.closest == {"floor_z": 0, "landing_z": 1}
    t.boundary("sphere_tangent", -0.0, 0.0)  # -0 and +0 are the same value
    assert t["boundary:sphere_tangent"] == 1


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
