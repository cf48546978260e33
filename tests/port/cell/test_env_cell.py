"""EnvCells built from DatLoader records (indoor_rooms.py's bytes): the readers, CellStruct's cell-tree
questions, find_transit_cells through portals, find_cell_list's indoor branch and transitions
walking across portals and off ledges inside."""

from __future__ import annotations

import pytest

from acconform.flags import PhysicsState, TransientState
from acconform.numerics import EXACT
from acconform.port.bbox import BBox
from acconform.port.cell.env_cell import EnvCell
from acconform.port.cell.obj_cell import find_cell_list
from acconform.port.dat.binary_reader import BinaryReader
from acconform.port.dat.bsp_node import BSP_TYPE_CELL, BSP_TYPE_DRAWING, read_node
from acconform.port.dat.bsp_portal import BSPPortal
from acconform.port.dat.env_cell import EnvCell as DatEnvCell
from acconform.port.dat.environment import Environment as DatEnvironment
from acconform.port.errors import ArgumentException, InvalidCastException
from acconform.port.frame import AFrame, Position
from acconform.port.geom.bsp import BoundingType
from acconform.port.geom.sphere import Sphere
from acconform.port.transition.branches import Trace
from acconform.port.transition.cell_array import CellArray
from acconform import dat
from acconform.port.run import run_scene
from acconform.scene import Frame as FrameRec
from indoor_rooms import LB, ENV_ID, indoor_scene, portal, room, tag, two_rooms, world

WALK = int(PhysicsState.EdgeSlide | PhysicsState.Gravity)
NO_EDGE_SLIDE = int(PhysicsState.Gravity)
GROUNDED = int(TransientState.Contact | TransientState.OnWalkable)
A, B = LB | 0x0100, LB | 0x0101
v = EXACT.vec


def rooms_world(**kw):
    env, cells = two_rooms(**kw)
    scene = indoor_scene(env, cells, (63.0, 60.0, 20.0), (63.0, 60.0, 20.0), state=WALK, transient=GROUNDED,
                         begin_cell=A, end_cell=A)
    return world(scene, EXACT)[0]


def across(env, cells, start, end, state=WALK, begin=A, trace=None):
    scene = indoor_scene(env, cells, start, end, state=state, transient=GROUNDED, begin_cell=begin, end_cell=begin)
    return run_scene(scene, trace=trace)


# ---------------------------------------------------------------- DatLoader readers


@pytest.mark.anchor("ACE.DatLoader/FileTypes/EnvCell.cs:Unpack")
def test_an_env_cell_record_reads_back_its_portals_visible_cells_stabs_and_widened_ids():
    import struct
    rec = room(0x0100, 60.0, portals=(portal(0, 0x0101, flags=0x2), portal(1, 0xFFFF)), visible=(0x0101, 0x0102),
               seen_outside=True)
    data = dat.env_cell_record(rec, ((0x01000005, FrameRec((1.0, 2.0, 3.0))),)).data
    # the writer never sets HasRestrictionObj: add it and the id it guards
    data = data[:4] + struct.pack("<I", struct.unpack_from("<I", data, 4)[0] | 0x8) + data[8:] + struct.pack("<I", 7)
    c = DatEnvCell.unpack(BinaryReader(data, EXACT))
    assert c.id == A and c.flags == 0xB and c.seen_outside
    assert c.environment_id == ENV_ID and c.cell_structure == 0 and c.surfaces == []
    assert [(p.polygon_id, p.other_cell_id, p.portal_side) for p in c.cell_portals] == [(0, 0x0101, False), (1, 0xFFFF, True)]
    assert c.visible_cells == [0x0101, 0x0102]
    assert [(s.id, float(s.frame.origin.y), float(s.frame.orientation.w)) for s in c.static_objects] == [(0x01000005, 2.0, 1.0)]
    assert c.restriction_obj == 7
    assert float(c.position.origin.x) == 60.0


@pytest.mark.anchor("ACE.DatLoader/Entity/CellStruct.cs:Unpack")
@pytest.mark.anchor("ACE.DatLoader/FileTypes/Environment.cs:Unpack")
@pytest.mark.anchor("ACE.DatLoader/UnpackableExtensions.cs:Unpack(Dictionary<uint, T>)")
def test_a_cell_struct_reads_its_cell_tree_as_planes_and_children_only_after_the_dword_alignment():
    env, _ = two_rooms()
    e = DatEnvironment.unpack(BinaryReader(dat.environment_record(env).data, EXACT))
    assert e.id == ENV_ID and sorted(e.cells) == [0, 1]
    s = e.cells[0]
    assert s.portals == [0, 1] and len(s.polygons) == 2 and len(s.physics_polygons) == 2
    node, depth = s.cell_bsp.root_node, 0
    while node is not None:
        assert node.sphere is None and node.in_polys is None and node.neg_node is None
        node, depth = node.pos_node, depth + 1
    assert depth == 6
    assert s.physics_bsp.root_node.sphere is not None  # the physics tree keeps its spheres


@pytest.mark.anchor("ACE.DatLoader/Entity/BSPNode.cs:ReadNode")
@pytest.mark.parametrize("name, front, back", [("BPnn", True, False), ("BPIn", True, False), ("BpIN", False, True),
                                               ("BpnN", False, True), ("BPIN", True, True), ("BPnN", True, True),
                                               ("BpIn", False, False), ("BPOL", False, False)])
def test_a_cell_tree_node_reads_the_children_its_tag_names(name, front, back):
    leaf = tag("LEAF") + (3).to_bytes(4, "little")
    data = tag(name) + b"\0" * 16 + leaf * (front + back)
    node = read_node(BinaryReader(data, EXACT), BSP_TYPE_CELL)
    assert (node.pos_node is not None, node.neg_node is not None) == (front, back)
    assert node.type == name


@pytest.mark.anchor("ACE.DatLoader/Entity/BSPPortal.cs:Unpack")
@pytest.mark.anchor("ACE.DatLoader/Entity/PortalPoly.cs:Unpack")
def test_a_drawing_trees_portal_node_reads_both_children_its_sphere_polygons_and_portal_polygons():
    import struct
    leaf = tag("LEAF") + (0).to_bytes(4, "little")
    data = (tag("PORT") + struct.pack("<4f", 1, 0, 0, -5) + leaf + leaf + struct.pack("<4f", 0, 0, 0, 9)
            + struct.pack("<II", 2, 1) + struct.pack("<HH", 4, 5) + struct.pack("<hh", 0, 4))
    reader = BinaryReader(data, EXACT)
    node = read_node(reader, BSP_TYPE_DRAWING)
    assert isinstance(node, BSPPortal) and node.in_polys == [4, 5]
    assert [(p.portal_index, p.polygon_id) for p in node.in_portals] == [(0, 4)]
    assert reader.position == len(data)


@pytest.mark.anchor("ACE.DatLoader/Entity/CellStruct.cs:Unpack")
@pytest.mark.anchor("ACE.DatLoader/Entity/BSPPortal.cs:Unpack")
@pytest.mark.anchor("ACE.DatLoader/Entity/PortalPoly.cs:Unpack")
@pytest.mark.anchor("ACE.DatLoader/Entity/BSPLeaf.cs:Unpack")
def test_a_cell_structs_drawing_tree_reads_its_portal_polygons_in_port_nodes_to_the_records_last_byte():
    env, _ = two_rooms()
    data = dat.environment_record(env).data
    reader = BinaryReader(data, EXACT)
    e = DatEnvironment.unpack(reader)
    assert reader.position == len(data)
    for s in e.cells.values():
        root = s.drawing_bsp.root_node  # polygon 0 at the root, polygon 1 in its front subtree
        assert isinstance(root, BSPPortal) and root.in_polys == [1] and root.sphere is not None
        assert [(p.portal_index, p.polygon_id) for p in root.in_portals] == [(1, 1)]
        front = root.pos_node
        assert isinstance(front, BSPPortal) and [(p.portal_index, p.polygon_id) for p in front.in_portals] == [(0, 0)]
        leaves = [front.pos_node, front.neg_node, root.neg_node]
        assert [(n.type, n.leaf_index, n.sphere, n.in_polys) for n in leaves] == [("LEAF", i, None, None) for i in range(3)]


# ---------------------------------------------------------------- CellStruct, EnvCell


@pytest.mark.anchor("CCellStruct::UnPack")
@pytest.mark.anchor("BSPTREE::UnPack")
@pytest.mark.anchor("BSPNODE::UnPackChild")
@pytest.mark.anchor("BSPLeaf.cs:BSPLeaf(DatLoader.Entity.BSPLeaf, Dictionary<ushort, Polygon>, CVertexArray)")
def test_a_cell_struct_builds_its_drawing_tree_over_its_polygons_with_portal_nodes_as_plain_nodes():
    from acconform.port.cell.cell_struct import CellStruct
    from acconform.port.geom.bsp import BSPLeaf, BSPNode

    env, _ = two_rooms()
    s = DatEnvironment.unpack(BinaryReader(dat.environment_record(env).data, EXACT)).cells[0]
    c = CellStruct.from_dat(s, EXACT)
    root = c.drawing_bsp.root_node
    assert type(root) is BSPNode and type(root.pos_node) is BSPNode  # ACE: a DAT PORT node is no BSPLeaf
    assert root.num_polys == 1 and root.polygons[0].plane == c.polygons[1].plane
    assert root.polygons[0] is not c.polygons[1]  # PolygonCache is off: a Polygon of its own
    assert root.pos_node.polygons[0].plane == c.polygons[0].plane
    assert root.splitting_plane.normal == EXACT.vec(-1, 0, 0) and root.splitting_plane.d == EXACT.scalar(-5)  # x = -5
    leaf = root.neg_node
    assert type(leaf) is BSPLeaf and leaf.num_polys == 0 and leaf.sphere is None and not leaf.solid


@pytest.mark.anchor("CEnvCell::point_in_cell")
@pytest.mark.anchor("CCellStruct::point_in_cell")
@pytest.mark.anchor("BSPTREE::point_inside_cell_bsp")
@pytest.mark.anchor("BSPNODE::point_inside_cell_bsp")
def test_point_in_cell_holds_points_inside_the_rooms_cell_tree_in_its_frame_and_not_beyond_its_walls():
    a = rooms_world().get_landcell(A)
    assert a.point_in_cell(v(61, 60, 21)) and a.point_in_cell(v(65, 60, 20))  # on the wall plane: Close counts
    assert not a.point_in_cell(v(66, 60, 21)) and not a.point_in_cell(v(60, 60, 19))


@pytest.mark.anchor("CCellStruct::sphere_intersects_cell")
@pytest.mark.anchor("BSPTREE::sphere_intersects_cell_bsp")
@pytest.mark.anchor("BSPNODE::sphere_intersects_cell_bsp")
def test_sphere_intersects_cell_tells_entirely_inside_from_straddling_a_wall_and_outside():
    s = rooms_world().get_landcell(A).cell_structure
    assert s.sphere_intersects_cell(Sphere(v(0, 0, 2), EXACT.scalar(1))) == BoundingType.EntirelyInside
    assert s.sphere_intersects_cell(Sphere(v(4.8, 0, 2), EXACT.scalar(0.5))) == BoundingType.PartiallyInside
    assert s.sphere_intersects_cell(Sphere(v(6, 0, 2), EXACT.scalar(0.5))) == BoundingType.Outside


@pytest.mark.anchor("CCellStruct::box_intersects_cell")
@pytest.mark.anchor("BSPTREE::box_intersects_cell_bsp")
@pytest.mark.anchor("BSPNODE::box_intersects_cell_bsp")
@pytest.mark.anchor("BSPNode.cs:box_intersects_cell_bsp_inner")
@pytest.mark.anchor("BBox.cs:GetCorners")
def test_box_intersects_cell_is_false_only_for_a_box_wholly_behind_one_wall():
    s = rooms_world().get_landcell(A).cell_structure
    assert s.box_intersects_cell(BBox(v(-1, -1, 1), v(1, 1, 2)))
    assert s.box_intersects_cell(BBox(v(4, -1, 1), v(6, 1, 2)))
    assert not s.box_intersects_cell(BBox(v(-8, -1, 1), v(-6, 1, 2)))


@pytest.mark.anchor("CEnvCell::build_visible_cells")
@pytest.mark.anchor("CCellStruct::UnPack")
@pytest.mark.anchor("EnvCell.cs:PostInit")
@pytest.mark.anchor("DBObj.cs:GetEnvCell")
@pytest.mark.anchor("DBObj.cs:GetEnvironment")
def test_building_a_cell_builds_every_cell_it_sees_keyed_by_short_id_and_caches_them_in_the_landblock():
    lscape = rooms_world()
    a = lscape.get_landcell(A)
    b = lscape.get_landcell(B)
    assert a.visible_cells == {0x0101: b} and b.visible_cells == {0x0100: a}
    landblock = lscape.get_landblock(A)
    assert landblock.land_cells[0x0100] is a and landblock.land_cells[0x0101] is b


@pytest.mark.anchor("CEnvCell::build_visible_cells")
def test_a_short_visible_cell_id_listed_twice_throws_argument_exception():
    env, (a, b) = two_rooms()
    a = a.__class__(a.id, a.frame, a.environment, a.cell_structure, a.portals, (0x0101, 0x0101))
    scene = indoor_scene(env, (a, b), (63, 60, 20), (63, 60, 20), state=WALK, transient=GROUNDED, begin_cell=A, end_cell=A)
    with pytest.raises(ArgumentException):
        world(scene, EXACT)[0].get_landcell(A)


@pytest.mark.anchor("CEnvCell::build_visible_cells")
def test_an_outdoor_cell_in_the_visible_list_is_an_invalid_cast():
    env, (a, b) = two_rooms()
    a = a.__class__(a.id, a.frame, a.environment, a.cell_structure, a.portals, (0x0001,))
    scene = indoor_scene(env, (a, b), (63, 60, 20), (63, 60, 20), state=WALK, transient=GROUNDED, begin_cell=A, end_cell=A)
    with pytest.raises(InvalidCastException):
        world(scene, EXACT)[0].get_landcell(A)


def _path(trace=None):
    from acconform.port.transition.sphere_path import SpherePath

    path = SpherePath(EXACT)
    path.trace = trace
    return path


def _transit(lscape, cell_id, center, radius=0.48, trace=None):
    cells = CellArray()
    sphere = Sphere(v(*center), EXACT.scalar(radius))
    position = Position(cell_id, AFrame(v(*center), EXACT.quat(0, 0, 0, 1)))
    lscape.get_landcell(cell_id).find_transit_cells(lscape, position, 1, [sphere], cells, _path(trace))
    return cells.cells


@pytest.mark.anchor("CEnvCell::find_transit_cells")
def test_find_transit_cells_adds_the_neighbour_a_sphere_reaches_through_a_portal_and_nothing_from_mid_room():
    lscape = rooms_world()
    trace = Trace()
    assert _transit(lscape, A, (64.8, 60, 21), trace=trace).keys() == [B]
    assert trace["env_cell:other_cell"] == 1
    assert _transit(lscape, A, (60, 60, 21), trace=trace).keys() == []
    assert trace["env_cell:other_cell"] == 1


@pytest.mark.anchor("CEnvCell::find_transit_cells")
def test_find_transit_cells_adds_an_unloaded_neighbour_under_its_short_id_with_no_cell():
    env, (a, b) = two_rooms()
    a = room(0x0100, 60.0, portals=(portal(0, 0x0105),))  # 0x0105: not visible, never loaded
    scene = indoor_scene(env, (a, b), (63, 60, 20), (63, 60, 20), state=WALK, transient=GROUNDED, begin_cell=A, end_cell=A)
    lscape = world(scene, EXACT)[0]
    trace = Trace()
    cells = _transit(lscape, A, (64.8, 60, 21), trace=trace)
    assert cells.keys() == [0x0105] and cells[0x0105] is None and trace["env_cell:unloaded_cell"] == 1


@pytest.mark.anchor("CEnvCell::find_transit_cells")
def test_a_portal_to_0xffff_adds_the_outdoor_cells_the_sphere_touches():
    env, (a, b) = two_rooms()
    a = room(0x0100, 60.0, portals=(portal(0, 0xFFFF),), seen_outside=True)
    scene = indoor_scene(env, (a, b), (63, 60, 20), (63, 60, 20), state=WALK, transient=GROUNDED, begin_cell=A, end_cell=A)
    lscape = world(scene, EXACT)[0]
    trace = Trace()
    assert _transit(lscape, A, (64.8, 60, 21), trace=trace).keys() == [LB | (2 * 8 + 2 + 1)]  # the cell at (64.8, 60)
    assert _transit(lscape, A, (62, 60, 21), trace=trace).keys() == []
    assert trace["env_cell:outside_portal"] == 1


@pytest.mark.anchor("CObjCell::find_cell_list")
def test_find_cell_list_indoors_keeps_the_first_env_cell_holding_the_center_and_flags_an_interior_hit():
    lscape = rooms_world()
    cells = CellArray()
    sphere = Sphere(v(64.8, 60, 20.48), EXACT.scalar(0.48))
    position = Position(A, AFrame(v(64.8, 60, 20), EXACT.quat(0, 0, 0, 1)))
    path = _path()
    current = find_cell_list(lscape, position, 1, [sphere], cells, lscape.get_landcell(A), path)
    assert cells.cells.keys() == [A, B] and current.id == A and path.hits_interior_cell


@pytest.mark.anchor("CObjCell::find_cell_list")
def test_find_cell_list_indoors_drops_cells_the_position_cell_does_not_see():
    env, (a, b) = two_rooms()
    c = room(0x0102, 90.0)  # sees nothing, seen by nothing
    scene = indoor_scene(env, (a, b, c), (63, 60, 20), (63, 60, 20), state=WALK, transient=GROUNDED, begin_cell=A,
                         end_cell=A)
    lscape = world(scene, EXACT)[0]
    cells = CellArray()
    cells.add_cell(LB | 0x0102, lscape.get_landcell(LB | 0x0102))  # a stale entry (CellArray is never cleared)
    position = Position(B, AFrame(v(70, 60, 20), EXACT.quat(0, 0, 0, 1)))
    trace = Trace()
    find_cell_list(lscape, position, 1, [Sphere(v(70, 60, 20.48), EXACT.scalar(0.48))], cells, None, _path(trace))
    assert cells.cells.keys() == [B] and trace["find_cell_list:pruned"] == 1 and trace["find_cell_list:indoor"] == 1


# ---------------------------------------------------------------- transitions indoors


@pytest.mark.anchor("CEnvCell::find_env_collisions")
def test_a_mover_walks_across_a_portal_into_the_neighbouring_room_on_its_floor():
    env, cells = two_rooms()
    trace = Trace()
    out = across(env, cells, (63.0, 60.0, 20.0), (67.0, 60.0, 20.0), trace=trace)
    assert out.error is None and out.ok and out.cell == B and out.origin[2] == 20.0
    assert out.contact_plane.valid
    assert trace["env_cell:physics_bsp"] and trace["env_cell:other_cell"] and trace["find_cell_list:indoor"]


@pytest.mark.anchor("CEnvCell::find_collisions")
def test_a_mover_walking_into_the_rooms_back_wall_stops_against_it():
    env, cells = two_rooms()
    out = across(env, cells, (57.0, 60.0, 20.0), (53.0, 60.0, 20.0))
    assert out.cell == A and 55.48 <= out.origin[0] < 57.0
    assert out.collision_normal.valid


@pytest.mark.anchor("CTransition::step_down")
def test_a_mover_steps_down_a_small_ledge_onto_the_next_rooms_lower_floor():
    env, cells = two_rooms(z_b=19.8)
    out = across(env, cells, (63.0, 60.0, 20.0), (67.0, 60.0, 20.0))
    assert out.ok and out.cell == B and out.origin[2] == pytest.approx(19.8, abs=1e-5)
    assert out.contact_plane.valid


@pytest.mark.anchor("CSpherePath::precipice_slide")
def test_with_edge_slide_a_mover_stops_at_a_tall_ledge_by_precipice_slide_off_the_rooms_floor():
    env, cells = two_rooms(z_b=17.0)
    trace = Trace()
    out = across(env, cells, (63.0, 60.0, 20.0), (67.0, 60.0, 20.0), trace=trace)
    assert out.origin[0] < 67.0 and out.origin[2] == 20.0
    assert trace["edge_slide:back_probe_precipice_slide"] or trace["edge_slide:precipice_slide"]


@pytest.mark.anchor("CTransition::edge_slide")
def test_without_edge_slide_a_mover_walks_off_a_tall_ledge_and_loses_contact():
    env, cells = two_rooms(z_b=17.0)
    out = across(env, cells, (63.0, 60.0, 20.0), (67.0, 60.0, 20.0), state=NO_EDGE_SLIDE)
    assert out.ok and out.cell == B and out.origin[0] == pytest.approx(67.0, abs=1e-4)
    assert not out.contact_plane.valid


@pytest.mark.anchor("CEnvCell::init_static_objects")
def test_an_env_cells_stabs_become_statics_registered_in_the_cell_and_the_neighbour_they_straddle():
    from acconform.scene import StaticObject, Position as PosRec
    from object_scenes import box

    env, cells = two_rooms()
    boulder = StaticObject(0x70000000, PosRec(A, FrameRec((64.5, 60.0, 20.0))), box(2.0, 2.0, 2.0))
    scene = indoor_scene(env, cells, (61, 60, 20), (61, 60, 20), state=WALK, transient=GROUNDED, begin_cell=A,
                         end_cell=A, objects=(boulder,))
    lscape, _ = world(scene, EXACT)
    a = lscape.get_landcell(A)
    (static,) = a.static_objects
    assert static.id == 0 and static.dat_object and static.cur_cell is a
    assert list(static.shadow_objects) == [A, B]
    assert a.shadow_object_list[0].physics_obj is static
    assert run_scene(scene).static_cells == ((A, B),)


@pytest.mark.anchor("CEnvCell::init_static_objects")
def test_a_stab_of_a_setup_with_no_parts_is_destroyed_and_left_out_of_the_cell():
    """A Setup with no parts makes no PartArray (InitParts fails), so add_obj_to_cell's enter_cell leaves CurCell
    null: ACE's init_static_objects destroys that stab and goes on (EnvCell.cs init_static_objects)."""
    from acconform.scene import Position as PosRec, SetupRec, StaticObject
    from object_scenes import box

    env, cells = two_rooms()
    empty = StaticObject(0x70000000, PosRec(A, FrameRec((62.0, 60.0, 20.0))), None, setup=SetupRec(()))
    boulder = StaticObject(0x70000001, PosRec(A, FrameRec((64.5, 60.0, 20.0))), box(2.0, 2.0, 2.0))
    scene = indoor_scene(env, cells, (61, 60, 20), (61, 60, 20), state=WALK, transient=GROUNDED, begin_cell=A,
                         end_cell=A, objects=(empty, boulder))
    lscape, _ = world(scene, EXACT)
    a = lscape.get_landcell(A)
    (static,) = a.static_objects
    assert static.part_array is not None and static.cur_cell is a
    assert run_scene(scene).static_cells == ((), (A, B))
