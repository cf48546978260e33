"""The mover's free heading (scene/8 `mover.free_heading`, protocol feature `mover.free_heading`): its JSON form,
the format and feature it needs, and the Setup record acconform/dat.py writes, read back as ACE.DatLoader's
SetupModel.Unpack reads it (port/dat/setup_model.py): the flag AllowFreeHeading that PhysicsObj.get_object_info
turns into ObjectInfoState.FreeRotate."""

from __future__ import annotations

from dataclasses import replace

import pytest

from acconform import dat
from acconform.numerics import EXACT
from acconform.port.dat.binary_reader import BinaryReader
from acconform.port.dat.setup_model import SetupModel
from acconform.protocol import scene_features
from acconform.scene import FORMAT, FORMAT_V7, Scene
from tests.test_scene_setup import refused, scene


def _setup_of(records) -> SetupModel:
    rec = next(r for r in records.records if r.kind == "SetupModel")
    return SetupModel.unpack(BinaryReader(rec.data, EXACT))


def test_a_free_heading_mover_makes_the_scene_scene_8_needing_its_feature_and_reads_back():
    s = scene()
    free = s.replace(mover=replace(s.mover, free_heading=True))
    doc = free.to_json()
    assert doc["format"] == FORMAT and doc["mover"]["free_heading"] is True
    assert Scene.loads(free.dumps()) == free
    assert "mover.free_heading" in scene_features(free) and "mover.free_heading" not in scene_features(s)
    assert "free_heading" not in s.to_json()["mover"] and s.to_json()["format"] == FORMAT_V7


def test_scene_7_refuses_a_free_heading_naming_the_format_it_needs():
    doc = scene().to_json()
    doc["mover"]["free_heading"] = True
    assert "mover.free_heading: free_heading needs format 'acconform.scene/8'" in refused(doc)


@pytest.mark.anchor("ACE.DatLoader/FileTypes/SetupModel.cs:Unpack")
def test_the_movers_setup_says_allow_free_heading_only_with_a_free_heading():
    m = scene().mover
    plain = _setup_of(dat.mover_records(m))
    free = _setup_of(dat.mover_records(replace(m, free_heading=True)))
    assert (plain.flags, plain.allow_free_heading) == (0, False)
    assert (free.flags, free.allow_free_heading) == (dat.SETUP_ALLOW_FREE_HEADING, True)
    assert (free.spheres, free.step_up_height) == (plain.spheres, plain.step_up_height)
