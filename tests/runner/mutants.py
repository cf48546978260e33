"""Planted bugs: mutated copies of the port, loaded as separate packages beside the real one.

`load_mutant(m)` copies port/ into a temporary directory as package ``acconform_mutant_<i>``,
rewrites its absolute ``acconform.port`` imports to point at the copy, applies the mutation
(an exact text replacement that must match exactly once, so a mutation that no longer applies
fails loudly instead of testing nothing) and returns the copy's ``run_scene``. The real port is
never edited and keeps working in the same process (it is the oracle in the mutation check).
"""

from __future__ import annotations

import functools

import importlib
import shutil
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

PORT_DIR = Path(__file__).resolve().parents[2] / "port"


TICKS = ("ticks",)  # a tick-loop mutant: replayed over the tick records (tick_kill)


@dataclass(frozen=True)
class Mutation:
    name: str
    file: str  # relative to port/
    old: str
    new: str
    what: str
    kinds: tuple[str, ...] = ("terrain", "bsp", "obstacles")  # the scene kinds its hunt draws


MUTATIONS: tuple[Mutation, ...] = (
    Mutation("cliff_slide_sign_flipped", "transition/transition.py",
             "        if angle <= 0.0:\n            self._hit(\"cliff_slide:normal_kept\")",
             "        if angle > 0.0:\n            self._hit(\"cliff_slide:normal_kept\")",
             "CliffSlide's sign test flipped: slides toward the cliff instead of along it"),
    Mutation("edge_slide_back_probe_skipped", "transition/transition.py",
             "        sp.add_offset_to_check_pos(offset)\n\n        self.step_down(step_down_height, zval)\n",
             "        sp.add_offset_to_check_pos(offset)\n\n",
             "EdgeSlide's back-probe (the StepDown from the previous position) skipped"),
    Mutation("adjust_offset_block_offset_dropped", "transition/transition.py",
             "dist = dot(glob_sphere.center - block_offset, ci.contact_plane.normal)",
             "dist = dot(glob_sphere.center, ci.contact_plane.normal)",
             "AdjustOffset ignores the block offset of a contact plane in another landblock"),
    Mutation("cliff_slide_block_offset_dropped", "transition/transition.py",
             "angle = dot(collide_normal, offset + block_offset)",
             "angle = dot(collide_normal, offset)",
             "CliffSlide ignores the block offset between current and check cell"),
    Mutation("step_down_one_sphere_halved_differently", "transition/transition.py",
             "step_down_height = sp.global_sphere[0].radius * 0.5",
             "step_down_height = sp.global_sphere[0].radius * 0.25",
             "the one-sphere step-down cap is r/4 instead of r/2"),
    Mutation("step_down_two_halves_made_thirds", "transition/transition.py",
             "step_down_height = step_down_height * 0.5",
             "step_down_height = step_down_height * 0.333",
             "the two half step-downs are thirds"),
    Mutation("validate_walkable_contact_test_strict", "transition/object_info.py",
             "        if dist >= -EPSILON:\n            if dist > EPSILON:",
             "        if dist > -EPSILON:\n            if dist > EPSILON:",
             "ValidateWalkable's sphere-on-plane test `>=` made `>`"),
    Mutation("validate_walkable_touch_band_widened", "transition/object_info.py",
             "            if dist > EPSILON:\n                return TransitionState.OK",
             "            if dist > EPSILON * 4:\n                return TransitionState.OK",
             "ValidateWalkable treats a sphere up to 4 epsilon above the ground as touching it"),
    Mutation("step_down_interp_floor_raised", "transition/object_info.py",
             "if interp >= path.walk_interp or interp < -0.1:",
             "if interp >= path.walk_interp or interp < 0.0:",
             "the step-down interpolation accepts no overshoot (-0.1 made 0)"),
    Mutation("edge_slide_cliff_threshold_lowered", "transition/transition.py",
             "if ci.contact_plane_valid and ci.contact_plane.normal.z < zval:",
             "if ci.contact_plane_valid and ci.contact_plane.normal.z < zval * 0.9:",
             "EdgeSlide takes slopes just past FloorZ for precipices, not cliffs"),
    Mutation("block_offset_x_sign_flipped", "land_defs.py",
             "(local_to[0] - local_from[0]) * SQUARE_LENGTH",
             "(local_from[0] - local_to[0]) * SQUARE_LENGTH",
             "GetBlockOffset's x offset has the wrong sign"),
    Mutation("partial_water_depth_changed", "land/landblock_struct.py",
             "return s(WATER_DEPTH_PARTIAL_WATER) if has_water != 0 else s(WATER_DEPTH_DRY)",
             "return s(WATER_DEPTH_DRY) if has_water != 0 else s(WATER_DEPTH_DRY)",
             "a partly flooded cell's water corner sinks the sphere like dry land"),
    Mutation("walkable_floor_z_one_percent_lower", "physics_obj.py",
             "return bool(normal.z >= FLOOR_Z)",
             "return bool(normal.z >= FLOOR_Z * 0.99)",
             "IsValidWalkable accepts slopes 1% steeper than FloorZ"),
    Mutation("num_steps_divides_instead", "transition/transition.py",
             "offset_per_step = offset * (s(1.0) / s(num_steps))",
             "offset_per_step = offset / s(num_steps)",
             "CalcNumSteps divides by the step count instead of multiplying by its reciprocal"),
    # ---- exact boundaries (issue 14): each changes behaviour only where two values are bit-equal
    Mutation("walkable_floor_z_strict", "physics_obj.py",
             "return bool(normal.z >= FLOOR_Z)",
             "return bool(normal.z > FLOOR_Z)",
             "IsValidWalkable's `normal.z >= FloorZ` made `>`: a slope exactly at FloorZ slides"),
    Mutation("floor_z_one_ulp_low", "constants.py",
             "FLOOR_Z = f32_from_bits(0x3F2A0751)",
             "FLOOR_Z = f32_from_bits(0x3F2A0750)",
             "FloorZ one ulp low (OpenAC's rounding): a slope one ulp under FloorZ stands"),
    Mutation("floor_z_one_ulp_high", "constants.py",
             "FLOOR_Z = f32_from_bits(0x3F2A0751)",
             "FLOOR_Z = f32_from_bits(0x3F2A0752)",
             "FloorZ one ulp high: a slope exactly at FloorZ slides"),
    Mutation("landing_z_one_ulp_low", "constants.py",
             "LANDING_Z = f32_from_bits(0x3DB27EB0)",
             "LANDING_Z = f32_from_bits(0x3DB27EAF)",
             "LandingZ one ulp low: a landing slope exactly one ulp under LandingZ lands"),
    Mutation("step_down_walkable_strict", "transition/transition.py",
             "and ci.contact_plane.normal.z >= z_val",
             "and ci.contact_plane.normal.z > z_val",
             "StepDown's `contact_plane.normal.z >= zVal` made `>`"),
    Mutation("walkable_allowable_inclusive", "transition/sphere_path.py",
             "return bool(zval > self.walkable_allowance)",
             "return bool(zval >= self.walkable_allowance)",
             "IsWalkableAllowable's `zval > WalkableAllowance` made `>=`"),
    Mutation("walkable_hits_sphere_strict", "geom/polygon.py",
             "        if dp <= path.walkable_allowance:\n            return False",
             "        if dp < path.walkable_allowance:\n            return False",
             "walkable_hits_sphere's `dp <= WalkableAllowance` made `<`: a polygon exactly at the allowance is walkable"),
    Mutation("step_sphere_down_allowance_strict", "geom/sphere.py",
             "    if disp.z <= path.walkable_allowance:",
             "    if disp.z < path.walkable_allowance:",
             "Sphere.StepSphereDown's `disp.Z <= WalkableAllowance` made `<`"),
    Mutation("sphere_tangent_not_touching", "geom/sphere.py",
             "    return other_sphere.length_squared() <= radsum * radsum",
             "    return other_sphere.length_squared() < radsum * radsum",
             "Sphere.CollidesWithSphere: spheres exactly touching no longer collide"),
    Mutation("sphere_placement_tangent_not_touching", "geom/sphere.py",
             "        if disp.length_squared() <= radsum * radsum:\n            return TransitionState.Collided",
             "        if disp.length_squared() < radsum * radsum:\n            return TransitionState.Collided",
             "Sphere.IntersectsSphere's placement test: exactly touching is no collision"),
    Mutation("cylsphere_tangent_not_touching", "geom/cyl_sphere.py",
             "        if disp.x * disp.x + disp.y * disp.y <= radsum * radsum:",
             "        if disp.x * disp.x + disp.y * disp.y < radsum * radsum:",
             "CylSphere.CollidesWithSphere: a sphere exactly touching the cylinder no longer collides"),
    Mutation("bsp_find_walkable_order_swapped", "geom/bsp.py",
             "        found, changed = self.pos_node.find_walkable(path, valid_pos, polygon, movement, up, changed)\n"
             "        last, changed = self.neg_node.find_walkable(path, valid_pos, found, movement, up, changed)",
             "        found, changed = self.neg_node.find_walkable(path, valid_pos, polygon, movement, up, changed)\n"
             "        last, changed = self.pos_node.find_walkable(path, valid_pos, found, movement, up, changed)",
             "BSPNode.find_walkable visits the back side first when the sphere straddles the split"),
    Mutation("outside_cell_border_belongs_below", "land_defs.py",
             "        x = offset[0] + cast_float(_x, cs_floor(_x / CELL_LENGTH))",
             "        x = offset[0] + cast_float(_x, -cs_floor(-_x / CELL_LENGTH) - 1)",
             "get_outside_lcoord puts a point exactly on a cell border (x) in the cell below it"),
    # polygon touches, step heights at the rise (issue 14's second set): each comparison flipped at its equality
    Mutation("plane_tangent_not_touching", "geom/polygon.py",
             "        if abs(dp_pos) > rad:\n            return False, contact_point\n\n"
             "        diff = rad * rad - dp_pos * dp_pos\n        contact_point = sphere.center - plane.normal * dp_pos",
             "        if abs(dp_pos) >= rad:\n            return False, contact_point\n\n"
             "        diff = rad * rad - dp_pos * dp_pos\n        contact_point = sphere.center - plane.normal * dp_pos",
             "polygon_hits_sphere_precise's `|dp_pos| > rad` made `>=`: a plane exactly rad from the centre is missed"),
    Mutation("polygon_edge_touch_missed", "geom/polygon.py",
             "if cross_.length_squared() * diff < disp_dot * disp_dot:",
             "if cross_.length_squared() * diff <= disp_dot * disp_dot:",
             "polygon_hits_sphere_precise's edge test `<` made `<=`: an edge exactly tangent to the sphere is missed"),
    Mutation("polygon_vertex_touch_missed", "geom/polygon.py",
             "                if disp.length_squared() <= diff:\n                    return True, contact_point",
             "                if disp.length_squared() < diff:\n                    return True, contact_point",
             "polygon_hits_sphere_precise's vertex test `<=` made `<`: a vertex exactly on the sphere is missed"),
    Mutation("sphere_step_up_inclusive", "geom/sphere.py",
             "    if transition.object_info.step_up_height < radsum - disp.z:",
             "    if transition.object_info.step_up_height <= radsum - disp.z:",
             "Sphere.StepSphereUp's `StepUpHeight < rise` made `<=`: a rise exactly the step-up height slides"),
    Mutation("cylsphere_step_up_inclusive", "geom/cyl_sphere.py",
             "        if obj.step_up_height < check_pos.radius + self.height - disp.z:",
             "        if obj.step_up_height <= check_pos.radius + self.height - disp.z:",
             "CylSphere.StepSphereUp's `StepUpHeight < rise` made `<=`: a rise exactly the step-up height slides"),
    Mutation("step_down_whole_strict", "transition/transition.py",
             "                    if radsum >= step_down_height:",
             "                    if radsum > step_down_height:",
             "TransitionalInsert's `2r >= stepDownHeight` made `>`: a step-down of exactly 2r is taken in two halves"),
    Mutation("check_walkable_halving_inclusive", "transition/transition.py",
             "        if step_height > glob_sphere.radius * 2:\n            step_height = step_height * 0.5",
             "        if step_height >= glob_sphere.radius * 2:\n            step_height = step_height * 0.5",
             "CheckWalkable's `stepHeight > 2r` made `>=`: a probe of exactly 2r is halved"),
    # registration: where a static is placed (PhysicsObj.add_obj_to_cell's chain)
    Mutation("add_cell_block_own_landblock_skip_dropped", "cell/land_cell.py",
             "            if id >> 16 != cell_id >> 16:\n                continue\n",
             "",
             "add_cell_block registers a bbox-placed static in the neighbouring landblock's cells too (its FIXME skip dropped)"),
    Mutation("part_bbox_taken_from_the_sphere", "part_array.py",
             "        return self.gfx_obj.gfx_bound_box",
             "        s = self.gfx_obj.physics_sphere\n"
             "        if s is None:\n"
             "            return self.gfx_obj.gfx_bound_box\n"
             "        from .bbox import BBox\n"
             "        r = Vector3(s.radius, s.radius, s.radius)\n"
             "        return BBox(s.center - r, s.center + r)",
             "a BSP part's bounding box is its physics sphere's box, not the box over its vertices (GfxObj.Init)"),
    Mutation("shadow_cells_in_reverse_cell_array_order", "physics_obj.py",
             "        for cell in cell_array.cells.values():",
             "        for cell in reversed(cell_array.cells.values()):",
             "add_shadows_to_cell walks the CellArray backwards: shadow lists and ShadowObjects in reverse order"),
    Mutation("cylsphere_placed_by_its_bbox", "physics_obj.py",
             "        if (self.part_array is not None and self.part_array.get_num_cylsphere() != 0",
             "        if (False and self.part_array is not None and self.part_array.get_num_cylsphere() != 0",
             "a cylsphere static is placed by its part's bbox (find_bbox_cell_list), not by find_cell_list"),
    # ---- indoors (issue 12): hunted on the indoor kind (strategies/dungeon.py)
    Mutation("portal_side_flipped", "dat/cell_portal.py",
             "return (self.flags & PORTAL_FLAG_PORTAL_SIDE) == 0",
             "return (self.flags & PORTAL_FLAG_PORTAL_SIDE) != 0",
             "CellPortal.PortalSide read from the wrong sense of flag bit 0x2: a portal's far side is its near side",
             ("indoor",)),
    Mutation("cell_bsp_slack_dropped", "geom/bsp.py",
             "check_rad = cur_sphere.radius + CELL_BSP_SLACK",
             "check_rad = cur_sphere.radius",
             "sphere_intersects_cell_bsp without its 0.01 m slack: a sphere about to reach a cell is outside it",
             ("indoor",)),
    Mutation("point_in_cell_close_is_outside", "geom/bsp.py",
             "if side == Side.Front or side == Side.Close:",
             "if side == Side.Front:",
             "point_inside_cell_bsp drops the EPSILON band (Side.Close): a point on a cell's plane is outside it",
             ("indoor",)),
    Mutation("visible_cell_pruning_skipped", "cell/obj_cell.py",
             "            if not found:\n                cell_array.remove_cell(cell)",
             "            if False:\n                cell_array.remove_cell(cell)",
             "find_cell_list keeps the cells the mover's EnvCell does not see",
             ("indoor",)),
    Mutation("neighbour_tested_in_own_frame", "cell/env_cell.py",
             "                        center = other_cell.pos.frame.global_to_local(sphere.center)",
             "                        center = self.pos.frame.global_to_local(sphere.center)",
             "find_transit_cells tests a sphere against the neighbour's cell BSP in this cell's frame",
             ("indoor",)),
    Mutation("outside_portal_test_off", "cell/env_cell.py",
             "            if portal.other_cell_id == OUTSIDE_CELL_ID:\n                for sphere in spheres:",
             "            if False:\n                for sphere in spheres:",
             "find_transit_cells treats a portal to 0xFFFF as one to an unloaded cell: the outdoor cells never added",
             ("indoor",)),
    # ---- buildings (issue 20): hunted on the buildings kind (strategies/buildings.py)
    Mutation("building_portal_side_unflipped", "dat/c_bld_portal.py",
             "return (self.flags & PORTAL_FLAG_PORTAL_SIDE) == 0  # ACE: !Flags.HasFlag(PortalFlags.PortalSide)",
             "return (self.flags & PORTAL_FLAG_PORTAL_SIDE) != 0",
             "CBldPortal.PortalSide read as before ACE #4315 (set when the flag bit is set)",
             ("buildings",)),
    Mutation("building_hits_interior_cell_never_set", "cell/env_cell.py",
             "            if path is not None:\n                path.hits_interior_cell = True\n\n            cell_array.add_cell(self.id, self)",
             "            cell_array.add_cell(self.id, self)",
             "check_building_transit adds the building's cell but never sets SpherePath.HitsInteriorCell",
             ("buildings",)),
    Mutation("building_check_ignored", "cell/building_obj.py",
             "        transition.sphere_path.building_check = True\n",
             "",
             "find_building_collisions never sets SpherePath.BuildingCheck: the shell's BSP always clears the cell",
             ("buildings",)),
    Mutation("building_collisions_before_terrain", "cell/land_cell.py",
             "        transit_state = self.find_env_collisions(transition)\n        if transit_state == TransitionState.OK:\n"
             "            transit_state = SortCell.find_collisions(self, transition)  # base.FindCollisions",
             "        transit_state = SortCell.find_collisions(self, transition)  # base.FindCollisions\n"
             "        if transit_state == TransitionState.OK:\n            transit_state = self.find_env_collisions(transition)",
             "LandCell.FindCollisions tests the building before the terrain",
             ("buildings",)),
    Mutation("building_cells_not_recursive", "cell/building_obj.py",
             "        for visible_cell in cell.visible_cells.values():\n            self.add_cells_recursive(visible_cell)",
             "        pass",
             "add_cells_recursive stops at the portal's cell: a building's cells one level deep only",
             ("buildings",)),
    Mutation("building_transit_first_sphere_only", "cell/env_cell.py",
             "        trace = path.trace if path is not None else None\n        for sphere in spheres:",
             "        trace = path.trace if path is not None else None\n        for sphere in spheres[:1]:",
             "check_building_transit tests only the first sphere (ACE tests every sphere, not numSphere)",
             ("buildings",)),
    # ---- placement (issue 12: a scene's mover.placement, ACE's SetPositionInternal): every kind draws one
    Mutation("placement_slide_flag_ignored", "physics_obj.py",
             "        if not set_pos_flags & SetPositionFlags.Slide:\n"
             "            transition.sphere_path.placement_allows_sliding = False\n",
             "",
             "CheckPositionInternal ignores a SetPosition without Slide: a blocked placement always slides",
             ("terrain", "bsp", "obstacles", "indoor")),
    Mutation("placement_in_no_cell_left_active", "physics_obj.py",
             "            self.set_active(False)\n            return SetPositionError.OK",
             "            return SetPositionError.OK",
             "SetPositionInternal stores a position in no cell but leaves the mover Active",
             ("terrain", "bsp", "obstacles", "indoor")),
    Mutation("adjust_position_seen_outside_ignored", "physics_obj.py",
             "        if not visible_cell.seen_outside:\n            return None\n",
             "",
             "AdjustPosition falls out to the landblock from any EnvCell, not only a SeenOutside one",
             ("indoor",)),
    # ---- the tick loop (issue 19): caught by replaying the tick records (tick_kill), not by the hunt
    Mutation("tick_remainder_dropped", "physics_obj.py",
             "        self.update_time = self.physics_timer_current_time\n        return True",
             "        self.update_time = self.timer.current_time\n        return True",
             "update_object drops the remainder under MinQuantum (UpdateTime = CurrentTime, as ClassicDereth)",
             TICKS),
    Mutation("tick_max_quantum_retail", "constants.py",
             "MAX_QUANTUM = f32_from_bits(0x3DCCCCCD)",
             "MAX_QUANTUM = f32_from_bits(0x3E4CCCCD)",
             "MaxQuantum 0.2f (retail's) instead of ACE's 0.1f", TICKS),
    Mutation("tick_sledding_flat_z_cos_10", "constants.py",
             "SLEDDING_FLAT_Z = f32_from_bits(0x3F7FFFB2)",
             "SLEDDING_FLAT_Z = f32_from_bits(0x3F7C1C5C)",
             "calc_friction's sledding glide threshold cos 10 deg (other ports') instead of 0.99999536f", TICKS),
    Mutation("tick_friction_before_velocity_clamp", "physics_obj.py",
             "            if velocity_mag2 > MAX_VELOCITY_SQUARED:\n"
             "                _hit(trace, \"update_physics:velocity_clamped\")\n"
             "                self.velocity = normalize(self.velocity) * MAX_VELOCITY\n"
             "                velocity_mag2 = type(velocity_mag2)(MAX_VELOCITY_SQUARED)\n"
             "            # todo: collision normals (ACE)\n"
             "            self.calc_friction(quantum, velocity_mag2, trace)\n",
             "            self.calc_friction(quantum, velocity_mag2, trace)\n"
             "            if velocity_mag2 > MAX_VELOCITY_SQUARED:\n"
             "                _hit(trace, \"update_physics:velocity_clamped\")\n"
             "                self.velocity = normalize(self.velocity) * MAX_VELOCITY\n"
             "                velocity_mag2 = type(velocity_mag2)(MAX_VELOCITY_SQUARED)\n",
             "UpdatePhysicsInternal applies friction before clamping the velocity to MaxVelocity", TICKS),
    Mutation("tick_elasticity_sign_flipped", "physics_obj.py",
             "elastic_angle = -(collision_angle * (self.elasticity + type(collision_angle)(1.0)))",
             "elastic_angle = -(collision_angle * (type(collision_angle)(1.0) - self.elasticity))",
             "handle_all_collisions' bounce with the elasticity's sign flipped (1 - e instead of 1 + e)", TICKS),
    Mutation("tick_block_dist_off_by_one", "physics_obj.py",
             "        return max(dx, dy)",
             "        return max(dx, dy) + 1",
             "GetBlockDist one too many: a RequestPos in the next landblock is refused", TICKS),
    Mutation("tick_huge_quantum_inclusive", "physics_obj.py",
             "        if delta_time > HUGE_QUANTUM:",
             "        if delta_time >= HUGE_QUANTUM:",
             "update_object's `deltaTime > HugeQuantum` made `>=`: a tick of exactly 2 s is skipped", TICKS),
    Mutation("tick_rate_gate_dropped", "physics_obj.py",
             "        if delta_time < TICK_RATE:",
             "        if delta_time < 0.0:",
             "update_object runs every tick, however short (no TickRate gate)", TICKS),
    Mutation("tick_cached_velocity_unscaled_by_quantum", "physics_obj.py",
             "                    self.cached_velocity = self.position.get_offset(transit.sphere_path.cur_pos) "
             "/ cast_float(self.scale, quantum)",
             "                    self.cached_velocity = self.position.get_offset(transit.sphere_path.cur_pos)",
             "UpdateObjectInternal's CachedVelocity is the offset, not the offset over the quantum", TICKS),
    # ---- the motion layer (issue 40): caught by replaying the motion tick records (tick_kill)
    Mutation("motion_run_rate_rounded", "animation/motion_interp.py",
             "                motion = MotionCommand.RunForward\n\n            speed *= speed_mod\n",
             "                motion = MotionCommand.RunForward\n\n            speed = s(round(float(speed * speed_mod), 2))\n",
             "apply_run_to_command's forward speed times the run rate rounded to two decimals", TICKS),
    Mutation("motion_link_from_wrong_state", "animation/motion_table.py",
             "            link = self.links.get(_shl16(style) | (substate & 0xFFFFFF))\n"
             "            if link is not None:\n                result = link.get(motion)\n",
             "            link = self.links.get(_shl16(style) | (motion & 0xFFFFFF))\n"
             "            if link is not None:\n                result = link.get(substate)\n",
             "get_link at a positive speed looks the link up from the target motion to the substate "
             "(the negative-speed arm's order)", TICKS),
    Mutation("motion_jump_update_time_as_ordinary", "run.py",
             "        if not moving:\n            mover.update_time = mover.timer.current_time\n",
             "        mover.update_time = mover.timer.current_time\n",
             "the PK (FastTick) jump sets UpdateTime always, as the ordinary player's jump does", TICKS),
    Mutation("motion_frame_boundary_off_by_one", "animation/sequence.py",
             "            if curr_anim.get_high_frame() < cs_floor(frame_num):",
             "            if curr_anim.get_high_frame() <= cs_floor(frame_num):",
             "Sequence.update_internal ends a forward animation on its high frame, one frame early", TICKS),
    Mutation("motion_move_to_distance_inclusive", "animation/movement_parameters.py",
             "                if dist > self.distance_to_object:\n",
             "                if dist >= self.distance_to_object:\n",
             "MovementParameters.get_command's `dist > DistanceToObject` made `>=`: a MoveTo that starts exactly "
             "at its distance walks instead of arriving at once", TICKS),
    Mutation("motion_backwards_at_full_speed", "animation/motion_interp.py",
             "            motion = MotionCommand.WalkForward\n            speed *= -BACKWARDS_FACTOR\n",
             "            motion = MotionCommand.WalkForward\n            speed *= -1.0\n",
             "adjust_motion walks backward at the forward speed (no BackwardsFactor)", TICKS),
    Mutation("motion_run_turn_factor_dropped", "animation/motion_interp.py",
             "        elif motion == MotionCommand.TurnRight:\n            speed *= RUN_TURN_FACTOR\n",
             "        elif motion == MotionCommand.TurnRight:\n            pass\n",
             "apply_run_to_command turns at the walk's rate with the Run hold key (no RunTurnFactor)", TICKS),
    Mutation("motion_hold_key_of_raw_state_ignored", "animation/motion_interp.py",
             "        if hold_key == HoldKey.Invalid:\n            hold_key = self.raw_state.current_hold_key\n",
             "",
             "adjust_motion ignores the raw state's hold key when the command has none (Invalid)", TICKS),
    Mutation("motion_root_motion_of_next_frame", "animation/sequence.py",
             "                    if curr_anim.anim.pos_frames is not None:\n"
             "                        frame = AFrame.combine(frame, curr_anim.get_pos_frame(last_frame))\n",
             "                    if curr_anim.anim.pos_frames is not None:\n"
             "                        frame = AFrame.combine(frame, curr_anim.get_pos_frame(last_frame + 1))\n",
             "Sequence.update_internal applies the next frame's root motion, not the frame it leaves", TICKS),
    # ---- several movers (issue 41): caught by replaying the movers' tick records (tick_kill)
    Mutation("movers_pk_exemption_inverted", "physics_obj.py",
             "                         or state & ObjectInfoState.IsPK and wobj.is_pk()\n",
             "                         or state & ObjectInfoState.IsPK and not wobj.is_pk()\n",
             "FindObjCollisions' PK exemption inverted: two PK players pass through each other, a PK and an NPK "
             "one collide", TICKS),
    Mutation("movers_second_stepped_first", "run.py",
             "            timer.set(time)\n"
             "            if ticks.driver == \"update_object\":\n                updated = mover.update_object(lscape, trace)\n"
             "            else:\n"
             "                updated, location_cell = update_player_position(mover, Position.from_record(step.request_pos, mode),\n"
             "                                                                location_cell, lscape, trace)\n"
             "            others_updated = step_others(launches, stepped, lscape, trace, landblocks)\n",
             "            timer.set(time)\n"
             "            others_updated = step_others(launches, stepped, lscape, trace, landblocks)\n"
             "            if ticks.driver == \"update_object\":\n                updated = mover.update_object(lscape, trace)\n"
             "            else:\n"
             "                updated, location_cell = update_player_position(mover, Position.from_record(step.request_pos, mode),\n"
             "                                                                location_cell, lscape, trace)\n",
             "the other movers are stepped before the mover, not after it in the order they entered the landblock",
             TICKS),
    Mutation("movers_collision_records_never_end", "physics_obj.py",
             "            if delta_time > COLLISION_RECORD_LIFETIME or collision.ethereal and delta_time > 0.0 or force_end:",
             "            if force_end:",
             "report_collision_end ends a CollisionTable record only when forced: never by age or ethereality", TICKS),
    # ---- children (issue 41): caught by replaying the named child scenes' tick records (tick_kill)
    Mutation("children_frame_not_combined", "physics_obj.py",
             "            frame = AFrame.combine(self.position.frame, child_frame)\n",
             "            frame = self.position.frame\n",
             "UpdateChild: the holding location's frame is not combined with the parent's frame (a child held past "
             "its parent's parts sits at the parent's Position)", TICKS),
    Mutation("missile_ignore_player_test_dropped", "transition/object_info.py",
             "        if collide_obj.state & PhysicsState.Missile:\n            if not self.object.is_player:\n                return True\n",
             "        if collide_obj.state & PhysicsState.Missile:\n",
             "missile_ignore's player test dropped: a mover that is no player collides with a missile aimed at it "
             "instead of ignoring it", TICKS),
    Mutation("multipart_part_scale_ignored", "part_array.py",
             "                    part.gfx_obj_scale = self.setup.default_scale[i] * new_scale",
             "                    part.gfx_obj_scale = new_scale",
             "PartArray.SetScaleInternal ignores a part's DefaultScale (the Setup's per-part scale)", ("bsp",)),
)


_loaded: dict[str, object] = {}
_tmp = None


def load_mutant(index: int):
    """The mutated port's run_scene for MUTATIONS[index] (cached per process)."""
    global _tmp
    m = MUTATIONS[index]
    if m.name in _loaded:
        return _loaded[m.name]
    if _tmp is None:
        _tmp = tempfile.mkdtemp(prefix="acconform-mutants-")
        sys.path.insert(0, _tmp)
    pkg = f"acconform_mutant_{index}"
    dest = Path(_tmp) / pkg
    shutil.copytree(PORT_DIR, dest, ignore=shutil.ignore_patterns("__pycache__"))
    for f in dest.rglob("*.py"):
        text = f.read_text()
        if "acconform.port" in text:
            f.write_text(text.replace("acconform.port", pkg))
    target = dest / m.file
    text = target.read_text()
    count = text.count(m.old)
    if count != 1:
        raise AssertionError(f"mutation {m.name}: expected its text once in port/{m.file}, found {count} times")
    target.write_text(text.replace(m.old, m.new))
    importlib.invalidate_caches()
    run = importlib.import_module(f"{pkg}.run").run_scene
    _loaded[m.name] = run
    return run


# ---------------------------------------------------------------- the hunt (test and report share it)

BUDGET = 1500  # generated scenes per mutant before we call it missed
SEED = 0


def scene_size(scene) -> dict:
    """How big a (shrunk) scene is: landblocks, objects, and the mover's path length in metres."""
    import math

    def glob(p):
        return ((p.cell >> 24) * 192.0 + p.frame.origin[0], ((p.cell >> 16) & 0xFF) * 192.0 + p.frame.origin[1],
                p.frame.origin[2])

    m = scene.mover
    return {"landblocks": len(scene.landblocks), "objects": len(scene.objects),
            "path": round(math.dist(glob(m.begin), glob(m.end)), 3)}


def hunt(index: int, budget: int = BUDGET, seed: int = SEED, failures_dir=None, kinds=None) -> dict:
    """Run the mutant against the real port through run_campaign (one worker, no database) and
    say whether it was caught, after how many generated scenes, and how small the shrunk scene is."""
    import time
    import warnings

    from acconform.compare import compare
    from acconform.port.run import run_scene
    from acconform.runner import guarded, run_campaign

    warnings.simplefilter("ignore", RuntimeWarning)
    mutant = load_mutant(index)
    calls = {"n": 0, "first": None, "last": None}
    trace_type = importlib.import_module(mutant.__module__.rsplit(".", 1)[0] + ".transition.branches").Trace

    class Port:
        """The mutant as `acconform check` runs the built-in port: boundaries traced for target()."""

        trace_boundaries = False
        last_trace = None

        def __call__(self, scene):
            self.last_trace = trace_type() if self.trace_boundaries else None
            calls["last"] = guarded(lambda s: mutant(s, trace=self.last_trace), scene)
            return calls["last"]

    port = Port()

    def oracle(scene):
        calls["n"] += 1
        b = run_scene(scene)
        if calls["first"] is None and compare(calls["last"], b, "exact"):
            calls["first"] = calls["n"]
        return b

    t0 = time.monotonic()
    kinds = kinds if kinds is not None else MUTATIONS[index].kinds
    r = run_campaign(port, oracle, kinds=kinds, n=budget, seed=seed, failures_dir=failures_dir, database=None,
                     workers=1)
    out = {"name": MUTATIONS[index].name, "caught": bool(r.found), "scenes_to_find": calls["first"],
           "runs": r.cases, "seconds": round(time.monotonic() - t0, 1)}
    if r.found:
        f = r.found[0]
        out.update(scene_size(f.case.scene), shrunk=f.shrunk, scene_name=f.case.scene.name,
                   differences=len(f.case.differences), path_file=str(f.path) if f.path else None)
    return out


# ---------------------------------------------------------------- scenes that kill a mutant (explain's tests)

def killing_records(name: str, n: int, runtime: str = "coreclr", branch: str | None = None) -> list:
    """Up to `n` (record, mutant outcome) pairs from the fast lane's corpus sample of `runtime`, in
    corpus order, where the named mutant differs from ACE's recorded answer and the real port does
    not; `branch`: only records that fire it (the sample lists each record's branches)."""
    import json

    from acconform.compare import compare
    from acconform.oracle import default_corpus
    from acconform.oracle.recorded import RecordedOracle
    from acconform.port.run import run_scene
    from acconform.runner import guarded

    mutant = load_mutant([m.name for m in MUTATIONS].index(name))
    sample = json.loads((default_corpus(runtime) / "fast-sample.json").read_text())
    wanted = sample["branches"].index(branch) if branch is not None else None
    keys = {k for k, _, branches in sample["records"] if wanted is None or wanted in branches}
    oracle = RecordedOracle(default_corpus())
    out = []
    for entry in oracle.select(runtime=runtime):
        if entry.key in keys:
            rec = oracle._record(entry)
            got = guarded(lambda s: mutant(s, runtime=runtime), rec.scene)
            if compare(got, rec.outcome) and not compare(run_scene(rec.scene, runtime=runtime), rec.outcome):
                out.append((rec, got))
                if len(out) == n:
                    break
    return out


# ---------------------------------------------------------------- the corpus replay (no generation)

def corpus_kill(index: int, corpus_dir, runtime: str = "mono", seed: int = SEED, only=None) -> dict:
    """Replay the recorded corpus (records of `runtime`, in a seeded shuffle) through the mutant
    against ACE's recorded answer, until a record where the mutant differs from ACE and the real
    port does not (a record the real port already gets wrong kills nothing). Says whether the
    corpus kills the mutant and after how many records. `only`: replay just these record keys (in
    the same shuffle), e.g. the fast lane's sample."""
    import random
    import time
    import warnings

    from acconform.compare import compare
    from acconform.oracle.recorded import RecordedOracle
    from acconform.port.run import run_scene
    from acconform.runner import guarded

    warnings.simplefilter("ignore", RuntimeWarning)
    mutant = load_mutant(index)
    oracle = RecordedOracle(corpus_dir)
    keys = oracle.select(runtime=runtime)  # entries, in corpus order
    if only is not None:
        only = set(only)
        keys = [e for e in keys if e.key in only]
    random.Random(seed).shuffle(keys)
    t0 = time.monotonic()
    out = {"name": MUTATIONS[index].name, "killed": False, "records": len(keys), "records_to_kill": None}
    for n, key in enumerate(keys, 1):
        rec = oracle._record(key)
        got = guarded(lambda s: mutant(s, runtime=runtime), rec.scene)
        if compare(got, rec.outcome, "exact") and not compare(run_scene(rec.scene, runtime=runtime), rec.outcome,
                                                              "exact"):
            out.update(killed=True, records_to_kill=n, scene_name=rec.scene.name)
            break
    out["seconds"] = round(time.monotonic() - t0, 1)
    return out


# ---------------------------------------------------------------- the tick records (issue 19)

@functools.lru_cache(maxsize=2)
def _tick_entries(runtime: str) -> tuple:
    """The corpus's tick records on `runtime` as (scene key, entry), the coverage kernel's first (they
    take every branch the tick records take, so a tick-loop bug's killing record is most often among
    them), then the rest in corpus order; () when the corpus has no tick shards. Read once per process
    (keys from the oracle's kept index): every tick mutant walks them."""
    import json

    from acconform.oracle import default_corpus
    from acconform.oracle.recorded import RecordedOracle, shards

    corpus = default_corpus(runtime)
    if not any(p.name.startswith("ticks-") for p in shards(corpus)):
        return ()
    oracle = RecordedOracle(corpus)
    key_of = {id(e): k for k, e in oracle.index().items()}
    kernel = set(json.loads((corpus / "coverage-kernel.json").read_text())["keys"])
    # (a record whose scene an earlier one repeats is not in the index: keyed on its own)
    keyed = [(key_of.get(id(e)) or e.key, e) for e in oracle.select(kinds=("ticks",), runtime=runtime)]
    return tuple(sorted(keyed, key=lambda ke: ke[0] not in kernel))


def tick_records(runtime: str, first: tuple[str, ...] = ()):
    """(source, scene, ACE's outcome) for every tick scene with ACE's recorded answer on `runtime`: the named
    scenes of several movers (tests/oracle/mover_scenes.py) of a carried child (tests/oracle/child_scenes.py) and of missiles (tests/oracle/missile_scenes.py), the corpus's tick shards (ticks-NNNN.jsonl.gz) when present (the records keyed `first` first, then as
    _tick_entries orders them), then the example tick scenes, the hand-written ones and the named ones
    (tests/oracle/data)."""
    import json

    from acconform.case import Record, load_document
    from acconform.outcome import Outcome
    from acconform.scene import Scene

    root = PORT_DIR.parent
    data = root / "tests" / "oracle" / "data"
    # the named scenes of several movers first: a dozen short scenes, each aimed at one of their rules
    sys.path.insert(0, str(root / "tests"))
    from oracle.mover_scenes import scenes as mover_scenes

    from oracle.child_scenes import scenes as child_scenes

    movers = json.loads((data / "ace_mover_outcomes.json").read_text())["outcomes"][runtime]
    for name, scene in mover_scenes().items():
        yield f"tests/oracle/mover_scenes.py {name}", scene, Outcome.from_json(movers[name])
    # then the named scenes of a carried child (tests/oracle/child_scenes.py), as short and as aimed
    children = json.loads((data / "ace_child_outcomes.json").read_text())["outcomes"][runtime]
    for name, scene in child_scenes().items():
        yield f"tests/oracle/child_scenes.py {name}", scene, Outcome.from_json(children[name])
    # then the named missile scenes (tests/oracle/missile_scenes.py): eight, each an arrow or a spell launched at a tick
    from oracle.missile_scenes import scenes as missile_scenes

    missiles = json.loads((data / "ace_missile_outcomes.json").read_text())["outcomes"][runtime]
    for name, scene in missile_scenes().items():
        yield f"tests/oracle/missile_scenes.py {name}", scene, Outcome.from_json(missiles[name])
    for _, e in sorted(_tick_entries(runtime), key=lambda ke: ke[0] not in first):
        rec = Record.from_json(e.doc())
        yield e.where, rec.scene, rec.outcome
    examples = json.loads((data / "ace_tick_outcomes.json").read_text())["outcomes"][runtime]
    for p in sorted((root / "examples").glob("tick_*.json")):
        yield f"examples/{p.name}", load_document(p), Outcome.from_json(examples[p.stem])
    hand = json.loads((data / "ace_tick_handwritten.json").read_text())
    for name, s in hand["scenes"].items():
        yield f"hand-written {name}", Scene.from_json(s), Outcome.from_json(hand["outcomes"][runtime][name])
    named = json.loads((data / "ace_named_outcomes.json").read_text())["outcomes"][runtime]
    for p in sorted((root / "examples" / "named").glob("*.json")):
        yield f"examples/named/{p.name}", load_document(p), Outcome.from_json(named[p.stem])


def tick_kill(index: int, runtime: str = "coreclr", budget: int = 150, first: tuple[str, ...] = ()) -> dict:
    """Replay the tick records through the mutant against ACE's recorded answers, in order, until one
    where the mutant differs from ACE and the real port does not; then shrink that scene against the
    real port (standing in for ACE, as `check` shrinks without ACE): first to the ticks up to the first
    one that differs (a tick's state depends only on the ticks before it), then acconform.shrink's
    scene shrinking. Says whether the records kill the mutant, after how many, and how small it got.
    `first`: scene keys of records to try before the others (tick_records)."""
    import dataclasses
    import time
    import warnings

    from acconform.compare import compare
    from acconform.port.run import run_scene
    from acconform.runner import guarded
    from acconform.shrink import scene_bytes, shrink_scene

    warnings.simplefilter("ignore", RuntimeWarning)
    mutant = load_mutant(index)
    t0 = time.monotonic()
    out = {"name": MUTATIONS[index].name, "killed": False, "records_to_kill": None}
    n = 0
    for n, (where, scene, ace) in enumerate(tick_records(runtime, first), 1):
        got = guarded(lambda s: mutant(s, runtime=runtime), scene)
        if not compare(got, ace, "exact") or compare(run_scene(scene, runtime=runtime), ace, "exact"):
            continue
        port = run_scene(scene, runtime=runtime)
        first = next(i for i, (a, b) in enumerate(zip(got.ticks or (), port.ticks or ())) if a != b) \
            if got.ticks and port.ticks else len(scene.ticks.steps) - 1
        cut = scene.replace(ticks=dataclasses.replace(scene.ticks, steps=scene.ticks.steps[:first + 1]))

        def still_fails(s):
            return bool(compare(guarded(lambda x: mutant(x, runtime=runtime), s),
                                guarded(lambda x: run_scene(x, runtime=runtime), s), "exact"))

        assert still_fails(cut), f"{where}: the difference is not in the ticks up to the first differing one"
        small, tried = shrink_scene(cut, still_fails, budget)
        out.update(killed=True, records_to_kill=n, record=where, ticks=len(scene.ticks.steps),
                   first_differing_tick=first, shrunk_ticks=len(small.ticks.steps), shrunk_objects=len(small.objects),
                   shrunk_landblocks=len(small.landblocks), shrunk_bytes=scene_bytes(small),
                   original_bytes=scene_bytes(scene), candidates=tried)
        break
    out["records"] = n
    out["seconds"] = round(time.monotonic() - t0, 1)
    return out
