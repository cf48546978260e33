"""LocationType: Unpack -- a Setup's holding location or connection point (ACE.DatLoader Entity/LocationType.cs)."""

from __future__ import annotations

from dataclasses import dataclass

from ..anchors import anchor
from .frame import Frame


@dataclass(slots=True)
class LocationType:
    part_id: int = 0
    frame: Frame | None = None

    @staticmethod
    @anchor(None, "ACE.DatLoader/Entity/LocationType.cs:Unpack")
    def unpack(reader) -> "LocationType":
        t = LocationType()
        t.part_id = reader.read_int32()
        t.frame = Frame.unpack(reader)
        return t
