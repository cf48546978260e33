"""BldPortal: BldPortal(CBldPortal), GetOtherCell, add_to_stablist -- a building's portal into one of its EnvCells (ACE's Common/BldPortal.cs).

The fields are copied from the DAT's CBldPortal (port/dat/c_bld_portal.py): PortalSide as
ACE reads it since ACE #4315 (true when the flag bit 0x2 is clear). GetOtherCell reaches ACE's
static LScape; here the run's LScape is the first argument.
"""

from __future__ import annotations

from ..anchors import anchor
from ..errors import InvalidCastException


class BldPortal:
    __slots__ = ("flags", "exact_match", "portal_side", "other_cell_id", "other_portal_id", "stab_list")

    @anchor("CBldPortal::CBldPortal", "BldPortal.cs:BldPortal(DatLoader.Entity.CBldPortal)")
    def __init__(self, bld_portal):
        self.flags = bld_portal.flags
        self.exact_match = bld_portal.exact_match
        self.portal_side = bld_portal.portal_side
        self.other_cell_id = bld_portal.other_cell_id
        self.other_portal_id = bld_portal.other_portal_id
        self.stab_list = bld_portal.stab_list  # the same List (a reference)

    @anchor("CBldPortal::GetOtherCell", "BldPortal.cs:GetOtherCell")
    def get_other_cell(self, lscape, landblock_id: int):
        """``(EnvCell)LScape.get_landcell(landblockID & 0xFFFF0000 | OtherCellId)``: null stays null,
        any other cell throws InvalidCastException."""
        from .env_cell import EnvCell

        block_cell_id = (landblock_id & 0xFFFF0000) | self.other_cell_id

        cell = lscape.get_landcell(block_cell_id)
        if cell is not None and not isinstance(cell, EnvCell):
            raise InvalidCastException(f"cell {cell.id:08X} is a {type(cell).__name__}, not an EnvCell")
        return cell

    @anchor("CBldPortal::add_to_stablist", "BldPortal.cs:add_to_stablist")
    def add_to_stablist(self, stab_list, max_size: int, stab_num: int):
        """The C# refs come back: (stabList, maxSize, stabNum). As ACE writes it, a stab is appended
        only when it is already in the first stabNum entries, so from stabNum 0 (every landblock
        starts there) nothing is ever added and the landblock's null StabList is never touched."""
        # is maxSize needed with list? (ACE)
        for i in range(len(self.stab_list)):
            j = stab_num
            while j > 0:
                if self.stab_list[i] == stab_list[j - 1]:
                    break
                j -= 1
            if j > 0:
                if stab_num >= max_size:
                    stab_list = []
                    max_size += 10
                    for stab in self.stab_list:
                        stab_list.append(stab)
                stab_list.append(self.stab_list[i])
                stab_num += 1
        return stab_list, max_size, stab_num
