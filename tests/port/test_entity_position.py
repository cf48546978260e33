"""A projectile's Location (port/entity_position.py, port/missile_launch.py projectile_location): ACE.Entity.Position's
Pos setter finds the outdoor landblock and cell of the spawn point anew (SetPosition: SetLandblock, SetLandCell), so
a spawn point across a cell line, a landblock's edge or the world's enters the world from its own cell, as ACE's
Creature.LaunchProjectile and LaunchSpellProjectiles make it (ACE.Entity/Position.cs at 7b47913)."""

from __future__ import annotations

import numpy as np
import pytest

from acconform.numerics import Vector3
from acconform.port.entity_position import EntityPosition
from acconform.port.frame import AFrame, Position
from acconform.port.missile_launch import projectile_location

F = np.float32


def _v(x, y, z=10.0):
    return Vector3(F(x), F(y), F(z))


class _Launcher:
    def __init__(self, cell, x, y):
        self.position = Position(cell, AFrame(_v(x, y), None))


@pytest.mark.anchor("ACE.Entity/Position.cs:SetLandCell")
def test_a_spawn_point_across_a_cell_line_takes_the_next_cell():
    location = projectile_location(_Launcher(0xA9B40031, 143.6, 100.0), _v(144.4, 100.0))  # x = 144: cell column 6
    assert location.landblock_id == 0xA9B40035 and location.pos == _v(144.4, 100.0)


@pytest.mark.anchor("ACE.Entity/Position.cs:SetLandblock")
def test_a_spawn_point_past_the_landblock_moves_onto_the_next_landblock_192_m_back():
    location = projectile_location(_Launcher(0xA9B40039, 191.6, 100.0), _v(192.4, 100.0))
    assert location.landblock_id == 0xAAB40005  # x 0xAA, cell column 0
    assert location.pos.x == F(192.4) - F(192) and location.pos.y == F(100.0)


@pytest.mark.anchor("ACE.Entity/Position.cs:SetLandblock")
def test_past_the_worlds_east_edge_x_is_clamped_to_192_and_the_cell_id_runs_past_64():
    location = projectile_location(_Launcher(0xFE400039, 191.6, 100.0), _v(192.4, 100.0))
    assert location.pos.x == F(192.0)
    assert location.landblock_id == 0xFE400045  # 8 * 8 + 4 + 1: no cell of the landblock (get_landcell refuses it)


@pytest.mark.anchor("ACE.Entity/Position.cs:SetLandblock")
def test_past_the_worlds_south_edge_y_is_clamped_to_0_a_cell_of_the_landblock():
    location = projectile_location(_Launcher(0x40000029, 100.0, 0.3), _v(100.0, -0.5))
    assert location.landblock_id == 0x40000021 and location.pos.y == F(0.0)


@pytest.mark.anchor("ACE.Entity/Position.cs:SetLandblock")
def test_a_point_a_hair_south_of_the_line_crosses_and_comes_back_as_csharp_computes_it():
    """-1e-8: (int) truncates to 0, so the offset is -1; -1e-8 + 192 rounds to 192.0f, so the second test moves it back."""
    p = EntityPosition(0x40B40001, _v(1.0, 1.0), None)
    p.set_position(_v(1.0, -1e-8))
    assert p.landblock_id == 0x40B40001 and p.pos.y == F(0.0)


@pytest.mark.anchor("ACE.Entity/Position.cs:SetPosition")
def test_an_indoor_location_keeps_its_cell_and_its_pos():
    p = EntityPosition(0xA9B40105, _v(10.0, 10.0), None)
    p.set_position(_v(300.0, -5.0))
    assert p.landblock_id == 0xA9B40105 and p.pos == _v(300.0, -5.0)


@pytest.mark.anchor("ACE.Entity/Position.cs:SetLandblock")
def test_a_spell_cast_out_over_the_worlds_east_edge_never_enters_the_world():
    """AddPhysicsObj: get_landcell refuses the clamped Location's cell (0xFE40004x), so the spell is destroyed at its
    launch (shard ticks-0068 holds ACE's answers for such scenes)."""
    from hypothesis import strategies as st

    from acconform.port.run import run_scene
    from acconform.strategies.determinism import pinned_constants
    from acconform.strategies.fast_draw import FastDrawer
    from acconform.strategies.missiles import draw_border_scene

    drawer = FastDrawer(st.composite(lambda d: draw_border_scene(d, "world_edge"))(), 7 * 1000003)
    with pinned_constants():
        scene = next(s for s in (drawer.draw()[0] for _ in range(40)) if s.landblocks[0].id >> 16 == 0xFE40)
    spell = next(o for o in scene.others if o.launch is not None)
    out = run_scene(scene, runtime="coreclr")
    assert all(t.error is None for t in out.ticks)
    states = [next(o for o in t.others if o.id == spell.id) for t in out.ticks]
    assert all(s.cur_cell == 0 for s in states)
