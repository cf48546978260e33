"""CellDat: the run's DatManager.CellDat (a CellDatDatabase: ACE.DatLoader/CellDatDatabase.cs).

A DatDatabase (port/dat/dat_database.py) of the cell records acconform/dat.py wrote for the
scene: its EnvCells and their landblocks' LandblockInfos (dat.cell_dat_records). A landblock's
CellLandblock is built from the scene's record directly (port/land/landblock.py).
"""

from __future__ import annotations

from .dat_database import DatDatabase


class CellDat(DatDatabase):
    __slots__ = ()
