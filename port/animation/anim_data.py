"""AnimData: AnimData(), AnimData(DatLoader AnimData, speed) -- an animation to append to a Sequence: id, frame range, framerate scaled by the motion's speed (ACE's Physics/Animation/AnimData.cs)."""

from __future__ import annotations

from dataclasses import dataclass

from ..anchors import anchor


@dataclass(slots=True, eq=False)
class AnimData:
    anim_id: int = 0
    low_frame: int = 0
    high_frame: int = 0
    framerate: object = 0.0  # float: C#'s default 0f when made empty (PartArray.InitDefaults)

    @staticmethod
    @anchor(None, "AnimData.cs:AnimData()", "the empty constructor; `mode` gives Framerate's 0f the run's type")
    def create(mode) -> "AnimData":
        return AnimData(0, 0, 0, mode.scalar(0.0))

    @staticmethod
    @anchor(None, "AnimData.cs:AnimData(DatLoader.Entity.AnimData, float)")
    def from_dat(anim_data, speed) -> "AnimData":
        """`speed` is a float (1.0f by default in ACE: pass it)."""
        return AnimData(anim_data.anim_id, anim_data.low_frame, anim_data.high_frame, anim_data.framerate * speed)
