"""Transition: AdjustOffset, BuildCellArray, CalcNumSteps, CheckCollisions, CheckOtherCells, CheckWalkable, CleanupTransition, CliffSlide, EdgeSlide, SetEdgeSlide, FindPlacementPos, FindPlacementPosition, FindTransitionalPosition, FindValidPosition, Init, InitContactPlane, InitLastKnownContactPlane, InitObject, InitPath, InitSlidingNormal, InitSphere, InsertIntoCell, PlacementInsert, StepDown, StepUp, TransitionalInsert, ValidatePlacement, ValidatePlacementTransition, ValidateTransition, SetCurrentCheckPos.

ACE's Animation/Transition.cs, line by line. The placement routines (FindPlacementPosition and
what it calls) run when a scene's mover is placed (PhysicsObj.CheckPositionInternal); a
transition always moves from a begin position (InsertType.Transition).

The run's world (`lscape`, an acconform.port.land.lscape.LScape) replaces ACE's static LScape,
and `trace` (a collections.Counter or None) counts the branches named in branches.py.
"""

from __future__ import annotations


from acconform.flags import InsertType, ObjectInfoState, PhysicsState, TransitionState
import math

from acconform.numerics import Mode, Plane, Vector3, cast_float, cs_ceiling, cs_floor, cross, dot, wrap_i32

from ..anchors import anchor
from ..constants import (EPSILON, EPSILON_SQ, FLOOR_Z, LANDING_Z, PLACEMENT_ADJUST_DIST, PLACEMENT_FAKE_ADJUST_RAD,
                         PLACEMENT_FAKE_SPHERE_RADIUS, PLACEMENT_MIN_RADIUS, STEP_DOWN_PROBE)
from .. import land_defs
from ..cell.obj_cell import EMPTY_CELL, find_cell_list_path
from ..vec import normalize_check_small, snap_to_plane, unit_z_like
from .cell_array import CellArray
from .collision_info import CollisionInfo
from .object_info import ObjectInfo
from .sphere_path import SpherePath
from ..frame import AFrame

# Transition.FindTransitionalPosition: `var maxSteps = 1000;`
MAX_STEPS = 1000


def _position_equals(a, b) -> bool:
    """Position.Equals(Position): same cell id and AFrame.Equals (origins within EPSILON)."""
    return a.obj_cell_id == b.obj_cell_id and a.frame.equals(b.frame)


class Transition:
    """CTransition. `mode` is the run's numerics, `lscape` its world, `trace` a branch counter."""

    __slots__ = ("object_info", "sphere_path", "collision_info", "cell_array", "mode", "lscape", "trace")

    def __init__(self, mode: Mode, lscape, trace=None):
        self.mode = mode
        self.lscape = lscape
        self.trace = trace
        self.init()
        self.sphere_path.trace = trace

    def _hit(self, branch: str) -> None:
        if self.trace is not None:
            self.trace[branch] += 1

    def _zero(self) -> Vector3:
        return self.mode.vec(0, 0, 0)

    @anchor("CTransition::init", "Transition.cs:Init")
    def init(self) -> None:
        self.object_info = ObjectInfo()
        self.sphere_path = SpherePath(self.mode)
        self.collision_info = CollisionInfo.create(self.mode.scalar(0.0))
        self.cell_array = CellArray()

    @anchor("CTransition::adjust_offset", "Transition.cs:AdjustOffset")
    def adjust_offset(self, _offset: Vector3) -> Vector3:
        ci = self.collision_info
        sp = self.sphere_path
        offset = Vector3(_offset.x, _offset.y, _offset.z)
        check_slide = False

        sliding_angle = dot(offset, ci.sliding_normal)
        if ci.sliding_normal_valid:
            if sliding_angle < 0.0:
                check_slide = True
            else:
                ci.sliding_normal_valid = False

        if not ci.contact_plane_valid:
            if check_slide:
                self._hit("adjust_offset:slide_no_contact")
                offset = offset - ci.sliding_normal * sliding_angle
            return offset

        collision_angle = dot(offset, ci.contact_plane.normal)
        slide_offset = cross(ci.contact_plane.normal, ci.sliding_normal)

        if check_slide:
            small, slide_offset = normalize_check_small(slide_offset)
            if small:
                self._hit("adjust_offset:slide_blocked")
                offset = self._zero()
            else:
                self._hit("adjust_offset:slide_along_crease")
                offset = dot(slide_offset, offset) * slide_offset
        elif collision_angle <= 0.0:
            offset = offset - ci.contact_plane.normal * collision_angle
        else:
            offset = snap_to_plane(ci.contact_plane, offset)

        if ci.contact_plane_cell_id == 0 or ci.contact_plane_is_water:
            return offset

        glob_sphere = sp.global_sphere[0]
        block_offset = land_defs.get_block_offset(sp.check_pos.obj_cell_id, ci.contact_plane_cell_id)
        dist = dot(glob_sphere.center - block_offset, ci.contact_plane.normal) + ci.contact_plane.d
        if dist >= glob_sphere.radius - EPSILON:
            return offset

        z_dist = (glob_sphere.radius - dist) / ci.contact_plane.normal.z
        if glob_sphere.radius > abs(z_dist):
            self._hit("adjust_offset:lift_above_contact_plane")
            s = type(z_dist)
            sp.add_offset_to_check_pos(Vector3(s(0.0), s(0.0), z_dist))
        return offset

    @anchor("CTransition::build_cell_array", "Transition.cs:BuildCellArray")
    def build_cell_array(self, new_cell):
        """BuildCellArray(ref newCell): returns newCell after the call."""
        self.sphere_path.cell_array_valid = True
        self.sphere_path.hits_interior_cell = False
        return find_cell_list_path(self.lscape, self.cell_array, new_cell, self.sphere_path)

    @anchor("CTransition::calc_num_steps", "Transition.cs:CalcNumSteps")
    def calc_num_steps(self) -> tuple[Vector3, Vector3, int]:
        """CalcNumSteps(ref offset, ref offsetPerStep, ref numSteps): returns the three."""
        sp = self.sphere_path
        s = self.mode.scalar
        if sp.begin_pos is None:
            return self._zero(), self._zero(), 1
        offset = sp.begin_pos.get_offset(sp.end_pos)
        dist = offset.length()
        step = dist / sp.local_sphere[0].radius

        if not self.object_info.state & ObjectInfoState.IsViewer:
            if step > 1.0:
                num_steps = self.mode.runtime.to_int32(cs_ceiling(step))
                offset_per_step = offset * (s(1.0) / s(num_steps))
            elif not offset == self._zero():
                offset_per_step = offset
                num_steps = 1
            else:
                offset_per_step = self._zero()
                num_steps = 0
            return offset, offset_per_step, num_steps

        if dist <= EPSILON:
            return offset, self._zero(), 0
        offset_per_step = offset * (s(1.0) / step)
        num_steps = self.mode.runtime.to_int32(cs_floor(step)) + 1
        return offset, offset_per_step, num_steps

    @anchor("CTransition::check_other_cells", "Transition.cs:CheckOtherCells")
    def check_other_cells(self, curr_cell) -> TransitionState:
        sp = self.sphere_path
        ci = self.collision_info
        result = TransitionState.OK

        sp.cell_array_valid = True
        sp.hits_interior_cell = False

        new_cell = find_cell_list_path(self.lscape, self.cell_array, EMPTY_CELL, sp)

        i = 0
        while i < len(self.cell_array.cells):
            cell = self.cell_array.cells.value_at(i)
            i += 1
            if cell is None or cell.equals(curr_cell):
                continue
            collides = cell.find_collisions(self)
            if collides == TransitionState.Slid:
                ci.contact_plane_valid = False
                ci.contact_plane_is_water = False
                return collides
            if collides in (TransitionState.Collided, TransitionState.Adjusted):
                self._hit("check_other_cells:other_cell_collided")
                return collides

        sp.check_cell = new_cell

        if new_cell is not None:
            sp.adjust_check_pos(new_cell.id)
            return result

        self._hit("check_other_cells:no_cell")
        if sp.step_down:
            return TransitionState.Collided

        check_pos = sp.check_pos.copy()
        if (check_pos.obj_cell_id & 0xFFFF) < 0x100:
            land_defs.adjust_to_outside_pos(check_pos)

        if check_pos.obj_cell_id != 0:
            sp.adjust_check_pos(check_pos.obj_cell_id)
            sp.set_check_pos(check_pos, None)
            sp.cell_array_valid = True
            return result
        return TransitionState.Collided

    @anchor("CTransition::check_walkable", "Transition.cs:CheckWalkable")
    def check_walkable(self, z_check) -> bool:
        sp = self.sphere_path
        oi = self.object_info
        if not oi.state & ObjectInfoState.OnWalkable or sp.check_walkables():
            self._hit("check_walkable:walkable_ok")
            return True

        sp.backup_check_pos = sp.check_pos.copy()
        sp.backup_cell = sp.check_cell

        step_height = oi.step_down_height

        sp.walkable_allowance = z_check
        sp.check_walkable = True

        glob_sphere = sp.global_sphere[0]
        if self.trace is not None:
            self.trace.boundary("step_down_height", step_height, glob_sphere.radius * 2)
        if sp.num_sphere < 2 and step_height > glob_sphere.radius * 2:
            step_height = glob_sphere.radius * 0.5

        if step_height > glob_sphere.radius * 2:
            step_height = step_height * 0.5

        s = type(step_height)
        sp.add_offset_to_check_pos(Vector3(s(0.0), s(0.0), -step_height))

        transition_state = self.transitional_insert(1)

        sp.check_walkable = False
        sp.set_check_pos(sp.backup_check_pos, sp.backup_cell)

        self._hit("check_walkable:probe_blocked" if transition_state != TransitionState.OK else "check_walkable:probe_fell")
        return transition_state != TransitionState.OK

    @anchor("CTransition::cleanup_transition", "Transition.cs:CleanupTransition")
    def cleanup_transition(self) -> None:
        # removed static transitions (ACE)
        pass

    @anchor("CTransition::cliff_slide", "Transition.cs:CliffSlide")
    def cliff_slide(self, contact_plane: Plane) -> TransitionState:
        sp = self.sphere_path
        ci = self.collision_info
        contact_normal = cross(contact_plane.normal, ci.last_known_contact_plane.normal)
        contact_normal = contact_normal.with_z(type(contact_normal.z)(0.0))

        collide_normal = Vector3(contact_normal.z - contact_normal.y, contact_normal.x - contact_normal.z,
                                 type(contact_normal.z)(0.0))
        small, collide_normal = normalize_check_small(collide_normal)
        if small:
            self._hit("cliff_slide:parallel_planes")
            return TransitionState.OK

        block_offset = land_defs.get_block_offset(sp.cur_pos.obj_cell_id, sp.check_pos.obj_cell_id)
        offset = sp.global_sphere[0].center - sp.global_curr_center[0].center

        angle = dot(collide_normal, offset + block_offset)
        if angle <= 0.0:
            self._hit("cliff_slide:normal_kept")
            sp.add_offset_to_check_pos(collide_normal * angle)
            ci.set_collision_normal(collide_normal)
        else:
            self._hit("cliff_slide:normal_flipped")
            sp.add_offset_to_check_pos(collide_normal * -angle)
            ci.set_collision_normal(self.mode.runtime.negate(collide_normal))
        return TransitionState.Adjusted

    @anchor("CTransition::edge_slide", "Transition.cs:EdgeSlide")
    def edge_slide(self, transition_state: TransitionState, step_down_height, zval) -> tuple[bool, TransitionState]:
        """EdgeSlide(ref transitionState, ...): returns (result, transitionState after the call)."""
        sp = self.sphere_path
        ci = self.collision_info
        oi = self.object_info
        if not oi.state & ObjectInfoState.OnWalkable or not oi.state & ObjectInfoState.EdgeSlide:
            self._hit("edge_slide:off")
            return True, self.set_edge_slide(True, True, TransitionState.OK)

        if ci.contact_plane_valid and ci.contact_plane.normal.z < zval:
            self._hit("edge_slide:cliff_slide")
            return False, self.set_edge_slide(True, False, self.cliff_slide(ci.contact_plane))

        if sp.walkable is not None:
            self._hit("edge_slide:precipice_slide")
            transition_state = self.set_edge_slide(False, False, sp.precipice_slide(self))
            return transition_state == TransitionState.Collided, transition_state

        if ci.contact_plane_valid:
            self._hit("edge_slide:contact_plane_valid")
            return True, self.set_edge_slide(True, True, TransitionState.OK)

        self._hit("edge_slide:back_probe")
        offset = sp.global_curr_center[0].center - sp.global_sphere[0].center
        sp.add_offset_to_check_pos(offset)

        self.step_down(step_down_height, zval)

        ci.contact_plane_valid = False
        ci.contact_plane_is_water = False
        sp.restore_check_pos()

        if sp.walkable is not None:
            self._hit("edge_slide:back_probe_precipice_slide")
            sp.cache_local_space_sphere(sp.get_walkable_pos(), sp.walkable_scale)
            sp.set_walkable_check_pos(sp.local_space_sphere[0])
            transition_state = sp.precipice_slide(self)
            return transition_state == TransitionState.Collided, transition_state

        self._hit("edge_slide:back_probe_no_walkable")
        sp.walkable = None
        sp.cell_array_valid = True
        return True, TransitionState.Collided

    @anchor("CTransition::set_edge_slide", "Transition.cs:SetEdgeSlide")
    def set_edge_slide(self, unwalkable: bool, valid_cell: bool, transition_state: TransitionState) -> TransitionState:
        sp = self.sphere_path
        if unwalkable:
            sp.walkable = None
        sp.restore_check_pos()
        self.collision_info.contact_plane_valid = False
        self.collision_info.contact_plane_is_water = False
        if valid_cell:
            sp.cell_array_valid = True
        return transition_state

    @anchor("CTransition::find_transitional_position", "Transition.cs:FindTransitionalPosition")
    def find_transitional_position(self) -> bool:
        sp = self.sphere_path
        ci = self.collision_info
        oi = self.object_info
        s = self.mode.scalar
        if sp.begin_cell is None:
            return False

        transition_state = TransitionState.OK
        offset, offset_per_step, num_steps = self.calc_num_steps()

        if num_steps > MAX_STEPS and not oi.object.is_sight_obj:
            self._hit("find_transitional_position:too_many_steps")
            return False

        if oi.state & ObjectInfoState.FreeRotate:
            sp.cur_pos.frame.set_rotate(sp.end_pos.frame.orientation)

        sp.set_check_pos(sp.cur_pos, sp.cur_cell)

        redo = 0
        if num_steps <= 0:
            self._hit("find_transitional_position:no_steps")
            if not oi.state & ObjectInfoState.FreeRotate:
                sp.cur_pos.frame.set_rotate(sp.end_pos.frame.orientation)
            sp.cell_array_valid = True
            sp.hits_interior_cell = False
            find_cell_list_path(self.lscape, self.cell_array, None, sp)
            return True

        for step in range(num_steps):
            if self.trace is not None and self.trace.recorder is not None:  # tracing (port/tracing.py)
                self.trace.recorder.at_step(self, step)
            if oi.state & ObjectInfoState.IsViewer:
                last_step = num_steps - 1
                if step == last_step:
                    offset_len = offset.length()
                    if offset_len > EPSILON:
                        redo = last_step
                        offset_per_step = offset * (offset_len - sp.local_sphere[0].radius * s(last_step)) / offset_len

            sp.global_offset = self.adjust_offset(offset_per_step)
            if not oi.state & ObjectInfoState.IsViewer:
                if sp.global_offset.length_squared() < EPSILON_SQ:
                    self._hit("find_transitional_position:offset_vanished")
                    return step != 0 and transition_state == TransitionState.OK

            if not oi.state & ObjectInfoState.FreeRotate:
                redo = step + 1
                delta = s(redo) / s(num_steps)
                sp.check_pos.frame.interpolate_rotation(sp.begin_pos.frame, sp.end_pos.frame, delta)

            ci.sliding_normal_valid = False
            ci.contact_plane_valid = False
            ci.contact_plane_is_water = False

            if sp.insert_type != InsertType.Transition:
                raise NotImplementedError("placement inserts (InsertType != Transition) are not ported")

            sp.add_offset_to_check_pos(sp.global_offset)
            transition_insert = self.transitional_insert(3)
            transition_state = self.validate_transition(transition_insert)

            if ci.frames_stationary_fall > 0:
                self._hit("find_transitional_position:stationary_fall_stop")
                break

            if ci.collision_normal_valid and oi.state & ObjectInfoState.PathClipped:
                break

        return transition_state == TransitionState.OK

    @anchor("CTransition::find_valid_position", "Transition.cs:FindValidPosition")
    def find_valid_position(self) -> bool:
        if self.sphere_path.insert_type == InsertType.Transition:
            return self.find_transitional_position()
        else:
            return self.find_placement_position()

    @anchor("CTransition::find_placement_pos", "Transition.cs:FindPlacementPos")
    def find_placement_pos(self) -> bool:
        sp = self.sphere_path
        ci = self.collision_info
        s = self.mode.scalar
        # refactor me (ACE)
        sp.set_check_pos(sp.cur_pos, sp.cur_cell)

        ci.sliding_normal_valid = False
        ci.contact_plane_valid = False
        ci.contact_plane_is_water = False

        transition_state = self.transitional_insert(3)

        transition_state = self.validate_placement_transition(transition_state)

        if transition_state == TransitionState.OK:
            self._hit("find_placement_pos:in_place")
            return True

        if not sp.placement_allows_sliding:
            self._hit("find_placement_pos:no_sliding")
            return False

        adjust_dist = s(PLACEMENT_ADJUST_DIST)
        adjust_rad = adjust_dist
        sphere_rad = sp.local_sphere[0].radius

        fake_sphere = False

        if sphere_rad < PLACEMENT_FAKE_SPHERE_RADIUS:
            fake_sphere = True
            adjust_rad = s(PLACEMENT_FAKE_ADJUST_RAD)
        elif sphere_rad < PLACEMENT_MIN_RADIUS:
            sphere_rad = s(PLACEMENT_MIN_RADIUS)

        movement_delta = sphere_rad

        f_num_steps = s(4.0) / movement_delta

        if fake_sphere:
            f_num_steps *= s(0.5)

        if f_num_steps <= 1.0:
            return False

        num_steps = self.mode.runtime.to_int32(cs_ceiling(f_num_steps))
        dist_per_step = adjust_rad / s(num_steps)
        radians_per_step = cast_float(dist_per_step, math.pi * float(dist_per_step) / float(sphere_rad))

        total_dist = s(0.0)
        total_rad = s(0.0)

        for _ in range(num_steps):
            total_dist += dist_per_step
            total_rad += radians_per_step

            rad = self.mode.runtime.to_int32(cs_ceiling(total_rad))
            rad = wrap_i32(rad * 2)
            angle = s(360.0) / s(rad)

            frame = AFrame.identity(self.mode)

            for j in range(rad):
                sp.set_check_pos(sp.cur_pos, sp.cur_cell)
                frame.set_heading(angle * s(j))
                offset = frame.get_vector_heading() * total_dist
                sp.global_offset = self.adjust_offset(offset)
                if sp.global_offset.length() >= EPSILON:
                    sp.add_offset_to_check_pos(sp.global_offset)

                    # possibly reset by AdjustOffset (ACE)
                    ci.sliding_normal_valid = False
                    ci.contact_plane_valid = False
                    ci.contact_plane_is_water = False

                    transition_state = self.transitional_insert(3)
                    transition_state = self.validate_placement_transition(transition_state)

                    if transition_state == TransitionState.OK:
                        self._hit("find_placement_pos:slid_to_free_spot")
                        return True
        self._hit("find_placement_pos:no_free_spot")
        return False

    @anchor("CTransition::find_placement_position", "Transition.cs:FindPlacementPosition")
    def find_placement_position(self) -> bool:
        sp = self.sphere_path
        sp.set_check_pos(sp.cur_pos, sp.cur_cell)
        sp.insert_type = InsertType.InitialPlacement
        transition_state = TransitionState.Invalid  # new TransitionState()

        if sp.check_cell is not None:
            transition_state = self.insert_into_cell(sp.check_cell, 3)

            if transition_state == TransitionState.OK:
                transition_state = self.check_other_cells(sp.check_cell)
        else:
            transition_state = TransitionState.Collided

        result = self.validate_placement(transition_state, True)
        if result != TransitionState.OK:
            self._hit("find_placement_position:initial_blocked")
            return False

        sp.insert_type = InsertType.Placement
        if not self.find_placement_pos():
            return False

        if not self.object_info.step_down:
            result = self.validate_placement(TransitionState.OK, True)
            return result == TransitionState.OK

        sp.walkable_allowance = self.mode.scalar(LANDING_Z)
        sp.save_check_pos()

        sp.backup = sp.insert_type
        sp.insert_type = InsertType.Transition

        glob_sphere = sp.global_sphere[0]
        step_down_height = self.object_info.step_down_height

        if sp.num_sphere < 2 and glob_sphere.radius * 2 < step_down_height:
            step_down_height = glob_sphere.radius * self.mode.scalar(0.5)

        if step_down_height <= glob_sphere.radius * 2:
            if not self.step_down(step_down_height, self.mode.scalar(LANDING_Z)):
                sp.restore_check_pos()
                self.collision_info.contact_plane_valid = False
                self.collision_info.contact_plane_is_water = False
        else:
            step_down_height *= self.mode.scalar(0.5)
            if (not self.step_down(step_down_height, self.mode.scalar(LANDING_Z))
                    and not self.step_down(step_down_height, self.mode.scalar(LANDING_Z))):
                sp.restore_check_pos()
                self.collision_info.contact_plane_valid = False
                self.collision_info.contact_plane_is_water = False

        sp.insert_type = sp.backup
        sp.walkable = None

        result = self.validate_placement(TransitionState.OK, True)
        return result == TransitionState.OK

    @anchor("CTransition::placement_insert", "Transition.cs:PlacementInsert")
    def placement_insert(self) -> TransitionState:
        sp = self.sphere_path
        if sp.check_cell is None:
            return TransitionState.Collided

        check_cell = sp.check_cell
        transit_state = self.insert_into_cell(check_cell, 3)

        if transit_state == TransitionState.OK:
            transit_state = self.check_other_cells(check_cell)

        return transit_state

    @anchor("CTransition::validate_placement", "Transition.cs:ValidatePlacement")
    def validate_placement(self, transition_state: TransitionState, adjust: bool) -> TransitionState:
        """``CurPos = CheckPos`` is ACE's assignment of the reference: the two stay one Position
        until SetCheckPos or RestoreCheckPos makes a new CheckPos."""
        sp = self.sphere_path
        if sp.check_cell is None:
            return TransitionState.Collided

        if transition_state == TransitionState.OK:
            sp.cur_pos = sp.check_pos
            sp.cur_cell = sp.check_cell
            sp.cache_global_curr_center()
        elif transition_state in (TransitionState.Adjusted, TransitionState.Slid):
            if adjust:
                return self.validate_placement(self.placement_insert(), False)
        return transition_state

    @anchor("CTransition::validate_placement_transition", "Transition.cs:ValidatePlacementTransition")
    def validate_placement_transition(self, transition_state: TransitionState) -> TransitionState:
        """ACE's `ref int redo` is set to 0 and never read by its callers; it is dropped. ``CurPos =
        CheckPos`` shares the reference, as in ValidatePlacement."""
        sp = self.sphere_path
        if sp.check_cell is None:
            return TransitionState.Collided

        if transition_state == TransitionState.OK:
            sp.cur_pos = sp.check_pos
            sp.cur_cell = sp.check_cell
            sp.cache_global_curr_center()
        elif transition_state in (TransitionState.Collided, TransitionState.Adjusted, TransitionState.Slid):
            # added target id (ACE)
            if sp.placement_allows_sliding and self.object_info.target_id == 0:
                self.collision_info.init()
        return transition_state

    @anchor("CTransition::init_contact_plane", "Transition.cs:InitContactPlane")
    def init_contact_plane(self, cell_id: int, contact_plane: Plane, is_water: bool) -> None:
        self.init_last_known_contact_plane(cell_id, contact_plane, is_water)
        ci = self.collision_info
        ci.contact_plane_valid = True
        ci.contact_plane = Plane(contact_plane.normal, contact_plane.d)
        ci.contact_plane_is_water = is_water
        ci.contact_plane_cell_id = cell_id

    @anchor("CTransition::init_last_known_contact_plane", "Transition.cs:InitLastKnownContactPlane")
    def init_last_known_contact_plane(self, cell_id: int, contact_plane: Plane, is_water: bool) -> None:
        ci = self.collision_info
        ci.last_known_contact_plane_valid = True
        ci.last_known_contact_plane = Plane(contact_plane.normal, contact_plane.d)
        ci.last_known_contact_plane_is_water = is_water
        ci.last_known_contact_plane_cell_id = cell_id

    @anchor("CTransition::init_object", "Transition.cs:InitObject")
    def init_object(self, obj, object_state: int) -> None:
        self.object_info.init(obj, object_state)

    @anchor("CTransition::init_path", "Transition.cs:InitPath")
    def init_path(self, begin_cell, begin_pos, end_pos) -> None:
        self.sphere_path.init_path(begin_cell, begin_pos, end_pos)

    @anchor("CTransition::check_collisions", "Transition.cs:CheckCollisions")
    def check_collisions(self, obj) -> bool:
        self.sphere_path.insert_type = InsertType.Placement
        self.sphere_path.set_check_pos(self.sphere_path.cur_pos, self.sphere_path.cur_cell)

        return obj.find_obj_collisions(self) != TransitionState.OK

    @anchor("CTransition::init_sliding_normal", "Transition.cs:InitSlidingNormal")
    def init_sliding_normal(self, normal: Vector3) -> None:
        ci = self.collision_info
        ci.sliding_normal_valid = True
        ci.sliding_normal = Vector3(normal.x, normal.y, normal.z)
        small, ci.sliding_normal = normalize_check_small(ci.sliding_normal)
        if small:
            ci.sliding_normal = self._zero()

    @anchor("CTransition::init_sphere", "Transition.cs:InitSphere")
    def init_sphere(self, num_sphere: int, spheres: list, scale) -> None:
        """Both ACE overloads: pass a one-element list for InitSphere(int, Sphere, float)."""
        self.sphere_path.init_sphere(num_sphere, spheres, scale)

    @anchor("CTransition::insert_into_cell", "Transition.cs:InsertIntoCell")
    def insert_into_cell(self, cell, num_insertion_attempts: int) -> TransitionState:
        if cell is None:
            return TransitionState.Collided
        transition_state = TransitionState.OK
        for _ in range(num_insertion_attempts):
            transition_state = cell.find_collisions(self)
            if transition_state in (TransitionState.OK, TransitionState.Collided):
                return transition_state
            if transition_state == TransitionState.Slid:
                self.collision_info.contact_plane_valid = False
                self.collision_info.contact_plane_is_water = False
        return transition_state

    @anchor("CTransition::step_down", "Transition.cs:StepDown")
    def step_down(self, step_down_height, z_val) -> bool:
        sp = self.sphere_path
        ci = self.collision_info
        sp.neg_poly_hit = False
        sp.step_down = True
        sp.step_down_amt = step_down_height
        sp.walk_interp = self.mode.scalar(1.0)

        if not sp.step_up:
            sp.cell_array_valid = False
            s = type(step_down_height)
            offset = Vector3(s(0.0), s(0.0), -step_down_height)
            origin = sp.check_pos.frame.origin
            sp.check_pos.frame.origin = origin.with_z(origin.z - step_down_height)
            sp.cache_global_sphere(offset)

        transition_state = self.transitional_insert(5)
        sp.step_down = False

        if self.trace is not None and transition_state == TransitionState.OK and ci.contact_plane_valid:
            self.trace.walkable(ci.contact_plane.normal.z, z_val)
        if (transition_state == TransitionState.OK and ci.contact_plane_valid and ci.contact_plane.normal.z >= z_val
                and (not self.object_info.state & ObjectInfoState.EdgeSlide or sp.step_up or self.check_walkable(z_val))):
            sp.backup = sp.insert_type
            sp.insert_type = InsertType.Placement
            transition_state = self.transitional_insert(1)
            sp.insert_type = sp.backup
            ok = transition_state == TransitionState.OK
            self._hit("step_down:ok" if ok else "step_down:placement_blocked")
            return ok

        self._hit("step_down:fail")
        return False

    @anchor("CTransition::step_up", "Transition.cs:StepUp")
    def step_up(self, collision_normal: Vector3) -> bool:
        sp = self.sphere_path
        ci = self.collision_info
        oi = self.object_info
        ci.contact_plane_valid = False
        ci.contact_plane_is_water = False

        sp.step_up = True
        sp.step_up_normal = Vector3(collision_normal.x, collision_normal.y, collision_normal.z)

        step_down_height = self.mode.scalar(STEP_DOWN_PROBE)
        z_landing_value = self.mode.scalar(LANDING_Z)

        if oi.state & ObjectInfoState.OnWalkable:
            z_landing_value = oi.get_walkable_z()
            step_down_height = oi.step_up_height

        sp.walkable_allowance = z_landing_value
        sp.backup_cell = sp.check_cell
        sp.backup_check_pos = sp.check_pos.copy()

        step_down = self.step_down(step_down_height, z_landing_value)

        sp.step_up = False
        sp.walkable = None

        if not step_down:
            sp.restore_check_pos()
        self._hit("step_up:ok" if step_down else "step_up:fail")
        return step_down

    @anchor("CTransition::transitional_insert", "Transition.cs:TransitionalInsert")
    def transitional_insert(self, num_insertion_attempts: int) -> TransitionState:
        sp = self.sphere_path
        ci = self.collision_info
        oi = self.object_info
        if sp.check_cell is None:
            return TransitionState.OK
        if num_insertion_attempts <= 0:
            return TransitionState.Invalid

        transit_state = TransitionState.Invalid

        for _ in range(num_insertion_attempts):
            if self.trace is not None and self.trace.recorder is not None:  # tracing (port/tracing.py)
                self.trace.recorder.at_insert(self)
            transit_state = self.insert_into_cell(sp.check_cell, num_insertion_attempts)

            if transit_state == TransitionState.OK:
                transit_state = self.check_other_cells(sp.check_cell)
                if transit_state != TransitionState.OK:
                    sp.neg_poly_hit = False
                if transit_state == TransitionState.Collided:
                    return transit_state
            elif transit_state == TransitionState.Collided:
                return transit_state
            elif transit_state == TransitionState.Adjusted:
                sp.neg_poly_hit = False
            elif transit_state == TransitionState.Slid:
                ci.contact_plane_valid = False
                ci.contact_plane_is_water = False
                sp.neg_poly_hit = False

            if transit_state != TransitionState.OK:
                continue

            if not sp.collide:
                if sp.neg_poly_hit and not sp.step_down and not sp.step_up:
                    sp.neg_poly_hit = False
                    if sp.neg_step_up:
                        self._hit("transitional_insert:neg_poly_step_up")
                        if not self.step_up(sp.neg_collision_normal):
                            transit_state = sp.step_up_slide(self)
                    else:
                        self._hit("transitional_insert:neg_poly_slide")
                        transit_state, sp.neg_collision_normal = sp.global_sphere[0].slide_sphere(
                            self, sp.neg_collision_normal, sp.global_curr_center[0].center)
                else:
                    if (ci.contact_plane_valid or not oi.state & ObjectInfoState.Contact or sp.step_down
                            or sp.check_cell is None or not oi.step_down):
                        return TransitionState.OK

                    z_val = self.mode.scalar(LANDING_Z)
                    step_down_height = self.mode.scalar(STEP_DOWN_PROBE)

                    if oi.state & ObjectInfoState.OnWalkable:
                        z_val = oi.get_walkable_z()
                        step_down_height = oi.step_down_height
                    sp.walkable_allowance = z_val
                    sp.save_check_pos()

                    radsum = sp.global_sphere[0].radius * 2
                    if self.trace is not None:
                        self.trace.boundary("step_down_height", step_down_height, radsum)
                    if sp.num_sphere < 2:
                        if radsum < step_down_height:
                            step_down_height = sp.global_sphere[0].radius * 0.5

                    if radsum >= step_down_height:
                        self._hit("transitional_insert:step_down_whole")
                        if self.step_down(step_down_height, z_val):
                            sp.walkable = None
                            return TransitionState.OK
                    else:
                        # 2 half-steps (ACE)
                        self._hit("transitional_insert:step_down_halves")
                        step_down_height = step_down_height * 0.5
                        if self.step_down(step_down_height, z_val) or self.step_down(step_down_height, z_val):
                            sp.walkable = None
                            return TransitionState.OK

                    result, transit_state = self.edge_slide(transit_state, step_down_height, z_val)
                    if result:
                        return transit_state
            else:
                reset = False
                sp.collide = False
                if ci.contact_plane_valid and self.check_walkable(self.mode.scalar(LANDING_Z)):
                    sp.backup = sp.insert_type
                    sp.insert_type = InsertType.Placement
                    transit_state = self.transitional_insert(num_insertion_attempts)
                    sp.insert_type = sp.backup
                    if transit_state != TransitionState.OK:
                        transit_state = TransitionState.OK
                        reset = True
                else:
                    reset = True

                sp.walkable = None

                if not reset:
                    self._hit("transitional_insert:collide_landed")
                    return transit_state

                self._hit("transitional_insert:collide_reset")
                sp.restore_check_pos()
                ci.contact_plane_valid = False
                ci.contact_plane_is_water = False

                if ci.last_known_contact_plane_valid:
                    ci.last_known_contact_plane_valid = False
                    oi.stop_velocity()
                else:
                    ci.set_collision_normal(sp.step_up_normal)
                return TransitionState.Collided
        return transit_state

    @anchor("CTransition::validate_transition", "Transition.cs:ValidateTransition")
    def validate_transition(self, transition_state: TransitionState) -> TransitionState:
        """ValidateTransition(transitionState, ref redo): redo is always 0 afterwards and unused."""
        sp = self.sphere_path
        ci = self.collision_info
        oi = self.object_info
        _redo = 1
        z = self.mode.scalar(0.0)
        contact_plane = Plane(self._zero(), z)

        if transition_state != TransitionState.OK or _position_equals(sp.check_pos, sp.cur_pos):
            _redo = 0
            if transition_state != TransitionState.OK:
                if transition_state != TransitionState.Invalid:
                    self._hit("validate_transition:rejected_step")
                    if ci.last_known_contact_plane_valid:
                        oi.stop_velocity()
                        angle = dot(ci.last_known_contact_plane.normal, sp.global_curr_center[0].center) + ci.last_known_contact_plane.d
                        if sp.global_sphere[0].radius + EPSILON > abs(angle):
                            self._hit("validate_transition:last_known_contact_restored")
                            ci.set_contact_plane(ci.last_known_contact_plane, ci.last_known_contact_plane_is_water)
                            ci.contact_plane_cell_id = ci.last_known_contact_plane_cell_id
                            if oi.state & ObjectInfoState.OnWalkable:
                                _redo = 1
                    if not ci.collision_normal_valid:
                        contact_plane = Plane(unit_z_like(z), contact_plane.d)
                        ci.set_collision_normal(contact_plane.normal)
                    sp.set_check_pos(sp.cur_pos, sp.cur_cell)
                    self.build_cell_array(None)
                    transition_state = TransitionState.OK
            else:
                self.set_current_check_pos()
        else:
            self.set_current_check_pos()

        if ci.collision_normal_valid:
            ci.set_sliding_normal(ci.collision_normal)

        if not oi.state & ObjectInfoState.IsViewer:
            if oi.object.state & PhysicsState.Gravity:
                if _redo == 0:
                    if ci.frames_stationary_fall > 0:
                        if ci.frames_stationary_fall > 1:
                            self._hit("validate_transition:stationary_fall_3")
                            ci.frames_stationary_fall = 3
                            glob = sp.global_sphere[0]
                            contact_plane = Plane(unit_z_like(z), glob.radius - glob.center.z)
                            ci.set_contact_plane(contact_plane, False)
                            ci.contact_plane_cell_id = sp.check_pos.obj_cell_id
                            if not oi.state & ObjectInfoState.Contact:
                                ci.set_collision_normal(contact_plane.normal)
                                ci.collided_with_environment = True
                        else:
                            self._hit("validate_transition:stationary_fall_2")
                            ci.frames_stationary_fall = 2
                    else:
                        self._hit("validate_transition:stationary_fall_1")
                        ci.frames_stationary_fall = 1
                else:
                    ci.frames_stationary_fall = 0

        ci.last_known_contact_plane_valid = ci.contact_plane_valid

        if ci.contact_plane_valid:
            ci.last_known_contact_plane = ci.contact_plane
            ci.last_known_contact_plane_cell_id = ci.contact_plane_cell_id
            ci.last_known_contact_plane_is_water = ci.contact_plane_is_water
            oi.state |= ObjectInfoState.Contact
            if self.trace is not None:
                self.trace.walkable(ci.contact_plane.normal.z, FLOOR_Z)
            if oi.is_valid_walkable(ci.contact_plane.normal):
                oi.state |= ObjectInfoState.OnWalkable
            else:
                oi.state &= ~int(ObjectInfoState.OnWalkable)
        else:
            oi.state &= ~int(ObjectInfoState.Contact | ObjectInfoState.OnWalkable)

        return transition_state

    @anchor("CTransition::set_current_check_pos", "Transition.cs:SetCurrentCheckPos")
    def set_current_check_pos(self) -> None:
        sp = self.sphere_path
        sp.cur_pos = sp.check_pos.copy()
        sp.cur_cell = sp.check_cell
        sp.cache_global_curr_center()
        sp.set_check_pos(sp.cur_pos, sp.cur_cell)
