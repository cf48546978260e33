"""LandDefs: AdjustToOutside, GetBlockOffset, InBlock, blockid_to_lcoord, gid_to_lcoord, get_outside_lcoord, cell_in_range, lcoord_to_gid, inbound_valid_cellid.

ACE's Common/LandDefs.cs. Cell ids are uint32 Python ints. A C# ``Vector2?`` land coordinate
is a tuple ``(x, y)`` or ``None``; blockid_to_lcoord and gid_to_lcoord hold whole numbers below
2048, which float32 stores exactly, so they are Python floats and take the run's scalar type
from whatever they meet. get_outside_lcoord computes in the caller's scalar type (float32 in
exact mode), as C# does. GetBlockOffset's Vector3 is made of Python floats for the same reason
(multiples of 24 below 2^16, exact in float32): adding it to a mode vector rounds as C# does.
"""

from __future__ import annotations

from enum import IntEnum

from acconform.numerics import Runtime, Vector3, cast_float, cs_floor, wrap_i32, wrap_u32
from acconform.port.anchors import anchor, harness, remembers
from acconform.port.constants import EPSILON
from acconform.port.errors import InvalidOperationException

# LandDefs constants (C# int consts)
BLOCK_CELL_ID = 0x0000FFFF
FIRST_ENV_CELL_ID = 0x100
LAST_ENV_CELL_ID = 0xFFFD
FIRST_LAND_CELL_ID = 1
LAST_LAND_CELL_ID = 64
BLOCK_MASK = 0xFFFF0000
BLOCK_X_MASK = 0xFF00
BLOCK_Y_MASK = 0x00FF
CELL_ID_MASK = 0x0000FFFF
LANDBLOCK_MASK = 7
BLOCK_PART_SHIFT = 16
LANDBLOCK_SHIFT = 3
MAX_BLOCK_SHIFT = 8
BLOCK_LENGTH = 192
CELL_LENGTH = 24
LAND_LENGTH = 2040
VERTEX_DIM = 9
BLOCK_SIDE = 8
VERTEX_PER_CELL = 1
HALF_SQUARE_LENGTH = 12
SQUARE_LENGTH = 24


class Direction(IntEnum):
    Inside = 0x0
    North = 0x1
    South = 0x2
    East = 0x3
    West = 0x4
    NorthWest = 0x5
    SouthWest = 0x6
    NorthEast = 0x7
    SouthEast = 0x8
    Unknown = 0x9


class WaterType(IntEnum):
    NotWater = 0x0
    PartiallyWater = 0x1
    EntirelyWater = 0x2


# ACE's "Nullable object must have a value" (InvalidOperationException), now in port/errors.py;
# the old name stays for callers that catch it.
InvalidOperation = InvalidOperationException


@harness(".NET Nullable<T>.Value: the value, or InvalidOperationException when empty")
def value_of(lcoord, where: str):
    """C# ``nullable.Value``: the value, or InvalidOperationException when there is none."""
    if lcoord is None:
        raise InvalidOperationException(where)
    return lcoord


@anchor("LandDefs::adjust_to_outside", "LandDefs.cs:AdjustToOutside")
def adjust_to_outside(block_cell_id: int, loc: Vector3, runtime: Runtime) -> tuple[bool, int, Vector3]:
    """AdjustToOutside(ref blockCellID, ref loc): returns (result, new blockCellID, new loc).

    Note ACE snaps |x|,|y| < EPSILON to 0 before it knows whether it succeeds, so a failed
    call still hands back the snapped loc (with blockCellID 0). `runtime` makes lcoord_to_gid's
    ``(int)`` casts: a NaN loc passes get_outside_lcoord's range test, and ``(int)NaN`` is
    int.MinValue on mono (no cell: 0) but 0 on .NET 10 (land coordinate 0: landblock 0x0000's
    first cell).
    """
    cell_id = block_cell_id & CELL_ID_MASK
    if cell_in_range(cell_id):
        zero = type(loc.x)(0)
        if abs(loc.x) < EPSILON:
            loc = loc.with_x(zero)
        if abs(loc.y) < EPSILON:
            loc = loc.with_y(zero)

        lcoord = get_outside_lcoord(block_cell_id, loc.x, loc.y)
        if lcoord is not None:
            block_cell_id = wrap_u32(lcoord_to_gid(lcoord[0], lcoord[1], runtime))
            loc = loc.with_x(loc.x - cast_float(loc.x, cs_floor(loc.x / BLOCK_LENGTH)) * BLOCK_LENGTH)
            loc = loc.with_y(loc.y - cast_float(loc.y, cs_floor(loc.y / BLOCK_LENGTH)) * BLOCK_LENGTH)
            return True, block_cell_id, loc
    return False, 0, loc


@anchor("LandDefs::adjust_to_outside", "LandDefs.cs:AdjustToOutside(Position)")
def adjust_to_outside_pos(pos) -> bool:
    """AdjustToOutside(Position): updates pos.obj_cell_id and pos.frame.origin in place (computing as
    the runtime whose arithmetic made the frame's orientation)."""
    ok, pos.obj_cell_id, pos.frame.origin = adjust_to_outside(pos.obj_cell_id, pos.frame.origin,
                                                              pos.frame.orientation.runtime)
    return ok


_NO_OFFSET = Vector3(0.0, 0.0, 0.0)
_BLOCK_OFFSETS: dict[tuple[int, int], Vector3] = {}  # get_block_offset's answers (Vector3 is immutable)


def _get_block_offset_every_time(cell_from: int, cell_to: int) -> Vector3:
    """GetBlockOffset as ACE writes it, nothing remembered (what a traced run runs)."""
    if cell_from >> BLOCK_PART_SHIFT == cell_to >> BLOCK_PART_SHIFT:
        return _NO_OFFSET
    return _block_offset(cell_from, cell_to)


@anchor("LandDefs::get_block_offset", "LandDefs.cs:GetBlockOffset")
@remembers(_get_block_offset_every_time)
def get_block_offset(cell_from: int, cell_to: int) -> Vector3:
    """The offset from cell_from's landblock to cell_to's (Python floats, see the module note).

    Raises InvalidOperationException where ACE's ``.Value`` throws: a landblock in column or row 0xFF.
    The answer depends on the two landblock ids only, so it is remembered (the transition asks
    for the same few pairs tens of thousands of times); a throwing pair is never remembered. A
    traced run computes it every time (anchors.remembers), so its trace holds blockid_to_lcoord's
    calls whatever ran before.
    """
    block_from = cell_from >> BLOCK_PART_SHIFT
    block_to = cell_to >> BLOCK_PART_SHIFT
    if block_from == block_to:
        return _NO_OFFSET
    offset = _BLOCK_OFFSETS.get((block_from, block_to))
    if offset is None:
        offset = _block_offset(cell_from, cell_to)
        if len(_BLOCK_OFFSETS) >= 4096:
            _BLOCK_OFFSETS.clear()
        _BLOCK_OFFSETS[(block_from, block_to)] = offset
    return offset


def _block_offset(cell_from: int, cell_to: int) -> Vector3:
    """GetBlockOffset as ACE writes it, for two different landblocks."""
    local_from = value_of(blockid_to_lcoord(cell_from), "LandDefs.GetBlockOffset")
    local_to = value_of(blockid_to_lcoord(cell_to), "LandDefs.GetBlockOffset")
    return Vector3((local_to[0] - local_from[0]) * SQUARE_LENGTH, (local_to[1] - local_from[1]) * SQUARE_LENGTH, 0.0)


@anchor("LandDefs::in_block", "LandDefs.cs:InBlock")
def in_block(pos: Vector3, radius) -> bool:
    if pos.x < radius or pos.y < radius:
        return False
    block_radius = BLOCK_LENGTH - radius
    return bool(pos.x < block_radius and pos.y < block_radius)


@anchor("LandDefs::blockid_to_lcoord", "LandDefs.cs:blockid_to_lcoord")
def blockid_to_lcoord(cell_id: int):
    """The land coordinate (in cells) of the landblock's south-west corner, or None past 2040."""
    x = ((cell_id >> BLOCK_PART_SHIFT & BLOCK_X_MASK) >> MAX_BLOCK_SHIFT) << LANDBLOCK_SHIFT
    y = (cell_id >> BLOCK_PART_SHIFT & BLOCK_Y_MASK) << LANDBLOCK_SHIFT
    # x, y are uint: the `< 0` tests in ACE never hold
    if x >= LAND_LENGTH or y >= LAND_LENGTH:
        return None
    return (float(x), float(y))


@anchor("LandDefs::gid_to_lcoord", "LandDefs.cs:gid_to_lcoord")
def gid_to_lcoord(cell_id: int, env_check: bool = True):
    if not inbound_valid_cellid(cell_id):
        return None
    if env_check and (cell_id & CELL_ID_MASK) >= FIRST_ENV_CELL_ID:
        return None

    x = ((cell_id >> BLOCK_PART_SHIFT & BLOCK_X_MASK) >> MAX_BLOCK_SHIFT) << LANDBLOCK_SHIFT
    y = (cell_id >> BLOCK_PART_SHIFT & BLOCK_Y_MASK) << LANDBLOCK_SHIFT

    # uint arithmetic: `-` binds before `>>`/`&`; low word 0 cannot get here (not in range)
    # (`& 0xFFFFFFFF` is wrap_u32, written out in this hot spot)
    x = (x + (((cell_id & CELL_ID_MASK) - FIRST_LAND_CELL_ID & 0xFFFFFFFF) >> LANDBLOCK_SHIFT)) & 0xFFFFFFFF
    y = (y + ((cell_id & CELL_ID_MASK) - FIRST_LAND_CELL_ID & 0xFFFFFFFF & LANDBLOCK_MASK)) & 0xFFFFFFFF

    if x >= LAND_LENGTH or y >= LAND_LENGTH:
        return None
    return (float(x), float(y))


@anchor("LandDefs::get_outside_lcoord", "LandDefs.cs:get_outside_lcoord")
def get_outside_lcoord(block_cell_id: int, _x, _y):
    """The land coordinate of the cell holding (_x, _y) relative to block_cell_id's landblock.

    Computed in _x's scalar type: ``offset.X + (float)Math.Floor(_x / CellLength)``.
    """
    cell_id = block_cell_id & CELL_ID_MASK
    if cell_in_range(cell_id):
        offset = blockid_to_lcoord(block_cell_id)
        if offset is None:
            return None
        x = offset[0] + cast_float(_x, cs_floor(_x / CELL_LENGTH))
        y = offset[1] + cast_float(_y, cs_floor(_y / CELL_LENGTH))
        if x < 0 or y < 0 or x >= LAND_LENGTH or y >= LAND_LENGTH:
            return None
        return (x, y)
    return None  # a cell id out of range


@anchor("LandDefs::cell_in_range", "LandDefs.cs:cell_in_range")
def cell_in_range(cell_id: int) -> bool:
    return (
        cell_id == BLOCK_CELL_ID
        or FIRST_LAND_CELL_ID <= cell_id <= LAST_LAND_CELL_ID
        or FIRST_ENV_CELL_ID <= cell_id <= LAST_ENV_CELL_ID
    )


@anchor("LandDefs::lcoord_to_gid", "LandDefs.cs:lcoord_to_gid", note="(int) casts as the runtime makes them")
def lcoord_to_gid(_x, _y, runtime: Runtime) -> int:
    """The cell id (as C# int: negative from landblock column 0x80 on) of a land coordinate, or 0.

    A NaN coordinate gets here from get_outside_lcoord (NaN passes its range test); mono's
    ``(int)NaN`` is int.MinValue, so the answer is 0; .NET 10's is 0, landblock 0x0000's first cell.
    """
    x = runtime.to_int32(_x)
    y = runtime.to_int32(_y)
    if x < 0 or y < 0 or x >= LAND_LENGTH or y >= LAND_LENGTH:
        return 0
    block = (x >> LANDBLOCK_SHIFT << MAX_BLOCK_SHIFT) | (y >> LANDBLOCK_SHIFT)
    cell = FIRST_LAND_CELL_ID + ((x & LANDBLOCK_MASK) << LANDBLOCK_SHIFT) + (y & LANDBLOCK_MASK)
    return wrap_i32(block << BLOCK_PART_SHIFT | cell)


@anchor("LandDefs::inbound_valid_cellid", "LandDefs.cs:inbound_valid_cellid")
def inbound_valid_cellid(block_cell_id: int) -> bool:
    """Note ACE checks only the block's x against LandLength, not y."""
    cell_id = block_cell_id & CELL_ID_MASK
    if cell_in_range(cell_id):
        block_x = ((block_cell_id >> BLOCK_PART_SHIFT & BLOCK_X_MASK) >> MAX_BLOCK_SHIFT) << LANDBLOCK_SHIFT
        if block_x < LAND_LENGTH:
            return True
    return False
