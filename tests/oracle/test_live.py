"""The live oracle against ACE itself (lane `live_oracle`; set ACE_ASSEMBLY to run it)."""

import pytest

from acconform.errors import OracleUnavailable
from acconform.flags import ObjectInfoState

from .scenes import PROBE, boulder, off_the_map, post, walk, flat, cliff, ramp, wall

pytestmark = pytest.mark.live_oracle

F = 1e-6  # the probe printed 6 decimals


def _close(a, b, tol=F):
    return all(abs(x - y) <= tol for x, y in zip(a, b))


def test_flat_one_step_walk_matches_the_probe(live):
    o = live.run(PROBE["flat 1-step walk"])
    assert o.error is None and o.ok
    assert o.cell == 0xA9B40001 and _close(o.origin, (12.4, 12.0, 20.0))
    assert o.contact_plane.valid and o.contact_plane.cell == 0xA9B40001 and o.contact_plane.normal == (0.0, 0.0, 1.0)
    assert o.contact_plane.d == -20.0 and o.last_known_contact_plane == o.contact_plane
    assert not o.sliding_normal.valid and not o.collision_normal.valid and not o.collided_with_environment
    assert o.object_info_state == (ObjectInfoState.Contact | ObjectInfoState.OnWalkable | ObjectInfoState.IsPlayer
                                   | ObjectInfoState.EdgeSlide)


def test_flat_eleven_step_walk_matches_the_probe(live):
    o = live.run(PROBE["flat ~11-step walk (5 m)"])
    assert o.ok and o.cell == 0xA9B40001 and _close(o.origin, (16.999998, 12.0, 20.0))
    assert o.contact_plane.valid and o.contact_plane.d == -20.0


def test_cliff_edge_walk_stops_at_the_edge_like_the_probe(live):
    o = live.run(PROBE["cliff edge walk (EdgeSlide)"])
    assert o.ok and o.cell == 0xA9B40011 and _close(o.origin, (71.818176, 12.0, 200.0))
    assert o.sliding_normal.valid and o.sliding_normal.vector == (0.0, 0.0, 0.0)
    assert o.collision_normal.valid and o.collision_normal.vector == (0.0, 0.0, 1.0)
    assert o.contact_plane.d == -200.0


def test_ramp_walk_follows_the_slope_like_the_probe(live):
    o = live.run(PROBE["ramp walk uphill"])
    assert o.ok and o.cell == 0xA9B40009 and _close(o.origin, (34.999992, 12.0, 22.916666))
    assert _close(o.contact_plane.normal, (-0.083045, 0.0, 0.996546)) and abs(o.contact_plane.d + 19.930916) < F


def test_every_outcome_field_is_filled_from_ace(live):
    o = live.run(PROBE["cliff edge walk (EdgeSlide)"])
    assert o.check_cell != 0 and o.walkable in (True, False) and o.frames_stationary_fall == 0
    assert o.orientation == (1.0, 0.0, 0.0, 0.0) and o.velocity == (0.0, 0.0, 0.0)


def test_scene_a_then_b_then_a_gives_identical_outcomes(live):
    a, b = PROBE["cliff edge walk (EdgeSlide)"], walk(flat, (12.0, 12.0, 20.0), (17.0, 12.0, 20.0), 20.0, objects=(wall(),))
    first = live.run(a)
    between = live.run(b)
    assert live.run(a) == first
    assert between != first


def test_landblock_cache_changes_no_outcome(live):
    scenes = list(PROBE.values()) + [walk(flat, (12.0, 12.0, 20.0), (30.0, 12.0, 20.0), 20.0, objects=(o,)) for o in (wall(), post(), boulder())]
    cached = [live.run(s) for s in scenes] + [live.run(s) for s in scenes]
    live.set_landblock_cache(False)
    try:
        fresh = [live.run(s) for s in scenes]
    finally:
        live.set_landblock_cache(True)
    assert cached[: len(scenes)] == fresh and cached[len(scenes):] == fresh


def test_an_ace_exception_is_the_outcome_not_a_crash(live):
    o = live.run(off_the_map())
    assert o.error is not None and o.error.startswith("ArgumentOutOfRangeException")
    assert live.run(PROBE["flat 1-step walk"]).error is None  # and the next scene is unaffected


def test_a_bsp_wall_stops_the_mover(live):
    o = live.run(walk(flat, (12.0, 12.0, 20.0), (17.0, 12.0, 20.0), 20.0, objects=(wall(),)))
    assert o.ok and o.origin[0] < 14.0 - 0.48 + 1e-3
    assert o.collision_normal.valid and o.collision_normal.vector == (-1.0, 0.0, 0.0)


def test_a_bsp_wall_seen_from_behind_lets_the_mover_through(live):
    """ACE's BSP polygons are one-sided (Polygon.pos_hits_sphere)."""
    o = live.run(walk(flat, (12.0, 12.0, 20.0), (17.0, 12.0, 20.0), 20.0, objects=(wall(facing_mover=False),)))
    assert o.ok and o.origin[0] > 16.9


def test_a_wall_in_the_next_cell_is_found_through_its_shadow_in_this_cell(live):
    o = live.run(walk(flat, (12.0, 12.0, 20.0), (30.0, 12.0, 20.0), 20.0, objects=(wall(x=24.5, cell=0xA9B40009),)))
    assert o.cell == 0xA9B40001 and o.origin[0] < 24.5 - 0.48 + 1e-3


@pytest.mark.parametrize("obstacle", [post, boulder], ids=["cylsphere", "sphere"])
def test_sphere_and_cylsphere_obstacles_stop_the_mover(live, obstacle):
    o = live.run(walk(flat, (12.0, 12.0, 20.0), (17.0, 12.0, 20.0), 20.0, objects=(obstacle(),)))
    assert o.ok and o.origin[0] < 14.6 and o.collision_normal.valid


def _server_and_client_scenes():
    out = []
    for fn in (flat, cliff, ramp):
        for sx in (12.0, 30.0, 70.0, 100.0, 150.0):
            for dx, dy in ((5.0, 0.0), (-3.0, 4.0), (0.4, 0.1), (20.0, -7.0)):
                start = (sx, 60.0, 0.0)
                out.append((fn, start, (sx + dx, 60.0 + dy)))
    return out


def test_server_and_client_modes_give_the_same_physics(live):
    """Server mode finds landblocks through LandblockManager, client mode through LScape.Landblocks;
    nothing else in the transition reads PhysicsEngine.Server (docs/oracle.md)."""
    from acconform.scene import ContactPlane, Frame, PlaneRec, Position, replace as _r  # noqa: F401
    n = 0
    for fn, start, end in _server_and_client_scenes():
        z = 2.0 * fn(int(start[0] // 24), int(start[1] // 24))
        for objs in ((), (wall(x=start[0] + 2.0, cell=0xA9B40000 | (int((start[0] + 2) // 24) * 8 + 3)),)):
            s = walk(fn, (start[0], start[1], z), (end[0], end[1], z), z, objects=objs)
            c = s.replace(engine_mode="client")
            assert live.run(s) == live.run(c), s.to_json()
            n += 1
    assert n >= 100


def test_batch_and_single_runs_agree(live):
    scenes = list(PROBE.values()) + [off_the_map()]
    assert [o for o, _ in live.run_many(scenes)] == [live.run(s) for s in scenes]


def test_versions_name_ace_and_the_runtime(live):
    assert "sha256:" in live.versions.ace and live.versions.runtime.split()[0] in ("mono", "coreclr")


def test_a_bogus_member_asked_through_the_real_checker_fails_clearly(live):
    from acconform.oracle.runtime import check_required

    check_required((("ACE.Server.Physics.PhysicsObj", ("FindObjCollisions",)),))  # a real one passes
    with pytest.raises(OracleUnavailable, match=r"ACE\.Server\.Physics\.PhysicsObj\.NoSuchMember"):
        check_required((("ACE.Server.Physics.PhysicsObj", ("NoSuchMember",)),))


def test_the_facade_counts_landblocks_built_and_reused(live):
    s = walk(ramp, (30.0, 12.0, 22.5), (31.0, 12.0, 22.5 + 2 / 24), 22.5, name="counted")
    live.run(s)
    live.run(s)
    assert (live.last_landblocks_built, live.last_landblocks_reused) == (0, 1)  # same bytes, same height table
    other = s.replace(land_height_table=tuple(x * 2 for x in s.land_height_table))
    first = live.run(other)
    assert (live.last_landblocks_built, live.last_landblocks_reused) == (1, 0) and live.last_build_micros > 0
    live.set_landblock_cache(False)
    try:
        assert live.run(other) == first and live.last_landblocks_built == 1
    finally:
        live.set_landblock_cache(True)


def test_ace_unpacks_every_dat_record_to_its_last_byte(live):
    """acconform/dat.py's bytes read by ACE's own DatLoader Unpack: nothing left over, counts as written."""
    import clr  # noqa: F401  (the live fixture has started the runtime)
    from System.IO import BinaryReader, MemoryStream  # type: ignore[import-not-found]
    from ACE.DatLoader.FileTypes import GfxObj, SetupModel  # type: ignore[import-not-found]

    import numpy as np

    from acconform import dat
    from acconform.scene import BSPLeaf

    objects = [wall(), post(), boulder()]
    seen = 0
    for i, obj in enumerate(objects):
        for rec in dat.static_records(obj, i).records + dat.mover_records(PROBE["flat 1-step walk"].mover).records:
            stream = MemoryStream(bytes(rec.data))
            file = GfxObj() if rec.kind == "GfxObj" else SetupModel()
            file.Unpack(BinaryReader(stream))
            assert int(stream.Position) == len(rec.data) and int(file.Id) == rec.id, rec
            if rec.kind == "GfxObj" and obj.shape.kind == "bsp" and rec.id == dat.GFX_OBJ_BASE + i:
                shape = obj.shape
                assert int(file.PhysicsPolygons.Count) == len(shape.polygons)
                root = file.PhysicsBSP.RootNode
                assert str(root.Type) == ("LEAF" if isinstance(shape.root, BSPLeaf) else "BPIN")
                assert float(root.Sphere.Radius) == float(np.float32(shape.root.sphere.radius))
            if rec.kind == "Setup":
                assert int(file.Parts.Count) == 1 and int(file.Spheres.Count) + int(file.CylSpheres.Count) >= 1
            seen += 1
    assert seen == 1 + 2 + 2 + 3 * 2
