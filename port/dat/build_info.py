"""BuildInfo: Unpack -- one building of a landblock: its model (a GfxObj 0x01 or Setup 0x02), frame, NumLeaves and portals (ACE.DatLoader Entity/BuildInfo.cs)."""

from __future__ import annotations

from dataclasses import dataclass, field

from ..anchors import anchor
from .c_bld_portal import CBldPortal
from .frame import Frame
from .unpackable_extensions import unpack_list


@dataclass(slots=True)
class BuildInfo:
    model_id: int = 0
    frame: Frame = field(default_factory=Frame)
    num_leaves: int = 0
    portals: list = field(default_factory=list)  # CBldPortal

    @staticmethod
    @anchor(None, "ACE.DatLoader/Entity/BuildInfo.cs:Unpack")
    def unpack(reader) -> "BuildInfo":
        b = BuildInfo()
        b.model_id = reader.read_uint32()

        b.frame = Frame.unpack(reader)

        b.num_leaves = reader.read_uint32()

        b.portals = unpack_list(reader, CBldPortal.unpack)
        return b
