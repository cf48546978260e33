"""AdjustCell: AdjustCell(dungeonID), BuildEnv, GetCell, Get -- a dungeon's EnvCells, to find the one holding a point (ACE's Physics/Util/AdjustCell.cs).

Position.GetIndoorCell asks it. ACE keeps every landblock's AdjustCell in a static dictionary
(AdjustCells); a run keeps its own in its LScape (`lscape.adjust_cells`), as it keeps its cells.
The LandblockInfo record (0xXXYYFFFE in the cell DAT) says how many EnvCells to load, from 0x0100 up.
"""

from __future__ import annotations

from .anchors import anchor
from .dat.landblock_info import LandblockInfo


class AdjustCell:
    __slots__ = ("env_cells",)

    @anchor(None, "AdjustCell.cs:AdjustCell(uint)")
    def __init__(self, dungeon_id: int, lscape):
        block_info_id = ((dungeon_id << 16) | 0xFFFE) & 0xFFFFFFFF
        blockinfo = lscape.cell_dat.read_from_dat(block_info_id, LandblockInfo)
        num_cells = blockinfo.num_cells

        self.build_env(dungeon_id, num_cells, lscape)

    @anchor(None, "AdjustCell.cs:BuildEnv")
    def build_env(self, dungeon_id: int, num_cells: int, lscape) -> None:
        from .cell.env_cell import EnvCell

        self.env_cells = []
        first_cell_id = 0x100
        for i in range(num_cells):
            cell_id = first_cell_id + i
            block_cell = ((dungeon_id << 16) | cell_id) & 0xFFFFFFFF

            obj_cell = lscape.get_landcell(block_cell)
            env_cell = obj_cell if isinstance(obj_cell, EnvCell) else None
            if env_cell is not None:
                self.env_cells.append(env_cell)

    @anchor(None, "AdjustCell.cs:GetCell")
    def get_cell(self, point) -> int | None:
        for env_cell in self.env_cells:
            if env_cell.point_in_cell(point):
                return env_cell.id
        return None

    @staticmethod
    @anchor(None, "AdjustCell.cs:Get")
    def get(dungeon_id: int, lscape) -> "AdjustCell":
        adjust_cell = lscape.adjust_cells.get(dungeon_id)
        if adjust_cell is None:
            adjust_cell = AdjustCell(dungeon_id, lscape)
            lscape.adjust_cells.setdefault(dungeon_id, adjust_cell)  # TryAdd
        return adjust_cell
