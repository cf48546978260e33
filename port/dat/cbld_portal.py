"""CBldPortal: Unpack -- a building's portal into the cells behind it (ACE.DatLoader Entity/CBldPortal.cs)."""

from __future__ import annotations

from dataclasses import dataclass, field

from ..anchors import anchor


@dataclass(slots=True)
class CBldPortal:
    flags: int = 0
    other_cell_id: int = 0
    other_portal_id: int = 0
    stab_list: list = field(default_factory=list)  # ushort

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
