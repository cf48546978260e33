"""The anchor registry audits itself: every public port function is anchored to ACE or registered
as harness glue, every ACE anchor names a real ACE file, and no ACE method is claimed twice silently."""

from __future__ import annotations

import inspect
import os
import sys
from collections import defaultdict
from pathlib import Path

import pytest

from acconform.port.anchors import HARNESS, REGISTRY, load_all

ACE_SOURCE = Path(os.environ.get("ACE_SOURCE", "/work/ace")) / "Source"
ACE_PHYSICS = ACE_SOURCE / "ACE.Server/Physics"
DATLOADER = "ACE.DatLoader/"  # DatLoader anchors name their file by its path under Source/
SERVER = ("ACE.Server/Managers/", "ACE.Server/Entity/", "ACE.Server/WorldObjects/",  # so do the server's (LandblockManager,
          "ACE.Entity/")  # the server Landblock, the WorldObjects) and ACE.Entity's (Position, LandblockId)
# the registry itself is not port code
NOT_PORT = {"acconform.port.anchors"}


def _port_modules():
    load_all()
    return [m for name, m in sorted(sys.modules.items())
            if m is not None and (name == "acconform.port" or name.startswith("acconform.port."))
            and name not in NOT_PORT]


def _plain(v):
    return v.__func__ if isinstance(v, (classmethod, staticmethod)) else v


def public_port_functions() -> dict[str, object]:
    """key (fn.__module__ + "." + fn.__qualname__) -> function, for every public function defined in a
    port module: module-level functions, and methods found in port classes' dicts -- including
    functions attached with setattr (LandCell's ObjCell methods), keyed by where they are defined.
    Dunder methods and properties are not routines of their own and are left out."""
    found: dict[str, object] = {}
    for mod in _port_modules():
        for name, value in vars(mod).items():
            fn = _plain(value)
            if inspect.isfunction(fn) and not name.startswith("_"):
                found.setdefault(f"{fn.__module__}.{fn.__qualname__}", fn)
            if inspect.isclass(value) and value.__module__.startswith("acconform.port"):
                for attr, member in vars(value).items():
                    fn = _plain(member)
                    if inspect.isfunction(fn) and not attr.startswith("_"):
                        found.setdefault(f"{fn.__module__}.{fn.__qualname__}", fn)
    # keep only functions a port module defines (not e.g. numerics helpers imported into one)
    return {k: f for k, f in found.items()
            if f.__module__.startswith("acconform.port") and f.__module__ not in NOT_PORT
            and not f.__qualname__.split(".")[-1].startswith("_")}


def test_the_audit_sees_module_functions_methods_and_setattr_attached_methods():
    keys = public_port_functions()
    assert "acconform.port.land_defs.gid_to_lcoord" in keys
    assert "acconform.port.transition.transition.Transition.edge_slide" in keys
    assert "acconform.port.cell.obj_cell.ObjCell.equals" in keys  # also LandCell.equals (setattr)
    assert "acconform.port.cell.land_cell.LandCell.find_collisions" in keys
    assert len(keys) > 250


def test_every_public_port_function_is_anchored_or_harness_glue():
    missing = sorted(k for k in public_port_functions() if k not in REGISTRY and k not in HARNESS)
    assert missing == [], (
        "public port functions with no anchor: give each @anchor(retail, 'File.cs:Method') or, "
        "if it has no ACE counterpart, @harness('what it does') (port/anchors.py), or make it private: "
        + ", ".join(missing))


def test_no_function_is_both_an_ace_anchor_and_harness_glue():
    assert set(REGISTRY) & set(HARNESS) == set()


def test_every_registered_name_is_a_function_that_exists():
    functions = public_port_functions()
    stale = [k for k in list(REGISTRY) + list(HARNESS) if k not in functions and not k.split(".")[-1] == "__init__"]
    assert stale == []


def test_harness_glue_says_what_it_does():
    assert all(h.what.strip() for h in HARNESS.values())


@pytest.mark.skipif(not ACE_PHYSICS.is_dir(), reason=f"ACE's source tree is not at {ACE_PHYSICS} (set ACE_SOURCE)")
def test_every_ace_anchor_names_a_file_in_aces_physics_tree_or_datloader():
    files = {p.name for p in ACE_PHYSICS.rglob("*.cs")}
    files |= {DATLOADER + str(p.relative_to(ACE_SOURCE / DATLOADER)) for p in (ACE_SOURCE / DATLOADER).rglob("*.cs")}
    files |= {folder + p.name for folder in SERVER for p in (ACE_SOURCE / folder).glob("*.cs")}
    load_all()
    unknown = sorted(f"{key}: {a.ace}" for key, a in REGISTRY.items() if a.ace.split(":", 1)[0] not in files)
    assert unknown == []


def test_no_two_port_functions_claim_one_ace_method_unless_noted():
    """Overloads and split-out tests share an ACE method; all but one claimant must say why (a note)."""
    claims = defaultdict(list)
    for key, a in load_all().items():
        claims[a.ace].append(a)
    silent = {ace: [a.qualname for a in v] for ace, v in claims.items()
              if len(v) > 1 and sum(1 for a in v if not a.note) > 1}
    assert silent == {}
