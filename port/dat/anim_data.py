"""AnimData: Unpack -- one animation of a motion: its id, frame range and framerate (ACE.DatLoader Entity/AnimData.cs)."""

from __future__ import annotations

from dataclasses import dataclass

from ..anchors import anchor


@dataclass(slots=True)
class AnimData:
    anim_id: int = 0
    low_frame: int = 0
    high_frame: int = 0
    framerate: object = 0.0  # negative plays the animation in reverse

    @staticmethod
    @anchor(None, "ACE.DatLoader/Entity/AnimData.cs:Unpack")
    def unpack(reader) -> "AnimData":
        a = AnimData()
        a.anim_id = reader.read_uint32()
        a.low_frame = reader.read_int32()
        a.high_frame = reader.read_int32()
        a.framerate = reader.read_single()
        return a
