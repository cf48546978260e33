"""A projectile's physics from launch to hit (port/missile_launch.py and the PhysicsObj calls it
makes: enter_world, update_object, DestroyObject), on flat ground with a sphere target, as ACE's
server code makes those calls (Creature_Missile.cs, WorldObject.AddPhysicsObj, WorldObject_Tick.cs
UpdateObjectPhysics, ProjectileCollisionHelper.cs, SpellProjectile.cs at 7b47913). The projectiles are
port/world_objects' Ammunition, Missile and SpellProjectile; the sphere target gets a Creature WorldObject,
so WeenieObject.DoCollision runs the projectile's OnCollideObject on a hit, as on a server.
"""

from __future__ import annotations

import sys
import warnings
from pathlib import Path

import numpy as np
import pytest

from acconform import dat
from acconform.flags import PhysicsState, TransientState
from acconform.numerics import EXACT, normalize
from acconform.port import missile_launch as ml
from acconform.port.frame import AFrame, Position
from acconform.port.physics_timer import PhysicsTimer
from acconform.port.server_landblock import Landblock
from acconform.port.world_objects import Ammunition, Creature, Missile, SpellProjectile
from acconform.port.run import build_mover, build_static, scene_world
from acconform.port.weenie_object import WeenieObject
from acconform.scene import SphereRec, SphereShape

sys.path.insert(0, str(Path(__file__).resolve().parent / "objects"))
from object_scenes import BSP_STATE, GROUND, LB, box, cell_id, obj, walk  # noqa: E402

F = np.float32
ARROW_ID = 0x80000001
TARGET = (100.0, 97.0)  # off the cell border at y = 96 (a placement on it lands in the cell below)
MISSILE_BITS = PhysicsState.Missile | PhysicsState.AlignPath | PhysicsState.PathClipped


@pytest.fixture(autouse=True)
def _quiet_numpy():
    with warnings.catch_warnings(), np.errstate(all="ignore"):
        warnings.simplefilter("ignore", RuntimeWarning)
        yield


def make_world(extra=()):
    """Flat ground at 20 m, a 0.5 m sphere target (a dynamic object: not Static) at (100, 97), the
    `extra` statics, and an arrow: a 0.05 m sphere with gravity, built but not in the world
    (InitPhysicsObj leaves CurCell null), whose WorldObject is Ammunition."""
    target_rec = obj(0, SphereShape(SphereRec((0.0, 0.0, 0.5), 0.5)), *TARGET, state=0)
    scene = walk("arrow", (90, 97, GROUND + 0.5), (91, 97, GROUND + 0.5), [target_rec, *extra],
                 spheres=(SphereRec((0.0, 0.0, 0.0), 0.05),), state=int(PhysicsState.Gravity), transient=0, contact=False)
    timer = PhysicsTimer(10.0)
    lscape, portal_dat, dids = scene_world(scene, EXACT, timer)
    statics = [build_static(rec, did, portal_dat, lscape) for rec, did in zip(scene.objects, dids)]
    statics[0].weenie_obj = WeenieObject.of(Creature(guid=statics[0].id, is_monster=True))
    arrow = build_mover(scene.mover, dat.MOVER_SETUP_ID, ARROW_ID, portal_dat, lscape)
    arrow.cur_cell = None
    arrow.position = Position(0, AFrame.identity(EXACT))
    return lscape, timer, statics, arrow


@pytest.fixture
def world():
    lscape, timer, statics, arrow = make_world()
    yield lscape, timer, statics[0], arrow
    lscape.release()


def fly(wo, lscape, timer, ticks=40):
    """Ticks of 0.05 s until the arrow's Missile bit is gone (it touched something)."""
    t = timer.current_time
    for _ in range(ticks):
        t += 0.05
        timer.set(t)
        ml.update_object_physics(wo, lscape)
        if not wo.physics_obj.state & PhysicsState.Missile or not wo.physics_obj.is_active():
            break
    return t


def v(x, y, z):
    return EXACT.vec(x, y, z)


def launch(lscape, timer, target, arrow, kind=Ammunition, speed=20.0):
    """Launched by no Creature (IsProjectileVisible: seen), at the target's WorldObject and PhysicsObj."""
    wo = kind(guid=ARROW_ID, physics_obj=arrow, physics_creation_time=timer.current_time)
    arrow.weenie_obj = WeenieObject.of(wo)
    origin = v(90, 97, GROUND + 0.5)
    dest = target.position.frame.origin + v(0, 0, 0.5)
    velocity, _ = ml.get_projectile_velocity(origin, dest, F(speed), v(0, 0, 0))
    ok = ml.launch_projectile(wo, None, None, target.weenie_obj.world_object, target, origin, EXACT.quat(0, 0, 0, 1),
                              Landblock(LB >> 16), cell_id(LB, 90, 97), velocity, lscape)
    return wo, ok, velocity


def test_a_launched_arrow_enters_the_world_active_with_the_missile_bits_and_its_target(world):
    lscape, timer, target, arrow = world
    wo, ok, velocity = launch(lscape, timer, target, arrow)
    assert ok and wo.current_landblock is not None and wo.current_landblock.pending_additions == {ARROW_ID: wo}
    assert arrow.cur_cell is not None and arrow.is_active()
    assert arrow.state & MISSILE_BITS == MISSILE_BITS and arrow.state & PhysicsState.ReportCollisions
    assert not arrow.state & (PhysicsState.Ethereal | PhysicsState.IgnoreCollisions)
    assert arrow.projectile_target is target and wo.projectile_target is target.weenie_obj.world_object
    assert arrow.velocity == velocity  # assigned, not set_velocity's clamp
    assert arrow.server_objects.get_object_a(ARROW_ID) is arrow


def test_an_arrow_flies_until_it_strikes_its_target_and_the_hit_destroys_its_physics(world):
    lscape, timer, target, arrow = world
    wo, ok, _ = launch(lscape, timer, target, arrow)
    assert ok
    cell = arrow.cur_cell
    t = fly(wo, lscape, timer)
    # report_object_collision cleared Missile | AlignPath | PathClipped on touching the target, built the
    # missile's AtkCollisionProfile and ran Ammunition.OnCollideObject(target): ProjectileCollisionHelper's hit
    assert not arrow.state & MISSILE_BITS
    # stopped at the target's surface: the arrow's 0.05 m sphere against the target's 0.5 m one, whose
    # centre is 0.5 m up (PathClipped: the rest of the step is cut off, not slid along)
    gap = (arrow.position.frame.origin - (target.position.frame.origin + v(0, 0, 0.5))).length()
    assert 0.55 <= gap < 0.6
    assert arrow.cur_cell is None and not arrow.is_active()  # destroyed inside its own set_position_internal
    assert arrow.position.obj_cell_id == 0
    assert arrow not in cell.object_list and cell.id & 0xFFFF0000 == LB
    assert arrow.server_objects.get_object_a(ARROW_ID) is None
    assert wo.hit_msg and wo.current_landblock is None
    # the next tick does nothing: UpdateObjectPhysics returns at its is_active check
    timer.set(t + 0.05)
    assert ml.update_object_physics(wo, lscape) is False


def test_an_arrow_hitting_another_object_counts_as_hitting_the_environment(world):
    lscape, timer, target, arrow = world
    wo, ok, _ = launch(lscape, timer, target, arrow)
    other = Creature(guid=0x80000002)
    wo.on_collide_object(other)
    assert arrow.cur_cell is None and not arrow.is_active() and wo.hit_msg


def test_a_hit_while_the_arrow_is_still_entering_the_world_is_no_environment_hit(world):
    lscape, timer, target, arrow = world
    wo, ok, _ = launch(lscape, timer, target, arrow)
    arrow.entering_world = True
    wo.on_collide_environment()
    assert arrow.is_active() and arrow.cur_cell is not None and not wo.hit_msg


def test_a_thrown_weapon_without_a_target_ignores_its_collisions(world):
    lscape, timer, target, arrow = world
    wo, ok, _ = launch(lscape, timer, target, arrow, kind=Missile)
    wo.projectile_target = None  # WorldObject.OnCollideObject/OnCollideEnvironment: no ProjectileTarget, no helper
    wo.on_collide_environment()
    wo.on_collide_object(target.weenie_obj.world_object)
    assert arrow.is_active() and arrow.cur_cell is not None


def test_a_missile_times_out_thirty_seconds_after_it_was_made(world):
    lscape, timer, target, arrow = world
    wo, ok, _ = launch(lscape, timer, target, arrow, speed=1.0)
    timer.set(wo.physics_creation_time + 30.0)
    assert ml.update_object_physics(wo, lscape) is False
    assert wo.is_destroyed and arrow.cur_cell is None and not arrow.is_active()


def test_an_invalid_velocity_misfires_before_anything_is_made(world):
    lscape, timer, target, arrow = world
    wo = Ammunition(guid=ARROW_ID, physics_obj=arrow)
    nan = float("nan")
    assert ml.launch_projectile(wo, None, None, target.weenie_obj.world_object, target, v(90, 97, GROUND + 0.5),
                                EXACT.quat(0, 0, 0, 1), Landblock(LB >> 16), cell_id(LB, 90, 97), v(nan, 0, 0), lscape) is False
    assert arrow.state & PhysicsState.Missile == 0 and wo.projectile_target is None


def test_a_spell_projectile_impact_makes_it_ethereal_inert_and_still(world):
    lscape, timer, target, arrow = world
    wo = SpellProjectile(guid=ARROW_ID, physics_obj=arrow, spell_type=ml.BOLT, physics_creation_time=timer.current_time)
    arrow.weenie_obj = WeenieObject.of(wo)
    ml.spell_projectile_setup(wo)
    assert arrow.state & MISSILE_BITS == MISSILE_BITS and not arrow.state & PhysicsState.EdgeSlide
    velocity = ml.calculate_spell_projectile_velocity(v(90, 97, GROUND + 1), v(100, 97, GROUND + 0.5), F(15), v(0, 0, 0), ml.BOLT)
    assert velocity == normalize(v(10, 0, -0.5)) * F(15)  # a Bolt at a still target: dir * speed
    ml.spell_projectile_set_physics_state(wo, target.weenie_obj.world_object, target, velocity, v(90, 97, GROUND + 1))
    landblock = Landblock(LB >> 16)
    assert ml.launch_spell_projectile(wo, None, None, landblock,
                                      Position(cell_id(LB, 90, 97), AFrame(v(90, 97, GROUND + 1), arrow.position.frame.orientation)),
                                      lscape)
    assert arrow.is_active() and arrow.projectile_target is target
    wo.on_collide_object(target.weenie_obj.world_object)
    for bit in (PhysicsState.Ethereal, PhysicsState.IgnoreCollisions, PhysicsState.NoDraw, PhysicsState.Cloaked):
        assert arrow.state & bit
    assert not arrow.state & (PhysicsState.ReportCollisions | PhysicsState.LightingOn)
    assert not arrow.is_active() and arrow.velocity == v(0, 0, 0)
    assert arrow.cur_cell is not None  # destroyed only 5 s later (its action chain)
    wo.destroy()
    assert arrow.cur_cell is None and wo.current_landblock is None and landblock.pending_additions == {}


def test_an_arrow_flies_through_an_ethereal_object_that_is_not_its_target():
    # ObjectInfo.MissileIgnore: a missile ignores an ethereal object that is not its target
    lscape, timer, statics, arrow = make_world([obj(1, SphereShape(SphereRec((0.0, 0.0, 0.5), 0.5)), 95.0, 97.0,
                                                    state=int(PhysicsState.Ethereal))])
    try:
        target = statics[0]
        wo, ok, _ = launch(lscape, timer, target, arrow)
        t = timer.current_time
        while arrow.position.frame.origin.x < 96.0:  # through the sphere's x = 94.5 .. 95.5
            t += 0.05
            timer.set(t)
            ml.update_object_physics(wo, lscape)
        # no collision was reported: an ethereal obstacle would otherwise be a CollideObject, whose report
        # clears the missile bits
        assert arrow.state & MISSILE_BITS == MISSILE_BITS and not arrow.collision_table
        fly(wo, lscape, timer)
        assert not arrow.state & MISSILE_BITS and wo.hit_msg
        assert arrow.position.frame.origin.x > 99.0  # stopped at the target
    finally:
        lscape.release()


def test_an_arrow_striking_a_wall_loses_only_its_missile_bit_and_the_environment_hit_destroys_it():
    # a static BSP wall 1 m thick across the path at x = 95: track_object_collision of a Static reports an
    # environment collision, which clears Missile alone (AlignPath and PathClipped stay; an object hit clears all three)
    lscape, timer, statics, arrow = make_world([obj(1, box(1.0, 6.0, 4.0), 95.0, 97.0, state=BSP_STATE)])
    try:
        target = statics[0]
        wo, ok, _ = launch(lscape, timer, target, arrow)
        fly(wo, lscape, timer)
        assert not arrow.state & PhysicsState.Missile
        assert arrow.state & (PhysicsState.AlignPath | PhysicsState.PathClipped) == PhysicsState.AlignPath | PhysicsState.PathClipped
        assert 94.0 < arrow.position.frame.origin.x < 94.5  # at the wall's near face (x = 94.5), not through it
        # the wall is a static (DummyObject): track_object_collision reported it as the environment, and
        # DoCollision(EnvCollisionProfile) ran Ammunition.OnCollideEnvironment: the helper destroyed it
        assert arrow.cur_cell is None and not arrow.is_active() and wo.hit_msg
    finally:
        lscape.release()


def test_a_projectile_with_a_rotation_speed_tumbles_about_its_x_axis_and_does_not_align_with_its_path(world):
    # Creature.SetProjectilePhysicsState / SpellProjectile.Setup: RotationSpeed clears AlignPath, Omega = (2 pi r, 0, 0)
    lscape, timer, target, arrow = world
    wo = Ammunition(guid=ARROW_ID, physics_obj=arrow, rotation_speed=F(1.5))
    ml.set_projectile_physics_state(wo, target, v(1, 0, 0), v(90, 97, GROUND + 0.5), EXACT.quat(0, 0, 0, 1))
    assert not arrow.state & PhysicsState.AlignPath and arrow.state & PhysicsState.Missile
    assert arrow.omega == v(F(np.pi * 2 * 1.5), 0, 0)
    spell = SpellProjectile(guid=ARROW_ID, physics_obj=arrow, spell_type=ml.BOLT, rotation_speed=F(-0.5))
    ml.spell_projectile_setup(spell)
    assert not arrow.state & PhysicsState.AlignPath and arrow.omega == v(F(-np.pi), 0, 0)


@pytest.mark.parametrize("kind, ethereal, scripted", [("plain", False, None), ("rolling_death", True, None),
                                                       ("wall", False, False), ("ring", False, False),
                                                       ("ring_3818", False, True)])
def test_a_spells_setup_leaves_rolling_death_ethereal_and_sets_scripted_collision_by_wall_and_ring(world, kind, ethereal,
                                                                                                   scripted):
    from acconform.port.run import world_object_of
    from acconform.scene import Launch, OtherMover

    lscape, timer, target, arrow = world
    arrow.state = int(PhysicsState.Ethereal | PhysicsState.ScriptedCollision) if scripted is False else int(PhysicsState.Ethereal)
    launch = Launch(0, 0x50000001, None, 10.0, (90.0, 97.0, 21.0), spell=kind)
    other = OtherMover(ARROW_ID, "spell_projectile", (SphereRec((0.0, 0.0, 0.0), 0.1),), None, 0.0, 0.0, launch=launch)
    wo = world_object_of(other)
    wo.physics_obj = arrow
    assert wo.spell_type == (ml.WALL if kind == "wall" else ml.RING if kind.startswith("ring") else ml.BOLT)
    ml.spell_projectile_setup(wo, kind == "rolling_death",
                              None if scripted is None else scripted)
    assert bool(arrow.state & PhysicsState.Ethereal) == ethereal
    if scripted is not None:
        assert bool(arrow.state & PhysicsState.ScriptedCollision) == scripted


def test_a_weenies_report_collisions_property_and_a_thrown_weapon_are_made_as_the_scene_says():
    from acconform.port.run import world_object_of
    from acconform.scene import Launch, OtherMover

    body = (SphereRec((0.0, 0.0, 0.5), 0.5),)
    crate = world_object_of(OtherMover(0x80000002, "object", (), None, 0.0, 0.0, report_collisions=False))
    assert crate.report_collisions is False
    assert world_object_of(OtherMover(0x80000003, "monster", body, None, 0.0, 0.0)).report_collisions is None
    launch = Launch(0, 0x50000001, 0x80000003, 10.0, (90.0, 97.0, 21.0), rotation_speed=2.0)
    thrown = world_object_of(OtherMover(ARROW_ID, "missile", body, None, 0.0, 0.0, launch=launch))
    assert type(thrown) is Missile and thrown.rotation_speed == 2.0


def _relocation_scene(blocked: bool):
    from hypothesis import strategies as st

    from acconform.strategies.determinism import pinned_constants
    from acconform.strategies.fast_draw import FastDrawer
    from acconform.strategies.missiles import draw_relocation_scene

    drawer = FastDrawer(st.composite(draw_relocation_scene)(), 71 * 1000003)
    with pinned_constants():
        return next(s for s in (drawer.draw()[0] for _ in range(60)) if s.name.endswith(":blocked") == blocked
                    and s.ticks.steps[0].dt < 0.05)


@pytest.mark.anchor("ACE.Server/Managers/LandblockManager.cs:GetLandblock")
def test_a_spell_flying_into_the_next_landblock_is_moved_there_and_left_in_the_world(monkeypatch):
    """LandblockManager.RelocateObjectForPhysics after the tick it crosses in: the old landblock, whose worldObjects
    took it at a tick's start (ProcessPendingWorldObjectAdditionsAndRemovals), lets it go (pendingRemovals) without
    destroying it (adjacencyMove), the new one files it (AddWorldObjectInternal finds its CurCell set: no second
    enter_world), and GetLandblock(id, true)'s SetAdjacents gives the new physics landblock its neighbour anew."""
    from acconform.port import missile_launch
    from acconform.port.run import run_scene

    scene = _relocation_scene(blocked=False)
    seen = []
    relocate = missile_launch.relocate_object_for_physics

    def watched(wo, landblocks, lscape, trace=None):
        old = wo.current_landblock
        cell_before = wo.physics_obj.cur_cell.id
        relocate(wo, landblocks, lscape, trace)
        new = wo.current_landblock
        seen.append((old.id, new.id, wo.guid in old.pending_removals, new.pending_additions.get(wo.guid) is wo,
                     wo.physics_obj.cur_cell.id == cell_before,
                     [a.raw for a in lscape.landblocks[new.id << 16 | 0xFFFF].adjacents]))

    monkeypatch.setattr(missile_launch, "relocate_object_for_physics", watched)
    out = run_scene(scene, runtime="coreclr")
    assert all(t.error is None for t in out.ticks)
    first, second = (b.id >> 16 for b in scene.landblocks)
    assert seen == [(first, second, True, True, True, [first << 16 | 0xFFFF])]



def test_a_landblocks_tick_files_its_pending_additions_and_drops_its_pending_removals():
    """ProcessPendingWorldObjectAdditionsAndRemovals: additions into worldObjects, then removals out of it."""
    from acconform.port.server_landblock import Landblock as ServerLandblock

    lb = ServerLandblock(0xA9B4)
    a, b = object(), object()
    lb.world_objects[1] = a
    lb.pending_additions[2] = b
    lb.pending_removals.append(1)
    lb.process_pending_world_object_additions_and_removals()
    assert lb.world_objects == {2: b} and not lb.pending_additions and not lb.pending_removals
