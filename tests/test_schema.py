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
    assert set(outcome["properties"]) == set(outcome["required"]) == names | {"format"}
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
