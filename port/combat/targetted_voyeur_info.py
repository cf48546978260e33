"""TargettedVoyeurInfo (TargettedVoyeurInfo(objectID, radius, quantum)).

ACE's Combat/TargettedVoyeurInfo.cs: an object watching this one (a TargetManager's VoyeurTable
entry): how far this one must move before the voyeur is told again (`radius`), how far ahead its
position is projected (`quantum`, a double), and the position last sent.
"""

from __future__ import annotations

from dataclasses import dataclass

from ..anchors import anchor


@dataclass(slots=True, eq=False)
class TargettedVoyeurInfo:
    object_id: int = 0
    quantum: float = 0.0  # double
    radius: object = 0.0  # float
    last_sent_position: object = None  # Position

    @staticmethod
    @anchor(None, "TargettedVoyeurInfo.cs:TargettedVoyeurInfo(uint, float, double)")
    def create(object_id: int, radius, quantum: float) -> "TargettedVoyeurInfo":
        return TargettedVoyeurInfo(object_id=object_id, quantum=float(quantum), radius=radius)


__all__ = ["TargettedVoyeurInfo"]
