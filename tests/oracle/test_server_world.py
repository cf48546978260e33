"""The world loaded as ACE's server loads it (issue 44), asked of live ACE on each runtime and of the port.

A running server's LandblockManager gives each landblock it loads its adjacent landblocks
(SetAdjacents); Landblock.GetServerObjects(true), which a server-mode cell change reaches
(change_cell_server -> enter_cell_server -> handle_visible_cells -> ObjectMaint.GetVisibleObjects),
reads them. The facade loads a server-mode scene's landblocks through ACE's own SetAdjacents, in the
scene's order (docs/oracle.md, the audit); the port mirrors it (port/land/landblock_manager.py). In
client mode no LandblockManager loads them, and the player path has no RequestPos to request with.
Run with ACE_ASSEMBLY at a mono build, then at a .NET 10 build (one runtime per process).
"""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from acconform.case import load_document
from acconform.compare import compare
from acconform.port.run import run_scene
from acconform.scene import Landblock

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from server_scenes import request_pos_scene  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]


def _neighbours(scene):
    """The scene with its landblock's eight neighbours listed too, flat (ACE loads them, in this order,
    after the scene's own: each gets the ones loaded before it)."""
    home = scene.landblocks[0]
    x, y = home.id >> 24, (home.id >> 16) & 0xFF
    more = tuple(Landblock(id=((x + dx) << 24) | ((y + dy) << 16) | 0xFFFF, heights=home.heights, terrain=home.terrain)
                 for dx, dy in ((0, 1), (0, -1), (-1, 0), (1, 0), (-1, 1), (1, 1), (-1, -1), (1, -1)))
    return scene.replace(landblocks=scene.landblocks + more)


@pytest.mark.live_oracle
def test_live_in_server_mode_the_cell_change_that_threw_in_client_mode_moves_the_mover(live):
    scene = request_pos_scene("server")
    ace = live.run(scene)
    assert ace.error is None and all(t.error is None for t in ace.ticks), ace.ticks
    assert ace.ticks[4].cell == 0xA9B40009 and ace.ticks[5].cell == 0xA9B40001
    assert compare(ace, run_scene(scene, runtime=live.location.runtime), "exact") == []


@pytest.mark.live_oracle
def test_live_a_server_scene_with_loaded_neighbours_answers_as_the_port(live):
    scene = _neighbours(request_pos_scene("server"))
    ace = live.run(scene)
    assert all(t.error is None for t in ace.ticks), ace.ticks
    assert compare(ace, run_scene(scene, runtime=live.location.runtime), "exact") == []


@pytest.mark.live_oracle
def test_live_in_client_mode_the_player_path_throws_in_its_first_tick_after_a_server_scene_used_the_landblock(live):
    """A client-mode PhysicsObj has no RequestPos (the constructor makes one in server mode only), so
    set_request_pos throws in the first request_pos tick; the server scene before it leaves nothing behind."""
    live.run(request_pos_scene("server"))
    ace = live.run(request_pos_scene("client"))
    assert len(ace.ticks) == 1 and ace.ticks[0].error.startswith("NullReferenceException"), ace.ticks
    assert compare(ace, run_scene(request_pos_scene("client"), runtime=live.location.runtime), "exact") == []


@pytest.mark.live_oracle
def test_live_a_placement_in_server_mode_enters_its_cell_through_enter_cell_server_as_the_port(live):
    scene = load_document(ROOT / "examples" / "placement_wall_push.json").replace(engine_mode="server")
    ace = live.run(scene)
    assert ace.error is None and ace.placement is not None and ace.placement.cur_cell != 0, ace
    assert compare(ace, run_scene(scene, runtime=live.location.runtime), "exact") == []
