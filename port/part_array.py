"""PartArray and PhysicsPart: PartArray (AddPartsShadow, Update, HandleMovement, HandleEnterWorld, HandleExitWorld, AnimationDone, CheckForCompletedMotions, DoInterpretedMotion, HasAnims, InitializeMotionTables, SetMotionTableID, StopCompletelyInternal, StopInterpretedMotion, RemoveParts, SetNoDrawInternal, GetSortingSphere, AllowsFreeHeading, CacheHasPhysicsBSP, CreateMesh, CreateSetup, DestroyParts, DestroySetup, FindObjCollisions, GetCylSphere, GetNumCylsphere, GetNumSphere, GetSphere, GetStepDownHeight, GetStepUpHeight, InitDefaults, InitParts, SetCellID, SetFrame, SetMeshID, SetPlacementFrame, SetScaleInternal, SetSetupID, UpdateParts, calc_cross_cells_static), PhysicsPart (InitEmpty, SetPart, LoadGfxObjArray, MakePhysicsPart, MorphToExistingObject, SetNoDraw, GetBoundingBox, FindObjCollisions).

ACE's Physics/PartArray.cs and Physics/PhysicsPart.cs. A static object's PartArray is made by
PhysicsObj.makeObject from its DAT record: CreateMesh for a GfxObj id (one part over a simple
Setup), CreateSetup for a Setup id (a part per GfxObj the Setup names; a Setup with no parts
makes no PartArray at all). With no placement frame, UpdateParts makes a single part's Pos the
owner's Position object itself (not a copy), so the part moves with the object. The mover's
PartArray is made the same way, from its own Setup record (CreateSetup).
"""

from __future__ import annotations

from dataclasses import dataclass

from acconform.flags import TransitionState
from acconform.motion_enums import MovementType, WeenieError
from acconform.numerics import Vector3, cast_float

from . import gfx_obj_cache
from .anchors import anchor
from .frame import AFrame, Position
from .animation.anim_data import AnimData
from .animation.sequence import Sequence
from .setup import Setup

# PhysicsObj passes 0x65 to SetPlacementFrame (Placement.Resting... as ACE writes it)
PLACEMENT_FRAME_ID = 0x65
INT32_MAX = 0x7FFFFFFF  # Int32.MaxValue: InitDefaults' high frame for a default animation


@dataclass(slots=True, eq=False)
class PhysicsPart:
    gfx_obj: object = None  # port.gfx_obj.GfxObj
    gfx_obj_scale: Vector3 | None = None
    physics_obj: object = None
    pos: object = None  # frame.Position
    phys_obj_index: int = -1

    @staticmethod
    @anchor("CPhysicsPart::CPhysicsPart", "PhysicsPart.cs:PhysicsPart()", "the empty constructor: InitEmpty")
    def create_empty(mode) -> "PhysicsPart":
        part = PhysicsPart()
        part.init_empty(mode)
        return part

    @staticmethod
    @anchor(None, "PhysicsPart.cs:PhysicsPart(uint)", "InitEmpty, then SetPart(partID)")
    def create(portal_dat, part_id: int) -> "PhysicsPart":
        part = PhysicsPart()
        part.init_empty(portal_dat.mode)
        part.set_part(portal_dat, part_id)
        return part

    @anchor("CPhysicsPart::InitEmpty", "PhysicsPart.cs:InitEmpty")
    def init_empty(self, mode) -> None:
        self.gfx_obj_scale = mode.vec(1.0, 1.0, 1.0)
        self.pos = Position(0, AFrame.identity(mode))
        self.phys_obj_index = -1

    @anchor("CPhysicsPart::SetPart", "PhysicsPart.cs:SetPart")
    def set_part(self, portal_dat, gfx_obj_id: int) -> bool:
        return self.load_gfx_obj_array(portal_dat, gfx_obj_id)

    @anchor("CPhysicsPart::LoadGfxObjArray", "PhysicsPart.cs:LoadGfxObjArray")
    def load_gfx_obj_array(self, portal_dat, root_object_id: int) -> bool:
        self.gfx_obj = gfx_obj_cache.get(portal_dat, root_object_id)
        # degrades omitted (ACE)
        return self.gfx_obj is not None

    @staticmethod
    @anchor("CPhysicsPart::makePhysicsPart", "PhysicsPart.cs:MakePhysicsPart(PhysicsPart)")
    def make_physics_part(template: "PhysicsPart", mode) -> "PhysicsPart":
        part = PhysicsPart.create_empty(mode)
        part.morph_to_existing_object(template)
        return part

    @anchor("CPhysicsPart::MorphToExistingObject", "PhysicsPart.cs:MorphToExistingObject")
    def morph_to_existing_object(self, template: "PhysicsPart") -> bool:
        """Copies the references: GfxObj, GfxObjScale (a struct: its value) and Pos (the same Position)."""
        self.gfx_obj = template.gfx_obj
        self.gfx_obj_scale = template.gfx_obj_scale
        self.pos = template.pos
        return True

    @anchor("CPhysicsPart::SetNoDraw", "PhysicsPart.cs:SetNoDraw")
    def set_no_draw(self, no_draw: bool) -> None:
        """Graphics omitted from server (ACE): nothing happens."""
        return None

    @anchor("CPhysicsPart::GetBoundingBox", "PhysicsPart.cs:GetBoundingBox")
    def get_bounding_box(self):
        return self.gfx_obj.gfx_bound_box

    @anchor("CPhysicsPart::find_obj_collisions", "PhysicsPart.cs:FindObjCollisions")
    def find_obj_collisions(self, transition) -> TransitionState:
        if self.gfx_obj is not None and self.gfx_obj.physics_bsp is not None:
            transition.sphere_path.cache_local_space_sphere(self.pos, self.gfx_obj_scale.z)
            return self.gfx_obj.find_obj_collisions(transition, self.gfx_obj_scale.z)
        return TransitionState.OK  # should be invalid? (ACE)


@dataclass(slots=True, eq=False)
class PartArray:
    owner: object = None  # the PhysicsObj
    setup: Setup | None = None
    num_parts: int = 0
    parts: list | None = None  # PhysicsPart
    scale: Vector3 | None = None  # Vector3.One from the constructor; set by SetScaleInternal
    state: int = 0
    sequence: Sequence | None = None
    motion_table_manager: object = None  # port/managers/motion_table_manager.MotionTableManager, or None
    last_anim_frame: object = None  # LastAnimFrame (dat.animation_frame.AnimationFrame): never set in ACE
    portal_dat: object = None  # the run's DatManager.PortalDat (MotionTableManager.Create reads it)

    @staticmethod
    @anchor("CPartArray::CPartArray", "PartArray.cs:PartArray()")
    def create(mode, portal_dat=None) -> "PartArray":
        """`portal_dat` is the run's PortalDat: ACE's statics that the Sequence's animations and
        SetMotionTableID read (None where nothing animates)."""
        return PartArray(scale=mode.vec(1, 1, 1), sequence=Sequence.create(mode, portal_dat), portal_dat=portal_dat)

    @staticmethod
    @anchor("CPartArray::CreateMesh", "PartArray.cs:CreateMesh")
    def create_mesh(owner, setup_did: int, portal_dat) -> "PartArray | None":
        mesh = PartArray.create(portal_dat.mode, portal_dat)
        mesh.owner = owner
        mesh.sequence.set_object(owner)
        if not mesh.set_mesh_id(setup_did, portal_dat):
            return None
        mesh.set_placement_frame(PLACEMENT_FRAME_ID)
        return mesh

    @staticmethod
    @anchor("CPartArray::CreateSetup", "PartArray.cs:CreateSetup")
    def create_setup(owner, setup_did: int, create_parts: bool, portal_dat) -> "PartArray | None":
        setup = PartArray.create(portal_dat.mode, portal_dat)
        setup.owner = owner
        setup.sequence.set_object(owner)
        if not setup.set_setup_id(setup_did, create_parts, portal_dat):
            return None
        setup.set_placement_frame(PLACEMENT_FRAME_ID)
        return setup

    @anchor("CPartArray::DestroyParts", "PartArray.cs:DestroyParts")
    def destroy_parts(self) -> None:
        self.parts = None
        self.num_parts = 0

    @anchor("CPartArray::DestroySetup", "PartArray.cs:DestroySetup")
    def destroy_setup(self) -> None:
        self.setup = None

    @anchor("CPartArray::SetMeshID", "PartArray.cs:SetMeshID")
    def set_mesh_id(self, mesh_did: int, portal_dat) -> bool:
        if mesh_did == 0:
            return False
        setup = Setup.make_simple_setup(portal_dat, mesh_did)
        if setup is None:
            return False
        self.destroy_parts()
        self.destroy_setup()
        self.setup = setup
        return self.init_parts(portal_dat.mode)

    @anchor("CPartArray::SetSetupID", "PartArray.cs:SetSetupID")
    def set_setup_id(self, setup_id: int, create_parts: bool, portal_dat) -> bool:
        if self.setup is not None and self.setup.id == setup_id:
            return True

        self.setup = Setup.get(portal_dat, setup_id)
        if self.setup is None:
            return False

        self.destroy_parts()

        if create_parts and not self.init_parts(portal_dat.mode):
            return False

        self.init_defaults()
        return True

    @anchor("CPartArray::InitParts", "PartArray.cs:InitParts")
    def init_parts(self, mode) -> bool:
        """A Setup with no parts fails (NumParts 0): CreateSetup then makes no PartArray."""
        self.num_parts = self.setup.num_parts
        if self.num_parts == 0:
            return False

        self.parts = [None] * self.num_parts

        if self.setup.parts is None:
            return True

        created = 0
        for i in range(self.num_parts):
            self.parts[i] = PhysicsPart.make_physics_part(self.setup.parts[i], mode)
            if self.parts[i] is None:
                break
            created += 1

        if created == self.num_parts:
            for i in range(self.num_parts):
                self.parts[i].physics_obj = self.owner
                self.parts[i].phys_obj_index = i

            if self.setup.default_scale is not None and len(self.setup.default_scale) == self.num_parts:
                for i in range(self.num_parts):
                    self.parts[i].gfx_obj_scale = self.setup.default_scale[i]
            return True

        return False

    @anchor("CPartArray::InitDefaults", "PartArray.cs:InitDefaults")
    def init_defaults(self) -> None:
        """A Setup's DefaultAnimation plays frames 0 .. Int32.MaxValue (AnimSequenceNode clamps the high
        frame to the animation's last) at framerate 0f: the empty AnimData's."""
        if self.setup.default_animation != 0:
            self.sequence.clear_animations()
            anim_data = AnimData.create(self.sequence.mode)
            anim_data.anim_id = self.setup.default_animation
            anim_data.low_frame = 0
            anim_data.high_frame = INT32_MAX
            self.sequence.append_animation(anim_data)
            # WeenieDesc.Destroy(animData): an empty method in ACE

        if self.owner is not None:
            self.owner.init_defaults(self.setup)

    @anchor("CPartArray::SetPlacementFrame", "PartArray.cs:SetPlacementFrame")
    def set_placement_frame(self, placement_id: int) -> bool:
        placement_frame = self.setup.placement_frames.get(placement_id)
        if placement_frame is not None:
            self.sequence.set_placement_frame(placement_frame.anim_frame, placement_id)
            return True

        placement_frame = self.setup.placement_frames.get(0)
        if placement_frame is not None:
            self.sequence.set_placement_frame(placement_frame.anim_frame, 0)
            return True

        self.sequence.set_placement_frame(None, 0)
        return False

    @anchor("CPartArray::SetFrame", "PartArray.cs:SetFrame")
    def set_frame(self, frame: AFrame) -> None:
        self.update_parts(frame)

    @anchor("CPartArray::UpdateParts", "PartArray.cs:UpdateParts")
    def update_parts(self, frame: AFrame) -> None:
        cur_frame = self.sequence.get_curr_anim_frame()
        if cur_frame is None:
            if len(self.parts) == 1:
                self.parts[0].pos = self.owner.position  # the owner's Position itself
            return
        num_parts = min(self.num_parts, len(cur_frame.frames))
        for i in range(num_parts):
            self.parts[i].pos.frame.combine_scaled(frame, AFrame.from_dat(cur_frame.frames[i]), self.scale)

    @anchor("CPartArray::Update", "PartArray.cs:Update")
    def update(self, quantum, offset_frame):
        """`quantum` is a double, cast to float for the Sequence. Returns the offset frame (C# `ref
        AFrame`): changed in place, or replaced when an animation's root motion is combined in."""
        return self.sequence.update(cast_float(self.scale.x, quantum), offset_frame)

    @anchor("CPartArray::HandleMovement", "PartArray.cs:HandleMovement")
    def handle_movement(self) -> None:
        if self.motion_table_manager is not None:
            self.motion_table_manager.use_time()

    @anchor("CPartArray::HandleEnterWorld", "PartArray.cs:HandleEnterWorld")
    def handle_enter_world(self) -> None:
        if self.motion_table_manager is not None:
            self.motion_table_manager.handle_enter_world(self.sequence)

    @anchor("CPartArray::HandleExitWorld", "PartArray.cs:HandleExitWorld")
    def handle_exit_world(self) -> None:
        if self.motion_table_manager is not None:
            self.motion_table_manager.handle_exit_world()

    @anchor("CPartArray::AnimationDone", "PartArray.cs:AnimationDone")
    def animation_done(self, success: bool) -> None:
        if self.motion_table_manager is not None:
            self.motion_table_manager.animation_done(success)

    @anchor("CPartArray::CheckForCompletedMotions", "PartArray.cs:CheckForCompletedMotions")
    def check_for_completed_motions(self) -> None:
        if self.motion_table_manager is not None:
            self.motion_table_manager.check_for_completed_motions()

    @anchor("CPartArray::DoInterpretedMotion", "PartArray.cs:DoInterpretedMotion")
    def do_interpreted_motion(self, motion: int, movement_parameters) -> int:
        """Returns a WeenieError."""
        from .animation.movement_struct import MovementStruct

        if self.motion_table_manager is None:
            return WeenieError.NoAnimationTable

        mvs = MovementStruct.create(MovementType.InterpretedCommand, motion, movement_parameters)
        return self.motion_table_manager.perform_movement(mvs, self.sequence)

    @anchor("CPartArray::HasAnims", "PartArray.cs:HasAnims")
    def has_anims(self) -> bool:
        return self.sequence.has_anims()

    @anchor("CPartArray::InitializeMotionTables", "PartArray.cs:InitializeMotionTables")
    def initialize_motion_tables(self) -> None:
        if self.motion_table_manager is not None:
            self.motion_table_manager.initialize_state(self.sequence)

    @anchor("CPartArray::SetMotionTableID", "PartArray.cs:SetMotionTableID")
    def set_motion_table_id(self, mtable_id: int) -> bool:
        from .managers.motion_table_manager import MotionTableManager

        if self.motion_table_manager is not None:
            if self.motion_table_manager.get_motion_table_id(mtable_id) == mtable_id:
                return True

            self.motion_table_manager = None
        if mtable_id == 0:
            return True

        self.motion_table_manager = MotionTableManager.create(mtable_id, self.portal_dat.mode, self.portal_dat)
        if self.motion_table_manager is None:
            return False

        self.motion_table_manager.set_physics_object(self.owner)

        # chat blob? (ACE)
        return True

    @anchor("CPartArray::StopCompletelyInternal", "PartArray.cs:StopCompletelyInternal")
    def stop_completely_internal(self) -> int:
        """Returns a WeenieError."""
        from .animation.movement_struct import MovementStruct

        if self.motion_table_manager is None:
            return WeenieError.NoAnimationTable
        mvs = MovementStruct.create(MovementType.StopCompletely)
        return self.motion_table_manager.perform_movement(mvs, self.sequence)

    @anchor("CPartArray::StopInterpretedMotion", "PartArray.cs:StopInterpretedMotion")
    def stop_interpreted_motion(self, motion: int, movement_parameters) -> int:
        """Returns a WeenieError."""
        from .animation.movement_struct import MovementStruct

        if self.motion_table_manager is None:
            return WeenieError.NoAnimationTable
        mvs = MovementStruct.create(MovementType.StopInterpretedCommand)
        mvs.motion = motion
        mvs.params = movement_parameters
        return self.motion_table_manager.perform_movement(mvs, self.sequence)

    @anchor("CPartArray::RemoveParts", "PartArray.cs:RemoveParts")
    def remove_parts(self, cell) -> None:
        """ACE calls PartCell.RemovePart per part, which returns at once (its body is commented
        out in ACE): nothing happens."""
        return None

    @anchor("CPartArray::SetCellID", "PartArray.cs:SetCellID")
    def set_cell_id(self, cell_id: int) -> None:
        for part in self.parts:
            if part is not None:
                part.pos.obj_cell_id = cell_id

    @anchor("CPartArray::SetNoDrawInternal", "PartArray.cs:SetNoDrawInternal")
    def set_no_draw_internal(self, no_draw: bool) -> None:
        if self.setup is None:
            return
        for part in self.parts:
            if part is not None:
                part.set_no_draw(no_draw)

    @anchor("CPartArray::GetSortingSphere", "PartArray.cs:GetSortingSphere")
    def get_sorting_sphere(self):
        """PhysicsGlobals.DefaultSortingSphere (never assigned: null) without a Setup."""
        if self.setup is None:
            return None
        return self.setup.sorting_sphere

    @anchor("CPartArray::calc_cross_cells_static", "PartArray.cs:calc_cross_cells_static")
    def calc_cross_cells_static(self, cell, cell_array, lscape) -> None:
        if cell is not None:  # fixme (ACE)
            cell.find_transit_cells_parts(lscape, self.num_parts, self.parts, cell_array)

    @anchor("CPartArray::AddPartsShadow", "PartArray.cs:AddPartsShadow")
    def add_parts_shadow(self, obj_cell, num_shadow_parts: int) -> None:
        """ACE calls PartCell.AddPart per part, which returns at once (its body is commented
        out in ACE): nothing happens."""
        return None

    @anchor("CPartArray::AllowsFreeHeading", "PartArray.cs:AllowsFreeHeading")
    def allows_free_heading(self) -> bool:
        return self.setup.allow_free_heading

    @anchor("CPartArray::CacheHasPhysicsBSP", "PartArray.cs:CacheHasPhysicsBSP")
    def cache_has_physics_bsp(self) -> bool:
        for part in self.parts:
            if part.gfx_obj.physics_bsp is not None:
                self.state |= 0x10000
                return True
        self.state &= 0xFFFEFFFF
        return False

    @anchor("CPartArray::FindObjCollisions", "PartArray.cs:FindObjCollisions")
    def find_obj_collisions(self, transition) -> TransitionState:
        for part in self.parts:
            result = part.find_obj_collisions(transition)
            if result != TransitionState.OK:
                return result
        return TransitionState.OK

    @anchor("CPartArray::GetCylSphere", "PartArray.cs:GetCylSphere")
    def get_cyl_sphere(self) -> list:
        return self.setup.cyl_sphere

    @anchor("CPartArray::GetNumCylsphere", "PartArray.cs:GetNumCylsphere")
    def get_num_cylsphere(self) -> int:
        return self.setup.num_cylsphere

    @anchor("CPartArray::GetDataID", "PartArray.cs:GetDataID")
    def get_data_id(self) -> int:
        if self.setup.id != 0:
            return self.setup.id
        if self.num_parts == 1:
            return self.parts[0].gfx_obj.id
        return 0

    @anchor("CPartArray::GetHeight", "PartArray.cs:GetHeight")
    def get_height(self):
        return self.setup.height * self.scale.z

    @anchor("CPartArray::GetRadius", "PartArray.cs:GetRadius")
    def get_radius(self):
        return self.setup.radius * self.scale.z

    @anchor("CPartArray::GetNumSphere", "PartArray.cs:GetNumSphere")
    def get_num_sphere(self) -> int:
        return self.setup.num_sphere

    @anchor("CPartArray::GetSphere", "PartArray.cs:GetSphere")
    def get_sphere(self) -> list:
        return self.setup.sphere

    @anchor("CPartArray::GetStepDownHeight", "PartArray.cs:GetStepDownHeight")
    def get_step_down_height(self):
        return self.setup.step_down_height * self.scale.z

    @anchor("CPartArray::GetStepUpHeight", "PartArray.cs:GetStepUpHeight")
    def get_step_up_height(self):
        return self.setup.step_up_height * self.scale.z

    @anchor("CPartArray::SetScaleInternal", "PartArray.cs:SetScaleInternal")
    def set_scale_internal(self, new_scale: Vector3) -> bool:
        self.scale = new_scale
        for i in range(self.num_parts):
            part = self.parts[i]
            if part is not None:
                if self.setup is not None and len(self.setup.default_scale) > i:
                    part.gfx_obj_scale = self.setup.default_scale[i] * new_scale
                else:
                    part.gfx_obj_scale = new_scale
        return True
