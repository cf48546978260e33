"""The mover as a running server's player (issue 44), asked of live ACE on each runtime and of the port.

A server's player is a Creature's PhysicsObj with the WeenieObject of its Player (WorldObject.InitPhysicsObj),
entering the world through PhysicsObj.enter_world (WorldObject.AddPhysicsObj) and moved by the physics calls of
Player.UpdatePlayerPosition; ACE's DATs answer for a record the scene lacks as a DAT lacking the file does (an
empty record). Each test runs one departure the oracle used to make (docs/oracle.md, the audit) and checks
ACE's server answer and the port's agreeing with it, bit for bit. Run with ACE_ASSEMBLY at a mono build,
then at a .NET 10 build (one runtime per process); the port's half runs in the fast lane
(tests/port/test_server_player.py reads the same scenes).
"""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from acconform.compare import compare
from acconform.flags import ObjectInfoState, SetPositionError
from acconform.port.run import run_scene

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from server_scenes import (failed_entry_scene, landblock_info_as_env_cell_scene, request_pos_scene,  # noqa: E402
                           transition_scene)


def both(live, scene):
    ace = live.run(scene)
    assert compare(ace, run_scene(scene, runtime=live.location.runtime), "exact") == []
    return ace


@pytest.mark.live_oracle
@pytest.mark.anchor("CPhysicsObj::enter_world")
def test_live_a_failed_enter_world_keeps_the_requested_cell_and_frame(live):
    scene = failed_entry_scene()
    ace = both(live, scene)
    begin = scene.mover.begin
    assert ace.placement.result == SetPositionError.GeneralFailure
    assert ace.placement.cell == begin.cell and ace.placement.origin == begin.frame.origin


@pytest.mark.live_oracle
@pytest.mark.anchor("CPhysicsObj::get_object_info")
def test_live_the_players_transition_carries_is_player(live):
    ace = both(live, transition_scene())
    assert ace.object_info_state & ObjectInfoState.IsPlayer


@pytest.mark.live_oracle
def test_live_a_request_pos_into_another_land_cell_takes_the_terrains_contact_plane(live):
    ace = both(live, request_pos_scene("server"))
    tick = ace.ticks[4]
    assert tick.cell == tick.contact_plane_cell == 0xA9B40009 and tick.contact_plane.normal == (0.0, 0.0, 1.0)


@pytest.mark.live_oracle
def test_live_a_landblock_info_id_read_as_an_env_cell_is_an_invalid_cast(live):
    ace = both(live, landblock_info_as_env_cell_scene())
    assert ace.error is not None and ace.error.startswith("InvalidCastException"), ace.error
