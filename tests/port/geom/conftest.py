"""Stand-ins for the Transition / SpherePath / CollisionInfo / ObjectInfo members port/geom
touches (ACE's names, snake_cased), so geometry is tested without the transition package."""

from __future__ import annotations

from dataclasses import dataclass, field

import pytest

from acconform.numerics import EXACT, Mode, Plane, Vector3
from acconform.port.constants import FLOOR_Z


@dataclass
class FakeCollisions:
    contact_plane_valid: bool = False
    contact_plane: Plane | None = None
    contact_plane_is_water: bool = False
    contact_plane_cell_id: int = 0
    last_known_contact_plane: Plane | None = None
    collision_normal: Vector3 | None = None
    collision_normals: list = field(default_factory=list)

    def set_contact_plane(self, plane, is_water):
        self.contact_plane_valid = True
        self.contact_plane = plane
        self.contact_plane_is_water = is_water

    def set_collision_normal(self, normal):
        self.collision_normal = normal
        self.collision_normals.append(normal)


@dataclass
class FakePath:
    mode: Mode = EXACT  # the run's numerics (its runtime negates vectors)
    num_sphere: int = 1
    global_sphere: list = field(default_factory=list)
    global_curr_center: list = field(default_factory=list)
    local_space_sphere: list = field(default_factory=list)
    local_space_curr_center: list = field(default_factory=list)
    local_space_z: Vector3 = None
    local_space_pos: object = None
    cur_pos: object = None
    check_pos: object = None
    insert_type: int = 0
    obstruction_ethereal: bool = False
    building_check: bool = False
    hits_interior_cell: bool = False
    step_down: bool = False
    check_walkable: bool = False
    collide: bool = False
    walkable_allowance: object = None
    walk_interp: object = None
    step_down_amt: object = None
    offsets: list = field(default_factory=list)
    collide_normal: Vector3 | None = None
    walkable: tuple | None = None
    neg_poly_hit: tuple | None = None

    def add_offset_to_check_pos(self, offset, radius=None):
        self.offsets.append(offset)

    def set_collide(self, normal):
        self.collide = True
        self.collide_normal = normal
        self.walk_interp = EXACT.scalar(1.0)

    def set_walkable(self, sphere, poly, z_axis, local_pos, scale):
        self.walkable = (sphere, poly, z_axis, scale)

    def set_neg_poly_hit(self, step_up, normal):
        self.neg_poly_hit = (step_up, normal)

    def cache_global_sphere(self, offset):
        pass

    def get_cur_pos_check_pos_block_offset(self):
        return Vector3(0.0, 0.0, 0.0)

    def is_walkable_allowable(self, zval):
        return zval > self.walkable_allowance


@dataclass
class FakeObjectInfo:
    state: int = 0
    step_up_height: object = None


@dataclass
class FakeTransition:
    sphere_path: FakePath
    collision_info: FakeCollisions
    object_info: FakeObjectInfo


@pytest.fixture
def make_transition():
    from acconform.port.frame import AFrame, Position

    def make(**path_fields):
        def pos():
            return Position(0xA9B40001, AFrame(EXACT.vec(0, 0, 0), EXACT.quat(0, 0, 0, 1)))

        path = FakePath(local_space_z=EXACT.vec(0, 0, 1), local_space_pos=pos(), cur_pos=pos(), check_pos=pos(),
                        walkable_allowance=EXACT.scalar(FLOOR_Z), walk_interp=EXACT.scalar(1.0),
                        step_down_amt=EXACT.scalar(0.0))
        for k, v in path_fields.items():
            setattr(path, k, v)
        up = EXACT.vec(0, 0, 1)
        collisions = FakeCollisions(last_known_contact_plane=Plane(up, EXACT.scalar(0.0)))
        return FakeTransition(path, collisions, FakeObjectInfo(step_up_height=EXACT.scalar(0.5)))

    return make
