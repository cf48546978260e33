"""PhysicsObj: PhysicsObj(), makeObject, InitObjectBegin, InitPartArrayObject, makeAnimObject, SetTranslucencyInternal, InitObjectEnd, InitDefaults, AdjustPosition, add_obj_to_cell, enter_cell, UpdateChildrenInternal, calc_cross_cells_static, find_bbox_cell_list, remove_shadows_from_cells, add_shadows_to_cell(CellArray), is_completely_visible, transition, get_object_info, check_contact, get_walkable_z, is_valid_walkable, set_velocity, GetStepUpHeight, GetStepDownHeight, FindObjCollisions, FindObjCollisions_Inner, CacheHasPhysicsBSP, SetScaleStatic, IsPlayer, Equals; MasterDBMap.DivineType.

The part of ACE's PhysicsObj.cs a transition uses: how a static object is made from its DAT
record (makeObject: a PartArray over a GfxObj mesh or a Setup) and placed (add_obj_to_cell ->
calc_cross_cells_static: find_bbox_cell_list over the parts' boxes, or find_cell_list for a
cylsphere without a physics BSP -> add_shadows_to_cell, in the CellArray's .NET order); the
set-up PhysicsObj.transition does before FindValidPosition, the members the transition reads
back (walkable checks, StopVelocity's set_velocity), and a static's FindObjCollisions (BSP
through the PartArray, or the Setup's spheres / cylspheres). The mover's PartArray is the
harness's (run.py, as the oracle builds it). The WeenieObj is ACE's WeenieObject.DummyObject (no
player, creature or PK flags), which is what a PhysicsObj made without a WorldObject carries;
a static's DatObject is true (as Landblock.init_static_objs sets it), the mover's false.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from acconform.flags import ObjectInfoState, PhysicsState, SetPositionError, SetPositionFlags, TransientState, TransitionState
from acconform.numerics import Plane, Vector3, dot

from .anchors import anchor
from .constants import (DEFAULT_ELASTICITY, DEFAULT_SCALE, DUMMY_SPHERE_RADIUS, EPSILON, FLOOR_Z, GRAVITY, PLACEMENT_CLOSE,
                        TRANSLUCENCY_ETHEREAL)
from .frame import AFrame, Position
from . import land_defs
from .cell import obj_cell
from .part_array import PLACEMENT_FRAME_ID, PartArray
from .shadow_obj import ShadowObj
from .transition.object_info import ObjectInfo
from .transition.transition import Transition

# PhysicsGlobals.MaxVelocity = 50.0f
MAX_VELOCITY = 50.0
# PhysicsEngine.cs TransientStateFlags.StationaryComplete = StationaryStuck | StationaryStop | StationaryFall
STATIONARY_COMPLETE = TransientState.StationaryStuck | TransientState.StationaryStop | TransientState.StationaryFall
# PhysicsGlobals.DefaultState
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


@dataclass(frozen=True, slots=True)
class DummyWeenie:
    """WeenieObject.DummyObject: every flag false."""

    is_player: bool = False
    is_creature: bool = False
    is_storage: bool = False
    is_corpse: bool = False

    @anchor(None, "WeenieObject.cs:IsImpenetrable", "DummyObject: no Player, so false")
    def is_impenetrable(self) -> bool:
        return False

    @anchor(None, "WeenieObject.cs:IsPK", "DummyObject: no Player, so false")
    def is_pk(self) -> bool:
        return False

    @anchor(None, "WeenieObject.cs:IsPKLite", "DummyObject: no Player, so false")
    def is_pk_lite(self) -> bool:
        return False


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
    weenie_obj: object = field(default_factory=DummyWeenie)
    dat_object: bool = False
    projectile_target: object = None
    parent: object = None
    is_sight_obj: bool = False
    jumped_this_frame: bool = False
    shadow_objects: dict = field(default_factory=dict)  # cell id -> ShadowObj (a .NET Dictionary)
    num_shadow_objects: int = 0
    cell_array: object = None  # transition.cell_array.CellArray (the object's own, for its placement)
    children: list = field(default_factory=list)  # ChildList.Objects (always empty here)
    translucency: object = 0.0
    translucency_original: object = 0.0
    acceleration: Vector3 | None = None
    omega: Vector3 | None = None
    cur_landblock: object = None  # port.land.landblock.Landblock
    colliding_with_environment: bool = False
    collision_table: dict | None = None  # object id -> CollisionRecord's Ethereal (TouchedTime: see report_collision_end)
    entering_world: bool = False
    elasticity: object = DEFAULT_ELASTICITY

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

    @staticmethod
    @anchor("CPhysicsObj::CPhysicsObj", "PhysicsObj.cs:PhysicsObj()")
    def create(mode) -> "PhysicsObj":
        """``new PhysicsObj()``: the fields a static's placement and a transition read, at ACE's
        defaults (Position cell 0 and identity frame, PhysicsGlobals.DefaultState, scale 1,
        zero velocity and sliding normal, default(Plane) contact plane, an empty CellArray)."""
        from .transition.cell_array import CellArray

        zero = mode.vec(0, 0, 0)
        return PhysicsObj(id=0, state=int(DEFAULT_STATE), position=Position(0, AFrame.identity(mode)),
                          velocity=zero, contact_plane=Plane(zero, mode.scalar(0.0)), sliding_normal=zero,
                          scale=mode.scalar(DEFAULT_SCALE), cell_array=CellArray(), acceleration=zero, omega=zero,
                          elasticity=mode.scalar(DEFAULT_ELASTICITY))

    @staticmethod
    @anchor("CPhysicsObj::makeObject", "PhysicsObj.cs:makeObject(uint, uint, bool, bool)")
    def make_object(data_did: int, object_iid: int, dynamic: bool, portal_dat, sight_obj: bool = False) -> "PhysicsObj":
        """`portal_dat` (port/dat/portal_dat.py) stands in for the DAT statics the DAT readers use."""
        obj = PhysicsObj.create(portal_dat.mode)
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
        """Scripts and motion tables are not ported: a Setup naming one stops the port (dat.py
        writes none)."""
        if setup.default_script != 0 or setup.default_motion_table != 0:
            raise NotImplementedError("default scripts and motion tables are not ported")
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
            collided = self.handle_all_collisions(transition.collision_info, False, False)
            transition._hit("set_position:collided" if collided else "set_position:no_valid_position")
            return SetPositionError.Collided if collided else SetPositionError.NoValidPosition

        if transition.sphere_path.cur_cell is None:
            return SetPositionError.NoCell

        # custom (ACE): a non-ethereal spell projectile's collision on world entry; the mover has no
        # WorldObject (WeenieObject.DummyObject), so `WeenieObj.WorldObject is SpellProjectile` is false

        if self.entering_world and transition.sphere_path.cur_pos.landblock != pos.landblock:
            return SetPositionError.NoValidPosition

        if not self.set_position_internal(transition):
            return SetPositionError.GeneralFailure

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
            for child in self.children:
                raise NotImplementedError("child objects are not ported")
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
            # MovementManager.LeaveGround(): the mover has no MovementManager
            self.calc_acceleration()

        self.sliding_normal = collisions.sliding_normal

        if collisions.sliding_normal_valid:
            self.transient_state |= TransientState.Sliding
        else:
            self.transient_state &= ~TransientState.Sliding

        self.handle_all_collisions(collisions, prev_contact, prev_on_walkable)

        if self.cur_cell is not None:
            if self.state & PhysicsState.HasPhysicsBSP:
                self.calc_cross_cells(transition.lscape)
                return True

            if len(transition.cell_array.cells) > 0:
                self.remove_shadows_from_cells()
                self.add_shadows_to_cell(transition.cell_array)
                return True
        return True

    @anchor("CPhysicsObj::prepare_to_enter_world", "PhysicsObj.cs:prepare_to_enter_world")
    def prepare_to_enter_world(self) -> None:
        """UpdateTime (PhysicsTimer.CurrentTime) and ObjMaint's destruction queue are not kept:
        nothing in a placement or a transition reads them."""
        for child in self.children:
            raise NotImplementedError("child objects are not ported")

        if not self.state & PhysicsState.Static:
            self.transient_state |= TransientState.Active

    @anchor("CPhysicsObj::prepare_to_leave_visibility", "PhysicsObj.cs:prepare_to_leave_visibility")
    def prepare_to_leave_visibility(self) -> bool:
        """ObjMaint.AddObjectToBeDestroyed (a queue nothing here reads) is not kept."""
        self.remove_shadows_from_cells()
        self.leave_cell(False)
        return False

    @anchor("CPhysicsObj::leave_cell", "PhysicsObj.cs:leave_cell")
    def leave_cell(self, is_changing_cell: bool) -> None:
        if self.cur_cell is None:
            return
        raise NotImplementedError("leaving a cell (ObjCell.RemoveObject) is not ported: a scene places its mover once")

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
        """UpdateTime is not kept (see prepare_to_enter_world)."""
        if active:
            if self.state & PhysicsState.Static:
                return False
            self.transient_state |= TransientState.Active
            return True
        else:
            self.transient_state &= ~TransientState.Active
            return True

    @anchor("CPhysicsObj::change_cell", "PhysicsObj.cs:change_cell")
    def change_cell(self, new_cell, lscape) -> None:
        if lscape.portal_dat.server:
            raise NotImplementedError("change_cell_server (the server's ObjectMaint visibility) is not ported; "
                                      "a scene's placement runs in client mode")

        if self.cur_cell is not None:
            self.leave_cell(True)
        if new_cell is None:
            self.position.obj_cell_id = 0
            if self.part_array is not None and not self.state & PhysicsState.ParticleEmitter:
                self.part_array.set_cell_id(0)
            self.cur_cell = None
        else:
            self.enter_cell(new_cell, lscape)

    @anchor("CPhysicsObj::set_frame", "PhysicsObj.cs:set_frame")
    def set_frame(self, frame: AFrame, lscape) -> None:
        """Writes the frame's orientation in place when ACE does (a frame valid except for its
        heading gets the zero quaternion). The run's `lscape` says PhysicsEngine.Instance.Server."""
        if not frame.is_valid() and frame.is_valid_except_for_heading():
            z = type(frame.orientation.w)(0.0)
            frame.orientation = frame.orientation.runtime.quaternion(z, z, z, z)

        self.position.frame = frame.copy()

        # custom for server: only update part frames for objects with physics bsp (ACE)
        if self.part_array is not None and not self.state & PhysicsState.ParticleEmitter and (
                self.state & PhysicsState.HasPhysicsBSP or not lscape.portal_dat.server):
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
        """The mover has no MovementManager (HitGround / LeaveGround)."""
        if is_on_walkable:
            self.transient_state |= TransientState.OnWalkable
        else:
            self.transient_state &= ~TransientState.OnWalkable
        self.calc_acceleration()

    @anchor("CPhysicsObj::handle_all_collisions", "PhysicsObj.cs:handle_all_collisions")
    def handle_all_collisions(self, collisions, prev_has_contact: bool, prev_on_walkable: bool) -> bool:
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
                    z = type(self.velocity.x)(0.0)
                    self.velocity = Vector3(z, z, z)

                    # custom for spell projectiles: explode on server (ACE)
                    self.report_environment_collision(prev_has_contact)
                else:
                    collision_angle = dot(self.velocity, collisions.collision_normal)
                    if collision_angle < 0.0:
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
            self.collision_table = {}

        self.collision_table[obj.id] = bool(obj.state & PhysicsState.Ethereal)

        return self.report_object_collision(obj, prev_has_contact)

    @anchor("CPhysicsObj::report_collision_end", "PhysicsObj.cs:report_collision_end")
    def report_collision_end(self, force_end: bool) -> None:
        """PhysicsTimer.CurrentTime is Timers.PortalYearTicks, which nothing advances outside a
        running server: every record's deltaTime is 0, so only `force_end` ends one; ending it calls
        WeenieObject.DoCollisionEnd, which returns at once for DummyObject (no WorldObject)."""
        if self.collision_table is None:
            return
        ends = [collision_id for collision_id, ethereal in self.collision_table.items() if force_end]
        for end in ends:
            del self.collision_table[end]

    @anchor("CPhysicsObj::report_environment_collision", "PhysicsObj.cs:report_environment_collision")
    def report_environment_collision(self, prev_has_contact: bool) -> bool:
        """WeenieObj.DoCollision(EnvCollisionProfile) returns at once for DummyObject (no WorldObject)."""
        if self.colliding_with_environment:
            return False

        result = False
        if self.state & PhysicsState.ReportCollisions and self.weenie_obj is not None:
            result = True
        self.colliding_with_environment = True
        if self.state & PhysicsState.Missile:
            self.state &= ~PhysicsState.Missile
        return result

    @anchor("CPhysicsObj::report_object_collision", "PhysicsObj.cs:report_object_collision")
    def report_object_collision(self, obj, prev_has_contact: bool) -> bool:
        """The collision profiles and WeenieObj.DoCollision return at once for DummyObject."""
        if obj.state & PhysicsState.ReportCollisionsAsEnvironment:
            return self.report_environment_collision(prev_has_contact)

        collided = False

        if not obj.state & PhysicsState.IgnoreCollisions:
            if self.state & PhysicsState.ReportCollisions and self.weenie_obj is not None:
                collided = True

            if self.state & PhysicsState.Missile:
                self.state &= ~(PhysicsState.Missile | PhysicsState.AlignPath | PhysicsState.PathClipped)

        if obj.state & PhysicsState.ReportCollisions and not self.state & PhysicsState.IgnoreCollisions and obj.weenie_obj is not None:
            collided = True

        return collided

    @anchor("CPhysicsObj::calc_cross_cells", "PhysicsObj.cs:calc_cross_cells")
    def calc_cross_cells(self, lscape) -> None:
        self.cell_array.set_dynamic()

        if self.state & PhysicsState.HasPhysicsBSP:
            self.find_bbox_cell_list(self.cell_array, lscape)
        else:
            raise NotImplementedError("calc_cross_cells without a physics BSP is not reached (SetPositionInternal "
                                      "calls it only with HasPhysicsBSP)")
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
        for child in self.children:
            child.enter_cell(new_cell, lscape)

        self.cur_cell = new_cell
        self.position.obj_cell_id = new_cell.id  # (ACE) Position inconsistent until set_frame runs
        if self.part_array is not None and not self.state & PhysicsState.ParticleEmitter:
            self.part_array.set_cell_id(new_cell.id)

        if not self.dat_object and new_cell is not None:
            self.cur_landblock = lscape.get_landblock(new_cell.id)
            if self.cur_landblock is not None:
                self.cur_landblock.add_server_object(self)

    @anchor("CPhysicsObj::UpdateChildrenInternal", "PhysicsObj.cs:UpdateChildrenInternal")
    def update_children_internal(self) -> None:
        if self.part_array is None or not self.children:
            return
        raise NotImplementedError("child objects (UpdateChild) are not ported")

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
        """A static is placed once: its ShadowObjects are still empty here, as ACE's are. Removing
        entries from a cell's shadow list is not ported."""
        for shadow_obj in self.shadow_objects.values():
            if shadow_obj.cell is None:
                continue
            raise NotImplementedError("removing shadow objects (ObjCell.remove_shadow_object) is not ported")
        self.num_shadow_objects = 0  # should be ShadowObjects.Count (ACE)
        for child in self.children:
            child.remove_shadows_from_cells()

    @anchor("CPhysicsObj::add_shadows_to_cell", "PhysicsObj.cs:add_shadows_to_cell(CellArray)")
    def add_shadows_to_cell(self, cell_array) -> None:
        if self.state & PhysicsState.ParticleEmitter:
            raise NotImplementedError("particle emitters (add_particle_shadow_to_cell) are not ported")
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
        for child in self.children:
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
        """The observable part: Velocity (clamped to MaxVelocity) and the Active transient flag."""
        if not velocity == self.velocity:
            self.velocity = velocity
            if self.velocity.length() > MAX_VELOCITY:
                self.velocity = self.velocity / self.velocity.length()
                self.velocity = self.velocity * MAX_VELOCITY
            self.jumped_this_frame = True
        if not self.state & PhysicsState.Static:
            self.transient_state |= TransientState.Active

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
            from .geom.sphere import Sphere

            dummy = Sphere(mode.vec(0, 0, DUMMY_SPHERE_RADIUS), mode.scalar(DUMMY_SPHERE_RADIUS))
            trans.init_sphere(1, [dummy], mode.scalar(1.0))
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
