"""CellDat: the run's DatManager.CellDat (a CellDatDatabase: ACE.DatLoader/CellDatDatabase.cs).

A DatDatabase (port/dat/dat_database.py) of the cell records acconform/dat.py wrote for the
scene: its EnvCells and their landblocks' LandblockInfos (dat.cell_dat_records). A landblock's
CellLandblock is built from the scene's record directly (port/land/landblock.py).
"""

from __future__ import annotations

from ..anchors import harness
from .dat_database import DatDatabase


class CellDat(DatDatabase):
    __slots__ = ()

    @staticmethod
    @harness("the kind of cell DAT record an id names")
    def kind_of(file_id: int) -> str:
        """0xXXYYFFFF a CellLandblock, 0xXXYYFFFE a LandblockInfo, any other an EnvCell."""
        low = file_id & 0xFFFF
        return "CellLandblock" if low == 0xFFFF else "LandblockInfo" if low == 0xFFFE else "EnvCell"
