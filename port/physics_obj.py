"""PhysicsObj: transition, get_object_info, check_contact, get_walkable_z, is_valid_walkable, set_velocity, GetStepUpHeight, GetStepDownHeight, FindObjCollisions, FindObjCollisions_Inner, Equals.

The part of ACE's PhysicsObj.cs a transition uses: the set-up PhysicsObj.transition does before
FindValidPosition, and the members the transition reads back (walkable checks, StopVelocity's
set_velocity). The mover's PartArray is reduced to what it answers here: its Setup's spheres,
step heights and AllowFreeHeading; the WeenieObj is ACE's WeenieObject.DummyObject (no player,
creature or PK flags), which is what a PhysicsObj made without a WorldObject carries.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from acconform.flags import ObjectInfoState, PhysicsState, TransientState, TransitionState
from acconform.numerics import Plane, Vector3, dot

from .anchors import anchor
from .constants import DUMMY_SPHERE_RADIUS, EPSILON, FLOOR_Z
from .transition.object_info import ObjectInfo
from .transition.transition import Transition

# PhysicsGlobals.MaxVelocity = 50.0f
MAX_VELOCITY = 50.0


@dataclass(frozen=True, slots=True)
class DummyWeenie:
    """WeenieObject.DummyObject: every flag false."""

    is_player: bool = False
    is_creature: bool = False

    def is_impenetrable(self) -> bool:
        return False

    def is_pk(self) -> bool:
        return False

    def is_pk_lite(self) -> bool:
        return False


@dataclass(slots=True)
class ShadowObj:
    """Common/ShadowObj.cs: an object's entry in a cell it overlaps."""

    physics_obj: "PhysicsObj"
    cell: object


@dataclass(slots=True, eq=False)
class PhysicsObj:
    id: int
    state: int  # PhysicsState
    position: object  # frame.Position
    cur_cell: object = None
    transient_state: int = 0
    velocity: Vector3 | None = None
    contact_plane: Plane | None = None
    contact_plane_cell_id: int = 0
    sliding_normal: Vector3 | None = None
    scale: object = 1.0
    spheres: list = field(default_factory=list)  # PartArray.GetSphere(): the Setup's spheres
    setup_step_up_height: object = 0.0
    setup_step_down_height: object = 0.0
    has_part_array: bool = True
    allows_free_heading: bool = False
    weenie_obj: object = field(default_factory=DummyWeenie)
    projectile_target: object = None
    parent: object = None
    is_player: bool = False
    is_sight_obj: bool = False
    jumped_this_frame: bool = False
    shape: object = None  # a static object's collision shape (see find_obj_collisions)

    @anchor(None, "PhysicsObj.cs:Equals")
    def equals(self, obj) -> bool:
        if obj is None:
            return False
        return self.id == obj.id

    @anchor("CPhysicsObj::GetStepUpHeight", "PhysicsObj.cs:GetStepUpHeight")
    def get_step_up_height(self):
        """PartArray.GetStepUpHeight: Setup.StepUpHeight * PartArray.Scale.Z (the object's scale)."""
        if not self.has_part_array:
            return type(self.scale)(0.0)
        return self.setup_step_up_height * self.scale

    @anchor("CPhysicsObj::GetStepDownHeight", "PhysicsObj.cs:GetStepDownHeight")
    def get_step_down_height(self):
        if not self.has_part_array:
            return type(self.scale)(0.0)
        return self.setup_step_down_height * self.scale

    @anchor("CPhysicsObj::check_contact", "PhysicsObj.cs:check_contact")
    def check_contact(self, contact: bool) -> bool:
        if self.transient_state & TransientState.Contact and dot(self.velocity, self.contact_plane.normal) > EPSILON:
            return False
        return contact

    @anchor("CPhysicsObj::get_object_info", "PhysicsObj.cs:get_object_info")
    def get_object_info(self, transition: Transition, admin_move: bool) -> ObjectInfo:
        obj_info = ObjectInfo()
        if self.state & PhysicsState.EdgeSlide:
            obj_info.state |= ObjectInfoState.EdgeSlide

        if not admin_move:
            if self.transient_state & TransientState.Contact:
                is_water = bool(self.transient_state & TransientState.WaterContact)
                if self.check_contact(True):
                    transition.init_contact_plane(self.contact_plane_cell_id, self.contact_plane, is_water)
                    obj_info.state |= ObjectInfoState.Contact
                    if self.transient_state & TransientState.OnWalkable:
                        obj_info.state |= ObjectInfoState.OnWalkable
                else:
                    if transition.trace is not None:
                        transition.trace["get_object_info:leaving_contact"] += 1
                    transition.init_last_known_contact_plane(self.contact_plane_cell_id, self.contact_plane, is_water)

            if self.transient_state & TransientState.Sliding:
                transition.init_sliding_normal(self.sliding_normal)

        if self.has_part_array and self.allows_free_heading:
            obj_info.state |= ObjectInfoState.FreeRotate

        if self.state & PhysicsState.Missile:
            obj_info.state |= ObjectInfoState.PathClipped

        return obj_info

    @anchor("CPhysicsObj::get_walkable_z", "PhysicsObj.cs:get_walkable_z")
    def get_walkable_z(self):
        return type(self.scale)(FLOOR_Z)

    @staticmethod
    @anchor("CPhysicsObj::is_valid_walkable", "PhysicsObj.cs:is_valid_walkable")
    def is_valid_walkable(normal: Vector3) -> bool:
        return bool(normal.z >= FLOOR_Z)

    @anchor("CPhysicsObj::set_velocity", "PhysicsObj.cs:set_velocity")
    def set_velocity(self, velocity: Vector3, send_event: bool) -> None:
        """The observable part: Velocity (clamped to MaxVelocity) and the Active transient flag."""
        if not velocity == self.velocity:
            self.velocity = velocity
            if self.velocity.length() > MAX_VELOCITY:
                self.velocity = self.velocity / self.velocity.length()
                self.velocity = self.velocity * MAX_VELOCITY
            self.jumped_this_frame = True
        if not self.state & PhysicsState.Static:
            self.transient_state |= TransientState.Active

    @anchor("CPhysicsObj::FindObjCollisions", "PhysicsObj.cs:FindObjCollisions")
    def find_obj_collisions(self, transition: Transition) -> TransitionState:
        raise NotImplementedError("static object collisions are not ported yet")

    @anchor("CPhysicsObj::transition", "PhysicsObj.cs:transition")
    def transition(self, old_pos, new_pos, admin_move: bool, lscape, trace=None) -> tuple[Transition, bool]:
        """Returns (the transition, FindValidPosition's answer). ACE returns null when the answer
        is False; the outcome reads the transition either way (as the oracle does)."""
        trans = Transition(lscape.mode, lscape, trace)

        object_info = self.get_object_info(trans, admin_move)
        trans.init_object(self, object_info.state)

        mode = lscape.mode
        if not self.has_part_array or len(self.spheres) == 0:
            from .geom.sphere import Sphere

            dummy = Sphere(mode.vec(0, 0, DUMMY_SPHERE_RADIUS), mode.scalar(DUMMY_SPHERE_RADIUS))
            trans.init_sphere(1, [dummy], mode.scalar(1.0))
        else:
            trans.init_sphere(len(self.spheres), self.spheres, self.scale)

        trans.init_path(self.cur_cell, old_pos, new_pos)

        if self.transient_state & TransientState.StationaryStuck:
            trans.collision_info.frames_stationary_fall = 3
        elif self.transient_state & TransientState.StationaryStop:
            trans.collision_info.frames_stationary_fall = 2
        elif self.transient_state & TransientState.StationaryFall:
            trans.collision_info.frames_stationary_fall = 1

        valid_pos = trans.find_valid_position()
        trans.cleanup_transition()
        return trans, valid_pos
