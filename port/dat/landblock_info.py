"""LandblockInfo: Unpack -- a landblock's 0xXXYYFFFE cell-DAT record: how many EnvCells it has, its static objects and its buildings (ACE.DatLoader FileTypes/LandblockInfo.cs).

AdjustCell (port/adjust_cell.py) reads NumCells to know which EnvCells a dungeon has; a
Landblock whose CellLandblock has HasObjects reads the whole record (DBObj.GetLandblockInfo) and
builds its buildings from it (Landblock.init_buildings) and gives its land cells the restriction
table's objects (PackMask bit 0: a housing barrier's owner per cell; scene/8 landblocks[].restrictions,
acconform/dat.landblock_info_record).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ..anchors import anchor
from .build_info import BuildInfo
from .stab import Stab
from .unpackable_extensions import unpack_list, unpack_list_fixed, unpack_packed_hash_table_uint


@dataclass(slots=True, eq=False)
class LandblockInfo:
    id: int = 0
    num_cells: int = 0
    objects: list = field(default_factory=list)  # Stab
    pack_mask: int = 0
    buildings: list = field(default_factory=list)  # BuildInfo
    restriction_tables: dict = field(default_factory=dict)  # cell id -> the restriction object's id


    @staticmethod
    @anchor(None, "ACE.DatLoader/FileTypes/LandblockInfo.cs:LandblockInfo()")
    def empty(mode) -> "LandblockInfo":
        """``new LandblockInfo()``, what ReadFromDat gives for an id its DAT lacks: no cells, no objects, no buildings."""
        return LandblockInfo()
    @staticmethod
    @anchor(None, "ACE.DatLoader/FileTypes/LandblockInfo.cs:Unpack")
    def unpack(reader) -> "LandblockInfo":
        i = LandblockInfo()
        i.id = reader.read_uint32()

        i.num_cells = reader.read_uint32()

        i.objects = unpack_list(reader, Stab.unpack)

        num_buildings = reader.read_uint16()
        i.pack_mask = reader.read_uint16()

        i.buildings = unpack_list_fixed(reader, BuildInfo.unpack, num_buildings)

        if (i.pack_mask & 1) == 1:
            i.restriction_tables = unpack_packed_hash_table_uint(reader)
        return i
