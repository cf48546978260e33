"""Sequence: Sequence(), Sequence(int), Sequence(bool), is_idle_anim, is_first_cyclic, Clear, CombinePhysics, GetCurrAnimFrame, HasAnims, Init, SetObject, SetOmega, SetPlacementFrame, SetVelocity, Update, advance_to_next_animation, append_animation, apply_physics, apricot, clear_animations, clear_physics, execute_hooks, get_curr_frame_number, multiply_cyclic_animation_framerate, remove_all_link_animations, remove_cyclic_anims, remove_link_animations, subtract_physics, update_internal -- an object's animation queue, its placement frame and its root motion.

ACE's Physics/Animation/Sequence.cs. AnimList is a .NET LinkedList of AnimSequenceNodes
(port/linked_list.py); CurrAnim and FirstCyclic are nodes of it (None for null). MotionTable
appends a motion's animations (append_animation: every append makes the new last node the first
cyclic one) and the Sequence plays them: Update advances CurrAnim's frame number by framerate x
time, and every whole frame passed adds that frame's root motion (the Animation's PosFrames:
AFrame.Combine going forward, AFrame.Subtract going backward) and the sequence's Velocity and Omega
over one frame's time (apply_physics) to the tick's offset frame, and hands the frame's hooks to the
object (execute_hooks); at an animation's end it moves to the next node (to FirstCyclic after the
last: the cycle loops), and apricot drops the link animations played out. With no animations,
Update applies Velocity and Omega over the whole quantum.

C# `ref` parameters are returned (docs/port-conventions.md): Update and update_internal return the
offset frame, which AFrame.Combine replaces (the caller must take it); update_internal and
advance_to_next_animation return (node, frame number, frame), which Update stores in CurrAnim and
FrameNumber (ACE passes those fields by ref; nothing between reads them). update_internal's tail
call to itself stays a call, as in ACE. AnimSequenceNode's constructor reads the Animation record
through DBObj (ACE's static DatManager.PortalDat): a Sequence carries the run's PortalDat
(`portal_dat`) for it. Hooks: see port/dat/animation_hook.py (PhysicsObj.add_anim_hook queues them).
"""

from __future__ import annotations

from dataclasses import dataclass

from acconform.numerics import Vector3, cs_floor

from ..anchors import anchor
from ..constants import EPSILON
from ..dat.animation_hook import ANIM_DONE_HOOK, AnimationHookDir
from ..frame import AFrame
from ..linked_list import LinkedList
from .anim_sequence_node import AnimSequenceNode

# Sequence.PlayerIdleAnims (the static constructor's set; ThrownWeaponCombat repeats AtlatlCombat's)
PLAYER_IDLE_ANIMS = frozenset((
    0x03000001,  # NonCombat
    0x0300049E,  # AtlatlCombat
    0x0300045A,  # BowCombat
    0x03000474,  # CrossbowCombat
    0x03000CA8,  # DualWieldCombat
    0x03000448,  # HandCombat
    0x0300076C,  # Magic
    0x0300043D,  # SwordCombat
    0x03000426,  # SwordShieldCombat
    0x030008DF,  # ThrownShieldCombat
    0x0300049E,  # ThrownWeaponCombat
    0x03000B05,  # TwoHandedSwordCombat
))


@dataclass(slots=True, eq=False)
class Sequence:
    id: int = 0
    anim_list: LinkedList | None = None  # of AnimSequenceNode
    first_cyclic: object = None  # a node of anim_list
    velocity: Vector3 | None = None
    omega: Vector3 | None = None
    hook_obj: object = None  # the PhysicsObj
    frame_number: object = 0.0  # float
    curr_anim: object = None  # a node of anim_list
    placement_frame: object = None  # dat.animation_frame.AnimationFrame
    placement_frame_id: int = 0
    is_trivial: bool = False
    mode: object = None  # the run's mode (Vector3.Zero and 0f in its type)
    portal_dat: object = None  # the run's DatManager.PortalDat, for AnimSequenceNode's Animation records

    @staticmethod
    @anchor("CSequence::CSequence", "Sequence.cs:Sequence()", "the constructor: Init")
    def create(mode, portal_dat=None) -> "Sequence":
        sequence = Sequence(mode=mode, portal_dat=portal_dat)
        sequence.init()
        return sequence

    @staticmethod
    @anchor("CSequence::CSequence", "Sequence.cs:Sequence(int)")
    def create_with_id(id: int, mode, portal_dat=None) -> "Sequence":
        sequence = Sequence(id=id, mode=mode, portal_dat=portal_dat)
        sequence.init()
        return sequence

    @staticmethod
    @anchor("CSequence::CSequence", "Sequence.cs:Sequence(bool)")
    def create_with_bool(id: bool, mode, portal_dat=None) -> "Sequence":
        sequence = Sequence(id=1 if id else 0, mode=mode, portal_dat=portal_dat)
        sequence.init()
        return sequence

    @anchor(None, "Sequence.cs:is_idle_anim")
    def is_idle_anim(self) -> bool:
        return self.curr_anim is None or self.curr_anim.value.anim.id in PLAYER_IDLE_ANIMS

    @anchor(None, "Sequence.cs:is_first_cyclic")
    def is_first_cyclic(self) -> bool:
        return self.curr_anim is None or self.curr_anim.equals(self.first_cyclic)

    @anchor("CSequence::clear", "Sequence.cs:Clear")
    def clear(self) -> None:
        self.clear_animations()
        self.clear_physics()

        self.placement_frame = None
        self.placement_frame_id = 0

    @anchor("CSequence::combine_physics", "Sequence.cs:CombinePhysics")
    def combine_physics(self, velocity: Vector3, omega: Vector3) -> None:
        """Adds to the sequence velocity / omega (ACE)."""
        self.velocity = self.velocity + velocity
        self.omega = self.omega + omega

    @anchor("CSequence::get_curr_animframe", "Sequence.cs:GetCurrAnimFrame")
    def get_curr_anim_frame(self):
        if self.curr_anim is None:
            return self.placement_frame

        return self.curr_anim.value.get_part_frame(self.get_curr_frame_number())

    @anchor("CSequence::has_anims", "Sequence.cs:HasAnims")
    def has_anims(self) -> bool:
        return self.anim_list is not None and self.anim_list.count != 0

    @anchor("CSequence::init", "Sequence.cs:Init")
    def init(self) -> None:
        self.velocity = self.mode.vec(0, 0, 0)
        self.omega = self.mode.vec(0, 0, 0)
        self.frame_number = self.mode.scalar(0.0)

        self.anim_list = LinkedList()

    @anchor("CSequence::set_object", "Sequence.cs:SetObject")
    def set_object(self, obj) -> None:
        self.hook_obj = obj

    @anchor("CSequence::SetOmega", "Sequence.cs:SetOmega")
    def set_omega(self, omega: Vector3) -> None:
        self.omega = omega

    @anchor("CSequence::set_placement_frame", "Sequence.cs:SetPlacementFrame")
    def set_placement_frame(self, frame, frame_id: int) -> None:
        self.placement_frame = frame
        self.placement_frame_id = frame_id

    @anchor("CSequence::SetVelocity", "Sequence.cs:SetVelocity")
    def set_velocity(self, velocity: Vector3) -> None:
        self.velocity = velocity

    @anchor("CSequence::update", "Sequence.cs:Update")
    def update(self, quantum, offset_frame):
        """`quantum` is a float (PartArray.Update casts it). Returns the offset frame (C# `ref AFrame`):
        apply_physics changes it in place, AFrame.Combine replaces it."""
        if self.anim_list.first is not None:
            self.curr_anim, self.frame_number, offset_frame = self.update_internal(
                quantum, self.curr_anim, self.frame_number, offset_frame)
            self.apricot()
        elif offset_frame is not None:
            self.apply_physics(offset_frame, quantum, quantum)
        return offset_frame

    @anchor("CSequence::advance_to_next_animation", "Sequence.cs:advance_to_next_animation")
    def advance_to_next_animation(self, time_elapsed, anim_node, frame_num, frame):
        """Returns (anim_node, frame_num, frame): C#'s three `ref` parameters."""
        to_int32 = self.mode.runtime.to_int32
        curr_anim = anim_node.value

        if time_elapsed >= 0.0:
            if frame is not None and curr_anim.framerate < 0.0:
                if len(curr_anim.anim.pos_frames) > 0:
                    frame.subtract(curr_anim.get_pos_frame(to_int32(frame_num)))
                if abs(curr_anim.framerate) > EPSILON:
                    self.apply_physics(frame, 1.0 / curr_anim.framerate, time_elapsed)
            if anim_node.next is not None:
                anim_node = anim_node.next
            else:
                anim_node = self.first_cyclic

            curr_anim = anim_node.value

            frame_num = curr_anim.get_starting_frame()

            if frame is not None and curr_anim.framerate > 0.0:
                if len(curr_anim.anim.pos_frames) > 0:
                    frame = AFrame.combine(frame, curr_anim.get_pos_frame(to_int32(frame_num)))
                if abs(curr_anim.framerate) > EPSILON:
                    self.apply_physics(frame, 1.0 / curr_anim.framerate, time_elapsed)
        else:
            if frame is not None and curr_anim.framerate >= 0.0:
                if len(curr_anim.anim.pos_frames) > 0:
                    frame.subtract(curr_anim.get_pos_frame(to_int32(frame_num)))
                if abs(curr_anim.framerate) > EPSILON:
                    self.apply_physics(frame, 1.0 / curr_anim.framerate, time_elapsed)
            if anim_node.previous is not None:
                anim_node = anim_node.previous
            else:
                anim_node = anim_node.list.last

            curr_anim = anim_node.value

            frame_num = curr_anim.get_ending_frame()

            if frame is not None and curr_anim.framerate < 0.0:
                if len(curr_anim.anim.pos_frames) > 0:
                    frame = AFrame.combine(frame, curr_anim.get_pos_frame(to_int32(frame_num)))
                if abs(curr_anim.framerate) > EPSILON:
                    self.apply_physics(frame, 1.0 / curr_anim.framerate, time_elapsed)
        return anim_node, frame_num, frame

    @anchor("CSequence::append_animation", "Sequence.cs:append_animation")
    def append_animation(self, anim_data) -> None:
        """`anim_data` is a physics AnimData (port/animation/anim_data.py)."""
        node = AnimSequenceNode.from_anim_data(anim_data, self.portal_dat)
        if not node.has_anim():
            return

        self.anim_list.add_last(node)
        self.first_cyclic = self.anim_list.last

        if self.curr_anim is None:
            self.curr_anim = self.anim_list.first
            self.frame_number = self.curr_anim.value.get_starting_frame()

    @anchor("CSequence::apply_physics", "Sequence.cs:apply_physics")
    def apply_physics(self, frame: AFrame, quantum, sign) -> None:
        """Performs the translation and rotation on the frame (ACE). `sign >= 0.0` compares a float
        with a double literal: the same test in float."""
        if sign >= 0.0:
            quantum = abs(quantum)
        else:
            quantum = -abs(quantum)

        frame.origin = frame.origin + self.velocity * quantum
        frame.rotate_vec(self.omega * quantum)

    @anchor("CSequence::apricot", "Sequence.cs:apricot")
    def apricot(self) -> None:
        node = self.anim_list.first
        while not node.equals(self.curr_anim):
            if node.equals(self.first_cyclic):
                break

            self.anim_list.remove_node(node)
            node = self.anim_list.first

    @anchor("CSequence::clear_animations", "Sequence.cs:clear_animations")
    def clear_animations(self) -> None:
        self.anim_list.clear()
        self.first_cyclic = None
        self.frame_number = self.mode.scalar(0)
        self.curr_anim = None

    @anchor("CSequence::clear_physics", "Sequence.cs:clear_physics")
    def clear_physics(self) -> None:
        """Sets the sequence velocity/omega to zero (ACE)."""
        self.velocity = self.mode.vec(0, 0, 0)
        self.omega = self.mode.vec(0, 0, 0)

    @anchor("CSequence::execute_hooks", "Sequence.cs:execute_hooks")
    def execute_hooks(self, anim_frame, dir: int) -> None:
        if anim_frame is None or self.hook_obj is None:
            return
        for hook in anim_frame.hooks:
            if hook.direction == AnimationHookDir.Both or hook.direction == dir:
                self.hook_obj.add_anim_hook(hook)

    @anchor("CSequence::get_curr_frame_number", "Sequence.cs:get_curr_frame_number")
    def get_curr_frame_number(self) -> int:
        return self.mode.runtime.to_int32(cs_floor(self.frame_number))

    @anchor("CSequence::multiply_cyclic_animation_framerate", "Sequence.cs:multiply_cyclic_animation_framerate")
    def multiply_cyclic_animation_framerate(self, rate) -> None:
        curr_node = self.first_cyclic

        while curr_node is not None:
            curr_node.value.multiply_framerate(rate)

            curr_node = curr_node.next

    @anchor("CSequence::remove_all_link_animations", "Sequence.cs:remove_all_link_animations")
    def remove_all_link_animations(self) -> None:
        while self.first_cyclic is not None and self.first_cyclic.previous is not None:
            if self.curr_anim.equals(self.first_cyclic.previous):
                self.curr_anim = self.first_cyclic
                if self.curr_anim is not None:
                    self.frame_number = self.curr_anim.value.get_starting_frame()
            self.anim_list.remove_node(self.first_cyclic.previous)

    @anchor("CSequence::remove_cyclic_anims", "Sequence.cs:remove_cyclic_anims")
    def remove_cyclic_anims(self) -> None:
        node = self.first_cyclic
        while node is not None:
            if self.curr_anim.equals(node):
                self.curr_anim = node.previous
                if self.curr_anim is not None:
                    self.frame_number = self.curr_anim.value.get_ending_frame()
                else:
                    self.frame_number = self.mode.scalar(0.0)
            following = node.next  # handle linked list properly (ACE)
            self.anim_list.remove(node.value)
            node = following

        self.first_cyclic = self.anim_list.last

    @anchor("CSequence::remove_link_animations", "Sequence.cs:remove_link_animations")
    def remove_link_animations(self, amount: int) -> None:
        for _ in range(amount):
            if self.first_cyclic.previous is None:
                return

            if self.curr_anim.equals(self.first_cyclic.previous):
                self.curr_anim = self.first_cyclic

                if self.curr_anim is not None:
                    self.frame_number = self.curr_anim.value.get_starting_frame()
            self.anim_list.remove_node(self.first_cyclic.previous)

    @anchor("CSequence::subtract_physics", "Sequence.cs:subtract_physics")
    def subtract_physics(self, velocity: Vector3, omega: Vector3) -> None:
        """Subtracts from the sequence velocity / omega (ACE)."""
        self.velocity = self.velocity - velocity
        self.omega = self.omega - omega

    @anchor("CSequence::update_internal", "Sequence.cs:update_internal")
    def update_internal(self, time_elapsed, anim_node, frame_num, frame):
        """Returns (anim_node, frame_num, frame): C#'s three `ref` parameters. `time_elapsed` and
        `frame_num` are floats; Math.Floor of a float is a double, compared with the int frames."""
        curr_anim = anim_node.value

        framerate = curr_anim.framerate
        frametime = framerate * time_elapsed

        last_frame = self.mode.runtime.to_int32(cs_floor(frame_num))

        frame_num = frame_num + frametime
        frame_time_elapsed = self.mode.scalar(0.0)
        anim_done = False

        if frametime > 0.0:
            if curr_anim.get_high_frame() < cs_floor(frame_num):
                frame_offset = frame_num - self.mode.scalar(curr_anim.get_high_frame()) - 1.0
                if frame_offset < 0.0:
                    frame_offset = self.mode.scalar(0.0)

                if abs(framerate) > EPSILON:
                    frame_time_elapsed = frame_offset / framerate

                frame_num = self.mode.scalar(curr_anim.get_high_frame())
                anim_done = True
            while cs_floor(frame_num) > last_frame:
                if frame is not None:
                    if curr_anim.anim.pos_frames is not None:
                        frame = AFrame.combine(frame, curr_anim.get_pos_frame(last_frame))

                    if abs(framerate) > EPSILON:
                        self.apply_physics(frame, 1.0 / framerate, time_elapsed)

                self.execute_hooks(curr_anim.get_part_frame(last_frame), AnimationHookDir.Forward)
                last_frame += 1
        elif frametime < 0.0:
            if curr_anim.get_low_frame() > cs_floor(frame_num):
                frame_offset = frame_num - self.mode.scalar(curr_anim.get_low_frame())
                if frame_offset > 0.0:
                    frame_offset = self.mode.scalar(0.0)

                if abs(framerate) > EPSILON:
                    frame_time_elapsed = frame_offset / framerate

                frame_num = self.mode.scalar(curr_anim.get_low_frame())
                anim_done = True
            while cs_floor(frame_num) < last_frame:
                if frame is not None:
                    if curr_anim.anim.pos_frames is not None:
                        frame.subtract(curr_anim.get_pos_frame(last_frame))

                    if abs(framerate) > EPSILON:
                        self.apply_physics(frame, 1.0 / framerate, time_elapsed)

                self.execute_hooks(curr_anim.get_part_frame(last_frame), AnimationHookDir.Backward)
                last_frame -= 1
        else:
            if frame is not None and abs(time_elapsed) > EPSILON:
                self.apply_physics(frame, time_elapsed, time_elapsed)

        if not anim_done:
            return anim_node, frame_num, frame

        if self.hook_obj is not None:
            node = self.anim_list.first
            if not node.equals(self.first_cyclic):
                self.hook_obj.add_anim_hook(ANIM_DONE_HOOK)

        anim_node, frame_num, frame = self.advance_to_next_animation(time_elapsed, anim_node, frame_num, frame)
        time_elapsed = frame_time_elapsed

        # loop to next anim (ACE)
        return self.update_internal(time_elapsed, anim_node, frame_num, frame)
