"""Sequence: Sequence(), Init, SetObject, SetPlacementFrame, GetCurrAnimFrame, SetVelocity, SetOmega, Update, apply_physics, is_first_cyclic, HasAnims -- an object's animation sequence: the placement frame that places its parts, and its root motion.

ACE's Physics/Animation/Sequence.cs. No object animates here: acconform/dat.py writes no
DefaultAnimation and no MotionTable, so AnimList stays empty, CurrAnim null, and the current
frame is the placement frame PartArray.SetPlacementFrame chose (or null when the Setup has none).
A tick scene drives root motion through the sequence's own Velocity and Omega (SetVelocity,
SetOmega), which Update applies to the tick's offset frame (apply_physics) when there are no
animations -- the branch of Update every object here takes.
"""

from __future__ import annotations

from dataclasses import dataclass

from acconform.numerics import Vector3

from .anchors import anchor


@dataclass(slots=True, eq=False)
class Sequence:
    velocity: Vector3 | None = None
    omega: Vector3 | None = None
    hook_obj: object = None
    frame_number: object = 0.0
    anim_list: list | None = None  # AnimList (a LinkedList of AnimSequenceNode): always empty here
    first_cyclic: object = None
    placement_frame: object = None  # dat.animation_frame.AnimationFrame
    placement_frame_id: int = 0
    curr_anim: object = None  # never set: no animation is ever appended

    @staticmethod
    @anchor("CSequence::CSequence", "Sequence.cs:Sequence()", "the constructor: Init")
    def create(mode) -> "Sequence":
        sequence = Sequence()
        sequence.init(mode)
        return sequence

    @anchor("CSequence::init", "Sequence.cs:Init")
    def init(self, mode) -> None:
        self.velocity = mode.vec(0, 0, 0)
        self.omega = mode.vec(0, 0, 0)
        self.frame_number = mode.scalar(0.0)
        self.anim_list = []

    @anchor("CSequence::set_object", "Sequence.cs:SetObject")
    def set_object(self, obj) -> None:
        self.hook_obj = obj

    @anchor("CSequence::set_placement_frame", "Sequence.cs:SetPlacementFrame")
    def set_placement_frame(self, frame, frame_id: int) -> None:
        self.placement_frame = frame
        self.placement_frame_id = frame_id

    @anchor("CSequence::get_curr_animframe", "Sequence.cs:GetCurrAnimFrame")
    def get_curr_anim_frame(self):
        if self.curr_anim is None:
            return self.placement_frame
        raise NotImplementedError("animations (AnimSequenceNode.get_part_frame) are not ported")

    @anchor("CSequence::SetVelocity", "Sequence.cs:SetVelocity")
    def set_velocity(self, velocity: Vector3) -> None:
        self.velocity = velocity

    @anchor("CSequence::SetOmega", "Sequence.cs:SetOmega")
    def set_omega(self, omega: Vector3) -> None:
        self.omega = omega

    @anchor(None, "Sequence.cs:is_first_cyclic")
    def is_first_cyclic(self) -> bool:
        return self.curr_anim is None or self.curr_anim is self.first_cyclic

    @anchor("CSequence::has_anims", "Sequence.cs:HasAnims")
    def has_anims(self) -> bool:
        return self.anim_list is not None and len(self.anim_list) != 0

    @anchor("CSequence::update", "Sequence.cs:Update")
    def update(self, quantum, offset_frame) -> None:
        """`quantum` is a float (PartArray.Update casts it); `offset_frame` (C# `ref AFrame`) is
        changed in place: with no animations Update never replaces it."""
        if self.anim_list:
            raise NotImplementedError("animations (Sequence.update_internal, apricot) are not ported: no scene has any")
        elif offset_frame is not None:
            self.apply_physics(offset_frame, quantum, quantum)

    @anchor("CSequence::apply_physics", "Sequence.cs:apply_physics")
    def apply_physics(self, frame, quantum, sign) -> None:
        """Performs the translation and rotation on the frame (ACE). `sign >= 0.0` compares a float
        with a double literal: the same test in float."""
        if sign >= 0.0:
            quantum = abs(quantum)
        else:
            quantum = -abs(quantum)

        frame.origin = frame.origin + self.velocity * quantum
        frame.rotate_vec(self.omega * quantum)
