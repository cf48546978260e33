"""MovementManager: MovementManager(obj, wobj), Create, CancelMoveTo, EnterDefaultState, HandleEnterWorld, HandleExitWorld, HandleUpdateTarget, HitGround, InqInterpretedMotionState, InqRawMotionState, IsMovingTo, LeaveGround, MakeMoveToManager, MotionDone, PerformMovement, ReportExhaustion, SetWeenieObject, UseTime, get_minterp, motions_pending, move_to_interpreted_state, unpack_movement.

ACE's Managers/MovementManager.cs: the PhysicsObj's door to the motion layer. Commands (raw or
interpreted, their stops, StopCompletely) go to the MotionInterp, moves and turns to an object or a
position to the MoveToManager; each is made on first use (the MotionInterp entering its default
state when the manager has an object). `mode` is the run's mode, which the MotionInterp and the
MoveToManager take their scalar types from (the port's: ACE's types need none).
"""

from __future__ import annotations

from dataclasses import dataclass

from acconform.motion_enums import MovementType, WeenieError

from ..anchors import anchor
from ..animation.motion_interp import MotionInterp
from .move_to_manager import MoveToManager

_TO_MOTION_INTERP = (MovementType.RawCommand, MovementType.InterpretedCommand, MovementType.StopRawCommand,
                     MovementType.StopInterpretedCommand, MovementType.StopCompletely)
_TO_MOVE_TO_MANAGER = (MovementType.MoveToObject, MovementType.MoveToPosition, MovementType.TurnToObject,
                       MovementType.TurnToHeading)


@dataclass(slots=True, eq=False)
class MovementManager:
    motion_interpreter: MotionInterp | None = None
    move_to_manager: MoveToManager | None = None
    physics_obj: object = None
    weenie_obj: object = None
    mode: object = None  # the run's mode (the port's)

    @staticmethod
    @anchor("MovementManager::Create", "MovementManager.cs:Create")
    def create(obj, wobj, mode) -> "MovementManager":
        """``new MovementManager(obj, wobj)``: a MotionInterp and a MoveToManager for the object."""
        manager = MovementManager(physics_obj=obj, weenie_obj=wobj, mode=mode)

        manager.motion_interpreter = MotionInterp.create(obj, wobj, mode)
        manager.move_to_manager = MoveToManager.create(obj, wobj, mode)
        return manager

    @anchor("MovementManager::CancelMoveTo", "MovementManager.cs:CancelMoveTo")
    def cancel_move_to(self, error: WeenieError) -> None:
        if self.move_to_manager is not None:
            self.move_to_manager.cancel_move_to(error)

    @anchor("MovementManager::EnterDefaultState", "MovementManager.cs:EnterDefaultState")
    def enter_default_state(self) -> None:
        if self.physics_obj is None:
            return

        if self.motion_interpreter is None:
            self.motion_interpreter = MotionInterp.create(self.physics_obj, self.weenie_obj, self.mode)

        self.motion_interpreter.enter_default_state()

    @anchor("MovementManager::HandleEnterWorld", "MovementManager.cs:HandleEnterWorld")
    def handle_enter_world(self) -> None:
        pass  # ACE comments out NoticeHandler.RecvNotice_PrevSpellSelection

    @anchor("MovementManager::HandleExitWorld", "MovementManager.cs:HandleExitWorld")
    def handle_exit_world(self) -> None:
        if self.motion_interpreter is not None:
            self.motion_interpreter.handle_exit_world()

    @anchor("MovementManager::HandleUpdateTarget", "MovementManager.cs:HandleUpdateTarget")
    def handle_update_target(self, target_info) -> None:
        if self.move_to_manager is not None:
            self.move_to_manager.handle_update_target(target_info)

    @anchor("MovementManager::HitGround", "MovementManager.cs:HitGround")
    def hit_ground(self) -> None:
        if self.motion_interpreter is not None:
            self.motion_interpreter.hit_ground()

        if self.move_to_manager is not None:
            self.move_to_manager.hit_ground()

    @anchor("MovementManager::InqInterpretedMotionState", "MovementManager.cs:InqInterpretedMotionState")
    def inq_interpreted_motion_state(self):
        if self.motion_interpreter is None:
            self.motion_interpreter = MotionInterp.create(self.physics_obj, self.weenie_obj, self.mode)
            if self.physics_obj is not None:
                self.motion_interpreter.enter_default_state()
        return self.motion_interpreter.interpreted_state

    @anchor("MovementManager::InqRawMotionState", "MovementManager.cs:InqRawMotionState")
    def inq_raw_motion_state(self):
        if self.motion_interpreter is None:
            self.motion_interpreter = MotionInterp.create(self.physics_obj, self.weenie_obj, self.mode)
            if self.physics_obj is not None:
                self.motion_interpreter.enter_default_state()
        return self.motion_interpreter.raw_state

    @anchor("MovementManager::IsMovingTo", "MovementManager.cs:IsMovingTo")
    def is_moving_to(self) -> bool:
        if self.move_to_manager is None:
            return False

        return self.move_to_manager.is_moving_to()

    @anchor("MovementManager::LeaveGround", "MovementManager.cs:LeaveGround")
    def leave_ground(self) -> None:
        if self.motion_interpreter is not None:
            self.motion_interpreter.leave_ground()

    @anchor("MovementManager::MakeMoveToManager", "MovementManager.cs:MakeMoveToManager")
    def make_move_to_manager(self) -> None:
        if self.move_to_manager is None:
            self.move_to_manager = MoveToManager.create(self.physics_obj, self.weenie_obj, self.mode)

    @anchor("MovementManager::MotionDone", "MovementManager.cs:MotionDone")
    def motion_done(self, motion: int, success: bool) -> None:
        if self.motion_interpreter is not None:
            self.motion_interpreter.motion_done(success)

    @anchor("MovementManager::PerformMovement", "MovementManager.cs:PerformMovement")
    def perform_movement(self, mvs) -> WeenieError:
        self.physics_obj.set_active(True)

        if mvs.type in _TO_MOTION_INTERP:
            if self.motion_interpreter is None:
                self.motion_interpreter = MotionInterp.create(self.physics_obj, self.weenie_obj, self.mode)
                if self.physics_obj is not None:
                    self.motion_interpreter.enter_default_state()
            return self.motion_interpreter.perform_movement(mvs)

        elif mvs.type in _TO_MOVE_TO_MANAGER:
            if self.move_to_manager is None:
                self.move_to_manager = MoveToManager.create(self.physics_obj, self.weenie_obj, self.mode)

            return self.move_to_manager.perform_movement(mvs)

        else:
            return WeenieError.GeneralMovementFailure

    @anchor("MovementManager::ReportExhaustion", "MovementManager.cs:ReportExhaustion")
    def report_exhaustion(self) -> None:
        if self.motion_interpreter is not None:
            self.motion_interpreter.report_exhaustion()

    @anchor("MovementManager::SetWeenieObject", "MovementManager.cs:SetWeenieObject")
    def set_weenie_object(self, wobj) -> None:
        self.weenie_obj = wobj
        if self.motion_interpreter is not None:
            self.motion_interpreter.set_weenie_object(wobj)
        if self.move_to_manager is not None:
            self.move_to_manager.set_weenie_object(wobj)

    @anchor("MovementManager::UseTime", "MovementManager.cs:UseTime")
    def use_time(self) -> None:
        if self.move_to_manager is not None:
            self.move_to_manager.use_time()

    @anchor("MovementManager::get_minterp", "MovementManager.cs:get_minterp")
    def get_minterp(self) -> MotionInterp:
        if self.motion_interpreter is None:
            self.motion_interpreter = MotionInterp.create(self.physics_obj, self.weenie_obj, self.mode)
            if self.physics_obj is not None:
                self.motion_interpreter.enter_default_state()
        return self.motion_interpreter

    @anchor("MovementManager::motions_pending", "MovementManager.cs:motions_pending")
    def motions_pending(self) -> bool:
        if self.motion_interpreter is None:
            return False

        return self.motion_interpreter.motions_pending()

    @anchor("MovementManager::move_to_interpreted_state", "MovementManager.cs:move_to_interpreted_state")
    def move_to_interpreted_state(self, state) -> None:
        if self.motion_interpreter is None:
            self.motion_interpreter = MotionInterp.create(self.physics_obj, self.weenie_obj, self.mode)
            if self.physics_obj is not None:
                self.motion_interpreter.enter_default_state()
        self.motion_interpreter.move_to_interpreted_state(state)

    @anchor("MovementManager::unpack_movement", "MovementManager.cs:unpack_movement")
    def unpack_movement(self, addr, size: int) -> None:
        pass  # empty (ACE)


__all__ = ["MovementManager"]
