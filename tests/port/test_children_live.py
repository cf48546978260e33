"""Children against live ACE (lane `live_oracle`): children_world.py's parent (a Setup of two parts
with holding locations) and child written as DAT bytes by acconform/dat.py, unpacked by ACE's own
DatLoader into DatManager.PortalDat's FileCache (after the facade's Reset, which makes the
PhysicsEngine; removed after); both objects made by ACE's
PhysicsObj.makeObject and by the port's, the child parented by the harness's calls (port/parenting.py
and the facade's SetParent, oracle/facade/Child.cs.txt: SetPlacementFrame, then set_parent at the
holding location), then the parent moved by set_frame through children_world.MOVES; after each move
the child's frame, the parent's part frames and both objects' cell ids and states are compared bit
for bit. In server mode (ACE's server: PhysicsEngine.Server) and in client mode (the parts follow
the parent: set_frame updates them), a child held by a part and one held past the parts (the parent's
Position). Run once per runtime (one runtime per process): ACE_ASSEMBLY=<mono or .NET 10 build>."""

from __future__ import annotations

import numpy as np
import pytest

from acconform.numerics import f32_bits, get_mode, runtime_named
from acconform.scene import Frame
from acconform.port import parenting
from acconform.port.dat.portal_dat import PortalDat
from acconform.port.frame import AFrame
from acconform.port.physics_obj import PhysicsObj

import children_world as w

pytestmark = pytest.mark.live_oracle

f = np.float32


@pytest.fixture(scope="module")
def ace(live):
    from System.IO import BinaryReader, MemoryStream  # type: ignore[import-not-found]
    from ACE.DatLoader import DatManager  # type: ignore[import-not-found]
    from ACE.DatLoader.FileTypes import GfxObj, SetupModel  # type: ignore[import-not-found]
    from ACE.Server import Physics  # type: ignore[import-not-found]

    from Acconform.Oracle import Facade  # type: ignore[import-not-found]

    Facade.Reset(True)  # a PhysicsEngine.Instance (ACE's static), as every scene starts; empties the FileCache
    cache = DatManager.PortalDat.FileCache
    for i, data in w.records().items():
        stream = MemoryStream(bytes(data))
        file = SetupModel() if i >> 24 == 2 else GfxObj()
        file.Unpack(BinaryReader(stream))
        assert int(stream.Position) == len(data) and int(file.Id) == i
        cache[i] = file
    mode = get_mode("exact", runtime_named(live.versions.runtime))
    yield Physics, mode
    for i in w.records():
        cache.TryRemove(i)


def _ace_frame(Physics, origin, wxyz):
    from System.Numerics import Quaternion, Vector3  # type: ignore[import-not-found]

    q = [float(f(c)) for c in wxyz]
    return Physics.Animation.AFrame(Vector3(*(float(f(c)) for c in origin)), Quaternion(q[1], q[2], q[3], q[0]))


def _bits_ace(fr) -> tuple:
    o, q = fr.Origin, fr.Orientation
    return tuple(f32_bits(c) for c in (o.X, o.Y, o.Z, q.X, q.Y, q.Z, q.W))


def _bits_port(fr) -> tuple:
    o, q = fr.origin, fr.orientation
    return tuple(f32_bits(c) for c in (o.x, o.y, o.z, q.x, q.y, q.z, q.w))


def _make_both(ace, server: bool, location: int):
    Physics, mode = ace
    Physics.PhysicsEngine.Instance.Server = server
    a_parent = Physics.PhysicsObj.makeObject(w.PARENT_SETUP, w.PARENT_ID, True, False)
    a_child = Physics.PhysicsObj.makeObject(w.CHILD_SETUP, w.CHILD_ID, True, False)
    # the facade's SetParent (oracle/facade/Child.cs.txt)
    a_child.SetPlacementFrame(0x65, False)
    a_ok = a_child.set_parent(a_parent, location)

    pd = PortalDat(w.records(), mode, server)
    p_parent = PhysicsObj.make_object(w.PARENT_SETUP, w.PARENT_ID, True, pd)
    p_child = PhysicsObj.make_object(w.CHILD_SETUP, w.CHILD_ID, True, pd)
    p_ok = parenting.set_parent(p_child, p_parent, location, 0x65, None)
    assert bool(a_ok) == p_ok
    return (a_parent, a_child), (p_parent, p_child)


def _state(a_obj, p_obj):
    return ((int(a_obj.Position.ObjCellID), int(a_obj.State), int(a_obj.TransientState)),
            (p_obj.position.obj_cell_id, p_obj.state, p_obj.transient_state))


@pytest.fixture
def engine(ace):
    from ACE.Server import Physics  # type: ignore[import-not-found]

    eng = Physics.PhysicsEngine.Instance
    was = eng.Server
    yield
    eng.Server = was


@pytest.mark.anchor("CPhysicsObj::UpdateChild")
@pytest.mark.parametrize("server", [True, False], ids=["server", "client"])
@pytest.mark.parametrize("location", [w.RIGHT_HAND, w.SHIELD], ids=["part", "position"])
def test_a_child_follows_its_parents_set_frame_as_ace_moves_it(ace, engine, server, location):
    Physics, mode = ace
    (a_parent, a_child), (p_parent, p_child) = _make_both(ace, server, location)
    assert _bits_ace(a_child.Position.Frame) == _bits_port(p_child.position.frame)
    a_ch, p_ch = a_parent.Children, p_parent.children
    assert (int(a_ch.NumObjects), list(a_ch.PartNumbers), list(a_ch.LocationIDs)) == \
        (p_ch.num_objects, p_ch.part_numbers, p_ch.location_ids)
    assert _bits_ace(a_ch.Frames[0]) == _bits_port(p_ch.frames[0])
    moved = set()
    for origin, wxyz in w.MOVES:
        a_parent.set_frame(_ace_frame(Physics, origin, wxyz))
        p_parent.set_frame(AFrame.from_record(Frame(origin, wxyz), mode))
        assert _bits_ace(a_parent.Position.Frame) == _bits_port(p_parent.position.frame)
        for k in range(2):
            assert _bits_ace(a_parent.PartArray.Parts[k].Pos.Frame) == _bits_port(p_parent.part_array.parts[k].pos.frame), k
        assert _bits_ace(a_child.Position.Frame) == _bits_port(p_child.position.frame), (origin, wxyz)
        assert _state(a_child, p_child)[0] == _state(a_child, p_child)[1]
        moved.add(_bits_port(p_child.position.frame))
    # the case shows what it says: a part-held child on the server does not move, the others do
    assert (len(moved) == 1) == (server and location == w.RIGHT_HAND)


@pytest.mark.anchor("CPhysicsObj::set_parent")
def test_set_parent_refuses_a_missing_location_and_a_part_minus_one_throws_as_in_ace(ace, engine):
    Physics, mode = ace
    (a_parent, a_child), (p_parent, p_child) = _make_both(ace, True, w.MISSING)
    assert a_child.Parent is None and p_child.parent is None and int(a_parent.Children.NumObjects) == 0
    (a_parent, a_child), (p_parent, p_child) = _make_both(ace, True, w.BAD_PART)
    from System import ArgumentOutOfRangeException  # type: ignore[import-not-found]
    from acconform.port.errors import ArgumentOutOfRangeException as PortArgumentOutOfRange

    with pytest.raises(ArgumentOutOfRangeException):
        a_parent.set_frame(_ace_frame(Physics, (1.0, 1.0, 1.0), (1.0, 0.0, 0.0, 0.0)))
    with pytest.raises(PortArgumentOutOfRange):
        p_parent.set_frame(AFrame.from_record(Frame((1.0, 1.0, 1.0)), mode))


@pytest.mark.anchor("CPhysicsObj::unset_parent")
def test_reparenting_leaves_the_old_parents_count_as_ace_leaves_it(ace, engine):
    Physics, mode = ace
    (a_parent, a_child), (p_parent, p_child) = _make_both(ace, True, w.SHIELD)
    a_other = Physics.PhysicsObj.makeObject(w.PARENT_SETUP, w.OTHER_ID, True, False)
    p_other = PhysicsObj.make_object(w.PARENT_SETUP, w.OTHER_ID, True, PortalDat(w.records(), mode, True))
    assert a_child.set_parent(a_other, w.SHIELD) and p_child.set_parent(p_other, w.SHIELD, None)
    assert (int(a_parent.Children.NumObjects), int(a_parent.Children.Objects.Count)) == \
        (p_parent.children.num_objects, len(p_parent.children.objects)) == (1, 0)
    a_other.set_frame(_ace_frame(Physics, (3.0, 4.0, 5.0), (0.0, 0.0, 0.0, 1.0)))
    p_other.set_frame(AFrame.from_record(Frame((3.0, 4.0, 5.0), (0.0, 0.0, 0.0, 1.0)), mode))
    assert _bits_ace(a_child.Position.Frame) == _bits_port(p_child.position.frame)
    assert _state(a_child, p_child)[0] == _state(a_child, p_child)[1]


# ---------------------------------------------------------------- in a cell of ACE's landscape


def _landscape_scene():
    from acconform.scene import Landblock, Mover, Position, Scene, SphereRec

    pos = Position(0xA9B40001, Frame((12.0, 12.0, 0.0)))
    mover = Mover((SphereRec((0.0, 0.0, 0.5), 0.5),), pos, pos, 0.5, 0.5)
    return Scene((Landblock(0xA9B4FFFF, (0,) * 81, (0,) * 81),), mover)


def _cells(a_obj, p_obj):
    a_cell = 0 if a_obj.CurCell is None else int(a_obj.CurCell.ID)
    p_cell = 0 if p_obj.cur_cell is None else p_obj.cur_cell.id
    return ((a_cell, [int(k) for k in a_obj.ShadowObjects.Keys], int(a_obj.NumShadowObjects)),
            (p_cell, list(p_obj.shadow_objects), p_obj.num_shadow_objects))


@pytest.mark.anchor("CPhysicsObj::set_parent")
def test_a_child_parented_in_a_cell_takes_aces_cells_and_follows_its_parent_across_them(live, ace):
    """ACE's world: the scene's landblock as the live oracle built it (a scene run first; its
    landblock stays in LScape until the next scene). The parent placed by add_obj_to_cell, the
    child parented (change_cell into the parent's cell, recalc_cross_cells with its sorting sphere),
    the parent moved by set_frame, then into the next cell by change_cell and recalc_cross_cells:
    the child's cell, shadow cells, frame and flags against the port's after every step. Both leave
    their cells after, so the cached landblock is as the live oracle left it."""
    from acconform.port.dat.cell_dat import CellDat
    from acconform.port.land.lscape import LScape
    from ACE.DatLoader import DatManager  # type: ignore[import-not-found]
    from ACE.DatLoader.FileTypes import GfxObj, SetupModel  # type: ignore[import-not-found]
    from ACE.Server.Physics.Common import LScape as AceLScape  # type: ignore[import-not-found]
    from System.IO import BinaryReader, MemoryStream  # type: ignore[import-not-found]

    Physics, mode = ace
    scene = _landscape_scene()
    assert live.run(scene).error is None
    cache = DatManager.PortalDat.FileCache  # the run's Reset emptied it: the records again
    for i, data in w.records().items():
        file = SetupModel() if i >> 24 == 2 else GfxObj()
        file.Unpack(BinaryReader(MemoryStream(bytes(data))))
        cache[i] = file
    Physics.PhysicsEngine.Instance.Server = True

    pd = PortalDat(w.records(), mode, True)
    lscape = LScape(scene, mode, pd, CellDat({}, mode))
    a_parent = Physics.PhysicsObj.makeObject(w.PARENT_SETUP, w.PARENT_ID, True, False)
    a_child = Physics.PhysicsObj.makeObject(w.CHILD_SETUP, w.CHILD_ID, True, False)
    p_parent = PhysicsObj.make_object(w.PARENT_SETUP, w.PARENT_ID, True, pd)
    p_child = PhysicsObj.make_object(w.CHILD_SETUP, w.CHILD_ID, True, pd)
    try:
        start = ((23.5, 12.0, 0.0), (1.0, 0.0, 0.0, 0.0))
        a_parent.add_obj_to_cell(AceLScape.get_landcell(0xA9B40001), _ace_frame(Physics, *start))
        p_parent.add_obj_to_cell(lscape.get_landcell(0xA9B40001), AFrame.from_record(Frame(*start), mode), lscape)
        assert _cells(a_parent, p_parent)[0] == _cells(a_parent, p_parent)[1]

        a_child.SetPlacementFrame(0x65, False)
        assert a_child.set_parent(a_parent, w.SHIELD)
        assert parenting.set_parent(p_child, p_parent, w.SHIELD, 0x65, lscape)

        def same(step):
            assert _bits_ace(a_child.Position.Frame) == _bits_port(p_child.position.frame), step
            ac, pc = _cells(a_child, p_child)
            assert ac == pc, step
            assert _state(a_child, p_child)[0] == _state(a_child, p_child)[1], step
            return pc

        cells = {tuple(same("set_parent")[1])}
        for origin, wxyz in w.MOVES[:2] + (((24.2, 12.0, 0.0), (1.0, 0.0, 0.0, 0.0)),):
            a_parent.set_frame(_ace_frame(Physics, origin, wxyz))
            p_parent.set_frame(AFrame.from_record(Frame(origin, wxyz), mode))
            same(("set_frame", origin))
        a_parent.change_cell(AceLScape.get_landcell(0xA9B40009))
        p_parent.change_cell(lscape.get_landcell(0xA9B40009), lscape)
        cells.add(tuple(same("change_cell")[1]))
        a_parent.recalc_cross_cells()
        p_parent.recalc_cross_cells(lscape)
        cells.add(tuple(same("recalc_cross_cells")[1]))
        assert len(cells) > 1  # the child's shadow cells changed along the way
    finally:
        for obj in (a_child, a_parent):
            obj.remove_shadows_from_cells()
            obj.leave_cell(False)


def _set_ace_clock(t: float) -> None:
    """Timers.PortalYearTicks (ACE's PhysicsTimer.CurrentTime), as the facade's SetClock sets it."""
    import clr  # type: ignore[import-not-found]  # noqa: F401
    from System.Reflection import BindingFlags  # type: ignore[import-not-found]
    from ACE.Server.Entity import Timers  # type: ignore[import-not-found]

    prop = clr.GetClrType(Timers).GetProperty("PortalYearTicks", BindingFlags.Public | BindingFlags.Static)
    prop.GetSetMethod(True).Invoke(None, [float(t)])


@pytest.mark.anchor("CPhysicsObj::UpdateChildrenInternal")
def test_a_child_follows_its_parents_update_object_ticks_across_cells_as_in_ace(live, ace):
    """The parent (dynamic, Active, gravity, a velocity east) placed just west of a cell edge, ticked
    by update_object with the clock 0.05 s on each time (UpdateObjectInternal's transition and
    SetPositionInternal: set_frame, and change_cell when the parent crosses into the next cell, which
    takes the children along): the parent's and the child's frame, cells and flags against the port's
    after every tick."""
    from acconform.port.dat.cell_dat import CellDat
    from acconform.port.land.lscape import LScape
    from acconform.port.physics_timer import PhysicsTimer
    from ACE.DatLoader import DatManager  # type: ignore[import-not-found]
    from ACE.DatLoader.FileTypes import GfxObj, SetupModel  # type: ignore[import-not-found]
    from ACE.Server.Physics.Common import LScape as AceLScape  # type: ignore[import-not-found]
    from System.IO import BinaryReader, MemoryStream  # type: ignore[import-not-found]
    from System.Numerics import Vector3  # type: ignore[import-not-found]

    Physics, mode = ace
    scene = _landscape_scene()
    assert live.run(scene).error is None
    cache = DatManager.PortalDat.FileCache
    for i, data in w.records().items():
        file = SetupModel() if i >> 24 == 2 else GfxObj()
        file.Unpack(BinaryReader(MemoryStream(bytes(data))))
        cache[i] = file
    Physics.PhysicsEngine.Instance.Server = True
    t0 = 1000.0
    _set_ace_clock(t0)
    timer = PhysicsTimer(t0)

    pd = PortalDat(w.records(), mode, True, timer)
    lscape = LScape(scene, mode, pd, CellDat({}, mode))
    a_parent = Physics.PhysicsObj.makeObject(w.PARENT_SETUP, w.PARENT_ID, True, False)
    a_child = Physics.PhysicsObj.makeObject(w.CHILD_SETUP, w.CHILD_ID, True, False)
    p_parent = PhysicsObj.make_object(w.PARENT_SETUP, w.PARENT_ID, True, pd)
    p_child = PhysicsObj.make_object(w.CHILD_SETUP, w.CHILD_ID, True, pd)
    try:
        start = ((23.5, 12.0, 0.0), (1.0, 0.0, 0.0, 0.0))
        a_parent.add_obj_to_cell(AceLScape.get_landcell(0xA9B40001), _ace_frame(Physics, *start))
        p_parent.add_obj_to_cell(lscape.get_landcell(0xA9B40001), AFrame.from_record(Frame(*start), mode), lscape)
        a_child.SetPlacementFrame(0x65, False)
        assert a_child.set_parent(a_parent, w.SHIELD)
        assert parenting.set_parent(p_child, p_parent, w.SHIELD, 0x65, lscape)
        assert a_parent.set_active(True) and p_parent.set_active(True)
        a_parent.set_velocity(Vector3(float(f(4.0)), 0.0, 0.0), False)
        p_parent.set_velocity(mode.vec(4.0, 0.0, 0.0), False)

        parent_cells = set()
        for k in range(1, 9):
            t = t0 + 0.05 * k
            _set_ace_clock(t)
            timer.set(t)
            assert bool(a_parent.update_object()) == p_parent.update_object(lscape)
            assert _bits_ace(a_parent.Position.Frame) == _bits_port(p_parent.position.frame), k
            assert _cells(a_parent, p_parent)[0][0] == _cells(a_parent, p_parent)[1][0], k
            assert _bits_ace(a_child.Position.Frame) == _bits_port(p_child.position.frame), k
            assert _cells(a_child, p_child)[0] == _cells(a_child, p_child)[1], k
            assert _state(a_child, p_child)[0] == _state(a_child, p_child)[1], k
            assert _state(a_parent, p_parent)[0] == _state(a_parent, p_parent)[1], k
            parent_cells.add(p_parent.cur_cell.id)
        assert parent_cells == {0xA9B40001, 0xA9B40009}  # it crossed the edge, the child with it
        assert p_child.cur_cell.id == 0xA9B40009
    finally:
        for obj in (a_child, a_parent):
            obj.remove_shadows_from_cells()
            obj.leave_cell(False)
