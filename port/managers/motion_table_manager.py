"""MotionTableManager: MotionTableManager(mtableID), Create, AnimationDone, CheckForCompletedMotions, GetMotionTableID, Init, HandleEnterWorld, HandleExitWorld, PerformMovement, SetMotionTableID, SetPhysicsObject, UseTime, add_to_queue, initialize_state, remove_redundant_links, remove_redundant_links_inner, trancuate_animation_list.

ACE's Managers/MotionTableManager.cs: the object's motion table, its MotionState, and the queue of
motions waiting for their animations (PendingAnimations: AnimNodes, each a motion and how many
animations of the Sequence it still waits for). The MotionInterp's interpreted commands arrive in
PerformMovement; AnimationDone (the Sequence's AnimDone hook) counts finished animations and, as
each motion's count is met, tells the PhysicsObj (MotionDone) and its weenie. remove_redundant_links
drops the link animations of a motion that an equal later one makes unnecessary.

`AnimationCounter` and the NumAnims are C# uints (wrapped here). The table comes from the run's
portal DAT (`portal_dat`, ACE's DatManager.PortalDat); `mode` gives the MotionState's scalars.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from acconform.motion_enums import CommandMask, MotionCommand, MovementType, WeenieError
from acconform.numerics import wrap_u32

from ..anchors import anchor
from ..animation.anim_node import AnimNode
from ..animation.motion_state import MotionState
from ..linked_list import LinkedList

# remove_redundant_links_inner: `first ? 0x70000000 : 0xB0000000`, the masks of the kinds of
# command a link stops at (SubState | Modifier | Action; Style | Modifier | Action)
STOP_AT_FIRST = 0x70000000
STOP_AT_SUBSTATE = 0xB0000000


@dataclass(slots=True, eq=False)
class MotionTableManager:
    physics_obj: object = None
    table: object = None  # MotionTable
    state: MotionState | None = None
    animation_counter: int = 0  # uint
    pending_animations: LinkedList | None = None  # of AnimNode
    mode: object = None  # the run's mode (the port's)
    portal_dat: object = None  # the run's DatManager.PortalDat (the port's: ACE's static)

    @staticmethod
    @anchor("MotionTableManager::Create", "MotionTableManager.cs:Create")
    def create(mtable_id: int, mode, portal_dat=None) -> "MotionTableManager":
        """``new MotionTableManager(mtableID)``: Init, then SetMotionTableID unless the id is 0."""
        manager = MotionTableManager(mode=mode, portal_dat=portal_dat)
        manager.init()

        if mtable_id != 0:
            manager.set_motion_table_id(mtable_id)
        return manager

    @anchor("MotionTableManager::AnimationDone", "MotionTableManager.cs:AnimationDone")
    def animation_done(self, success: bool) -> None:
        node = self.pending_animations.first
        if node is not None:
            self.animation_counter = wrap_u32(self.animation_counter + 1)
            while True:
                entry = node.value

                if entry.num_anims > self.animation_counter:
                    break

                if entry.motion & CommandMask.Action != 0:
                    self.state.remove_action_head()

                motion_id = entry.motion
                self.physics_obj.motion_done(motion_id, success)
                self.animation_counter = wrap_u32(self.animation_counter - entry.num_anims)

                if self.pending_animations.first is not None:
                    self.pending_animations.remove_first()

                if self.physics_obj.weenie_obj is not None:
                    self.physics_obj.weenie_obj.on_motion_done(motion_id, success)

                node = self.pending_animations.first
                if node is None:
                    break

            if self.animation_counter != 0 and node is None:
                self.animation_counter = 0

    @anchor("MotionTableManager::CheckForCompletedMotions", "MotionTableManager.cs:CheckForCompletedMotions")
    def check_for_completed_motions(self) -> None:
        while self.pending_animations.first is not None:
            pending_animation = self.pending_animations.first

            if pending_animation.value.num_anims != 0:
                return

            motion_id = pending_animation.value.motion

            if motion_id & CommandMask.Action != 0:
                self.state.remove_action_head()

            self.physics_obj.motion_done(motion_id, True)

            if self.pending_animations.first is not None:
                self.pending_animations.remove_node(pending_animation)

            if self.physics_obj.weenie_obj is not None:
                self.physics_obj.weenie_obj.on_motion_done(motion_id, True)

    @anchor("MotionTableManager::GetMotionTableID", "MotionTableManager.cs:GetMotionTableID")
    def get_motion_table_id(self, mtable_id: int) -> int:
        return 0 if self.table is None else self.table.id

    @anchor("MotionTableManager::Init", "MotionTableManager.cs:Init")
    def init(self) -> None:
        self.state = MotionState.create(self.mode)
        self.pending_animations = LinkedList()

    @anchor("MotionTableManager::HandleEnterWorld", "MotionTableManager.cs:HandleEnterWorld")
    def handle_enter_world(self, sequence) -> None:
        sequence.remove_all_link_animations()
        while self.pending_animations.count > 0:
            self.animation_done(False)

    @anchor("MotionTableManager::HandleExitWorld", "MotionTableManager.cs:HandleExitWorld")
    def handle_exit_world(self) -> None:
        while self.pending_animations.count > 0:
            self.animation_done(False)

    @anchor("MotionTableManager::PerformMovement", "MotionTableManager.cs:PerformMovement")
    def perform_movement(self, mvs, seq) -> WeenieError:
        if self.table is None:
            return WeenieError.NoAnimationTable

        counter = 0
        if mvs.type == MovementType.InterpretedCommand:
            ok, counter = self.table.do_object_motion(mvs.motion, self.state, seq, mvs.params.speed, counter)
            if not ok:
                return WeenieError.NoMtableData

            self.add_to_queue(mvs.motion, counter, seq)
            return WeenieError.None_

        elif mvs.type == MovementType.StopInterpretedCommand:
            ok, counter = self.table.stop_object_motion(mvs.motion, mvs.params.speed, self.state, seq, counter)
            if not ok:
                return WeenieError.NoMtableData

            self.add_to_queue(MotionCommand.Ready, counter, seq)
            return WeenieError.None_

        elif mvs.type == MovementType.StopCompletely:
            _, counter = self.table.stop_object_completely(self.state, seq, counter)
            self.add_to_queue(MotionCommand.Ready, counter, seq)
            return WeenieError.None_

        else:
            return WeenieError.None_  # ?? (ACE)

    @anchor("MotionTableManager::SetMotionTableID", "MotionTableManager.cs:SetMotionTableID")
    def set_motion_table_id(self, mtable_id: int) -> bool:
        from ..animation.motion_table import MotionTable  # late: the table's module is below the managers

        self.table = MotionTable.get(mtable_id, self.portal_dat)
        return self.table is not None

    @anchor("MotionTableManager::SetPhysicsObject", "MotionTableManager.cs:SetPhysicsObject")
    def set_physics_object(self, obj) -> None:
        self.physics_obj = obj

    @anchor("MotionTableManager::UseTime", "MotionTableManager.cs:UseTime")
    def use_time(self) -> None:
        self.check_for_completed_motions()

    @anchor("MotionTableManager::add_to_queue", "MotionTableManager.cs:add_to_queue")
    def add_to_queue(self, motion: int, num_anims: int, sequence) -> None:
        self.pending_animations.add_last(AnimNode.create(int(motion), num_anims))
        self.remove_redundant_links(sequence)

    @anchor("MotionTableManager::initialize_state", "MotionTableManager.cs:initialize_state")
    def initialize_state(self, sequence) -> None:
        num_anims = 0

        if self.table is not None:
            _, num_anims = self.table.set_default_state(self.state, sequence, num_anims)

        self.add_to_queue(MotionCommand.Ready, num_anims, sequence)

    @anchor("MotionTableManager::remove_redundant_links", "MotionTableManager.cs:remove_redundant_links")
    def remove_redundant_links(self, sequence) -> None:
        node = self.pending_animations.last

        while node is not None:
            entry = node.value

            if entry.num_anims != 0:
                if entry.motion & CommandMask.SubState == 0 or entry.motion & CommandMask.Modifier != 0:
                    if entry.motion & CommandMask.Style == 0:
                        return

                    if self.remove_redundant_links_inner(node, sequence, True):
                        return
                else:
                    if self.remove_redundant_links_inner(node, sequence, False):
                        return
            node = node.previous

    @anchor("MotionTableManager::remove_redundant_links_inner", "MotionTableManager.cs:remove_redundant_links_inner")
    def remove_redundant_links_inner(self, node, sequence, first: bool) -> bool:
        entry = node.value
        prev = node.previous

        motion = STOP_AT_FIRST if first else STOP_AT_SUBSTATE

        while prev is not None:
            prev_entry = prev.value

            if entry.motion == prev_entry.motion and (first or prev_entry.num_anims != 0):
                self.trancuate_animation_list(prev, sequence)
                return True

            if prev_entry.num_anims != 0 and (prev_entry.motion & motion) != 0:
                return True

            prev = prev.previous

        return False

    @anchor("MotionTableManager::trancuate_animation_list", "MotionTableManager.cs:trancuate_animation_list")
    def trancuate_animation_list(self, node, sequence) -> None:
        if node is None:
            return

        total_anims = 0
        entry = self.pending_animations.last

        while entry is not node:
            if entry is None:
                return

            total_anims = wrap_u32(total_anims + entry.value.num_anims)
            entry.value.num_anims = 0
            entry = entry.previous
        sequence.remove_link_animations(total_anims)


__all__ = ["MotionTableManager"]
