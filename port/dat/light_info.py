"""LightInfo: Unpack -- a Setup's light (ACE.DatLoader Entity/LightInfo.cs)."""

from __future__ import annotations

from dataclasses import dataclass

from ..anchors import anchor
from .frame import Frame


@dataclass(slots=True)
class LightInfo:
    viewer_space_location: Frame | None = None
    color: int = 0
    intensity: object = None
    falloff: object = None
    cone_angle: object = None

    @staticmethod
    @anchor(None, "ACE.DatLoader/Entity/LightInfo.cs:Unpack")
    def unpack(reader) -> "LightInfo":
        li = LightInfo()
        li.viewer_space_location = Frame.unpack(reader)
        li.color = reader.read_uint32()
        li.intensity = reader.read_single()
        li.falloff = reader.read_single()
        li.cone_angle = reader.read_single()
        return li
