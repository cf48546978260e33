"""Children parented to a PhysicsObj (port/child_list.py, port/physics_obj.py's children routines,
port/parenting.py): ChildList, add_child at a Setup's holding location, set_parent, UpdateChild as
the parent moves, unset_parent, and the walks over children (cells, shadows, cell ids).

Expected frames are worked out from ACE's code (PhysicsObj.cs UpdateChild: Combine(part frame or
Position, holding frame); PartArray.UpdateParts: Combine(frame, placement frame, scale)) with
rotations whose float32 arithmetic is exact (identity, half turns), never by calling the routine
under test. children_world.py holds the records.
"""

from __future__ import annotations

import numpy as np
import pytest

from acconform import dat
from acconform.flags import PhysicsState, TransientState
from acconform.numerics import EXACT, f32_bits
from acconform.scene import Frame, Landblock, Mover, Position as ScenePosition, Scene, SphereRec
from acconform.port import parenting
from acconform.port.child_list import ChildList
from acconform.port.dat.cell_dat import CellDat
from acconform.port.dat.portal_dat import PortalDat
from acconform.port.dat.setup_model import SetupModel
from acconform.port.dat.binary_reader import BinaryReader
from acconform.port.errors import ArgumentOutOfRangeException, InvalidOperationException
from acconform.port.frame import AFrame
from acconform.port.land.lscape import LScape
from acconform.port.physics_obj import PhysicsObj

import children_world as w

F = np.float32
HALF_TURN = (0.0, 0.0, 0.0, 1.0)  # (w, x, y, z): 180 degrees about z, (x, y, z) -> (-x, -y, z) exactly


def portal(server: bool = True) -> PortalDat:
    return PortalDat(w.records(), EXACT, server)


def make(portal_dat, did=w.PARENT_SETUP, obj_id=w.PARENT_ID) -> PhysicsObj:
    return PhysicsObj.make_object(did, obj_id, True, portal_dat)


def pair(server: bool = True):
    pd = portal(server)
    return make(pd), make(pd, w.CHILD_SETUP, w.CHILD_ID), pd


def frame(origin, orientation=(1.0, 0.0, 0.0, 0.0)) -> AFrame:
    return AFrame.from_record(Frame(origin, orientation), EXACT)


def bits(f: AFrame):
    o, q = f.origin, f.orientation
    return tuple(f32_bits(c) for c in (o.x, o.y, o.z, q.x, q.y, q.z, q.w))


def expect(origin, orientation=(1.0, 0.0, 0.0, 0.0)):
    return bits(frame(origin, orientation))


def no_lscape():
    return None  # set_parent reads the world only when the parent is in a cell


# ---------------------------------------------------------------- the DAT and the Setup


@pytest.mark.anchor("CSetup::GetHoldingLocation")
def test_a_setup_record_carries_its_holding_locations_to_get_holding_location():
    model = SetupModel.unpack(BinaryReader(w.records()[w.PARENT_SETUP], EXACT))
    assert sorted(model.holding_locations) == [w.RIGHT_HAND, w.SHIELD, w.BAD_PART]
    parent, _, _ = pair()
    right = parent.part_array.setup.get_holding_location(w.RIGHT_HAND)
    assert right.part_id == 1 and (F(right.frame.origin.x), F(right.frame.origin.y)) == (F(0.25), F(0.0))
    assert parent.part_array.setup.get_holding_location(w.SHIELD).part_id == 7
    assert parent.part_array.setup.get_holding_location(w.MISSING) is None


def test_a_setup_written_without_holding_locations_reads_none():
    body = dat.setup(dat.SETUP_BASE, [dat.GFX_OBJ_BASE])
    assert SetupModel.unpack(BinaryReader(body, EXACT)).holding_locations == {}


# ---------------------------------------------------------------- ChildList


@pytest.mark.anchor("CHILDLIST::remove_child")
def test_remove_child_takes_the_child_out_of_every_list_but_keeps_the_count():
    a, b, _ = pair()
    children = ChildList()
    children.add_child(a, frame((1.0, 0.0, 0.0)), 0, 1)
    children.add_child(b, frame((2.0, 0.0, 0.0)), 1, 3)
    assert children.find_child_index(b) == 1
    assert children.remove_child(a)
    assert (children.objects, children.part_numbers, children.location_ids) == ([b], [1], [3])
    assert children.num_objects == 2  # NumObjects is never decremented (ACE)
    assert children.find_child_index(b) == 0


@pytest.mark.anchor("CHILDLIST::FindChildIndex")
def test_find_child_index_past_a_removal_reads_past_the_list_and_throws():
    a, b, pd = pair()
    c = make(pd, w.CHILD_SETUP, w.OTHER_ID)
    children = ChildList()
    children.add_child(a, frame((0.0, 0.0, 0.0)), 0, 1)
    children.add_child(b, frame((0.0, 0.0, 0.0)), 0, 1)
    children.remove_child(a)
    with pytest.raises(ArgumentOutOfRangeException):
        children.find_child_index(c)  # NumObjects 2, one object left


# ---------------------------------------------------------------- add_child


@pytest.mark.anchor("CPhysicsObj::add_child")
def test_add_child_holds_the_child_at_the_holding_locations_part_and_frame():
    parent, child, _ = pair()
    assert parent.add_child(child, w.RIGHT_HAND)
    ch = parent.children
    assert (ch.num_objects, ch.objects, ch.part_numbers, ch.location_ids) == (1, [child], [1], [w.RIGHT_HAND])
    assert bits(ch.frames[0]) == expect((0.25, 0.0, 0.0))


@pytest.mark.anchor("CPhysicsObj::add_child")
def test_add_child_refuses_a_missing_location_and_the_parent_itself():
    parent, child, _ = pair()
    assert not parent.add_child(child, w.MISSING)
    assert not parent.add_child(parent, w.RIGHT_HAND)
    assert parent.children.num_objects == 0


@pytest.mark.anchor("CPhysicsObj::add_child")
def test_add_child_with_a_frame_takes_minus_one_and_refuses_a_part_past_the_parts():
    parent, child, _ = pair()
    f = frame((1.0, 2.0, 3.0))
    assert not parent.add_child_frame(child, 2, f)
    assert parent.add_child_frame(child, -1, f)
    assert parent.children.frames[0] is f and parent.children.location_ids == [0]


# ---------------------------------------------------------------- UpdateChild as the parent moves


@pytest.mark.anchor("CPhysicsObj::UpdateChild")
def test_a_child_held_past_the_parts_follows_the_parents_position():
    parent, child, _ = pair()
    assert child.set_parent(parent, w.SHIELD, no_lscape())
    assert child.parent is parent
    parent.set_frame(frame((10.0, 20.0, 30.0), HALF_TURN))
    # Combine(Position.Frame, holding (0, 0.5, 0) half turn): origin + (0, -0.5, 0), orientation q * q
    assert bits(child.position.frame) == expect((10.0, 19.5, 30.0), (-1.0, 0.0, 0.0, 0.0))
    parent.set_frame(frame((1.0, 2.0, 3.0)))
    assert bits(child.position.frame) == expect((1.0, 2.5, 3.0), HALF_TURN)


@pytest.mark.anchor("CPhysicsObj::UpdateChild")
def test_a_client_childs_frame_is_the_parts_frame_combined_with_the_holding_frame():
    parent, child, _ = pair(server=False)
    child.set_parent(parent, w.RIGHT_HAND, no_lscape())
    parent.set_frame(frame((10.0, 20.0, 30.0), HALF_TURN))
    # part 1 = Combine(frame, placement (0.5, 0, 1.5)) = (9.5, 20, 31.5); child = part + (-0.25, 0, 0)
    assert bits(parent.part_array.parts[1].pos.frame) == expect((9.5, 20.0, 31.5), HALF_TURN)
    assert bits(child.position.frame) == expect((9.25, 20.0, 31.5), HALF_TURN)


@pytest.mark.anchor("CPhysicsObj::UpdateChild")
def test_on_the_server_a_child_held_by_a_part_stays_where_the_part_was():
    """set_frame updates the parts only for an object with a physics BSP on the server: the part,
    and the child held by it, do not move with the parent."""
    parent, child, _ = pair(server=True)
    assert not parent.state & PhysicsState.HasPhysicsBSP
    child.set_parent(parent, w.RIGHT_HAND, no_lscape())
    parent.set_frame(frame((10.0, 20.0, 30.0), HALF_TURN))
    first = bits(child.position.frame)
    parent.set_frame(frame((50.0, 60.0, 70.0)))
    assert bits(child.position.frame) == first
    part = parent.part_array.parts[1].pos.frame
    assert bits(child.position.frame) == bits(AFrame.combine(part, frame((0.25, 0.0, 0.0))))


@pytest.mark.anchor("CPhysicsObj::UpdateChild")
def test_a_child_held_at_part_minus_one_throws_when_the_parent_moves():
    parent, child, _ = pair()
    child.set_parent(parent, w.BAD_PART, no_lscape())
    with pytest.raises(ArgumentOutOfRangeException):
        parent.set_frame(frame((1.0, 1.0, 1.0)))


@pytest.mark.anchor("CPhysicsObj::UpdateChildrenInternal")
def test_update_children_internal_moves_every_child_in_order():
    parent, a, pd = pair()
    b = make(pd, w.CHILD_SETUP, w.OTHER_ID)
    a.set_parent(parent, w.SHIELD, no_lscape())
    b.set_parent(parent, w.SHIELD, no_lscape())
    parent.set_frame(frame((4.0, 4.0, 4.0)))
    assert bits(a.position.frame) == bits(b.position.frame) == expect((4.0, 4.5, 4.0), HALF_TURN)


# ---------------------------------------------------------------- set_parent, unset_parent


@pytest.mark.anchor("CPhysicsObj::set_parent")
def test_set_parent_to_a_missing_location_changes_nothing():
    parent, child, _ = pair()
    child.transient_state = int(TransientState.Active | TransientState.Contact)
    assert not child.set_parent(parent, w.MISSING, no_lscape())
    assert child.parent is None and child.transient_state == TransientState.Active | TransientState.Contact


@pytest.mark.anchor("CPhysicsObj::set_parent")
def test_set_parent_takes_the_child_out_of_the_world_and_clears_its_transient_state():
    parent, child, _ = pair()
    child.transient_state = int(TransientState.Active | TransientState.Contact | TransientState.OnWalkable)
    child.position.obj_cell_id = 0xA9B40001
    assert child.set_parent(parent, w.SHIELD, no_lscape())
    assert child.transient_state == 0 and child.position.obj_cell_id == 0
    assert all(p.pos.obj_cell_id == 0 for p in child.part_array.parts)


@pytest.mark.anchor("CPhysicsObj::unset_parent")
def test_a_second_set_parent_moves_the_child_to_the_new_parent():
    parent, child, pd = pair()
    other = make(pd, w.PARENT_SETUP, w.OTHER_ID)
    child.set_parent(parent, w.SHIELD, no_lscape())
    child.set_parent(other, w.SHIELD, no_lscape())
    assert child.parent is other and other.children.objects == [child]
    assert parent.children.objects == [] and parent.children.num_objects == 1  # RemoveChild keeps the count
    other.set_frame(frame((1.0, 1.0, 1.0)))
    parent.set_frame(frame((9.0, 9.0, 9.0)))  # reads Objects.Count: the stale count is not walked
    assert bits(child.position.frame) == expect((1.0, 1.5, 1.0), HALF_TURN)


@pytest.mark.anchor("CPhysicsObj::unset_parent")
def test_a_child_of_a_hidden_parent_is_no_draw_and_unset_parent_clears_hidden_instead():
    parent, child, _ = pair()
    parent.state |= PhysicsState.Hidden
    child.set_parent(parent, w.SHIELD, no_lscape())
    assert child.state & PhysicsState.NoDraw and not child.state & PhysicsState.Hidden
    child.state |= PhysicsState.Hidden
    child.unset_parent()
    assert child.parent is None and child.state & PhysicsState.NoDraw and not child.state & PhysicsState.Hidden


@pytest.mark.anchor("CPhysicsObj::remove_shadows_from_cells")
def test_remove_shadows_from_cells_after_a_removal_reads_past_the_children_and_throws():
    parent, child, _ = pair()
    child.set_parent(parent, w.SHIELD, no_lscape())
    child.unset_parent()
    with pytest.raises(ArgumentOutOfRangeException):
        parent.remove_shadows_from_cells()  # loops to NumObjects (1) over an empty list


@pytest.mark.anchor("CPhysicsObj::unparent_children")
def test_unparent_children_unsets_the_first_child_then_throws_as_the_list_changed():
    parent, a, pd = pair()
    b = make(pd, w.CHILD_SETUP, w.OTHER_ID)
    a.set_parent(parent, w.SHIELD, no_lscape())
    b.set_parent(parent, w.SHIELD, no_lscape())
    with pytest.raises(InvalidOperationException):
        parent.unparent_children()
    assert a.parent is None and b.parent is parent


@pytest.mark.anchor("CPhysicsObj::set_cell_id_recursive")
def test_set_cell_id_recursive_gives_the_children_the_cell_id():
    parent, child, _ = pair()
    child.set_parent(parent, w.SHIELD, no_lscape())
    parent.set_cell_id_recursive(0xA9B40012)
    assert child.position.obj_cell_id == 0xA9B40012 == parent.position.obj_cell_id


# ---------------------------------------------------------------- in a cell


def world(pd) -> LScape:
    pos = ScenePosition(0xA9B40001, Frame((12.0, 12.0, 0.0)))
    mover = Mover((SphereRec((0.0, 0.0, 0.5), 0.5),), pos, pos, 0.5, 0.5)
    scene = Scene((Landblock(0xA9B4FFFF, (0,) * 81, (0,) * 81),), mover)
    return LScape(scene, EXACT, pd, CellDat({}, EXACT))


@pytest.mark.anchor("CPhysicsObj::set_parent")
def test_a_child_parented_in_a_cell_enters_the_parents_cell_and_shadows_the_cells_its_sphere_reaches():
    parent, child, pd = pair()
    lscape = world(pd)
    cell = lscape.get_landcell(0xA9B40001)
    parent.add_obj_to_cell(cell, frame((23.9, 12.0, 0.0)), lscape)  # beside the cell's edge at x 24
    assert parenting.set_parent(child, parent, w.SHIELD, 0, lscape)
    assert child.cur_cell is cell and child.position.obj_cell_id == 0xA9B40001
    assert child in cell.object_list
    # Position (23.9, 12, 0), identity, + (0, 0.5, 0); the sorting sphere (centre 0.5 up, radius 1)
    # at (23.9, 12.5, 0.5) reaches over x 24 into the next cell east (x index 1: cell 9)
    assert bits(child.position.frame) == expect((23.9, 12.5, 0.0), HALF_TURN)
    assert list(child.shadow_objects) == [0xA9B40001, 0xA9B40009]
    assert all(any(s.physics_obj is child for s in lscape.get_landcell(c).shadow_object_list) for c in child.shadow_objects)


@pytest.mark.anchor("CPhysicsObj::leave_cell")
def test_a_parent_leaving_its_cell_takes_its_children_out_too():
    parent, child, pd = pair()
    lscape = world(pd)
    cell = lscape.get_landcell(0xA9B40001)
    parent.add_obj_to_cell(cell, frame((12.0, 12.0, 0.0)), lscape)
    parenting.set_parent(child, parent, w.SHIELD, 0, lscape)
    parent.leave_cell(False)
    assert child.cur_cell is None and child not in cell.object_list


def test_the_harness_parents_the_child_and_answers_as_set_parent():
    parent, child, _ = pair()
    assert not parenting.set_parent(child, parent, w.MISSING, 0, None) and child.parent is None
    assert parenting.set_parent(child, parent, w.SHIELD, 0x65, None) and child.parent is parent
