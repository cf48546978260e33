"""MoveToManager on hand-built moves: it turns before it walks, arrives within DistanceToObject,
gives up past FailDistance, counts frames without progress; and its pure heading arithmetic."""

import numpy as np
import pytest
from movers import MODE, Minterp, mover, position, world

from acconform.motion_enums import HoldKey, MotionCommand, MovementType, WeenieError
from acconform.port.animation.movement_parameters import MovementParameters
from acconform.port.managers.move_to_manager import MoveToManager

F = np.float32


def _move_north(heading=90.0, **params):
    """A mover at the origin facing `heading`, told to move to (0, 10)."""
    timer, objects = world()
    obj = mover(timer, objects, heading=heading, minterp=Minterp())
    manager = MoveToManager.create(obj, obj.weenie_obj, MODE)
    obj.move_to_manager = manager
    mvp = MovementParameters.create(MODE)
    for k, v in params.items():
        setattr(mvp, k, v)
    manager.move_to_position(position(0.0, 10.0), mvp)
    return timer, obj, manager


@pytest.mark.anchor("MoveToManager::MoveToPosition")
def test_move_to_position_queues_a_turn_to_face_the_target_before_the_walk():
    _, obj, manager = _move_north(heading=90.0)
    assert [n.type for n in manager.pending_actions] == [MovementType.TurnToHeading, MovementType.MoveToPosition]
    assert manager.pending_actions[0].heading == 0.0
    # facing east, north is a quarter turn to the left: the turn begins at once
    assert obj.minterp.done == [MotionCommand.TurnLeft]
    assert manager.current_command == MotionCommand.TurnLeft


@pytest.mark.anchor("MoveToManager::HandleTurnToHeading")
def test_a_turn_that_passes_the_heading_snaps_to_it_and_starts_the_walk():
    _, obj, manager = _move_north(heading=90.0)
    obj.set_heading(F(359.0), True)  # the turn left went a degree past north
    manager.use_time()
    assert abs(float(obj.get_heading()) % 360.0) < 1e-3
    assert obj.minterp.stopped == [MotionCommand.TurnLeft]
    assert obj.minterp.done == [MotionCommand.TurnLeft, MotionCommand.WalkForward]
    assert [n.type for n in manager.pending_actions] == [MovementType.MoveToPosition]
    assert manager.movement_params.hold_key_to_apply == HoldKey.Run  # 10 - 0.6 is past the walk/run threshold 1


@pytest.mark.anchor("MoveToManager::HandleMoveToPosition")
def test_the_walk_stops_within_distance_to_object_and_tells_the_weenie():
    _, obj, manager = _move_north(heading=0.0)
    assert obj.minterp.done == [MotionCommand.WalkForward]  # already facing: no turn node
    obj.position = position(0.0, 9.5)  # 0.5 from the target: within the default 0.6
    manager.use_time()
    assert obj.minterp.stopped[0] == MotionCommand.WalkForward
    assert obj.weenie_obj.moves_completed == [WeenieError.None_]
    assert manager.pending_actions == [] and not manager.is_moving_to()


@pytest.mark.anchor("MoveToManager::HandleMoveToPosition")
def test_the_walk_goes_on_outside_distance_to_object():
    _, obj, manager = _move_north(heading=0.0)
    obj.position = position(0.0, 9.0)  # 1.0 from the target
    manager.use_time()
    assert obj.weenie_obj.moves_completed == [] and manager.is_moving_to()


@pytest.mark.anchor("MoveToManager::HandleMoveToPosition")
def test_a_mover_beyond_fail_distance_from_its_start_is_cancelled_as_charged_too_far():
    _, obj, manager = _move_north(heading=0.0, fail_distance=F(3.0))
    obj.position = position(3.0, 3.0)  # 4.24 from the start, 7.6 from the target
    manager.use_time()
    assert obj.weenie_obj.moves_completed == [WeenieError.YouChargedTooFar]
    assert manager.movement_type == MovementType.Invalid and manager.pending_actions == []


@pytest.mark.anchor("MoveToManager::CheckProgressMade")
def test_a_second_without_progress_counts_a_failed_frame_and_skips_the_arrival_checks():
    timer, obj, manager = _move_north(heading=0.0, fail_distance=F(3.0))
    timer.set(2.0)
    obj.position = position(3.0, 0.0)  # no closer to the target, and past FailDistance
    manager.use_time()
    assert manager.fail_progress_count == 1
    assert obj.weenie_obj.moves_completed == []  # FailDistance is checked only on a frame with progress


@pytest.mark.anchor("MoveToManager::MoveToPosition")
def test_move_to_position_reads_the_old_params_use_final_heading_as_ace_does():
    _, obj, manager = _move_north(heading=0.0, use_final_heading=True, desired_heading=F(90.0))
    # the manager's previous MovementParams (the defaults) had no UseFinalHeading: no final turn
    assert [n.type for n in manager.pending_actions] == [MovementType.MoveToPosition]
    assert manager.movement_params.use_final_heading


@pytest.mark.anchor("MoveToManager::UseTime")
def test_use_time_does_nothing_out_of_contact():
    _, obj, manager = _move_north(heading=0.0)
    obj.transient_state = 0
    obj.position = position(0.0, 9.5)
    manager.use_time()
    assert obj.weenie_obj.moves_completed == []


@pytest.mark.anchor("MoveToManager::MoveToObject")
def test_move_to_object_waits_for_the_targets_update_then_moves_and_sticks():
    timer, objects = world()
    obj = mover(timer, objects, heading=0.0, minterp=Minterp())
    target = mover(timer, objects, id=0x80000001, at=(0.0, 10.0))
    manager = MoveToManager.create(obj, obj.weenie_obj, MODE)
    obj.move_to_manager = manager
    mvp = MovementParameters.create(MODE)
    mvp.sticky = True
    manager.move_to_object(target.id, target.id, F(0.5), F(1.0), mvp)
    # set_target -> the target's add_voyeur -> its first update -> MoveToObject_Internal
    assert manager.initialized
    # already facing north: the turn node ends at once and the walk begins
    assert [n.type for n in manager.pending_actions] == [MovementType.MoveToPosition]
    assert obj.minterp.done == [MotionCommand.WalkForward]
    obj.position = position(0.0, 9.0)  # 1.0 to the target's centre, 0.5 to its cylinder
    manager.use_time()
    assert obj.weenie_obj.moves_completed == [WeenieError.None_]
    sticky = obj.position_manager.sticky_manager
    assert sticky.target_id == target.id and sticky.target_radius == F(0.5) and sticky.initialized


@pytest.mark.anchor("MoveToManager::heading_diff")
@pytest.mark.parametrize("h1, h2, motion, expected", [
    (10.0, 350.0, MotionCommand.TurnRight, 20.0),
    (10.0, 350.0, MotionCommand.TurnLeft, 340.0),
    (350.0, 10.0, MotionCommand.TurnRight, 340.0),
    (90.0, 90.0, MotionCommand.TurnLeft, 0.0),
])
def test_heading_diff_measures_the_turn_in_its_direction(h1, h2, motion, expected):
    got = MoveToManager.heading_diff(F(h1), F(h2), motion)
    assert type(got) is np.float32 and got == F(expected)


@pytest.mark.anchor("MoveToManager::heading_greater")
@pytest.mark.parametrize("h1, h2, motion, expected", [
    (20.0, 10.0, MotionCommand.TurnRight, True),
    (5.0, 10.0, MotionCommand.TurnRight, False),
    (5.0, 355.0, MotionCommand.TurnRight, True),  # across north
    (355.0, 5.0, MotionCommand.TurnLeft, True),
    (20.0, 10.0, MotionCommand.TurnLeft, False),
])
def test_heading_greater_says_whether_the_turn_has_passed_its_heading(h1, h2, motion, expected):
    assert MoveToManager.heading_greater(F(h1), F(h2), motion) is expected
