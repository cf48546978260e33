"""Landblock, LandCell and LScape (port/land/landblock.py, land_cell.py, lscape.py): cells, GetZ, outside cells."""

from __future__ import annotations

import numpy as np
import pytest

from acconform.numerics import EXACT, FAST, f32_bits
from acconform.port.frame import AFrame, Position
from acconform.port.cell import land_cell as lc
from acconform.port.errors import ArgumentOutOfRangeException
from acconform.port.land_defs import InvalidOperation, WaterType

from land_helpers import WATER, CellArrayStub, SphereStub, landblock, world

F = np.float32
NE = 0xFEFEFFFF  # global cell (2039, 2039) = cell 0x40 here cuts SE-NW (first branch, mono)


def slope_world(mode=EXACT):
    heights = [0] * 81
    heights[8 * 9 + 8] = 12  # vertex (8, 8) at 24 m; the rest of cell 0x40 at 0
    return world(landblock(NE, heights), mode=mode)


@pytest.mark.anchor("CLandBlock::GetZ")
def test_get_z_on_the_flat_triangle_is_negative_zero_as_ace_computes_it():
    w = slope_world()
    lb = w.get_landblock(NE)
    z = lb.get_z(w, EXACT.vec(170, 170, 5))
    # plane z = 0 with D = -(0/3) = -0: (0 + -0) / 1 * -1 = -0
    assert f32_bits(z) == 0x80000000


@pytest.mark.anchor("CLandBlock::GetZ")
def test_get_z_on_the_sloped_triangle_follows_its_plane():
    w = slope_world()
    z = w.get_landblock(NE).get_z(w, EXACT.vec(190, 190, 5))
    assert abs(float(z) - 20.0) < 1e-4  # plane through (192,168,0), (168,192,0), (192,192,24)
    zf = slope_world(FAST).get_landblock(NE).get_z(slope_world(FAST), FAST.vec(190, 190, 5))
    assert type(zf) is np.float64 and abs(zf - 20.0) < 1e-9


@pytest.mark.anchor("CLandCell::find_terrain_poly")
def test_a_point_on_the_diagonal_belongs_to_the_first_triangle():
    w = slope_world()
    cell = w.get_landcell(0xFEFE0040)
    found, poly = cell.find_terrain_poly(EXACT.vec(180, 180, 0))
    assert found and poly is cell.polygons[0]
    found, poly = cell.find_terrain_poly(EXACT.vec(191, 191, 0))
    assert found and poly is cell.polygons[1]


@pytest.mark.anchor("CLandCell::find_terrain_poly")
def test_points_on_cell_edges_count_as_inside_and_outside_points_keep_walkable():
    cell = slope_world().get_landcell(0xFEFE0040)
    for p in ((168, 170), (192, 170), (170, 168), (170, 192), (168, 168), (192, 192)):
        assert cell.point_in_cell(EXACT.vec(*p, 0)), p
    sentinel = object()
    assert cell.find_terrain_poly(EXACT.vec(167.9, 170, 0), sentinel) == (False, sentinel)


@pytest.mark.anchor("CLandBlock::GetCell")
def test_get_cell_at_192_takes_no_cell_for_x_and_the_next_column_for_y():
    w = slope_world()
    lb = w.get_landblock(NE)
    assert lb.get_cell(w, EXACT.vec(192, 10, 0)) is None  # id 0x41..: not a land cell
    assert lb.get_cell(w, EXACT.vec(10, 192, 0)).id == 0xFEFE0009  # cell (1, 0)
    assert lb.get_cell(w, EXACT.vec(-0.0, 0, 0)).id == 0xFEFE0001
    assert lb.get_cell(w, EXACT.vec(-0.01, 0, 0)) is None
    # so GetZ there falls back to the point's own z
    assert lb.get_z(w, EXACT.vec(10, 192, 7)) == 7
    assert lb.get_z(w, EXACT.vec(192.5, 10, 7)) == 7


@pytest.mark.anchor("CLandBlock::get_landcell")
def test_landblock_get_landcell_checks_the_id_and_raises_where_ace_throws():
    w = slope_world()
    lb = w.get_landblock(NE)
    assert lb.get_landcell(0xFEFE0040).id == 0xFEFE0040
    assert lb.get_landcell(0xA9B40040) is None  # same slot, other block
    with pytest.raises(InvalidOperation):
        lb.get_landcell(0xFEFE0041)


@pytest.mark.anchor("LScape::get_landcell")
def test_lscape_finds_cells_of_listed_landblocks_only():
    w = world(landblock(0xA9B4FFFF), landblock(0xAAB4FFFF))
    assert w.get_landcell(0xAAB40005).id == 0xAAB40005
    assert w.get_landcell(0xAAB40005).cur_landblock is w.get_landblock(0xAAB40000)
    with pytest.raises(ArgumentOutOfRangeException, match="Height"):
        w.get_landcell(0xABB40005)  # not in the scene: ACE reads its DAT, an empty CellLandblock, and throws building it
    assert w.get_landcell(0xA9B40041) is None
    assert w.get_landblock(0xA9B40017) is w.get_landblock(0xA9B4FFFF)


@pytest.mark.anchor("CObjCell::get_water_depth")
def test_water_depth_of_cells():
    terrain = [0] * 81
    for i in (0, 1, 9, 10):
        terrain[i] = WATER
    terrain[9 * 3 + 3] = WATER
    w = world(landblock(0xA9B4FFFF, terrain=terrain))
    full, part, dry = (w.get_landcell(0xA9B40000 | c) for c in (1, 8 * 3 + 3 + 1, 8 * 5 + 5 + 1))
    assert (full.water_type, part.water_type, dry.water_type) == (WaterType.EntirelyWater, WaterType.PartiallyWater, WaterType.NotWater)
    assert f32_bits(full.get_water_depth(EXACT.vec(1, 1, 0))) == 0x3F666666  # 0.89999998f
    assert f32_bits(part.get_water_depth(EXACT.vec(73, 73, 0))) == 0x3EE66666  # 73 % 24 = 1: SW corner (3,3), water
    assert f32_bits(part.get_water_depth(EXACT.vec(70, 70, 0))) == 0x3DCCCCCD  # 70 % 24 = 22: NE corner, dry
    assert dry.get_water_depth(EXACT.vec(1, 1, 0)) == 0
    assert full.get_block_water_type() == WaterType.PartiallyWater


@pytest.mark.anchor("CLandCell::add_all_outside_cells")
def test_a_sphere_near_a_corner_adds_the_four_cells_across_blocks():
    w = world(landblock(0xA9B4FFFF), landblock(0xAAB4FFFF), landblock(0xA9B5FFFF), landblock(0xAAB5FFFF))
    ca = CellArrayStub()
    pos = Position(0xA9B40040, AFrame.identity(EXACT))
    lc.add_all_outside_cells(w, pos, 1, [SphereStub(EXACT.vec(191.8, 191.8, 0.5), F(0.5))], ca)
    assert sorted(ca.cells) == [0xA9B40040, 0xA9B50039, 0xAAB40008, 0xAAB50001]
    assert ca.added_outside is False  # this overload never sets it


@pytest.mark.anchor("CLandCell::check_add_cell_boundary")
def test_neighbours_west_of_the_world_are_skipped_because_mono_wraps_negative_uint():
    w = world(landblock(0x0000FFFF))
    ca = CellArrayStub()
    lc.add_all_outside_cells(w, Position(0x00000001, AFrame.identity(EXACT)), 1,
                             [SphereStub(EXACT.vec(0.2, 0.2, 0.5), F(0.5))], ca)
    assert sorted(ca.cells) == [0x00000001]  # (uint)(-1.0f) on mono is 0xFFFFFFFF, not 0


@pytest.mark.anchor("CLandCell::add_all_outside_cells")
def test_without_spheres_the_position_itself_is_moved_outside():
    w = world(landblock(0xA9B4FFFF), landblock(0xAAB4FFFF))
    ca = CellArrayStub()
    pos = Position(0xA9B40001, AFrame(EXACT.vec(200, 5, 0), EXACT.quat(0, 0, 0, 1)))
    lc.add_all_outside_cells(w, pos, 0, [], ca)
    assert pos.obj_cell_id == 0xAAB40001 and pos.frame.origin.x == 8
    assert sorted(ca.cells) == [0xAAB40001]
    ca.added_outside = True
    lc.add_all_outside_cells(w, Position(0xA9B40001, AFrame.identity(EXACT)), 0, [], ca)
    assert sorted(ca.cells) == [0xAAB40001]


@pytest.mark.anchor("CLandCell::add_cell_block")
def test_add_cell_block_keeps_only_cells_of_the_given_block():
    w = world(landblock(0xA9B4FFFF), landblock(0xAAB4FFFF))
    ca = CellArrayStub()
    lc.add_cell_block(w, 1358, 1440, 1361, 1441, ca, 0xA9B40001)
    # x 1358..1361: 1360 and 1361 are block 0xAA, dropped by ACE's "FIXME" same-block test
    assert sorted(ca.cells) == [0xA9B40031, 0xA9B40032, 0xA9B40039, 0xA9B4003A]


def test_replayed_outside_cells_leave_the_cell_array_as_running_it_again_does():
    """add_all_outside_cells_replayed (the per-run memory) against ACE's routine run every time:
    same cells in the same .NET entry order, from a fresh array and from one already holding
    cells, over spheres placed across cell and block borders, repeats included."""
    from acconform.port.transition.cell_array import CellArray

    w = world(*(landblock(((0xA8 + i) << 24) | ((0xB3 + j) << 16) | 0xFFFF) for i in range(4) for j in range(4)))
    rng = np.random.default_rng(5)
    coords = [0.0, -0.0, 0.3, 23.8, 24.0, 24.2, 100.0, 191.7, 191.99]
    calls = 0
    for trial in range(400):
        # few cells (in two blocks), so inputs meet again
        cell = int(rng.choice([0xA9B40000, 0xAAB50000])) | int(rng.choice([1, 8, 57, 64]))
        spheres = [SphereStub(EXACT.vec(F(rng.choice(coords)) + F(rng.integers(0, 2) * 48),
                                        F(rng.choice(coords)), 0.5), F(rng.choice([0.3, 0.5, 2.0])))
                   for _ in range(int(rng.integers(1, 3)))]
        direct, replayed = CellArray(), CellArray()
        for ca in (direct, replayed):
            ca.add_cell(0xA9B40001, w.get_landcell(0xA9B40001))  # an earlier step's cell
        for _ in range(2):  # the second call is answered from memory
            lc.add_all_outside_cells(w, Position(cell, AFrame.identity(EXACT)), len(spheres), spheres, direct)
            lc.add_all_outside_cells_replayed(w, Position(cell, AFrame.identity(EXACT)), len(spheres), spheres,
                                              replayed)
            calls += 1
        assert direct.cells.keys() == replayed.cells.keys()
        assert direct.num_cells == replayed.num_cells
        # a removed cell comes back: the array's memory of its last replay ends at remove_cell
        gone = w.get_landcell(direct.cells.keys()[-1])
        for ca in (direct, replayed):
            ca.remove_cell(gone)
        lc.add_all_outside_cells(w, Position(cell, AFrame.identity(EXACT)), len(spheres), spheres, direct)
        lc.add_all_outside_cells_replayed(w, Position(cell, AFrame.identity(EXACT)), len(spheres), spheres, replayed)
        assert direct.cells.keys() == replayed.cells.keys() and direct.num_cells == replayed.num_cells
    assert calls == 800 and len(w.outside_cells) > 50  # the memory was used, and for many inputs


@pytest.mark.anchor("CLandCell::find_terrain_poly")
def test_a_cells_remembered_terrain_polygon_answers_are_the_triangle_test_itself():
    """find_terrain_poly's per-cell memory against the two point_in_poly2D tests run directly, on
    points on and around both triangles' edges (the diagonal, the cell's sides, +-0), asked twice."""
    from acconform.port.geom.polygon import Sidedness

    w = slope_world()
    cell = w.get_landcell(NE - 0xFFFF + 0x40)
    rng = np.random.default_rng(7)
    coords = [-0.0, 0.0, 168.0, 168.00002, 179.99998, 180.0, 191.99998, 192.0, 192.00002, 170.5]
    points = [EXACT.vec(F(rng.choice(coords)), F(rng.choice(coords)), 3.0) for _ in range(300)]
    points += [EXACT.vec(F(x), F(x), 1.0) for x in (168.0, 180.0, 192.0)]  # on the diagonal
    for p in points + points:
        direct = next((poly for poly in cell.polygons if poly.point_in_poly2D(p, Sidedness.Positive)), None)
        found, poly = cell.find_terrain_poly(p, None)
        assert (found, poly) == (direct is not None, direct)
    assert 0 < len(cell.terrain_polys) <= len(points)
