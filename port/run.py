"""run_scene: one scene through the port's PhysicsObj.transition, read back as an Outcome.

The world (LScape) and the mover (PhysicsObj) are built from the scene the way the oracle builds
ACE's; the outcome reads the same fields the oracle reads. A Python exception inside the port
becomes ``Outcome(error=...)``: a verdict, not a crash. An AceException (port/errors.py: where
ACE itself throws) reads ``"<.NET type>: <message>"``, as the oracle formats ACE's exceptions.
Static objects are built from the DAT records acconform/dat.py writes (read by port/dat/) with
ACE's constructors and placed by ACE's placement chain (add_obj_to_cell), as the oracle does with
ACE's own code: an outdoor static by Landblock.init_static_objs' steps here, a static inside an
EnvCell by ACE's EnvCell.init_static_objects when the cell loads (LScape.get_landcell -> PostInit),
from the stabs of the cell's DAT record. The run's portal DAT and cell DAT (port/dat/portal_dat.py,
cell_dat.py) hold the records dat.py writes and are handed to the LScape (`lscape.portal_dat`,
`lscape.cell_dat`), where DBObj reads them. The mover is made by ACE's makeObject from its own records (dat.mover_records)
with the id acconform.staging.MOVER_ID. Given a request's DAT records instead (the protocol's feature
`dat`: an acconform.dat.DatWorld), the world is built from them alone: the DATs hold the request's
records, the landblocks are its CellLandblocks (read through the cell DAT), the statics and the mover
are the request's (`dat_landscape`); of the scene only its engine mode and ticks are read. Pass a ``collections.Counter`` as
`trace` to count the branches the run took (names in acconform.port.transition.branches); a
branches.Trace carrying a tracing.Recorder gets a trace of snapshots too (`traced_run` wraps the
routines for that run).
"""

from __future__ import annotations

import gc
from dataclasses import dataclass, replace

import numpy as np

from acconform.flags import PhysicsState, SetPositionError, TransientState
from acconform.numerics import Plane, get_mode
from acconform.outcome import (AttackFrameState, CollisionState, CommandState, ContactPlaneState, MotionAnswerState,
                               MotionTickState, NormalState, Outcome, PlacementState, PlaneState, TickState)
from acconform import dat, deep
from acconform.staging import MOVER_ID
from acconform.scene import ENV_CELL_FIRST, NO_TERRAIN, Landblock, OtherMover, Scene, StaticObject

from .anchors import anchor, harness
from .constants import BLOCK_LENGTH, CELL_LENGTH
from .errors import AceException, NullReferenceException
from .dat.cell_dat import CellDat
from .dat.portal_dat import PortalDat
from .frame import AFrame, Position
from . import db_obj, land_defs, parenting
from .land.lscape import LScape
from .physics_obj import PhysicsObj
from .physics_timer import PhysicsTimer
from .weenie_object import WeenieObject
from .world_objects import Ammunition, Creature, GenericObject, Missile, Player, SpellProjectile
from .world_objects.spell_projectile import ARC, BOLT, RING, WALL
from . import missile_launch
from . import transition as _transition  # noqa: F401  (gives LandCell its collision methods)
from .transition.branches import Trace

# the mover's PhysicsObj.ID, as the oracle's: player range, so PhysicsObj.IsPlayer is true


def _vec(v) -> tuple[float, float, float]:
    return (float(v.x), float(v.y), float(v.z))


def _plane_state(valid: bool, cell: int, is_water: bool, plane: Plane) -> ContactPlaneState:
    return ContactPlaneState(bool(valid), int(cell), bool(is_water), _vec(plane.normal), float(plane.d))


@harness("builds the mover from its DAT records and the scene, as the oracle's facade does")
def build_mover(m, did: int, obj_id: int, portal_dat: PortalDat, lscape: LScape) -> PhysicsObj:
    """The mover as the oracle builds it (docs/oracle.md's audit): a player's PhysicsObj as
    WorldObject.InitPhysicsObj makes a Creature's -- ``new PhysicsObj()``, makeAnimObject(did) over
    dat.mover_records (its Setup: its spheres and step heights, one empty mesh part),
    set_object_guid(obj_id), set_weenie_obj(the WeenieObject of its Player: its PlayerKillerStatus and skills), SetMotionTableID(its motion
    table: the one its Setup names, acconform.motion_scene.MOTION_TABLE_ID, or 0),
    SetScaleStatic(scale), State -- then TransientState, Velocity, the contact plane (and its cell) and
    the sliding normal as `m` gives them (the scene's Mover, or a request's dat.DatMover), Position =
    begin, CurCell = the begin cell. It is not entered in any cell. With a placement, Position and
    CurCell stay as the constructor left them: `place_mover` places it."""
    mode = lscape.mode
    s = mode.scalar
    obj = PhysicsObj.create(mode, portal_dat.timer, portal_dat.server, portal_dat.server_objects)
    obj.make_anim_object(did, True, portal_dat)
    obj.set_object_guid(obj_id)
    obj.set_weenie_obj(WeenieObject.of(Player.of_skills(obj_id, m.player_killer_status, m.skills)))
    obj.set_motion_table_id(m.motion_table_id)
    obj.set_scale_static(s(m.scale))
    obj.state = m.state
    obj.transient_state = m.transient_state
    obj.velocity = mode.vec(*m.velocity)
    if m.contact_plane is not None:
        obj.contact_plane = Plane(mode.vec(*m.contact_plane.plane.normal), s(m.contact_plane.plane.d))
        obj.contact_plane_cell_id = m.contact_plane.cell
    if m.sliding_normal is not None:
        obj.sliding_normal = mode.vec(*m.sliding_normal)
    if m.placement is None:
        obj.position = Position.from_record(m.begin, mode)
        obj.cur_cell = lscape.get_landcell(m.begin.cell)
    return obj


@harness("builds another mover and enters it into the world, as the oracle's facade does (WorldObject.InitPhysicsObj, AddPhysicsObj)")
def build_other(o: OtherMover, did: int, portal_dat: PortalDat, lscape: LScape, trace,
                holders=None) -> tuple[PhysicsObj, PlacementState, bool]:
    """WorldObject.InitPhysicsObj for the other mover's WorldObject (acconform.scene.OtherMover): a
    creature's PhysicsObj by ``new PhysicsObj()`` and makeAnimObject(did, true), a GenericObject's by
    makeObject(did, id, true) (dynamic); set_object_guid(id), set_weenie_obj(new WeenieObject(the
    WorldObject)), SetMotionTableID(its MotionTableId: 0, or scene/8's others[].motion_table), SetScaleStatic(scale), State; then TransientState and Velocity as
    the scene gives them, and AddPhysicsObj's physics calls: LScape.get_landcell of the begin cell,
    Position.ObjCellID = its id, enter_world(Position(cell, frame)). Returns the object, its placement
    and whether it is in the world (AddPhysicsObj's success: entered and in a cell); one that is not
    keeps its PhysicsObj as enter_world left it and no tick steps it (a server's landblock ticks no
    WorldObject without a PhysicsObj). A child (`o.parent`) is held instead by its parent, found in `holders`
    (id -> PhysicsObj: the mover and the others made before it), as the client parents a wielded item
    (parenting.set_parent: SetPlacementFrame, set_parent); its placement's result is set_parent's answer and it is
    never in the world itself (no tick steps it: its parent's UpdateChild carries it)."""
    mode = lscape.mode
    if o.weenie in ("object", "ammunition", "spell_projectile", "missile"):
        obj = PhysicsObj.make_object(did, o.id, True, portal_dat)
    else:
        obj = PhysicsObj.create(mode, portal_dat.timer, portal_dat.server, portal_dat.server_objects)
        obj.make_anim_object(did, True, portal_dat)
    obj.set_object_guid(o.id)
    wo = world_object_of(o)
    obj.set_weenie_obj(WeenieObject.of(wo))
    obj.set_motion_table_id(o.motion_table_id)  # its WorldObject's MotionTableId (scene/8 others[].motion_table), else 0
    obj.set_scale_static(mode.scalar(o.scale))
    obj.state = o.state
    obj.transient_state = o.transient_state
    obj.velocity = mode.vec(*o.velocity)
    if o.parent is not None:
        held = parenting.hold_child(obj, holders[o.parent.id], o.parent, lscape)
        return obj, _placement_state(obj, SetPositionError.OK if held else SetPositionError.GeneralFailure), False
    if getattr(o, "launch", None) is not None:
        # a projectile: made, not entered; its launch puts it in the world (run_ticks)
        wo.physics_obj = obj
        return obj, _placement_state(obj, SetPositionError.GeneralFailure), False
    cell = lscape.get_landcell(o.begin.cell)
    entered = False
    if cell is not None:
        obj.position.obj_cell_id = cell.id
        begin = Position.from_record(o.begin, mode)
        entered = obj.enter_world(Position(cell.id, AFrame(begin.frame.origin, begin.frame.orientation)), lscape, trace) \
            and obj.cur_cell is not None
    return obj, _placement_state(obj, SetPositionError.OK if entered else SetPositionError.GeneralFailure), entered


@harness("the server WorldObject another mover's PhysicsObj is made for (a Player, a Creature, a GenericObject, an Ammunition, a SpellProjectile or a Missile)")
def world_object_of(o: OtherMover):
    """The server's WorldObject for another mover: a Player, a Creature, a GenericObject, or a projectile's Ammunition,
    SpellProjectile (a Bolt, an Arc, or a Wall or Ring spell's) or Missile (a thrown weapon). A monster is a Creature
    with IsMonster (Creature.SetMonsterState: Attackable, ACE's default for an object without the property); an NPC
    one that is not Attackable, so not a monster. A projectile's RotationSpeed is its launch's (0: none, ACE's null);
    the ReportCollisions property the scene's (None: unset), which a weenie may carry."""
    if o.weenie == "player":
        wo = Player(guid=o.id, player_killer_status=o.player_killer_status)
    elif o.weenie == "object":
        wo = GenericObject(guid=o.id)
    elif o.weenie == "ammunition":
        wo = Ammunition(guid=o.id, rotation_speed=o.launch.rotation_speed or None)
    elif o.weenie == "missile":  # a thrown weapon
        wo = Missile(guid=o.id, rotation_speed=o.launch.rotation_speed or None)
    elif o.weenie == "spell_projectile":
        kind = o.launch.spell
        spell_type = WALL if kind == "wall" else RING if kind in ("ring", "ring_3818") else ARC if o.launch.arc else BOLT
        wo = SpellProjectile(guid=o.id, spell_type=spell_type, rotation_speed=o.launch.rotation_speed or None)
    else:
        monster = o.weenie == "monster"
        wo = Creature(guid=o.id, is_monster=monster, attackable=monster, player_killer_status=o.player_killer_status)
    if o.report_collisions is not None:
        wo.report_collisions = o.report_collisions
    return wo


def _placement_state(mover: PhysicsObj, result) -> PlacementState:
    q = mover.position.frame.orientation
    return PlacementState(
        result=int(result),
        cell=int(mover.position.obj_cell_id),
        origin=_vec(mover.position.frame.origin),
        orientation=(float(q.w), float(q.x), float(q.y), float(q.z)),
        cur_cell=mover.cur_cell.id if mover.cur_cell is not None else 0,
        transient_state=int(mover.transient_state),
        shadow_cells=tuple(mover.shadow_objects),
    )


@harness("places the mover as the oracle's facade does: WorldObject.AddPhysicsObj's physics calls and enter_world, or PhysicsObj.SetPosition")
def place_mover(m, mover: PhysicsObj, lscape: LScape, trace) -> PlacementState:
    """The begin position (its cell id first replaced by Position.GetCell when the placement asks, as
    WorldObject.AdjustDungeon does), then, via enter_world, WorldObject.AddPhysicsObj's physics calls:
    LScape.get_landcell of its cell (none: not entered, GeneralFailure), Position.ObjCellID = that
    cell's id, enter_world(Position(cell, frame)), whose bool is the result (OK or GeneralFailure);
    via set_position, PhysicsObj.SetPosition with the placement's flags (docs/oracle.md's audit).
    `m` is the mover's record (the scene's Mover, or a request's dat.DatMover)."""
    mode = lscape.mode
    placement = m.placement
    pos = Position.from_record(m.begin, mode)
    if placement.get_cell:
        pos.obj_cell_id = pos.get_cell(pos.obj_cell_id, mode.runtime, lscape)

    if placement.via == "enter_world":
        cell = lscape.get_landcell(pos.obj_cell_id)
        if cell is None:
            result = SetPositionError.GeneralFailure
        else:
            mover.position.obj_cell_id = cell.id
            location = Position(cell.id, AFrame(pos.frame.origin, pos.frame.orientation))
            result = SetPositionError.OK if mover.enter_world(location, lscape, trace) else SetPositionError.GeneralFailure
    else:
        result = mover.set_position(pos, placement.flags, lscape, trace)
    return _placement_state(mover, result)


@harness("the run's portal DAT: every record acconform/dat.py writes for the scene's objects, mover, Environments and buildings, and each static's did")
def portal_dat_for(scene: Scene, mode, timer: PhysicsTimer | None = None) -> tuple[PortalDat, list[int]]:
    """The PortalDat (carrying the run's clock `timer`) and, per static object in scene order, the
    id makeObject takes."""
    written = dat.scene_records(scene)
    records = {r.id: r.data for r in written.mover.records}
    for static in written.statics:
        for dat_record in static.records:
            records[dat_record.id] = dat_record.data
    for dat_record in written.portal:
        records[dat_record.id] = dat_record.data
    for other in written.others:
        for dat_record in other.records:
            records[dat_record.id] = dat_record.data
    return PortalDat(records, mode, scene.engine_mode == "server", timer), [static.did for static in written.statics]


@harness("the run's cell DAT: the EnvCell and LandblockInfo records acconform/dat.py writes for the scene")
def cell_dat_for(scene: Scene, mode) -> CellDat:
    return CellDat({r.id: r.data for r in dat.scene_records(scene).cell}, mode)


@harness("the run's world: its portal and cell DATs and the LScape that reads them (release it after)")
def scene_world(scene: Scene, mode, timer: PhysicsTimer | None = None) -> tuple[LScape, PortalDat, list[int]]:
    """(the LScape, the portal DAT, each static's did): a landblock with buildings reads both DATs
    when it is built, so anything that builds the scene's landblocks starts here."""
    portal_dat, dids = portal_dat_for(scene, mode, timer)
    return LScape(scene, mode, portal_dat, cell_dat_for(scene, mode)), portal_dat, dids


@dataclass(frozen=True, slots=True)
class _Land:
    """What an LScape reads of its world: the landblocks and the land height table."""

    landblocks: tuple
    land_height_table: tuple


@harness("the run's world from a request's DAT records (the protocol's feature dat): its DATs, and an LScape of its CellLandblocks")
def dat_landscape(world: dat.DatWorld, server: bool, mode, timer: PhysicsTimer) -> tuple[LScape, PortalDat]:
    """(the LScape, the portal DAT) from the request's records alone: the portal and cell DATs hold
    them, the landblocks are the CellLandblocks in `cell` order, read through the cell DAT
    (DBObj.GetCellLandblock), with HasObjects as they say and the request's land height table. A
    CellLandblock of 81 zero heights and terrain words (a dungeon's) is a landblock without terrain,
    as the scene's record reads (its terrain is built when first read)."""
    portal_dat = PortalDat({r.id: r.data for r in world.portal}, mode, server, timer)
    cell_dat = CellDat({r.id: r.data for r in world.cell}, mode)
    landblocks, with_objects = [], set()
    for record in world.cell:
        if record.kind != "CellLandblock":
            continue
        c = db_obj.get_cell_landblock(cell_dat, record.id)
        heights, terrain = tuple(c.height), tuple(c.terrain)
        landblocks.append(Landblock(c.id, heights, terrain) if heights != NO_TERRAIN or terrain != NO_TERRAIN
                          else Landblock(c.id, has_terrain=False))
        if c.has_objects:
            with_objects.add(c.id | 0xFFFF)
    land = _Land(tuple(landblocks), world.land_height_table)
    return LScape(land, mode, portal_dat, cell_dat, with_objects), portal_dat


@harness("reads a static's cells: an outdoor static's ShadowObjects, or, for a static in an EnvCell, those of the object its loaded cell made from the static's did")
def static_cells(record: StaticObject, did: int, obj: PhysicsObj | None, lscape: LScape) -> tuple[int, ...]:
    """What the oracle reads: the ShadowObjects keys, in order, of the static's PhysicsObj. A static
    in an EnvCell is made by ACE when the cell loads (EnvCell.init_static_objects, id 0): it is the
    object of that cell's StaticObjects whose PartArray.GetDataID is the static's did; () when the
    cell was never loaded or ACE dropped the object."""
    if record.position.cell & 0xFFFF < ENV_CELL_FIRST:
        return tuple(obj.shadow_objects) if obj is not None else ()
    landblock = lscape.landblocks.get(record.position.cell | 0xFFFF)
    cell = landblock.land_cells.get(record.position.cell & 0xFFFF) if landblock is not None else None
    for made in (cell.static_objects or ()) if cell is not None else ():
        if made.part_array is not None and made.part_array.get_data_id() == did:
            return tuple(made.shadow_objects)
    return ()


@harness("builds and places a static object from its DAT records, as the oracle's facade does (init_static_objs)")
def build_static(record: StaticObject, did: int, portal_dat: PortalDat, lscape: LScape) -> PhysicsObj | None:
    """The static as the oracle builds it (docs/oracle.md's audit): ``makeObject(did, scene id,
    false)`` over the records dat.py wrote; set_object_guid(scene id) (WorldObject.InitPhysicsObj's:
    the run's ServerObjectManager files it); SetScaleStatic(scene scale); State = the scene's
    flags (as WorldObject.InitPhysicsObj overwrites it); DatObject = true; then
    Landblock.init_static_objs' placement: a Position in the landblock's 0xXXYYFFFF id with the
    scene's frame, LandDefs.AdjustToOutside, the landblock's get_landcell, and add_obj_to_cell.
    None when the landblock has no such cell (ACE drops the object)."""
    mode = lscape.mode
    obj = PhysicsObj.make_object(did, record.id, False, portal_dat)
    obj.set_object_guid(record.id)  # ServerObjectManager files it: a MoveTo's target is found there
    obj.set_scale_static(mode.scalar(record.scale))
    obj.state = record.state
    obj.dat_object = True
    landblock = lscape.get_landblock(record.position.cell)
    position = Position((record.position.cell & 0xFFFF0000) | 0xFFFF, AFrame.from_record(record.position.frame, mode))
    land_defs.adjust_to_outside_pos(position)
    cell = landblock.get_landcell(position.obj_cell_id)
    if cell is None:
        return None
    obj.add_obj_to_cell(cell, position.frame, lscape)
    return obj


@harness("counts the cell_border and landblock_border boundaries where a transition ends")
def border_boundaries(origin, trace: Trace) -> None:
    """A block-local end x or y exactly on a cell border (a multiple of 24 m; 0 and 192 are
    landblock borders too)."""
    for c in (float(origin.x), float(origin.y)):
        if c % CELL_LENGTH == 0.0:
            trace["boundary:cell_border"] += 1
            if c % BLOCK_LENGTH == 0.0:
                trace["boundary:landblock_border"] += 1


@anchor(None, "PhysicsObj.cs:transition", "the scene -> outcome driver around PhysicsObj.transition")
def run_scene(scene: Scene, mode: str = "exact", trace=None, runtime: str = "mono", world: dat.DatWorld | None = None) -> Outcome:
    """Run the scene's transition in the port, computing as ACE on `runtime` ("mono" or "coreclr",
    .NET 10) does; `trace` (a Counter, or a branches.Trace to keep the closest approach to each
    boundary too) is incremented in place. `world`: a request's DAT records (feature `dat`), to build
    the world from instead of the scene."""
    if trace is not None and not isinstance(trace, Trace):
        into, trace = trace, Trace()
        try:
            return run_scene(scene, mode, trace, runtime, world)
        finally:
            into.update(trace)
    numerics = get_mode(mode, runtime)  # an unknown mode or runtime is misuse, not a verdict
    try:
        try:
            return _run_quietly(scene, numerics, trace, world)
        except RecursionError:  # a BSP deeper than Python's default stack allows: again on a deep one
            if trace is not None:
                trace.clear()
                trace.closest.clear()
                if trace.recorder is not None:
                    trace.recorder.clear()
            return deep.call(_run_quietly, scene, numerics, trace, world, frames=deep.RUN_FRAMES)
    except deep.TooDeep:
        raise  # deeper than the harness runs anything: misuse (exit 2), not a verdict
    except Exception as e:
        return Outcome(error=verdict(e))
    finally:
        # A run's world holds cycles (a cell and its landblock, a PhysicsObj and its PartArray), so
        # only the collector frees it. Collected as the run ends, it is freed young, in one pass;
        # left to the thresholds, the collector walks it while it is alive, promotes it and walks
        # it again later: runs took 7-20% longer (corpus scenes of four kinds, under campaign_gc).
        if gc.isenabled():
            gc.collect(1)


@harness("runs a scene with tracing on: its outcome and its trace records (acconform.trace)")
def traced_run(scene: Scene, mode: str = "exact", runtime: str = "mono"):
    from .tracing import Recorder, installed

    trace = Trace(Recorder())
    with installed(trace.recorder):  # the routines wrapped for this run only
        outcome = run_scene(scene, mode, trace, runtime)
    return outcome, tuple(trace.recorder.records)


@harness("the routines a traced run records at enter, exit or call: every anchored ACE method")
def traced_anchors() -> frozenset:
    from .anchors import load_all

    return frozenset(a.ace for a in load_all().values())


@harness("an exception in the port as an outcome's error string, as the oracle reports ACE's")
def verdict(e: Exception) -> str:
    """Where ACE throws (an AceException): ``"<.NET type>: <message>"``; a member of None is where C#
    meets null (e.g. a missing BSP child): NullReferenceException; any other port exception is a
    verdict too (a port bug or gap), under its Python type."""
    if isinstance(e, AceException):
        return e.verdict()
    if isinstance(e, AttributeError) and e.obj is None:
        return NullReferenceException.from_none(e).verdict()
    return f"{type(e).__name__}: {e}"


def _run_quietly(scene: Scene, mode, trace, world: dat.DatWorld | None) -> Outcome:
    with np.errstate(all="ignore"):  # IEEE results (inf, NaN) are C#'s too; no warnings
        return _run(scene, mode, trace, world)


def _run(scene: Scene, mode, trace, world: dat.DatWorld | None) -> Outcome:
    # the clock: at the tick scene's start before anything is made (PhysicsObj() reads it)
    timer = PhysicsTimer(scene.ticks.start if scene.ticks is not None else 0.0)
    if world is None:
        lscape, portal_dat, dids = scene_world(scene, mode, timer)
        objects, mover, mover_did, mover_id = scene.objects, scene.mover, dat.MOVER_SETUP_ID, MOVER_ID
        others = tuple(zip(scene.others, (r.did for r in dat.scene_records(scene).others)))
    else:
        lscape, portal_dat = dat_landscape(world, scene.engine_mode == "server", mode, timer)
        objects, dids = world.statics, [s.did for s in world.statics]
        mover, mover_did, mover_id = world.mover, world.mover.did, world.mover.id
        others = tuple((o, o.did) for o in world.others)
    try:
        return _run_in(scene, mode, trace, lscape, timer, portal_dat, objects, dids, mover, mover_did, mover_id, others)
    finally:
        lscape.release()


def _run_in(scene: Scene, mode, trace, lscape: LScape, timer: PhysicsTimer, portal_dat: PortalDat, objects, dids,
            m, mover_did: int, mover_id: int, others=()) -> Outcome:
    """`objects`: the statics (the scene's, or a request's dat.DatStatic records) and `dids` the ids
    makeObject takes for them; `m` the mover's record (the scene's Mover, or a dat.DatMover); `others`
    (record, Setup id) per other mover (the scene's OtherMover, or a dat.DatOther)."""
    statics = [build_static(record, did, portal_dat, lscape) if record.position.cell & 0xFFFF < ENV_CELL_FIRST else None
               for record, did in zip(objects, dids)]
    mover = build_mover(m, mover_did, mover_id, portal_dat, lscape)
    placement = None
    if m.placement is not None:
        placement = place_mover(m, mover, lscape, trace)
    holders = {mover_id: mover}  # a child's parent: the mover or an other made before it
    movers = []
    for o, did in others:
        movers.append(build_other(o, did, portal_dat, lscape, trace, holders))
        holders[o.id] = movers[-1][0]
    other_placements = tuple(p for _, p, _ in movers) if others else None
    if scene.ticks is not None:
        ticks = run_ticks(scene, mover, timer, lscape, trace, movers, tuple(o for o, _ in others), statics)
        answers = motion_answers(scene, portal_dat) if scene.motion_queries else None
        return Outcome(placement=placement, ticks=ticks, other_placements=other_placements, motion_answers=answers,
                       static_cells=tuple(static_cells(record, did, obj, lscape)
                                          for record, did, obj in zip(objects, dids, statics)))
    if placement is not None:
        if mover.cur_cell is None:  # placed in no cell: no transition (the oracle writes the same record)
            return Outcome(velocity=_vec(mover.velocity), placement=placement, other_placements=other_placements,
                           static_cells=tuple(static_cells(record, did, obj, lscape)
                                              for record, did, obj in zip(objects, dids, statics)))
    old_pos = mover.position.copy()
    new_pos = Position.from_record(m.end, mode)
    trans, ok = mover.transition(old_pos, new_pos, False, lscape, trace)
    if trace is not None:
        border_boundaries(trans.sphere_path.cur_pos.frame.origin, trace)

    sp = trans.sphere_path
    ci = trans.collision_info
    q = sp.cur_pos.frame.orientation
    return Outcome(
        ok=bool(ok),
        cell=sp.cur_cell.id if sp.cur_cell is not None else 0,
        origin=_vec(sp.cur_pos.frame.origin),
        orientation=(float(q.w), float(q.x), float(q.y), float(q.z)),
        object_info_state=int(trans.object_info.state),
        contact_plane=_plane_state(ci.contact_plane_valid, ci.contact_plane_cell_id, ci.contact_plane_is_water,
                                   ci.contact_plane),
        last_known_contact_plane=_plane_state(ci.last_known_contact_plane_valid, ci.last_known_contact_plane_cell_id,
                                              ci.last_known_contact_plane_is_water, ci.last_known_contact_plane),
        collision_normal=NormalState(bool(ci.collision_normal_valid), _vec(ci.collision_normal)),
        sliding_normal=NormalState(bool(ci.sliding_normal_valid), _vec(ci.sliding_normal)),
        collided_with_environment=bool(ci.collided_with_environment),
        frames_stationary_fall=int(ci.frames_stationary_fall),
        velocity=_vec(mover.velocity),
        check_cell=sp.check_cell.id if sp.check_cell is not None else 0,
        walkable=sp.walkable is not None,
        step_up=bool(sp.step_up),
        neg_poly_hit=bool(sp.neg_poly_hit),
        static_cells=tuple(static_cells(record, did, obj, lscape)
                           for record, did, obj in zip(objects, dids, statics)),
        placement=placement,
        other_placements=other_placements,
    )


# ---------------------------------------------------------------- motion queries


@harness("asks the scene's motion_queries of the mover's motion table after the last tick, as a server's WorldObjects "
         "ask them (the ported statics and DatLoader methods), each answer or what it threw")
def motion_answers(scene: Scene, portal_dat: PortalDat) -> tuple:
    """The scene's MotionTableId (the mover's table, or 0) and the run's PortalDat, whose RunSpeed, TurnSpeed and
    attack-frame caches ACE keeps for the process: a scene is a fresh server's, so they start empty and are shared by
    the scene's queries in order."""
    from .animation.motion_table import MotionTable
    from .dat.motion_table import MotionTable as DatMotionTable

    table_id = scene.mover.motion_table_id
    scalar = portal_dat.mode.scalar
    out = []
    for q in scene.motion_queries:
        speed = None if q.speed is None else scalar(q.speed)
        try:
            if q.function == "GetAttackFrames":
                frames = MotionTable.get_attack_frames(table_id, q.stance, q.motion, portal_dat)
                out.append(MotionAnswerState(attack_frames=tuple(_attack_frame(t, h) for t, h in frames)))
                continue
            if q.function == "GetAnimationLength":
                v = (MotionTable.get_animation_length(table_id, q.stance, q.motion, portal_dat, speed)
                     if q.current_motion is None else
                     MotionTable.get_animation_length_from(table_id, q.stance, q.current_motion, q.motion, portal_dat, speed))
            elif q.function == "GetRunSpeed":
                v = MotionTable.get_run_speed(table_id, portal_dat)
            elif q.function == "GetTurnSpeed":
                v = MotionTable.get_turn_speed(table_id, portal_dat)
            else:  # Dat.GetAnimationLength: DatManager.PortalDat.ReadFromDat<MotionTable>(MotionTableId), then its overload
                table = portal_dat.read_from_dat(table_id, DatMotionTable)
                v = (table.get_animation_length_of_motion(q.motion, portal_dat) if q.current_motion is None else
                     table.get_animation_length(q.stance, q.motion, q.current_motion, portal_dat))
            out.append(MotionAnswerState(value=float(v)))
        except Exception as e:
            out.append(MotionAnswerState(error=verdict(e)))
    return tuple(out)


def _attack_frame(time, hook) -> AttackFrameState:
    c = hook.attack_cone
    return AttackFrameState(float(time), int(hook.direction), int(c.part_index), float(c.left_x), float(c.left_y),
                            float(c.right_x), float(c.right_y), float(c.radius), float(c.height))


# ---------------------------------------------------------------- tick scenes


@anchor(None, "ACE.Server/WorldObjects/Player.cs:HandleActionJump",
        "its physics calls only, both branches, as the oracle's facade makes them (the stamina cost, LastJumpTime and "
        "the broadcasts are no physics); traced with the mover's state at its entry and exit")
def handle_action_jump(mover: PhysicsObj, velocity) -> None:
    """With a local jump velocity (the JumpPack's). The branch is the Player's FastTick (IsPKType: a
    PK or PKLite player's): it sets UpdateTime only when the mover is not moving or animating; the
    other branch (an ordinary player's) always. Then the same calls in both: ``TransientState &=
    ~(Contact | WaterContact)``, calc_acceleration, set_on_walkable(false), set_local_velocity,
    RemoveLinkAnimations, MotionInterpreter.PendingMotions.Clear(), IsAnimating = false. A mover
    without a motion table has no MovementManager: where ACE's IsMovingOrAnimating reaches it (every
    earlier term false) and throws NullReferenceException the jump counts the mover as not moving,
    and PendingMotions.Clear() has no interpreter to clear (docs/oracle.md's audit table). FastTick's
    magic-cast stop is left out: no scene casts. The stamina, burden and broadcasts are not physics."""
    if mover.weenie_obj.world_object.fast_tick:
        try:
            moving = mover.is_moving_or_animating()
        except AttributeError as e:
            if e.obj is not None:
                raise
            moving = False
        if not moving:
            mover.update_time = mover.timer.current_time
    else:
        mover.update_time = mover.timer.current_time

    # perform jump in physics engine (ACE)
    mover.transient_state &= ~(TransientState.Contact | TransientState.WaterContact)
    mover.calc_acceleration()
    mover.set_on_walkable(False)
    mover.set_local_velocity(velocity, False)
    mover.remove_link_animations()  # matches MotionInterp.LeaveGround more closely (ACE)
    if mover.movement_manager is not None:
        mover.movement_manager.motion_interpreter.pending_motions.clear()  # hack (ACE)
    mover.is_animating = False


@harness("a tick step's inputs, in the scene's order, as the oracle's facade applies them")
def apply_inputs(mover: PhysicsObj, step, mode, lscape: LScape | None = None, others=None) -> None:
    """The setters and the jump first (TICK_INPUTS begins with OTHER_INPUTS, in their order), then the rest.
    `others`: the other movers' PhysicsObjs by id (a MoveToObject's target the server destroyed is found there)."""
    apply_other_inputs(mover, step, mode)
    if step.motion is not None:
        move_to_state(mover, step.motion, mode)
    if step.stop is not None:
        stop_movement(mover, step.stop)
    if step.do_motion is not None:
        key_motion(mover, step.do_motion, True, mode)
    if step.stop_motion is not None:
        key_motion(mover, step.stop_motion, False, mode)
    if step.move_to is not None:
        move_to_position(mover, step.move_to, mode)
    if step.move_to_object is not None:
        object_move(mover, step.move_to_object, False, mode, others)
    if step.turn_to_heading is not None:
        turn_to_heading(mover, step.turn_to_heading, mode)
    if step.turn_to_object is not None:
        object_move(mover, step.turn_to_object, True, mode, others)
    if step.door is not None:
        door(mover.server_objects.get_object_a(step.door.object), step.door.ethereal, lscape)
    if step.stick_to is not None:  # a melee swing's stick (Monster_Melee.MeleeAttack, Player_Melee.DoSwingMotion)
        mover.stick_to_object(step.stick_to)


@harness("another mover destroyed by the server (scene/8 others[].destroy), as the oracle's facade destroys it")
def destroy_other(obj: PhysicsObj, oid: int, movers, stepped: list) -> None:
    """WorldObject.Destroy's physics for another mover in the world: its landblock's RemoveWorldObject calls
    PhysicsObj.DestroyObject, and the landblock ticks it no more (one not in the world: nothing)."""
    k = next(k for k, (o, _, _) in enumerate(movers) if o.id == oid)
    if stepped[k]:
        obj.destroy_object()
        stepped[k] = False


@harness("another mover's tick inputs (scene/8 ticks.steps[].others), as the oracle's facade applies them")
def apply_other_inputs(obj: PhysicsObj, inputs, mode) -> None:
    """The setters and the jump in OTHER_INPUTS order (`inputs`: an OtherInputs, or the mover's TickStep, whose
    TICK_INPUTS begin with the same inputs in the same order)."""
    if inputs.state is not None:
        obj.state = inputs.state
    if inputs.transient_state is not None:
        obj.transient_state = inputs.transient_state
    if inputs.velocity is not None:
        obj.set_velocity(mode.vec(*inputs.velocity), False)
    if inputs.local_velocity is not None:
        obj.set_local_velocity(mode.vec(*inputs.local_velocity), False)
    if inputs.omega is not None:
        obj.set_omega(mode.vec(*inputs.omega), False)
    if inputs.jump is not None:
        handle_action_jump(obj, mode.vec(*inputs.jump))
    if inputs.sequence_velocity is not None:
        obj.part_array.sequence.set_velocity(mode.vec(*inputs.sequence_velocity))
    if inputs.sequence_omega is not None:
        obj.part_array.sequence.set_omega(mode.vec(*inputs.sequence_omega))


@anchor(None, "ACE.Server/WorldObjects/WorldObject.cs:ExecuteMotion",
        "its physics (scene/8 others[].execute_motion), as the oracle's facade makes them")
def execute_motion(obj: PhysicsObj, command: int, mode) -> None:
    """WorldObject.ExecuteMotion's physics for a motion command that is not Ready (`command`: the Motion's
    ForwardCommand, or its Stance when that is Ready): get_minterp, a new RawMotionState whose ForwardCommand is 0
    ("must be this for monster sleep animations"), CurrentHoldKey Run and CurrentStyle the command; UpdateTime when
    the object is not moving or animating; RawState = it, apply_raw_movement(true, true). A Chest's open and close
    (Chest.DoOnOpenMotionChanges), an emote's motion (EmoteManager), a creature's death (Creature_Death)."""
    from acconform.motion_enums import HoldKey

    from .animation.raw_motion_state import RawMotionState

    minterp = obj.get_minterp()
    raw = RawMotionState.create(mode)
    raw.forward_command = 0
    raw.current_hold_key = HoldKey.Run
    raw.current_style = command
    if not obj.is_moving_or_animating():
        obj.update_time = obj.timer.current_time
    minterp.raw_state = raw
    minterp.apply_raw_movement(True, True)


@harness("the physics of ACE's server Door (Door.Open, Door.FinalizeClose), as the oracle's facade makes them")
def door(obj: PhysicsObj, ethereal: bool, lscape: LScape) -> None:
    """Open: the WorldObject's Ethereal setter (SetPhysicsPropertyState -> SetPhysicsState) sets
    PhysicsState.Ethereal on State directly, not through set_ethereal. FinalizeClose: the flag
    cleared, then with allow_door_hold (a default server's PropertyManager: true)
    ethereal_check_for_collisions: an object overlapping the door sets it again (held open)."""
    if ethereal:
        obj.state |= PhysicsState.Ethereal
        return
    obj.state &= ~PhysicsState.Ethereal
    if obj.ethereal_check_for_collisions(lscape):
        obj.state |= PhysicsState.Ethereal


@harness("a scene's MovementParameters built as the oracle's facade builds it: ACE's constructor, then each field the scene gives")
def movement_parameters(p, mode):
    """`p`: acconform.motion_scene.MovementParams. Flags, DistanceToObject, MinDistance, FailDistance,
    Speed, WalkRunThreshold, DesiredHeading, HoldKeyToApply, in that order (the facade's Params)."""
    from .animation.movement_parameters import MovementParameters

    s = mode.scalar
    mvp = MovementParameters.create(mode)
    mvp.flags = p.flags
    mvp.distance_to_object = s(p.distance_to_object)
    mvp.min_distance = s(p.min_distance)
    mvp.fail_distance = s(p.fail_distance)
    mvp.speed = s(p.speed)
    mvp.walk_run_threshold = s(p.walk_run_threshold)
    mvp.desired_heading = s(p.desired_heading)
    mvp.hold_key_to_apply = p.hold_key_to_apply
    return mvp


@harness("the server's stops, as the oracle's facade makes them (acconform.motion_scene.STOPS)")
def stop_movement(mover: PhysicsObj, stop: str) -> None:
    """stop_completely: PhysicsObj.StopCompletely (Creature_Death, Player_Tick's PK logout);
    cancel_moveto: PhysicsObj.cancel_moveto (Player_Move2.StopExistingMoveToChains2, Player_Melee);
    move_to_manager_cancel: MoveToManager.CancelMoveTo(ActionCancelled), FailProgressCount = 0
    (Monster_Navigation.CancelMoveTo, Creature_Navigation's MoveTo tick)."""
    from acconform.motion_enums import WeenieError

    if stop == "stop_completely":
        mover.stop_completely(True)
    elif stop == "cancel_moveto":
        mover.cancel_moveto()
    else:
        mover.movement_manager.move_to_manager.cancel_move_to(WeenieError.ActionCancelled)
        mover.movement_manager.move_to_manager.fail_progress_count = 0


@harness("Player.OnMoveToState_ClientMethod's physics calls for one key, as the oracle's facade makes them")
def key_motion(mover: PhysicsObj, command, press: bool, mode) -> None:
    """A MovementParameters() with HoldKeyToApply the current hold key, UpdateTime when not moving or
    animating, then DoMotion(motion, mvp) or StopMotion(motion, mvp, true)."""
    from .animation.movement_parameters import MovementParameters

    mvp = MovementParameters.create(mode)
    mvp.hold_key_to_apply = command.hold_key
    if not mover.is_moving_or_animating():
        mover.update_time = mover.timer.current_time
    if press:
        mover.do_motion(command.motion, mvp)
    else:
        mover.stop_motion(command.motion, mvp, True)


@harness("Creature.MoveTo(Position)'s physics calls, as the oracle's facade makes them")
def move_to_position(mover: PhysicsObj, move, mode) -> None:
    """UpdateTime when not moving or animating, then MoveToPosition(a copy of the position, mvp)."""
    if not mover.is_moving_or_animating():
        mover.update_time = mover.timer.current_time
    mover.move_to_position(Position.from_record(move.position, mode).copy(), movement_parameters(move.params, mode))


@harness("PhysicsObj.TurnToHeading with the calls of Creature.MoveTo around it, as the oracle's facade makes them")
def turn_to_heading(mover: PhysicsObj, turn, mode) -> None:
    """No WorldObject of ACE's server calls TurnToHeading (the client does, from a TurnToHeading
    motion): UpdateTime when not moving or animating, then TurnToHeading(mvp)."""
    if not mover.is_moving_or_animating():
        mover.update_time = mover.timer.current_time
    mover.turn_to_heading(movement_parameters(turn.params, mode))


@harness("Monster_Navigation.StartTurn's physics calls, as the oracle's facade makes them")
def object_move(mover: PhysicsObj, move, turn: bool, mode, others=None) -> None:
    """MoveToObject / TurnToObject(the target's PhysicsObj, mvp), then UpdateTime = CurrentTime
    ("prevent initial snap"). The target is the object the run's ServerObjectManager filed under
    its id (set_object_guid); a MoveToObject's or TurnToObject's target the server destroyed (feature
    objects.gone_targets: out of ServerObjectManager) is its PhysicsObj still, as Monster_Navigation passes
    AttackTarget.PhysicsObj to either after the target's Destroy (`others`: the other movers' PhysicsObjs by id)."""
    target = mover.server_objects.get_object_a(move.object)
    if target is None and others is not None:
        target = others.get(move.object)
    mvp = movement_parameters(move.params, mode)
    if turn:
        mover.turn_to_object(target, mvp)
    else:
        mover.move_to_object(target, mvp)
    mover.update_time = mover.timer.current_time


@harness("the physics calls of a player's MoveToState (Player.OnMoveToState, FastTick; OnMoveToState_ServerMethod), as the oracle's facade makes them")
def move_to_state(mover: PhysicsObj, raw, mode) -> None:
    """`raw`: the MoveToState's RawMotionState (acconform.motion_scene.MotionInput). ACE's default
    (client_movement_formula off, no standing long jump): UpdateTime when the mover is not moving
    or animating, the interpreter's RawState.SetState, then apply_raw_movement(true, whether
    motion_allows_jump of the interpreted forward command is None)."""
    from acconform.motion_enums import WeenieError

    if not mover.is_moving_or_animating():
        mover.update_time = mover.timer.current_time
    minterp = mover.get_minterp()
    minterp.raw_state.set_state(raw, mode)
    allow_jump = minterp.motion_allows_jump(minterp.interpreted_state.forward_command) == WeenieError.None_
    minterp.apply_raw_movement(True, allow_jump)


def _command_state(state) -> CommandState:
    return CommandState(int(state.current_style), int(state.forward_command), float(state.forward_speed),
                        int(state.side_step_command), float(state.side_step_speed), int(state.turn_command),
                        float(state.turn_speed))


@harness("reads the mover's motion layer after a tick, as the oracle's facade does")
def motion_tick_state(mover: PhysicsObj) -> MotionTickState:
    """The fields as they stand, with no call that makes or asks anything (not get_minterp, which
    makes a MovementManager; not get_state_velocity, which asks the WeenieObject its run rate):
    the MovementManager's MotionInterpreter's InterpretedState and RawState, the PartArray's
    Sequence (CurrAnim's animation id, FrameNumber, Velocity, Omega), the MoveToManager's
    MovementType, and IsMovingTo()."""
    manager = mover.movement_manager
    minterp = manager.motion_interpreter if manager is not None else None
    move_to = manager.move_to_manager if manager is not None else None
    seq = mover.part_array.sequence
    node = seq.curr_anim
    anim = node.value.anim if node is not None else None
    return MotionTickState(
        interpreted=_command_state(minterp.interpreted_state) if minterp is not None else None,
        raw=_command_state(minterp.raw_state) if minterp is not None else None,
        animation=int(anim.id) if anim is not None else None,
        frame_number=float(seq.frame_number),
        sequence_velocity=_vec(seq.velocity),
        sequence_omega=_vec(seq.omega),
        movement_type=int(move_to.movement_type) if move_to is not None else None,
        is_moving_to=bool(mover.is_moving_to()),
    )


@harness("reads a PhysicsObj's CollisionTable after a tick, as the oracle's facade does")
def collision_states(obj: PhysicsObj) -> tuple[CollisionState, ...]:
    """Its records in the table's order (ACE's PhysicsObj constructor makes the table and nothing sets it to null)."""
    return tuple(CollisionState(int(key), float(record.touched_time), bool(record.ethereal))
                 for key, record in obj.collision_table.items())


@harness("reads the mover's PhysicsObj after a tick, as the oracle's facade does")
def tick_state(mover: PhysicsObj, updated: bool, motion: bool = False, others=None, collisions: bool = False) -> TickState:
    """`motion`: whether the mover has a motion table (the scene's `mover.motion_table`): then the
    tick also carries its motion layer (`motion_tick_state`), and only then, so a scene without one
    is answered as before. `others`: in a scene with other movers, their states (TickState with its id): then the
    tick carries them and the mover's CollisionTable; `collisions`: the table alone (another mover's tick)."""
    q = mover.position.frame.orientation
    return TickState(
        updated=bool(updated),
        update_time=float(mover.update_time),
        cell=int(mover.position.obj_cell_id),
        cur_cell=mover.cur_cell.id if mover.cur_cell is not None else 0,
        origin=_vec(mover.position.frame.origin),
        orientation=(float(q.w), float(q.x), float(q.y), float(q.z)),
        velocity=_vec(mover.velocity),
        acceleration=_vec(mover.acceleration),
        omega=_vec(mover.omega),
        cached_velocity=_vec(mover.cached_velocity),
        state=int(mover.state),
        transient_state=int(mover.transient_state),
        contact_plane_cell=int(mover.contact_plane_cell_id),
        contact_plane=PlaneState(_vec(mover.contact_plane.normal), float(mover.contact_plane.d)),
        sliding_normal=_vec(mover.sliding_normal),
        jumped_this_frame=bool(mover.jumped_this_frame),
        shadow_cells=tuple(mover.shadow_objects),
        motion=motion_tick_state(mover) if motion else None,
        collisions=collision_states(mover) if others is not None or collisions else None,
        others=others,
    )


@harness("the physics calls of Player.UpdatePlayerPosition for a requested position that moves, as the oracle's facade makes them")
def update_player_position(mover: PhysicsObj, request_pos: Position, location_cell: int, lscape: LScape, trace):
    """The legacy (non-FastTick) path: LScape.get_landcell of the request's cell (none: no update),
    set_request_pos(origin, orientation, that cell, `location_cell`: the cell of the Player's Location,
    the last position update_object_server accepted or where the mover entered), update_object_server(),
    and a mover left in no cell put in that cell. Returns (updated, the Location's cell after it)."""
    cur_cell = lscape.get_landcell(request_pos.obj_cell_id)
    if cur_cell is None:
        return False, location_cell
    mover.set_request_pos(request_pos.frame.origin, request_pos.frame.orientation, cur_cell, location_cell, lscape)
    success = mover.update_object_server(True, lscape, trace)
    if mover.cur_cell is None and cur_cell.id >> 16 != 0x18A:
        mover.cur_cell = cur_cell
    return success, request_pos.obj_cell_id if success else location_cell


@harness("steps the other movers after the mover, in `others` order, as the oracle's facade does: update_object, or a projectile's UpdateObjectPhysics")
def step_others(launches, stepped: list, lscape: LScape, trace, landblocks: dict) -> dict:
    """`launches`: (PhysicsObj, its Launch or None) per other mover; `stepped`: whether each is in the world (a
    projectile: launched), updated here when a projectile's landblock no longer holds it (destroyed, or never
    entered: the landblock ticks it no more). A projectile that changed landblocks is then relocated
    (missile_launch.relocate_object_for_physics) into `landblocks` (the run's server Landblocks by id), as
    LandblockManager.TickPhysics relocates its movedObjects. Returns {id: updated} for those stepped."""
    others_updated = {}
    moved = []
    for k, (obj, launch) in enumerate(launches):
        if not stepped[k]:
            continue
        if launch is None:
            others_updated[obj.id] = obj.update_object(lscape, trace)
        else:
            wo = obj.weenie_obj.world_object
            if wo.current_landblock is None:
                stepped[k] = False
                continue
            others_updated[obj.id] = landblock_update = missile_launch.update_object_physics(wo, lscape, trace)
            if landblock_update:
                moved.append(wo)  # Landblock.TickPhysics' movedObjects
    # LandblockManager.TickPhysics: after every landblock's physics, each object that changed landblocks
    for wo in moved:
        missile_launch.relocate_object_for_physics(wo, landblocks, lscape, trace)
    return others_updated


@anchor(None, "PhysicsObj.cs:update_object", "the tick scene driver: per step the inputs, the clock, then "
        "update_object or the legacy player path (Player.UpdatePlayerPosition's physics calls)")
def run_ticks(scene: Scene, mover: PhysicsObj, timer: PhysicsTimer, lscape: LScape, trace, movers=(), records=(),
              statics=()) -> tuple[TickState, ...]:
    """Per step: the inputs (the mover's, then each other mover's in the step's order; the clock still
    at the previous tick's time), the clock set to the step's time (Ticks.times()), the driver for the
    mover, then update_object for each other mover in the world, in the order they entered (a server
    landblock's worldObjects), then every mover read back. `movers`: `build_other`'s (object,
    placement, entered) per other mover, `records` their scene records (OtherMover or dat.DatOther), `statics`
    the statics' PhysicsObjs (a launch may aim at one). A projectile (a record with a `launch`) is launched at
    its step after the inputs and before the clock (missile_launch.scene_launch), then stepped each tick by
    WorldObject.UpdateObjectPhysics (missile_launch.update_object_physics) while its landblock holds it; its
    `updated` is that method's answer. An exception in a tick is that tick's error and ends the run, as in
    the oracle."""
    ticks = scene.ticks
    mode = lscape.mode
    states = []
    location_cell = mover.position.obj_cell_id  # where it entered: its WorldObject's Location (SyncLocation)
    motion = getattr(scene.mover, "motion_table", None) is not None
    by_id = {obj.id: obj for obj, _, _ in movers}
    other_objs = dict(by_id)  # the other movers alone (a destroyed one stays here: objects.gone_targets)
    by_id[mover.id] = mover
    if statics:
        by_id.update((obj.id, obj) for obj in statics if obj is not None)
    launches = [(obj, o.launch) for (obj, _, _), o in zip(movers, records)] if records else [(obj, None) for obj, _, _ in movers]
    stepped = [entered for _, _, entered in movers]  # per other mover: in the world (a projectile: launched)
    landblocks = {}  # the server Landblocks the projectiles joined, by landblock id
    for index, (step, time) in enumerate(zip(ticks.steps, ticks.times())):
        if trace is not None and trace.recorder is not None:  # tracing (port/tracing.py): the tick it is in
            trace.recorder.at_tick(index)
        try:
            apply_inputs(mover, step, mode, lscape, other_objs)
            for inputs in step.others:
                apply_other_inputs(by_id[inputs.id], inputs, mode)
                # EmoteManager's Motion emote: an object moving to something (IsMovingTo) is skipped, else ExecuteMotion
                if inputs.execute_motion is not None and not by_id[inputs.id].is_moving_to():
                    execute_motion(by_id[inputs.id], inputs.execute_motion, mode)
                parenting.apply_parenting_inputs(by_id[inputs.id], inputs, by_id, lscape)
                if inputs.destroy:
                    destroy_other(by_id[inputs.id], inputs.id, movers, stepped)
            for k, (obj, launch) in enumerate(launches):
                if launch is not None and launch.tick == index:
                    missile_launch.scene_launch(obj.weenie_obj.world_object, launch, by_id[launch.launcher],
                                                by_id[launch.target] if launch.target is not None else None,
                                                landblocks, lscape, trace)
                    stepped[k] = True
            # Landblock.TickPhysics' first step, on each server landblock (the launches above are a server's actions,
            # run after the previous tick's physics; it reads no clock)
            for landblock in landblocks.values():
                landblock.process_pending_world_object_additions_and_removals()
            timer.set(time)
            if ticks.driver == "update_object":
                updated = mover.update_object(lscape, trace)
            else:
                updated, location_cell = update_player_position(mover, Position.from_record(step.request_pos, mode),
                                                                location_cell, lscape, trace)
            others_updated = step_others(launches, stepped, lscape, trace, landblocks)
        except Exception as e:
            states.append(TickState(error=verdict(e)))
            break
        others = tuple(replace(tick_state(obj, others_updated.get(obj.id, False), False, None, True), id=obj.id)
                       for obj, _, _ in movers) if movers else None
        states.append(tick_state(mover, updated, motion, others))
        if trace is not None and trace.recorder is not None:  # tracing: the mover after the tick
            trace.recorder.at_tick(index, states[-1])
    return tuple(states)
