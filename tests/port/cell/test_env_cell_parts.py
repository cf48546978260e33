"""The pieces around EnvCells: a static's placement through portals (the parts overload), the
plane-box sidedness it uses, the DAT readers' small records, and the landblock pool keeping no
EnvCell between runs."""

from __future__ import annotations

import pytest

from acconform.numerics import EXACT
from acconform.port.bbox import BBox
from acconform.port.cell.env_cell import EnvCell
from acconform.port.dat.binary_reader import BinaryReader
from acconform.port.dat.cell_portal import CellPortal
from acconform.port.dat.stab import Stab
from acconform.port.frame import AFrame, Position
from acconform.port.land.lscape import POOL
from acconform.port.physics_timer import PhysicsTimer
from acconform.port.vec import Sidedness, intersect_box
from acconform.numerics import Plane
from indoor_rooms import LB, indoor_scene, portal, room, two_rooms, world

A, B = LB | 0x0100, LB | 0x0101
v = EXACT.vec


def _world(cells=None, **kw):
    env, default = two_rooms(**kw)
    scene = indoor_scene(env, cells or default, (63, 60, 20), (63, 60, 20), state=0, transient=0, begin_cell=A,
                         end_cell=A)
    return world(scene, EXACT)


@pytest.mark.anchor("PlaneExtensions.cs:intersect_box")
def test_intersect_box_names_the_side_a_box_is_on_and_a_corner_on_the_plane_makes_it_crossing():
    p = Plane(v(1, 0, 0), EXACT.scalar(-5))
    assert intersect_box(p, BBox(v(6, 0, 0), v(7, 1, 1))) == Sidedness.Positive
    assert intersect_box(p, BBox(v(1, 0, 0), v(2, 1, 1))) == Sidedness.Negative
    assert intersect_box(p, BBox(v(4, 0, 0), v(6, 1, 1))) == Sidedness.Crossing
    # Max on the plane (within EPSILON): GetSide says Close, which as a Sidedness is InPlane
    assert intersect_box(p, BBox(v(1, 0, 0), v(5, 1, 1))) == Sidedness.Crossing


@pytest.mark.anchor("BBox.cs:LocalToLocal")
def test_a_box_carried_into_a_cells_frame_spans_its_corners_there():
    box = BBox(v(-1, -1, 0), v(1, 1, 2))
    part_pos = Position(A, AFrame(v(64.5, 60, 20), EXACT.quat(0, 0, 0, 1)))
    cell_pos = Position(B, AFrame(v(70, 60, 20), EXACT.quat(0, 0, 0, 1)))
    out = BBox()
    out.local_to_local(box, part_pos, cell_pos)
    assert (out.min, out.max) == (v(-6.5, -1, 0), v(-4.5, 1, 2))
    assert len(out.get_corners()) == 8 and out.get_corners()[7] == out.max


@pytest.mark.anchor("CEnvCell::find_transit_cells")
@pytest.mark.anchor("CPhysicsObj::is_completely_visible")
def test_a_parts_box_crossing_a_portal_adds_the_neighbour_when_its_cell_tree_holds_the_box():
    from object_scenes import box
    from acconform import dat
    from acconform.scene import Frame, Position as PosRec, StaticObject
    from acconform.port.physics_obj import PhysicsObj

    lscape, portal_dat = _world()
    a = lscape.get_landcell(A)
    for x, want in ((64.5, [A, B]), (60.0, [A])):
        written = dat.static_records(StaticObject(0x70000000, PosRec(A, Frame((x, 60.0, 20.0))), box(2.0, 2.0, 2.0)), 0)
        for r in written.records:
            portal_dat.records[r.id] = r.data
        portal_dat.gfx_objs.clear()
        portal_dat.file_cache.clear()
        obj = PhysicsObj.make_object(written.did, 0, False, portal_dat)
        obj.dat_object = True
        obj.add_obj_to_cell(a, AFrame(v(x, 60, 20), EXACT.quat(0, 0, 0, 1)), lscape)
        assert list(obj.shadow_objects) == want
        # add_shadows_to_cell never counts NumShadowObjects (ACE), so a placed static never reads as
        # completely visible: a second init_static_objects would place it again
        assert not obj.is_completely_visible()


@pytest.mark.anchor("CEnvCell::find_visible_child_cell")
@pytest.mark.anchor("CEnvCell::GetVisible")
def test_find_visible_child_cell_finds_the_cell_holding_a_point_through_visible_cells_or_portals():
    lscape, _ = _world()
    a = lscape.get_landcell(A)
    b = lscape.get_landcell(B)
    assert a.find_visible_child_cell(v(61, 60, 21), True) is a
    assert a.find_visible_child_cell(v(71, 60, 21), True) is b
    assert a.find_visible_child_cell(v(71, 60, 21), False) is b
    assert a.find_visible_child_cell(v(90, 60, 21), False) is None
    assert a.get_visible(0x0101) is b and a.get_visible(B) is None  # keyed by the short id


@pytest.mark.anchor("CEnvCell::handle_move_restriction")
def test_an_env_cell_allows_every_move_restriction():
    lscape, _ = _world()
    c = lscape.get_landcell(A)
    assert isinstance(c, EnvCell) and c.handle_move_restriction(None) is True
    lscape.release()


@pytest.mark.anchor("ACE.DatLoader/Entity/CellPortal.cs:Unpack")
def test_a_cell_portals_side_is_true_when_the_portal_side_bit_is_clear():
    p = CellPortal.unpack(BinaryReader(bytes((3, 0, 7, 0, 0x01, 0x01, 2, 0)), EXACT))
    assert (p.flags, p.polygon_id, p.other_cell_id, p.other_portal_id) == (3, 7, 0x0101, 2)
    assert p.exact_match and not p.portal_side
    assert CellPortal().portal_side


@pytest.mark.anchor("ACE.DatLoader/Entity/Stab.cs:Unpack")
def test_a_stab_reads_its_id_then_its_frame_written_w_first():
    import struct
    s = Stab.unpack(BinaryReader(struct.pack("<I7f", 0x01000009, 1, 2, 3, 0.5, 0.5, 0.5, 0.5), EXACT))
    assert s.id == 0x01000009 and float(s.frame.origin.z) == 3.0
    assert (float(s.frame.orientation.w), float(s.frame.orientation.x)) == (0.5, 0.5)


@pytest.mark.anchor("ACE.DatLoader/BinaryReaderExtensions.cs:AlignBoundary")
@pytest.mark.parametrize("at, to", [(0, 0), (1, 4), (3, 4), (4, 4), (5, 8)])
def test_align_boundary_moves_to_the_next_dword_of_the_record(at, to):
    r = BinaryReader(b"\0" * 8, EXACT)
    r.position = at
    r.align_boundary()
    assert r.position == to


@pytest.mark.anchor("CEnvCell::UnPack")
def test_a_released_landblock_keeps_no_env_cell_for_the_next_run():
    lscape, _ = _world()
    landblock = lscape.get_landblock(A)
    lscape.get_landcell(A)
    assert {k for k in landblock.land_cells if k >= 0x100} == {0x0100, 0x0101}
    lscape.release()
    assert not [k for k in landblock.land_cells if k >= 0x100]
    again, _ = _world()
    assert again.get_landblock(A) is landblock  # the pooled one, rebuilt cells on demand
    assert again.get_landcell(A) is not None
    again.release()
    POOL.clear()


@pytest.mark.anchor("ACE.DatLoader/FileTypes/LandblockInfo.cs:Unpack")
def test_a_landblock_info_reads_its_cell_count_and_objects_to_its_last_byte():
    import struct
    from acconform import dat
    from acconform.port.dat.landblock_info import LandblockInfo

    data = dat.landblock_info_record(0xA9B4, 3).data  # what a scene's landblock gets
    reader = BinaryReader(data, EXACT)
    info = LandblockInfo.unpack(reader)
    assert (info.id, info.num_cells, info.objects, info.pack_mask, reader.position) == (0xA9B4FFFE, 3, [], 0, len(data))
    stab = struct.pack("<I7f", 0x01000001, 1, 2, 3, 1, 0, 0, 0)
    data = struct.pack("<III", 0xA9B4FFFE, 3, 1) + stab + struct.pack("<HH", 0, 2)
    reader = BinaryReader(data, EXACT)
    info = LandblockInfo.unpack(reader)
    assert [s.id for s in info.objects] == [0x01000001] and info.pack_mask == 2 and reader.position == len(data)


@pytest.mark.anchor("ACE.DatLoader/FileTypes/LandblockInfo.cs:Unpack")
@pytest.mark.anchor("ACE.DatLoader/UnpackableExtensions.cs:UnpackPackedHashTable(Dictionary<uint, uint>)")
def test_a_landblock_info_reads_its_restriction_table_and_a_key_given_twice_throws_as_dictionary_add_does():
    import struct
    from acconform.port.dat.landblock_info import LandblockInfo
    from acconform.port.errors import ArgumentException

    head = struct.pack("<IIIHH", 0xA9B4FFFE, 3, 0, 0, 1)
    table = struct.pack("<HHIIII", 2, 89, 0xA9B40001, 0x7ABC0001, 0xA9B40100, 0x50000001)
    info = LandblockInfo.unpack(BinaryReader(head + table, EXACT))
    assert info.restriction_tables == {0xA9B40001: 0x7ABC0001, 0xA9B40100: 0x50000001}
    twice = struct.pack("<HHIIII", 2, 89, 0xA9B40001, 0x7ABC0001, 0xA9B40001, 0x50000001)
    with pytest.raises(ArgumentException):
        LandblockInfo.unpack(BinaryReader(head + twice, EXACT))


@pytest.mark.anchor("Position::get_indoor_cell")
@pytest.mark.anchor("AdjustCell.cs:AdjustCell(uint)")
@pytest.mark.anchor("AdjustCell.cs:BuildEnv")
@pytest.mark.anchor("AdjustCell.cs:GetCell")
@pytest.mark.anchor("AdjustCell.cs:Get")
@pytest.mark.anchor("Position::get_cell")
def test_get_cell_of_an_indoor_position_is_the_dungeon_cell_holding_its_origin_else_its_own_id():
    lscape, _ = _world()
    inside_b = Position(A, AFrame(v(71, 60, 21), EXACT.quat(0, 0, 0, 1)))
    assert inside_b.get_cell(A, lscape=lscape) == B
    nowhere = Position(A, AFrame(v(120, 60, 21), EXACT.quat(0, 0, 0, 1)))
    assert nowhere.get_cell(A, lscape=lscape) == A
    assert list(lscape.adjust_cells) == [LB >> 16]


@pytest.mark.anchor("CPhysicsObj::AdjustPosition")
def test_adjust_position_moves_an_indoor_position_into_the_visible_child_cell_or_outside_when_seen_outside():
    from acconform.port.physics_obj import PhysicsObj

    env, (a, b) = two_rooms()
    a = room(0x0100, 60.0, portals=a.portals, visible=a.visible_cells, seen_outside=True)
    lscape, _ = _world(cells=(a, b))
    obj = PhysicsObj.create(EXACT, PhysicsTimer())
    low = v(0, 0, 0.5)
    pos = Position(A, AFrame(v(71, 60, 20), EXACT.quat(0, 0, 0, 1)))
    assert obj.adjust_position(pos, low, False, True, lscape).id == B and pos.obj_cell_id == B
    out = Position(A, AFrame(v(100, 60, 20), EXACT.quat(0, 0, 0, 1)))
    cell = obj.adjust_position(out, low, False, True, lscape)
    assert cell.id == out.obj_cell_id == LB | (4 * 8 + 2 + 1)  # adjusted to the outdoor cell at (100, 60)
    shut = Position(B, AFrame(v(100, 60, 20), EXACT.quat(0, 0, 0, 1)))
    assert obj.adjust_position(shut, low, False, True, lscape) is None  # B is not seen from outside
    assert obj.adjust_position(Position(LB | 0x0050, AFrame(v(1, 1, 1), EXACT.quat(0, 0, 0, 1))), low, False, True,
                               lscape) is None
