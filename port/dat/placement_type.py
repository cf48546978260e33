"""PlacementType: Unpack(reader, numParts) -- a Setup's placement frame (ACE.DatLoader Entity/PlacementType.cs)."""

from __future__ import annotations

from dataclasses import dataclass

from ..anchors import anchor
from .animation_frame import AnimationFrame


@dataclass(slots=True)
class PlacementType:
    anim_frame: AnimationFrame | None = None

    @staticmethod
    @anchor(None, "ACE.DatLoader/Entity/PlacementType.cs:Unpack")
    def unpack(reader, num_parts: int) -> "PlacementType":
        p = PlacementType()
        p.anim_frame = AnimationFrame.unpack(reader, num_parts)
        return p

    @staticmethod
    @anchor(None, "ACE.DatLoader/Entity/PlacementType.cs:PlacementType", "new PlacementType(): an empty AnimationFrame")
    def create() -> "PlacementType":
        return PlacementType(AnimationFrame())
