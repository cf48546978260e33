"""The branch names the port counts when run_scene is given a trace Counter.

Each name is "<ACE routine>:<branch>". `BRANCHES` documents every name the port can emit;
tests/port/transition/test_branches.py checks that the port emits exactly these names; each
one outside `NOT_YET_REACHED` is reached by a recorded test scene where the port matches ACE:
a terrain scene (tests/port/transition) or, for `REACHED_BY_OBJECT_SCENES`, a static-object
scene (tests/port/objects), or, for `REACHED_BY_INDOOR_SCENES`, a named indoor scene
(tests/port/cell).
"""

from __future__ import annotations

import struct
from collections import Counter

from acconform.numerics import f32_bits

from ..anchors import harness
from ..constants import FLOOR_Z, LANDING_Z


BRANCHES: dict[str, str] = {
    # Transition.AdjustOffset
    "adjust_offset:slide_no_contact": "sliding normal opposes the offset, no contact plane: its component removed",
    "adjust_offset:slide_blocked": "sliding normal opposes the offset, crease direction too small: offset zeroed",
    "adjust_offset:slide_along_crease": "sliding normal opposes the offset on a contact plane: slide along the crease",
    "adjust_offset:lift_above_contact_plane": "sphere sinks below the contact plane: check position lifted",
    # Transition.CheckOtherCells
    "check_other_cells:other_cell_collided": "a neighbouring cell's collision test returned Collided/Adjusted",
    "check_other_cells:no_cell": "sphere center in no cell (adjusted to outside)",
    # Transition.CheckWalkable
    "check_walkable:walkable_ok": "not on walkable ground, or the walkable polygon still holds the sphere",
    "check_walkable:probe_blocked": "downward probe met ground: walkable",
    "check_walkable:probe_fell": "downward probe met nothing: not walkable",
    # Transition.CliffSlide
    "cliff_slide:parallel_planes": "contact and last-known planes give no slide direction: OK",
    "cliff_slide:normal_kept": "movement opposes the cliff normal: slide with it",
    "cliff_slide:normal_flipped": "movement along the cliff normal: slide with it reversed",
    # Transition.EdgeSlide
    "edge_slide:off": "not on walkable ground or no EdgeSlide flag: no slide",
    "edge_slide:cliff_slide": "contact plane below walkable Z: cliff slide",
    "edge_slide:precipice_slide": "the walkable polygon just left is known: precipice slide along its crossed edge",
    "edge_slide:contact_plane_valid": "a walkable contact plane is still valid: OK",
    "edge_slide:back_probe": "walkable lost: step down from the current sphere center to rediscover it",
    "edge_slide:back_probe_precipice_slide": "the back-probe found the walkable polygon: precipice slide",
    "edge_slide:back_probe_no_walkable": "the back-probe found no walkable polygon (always on terrain): Collided",
    # SpherePath.PrecipiceSlide
    "precipice_slide:no_crossed_edge": "no crossed edge found: Collided",
    "precipice_slide:normal_flipped": "edge normal turned to oppose the movement",
    "precipice_slide:normal_kept": "edge normal already opposes the movement",
    # Transition.FindTransitionalPosition
    "find_transitional_position:too_many_steps": "more than 1000 steps: refused",
    "find_transitional_position:no_steps": "begin == end: cell list only",
    "find_transitional_position:offset_vanished": "the adjusted offset is below EPSILON: stop",
    "find_transitional_position:stationary_fall_stop": "FramesStationaryFall > 0 after a step: stop",
    # Transition.StepDown / StepUp
    "step_down:ok": "stepped down onto walkable ground",
    "step_down:placement_blocked": "found ground but the placement insert failed",
    "step_down:fail": "no walkable ground within reach",
    "step_up:ok": "stepped up",
    "step_up:fail": "could not step up: check position restored",
    # Transition.TransitionalInsert
    "transitional_insert:neg_poly_step_up": "hit a polygon from behind, step up requested",
    "transitional_insert:neg_poly_slide": "hit a polygon from behind: slide",
    "transitional_insert:step_down_whole": "lost contact: one step-down (height <= 2r, or r/2 for one sphere)",
    "transitional_insert:step_down_halves": "lost contact: two half step-downs (two spheres, height > 2r)",
    "transitional_insert:collide_landed": "collide flag: landed on walkable ground",
    "transitional_insert:collide_reset": "collide flag: check position reset, Collided",
    # Transition.ValidateTransition
    "validate_transition:rejected_step": "a step came back not OK: back to the current position",
    "validate_transition:last_known_contact_restored": "the last known contact plane still touches: restored",
    "validate_transition:stationary_fall_1": "FramesStationaryFall 0 -> 1",
    "validate_transition:stationary_fall_2": "FramesStationaryFall 1 -> 2",
    "validate_transition:stationary_fall_3": "FramesStationaryFall >= 2 -> 3, contact plane forced",
    # LandCell.FindEnvCollisions, PhysicsObj.get_object_info
    "land_cell:entirely_water_block": "an entirely-water landblock: Collided",
    "get_object_info:leaving_contact": "velocity leaves the contact plane: only a last-known plane",
    # indoors: EnvCell.FindEnvCollisions, EnvCell.find_transit_cells, ObjCell.find_cell_list
    "env_cell:physics_bsp": "an EnvCell's physics BSP tested the mover (placement or collision)",
    "env_cell:outside_portal": "a sphere straddles a portal to 0xFFFF: the outdoor cells added",
    "env_cell:other_cell": "a sphere reaches the loaded cell beyond a portal: that cell added",
    "env_cell:unloaded_cell": "a sphere reaches a portal to a cell not visible: its short id added, no cell",
    "find_cell_list:indoor": "the position is in an EnvCell: that cell added (path hits an interior cell)",
    "find_cell_list:pruned": "a cell the position's EnvCell does not see dropped from the CellArray",
    # buildings: BuildingObj.find_building_collisions (SortCell.FindCollisions of the cell it stands in),
    # EnvCell.check_building_transit (BuildingObj.find_building_transit_cells through its portals)
    "building:collisions": "the shell's physics BSP tested the mover (BuildingCheck set): OK",
    "building:collided": "the shell's physics BSP stopped or moved the mover (not OK)",
    "building:transit_cell": "a sphere reaches a building's EnvCell through its portal: the cell added, HitsInteriorCell set",
    # placement (a scene's mover.placement): PhysicsObj.SetPositionInternal / CheckPositionInternal,
    # Transition.FindPlacementPosition / FindPlacementPos
    "set_position:no_cell_stored": "AdjustPosition found no cell: the position stored, the mover in no cell, no transition",
    "set_position:collided": "no valid position and handle_all_collisions reported a collision: Collided",
    "set_position:no_valid_position": "no valid position, nothing reported: NoValidPosition",
    "set_position:placed": "placed: SetPositionInternal(Transition) entered the mover in its cell",
    "check_position:kept_close": "without Slide: moved less than 0.05 in x and in y, kept",
    "check_position:kept_far_negative": "without Slide: moved 0.05 or more toward -x or -y, kept all the same (no Math.Abs)",
    "check_position:moved_too_far": "without Slide: moved 0.05 or more toward +x or +y (or into another cell): refused",
    "find_placement_position:initial_blocked": "the initial placement insert failed: no valid position",
    "find_placement_pos:in_place": "the placement insert at the current position is OK",
    "find_placement_pos:no_sliding": "blocked where it stands, and the placement may not slide (no Slide)",
    "find_placement_pos:slid_to_free_spot": "blocked where it stands: the spiral search found a free spot",
    "find_placement_pos:no_free_spot": "blocked where it stands: the spiral search found no free spot within reach",
    # the tick (a tick scene's steps): PhysicsObj.update_object and what it calls
    "update_object:not_in_world": "a parent, no CurCell or Frozen: Active cleared, no update",
    "update_object:tick_rate_gate": "less than TickRate (1/30 s) since UpdateTime: no update, the time kept for later",
    "update_object:huge_quantum_skip": "more than HugeQuantum (2 s) since UpdateTime: the time consumed, no update",
    "update_object:max_quantum_step": "a MaxQuantum (0.1 s) sub-step while more than MaxQuantum is left",
    "update_object:remainder_step": "the remainder over MinQuantum run as a last sub-step",
    "update_object:remainder_kept": "a remainder at or under MinQuantum kept for the next tick (UpdateTime not advanced past it)",
    "update_object_internal:inactive": "not Active (or no CurCell): the sub-step does nothing",
    "update_object_internal:unmoved": "the new frame within EPSILON of the old: no transition, CachedVelocity zero",
    "update_object_internal:block_dist_refused": "the new position more than one landblock away (GetBlockDist > 1): refused",
    "update_object_internal:transition_failed": "the transition found no valid position (or no cell): the mover stays, CachedVelocity zero",
    "update_object_internal_server:block_dist_refused": "RequestPos more than one landblock away: refused, update fails",
    "update_object_internal_server:transition_failed": "the transition to RequestPos found no valid position",
    "update_physics:velocity_clamped": "speed over MaxVelocity: scaled down to it",
    "update_physics:small_velocity_zeroed": "squared speed within EPSILON of SmallVelocity squared, or under: velocity zeroed",
    "calc_friction:leaving_plane": "on walkable ground, velocity leaving the contact plane (dot >= 0.25): no friction",
    "calc_friction:sledding_stop": "sledding under 1.25 m/s: friction 1.0 (stops)",
    "calc_friction:sledding_glide": "sledding at 2.5 m/s or more on a plane flatter than 0.99999536: friction 0.2",
    "handle_all_collisions:elastic_bounce": "a collision normal the velocity runs into: bounced by Elasticity",
    "handle_all_collisions:inelastic_stop": "Inelastic and a collision normal: velocity zeroed",
}

# The tick's branches (a tick scene's steps) that the example tick scenes reach (examples/tick_*.json,
# against ACE's recorded answers on both runtimes in tests/oracle/data/ace_tick_outcomes.json;
# tests/port/test_tick_scenes.py checks each); the other scenes never do (handle_all_collisions'
# bounce also comes with a placement).
REACHED_BY_TICK_SCENES: dict[str, str] = {
    name: "tick scenes only" for name in (
        "update_object:tick_rate_gate", "update_object:huge_quantum_skip", "update_object:max_quantum_step",
        "update_object:remainder_step", "update_object_internal:inactive", "update_object_internal:unmoved",
        "update_physics:small_velocity_zeroed", "calc_friction:leaving_plane", "handle_all_collisions:elastic_bounce")
}

# Branches no recorded test scene reaches yet, and why.
NOT_YET_REACHED: dict[str, str] = {
    name: "a tick branch no example tick scene with ACE's recorded answers reaches yet (issue 19's tick corpus records them)"
    for name in BRANCHES if name.split(":")[0] in (
        "update_object", "update_object_internal", "update_object_internal_server", "update_physics", "calc_friction",
        "handle_all_collisions") and name not in REACHED_BY_TICK_SCENES
}
# ACE builds UpdateObjectInternal's newPos as `new Position(Position.ObjCellID)`: GetBlockDist(Position, newPos)
# compares a cell id with itself and is always 0, so this refusal cannot happen (counted, for the record)
NOT_YET_REACHED["update_object_internal:block_dist_refused"] = (
    "unreachable in ACE: newPos takes Position.ObjCellID, so GetBlockDist(Position, newPos) is always 0")


# Branches only the named indoor scenes reach (tests/port/cell: indoor_rooms.py and dungeon_scenes.py,
# against ACE's recorded answers); the outdoor scenes never do.
REACHED_BY_INDOOR_SCENES: dict[str, str] = {
    "check_other_cells:no_cell": "a sphere center in no loaded cell: indoors, beyond a portal to an unloaded cell",
    "env_cell:physics_bsp": "indoors only",
    "env_cell:outside_portal": "indoors only",
    "env_cell:other_cell": "indoors only",
    "env_cell:unloaded_cell": "indoors only",
    "find_cell_list:indoor": "indoors only",
    "find_cell_list:pruned": "indoors only",
}


# Branches only the named building scenes reach (tests/port/cell/building_scenes, against ACE's recorded
# answers on both runtimes); a scene without a building never does.
REACHED_BY_BUILDING_SCENES: dict[str, str] = {
    name: "buildings only" for name in BRANCHES if name.split(":")[0] == "building"
}


# Branches only the named placement scenes reach (tests/port/cell/placement_scenes.py, against ACE's
# recorded answers on both runtimes); a scene without a placement never does.
REACHED_BY_PLACEMENT_SCENES: dict[str, str] = {
    name: "placement only" for name in BRANCHES
    if name.split(":")[0] in ("set_position", "check_position", "find_placement_position", "find_placement_pos")
    and name not in NOT_YET_REACHED
}


# Branches only the static-object scenes reach (tests/port/objects: BSP sets SpherePath.Walkable,
# BSP/sphere collisions request step-up and SetCollide); the terrain scenes never do.
REACHED_BY_OBJECT_SCENES: dict[str, str] = {
    "check_walkable:probe_blocked": "needs SpherePath.Walkable, which only BSP geometry sets",
    "check_walkable:probe_fell": "needs SpherePath.Walkable (BSP)",
    "edge_slide:precipice_slide": "needs SpherePath.Walkable (BSP)",
    "edge_slide:back_probe_precipice_slide": "needs SpherePath.Walkable (BSP)",
    "edge_slide:contact_plane_valid": "not found on terrain in 1,000 sampled scenes; an obstacle scene reaches it",
    "precipice_slide:no_crossed_edge": "needs SpherePath.Walkable (BSP)",
    "precipice_slide:normal_flipped": "needs SpherePath.Walkable (BSP)",
    "precipice_slide:normal_kept": "needs SpherePath.Walkable (BSP)",
    "step_down:placement_blocked": "not found on terrain in 1,000 sampled scenes; an obstacle scene reaches it",
    "step_up:ok": "step up is requested by BSP/sphere collisions only",
    "step_up:fail": "step up is requested by BSP/sphere collisions only",
    "transitional_insert:neg_poly_step_up": "BSP only",
    "transitional_insert:neg_poly_slide": "BSP only",
    "transitional_insert:collide_landed": "SetCollide comes from BSP/sphere collisions",
    "transitional_insert:collide_reset": "SetCollide comes from BSP/sphere collisions",
}


# Exact boundaries: comparisons whose two sides can be bit-equal, where a `>=` written `>` (or a
# constant one ulp off) changes behaviour and nothing else does. A Trace counts each exact hit
# as "boundary:<name>" and keeps, per boundary, the closest approach in float32 ulps (for
# Hypothesis' target()).
BOUNDARIES: dict[str, str] = {
    "floor_z": "a walkable test compared a normal.z (or allowance) bit-equal to FloorZ",
    "landing_z": "a walkable test compared a normal.z (or allowance) bit-equal to LandingZ",
    "sphere_tangent": "a sphere test's squared distance bit-equal to the squared radius sum",
    "cylsphere_tangent": "a cylsphere test's squared horizontal distance bit-equal to the squared radius sum",
    "bsp_split_walkable": "a BSP node's two sides both gave a walkable polygon (the visiting order decides)",
    "cell_border": "the transition ended exactly on a cell border (x or y a multiple of 24 m)",
    "landblock_border": "the transition ended exactly on a landblock border (x or y a multiple of 192 m)",
    "plane_tangent": "Polygon.polygon_hits_sphere_precise: a polygon's plane exactly at the sphere's radius less EPSILON"
                     " from its centre (|dp_pos| == rad)",
    "polygon_edge": "Polygon.polygon_hits_sphere_precise: an edge exactly tangent to the circle the sphere cuts from the"
                    " plane (cross.LengthSquared() * diff == dispDot * dispDot)",
    "polygon_vertex": "Polygon.polygon_hits_sphere_precise: a vertex exactly on that circle (disp.LengthSquared() == diff;"
                      " 0 == 0 when the vertex is the contact point of a sphere tangent to the plane)",
    "step_up_height": "Sphere/CylSphere.StepSphereUp: the rise to climb bit-equal to the mover's StepUpHeight",
    "step_down_height": "Transition.TransitionalInsert and CheckWalkable: the step-down height bit-equal to the mover's"
                        " sphere diameter (one whole step-down or two halves)",
    # the tick's: update_object compares its double deltaTime with the float quanta (counted when equal in double)
    "tick_rate": "update_object: the time since UpdateTime exactly TickRate (updates: the gate is `<`)",
    "huge_quantum": "update_object: the time since UpdateTime exactly HugeQuantum (simulated: the skip is `>`)",
    "max_quantum": "update_object: the time left exactly MaxQuantum at the loop test (no further MaxQuantum step)",
    "min_quantum": "update_object: the remainder exactly MinQuantum (kept, not run: the test is `>`)",
    "max_velocity": "UpdatePhysicsInternal: the squared speed bit-equal to MaxVelocitySquared (not clamped)",
    "small_velocity": "UpdatePhysicsInternal: squared speed less SmallVelocitySquared bit-equal to EPSILON (kept)",
    "sledding_stop_speed": "calc_friction, sledding: the squared speed bit-equal to 1.5625 (not stopped)",
    "sledding_glide_speed": "calc_friction, sledding: the squared speed bit-equal to 6.25 (glides)",
    "sledding_flat_z": "calc_friction, sledding: the contact normal's z bit-equal to 0.99999536 (no glide: the test is `>`)",
}


# Where they are counted: floor_z/landing_z at every walkable test against those constants; the
# tangencies in Sphere/CylSphere.IntersectsSphere; plane_tangent, polygon_edge and polygon_vertex in
# Polygon.polygon_hits_sphere_precise, whose callers pass the trace down the BSP (BSPTree.adjust_to_plane
# has no path and passes none: its polygon tests go uncounted); step_up_height in StepSphereUp;
# step_down_height where TransitionalInsert and CheckWalkable compare the step-down height with 2r.
# Issue 14 also names rises "exactly 1.5x the step-up height": ACE (7b47913) compares no height with
# 1.5 x StepUpHeight anywhere (grep Physics/ for StepUpHeight: only the two StepSphereUp tests), so
# that is no boundary of ACE's to count; its step tests are the two above.

# the boundaries a Trace measures in ulps (the others are counted only when hit)
MEASURED_IN_ULPS = ("floor_z", "landing_z", "sphere_tangent", "cylsphere_tangent", "plane_tangent", "polygon_edge",
                    "polygon_vertex", "step_up_height", "step_down_height", "max_velocity", "small_velocity",
                    "sledding_stop_speed", "sledding_glide_speed", "sledding_flat_z")


_F32, _U32 = struct.Struct("<f"), struct.Struct("<I")


def _bits(x) -> int:
    # numerics.f32_bits, ten times faster through struct (a NaN's payload may come out quieted,
    # which no distance in ulps minds); a double past float32's range goes the exact way
    try:
        return _U32.unpack(_F32.pack(x))[0]
    except OverflowError:
        return f32_bits(x)


def _ordered(bits: int) -> int:
    # float32 bit patterns as integers that order like the floats (-0 and +0 meet at 0)
    return bits if bits < 0x80000000 else 0x80000000 - bits


class Trace(Counter):
    """A run's branch counts (`trace[branch]`), plus `closest`: per boundary, the fewest float32
    ulps seen between a compared value and its threshold; `recorder` (port/tracing.py's Recorder, or
    None) asks the run for a trace of snapshots too."""

    __slots__ = ("closest", "recorder")

    def __init__(self, recorder=None):
        super().__init__()
        self.closest: dict[str, int] = {}
        self.recorder = recorder

    @harness("counts an exact hit of a boundary and keeps its closest approach in ulps")
    def boundary(self, name: str, value, threshold) -> None:
        ulps = abs(_ordered(_bits(value)) - _ordered(_bits(threshold)))
        if ulps == 0:
            self["boundary:" + name] += 1
        if ulps < self.closest.get(name, 1 << 32):
            self.closest[name] = ulps

    @harness("a walkable test as the floor_z or landing_z boundary, by its threshold")
    def walkable(self, value, threshold) -> None:
        """A walkable test against FloorZ or LandingZ (other thresholds are no boundary of ours)."""
        t = float(threshold)  # a float32 threshold compares equal to the constant exactly
        if t == FLOOR_Z:
            self.boundary("floor_z", value, threshold)
        elif t == LANDING_Z:
            self.boundary("landing_z", value, threshold)
