"""InterpolationManager: InterpolationManager(obj), Create, InterpolateTo, IsInterpolating, NodeCompleted, SetPhysicsObject, StopInterpolating, UseTime, adjust_offset.

ACE's Managers/InterpolationManager.cs: a queue (at most 20) of positions the server was told an
object is at; adjust_offset walks the object toward the head node at up to twice its adjusted
max speed, completes a node within 0.05, and fails a node when five frames make less than 0.3 of
the speed's progress; UseTime jumps the object to the last node (SetPositionSimple) once more than
three nodes failed or a node was farther than the autonomy blip distance.

Kept as ACE has them (each pinned by tests/port/managers/test_interpolation_manager.py):
- adjust_offset subtracts the object's frame from the head node's Position *in place*
  (Position.Subtract changes its own frame and returns it) and then scales that frame; its last
  line ``frame = offset`` assigns the parameter, so the caller's frame is never changed;
- InterpolateTo keeps the caller's Position in the node (no copy) and, with keepHeading, sets its
  heading in place; the KeepHeading field is never set;
- UseTime's loop starts at ``ElementAt(PositionQueue.Count)``, which throws
  ArgumentOutOfRangeException whenever it is reached (a failed queue whose last node is a jump or
  velocity node); with no node left and NodeFailCounter > 0 it reads ``PositionQueue.Last.Value``
  of an empty list (NullReferenceException).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from acconform.flags import SetPositionError, TransientState
from acconform.numerics import D, cast_float

from ..anchors import anchor
from ..animation.interpolation_node import InterpolationNode, InterpolationNodeType
from ..constants import EPSILON, INTERPOLATION_LARGE_DISTANCE, INTERPOLATION_MIN_PROGRESS, INTERPOLATION_NODE_REACHED
from ..errors import ArgumentOutOfRangeException
from ..linked_list import LinkedList

LARGE_DISTANCE = INTERPOLATION_LARGE_DISTANCE  # InterpolationManager.LargeDistance = 999999.0f
MAX_INTERPOLATED_VELOCITY = 7.5  # InterpolationManager.MaxInterpolatedVelocity = 7.5f (exact)
USE_ADJUSTED_SPEED = True  # InterpolationManager.UseAdjustedSpeed (a static bool ACE never changes)
MAX_QUEUE = 20  # InterpolateTo keeps at most 20 nodes


@dataclass(slots=True, eq=False)
class InterpolationManager:
    position_queue: LinkedList = field(default_factory=LinkedList)  # of InterpolationNode
    physics_obj: object = None
    keep_heading: bool = False
    frame_counter: int = 0
    original_distance: object = 0.0  # float
    progress_quantum: object = 0.0  # float
    node_fail_counter: int = 0
    blip_to_position: object = None  # Position

    @staticmethod
    @anchor("InterpolationManager::Create", "InterpolationManager.cs:Create")
    def create(obj) -> "InterpolationManager":
        """``new InterpolationManager(obj)``: OriginalDistance = LargeDistance, SetPhysicsObject(obj).
        The float fields take the scalar type of the object's position (the run's mode)."""
        f = type(obj.position.frame.origin.x)
        manager = InterpolationManager(original_distance=f(LARGE_DISTANCE), progress_quantum=f(0.0))
        manager.set_physics_object(obj)
        return manager

    @anchor("InterpolationManager::InterpolateTo", "InterpolationManager.cs:InterpolateTo")
    def interpolate_to(self, position, keep_heading: bool) -> None:
        if self.physics_obj is None:
            return

        queue = self.position_queue
        if queue.count > 0 and queue.last.value.type == InterpolationNodeType.PositionType:
            dest = queue.last.value.position
        else:
            dest = self.physics_obj.position

        dist = dest.distance(position)

        if self.physics_obj.get_autonomy_blip_distance() >= dist:
            if self.physics_obj.position.distance(position) > INTERPOLATION_NODE_REACHED:
                while queue.count > 0:
                    last_node = queue.last.value
                    if (last_node.type != InterpolationNodeType.PositionType
                            or last_node.position.distance(position) >= INTERPOLATION_NODE_REACHED):
                        break

                    queue.remove_last()
                while queue.count >= MAX_QUEUE:
                    queue.remove_first()

                interpolation_node = InterpolationNode.create(InterpolationNodeType.PositionType, position)
                if keep_heading:
                    interpolation_node.position.frame.set_heading(self.physics_obj.get_heading())

                queue.add_last(interpolation_node)
            else:
                if not keep_heading:
                    self.physics_obj.set_heading(position.frame.get_heading(), True)

                self.stop_interpolating()
        else:
            interpolation_node = InterpolationNode.create(InterpolationNodeType.PositionType, position)
            if keep_heading:
                interpolation_node.position.frame.set_heading(self.physics_obj.get_heading())

            queue.add_last(interpolation_node)
            self.node_fail_counter = 4

    @anchor("InterpolationManager::IsInterpolating", "InterpolationManager.cs:IsInterpolating")
    def is_interpolating(self) -> bool:
        return self.position_queue.count > 0

    @anchor("InterpolationManager::NodeCompleted", "InterpolationManager.cs:NodeCompleted")
    def node_completed(self, success: bool) -> None:
        if self.physics_obj is None:
            return

        self.frame_counter = 0
        self.progress_quantum = type(self.progress_quantum)(0.0)

        queue = self.position_queue
        head = None if queue.count == 0 else queue.first.value
        next_ = None if queue.count <= 1 else queue.first.next.value  # ElementAt(1)

        if queue.count > 1:
            if next_.type == InterpolationNodeType.PositionType:
                self.original_distance = self.physics_obj.position.distance(next_.position)

            elif not success:
                if head is None:
                    return
                self.blip_to_position = head.position
        else:
            self.original_distance = type(self.original_distance)(LARGE_DISTANCE)
            if not success:
                if head is None:
                    return
                self.blip_to_position = head.position
            else:
                self.stop_interpolating()
        if queue.count > 0:
            queue.remove_first()

    @anchor("InterpolationManager::SetPhysicsObject", "InterpolationManager.cs:SetPhysicsObject")
    def set_physics_object(self, obj) -> None:
        self.physics_obj = obj

    @anchor("InterpolationManager::StopInterpolating", "InterpolationManager.cs:StopInterpolating")
    def stop_interpolating(self) -> None:
        self.position_queue.clear()
        self.original_distance = type(self.original_distance)(LARGE_DISTANCE)
        self.frame_counter = 0
        self.progress_quantum = type(self.progress_quantum)(0.0)
        self.node_fail_counter = 0

    @anchor("InterpolationManager::UseTime", "InterpolationManager.cs:UseTime")
    def use_time(self) -> None:
        if self.physics_obj is None:
            return

        queue = self.position_queue
        if self.node_fail_counter > 3 or queue.count == 0:
            if self.node_fail_counter <= 0:
                return

            last = queue.last.value  # an empty queue: null.Value, as ACE
            if last.type != InterpolationNodeType.JumpType and last.type != InterpolationNodeType.VelocityType:
                if self.physics_obj.set_position_simple(last.position, True) != SetPositionError.OK:
                    return

                self.stop_interpolating()
                return

            if queue.count > 1:
                i = queue.count
                while i >= 0:
                    # Enumerable.ElementAt(i) of a LinkedList: i starts at Count, past the end
                    if i >= queue.count:
                        raise ArgumentOutOfRangeException(f"ElementAt({i}) of a queue of {queue.count}")
                    node = queue.first
                    for _ in range(i):
                        node = node.next
                    node = node.value
                    if node.type == InterpolationNodeType.PositionType:
                        if self.physics_obj.set_position_simple(node.position, True) != SetPositionError.OK:
                            return

                        self.physics_obj.set_velocity(last.velocity, True)
                        self.stop_interpolating()
                        return
                    i -= 1

            if self.physics_obj.set_position_simple(self.blip_to_position, True) != SetPositionError.OK:
                return

            self.stop_interpolating()
            return

        first = queue.first.value
        if first.type == InterpolationNodeType.JumpType:
            self.node_completed(True)
        elif first.type == InterpolationNodeType.VelocityType:
            self.physics_obj.set_velocity(first.velocity, True)
            self.node_completed(True)

    @anchor("InterpolationManager::adjust_offset", "InterpolationManager.cs:adjust_offset")
    def adjust_offset(self, frame, quantum: float) -> None:
        """`quantum` is a double. ACE's ``frame = offset`` leaves the caller's `frame` as it was; the
        head node's Position is what changes (see the module note)."""
        queue = self.position_queue
        if queue.count == 0 or self.physics_obj is None or not self.physics_obj.transient_state & TransientState.Contact:
            return

        first = queue.first.value
        if first.type == InterpolationNodeType.JumpType or first.type == InterpolationNodeType.VelocityType:
            return

        dist = self.physics_obj.position.distance(first.position)
        if dist < INTERPOLATION_NODE_REACHED:
            self.node_completed(True)
            return
        max_speed = type(dist)(0.0)
        minterp = self.physics_obj.get_minterp()
        if minterp is not None:
            if USE_ADJUSTED_SPEED:
                max_speed = minterp.get_adjusted_max_speed() * 2.0
            else:
                max_speed = minterp.get_max_speed() * 2.0
        if max_speed < EPSILON:
            max_speed = type(dist)(MAX_INTERPOLATED_VELOCITY)

        delta = self.original_distance - dist
        self.progress_quantum += cast_float(self.progress_quantum, quantum)
        self.frame_counter += 1

        if self.frame_counter < 5 or (self.physics_obj.get_sticky_object() != 0
                                      or delta > EPSILON and delta / self.progress_quantum / max_speed >= INTERPOLATION_MIN_PROGRESS):
            if self.frame_counter >= 5:
                self.frame_counter = 0
                self.progress_quantum = type(self.progress_quantum)(0.0)
                self.original_distance = dist

            offset = first.position.subtract(self.physics_obj.position)
            max_quantum = D(max_speed) * D(quantum)  # float * double: a double
            distance = offset.origin.length()

            if distance <= INTERPOLATION_NODE_REACHED:
                self.node_completed(True)

            if distance > max_quantum:
                offset.origin = offset.origin * (cast_float(distance, max_quantum) / distance)

            if self.keep_heading:
                offset.set_heading(type(distance)(0.0))

            frame = offset  # noqa: F841  (ACE assigns its parameter: the caller's frame is unchanged)
            return
        self.node_fail_counter += 1
        self.node_completed(False)


__all__ = ["InterpolationManager"]
