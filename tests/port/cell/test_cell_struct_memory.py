"""The CellStructs the port remembers across runs (port/cell/cell_struct.py BUILT) change no outcome, and
their key holds every input CellStruct(DatLoader CellStruct) reads: the Environment record's bytes, the
structure's id, the mode."""

from __future__ import annotations

import numpy as np
import pytest

from acconform import dat
from acconform.numerics import EXACT, FAST
from acconform.port.cell import cell_struct
from acconform.port.dat.binary_reader import BinaryReader
from acconform.port.dat.environment import Environment as DatEnvironment
from acconform.port.dat.portal_dat import PortalDat
from acconform.port.run import run_scene
from acconform.scene import Environment
from dungeon_scenes import SCENES as DUNGEON_SCENES
from indoor_rooms import ENV_ID, SCENES as ROOM_SCENES, room_struct, two_rooms
from lazy_planes import plane_bits, plane_unset

SCENES = [s for s, _ in list(ROOM_SCENES.values()) + list(DUNGEON_SCENES.values())]


@pytest.mark.anchor("CCellStruct::UnPack")
@pytest.mark.parametrize("mode", ["exact", "fast"])
def test_remembered_cell_structs_give_the_outcomes_a_fresh_build_gives(mode):
    fresh = []
    for s in SCENES:
        cell_struct.clear_built()
        fresh.append(run_scene(s, mode))
    twice = [run_scene(s, mode) for s in SCENES] + [run_scene(s, mode) for s in SCENES]
    assert twice == fresh + fresh


def _built(env: Environment, mode, index: int):
    data = dat.environment_record(env).data
    portal_dat = PortalDat({env.id: data}, mode, True)
    structs = DatEnvironment.unpack(BinaryReader(data, mode)).cells
    return cell_struct.remembered(portal_dat, env.id, index, structs[index])


@pytest.mark.anchor("CCellStruct::UnPack")
def test_the_memory_is_keyed_by_the_records_bytes_the_structures_id_and_the_mode():
    cell_struct.clear_built()
    env, _ = two_rooms()
    a = _built(env, EXACT, 0)
    assert _built(env, EXACT, 0) is a
    other_id = _built(env, EXACT, 1)
    raised = _built(Environment(ENV_ID, (room_struct(floor=0.5, back_wall=True), env.cell_structs[1])), EXACT, 0)
    fast = _built(env, FAST, 0)
    assert other_id is not a and len(other_id.physics_polygons) == 1 and len(a.physics_polygons) == 2
    assert raised is not a and raised.physics_polygons[0].vertices[0].origin.z == np.float32(0.5)
    assert fast is not a and type(fast.physics_polygons[0].plane.d) is np.float64


@pytest.mark.anchor("CCellStruct::UnPack")
def test_a_structure_from_a_record_the_run_does_not_hold_is_not_remembered():
    cell_struct.clear_built()
    env, _ = two_rooms()
    data = dat.environment_record(env).data
    structs = DatEnvironment.unpack(BinaryReader(data, EXACT)).cells
    cell_struct.remembered(PortalDat({}, EXACT, True), env.id, 0, structs[0])
    assert cell_struct.BUILT == {}


@pytest.mark.anchor("CPolygon::UnPack")
@pytest.mark.parametrize("mode", [EXACT, FAST])
def test_dat_polygon_planes_made_when_first_read_are_the_planes_the_dat_constructor_made(mode, monkeypatch):
    from acconform.port.geom.polygon import Polygon

    env, _ = two_rooms()
    structs = DatEnvironment.unpack(BinaryReader(dat.environment_record(env).data, mode)).cells
    lazy = [cell_struct.CellStruct.from_dat(s, mode) for s in structs.values()]
    unread = [p for c in lazy for p in list(c.polygons.values()) + list(c.physics_polygons.values()) if plane_unset(p)]
    monkeypatch.setattr(Polygon, "make_plane_when_read", Polygon.make_plane)  # as ACE: in the constructor
    eager = [cell_struct.CellStruct.from_dat(s, mode) for s in structs.values()]
    polygons = [(a, b) for x, y in zip(lazy, eager) for a, b in zip(list(x.polygons.values()) + list(x.physics_polygons.values()),
                                                                     list(y.polygons.values()) + list(y.physics_polygons.values()))]
    assert unread and len(unread) == len(polygons)
    assert [plane_bits(a) for a, _ in polygons] == [plane_bits(b) for _, b in polygons]


def _tree(node) -> tuple:
    """A BSP node's whole subtree as plain values: kind, plane, sphere, polygons' vertices."""
    if node is None:
        return ()
    plane = node.splitting_plane
    return (type(node).__name__, float(plane.d), float(plane.normal.x), float(plane.normal.y), float(plane.normal.z),
            None if node.sphere is None else (float(node.sphere.radius), float(node.sphere.center.x)),
            tuple(tuple(float(v.origin.x) for v in p.vertices) for p in node.polygons or ()),
            _tree(node.pos_node), _tree(node.neg_node))


@pytest.mark.anchor("CCellStruct::UnPack")
@pytest.mark.anchor("BSPTREE::UnPack")
def test_a_drawing_tree_built_when_first_read_is_the_tree_the_constructor_would_build():
    from acconform.port.geom.bsp import BSPTree

    env, _ = two_rooms()
    structs = DatEnvironment.unpack(BinaryReader(dat.environment_record(env).data, EXACT)).cells
    for s in structs.values():
        c = cell_struct.CellStruct.from_dat(s, EXACT)
        eager = BSPTree.from_dat(s.drawing_bsp, s.polygons, s.vertex_array, EXACT)
        assert _tree(c.drawing_bsp.root_node) == _tree(eager.root_node) != ()


@pytest.mark.anchor("CCellStruct::UnPack")
def test_a_drawing_tree_naming_a_missing_polygon_throws_when_the_structure_is_built():
    from acconform.port.errors import KeyNotFoundException

    env, _ = two_rooms()
    s = next(iter(DatEnvironment.unpack(BinaryReader(dat.environment_record(env).data, EXACT)).cells.values()))
    node = s.drawing_bsp.root_node
    node.in_polys = list(node.in_polys) + [999]
    with pytest.raises(KeyNotFoundException, match="'999'"):
        cell_struct.CellStruct.from_dat(s, EXACT)
