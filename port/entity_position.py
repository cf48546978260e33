"""ACE.Entity.Position: Position(blockCellID, position, rotation), Pos, SetPosition, SetLandblock, SetLandCell, Indoors; LandblockId.TransitionX, TransitionY -- the outdoor landblock and cell a WorldObject's Location finds anew when its Pos is set.

ACE.Entity/Position.cs and ACE.Entity/LandblockId.cs: the server's own position (a WorldObject's Location),
outside the physics. Its `Pos` setter is SetPosition, which moves an outdoor position onto the landblock its
X and Y lie in (LandblockId.TransitionX/Y: no landblock past 0 or 254, where X or Y is clamped to 0 or
BlockLength) and then gives it the outdoor cell of its X and Y. A projectile's Location is such a position:
a copy of its launcher's with Pos moved to the spawn point (Creature.LaunchProjectile: ``proj.Location = new
Position(Location); proj.Location.Pos = origin``; LaunchSpellProjectiles: ``sp.Location = new
Position(casterLoc); sp.Location.Pos += ...``), so a spawn point in another cell or landblock than the
launcher's enters the world from that cell (port/missile_launch.py projectile_location). An indoor position
(a cell id of 0x100 or more) is left as it is.

The arithmetic is ACE's: ``(int)PositionX / BlockLength`` truncates toward zero (C#'s float-to-int and int
division), ``PositionX -= BlockLength * blockOffset`` is one float subtraction, and ``(uint)PositionX /
CellLength`` truncates a coordinate already within [0, BlockLength].
"""

from __future__ import annotations

from acconform.numerics import Vector3

from .anchors import anchor

# ACE.Entity/Position.cs: BlockLength = 192, CellSide = 8, CellLength = 24 (ints)
BLOCK_LENGTH = 192
CELL_SIDE = 8
CELL_LENGTH = 24


def _trunc_int(x) -> int:
    """C#'s (int) of a float: toward zero."""
    return int(float(x))


def _div(a: int, b: int) -> int:
    """C#'s int division: toward zero."""
    q = abs(a) // abs(b)
    return q if (a >= 0) == (b > 0) else -q


@anchor(None, "ACE.Entity/LandblockId.cs:TransitionX")
def transition_x(raw: int, block_offset: int) -> int | None:
    new_x = ((raw >> 24) & 0xFF) + block_offset
    if new_x < 0 or new_x > 254:
        return None
    return (new_x << 24 | ((raw >> 16) & 0xFF) << 16 | raw & 0xFFFF) & 0xFFFFFFFF


@anchor(None, "ACE.Entity/LandblockId.cs:TransitionY")
def transition_y(raw: int, block_offset: int) -> int | None:
    new_y = ((raw >> 16) & 0xFF) + block_offset
    if new_y < 0 or new_y > 254:
        return None
    return (((raw >> 24) & 0xFF) << 24 | new_y << 16 | raw & 0xFFFF) & 0xFFFFFFFF


class EntityPosition:
    """ACE.Entity.Position: `landblock_id` (LandblockId.Raw: landblock and cell), PositionX/Y/Z (float32,
    the scalar type of the port's vectors) and Rotation."""

    __slots__ = ("landblock_id", "position_x", "position_y", "position_z", "rotation")

    @anchor(None, "ACE.Entity/Position.cs:Position(uint, Vector3, Quaternion)",
            "ACE.Server/Entity/PositionExtensions.cs ACEPosition makes a physics Position's copy with it")
    def __init__(self, block_cell_id: int, position, rotation):
        self.landblock_id = block_cell_id
        self.position_x = self.position_y = self.position_z = None
        self.set_position(position)  # Pos = position
        self.rotation = rotation

        if (block_cell_id & 0xFFFF) == 0:
            self.set_position(self.pos)

    @property
    def pos(self):
        """Pos's getter: new Vector3(PositionX, PositionY, PositionZ). Its setter is set_position."""
        return Vector3(self.position_x, self.position_y, self.position_z)

    @property
    def indoors(self) -> bool:
        """LandblockId.Indoors: a cell id of 0x100 or more."""
        return (self.landblock_id & 0xFFFF) >= 0x100

    @anchor(None, "ACE.Entity/Position.cs:SetPosition")
    def set_position(self, pos) -> tuple[bool, bool]:
        self.position_x = pos.x
        self.position_y = pos.y
        self.position_z = pos.z

        block_update = self.set_landblock()
        cell_update = self.set_land_cell()

        return block_update, cell_update

    @anchor(None, "ACE.Entity/Position.cs:SetLandblock", "handles the Position crossing over landblock boundaries")
    def set_landblock(self) -> bool:
        if self.indoors:
            return False

        s = type(self.position_x)
        changed_block = False

        if self.position_x < 0:
            block_offset = _div(_trunc_int(self.position_x), BLOCK_LENGTH) - 1
            landblock = transition_x(self.landblock_id, block_offset)
            if landblock is not None:
                self.landblock_id = landblock
                self.position_x = self.position_x - s(BLOCK_LENGTH * block_offset)
                changed_block = True
            else:
                self.position_x = s(0)

        if self.position_x >= BLOCK_LENGTH:
            block_offset = _div(_trunc_int(self.position_x), BLOCK_LENGTH)
            landblock = transition_x(self.landblock_id, block_offset)
            if landblock is not None:
                self.landblock_id = landblock
                self.position_x = self.position_x - s(BLOCK_LENGTH * block_offset)
                changed_block = True
            else:
                self.position_x = s(BLOCK_LENGTH)

        if self.position_y < 0:
            block_offset = _div(_trunc_int(self.position_y), BLOCK_LENGTH) - 1
            landblock = transition_y(self.landblock_id, block_offset)
            if landblock is not None:
                self.landblock_id = landblock
                self.position_y = self.position_y - s(BLOCK_LENGTH * block_offset)
                changed_block = True
            else:
                self.position_y = s(0)

        if self.position_y >= BLOCK_LENGTH:
            block_offset = _div(_trunc_int(self.position_y), BLOCK_LENGTH)
            landblock = transition_y(self.landblock_id, block_offset)
            if landblock is not None:
                self.landblock_id = landblock
                self.position_y = self.position_y - s(BLOCK_LENGTH * block_offset)
                changed_block = True
            else:
                self.position_y = s(BLOCK_LENGTH)

        return changed_block

    @anchor(None, "ACE.Entity/Position.cs:SetLandCell", "determines the outdoor landcell for the current position")
    def set_land_cell(self) -> bool:
        if self.indoors:
            return False

        cell_x = _trunc_int(self.position_x) // CELL_LENGTH  # (uint)PositionX / CellLength
        cell_y = _trunc_int(self.position_y) // CELL_LENGTH

        cell_id = cell_x * CELL_SIDE + cell_y + 1

        cur_cell_id = self.landblock_id & 0xFFFF

        if cell_id == cur_cell_id:
            return False

        self.landblock_id = (self.landblock_id & 0xFFFF0000) | cell_id
        return True


__all__ = ["EntityPosition", "transition_x", "transition_y"]
