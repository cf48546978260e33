"""Animation: Unpack -- a 0x03 Animation record: its root-motion frames (PosFrames) and a frame per part per frame (ACE.DatLoader FileTypes/Animation.cs)."""

from __future__ import annotations

from dataclasses import dataclass, field

from ..anchors import anchor
from .animation_frame import AnimationFrame
from .frame import Frame
from .unpackable_extensions import unpack_list_fixed

# ACE.Entity.Enum.AnimationFlags
ANIMATION_POS_FRAMES = 0x1


@dataclass(slots=True, eq=False)
class Animation:
    id: int = 0
    flags: int = 0
    num_parts: int = 0
    num_frames: int = 0
    pos_frames: list = field(default_factory=list)  # Frame per frame, when flags has PosFrames
    part_frames: list = field(default_factory=list)  # AnimationFrame per frame

    @staticmethod
    @anchor(None, "ACE.DatLoader/FileTypes/Animation.cs:Unpack")
    def unpack(reader) -> "Animation":
        a = Animation()
        a.id = reader.read_uint32()
        a.flags = reader.read_uint32()
        a.num_parts = reader.read_uint32()
        a.num_frames = reader.read_uint32()

        if (a.flags & ANIMATION_POS_FRAMES) != 0:
            a.pos_frames = unpack_list_fixed(reader, Frame.unpack, a.num_frames)

        for _ in range(a.num_frames):
            animation_frame = AnimationFrame.unpack(reader, a.num_parts)
            a.part_frames.append(animation_frame)
        return a
