"""ObjectInfo: GetWalkableZ, Init, IsValidWalkable, MissileIgnore, StopVelocity, ValidateWalkable.

ACE's ObjectInfo.cs: the mover's flags and step heights for one transition. StopVelocity is an
observable event: it calls PhysicsObj.set_velocity(0), whose effect shows in the outcome.
"""

from __future__ import annotations

from dataclasses import dataclass

from acconform.flags import ObjectInfoState, PhysicsState, TransitionState
from acconform.numerics import Plane, Vector3, dot

from ..anchors import anchor
from ..constants import EPSILON, FLOOR_Z
from ..vec import zero_like


@dataclass(slots=True)
class ObjectInfo:
    object: object = None  # the PhysicsObj (port/physics_obj.py)
    state: int = 0  # ObjectInfoState
    scale: float = 1.0
    step_up_height: float = 0.0
    step_down_height: float = 0.0
    ethereal: bool = False
    step_down: bool = False
    target_id: int = 0

    @anchor("OBJECTINFO::get_walkable_z", "ObjectInfo.cs:GetWalkableZ")
    def get_walkable_z(self):
        return self.object.get_walkable_z()

    @anchor("OBJECTINFO::init", "ObjectInfo.cs:Init")
    def init(self, obj, state: int) -> None:
        self.object = obj
        self.state = state
        self.scale = obj.scale
        self.step_up_height = obj.get_step_up_height()
        self.step_down_height = obj.get_step_down_height()
        self.ethereal = bool(obj.state & PhysicsState.Ethereal)
        self.step_down = not obj.state & PhysicsState.Missile
        wobj = obj.weenie_obj
        if wobj is not None:
            if wobj.is_impenetrable():
                self.state |= ObjectInfoState.IsImpenetrable
            if wobj.is_player:
                self.state |= ObjectInfoState.IsPlayer
            if wobj.is_pk():
                self.state |= ObjectInfoState.IsPK
            if wobj.is_pk_lite():
                self.state |= ObjectInfoState.IsPKLite
        if obj.projectile_target is not None:
            self.target_id = obj.projectile_target.id

    @anchor("OBJECTINFO::is_valid_walkable", "ObjectInfo.cs:IsValidWalkable")
    def is_valid_walkable(self, normal: Vector3) -> bool:
        from ..physics_obj import PhysicsObj

        return PhysicsObj.is_valid_walkable(normal)

    @anchor("OBJECTINFO::missile_ignore", "ObjectInfo.cs:MissileIgnore")
    def missile_ignore(self, collide_obj) -> bool:
        if collide_obj.state & PhysicsState.Missile:
            if not self.object.is_player:
                return True
            if collide_obj.projectile_target is None or collide_obj.projectile_target is self.object:
                return False
            return True
        if self.object.state & PhysicsState.Missile:
            if collide_obj.weenie_obj is not None and collide_obj.id != self.target_id:
                if collide_obj.state & PhysicsState.Ethereal or self.target_id != 0 and collide_obj.weenie_obj.is_creature:
                    return True
        return False

    @anchor("OBJECTINFO::kill_velocity", "ObjectInfo.cs:StopVelocity")
    def stop_velocity(self) -> None:
        self.object.set_velocity(zero_like(self.object.velocity.x), False)

    @anchor("OBJECTINFO::validate_walkable", "ObjectInfo.cs:ValidateWalkable")
    def validate_walkable(self, check_pos, contact_plane: Plane, is_water: bool, water_depth, transition,
                          land_cell_id: int) -> TransitionState:
        from ..physics_obj import PhysicsObj

        path = transition.sphere_path
        collision = transition.collision_info
        s = type(check_pos.radius)

        if self.state & ObjectInfoState.IsViewer:
            dist = dot(check_pos.center, contact_plane.normal) + contact_plane.d - check_pos.radius
            if dist > -EPSILON and path.begin_pos is not None and (path.begin_pos.obj_cell_id & 0xFFFF) >= 0x100:
                return TransitionState.OK
            offset = check_pos.center - path.global_curr_center[0].center
            angle = dist / dot(offset, contact_plane.normal)
            if (angle <= 0.0 or angle > 1.0) and path.begin_pos is not None and (path.begin_pos.obj_cell_id & 0xFFFF) >= 0x100:
                return TransitionState.OK
            path.add_offset_to_check_pos(offset * -angle)
            collision.set_collision_normal(contact_plane.normal)
            collision.collided_with_environment = True
            return TransitionState.Adjusted

        dist = (dot(check_pos.center - Vector3(s(0.0), s(0.0), check_pos.radius), contact_plane.normal)
                + contact_plane.d + water_depth)
        if dist >= -EPSILON:
            if dist > EPSILON:
                return TransitionState.OK
            if path.trace is not None and not path.step_down and self.state & ObjectInfoState.OnWalkable:
                path.trace.walkable(contact_plane.normal.z, FLOOR_Z)
            if path.step_down or not self.state & ObjectInfoState.OnWalkable or PhysicsObj.is_valid_walkable(contact_plane.normal):
                collision.set_contact_plane(contact_plane, is_water)
                collision.contact_plane_cell_id = land_cell_id
            if not self.state & ObjectInfoState.Contact and not path.step_down:
                collision.set_collision_normal(contact_plane.normal)
                collision.collided_with_environment = True
            return TransitionState.OK

        if path.check_walkable:
            return TransitionState.Collided
        z_dist = dist / contact_plane.normal.z

        if path.trace is not None and not path.step_down and self.state & ObjectInfoState.OnWalkable:
            path.trace.walkable(contact_plane.normal.z, FLOOR_Z)
        if path.step_down or not self.state & ObjectInfoState.OnWalkable or PhysicsObj.is_valid_walkable(contact_plane.normal):
            collision.set_contact_plane(contact_plane, is_water)
            collision.contact_plane_cell_id = land_cell_id
            if path.step_down:
                interp = (1.0 - -1.0 / (path.step_down_amt * path.walk_interp) * z_dist) * path.walk_interp
                if interp >= path.walk_interp or interp < -0.1:
                    return TransitionState.Collided
                path.walk_interp = interp
            offset = Vector3(s(0.0), s(0.0), -z_dist)
            path.add_offset_to_check_pos(offset)

        if not self.state & ObjectInfoState.Contact and not path.step_down:
            collision.set_collision_normal(contact_plane.normal)
            collision.collided_with_environment = True
        return TransitionState.Adjusted
