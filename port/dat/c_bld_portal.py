"""CBldPortal: Unpack, ExactMatch, PortalSide -- a building's portal: its flags, the EnvCell it leads to, that cell's portal, and its stab list (ACE.DatLoader Entity/CBldPortal.cs).

PortalSide is read as ACE reads it since ACE #4315 (in 7b47913): true when the PortalSide flag bit
(0x2) is CLEAR, as CellPortal's is (port/dat/cell_portal.py). The record ends aligned to 4 bytes.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ..anchors import anchor
from .cell_portal import PORTAL_FLAG_EXACT_MATCH, PORTAL_FLAG_PORTAL_SIDE


@dataclass(slots=True)
class CBldPortal:
    flags: int = 0
    other_cell_id: int = 0
    other_portal_id: int = 0
    stab_list: list = field(default_factory=list)  # ushort cell low words

    @property
    def exact_match(self) -> bool:
        return (self.flags & PORTAL_FLAG_EXACT_MATCH) != 0

    @property
    def portal_side(self) -> bool:
        return (self.flags & PORTAL_FLAG_PORTAL_SIDE) == 0  # ACE: !Flags.HasFlag(PortalFlags.PortalSide)

    @staticmethod
    @anchor(None, "ACE.DatLoader/Entity/CBldPortal.cs:Unpack")
    def unpack(reader) -> "CBldPortal":
        p = CBldPortal()
        p.flags = reader.read_uint16()

        p.other_cell_id = reader.read_uint16()
        p.other_portal_id = reader.read_uint16()

        num_stabs = reader.read_uint16()
        for _ in range(num_stabs):
            p.stab_list.append(reader.read_uint16())

        reader.align_boundary()
        return p
