"""GfxObjCache: Get -- a GfxObj built once per id (ACE's Physics/Entity/GfxObjCache.cs).

ACE's cache is static; the port's lives in the run's PortalDat (`gfx_objs`), so it holds only
the scene's records and is dropped with the run: two objects naming one GfxObj id share one
GfxObj, as in ACE.

Across runs the port also remembers the GfxObj built from a record's exact bytes (`BUILT`, keyed
by the bytes, PhysicsEngine.Server and the mode): a campaign draws the same shapes again and
again, and reading and building a BSP record is a fifth of a static scene's time. The answer
cannot change: GfxObj(DatLoader GfxObj) is a function of those bytes and the Server flag, and
nothing after construction writes to a GfxObj, its BSP nodes, polygons, vertices or spheres
(ACE itself shares one GfxObj between every object that names it). A record the run does not
hold (ACE then builds from an empty GfxObj) is never remembered.
"""

from __future__ import annotations

from .anchors import anchor, harness
from .db_obj import get_gfx_obj
from .gfx_obj import GfxObj

BUILT_LIMIT = 512  # remembered GfxObjs before the memory forgets them all
BUILT: dict[tuple, GfxObj] = {}


@anchor(None, "GfxObjCache.cs:Get")
def get(portal_dat, gfx_obj_id: int) -> GfxObj:
    result = portal_dat.gfx_objs.get(gfx_obj_id)
    if result is not None:
        return result
    data = portal_dat.records.get(gfx_obj_id)
    key = (data, portal_dat.server, portal_dat.mode) if data is not None else None
    gfx_obj = BUILT.get(key) if key is not None else None
    if gfx_obj is None:
        _gfx_obj = get_gfx_obj(portal_dat, gfx_obj_id)
        gfx_obj = GfxObj.from_dat(_gfx_obj, portal_dat.server, portal_dat.mode)
        if key is not None:
            if len(BUILT) >= BUILT_LIMIT:
                BUILT.clear()
            BUILT[key] = gfx_obj
    return portal_dat.gfx_objs.setdefault(gfx_obj.id, gfx_obj)  # GetOrAdd(_gfxObj.Id, gfxObj)


@harness("empties the GfxObjs remembered across runs")
def clear_built() -> None:
    BUILT.clear()
