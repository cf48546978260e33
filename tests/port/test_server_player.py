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
