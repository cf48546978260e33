"""PortalDat: the run's DatManager.PortalDat (a PortalDatDatabase: ACE.DatLoader/PortalDatDatabase.cs).

A DatDatabase (port/dat/dat_database.py) of the portal records acconform/dat.py wrote for the
scene (its objects' and the mover's GfxObjs and Setups, its Environments). It also carries the
run's stand-ins for the other statics DAT loading reads: GfxObjCache's dictionary (`gfx_objs`)
and PhysicsEngine.Instance.Server (`server`).
"""

from __future__ import annotations

from .dat_database import DatDatabase


class PortalDat(DatDatabase):
    __slots__ = ("server", "gfx_objs")

    def __init__(self, records: dict[int, bytes], mode, server: bool):
        super().__init__(records, mode)
        self.server = server
        self.gfx_objs: dict = {}  # GfxObjCache.GfxObjs
