"""CollisionInfo: Init, SetContactPlane, SetCollisionNormal, SetSlidingNormal, AddObject.

ACE's Collision/CollisionInfo.cs: what a transition found. The collision and sliding normals are
stored as ACE stores them -- un-normalised (NormalizeCheckSmall works on a copy and only decides
whether the stored vector is replaced by zero).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from acconform.flags import TransitionState
from acconform.numerics import Plane, Vector3

from ..anchors import anchor
from ..vec import normalize_check_small, zero_like


@dataclass(slots=True)
class CollisionInfo:
    last_known_contact_plane_valid: bool = False
    last_known_contact_plane: Plane | None = None
    last_known_contact_plane_is_water: bool = False
    contact_plane_valid: bool = False
    contact_plane: Plane | None = None
    contact_plane_cell_id: int = 0
    last_known_contact_plane_cell_id: int = 0
    contact_plane_is_water: bool = False
    sliding_normal_valid: bool = False
    sliding_normal: Vector3 | None = None
    collision_normal_valid: bool = False
    collision_normal: Vector3 | None = None
    adjust_offset: Vector3 | None = None
    num_collide_object: int = 0
    collide_object: list = field(default_factory=list)
    last_collided_object: object = None
    collided_with_environment: bool = False
    frames_stationary_fall: int = 0
    verified_restrictions: bool = False  # custom for server (ACE)

    @staticmethod
    @anchor("COLLISIONINFO::COLLISIONINFO", "CollisionInfo.cs:CollisionInfo()", "C#'s default field values; Init's list is the dataclass default")
    def create(zero) -> "CollisionInfo":
        """``new CollisionInfo()``: C#'s default struct fields (zero vectors, zero plane) in the
        scalar type of `zero`."""
        z = zero_like(zero)
        return CollisionInfo(last_known_contact_plane=Plane(z, z.x), contact_plane=Plane(z, z.x),
                             sliding_normal=z, collision_normal=z, adjust_offset=z)

    @anchor("COLLISIONINFO::init", "CollisionInfo.cs:Init")
    def init(self) -> None:
        self.collide_object = []

    @anchor("COLLISIONINFO::set_contact_plane", "CollisionInfo.cs:SetContactPlane")
    def set_contact_plane(self, plane: Plane, is_water: bool) -> None:
        self.contact_plane_valid = True
        self.contact_plane = Plane(plane.normal, plane.d)
        self.contact_plane_is_water = is_water

    @anchor("COLLISIONINFO::set_collision_normal", "CollisionInfo.cs:SetCollisionNormal")
    def set_collision_normal(self, normal: Vector3) -> None:
        self.collision_normal_valid = True
        self.collision_normal = normal  # ACE keeps the vector it was given
        small, _ = normalize_check_small(normal)
        if small:
            self.collision_normal = zero_like(normal.x)

    @anchor("COLLISIONINFO::set_sliding_normal", "CollisionInfo.cs:SetSlidingNormal")
    def set_sliding_normal(self, normal: Vector3) -> None:
        self.sliding_normal_valid = True
        self.sliding_normal = Vector3(normal.x, normal.y, type(normal.x)(0.0))
        small, _ = normalize_check_small(normal)
        if small:
            self.sliding_normal = zero_like(normal.x)

    @anchor("COLLISIONINFO::add_object", "CollisionInfo.cs:AddObject")
    def add_object(self, obj, state: TransitionState) -> None:
        if any(o is obj for o in self.collide_object):
            return
        self.collide_object.append(obj)
        self.num_collide_object += 1
        if state != TransitionState.OK:
            self.last_collided_object = obj
