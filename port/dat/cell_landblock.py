"""CellLandblock: Unpack -- a landblock's 0xXXYYFFFF cell-DAT record: its HasObjects flag, 9x9 terrain words and heights (ACE.DatLoader FileTypes/CellLandblock.cs).

ACE's Landblock constructor builds the landblock's terrain from it (LandblockStruct) and, with
HasObjects, reads its LandblockInfo. A run given a request's DAT records (the protocol's feature
`dat`, port/run.py's `dat_landscape`) builds its landblocks from these; a run given a scene takes
the scene's Landblock records, which acconform/dat.cell_landblock writes in this layout.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ..anchors import anchor


@dataclass(slots=True, eq=False)
class CellLandblock:
    id: int = 0
    has_objects: bool = False
    terrain: list = field(default_factory=list)  # 81 ushorts, x-major
    height: list = field(default_factory=list)  # 81 bytes: indices into the land height table


    @staticmethod
    @anchor(None, "ACE.DatLoader/FileTypes/CellLandblock.cs:CellLandblock()")
    def empty(mode) -> "CellLandblock":
        """``new CellLandblock()``, what ReadFromDat gives for an id its DAT lacks: id 0, no heights, no terrain."""
        return CellLandblock()
    @staticmethod
    @anchor(None, "ACE.DatLoader/FileTypes/CellLandblock.cs:Unpack")
    def unpack(reader) -> "CellLandblock":
        c = CellLandblock()
        c.id = reader.read_uint32()

        has_objects = reader.read_uint32()
        if has_objects == 1:
            c.has_objects = True

        # Read in the terrain. 9x9 so 81 records.
        c.terrain = [reader.read_uint16() for _ in range(81)]
        # Read in the height. 9x9 so 81 records
        c.height = [reader.read_byte() for _ in range(81)]

        reader.align_boundary()
        return c
