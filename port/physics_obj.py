"""PhysicsObj: PhysicsObj(), makeObject, InitObjectBegin, InitPartArrayObject, makeAnimObject, SetTranslucencyInternal, InitObjectEnd, InitDefaults, play_script_internal, AdjustPosition, add_obj_to_cell, enter_cell, UpdateChild, UpdateChildrenInternal, add_child (both), set_parent (both), unparent_children, unset_parent, leave_world, clear_transient_states, recalc_cross_cells, calc_cross_cells, set_cell_id_recursive, SetPlacementFrame, SetPlacementFrameInternal, handle_visible_cells_non_player, calc_cross_cells_static, find_bbox_cell_list, remove_shadows_from_cells, add_particle_shadow_to_cell, add_shadows_to_cell(CellArray), is_completely_visible, transition, update_object, UpdateObjectInternal, UpdatePositionInternal, UpdatePhysicsInternal, calc_friction, set_local_velocity, set_omega, set_initial_frame, set_active, set_ethereal, ethereal_check_for_collisions, check_collision, IsMovingOrAnimating, RemoveLinkAnimations, GetBlockDist, process_hooks, UpdateObjectInternalServer, update_object_server, set_current_pos, change_cell, change_cell_server, leave_cell, track_object_collision, report_collision_end, report_object_collision_end, report_environment_collision, report_object_collision, build_collision_profile (both), get_object_info, check_contact, get_walkable_z, is_valid_walkable, set_velocity, GetStepUpHeight, GetStepDownHeight, FindObjCollisions, FindObjCollisions_Inner, CacheHasPhysicsBSP, SetScaleStatic, IsPlayer, Equals; MasterDBMap.DivineType.

The part of ACE's PhysicsObj.cs a transition uses: how a static object is made from its DAT
record (makeObject: a PartArray over a GfxObj mesh or a Setup) and placed (add_obj_to_cell ->
calc_cross_cells_static: find_bbox_cell_list over the parts' boxes, or find_cell_list for a
cylsphere without a physics BSP -> add_shadows_to_cell, in the CellArray's .NET order); the
set-up PhysicsObj.transition does before FindValidPosition, the members the transition reads
back (walkable checks, StopVelocity's set_velocity), and a static's FindObjCollisions (BSP
through the PartArray, or the Setup's spheres / cylspheres). The mover's PartArray is the
harness's (run.py, as the oracle builds it). A static's WeenieObj is ACE's WeenieObject.DummyObject (no
player, creature or PK flags), which is what a PhysicsObj made without a WorldObject carries, and its
DatObject is true (as Landblock.init_static_objs sets it); a mover is a WorldObject's PhysicsObj
(WorldObject.InitPhysicsObj: the WeenieObject of its Player, Creature or plain WorldObject,
port/weenie_object.py and port/world_objects/), DatObject false, entering the world through enter_world
or SetPosition. Two movers touching report to each other's WorldObjects (report_object_collision) and
keep each other in their CollisionTable, a .NET Dictionary whose order report_collision_end walks.

The tick (a tick scene's steps): update_object cuts the time since UpdateTime (the run's
PhysicsTimer, port/physics_timer.py, for ACE's static clock) into sub-steps of UpdateObjectInternal:
root motion from the PartArray's Sequence and the integration of UpdatePhysicsInternal give the new
frame, a transition moves there, SetPositionInternal(Transition) takes the cell, contact plane and
flags and handle_all_collisions bounces; UpdateObjectInternalServer is the legacy player path to
RequestPos. The managers ACE makes for creatures and players (movement, position, detection,
target, particle) are null unless the scene's calls make them; a Setup's DefaultScript makes a
ScriptManager (InitDefaults -> play_script_internal), whose UpdateScripts does nothing.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import math

from acconform.flags import ObjectInfoState, PhysicsState, SetPositionError, SetPositionFlags, TransientState, TransitionState
from acconform.numerics import Plane, Vector3, cast_float, dot, normalize

from .anchors import anchor
from .constants import (COLLISION_RECORD_LIFETIME, DEFAULT_ELASTICITY, DEFAULT_FRICTION, DEFAULT_SCALE, DUMMY_SPHERE_RADIUS,
                        EPSILON, FLOOR_Z, FRICTION_LEAVING_ANGLE, GRAVITY, HUGE_QUANTUM, MAX_QUANTUM, MAX_VELOCITY,
                        MAX_VELOCITY_SQUARED, MIN_QUANTUM, PLACEMENT_CLOSE, SLEDDING_FLAT_Z, SLEDDING_GLIDE_FRICTION,
                        SLEDDING_GLIDE_SPEED_SQUARED, SLEDDING_STOP_FRICTION, SLEDDING_STOP_SPEED_SQUARED,
                        SMALL_VELOCITY_SQUARED, TICK_RATE, TRANSLUCENCY_ETHEREAL)
from .frame import AFrame, Position
from . import land_defs
from .cell import obj_cell
from .child_list import ChildList
from .part_array import PLACEMENT_FRAME_ID, PartArray
from .world_objects import SpellProjectile
from .errors import ArgumentException, ArgumentOutOfRangeException, InvalidOperationException
from .shadow_obj import ShadowObj
from .transition.object_info import ObjectInfo
from .transition.transition import Transition
from .transition.cell_array import NetDictionary
from .weenie_object import DUMMY_OBJECT, WeenieObject
from .world_objects import Player
from .env_collision_profile import EnvCollisionProfile
from .obj_collision_profile import ObjCollisionProfile
from .anim_hook import anim_hook_execute
from .managers.script_manager import ScriptManager

# PhysicsEngine.cs TransientStateFlags.StationaryComplete = StationaryStuck | StationaryStop | StationaryFall
STATIONARY_COMPLETE = TransientState.StationaryStuck | TransientState.StationaryStop | TransientState.StationaryFall
# PhysicsGlobals.DefaultState
# PropertyManager's spell_projectile_ethereal on a default server (PhysicsObj.SetPositionInternal reads it)
SPELL_PROJECTILE_ETHEREAL = False

DEFAULT_STATE = PhysicsState.EdgeSlide | PhysicsState.LightingOn | PhysicsState.Gravity | PhysicsState.ReportCollisions


@anchor(None, "MasterDBMap.cs:DivineType")
def divine_type_of(data_did: int) -> int:
    """MasterDBMap.DivineType: 6 for a GfxObj (0x01...), 7 for a Setup (0x02...), else 0."""
    type_ = data_did >> 24
    if type_ == 0x01:
        return 6
    elif type_ == 0x02:
        return 7
    return 0


@dataclass(slots=True)
class CollisionRecord:
    """ACE's Collision/CollisionRecord.cs: when an object was last touched (PhysicsTimer.CurrentTime,
    double) and whether it was ethereal then."""

    touched_time: float
    ethereal: bool


def _dummy_sphere(mode):
    """PhysicsGlobals.DummySphere: radius 0.1, its centre 0.1 above the origin."""
    from .geom.sphere import Sphere

    return Sphere(mode.vec(0, 0, DUMMY_SPHERE_RADIUS), mode.scalar(DUMMY_SPHERE_RADIUS))


def _hit(trace, branch: str) -> None:
    if trace is not None:
        trace[branch] += 1


@dataclass(slots=True, eq=False)
class PhysicsObj:
    id: int
    state: int  # PhysicsState
    position: object  # frame.Position
    cur_cell: object = None
    transient_state: int = 0
    velocity: Vector3 | None = None
    contact_plane: Plane | None = None
    contact_plane_cell_id: int = 0
    sliding_normal: Vector3 | None = None
    scale: object = 1.0
    part_array: object = None  # port.part_array.PartArray
    weenie_obj: WeenieObject = DUMMY_OBJECT  # port/weenie_object.py
    dat_object: bool = False
    projectile_target: object = None
    parent: object = None
    is_sight_obj: bool = False
    jumped_this_frame: bool = False
    shadow_objects: dict = field(default_factory=dict)  # cell id -> ShadowObj (a .NET Dictionary)
    num_shadow_objects: int = 0
    cell_array: object = None  # transition.cell_array.CellArray (the object's own, for its placement)
    children: ChildList = field(default_factory=ChildList)  # Children (the constructor makes an empty one)
    examination_object: bool = False  # ExaminationObject
    translucency: object = 0.0
    translucency_original: object = 0.0
    acceleration: Vector3 | None = None
    omega: Vector3 | None = None
    cur_landblock: object = None  # port.land.landblock.Landblock
    colliding_with_environment: bool = False
    # CollisionTable: object id -> CollisionRecord, a .NET Dictionary (report_collision_end walks it in its
    # entry order, which a removal's free slot changes); ACE's constructor makes it, so it is never null
    collision_table: NetDictionary = field(default_factory=NetDictionary)
    entering_world: bool = False
    elasticity: object = DEFAULT_ELASTICITY
    friction: object = DEFAULT_FRICTION
    timer: object = None  # the run's PhysicsTimer (port/physics_timer.py): ACE's static PhysicsTimer.CurrentTime
    update_time: float = 0.0  # UpdateTime (double)
    physics_timer_current_time: float = 0.0  # PhysicsTimer_CurrentTime (double): update_object's running clock
    cached_velocity: Vector3 | None = None
    initial_updates: int = 0
    hooks: list = field(default_factory=list)  # PhysicsObjHook: nothing here ever adds one
    anim_hooks: list = field(default_factory=list)  # AnimationHook: the Sequence's (add_anim_hook)
    request_pos: object = None  # RequestPos (a Position; made by the constructor in server mode)
    request_cached_velocity: Vector3 | None = None  # requestCachedVelocity (set only by set_request_pos)
    is_animating: bool = False  # IsAnimating (the MotionInterpreter sets it)
    last_move_was_autonomous: bool = False  # LastMoveWasAutonomous
    mode: object = None  # the run's mode (the port's: the managers' scalars)
    server: bool = False  # PhysicsEngine.Instance.Server (the run's PortalDat says it)
    server_objects: object = None  # the run's ServerObjectManager (ACE's static one; port/managers/server_object_manager.py)
    # the managers ACE makes on demand for a creature or player: the scene's mover has none, and
    # their null checks stay as ACE has them (docs/oracle.md's audit table)
    movement_manager: object = None
    position_manager: object = None
    detection_manager: object = None
    target_manager: object = None
    script_manager: object = None
    particle_manager: object = None

    @property
    def is_player(self) -> bool:
        """``IsPlayer => ID >= 0x50000001 && ID <= 0x5FFFFFFF`` (the mover's id is in that range)."""
        return 0x50000001 <= self.id <= 0x5FFFFFFF

    @anchor(None, "PhysicsObj.cs:Equals")
    def equals(self, obj) -> bool:
        if obj is None:
            return False
        return self.id == obj.id

    @anchor("CPhysicsObj::GetStepUpHeight", "PhysicsObj.cs:GetStepUpHeight")
    def get_step_up_height(self):
        if self.part_array is None:
            return type(self.scale)(0.0)
        return self.part_array.get_step_up_height()

    @anchor("CPhysicsObj::GetStepDownHeight", "PhysicsObj.cs:GetStepDownHeight")
    def get_step_down_height(self):
        if self.part_array is None:
            return type(self.scale)(0.0)
        return self.part_array.get_step_down_height()

    @anchor("CPhysicsObj::CacheHasPhysicsBSP", "PhysicsObj.cs:CacheHasPhysicsBSP")
    def cache_has_physics_bsp(self) -> bool:
        if self.part_array is not None and self.part_array.cache_has_physics_bsp():
            self.state |= PhysicsState.HasPhysicsBSP
            return True
        self.state &= ~int(PhysicsState.HasPhysicsBSP)
        return False

    @anchor("CPhysicsObj::SetScaleStatic", "PhysicsObj.cs:SetScaleStatic")
    def set_scale_static(self, scale) -> None:
        self.scale = scale
        if self.part_array is not None:
            self.part_array.set_scale_internal(Vector3(scale, scale, scale))

    @classmethod
    @anchor("CPhysicsObj::CPhysicsObj", "PhysicsObj.cs:PhysicsObj()")
    def create(cls, mode, timer, server: bool = False, server_objects=None) -> "PhysicsObj":
        """``new PhysicsObj()``: ACE's defaults (Position cell 0 and identity frame,
        PhysicsGlobals.DefaultState, scale 1, default elasticity and friction, zero velocity,
        acceleration, omega, CachedVelocity and sliding normal, default(Plane) contact plane, an
        empty CellArray, UpdateTime and PhysicsTimer_CurrentTime from the clock `timer`, a
        RequestPos when PhysicsEngine.Instance.Server (`server`)). Called on a subclass (BuildingObj),
        it makes that class's object, as `base()` does. `server_objects`: the run's
        ServerObjectManager (ACE's is static), where set_object_guid files the object."""
        from .transition.cell_array import CellArray

        zero = mode.vec(0, 0, 0)
        obj = cls(id=0, state=int(DEFAULT_STATE), position=Position(0, AFrame.identity(mode)),
                         velocity=zero, contact_plane=Plane(zero, mode.scalar(0.0)), sliding_normal=zero,
                         scale=mode.scalar(DEFAULT_SCALE), cell_array=CellArray(), acceleration=zero, omega=zero,
                         elasticity=mode.scalar(DEFAULT_ELASTICITY), friction=mode.scalar(DEFAULT_FRICTION),
                         cached_velocity=zero, request_cached_velocity=zero, timer=timer, mode=mode,
                         server=server, server_objects=server_objects)
        obj.update_time = timer.current_time
        obj.physics_timer_current_time = timer.current_time
        if server:
            obj.request_pos = Position(0, AFrame.identity(mode))
        return obj

    @staticmethod
    @anchor("CPhysicsObj::makeObject", "PhysicsObj.cs:makeObject(uint, uint, bool, bool)")
    def make_object(data_did: int, object_iid: int, dynamic: bool, portal_dat, sight_obj: bool = False) -> "PhysicsObj":
        """`portal_dat` (port/dat/portal_dat.py) stands in for the DAT statics the DAT readers use,
        PhysicsEngine.Instance.Server and the PhysicsTimer."""
        obj = PhysicsObj.create(portal_dat.mode, portal_dat.timer, portal_dat.server, portal_dat.server_objects)
        obj.init_object_begin(object_iid, dynamic)
        obj.init_part_array_object(data_did, True, portal_dat)
        obj.init_object_end()

        # for direct visibility testing (ACE)
        obj.is_sight_obj = sight_obj
        return obj

    @anchor("CPhysicsObj::InitObjectBegin", "PhysicsObj.cs:InitObjectBegin")
    def init_object_begin(self, object_iid: int, dynamic: bool) -> bool:
        self.id = object_iid

        if not dynamic:
            self.state |= PhysicsState.Static
        else:
            self.state &= ~int(PhysicsState.Static)

        self.transient_state &= ~int(TransientState.Active)
        self.update_time = self.timer.current_time
        return True

    @anchor("CPhysicsObj::InitPartArrayObject", "PhysicsObj.cs:InitPartArrayObject")
    def init_part_array_object(self, data_did: int, create_parts: bool, portal_dat) -> bool:
        if data_did == 0:
            return False
        ethereal = False

        divine_type = divine_type_of(data_did)
        if divine_type == 6:
            self.part_array = PartArray.create_mesh(self, data_did, portal_dat)
        else:
            if divine_type != 7:
                if (data_did & 0xFF000000) != 0:
                    return False

                ethereal = True

                if not self.make_anim_object(data_did | 0x2000000, create_parts, portal_dat):
                    return False

            if not ethereal:
                self.part_array = PartArray.create_setup(self, data_did, create_parts, portal_dat)

        if self.part_array is None:
            return False
        self.cache_has_physics_bsp()
        if ethereal:
            self.state |= PhysicsState.Ethereal
            self.transient_state &= ~int(TransientState.CheckEthereal)
            self.set_translucency_internal(TRANSLUCENCY_ETHEREAL)
            self.state |= PhysicsState.IgnoreCollisions
        return True

    @anchor("CPhysicsObj::makeAnimObject", "PhysicsObj.cs:makeAnimObject")
    def make_anim_object(self, setup_id: int, create_parts: bool, portal_dat) -> bool:
        self.part_array = PartArray.create_setup(self, setup_id, create_parts, portal_dat)
        return self.part_array is not None

    @anchor("CPhysicsObj::SetTranslucencyInternal", "PhysicsObj.cs:SetTranslucencyInternal")
    def set_translucency_internal(self, translucency) -> None:
        """Translucency only (PartArray.SetTranslucencyInternal is empty on the server); the
        physics never reads it."""
        self.translucency = translucency if translucency < self.translucency_original else self.translucency_original

    @anchor("CPhysicsObj::InitObjectEnd", "PhysicsObj.cs:InitObjectEnd")
    def init_object_end(self) -> bool:
        if self.part_array is not None:
            self.part_array.set_placement_frame(PLACEMENT_FRAME_ID)

            if not self.state & PhysicsState.ParticleEmitter:
                self.part_array.set_frame(self.position.frame)
        return True

    @anchor("CPhysicsObj::InitDefaults", "PhysicsObj.cs:InitDefaults")
    def init_defaults(self, setup) -> None:
        """The Setup's DefaultScript is played (a ScriptManager made, the script not run: ACE's server
        runs none) and its DefaultMotionTable set; the sound and script tables ACE leaves commented out."""
        if setup.default_script != 0:
            self.play_script_internal(setup.default_script)

        if setup.default_motion_table != 0:
            self.set_motion_table_id(setup.default_motion_table)

        if self.state & PhysicsState.Static:
            if setup.default_animation != 0:
                self.state |= PhysicsState.HasDefaultAnim
            if setup.default_script != 0:
                self.state |= PhysicsState.HasDefaultScript

    @anchor("CPhysicsObj::AdjustPosition", "PhysicsObj.cs:AdjustPosition")
    def adjust_position(self, position, low_pt, dont_create_cells: bool, search_cells: bool, lscape):
        """The cell for `position` (moved to the outside, or into the EnvCell holding its low
        point, in place); None where ACE finds none. The run's world `lscape` stands in for
        ACE's static LScape."""
        from .cell.env_cell import EnvCell
        from .errors import InvalidCastException

        cell_id = position.obj_cell_id & 0xFFFF

        if (cell_id < 1 or cell_id > 0x40) and (cell_id < 0x100 or cell_id > 0xFFFD) and cell_id != 0xFFFF:
            return None

        if cell_id < 0x100:
            land_defs.adjust_to_outside_pos(position)
            return obj_cell.get_visible(lscape, position.obj_cell_id)

        visible_cell = obj_cell.get_visible(lscape, position.obj_cell_id)
        if visible_cell is not None and not isinstance(visible_cell, EnvCell):
            raise InvalidCastException(f"cell {visible_cell.id:08X} is a {type(visible_cell).__name__}, not an EnvCell")
        if visible_cell is None:
            return None

        point = position.local_to_global(low_pt)
        child = visible_cell.find_visible_child_cell(point, search_cells)
        if child is not None:
            position.obj_cell_id = child.id
            return child

        if not visible_cell.seen_outside:
            return None

        position.adjust_to_outside()
        return obj_cell.get_visible(lscape, position.obj_cell_id)

    @anchor("CPhysicsObj::SetPositionInternal", "PhysicsObj.cs:SetPositionInternal(Position, SetPosition, Transition)")
    def set_position_internal_pos(self, pos, set_pos_flags: int, transition: Transition, lscape) -> int:
        """Returns the SetPositionError. `set_pos_flags` is the SetPosition's Flags (its Pos is
        `pos`); the run's world `lscape` stands in for ACE's static LScape."""
        if self.cur_cell is None:
            self.prepare_to_enter_world()

        new_cell = self.adjust_position(pos, transition.sphere_path.local_sphere[0].center,
                                        bool(set_pos_flags & SetPositionFlags.DontCreateCells), True, lscape)

        if new_cell is None:
            transition._hit("set_position:no_cell_stored")
            self.prepare_to_leave_visibility()
            self.store_position(pos, lscape)
            # ObjMaint.GotoLostCell(this, Position.ObjCellID) (ACE: commented out)
            self.set_active(False)
            return SetPositionError.OK

        if self.weenie_obj is not None and (self.weenie_obj.is_storage or self.weenie_obj.is_corpse):
            raise NotImplementedError("storage and corpses (ForceIntoCell) are not ported")

        if not self.check_position_internal(new_cell, pos, transition, set_pos_flags):
            collided = self.handle_all_collisions(transition.collision_info, False, False, transition.trace)
            transition._hit("set_position:collided" if collided else "set_position:no_valid_position")
            return SetPositionError.Collided if collided else SetPositionError.NoValidPosition

        if transition.sphere_path.cur_cell is None:
            return SetPositionError.NoCell

        # custom: test for non-ethereal spell projectile collision on world entry (ACE); a default
        # server's spell_projectile_ethereal is false
        spell_collide = isinstance(self.weenie_obj.world_object, SpellProjectile) and \
            len(transition.collision_info.collide_object) > 0 and not SPELL_PROJECTILE_ETHEREAL

        if spell_collide:
            # send initial CO as ethereal (ACE): the PropertyBool only, not the PhysicsState bit
            self.weenie_obj.world_object.ethereal = True

        if self.entering_world and transition.sphere_path.cur_pos.landblock != pos.landblock:
            return SetPositionError.NoValidPosition

        if not self.set_position_internal(transition):
            return SetPositionError.GeneralFailure

        if spell_collide:
            self.handle_all_collisions(transition.collision_info, False, False, transition.trace)

        transition._hit("set_position:placed")
        return SetPositionError.OK

    @anchor("CPhysicsObj::CheckPositionInternal", "PhysicsObj.cs:CheckPositionInternal")
    def check_position_internal(self, new_cell, new_pos, transition: Transition, set_pos_flags: int) -> bool:
        transition.init_path(new_cell, None, new_pos)

        if not set_pos_flags & SetPositionFlags.Slide:
            transition.sphere_path.placement_allows_sliding = False

        if not transition.find_valid_position():
            return False

        if set_pos_flags & SetPositionFlags.Slide:
            return True

        diff = transition.sphere_path.cur_pos.frame.origin - new_pos.frame.origin

        # should be using Math.Abs(), bug in original? (ACE): a move of any length toward -x and -y is kept
        if transition.sphere_path.cur_pos.obj_cell_id == new_cell.id and diff.x < PLACEMENT_CLOSE and diff.y < PLACEMENT_CLOSE:
            if -diff.x < PLACEMENT_CLOSE and -diff.y < PLACEMENT_CLOSE:
                transition._hit("check_position:kept_close")
            else:
                transition._hit("check_position:kept_far_negative")
            new_pos.frame.origin = transition.sphere_path.cur_pos.frame.origin
            return True
        transition._hit("check_position:moved_too_far")
        return False

    @anchor("CPhysicsObj::SetPositionInternal", "PhysicsObj.cs:SetPositionInternal(Transition)")
    def set_position_internal(self, transition: Transition) -> bool:
        prev_on_walkable = (self.transient_state & TransientState.OnWalkable) != 0
        transit_cell = transition.sphere_path.cur_cell
        prev_contact = (self.transient_state & TransientState.Contact) != 0
        cur_pos = transition.sphere_path.cur_pos

        if transit_cell is None:
            self.prepare_to_leave_visibility()
            self.store_position(cur_pos, transition.lscape)
            self.set_active(False)
            return True

        # modified: maintain consistency for Position.Frame in change_cell (ACE)
        self.set_frame(cur_pos.frame, transition.lscape)

        if transit_cell.equals(self.cur_cell):
            self.position.obj_cell_id = cur_pos.obj_cell_id
            if self.part_array is not None and not self.state & PhysicsState.ParticleEmitter:
                self.part_array.set_cell_id(cur_pos.obj_cell_id)
            if self.children is not None:
                for i in range(self.children.num_objects):
                    child = self.children.item(i)
                    child.position.obj_cell_id = cur_pos.obj_cell_id
                    if child.part_array is not None and not child.state & PhysicsState.ParticleEmitter:
                        child.part_array.set_cell_id(cur_pos.obj_cell_id)
        else:
            self.change_cell(transit_cell, transition.lscape)

        collisions = transition.collision_info

        self.contact_plane_cell_id = collisions.contact_plane_cell_id
        self.contact_plane = collisions.contact_plane

        if collisions.contact_plane_valid:
            self.transient_state |= TransientState.Contact
        else:
            self.transient_state &= ~TransientState.Contact

        self.calc_acceleration()

        if collisions.contact_plane_is_water:
            self.transient_state |= TransientState.WaterContact
        else:
            self.transient_state &= ~TransientState.WaterContact

        if self.transient_state & TransientState.Contact:
            if self.contact_plane.normal.z < FLOOR_Z:
                self.set_on_walkable(False)
            else:
                self.set_on_walkable(True)
        else:
            self.transient_state &= ~TransientState.OnWalkable

            if self.movement_manager is not None and prev_on_walkable:
                self.movement_manager.leave_ground()

            self.calc_acceleration()

        self.sliding_normal = collisions.sliding_normal

        if collisions.sliding_normal_valid:
            self.transient_state |= TransientState.Sliding
        else:
            self.transient_state &= ~TransientState.Sliding

        self.handle_all_collisions(collisions, prev_contact, prev_on_walkable, transition.trace)

        if self.cur_cell is not None:
            if self.state & PhysicsState.HasPhysicsBSP:
                self.calc_cross_cells(transition.lscape)
                return True

            if len(transition.cell_array.cells) > 0:
                self.remove_shadows_from_cells()
                self.add_shadows_to_cell(transition.cell_array)
                return True
        return True  # no CurCell, or no cells to shadow

    @anchor("CPhysicsObj::prepare_to_enter_world", "PhysicsObj.cs:prepare_to_enter_world")
    def prepare_to_enter_world(self) -> None:
        """ObjMaint's destruction queue (RemoveObjectToBeDestroyed, for the object and each child) is
        not kept: nothing in the physics reads it."""
        self.update_time = self.timer.current_time

        for child in self.children.objects:
            pass  # ObjMaint.RemoveObjectToBeDestroyed(child)

        if not self.state & PhysicsState.Static:
            if not self.transient_state & TransientState.Active:
                self.update_time = self.timer.current_time  # hiword? (ACE)

            self.transient_state |= TransientState.Active

    @anchor("CPhysicsObj::prepare_to_leave_visibility", "PhysicsObj.cs:prepare_to_leave_visibility")
    def prepare_to_leave_visibility(self) -> bool:
        """ObjMaint.AddObjectToBeDestroyed (a queue nothing here reads, for the object and each
        child) is not kept."""
        self.remove_shadows_from_cells()
        self.leave_cell(False)
        for child in self.children.objects:
            pass  # ObjMaint.AddObjectToBeDestroyed(child)
        return True

    @anchor("CPhysicsObj::leave_cell", "PhysicsObj.cs:leave_cell")
    def leave_cell(self, is_changing_cell: bool) -> None:
        if self.cur_cell is None:
            return
        self.cur_cell.remove_object(self)
        for child in self.children.objects:
            child.leave_cell(is_changing_cell)
        # removed lighting (ACE)
        self.cur_cell = None

        if self.cur_landblock is not None and not self.dat_object:
            self.cur_landblock.remove_server_object(self)
            self.cur_landblock = None

    @anchor("CPhysicsObj::store_position", "PhysicsObj.cs:store_position")
    def store_position(self, pos, lscape) -> None:
        # position ref? (ACE)
        if (pos.obj_cell_id & 0xFFFF) < 0x100:
            land_defs.adjust_to_outside_pos(pos)

        if self.part_array is not None and not self.state & PhysicsState.ParticleEmitter:
            self.part_array.set_cell_id(pos.obj_cell_id)

        self.set_cell_id(pos.obj_cell_id)
        self.set_frame(pos.frame, lscape)

    @anchor("CPhysicsObj::set_cell_id", "PhysicsObj.cs:set_cell_id")
    def set_cell_id(self, new_cell_id: int) -> None:
        self.position.obj_cell_id = new_cell_id
        if not self.state & PhysicsState.ParticleEmitter and self.part_array is not None:
            self.part_array.set_cell_id(new_cell_id)

    @anchor("CPhysicsObj::set_active", "PhysicsObj.cs:set_active")
    def set_active(self, active: bool) -> bool:
        if active:
            if self.state & PhysicsState.Static:
                return False

            if not self.transient_state & TransientState.Active:
                self.update_time = self.timer.current_time

            self.transient_state |= TransientState.Active
            return True
        else:
            self.transient_state &= ~TransientState.Active
            return True

    @anchor("CPhysicsObj::change_cell", "PhysicsObj.cs:change_cell")
    def change_cell(self, new_cell, lscape) -> None:
        if lscape.portal_dat.server:
            self.change_cell_server(new_cell, lscape)
            return

        if self.cur_cell is not None:
            self.leave_cell(True)
        if new_cell is None:
            self.position.obj_cell_id = 0
            if self.part_array is not None and not self.state & PhysicsState.ParticleEmitter:
                self.part_array.set_cell_id(0)
            self.cur_cell = None
        else:
            self.enter_cell(new_cell, lscape)

    @anchor(None, "PhysicsObj.cs:change_cell_server")
    def change_cell_server(self, new_cell, lscape) -> None:
        if self.cur_cell is not None:
            self.leave_cell(True)
        if new_cell is None:
            self.position.obj_cell_id = 0
            if self.part_array is not None and not self.state & PhysicsState.ParticleEmitter:
                self.part_array.set_cell_id(0)
            self.cur_cell = None
        else:
            self.enter_cell_server(new_cell, lscape)

    @anchor(None, "PhysicsObj.cs:enter_cell_server")
    def enter_cell_server(self, new_cell, lscape) -> None:
        """ObjectMaint's tables (visible, known and to-be-destroyed objects, known players) are not
        kept: nothing in the physics reads them (they feed the server's network updates and a
        monster's targets); what can throw is kept (GetVisibleObjects in handle_visible_cells and
        handle_visible_cells_non_player)."""
        self.enter_cell(new_cell, lscape)
        self.request_pos.obj_cell_id = new_cell.id  # document this control flow better (ACE)

        # sync location for initial CO (ACE): WorldObject.SyncLocation copies Position into the Player's
        # Location, which no physics reads

        # handle self (ACE)
        if self.is_player:
            # enqueue_objs: the Player tracks each newly visible object with a WorldObject; a scene's statics
            # have none (DummyObject)
            self.handle_visible_cells()
        else:
            self.handle_visible_cells_non_player()

        # handle known players (ACE): each known player's handle_visible_obj(this) and enqueue_obj only feed
        # that player's ObjectMaint tables and its network queue; nothing in the physics reads them

    @anchor(None, "PhysicsObj.cs:handle_visible_cells_non_player")
    def handle_visible_cells_non_player(self) -> None:
        """A non-player entering a cell (a monster, a pet, a projectile): ObjMaint's visible targets
        (a monster's, a combat pet's) or known players (anything else), from GetVisibleObjects or,
        with ObjectMaint.InitialClamp (true), GetVisibleObjectsDist of CurCell. Those tables are not
        kept (see enter_cell_server), and neither lookup throws (no CurLandblock or no cell: an
        empty list), so nothing here changes the physics."""
        return None

    @anchor(None, "PhysicsObj.cs:handle_visible_cells")
    def handle_visible_cells(self) -> list:
        """ObjMaint.DestroyObjects, then ObjMaint.GetVisibleObjects(CurCell) (ObjectMaint.cs),
        whose answer is empty here (see enter_cell_server); the newly visible and occluded lists
        only feed ObjectMaint's tables."""
        from .cell.env_cell import EnvCell

        cell = self.cur_cell
        if self.cur_landblock is None or cell is None:
            return []

        # use PVS / VisibleCells for EnvCells not seen outside (ACE)
        if isinstance(cell, EnvCell):
            visible_objs = list(cell.object_list)
            for env_cell in (cell.visible_cells or {}).values():
                if env_cell is not None:
                    visible_objs.extend(env_cell.object_list)
            if cell.seen_outside:
                outside = [i for i in self.cur_landblock.get_server_objects(True)
                           if not isinstance(i.cur_cell, EnvCell) or i.cur_cell.seen_outside]
                visible_objs.extend(outside)
            return [i for i in visible_objs if not i.dat_object and i.id != self.id]

        # use current landblock + adjacents for outdoors (ACE)
        visible_objs = self.cur_landblock.get_server_objects(True)
        return [i for i in visible_objs if i.id != self.id and (not isinstance(i.cur_cell, EnvCell) or i.cur_cell.seen_outside)]

    @anchor("CPhysicsObj::set_frame", "PhysicsObj.cs:set_frame")
    def set_frame(self, frame: AFrame, lscape=None) -> None:
        """Writes the frame's orientation in place when ACE does (a frame valid except for its
        heading gets the zero quaternion). PhysicsEngine.Instance.Server is the object's `server`
        (`lscape` is not read)."""
        if not frame.is_valid() and frame.is_valid_except_for_heading():
            z = type(frame.orientation.w)(0.0)
            frame.orientation = frame.orientation.runtime.quaternion(z, z, z, z)

        self.position.frame = frame.copy()

        # custom for server: only update part frames for objects with physics bsp (ACE)
        if self.part_array is not None and not self.state & PhysicsState.ParticleEmitter and (
                self.state & PhysicsState.HasPhysicsBSP or not self.server):
            self.part_array.set_frame(frame)

        self.update_children_internal()

    @anchor("CPhysicsObj::calc_acceleration", "PhysicsObj.cs:calc_acceleration")
    def calc_acceleration(self) -> None:
        z = type(self.velocity.x)(0.0)
        zero = Vector3(z, z, z)
        if self.transient_state & TransientState.Contact and self.transient_state & TransientState.OnWalkable:
            self.omega = self.acceleration = zero
        else:
            if self.state & PhysicsState.Gravity:
                self.acceleration = Vector3(zero.x, zero.y, type(zero.x)(GRAVITY))
            else:
                self.acceleration = zero

    @anchor("CPhysicsObj::set_on_walkable", "PhysicsObj.cs:set_on_walkable")
    def set_on_walkable(self, is_on_walkable: bool) -> None:
        prev_on_walkable = bool(self.transient_state & TransientState.OnWalkable)

        if is_on_walkable:
            self.transient_state |= TransientState.OnWalkable
        else:
            self.transient_state &= ~TransientState.OnWalkable

        if self.movement_manager is not None:
            if prev_on_walkable:
                if not is_on_walkable:
                    self.movement_manager.leave_ground()
            else:
                if is_on_walkable:
                    self.movement_manager.hit_ground()
        self.calc_acceleration()

    @anchor("CPhysicsObj::handle_all_collisions", "PhysicsObj.cs:handle_all_collisions")
    def handle_all_collisions(self, collisions, prev_has_contact: bool, prev_on_walkable: bool, trace=None) -> bool:
        """`trace`: the run's branch counter (the transition's), or None."""
        apply_bounce = True
        if prev_on_walkable and self.transient_state & TransientState.OnWalkable and not self.state & PhysicsState.Sledding:
            apply_bounce = False

        retval = False
        for collide_object in collisions.collide_object:
            if collide_object is not None and self.track_object_collision(collide_object, prev_has_contact):
                retval = True

        self.report_collision_end(False)

        if self.colliding_with_environment:
            self.colliding_with_environment = collisions.collided_with_environment
        elif collisions.collided_with_environment or (not prev_on_walkable and self.transient_state & TransientState.OnWalkable):
            if self.report_environment_collision(prev_has_contact):
                retval = True

        if collisions.frames_stationary_fall <= 1:
            if apply_bounce and collisions.collision_normal_valid:
                if self.state & PhysicsState.Inelastic:
                    _hit(trace, "handle_all_collisions:inelastic_stop")
                    z = type(self.velocity.x)(0.0)
                    self.velocity = Vector3(z, z, z)

                    # custom for spell projectiles: explode on server (ACE)
                    self.report_environment_collision(prev_has_contact)
                else:
                    collision_angle = dot(self.velocity, collisions.collision_normal)
                    if collision_angle < 0.0:
                        _hit(trace, "handle_all_collisions:elastic_bounce")
                        elastic_angle = -(collision_angle * (self.elasticity + type(collision_angle)(1.0)))
                        self.velocity = self.velocity + collisions.collision_normal * elastic_angle
        else:
            z = type(self.velocity.x)(0.0)
            self.velocity = Vector3(z, z, z)
            if collisions.frames_stationary_fall == 3:
                self.transient_state &= ~STATIONARY_COMPLETE
                return retval

        if collisions.frames_stationary_fall == 0:
            self.transient_state &= ~STATIONARY_COMPLETE
        elif collisions.frames_stationary_fall == 1:
            self.transient_state |= TransientState.StationaryFall
        elif collisions.frames_stationary_fall == 2:
            self.transient_state |= TransientState.StationaryStop
        else:
            self.transient_state |= TransientState.StationaryStuck

        return retval

    @anchor("CPhysicsObj::track_object_collision", "PhysicsObj.cs:track_object_collision")
    def track_object_collision(self, obj, prev_has_contact: bool) -> bool:
        if obj.state & PhysicsState.Static:
            return self.report_environment_collision(prev_has_contact)

        if self.collision_table is None:
            self.collision_table = NetDictionary()

        self.collision_table.set(obj.id, CollisionRecord(self.timer.current_time, bool(obj.state & PhysicsState.Ethereal)))

        return self.report_object_collision(obj, prev_has_contact)

    @anchor("CPhysicsObj::report_collision_end", "PhysicsObj.cs:report_collision_end")
    def report_collision_end(self, force_end: bool) -> None:
        """A record ends when touched more than a second ago (PhysicsTimer.CurrentTime, the run's
        clock: a scene without ticks never moves it), when ethereal and touched before now, or when
        forced."""
        if self.collision_table is None:
            return

        ends = []
        for collision_id, collision in self.collision_table.items():
            delta_time = self.timer.current_time - collision.touched_time

            if delta_time > COLLISION_RECORD_LIFETIME or collision.ethereal and delta_time > 0.0 or force_end:
                ends.append(collision_id)

        for end in ends:
            self.collision_table.remove(end)
            self.report_object_collision_end(end)

    @anchor("CPhysicsObj::report_object_collision_end", "PhysicsObj.cs:report_object_collision_end")
    def report_object_collision_end(self, object_id: int) -> bool:
        """ObjMaint is never null (the constructor makes one): the object is looked up in ServerObjectManager
        (the run's `server_objects`; none: an empty table) and, found and not reporting collisions as the
        environment, each side that reports collisions is told through WeenieObject.DoCollisionEnd."""
        collision = self.server_objects.get_object_a(object_id) if self.server_objects is not None else None
        if collision is not None:
            if not collision.state & PhysicsState.ReportCollisionsAsEnvironment:
                if self.state & PhysicsState.ReportCollisions and self.weenie_obj is not None:
                    self.weenie_obj.do_collision_end(object_id)

                if collision.state & PhysicsState.ReportCollisions and collision.weenie_obj is not None:
                    collision.weenie_obj.do_collision_end(self.id)
        return True

    @anchor("CPhysicsObj::report_environment_collision", "PhysicsObj.cs:report_environment_collision")
    def report_environment_collision(self, prev_has_contact: bool) -> bool:
        """WeenieObj.DoCollision(EnvCollisionProfile): DummyObject returns at once (no WorldObject); a
        Player runs HandleFallingDamage, which changes only its Health; any other WorldObject its
        OnCollideEnvironment."""
        if self.colliding_with_environment:
            return False

        result = False
        if self.state & PhysicsState.ReportCollisions and self.weenie_obj is not None:
            collision = EnvCollisionProfile()
            collision.velocity = self.velocity
            collision.set_me_in_contact(prev_has_contact)
            self.weenie_obj.do_collision_env(collision, self.id, self)
            result = True
        self.colliding_with_environment = True
        if self.state & PhysicsState.Missile:
            self.state &= ~PhysicsState.Missile
        return result

    @anchor("CPhysicsObj::report_object_collision", "PhysicsObj.cs:report_object_collision")
    def report_object_collision(self, obj, prev_has_contact: bool) -> bool:
        """Each side that reports collisions gets its profile and WeenieObj.DoCollision(ObjCollisionProfile),
        whose answer ACE drops. Both calls pass `obj` as the target (ACE's custom parameters): the first
        tells this object's WorldObject it touched obj's; the second asks obj's WorldObject about itself,
        which DoCollision's "no collision with self" drops. A static's DummyObject (no WorldObject) drops
        both."""
        if obj.state & PhysicsState.ReportCollisionsAsEnvironment:
            return self.report_environment_collision(prev_has_contact)

        velocity_collide = self.velocity - obj.velocity

        collided = False

        if not obj.state & PhysicsState.IgnoreCollisions:
            if self.state & PhysicsState.ReportCollisions and self.weenie_obj is not None:
                profile = self.build_collision_profile(obj, prev_has_contact, velocity_collide)

                self.weenie_obj.do_collision_obj(profile, self.id, obj)

                collided = True

            if self.state & PhysicsState.Missile:
                self.state &= ~(PhysicsState.Missile | PhysicsState.AlignPath | PhysicsState.PathClipped)

        if obj.state & PhysicsState.ReportCollisions and not self.state & PhysicsState.IgnoreCollisions and obj.weenie_obj is not None:
            # acclient might have a bug here, prev_has_contact and missile state params swapped? (ACE)
            profile = obj.build_collision_profile(self, bool(obj.transient_state & TransientState.Contact), velocity_collide)

            # ObjID and obj are custom parameters added by ace (ACE)
            obj.weenie_obj.do_collision_obj(profile, self.id, obj)

            collided = True

        return collided

    @anchor("CPhysicsObj::build_collision_profile", "PhysicsObj.cs:build_collision_profile(PhysicsObj, bool, Vector3)")
    def build_collision_profile(self, obj, am_i_in_contact: bool, velocity_collide):
        if self.state & PhysicsState.Missile:
            from .atk_collision_profile import AtkCollisionProfile

            return AtkCollisionProfile.create_atk(obj.id, -1, obj.position.determine_quadrant(obj.get_height(), self.position))
        else:
            return self.build_collision_profile_for(obj, velocity_collide, am_i_in_contact,
                                                    bool(obj.state & PhysicsState.Missile),
                                                    bool(obj.transient_state & TransientState.Contact))

    @anchor("CPhysicsObj::build_collision_profile",
            "PhysicsObj.cs:build_collision_profile(PhysicsObj, Vector3, bool, bool, bool)", "the overload the first calls")
    def build_collision_profile_for(self, obj, velocity, am_i_in_contact: bool, obj_is_missile: bool, obj_has_contact: bool):
        if self.weenie_obj is None:
            return None

        profile = ObjCollisionProfile.create(obj.id, velocity, obj_is_missile, obj_has_contact, am_i_in_contact)

        self.weenie_obj.inq_collision_profile(profile)

        return profile

    @anchor("CPhysicsObj::calc_cross_cells", "PhysicsObj.cs:calc_cross_cells")
    def calc_cross_cells(self, lscape) -> None:
        self.cell_array.set_dynamic()

        if self.state & PhysicsState.HasPhysicsBSP:
            self.find_bbox_cell_list(self.cell_array, lscape)
        else:
            # SetPositionInternal calls it only with HasPhysicsBSP; recalc_cross_cells (a child) without
            if self.part_array is not None and self.part_array.get_num_cylsphere() != 0:
                obj_cell.find_cell_list_cyl(lscape, self.position, self.part_array.get_num_cylsphere(),
                                            self.part_array.get_cyl_sphere(), self.cell_array, None)
            else:
                # added sorting sphere null check (ACE)
                if self.part_array is not None and self.part_array.setup.sorting_sphere is not None:
                    sphere = self.part_array.get_sorting_sphere()
                else:
                    sphere = _dummy_sphere(self.mode)
                obj_cell.find_cell_list_sphere(lscape, self.position, sphere, self.cell_array, None)
        self.remove_shadows_from_cells()
        self.add_shadows_to_cell(self.cell_array)

    @anchor("CPhysicsObj::add_obj_to_cell", "PhysicsObj.cs:add_obj_to_cell")
    def add_obj_to_cell(self, new_cell, new_frame, lscape) -> None:
        """The run's world `lscape` stands in for ACE's static LScape."""
        self.enter_cell(new_cell, lscape)

        self.position.frame = new_frame
        if self.part_array is not None and not self.state & PhysicsState.ParticleEmitter:
            self.part_array.set_frame(self.position.frame)

        self.update_children_internal()
        self.calc_cross_cells_static(lscape)

    @anchor("CPhysicsObj::enter_cell", "PhysicsObj.cs:enter_cell")
    def enter_cell(self, new_cell, lscape) -> None:
        if self.part_array is None:
            return
        new_cell.add_object(self)
        for child in self.children.objects:
            child.enter_cell(new_cell, lscape)

        self.cur_cell = new_cell
        self.position.obj_cell_id = new_cell.id  # (ACE) Position inconsistent until set_frame runs
        if self.part_array is not None and not self.state & PhysicsState.ParticleEmitter:
            self.part_array.set_cell_id(new_cell.id)

        if not self.dat_object and new_cell is not None:
            self.cur_landblock = lscape.get_landblock(new_cell.id)
            if self.cur_landblock is not None:
                self.cur_landblock.add_server_object(self)

    # ------------------------------------------------------------------ children (ChildList, set_parent)
    @anchor("CPhysicsObj::UpdateChild", "PhysicsObj.cs:UpdateChild")
    def update_child(self, child_obj: "PhysicsObj", part_idx: int, child_frame: AFrame) -> None:
        """The child's frame is its holding frame in the parent's part `part_idx`, or in the parent's
        Position for an index past the parts. A part's Pos is what PartArray.UpdateParts last made it:
        on the server only an object with a physics BSP updates its parts in set_frame, so a child
        held by another object's part stays where the part was."""
        if part_idx >= self.part_array.num_parts:
            frame = AFrame.combine(self.position.frame, child_frame)
        else:
            if part_idx < 0:  # Parts[-1]: a List's indexer throws (a part index -1, add_child's "no part")
                raise ArgumentOutOfRangeException(f"Parts[{part_idx}] of a PartArray of {self.part_array.num_parts} parts")
            frame = AFrame.combine(self.part_array.parts[part_idx].pos.frame, child_frame)

        child_obj.set_frame(frame)

        if child_obj.particle_manager is not None:
            child_obj.particle_manager.update_particles()
        if child_obj.script_manager is not None:
            child_obj.script_manager.update_scripts()

    @anchor("CPhysicsObj::UpdateChildrenInternal", "PhysicsObj.cs:UpdateChildrenInternal")
    def update_children_internal(self) -> None:
        if self.part_array is None or self.children is None or self.children.num_objects == 0:
            return

        for i in range(len(self.children.objects)):  # Objects.Count, not NumObjects (ACE)
            self.update_child(self.children.objects[i], self.children.part_numbers[i], self.children.frames[i])

    @anchor("CPhysicsObj::add_child", "PhysicsObj.cs:add_child(PhysicsObj, int)")
    def add_child(self, obj: "PhysicsObj", where: int) -> bool:
        """At the Setup's holding location `where` (ParentLocation): its part and frame."""
        if self.part_array is None or obj.equals(self):
            return False

        setup = self.part_array.setup.get_holding_location(where)
        if setup is None:
            return False

        if self.children is None:
            self.children = ChildList()
        self.children.add_child(obj, AFrame.from_dat(setup.frame), setup.part_id, where)
        return True

    @anchor("CPhysicsObj::add_child", "PhysicsObj.cs:add_child(PhysicsObj, int, AFrame)")
    def add_child_frame(self, obj: "PhysicsObj", part_idx: int, frame: AFrame) -> bool:
        """At part `part_idx` (-1: the Position) with `frame` itself (not a copy), location 0."""
        if obj.equals(self):
            return False

        if self.part_array is None or part_idx != -1 and part_idx >= self.part_array.num_parts:
            return False

        if self.children is None:
            self.children = ChildList()
        self.children.add_child(obj, frame, part_idx, 0)
        return True

    @anchor("CPhysicsObj::set_parent", "PhysicsObj.cs:set_parent(PhysicsObj, int)")
    def set_parent(self, obj: "PhysicsObj | None", idx: int, lscape) -> bool:
        """Held at `obj`'s holding location `idx`. `lscape` is the run's world (ACE's static LScape),
        which change_cell and recalc_cross_cells read."""
        if obj is None:
            return False
        if not obj.add_child(self, idx):
            return False

        self.unset_parent()
        self.leave_world()

        self.parent = obj

        if obj.cur_cell is not None:
            self.change_cell(obj.cur_cell, lscape)

            if obj.children is not None:
                index = obj.children.find_child_index(self)
                if index != -1:
                    obj.update_child(self, obj.children.part_numbers[index], obj.children.frames[index])
                    self.recalc_cross_cells(lscape)

        if self.parent.state & PhysicsState.Hidden:
            self.state |= PhysicsState.NoDraw
            if self.part_array is not None:
                self.part_array.set_no_draw_internal(True)

        return True

    @anchor("CPhysicsObj::set_parent", "PhysicsObj.cs:set_parent(PhysicsObj, int, AFrame)")
    def set_parent_frame(self, obj: "PhysicsObj | None", part_idx: int, frame: AFrame, lscape) -> bool:
        """Held at `obj`'s part `part_idx` with `frame` (ParticleEmitter.SetParenting's call)."""
        if obj is None:
            return False
        if not obj.add_child_frame(self, part_idx, frame):
            return False

        self.examination_object = obj.examination_object

        self.unset_parent()
        self.leave_world()

        self.parent = obj

        if obj.cur_cell is not None:
            self.change_cell(obj.cur_cell, lscape)
            obj.update_child(self, part_idx, frame)
            self.recalc_cross_cells(lscape)

        return True

    @anchor("CPhysicsObj::unparent_children", "PhysicsObj.cs:unparent_children")
    def unparent_children(self) -> None:
        """``foreach (var child in Children.Objects) child.unset_parent()``: each unset_parent removes
        the child from the list being walked (RemoveChild, the one change that list sees, shortens
        it), and .NET's List enumerator then throws InvalidOperationException at its next MoveNext,
        as ACE does after the first child (nothing in ACE calls this)."""
        if self.children is None:
            return
        objects = self.children.objects
        i = 0
        while i < len(objects):
            count = len(objects)
            child = objects[i]
            i += 1
            child.unset_parent()
            if len(objects) != count:
                raise InvalidOperationException("Collection was modified; enumeration operation may not execute.")

    @anchor("CPhysicsObj::unset_parent", "PhysicsObj.cs:unset_parent")
    def unset_parent(self) -> None:
        """ACE clears Hidden (not the NoDraw set_parent set) when the parent is hidden."""
        if self.parent is None:
            return
        if self.parent.children is not None:
            self.parent.children.remove_child(self)
        if self.parent.state & PhysicsState.Hidden:
            self.state &= ~PhysicsState.Hidden
            if self.part_array is not None:
                self.part_array.set_no_draw_internal(False)
        self.parent = None
        self.update_time = self.timer.current_time
        self.clear_transient_states()

    @anchor("CPhysicsObj::leave_world", "PhysicsObj.cs:leave_world")
    def leave_world(self) -> None:
        """ObjMaint.RemoveObjectToBeDestroyed (a queue nothing here reads) is not kept."""
        self.report_collision_end(True)
        self.transient_state &= ~TransientState.Active
        self.remove_shadows_from_cells()
        self.leave_cell(False)

        self.position.obj_cell_id = 0
        if self.part_array is not None and not self.state & PhysicsState.ParticleEmitter:
            self.part_array.set_cell_id(0)

        self.transient_state &= ~TransientState.Contact
        self.calc_acceleration()
        walkable = bool(self.transient_state & TransientState.OnWalkable)
        self.transient_state &= ~(TransientState.OnWalkable | TransientState.WaterContact)
        if self.movement_manager is not None and walkable:
            self.movement_manager.leave_ground()
        self.calc_acceleration()
        self.transient_state = 0

    @anchor("CPhysicsObj::clear_transient_states", "PhysicsObj.cs:clear_transient_states")
    def clear_transient_states(self) -> None:
        self.transient_state &= ~TransientState.Contact
        self.calc_acceleration()
        walkable = bool(self.transient_state & TransientState.OnWalkable)
        self.transient_state &= ~(TransientState.OnWalkable | TransientState.WaterContact)
        if self.movement_manager is not None and walkable:
            self.movement_manager.leave_ground()
        self.calc_acceleration()
        self.transient_state = 0

    @anchor("CPhysicsObj::recalc_cross_cells", "PhysicsObj.cs:recalc_cross_cells")
    def recalc_cross_cells(self, lscape) -> None:
        if self.part_array is None:
            return
        if self.position.obj_cell_id != 0:
            self.calc_cross_cells(lscape)
        else:
            if not self.examination_object or not self.state & PhysicsState.ParticleEmitter:
                return
            self.add_particle_shadow_to_cell()
        for child in self.children.objects:
            child.recalc_cross_cells(lscape)

    @anchor("CPhysicsObj::set_cell_id_recursive", "PhysicsObj.cs:set_cell_id_recursive")
    def set_cell_id_recursive(self, new_cell_id: int) -> None:
        self.set_cell_id(new_cell_id)
        for i in range(len(self.children.objects)):
            child = self.children.objects[i]
            if child is not None:
                child.set_cell_id_recursive(new_cell_id)

    @anchor("CPhysicsObj::SetPlacementFrame", "PhysicsObj.cs:SetPlacementFrame")
    def set_placement_frame(self, frame_id: int, send_event: bool) -> bool:
        return self.set_placement_frame_internal(frame_id)

    @anchor("CPhysicsObj::SetPlacementFrameInternal", "PhysicsObj.cs:SetPlacementFrameInternal")
    def set_placement_frame_internal(self, frame_id: int) -> bool:
        result = False
        if self.part_array is not None:
            result = self.part_array.set_placement_frame(frame_id)
            if not self.state & PhysicsState.ParticleEmitter:
                self.part_array.set_frame(self.position.frame)
        return result

    @anchor("CPhysicsObj::calc_cross_cells_static", "PhysicsObj.cs:calc_cross_cells_static")
    def calc_cross_cells_static(self, lscape) -> None:
        self.cell_array.set_static()

        if (self.part_array is not None and self.part_array.get_num_cylsphere() != 0
                and not self.state & PhysicsState.HasPhysicsBSP):
            obj_cell.find_cell_list_cyl(lscape, self.position, self.part_array.get_num_cylsphere(),
                                        self.part_array.get_cyl_sphere(), self.cell_array, None)
        else:
            self.find_bbox_cell_list(self.cell_array, lscape)

        self.remove_shadows_from_cells()
        self.add_shadows_to_cell(self.cell_array)

    @anchor("CPhysicsObj::find_bbox_cell_list", "PhysicsObj.cs:find_bbox_cell_list")
    def find_bbox_cell_list(self, cell_array, lscape) -> None:
        if self.part_array is None or self.cur_cell is None:
            return
        cell_array.num_cells = 0
        cell_array.added_outside = False
        cell_array.add_cell(self.cur_cell.id, self.cur_cell)

        i = 0
        while i < len(cell_array.cells):  # Count re-read each pass, as ACE's for loop does
            cell = cell_array.cells.value_at(i)
            i += 1
            if cell is None:
                continue
            self.part_array.calc_cross_cells_static(cell, cell_array, lscape)

    @anchor("CPhysicsObj::remove_shadows_from_cells", "PhysicsObj.cs:remove_shadows_from_cells")
    def remove_shadows_from_cells(self) -> None:
        """Each ShadowObj leaves its cell's list (its Cell becomes null); ShadowObjects itself keeps
        every key it ever had, as ACE's dictionary does."""
        for shadow_obj in self.shadow_objects.values():
            if shadow_obj.cell is None:
                continue
            cell = shadow_obj.cell
            shadow_obj.cell.remove_shadow_object(shadow_obj)
            if self.part_array is not None:
                self.part_array.remove_parts(cell)
        self.num_shadow_objects = 0  # should be ShadowObjects.Count (ACE)
        i = 0
        while True:
            total_childs = 0 if self.children is None else self.children.num_objects
            if i >= total_childs:
                break
            if self.children is not None:
                child = self.children.item(i)  # Children.Objects[i++] (ACE)
                i += 1
                child.remove_shadows_from_cells()
            else:
                self.remove_shadows_from_cells()

    @anchor("CPhysicsObj::add_particle_shadow_to_cell", "PhysicsObj.cs:add_particle_shadow_to_cell")
    def add_particle_shadow_to_cell(self) -> None:
        """One ShadowObj in CurCell under key 1, which the cell's shadow list never holds (so no
        transition meets it). ShadowObjects.Add throws when key 1 is there already: the second
        call for one object (remove_shadows_from_cells keeps the keys)."""
        self.num_shadow_objects = 1

        shadow_obj = ShadowObj.create(self, self.cur_cell)
        if 1 in self.shadow_objects:
            raise ArgumentException("An item with the same key has already been added. Key: 1")
        self.shadow_objects[1] = shadow_obj

        if self.part_array is not None:
            self.part_array.add_parts_shadow(self.cur_cell, 1)

    @anchor("CPhysicsObj::add_shadows_to_cell", "PhysicsObj.cs:add_shadows_to_cell(CellArray)")
    def add_shadows_to_cell(self, cell_array) -> None:
        if self.state & PhysicsState.ParticleEmitter:
            self.add_particle_shadow_to_cell()
        else:
            for cell in cell_array.cells.values():
                if cell is None:
                    continue  # fixme (ACE)

                shadow_obj = ShadowObj.create(self, cell)
                # ShadowObjects.Add or overwrite: a .NET Dictionary keeps the key's slot either way
                self.shadow_objects[cell.id] = shadow_obj

                if cell is not None:
                    cell.add_shadow_object(shadow_obj)

                if self.part_array is not None:
                    self.part_array.add_parts_shadow(cell, self.num_shadow_objects)
        if self.children is not None:
            for child in self.children.objects:
                child.add_shadows_to_cell(cell_array)

    @anchor("CPhysicsObj::is_completely_visible", "PhysicsObj.cs:is_completely_visible")
    def is_completely_visible(self) -> bool:
        if self.cur_cell is None or self.num_shadow_objects == 0:
            return False

        for shadow_obj in self.shadow_objects.values():
            if shadow_obj.cell is None:
                return False
        return True

    @anchor("CPhysicsObj::check_contact", "PhysicsObj.cs:check_contact")
    def check_contact(self, contact: bool) -> bool:
        if self.transient_state & TransientState.Contact and dot(self.velocity, self.contact_plane.normal) > EPSILON:
            return False
        return contact

    @anchor("CPhysicsObj::get_object_info", "PhysicsObj.cs:get_object_info")
    def get_object_info(self, transition: Transition, admin_move: bool) -> ObjectInfo:
        obj_info = ObjectInfo()
        if self.state & PhysicsState.EdgeSlide:
            obj_info.state |= ObjectInfoState.EdgeSlide

        if not admin_move:
            if self.transient_state & TransientState.Contact:
                is_water = bool(self.transient_state & TransientState.WaterContact)
                if self.check_contact(True):
                    transition.init_contact_plane(self.contact_plane_cell_id, self.contact_plane, is_water)
                    obj_info.state |= ObjectInfoState.Contact
                    if self.transient_state & TransientState.OnWalkable:
                        obj_info.state |= ObjectInfoState.OnWalkable
                else:
                    if transition.trace is not None:
                        transition.trace["get_object_info:leaving_contact"] += 1
                    transition.init_last_known_contact_plane(self.contact_plane_cell_id, self.contact_plane, is_water)

            if self.transient_state & TransientState.Sliding:
                transition.init_sliding_normal(self.sliding_normal)

        if self.part_array is not None and self.part_array.allows_free_heading():
            obj_info.state |= ObjectInfoState.FreeRotate

        if self.state & PhysicsState.Missile:
            obj_info.state |= ObjectInfoState.PathClipped

        return obj_info

    @anchor("CPhysicsObj::get_walkable_z", "PhysicsObj.cs:get_walkable_z")
    def get_walkable_z(self):
        return type(self.scale)(FLOOR_Z)

    @staticmethod
    @anchor("CPhysicsObj::is_valid_walkable", "PhysicsObj.cs:is_valid_walkable")
    def is_valid_walkable(normal: Vector3) -> bool:
        return bool(normal.z >= FLOOR_Z)

    @anchor("CPhysicsObj::set_velocity", "PhysicsObj.cs:set_velocity")
    def set_velocity(self, velocity: Vector3, send_event: bool) -> None:
        if not velocity == self.velocity:
            self.velocity = velocity
            if self.velocity.length() > MAX_VELOCITY:
                self.velocity = self.velocity / self.velocity.length()  # todo: add normalize method (ACE)
                self.velocity = self.velocity * MAX_VELOCITY
            self.jumped_this_frame = True

        if not self.state & PhysicsState.Static:
            if not self.transient_state & TransientState.Active:
                self.update_time = self.timer.current_time

            self.transient_state |= TransientState.Active

    @anchor("CPhysicsObj::set_local_velocity", "PhysicsObj.cs:set_local_velocity")
    def set_local_velocity(self, new_vel: Vector3, send_event: bool) -> None:
        global_vec = self.position.local_to_global_vec(new_vel)
        self.set_velocity(global_vec, send_event)

    @anchor("CPhysicsObj::set_omega", "PhysicsObj.cs:set_omega")
    def set_omega(self, omega: Vector3, send_event: bool) -> None:
        self.omega = omega

    @anchor("CPhysicsObj::set_initial_frame", "PhysicsObj.cs:set_initial_frame")
    def set_initial_frame(self, frame: AFrame) -> None:
        """Position.Frame is the frame itself (no copy), and the parts follow it whatever the
        engine mode (unlike set_frame)."""
        self.position.frame = frame

        if self.part_array is not None and not self.state & PhysicsState.ParticleEmitter:
            self.part_array.set_frame(frame)

        self.update_children_internal()

    @anchor("CPhysicsObj::set_ethereal", "PhysicsObj.cs:set_ethereal")
    def set_ethereal(self, ethereal: bool, send_event: bool, lscape) -> bool:
        if ethereal:
            self.state |= PhysicsState.Ethereal
            self.transient_state &= ~TransientState.CheckEthereal
            return True

        self.state &= ~PhysicsState.Ethereal

        if self.parent is not None or self.cur_cell is None or not self.ethereal_check_for_collisions(lscape):
            self.transient_state &= ~TransientState.CheckEthereal
            return True

        # error path - go back to ethereal, start loop in CheckEthereal state (ACE)
        self.state |= PhysicsState.Ethereal
        self.transient_state |= TransientState.CheckEthereal
        return False

    @anchor("CPhysicsObj::ethereal_check_for_collisions", "PhysicsObj.cs:ethereal_check_for_collisions")
    def ethereal_check_for_collisions(self, lscape) -> bool:
        for shadow_obj in self.shadow_objects.values():
            if shadow_obj.cell is not None and shadow_obj.cell.check_collisions(self, lscape):
                return True
        return False

    @anchor("CPhysicsObj::check_collision", "PhysicsObj.cs:check_collision")
    def check_collision(self, obj, lscape) -> bool:
        """Whether `obj` collides with this object standing where it is (MakeTransition is a new
        Transition of the run)."""
        if self.state & PhysicsState.Static:
            return False

        mode = lscape.mode
        trans = Transition(mode, lscape, None)
        object_info = self.get_object_info(trans, False)
        trans.init_object(self, object_info.state)

        if self.part_array is not None and self.part_array.get_num_sphere() != 0:
            trans.init_sphere(self.part_array.get_num_sphere(), self.part_array.get_sphere(), self.scale)
        else:
            trans.init_sphere(1, [_dummy_sphere(mode)], self.scale)

        trans.init_path(self.cur_cell, self.position, self.position)
        return trans.check_collisions(obj)

    @anchor(None, "PhysicsObj.cs:IsMovingOrAnimating")
    def is_moving_or_animating(self) -> bool:
        """ACE's property, evaluated left to right: with no MovementManager, an object that is
        neither animating nor moving reaches ``MovementManager.MotionInterpreter`` and throws
        NullReferenceException (AttributeError on None here, which run_scene reports as that)."""
        return bool(self.is_animating or not self.part_array.sequence.is_first_cyclic()
                    or not self.cached_velocity == Vector3(0.0, 0.0, 0.0) or not self.velocity == Vector3(0.0, 0.0, 0.0)
                    or self.movement_manager.motion_interpreter.interpreted_state.has_commands()
                    or self.movement_manager.move_to_manager.initialized)

    @anchor("CPhysicsObj::RemoveLinkAnimations", "PhysicsObj.cs:RemoveLinkAnimations")
    def remove_link_animations(self) -> None:
        if self.part_array is not None:
            self.part_array.handle_enter_world()

    @staticmethod
    @anchor(None, "PhysicsObj.cs:GetBlockDist(Position, Position)")
    def get_block_dist(a, b) -> int:
        # protection, figure out FastTeleport state (ACE)
        if a is None or b is None:
            return 0

        return PhysicsObj.get_block_dist_ids(a.obj_cell_id, b.obj_cell_id)

    @staticmethod
    @anchor(None, "PhysicsObj.cs:GetBlockDist(uint, uint)")
    def get_block_dist_ids(a: int, b: int) -> int:
        """``(int)lbx_a - lbx_b`` is int minus uint, computed in long: no wraparound."""
        lbx_a = a >> 24
        lby_a = (a >> 16) & 0xFF

        lbx_b = b >> 24
        lby_b = (b >> 16) & 0xFF

        dx = abs(lbx_a - lbx_b)
        dy = abs(lby_a - lby_b)

        return max(dx, dy)

    @anchor("CPhysicsObj::process_hooks", "PhysicsObj.cs:process_hooks")
    def process_hooks(self) -> None:
        """Runs and clears the hooks: no PhysicsObjHook is ever queued here; the AnimationHooks are
        the Sequence's (a frame's hooks, AnimDoneHook), run by AnimHook.Execute."""
        for hook in self.hooks:
            raise NotImplementedError("physics object hooks (PhysicsObjHook.Execute) are not ported")
        self.hooks.clear()

        for anim_hook in self.anim_hooks:
            anim_hook_execute(self, anim_hook)
        self.anim_hooks.clear()

    @anchor("CPhysicsObj::calc_friction", "PhysicsObj.cs:calc_friction")
    def calc_friction(self, quantum: float, velocity_mag2, trace=None) -> None:
        """`quantum` is a double (UpdatePhysicsInternal's float, widened); ``Math.Pow(1.0f -
        friction, quantum)`` in double, cast to float."""
        if not self.transient_state & TransientState.OnWalkable:
            return

        angle = dot(self.velocity, self.contact_plane.normal)
        if angle >= FRICTION_LEAVING_ANGLE:
            _hit(trace, "calc_friction:leaving_plane")
            return

        self.velocity = self.velocity - self.contact_plane.normal * angle

        friction = self.friction
        if self.state & PhysicsState.Sledding:
            if trace is not None:
                trace.boundary("sledding_stop_speed", velocity_mag2, SLEDDING_STOP_SPEED_SQUARED)
                trace.boundary("sledding_glide_speed", velocity_mag2, SLEDDING_GLIDE_SPEED_SQUARED)
                trace.boundary("sledding_flat_z", self.contact_plane.normal.z, SLEDDING_FLAT_Z)
            if velocity_mag2 < SLEDDING_STOP_SPEED_SQUARED:
                _hit(trace, "calc_friction:sledding_stop")
                friction = type(friction)(SLEDDING_STOP_FRICTION)

            elif velocity_mag2 >= SLEDDING_GLIDE_SPEED_SQUARED and self.contact_plane.normal.z > SLEDDING_FLAT_Z:
                _hit(trace, "calc_friction:sledding_glide")
                friction = type(friction)(SLEDDING_GLIDE_FRICTION)

        scalar = cast_float(friction, math.pow(float(1.0 - friction), float(quantum)))
        self.velocity = self.velocity * scalar

    @anchor("CPhysicsObj::UpdatePhysicsInternal", "PhysicsObj.cs:UpdatePhysicsInternal")
    def update_physics_internal(self, quantum, frame_offset: AFrame, trace=None) -> None:
        """`quantum` is a float; `frame_offset` (C# `ref AFrame`) is changed in place."""
        velocity_mag2 = self.velocity.length_squared()

        if velocity_mag2 <= 0.0:
            if self.movement_manager is None and self.transient_state & TransientState.OnWalkable:
                self.transient_state &= ~TransientState.Active
        else:
            if trace is not None:
                trace.boundary("max_velocity", velocity_mag2, MAX_VELOCITY_SQUARED)
                trace.boundary("small_velocity", velocity_mag2 - SMALL_VELOCITY_SQUARED, EPSILON)
            if velocity_mag2 > MAX_VELOCITY_SQUARED:
                _hit(trace, "update_physics:velocity_clamped")
                self.velocity = normalize(self.velocity) * MAX_VELOCITY
                velocity_mag2 = type(velocity_mag2)(MAX_VELOCITY_SQUARED)
            # todo: collision normals (ACE)
            self.calc_friction(quantum, velocity_mag2, trace)

            if velocity_mag2 - SMALL_VELOCITY_SQUARED < EPSILON:
                _hit(trace, "update_physics:small_velocity_zeroed")
                z = type(velocity_mag2)(0.0)
                self.velocity = Vector3(z, z, z)

            movement = self.acceleration * 0.5 * quantum * quantum + self.velocity * quantum
            frame_offset.origin = frame_offset.origin + movement

        self.velocity = self.velocity + self.acceleration * quantum
        frame_offset.grotate(self.omega * quantum)

    @anchor("CPhysicsObj::UpdatePositionInternal", "PhysicsObj.cs:UpdatePositionInternal")
    def update_position_internal(self, quantum: float, new_frame: AFrame, mode, trace=None) -> AFrame:
        """`quantum` is a double. Returns the new frame (C# `ref AFrame newFrame`, replaced by
        AFrame.Combine)."""
        offset_frame = AFrame.identity(mode)

        if not self.state & PhysicsState.Hidden:
            if self.part_array is not None:
                offset_frame = self.part_array.update(quantum, offset_frame)  # C# `ref offsetFrame`

            if self.transient_state & TransientState.OnWalkable:
                offset_frame.origin = offset_frame.origin * self.scale
            else:
                offset_frame.origin = offset_frame.origin * 0.0  # OnWalkable getting reset? (ACE)
        if self.position_manager is not None:
            self.position_manager.adjust_offset(offset_frame, quantum)

        new_frame = AFrame.combine(self.position.frame, offset_frame)

        if not self.state & PhysicsState.Hidden:
            self.update_physics_internal(cast_float(self.scale, quantum), new_frame, trace)

        self.process_hooks()
        return new_frame

    @anchor("CPhysicsObj::UpdateObjectInternal", "PhysicsObj.cs:UpdateObjectInternal")
    def update_object_internal(self, quantum: float, lscape, trace=None) -> None:
        """`quantum` is a double. The run's world `lscape` stands in for ACE's static LScape."""
        if not self.transient_state & TransientState.Active or self.cur_cell is None:
            _hit(trace, "update_object_internal:inactive")
            return

        if self.transient_state & TransientState.CheckEthereal:
            self.set_ethereal(False, False, lscape)

        mode = lscape.mode
        self.jumped_this_frame = False
        new_pos = Position(self.position.obj_cell_id, AFrame.identity(mode))
        new_pos.frame = self.update_position_internal(quantum, new_pos.frame, mode, trace)

        zero = Vector3(type(self.scale)(0.0), type(self.scale)(0.0), type(self.scale)(0.0))
        if self.part_array is not None and self.part_array.get_num_sphere() != 0:
            if new_pos.frame.equals(self.position.frame):
                _hit(trace, "update_object_internal:unmoved")
                self.cached_velocity = zero
                self.set_frame(new_pos.frame, lscape)
                self.initial_updates += 1
            else:
                if self.state & PhysicsState.AlignPath:
                    diff = new_pos.frame.origin - self.position.frame.origin
                    new_pos.frame.set_vector_heading(normalize(diff))
                elif self.state & PhysicsState.Sledding and not self.velocity == zero:
                    new_pos.frame.set_vector_heading(normalize(self.velocity))

                if PhysicsObj.get_block_dist(self.position, new_pos) > 1:
                    _hit(trace, "update_object_internal:block_dist_refused")
                    return

                transit, valid = self.transition(self.position, new_pos, False, lscape, trace)

                # temporarily modified while debug path is examined (ACE); transition() is null when not valid
                if valid and transit.sphere_path.cur_cell is not None:
                    self.cached_velocity = self.position.get_offset(transit.sphere_path.cur_pos) / cast_float(self.scale, quantum)

                    self.set_position_internal(transit)
                else:
                    _hit(trace, "update_object_internal:transition_failed")
                    new_pos.frame.origin = self.position.frame.origin
                    self.set_initial_frame(new_pos.frame)
                    self.cached_velocity = zero
        else:
            if self.movement_manager is None and self.transient_state & TransientState.OnWalkable:
                self.transient_state &= ~TransientState.Active

            new_pos.frame.origin = self.position.frame.origin
            self.set_frame(new_pos.frame, lscape)
            self.cached_velocity = zero
            self.initial_updates += 1

        if self.detection_manager is not None:
            raise NotImplementedError("DetectionManager.CheckDetection is not ported")

        if self.target_manager is not None:
            self.target_manager.handle_targetting()

        if self.movement_manager is not None:
            self.movement_manager.use_time()

        if self.part_array is not None:
            self.part_array.handle_movement()

        if self.position_manager is not None:
            self.position_manager.use_time()

        if self.particle_manager is not None:
            raise NotImplementedError("ParticleManager.UpdateParticles is not ported")

        if self.script_manager is not None:
            self.script_manager.update_scripts()

    @anchor("CPhysicsObj::update_object", "PhysicsObj.cs:update_object")
    def update_object(self, lscape, trace=None) -> bool:
        """One tick: the time since UpdateTime cut into MaxQuantum sub-steps and a last one over
        MinQuantum; a remainder at or under MinQuantum is kept (UpdateTime advances only by the
        sub-steps run). ``deltaTime`` and the clocks are doubles, the float quanta widen to double."""
        if self.parent is not None or self.cur_cell is None or self.state & PhysicsState.Frozen:
            _hit(trace, "update_object:not_in_world")
            self.transient_state &= ~TransientState.Active
            return False

        self.physics_timer_current_time = self.update_time

        delta_time = self.timer.current_time - self.update_time
        if trace is not None:  # the quanta are doubles here: a boundary is bit-equal in double
            if delta_time == TICK_RATE:
                trace["boundary:tick_rate"] += 1
            if delta_time == HUGE_QUANTUM:
                trace["boundary:huge_quantum"] += 1

        if delta_time < TICK_RATE:
            _hit(trace, "update_object:tick_rate_gate")
            return False

        # commented out for debugging (ACE)
        if delta_time > HUGE_QUANTUM:
            _hit(trace, "update_object:huge_quantum_skip")
            self.update_time = self.timer.current_time  # consume time? (ACE)
            return False

        while delta_time > MAX_QUANTUM:
            _hit(trace, "update_object:max_quantum_step")
            self.physics_timer_current_time += MAX_QUANTUM
            self.update_object_internal(MAX_QUANTUM, lscape, trace)
            delta_time -= MAX_QUANTUM

        if trace is not None:
            if delta_time == MAX_QUANTUM:
                trace["boundary:max_quantum"] += 1
            if delta_time == MIN_QUANTUM:
                trace["boundary:min_quantum"] += 1
        if delta_time > MIN_QUANTUM:
            _hit(trace, "update_object:remainder_step")
            self.physics_timer_current_time += delta_time
            self.update_object_internal(delta_time, lscape, trace)
        else:
            _hit(trace, "update_object:remainder_kept")

        self.update_time = self.physics_timer_current_time
        return True

    @anchor(None, "PhysicsObj.cs:UpdateObjectInternalServer")
    def update_object_internal_server(self, quantum: float, lscape, trace=None) -> bool:
        """The legacy player path: a transition to RequestPos. `quantum` is a double."""
        if PhysicsObj.get_block_dist(self.position, self.request_pos) > 1:
            _hit(trace, "update_object_internal_server:block_dist_refused")
            return False

        request_cell = self.request_pos.obj_cell_id

        transit, valid = self.transition(self.position, self.request_pos, False, lscape, trace)
        if valid:  # transition() is null when not valid
            self.cached_velocity = self.position.get_offset(transit.sphere_path.cur_pos) / cast_float(self.scale, quantum)
            self.set_position_internal(transit)
        else:
            _hit(trace, "update_object_internal_server:transition_failed")

        if self.detection_manager is not None:
            raise NotImplementedError("DetectionManager.CheckDetection is not ported")

        if self.target_manager is not None:
            self.target_manager.handle_targetting()

        if self.movement_manager is not None:
            self.movement_manager.use_time()

        if self.part_array is not None:
            self.part_array.handle_movement()

        if self.position_manager is not None:
            self.position_manager.use_time()

        if self.particle_manager is not None:
            raise NotImplementedError("ParticleManager.UpdateParticles is not ported")

        if self.script_manager is not None:
            self.script_manager.update_scripts()

        return request_cell >> 16 != 0x18A or (self.cur_cell is not None and self.cur_cell.id >> 16 == request_cell >> 16)

    @anchor(None, "PhysicsObj.cs:update_object_server")
    def update_object_server(self, force_pos: bool, lscape, trace=None) -> bool:
        delta_time = self.timer.current_time - self.update_time

        wo = self.weenie_obj.world_object
        success = True
        if wo is not None and not wo.teleporting:
            success = self.update_object_internal_server(delta_time, lscape, trace)

        if force_pos and success:
            self.set_current_pos(self.request_pos, lscape)

        # temp for players (ACE)
        if self.transient_state & TransientState.Contact:
            z = type(self.scale)(0.0)
            self.cached_velocity = Vector3(z, z, z)

        if wo is not None and wo.teleporting:
            raise NotImplementedError("a teleporting WorldObject (update_object_server's SetPosition) is not ported")

        self.update_time = self.timer.current_time
        return success

    @anchor(None, "PhysicsObj.cs:set_request_pos")
    def set_request_pos(self, pos: Vector3, rotation, cell, block_cell_id: int, lscape) -> None:
        self.request_pos.frame.origin = pos
        self.request_pos.frame.orientation = rotation

        if self.cur_cell is None:
            self.cur_cell = lscape.get_landcell(block_cell_id)
            if self.cur_cell is None:
                return

        if cell is None:
            self.request_pos.obj_cell_id = self.request_pos.get_cell(self.cur_cell.id, lscape.mode.runtime, lscape)
        else:
            self.request_pos.obj_cell_id = cell.id

        self.request_cached_velocity = self.cached_velocity

    @anchor(None, "PhysicsObj.cs:set_current_pos")
    def set_current_pos(self, new_pos, lscape) -> None:
        from .cell.land_cell import LandCell

        self.position.obj_cell_id = new_pos.obj_cell_id
        self.position.frame = new_pos.frame.copy()

        if self.cur_cell is None or self.cur_cell.id != self.position.obj_cell_id:
            new_cell = lscape.get_landcell(new_pos.obj_cell_id)

            player = self.weenie_obj.world_object  # ACE: WeenieObj.WorldObject as Player
            if isinstance(player, Player) and player.last_contact and isinstance(new_cell, LandCell):
                found, walkable = new_cell.find_terrain_poly(new_pos.frame.origin, None)
                if found:
                    self.contact_plane_cell_id = new_pos.obj_cell_id
                    self.contact_plane = walkable.plane
            self.change_cell_server(new_cell, lscape)

        self.cached_velocity = self.request_cached_velocity

    # ------------------------------------------------------------ entering the world

    @anchor(None, "PhysicsObj.cs:set_object_guid")
    def set_object_guid(self, guid: int) -> None:
        """ServerObjectManager.AddServerObject(this) files the object by id in the run's table
        (`server_objects`), where GetObjectA finds a MoveTo's, TargetManager's or StickyManager's
        target."""
        self.id = guid
        if self.server_objects is not None:
            self.server_objects.add_server_object(self)

    @anchor(None, "PhysicsObj.cs:set_weenie_obj")
    def set_weenie_obj(self, wobj: WeenieObject) -> None:
        self.weenie_obj = wobj
        if self.movement_manager is not None:
            self.movement_manager.set_weenie_object(wobj)

    @anchor("CPhysicsObj::play_script_internal", "PhysicsObj.cs:play_script_internal")
    def play_script_internal(self, script_id: int) -> bool:
        """Makes the ScriptManager on the first script and hands it the script (which ACE's AddScript
        refuses: the server runs no PhysicsScript)."""
        if script_id == 0:
            return False
        if self.script_manager is None:
            self.script_manager = ScriptManager.create(self)

        return self.script_manager.add_script(script_id)

    @anchor("CPhysicsObj::SetMotionTableID", "PhysicsObj.cs:SetMotionTableID")
    def set_motion_table_id(self, mtable_id: int) -> bool:
        if self.part_array is None:
            return False
        if not self.part_array.set_motion_table_id(mtable_id):
            return False

        self.movement_manager = None
        if mtable_id != 0:
            self.make_movement_manager(True)

        return True

    @anchor("CPhysicsObj::MakeMovementManager", "PhysicsObj.cs:MakeMovementManager")
    def make_movement_manager(self, init_motion: bool) -> None:
        from .managers.movement_manager import MovementManager

        if self.movement_manager is not None:
            return

        self.movement_manager = MovementManager.create(self, self.weenie_obj, self.mode)

        if init_motion:
            self.movement_manager.enter_default_state()

        if not self.state & PhysicsState.Static:
            if not self.transient_state & TransientState.Active:
                self.update_time = self.timer.current_time

            self.transient_state |= TransientState.Active

    @anchor("CPhysicsObj::get_minterp", "PhysicsObj.cs:get_minterp")
    def get_minterp(self):
        from .managers.movement_manager import MovementManager

        if self.movement_manager is None:
            self.movement_manager = MovementManager.create(self, self.weenie_obj, self.mode)
            self.movement_manager.enter_default_state()
            if self.state & PhysicsState.Static:
                if self.transient_state & TransientState.Active:
                    # loword = cmd, hiword = param / refactor... (ACE)
                    self.update_time = self.timer.current_time
                self.transient_state |= TransientState.Active
        return self.movement_manager.get_minterp()

    @anchor("CPhysicsObj::DoMotion", "PhysicsObj.cs:DoMotion")
    def do_motion(self, motion: int, movement_params) -> int:
        from .animation.movement_struct import MovementStruct
        from acconform.motion_enums import MovementType, WeenieError

        self.last_move_was_autonomous = True
        if self.movement_manager is None:
            return WeenieError.NoAnimationTable
        mvs = MovementStruct.create(MovementType.RawCommand, motion, movement_params)
        return self.movement_manager.perform_movement(mvs)

    @anchor("CPhysicsObj::StopMotion", "PhysicsObj.cs:StopMotion")
    def stop_motion(self, motion: int, movement_params, send_event: bool) -> int:
        from .animation.movement_struct import MovementStruct
        from acconform.motion_enums import MovementType, WeenieError

        self.last_move_was_autonomous = True
        if self.movement_manager is None:
            return WeenieError.NoAnimationTable
        mvs = MovementStruct.create(MovementType.StopRawCommand)
        mvs.motion = motion
        mvs.params = movement_params
        return self.movement_manager.perform_movement(mvs)

    @anchor("CPhysicsObj::DoInterpretedMotion", "PhysicsObj.cs:DoInterpretedMotion")
    def do_interpreted_motion(self, motion: int, movement_params) -> int:
        from acconform.motion_enums import WeenieError

        if self.part_array is None:
            return WeenieError.GeneralMovementFailure

        return self.part_array.do_interpreted_motion(motion, movement_params)

    @anchor("CPhysicsObj::StopInterpretedMotion", "PhysicsObj.cs:StopInterpretedMotion")
    def stop_interpreted_motion(self, motion: int, movement_params) -> int:
        from acconform.motion_enums import WeenieError

        if self.part_array is None:
            return WeenieError.GeneralMovementFailure
        return self.part_array.stop_interpreted_motion(motion, movement_params)

    @anchor("CPhysicsObj::StopCompletely", "PhysicsObj.cs:StopCompletely")
    def stop_completely(self, send_event: bool) -> None:
        from .animation.movement_struct import MovementStruct
        from acconform.motion_enums import MovementType

        if self.movement_manager is None:
            return
        mvs = MovementStruct.create(MovementType.StopCompletely)
        self.movement_manager.perform_movement(mvs)

    @anchor("CPhysicsObj::StopCompletely_Internal", "PhysicsObj.cs:StopCompletely_Internal")
    def stop_completely_internal(self) -> None:
        if self.part_array is not None:
            self.part_array.stop_completely_internal()

    @anchor("CPhysicsObj::InitializeMotionTables", "PhysicsObj.cs:InitializeMotionTables")
    def initialize_motion_tables(self) -> None:
        if self.part_array is not None:
            self.part_array.initialize_motion_tables()

    @anchor("CPhysicsObj::CheckForCompletedMotions", "PhysicsObj.cs:CheckForCompletedMotions")
    def check_for_completed_motions(self) -> None:
        if self.part_array is not None:
            self.part_array.check_for_completed_motions()

    @anchor("CPhysicsObj::MotionDone", "PhysicsObj.cs:MotionDone")
    def motion_done(self, motion: int, success: bool) -> None:
        if self.movement_manager is not None:
            self.movement_manager.motion_done(motion, success)

    @anchor("CPhysicsObj::Hook_AnimDone", "PhysicsObj.cs:Hook_AnimDone")
    def hook_anim_done(self) -> None:
        if self.part_array is not None:
            self.part_array.animation_done(True)

    @anchor("CPhysicsObj::add_anim_hook", "PhysicsObj.cs:add_anim_hook")
    def add_anim_hook(self, hook) -> None:
        self.anim_hooks.append(hook)

    @anchor("CPhysicsObj::HasAnims", "PhysicsObj.cs:HasAnims")
    def has_anims(self) -> bool:
        if self.part_array is None:
            return False
        return self.part_array.has_anims()

    @anchor("CPhysicsObj::movement_is_autonomous", "PhysicsObj.cs:movement_is_autonomous")
    def movement_is_autonomous(self) -> bool:
        return self.last_move_was_autonomous

    @anchor("CPhysicsObj::InqInterpretedMotionState", "PhysicsObj.cs:InqInterpretedMotionState")
    def inq_interpreted_motion_state(self):
        if self.movement_manager is None:
            return None
        else:
            return self.movement_manager.inq_interpreted_motion_state()

    @anchor("CPhysicsObj::IsMovingTo", "PhysicsObj.cs:IsMovingTo")
    def is_moving_to(self) -> bool:
        if self.movement_manager is None:
            return False
        else:
            return self.movement_manager.is_moving_to()

    @anchor("CPhysicsObj::cancel_moveto", "PhysicsObj.cs:cancel_moveto")
    def cancel_moveto(self) -> None:
        from acconform.motion_enums import WeenieError

        if self.movement_manager is not None:
            self.movement_manager.cancel_move_to(WeenieError.ActionCancelled)

    def _make_movement_manager_for_move_to(self) -> None:
        """The block MoveToObject, MoveToObject_Internal, TurnToHeading and TurnToObject_Internal
        repeat (ACE's "refactor into common method"): note it clears Active, where
        MakeMovementManager sets it."""
        from .managers.movement_manager import MovementManager

        if self.movement_manager is None:
            self.movement_manager = MovementManager.create(self, self.weenie_obj, self.mode)
            self.movement_manager.enter_default_state()
            if not self.state & PhysicsState.Static:
                if not self.transient_state & TransientState.Active:
                    self.update_time = self.timer.current_time

                self.transient_state &= ~TransientState.Active

    @anchor("CPhysicsObj::MoveToObject", "PhysicsObj.cs:MoveToObject")
    def move_to_object(self, obj: "PhysicsObj", movement_params) -> None:
        self._make_movement_manager_for_move_to()

        zero = self.mode.scalar(0.0)
        height = obj.part_array.get_height() if obj.part_array is not None else zero
        radius = obj.part_array.get_radius() if obj.part_array is not None else zero
        parent = obj.parent if obj.parent is not None else obj

        self.move_to_object_internal(obj, parent.id, radius, height, movement_params)

    @anchor("CPhysicsObj::MoveToObject_Internal", "PhysicsObj.cs:MoveToObject_Internal")
    def move_to_object_internal(self, obj: "PhysicsObj", top_level_id: int, obj_radius, obj_height,
                                movement_params) -> None:
        from .animation.movement_struct import MovementStruct
        from acconform.motion_enums import MovementType

        self._make_movement_manager_for_move_to()
        mvs = MovementStruct()
        # packobj vtable (ACE)
        mvs.top_level_id = top_level_id
        mvs.radius = obj_radius
        mvs.object_id = obj.id
        mvs.params = movement_params
        mvs.type = MovementType.MoveToObject
        mvs.height = obj_height
        self.movement_manager.perform_movement(mvs)

    @anchor("CPhysicsObj::MoveToPosition", "PhysicsObj.cs:MoveToPosition")
    def move_to_position(self, pos, movement_params) -> None:
        """No MovementManager check (ACE has none): a mover without a motion table throws."""
        from .animation.movement_struct import MovementStruct
        from acconform.motion_enums import MovementType

        mvs = MovementStruct()
        mvs.position = pos.copy()
        mvs.type = MovementType.MoveToPosition
        mvs.params = movement_params
        self.movement_manager.perform_movement(mvs)

    @anchor("CPhysicsObj::TurnToHeading", "PhysicsObj.cs:TurnToHeading")
    def turn_to_heading(self, movement_params) -> None:
        from .animation.movement_struct import MovementStruct
        from acconform.motion_enums import MovementType

        self._make_movement_manager_for_move_to()
        mvs = MovementStruct.create(MovementType.TurnToHeading)
        mvs.params = movement_params
        self.movement_manager.perform_movement(mvs)

    @anchor("CPhysicsObj::TurnToObject", "PhysicsObj.cs:TurnToObject")
    def turn_to_object(self, obj: "PhysicsObj", movement_params) -> bool:
        if obj is None:
            return False

        parent = obj.parent if obj.parent is not None else obj

        self.turn_to_object_internal(obj.id, parent.id, movement_params)
        return True

    @anchor("CPhysicsObj::TurnToObject_Internal", "PhysicsObj.cs:TurnToObject_Internal")
    def turn_to_object_internal(self, object_id: int, top_level_id: int, movement_params) -> None:
        from .animation.movement_struct import MovementStruct
        from acconform.motion_enums import MovementType

        self._make_movement_manager_for_move_to()
        mvs = MovementStruct.create(MovementType.TurnToObject)
        mvs.object_id = object_id
        mvs.top_level_id = top_level_id
        mvs.params = movement_params
        self.movement_manager.perform_movement(mvs)

    @anchor("CPhysicsObj::GetObjectA", "PhysicsObj.cs:GetObjectA")
    def get_object_a(self, object_id: int):
        return self.server_objects.get_object_a(object_id)

    @anchor("CPhysicsObj::GetHeight", "PhysicsObj.cs:GetHeight")
    def get_height(self):
        if self.part_array is None:
            return self.mode.scalar(0.0)
        return self.part_array.get_height()

    @anchor("CPhysicsObj::GetRadius", "PhysicsObj.cs:GetRadius")
    def get_radius(self):
        if self.part_array is not None:
            return self.part_array.get_radius()
        else:
            return self.mode.scalar(0.0)

    @anchor("CPhysicsObj::HandleUpdateTarget", "PhysicsObj.cs:HandleUpdateTarget")
    def handle_update_target(self, target_info) -> None:
        if target_info.context_id != 0:
            return

        if self.movement_manager is not None:
            self.movement_manager.handle_update_target(target_info)
        if self.position_manager is not None:
            self.position_manager.handle_update_target(target_info)

    @anchor("CPhysicsObj::MakePositionManager", "PhysicsObj.cs:MakePositionManager")
    def make_position_manager(self) -> None:
        from .managers.position_manager import PositionManager

        if self.position_manager is not None:
            return

        self.position_manager = PositionManager.create(self)

        if not self.state & PhysicsState.Static:
            if not self.transient_state & TransientState.Active:
                self.update_time = self.timer.current_time

            self.transient_state |= TransientState.Active

    @anchor("CPhysicsObj::get_position_manager", "PhysicsObj.cs:get_position_manager")
    def get_position_manager(self):
        self.make_position_manager()

        return self.position_manager

    @anchor("CPhysicsObj::IsInterpolating", "PhysicsObj.cs:IsInterpolating")
    def is_interpolating(self) -> bool:
        if self.position_manager is None:
            return False
        else:
            return self.position_manager.is_interpolating()

    @anchor("CPhysicsObj::IsFullyConstrained", "PhysicsObj.cs:IsFullyConstrained")
    def is_fully_constrained(self) -> bool:
        if self.position_manager is None:
            return False
        else:
            return self.position_manager.is_fully_constrained()

    @anchor("CPhysicsObj::StopInterpolating", "PhysicsObj.cs:StopInterpolating")
    def stop_interpolating(self) -> None:
        if self.position_manager is not None:
            self.position_manager.stop_interpolating()

    @anchor("CPhysicsObj::get_sticky_object", "PhysicsObj.cs:get_sticky_object")
    def get_sticky_object(self) -> int:
        if self.position_manager is None:
            return 0

        return self.position_manager.get_sticky_object_id()

    @anchor("CPhysicsObj::stick_to_object", "PhysicsObj.cs:stick_to_object")
    def stick_to_object(self, object_id: int) -> None:
        """ObjMaint is never null (the constructor makes one)."""
        self.make_position_manager()

        object_a = self.server_objects.get_object_a(object_id)
        if object_a is None:
            return
        if object_a.parent is not None:
            object_a = self.parent

        if object_a.part_array is not None:
            self.position_manager.stick_to(object_a.id, object_a.part_array.get_radius(), object_a.part_array.get_height())
        else:
            zero = self.mode.scalar(0.0)
            self.position_manager.stick_to(object_a.id, zero, zero)

    @anchor("CPhysicsObj::unstick_from_object", "PhysicsObj.cs:unstick_from_object")
    def unstick_from_object(self) -> None:
        if self.position_manager is not None:
            self.position_manager.unstick()

    @anchor("CPhysicsObj::set_target", "PhysicsObj.cs:set_target")
    def set_target(self, context_id: int, object_id: int, radius, quantum: float) -> None:
        from .managers.target_manager import TargetManager

        if self.target_manager is None:
            self.target_manager = TargetManager.create(self)

        self.target_manager.set_target(context_id, object_id, radius, quantum)

    @anchor("CPhysicsObj::set_target_quantum", "PhysicsObj.cs:set_target_quantum")
    def set_target_quantum(self, new_quantum: float) -> None:
        if self.target_manager is not None:
            self.target_manager.set_target_quantum(new_quantum)

    @anchor("CPhysicsObj::get_target_quantum", "PhysicsObj.cs:get_target_quantum")
    def get_target_quantum(self) -> float:
        if self.target_manager is None or self.target_manager.target_info is None:
            return 0.0

        return self.target_manager.target_info.quantum

    @anchor("CPhysicsObj::clear_target", "PhysicsObj.cs:clear_target")
    def clear_target(self) -> None:
        if self.target_manager is not None:
            self.target_manager.clear_target()

    @anchor("CPhysicsObj::add_voyeur", "PhysicsObj.cs:add_voyeur")
    def add_voyeur(self, object_id: int, radius, quantum: float) -> None:
        from .managers.target_manager import TargetManager

        if self.target_manager is None:
            self.target_manager = TargetManager.create(self)
        self.target_manager.add_voyeur(object_id, radius, quantum)

    @anchor("CPhysicsObj::remove_voyeur", "PhysicsObj.cs:remove_voyeur")
    def remove_voyeur(self, object_id: int) -> bool:
        if self.target_manager is None:
            return False
        return self.target_manager.remove_voyeur(object_id)

    @anchor("CPhysicsObj::receive_target_update", "PhysicsObj.cs:receive_target_update")
    def receive_target_update(self, info) -> None:
        if self.target_manager is not None:
            self.target_manager.receive_update(info)

    @anchor("CPhysicsObj::get_heading", "PhysicsObj.cs:get_heading")
    def get_heading(self):
        return self.position.frame.get_heading()

    @anchor("CPhysicsObj::set_heading", "PhysicsObj.cs:set_heading")
    def set_heading(self, degrees, send_event: bool) -> None:
        self.position.frame.set_heading(degrees)
        self.set_frame(self.position.frame)

    @anchor("CPhysicsObj::get_velocity", "PhysicsObj.cs:get_velocity")
    def get_velocity(self):
        return self.cached_velocity

    @anchor("CPhysicsObj::is_active", "PhysicsObj.cs:is_active")
    def is_active(self) -> bool:
        return bool(self.transient_state & TransientState.Active)

    @anchor("CPhysicsObj::exit_world", "PhysicsObj.cs:exit_world")
    def exit_world(self) -> None:
        if self.part_array is not None:
            self.part_array.handle_exit_world()
        if self.movement_manager is not None:
            self.movement_manager.handle_exit_world()
        if self.position_manager is not None:
            self.position_manager.unstick()
        if self.target_manager is not None:
            from .combat.target_info import TargetStatus

            self.target_manager.clear_target()
            self.target_manager.notify_voyeur_of_event(TargetStatus.ExitWorld)
        if self.detection_manager is not None:
            raise NotImplementedError("DetectionManager.DestroyDetectionCylsphere is not ported")

        self.report_collision_end(True)

    @anchor(None, "PhysicsObj.cs:DestroyObject")
    def destroy_object(self) -> None:
        """What the server's Landblock.RemoveWorldObject does to a removed object's physics.
        ObjMaint.DestroyObject: the other objects' ObjMaint tables are not kept (nothing in the
        physics reads them); its last step, ServerObjectManager.RemoveServerObject, is."""
        self.leave_cell(False)
        self.remove_shadows_from_cells()
        self.leave_world()
        self.exit_world()

        if self.server_objects is not None:
            self.server_objects.remove_server_object(self)

    @anchor("CPhysicsObj::enter_world", "PhysicsObj.cs:enter_world(Position)")
    def enter_world(self, pos, lscape, trace=None) -> bool:
        self.entering_world = True

        self.store_position(pos, lscape)
        slide = self.projectile_target is None or isinstance(self.weenie_obj.world_object, SpellProjectile)
        result = self.enter_world_slide(slide, lscape, trace)

        self.entering_world = False
        return result

    @anchor("CPhysicsObj::enter_world", "PhysicsObj.cs:enter_world(bool)")
    def enter_world_slide(self, slide: bool, lscape, trace=None) -> bool:
        if self.parent is not None:
            return False

        self.update_time = self.timer.current_time

        # setPos.Pos is the object's own Position: the placement moves it in place
        flags = SetPositionFlags.Placement
        if slide:
            flags |= SetPositionFlags.Slide

        result = self.set_position(self.position, int(flags), lscape, trace)
        if result != SetPositionError.OK:
            return False

        if not self.state & PhysicsState.Static:
            self.transient_state |= TransientState.Active

        if self.part_array is not None:
            self.part_array.handle_enter_world()

        if self.movement_manager is not None:
            self.movement_manager.handle_enter_world()
        return True

    @anchor("CPhysicsObj::SetPosition", "PhysicsObj.cs:SetPosition")
    def set_position(self, pos, set_pos_flags: int, lscape, trace=None) -> int:
        """``SetPosition(SetPosition)`` with the SetPosition's Pos `pos` and Flags `set_pos_flags`;
        returns the SetPositionError."""
        transition = Transition(lscape.mode, lscape, trace)  # Transition.MakeTransition()
        transition.init_object(self, 0)  # ObjectInfoState.Default
        mode = lscape.mode
        if self.part_array is not None and self.part_array.get_num_sphere() != 0:
            transition.init_sphere(self.part_array.get_num_sphere(), self.part_array.get_sphere(), self.scale)
        else:
            transition.init_sphere(1, [_dummy_sphere(mode)], mode.scalar(1.0))

        result = self.set_position_internal_set_pos(pos, set_pos_flags, transition, lscape)
        transition.cleanup_transition()
        return result

    @anchor("CPhysicsObj::SetPositionInternal", "PhysicsObj.cs:SetPositionInternal(SetPosition, Transition)")
    def set_position_internal_set_pos(self, pos, set_pos_flags: int, transition: Transition, lscape) -> int:
        wo = self.weenie_obj.world_object
        if wo is None:
            return SetPositionError.GeneralFailure

        if wo.scatter_pos is not None:
            raise NotImplementedError("a WorldObject's ScatterPos (SetScatterPositionInternal) is not ported")

        # frame ref? (ACE)
        result = self.set_position_internal_pos(pos, set_pos_flags, transition, lscape)

        if result != SetPositionError.OK and set_pos_flags & SetPositionFlags.Scatter:
            raise NotImplementedError("SetScatterPositionInternal draws random positions: scenes refuse Scatter")
        return result

    @anchor("CPhysicsObj::FindObjCollisions", "PhysicsObj.cs:FindObjCollisions")
    def find_obj_collisions(self, transition: Transition) -> TransitionState:
        ethereal = False

        if self.state & PhysicsState.Ethereal and self.state & PhysicsState.IgnoreCollisions:
            return TransitionState.OK

        if (self.weenie_obj is not None and transition.object_info.state & ObjectInfoState.IsViewer
                and self.weenie_obj.is_creature):
            return TransitionState.OK

        if self.state & PhysicsState.Ethereal or not self.state & PhysicsState.Static and transition.object_info.ethereal:
            if transition.sphere_path.step_down:
                return TransitionState.OK
            ethereal = True
        transition.sphere_path.obstruction_ethereal = ethereal

        state = transition.object_info.state

        wobj = self.weenie_obj
        exemption = not (self.dat_object or not wobj.is_player or not state & ObjectInfoState.IsPlayer
                         or state & ObjectInfoState.IsImpenetrable or wobj.is_impenetrable()
                         or state & ObjectInfoState.IsPK and wobj.is_pk()
                         or state & ObjectInfoState.IsPKLite and wobj.is_pk_lite())

        missile_ignore = transition.object_info.missile_ignore(self)

        is_creature = bool(self.state & PhysicsState.Missile) or self.weenie_obj is not None and self.weenie_obj.is_creature

        pa = self.part_array
        if not self.state & PhysicsState.HasPhysicsBSP or missile_ignore or exemption:
            if pa is None or pa.get_num_cylsphere() == 0 or missile_ignore or exemption:
                if pa is not None and pa.get_num_sphere() != 0 and not missile_ignore and not exemption:
                    spheres = pa.get_sphere()
                    for i in range(pa.get_num_sphere()):
                        intersects = spheres[i].intersects_sphere(self.position, self.scale, transition, is_creature)
                        if intersects != TransitionState.OK:
                            return self.find_obj_collisions_inner(transition, intersects, ethereal, is_creature)
            else:
                if pa is not None and pa.get_num_cylsphere() != 0 and not missile_ignore and not exemption:
                    cyl_spheres = pa.get_cyl_sphere()
                    for i in range(pa.get_num_cylsphere()):
                        intersects = cyl_spheres[i].intersects_sphere_at(self.position, self.scale, transition)
                        if intersects != TransitionState.OK:
                            return self.find_obj_collisions_inner(transition, intersects, ethereal, is_creature)
        elif pa is not None:
            collided = pa.find_obj_collisions(transition)
            if collided != TransitionState.OK:
                return self.find_obj_collisions_inner(transition, collided, ethereal, is_creature)

        transition.sphere_path.obstruction_ethereal = False
        return TransitionState.OK

    @anchor("CPhysicsObj::FindObjCollisions_Inner", "PhysicsObj.cs:FindObjCollisions_Inner")
    def find_obj_collisions_inner(self, transition: Transition, result: TransitionState, ethereal: bool,
                                  is_creature: bool) -> TransitionState:
        if not transition.sphere_path.step_down:
            if self.state & PhysicsState.Static:
                if not transition.object_info.state & ObjectInfoState.Contact:
                    transition.collision_info.collided_with_environment = True
            elif ethereal or is_creature and transition.object_info.state & ObjectInfoState.IgnoreCreatures:
                result = TransitionState.OK
                transition.collision_info.collision_normal_valid = False
                transition.collision_info.add_object(self, TransitionState.OK)
            else:
                transition.collision_info.add_object(self, result)
        transition.sphere_path.obstruction_ethereal = False
        return result

    @anchor("CPhysicsObj::transition", "PhysicsObj.cs:transition")
    def transition(self, old_pos, new_pos, admin_move: bool, lscape, trace=None) -> tuple[Transition, bool]:
        """Returns (the transition, FindValidPosition's answer). ACE returns null when the answer
        is False; the outcome reads the transition either way (as the oracle does)."""
        trans = Transition(lscape.mode, lscape, trace)

        object_info = self.get_object_info(trans, admin_move)
        trans.init_object(self, object_info.state)

        mode = lscape.mode
        if self.part_array is None or self.part_array.get_num_sphere() == 0:
            trans.init_sphere(1, [_dummy_sphere(mode)], mode.scalar(1.0))
        else:
            trans.init_sphere(self.part_array.get_num_sphere(), self.part_array.get_sphere(), self.scale)

        trans.init_path(self.cur_cell, old_pos, new_pos)

        if self.transient_state & TransientState.StationaryStuck:
            trans.collision_info.frames_stationary_fall = 3
        elif self.transient_state & TransientState.StationaryStop:
            trans.collision_info.frames_stationary_fall = 2
        elif self.transient_state & TransientState.StationaryFall:
            trans.collision_info.frames_stationary_fall = 1

        valid_pos = trans.find_valid_position()
        trans.cleanup_transition()
        return trans, valid_pos
