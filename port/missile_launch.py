"""The server's physics calls for a projectile: launch (Creature_Missile: GetProjectileVelocity, SetProjectilePhysicsState, LaunchProjectile; WorldObject_Magic: CalculateProjectileVelocity, LaunchSpellProjectiles; SpellProjectile.Setup), entering the world (Landblock.AddWorldObject, WorldObject.AddPhysicsObj, IsProjectileVisible) and the per-tick missile branch of WorldObject.UpdateObjectPhysics.

Harness glue, not ACE's physics: these are the calls ACE's WorldObject code makes on a projectile's
PhysicsObj, as the oracle's facade makes them (oracle/facade/Facade.cs), with everything else those
methods do (damage, broadcasts, chat, sounds, proc effects) left out because no physics reads it.
The projectile is a WorldObject of port/world_objects (Ammunition, Missile, SpellProjectile), whose
OnCollideObject / OnCollideEnvironment (ProjectileCollisionHelper, SpellProjectile.ProjectileImpact)
WeenieObject.DoCollision runs on a hit; its landblock a port/server_landblock.py Landblock. The
launcher and the target are given as their WorldObject (None for a static: it has none) and their
PhysicsObj. The solvers are ACE's own, ported in port/trajectory.py and port/trajectory2.py.

The WorldObject property setters ACE calls change the PhysicsState bits directly
(WorldObject.SetPhysicsState: ``State |= bit`` or ``State &= ~bit``), never through set_ethereal
or a PhysicsObj setter; so do these functions.
"""

from __future__ import annotations

import math

from acconform.flags import PhysicsState
from acconform.numerics import MONO, Runtime, Vector3, f32_from_bits, normalize

from .anchors import harness
from .constants import GRAVITY
from .entity_position import EntityPosition
from .frame import AFrame, Position
from .server_landblock import Landblock as ServerLandblock
from .world_objects import Creature, SpellProjectile, WorldObject
from .world_objects.spell_projectile import ARC, BLAST, BOLT, RING, STREAK, STRIKE, UNDEF, VOLLEY, WALL  # noqa: F401
from .trajectory import solve_ballistic_arc, solve_ballistic_arc_lateral, solve_ballistic_arc_moving
from .trajectory2 import calculate_trajectory
from .vec import zero_like

# WorldObject_Magic.cs: ProjHeight = 2.0f / 3.0f, ProjHeightArc = 5.0f / 6.0f (a spell's aim point up the target)
PROJ_HEIGHT = f32_from_bits(0x3F2AAAAB)
PROJ_HEIGHT_ARC = f32_from_bits(0x3F555555)
# Creature_Combat.cs GetAimHeight: 2.0f (a creature's; a player's at AttackHeight Medium)
AIM_HEIGHT = 2.0
# Creature.GetProjectileVelocity's gravity without gravity: 0.00001f
NO_GRAVITY = f32_from_bits(0x3727C5AC)
# WorldObject.ProjectileTimeout = 30.0f, stored in a double
PROJECTILE_TIMEOUT = 30.0


# ---------------------------------------------------------------- launch arithmetic


@harness("Creature.GetProjectileVelocity: which Trajectory solver a missile launch calls, and with what")
def get_projectile_velocity(origin: Vector3, dest: Vector3, speed, target_velocity: Vector3, use_gravity: bool = True,
                            lead_target: bool = True, alt_solver: bool = False, runtime: Runtime = MONO) -> tuple[Vector3, object]:
    """(velocity, time). `target_velocity` is the target PhysicsObj's CachedVelocity; `lead_target`
    false is a Player launcher without the LeadMissileTargets option (a monster always leads);
    `alt_solver` the server's trajectory_alt_solver property (false by default). Gravity is
    ``-PhysicsGlobals.Gravity`` (9.8f, positive down) or 0.00001f. `runtime`: the run's (its
    Math.Sin/Math.Cos, port/trajectory.py)."""
    s = type(speed)
    time = s(0.0)

    gravity = -s(GRAVITY) if use_gravity else s(NO_GRAVITY)

    if not target_velocity == zero_like(speed):
        if lead_target:
            # use movement quartic solver (ACE)
            if not alt_solver:
                num_solutions, s0, _, time = solve_ballistic_arc_moving(origin, speed, dest, target_velocity, gravity, runtime)

                if num_solutions > 0:
                    return s0, time
            else:
                return calculate_trajectory(origin, dest, target_velocity, speed, use_gravity, runtime), time

    # use stationary solver (ACE)
    if not alt_solver:
        _, s0, _, t0, _ = solve_ballistic_arc(origin, speed, dest, gravity, runtime)

        time = t0
        return s0, time
    else:
        return calculate_trajectory(origin, dest, zero_like(speed), speed, use_gravity, runtime), time


@harness("WorldObject.CalculateProjectileVelocity's solver for a spell projectile aimed at a target, from its start and end points")
def calculate_spell_projectile_velocity(start_pos: Vector3, end_pos: Vector3, speed, target_velocity: Vector3,
                                        spell_type: int, alt_solver: bool = False, runtime: Runtime = MONO) -> Vector3:
    """`target_velocity` is the target's CachedVelocity for a tracking spell, else zero. An Arc spell
    falls under PhysicsGlobals.Gravity; the others fly straight (``dir * speed``) unless the target
    moves."""
    s = type(speed)
    direction = normalize(end_pos - start_pos)

    zero = zero_like(speed)
    use_gravity = spell_type == ARC

    if use_gravity or not target_velocity == zero:
        gravity = s(GRAVITY) if use_gravity else s(0.0)

        if not alt_solver:
            _, velocity, _, _ = solve_ballistic_arc_lateral(start_pos, speed, end_pos, target_velocity, gravity)
        else:
            velocity = calculate_trajectory(start_pos, end_pos, target_velocity, speed, use_gravity, runtime)

        if velocity == zero and use_gravity and not target_velocity == zero:
            # intractable? try to solve w/ zero velocity (ACE)
            if not alt_solver:
                _, velocity, _, _ = solve_ballistic_arc_lateral(start_pos, speed, end_pos, zero, gravity)
            else:
                velocity = calculate_trajectory(start_pos, end_pos, zero, speed, use_gravity, runtime)
        if not velocity == zero:
            return velocity

    return direction * speed


# ---------------------------------------------------------------- launch: the physics state


def _set(obj, bit: int, value: bool) -> None:
    """WorldObject.SetPhysicsState(bit, value)."""
    if value:
        obj.state |= bit
    else:
        obj.state &= ~bit


@harness("Creature.SetProjectilePhysicsState's physics calls on an arrow's, bolt's or thrown weapon's PhysicsObj")
def set_projectile_physics_state(wo: WorldObject, target_obj, velocity: Vector3, origin: Vector3, orientation) -> None:
    """After InitPhysicsObj (the caller built the PhysicsObj as WorldObject.InitPhysicsObj does: a
    non-creature's makeObject(setup, guid, dynamic), set_object_guid, set_weenie_obj, SetMotionTableID,
    SetScaleStatic, State = the weenie's PhysicsState): ReportCollisions, Missile, AlignPath and
    PathClipped set, Ethereal and IgnoreCollisions cleared; Position.Frame = (origin, orientation)
    (Location's); Velocity assigned (the field, not set_velocity: no MaxVelocity clamp);
    PhysicsObj.ProjectileTarget = the target's PhysicsObj (`target_obj`); a RotationSpeed clears AlignPath
    and sets Omega = ((float)(2 pi RotationSpeed), 0, 0); set_active(true). Placement and
    CurrentMotionState are no physics."""
    obj = wo.physics_obj
    s = type(velocity.x)

    wo.report_collisions = True
    _set(obj, PhysicsState.ReportCollisions, True)
    _set(obj, PhysicsState.Missile, True)
    _set(obj, PhysicsState.AlignPath, True)
    _set(obj, PhysicsState.PathClipped, True)
    wo.ethereal = False
    _set(obj, PhysicsState.Ethereal, False)
    _set(obj, PhysicsState.IgnoreCollisions, False)

    obj.position.frame.origin = origin
    obj.position.frame.orientation = orientation

    obj.velocity = velocity
    obj.projectile_target = target_obj

    # projectiles with RotationSpeed get omega values and "align path" turned off (ACE)
    if (wo.rotation_speed or 0) != 0:
        _set(obj, PhysicsState.AlignPath, False)
        obj.omega = Vector3(s(math.pi * 2 * wo.rotation_speed), s(0.0), s(0.0))

    obj.set_active(True)


@harness("SpellProjectile.Setup's physics calls on a spell projectile's PhysicsObj (after InitPhysicsObj)")
def spell_projectile_setup(wo: SpellProjectile, rolling_death: bool = False, scripted_collision: bool | None = None) -> None:
    """ReportCollisions, Missile, AlignPath, PathClipped set, IgnoreCollisions cleared; Ethereal
    cleared unless the spell is Rolling Death; ScriptedCollision as `scripted_collision` (None leaves
    it: Setup clears it for some wall spells and Ring spells, Ring spell 3818 sets it); AllowEdgeSlide
    false clears EdgeSlide; a RotationSpeed clears AlignPath and sets Omega."""
    obj = wo.physics_obj
    s = type(obj.scale)

    wo.report_collisions = True
    _set(obj, PhysicsState.ReportCollisions, True)
    _set(obj, PhysicsState.Missile, True)
    _set(obj, PhysicsState.AlignPath, True)
    _set(obj, PhysicsState.PathClipped, True)
    _set(obj, PhysicsState.IgnoreCollisions, False)

    if not rolling_death:  # FIXME: use data here (ACE)
        wo.ethereal = False
        _set(obj, PhysicsState.Ethereal, False)

    if scripted_collision is not None:
        _set(obj, PhysicsState.ScriptedCollision, scripted_collision)

    _set(obj, PhysicsState.EdgeSlide, False)

    if (wo.rotation_speed or 0) != 0:
        _set(obj, PhysicsState.AlignPath, False)
        obj.omega = Vector3(s(math.pi * 2 * wo.rotation_speed), s(0.0), s(0.0))


@harness("LaunchSpellProjectiles' and SpellProjectile.SetProjectilePhysicsState's physics calls for one spell projectile")
def spell_projectile_set_physics_state(wo: SpellProjectile, target: WorldObject | None, target_obj, velocity: Vector3,
                                       origin: Vector3) -> None:
    """``sp.PhysicsObj.Velocity = velocity`` (a spread angle's rotation is the caller's), the heading:
    Position.Frame.set_vector_heading(Normalize(Velocity)), whose orientation becomes Location.Rotation;
    ProjectileTarget = `target`; then SetProjectilePhysicsState(target, useGravity): GravityStatus set for
    an Arc spell, Position.Frame = (Location.Pos, Location.Rotation), PhysicsObj.ProjectileTarget = the
    target's PhysicsObj when there is a target, set_active(true). `origin` is Location.Pos (the caster's
    position plus the rotated spawn offset). A static target has no WorldObject: `target` None and
    `target_obj` its PhysicsObj."""
    obj = wo.physics_obj

    obj.velocity = velocity

    # set orientation (ACE)
    obj.position.frame.set_vector_heading(normalize(obj.velocity))
    rotation = obj.position.frame.orientation

    wo.projectile_target = target

    # SpellProjectile.SetProjectilePhysicsState
    if wo.spell_type == ARC:
        _set(obj, PhysicsState.Gravity, True)

    obj.position.frame.origin = origin
    obj.position.frame.orientation = rotation

    if target_obj is not None:
        obj.projectile_target = target_obj

    obj.set_active(True)


# ---------------------------------------------------------------- entering the world


@harness("WorldObject.AddPhysicsObj: the projectile's PhysicsObj entered at its Location (enter_world, slide unless it has a ProjectileTarget)")
def add_physics_obj(wo: WorldObject, location: Position, lscape, trace=None) -> bool:
    """CurCell already set: false. LScape.get_landcell(Location.Cell) (none: DestroyObject,
    PhysicsObj = null, false); Position.ObjCellID = that cell's id; enter_world(Position(cell,
    Location's frame)); failing, or without a CurCell after: DestroyObject, PhysicsObj = null,
    false. AdjustDungeon (a dungeon's Location moved to the cell holding it) is the caller's, as
    place_mover's get_cell is."""
    obj = wo.physics_obj
    if obj.cur_cell is not None:
        return False

    cell = lscape.get_landcell(location.obj_cell_id)
    if cell is None:
        obj.destroy_object()
        wo.physics_obj = None
        return False

    obj.position.obj_cell_id = cell.id

    entry = Position(cell.id, AFrame(location.frame.origin, location.frame.orientation))

    success = obj.enter_world(entry, lscape, trace)

    if not success or obj.cur_cell is None:
        obj.destroy_object()
        wo.physics_obj = None
        return False

    return True


@harness("Landblock.AddWorldObject's physics: the projectile joins the landblock (CurrentLandblock), then AddPhysicsObj")
def add_world_object(wo: WorldObject, landblock, location: Position, lscape, trace=None) -> bool:
    """AddWorldObjectInternal: CurrentLandblock = the landblock before AddPhysicsObj (so a hit during
    enter_world finds it, but the landblock lists the object only after: RemoveWorldObject then
    returns without destroying); an object already holding a PhysicsObj is filed again
    (set_object_guid); failing, CurrentLandblock is cleared; succeeding, pendingAdditions holds it."""
    wo.current_landblock = landblock

    wo.physics_obj.set_object_guid(wo.guid)

    if wo.physics_obj.cur_cell is None:
        if not add_physics_obj(wo, location, lscape, trace):
            wo.current_landblock = None
            return False

    landblock.add_pending(wo)
    return True


@harness("WorldObject.IsProjectileVisible: the line-of-sight transition from the projectile back to its launcher's eye level")
def is_projectile_visible(launcher: WorldObject, launcher_obj, wo: WorldObject, lscape, trace=None) -> bool:
    """A launcher that is no Creature, or whose Ethereal property is true, sees every projectile.
    Otherwise: a transition of the projectile's PhysicsObj from its Position to the launcher's
    (`launcher_obj`), the launcher's raised by (launcher height - projectile height), with
    ProjectileTarget the launcher for the duration; visible when the transition is valid and the
    launcher is among its CollideObject."""
    if not isinstance(launcher, Creature) or (launcher.ethereal or False):
        return True

    proj = wo.physics_obj
    if launcher_obj is None or proj is None:
        return False

    start_pos = Position(proj.position.obj_cell_id, AFrame(proj.position.frame.origin, proj.position.frame.orientation))
    target_frame = launcher_obj.position.frame
    target_pos = Position(launcher_obj.position.obj_cell_id, AFrame(target_frame.origin, target_frame.orientation))

    # set to eye level (ACE)
    target_pos.frame.origin = target_pos.frame.origin.with_z(
        target_pos.frame.origin.z + (launcher_obj.get_height() - proj.get_height()))

    prev_target = proj.projectile_target
    proj.projectile_target = launcher_obj

    # perform line of sight test (ACE)
    transit, valid = proj.transition(start_pos, target_pos, False, lscape, trace)

    proj.projectile_target = prev_target

    if not valid:
        return False

    # check if target object was reached (ACE)
    return any(c.id == launcher_obj.id for c in transit.collision_info.collide_object)


@harness("Creature.LaunchProjectile's physics: SetProjectilePhysicsState, AddObject, IsProjectileVisible, and the Destroy of a failed launch")
def launch_projectile(wo: WorldObject, launcher: WorldObject, launcher_obj, target: WorldObject | None, target_obj,
                      origin: Vector3, orientation, landblock, cell_id: int, velocity: Vector3, lscape, trace=None) -> bool:
    """Whether the projectile is in flight after LaunchProjectile. An invalid velocity (a NaN
    component: the moving-target solver's NaN answers) misfires before anything is made. The
    projectile's Location is `cell_id` (projectile_location's) with Pos = `origin` and Rotation = orientation.
    ProjectileSource is the launcher, ProjectileTarget the target (None for a static)."""
    if math.isnan(velocity.x) or math.isnan(velocity.y) or math.isnan(velocity.z):
        return False  # YourAttackMisfired (ACE)

    wo.projectile_source = launcher
    wo.projectile_target = target

    set_projectile_physics_state(wo, target_obj, velocity, origin, orientation)

    location = Position(cell_id, AFrame(origin, orientation))
    success = add_world_object(wo, landblock, location, lscape, trace)

    if not success or wo.physics_obj is None:
        wo.destroy()
        return False

    if not is_projectile_visible(launcher, launcher_obj, wo, lscape, trace):
        wo.on_collide_environment()

        wo.destroy()
        return False

    return True


@harness("LaunchSpellProjectiles' entering of one spell projectile: AddObject, WorldEntryCollision, IsProjectileVisible")
def launch_spell_projectile(wo: SpellProjectile, caster: WorldObject, caster_obj, landblock, location: Position, lscape,
                            trace=None) -> bool:
    """After spell_projectile_setup and spell_projectile_set_physics_state. Whether the projectile
    is in flight: AddObject failing destroys it; a WorldEntryCollision (ProjectileImpact during
    enter_world) leaves it in the world, inactive; a projectile the caster cannot see hits the
    environment (ProjectileImpact)."""
    wo.projectile_source = caster

    if not add_world_object(wo, landblock, location, lscape, trace):
        wo.destroy()
        return False

    if wo.world_entry_collision:
        return False

    if not is_projectile_visible(caster, caster_obj, wo, lscape, trace):
        wo.on_collide_environment()
        return False

    return True


# ---------------------------------------------------------------- the tick


@harness("WorldObject.UpdateObjectPhysics for a projectile (not a Creature): the missile timeout, update_object, and the Destroy of one without a cell")
def update_object_physics(wo: WorldObject, lscape, trace=None) -> bool:
    """Returns ACE's landblockUpdate (the object's landblock changed); a projectile already hit or
    never active returns false before any physics. A missile (PhysicsState.Missile still set) runs
    every tick until 30 s after its creation (then set_active(false) and Destroy); once its Missile
    bit is gone it runs only while animating or in its first two updates. Left to the caller: a Ring
    spell's range check (ACE.Entity.Position.DistanceTo from SpawnPos, then set_active(false) and
    ProjectileImpact) and relocating to another landblock (a SpellProjectile entering a dormant one
    is destroyed)."""
    obj = wo.physics_obj
    if obj is None or not obj.is_active():
        return False

    if obj.state & PhysicsState.Missile:
        if wo.physics_creation_time + PROJECTILE_TIMEOUT <= obj.timer.current_time:
            obj.set_active(False)
            wo.destroy()
            return False
        # missiles always run an update (ACE)
    else:
        run_update = obj.is_animating or obj.initial_updates <= 1
        if not run_update:
            return False

    cell_before = obj.cur_cell.id if obj.cur_cell is not None else 0

    obj.update_object(lscape, trace)

    if obj.cur_cell is None:
        obj.set_active(False)
        wo.destroy()
        return False

    landblock_update = (cell_before >> 16) != (obj.cur_cell.id >> 16)

    return landblock_update


@harness("LandblockManager.RelocateObjectForPhysics(wo, adjacencyMove: true) for a projectile that changed landblocks: "
         "GetLandblock(id, true) on the scene's landblocks, the old block's RemoveWorldObjectForPhysics, the new block's AddWorldObjectForPhysics")
def relocate_object_for_physics(wo: WorldObject, landblocks: dict, lscape, trace=None) -> None:
    """After a tick's physics (LandblockManager.TickPhysics' movedObjects), for a projectile whose
    update_object_physics answered landblockUpdate; its Location's LandblockId is its CurCell's (UpdateObjectPhysics
    sets it). GetLandblock(Location.LandblockId, loadAdjacents: true) finds the new block loaded (the physics could
    reach its cell) and runs SetAdjacents(landblock, true, true), which gives its physics landblock its loaded
    neighbours anew; its loads of neighbours the scene lacks are left out, as the facade leaves them (a real DAT's
    landblock, with no server objects: what SetAdjacents would add is read only by ObjectMaint's visibility lists).
    IsDormant is never set in a scene, so a SpellProjectile is never destroyed here. Then the old block's
    RemoveWorldObjectForPhysics(Guid, adjacencyMove: true) (left in the world: no DestroyObject) and the new block's
    AddWorldObjectForPhysics: AddWorldObjectInternal, which finds its CurCell set (no AddPhysicsObj)."""
    old_block = wo.current_landblock
    cell_id = wo.physics_obj.cur_cell.id
    manager = lscape.landblock_manager
    server_block = manager.get_landblock(cell_id | 0xFFFF, None)  # loaded: no new Landblock
    manager.set_adjacents(server_block, True, True)
    new_block = landblocks.setdefault(cell_id >> 16, ServerLandblock(cell_id >> 16))

    # Remove from the old landblock -- force (ACE)
    if old_block is not None:
        old_block.remove_world_object(wo.guid, adjacency_move=True)
    # Add to the new landblock (ACE)
    frame = wo.physics_obj.position.frame
    add_world_object(wo, new_block, Position(cell_id, AFrame(frame.origin, frame.orientation)), lscape, trace)


# ---------------------------------------------------------------- a scene's launch


@harness("the projectile's Location: a copy of its launcher's (PhysicsObj.Position.ACEPosition()) with Pos moved to the spawn point")
def projectile_location(launcher_obj, origin: Vector3) -> EntityPosition:
    """Creature.LaunchProjectile's ``proj.Location = new Position(Location); proj.Location.Pos = origin`` and
    LaunchSpellProjectiles' ``sp.Location = new Position(casterLoc); sp.Location.Pos += offset`` (`origin` the
    sum): an ACE.Entity.Position of the launcher's cell and frame (its Location: SyncLocation keeps it its
    PhysicsObj's Position), whose Pos setter then finds the outdoor landblock and cell of the spawn point anew
    (port/entity_position.py). The projectile enters the world from that cell, at that Pos (moved onto another
    landblock, or clamped at the world's edge, when the spawn point lies past its launcher's landblock)."""
    frame = launcher_obj.position.frame
    location = EntityPosition(launcher_obj.position.obj_cell_id, frame.origin, frame.orientation)
    location.set_position(origin)
    return location


@harness("the server Landblock of the projectile's Location (LandblockManager.AddObject's GetLandblock): the scene's, or refused")
def location_landblock(location: EntityPosition, landblocks: dict, lscape):
    """LandblockManager.GetLandblock(Location.LandblockId) finds the scene's landblock in its table; one the scene
    lacks it would load from a cell DAT that has no such landblock: refused (NotSupportedException), as the facade
    refuses it. `landblocks`: the run's server Landblocks by landblock id, one made when first joined."""
    from .errors import NotSupportedException

    landblock_id = location.landblock_id >> 16
    if (location.landblock_id | 0xFFFF) not in lscape.records:
        raise NotSupportedException("acconform: a projectile's Location in a landblock the scene lacks "
                                    "(LandblockManager.GetLandblock would load it) is not modelled")
    # LandblockManager.AddObject: GetLandblock(Location.LandblockId, loadAdjacents: false) finds it loaded
    lscape.landblock_manager.get_landblock(location.landblock_id | 0xFFFF, None)  # loaded: no new Landblock
    return landblocks.setdefault(landblock_id, ServerLandblock(landblock_id))


@harness("a scene's projectile launch (scene/8 others[].launch), as the oracle's facade makes it: ACE's launch calls for an arrow or a spell")
def scene_launch(wo: WorldObject, launch, launcher_obj, target_obj, landblocks: dict, lscape, trace=None) -> bool:
    """`wo` is the projectile's WorldObject (Ammunition or SpellProjectile) holding its PhysicsObj as made;
    `launch` the scene's Launch; `launcher_obj` / `target_obj` the PhysicsObjs (their WorldObjects are their
    WeenieObjects'; a static's is none); `landblocks` the run's server Landblocks by id, which the projectile's
    Location's landblock joins (projectile_location: the launcher's Location, its PhysicsObj's Position, with Pos
    moved to the spawn point, which finds its own outdoor landblock and cell). The WorldObject is made
    now (physicsCreationTime: the clock now). An arrow: CalculateProjectileVelocity's aim (the target's
    origin raised by Height / GetAimHeight) and GetProjectileVelocity from `origin`, then LaunchProjectile. A
    spell: CalculateProjectileVelocity's aim (raised by Height * ProjHeight or ProjHeightArc) and solver, then
    Setup, the physics state and LaunchSpellProjectiles' AddObject. A launcher and target in different
    landblocks would need ACE.Entity.Position.ToGlobal: refused (NotSupportedException), as the facade
    refuses it. A spell with no target (`target_obj` None): CalculateProjectileVelocity's arm for none (the
    launcher has no AttackTarget), along the launcher's forward vector, Vector3.Transform(UnitY, its orientation)
    * speed; no ProjectileTarget."""
    from .errors import NotSupportedException
    from .world_objects import Player

    mode = lscape.mode
    runtime = mode.runtime
    obj = wo.physics_obj
    s = type(obj.scale)

    if target_obj is not None and launcher_obj.position.landblock != target_obj.position.landblock:
        raise NotSupportedException("acconform: a launch across landblocks (ACE.Entity.Position.ToGlobal) is not modelled")

    wo.physics_creation_time = obj.timer.current_time

    launcher = launcher_obj.weenie_obj.world_object
    target = target_obj.weenie_obj.world_object if target_obj is not None else None
    speed = s(launch.speed)
    origin = mode.vec(*launch.origin)
    location = projectile_location(launcher_obj, origin)
    landblock = location_landblock(location, landblocks, lscape)

    # what SpellProjectile.Setup does to ScriptedCollision for the scene's spell kind: a wall spell's weenie (7278,
    # 7281, 7282, 23144) clears it; SpellType Ring sets it for spell 3818, else clears it; otherwise left (None)
    scripted_collision = None
    if isinstance(wo, SpellProjectile):
        if wo.spell_type == RING:
            scripted_collision = launch.spell == "ring_3818"
        elif launch.spell == "wall":
            scripted_collision = False

    if isinstance(wo, SpellProjectile) and target_obj is None:
        # launch along forward vector (casterLoc.Rotation: the launcher's Location, its PhysicsObj's Position)
        unit_y = mode.vec(0.0, 1.0, 0.0)
        velocity = runtime.transform_by_quaternion(unit_y, launcher_obj.position.frame.orientation) * speed
        spell_projectile_setup(wo, launch.spell == "rolling_death", scripted_collision)
        spell_projectile_set_physics_state(wo, None, None, velocity, location.pos)
        entry = Position(location.landblock_id, AFrame(location.pos, obj.position.frame.orientation))
        return launch_spell_projectile(wo, launcher, launcher_obj, landblock, entry, lscape, trace)

    end_pos = target_obj.position.frame.origin
    height = target_obj.get_height()
    if isinstance(wo, SpellProjectile):
        end_pos = end_pos.with_z(end_pos.z + height * (s(PROJ_HEIGHT_ARC) if launch.arc else s(PROJ_HEIGHT)))
        target_velocity = target_obj.cached_velocity if launch.tracking else zero_like(speed)
        velocity = calculate_spell_projectile_velocity(origin, end_pos, speed, target_velocity, wo.spell_type,
                                                       launch.alt_solver, runtime)
        spell_projectile_setup(wo, launch.spell == "rolling_death", scripted_collision)
        spell_projectile_set_physics_state(wo, target, target_obj, velocity, location.pos)
        entry = Position(location.landblock_id, AFrame(location.pos, obj.position.frame.orientation))
        return launch_spell_projectile(wo, launcher, launcher_obj, landblock, entry, lscape, trace)

    end_pos = end_pos.with_z(end_pos.z + height / s(AIM_HEIGHT))
    lead = launch.lead_target or not isinstance(launcher, Player)
    velocity, _ = get_projectile_velocity(origin, end_pos, speed, target_obj.cached_velocity, True, lead, launch.alt_solver,
                                          runtime)
    w, x, y, z = launch.orientation  # written (w, x, y, z), as a scene's frames are
    orientation = mode.quat(x, y, z, w)
    return launch_projectile(wo, launcher, launcher_obj, target, target_obj, location.pos, orientation, landblock,
                             location.landblock_id, velocity, lscape, trace)
