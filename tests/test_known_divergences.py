"""The registry of known divergences (acconform/divergences.py): each row true of ACE's source and of
the port, each naming registered ACE methods, docs/divergences.md holding its table, and a first
divergence in a row's routine and field labelled known."""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import pytest

from acconform.divergences import ACE_COMMIT, ACE_PHYSICS, KNOWN, TABLE_BEGIN, TABLE_END, known_for, markdown
from acconform.port.anchors import load_all
from acconform.trace import Divergence, TraceRecord

ROOT = Path(__file__).resolve().parents[1]
MIRROR = Path(os.environ.get("ACE_MIRROR", "/work/.mirror/ACEmulator+ACE/repo"))


def ace_source(path: str) -> str | None:
    if not MIRROR.is_dir():
        return None
    r = subprocess.run(["git", f"--git-dir={MIRROR}", "show", f"{ACE_COMMIT}:{ACE_PHYSICS}{path}"],
                       capture_output=True, text=True)
    return r.stdout if r.returncode == 0 else None


def test_each_known_divergence_is_in_aces_source_and_in_the_port():
    if ace_source("PhysicsGlobals.cs") is None:
        pytest.skip(f"ACE's source is not at {MIRROR} (a git directory holding commit {ACE_COMMIT}; set ACE_MIRROR)")
    for k in KNOWN:
        ace = ace_source(k.ace.path)
        assert ace is not None, f"{k.name}: ACE has no {k.ace.path} at {ACE_COMMIT}"
        port = (ROOT / "port" / k.port.path).read_text()
        for side, text, check in (("ACE", ace, k.ace), ("the port", port, k.port)):
            for needed in check.present:
                assert needed in text, f"{k.name}: {side}'s {check.path} no longer holds {needed!r}"
            for banned in check.absent:
                assert banned not in text, f"{k.name}: {side}'s {check.path} now holds {banned!r}"


def test_each_known_divergence_names_registered_ace_methods_and_a_source():
    methods = {a.ace for a in load_all().values()}
    names = [k.name for k in KNOWN]
    assert len(set(names)) == len(names) >= 8
    for k in KNOWN:
        assert k.anchors and set(k.anchors) <= methods, f"{k.name}: {set(k.anchors) - methods} are no anchors"
        assert k.ace_does and k.retail_does and k.source and k.pinned_by
    assert sum("dereth" in k.source for k in KNOWN) >= 5


def test_the_divergence_doc_holds_the_registrys_table():
    text = (ROOT / "docs" / "divergences.md").read_text()
    held = text.split(TABLE_BEGIN, 1)[1].split(TABLE_END, 1)[0].strip()
    assert held == markdown(), "docs/divergences.md's table is stale: write acconform.divergences.markdown() there"


def _divergence(routine: str, field: str) -> Divergence:
    r = TraceRecord(routine, "exit", result=0.2)
    return Divergence(0, r, r, field, 0.2, 1.0, routine, 0, 0)


def test_a_first_divergence_in_a_rows_routine_and_field_is_known_and_another_is_not():
    assert known_for(_divergence("PhysicsObj.cs:calc_friction", "mover.velocity[0]")).name == "sledding_threshold"
    assert known_for(_divergence("LandCell.cs:FindEnvCollisions", "path.walkable.normal[2]")).name == "terrain_never_walkable"
    assert known_for(_divergence("LandCell.cs:FindEnvCollisions", "path.check_pos[2]")) is None
    assert known_for(_divergence("Transition.cs:StepDown", "result")) is None
    assert known_for(None) is None


def test_a_quantum_handed_on_by_update_object_is_max_quantum_but_another_callee_is_not():
    # the stepped-first mover mutant parts at update_object's `anchor` (another mover's sub-step called first)
    assert known_for(_divergence("PhysicsObj.cs:update_object", "args[1]")).name == "max_quantum"
    assert known_for(_divergence("PhysicsObj.cs:update_object", "anchor")) is None


def test_a_divergence_from_aces_trace_is_known_for_an_implementation_but_never_for_the_port_which_follows_ace():
    from types import SimpleNamespace

    from acconform.explain import known_here

    d = _divergence("EnvCell.cs:find_transit_cells(int, List<PhysicsPart>, CellArray)", "args[0][0]")
    assert known_here(d, SimpleNamespace(command="python my_port.py")).name == "static_cell_search"
    assert known_here(d, SimpleNamespace()) is None  # the built-in port: that ACE is not the one it follows
    assert known_here(None, SimpleNamespace(command="python my_port.py")) is None
