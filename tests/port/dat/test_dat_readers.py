"""port/dat: DatLoader's readers read back what acconform/dat.py writes, and ACE's DAT constructors
build the physics objects a static's placement reads (parts, Pos, bounding box, BSP root)."""

from __future__ import annotations

import struct

import numpy as np
import pytest

from acconform import dat
from acconform.flags import CullMode, PhysicsState
from acconform.numerics import EXACT, f32_bits
from acconform.port import constants as k
from acconform.port.dat.binary_reader import BinaryReader
from acconform.port.dat.bsp_leaf import BSPLeaf as DatLeaf
from acconform.port.dat.bsp_node import BSP_TYPE_PHYSICS, BSPNode as DatNode, read_node
from acconform.port.dat.gfx_obj import GfxObj as DatGfxObj
from acconform.port.dat.portal_dat import PortalDat
from acconform.port.dat.setup_model import SetupModel
from acconform.port.errors import EndOfStreamException
from acconform.port.geom.bsp import BSPLeaf, BSPNode
from acconform.port.physics_obj import PhysicsObj
from acconform.scene import CylSphereShape, SphereRec, SphereShape
from dat_shapes import dat_gfx_obj, gfx_obj
from object_scenes import box
from straddle_scenes import leaf_root_box

F = np.float32


def reader(data: bytes) -> BinaryReader:
    return BinaryReader(data, EXACT)


@pytest.mark.anchor("ACE.DatLoader/BinaryReaderExtensions.cs:ReadCompressedUInt32")
@pytest.mark.parametrize("n", [0, 0x7F, 0x80, 0x3FFF, 0x4000, 0x12345678 & 0x3FFFFFFF])
def test_compressed_uint32_reads_back_its_one_two_and_four_byte_forms(n):
    assert reader(dat.compressed_u32(n)).read_compressed_uint32() == n


@pytest.mark.anchor("ACE.DatLoader/FileTypes/GfxObj.cs:Unpack")
def test_a_bsp_shapes_gfx_obj_record_reads_back_its_vertices_polygons_and_tree():
    shape = box(2.0, 2.0, 2.0)
    g = dat_gfx_obj(shape, EXACT)
    assert g.id == dat.GFX_OBJ_BASE and g.flags == 1 and g.surfaces == []
    assert len(g.vertex_array.vertices) == 8  # the box's corners, each once
    assert sorted(g.physics_polygons) == list(range(6))
    assert all(p.num_pts == 4 and p.sides_type == CullMode.Clockwise and p.pos_uv_indices == [] for p in
               g.physics_polygons.values())
    root = g.physics_bsp.root_node
    assert type(root) is DatNode and root.type == "BPIN" and root.in_polys is None
    node, leaves = root, 0
    while type(node) is DatNode:
        assert isinstance(node.pos_node, DatLeaf) and node.pos_node.in_polys == []
        node, leaves = node.neg_node, leaves + 1
    assert isinstance(node, DatLeaf) and node.solid == 1 and node.in_polys == list(range(6)) and node.leaf_index == 6


@pytest.mark.anchor("ACE.DatLoader/Entity/BSPNode.cs:Unpack")
def test_a_node_tagged_bpnn_reads_a_front_child_only():
    leaf = struct.pack("<Iii4fI", 0x4C454146, 0, 1, 0.0, 0.0, 0.0, 1.0, 0)
    data = struct.pack("<I4f", 0x42506E6E, 0.0, 0.0, 1.0, 0.0) + leaf + struct.pack("<4f", 0.0, 0.0, 0.0, 2.0)
    r = reader(data)
    node = read_node(r, BSP_TYPE_PHYSICS)
    assert node.type == "BPnn" and isinstance(node.pos_node, DatLeaf) and node.neg_node is None
    assert node.sphere.radius == F(2.0) and r.position == len(data)


@pytest.mark.anchor("ACE.DatLoader/FileTypes/GfxObj.cs:Unpack")
def test_a_record_cut_short_is_an_end_of_stream_exception():
    data = dat.gfx_obj_physics(dat.GFX_OBJ_BASE, box(1.0, 1.0, 1.0))
    with pytest.raises(EndOfStreamException):
        DatGfxObj.unpack(reader(data[:-5]))


@pytest.mark.anchor("ACE.DatLoader/FileTypes/SetupModel.cs:Unpack")
def test_a_cylsphere_setup_record_reads_back_its_part_and_cylsphere():
    o = StaticObjectAt(CylSphereShape((0.0, 0.0, 0.5), 1.5, 2.0))
    recs = dat.static_records(o, 3)
    s = SetupModel.unpack(reader(recs.records[-1].data))
    assert s.id == dat.SETUP_BASE + 3 and s.parts == [dat.GFX_OBJ_BASE + 3] and s.placement_frames == {}
    (c,) = s.cyl_spheres
    assert (c.origin.z, c.radius, c.height) == (F(0.5), F(1.5), F(2.0)) and s.spheres == []


def StaticObjectAt(shape, state=int(PhysicsState.Static)):
    from acconform.scene import Frame, Position, StaticObject

    return StaticObject(0x70000001, Position(0xA9B40001, Frame((10.0, 10.0, 20.0))), shape, state)


def portal_for(shape) -> tuple[PortalDat, int]:
    recs = dat.static_records(StaticObjectAt(shape), 0)
    return PortalDat({r.id: r.data for r in recs.records}, EXACT, True), recs.did


# ---------------------------------------------------------------- ACE's constructors


@pytest.mark.anchor("CGfxObj::InitEnd")
def test_gfx_obj_init_bounds_the_vertices():
    g = gfx_obj(box(2.0, 4.0, 1.0), EXACT)
    assert (g.gfx_bound_box.min, g.gfx_bound_box.max) == (EXACT.vec(-1, -2, 0), EXACT.vec(1, 2, 1))
    assert g.physics_sphere is g.physics_bsp.root_node.sphere  # PhysicsBSP.GetSphere()


@pytest.mark.anchor("BSPTREE::UnPack")
def test_a_dat_leaf_at_the_root_becomes_a_childless_bsp_node():
    g = gfx_obj(leaf_root_box(2.0, 2.0, 2.0), EXACT)
    root = g.physics_bsp.root_node
    assert type(root) is BSPNode and not isinstance(root, BSPLeaf)
    assert root.pos_node is None and root.neg_node is None and root.num_polys == 6
    assert root.splitting_plane.normal == EXACT.vec(0, 0, 0) and root.splitting_plane.d == F(0)


@pytest.mark.anchor("CPhysicsObj::makeObject")
def test_a_bsp_object_is_a_mesh_whose_single_part_shares_the_objects_position():
    portal, did = portal_for(box(1.0, 1.0, 1.0))
    obj = PhysicsObj.make_object(did, 0x70000001, False, portal)
    pa = obj.part_array
    assert pa.num_parts == 1 and pa.parts[0].pos is obj.position  # UpdateParts with no placement frame
    assert obj.state & PhysicsState.Static and obj.state & PhysicsState.HasPhysicsBSP
    assert pa.setup.num_sphere == 0 and pa.setup.allow_free_heading  # MakeSimpleSetup


@pytest.mark.anchor("CPhysicsObj::makeObject")
def test_a_sphere_object_is_a_setup_with_one_part_and_no_physics_bsp():
    portal, did = portal_for(SphereShape(SphereRec((0.0, 0.0, 0.5), 1.0)))
    obj = PhysicsObj.make_object(did, 0x70000001, False, portal)
    assert obj.part_array.setup.num_sphere == 1 and not obj.state & PhysicsState.HasPhysicsBSP
    assert obj.part_array.parts[0].get_bounding_box().max == EXACT.vec(1, 1, 1.5)


@pytest.mark.anchor("CPartArray::InitParts")
def test_a_setup_with_no_parts_gives_no_part_array():
    portal = PortalDat({dat.SETUP_BASE: dat.setup(dat.SETUP_BASE, [], spheres=[((0.0, 0.0, 0.0), 1.0)])}, EXACT, True)
    obj = PhysicsObj.make_object(dat.SETUP_BASE, 0x70000001, False, portal)
    assert obj.part_array is None


@pytest.mark.anchor("CPhysicsObj::SetScaleStatic")
def test_the_new_constants_are_pinned_by_their_float32_bits():
    assert f32_bits(k.DEFAULT_SCALE) == 0x3F800000 and f32_bits(k.TRANSLUCENCY_ETHEREAL) == 0x3E800000
