"""Helpers for the land tests: scenes built from height/terrain grids, stand-ins for CellArray and Sphere."""

from __future__ import annotations

from acconform.numerics import EXACT
from acconform.scene import Frame, Landblock, Mover, Position, Scene, SphereRec
from acconform.port.land.lscape import LScape

WATER = 0x10 << 2  # terrain word with terrain type WaterRunning (SurfChar 1)


def scene_with(*landblocks: Landblock, table=None) -> Scene:
    first = landblocks[0].id & 0xFFFF0000 | 1
    pos = Position(first, Frame((12.0, 12.0, 0.0)))
    mover = Mover((SphereRec((0.0, 0.0, 0.5), 0.5),), pos, pos, 0.5, 0.5)
    kw = {} if table is None else {"land_height_table": table}
    return Scene(tuple(landblocks), mover, **kw)


def landblock(lb_id: int, heights=None, terrain=None) -> Landblock:
    return Landblock(lb_id, tuple(heights or (0,) * 81), tuple(terrain or (0,) * 81))


def world(*landblocks, mode=EXACT, table=None) -> LScape:
    """An LScape of these landblocks whose cell DAT holds no record (as the oracle's, the file table empty)."""
    from acconform.port.dat.cell_dat import CellDat

    return LScape(scene_with(*landblocks, table=table), mode, cell_dat=CellDat({}, mode))


class CellArrayStub:
    """The two members of CellArray the land helpers use."""

    def __init__(self):
        self.added_outside = False
        self.cells: dict[int, object] = {}

    def add_cell(self, cell_id, cell):
        self.cells[cell_id] = cell


class SphereStub:
    def __init__(self, center, radius):
        self.center = center
        self.radius = radius

