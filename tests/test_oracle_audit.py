"""docs/oracle.md's audit table ("Decisions the harness makes on ACE's behalf") against the facade
(oracle/facade/Facade.cs): every place the facade reaches past ACE's public surface (a private or
internal member by reflection, an object made without its constructor) and every sequence of ACE's
calls the facade runs in place of a running server's own caller is named in a row, so a departure
from a running server cannot be added to the facade without the table saying why."""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
FACADE = (ROOT / "oracle" / "facade" / "Facade.cs").read_text()

# The facade's methods that run a sequence of ACE's calls where a running server's own caller
# (WorldObject, Player, Landblock, LandblockManager, WorldManager) would: each stands for a decision.
SERVER_SEQUENCES = ("LoadServerLandblock", "MakeServerLandblock", "ClearAdjacents", "InstallDat", "SetClock",
                    "Place", "UpdatePlayerPosition", "MakePlayer", "PrepareServerPlayer", "SetServerPlayerPhysics", "Jump", "MoveToState", "BuildStatic", "BuildMover", "RemoveStatics",
                    "QuietLog4netStartup", "EnterOthers", "MakeWorldObject", "ApplyOtherInputs",
                    "SceneLaunch", "FindObj", "ProjectileLocation", "LocationLandblock", "GetProjectileVelocity", "CalculateSpellProjectileVelocity",
                    "SetPhysicsObj", "SetCurrentLandblock", "SetProjectilePhysicsState", "SpellProjectileSetup",
                    "SpellProjectileSetPhysicsState", "AddPhysicsObj", "AddWorldObject", "IsProjectileVisible",
                    "LaunchProjectile", "LaunchSpellProjectile", "UpdateObjectPhysics")


def audit_table() -> str:
    text = (ROOT / "docs" / "oracle.md").read_text()
    start = text.index("## Decisions the harness makes on ACE's behalf (the audit)")
    end = text.index("\n## ", start + 1)
    rows = [line for line in text[start:end].splitlines() if line.startswith("| ") and not line.startswith("|---")]
    assert len(rows) > 40, "the audit table was not found"
    return "\n".join(rows)


def reflected_members() -> set[str]:
    """Every member the facade names by string (GetField / GetMethod / GetProperty, backing fields)."""
    names = set(re.findall(r'Get(?:Field|Method|Property)\("([^"]+)"', FACADE))
    names |= set(re.findall(r'"(<\w+>k__BackingField)"', FACADE))
    return names


def test_every_member_the_facade_reaches_by_reflection_is_named_in_the_audit_table():
    table = audit_table()
    members = reflected_members()
    assert {"SetAdjacents", "adjacents", "landblocks", "PortalYearTicks", "<CellLandblock>k__BackingField"} <= members
    missing = sorted(m for m in members if m.replace("<", "").split(">")[0] not in table)
    assert missing == []


def test_every_object_the_facade_makes_without_its_constructor_is_named_in_the_audit_table():
    table = audit_table()
    made = re.findall(r"GetUninitializedObject\(", FACADE)
    assert len(made) == 3  # the DAT databases (InstallDat), the server Landblock (MakeServerLandblock), a Player
    assert "PortalDatDatabase" in table and "CellDatDatabase" in table
    assert "otherwise uninitialized" in table  # a build's Player without a parameterless constructor (MakePlayer)
    assert "server `Landblock`" in table and "without its DAT-reading constructor" in table


def test_every_server_sequence_the_facade_runs_is_a_method_of_it_named_in_the_audit_table():
    table = audit_table()
    for name in SERVER_SEQUENCES:
        assert re.search(r"static [\w.]+(?:<[^>]*>)? " + name + r"\(", FACADE), f"Facade.cs has no method {name}"
    assert [name for name in SERVER_SEQUENCES if f"`Facade.{name}`" not in table] == []
