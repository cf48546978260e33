"""CellPortal: Unpack, ExactMatch, PortalSide -- a portal of an EnvCell: its flags, polygon and the cell beyond (ACE.DatLoader Entity/CellPortal.cs).

PortalSide is true when the PortalSide flag bit (0x2) is CLEAR (ACE's `(Flags & PortalSide) == 0`).
An OtherCellId of 0xFFFF leads outside.
"""

from __future__ import annotations

from dataclasses import dataclass

from ..anchors import anchor

# ACE.Entity.Enum.PortalFlags
PORTAL_FLAG_EXACT_MATCH = 0x1
PORTAL_FLAG_PORTAL_SIDE = 0x2


@dataclass(slots=True)
class CellPortal:
    flags: int = 0
    polygon_id: int = 0
    other_cell_id: int = 0
    other_portal_id: int = 0

    @property
    def exact_match(self) -> bool:
        return (self.flags & PORTAL_FLAG_EXACT_MATCH) != 0

    @property
    def portal_side(self) -> bool:
        return (self.flags & PORTAL_FLAG_PORTAL_SIDE) == 0

    @staticmethod
    @anchor(None, "ACE.DatLoader/Entity/CellPortal.cs:Unpack")
    def unpack(reader) -> "CellPortal":
        p = CellPortal()
        p.flags = reader.read_uint16()
        p.polygon_id = reader.read_uint16()
        p.other_cell_id = reader.read_uint16()
        p.other_portal_id = reader.read_uint16()
        return p
