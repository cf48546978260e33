"""Buildings (acconform.scene/5): a landblock's buildings, written as the LandblockInfo ACE reads. Every
malformed field is refused naming it; older formats refuse the field; scenes without buildings keep
the oldest format that holds them."""

import copy
import json

import pytest

from acconform.case import parse_document
from acconform.errors import InvalidScene
from acconform.scene import FORMAT, FORMAT_V4, FORMAT_V5, Scene, validate_scene
from acconform.strategies import sample_scenes

BASE = next(s for s in sample_scenes(("buildings",), 40, 3) if s.name.startswith("building:in") and s.mover.placement is None)
DOC = BASE.to_json()


def refused(doc) -> str:
    with pytest.raises(InvalidScene) as e:
        parse_document(doc)
    return str(e.value)


def changed(mutate, base=DOC):
    doc = copy.deepcopy(base)
    mutate(doc)
    return doc


def portal(d):
    return d["buildings"][0]["portals"][0]


def test_a_scene_with_buildings_is_written_as_scene_5_and_round_trips():
    doc = json.loads(BASE.dumps())
    assert doc["format"] == FORMAT_V5 == "acconform.scene/5" and len(doc["buildings"]) == 1
    assert Scene.from_json(doc) == BASE and validate_scene(BASE) == BASE


def test_a_scene_without_buildings_keeps_its_older_format():
    assert BASE.replace(buildings=()).to_json()["format"] == "acconform.scene/2"
    assert FORMAT_V4 == "acconform.scene/4"


def test_an_older_format_cannot_hold_buildings():
    for old in ("acconform.scene/2", "acconform.scene/3", "acconform.scene/4"):
        assert "buildings: buildings need format 'acconform.scene/5' or later" in refused(
            changed(lambda d: d.__setitem__("format", old)))


@pytest.mark.parametrize("mutate, message", [
    (lambda d: d["buildings"][0].__setitem__("landblock", "0xA9B40001"),
     "buildings[0].landblock: a landblock id ends in FFFF"),
    (lambda d: d["buildings"][0].__setitem__("landblock", "0x0102FFFF"),
     "buildings[0].landblock: landblock 0102FFFF is not defined in landblocks"),
    (lambda d: portal(d).__setitem__("other_cell", "0x0140"),
     "buildings[0].portals[0].other_cell: EnvCell"),
    (lambda d: portal(d).__setitem__("other_cell", "0xFFFF"),
     "buildings[0].portals[0].other_cell: a building's portal leads into one of its EnvCells"),
    (lambda d: portal(d).__setitem__("other_portal", 200),
     "buildings[0].portals[0].other_portal: EnvCell"),
    (lambda d: portal(d).__setitem__("flags", 4), "buildings[0].portals[0].flags"),
    (lambda d: portal(d).__setitem__("stab_list", ["0x0150"]),
     "buildings[0].portals[0].stab_list[0]: EnvCell"),
    (lambda d: portal(d).__setitem__("stab_list", ["0x0010"]),
     "buildings[0].portals[0].stab_list[0]: a stab is an EnvCell's low word"),
    (lambda d: d["buildings"][0]["shape"].__setitem__("kind", "sphere"),
     "buildings[0].shape"),
    (lambda d: d["buildings"][0].__setitem__("num_leaves", -1), "buildings[0].num_leaves"),
    (lambda d: d["buildings"][0].__setitem__("colour", 1), "buildings[0]: unknown field 'colour'"),
    (lambda d: d["buildings"][0].__setitem__("orientation", [0, 0, 0, 0]),
     "buildings[0].orientation: a zero quaternion is not a rotation"),
])
def test_a_malformed_building_is_refused_naming_its_field(mutate, message):
    assert message in refused(changed(mutate))


def test_a_building_on_a_landblock_without_terrain_is_refused():
    def no_terrain(d):
        lb = d["landblocks"][0]
        lb.pop("heights")
        lb.pop("terrain")
    assert "has no terrain: a building stands in one of its outdoor cells" in refused(changed(no_terrain))
