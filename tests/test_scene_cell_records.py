"""Cell records of shapes only scene/8 says (strategies/cell_records.py, shard buildings-0018): housing barriers
(`env_cells[].restriction_obj`, `landblocks[].restrictions`, protocol feature `dat.restrictions`) and visible cells or
building portals naming a low word below 0x0100 (`dat.outdoor_words`). Their JSON form and format, the records
acconform/dat.py writes read back as ACE.DatLoader reads them (port/dat/), and what ACE's physics makes of them in a
run of the port: a player entering a restricted cell whose object ServerObjectManager lacks collides; one whose object
is no House passes, the restriction verified."""

from __future__ import annotations

import copy
from dataclasses import replace

import pytest

from acconform import dat
from acconform.case import parse_document
from acconform.codec import compact, dumps_compact
from acconform.errors import InvalidScene
from acconform.numerics import EXACT
from acconform.port.dat.binary_reader import BinaryReader
from acconform.port.dat.env_cell import ENV_CELL_HAS_RESTRICTION_OBJ
from acconform.port.dat.env_cell import EnvCell as DatEnvCell
from acconform.port.dat.environment import Environment
from acconform.port.dat.landblock_info import LandblockInfo
from acconform.port.run import run_scene
from acconform.protocol import scene_features
from acconform.scene import FORMAT, BuildingPortalRec, Scene
from acconform.staging import MOVER_ID
from acconform.strategies import sample_scenes
from acconform.strategies.cell_records import _leaf_plus

BASE = next(s for s in sample_scenes(("buildings",), 40, 3) if s.name.startswith("building:in") and s.mover.placement is None)
NOBODY = 0x7ABC0001  # an id ServerObjectManager does not hold


def restricted(obj: int) -> Scene:
    """BASE with every EnvCell and every land cell of its building's landblock restricted to `obj`."""
    block = BASE.buildings[0].landblock
    landblocks = tuple(replace(lb, restrictions=tuple(((block & 0xFFFF0000) | k, obj) for k in range(1, 65)))
                       if lb.id == block else lb for lb in BASE.landblocks)
    return BASE.replace(env_cells=tuple(replace(c, restriction_obj=obj) for c in BASE.env_cells), landblocks=landblocks)


def refused(doc) -> str:
    with pytest.raises(InvalidScene) as e:
        parse_document(doc)
    return str(e.value)


def test_a_restricted_scene_is_scene_8_needing_its_feature_and_round_trips():
    s = restricted(NOBODY)
    doc = s.to_json()
    assert doc["format"] == FORMAT and doc["env_cells"][0]["restriction_obj"] == "0x7ABC0001"
    assert Scene.loads(s.dumps()) == s
    assert "dat.restrictions" in scene_features(s) and "dat.restrictions" not in scene_features(BASE)
    assert "restriction_obj" not in BASE.to_json()["env_cells"][0] and "restrictions" not in BASE.to_json()["landblocks"][0]


def test_a_restriction_table_is_refused_on_a_landblock_without_buildings_twice_for_a_cell_or_naming_object_0():
    doc = restricted(NOBODY).to_json()
    no_buildings = copy.deepcopy(doc)
    no_buildings["buildings"] = []
    assert "landblocks[0].restrictions: landblock" in refused(no_buildings)
    twice = copy.deepcopy(doc)
    twice["landblocks"][0]["restrictions"][1]["cell"] = twice["landblocks"][0]["restrictions"][0]["cell"]
    assert "is restricted twice" in refused(twice)
    zero = copy.deepcopy(doc)
    zero["landblocks"][0]["restrictions"][0]["object"] = "0x0"
    assert "a restriction object is not 0" in refused(zero)


@pytest.mark.anchor("ACE.DatLoader/FileTypes/EnvCell.cs:Unpack")
def test_a_restricted_env_cell_record_carries_the_flag_and_its_object_last():
    cell = replace(BASE.env_cells[0], restriction_obj=NOBODY)
    read = DatEnvCell.unpack(BinaryReader(dat.env_cell_record(cell, ()).data, EXACT))
    plain = DatEnvCell.unpack(BinaryReader(dat.env_cell_record(BASE.env_cells[0], ()).data, EXACT))
    assert read.flags & ENV_CELL_HAS_RESTRICTION_OBJ and read.restriction_obj == NOBODY
    assert not plain.flags & ENV_CELL_HAS_RESTRICTION_OBJ and plain.restriction_obj == 0


@pytest.mark.anchor("ACE.DatLoader/FileTypes/LandblockInfo.cs:Unpack")
def test_a_landblock_info_with_restrictions_has_pack_mask_1_and_the_table_in_order():
    pairs = ((0xA9B40003, NOBODY), (0xA9B40100, MOVER_ID), (0xA9B40001, NOBODY))
    info = LandblockInfo.unpack(BinaryReader(dat.landblock_info_record(0xA9B4, 1, (), pairs).data, EXACT))
    assert info.pack_mask == 1 and list(info.restriction_tables.items()) == list(pairs)
    assert LandblockInfo.unpack(BinaryReader(dat.landblock_info_record(0xA9B4, 1).data, EXACT)).restriction_tables == {}


@pytest.mark.anchor("ObjCell.cs:check_entry_restrictions")
def test_a_player_entering_a_cell_restricted_to_no_object_collides_and_one_restricted_to_a_non_house_passes():
    free, nobody, mover = (run_scene(s) for s in (BASE, restricted(NOBODY), restricted(MOVER_ID)))
    assert free.ok and free.cell != BASE.mover.begin.cell  # the walk leaves its begin cell
    assert nobody.ok and nobody.cell == BASE.mover.begin.cell and nobody.origin != free.origin  # held at the door
    assert mover == free


def test_visible_cells_and_building_portals_may_name_low_words_below_0x0100_in_scene_8():
    cell = replace(BASE.env_cells[0], visible_cells=(*BASE.env_cells[0].visible_cells, 0x0041, 0x0003))
    b = replace(BASE.buildings[0], portals=(*BASE.buildings[0].portals, BuildingPortalRec(0x0000, 0xFFFF)))
    s = BASE.replace(env_cells=(cell, *BASE.env_cells[1:]), buildings=(b,))
    assert Scene.loads(s.dumps()) == s and s.to_json()["format"] == FORMAT
    assert "dat.outdoor_words" in scene_features(s) and "dat.outdoor_words" not in scene_features(BASE)
    doc = s.to_json()
    doc["env_cells"][0]["visible_cells"][-1] = "0x0100"[:2] + "FFFE"
    assert "a visible cell is an EnvCell's low word (0x0100..0xFFFD) or 0x0000..0x00FF, got 0xFFFE" in refused(doc)


@pytest.mark.anchor("ACE.DatLoader/Entity/CellStruct.cs:Unpack")
def test_a_cell_structure_without_a_drawing_bsp_is_scene_8_and_reads_back_with_none_and_the_same_physics():
    env = BASE.environments[0]
    bare = replace(env, cell_structs=tuple(replace(c, drawing_bsp=False) for c in env.cell_structs))
    s = BASE.replace(environments=(bare, *BASE.environments[1:]))
    assert Scene.loads(s.dumps()) == s and s.to_json()["format"] == FORMAT
    assert s.to_json()["environments"][0]["cell_structs"][0]["drawing_bsp"] is False
    assert compact(s.to_json) == dumps_compact(s.to_json())  # the structure's own text (json_text) says it too
    read, full = (Environment.unpack(BinaryReader(dat.environment_record(e).data, EXACT)) for e in (bare, env))
    assert all(c.drawing_bsp is None for c in read.cells.values())
    assert all(c.drawing_bsp is not None for c in full.cells.values())
    assert run_scene(s) == run_scene(BASE)



def _missing(kind: str) -> Scene:
    env = BASE.environments[0]
    cells = list(BASE.env_cells)
    if kind == "cell_structure":
        cells[0] = replace(cells[0], cell_structure=len(env.cell_structs))
        return BASE.replace(env_cells=tuple(cells))
    if kind == "shell_leaf":
        b = BASE.buildings[0]
        shape = replace(b.shape, root=_leaf_plus(b.shape.root, len(b.shape.polygons)))
        return BASE.replace(buildings=(replace(b, shape=shape),))
    struct = env.cell_structs[cells[0].cell_structure]
    changed = replace(struct, portals=(*struct.portals, len(struct.polygons)))
    env = replace(env, cell_structs=tuple(changed if c is struct else c for c in env.cell_structs))
    return BASE.replace(environments=(env, *BASE.environments[1:]))


@pytest.mark.anchor("EnvCell.cs:EnvCell(DatLoader.FileTypes.EnvCell)")
@pytest.mark.parametrize("kind, error", [("cell_structure", "NullReferenceException"),
                                         ("struct_portal", "KeyNotFoundException"),
                                         ("shell_leaf", "KeyNotFoundException")])
def test_a_missing_structure_portal_polygon_or_leaf_polygon_is_scene_8_and_ace_throws_where_it_is_read(kind, error):
    s = _missing(kind)
    assert Scene.loads(s.dumps()) == s and s.to_json()["format"] == FORMAT and s.has_missing_keys
    assert not BASE.has_missing_keys
    assert run_scene(s).error.startswith(error)


@pytest.mark.anchor("ACE.DatLoader/Entity/BSPPortal.cs:Unpack")
def test_a_cell_tree_node_tagged_port_is_scene_8_reads_as_a_portal_node_and_changes_nothing_ace_reads():
    from acconform.port.dat.bsp_portal import BSPPortal
    from acconform.strategies.cell_records import _port_nodes

    class Always:  # every node a PORT one
        def __call__(self, strategy):
            return True

    env = BASE.environments[0]
    ported = replace(env, cell_structs=tuple(replace(c, cell_bsp=_port_nodes(Always(), c.cell_bsp)) for c in env.cell_structs))
    s = BASE.replace(environments=(ported, *BASE.environments[1:]))
    assert s.has_cell_bsp_portals and not BASE.has_cell_bsp_portals and s.to_json()["format"] == FORMAT
    assert Scene.loads(s.dumps()) == s and compact(s.to_json) == dumps_compact(s.to_json())
    root = Environment.unpack(BinaryReader(dat.environment_record(ported).data, EXACT)).cells[0].cell_bsp.root_node
    assert isinstance(root, BSPPortal) and root.in_polys is None and root.sphere is None
    doc = s.to_json()
    node = doc["environments"][0]["cell_structs"][0]["cell_bsp"]
    node.pop("back")
    assert "a portal node (tag PORT) has both children" in refused(doc)
