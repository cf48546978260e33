"""DBObj: GetEnvCell, GetLandblockInfo, GetGfxObj, GetSetup, GetEnvironment -- the DAT records the physics asks for by id (ACE's Physics/Common/DBObj.cs).

GetGfxObj, GetSetup and GetEnvironment read DatManager.PortalDat, GetEnvCell and GetLandblockInfo DatManager.CellDat;
a run stands in for both with the DAT databases it fills from the scene (port/dat/portal_dat.py:
the records acconform/dat.py wrote). GetEnvCell builds the physics EnvCell from the record, as
ACE's does.
"""

from __future__ import annotations

from .anchors import anchor
from .dat.env_cell import EnvCell as DatEnvCell
from .dat.environment import Environment as DatEnvironment
from .dat.gfx_obj import GfxObj as DatGfxObj
from .dat.landblock_info import LandblockInfo
from .dat.setup_model import SetupModel


@anchor(None, "DBObj.cs:GetEnvCell")
def get_env_cell(cell_dat, portal_dat, file_id: int):
    """``new EnvCell(DatManager.CellDat.ReadFromDat<EnvCell>(id))``; `portal_dat` is what the
    constructor's GetEnvironment reads."""
    from .cell.env_cell import EnvCell

    env_cell = cell_dat.read_from_dat(file_id, DatEnvCell)

    return EnvCell.from_dat(env_cell, portal_dat)


@anchor(None, "DBObj.cs:GetLandblockInfo")
def get_landblock_info(cell_dat, file_id: int) -> LandblockInfo:
    return cell_dat.read_from_dat(file_id, LandblockInfo)


@anchor(None, "DBObj.cs:GetGfxObj")
def get_gfx_obj(portal_dat, file_id: int) -> DatGfxObj:
    return portal_dat.read_from_dat(file_id, DatGfxObj)


@anchor(None, "DBObj.cs:GetSetup")
def get_setup(portal_dat, file_id: int) -> SetupModel:
    return portal_dat.read_from_dat(file_id, SetupModel)


@anchor(None, "DBObj.cs:GetEnvironment")
def get_environment(portal_dat, file_id: int) -> DatEnvironment:
    return portal_dat.read_from_dat(file_id, DatEnvironment)
