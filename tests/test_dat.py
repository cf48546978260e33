"""acconform/dat.py writes ACE.DatLoader's layouts: each record read back field by field.

The reader here follows ACE.DatLoader's Unpack methods (FileTypes/GfxObj.cs, SetupModel.cs,
Entity/CVertexArray.cs, SWVertex.cs, Polygon.cs, BSPNode.cs, BSPLeaf.cs) step by step, to the last
byte: a record it cannot read to its end exactly fails. The live lane unpacks the same bytes with
ACE's own Unpack (tests/oracle/test_live.py).
"""

from __future__ import annotations

import os
import re
import struct
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from acconform import dat
from acconform.scene import (BSPLeaf, BSPNode, BSPShape, CylSphereShape, Environment, Frame, PlaneRec, PolygonRec,
                             Position, SphereRec, SphereShape, StaticObject)
from oracle import indoor_scenes


class DatReader:
    def __init__(self, data: bytes):
        self.data, self.pos = data, 0

    def take(self, fmt: str):
        vals = struct.unpack_from("<" + fmt, self.data, self.pos)
        self.pos += struct.calcsize("<" + fmt)
        return vals if len(vals) > 1 else vals[0]

    def compressed_u32(self) -> int:  # BinaryReaderExtensions.ReadCompressedUInt32
        b0 = self.take("B")
        if not b0 & 0x80:
            return b0
        b1 = self.take("B")
        if not b0 & 0x40:
            return ((b0 & 0x7F) << 8) | b1
        return ((((b0 & 0x3F) << 8) | b1) << 16) | self.take("H")

    def tag(self) -> str:  # 4 ASCII bytes, reversed
        return self.data[self.pos:self.pos + 4].decode("ascii")[::-1]

    def end(self):
        assert self.pos == len(self.data), f"{len(self.data) - self.pos} bytes left unread"


def read_node(r: DatReader):
    """BSPNode.ReadNode with BSPType.Physics: ("leaf", index, solid, sphere, polys) or
    ("node", type, plane, pos, neg, sphere)."""
    t = r.tag()
    r.take("I")
    if t == "LEAF":
        index, solid = r.take("ii")
        sph = r.take("4f")
        n = r.take("I")
        polys = r.take(f"{n}H") if n else ()
        return ("leaf", index, solid, sph, tuple(polys) if n > 1 else ((polys,) if n else ()))
    plane = r.take("4f")
    pos = read_node(r) if t in ("BPnn", "BPIn", "BPIN", "BPnN") else None
    neg = read_node(r) if t in ("BpIN", "BpnN", "BPIN", "BPnN") else None
    return ("node", t, plane, pos, neg, r.take("4f"))


def read_gfx_obj(data: bytes) -> dict:
    r = DatReader(data)
    out = {"id": r.take("I"), "flags": r.take("I")}
    out["surfaces"] = [r.take("I") for _ in range(r.compressed_u32())]
    vtype, n = r.take("iI")
    assert vtype == 1
    verts = {}
    for _ in range(n):
        key, nuv = r.take("HH")
        origin, normal = r.take("3f"), r.take("3f")
        uvs = [r.take("2f") for _ in range(nuv)]
        verts[key] = (origin, normal, uvs)
    out["vertices"] = verts
    if out["flags"] & 1:
        polys = {}
        for _ in range(r.compressed_u32()):
            key = r.take("H")
            npts, stip, sides, pos_s, neg_s = r.take("BBihh")
            ids = [r.take("h") for _ in range(npts)]
            if not stip & 4:
                r.take(f"{npts}B")
            if sides == 2 and not stip & 8:  # CullMode.Clockwise
                r.take(f"{npts}B")
            polys[key] = (stip, sides, pos_s, neg_s, ids)
        out["polygons"] = polys
        out["tree"] = read_node(r)
    out["sort_center"] = r.take("3f")
    assert not out["flags"] & 2 and not out["flags"] & 8
    r.end()
    return out


def read_setup(data: bytes) -> dict:
    r = DatReader(data)
    out = {"id": r.take("I"), "flags": r.take("I")}
    n = r.take("I")
    out["parts"] = [r.take("I") for _ in range(n)]
    assert out["flags"] & 3 == 0  # no ParentIndex, no DefaultScale
    assert r.take("iii") == (0, 0, 0)  # HoldingLocations, ConnectionPoints, PlacementFrames
    out["cylspheres"] = [r.take("5f") for _ in range(r.take("I"))]
    out["spheres"] = [r.take("4f") for _ in range(r.take("I"))]
    out["dims"] = r.take("4f")
    out["sorting"], out["selection"] = r.take("4f"), r.take("4f")
    assert r.take("i") == 0  # Lights
    out["dids"] = r.take("5I")
    r.end()
    return out


def f32(x):
    return float(np.float32(x))


SQUARE = ((0.0, 0.0, 1.0), (2.0, 0.0, 1.0), (2.0, 2.0, 1.0), (0.0, 2.0, 1.0))
WALL = ((0.0, 0.0, 0.0), (0.0, 2.0, 0.0), (0.0, 2.0, f32(2.3)), (0.0, 0.0, f32(2.3)))


def bsp_object(root, polygons=(PolygonRec(SQUARE, 1), PolygonRec(WALL, 2))):
    return StaticObject(0x70000010, Position(0xA9B40001, Frame((10.0, 12.0, 20.0))),
                        BSPShape(polygons, root, SphereRec((1.0, 1.0, 1.0), 2.0)))


LEAF_A = BSPLeaf((0,), True, SphereRec((1.0, 1.0, 1.0), f32(1.5)))
LEAF_B = BSPLeaf((0, 1), False, SphereRec((0.5, 1.0, 1.0), 1.0))
LEAF_EMPTY = BSPLeaf((), False, SphereRec((0.0, 0.0, 0.0), 0.0))
TREE = BSPNode(PlaneRec((1.0, 0.0, 0.0), -1.0), SphereRec((1.0, 1.0, 1.0), 2.0), LEAF_A,
               BSPNode(PlaneRec((0.0, 0.0, 1.0), f32(-0.7)), SphereRec((0.5, 1.0, 1.0), f32(1.25)), LEAF_B, LEAF_EMPTY))


def test_a_bsp_object_is_one_physics_gfx_obj_whose_id_makeobject_takes():
    recs = dat.static_records(bsp_object(TREE), 4)
    assert recs.did == 0x01000005 and [(r.id, r.kind) for r in recs.records] == [(0x01000005, "GfxObj")]
    g = read_gfx_obj(recs.records[0].data)
    assert g["id"] == 0x01000005 and g["flags"] == 1 and g["surfaces"] == [] and g["sort_center"] == (0.0, 0.0, 0.0)


def test_gfx_obj_vertices_are_shared_by_exact_bits_in_first_appearance_order():
    g = read_gfx_obj(dat.static_records(bsp_object(TREE), 0).records[0].data)
    want = [SQUARE[0], SQUARE[1], SQUARE[2], SQUARE[3], WALL[0], WALL[1], WALL[2], WALL[3]]
    # WALL[0] = (0,0,0) differs from SQUARE[0] = (0,0,1): nothing shared here; -0.0 and 0.0 stay apart too
    assert [g["vertices"][k][0] for k in range(8)] == [tuple(map(f32, v)) for v in want]
    assert all(n == (0.0, 0.0, 0.0) and uv == [] for _, n, uv in g["vertices"].values())
    shared = PolygonRec((SQUARE[0], SQUARE[1], (-0.0, 0.0, 1.0)), 0)
    g2 = read_gfx_obj(dat.static_records(bsp_object(LEAF_A, (PolygonRec(SQUARE, 0), shared)), 0).records[0].data)
    assert len(g2["vertices"]) == 5 and g2["polygons"][1][4] == [0, 1, 4]


def test_gfx_obj_polygons_keep_scene_index_winding_and_sides_without_uv_indices():
    g = read_gfx_obj(dat.static_records(bsp_object(TREE), 0).records[0].data)
    assert g["polygons"] == {0: (0x0C, 1, 0, 0, [0, 1, 2, 3]), 1: (0x0C, 2, 0, 0, [4, 5, 6, 7])}  # None, Clockwise


def test_the_physics_tree_is_written_pre_order_with_node_spheres_leaf_ordinals_and_polygon_ids():
    tree = read_gfx_obj(dat.static_records(bsp_object(TREE), 0).records[0].data)["tree"]
    a = ("leaf", 0, 1, (1.0, 1.0, 1.0, f32(1.5)), (0,))
    b = ("leaf", 1, 0, (0.5, 1.0, 1.0, 1.0), (0, 1))
    empty = ("leaf", 2, 0, (0.0, 0.0, 0.0, 0.0), ())
    inner = ("node", "BPIN", (0.0, 0.0, 1.0, f32(-0.7)), b, empty, (0.5, 1.0, 1.0, f32(1.25)))
    assert tree == ("node", "BPIN", (1.0, 0.0, 0.0, -1.0), a, inner, (1.0, 1.0, 1.0, 2.0))


def test_a_tree_whose_root_is_a_leaf_is_written_as_a_leaf():
    tree = read_gfx_obj(dat.static_records(bsp_object(LEAF_B), 0).records[0].data)["tree"]
    assert tree == ("leaf", 0, 0, (0.5, 1.0, 1.0, 1.0), (0, 1))


def test_a_sphere_is_a_setup_with_one_part_whose_mesh_is_the_spheres_box():
    obj = StaticObject(0x70000002, Position(0xA9B40001, Frame((15.0, 12.0, 20.0))),
                       SphereShape(SphereRec((0.0, 0.0, 0.5), f32(1.1))))
    recs = dat.static_records(obj, 2)
    assert recs.did == 0x02000003 and [(r.id, r.kind) for r in recs.records] == [(0x01000003, "GfxObj"), (0x02000003, "SetupModel")]
    s = read_setup(recs.records[1].data)
    assert s["parts"] == [0x01000003] and s["flags"] == 0 and s["cylspheres"] == []
    assert s["spheres"] == [(0.0, 0.0, 0.5, f32(1.1))]
    assert s["dims"] == (0.0,) * 4 and s["sorting"] == s["selection"] == (0.0,) * 4 and s["dids"] == (0,) * 5
    g = read_gfx_obj(recs.records[0].data)
    assert g["flags"] == 0 and "polygons" not in g
    r = np.float32(1.1)
    lo = (float(-r), float(-r), float(np.float32(0.5) - r))
    hi = (float(r), float(r), float(np.float32(0.5) + r))
    corners = [g["vertices"][k][0] for k in range(8)]
    assert corners[0] == lo and corners[7] == hi and corners[1] == (hi[0], lo[1], lo[2]) and corners[6] == (lo[0], hi[1], hi[2])


def test_a_cylsphere_is_a_setup_whose_part_mesh_spans_its_radius_and_height():
    obj = StaticObject(0x70000001, Position(0xA9B40001, Frame((15.0, 12.0, 20.0))), CylSphereShape((1.0, 0.0, 0.25), 0.5, 2.0))
    recs = dat.static_records(obj, 0)
    s = read_setup(recs.records[1].data)
    assert s["cylspheres"] == [(1.0, 0.0, 0.25, 0.5, 2.0)] and s["spheres"] == [] and s["parts"] == [0x01000001]
    corners = [v[0] for v in read_gfx_obj(recs.records[0].data)["vertices"].values()]
    assert corners[0] == (0.5, -0.5, 0.25) and corners[7] == (1.5, 0.5, 2.25)


@pytest.mark.parametrize("n,size", [(0, 1), (0x7F, 1), (0x80, 2), (0x3FFF, 2), (0x4000, 4), (0x3FFFFFFF, 4)])
def test_compressed_counts_read_back_at_every_width(n, size):
    b = dat.compressed_u32(n)
    assert len(b) == size and DatReader(b).compressed_u32() == n


def test_a_many_polygon_gfx_obj_counts_its_polygons_in_two_bytes():
    polys = tuple(PolygonRec(((float(i), 0.0, 0.0), (float(i), 1.0, 0.0), (float(i), 1.0, 1.0)), 0) for i in range(200))
    leaf = BSPLeaf(tuple(range(200)), True, SphereRec((100.0, 0.5, 0.5), 120.0))
    g = read_gfx_obj(dat.static_records(bsp_object(leaf, polys), 0).records[0].data)
    assert len(g["polygons"]) == 200 and g["tree"][4] == tuple(range(200))


def test_record_ids_stay_inside_their_dat_types_range_below_the_parts_and_the_buildings_shells():
    with pytest.raises(ValueError, match="index"):
        dat.static_records(bsp_object(TREE), 0xEFFFFF)
    assert dat.static_records(bsp_object(TREE), 0xEFFFFE).did == 0x01EFFFFF < dat.PART_GFX_OBJ_BASE == 0x01F00000


def test_the_mover_is_a_setup_with_its_spheres_and_step_heights_and_one_empty_mesh_part():
    from acconform.scene import Mover

    spheres = (SphereRec((0.0, 0.0, 0.48), 0.48), SphereRec((0.0, 0.0, f32(1.35)), 0.48))
    m = Mover(spheres, Position(0xA9B40001, Frame((12.0, 12.0, 20.0))), Position(0xA9B40001, Frame((13.0, 12.0, 20.0))),
              f32(0.4), f32(1.5))
    recs = dat.mover_records(m)
    assert recs.did == 0x02000000 and [(r.id, r.kind) for r in recs.records] == [(0x01000000, "GfxObj"), (0x02000000, "SetupModel")]
    s = read_setup(recs.records[1].data)
    assert s["parts"] == [0x01000000] and s["cylspheres"] == []
    assert s["spheres"] == [(0.0, 0.0, f32(0.48), f32(0.48)), (0.0, 0.0, f32(1.35), f32(0.48))]
    assert s["dims"] == (0.0, 0.0, f32(0.4), 1.5)  # Height and Radius 0: ACE's transition never reads them
    g = read_gfx_obj(recs.records[0].data)
    assert g["flags"] == 0 and g["vertices"] == {}


# ---------------------------------------------------------------- indoors: Environment, EnvCell, LandblockInfo

def read_polygons(r: DatReader, n: int) -> dict:
    polys = {}
    for _ in range(n):
        key = r.take("H")
        npts, stip, sides, pos_s, neg_s = r.take("BBihh")
        polys[key] = (stip, sides, pos_s, neg_s, [r.take("h") for _ in range(npts)])
        assert stip & 0xC == 0xC  # no UV indices follow
    return polys


def read_cell_node(r: DatReader):
    """BSPNode.ReadNode with BSPType.Cell: ("leaf", index) or ("node", type, plane, pos, neg); DatLoader's
    switch: BPnn/BPIn a front child, BpIN/BpnN a back child, BPIN/BPnN both, any other tag none."""
    t = r.tag()
    r.take("I")
    if t == "LEAF":
        return ("leaf", r.take("i"))
    plane = r.take("4f")
    pos = read_cell_node(r) if t in ("BPnn", "BPIn", "BPIN", "BPnN") else None
    neg = read_cell_node(r) if t in ("BpIN", "BpnN", "BPIN", "BPnN") else None
    return ("node", t, plane, pos, neg)


def align(r: DatReader):  # BinaryReaderExtensions.AlignBoundary
    r.pos += -r.pos % 4


def read_cell_struct(r: DatReader) -> dict:
    npolys, nphysics, nportals = r.take("III")
    vtype, n = r.take("iI")
    assert vtype == 1
    verts = {}
    for _ in range(n):
        key, nuv = r.take("HH")
        verts[key] = r.take("3f")
        assert r.take("3f") == (0.0, 0.0, 0.0) and nuv == 0
    out = {"vertices": verts, "polygons": read_polygons(r, npolys), "portals": [r.take("H") for _ in range(nportals)]}
    align(r)
    out["cell_bsp"] = read_cell_node(r)
    out["physics_polygons"] = read_polygons(r, nphysics)
    out["physics_bsp"] = read_node(r)
    has_drawing_bsp = r.take("I")
    out["drawing_bsp"] = read_drawing_node(r) if has_drawing_bsp else None
    align(r)
    return out


def read_drawing_node(r: DatReader):
    """BSPNode.ReadNode with BSPType.Drawing: ("leaf", index); ("node", type, plane, pos, neg, sphere, polys);
    or a PORT node (BSPPortal.Unpack: both children) ("port", plane, pos, neg, sphere, polys, portals)."""
    t = r.tag()
    r.take("I")
    if t == "LEAF":
        return ("leaf", r.take("i"))
    plane = r.take("4f")
    if t == "PORT":
        pos, neg = read_drawing_node(r), read_drawing_node(r)
        sph = r.take("4f")
        npolys, nportals = r.take("II")
        polys = [r.take("H") for _ in range(npolys)]
        return ("port", plane, pos, neg, sph, polys, [r.take("hh") for _ in range(nportals)])
    pos = read_drawing_node(r) if t in ("BPnn", "BPIn", "BPIN", "BPnN") else None
    neg = read_drawing_node(r) if t in ("BpIN", "BpnN", "BPIN", "BPnN") else None
    sph = r.take("4f")
    return ("node", t, plane, pos, neg, sph, [r.take("H") for _ in range(r.take("I"))])


def drawing_nodes(node):
    """The drawing tree's nodes and leaves, pre-order."""
    if node is None:
        return []
    kids = (node[2], node[3]) if node[0] == "port" else (node[3], node[4]) if node[0] == "node" else ()
    return [node] + [n for k in kids for n in drawing_nodes(k)]


def read_environment(data: bytes) -> dict:
    r = DatReader(data)
    env_id, n = r.take("II")
    cells = {}
    for _ in range(n):
        key = r.take("I")
        cells[key] = read_cell_struct(r)
    r.end()
    return {"id": env_id, "cells": cells}


def read_env_cell(data: bytes) -> dict:
    r = DatReader(data)
    out = {"id": r.take("I"), "flags": r.take("I")}
    r.take("I")  # the cell id again
    nsurf, nportals, nvisible = r.take("BBH")
    out["surfaces"] = [r.take("H") for _ in range(nsurf)]
    out["environment"] = 0x0D000000 | r.take("H")
    out["cell_structure"] = r.take("H")
    out["frame"] = (r.take("3f"), r.take("4f"))
    out["portals"] = [r.take("4H") for _ in range(nportals)]
    out["visible"] = [r.take("H") for _ in range(nvisible)]
    out["stabs"] = []
    if out["flags"] & 2:
        out["stabs"] = [(r.take("I"), r.take("3f"), r.take("4f")) for _ in range(r.take("I"))]
    assert not out["flags"] & 8
    r.end()
    return out


def read_landblock_info(data: bytes) -> dict:
    r = DatReader(data)
    out = {"id": r.take("I"), "num_cells": r.take("I"), "objects": r.take("I")}
    out["buildings"], out["pack_mask"] = r.take("HH")
    r.end()
    return out


def test_an_environment_holds_each_cell_structure_by_index_to_its_last_aligned_byte():
    rec = dat.environment_record(indoor_scenes.ENVIRONMENT)
    assert rec.id == indoor_scenes.ENV and rec.kind == "Environment" and len(rec.data) % 4 == 0
    env = read_environment(rec.data)
    assert env["id"] == indoor_scenes.ENV and sorted(env["cells"]) == [0, 1, 2]
    for k, struct_rec in enumerate(indoor_scenes.ENVIRONMENT.cell_structs):
        got = env["cells"][k]
        verts = got["vertices"]
        polys = struct_rec.polygons + struct_rec.physics_polygons
        assert len(verts) == len({tuple(map(f32, v)) for p in polys for v in p.vertices})
        for key, p in enumerate(struct_rec.physics_polygons):
            stip, sides, pos_s, neg_s, ids = got["physics_polygons"][key]
            assert [verts[i] for i in ids] == [tuple(map(f32, v)) for v in p.vertices] and sides == p.sides_type
        for key, p in enumerate(struct_rec.polygons):
            assert [verts[i] for i in got["polygons"][key][4]] == [tuple(map(f32, v)) for v in p.vertices]
        assert got["portals"] == list(struct_rec.portals)


def test_a_cell_bsp_node_says_by_its_tag_which_children_follow_and_carries_no_sphere():
    from acconform.scene import CellBSPLeaf, CellBSPNode, CellStructRec

    plane = PlaneRec((0.0, 0.0, 1.0), f32(-0.5))
    tree = CellBSPNode(plane, CellBSPNode(plane, None, CellBSPLeaf()), CellBSPNode(plane, CellBSPLeaf(), None))
    lone = CellBSPNode(plane, None, None)
    p = (0.0, 0.0, 1.0, f32(-0.5))
    for root, want in ((tree, ("node", "BPIN", p, ("node", "BpIN", p, None, ("leaf", 0)), ("node", "BPIn", p, ("leaf", 1), None))),
                       (lone, ("node", "Bpnn", p, None, None)), (CellBSPLeaf(), ("leaf", 0))):
        rec = CellStructRec((), (), (PolygonRec(SQUARE),), LEAF_A, root)
        got = read_environment(dat.environment_record(Environment(0x0D000002, (rec,))).data)["cells"][0]
        assert got["cell_bsp"] == want


def test_an_env_cell_holds_its_frame_portals_visible_cells_and_the_statics_inside_it_as_stabs():
    scene = indoor_scenes.room_with_static()
    (cell,) = scene.env_cells
    (record,) = [r for r in dat.cell_dat_records(scene) if r.kind == "EnvCell"]
    got = read_env_cell(record.data)
    assert got["id"] == record.id == cell.id and got["flags"] == 2 and got["surfaces"] == []
    assert got["environment"] == indoor_scenes.ENV and got["cell_structure"] == 0
    assert got["frame"] == (indoor_scenes.ROOM_A, (1.0, 0.0, 0.0, 0.0)) and got["portals"] == [] and got["visible"] == []
    obj = scene.objects[0]
    assert got["stabs"] == [(dat.static_records(obj, 0).did, obj.position.frame.origin, obj.position.frame.orientation)]
    a = read_env_cell(dat.env_cell_record(indoor_scenes.two_rooms().env_cells[0], ()).data)
    assert a["flags"] == 0 and a["portals"] == [(0, 0, 0x0101, 0)] and a["visible"] == [0x0101] and a["stabs"] == []
    assert read_env_cell(dat.env_cell_record(replace(cell, seen_outside=True), ()).data)["flags"] == 1


def test_a_landblock_with_env_cells_gets_a_landblock_info_counting_them():
    records = dat.cell_dat_records(indoor_scenes.two_rooms())
    assert [(r.kind, r.id) for r in records] == [("EnvCell", indoor_scenes.BLOCK | 0x0100), ("EnvCell", indoor_scenes.BLOCK | 0x0101),
                                                 ("LandblockInfo", indoor_scenes.BLOCK | 0xFFFE)]
    info = read_landblock_info(records[-1].data)
    assert info == {"id": indoor_scenes.BLOCK | 0xFFFE, "num_cells": 2, "objects": 0, "buildings": 0, "pack_mask": 0}
    assert dat.cell_dat_records(replace(indoor_scenes.two_rooms(), env_cells=())) == ()


def _room_with_doors():
    """Five polygons: the floor, two walls, two doors; door 4 is listed as a portal twice."""
    from acconform.scene import CellStructRec

    s = indoor_scenes
    polygons = (s.FLOOR, s.NORTH, s.EAST, s.SOUTH, s.WEST)
    return CellStructRec(polygons, (4, 2, 4), (s.FLOOR,), s.physics_bsp(1), s.cell_bsp())


def test_drawing_bsp_lists_every_portal_polygon_in_a_port_node():
    rec = _room_with_doors()
    got = read_environment(dat.environment_record(Environment(0x0D000002, (rec,))).data)["cells"][0]
    nodes = [n for n in drawing_nodes(got["drawing_bsp"]) if n[0] != "leaf"]
    ports = {n[5][0]: n[6] for n in nodes if n[0] == "port"}
    assert ports == {2: [(1, 2)], 4: [(0, 4), (2, 4)]}  # (index in Portals, polygon id)
    assert all(n[1] == "BPIN" for n in nodes if n[0] == "node")
    assert sorted(p for n in nodes for p in (n[5] if n[0] == "port" else n[6])) == list(range(len(rec.polygons)))


def test_drawing_bsp_is_balanced_and_each_node_has_its_polygons_plane_and_a_sphere_around_its_subtree():
    rec = _room_with_doors()
    tree = read_environment(dat.environment_record(Environment(0x0D000002, (rec,))).data)["cells"][0]["drawing_bsp"]

    def check(node, depth):
        """The node's polygon ids, checking its plane and sphere; the leaves' indices in pre-order."""
        if node[0] == "leaf":
            leaves.append(node[1])
            return []
        plane, pos, neg, sph, polys = node[1:6] if node[0] == "port" else node[2:7]
        (k,) = polys
        nx, ny, nz, d = plane
        assert abs(nx * nx + ny * ny + nz * nz - 1.0) < 1e-6
        assert all(abs(nx * x + ny * y + nz * z + d) < 1e-5 for x, y, z in rec.polygons[k].vertices)
        below, above = check(pos, depth + 1), check(neg, depth + 1)
        assert all(i < k for i in below) and all(i > k for i in above) and depth <= 2
        cx, cy, cz, r = sph
        for i in below + [k] + above:
            assert all(((x - cx) ** 2 + (y - cy) ** 2 + (z - cz) ** 2) ** 0.5 <= r + 1e-5
                       for x, y, z in rec.polygons[i].vertices)
        return below + [k] + above

    leaves = []
    assert check(tree, 0) == [0, 1, 2, 3, 4] and leaves == list(range(6))


def test_a_structure_without_polygons_has_a_drawing_bsp_of_one_leaf():
    got = read_environment(dat.environment_record(indoor_scenes.ENVIRONMENT).data)["cells"]
    assert got[0]["drawing_bsp"] == ("leaf", 0)
    assert got[1]["drawing_bsp"][0] == "port" and got[1]["drawing_bsp"][6] == [(0, 0)]


ACE_DATLOADER_BSP_NODE = Path(os.environ.get("ACE_SOURCE", "/work/ace")) / "Source/ACE.DatLoader/Entity/BSPNode.cs"


@pytest.mark.skipif(not ACE_DATLOADER_BSP_NODE.is_file(), reason=f"ACE's source is not at {ACE_DATLOADER_BSP_NODE} (set ACE_SOURCE)")
def test_the_writers_node_tags_are_datloaders_and_a_childless_cell_node_is_none_of_them():
    """DatLoader's BSPNode.cs names each tag it switches on (`private const uint BPIN = ...`); the
    writer's tags are those, read back to the same names, and its childless cell-node tag Bpnn is none
    of them (DatLoader's BPnn, one letter apart, reads a front child)."""
    consts = {m[1]: int(m[2]) for m in re.finditer(r"const uint (\w+) = (\d+);", ACE_DATLOADER_BSP_NODE.read_text())}
    written = {"BPIN": dat.TAG_BPIN, "BPIn": dat.TAG_BPIn, "BpIN": dat.TAG_BpIN, "LEAF": dat.TAG_LEAF, "PORT": dat.TAG_PORT}
    assert {name: consts[name] for name in written} == written
    assert {name: DatReader(struct.pack("<I", t)).tag() for name, t in written.items()} == {n: n for n in written}
    assert DatReader(struct.pack("<I", dat.TAG_Bpnn)).tag() == "Bpnn" and dat.TAG_Bpnn not in consts.values()
    assert consts["BPnn"] != dat.TAG_Bpnn
