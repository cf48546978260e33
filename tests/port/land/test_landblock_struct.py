"""LandblockStruct (port/land/landblock_struct.py): the terrain mesh, the split rule, water.

Split hashes and FSplitNESW answers below were computed by mono from ACE's own C# expressions
(uint/long promotion, unchecked int overflow), not by the port.
"""

from __future__ import annotations

import numpy as np
import pytest

from acconform.numerics import EXACT, FAST, f32_bits
from acconform.port.cell.land_cell import is_built
from acconform.port.land import landblock_struct as lbs
from acconform.port.land_defs import WaterType
from acconform.port.land.landblock import Landblock

from land_helpers import WATER, landblock
from lazy_planes import plane_bits, plane_unset

F = np.float32
TABLE = tuple(2.0 * i for i in range(256))


def build(lb_id=0xA9B4FFFF, heights=None, terrain=None, mode=EXACT, table=TABLE):
    return Landblock(landblock(lb_id, heights, terrain), table, mode)


@pytest.mark.anchor("CLandBlockStruct::ConstructPolygons")
@pytest.mark.parametrize("split_dir, first_branch", [
    (0, True), (2**31 - 1, True), (2**31, True), (2**31 + 33, True),  # the double literal is < 2^-32
    (2**31 + 34, False), (2**32 - 1, False),
])
def test_split_rule_compares_in_double_so_2_pow_31_plus_33_still_cuts_se_to_nw(split_dir, first_branch):
    assert lbs.split_cuts_se_to_nw(split_dir) is first_branch


def test_split_scale_is_the_double_literal():
    assert lbs.SPLIT_SCALE == float("2.3283064e-10") and lbs.SPLIT_SCALE < 2.0**-32


# (global cell x, y) -> splitDir as mono computes ACE's expression
MONO_SPLITS = {(0, 0): 2925818075, (657, 1857): 2147484088, (2039, 2039): 944173284,
               (11, 5): 3007762004, (1000, 3): 2646572240, (1352, 1444): 2900567183}


@pytest.mark.anchor("CLandBlockStruct::ConstructPolygons")
@pytest.mark.parametrize("gx, gy", sorted(MONO_SPLITS))
def test_construct_polygons_hashes_global_cell_coordinates_with_csharp_wraparound(gx, gy, monkeypatch):
    seen = []
    monkeypatch.setattr(lbs, "split_cuts_se_to_nw", lambda s: seen.append(s) or s * lbs.SPLIT_SCALE < 0.5)
    lb = build(((gx >> 3) << 24) | ((gy >> 3) << 16) | 0xFFFF)
    idx = (gx & 7) * 8 + (gy & 7)
    assert seen == []  # a cell's polygons are made when the cell is first read
    lb.land_cells[idx].polygons
    assert seen == [MONO_SPLITS[(gx, gy)]]
    assert lb.sw_to_ne_cut[idx] is (not MONO_SPLITS[(gx, gy)] * 2.3283064e-10 < 0.5)


@pytest.mark.anchor("CLandBlockStruct::ConstructPolygons")
def test_no_land_cell_hashes_near_the_split_boundary():
    gx = np.arange(2040, dtype=np.uint64)[:, None]
    gy = np.arange(2040, dtype=np.uint64)[None, :]
    s = (gy * ((214614067 * gx + 1813693831) % 2**32) + 2**34 - (1109124029 * gx) % 2**32 - 1369149221) % 2**32
    d = np.abs(s.astype(np.int64) - 2**31)
    assert d.min() == 440 and tuple(np.argwhere(d == 440)[0]) == (657, 1857)


@pytest.mark.anchor("CLandBlockStruct::ConstructPolygons")
def test_polygons_follow_the_cut_and_cells_get_ids_and_centres():
    lb = build(0xFEFEFFFF)  # cell 63 is global (2039, 2039): first branch (mono)
    cell = lb.land_cells[63]
    assert cell.id == 0xFEFE0040 and cell.pos.obj_cell_id == 0xFEFE0040
    assert cell.pos.frame.origin == EXACT.vec(180, 180, 0)
    assert lb.sw_to_ne_cut[63] is False
    ids = [p.vertex_ids for p in cell.polygons]
    v = lambda x, y: x * 9 + y  # noqa: E731
    assert ids == [[v(7, 7), v(8, 7), v(7, 8)], [v(8, 8), v(7, 8), v(8, 7)]]
    lb0 = build(0x0000FFFF)  # global (0, 0): second branch (mono)
    lb0.land_cells[0].id  # built when first read, its SWtoNEcut entry with it
    assert lb0.sw_to_ne_cut[0] is True
    assert [p.vertex_ids for p in lb0.land_cells[0].polygons] == [[v(0, 0), v(1, 0), v(1, 1)], [v(0, 0), v(1, 1), v(0, 1)]]
    assert lb0.land_cells[0].polygons[0].vertices[2] is lb0.vertex_array[v(1, 1)]  # shared, as ACE's class refs


@pytest.mark.anchor("CLandBlockStruct::ConstructVertices")
def test_vertices_take_heights_through_the_land_height_table():
    table = tuple(F(0.37) * i for i in range(256))
    heights = [0] * 81
    heights[3 * 9 + 4] = 7
    lb = build(heights=heights, table=table)
    assert lb.vertex_array[3 * 9 + 4].origin == EXACT.vec(72, 96, F(0.37) * 7)
    assert f32_bits(lb.vertex_array[3 * 9 + 4].origin.z) == f32_bits(F(F(0.37) * 7))
    assert (lb.min_z, lb.max_z) == (0, F(0.37) * 7)


@pytest.mark.anchor("CLandBlockStruct::FSplitNESW")
@pytest.mark.parametrize("x, y, want", [(0, 0, False), (1, 0, True), (0, 1, False), (3, 7, False), (100, 200, False),
                                        (2039, 2039, False), (0, -1782484749, True), (1, -1782484749, True),
                                        (-5, 9, False)])
def test_f_split_nesw_matches_mono(x, y, want):
    # y = -1782484749 makes (y * 0x6C1AC587 - 0x519B8F25) int.MinValue: the long division gives -1
    assert build().f_split_nesw(x, y) is want


@pytest.mark.anchor("CLandBlockStruct::calc_water")
def test_water_cells_entire_partial_and_dry():
    terrain = [0] * 81
    for vx, vy in ((0, 0), (1, 0), (0, 1), (1, 1)):  # cell (0, 0) all water
        terrain[vx * 9 + vy] = WATER
    terrain[5 * 9 + 5] = WATER | 0x3  # one corner of cells (4,4), (4,5), (5,4), (5,5); road bits ignored
    lb = build(terrain=terrain)
    assert lb.land_cells[0].water_type == WaterType.EntirelyWater
    assert lb.land_cells[1].water_type == WaterType.PartiallyWater  # shares corners (0,1), (1,1)
    assert lb.land_cells[4 * 8 + 4].water_type == WaterType.PartiallyWater
    assert lb.land_cells[3 * 8 + 3].water_type == WaterType.NotWater
    assert lb.water_type == WaterType.PartiallyWater
    assert build(terrain=[WATER] * 81).water_type == WaterType.EntirelyWater
    assert build().water_type == WaterType.NotWater
    assert build(terrain=[0x15 << 2] * 81).water_type == WaterType.NotWater  # type 0x15 is not water


@pytest.mark.anchor("CLandBlockStruct::calc_water_depth")
def test_calc_water_depth_picks_the_nearest_corner_with_csharp_float_remainder():
    terrain = [0] * 81
    terrain[1 * 9 + 0] = WATER  # corner (1, 0): the south-east corner of cell 1
    lb = build(terrain=terrain)
    deep, dry = F(0.44999999), F(0.1)
    assert f32_bits(lb.calc_water_depth(0xA9B40001, EXACT.vec(13, 2, 0))) == f32_bits(deep)
    assert f32_bits(lb.calc_water_depth(0xA9B40001, EXACT.vec(11.9, 2, 0))) == f32_bits(dry)
    assert lb.calc_water_depth(0xA9B40001, EXACT.vec(13, 12, 0)) == dry  # y >= 12 picks the north corner
    # x % 24 of -13 is -13 (sign of the dividend), never >= 12: the west corner
    assert lb.calc_water_depth(0xA9B40001, EXACT.vec(-13, 2, 0)) == dry
    assert lb.calc_water_depth(0xA9B40001, EXACT.vec(37, 2, 0)) == deep  # 37 % 24 = 13
    assert type(lb.calc_water_depth(0xA9B40001, EXACT.vec(13, 2, 0))) is np.float32


def test_water_depth_constants_are_pinned_by_bits():
    assert f32_bits(lbs.WATER_DEPTH_PARTIAL_WATER) == 0x3EE66666
    assert f32_bits(lbs.WATER_DEPTH_DRY) == 0x3DCCCCCD
    assert float(F(lbs.WATER_DEPTH_PARTIAL_WATER)) == lbs.WATER_DEPTH_PARTIAL_WATER


@pytest.mark.anchor("CLandBlockStruct::Generate")
def test_fast_mode_builds_the_same_mesh_in_double():
    lb = build(heights=[(i * 7) % 50 for i in range(81)], mode=FAST)
    assert all(type(c) is np.float64 for c in lb.vertex_array[10].origin)
    ex = build(heights=[(i * 7) % 50 for i in range(81)])
    assert lb.sw_to_ne_cut == ex.sw_to_ne_cut


def _terrain(lb):
    """Everything a built terrain holds, as plain values (vertex origins, polygon vertices and planes,
    cells with their ids, frames, water and polygons, the block's counts and water)."""
    def v(x):
        return (float(x.x), float(x.y), float(x.z))

    def poly(p):
        return ([v(x.origin) for x in p.vertices], v(p.plane.normal), float(p.plane.d), p.pos_surface)

    cells = [(k, c.id, c.water_type, v(c.pos.frame.origin), [poly(p) for p in c.polygons], c.cur_landblock is lb)
             for k, c in lb.land_cells.items()]  # first: a polygon is made when its cell is first read
    return ([v(x.origin) for x in lb.vertex_array], [poly(p) for p in lb.polygons], list(lb.sw_to_ne_cut), cells,
            lb.water_type, lb.side_cell_count, lb.side_vertex_count, lb.side_poly_count, lb.trans_dir, lb.id)


@pytest.mark.anchor("LandblockStruct.cs:Generate")
def test_a_landblock_without_terrain_builds_it_when_first_read_and_builds_the_same_terrain():
    from acconform.scene import Landblock as LandblockRecord

    record = LandblockRecord(0x01D9FFFF, has_terrain=False)
    eager = Landblock(LandblockRecord(0x01D9FFFF, record.heights, record.terrain), TABLE, EXACT)  # zeros, built now
    eager.post_init()
    lazy = Landblock(record, TABLE, EXACT)
    lazy.post_init()
    assert eager.terrain_built() and not lazy.terrain_built() and lazy.land_cells == {}
    marker = object()
    lazy.land_cells[0x100] = marker  # an EnvCell the run loaded before anything read the terrain
    assert lazy.side_cell_count == 8 and lazy.terrain_built()
    assert list(lazy.land_cells)[-1] == 0x100 and lazy.land_cells.pop(0x100) is marker
    assert _terrain(lazy) == _terrain(eager) and len(lazy.land_cells) == 64


@pytest.mark.anchor("LandblockStruct.cs:Generate")
def test_indoor_scenes_build_no_terrain():
    from acconform.port.land import lscape
    from acconform.port.run import run_scene
    from oracle.indoor_scenes import SCENES

    lscape.clear_landblock_cache()
    for scene in SCENES.values():
        assert run_scene(scene).error is None
    (landblock,) = lscape.POOL.idle.values()
    assert not landblock.terrain_built() and landblock.land_cells == {}


@pytest.mark.anchor("CLandBlockStruct::AddPolygon")
@pytest.mark.parametrize("mode", [EXACT, FAST])
def test_terrain_planes_made_when_first_read_are_the_planes_add_polygon_made(mode, monkeypatch):
    heights = [(i * 37 + i // 9 * 11) % 256 for i in range(81)]
    lazy = build(heights=heights, mode=mode)
    for cell in lazy.land_cells.values():
        cell.polygons  # built: AddPolygon has run on every polygon
    unread = sum(1 for p in lazy.polygons if plane_unset(p))
    monkeypatch.setattr(lbs.Polygon, "make_plane_when_read", lbs.Polygon.make_plane)  # as ACE: at AddPolygon
    eager = build(heights=heights, mode=mode)
    for cell in eager.land_cells.values():
        cell.polygons
    assert unread == len(lazy.polygons) == 128 and not any(plane_unset(p) for p in eager.polygons)
    assert [plane_bits(p) for p in lazy.polygons] == [plane_bits(p) for p in eager.polygons]


@pytest.mark.anchor("CLandBlockStruct::ConstructPolygons")
@pytest.mark.parametrize("mode", [EXACT, FAST])
def test_land_cells_are_built_when_first_read_and_any_order_builds_the_same_cells(mode):
    heights = [(i * 37 + i // 9 * 11) % 256 for i in range(81)]
    terrain = [WATER if i % 7 < 3 else 0 for i in range(81)]
    in_order = build(0x7F7FFFFF, heights, terrain, mode)
    assert not any(is_built(c) for c in in_order.land_cells.values())
    for cell in in_order.land_cells.values():  # every cell read at once, in ACE's order: as ACE builds them
        cell.id
    in_order.post_init()
    later = build(0x7F7FFFFF, heights, terrain, mode)
    later.post_init()
    assert later.get_landcell(0x7F7F0026) is later.land_cells[37]
    assert [k for k, c in later.land_cells.items() if is_built(c)] == [37]
    for k in reversed(list(later.land_cells)):
        later.land_cells[k].polygons
    assert _terrain(later) == _terrain(in_order)
