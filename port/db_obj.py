"""DBObj: GetEnvCell, GetLandblockInfo, GetGfxObj, GetSetup, GetAnimation, GetEnvironment -- the DAT records the physics asks for by id (ACE's Physics/Common/DBObj.cs).

GetGfxObj, GetSetup, GetAnimation and GetEnvironment read DatManager.PortalDat, GetEnvCell and GetLandblockInfo DatManager.CellDat;
a run stands in for both with the DAT databases it fills from the scene (port/dat/portal_dat.py:
the records acconform/dat.py wrote). GetEnvCell builds the physics EnvCell from the record, as
ACE's does.

Across runs the port remembers the Environment unpacked from a record's exact bytes
(`ENVIRONMENTS`, keyed by the bytes and the mode), as ACE's DatDatabase.FileCache keeps every
record it unpacked for the life of the process: a campaign's indoor scenes draw the same rooms
again and again, and unpacking an Environment (its structures' polygons and three BSP trees) was
a third of an indoor run. The answer cannot change: Environment.Unpack is a function of those
bytes (its floats read in the mode's type), and nothing reads an Environment but EnvCell's
constructor, which looks a structure up by id (port/cell/cell_struct.py remembers the CellStruct
built from it, by the same bytes). A record the run does not hold is never remembered. Where
the port answers from that memory, ACE asks its DatDatabase again (ReadFromDat, a FileCache hit);
a traced run asks it every time (anchors.remembers), so its trace holds each ReadFromDat call.
"""

from __future__ import annotations

from .anchors import anchor, harness, remembers
from .dat.animation import Animation as DatAnimation
from .dat.cell_landblock import CellLandblock
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


@anchor(None, "DBObj.cs:GetCellLandblock")
def get_cell_landblock(cell_dat, file_id: int) -> CellLandblock:
    return cell_dat.read_from_dat(file_id, CellLandblock)


@anchor(None, "DBObj.cs:GetLandblockInfo")
def get_landblock_info(cell_dat, file_id: int) -> LandblockInfo:
    return cell_dat.read_from_dat(file_id, LandblockInfo)


@anchor(None, "DBObj.cs:GetGfxObj")
def get_gfx_obj(portal_dat, file_id: int) -> DatGfxObj:
    return portal_dat.read_from_dat(file_id, DatGfxObj)


@anchor(None, "DBObj.cs:GetSetup")
def get_setup(portal_dat, file_id: int) -> SetupModel:
    return portal_dat.read_from_dat(file_id, SetupModel)


@anchor(None, "DBObj.cs:GetAnimation")
def get_animation(portal_dat, file_id: int) -> DatAnimation:
    return portal_dat.read_from_dat(file_id, DatAnimation)


ENVIRONMENTS_LIMIT = 256  # remembered Environments before the memory forgets them all
ENVIRONMENTS: dict[tuple, DatEnvironment] = {}


def _get_environment_every_time(portal_dat, file_id: int) -> DatEnvironment:
    """GetEnvironment as ACE writes it, nothing remembered (what a traced run runs)."""
    return portal_dat.read_from_dat(file_id, DatEnvironment)


@anchor(None, "DBObj.cs:GetEnvironment")
@remembers(_get_environment_every_time)
def get_environment(portal_dat, file_id: int) -> DatEnvironment:
    data = portal_dat.records.get(file_id)
    if data is None:
        return portal_dat.read_from_dat(file_id, DatEnvironment)  # an empty one, as ACE's DAT read gives
    key = (data, portal_dat.mode)
    environment = ENVIRONMENTS.get(key)
    if environment is None:
        environment = portal_dat.read_from_dat(file_id, DatEnvironment)
        if len(ENVIRONMENTS) >= ENVIRONMENTS_LIMIT:
            ENVIRONMENTS.clear()
        ENVIRONMENTS[key] = environment
    return portal_dat.file_cache.setdefault(file_id, environment)


@harness("empties the Environments remembered across runs")
def clear_environments() -> None:
    ENVIRONMENTS.clear()
