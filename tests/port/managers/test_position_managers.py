"""StickyManager, InterpolationManager, ConstraintManager and PositionManager.AdjustOffset on small
hand-built situations, ACE's quirks included."""

import numpy as np
import pytest
from movers import MODE, Minterp, mover, position, world

from acconform.numerics import f32_bits
from acconform.port import constants as k
from acconform.port.errors import ArgumentOutOfRangeException
from acconform.port.frame import AFrame
from acconform.port.animation.interpolation_node import InterpolationNode, InterpolationNodeType
from acconform.port.managers.constraint_manager import ConstraintManager
from acconform.port.managers.interpolation_manager import InterpolationManager
from acconform.port.managers.position_manager import PositionManager

F = np.float32


def _stuck(at=(0.0, 0.0), heading=0.0, target_at=(0.0, 5.0), minterp=None):
    """A mover (radius 0.5) stuck to a target (radius 0.5) through the real TargetManagers."""
    timer, objects = world()
    obj = mover(timer, objects, at=at, heading=heading, radius=F(0.5), minterp=minterp)
    target = mover(timer, objects, id=0x80000001, at=target_at, radius=F(0.5))
    obj.get_position_manager().stick_to(target.id, F(0.5), F(1.0))
    return timer, obj, target


@pytest.mark.parametrize("name, bits", [
    ("INTERPOLATION_NODE_REACHED", 0x3D4CCCCD), ("INTERPOLATION_MIN_PROGRESS", 0x3E99999A),
    ("INTERPOLATION_LARGE_DISTANCE", 0x497423F0), ("STICKY_RADIUS", 0x3E99999A),
    ("MOVE_TO_MIN_VELOCITY", 0x3DCCCCCD), ("CONSTRAINT_FULL_FRACTION", 0x3F666666), ("FLOAT_MAX_VALUE", 0x7F7FFFFF),
])
def test_the_managers_constants_are_pinned_by_their_float32_bits(name, bits):
    assert f32_bits(getattr(k, name)) == bits


@pytest.mark.anchor("StickyManager::HandleUpdateTarget")
def test_stick_to_is_initialized_by_the_targets_first_update():
    _, obj, target = _stuck()
    sticky = obj.position_manager.sticky_manager
    assert sticky.target_id == target.id and sticky.initialized
    assert target.target_manager.voyeur_table.keys() == [obj.id]


@pytest.mark.anchor("StickyManager::adjust_offset")
def test_sticky_offset_steps_toward_the_target_at_fifteen_without_a_motion_interpreter():
    _, obj, _ = _stuck()
    frame = AFrame.identity(MODE)
    obj.position_manager.sticky_manager.adjust_offset(frame, 0.1)
    assert frame.origin.x == 0 and frame.origin.z == 0
    assert f32_bits(frame.origin.y) == f32_bits(F(15.0) * F(0.1))
    assert float(frame.get_heading()) % 360.0 == pytest.approx(0.0, abs=1e-4)


@pytest.mark.anchor("StickyManager::adjust_offset")
def test_sticky_speed_is_five_times_the_max_speed():
    _, obj, _ = _stuck(minterp=Minterp(max_speed=F(2.0)))
    frame = AFrame.identity(MODE)
    obj.position_manager.sticky_manager.adjust_offset(frame, 0.1)
    assert f32_bits(frame.origin.y) == f32_bits(F(10.0) * F(0.1))


@pytest.mark.anchor("StickyManager::adjust_offset")
def test_sticky_offset_stops_at_the_sticky_radius_from_the_targets_cylinder():
    _, obj, _ = _stuck(at=(0.0, 3.4))
    frame = AFrame.identity(MODE)
    obj.position_manager.sticky_manager.adjust_offset(frame, 0.1)
    gap = (F(5.0) - F(3.4)) - (F(0.5) + F(0.5)) - k.STICKY_RADIUS  # centre 1.6 away, less both radii and 0.3
    assert frame.origin.y == pytest.approx(float(gap), abs=1e-6) and frame.origin.y > 0
    # one step later the mover keeps its place (the gap is the sticky radius)
    obj.position = position(0.0, float(F(3.4) + frame.origin.y))
    frame = AFrame.identity(MODE)
    obj.position_manager.sticky_manager.adjust_offset(frame, 0.1)
    assert abs(frame.origin.y) < 1e-6


@pytest.mark.anchor("StickyManager::adjust_offset")
def test_sticky_offset_backs_a_mover_too_close_away_and_turns_it_to_face_the_target():
    _, obj, _ = _stuck(at=(0.0, 3.8), heading=90.0)  # facing east, the target 1.2 north
    frame = AFrame.identity(MODE)
    obj.position_manager.sticky_manager.adjust_offset(frame, 0.1)
    # the target lies to the mover's left (-x local); the step is negative: away from it
    assert frame.origin.x > 0 and frame.origin.x == pytest.approx(0.1, abs=1e-6)
    assert float(frame.get_heading()) == pytest.approx(270.0, abs=1e-3)


@pytest.mark.anchor("StickyManager::UseTime")
def test_sticky_target_is_dropped_a_second_after_stick_to():
    timer, obj, target = _stuck()
    timer.set(1.0)
    obj.position_manager.use_time()
    assert obj.position_manager.sticky_manager.target_id != 0
    timer.set(1.5)
    obj.position_manager.use_time()
    assert obj.position_manager.sticky_manager.target_id == 0
    assert obj.target_manager.target_info is None and target.target_manager.voyeur_table.keys() == []


def _interpolating(at=(0.0, 0.0)):
    timer, objects = world()
    obj = mover(timer, objects, at=at)
    obj.position_manager = PositionManager.create(obj)
    return obj


@pytest.mark.anchor("InterpolationManager::InterpolateTo")
def test_interpolate_to_keeps_at_most_twenty_nodes():
    obj = _interpolating()
    for i in range(1, 26):
        obj.position_manager.interpolate_to(position(float(i), 0.0), False)
    queue = obj.position_manager.interpolation_manager.position_queue
    assert queue.count == 20 and queue.first.value.position.frame.origin.x == 6.0


@pytest.mark.anchor("InterpolationManager::InterpolateTo")
def test_a_node_within_5cm_of_the_last_replaces_it():
    obj = _interpolating()
    obj.position_manager.interpolate_to(position(1.0, 0.0), False)
    obj.position_manager.interpolate_to(position(1.01, 0.0), False)
    queue = obj.position_manager.interpolation_manager.position_queue
    assert queue.count == 1 and queue.last.value.position.frame.origin.x == F(1.01)


@pytest.mark.anchor("InterpolationManager::UseTime")
def test_a_node_beyond_the_blip_distance_jumps_the_mover_there_at_the_next_use_time():
    obj = _interpolating()
    far = position(150.0, 0.0)  # outdoors the autonomy blip distance is 100
    obj.position_manager.interpolate_to(far, False)
    manager = obj.position_manager.interpolation_manager
    assert manager.node_fail_counter == 4
    obj.position_manager.use_time()
    assert obj.set_positions == [far] and not manager.is_interpolating() and manager.node_fail_counter == 0


@pytest.mark.anchor("InterpolationManager::adjust_offset")
def test_interpolation_adjust_offset_leaves_the_callers_frame_and_rewrites_the_node_as_ace_does():
    obj = _interpolating()
    obj.position_manager.interpolate_to(position(10.0, 0.0), False)
    node = obj.position_manager.interpolation_manager.position_queue.first.value
    frame = AFrame.identity(MODE)
    obj.position_manager.adjust_offset(frame, 0.1)
    assert frame.origin == MODE.vec(0, 0, 0)  # ACE's `frame = offset` assigns its parameter only
    # the node's Position was Subtract'ed in place and scaled to 7.5 * 0.1
    assert f32_bits(node.position.frame.origin.x) == f32_bits(F(10.0) * (F(0.75) / F(10.0)))


@pytest.mark.anchor("InterpolationManager::adjust_offset")
def test_a_node_without_progress_fails_after_five_frames_and_use_time_then_reads_the_empty_queue():
    obj = _interpolating()
    obj.position_manager.interpolate_to(position(10.0, 0.0), False)
    manager = obj.position_manager.interpolation_manager
    for _ in range(9):
        obj.position_manager.adjust_offset(AFrame.identity(MODE), 0.1)
    assert manager.node_fail_counter == 0 and manager.is_interpolating()
    obj.position_manager.adjust_offset(AFrame.identity(MODE), 0.1)  # frame 5 of the second window: no progress
    assert manager.node_fail_counter == 1 and not manager.is_interpolating()
    assert manager.blip_to_position is not None
    with pytest.raises(AttributeError):  # PositionQueue.Last.Value of an empty list: NullReferenceException
        manager.use_time()


@pytest.mark.anchor("InterpolationManager::UseTime")
def test_use_time_over_a_failed_queue_ending_in_a_jump_node_throws_out_of_range_as_ace_does():
    obj = _interpolating()
    manager = InterpolationManager.create(obj)
    manager.position_queue.add_last(InterpolationNode.create(InterpolationNodeType.PositionType, position(1.0, 0.0)))
    manager.position_queue.add_last(InterpolationNode.create(InterpolationNodeType.JumpType, position(2.0, 0.0)))
    manager.node_fail_counter = 4
    with pytest.raises(ArgumentOutOfRangeException):
        manager.use_time()


@pytest.mark.anchor("InterpolationManager::NodeCompleted")
def test_completing_the_last_node_stops_interpolating():
    obj = _interpolating()
    obj.position_manager.interpolate_to(position(0.04, 0.0), False)  # within 5 cm: no node, heading kept
    assert not obj.position_manager.is_interpolating()
    obj.position_manager.interpolate_to(position(1.0, 0.0), False)
    obj.position = position(1.0, 0.0)
    obj.position_manager.adjust_offset(AFrame.identity(MODE), 0.1)  # within 5 cm of the node
    assert not obj.position_manager.is_interpolating()
    assert obj.position_manager.interpolation_manager.original_distance == k.INTERPOLATION_LARGE_DISTANCE


@pytest.mark.anchor("ConstraintManager::adjust_offset")
def test_a_constraint_shortens_the_offset_between_its_start_and_max_distance_and_stops_it_past_max():
    timer, objects = world()
    obj = mover(timer, objects)
    manager = ConstraintManager.create(obj)
    manager.constrain_to(position(0.0, 5.0), F(0.0), F(10.0))  # 5 from the pin: half way
    frame = AFrame(MODE.vec(0, 2, 0), MODE.quat(0, 0, 0, 1))
    manager.adjust_offset(frame, 0.1)
    assert frame.origin == MODE.vec(0, 1, 0)
    assert manager.constraint_pos_offset == F(1.0)  # from now on the offset's length (ACE)
    manager.constraint_pos_offset = F(10.0)
    assert manager.is_fully_constrained()
    manager.adjust_offset(frame, 0.1)
    assert frame.origin == MODE.vec(0, 0, 0)


@pytest.mark.anchor("PositionManager::adjust_offset")
def test_position_manager_runs_interpolation_then_sticky_then_the_constraint():
    _, obj, _ = _stuck()
    pm = obj.position_manager
    pm.interpolate_to(position(0.0, -20.0), False)  # changes no caller frame (ACE)
    pm.constrain_to(position(0.0, 5.0), F(0.0), F(10.0))  # half way: halves what sticky leaves
    frame = AFrame.identity(MODE)
    pm.adjust_offset(frame, 0.1)
    step = F(15.0) * F(0.1)
    assert f32_bits(frame.origin.y) == f32_bits(step * ((F(10.0) - F(5.0)) / (F(10.0) - F(0.0))))
    assert pm.get_sticky_object_id() == 0x80000001 and pm.is_interpolating()
