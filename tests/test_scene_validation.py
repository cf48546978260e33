"""Every malformed or inconsistent scene is refused with a message naming the field."""

import copy
import json
from pathlib import Path

import pytest

from acconform.case import parse_document
from acconform.errors import InvalidScene
from acconform.scene import Scene, validate_scene

EXAMPLE = json.loads((Path(__file__).parent.parent / "examples" / "flat_walk.json").read_text())

WALL = {
    "kind": "bsp",
    "polygons": [{"vertices": [[2, -1, 0], [2, 1, 0], [2, 1, 2], [2, -1, 2]], "sides_type": "None"}],
    "root": {
        "type": "node",
        "plane": {"normal": [1, 0, 0], "d": -2},
        "sphere": {"center": [2, 0, 1], "radius": 1.5},
        "front": {"type": "leaf", "polygons": [0], "solid": False, "sphere": {"center": [2, 0, 1], "radius": 1.5}},
        "back": {"type": "leaf", "polygons": [], "solid": False, "sphere": {"center": [2, 0, 1], "radius": 1.5}},
    },
    "sphere": {"center": [2, 0, 1], "radius": 1.5},
}


def scene_with(mutate):
    doc = copy.deepcopy(EXAMPLE)
    mutate(doc)
    return doc


def with_wall(mutate=lambda w: None):
    def m(doc):
        wall = copy.deepcopy(WALL)
        mutate(wall)
        doc["objects"] = [{"id": "0x70000001", "position": {"cell": "0xA9B40001", "origin": [10, 12, 20]}, "shape": wall}]
    return m


def refused(doc) -> str:
    with pytest.raises(InvalidScene) as e:
        parse_document(doc)
    return str(e.value)


def test_the_example_scene_is_valid_and_round_trips():
    s = Scene.from_json(EXAMPLE)
    assert Scene.from_json(json.loads(s.dumps())) == s
    assert validate_scene(s) == s


def test_a_scene_with_a_wall_is_valid():
    s = Scene.from_json(scene_with(with_wall()))
    assert s.objects[0].shape.root.front.polygons == (0,)


@pytest.mark.parametrize(
    "mutate, message",
    [
        (lambda d: d["landblocks"][0].__setitem__("heights", [1, 2, 3]), "landblocks[0].heights: expected 81 values, got 3"),
        (lambda d: d["landblocks"][0].__setitem__("terrain", [0] * 80), "landblocks[0].terrain: expected 81 values, got 80"),
        (lambda d: d.__setitem__("land_height_table", [0.0] * 255), "land_height_table: expected 256 values, got 255"),
        (lambda d: d["mover"].__setitem__("spheres", []), "mover.spheres: expected at least 1 values, got 0"),
        (lambda d: d["mover"].__setitem__("spheres", [d["mover"]["spheres"][0]] * 3), "mover.spheres: expected at most 2 values, got 3"),
        (lambda d: d["mover"]["begin"].__setitem__("origin", [1, 2]), "mover.begin.origin: expected 3 values, got 2"),
        (lambda d: d["mover"]["begin"].__setitem__("orientation", [1, 0, 0]), "mover.begin.orientation: expected 4 values, got 3"),
    ],
)
def test_wrong_counts_are_refused_naming_the_field(mutate, message):
    assert message in refused(scene_with(mutate))


def test_non_finite_numbers_are_refused():
    doc = scene_with(lambda d: d["mover"]["end"].__setitem__("origin", [float("nan"), 0, 0]))
    assert "mover.end.origin[0]: expected a finite number, got nan" in refused(doc)
    doc = scene_with(lambda d: d["mover"].__setitem__("step_up_height", float("inf")))
    assert "mover.step_up_height: expected a finite number" in refused(doc)
    doc = scene_with(lambda d: d["mover"].__setitem__("scale", 1e39))
    assert "mover.scale: 1e+39 is outside float32's range" in refused(doc)


def test_unknown_flag_names_are_refused_listing_the_known_ones():
    msg = refused(scene_with(lambda d: d["mover"].__setitem__("state", ["Gravity", "Flying"])))
    assert "mover.state[1]: unknown PhysicsState flag 'Flying'" in msg and "EdgeSlide" in msg
    msg = refused(scene_with(lambda d: d["mover"].__setitem__("transient_state", ["Grounded"])))
    assert "mover.transient_state[0]: unknown TransientState flag 'Grounded'" in msg


def test_an_unknown_format_version_is_refused():
    assert "format: unknown format version '9' (this acconform reads acconform.scene/8)" in refused(
        scene_with(lambda d: d.__setitem__("format", "acconform.scene/9")))
    assert "unknown format 'somethingelse/1'" in refused(scene_with(lambda d: d.__setitem__("format", "somethingelse/1")))


def test_a_polygon_with_fewer_than_three_vertices_is_refused():
    msg = refused(scene_with(with_wall(lambda w: w["polygons"][0].__setitem__("vertices", [[0, 0, 0], [1, 0, 0]]))))
    assert "objects[0].shape.polygons[0].vertices: a polygon needs at least 3 vertices, got 2" in msg


def test_a_degenerate_polygon_is_refused():
    collinear = [[0, 0, 0], [1, 0, 0], [2, 0, 0]]
    msg = refused(scene_with(with_wall(lambda w: w["polygons"][0].__setitem__("vertices", collinear))))
    assert "objects[0].shape.polygons[0].vertices: degenerate polygon: its vertices span no area" in msg


def test_a_bsp_whose_root_is_a_leaf_is_accepted_because_ace_makes_it_a_childless_node():
    s = Scene.from_json(scene_with(with_wall(lambda w: w.__setitem__("root", w["root"]["front"]))))
    assert s.objects[0].shape.root.polygons == (0,)
    assert validate_scene(s) == s


def test_an_empty_leaf_whose_bounding_sphere_has_radius_zero_is_accepted():
    s = Scene.from_json(scene_with(with_wall(lambda w: w["root"]["back"]["sphere"].__setitem__("radius", 0))))
    assert s.objects[0].shape.root.back.sphere.radius == 0.0


def test_a_bsp_node_whose_bounding_sphere_has_radius_zero_is_accepted():
    s = Scene.from_json(scene_with(with_wall(lambda w: w["root"]["sphere"].__setitem__("radius", 0))))
    assert s.objects[0].shape.root.sphere.radius == 0.0


@pytest.mark.parametrize("where", ["root", "front"])
def test_a_bsp_bounding_sphere_with_a_negative_radius_is_refused_naming_it(where):
    node = (lambda w: w["root"]) if where == "root" else (lambda w: w["root"]["front"])
    msg = refused(scene_with(with_wall(lambda w: node(w)["sphere"].__setitem__("radius", -0.5))))
    path = "root" if where == "root" else "root.front"
    assert f"objects[0].shape.{path}.sphere.radius: a bounding sphere needs a radius of 0 or more, got -0.5" in msg


def test_an_internal_bsp_node_without_both_children_is_refused():
    msg = refused(scene_with(with_wall(lambda w: w["root"].pop("back"))))
    assert "objects[0].shape.root: an internal BSP node needs both children; 'back' is missing" in msg


def test_a_leaf_naming_a_polygon_id_past_a_ushort_is_refused():
    # one past the shape's polygons is scene/8 (Scene.has_missing_keys: ACE's BSPNode throws KeyNotFoundException)
    msg = refused(scene_with(with_wall(lambda w: w["root"]["front"].__setitem__("polygons", [70000]))))
    assert "objects[0].shape.root.front.polygons[0]: expected an integer in [0, 65535], got 70000" in msg


def test_a_begin_position_in_an_undefined_landblock_is_refused():
    doc = scene_with(lambda d: d["mover"]["begin"].__setitem__("cell", "0xAAB40001"))
    assert "mover.begin.cell: landblock AAB4 of cell AAB40001 is not defined in landblocks (defined: A9B4)" in refused(doc)


@pytest.mark.parametrize("where", ["spheres", "object"])
def test_a_sphere_with_a_non_positive_radius_is_refused(where):
    if where == "spheres":
        doc = scene_with(lambda d: d["mover"]["spheres"][0].__setitem__("radius", 0))
        assert "mover.spheres[0].radius: a sphere needs a positive radius, got 0.0" in refused(doc)
    else:
        doc = scene_with(with_wall(lambda w: w["sphere"].__setitem__("radius", -1)))
        assert "objects[0].shape.sphere.radius: a sphere needs a positive radius, got -1.0" in refused(doc)


def test_unknown_and_missing_fields_are_named():
    assert "mover: unknown field 'spheers'" in refused(scene_with(lambda d: d["mover"].__setitem__("spheers", [])))
    assert "mover.step_down_height: missing required field" in refused(scene_with(lambda d: d["mover"].pop("step_down_height")))


def test_a_cell_that_is_neither_outdoor_nor_an_env_cell_is_refused():
    doc = scene_with(lambda d: d["mover"]["end"].__setitem__("cell", "0xA9B40041"))
    assert "mover.end.cell: cell A9B40041 is neither an outdoor land cell (low word 0x0001..0x0040) nor an EnvCell" in refused(doc)
    doc = scene_with(lambda d: d["mover"]["begin"].__setitem__("cell", "0xA9B4FFFE"))
    assert "mover.begin.cell: cell A9B4FFFE is neither" in refused(doc)


def test_a_landblock_id_must_end_in_ffff_and_appear_once():
    assert "landblocks[0].id: a landblock id ends in FFFF" in refused(scene_with(lambda d: d["landblocks"][0].__setitem__("id", "0xA9B40001")))
    assert "landblocks[1].id: landblock A9B4FFFF is defined twice" in refused(
        scene_with(lambda d: d["landblocks"].append(copy.deepcopy(d["landblocks"][0]))))


def test_heights_must_be_byte_indices():
    doc = scene_with(lambda d: d["landblocks"][0]["heights"].__setitem__(5, 256))
    assert "landblocks[0].heights[5]: expected an integer in [0, 255], got 256" in refused(doc)


PLACED = json.loads((Path(__file__).parent.parent / "examples" / "placement_wall_push.json").read_text())


@pytest.mark.parametrize("mutate, field, says", [
    (lambda d: d["mover"]["placement"].update(flags=["Slide", "Scatter"]), "mover.placement.flags", "ThreadSafeRandom"),
    (lambda d: d["mover"]["placement"].update(flags=["NoSuchFlag"]), "mover.placement.flags", "NoSuchFlag"),
    (lambda d: d["mover"]["placement"].update(get_cell="yes"), "mover.placement.get_cell", "true or false"),
    (lambda d: d["mover"]["placement"].update(where="here"), "mover.placement", "where"),
    (lambda d: d.update(format="acconform.scene/2"), "mover.placement", "acconform.scene/3"),
    (lambda d: d["mover"]["begin"].update(cell="0x12340100"), "mover.begin.cell", "not defined"),
], ids=["scatter", "unknown flag", "get_cell not a bool", "unknown field", "older format", "no landblock"])
def test_a_bad_placement_is_refused_naming_its_field(mutate, field, says):
    doc = copy.deepcopy(PLACED)
    mutate(doc)
    with pytest.raises(InvalidScene) as e:
        parse_document(doc)
    assert field in str(e.value) and says in str(e.value), str(e.value)


def test_a_placement_may_name_any_cell_of_a_defined_landblock_for_adjust_position_to_judge():
    doc = copy.deepcopy(PLACED)
    doc["mover"]["begin"]["cell"] = "0xA9B40050"  # out of AdjustPosition's ranges: ACE stores it, no cell
    assert parse_document(doc).mover.begin.cell == 0xA9B40050


def test_a_placement_runs_in_either_engine_mode():
    """ACE's server places the mover through change_cell_server -> enter_cell_server, whose visibility update
    reads the landblock's adjacents: the oracle loads a server scene's landblocks as LandblockManager does."""
    doc = copy.deepcopy(PLACED)
    doc["engine"]["mode"] = "server"
    assert validate_scene(parse_document(doc)).engine_mode == "server"


def test_a_document_of_every_scene_and_outcome_format_this_acconform_writes_is_read_by_its_format():
    """`acconform run`/`show`/`repro` read a file by its "format" (acconform.case.parse_document): every
    scene and outcome format version the writers produce has a reader there (scene/6 once had none)."""
    from acconform import case, outcome, scene

    for module in (scene, outcome):
        versions = {v for k, v in vars(module).items() if k == "FORMAT" or k.startswith("FORMAT_V")}
        assert versions and versions <= set(case._READERS), sorted(versions - set(case._READERS))
