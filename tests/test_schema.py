"""The JSON Schemas are generated from the records: every field a record writes is in them."""

from dataclasses import fields

import pytest

from acconform.outcome import Outcome
from acconform.schema import schemas


@pytest.fixture(scope="module")
def generated():
    return schemas()


def test_the_outcome_schema_names_and_requires_every_outcome_field(generated):
    _, outcome = generated
    names = {f.name for f in fields(Outcome)}
    assert set(outcome["properties"]) == names | {"format"}
    # only a placed scene's outcome has a placement, only a tick scene's has ticks, only one with other movers
    # has their placements
    assert set(outcome["required"]) == names - {"placement", "ticks", "other_placements", "motion_answers"} | {"format"}
    assert {s.get("type") for s in outcome["properties"]["error"]["anyOf"]} == {"null", "string"}


def test_the_scene_schema_covers_every_field_a_scene_writes_and_the_bsp_tree_recurses(generated):
    scene, _ = generated
    assert {"format", "name", "engine", "land_height_table", "landblocks", "objects", "mover"} <= set(scene["properties"])
    assert {"contact_plane", "sliding_normal"} <= set(scene["properties"]["mover"]["properties"])
    node = scene["$defs"]["type:node"]["properties"]
    assert {r["$ref"] for r in node["front"]["oneOf"]} == {"#/$defs/type:node", "#/$defs/type:leaf"}
    assert set(scene["$defs"]) >= {"kind:bsp", "kind:sphere", "kind:cylsphere"}
    heights = scene["properties"]["landblocks"]["items"]["properties"]["heights"]
    assert heights["minItems"] == heights["maxItems"] == 81


def test_the_scene_schema_names_the_indoor_fields_and_reads_both_scene_formats(generated):
    scene, _ = generated
    props = scene["properties"]
    assert props["format"] == {"enum": ["acconform.scene/1", "acconform.scene/2", "acconform.scene/3", "acconform.scene/4",
                                        "acconform.scene/5", "acconform.scene/6", "acconform.scene/7",
                                        "acconform.scene/8"]}
    assert {"environments", "env_cells"} <= set(props) and not {"environments", "env_cells"} & set(scene["required"])
    landblock = props["landblocks"]["items"]
    assert landblock["required"] == ["id"] and {"heights", "terrain"} <= set(landblock["properties"])
    cell = props["env_cells"]["items"]["properties"]
    assert {"id", "origin", "orientation", "environment", "cell_structure", "portals", "visible_cells", "seen_outside"} <= set(cell)
    assert {"polygon", "other_cell", "other_portal", "flags"} <= set(cell["portals"]["items"]["properties"])
    structure = props["environments"]["items"]["properties"]["cell_structs"]["items"]["properties"]
    assert set(structure) == {"polygons", "portals", "physics_polygons", "physics_bsp", "cell_bsp", "drawing_bsp"}
    # scene/8's housing barriers (schema._cell_record_scenes)
    assert "restriction_obj" in cell and "restrictions" in landblock["properties"]
    assert "portal" in scene["$defs"]["type:node"]["properties"]  # a cell-tree node's tag PORT


def test_the_scene_schema_names_every_building_field(generated):
    scene, _ = generated
    props = scene["properties"]
    assert "buildings" in props and "buildings" not in scene["required"]
    building = props["buildings"]["items"]["properties"]
    assert {"landblock", "origin", "orientation", "shape", "num_leaves", "portals"} <= set(building)
    assert {"other_cell", "other_portal", "flags", "stab_list"} <= set(building["portals"]["items"]["properties"])


def test_the_schemas_name_every_tick_record_field_and_the_tick_formats(generated):
    from acconform.outcome import TickState
    from acconform.scene import TICK_INPUTS

    scene, outcome = generated
    ticks = scene["properties"]["ticks"]
    assert "ticks" not in scene["required"] and set(ticks["required"]) == {"driver", "start", "steps"}
    step = ticks["properties"]["steps"]["items"]
    assert set(step["properties"]) == {"dt", "others", *TICK_INPUTS} and step["required"] == ["dt"]
    assert "end" not in scene["properties"]["mover"]["required"]  # a tick scene's mover has none
    tick = outcome["properties"]["ticks"]["items"]
    assert set(tick["properties"]) == {f.name for f in fields(TickState)} - {"id"}  # only an entry of others has one
    # an errored tick writes the defaults; a tick of a mover without a motion table has no motion; only a scene with
    # other movers has their states and the CollisionTables, and only their entries an id
    assert set(tick["required"]) == {f.name for f in fields(TickState)} - {"error", "motion", "collisions", "others", "id"}
    assert outcome["properties"]["format"] == {"enum": ["acconform.outcome/2", "acconform.outcome/3", "acconform.outcome/4",
                                                        "acconform.outcome/5", "acconform.outcome/6"]}
    other = tick["properties"]["others"]["items"]
    assert "id" in other["required"] and not {"motion", "others", "error"} & set(other["properties"])


def test_the_outcome_schema_names_every_field_of_a_ticks_motion_layer(generated):
    from acconform.outcome import CommandState, MotionTickState

    motion = generated[1]["properties"]["ticks"]["items"]["properties"]["motion"]
    assert set(motion["properties"]) == set(motion["required"]) == {f.name for f in fields(MotionTickState)}
    interpreted = next(o for o in motion["properties"]["interpreted"]["anyOf"] if o.get("type") == "object")
    assert set(interpreted["properties"]) == {f.name for f in fields(CommandState)}
    assert {"type": "null"} in motion["properties"]["animation"]["anyOf"]  # no CurrAnim


def test_the_trace_schema_names_every_field_a_trace_record_and_its_snapshot_write():
    from acconform.schema import trace_schema
    from acconform.trace import FORMAT, OPTIONAL_PATH_FLAGS, PathState, TraceRecord

    schema = trace_schema()
    assert schema["properties"]["format"] == {"const": FORMAT}
    record = schema["properties"]["records"]["items"]
    assert set(record["properties"]) == {f.name for f in fields(TraceRecord)}
    assert set(record["required"]) == {"anchor", "event"}
    path = next(o for o in record["properties"]["path"].get("anyOf", [record["properties"]["path"]])
                if o.get("type") == "object")
    assert set(path["properties"]) == {f.name for f in fields(PathState)}
    assert set(path["required"]) == {f.name for f in fields(PathState)} - OPTIONAL_PATH_FLAGS


def test_the_scene_schema_names_a_statics_setup_and_every_field_of_its_parts(generated):
    scene, _ = generated
    obj = scene["properties"]["objects"]["items"]
    assert {"shape", "setup"} <= set(obj["properties"]) and not {"shape", "setup"} & set(obj["required"])
    setup = obj["properties"]["setup"]
    assert set(setup["properties"]) == {"parts", "spheres", "cylspheres", "parent_index", "default_script",
                                        "default_animation"} and setup["required"] == ["parts"]
    assert set(setup["properties"]["parts"]["items"]["properties"]) == {"shape", "origin", "orientation", "scale"}
    assert set(setup["properties"]["default_animation"]["items"]["properties"]) == {"origin", "orientation"}


def test_the_scene_schema_names_a_childs_parent_and_the_holding_locations_and_a_child_has_no_begin(generated):
    scene, _ = generated
    other = scene["properties"]["others"]["items"]
    assert {"parent", "sorting_sphere", "begin"} <= set(other["properties"])
    assert not {"parent", "sorting_sphere", "begin"} & set(other["required"])
    assert set(other["properties"]["parent"]["properties"]) == {"id", "location", "placement"}
    inputs = scene["properties"]["ticks"]["properties"]["steps"]["items"]["properties"]["others"]["items"]
    assert {"unparent", "parent"} <= set(inputs["properties"]) and not {"unparent", "parent"} & set(inputs["required"])
    held = scene["properties"]["mover"]["properties"]["holding_locations"]["items"]
    assert set(held["properties"]) == {"location", "part", "frame"} == set(held["required"])


def test_the_scene_schema_names_every_field_of_a_projectiles_launch(generated):
    scene, _ = generated
    other = scene["properties"]["others"]["items"]
    assert "launch" in other["properties"] and "launch" not in other.get("required", [])
    launch = other["properties"]["launch"]
    assert set(launch["properties"]) == {"tick", "launcher", "target", "speed", "origin", "orientation", "lead_target",
                                         "arc", "tracking", "alt_solver", "rotation_speed", "spell"}
    # a spell may have no target; a weenie may carry ReportCollisions
    assert not {"target", "rotation_speed", "spell"} & set(launch.get("required", []))
    assert "report_collisions" in other["properties"] and "report_collisions" not in other.get("required", [])
    assert {"ammunition", "spell_projectile"} <= set(other["properties"]["weenie"].get("enum", ())) or \
        other["properties"]["weenie"].get("type") == "string"
