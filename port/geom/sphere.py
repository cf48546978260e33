"""CSphere: Sphere (Intersects, IntersectsSphere, CollidesWithSphere, FindTimeOfCollision, CollideWithPoint, LandOnSphere, SlideSphere x3, StepSphereDown, StepSphereUp, SphereIntersectsRay).

Ports ACE Sphere.cs. ACE's static overloads (which take the sphere's center explicitly) are the
module-level functions; the instance methods pass ``self.center`` (and ``self.radius``) to them,
as ACE's do. The three SlideSphere overloads get distinct names:

* `slide_sphere_by_disp(center, transition, disp, sphere_num)`  -- SlideSphere(Vector3, Transition, Vector3, int)
* `slide_sphere_by_check_pos(center, transition, check_pos, sphere_num)` -- SlideSphere(Vector3, Transition, Sphere, int)
* `Sphere.slide_sphere(transition, collision_normal, curr_pos)` -- SlideSphere(Transition, ref Vector3, Vector3),
  returning ``(state, collision_normal)`` because ACE writes the ref back (SpherePath.StepUpNormal,
  NegCollisionNormal: callers must store it).

Double-precision spots kept as ACE computes them: FindTimeOfCollision's ``Math.Sqrt`` result and
everything after it is double (it returns a double); IntersectsSphere's ``t`` is double until
``(float)t / lenSq``; StepSphereDown's ``val`` is double until ``(float)(val - disp.Z)``;
SphereIntersectsRay's time is double.
"""

from __future__ import annotations

from acconform.flags import ObjectInfoState, TransitionState
from acconform.numerics import D, Plane, Vector3, cast_float, cross, dot

from ..anchors import anchor
from ..constants import EPSILON, LANDING_Z, STEP_INTERP_LIMIT
from ..land_defs import get_block_offset
from ..vec import cs_sqrt, normalize_check_small, zero_like

# SpherePath.cs InsertType.Placement (InsertType is Transition 0, Placement 1, InitialPlacement 2)
INSERT_TYPE_PLACEMENT = 1


class Sphere:
    """Sphere.cs: a center (Vector3) and a radius. A C# class: shared by reference, mutable."""

    __slots__ = ("center", "radius")

    @anchor("CSphere::CSphere", "Sphere.cs:Sphere")
    def __init__(self, center: Vector3 | None = None, radius=None):
        self.center = center
        self.radius = radius

    @anchor(None, "Sphere.cs:Sphere", "the copy constructor Sphere(Sphere)")
    def copy(self) -> "Sphere":
        return Sphere(self.center, self.radius)

    @classmethod
    @anchor(None, "Sphere.cs:Sphere(DatLoader.Entity.Sphere)", "the DAT constructor")
    def from_dat(cls, sphere) -> "Sphere":
        """``new Sphere(DatLoader.Entity.Sphere)``: Center = Origin, Radius."""
        return cls(sphere.origin, sphere.radius)

    def __eq__(self, o) -> bool:
        return isinstance(o, Sphere) and self.center == o.center and self.radius == o.radius

    __hash__ = None

    def __repr__(self) -> str:
        return f"Sphere({self.center!r}, {float(self.radius)!r})"

    @anchor("CSphere::intersects", "Sphere.cs:Intersects")
    def intersects(self, sphere: "Sphere") -> bool:
        delta = sphere.center - self.center
        rad_sum = self.radius + sphere.radius
        return delta.length_squared() < rad_sum * rad_sum

    @anchor("CSphere::intersects_sphere", "Sphere.cs:IntersectsSphere", "overload (Position, scale, Transition, isCreature)")
    def intersects_sphere(self, position, scale, transition, is_creature: bool) -> TransitionState:
        glob_pos = transition.sphere_path.check_pos.local_to_global_from(position, self.center * scale)
        return intersects_sphere(glob_pos, self.radius * scale, transition, is_creature)

    @anchor(None, "Sphere.cs:CollideWithPoint", "instance overload: passes Center")
    def collide_with_point(self, transition, check_pos: "Sphere", radsum, sphere_num: int) -> TransitionState:
        return collide_with_point(self.center, transition, check_pos, radsum, sphere_num)

    @anchor(None, "Sphere.cs:LandOnSphere", "instance overload: passes Center")
    def land_on_sphere(self, transition) -> TransitionState:
        return land_on_sphere(self.center, transition)

    @anchor(None, "Sphere.cs:SlideSphere", "instance overload (Transition, Vector3 disp, int): passes Center")
    def slide_sphere_by_disp(self, transition, disp: Vector3, sphere_num: int) -> TransitionState:
        return slide_sphere_by_disp(self.center, transition, disp, sphere_num)

    @anchor(None, "Sphere.cs:SlideSphere", "instance overload (Transition, Sphere checkPos, int): passes Center")
    def slide_sphere_by_check_pos(self, transition, check_pos: "Sphere", sphere_num: int) -> TransitionState:
        return slide_sphere_by_check_pos(self.center, transition, check_pos, sphere_num)

    @anchor("CSphere::slide_sphere", "Sphere.cs:SlideSphere", "overload (Transition, ref Vector3 collisionNormal, Vector3 currPos)")
    def slide_sphere(self, transition, collision_normal: Vector3, curr_pos: Vector3) -> tuple[TransitionState, Vector3]:
        """Slides this (global check) sphere along the contact plane away from collision_normal.

        Returns (state, collision_normal after the call): ACE's ``ref`` normal is overwritten
        with ``-gDelta`` (normalised unless tiny) on the OK path.
        """
        path = transition.sphere_path
        collisions = transition.collision_info

        if collision_normal == Vector3(0.0, 0.0, 0.0):
            half_offset = (curr_pos - self.center) * 0.5
            path.add_offset_to_check_pos(half_offset, self.radius)
            return TransitionState.Adjusted, collision_normal

        collisions.set_collision_normal(collision_normal)

        block_offset = get_block_offset(path.cur_pos.obj_cell_id, path.check_pos.obj_cell_id)
        g_delta = block_offset + (self.center - curr_pos)

        contact_plane = collisions.contact_plane if collisions.contact_plane_valid else collisions.last_known_contact_plane
        direction = cross(collision_normal, contact_plane.normal)
        dir_len_sq = direction.length_squared()
        if dir_len_sq >= EPSILON:
            diff = dot(direction, g_delta)
            inv_dir_len_sq = 1.0 / dir_len_sq
            offset = direction * diff * inv_dir_len_sq
            if offset.length_squared() < EPSILON:
                return TransitionState.Collided, collision_normal

            offset = offset - g_delta
            path.add_offset_to_check_pos(offset, self.radius)
            return TransitionState.Slid, collision_normal

        if dot(collision_normal, contact_plane.normal) >= 0.0:
            diff = dot(collision_normal, g_delta)
            offset = path.mode.runtime.negate(collision_normal) * diff
            path.add_offset_to_check_pos(offset, self.radius)
            return TransitionState.Slid, collision_normal

        collision_normal = path.mode.runtime.negate(g_delta)
        small, collision_normal = normalize_check_small(collision_normal)
        if not small:
            collisions.set_collision_normal(collision_normal)

        return TransitionState.OK, collision_normal

    @anchor(None, "Sphere.cs:StepSphereDown", "instance overload: passes Center, Radius")
    def step_sphere_down(self, transition, check_pos: "Sphere", disp: Vector3, radsum) -> tuple[TransitionState, Vector3]:
        return step_sphere_down(self.center, self.radius, transition, check_pos, disp, radsum)

    @anchor(None, "Sphere.cs:StepSphereUp", "instance overload: passes Center")
    def step_sphere_up(self, transition, disp: Vector3, radsum) -> TransitionState:
        return step_sphere_up(self.center, transition, disp, radsum)

    @anchor("CSphere::sphere_intersects_ray", "Sphere.cs:SphereIntersectsRay")
    def sphere_intersects_ray(self, ray) -> tuple[bool, object]:
        """Returns (hit, time_of_intersection); the time is a C# double (0.0 on a miss)."""
        time_of_intersection = D(0.0)

        dist_sq = ray.dir.length_squared()
        if dist_sq < EPSILON:
            return False, time_of_intersection

        delta = ray.point - self.center
        c = delta.length_squared() - self.radius * self.radius
        if c <= 0:
            return False, time_of_intersection

        b = -dot(delta, ray.dir)
        d = b * b - c * dist_sq
        if d < 0:
            return False, time_of_intersection

        dist = cs_sqrt(d)
        if b <= dist:
            time_of_intersection = (b + dist) / dist_sq
        else:
            time_of_intersection = (b - dist) / dist_sq
        return True, time_of_intersection


# ---------------------------------------------------------------- ACE's static overloads


@anchor("CSphere::collide_with_point", "Sphere.cs:CollideWithPoint", "static overload (center, ...)")
def collide_with_point(center: Vector3, transition, check_pos: Sphere, radsum, sphere_num: int) -> TransitionState:
    obj = transition.object_info
    path = transition.sphere_path
    collisions = transition.collision_info

    g_center = path.global_curr_center[sphere_num].center
    global_offset = g_center - center

    # if set to PerfectClip, does a more precise check
    if obj.state & ObjectInfoState.PerfectClip:
        block_offset = get_block_offset(path.cur_pos.obj_cell_id, path.check_pos.obj_cell_id)
        check_offset = check_pos.center - g_center + block_offset
        collision_time = find_time_of_collision(check_offset, global_offset, radsum + EPSILON)
        if collision_time < EPSILON or collision_time > 1.0:
            return TransitionState.Collided
        collision_offset = check_offset * cast_float(radsum, collision_time) - check_offset
        old_disp = collision_offset + check_pos.center - center
        inv_rad = 1.0 / radsum
        collision_normal = old_disp * inv_rad
        collisions.set_collision_normal(collision_normal)
        path.add_offset_to_check_pos(old_disp, check_pos.radius)
        return TransitionState.Adjusted

    small, global_offset = normalize_check_small(global_offset)
    if not small:
        collisions.set_collision_normal(global_offset)
    return TransitionState.Collided


@anchor("CSphere::collides_with_sphere", "Sphere.cs:CollidesWithSphere")
def collides_with_sphere(other_sphere: Vector3, radsum) -> bool:
    """Touching counts: ``LengthSquared() <= radsum * radsum``."""
    return other_sphere.length_squared() <= radsum * radsum


@anchor("CSphere::find_time_of_collision", "Sphere.cs:FindTimeOfCollision")
def find_time_of_collision(movement: Vector3, sphere_pos: Vector3, rad_sum):
    """A C# double: the time along `movement`, or -1. After ``Math.Sqrt`` it computes in double."""
    dist_sq = movement.length_squared()
    if dist_sq < EPSILON:
        return D(-1.0)

    non_collide = sphere_pos.length_squared() - rad_sum * rad_sum
    if non_collide < EPSILON:
        return D(-1.0)

    similar = -dot(sphere_pos, movement)
    non_collide_b = similar * similar - non_collide * dist_sq
    if non_collide_b < 0:
        return D(-1.0)

    c_dist = cs_sqrt(non_collide_b)
    if similar - c_dist < 0:
        return -1 * (c_dist + similar) / dist_sq
    return -1 * (similar - c_dist) / dist_sq


@anchor("CSphere::intersects_sphere", "Sphere.cs:IntersectsSphere", "static overload (center, radius, Transition, isCreature)")
def intersects_sphere(center: Vector3, radius, transition, is_creature: bool) -> TransitionState:
    path = transition.sphere_path
    glob_sphere = path.global_sphere[0]
    disp = glob_sphere.center - center

    glob_sphere_ = None
    disp_ = zero_like(radius)

    if path.num_sphere > 1:
        glob_sphere_ = path.global_sphere[1]
        disp_ = glob_sphere_.center - center

    radsum = glob_sphere.radius + radius - EPSILON
    if path.trace is not None:
        path.trace.boundary("sphere_tangent", disp.length_squared(), radsum * radsum)
        if path.num_sphere > 1:
            path.trace.boundary("sphere_tangent", disp_.length_squared(), radsum * radsum)

    if path.obstruction_ethereal or path.insert_type == INSERT_TYPE_PLACEMENT:
        if disp.length_squared() <= radsum * radsum:
            return TransitionState.Collided

        if path.num_sphere > 1:
            if collides_with_sphere(disp_, radsum):
                return TransitionState.Collided
        return TransitionState.OK

    if path.step_down:
        if is_creature:
            return TransitionState.OK

        state, _disp = step_sphere_down(center, radius, transition, glob_sphere, disp, radsum)
        return state

    if path.check_walkable:
        if collides_with_sphere(disp, radsum):
            return TransitionState.Collided

        if path.num_sphere > 1:
            if collides_with_sphere(disp_, radsum):
                return TransitionState.Collided
        return TransitionState.OK

    if not path.collide:
        state = transition.object_info.state
        if state & ObjectInfoState.Contact or state & ObjectInfoState.OnWalkable:
            if collides_with_sphere(disp, radsum):
                return step_sphere_up(center, transition, disp, radsum)

            if path.num_sphere > 1:
                if collides_with_sphere(disp_, radsum):
                    return slide_sphere_by_check_pos(center, transition, glob_sphere_, 1)
            return TransitionState.OK
        elif state & ObjectInfoState.PathClipped:
            if collides_with_sphere(disp, radsum):
                return collide_with_point(center, transition, glob_sphere, radsum, 0)
        else:
            if collides_with_sphere(disp, radsum):
                return land_on_sphere(center, transition)

            if path.num_sphere > 1:
                if collides_with_sphere(disp_, radsum):
                    return collide_with_point(center, transition, glob_sphere_, radsum, 1)
        return TransitionState.OK

    if is_creature:
        return TransitionState.OK

    if not collides_with_sphere(disp, radsum):
        if path.num_sphere > 1:
            if not collides_with_sphere(disp_, radsum):
                return TransitionState.OK

    # handles movement interpolation
    block_offset = path.get_cur_pos_check_pos_block_offset()
    movement = path.global_curr_center[0].center - glob_sphere.center - block_offset
    radsum += EPSILON
    len_sq = movement.length_squared()
    diff = -dot(movement, disp)
    if abs(len_sq) < EPSILON:
        return TransitionState.Collided

    t = cs_sqrt(diff * diff - (disp.length_squared() - radsum * radsum) * len_sq) + diff  # solve for t (double)
    if t > 1:
        t = diff * 2 - t
    time = cast_float(len_sq, t) / len_sq
    timecheck = (1 - time) * path.walk_interp
    if timecheck >= path.walk_interp or timecheck < STEP_INTERP_LIMIT:
        return TransitionState.Collided

    movement = movement * time
    disp = (disp + movement) / radsum

    if not path.is_walkable_allowable(disp.z):
        return TransitionState.OK

    disp2 = glob_sphere.center - disp * glob_sphere.radius

    contact_plane = Plane(disp, -dot(disp, disp2))
    collisions = transition.collision_info
    collisions.set_contact_plane(contact_plane, True)
    collisions.contact_plane_cell_id = path.check_pos.obj_cell_id
    path.walk_interp = timecheck
    path.add_offset_to_check_pos(movement, glob_sphere.radius)

    return TransitionState.Adjusted


@anchor("CSphere::land_on_sphere", "Sphere.cs:LandOnSphere", "static overload (center, Transition)")
def land_on_sphere(center: Vector3, transition) -> TransitionState:
    path = transition.sphere_path

    collision_normal = path.global_curr_center[0].center - center

    small, collision_normal = normalize_check_small(collision_normal)
    if small:
        return TransitionState.Collided
    path.set_collide(collision_normal)
    path.walkable_allowance = type(collision_normal.x)(LANDING_Z)
    return TransitionState.Adjusted


@anchor("CSphere::slide_sphere", "Sphere.cs:SlideSphere", "static overload (center, Transition, Vector3 disp, int sphereNum)")
def slide_sphere_by_disp(center: Vector3, transition, disp: Vector3, sphere_num: int) -> TransitionState:
    path = transition.sphere_path
    collisions = transition.collision_info

    glob_sphere = path.global_sphere[sphere_num]

    collision_normal = path.global_curr_center[sphere_num].center - center
    small, collision_normal = normalize_check_small(collision_normal)
    if small:
        return TransitionState.Collided

    collisions.set_collision_normal(collision_normal)

    contact_plane = collisions.contact_plane if collisions.contact_plane_valid else collisions.last_known_contact_plane
    skid_dir = contact_plane.normal
    direction = cross(collision_normal, skid_dir)

    block_offset = get_block_offset(path.cur_pos.obj_cell_id, path.check_pos.obj_cell_id)
    glob_offset = glob_sphere.center - path.global_curr_center[sphere_num].center + block_offset
    dir_len_sq = direction.length_squared()
    if dir_len_sq >= EPSILON:
        # C# `Vector3.Dot(globOffset, direction) * direction`: float * Vector3 multiplies
        # each component by the scalar (commutative, so written vector * scalar here)
        skid_dir = direction * dot(glob_offset, direction)

        inv_dir_len_sq = 1.0 / dir_len_sq

        skid_dir = skid_dir * inv_dir_len_sq
        direction = skid_dir

        if direction.length_squared() < EPSILON:
            return TransitionState.Collided

        direction = direction - glob_offset

        path.add_offset_to_check_pos(direction, glob_sphere.radius)
        return TransitionState.Slid

    if dot(skid_dir, disp) < 0.0:
        return TransitionState.Collided

    direction = collision_normal * -dot(glob_offset, collision_normal)
    path.add_offset_to_check_pos(direction, glob_sphere.radius)
    return TransitionState.Slid


@anchor(None, "Sphere.cs:SlideSphere", "static overload (center, Transition, Sphere checkPos, int sphereNum)")
def slide_sphere_by_check_pos(center: Vector3, transition, check_pos: Sphere, sphere_num: int) -> TransitionState:
    global_center = transition.sphere_path.global_curr_center[sphere_num].center

    collision_normal = global_center - center

    small, collision_normal = normalize_check_small(collision_normal)
    if small:
        return TransitionState.Collided
    state, _normal = check_pos.slide_sphere(transition, collision_normal, global_center)
    return state


@anchor("CSphere::step_sphere_down", "Sphere.cs:StepSphereDown", "static overload (center, radius, ...)")
def step_sphere_down(center: Vector3, radius, transition, check_pos: Sphere, disp: Vector3, radsum) -> tuple[TransitionState, Vector3]:
    """``StepSphereDown(..., ref disp, radsum)``: returns (state, disp after the call)."""
    path = transition.sphere_path
    collisions = transition.collision_info

    if not collides_with_sphere(disp, radsum):
        if path.num_sphere <= 1:
            return TransitionState.OK, disp

        disp_ = path.global_sphere[1].center - center
        if not collides_with_sphere(disp_, radsum):
            return TransitionState.OK, disp

    step_down = path.step_down_amt * path.walk_interp
    if abs(step_down) < EPSILON:
        return TransitionState.Collided, disp

    radsum += EPSILON
    val = cs_sqrt(radsum * radsum - (disp.x * disp.x + disp.y * disp.y))  # double
    scaled_step = cast_float(step_down, val - disp.z) / step_down
    timecheck = (1.0 - scaled_step) * path.walk_interp
    if timecheck >= path.walk_interp or timecheck < STEP_INTERP_LIMIT:
        return TransitionState.Collided, disp

    interp = step_down * scaled_step
    inv_rad_sum = 1.0 / radsum

    disp = Vector3(disp.x, disp.y, disp.z + interp) * inv_rad_sum

    if path.trace is not None:
        path.trace.walkable(disp.z, path.walkable_allowance)
    if disp.z <= path.walkable_allowance:
        return TransitionState.OK, disp

    scaled_disp = disp * radius + center
    rest_plane = Plane(disp, -dot(disp, scaled_disp))

    collisions.set_contact_plane(rest_plane, True)
    collisions.contact_plane_cell_id = path.check_pos.obj_cell_id
    path.walk_interp = timecheck

    zero = type(interp)(0.0)
    offset = Vector3(zero, zero, interp)
    path.add_offset_to_check_pos(offset, check_pos.radius)

    return TransitionState.Adjusted, disp


@anchor("CSphere::step_sphere_up", "Sphere.cs:StepSphereUp", "static overload (center, Transition, disp, radsum)")
def step_sphere_up(center: Vector3, transition, disp: Vector3, radsum) -> TransitionState:
    radsum += EPSILON
    if transition.trace is not None:
        transition.trace.boundary("step_up_height", transition.object_info.step_up_height, radsum - disp.z)
    if transition.object_info.step_up_height < radsum - disp.z:
        return slide_sphere_by_disp(center, transition, disp, 0)
    glob_center = transition.sphere_path.global_curr_center[0].center
    collision_normal = glob_center - center
    if transition.step_up(collision_normal):
        return TransitionState.OK
    return transition.sphere_path.step_up_slide(transition)
