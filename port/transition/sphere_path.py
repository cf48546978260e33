"""SpherePath: Init, InitPath, InitSphere, AddOffsetToCheckPos, AdjustCheckPos, CacheGlobalCurrCenter, CacheGlobalSphere, CacheLocalSpaceSphere, CheckWalkables, GetCurPosCheckPosBlockOffset, GetWalkablePos, IsWalkableAllowable, PrecipiceSlide, RestoreCheckPos, SaveCheckPos, SetCheckPos, SetCollide, SetNegPolyHit, SetWalkable, SetWalkableCheckPos, StepUpSlide.

ACE's SpherePath.cs: the path's state. Positions are mutable objects as in C# (classes); where
ACE copies (``new Position(p)``) the port calls ``copy()``, and where ACE shares a reference the
port shares it too. The global spheres are mutated in place, as ACE's Sphere objects are, so a
Sphere method on ``global_sphere[0]`` sees the offsets it adds.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from acconform.flags import InsertType, TransitionState
from acconform.numerics import Mode, Vector3, dot

from ..anchors import anchor
from ..frame import AFrame, Position
from ..geom.sphere import Sphere
from .. import land_defs
from ..vec import unit_z_like, zero_like


@dataclass(slots=True, eq=False)
class SpherePath:
    mode: Mode
    num_sphere: int = 0
    local_sphere: list = field(default_factory=list)
    local_low_point: Vector3 | None = None
    global_sphere: list = field(default_factory=list)
    global_low_point: Vector3 | None = None
    local_space_sphere: list = field(default_factory=list)
    local_space_low_point: Vector3 | None = None
    local_space_curr_center: list = field(default_factory=list)
    global_curr_center: list = field(default_factory=list)
    local_space_pos: Position | None = None
    local_space_z: Vector3 | None = None
    begin_cell: object = None
    begin_pos: Position | None = None
    end_pos: Position | None = None
    cur_cell: object = None
    cur_pos: Position | None = None
    global_offset: Vector3 | None = None
    step_up: bool = False
    step_up_normal: Vector3 | None = None
    collide: bool = False
    check_cell: object = None
    check_pos: Position | None = None
    insert_type: InsertType = InsertType.Transition
    step_down: bool = False
    backup: InsertType = InsertType.Transition
    backup_cell: object = None
    backup_check_pos: Position | None = None
    obstruction_ethereal: bool = False
    hits_interior_cell: bool = False
    building_check: bool = False
    walkable_allowance: object = 0.0
    walk_interp: object = 0.0
    step_down_amt: object = 0.0
    walkable_check_pos: object = None
    walkable: object = None  # the Polygon, or None
    check_walkable: bool = False
    walkable_up: Vector3 | None = None
    walkable_pos: Position | None = None
    walkable_scale: object = 0.0
    cell_array_valid: bool = False
    neg_step_up: bool = False
    neg_collision_normal: Vector3 | None = None
    neg_poly_hit: bool = False
    placement_allows_sliding: bool = False
    # not ACE's: the run's branches.Trace (or None), for the boundary tests this path makes
    trace: object = None

    def __post_init__(self):
        # the C# constructor: new Positions and Sphere, empty lists, default struct fields
        m = self.mode
        z = m.vec(0, 0, 0)
        s0 = m.scalar(0.0)
        self.local_space_pos = Position(0, AFrame.identity(m))
        self.cur_pos = Position(0, AFrame.identity(m))
        self.check_pos = Position(0, AFrame.identity(m))
        self.backup_check_pos = Position(0, AFrame.identity(m))
        self.walkable_check_pos = Sphere(z, s0)
        self.local_low_point = self.global_low_point = self.local_space_low_point = z
        self.local_space_z = self.global_offset = self.step_up_normal = z
        self.walkable_up = self.neg_collision_normal = z
        self.walkable_allowance = self.walk_interp = self.step_down_amt = self.walkable_scale = s0
        self.init()

    @anchor("SPHEREPATH::init", "SpherePath.cs:Init")
    def init(self) -> None:
        self.placement_allows_sliding = True

    @anchor("SPHEREPATH::init_path", "SpherePath.cs:InitPath")
    def init_path(self, begin_cell, begin_pos: Position | None, end_pos: Position) -> None:
        self.begin_pos = begin_pos
        self.begin_cell = begin_cell
        self.end_pos = end_pos
        if begin_pos is not None:
            self.insert_type = InsertType.Transition
            self.cur_pos = begin_pos.copy()
        else:
            self.insert_type = InsertType.Placement
            self.cur_pos = end_pos.copy()
        self.cur_cell = begin_cell
        self.cache_global_curr_center()

    @anchor("SPHEREPATH::init_sphere", "SpherePath.cs:InitSphere")
    def init_sphere(self, num_sphere: int, spheres: list, scale) -> None:
        self.num_sphere = num_sphere if num_sphere <= 2 else 2
        for i in range(self.num_sphere):
            self.local_sphere.append(Sphere(spheres[i].center * scale, spheres[i].radius * scale))
        self.local_low_point = self.local_sphere[0].center
        self.local_low_point = self.local_low_point.with_z(self.local_low_point.z - self.local_sphere[0].radius)

    @anchor("SPHEREPATH::add_offset_to_check_pos", "SpherePath.cs:AddOffsetToCheckPos")
    def add_offset_to_check_pos(self, offset: Vector3, radius=None) -> None:
        """Both ACE overloads: the radius is ignored, as in ACE."""
        self.cell_array_valid = False
        self.check_pos.frame.origin = self.check_pos.frame.origin + offset
        self.cache_global_sphere(offset)

    @anchor("SPHEREPATH::adjust_check_pos", "SpherePath.cs:AdjustCheckPos")
    def adjust_check_pos(self, cell_id: int) -> None:
        if (cell_id & 0xFFFF) < 0x100:
            offset = land_defs.get_block_offset(cell_id, self.check_pos.obj_cell_id)
            self.cache_global_sphere(offset)
            self.check_pos.frame.origin = self.check_pos.frame.origin + offset
        self.check_pos.obj_cell_id = cell_id

    @anchor("SPHEREPATH::cache_global_curr_center", "SpherePath.cs:CacheGlobalCurrCenter")
    def cache_global_curr_center(self) -> None:
        while len(self.global_curr_center) < self.num_sphere:
            self.global_curr_center.append(Sphere(self.mode.vec(0, 0, 0), self.mode.scalar(0.0)))
        for i in range(self.num_sphere):
            self.global_curr_center[i].center = self.cur_pos.local_to_global(self.local_sphere[i].center)

    @anchor("SPHEREPATH::cache_global_sphere", "SpherePath.cs:CacheGlobalSphere")
    def cache_global_sphere(self, offset: Vector3 | None) -> None:
        if offset is not None:
            for glob_sphere in self.global_sphere:
                glob_sphere.center = glob_sphere.center + offset
            self.global_low_point = self.global_low_point + offset
        else:
            while len(self.global_sphere) < self.num_sphere:
                self.global_sphere.append(Sphere(self.mode.vec(0, 0, 0), self.mode.scalar(0.0)))
            for i in range(self.num_sphere):
                self.global_sphere[i].radius = self.local_sphere[i].radius
                self.global_sphere[i].center = self.check_pos.local_to_global(self.local_sphere[i].center)
            self.global_low_point = self.check_pos.local_to_global(self.local_low_point)

    @anchor("SPHEREPATH::cache_localspace_sphere", "SpherePath.cs:CacheLocalSpaceSphere")
    def cache_local_space_sphere(self, pos: Position, scale_z) -> None:
        inv_scale = 1.0 / scale_z
        m = self.mode
        while len(self.local_space_curr_center) < self.num_sphere:
            self.local_space_curr_center.append(Sphere(m.vec(0, 0, 0), m.scalar(0.0)))
        while len(self.local_space_sphere) < self.num_sphere:
            self.local_space_sphere.append(Sphere(m.vec(0, 0, 0), m.scalar(0.0)))
        for i in range(self.num_sphere):
            self.local_space_curr_center[i].center = pos.local_to_local(self.cur_pos, self.local_sphere[i].center) * inv_scale
            self.local_space_sphere[i].radius = self.local_sphere[i].radius * inv_scale
            self.local_space_sphere[i].center = pos.local_to_local(self.check_pos, self.local_sphere[i].center) * inv_scale
        self.local_space_pos = pos.copy()
        self.local_space_z = pos.global_to_local_vec(unit_z_like(inv_scale))
        self.local_space_low_point = self.local_space_sphere[0].center - (self.local_space_z * self.local_space_sphere[0].radius)

    @anchor("SPHEREPATH::check_walkables", "SpherePath.cs:CheckWalkables")
    def check_walkables(self) -> bool:
        if self.walkable is None:
            return True
        walk_check_pos = Sphere(self.walkable_check_pos.center, self.walkable_check_pos.radius * 0.5)
        return self.walkable.check_walkable(walk_check_pos, self.walkable_up)

    @anchor(None, "SpherePath.cs:GetCurPosCheckPosBlockOffset")
    def get_cur_pos_check_pos_block_offset(self) -> Vector3:
        return land_defs.get_block_offset(self.cur_pos.obj_cell_id, self.check_pos.obj_cell_id)

    @anchor("SPHEREPATH::get_walkable_pos", "SpherePath.cs:GetWalkablePos")
    def get_walkable_pos(self) -> Position:
        return self.walkable_pos

    @anchor("SPHEREPATH::is_walkable_allowable", "SpherePath.cs:IsWalkableAllowable")
    def is_walkable_allowable(self, zval) -> bool:
        if self.trace is not None:
            self.trace.walkable(zval, self.walkable_allowance)
        return bool(zval > self.walkable_allowance)

    @anchor("SPHEREPATH::precipice_slide", "SpherePath.cs:PrecipiceSlide")
    def precipice_slide(self, transition) -> TransitionState:
        trace = transition.trace
        collision_normal = zero_like(self.mode.scalar(0.0))
        found, collision_normal = self.walkable.find_crossed_edge(self.walkable_check_pos, self.walkable_up, collision_normal)
        if not found:
            if trace is not None:
                trace["precipice_slide:no_crossed_edge"] += 1
            self.walkable = None
            return TransitionState.Collided

        self.walkable = None
        self.step_up = False
        collision_normal = self.walkable_pos.frame.local_to_global_vec(collision_normal)

        block_offset = land_defs.get_block_offset(self.cur_pos.obj_cell_id, self.check_pos.obj_cell_id)
        offset = self.global_sphere[0].center - self.global_curr_center[0].center + block_offset

        if dot(collision_normal, offset) > 0.0:
            if trace is not None:
                trace["precipice_slide:normal_flipped"] += 1
            collision_normal = collision_normal * -1.0
        elif trace is not None:
            trace["precipice_slide:normal_kept"] += 1

        state, _ = self.global_sphere[0].slide_sphere(transition, collision_normal, self.global_curr_center[0].center)
        return state

    @anchor("SPHEREPATH::restore_check_pos", "SpherePath.cs:RestoreCheckPos")
    def restore_check_pos(self) -> None:
        self.check_pos = self.backup_check_pos.copy()
        self.check_cell = self.backup_cell
        self.cell_array_valid = False
        self.cache_global_sphere(None)

    @anchor("SPHEREPATH::save_check_pos", "SpherePath.cs:SaveCheckPos")
    def save_check_pos(self) -> None:
        self.backup_cell = self.check_cell
        self.backup_check_pos = self.check_pos.copy()

    @anchor("SPHEREPATH::set_check_pos", "SpherePath.cs:SetCheckPos")
    def set_check_pos(self, position: Position, cell) -> None:
        self.check_pos = position.copy()
        self.check_cell = cell
        self.cell_array_valid = False
        self.cache_global_sphere(None)

    @anchor("SPHEREPATH::set_collide", "SpherePath.cs:SetCollide")
    def set_collide(self, collision_normal: Vector3) -> None:
        self.collide = True
        self.backup_cell = self.check_cell
        self.backup_check_pos = self.check_pos.copy()
        self.step_up_normal = collision_normal
        self.walk_interp = self.mode.scalar(1.0)

    @anchor("SPHEREPATH::set_neg_poly_hit", "SpherePath.cs:SetNegPolyHit")
    def set_neg_poly_hit(self, step_up: bool, collision_normal: Vector3) -> None:
        self.neg_step_up = step_up
        self.neg_poly_hit = True
        self.neg_collision_normal = self.mode.runtime.negate(collision_normal)

    @anchor("SPHEREPATH::set_walkable", "SpherePath.cs:SetWalkable")
    def set_walkable(self, sphere, poly, z_axis: Vector3, local_pos: Position, scale) -> None:
        self.walkable_check_pos = Sphere(sphere.center, sphere.radius)
        self.walkable = poly
        self.walkable_up = z_axis
        self.walkable_pos = local_pos.copy()
        self.walkable_scale = scale

    @anchor("SPHEREPATH::set_walkable_check_pos", "SpherePath.cs:SetWalkableCheckPos")
    def set_walkable_check_pos(self, sphere) -> None:
        self.walkable_check_pos = Sphere(sphere.center, sphere.radius)

    @anchor("SPHEREPATH::step_up_slide", "SpherePath.cs:StepUpSlide")
    def step_up_slide(self, transition) -> TransitionState:
        collisions = transition.collision_info
        collisions.contact_plane_valid = False
        collisions.contact_plane_is_water = False
        state, self.step_up_normal = self.global_sphere[0].slide_sphere(transition, self.step_up_normal,
                                                                        self.global_curr_center[0].center)
        return state
