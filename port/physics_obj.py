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

from acconform.flags import ObjectInfoState, PhysicsState, TransientState, TransitionState
from acconform.numerics import Plane, Vector3, dot

from .anchors import anchor
from .constants import DEFAULT_SCALE, DUMMY_SPHERE_RADIUS, EPSILON, FLOOR_Z, TRANSLUCENCY_ETHEREAL
from .frame import AFrame, Position
from . import land_defs
from .cell import obj_cell
from .part_array import PLACEMENT_FRAME_ID, PartArray
from .shadow_obj import ShadowObj
from .transition.object_info import ObjectInfo
from .transition.transition import Transition

# PhysicsGlobals.MaxVelocity = 50.0f
MAX_VELOCITY = 50.0
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
                          scale=mode.scalar(DEFAULT_SCALE), cell_array=CellArray())

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
            raise NotImplementedError("a non-DAT object's landblock server list (Landblock.add_server_object) is not ported")

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
