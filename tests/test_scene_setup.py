"""A static of several parts (scene/7 `setup`): its JSON form, its refusals, and the Setup and part
GfxObj records acconform/dat.py writes for it, read back field by field as ACE.DatLoader's
SetupModel.Unpack reads them (and by the port's reader, port/dat/setup_model.py)."""

from __future__ import annotations

import copy
import struct

import numpy as np
import pytest

from acconform import dat
from acconform.errors import InvalidScene
from acconform.flags import PhysicsState
from acconform.scene import (FORMAT_V7 as FORMAT, FORMAT_V6, CylSphereShape, Frame, PartRec, Position, Scene, SetupRec, SphereRec,
                             StaticObject, validate_scene)
from acconform.strategies.shapes import box
from tests.oracle.scenes import cell_at, flat, walk
from tests.test_dat import DatReader, read_gfx_obj

TURN = (float(np.float32(0.9238795)), 0.0, 0.0, float(np.float32(0.38268343)))  # 45 degrees about z
PARTS = (PartRec(box(1.0, 2.0, 1.5), Frame((0.0, -1.25, 0.0))),
         PartRec(box(1.0, 1.0, 0.8), Frame((0.5, 1.0, 0.25), TURN)))
SPHERES = (SphereRec((0.0, -1.0, 0.5), 0.5), SphereRec((0.0, 1.0, 0.5), 0.25))
CYLS = (CylSphereShape((0.0, 0.0, 0.0), 0.5, 1.0), CylSphereShape((1.0, 0.0, 0.0), 0.25, 2.0))


def multipart(parts=PARTS, spheres=SPHERES, cyls=CYLS, state=int(PhysicsState.Static | PhysicsState.HasPhysicsBSP)):
    return StaticObject(0x70000020, Position(cell_at(15.0, 12.0), Frame((15.0, 12.0, 20.0))), None, state, 1.0,
                        SetupRec(parts, spheres, cyls))


def scene(obj=None):
    return walk(flat, (12.0, 12.0, 20.0), (17.0, 12.0, 20.0), 20.0, objects=(obj or multipart(),))


def refused(doc) -> str:
    with pytest.raises(InvalidScene) as e:
        Scene.from_json(doc)
    return str(e.value)


def test_a_scene_with_a_setup_static_is_scene_7_and_reads_back_to_the_same_bytes():
    s = scene()
    text = s.dumps()
    assert s.to_json()["format"] == FORMAT == "acconform.scene/7"
    assert Scene.loads(text) == s and Scene.loads(text).dumps() == text


def test_a_scene_without_a_setup_static_stays_in_its_old_format_with_its_old_bytes():
    from tests.oracle.scenes import wall

    s = walk(flat, (12.0, 12.0, 20.0), (17.0, 12.0, 20.0), 20.0, objects=(wall(),))
    assert s.to_json()["format"] == "acconform.scene/1" and "setup" not in s.dumps()
    assert FORMAT_V6 == "acconform.scene/6"


def test_an_older_format_refuses_a_setup_naming_the_format_it_needs():
    doc = scene().to_json()
    doc["format"] = FORMAT_V6
    assert "objects[0].setup: a static's setup needs format 'acconform.scene/7'" in refused(doc)


def _doc(mutate):
    doc = copy.deepcopy(scene().to_json())
    mutate(doc["objects"][0])
    return doc


def test_a_static_with_both_a_shape_and_a_setup_or_neither_is_refused():
    both = _doc(lambda o: o.__setitem__("shape", o["setup"]["parts"][0]["shape"]))
    assert "objects[0].setup: a static has a shape or a setup (several parts), not both" in refused(both)
    assert "objects[0]: missing: a static needs a shape or a setup" in refused(_doc(lambda o: o.pop("setup")))


def test_a_setup_needs_one_to_sixteen_parts():
    assert "objects[0].setup.parts: expected at least 1 values, got 0" in refused(
        _doc(lambda o: o["setup"].__setitem__("parts", [])))
    assert "objects[0].setup.parts: expected at most 16 values, got 17" in refused(
        _doc(lambda o: o["setup"].__setitem__("parts", o["setup"]["parts"][:1] * 17)))


def test_a_part_is_a_bsp_gfx_obj_not_a_sphere():
    msg = refused(_doc(lambda o: o["setup"]["parts"][1].__setitem__(
        "shape", {"kind": "sphere", "center": [0, 0, 0], "radius": 1})))
    assert "objects[0].setup.parts[1].shape.kind: a Setup's part is a GfxObj with a physics BSP" in msg


def test_a_part_scale_is_given_on_every_part_or_none_and_is_positive():
    msg = refused(_doc(lambda o: o["setup"]["parts"][1].__setitem__("scale", [1, 1, 2])))
    assert "objects[0].setup.parts[0]: no scale, but parts[1] has one" in msg
    def zero(o):
        for p in o["setup"]["parts"]:
            p["scale"] = [1, 0, 1]
    assert "objects[0].setup.parts[0].scale: a part's scale needs positive components, got y = 0.0" in refused(_doc(zero))


def test_a_setup_cylsphere_needs_a_positive_height_and_a_sphere_a_positive_radius():
    assert "objects[0].setup.cylspheres[1].height: a cylsphere needs a positive height" in refused(
        _doc(lambda o: o["setup"]["cylspheres"][1].__setitem__("height", 0)))
    assert "objects[0].setup.spheres[0].radius: a sphere needs a positive radius" in refused(
        _doc(lambda o: o["setup"]["spheres"][0].__setitem__("radius", -1)))
    assert "objects[0].setup: unknown field 'height'" in refused(_doc(lambda o: o["setup"].__setitem__("height", 1)))


def read_setup_full(data: bytes) -> dict:
    """SetupModel.Unpack step by step: flags, parts, ParentIndex (HasParent), DefaultScale (HasDefaultScale), holding locations,
    connection points, placement frames (key, a frame per part, hooks), cylspheres, spheres, the rest."""
    r = DatReader(data)
    out = {"id": r.take("I"), "flags": r.take("I")}
    n = r.take("I")
    out["parts"] = [r.take("I") for _ in range(n)]
    out["parent_index"] = [r.take("I") for _ in range(n)] if out["flags"] & 1 else []
    out["scale"] = [r.take("3f") for _ in range(n)] if out["flags"] & 2 else []
    assert r.take("ii") == (0, 0)  # HoldingLocations, ConnectionPoints
    out["placements"] = {}
    for _ in range(r.take("i")):
        key = r.take("i")
        frames = [(r.take("3f"), r.take("4f")) for _ in range(n)]
        assert r.take("I") == 0  # hooks
        out["placements"][key] = frames
    out["cylspheres"] = [r.take("5f") for _ in range(r.take("I"))]
    out["spheres"] = [r.take("4f") for _ in range(r.take("I"))]
    out["dims"] = r.take("4f")
    assert r.take("8f") == (0.0,) * 8 and r.take("i") == 0 and r.take("5I") == (0,) * 5
    r.end()
    return out


def test_a_setup_static_is_its_parts_gfx_objs_then_a_setup_naming_them_with_frames_and_spheres():
    recs = dat.static_records(multipart(), 3)
    ids = [0x01F00000 + 16 * 3, 0x01F00000 + 16 * 3 + 1]
    assert recs.did == dat.SETUP_BASE + 3 and [r.id for r in recs.records] == ids + [recs.did]
    assert [r.kind for r in recs.records] == ["GfxObj", "GfxObj", "SetupModel"]
    assert recs.records[0].data == dat.gfx_obj_physics(ids[0], PARTS[0].shape)
    assert read_gfx_obj(recs.records[1].data)["id"] == ids[1]
    s = read_setup_full(recs.records[2].data)
    assert s["flags"] == 0 and s["parts"] == ids and s["scale"] == []
    assert s["placements"] == {0: [((0.0, -1.25, 0.0), (1.0, 0.0, 0.0, 0.0)), ((0.5, 1.0, 0.25), TURN)]}
    assert s["spheres"] == [(0.0, -1.0, 0.5, 0.5), (0.0, 1.0, 0.5, 0.25)]
    assert s["cylspheres"] == [(0.0, 0.0, 0.0, 0.5, 1.0), (1.0, 0.0, 0.0, 0.25, 2.0)]
    assert s["dims"] == (0.0, 0.0, 0.0, 0.0)  # Height, Radius, step heights: a static's are 0


def test_part_scales_are_the_setups_default_scale_under_its_flag():
    parts = tuple(PartRec(p.shape, p.frame, (1.0, 2.0, 0.5)) for p in PARTS)
    s = read_setup_full(dat.static_records(multipart(parts), 0).records[-1].data)
    assert s["flags"] == dat.SETUP_HAS_DEFAULT_SCALE == 2 and s["scale"] == [(1.0, 2.0, 0.5)] * 2


def test_a_parent_index_is_the_setups_parent_index_under_its_flag_before_the_scales_and_makes_scene_8():
    parts = tuple(PartRec(p.shape, p.frame, (1.0, 2.0, 0.5)) for p in PARTS)
    obj = multipart(parts)
    obj = StaticObject(obj.id, obj.position, None, obj.state, 1.0, SetupRec(parts, SPHERES, CYLS, (0xFFFFFFFF, 0)))
    s = read_setup_full(dat.static_records(obj, 0).records[-1].data)
    assert s["flags"] == dat.SETUP_HAS_PARENT | dat.SETUP_HAS_DEFAULT_SCALE == 3
    assert s["parent_index"] == [0xFFFFFFFF, 0] and s["scale"] == [(1.0, 2.0, 0.5)] * 2
    sc = scene(obj)
    assert sc.format == "acconform.scene/8" and Scene.loads(sc.dumps()) == sc
    assert sc.to_json()["objects"][0]["setup"]["parent_index"] == [0xFFFFFFFF, 0]


def test_a_parent_index_has_one_entry_per_part():
    doc = scene().to_json()
    doc["format"] = "acconform.scene/8"
    doc["objects"][0]["setup"]["parent_index"] = [0]
    assert "parent_index" in refused(doc)


def test_the_ports_setup_reader_reads_every_field_written():
    from acconform.port.dat.binary_reader import BinaryReader
    from acconform.port.dat.setup_model import SetupModel
    from acconform.numerics import get_mode

    parts = tuple(PartRec(p.shape, p.frame, (1.0, 2.0, 0.5)) for p in PARTS)
    obj = multipart(parts)
    obj = StaticObject(obj.id, obj.position, None, obj.state, 1.0, SetupRec(parts, SPHERES, CYLS, (0xFFFFFFFF, 0)))
    data = dat.static_records(obj, 0).records[-1].data
    reader = BinaryReader(data, get_mode("exact", "mono"))
    m = SetupModel.unpack(reader)
    assert reader.position == len(data) and list(m.parent_index) == [0xFFFFFFFF, 0]
    assert len(m.parts) == 2 and len(m.default_scale) == 2 and list(m.placement_frames) == [0]
    assert len(m.placement_frames[0].anim_frame.frames) == 2 and len(m.spheres) == 2 and len(m.cyl_spheres) == 2


def test_a_setup_static_index_past_its_id_range_is_refused():
    with pytest.raises(ValueError, match="a static with a setup has an index in 0..57343"):
        dat.static_records(multipart(), 0xE000)


def test_the_scenes_records_make_the_setup_static_from_its_setup_id():
    s = validate_scene(scene())
    assert dat.scene_records(s).statics[0].did == dat.dat_world(s).statics[0].did == dat.SETUP_BASE


def test_a_scene_7_placement_through_set_position_says_its_via_and_reads_back():
    from dataclasses import replace

    from acconform.scene import Placement

    s = scene()
    placed = validate_scene(replace(s, mover=replace(s.mover, placement=Placement(0, False))))
    doc = placed.to_json()
    assert doc["format"] == FORMAT and doc["mover"]["placement"]["via"] == "set_position"
    assert Scene.from_json(doc) == placed


RAISED = (Frame((0.0, -1.25, 0.5)), Frame((0.5, 1.0, 0.75), TURN))  # each part half a metre up


def animated(frames=RAISED, index=0):
    obj = multipart()
    return StaticObject(obj.id, obj.position, None, obj.state, 1.0, SetupRec(PARTS, SPHERES, CYLS, default_animation=frames))


def test_a_default_animation_is_the_setups_default_animation_an_animation_of_one_frame_of_the_part_frames():
    from acconform.numerics import get_mode
    from acconform.port.dat.animation import Animation
    from acconform.port.dat.binary_reader import BinaryReader
    from acconform.port.dat.setup_model import SetupModel

    recs = dat.static_records(animated(), 5)
    assert [r.kind for r in recs.records] == ["GfxObj", "GfxObj", "SetupModel", "Animation"]
    anim_id = dat.STATIC_ANIMATION_BASE + 5 == recs.records[-1].id
    setup = SetupModel.unpack(BinaryReader(recs.records[2].data, get_mode("exact", "mono")))
    assert anim_id and setup.default_animation == recs.records[-1].id
    reader = BinaryReader(recs.records[-1].data, get_mode("exact", "mono"))
    a = Animation.unpack(reader)
    assert reader.position == len(recs.records[-1].data) and a.num_parts == 2 and a.num_frames == 1 and not a.pos_frames
    assert [(tuple(map(float, f.origin)), tuple(map(float, (f.orientation.w, f.orientation.x, f.orientation.y, f.orientation.z))))
            for f in a.part_frames[0].frames] == [(f.origin, f.orientation) for f in RAISED]
    assert SetupModel.unpack(BinaryReader(dat.static_records(multipart(), 5).records[-1].data,
                                          get_mode("exact", "mono"))).default_animation == 0


def test_a_default_animation_makes_scene_8_reads_back_and_has_one_frame_per_part():
    sc = scene(animated())
    assert sc.format == "acconform.scene/8" and Scene.loads(sc.dumps()) == sc
    assert sc.to_json()["objects"][0]["setup"]["default_animation"][1]["origin"] == [0.5, 1.0, 0.75]
    doc = sc.to_json()
    doc["objects"][0]["setup"]["default_animation"] = doc["objects"][0]["setup"]["default_animation"][:1]
    assert "default_animation" in refused(doc)
    doc = scene().to_json()
    doc["objects"][0]["setup"]["default_animation"] = [{"origin": [0, 0, 0]}] * 2
    assert "default_animation needs format 'acconform.scene/8'" in refused(doc)


def test_a_static_whose_setup_names_a_default_animation_has_its_parts_at_the_animations_frame():
    """PartArray.InitDefaults appends the DefaultAnimation; UpdateParts then places the parts at its frame, not the
    placement frames: with both parts moved 20 m aside the mover walks on where the placed parts stop it."""
    from acconform.port.run import run_scene

    aside = (Frame((0.0, -21.25, 0.0)), Frame((0.5, -19.0, 0.25), TURN))
    placed, moved = run_scene(scene(multipart())), run_scene(scene(animated(aside)))
    assert placed.collision_normal.valid and placed.origin[0] < 14.0
    assert not moved.collision_normal.valid and moved.origin[0] > 16.9
