"""LandCell collision: FindCollisions, FindEnvCollisions, find_transit_cells, handle_move_restriction (LandCell.cs), and the ObjCell/SortCell behaviour a LandCell inherits in ACE.

land_cell.py holds LandCell's data and geometry; ACE's LandCell derives from SortCell and
ObjCell, so importing this module gives the LandCell class those methods (ObjCell's from
obj_cell.py, and LandCell's overrides below). acconform.port.transition imports it.
FindEnvCollisions tests sphere 0 only (its low point picks the triangle) against the terrain.
"""

from __future__ import annotations

from acconform.flags import ObjectInfoState, PhysicsState, TransitionState
from acconform.numerics import Vector3

from ..anchors import anchor
from . import land_defs
from .land_cell import LandCell, add_all_outside_cells_replayed
from .land_defs import WaterType
from .obj_cell import ObjCell


@anchor("CLandCell::find_collisions", "LandCell.cs:FindCollisions")
def find_collisions(self, transition) -> TransitionState:
    transit_state = self.find_env_collisions(transition)
    if transit_state == TransitionState.OK:
        transit_state = self.sort_cell_find_collisions(transition)  # base.FindCollisions (SortCell)
        if transit_state == TransitionState.OK:
            transit_state = self.find_obj_collisions(transition)
    return transit_state


@anchor("CLandCell::find_env_collisions", "LandCell.cs:FindEnvCollisions")
def find_env_collisions(self, transition) -> TransitionState:
    transit_state = self.check_entry_restrictions(transition)
    if transit_state != TransitionState.OK:
        return transit_state

    path = transition.sphere_path
    block_offset = land_defs.get_block_offset(path.check_pos.obj_cell_id, self.id)
    local_point = transition.sphere_path.global_low_point - block_offset

    found, walkable = self.find_terrain_poly(local_point, None)
    if not found:
        return transit_state

    obj_info = transition.object_info
    if (self.get_block_water_type() == WaterType.EntirelyWater
            and not obj_info.state & ObjectInfoState.IsViewer and not obj_info.object.state & PhysicsState.Missile):
        if transition.trace is not None:
            transition.trace["land_cell:entirely_water_block"] += 1
        return TransitionState.Collided

    water_depth = self.get_water_depth(local_point)

    from ..geom.sphere import Sphere

    check_pos = Sphere(path.global_sphere[0].center, path.global_sphere[0].radius)
    check_pos.center = check_pos.center - land_defs.get_block_offset(path.check_pos.obj_cell_id, self.id)

    return obj_info.validate_walkable(check_pos, walkable.plane, self.water_type != WaterType.NotWater,
                                      water_depth, transition, self.id)


@anchor("CLandCell::find_transit_cells", "LandCell.cs:find_transit_cells")
def find_transit_cells(self, lscape, position, num_sphere, spheres, cell_array, path) -> None:
    """The run's world `lscape` comes first, standing in for ACE's static LScape."""
    add_all_outside_cells_replayed(lscape, position, num_sphere, spheres, cell_array)
    self.sort_cell_find_transit_cells(lscape, position, num_sphere, spheres, cell_array, path)


@anchor("CLandCell::handle_move_restriction", "LandCell.cs:handle_move_restriction")
def handle_move_restriction(self, transition) -> bool:
    offset = self.pos.get_offset(transition.sphere_path.cur_pos)
    s = type(offset.x)
    half = land_defs.HALF_SQUARE_LENGTH
    if offset.y >= -half:
        if offset.y <= half:
            offset = offset.with_y(s(0.0))
            offset = offset.with_x(s(-1.0) if offset.x < -half else s(1.0))
        else:
            offset = Vector3(s(0.0), s(1.0), offset.z)
    else:
        offset = Vector3(s(0.0), s(-1.0), offset.z)
    normal = Vector3(offset.x, offset.y, s(0.0))
    transition.collision_info.set_collision_normal(normal)
    return True


# ACE: class LandCell : SortCell : ObjCell -- the inherited behaviour, then LandCell's overrides.
for _name in ("equals", "add_shadow_object", "find_obj_collisions", "check_entry_restrictions", "sort_cell_find_collisions",
              "sort_cell_find_transit_cells"):
    setattr(LandCell, _name, getattr(ObjCell, _name))
LandCell.find_collisions = find_collisions
LandCell.find_env_collisions = find_env_collisions
LandCell.find_transit_cells = find_transit_cells
LandCell.handle_move_restriction = handle_move_restriction
