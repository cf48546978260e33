"""Port physics objects from scene shapes the way a run builds them: acconform/dat.py's bytes, read by
port/dat/, then ACE's DAT constructors (GfxObj(DatLoader GfxObj), BSPTree(DatLoader BSPTree, ...))."""

from __future__ import annotations

from acconform import dat
from acconform.port.dat.binary_reader import BinaryReader
from acconform.port.dat.gfx_obj import GfxObj as DatGfxObj
from acconform.port.geom.bsp import BSPTree
from acconform.port.gfx_obj import GfxObj

GFX_ID = dat.GFX_OBJ_BASE


def dat_gfx_obj(shape, mode) -> DatGfxObj:
    """The DatLoader GfxObj a BSP shape's record unpacks to."""
    return DatGfxObj.unpack(BinaryReader(dat.gfx_obj_physics(GFX_ID, shape), mode))


def gfx_obj(shape, mode, server: bool = True) -> GfxObj:
    return GfxObj.from_dat(dat_gfx_obj(shape, mode), server, mode)


def bsp_tree(shape, mode) -> BSPTree:
    g = dat_gfx_obj(shape, mode)
    return BSPTree.from_dat(g.physics_bsp, g.physics_polygons, g.vertex_array, mode)
