"""GfxObjCache: Get -- a GfxObj built once per id (ACE's Physics/Entity/GfxObjCache.cs).

ACE's cache is static; the port's lives in the run's PortalDat (`gfx_objs`), so it holds only
the scene's records and is dropped with the run: two objects naming one GfxObj id share one
GfxObj, as in ACE.
"""

from __future__ import annotations

from .anchors import anchor
from .db_obj import get_gfx_obj
from .gfx_obj import GfxObj


@anchor(None, "GfxObjCache.cs:Get")
def get(portal_dat, gfx_obj_id: int) -> GfxObj:
    result = portal_dat.gfx_objs.get(gfx_obj_id)
    if result is not None:
        return result
    _gfx_obj = get_gfx_obj(portal_dat, gfx_obj_id)
    gfx_obj = GfxObj.from_dat(_gfx_obj, portal_dat.server, portal_dat.mode)
    return portal_dat.gfx_objs.setdefault(_gfx_obj.id, gfx_obj)  # GetOrAdd(_gfxObj.Id, gfxObj)
