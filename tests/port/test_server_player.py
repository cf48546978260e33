"""The port's half of tests/oracle/test_server_player.py (the mover as a running server's player, issue 44):
the same scenes, the port's answers, without ACE."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from acconform.flags import ObjectInfoState, SetPositionError
from acconform.port.run import run_scene

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from server_scenes import failed_entry_scene, landblock_info_as_env_cell_scene, request_pos_scene, transition_scene  # noqa: E402


@pytest.mark.anchor("CPhysicsObj::enter_world")
def test_a_failed_enter_world_keeps_the_requested_cell_and_frame():
    scene = failed_entry_scene()
    out = run_scene(scene)
    assert out.placement.result == SetPositionError.GeneralFailure and out.placement.cur_cell == 0
    assert out.placement.cell == scene.mover.begin.cell and out.placement.origin == scene.mover.begin.frame.origin


@pytest.mark.anchor("CPhysicsObj::get_object_info")
def test_the_players_transition_carries_is_player_in_its_object_info():
    assert run_scene(transition_scene()).object_info_state & ObjectInfoState.IsPlayer


def test_a_request_pos_into_another_land_cell_takes_the_terrains_contact_plane_while_last_contact_holds():
    tick = run_scene(request_pos_scene("server")).ticks[4]
    assert tick.cell == tick.contact_plane_cell == 0xA9B40009 and tick.contact_plane.normal == (0.0, 0.0, 1.0)


def test_a_landblock_info_id_read_as_an_env_cell_is_an_invalid_cast():
    assert run_scene(landblock_info_as_env_cell_scene()).error.startswith("InvalidCastException")


def _shard_scene(runtime: str, wanted):
    """The first scene of shard ticks-0063 (`runtime`'s) that `wanted` accepts, with ACE's recorded outcome."""
    import gzip
    import json

    from acconform.case import parse_document

    path = Path(__file__).resolve().parents[1] / "data" / "corpus" / runtime / "ticks-0063.jsonl.gz"
    with gzip.open(path, "rt", encoding="utf-8") as f:
        for line in f:
            rec = parse_document(json.loads(line))
            if wanted(rec.scene):
                return rec.scene, rec.outcome
    raise AssertionError("no such scene in ticks-0063")


@pytest.mark.anchor("PhysicsObj.cs:UpdateObjectInternalServer")
@pytest.mark.parametrize("goal", ["move_to_object", "stick_to"])
def test_the_legacy_player_path_runs_the_movers_target_and_position_managers_as_ace_does(goal):
    """UpdateObjectInternalServer calls the mover's TargetManager.HandleTargetting (made by a MoveToObject's
    set_target) and PositionManager.UseTime (made by stick_to_object) after the transition to RequestPos."""
    from acconform.compare import compare

    scene, ace = _shard_scene("coreclr", lambda s: s.ticks.driver == "request_pos"
                              and getattr(s.ticks.steps[0], goal) is not None)
    out = run_scene(scene, runtime="coreclr")
    assert not any(t.error for t in out.ticks)
    assert compare(ace, out) == []
