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
        assert [int(p) for p in got.Portals] == list(rec.portals)
        drawing = got.DrawingBSP.RootNode  # a PORT node for the one portal polygon, or a lone leaf
        if rec.portals:
            assert str(drawing.Type) == "PORT" and [(int(p.PortalIndex), int(p.PolygonId)) for p in drawing.InPortals] == [(0, 0)]
        else:
            assert str(drawing.Type) == "LEAF" and int(drawing.LeafIndex) == 0
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


def _drawing_tree_matches(ace, port) -> int:
    """ACE's physics BSP node and the port's built from the same DAT drawing node agree field for
    field (class, sphere, splitting plane, polygons' planes, leaf index, children); the nodes compared."""
    assert type(port).__name__ == str(ace.GetType().Name)
    if port.sphere is None:
        assert ace.Sphere is None
    else:
        c = ace.Sphere.Center
        assert (float(c.X), float(c.Y), float(c.Z), float(ace.Sphere.Radius)) == (*map(float, port.sphere.center), float(port.sphere.radius))
    n = ace.SplittingPlane.Normal
    assert (float(n.X), float(n.Y), float(n.Z), float(ace.SplittingPlane.D)) == (*map(float, port.splitting_plane.normal), float(port.splitting_plane.d))
    assert int(ace.NumPolys) == port.num_polys
    for a, p in zip(ace.Polygons or (), port.polygons or ()):
        an = a.Plane.Normal
        assert (float(an.X), float(an.Y), float(an.Z), float(a.Plane.D)) == (*map(float, p.plane.normal), float(p.plane.d))
    if type(port).__name__ == "BSPLeaf":
        assert int(ace.LeafIdx) == port.leaf_idx and bool(ace.Solid) == port.solid
    count = 1
    for a, p in ((ace.PosNode, port.pos_node), (ace.NegNode, port.neg_node)):
        assert (a is None) == (p is None)
        if p is not None:
            count += _drawing_tree_matches(a, p)
    return count


def test_ace_builds_the_drawing_tree_of_a_cell_structure_as_the_port_does(live):
    from ACE.DatLoader.FileTypes import Environment  # type: ignore[import-not-found]
    from ACE.Server.Physics.Common import CellStruct as AceCellStruct  # type: ignore[import-not-found]
    from acconform.numerics import get_mode, runtime_named
    from acconform.port.cell.cell_struct import CellStruct
    from acconform.port.dat.binary_reader import BinaryReader
    from acconform.port.dat.environment import Environment as PortEnvironment
    from acconform.scene import CellStructRec, Environment as EnvironmentRec

    from . import indoor_scenes as s

    doors = CellStructRec((s.FLOOR, s.NORTH, s.EAST, s.SOUTH, s.WEST), (4, 2, 4), (s.FLOOR,), s.physics_bsp(1), s.cell_bsp())
    data = dat.environment_record(EnvironmentRec(ENV, (*ENVIRONMENT.cell_structs, doors))).data
    mode = get_mode("exact", runtime_named(live.versions.runtime))
    ace_env = _unpack(Environment(), data)
    port_env = PortEnvironment.unpack(BinaryReader(data, mode))
    compared = 0
    for entry in ace_env.Cells:
        ace = AceCellStruct(entry.Value)
        port = CellStruct.from_dat(port_env.cells[int(entry.Key)], mode)
        compared += _drawing_tree_matches(ace.DrawingBSP.RootNode, port.drawing_bsp.root_node)
    assert compared == 1 + 3 + 3 + 11  # a lone leaf, two portal nodes and their leaves, five nodes and six leaves


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
