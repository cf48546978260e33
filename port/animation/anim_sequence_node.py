"""AnimSequenceNode: AnimSequenceNode(), AnimSequenceNode(AnimData), get_ending_frame, get_high_frame, get_low_frame, get_part_frame, get_pos_frame, get_starting_frame, has_anim, multiply_framerate, set_animation_id -- one queued animation of a Sequence.

ACE's Physics/Animation/AnimSequenceNode.cs. set_animation_id reads the Animation record through
DBObj.GetAnimation (DatManager.PortalDat in ACE; the run's PortalDat here, passed in) and wraps it
in a physics Animation, which is never null, so has_anim is always true for a node made from an
AnimData (an id with no record throws in DBObj, as ACE's does). The frame numbers are floats:
``HighFrame + 1 - EPSILON`` is int + int, then minus the float EPSILON, in float.
"""

from __future__ import annotations

from dataclasses import dataclass

from acconform.numerics import cs_floor, wrap_i32

from .. import db_obj
from ..anchors import anchor
from ..constants import EPSILON
from ..frame import AFrame
from .animation import Animation

# AnimSequenceNode(): Framerate = 30.0f (exact)
DEFAULT_FRAMERATE = 30.0


@dataclass(slots=True, eq=False)
class AnimSequenceNode:
    anim: Animation | None = None
    framerate: object = DEFAULT_FRAMERATE  # float
    low_frame: int = 0
    high_frame: int = -1
    mode: object = None  # the run's mode: the type of the float frame numbers and of `new AFrame()`

    @staticmethod
    @anchor("AnimSequenceNode::AnimSequenceNode", "AnimSequenceNode.cs:AnimSequenceNode()")
    def create(mode) -> "AnimSequenceNode":
        return AnimSequenceNode(None, mode.scalar(DEFAULT_FRAMERATE), 0, -1, mode)

    @staticmethod
    @anchor("AnimSequenceNode::AnimSequenceNode", "AnimSequenceNode.cs:AnimSequenceNode(AnimData)")
    def from_anim_data(anim_data, portal_dat) -> "AnimSequenceNode":
        node = AnimSequenceNode(None, anim_data.framerate, anim_data.low_frame, anim_data.high_frame, portal_dat.mode)
        node.set_animation_id(anim_data.anim_id, portal_dat)
        return node

    @anchor("AnimSequenceNode::get_ending_frame", "AnimSequenceNode.cs:get_ending_frame")
    def get_ending_frame(self):
        if self.framerate >= 0.0:
            return self.mode.scalar(wrap_i32(self.high_frame + 1)) - EPSILON
        else:
            return self.mode.scalar(self.low_frame)

    @anchor("AnimSequenceNode::get_high_frame", "AnimSequenceNode.cs:get_high_frame")
    def get_high_frame(self) -> int:
        return self.high_frame

    @anchor("AnimSequenceNode::get_low_frame", "AnimSequenceNode.cs:get_low_frame")
    def get_low_frame(self) -> int:
        return self.low_frame

    @anchor("AnimSequenceNode::get_part_frame", "AnimSequenceNode.cs:get_part_frame")
    def get_part_frame(self, frame_idx: int):
        if self.anim is None:
            return None
        if frame_idx < 0 or frame_idx >= self.anim.num_frames:
            return None

        return self.anim.part_frames[frame_idx]

    @anchor("AnimSequenceNode::get_pos_frame", "AnimSequenceNode.cs:get_pos_frame(int)")
    def get_pos_frame(self, frame_idx: int) -> AFrame:
        """A frame out of range is a new identity AFrame; one in range is the Animation's own AFrame
        (AFrame.Combine reads it, Subtract reads it: neither writes it)."""
        if self.anim is None:
            return AFrame.identity(self.mode)
        if frame_idx < 0 or frame_idx >= len(self.anim.pos_frames):
            return AFrame.identity(self.mode)

        return self.anim.pos_frames[frame_idx]

    @anchor("AnimSequenceNode::get_pos_frame", "AnimSequenceNode.cs:get_pos_frame(float)")
    def get_pos_frame_float(self, frame_idx) -> AFrame:
        return self.get_pos_frame(self.mode.runtime.to_int32(cs_floor(frame_idx)))

    @anchor("AnimSequenceNode::get_starting_frame", "AnimSequenceNode.cs:get_starting_frame")
    def get_starting_frame(self):
        if self.framerate >= 0.0:
            return self.mode.scalar(self.low_frame)
        else:
            return self.mode.scalar(wrap_i32(self.high_frame + 1)) - EPSILON

    @anchor("AnimSequenceNode::has_anim", "AnimSequenceNode.cs:has_anim")
    def has_anim(self, appraisal_profile: int = 0) -> bool:
        return self.anim is not None

    @anchor("AnimSequenceNode::multiply_framerate", "AnimSequenceNode.cs:multiply_framerate")
    def multiply_framerate(self, multiplier) -> None:
        if multiplier < 0.0:
            swap = self.low_frame
            self.low_frame = self.high_frame
            self.high_frame = swap
        self.framerate = self.framerate * multiplier

    @anchor("AnimSequenceNode::set_animation_id", "AnimSequenceNode.cs:set_animation_id")
    def set_animation_id(self, anim_id: int, portal_dat) -> None:
        anim = db_obj.get_animation(portal_dat, anim_id)
        self.anim = Animation.from_dat(anim)
        if self.anim is None:
            return

        num_frames = self.anim.num_frames  # a uint: `(int)(NumFrames - 1)` of 0 is -1
        if self.high_frame < 0:
            self.high_frame = _to_int(num_frames - 1)

        if self.low_frame >= num_frames:
            self.low_frame = _to_int(num_frames - 1)

        if self.high_frame >= num_frames:
            self.high_frame = _to_int(num_frames - 1)

        if self.low_frame > self.high_frame:
            self.high_frame = self.low_frame


def _to_int(n: int) -> int:
    """``(int)(uint)``: the uint's bits as an int (NumFrames - 1 of 0 is uint 0xFFFFFFFF, int -1)."""
    return wrap_i32(n)
