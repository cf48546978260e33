"""A scene whose DAT records carry what a client draws (scene/8 `drawing`, protocol feature `dat.drawing`): its JSON
form, the format and feature it needs, and the records acconform/dat.py writes, read back as ACE.DatLoader reads them
(the port's readers, port/dat/): polygons with UV indices, a BSP GfxObj with drawing polygons, a drawing BSP, a surface
and a degrade table, an EnvCell with a surface; the GfxObj ACE's physics makes of it takes its DrawingSphere from the
drawing tree's root."""

from __future__ import annotations

from dataclasses import replace

import pytest

from acconform import dat
from acconform.flags import CullMode
from acconform.numerics import EXACT
from acconform.port.dat.binary_reader import BinaryReader
from acconform.port.dat.env_cell import EnvCell as DatEnvCell
from acconform.port.dat.gfx_obj import GFX_OBJ_HAS_DID_DEGRADE, GFX_OBJ_HAS_DRAWING, GFX_OBJ_HAS_PHYSICS
from acconform.port.dat.gfx_obj import GfxObj as DatGfxObj
from acconform.port.gfx_obj import GfxObj
from acconform.protocol import scene_features
from acconform.scene import FORMAT, FORMAT_V7, Scene
from oracle import indoor_scenes
from tests.test_dat import TREE, bsp_object
from tests.test_scene_setup import refused, scene


def _gfx(obj, drawing: bool) -> DatGfxObj:
    return DatGfxObj.unpack(BinaryReader(dat.static_records(obj, 0, drawing).records[0].data, EXACT))


def test_a_drawn_scene_is_scene_8_needing_its_feature_and_reads_back():
    s = scene()
    drawn = s.replace(drawing=True)
    doc = drawn.to_json()
    assert doc["format"] == FORMAT and doc["drawing"] is True
    assert Scene.loads(drawn.dumps()) == drawn
    assert "dat.drawing" in scene_features(drawn) and "dat.drawing" not in scene_features(s)
    assert "drawing" not in s.to_json() and s.to_json()["format"] == FORMAT_V7


def test_scene_7_refuses_drawing_naming_the_format_it_needs():
    doc = scene().to_json()
    doc["drawing"] = True
    assert "drawing: drawing needs format 'acconform.scene/8'" in refused(doc)


@pytest.mark.anchor("ACE.DatLoader/FileTypes/GfxObj.cs:Unpack")
def test_a_drawn_bsp_gfx_obj_carries_its_polygons_as_drawing_polygons_with_uv_indices_a_surface_and_a_degrade_table():
    obj = bsp_object(TREE)  # a None polygon, then a Clockwise one
    plain, drawn = _gfx(obj, False), _gfx(obj, True)
    assert plain.flags == GFX_OBJ_HAS_PHYSICS and not plain.polygons and plain.surfaces == []
    assert drawn.flags == GFX_OBJ_HAS_PHYSICS | GFX_OBJ_HAS_DRAWING | GFX_OBJ_HAS_DID_DEGRADE
    assert (drawn.surfaces, drawn.did_degrade) == ([dat.DRAWING_SURFACE], dat.DRAWING_DID_DEGRADE)
    assert sorted(drawn.polygons) == sorted(drawn.physics_polygons) == [0, 1]
    none, clockwise = drawn.physics_polygons[0], drawn.physics_polygons[1]
    assert (none.sides_type, clockwise.sides_type) == (CullMode.None_, CullMode.Clockwise)
    assert none.pos_uv_indices == [0, 1, 2, 3] and none.neg_uv_indices == none.pos_uv_indices  # None: NegUVIndices = Pos
    assert clockwise.pos_uv_indices == clockwise.neg_uv_indices == [0, 1, 2, 3]
    assert [p.vertex_ids for p in drawn.physics_polygons.values()] == [p.vertex_ids for p in plain.physics_polygons.values()]


@pytest.mark.anchor("GfxObj.cs:GfxObj(DatLoader.FileTypes.GfxObj)")
def test_the_gfx_obj_of_a_drawn_record_takes_its_drawing_sphere_from_the_drawing_trees_root_and_its_polygons_in_the_client():
    obj = bsp_object(TREE)
    client = GfxObj.from_dat(_gfx(obj, True), False, EXACT)
    server = GfxObj.from_dat(_gfx(obj, True), True, EXACT)
    assert sorted(client.polygons) == [0, 1] and server.polygons is None
    root = _gfx(obj, True).drawing_bsp.root_node
    assert client.drawing_sphere.radius == root.sphere.radius > 0
    assert client.physics_sphere.radius == server.physics_sphere.radius == GfxObj.from_dat(_gfx(obj, False), True, EXACT).physics_sphere.radius


@pytest.mark.anchor("ACE.DatLoader/FileTypes/EnvCell.cs:Unpack")
def test_a_drawn_env_cell_has_one_surface_and_reads_the_rest_alike():
    cell = indoor_scenes.two_rooms().env_cells[0]
    plain = DatEnvCell.unpack(BinaryReader(dat.env_cell_record(cell, ()).data, EXACT))
    drawn = DatEnvCell.unpack(BinaryReader(dat.env_cell_record(cell, (), True).data, EXACT))
    assert (plain.surfaces, drawn.surfaces) == ([], [dat.DRAWING_SURFACE])
    assert (drawn.environment_id, drawn.cell_structure, drawn.visible_cells) == (
        plain.environment_id, plain.cell_structure, plain.visible_cells)
