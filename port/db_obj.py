"""DBObj: GetGfxObj, GetSetup -- the DAT records the physics asks for by id (ACE's Physics/Common/DBObj.cs).

Both read DatManager.PortalDat, which a run stands in with port/dat/portal_dat.PortalDat (the
records acconform/dat.py wrote for the scene).
"""

from __future__ import annotations

from .anchors import anchor
from .dat.gfx_obj import GfxObj as DatGfxObj
from .dat.setup_model import SetupModel


@anchor(None, "DBObj.cs:GetGfxObj")
def get_gfx_obj(portal_dat, file_id: int) -> DatGfxObj:
    return portal_dat.read_from_dat(file_id, DatGfxObj)


@anchor(None, "DBObj.cs:GetSetup")
def get_setup(portal_dat, file_id: int) -> SetupModel:
    return portal_dat.read_from_dat(file_id, SetupModel)
