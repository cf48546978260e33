"""LandblockManager's adjacency bookkeeping in the port (port/land/landblock_manager.py), as ACE's
LandblockManager.GetLandblock / SetAdjacents give it: ACE's order, the neighbours loaded before a
landblock, none for a dungeon, none past the world's edge, null in client mode."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from acconform.numerics import get_mode
from acconform.port.errors import NullReferenceException
from acconform.port.land.landblock_manager import Adjacency, LandblockManager, ServerLandblock
from acconform.port.run import run_scene, scene_world
from acconform.scene import Landblock as LandblockRecord

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))
from server_scenes import request_pos_scene  # noqa: E402


class _Info:
    def __init__(self, num_cells, buildings=()):
        self.num_cells = num_cells
        self.buildings = list(buildings)


class _NoLScape:
    landblocks: dict = {}


def _server(x, y, heights=None, info=None):
    record = LandblockRecord(id=(x << 24) | (y << 16) | 0xFFFF, heights=heights or (1,) * 81)
    return ServerLandblock(record, info, _NoLScape())


def _xy(landblocks):
    return [(lb.landblock_x, lb.landblock_y) for lb in landblocks]


@pytest.mark.anchor("ACE.Server/Managers/LandblockManager.cs:GetAdjacentIDs")
def test_adjacent_ids_come_in_aces_order_north_south_west_east_then_the_diagonals():
    manager = LandblockManager()
    assert manager.get_adjacent_ids(_server(0x10, 0x20)) == [
        (0x10, 0x21), (0x10, 0x1F), (0x0F, 0x20), (0x11, 0x20),
        (0x0F, 0x21), (0x11, 0x21), (0x0F, 0x1F), (0x11, 0x1F)]


@pytest.mark.anchor("ACE.Server/Managers/LandblockManager.cs:GetAdjacentID")
def test_there_is_no_adjacent_past_the_worlds_edge():
    manager = LandblockManager()
    assert manager.get_adjacent_id(_server(0, 0x20), Adjacency.West) is None
    assert manager.get_adjacent_id(_server(0xFE, 0x20), Adjacency.East) is None
    assert manager.get_adjacent_ids(_server(0, 0)) == [(0, 1), (1, 0), (1, 1)]


@pytest.mark.anchor("ACE.Server/Managers/LandblockManager.cs:SetAdjacents")
def test_a_landblock_gets_the_neighbours_loaded_before_it_and_they_get_it_on_the_server_side_only():
    """SetAdjacents(landblock, traverse: true, pSync: true) at each load; the traverse runs without pSync,
    so the first landblock's physics adjacents stay what its own load gave it (none)."""
    manager = LandblockManager()
    a, b, c = _server(0x10, 0x20), _server(0x11, 0x20), _server(0x10, 0x21)
    for lb in (a, b, c):
        manager.get_landblock(lb.raw, lambda: lb)
    assert _xy(a.physics_adjacents) == []
    assert _xy(b.physics_adjacents) == [(0x10, 0x20)]
    assert _xy(c.physics_adjacents) == [(0x10, 0x20), (0x11, 0x20)]  # south, then south-east
    assert _xy(a.adjacents) == [(0x10, 0x21), (0x11, 0x20)]  # north, east: the server side knows both
    assert manager.get_landblock(0x1020FFFF, lambda: _server(0x10, 0x20)) is a  # loaded once


@pytest.mark.anchor("ACE.Server/Entity/Landblock.cs:IsDungeon")
def test_a_dungeon_has_no_adjacents_and_the_nw_island_is_never_a_dungeon():
    flat = (0,) * 81
    assert _server(0x10, 0x20, flat, _Info(3)).is_dungeon()
    assert not _server(0x10, 0x20, flat, _Info(3, ["a building"])).is_dungeon()
    assert not _server(0x10, 0x20, flat, None).is_dungeon()
    assert not _server(0x10, 0x20, (1,) + flat[1:], _Info(3)).is_dungeon()
    assert not _server(0x07, 0xF9, flat, _Info(3)).is_dungeon()  # the NW island hack
    manager = LandblockManager()
    manager.get_landblock(0x1120FFFF, lambda: _server(0x11, 0x20))
    dungeon = manager.get_landblock(0x1020FFFF, lambda: _server(0x10, 0x20, flat, _Info(3)))
    assert dungeon.physics_adjacents == [] and manager.landblocks[(0x11, 0x20)].adjacents == []


@pytest.mark.anchor("Landblock.cs:GetServerObjects")
def test_in_server_mode_the_landblock_has_its_adjacents_and_the_cell_change_throws_nothing():
    out = run_scene(request_pos_scene("server"), runtime="coreclr")
    assert out.error is None and all(t.error is None for t in out.ticks), out.ticks
    assert out.ticks[4].cell == 0xA9B40009


@pytest.mark.anchor("Landblock.cs:GetServerObjects")
def test_in_client_mode_the_player_path_has_no_request_pos_and_throws_in_its_first_tick_as_in_ace():
    run_scene(request_pos_scene("server"), runtime="coreclr")  # its landblock goes back to the pool with adjacents
    out = run_scene(request_pos_scene("client"), runtime="coreclr")  # PhysicsObj() makes RequestPos in server mode only
    assert len(out.ticks) == 1 and out.ticks[0].error.startswith("NullReferenceException"), out.ticks


def test_the_lscape_loads_the_scenes_landblocks_in_server_mode_only():
    scene = request_pos_scene("server")
    mode = get_mode("exact", "coreclr")
    lscape, _, _ = scene_world(scene, mode)
    try:
        assert list(lscape.landblock_manager.landblocks) == [(0xA9, 0xB4)]
        assert lscape.get_landblock(0xA9B4FFFF).adjacents == []
    finally:
        lscape.release()
    lscape, _, _ = scene_world(scene.replace(engine_mode="client"), mode)
    try:
        assert lscape.landblock_manager is None
        with pytest.raises(NullReferenceException):
            lscape.get_landblock(0xA9B4FFFF).get_server_objects(True)
    finally:
        lscape.release()
