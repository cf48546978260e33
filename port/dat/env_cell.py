"""EnvCell: Unpack, SeenOutside -- an indoor cell (0xXXYY0100 and up) as the cell DAT holds it (ACE.DatLoader FileTypes/EnvCell.cs).

The record repeats its cell id after the flags (skipped); surfaces are stored as ushorts and
widened with 0x08000000, the environment id as a ushort widened with 0x0D000000. The static
objects (a uint-counted list of Stabs) are there only with HasStaticObjs, the restriction object
only with HasRestrictionObj.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ..anchors import anchor
from .cell_portal import CellPortal
from .frame import Frame
from .stab import Stab
from .unpackable_extensions import unpack_list, unpack_list_fixed

# ACE.Entity.Enum.EnvCellFlags
ENV_CELL_SEEN_OUTSIDE = 0x1
ENV_CELL_HAS_STATIC_OBJS = 0x2
ENV_CELL_HAS_RESTRICTION_OBJ = 0x8


@dataclass(slots=True, eq=False)
class EnvCell:
    id: int = 0
    flags: int = 0
    surfaces: list = field(default_factory=list)  # uint
    environment_id: int = 0
    cell_structure: int = 0  # ushort
    position: Frame = field(default_factory=Frame)
    cell_portals: list = field(default_factory=list)  # CellPortal
    visible_cells: list = field(default_factory=list)  # ushort
    static_objects: list = field(default_factory=list)  # Stab
    restriction_obj: int = 0

    @staticmethod
    @anchor(None, "ACE.DatLoader/FileTypes/EnvCell.cs:EnvCell()")
    def empty(mode) -> "EnvCell":
        """``new EnvCell()``, what ReadFromDat gives for an id its DAT lacks: id 0, no structure, a new Frame."""
        return EnvCell(position=Frame.empty(mode))

    @property
    def seen_outside(self) -> bool:
        return (self.flags & ENV_CELL_SEEN_OUTSIDE) != 0

    @staticmethod
    @anchor(None, "ACE.DatLoader/FileTypes/EnvCell.cs:Unpack")
    def unpack(reader) -> "EnvCell":
        c = EnvCell()
        c.id = reader.read_uint32()
        c.flags = reader.read_uint32()
        reader.position += 4  # the cell id again

        num_surfaces = reader.read_byte()
        num_portals = reader.read_byte()
        num_stabs = reader.read_uint16()

        for _ in range(num_surfaces):
            c.surfaces.append(0x08000000 | reader.read_uint16())

        c.environment_id = 0x0D000000 | reader.read_uint16()

        c.cell_structure = reader.read_uint16()

        c.position = Frame.unpack(reader)

        c.cell_portals = unpack_list_fixed(reader, CellPortal.unpack, num_portals)

        for _ in range(num_stabs):
            c.visible_cells.append(reader.read_uint16())

        if c.flags & ENV_CELL_HAS_STATIC_OBJS:
            c.static_objects = unpack_list(reader, Stab.unpack)

        if c.flags & ENV_CELL_HAS_RESTRICTION_OBJ:
            c.restriction_obj = reader.read_uint32()
        return c
