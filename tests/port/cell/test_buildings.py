"""Buildings in the port: the LandblockInfo's BuildInfo and CBldPortal read in DatLoader's layout,
Landblock.init_buildings placing the building in its outdoor cell, and BuildingObj's own routines."""

from __future__ import annotations

import pytest

from acconform import dat
from acconform.numerics import EXACT
from acconform.port.cell.bld_portal import BldPortal
from acconform.port.cell.env_cell import EnvCell
from acconform.port.dat.binary_reader import BinaryReader
from acconform.port.dat.c_bld_portal import CBldPortal
from acconform.port.dat.landblock_info import LandblockInfo
from acconform.port.errors import InvalidCastException
from acconform.port.land.lscape import LScape
from acconform.port.physics_timer import PhysicsTimer
from acconform.port.run import cell_dat_for, portal_dat_for
from acconform.scene import PORTAL_EXACT_MATCH, PORTAL_SIDE_BIT
from acconform.strategies import sample_scenes

SCENES = list(sample_scenes(("buildings",), 60, 3))
BASE = next(s for s in SCENES if s.name.startswith("building:in"))
CELLAR = next(s for s in SCENES if len(s.env_cells) == 4)


def world(scene):
    portal_dat, _ = portal_dat_for(scene, EXACT, PhysicsTimer(0.0))
    return LScape(scene, EXACT, portal_dat, cell_dat_for(scene, EXACT))


def building_of(lscape, scene):
    b = scene.buildings[0]
    landblock = lscape.get_landblock(b.landblock)
    assert len(landblock.buildings) == 1
    return landblock, landblock.buildings[0]


@pytest.mark.anchor("ACE.DatLoader/FileTypes/LandblockInfo.cs:Unpack")
@pytest.mark.anchor("ACE.DatLoader/Entity/BuildInfo.cs:Unpack")
@pytest.mark.anchor("ACE.DatLoader/Entity/CBldPortal.cs:Unpack")
def test_the_landblock_info_reads_back_its_buildings_frame_portals_and_aligned_stab_lists():
    b = BASE.buildings[0]
    record = next(r for r in dat.cell_dat_records(BASE) if r.kind == "LandblockInfo")
    reader = BinaryReader(record.data, EXACT)
    info = LandblockInfo.unpack(reader)
    assert reader.position == len(record.data) and len(info.buildings) == 1 and info.num_cells == len(BASE.env_cells)
    got = info.buildings[0]
    assert got.model_id == dat.BUILDING_GFX_OBJ_BASE and got.num_leaves == b.num_leaves
    assert tuple(float(c) for c in (got.frame.origin.x, got.frame.origin.y, got.frame.origin.z)) == b.frame.origin
    p = got.portals[0]
    want = b.portals[0]
    assert (p.flags, p.other_cell_id, p.other_portal_id, tuple(p.stab_list)) == (
        want.flags, want.other_cell, want.other_portal, want.stab_list)


@pytest.mark.anchor("ACE.DatLoader/Entity/CBldPortal.cs:Unpack")
@pytest.mark.parametrize("flags, side, exact", [(0, True, False), (PORTAL_SIDE_BIT, False, False),
                                                 (PORTAL_EXACT_MATCH, True, True),
                                                 (PORTAL_SIDE_BIT | PORTAL_EXACT_MATCH, False, True)])
def test_portal_side_is_true_when_its_flag_bit_is_clear_as_ace_reads_it_since_pr_4315(flags, side, exact):
    import struct

    data = struct.pack("<4H", flags, 0x0100, 0, 1) + struct.pack("<H", 0x0100) + b"\0\0"
    reader = BinaryReader(data, EXACT)
    p = CBldPortal.unpack(reader)
    assert (p.portal_side, p.exact_match, reader.position) == (side, exact, 12)


@pytest.mark.anchor("CLandBlock::init_buildings")
@pytest.mark.anchor("CBuildingObj::makeBuilding")
@pytest.mark.anchor("CBuildingObj::add_to_cell")
@pytest.mark.anchor("CSortCell::add_building")
@pytest.mark.anchor("CSortCell::has_building")
@pytest.mark.anchor("CBldPortal::CBldPortal")
@pytest.mark.anchor("DBObj.cs:GetLandblockInfo")
def test_init_buildings_puts_the_building_in_the_outdoor_cell_under_its_origin():
    lscape = world(BASE)
    try:
        landblock, building = building_of(lscape, BASE)
        origin = BASE.buildings[0].frame.origin
        cell_id = (BASE.buildings[0].landblock & 0xFFFF0000) | (int(origin[0] // 24) * 8 + int(origin[1] // 24) + 1)
        cell = lscape.get_landcell(cell_id)
        assert cell.building is building and cell.has_building() and building.cur_cell is cell
        assert building.id == dat.BUILDING_GFX_OBJ_BASE and building.position.obj_cell_id == cell_id
        assert building.part_array.parts[0].pos is building.position  # ACE's "hack": the same Position
        assert isinstance(building.portals[0], BldPortal) and building.landblock_id == BASE.buildings[0].landblock
        assert sum(c.has_building() for c in landblock.land_cells.values()) == 1
    finally:
        lscape.release()


@pytest.mark.anchor("CBldPortal::add_to_stablist")
@pytest.mark.anchor("CBuildingObj::add_to_stablist")
def test_add_to_stablist_adds_nothing_from_an_empty_list_and_appends_only_stabs_already_listed():
    lscape = world(BASE)
    try:
        landblock, building = building_of(lscape, BASE)
        assert landblock.stab_list is None and building.add_to_stablist(None, 0, 0) == (None, 0, 0)
        portal = BldPortal(CBldPortal(stab_list=[0x0100, 0x0101]))
        # only a stab already among the first stabNum is appended (again)
        assert portal.add_to_stablist([0x0101], 20, 1) == ([0x0101, 0x0101], 20, 2)
    finally:
        lscape.release()


@pytest.mark.anchor("BuildingObj.cs:get_building_cells")
@pytest.mark.anchor("BuildingObj.cs:add_cells_recursive")
@pytest.mark.anchor("CBldPortal::GetOtherCell")
@pytest.mark.anchor("BuildingObj.cs:GetMinZ")
def test_get_building_cells_walks_every_visible_cell_once_from_the_portal_and_get_min_z_reads_their_vertices():
    lscape = world(CELLAR)
    try:
        _, building = building_of(lscape, CELLAR)
        cells = building.get_building_cells(lscape)
        assert [c.id for c in cells] == [c.id for c in CELLAR.env_cells]
        assert building.get_building_cells(lscape) is cells  # remembered
        lowest = min(v[2] for s in CELLAR.environments[0].cell_structs for p in s.polygons + s.physics_polygons
                     for v in p.vertices)
        assert float(building.get_min_z(lscape)) == lowest
    finally:
        lscape.release()


@pytest.mark.anchor("CBldPortal::GetOtherCell")
def test_get_other_cell_casts_to_env_cell_and_throws_for_a_land_cell():
    lscape = world(BASE)
    try:
        _, building = building_of(lscape, BASE)
        portal = building.portals[0]
        assert isinstance(portal.get_other_cell(lscape, building.cur_cell.id), EnvCell)
        portal.other_cell_id = 0x0001
        with pytest.raises(InvalidCastException):
            portal.get_other_cell(lscape, building.cur_cell.id)
    finally:
        lscape.release()
