"""Animation: Animation(DatLoader Animation) -- an animation's root-motion frames as AFrames and its part frames (ACE's Physics/Animation/Animation.cs)."""

from __future__ import annotations

from dataclasses import dataclass

from ..anchors import anchor
from ..frame import AFrame


@dataclass(slots=True, eq=False)
class Animation:
    id: int = 0
    pos_frames: list | None = None  # AFrame per frame (empty when the record has none)
    part_frames: list | None = None  # DatLoader AnimationFrame per frame: the record's own list
    has_hooks: bool = False
    num_parts: int = 0
    num_frames: int = 0

    @staticmethod
    @anchor(None, "Animation.cs:Animation(DatLoader.FileTypes.Animation)")
    def from_dat(anim) -> "Animation":
        a = Animation()
        a.id = anim.id
        a.has_hooks = False  # comes from bitfield? (ACE)
        a.num_parts = anim.num_parts
        a.num_frames = anim.num_frames
        a.part_frames = anim.part_frames
        a.pos_frames = []
        for pos_frame in anim.pos_frames:
            a.pos_frames.append(AFrame.from_dat(pos_frame))
        return a
