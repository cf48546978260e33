"""Indoor scenes on live ACE: the indoor DAT records read by ACE's own Unpack field for field, EnvCells
loaded by ACE's LScape.get_landcell from the cell DAT the facade installs, and nothing of a scene's
EnvCells left in the facade's cached landblocks for the next scene."""

import numpy as np
import pytest

from acconform import dat

from .indoor_scenes import BLOCK, ENV, ENVIRONMENT, SCENES, box_room, room_with_static, two_rooms

pytestmark = pytest.mark.live_oracle


def _unpack(file, data: bytes):
    from System.IO import BinaryReader, MemoryStream  # type: ignore[import-not-found]

    stream = MemoryStream(bytes(data))
    file.Unpack(BinaryReader(stream))
    assert int(stream.Position) == len(data), "bytes left unread"
    return file


def _f32(x) -> float:
    return float(np.float32(x))


def test_ace_unpacks_the_environment_field_for_field(live):
    from ACE.DatLoader.FileTypes import Environment  # type: ignore[import-not-found]

    env = _unpack(Environment(), dat.environment_record(ENVIRONMENT).data)
    assert int(env.Id) == ENV and int(env.Cells.Count) == len(ENVIRONMENT.cell_structs)
    for entry in env.Cells:
        rec = ENVIRONMENT.cell_structs[int(entry.Key)]
        got = entry.Value
        assert int(got.Polygons.Count) == len(rec.polygons) and int(got.PhysicsPolygons.Count) == len(rec.physics_polygons)
        assert [int(p) for p in got.Portals] == list(rec.portals) and got.DrawingBSP is None
        verts = got.VertexArray.Vertices
        for poly in got.PhysicsPolygons:
            want = rec.physics_polygons[int(poly.Key)]
            ids = [int(i) for i in poly.Value.VertexIds]
            assert [(float(verts[i].Origin.X), float(verts[i].Origin.Y), float(verts[i].Origin.Z)) for i in ids] == \
                [tuple(map(_f32, v)) for v in want.vertices]
            assert int(poly.Value.SidesType) == want.sides_type
        node, want = got.CellBSP.RootNode, rec.cell_bsp
        while want is not None:  # the rooms' cell BSP: a chain of front children
            assert str(node.Type) == ("BPIn" if want.front is not None else "Bpnn") and node.NegNode is None
            assert float(node.SplittingPlane.D) == _f32(want.plane.d) and node.Sphere is None
            node, want = node.PosNode, want.front
        assert node is None
        root = got.PhysicsBSP.RootNode
        assert str(root.Type) == "BPIN" and [int(i) for i in root.PosNode.InPolys] == list(rec.physics_bsp.front.polygons)


def test_ace_unpacks_the_env_cells_and_the_landblock_info_field_for_field(live):
    from ACE.DatLoader.FileTypes import EnvCell, LandblockInfo  # type: ignore[import-not-found]

    scene = room_with_static()
    pairs = [(s, rec) for s in (scene, two_rooms()) for rec in dat.cell_dat_records(s)]
    for source, rec in pairs:
        if rec.kind == "LandblockInfo":
            info = _unpack(LandblockInfo(), rec.data)
            assert int(info.Id) == BLOCK | 0xFFFE and int(info.NumCells) in (1, 2)
            assert int(info.Objects.Count) == 0 and int(info.Buildings.Count) == 0
            continue
        cell = _unpack(EnvCell(), rec.data)
        want = next(c for c in source.env_cells if c.id == rec.id)
        assert int(cell.Id) == want.id and int(cell.EnvironmentId) == want.environment
        assert int(cell.CellStructure) == want.cell_structure and bool(cell.SeenOutside) == want.seen_outside
        o = cell.Position.Origin
        assert (float(o.X), float(o.Y), float(o.Z)) == want.frame.origin and float(cell.Position.Orientation.W) == 1.0
        assert [(int(p.PolygonId), int(p.OtherCellId), int(p.OtherPortalId), bool(p.PortalSide))
                for p in cell.CellPortals] == [(p.polygon, p.other_cell, p.other_portal, True) for p in want.portals]
        assert [int(v) for v in cell.VisibleCells] == list(want.visible_cells)
    cell = _unpack(EnvCell(), pairs[0][1].data)
    (stab,) = list(cell.StaticObjects)
    assert int(stab.Id) == dat.static_records(scene.objects[0], 0).did and float(stab.Frame.Origin.X) == 50.0


def test_ace_loads_env_cells_from_the_cell_dat_walking_through_a_portal_and_into_walls(live):
    through = live.run(two_rooms())
    assert through.error is None and through.cell == BLOCK | 0x0101 and through.origin[0] > 54.9
    wall = live.run(SCENES["box room: into the east wall"])
    assert wall.cell == BLOCK | 0x0100 and wall.collision_normal.valid and wall.origin[0] < 52.0 - 0.48
    boulder = live.run(room_with_static())
    assert boulder.static_cells == ((BLOCK | 0x0100,),) and boulder.collision_normal.valid


def test_a_scenes_env_cells_do_not_outlive_it_in_the_cached_landblock(live):
    a, b = box_room((53.0, 48.0, -10.0)), two_rooms((53.0, 48.0, -10.0))  # the same landblock, different cells
    first_a, first_b = live.run(a), live.run(b)
    assert first_a != first_b and live.last_landblocks_reused == 1
    assert live.run(a) == first_a and live.run(b) == first_b
    live.set_landblock_cache(False)
    try:
        assert live.run(b) == first_b and live.run(a) == first_a
    finally:
        live.set_landblock_cache(True)


def test_a_missing_env_cell_throws_as_a_missing_landblock_does(live):
    a = two_rooms()
    lone = a.replace(env_cells=(a.env_cells[0],))  # the portal and the visible cell name 0x0101, never defined
    assert live.run(lone).error.startswith("NullReferenceException")


@pytest.mark.parametrize("name", sorted(SCENES))
def test_the_port_matches_ace_on_the_small_indoor_scenes(live, name):
    from acconform.numerics import runtime_named
    from acconform.port.run import run_scene

    scene = SCENES[name]
    assert run_scene(scene, runtime=runtime_named(live.versions.runtime)) == live.run(scene)


def test_indoors_the_server_and_client_modes_give_the_same_physics(live):
    for scene in (two_rooms(), room_with_static(), SCENES["box room: into the east wall"]):
        assert live.run(scene.replace(engine_mode="client")) == live.run(scene)
