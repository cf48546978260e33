"""A Setup's DefaultScript (scene/8 `mover.default_script` and `objects[].setup.default_script`): its JSON
form, the format it needs, and the Setup record acconform/dat.py writes, read back as ACE.DatLoader's
SetupModel.Unpack reads it (the port's reader, port/dat/setup_model.py)."""

from __future__ import annotations

from dataclasses import replace

import pytest

from acconform import dat
from acconform.port.dat.binary_reader import BinaryReader
from acconform.port.dat.setup_model import SetupModel
from acconform.numerics import EXACT
from acconform.scene import FORMAT, FORMAT_V7, Scene
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
