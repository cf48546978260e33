"""Stab: Unpack -- an object id and its frame, as an EnvCell lists its static objects (ACE.DatLoader Entity/Stab.cs)."""

from __future__ import annotations

from dataclasses import dataclass, field

from ..anchors import anchor
from .frame import Frame


@dataclass(slots=True)
class Stab:
    id: int = 0
    frame: Frame = field(default_factory=Frame)

    @staticmethod
    @anchor(None, "ACE.DatLoader/Entity/Stab.cs:Unpack")
    def unpack(reader) -> "Stab":
        s = Stab()
        s.id = reader.read_uint32()
        s.frame = Frame.unpack(reader)
        return s
