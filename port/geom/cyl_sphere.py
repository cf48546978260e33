"""CCylSphere: CylSphere (ctor, CollideWithPoint, CollidesWithSphere, IntersectsSphere x2, LandOnCylinder, SlideSphere, StepSphereDown, StepSphereUp, CollisionNormal).

Ports ACE CylSphere.cs. Double-precision spots kept as ACE computes them: ``LengthSquared2D()``
returns a double (a float32 sum widened), so CollideWithPoint's ``xyMoveLenSq``, ``diffSq`` and
``scaledLenSq`` are doubles; ``diff = (float)Math.Sqrt(diffSq)``; the times ``(float)((...) /
xyMoveLenSq)`` divide in double and round back to float32.
"""

from __future__ import annotations

from acconform.flags import ObjectInfoState, TransitionState
from acconform.numerics import Mode, Plane, Vector3, cast_float, dot

from ..anchors import anchor
from ..constants import EPSILON, LANDING_Z, STEP_INTERP_LIMIT
from ..land_defs import get_block_offset
from ..vec import cs_sqrt, dot2d, length_squared_2d, normalize_check_small, unit_z_like, zero_like

# SpherePath.cs InsertType.Placement
INSERT_TYPE_PLACEMENT = 1


class CylSphere:
    """CylSphere.cs: low_point (Vector3), height, radius."""

    __slots__ = ("low_point", "height", "radius")

    @anchor("CCylSphere::CCylSphere", "CylSphere.cs:CylSphere", "(lowPoint, height, radius[, scale])")
    def __init__(self, low_point: Vector3, height, radius, scale=None):
        if scale is None:
            self.low_point = low_point
            self.height = height
            self.radius = radius
        else:
            self.low_point = low_point * scale
            self.height = height * scale
            self.radius = radius * scale

    @classmethod
    @anchor(None, "CylSphere.cs:CylSphere(DatLoader.Entity.CylSphere)", "the DAT constructor")
    def from_dat(cls, cyl_sphere) -> "CylSphere":
        """``new CylSphere(DatLoader.Entity.CylSphere)``: LowPoint = Origin, Height, Radius."""
        return cls(cyl_sphere.origin, cyl_sphere.height, cyl_sphere.radius)

    def __eq__(self, o) -> bool:
        return isinstance(o, CylSphere) and self.height == o.height and self.radius == o.radius and self.low_point == o.low_point

    __hash__ = None

    def __repr__(self) -> str:
        return f"CylSphere({self.low_point!r}, height={float(self.height)!r}, radius={float(self.radius)!r})"

    @anchor("CCylSphere::collide_with_point", "CylSphere.cs:CollideWithPoint")
    def collide_with_point(self, transition, check_pos, disp: Vector3, radsum, sphere_num: int) -> TransitionState:
        obj = transition.object_info
        path = transition.sphere_path
        collisions = transition.collision_info

        definate, collision_normal = self.collision_normal(transition, check_pos, disp, radsum, sphere_num)
        small, collision_normal = normalize_check_small(collision_normal)
        if small:
            return TransitionState.Collided
        if not obj.state & ObjectInfoState.PerfectClip:
            collisions.set_collision_normal(collision_normal)
            return TransitionState.Collided
        glob_center = path.global_curr_center[0].center
        movement = get_block_offset(path.cur_pos.obj_cell_id, path.check_pos.obj_cell_id)
        movement = movement + (check_pos.center - glob_center)
        old_disp = glob_center - self.low_point
        radsum += EPSILON

        # this is similar to ray/sphere intersection
        xy_move_len_sq = length_squared_2d(movement)  # double
        xy_diff = -dot2d(movement, old_disp)
        diff_sq = xy_diff * xy_diff - (length_squared_2d(old_disp) - radsum * radsum) * xy_move_len_sq  # double
        diff = cast_float(radsum, cs_sqrt(diff_sq))

        if not definate:
            if abs(movement.z) < EPSILON:
                return TransitionState.Collided
            s = type(radsum)
            if movement.z > 0.0:
                collision_normal = Vector3(s(0.0), s(0.0), s(-1.0))
                time = (movement.z + check_pos.radius) / movement.z * -1.0
            else:
                collision_normal = Vector3(s(0.0), s(0.0), s(1.0))
                time = (check_pos.radius + self.height - movement.z) / movement.z

            scaled_movement = movement * time
            scaled_len_sq = length_squared_2d(scaled_movement + old_disp)
            if scaled_len_sq >= radsum * radsum:
                if abs(xy_move_len_sq) < EPSILON:
                    return TransitionState.Collided

                if diff_sq >= 0.0 and xy_move_len_sq > EPSILON:
                    if xy_diff - diff < 0.0:
                        time = cast_float(radsum, (diff - dot2d(movement, old_disp)) / xy_move_len_sq)
                    else:
                        time = cast_float(radsum, (xy_diff - diff) / xy_move_len_sq)

                    scaled_movement = movement * time
                collision_normal = (scaled_movement + glob_center - self.low_point) / radsum
                collision_normal = collision_normal.with_z(s(0.0))

            if time < 0.0 or time > 1.0:
                return TransitionState.Collided

            offset = glob_center - scaled_movement - check_pos.center
            path.add_offset_to_check_pos(offset, check_pos.radius)
            collisions.set_collision_normal(collision_normal)

            return TransitionState.Adjusted

        if collision_normal.z != 0.0:
            if abs(movement.z) < EPSILON:
                return TransitionState.Collided

            if movement.z > 0.0:
                time = -((old_disp.z + check_pos.radius) / movement.z)
            else:
                time = (check_pos.radius + self.height - old_disp.z) / movement.z

            scaled_movement = movement * time

            if time < 0.0 or time > 1.0:
                return TransitionState.Collided

            offset = glob_center + scaled_movement - check_pos.center
            path.add_offset_to_check_pos(offset, check_pos.radius)
            collisions.set_collision_normal(collision_normal)

            return TransitionState.Adjusted

        # duplicated from above in ACE
        if diff_sq < 0.0 or xy_move_len_sq < EPSILON:
            return TransitionState.Collided

        if xy_diff - diff < 0.0:
            time = cast_float(radsum, (diff - dot2d(movement, old_disp)) / xy_move_len_sq)
        else:
            time = cast_float(radsum, (xy_diff - diff) / xy_move_len_sq)

        scaled_movement = movement * time
        if time < 0.0 or time > 1.0:
            return TransitionState.Collided

        collision_normal = (scaled_movement + glob_center - self.low_point) / radsum
        collision_normal = collision_normal.with_z(type(radsum)(0.0))
        offset = glob_center + scaled_movement - check_pos.center
        path.add_offset_to_check_pos(offset, check_pos.radius)
        collisions.set_collision_normal(collision_normal)

        return TransitionState.Adjusted

    @anchor("CCylSphere::collides_with_sphere", "CylSphere.cs:CollidesWithSphere")
    def collides_with_sphere(self, check_pos, disp: Vector3, radsum) -> bool:
        result = False
        if disp.x * disp.x + disp.y * disp.y <= radsum * radsum:
            if check_pos.radius - EPSILON + self.height * 0.5 >= abs(self.height * 0.5 - disp.z):
                result = True
        return result

    @anchor("CCylSphere::intersects_sphere", "CylSphere.cs:IntersectsSphere", "overload (Transition)")
    def intersects_sphere(self, transition) -> TransitionState:
        obj = transition.object_info
        path = transition.sphere_path

        glob_sphere = path.global_sphere[0]
        disp = glob_sphere.center - self.low_point

        glob_sphere_ = None
        disp_ = zero_like(self.radius)

        if path.num_sphere > 1:
            glob_sphere_ = path.global_sphere[1]
            disp_ = glob_sphere_.center - self.low_point

        radsum = self.radius - EPSILON + glob_sphere.radius
        if path.trace is not None:
            path.trace.boundary("cylsphere_tangent", disp.x * disp.x + disp.y * disp.y, radsum * radsum)
            if path.num_sphere > 1:
                path.trace.boundary("cylsphere_tangent", disp_.x * disp_.x + disp_.y * disp_.y, radsum * radsum)

        if path.insert_type == INSERT_TYPE_PLACEMENT or path.obstruction_ethereal:
            if self.collides_with_sphere(glob_sphere, disp, radsum):
                return TransitionState.Collided

            if path.num_sphere > 1 and self.collides_with_sphere(glob_sphere_, disp_, radsum):
                return TransitionState.Collided

            return TransitionState.OK

        if path.step_down:
            return self.step_sphere_down(transition, glob_sphere, disp, radsum)

        if path.check_walkable:
            if self.collides_with_sphere(glob_sphere, disp, radsum):
                return TransitionState.Collided

            if path.num_sphere > 1:
                if self.collides_with_sphere(glob_sphere_, disp_, radsum):
                    return TransitionState.Collided
            return TransitionState.OK

        if not path.collide:
            if obj.state & ObjectInfoState.Contact or obj.state & ObjectInfoState.OnWalkable:
                if self.collides_with_sphere(glob_sphere, disp, radsum):
                    return self.step_sphere_up(transition, glob_sphere, disp, radsum)

                if path.num_sphere > 1:
                    if self.collides_with_sphere(glob_sphere_, disp_, radsum):
                        # ACE passes disp (sphere 0's), not disp_
                        return self.slide_sphere(transition, glob_sphere_, disp, radsum, 1)
            elif obj.state & ObjectInfoState.PathClipped:
                if self.collides_with_sphere(glob_sphere, disp, radsum):
                    return self.collide_with_point(transition, glob_sphere, disp, radsum, 0)
            else:
                if self.collides_with_sphere(glob_sphere, disp, radsum):
                    return self.land_on_cylinder(transition, glob_sphere, disp, radsum)

                if path.num_sphere > 1:
                    if self.collides_with_sphere(glob_sphere_, disp_, radsum):
                        return self.collide_with_point(transition, glob_sphere_, disp_, radsum, 1)
            return TransitionState.OK

        if self.collides_with_sphere(glob_sphere, disp, radsum) or (
            path.num_sphere > 1 and self.collides_with_sphere(glob_sphere_, disp_, radsum)
        ):
            block_offset = path.get_cur_pos_check_pos_block_offset()
            movement = path.global_curr_center[0].center - glob_sphere.center - block_offset

            if abs(movement.z) < EPSILON:
                return TransitionState.Collided

            timecheck = (self.height + glob_sphere.radius - disp.z) / movement.z

            offset = movement * timecheck

            offset_disp_sum = offset + disp

            if radsum * radsum < dot2d(offset_disp_sum, offset_disp_sum):
                return TransitionState.OK

            t = (1.0 - timecheck) * path.walk_interp

            if t >= path.walk_interp or t < STEP_INTERP_LIMIT:
                return TransitionState.Collided

            p_dist = glob_sphere.center + offset
            p_dist = p_dist.with_z(p_dist.z - glob_sphere.radius)

            unit_z = unit_z_like(self.radius)
            contact_plane = Plane(unit_z, -dot(unit_z, p_dist))

            collisions = transition.collision_info
            collisions.set_contact_plane(contact_plane, True)
            collisions.contact_plane_cell_id = path.check_pos.obj_cell_id
            path.walk_interp = t
            path.add_offset_to_check_pos(offset, glob_sphere.radius)

            return TransitionState.Adjusted

        return TransitionState.OK

    @anchor(None, "CylSphere.cs:IntersectsSphere", "overload (Position, scale, Transition)")
    def intersects_sphere_at(self, pos, scale, transition) -> TransitionState:
        path = transition.sphere_path

        path.cache_local_space_sphere(pos, type(scale)(1.0))
        global_cylsphere = CylSphere(self.low_point, self.height, self.radius, scale)
        global_cylsphere.low_point = path.check_pos.local_to_global_from(pos, global_cylsphere.low_point)

        return global_cylsphere.intersects_sphere(transition)

    @anchor("CCylSphere::land_on_cylinder", "CylSphere.cs:LandOnCylinder")
    def land_on_cylinder(self, transition, check_pos, disp: Vector3, radsum) -> TransitionState:
        _definate, collision_normal = self.collision_normal(transition, check_pos, disp, radsum, 0)

        small, collision_normal = normalize_check_small(collision_normal)
        if small:
            return TransitionState.Collided

        path = transition.sphere_path
        path.set_collide(collision_normal)
        path.walkable_allowance = type(self.radius)(LANDING_Z)

        return TransitionState.Adjusted

    @anchor("CCylSphere::slide_sphere", "CylSphere.cs:SlideSphere")
    def slide_sphere(self, transition, check_pos, disp: Vector3, radsum, sphere_num: int) -> TransitionState:
        _definate, collision_normal = self.collision_normal(transition, check_pos, disp, radsum, sphere_num)
        small, collision_normal = normalize_check_small(collision_normal)
        if small:
            return TransitionState.Collided

        state, _normal = check_pos.slide_sphere(
            transition, collision_normal, transition.sphere_path.global_curr_center[sphere_num].center
        )
        return state

    @anchor("CCylSphere::step_sphere_down", "CylSphere.cs:StepSphereDown")
    def step_sphere_down(self, transition, check_pos, disp: Vector3, radsum) -> TransitionState:
        path = transition.sphere_path

        glob_sphere_ = None
        disp_ = zero_like(self.radius)

        if path.num_sphere > 1:
            glob_sphere_ = path.global_sphere[1]
            disp_ = glob_sphere_.center - self.low_point

        if self.collides_with_sphere(check_pos, disp, radsum) or (
            path.num_sphere > 1 and self.collides_with_sphere(glob_sphere_, disp_, radsum)
        ):
            step_scale = path.step_down_amt * path.walk_interp
            if abs(step_scale) < EPSILON:
                return TransitionState.Collided

            deltaz = self.height + check_pos.radius - disp.z
            interp = (1.0 - deltaz / step_scale) * path.walk_interp
            if interp >= path.walk_interp or interp < STEP_INTERP_LIMIT:
                return TransitionState.Collided

            normal = unit_z_like(self.radius)
            c = check_pos.center
            contact_point = Vector3(c.x, c.y, c.z + (deltaz - check_pos.radius))
            contact_plane = Plane(normal, -dot(normal, contact_point))

            collisions = transition.collision_info
            collisions.set_contact_plane(contact_plane, True)
            path.walk_interp = interp
            zero = type(deltaz)(0.0)
            path.add_offset_to_check_pos(Vector3(zero, zero, deltaz), check_pos.radius)
            return TransitionState.Adjusted
        return TransitionState.OK

    @anchor("CCylSphere::step_sphere_up", "CylSphere.cs:StepSphereUp")
    def step_sphere_up(self, transition, check_pos, disp: Vector3, radsum) -> TransitionState:
        obj = transition.object_info

        if transition.trace is not None:
            transition.trace.boundary("step_up_height", obj.step_up_height, check_pos.radius + self.height - disp.z)
        if obj.step_up_height < check_pos.radius + self.height - disp.z:
            return self.slide_sphere(transition, check_pos, disp, radsum, 0)

        _definate, collision_normal = self.collision_normal(transition, check_pos, disp, radsum, 0)
        small, collision_normal = normalize_check_small(collision_normal)
        if small:
            return TransitionState.Collided

        path = transition.sphere_path
        global_pos = path.local_space_pos.local_to_global_vec(collision_normal)
        if transition.step_up(global_pos):
            return TransitionState.OK
        return path.step_up_slide(transition)

    @anchor("CCylSphere::collision_normal", "CylSphere.cs:CollisionNormal")
    def collision_normal(self, transition, check_pos, _disp: Vector3, radsum, sphere_num: int) -> tuple[bool, Vector3]:
        """``CollisionNormal(..., out normal)``: returns (definate, normal)."""
        disp = transition.sphere_path.global_curr_center[sphere_num].center - self.low_point
        s = type(radsum)
        if radsum * radsum < length_squared_2d(disp):
            normal = Vector3(disp.x, disp.y, s(0.0))
            definate = (
                check_pos.radius - EPSILON + self.height * 0.5 >= abs(self.height * 0.5 - disp.z)
                or abs(disp.z - _disp.z) <= EPSILON
            )
            return definate, normal
        norm_z = 1 if _disp.z - disp.z <= 0.0 else -1
        return True, Vector3(s(0.0), s(0.0), s(norm_z))
