"""A Setup's DefaultScript (scene/8 `mover.default_script` and `objects[].setup.default_script`) and the
mover's resting frame (scene/8 `mover.resting_frame`): their JSON form, the format they need, and the Setup
record acconform/dat.py writes, read back as ACE.DatLoader's SetupModel.Unpack reads it (the port's
reader, port/dat/setup_model.py), and the placement frame the mover's PartArray takes from it."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from acconform import dat
from acconform.port.dat.binary_reader import BinaryReader
from acconform.port.dat.setup_model import SetupModel
from acconform.numerics import EXACT
from acconform.scene import FORMAT, FORMAT_V7, Frame, Scene
from tests.test_scene_setup import multipart, refused, scene

SCRIPT = 0x3300002A


def _setup_of(records) -> SetupModel:
    rec = next(r for r in records.records if r.kind == "SetupModel")
    return SetupModel.unpack(BinaryReader(rec.data, EXACT))


def test_a_movers_default_script_makes_the_scene_scene_8_and_reads_back():
    s = scene()
    s = s.replace(mover=replace(s.mover, default_script=SCRIPT))
    doc = s.to_json()
    assert doc["format"] == FORMAT and doc["mover"]["default_script"] == "0x3300002A"
    assert Scene.loads(s.dumps()) == s


def test_a_static_setups_default_script_makes_the_scene_scene_8_and_reads_back():
    obj = multipart()
    s = scene(replace(obj, setup=replace(obj.setup, default_script=SCRIPT)))
    assert s.to_json()["format"] == FORMAT and Scene.loads(s.dumps()) == s
    assert scene().to_json()["format"] == FORMAT_V7


def test_scene_7_refuses_a_default_script_naming_the_format_it_needs():
    doc = scene().to_json()
    doc["mover"]["default_script"] = "0x33000001"
    assert "mover.default_script: default_script needs format 'acconform.scene/8'" in refused(doc)
    doc = scene().to_json()
    doc["objects"][0]["setup"]["default_script"] = "0x33000001"
    assert "objects[0].setup.default_script: default_script needs format 'acconform.scene/8'" in refused(doc)


@pytest.mark.anchor("ACE.DatLoader/FileTypes/SetupModel.cs:Unpack")
def test_the_setups_dat_records_carry_the_default_script_and_nothing_else_changes():
    s = scene()
    plain = _setup_of(dat.mover_records(s.mover))
    scripted = _setup_of(dat.mover_records(replace(s.mover, default_script=SCRIPT)))
    assert (plain.default_script, scripted.default_script) == (0, SCRIPT)
    assert (scripted.default_animation, scripted.default_motion_table) == (plain.default_animation, plain.default_motion_table)
    obj = multipart()
    assert _setup_of(dat.setup_records(replace(obj.setup, default_script=SCRIPT), 0)).default_script == SCRIPT
    assert _setup_of(dat.setup_records(obj.setup, 0)).default_script == 0


# the mover's resting frame (scene/8 `mover.resting_frame`): its Setup's placement frame Resting (0x65)

TURN_Z = (float(np.float32(0.70710677)), 0.0, 0.0, float(np.float32(0.70710677)))
RESTING = Frame((0.25, -0.125, 0.5), TURN_Z)


def test_a_movers_resting_frame_makes_the_scene_scene_8_and_reads_back():
    s = scene()
    s = s.replace(mover=replace(s.mover, resting_frame=RESTING))
    doc = s.to_json()
    assert doc["format"] == FORMAT and doc["mover"]["resting_frame"]["origin"] == [0.25, -0.125, 0.5]
    assert Scene.loads(s.dumps()) == s
    doc = scene().to_json()
    doc["mover"]["resting_frame"] = {"origin": [0, 0, 0]}
    assert "mover.resting_frame: resting_frame needs format 'acconform.scene/8'" in refused(doc)


@pytest.mark.anchor("ACE.DatLoader/FileTypes/SetupModel.cs:Unpack")
def test_the_movers_setup_carries_its_resting_frame_keyed_resting_and_no_placement_without_one():
    s = scene()
    assert _setup_of(dat.mover_records(s.mover)).placement_frames == {}
    frames = _setup_of(dat.mover_records(replace(s.mover, resting_frame=RESTING))).placement_frames
    assert list(frames) == [0x65]
    (part,) = frames[0x65].anim_frame.frames
    assert [float(c) for c in (part.origin.x, part.origin.y, part.origin.z)] == [0.25, -0.125, 0.5]


def _mover_made(resting_frame):
    """The mover's PhysicsObj as port/run.py's build_mover makes it from its records: makeAnimObject, whose
    PartArray.CreateSetup calls SetPlacementFrame(0x65)."""
    from acconform.port.dat.portal_dat import PortalDat
    from acconform.port.physics_obj import PhysicsObj

    s = scene()
    records = dat.mover_records(replace(s.mover, resting_frame=resting_frame))
    portal = PortalDat({r.id: r.data for r in records.records}, EXACT, True)
    obj = PhysicsObj.create(EXACT, portal.timer, portal.server, portal.server_objects)
    assert obj.make_anim_object(records.did, True, portal)
    return obj


@pytest.mark.anchor("CPartArray::SetPlacementFrame")
def test_set_placement_frame_takes_the_resting_frame_the_setup_has():
    obj = _mover_made(RESTING)
    sequence = obj.part_array.sequence
    assert sequence.placement_frame_id == 0x65 and sequence.placement_frame is not None
    assert sequence.get_curr_anim_frame() is sequence.placement_frame


@pytest.mark.anchor("CPartArray::SetPlacementFrame")
def test_set_placement_frame_without_a_placement_frame_leaves_the_sequence_none():
    sequence = _mover_made(None).part_array.sequence
    assert sequence.placement_frame is None and sequence.placement_frame_id == 0
