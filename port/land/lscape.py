"""LScape: get_landblock, get_landcell -- the per-run world that stands in for ACE's static LScape/LandblockManager.

ACE keeps loaded landblocks in statics (LScape.Landblocks on the client, LandblockManager on
the server) and loads a missing one from the cell DAT. A run here builds one LScape from the
scene: every landblock the scene lists, built and PostInit'ed up front, in a dict keyed by
landblock id (0xXXYYFFFF). There is no DAT: where ACE would load a landblock the scene does not
list, DAT-less ACE throws NullReferenceException (LandblockManager's landblock has no physics
landblock), and get_landblock raises the port's NullReferenceException (port/errors.py), which
run_scene reports as the same verdict. Indoor cells (EnvCells) are not supported and
get_landcell returns None for them.
"""

from __future__ import annotations

from acconform.numerics import Mode
from acconform.port.anchors import anchor
from acconform.port.errors import NullReferenceException
from acconform.port.land import land_defs
from acconform.port.land.land_cell import LandCell
from acconform.port.land.landblock import Landblock


class LScape:
    """The scene's outdoor world for one run (no globals: make one per run)."""

    def __init__(self, scene, mode: Mode):
        self.mode = mode
        self.landblocks: dict[int, Landblock] = {}
        for record in scene.landblocks:
            landblock = Landblock(record, scene.land_height_table, mode)
            self.landblocks[record.id | 0xFFFF] = landblock
            landblock.post_init()

    @anchor("LScape::get_landblock", "LScape.cs:get_landblock")
    def get_landblock(self, block_cell_id: int) -> Landblock:
        landblock_id = block_cell_id | 0xFFFF
        landblock = self.landblocks.get(landblock_id)
        if landblock is None:
            raise NullReferenceException(
                f"landblock {landblock_id:08X} is not in the scene (ACE would read it from the DAT)")
        return landblock

    @anchor("LScape::get_landcell", "LScape.cs:get_landcell")
    def get_landcell(self, block_cell_id: int) -> LandCell | None:
        """The outdoor cell with that id. Unlike Landblock.get_landcell, ACE does not check the
        slot's id here; the slot comes from gid_to_lcoord without the env check."""
        landblock = self.get_landblock(block_cell_id)
        cell_id = block_cell_id & 0xFFFF
        if cell_id < 0x100:
            lcoord = land_defs.gid_to_lcoord(block_cell_id, False)
            if lcoord is None:
                return None
            land_cell_idx = (int(lcoord[1]) % 8) + (int(lcoord[0]) % 8) * landblock.side_cell_count
            return landblock.land_cells.get(land_cell_idx)
        # indoor cells: ACE loads the EnvCell from the DAT; scenes have none
        return None
