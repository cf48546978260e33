"""LandDefs (port/land/land_defs.py): cell-id and land-coordinate arithmetic, hand-checked."""

from __future__ import annotations

import math

import numpy as np
import pytest

from acconform.numerics import EXACT, FAST, MONO, NET10
from acconform.port.constants import EPSILON
from acconform.port import land_defs as ld

F = np.float32


@pytest.mark.anchor("LandDefs::blockid_to_lcoord")
@pytest.mark.parametrize("cell, want", [(0xA9B4FFFF, (1352.0, 1440.0)), (0x0000FFFF, (0.0, 0.0)),
                                        (0xFEFE0001, (2032.0, 2032.0)), (0xFF000001, None), (0x00FFFFFF, None)])
def test_blockid_to_lcoord_is_eight_cells_per_block_and_stops_at_2040(cell, want):
    assert ld.blockid_to_lcoord(cell) == want


@pytest.mark.anchor("LandDefs::gid_to_lcoord")
@pytest.mark.parametrize("cell, env_check, want", [
    (0xA9B40001, True, (1352.0, 1440.0)),
    (0xA9B40009, True, (1353.0, 1440.0)),  # cells run x-major: 9 is x + 1
    (0xA9B40040, True, (1359.0, 1447.0)),
    (0xA9B40041, True, None),  # 65 is no land cell
    (0xA9B40000, True, None),
    (0xA9B40100, True, None),  # an EnvCell id
    (0xA9B40100, False, (1383.0, 1447.0)),  # without the env check: (0x100 - 1) >> 3 = 31 columns on
    (0x00FF0001, True, None),  # inbound_valid_cellid passes (it checks x only) but y = 2040
])
def test_gid_to_lcoord(cell, env_check, want):
    assert ld.gid_to_lcoord(cell, env_check) == want


@pytest.mark.anchor("LandDefs::inbound_valid_cellid")
def test_inbound_valid_cellid_checks_the_block_x_only():
    assert ld.inbound_valid_cellid(0x00FF0001)
    assert not ld.inbound_valid_cellid(0xFF000001)
    assert not ld.inbound_valid_cellid(0x00000041)
    assert ld.inbound_valid_cellid(0x0000FFFF)


@pytest.mark.anchor("LandDefs::lcoord_to_gid")
@pytest.mark.parametrize("x, y, want", [
    (1352.0, 1440.0, 0xA9B40001 - 2**32),  # C# int: negative from column 0x80 on
    (1359.0, 1447.0, 0xA9B40040 - 2**32),
    (8.0, 0.0, 0x01000001), (0.0, 0.0, 0x00000001),
    (-1.0, 0.0, 0), (0.0, 2040.0, 0), (2039.9, 0.0, 0xFE000039 - 2**32),
    (math.nan, 0.0, 0),  # mono: (int)NaN is int.MinValue, out of range
])
def test_lcoord_to_gid(x, y, want):
    assert ld.lcoord_to_gid(F(x), F(y), MONO) == want
    if not math.isnan(x):  # .NET 10: (int)NaN is 0 (test_adjust_to_outside_of_a_nan_point_names_no_cell_on_mono...)
        assert ld.lcoord_to_gid(F(x), F(y), NET10) == want


@pytest.mark.anchor("LandDefs::get_outside_lcoord")
def test_get_outside_lcoord_floors_in_float32():
    assert ld.get_outside_lcoord(0xA9B40001, F(-0.1), F(5)) == (1351.0, 1440.0)
    assert ld.get_outside_lcoord(0xA9B40001, F(200), F(5)) == (1360.0, 1440.0)
    # the float32 just below 24 divides to 0.99999994: still cell 0
    below = np.nextafter(F(24), F(0))
    assert ld.get_outside_lcoord(0xA9B40001, below, F(0)) == (1352.0, 1440.0)
    # a denormal negative x divides to -0 in float32 (floor -0: same cell); in double it is cell -1
    tiny = np.nextafter(F(-0.0), F(-1))
    assert ld.get_outside_lcoord(0xA9B40001, tiny, F(0)) == (1352.0, 1440.0)
    assert ld.get_outside_lcoord(0xA9B40001, np.float64(tiny), np.float64(0)) == (1351.0, 1440.0)
    assert ld.get_outside_lcoord(0x00000001, F(-0.5), F(0)) is None  # west of the world
    assert ld.get_outside_lcoord(0xA9B40041, F(1), F(1)) is None  # not a cell in range


@pytest.mark.anchor("LandDefs::adjust_to_outside")
def test_adjust_to_outside_moves_across_block_edges():
    ok, cell, loc = ld.adjust_to_outside(0xA9B40001, EXACT.vec(-0.5, 10, 3), EXACT.runtime)
    assert ok and cell == 0xA8B40039 and loc == EXACT.vec(191.5, 10, 3)
    ok, cell, loc = ld.adjust_to_outside(0xA9B40001, EXACT.vec(192, 10, 0), EXACT.runtime)
    assert ok and cell == 0xAAB40001 and loc == EXACT.vec(0, 10, 0)
    ok, cell, loc = ld.adjust_to_outside(0xA9B40001, EXACT.vec(30, 200, 0), EXACT.runtime)
    assert ok and cell == 0xA9B50009 and loc == EXACT.vec(30, 8, 0)
    ok, cell, loc = ld.adjust_to_outside(0xA9B4FFFF, EXACT.vec(100, 100, 0), EXACT.runtime)  # a block id works too
    assert ok and cell == 0xA9B40025


@pytest.mark.anchor("LandDefs::adjust_to_outside")
def test_adjust_to_outside_snaps_below_epsilon_to_zero_but_not_at_epsilon():
    just_under = np.nextafter(F(-EPSILON), F(0))
    ok, cell, loc = ld.adjust_to_outside(0xA9B40001, EXACT.vec(just_under, 5, 0), EXACT.runtime)
    assert ok and cell == 0xA9B40001 and loc.x == 0 and not np.signbit(loc.x)
    ok, cell, loc = ld.adjust_to_outside(0xA9B40001, EXACT.vec(-EPSILON, 5, 0), EXACT.runtime)
    assert ok and cell == 0xA8B40039 and loc.x == F(192) - F(EPSILON)


@pytest.mark.anchor("LandDefs::adjust_to_outside")
def test_adjust_to_outside_fails_with_cell_zero_and_keeps_the_snapped_point():
    ok, cell, loc = ld.adjust_to_outside(0x00000001, EXACT.vec(-5, F(1e-5), 0), EXACT.runtime)
    assert (ok, cell) == (False, 0) and loc.y == 0
    ok, cell, _ = ld.adjust_to_outside(0xA9B40041, EXACT.vec(5, 5, 0), EXACT.runtime)
    assert (ok, cell) == (False, 0)


@pytest.mark.anchor("LandDefs::adjust_to_outside")
def test_adjust_to_outside_of_a_nan_point_names_no_cell_on_mono_and_landblock_column_0_on_net10():
    # NaN passes get_outside_lcoord's range test; lcoord_to_gid's (int)NaN is int.MinValue on mono
    # (no cell: 0) and 0 on .NET 10 (land x 0: landblock 0x00YY)
    nan = EXACT.vec(math.nan, 5, 0)
    assert ld.adjust_to_outside(0xA9B40001, nan, MONO)[:2] == (True, 0)
    assert ld.adjust_to_outside(0xA9B40001, nan, NET10)[:2] == (True, 0x00B40001)


@pytest.mark.anchor("LandDefs::get_block_offset")
def test_get_block_offset():
    assert ld.get_block_offset(0xA9B40001, 0xA9B40040) == EXACT.vec(0, 0, 0)
    assert ld.get_block_offset(0xA9B40001, 0xAAB30005) == EXACT.vec(192, -192, 0)
    with pytest.raises(ld.InvalidOperation):
        ld.get_block_offset(0xFE000001, 0xFF000001)


@pytest.mark.anchor("LandDefs::get_block_offset")
def test_remembered_block_offsets_are_the_routine_run_every_time_and_a_throwing_pair_throws_each_time():
    cells = [0xA9B40001, 0xA9B40040, 0xAAB30005, 0x00000001, 0x01FE0009, 0xFE010001, 0x7F7F0100]
    for _ in range(2):  # the second round is answered from memory
        for a in cells:
            for b in cells:
                want = EXACT.vec(0, 0, 0) if a >> 16 == b >> 16 else ld._block_offset(a, b)
                assert ld.get_block_offset(a, b) == want
    for _ in range(2):
        with pytest.raises(ld.InvalidOperation):
            ld.get_block_offset(0xA9B40001, 0xA9FF0001)


@pytest.mark.anchor("LandDefs::in_block")
def test_in_block_keeps_radius_from_every_edge():
    assert ld.in_block(EXACT.vec(1, 1, 0), F(1))
    assert not ld.in_block(EXACT.vec(0.99, 100, 0), F(1))
    assert not ld.in_block(EXACT.vec(100, 191, 0), F(1))
    assert ld.in_block(FAST.vec(190.9, 100, 0), 1.0)


@pytest.mark.anchor("LandDefs::cell_in_range")
@pytest.mark.parametrize("cell, want", [(0, False), (1, True), (64, True), (65, False), (0xFF, False),
                                        (0x100, True), (0xFFFD, True), (0xFFFE, False), (0xFFFF, True)])
def test_cell_in_range(cell, want):
    assert ld.cell_in_range(cell) is want
