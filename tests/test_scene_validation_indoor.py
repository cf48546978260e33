"""Indoor scenes (acconform.scene/2): Environments, EnvCells, landblocks without terrain. Every
malformed field is refused naming it; what ACE can run is accepted; /1 scenes still read."""

import copy
import json

import pytest

from acconform.case import parse_document
from acconform.errors import InvalidScene
from acconform.scene import FORMAT_V2, Landblock, Scene, validate_scene
from oracle.indoor_scenes import SCENES, two_rooms, room_with_static

from test_scene_validation import EXAMPLE

TWO_ROOMS = two_rooms().to_json()
WITH_STATIC = room_with_static().to_json()


def refused(doc) -> str:
    with pytest.raises(InvalidScene) as e:
        parse_document(doc)
    return str(e.value)


def changed(mutate, base=TWO_ROOMS):
    doc = copy.deepcopy(base)
    mutate(doc)
    return doc


def struct(d, k=1):
    return d["environments"][0]["cell_structs"][k]


@pytest.mark.parametrize("name", sorted(SCENES))
def test_indoor_scenes_round_trip_through_json(name):
    scene = SCENES[name]
    doc = json.loads(scene.dumps())
    assert doc["format"] == FORMAT_V2 == "acconform.scene/2" and "heights" not in doc["landblocks"][0]
    assert Scene.from_json(doc) == scene and validate_scene(scene) == scene


def test_a_landblock_without_terrain_holds_zero_heights_and_terrain_words():
    lb = Scene.from_json(TWO_ROOMS).landblocks[0]
    assert not lb.has_terrain and lb.heights == (0,) * 81 and lb.terrain == (0,) * 81
    assert lb.to_json() == {"id": "0x01D9FFFF"}


def test_an_outdoor_scene_is_still_written_as_scene_1_so_files_and_recorded_keys_stay():
    scene = Scene.from_json(EXAMPLE)
    assert EXAMPLE["format"] == scene.to_json()["format"] == "acconform.scene/1" and not scene.indoor
    assert scene.to_json() == EXAMPLE
    assert two_rooms().indoor and scene.replace(landblocks=(Landblock(0xA9B4FFFF, has_terrain=False),)).indoor


def test_a_scene_1_file_cannot_hold_indoor_fields():
    assert "unknown field 'env_cells'" in refused(changed(lambda d: d.__setitem__("format", "acconform.scene/1")))
    no_terrain = changed(lambda d: d["landblocks"][0].pop("heights"), EXAMPLE)
    no_terrain["landblocks"][0].pop("terrain")
    assert "landblocks[0].heights: missing required field" in refused(no_terrain)


def test_a_cell_bsp_node_may_lack_children_but_a_structure_needs_both_trees():
    doc = changed(lambda d: struct(d, 0)["cell_bsp"].pop("front"))
    assert Scene.from_json(doc).environments[0].cell_structs[0].cell_bsp.front is None
    assert "cell_bsp: missing required field" in refused(changed(lambda d: struct(d, 0).pop("cell_bsp")))
    assert "physics_bsp: missing required field" in refused(changed(lambda d: struct(d, 0).pop("physics_bsp")))


@pytest.mark.parametrize("mutate, message", [
    (lambda d: d["landblocks"][0].__setitem__("heights", [0] * 81),
     "landblocks[0].terrain: missing: a landblock gives both heights and terrain, or neither"),
    (lambda d: d["environments"][0].__setitem__("id", "0x0E000001"),
     "environments[0].id: an Environment id is 0x0D00XXXX (an EnvCell stores its low word), got 0x0E000001"),
    (lambda d: d["environments"].append(copy.deepcopy(d["environments"][0])),
     "environments[1].id: Environment 0D000001 is defined twice"),
    (lambda d: d["environments"][0].__setitem__("cell_structs", []),
     "environments[0].cell_structs: expected at least 1 values, got 0"),
    (lambda d: struct(d).__setitem__("portals", [70000]),
     "environments[0].cell_structs[1].portals[0]: expected an integer in [0, 65535], got 70000"),
    (lambda d: struct(d)["physics_bsp"]["front"].__setitem__("polygons", [70000]),
     "environments[0].cell_structs[1].physics_bsp.front.polygons[0]: expected an integer in [0, 65535], got 70000"),
    (lambda d: struct(d)["cell_bsp"].__setitem__("type", "portal"),
     "environments[0].cell_structs[1].cell_bsp.type: unknown cell BSP element type 'portal' (known: node, leaf)"),
    (lambda d: struct(d)["cell_bsp"]["front"].__setitem__("sphere", {}),
     "environments[0].cell_structs[1].cell_bsp.front: unknown field 'sphere'"),
    (lambda d: struct(d)["polygons"][0].__setitem__("vertices", [[0, 0, 0], [1, 0, 0]]),
     "environments[0].cell_structs[1].polygons[0].vertices: a polygon needs at least 3 vertices, got 2"),
    (lambda d: d["env_cells"][0].__setitem__("id", "0x01D90040"),
     "env_cells[0].id: an EnvCell id is 0xXXYY0100 to 0xXXYYFFFD, got 0x01D90040"),
    (lambda d: d["env_cells"][1].__setitem__("id", "0x01D90100"),
     "env_cells[1].id: EnvCell 01D90100 is defined twice"),
    (lambda d: d["env_cells"][1].__setitem__("id", "0x01D90102"),
     "env_cells[1].id: landblock 01D9's EnvCells are numbered from 0x0100 without gaps (LandblockInfo.NumCells counts them): 0x0101 is missing"),
    (lambda d: d["env_cells"][0].__setitem__("id", "0x01DA0100"),
     "env_cells[0].id: landblock 01DA of EnvCell 01DA0100 is not defined in landblocks"),
    (lambda d: d["env_cells"][0].__setitem__("environment", "0x0D000009"),
     "env_cells[0].environment: Environment 0D000009 is not defined in environments"),
    (lambda d: d["env_cells"][0].__setitem__("cell_structure", 70000),
     "env_cells[0].cell_structure: expected an integer in [0, 65535], got 70000"),
    (lambda d: d["env_cells"][0]["portals"][0].__setitem__("polygon", 70000),
     "env_cells[0].portals[0].polygon: expected an integer in [0, 65535], got 70000"),
    (lambda d: struct(d).__setitem__("portals", []),
     "env_cells[0].portals[0].polygon: polygon 0 is not one of the cell structure's portals []"),
    (lambda d: d["env_cells"][0]["portals"][0].__setitem__("other_cell", "0x0040"),
     "env_cells[0].portals[0].other_cell: a portal leads to an EnvCell (0x0100..0xFFFD) or outside (0xFFFF), got 0x0040"),
    (lambda d: d["env_cells"][0]["portals"][0].__setitem__("other_cell", "0x1D90101"),
     "env_cells[0].portals[0].other_cell: expected a cell's low word like '0x0101'"),
    (lambda d: d["env_cells"][0]["portals"][0].__setitem__("flags", 4),
     "env_cells[0].portals[0].flags: expected an integer in [0, 3], got 4"),
    (lambda d: d["env_cells"][0]["portals"][0].pop("other_portal"),
     "env_cells[0].portals[0].other_portal: missing required field"),
    (lambda d: d["env_cells"][0].__setitem__("visible_cells", ["0xFFFE"]),
     "env_cells[0].visible_cells[0]: a visible cell is an EnvCell's low word (0x0100..0xFFFD) or 0x0000..0x00FF, got 0xFFFE"),
    (lambda d: d["env_cells"][0].__setitem__("seen_outside", 1),
     "env_cells[0].seen_outside: expected true or false"),
    (lambda d: d["env_cells"][0].__setitem__("orientation", [0, 0, 0, 0]),
     "env_cells[0].orientation: a zero quaternion is not a rotation"),
    (lambda d: d["mover"]["begin"].__setitem__("cell", "0x01D90102"),
     "mover.begin.cell: EnvCell 01D90102 is not defined in env_cells (the mover starts in it"),
    (lambda d: d["mover"]["begin"].__setitem__("cell", "0x01DA0100"),
     "mover.begin.cell: landblock 01DA of cell 01DA0100 is not defined in landblocks"),
    (lambda d: d["mover"]["end"].__setitem__("cell", "0x01DA0100"),
     "mover.end.cell: landblock 01DA of cell 01DA0100 is not defined in landblocks"),
    (lambda d: d["mover"]["contact_plane"].__setitem__("cell", "0x01DA0100"),
     "mover.contact_plane.cell: landblock 01DA of cell 01DA0100 is not defined in landblocks"),
])
def test_malformed_indoor_fields_are_refused_naming_the_field(mutate, message):
    assert message in refused(changed(mutate))


@pytest.mark.parametrize("mutate, message", [
    (lambda d: d["objects"][0]["position"].__setitem__("cell", "0x01D90101"),
     "objects[0].position.cell: EnvCell 01D90101 is not defined in env_cells (its stab is in that EnvCell's DAT record)"),
    (lambda d: d["objects"][0].__setitem__("state", ["Static", "Ethereal"]),
     "objects[0].state: a static in an EnvCell is a DAT stab: ACE's EnvCell.init_static_objects sets no state"),
    (lambda d: d["objects"][0].__setitem__("scale", 2.0),
     "objects[0].scale: a static in an EnvCell is a DAT stab: ACE's EnvCell.init_static_objects sets no scale"),
])
def test_a_static_inside_an_env_cell_is_a_stab_of_a_defined_cell(mutate, message):
    assert message in refused(changed(mutate, WITH_STATIC))


def test_what_ace_runs_is_accepted_a_portal_to_an_undefined_cell_and_an_end_in_any_env_cell():
    doc = changed(lambda d: d["env_cells"][0]["portals"][0].__setitem__("other_cell", "0x0150"))
    assert Scene.from_json(doc).env_cells[0].portals[0].other_cell == 0x0150
    doc = changed(lambda d: d["mover"]["end"].__setitem__("cell", "0x01D90200"))
    assert Scene.from_json(doc).mover.end.cell == 0x01D90200


def test_a_record_built_in_code_with_a_no_terrain_landblock_validates():
    lb = Landblock(0x01D9FFFF, has_terrain=False)
    assert validate_scene(two_rooms().replace(landblocks=(lb,))).landblocks == (lb,)
