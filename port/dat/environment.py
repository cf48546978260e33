"""Environment: Unpack -- a 0x0D portal-DAT record: the cell structures of a prefab dungeon piece by id (ACE.DatLoader FileTypes/Environment.cs)."""

from __future__ import annotations

from dataclasses import dataclass, field

from ..anchors import anchor
from .cell_struct import CellStruct
from .unpackable_extensions import unpack_uint_dict


@dataclass(slots=True, eq=False)
class Environment:
    id: int = 0
    cells: dict = field(default_factory=dict)  # uint -> CellStruct, in DAT order


    @staticmethod
    @anchor(None, "ACE.DatLoader/FileTypes/Environment.cs:Environment()")
    def empty(mode) -> "Environment":
        """``new Environment()``, what ReadFromDat gives for an id its DAT lacks: no cell structures."""
        return Environment()
    @staticmethod
    @anchor(None, "ACE.DatLoader/FileTypes/Environment.cs:Unpack")
    def unpack(reader) -> "Environment":
        e = Environment()
        e.id = reader.read_uint32()  # this will match fileId
        e.cells = unpack_uint_dict(reader, CellStruct.unpack)
        return e
