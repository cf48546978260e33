"""TargetManager's voyeur updates and MotionTableManager's pending-animation queue."""

import numpy as np
import pytest
from movers import MODE, Weenie, mover, position, world

from acconform.motion_enums import MotionCommand
from acconform.port.combat.target_info import TargetStatus
from acconform.port.managers.motion_table_manager import MotionTableManager

F = np.float32


@pytest.mark.anchor("TargetManager::HandleTargetting")
def test_a_voyeur_hears_of_its_target_only_after_the_target_moves_past_its_radius():
    timer, objects = world()
    watcher = mover(timer, objects)
    target = mover(timer, objects, id=0x80000001, at=(0.0, 5.0))
    watcher.set_target(0, target.id, F(0.5), 0.0)
    first = watcher.target_manager.target_info
    assert first.status == TargetStatus.OK and first.target_position.frame.origin.y == F(5.0)
    timer.set(1.0)
    target.position = position(0.0, 5.4)
    target.target_manager.handle_targetting()  # 0.4 < 0.5: nothing sent
    assert watcher.target_manager.target_info.target_position.frame.origin.y == F(5.0)
    timer.set(2.0)
    target.position = position(0.0, 5.6)
    target.target_manager.handle_targetting()
    info = watcher.target_manager.target_info
    assert info.target_position.frame.origin.y == F(5.6) and info.last_update_time == 2.0
    assert info.interpolated_heading == MODE.vec(0, 1, 0)


@pytest.mark.anchor("TargetManager::SetTarget")
def test_set_target_of_no_object_reports_a_timed_out_target():
    timer, objects = world()
    watcher = mover(timer, objects)
    seen = []
    watcher.handle_update_target = seen.append
    watcher.set_target(0, 0, F(0.5), 0.0)
    assert [i.status for i in seen] == [TargetStatus.TimedOut] and watcher.target_manager.target_info is None


class _Obj:
    def __init__(self):
        self.done = []
        self.weenie_obj = Weenie()

    def motion_done(self, motion, success):
        self.done.append((motion, success))


class _Sequence:
    def __init__(self):
        self.removed = []

    def remove_link_animations(self, n):
        self.removed.append(n)


def _manager():
    manager = MotionTableManager.create(0, MODE)
    manager.set_physics_object(_Obj())
    return manager


@pytest.mark.anchor("MotionTableManager::AnimationDone")
def test_animation_done_reports_each_motion_whose_animations_are_done():
    manager, seq = _manager(), _Sequence()
    manager.add_to_queue(MotionCommand.WalkForward, 2, seq)
    manager.add_to_queue(MotionCommand.Ready, 0, seq)
    manager.animation_done(True)
    assert manager.physics_obj.done == [] and manager.animation_counter == 1
    manager.animation_done(True)
    assert manager.physics_obj.done == [(MotionCommand.WalkForward, True), (MotionCommand.Ready, True)]
    assert manager.physics_obj.weenie_obj.motions_done == manager.physics_obj.done
    assert manager.pending_animations.count == 0 and manager.animation_counter == 0


@pytest.mark.anchor("MotionTableManager::remove_redundant_links")
def test_a_repeated_substate_truncates_the_links_queued_after_its_first():
    manager, seq = _manager(), _Sequence()
    manager.add_to_queue(MotionCommand.WalkForward, 2, seq)
    manager.add_to_queue(MotionCommand.WalkForward, 3, seq)
    assert seq.removed == [3]
    assert [n.num_anims for n in manager.pending_animations] == [2, 0]


@pytest.mark.anchor("MotionTableManager::PerformMovement")
def test_perform_movement_without_a_table_reports_no_animation_table():
    from acconform.motion_enums import MovementType, WeenieError
    from acconform.port.animation.movement_struct import MovementStruct

    manager = _manager()
    assert manager.perform_movement(MovementStruct.create(MovementType.StopCompletely), _Sequence()) == WeenieError.NoAnimationTable
