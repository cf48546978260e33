"""Sequence: SetObject, SetPlacementFrame, GetCurrAnimFrame -- the part of an object's animation sequence that places its parts.

ACE's Physics/Animation/Sequence.cs. A static object never animates here (no DefaultAnimation:
acconform/dat.py writes none), so CurrAnim stays null and the current frame is the placement
frame PartArray.SetPlacementFrame chose (or null when the Setup has none).
"""

from __future__ import annotations

from dataclasses import dataclass

from .anchors import anchor


@dataclass(slots=True, eq=False)
class Sequence:
    hook_obj: object = None
    placement_frame: object = None  # dat.animation_frame.AnimationFrame
    placement_frame_id: int = 0
    curr_anim: object = None  # never set: animations are not ported

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
