"""PortalDat: ReadFromDat -- the portal database's records by id, as DatManager.PortalDat hands them to DBObj.

ACE reads a record's bytes from client_portal.dat and unpacks it with the record type's
``Unpack`` (DatDatabase.ReadFromDat<T>, caching the result in its FileCache). Scenes carry no DAT
files: the run's PortalDat holds the bytes acconform/dat.py wrote for the scene's objects, keyed
by id, and unpacks on request. Nothing is cached across runs (a PortalDat lives for one run).
It also carries the run's stand-ins for the other statics DAT loading reads: GfxObjCache's
dictionary (`gfx_objs`) and PhysicsEngine.Instance.Server (`server`).
"""

from __future__ import annotations

from ..anchors import anchor
from .binary_reader import BinaryReader


class PortalDat:
    """The records of one run: id -> bytes; `file_cache` is DatDatabase.FileCache (id -> unpacked record)."""

    __slots__ = ("records", "file_cache", "mode", "server", "gfx_objs")

    def __init__(self, records: dict[int, bytes], mode, server: bool):
        self.records = records
        self.file_cache: dict = {}
        self.mode = mode
        self.server = server
        self.gfx_objs: dict = {}  # GfxObjCache.GfxObjs

    @anchor(None, "ACE.DatLoader/DatDatabase.cs:ReadFromDat")
    def read_from_dat(self, file_id: int, record_type):
        """``ReadFromDat<T>(fileId)``: `record_type` is T (e.g. dat.gfx_obj.GfxObj). An id with no
        record gives ``new T()``, not unpacked, as in ACE."""
        result = self.file_cache.get(file_id)
        if result is not None:
            return result
        data = self.records.get(file_id)
        if data is not None:
            obj = record_type.unpack(BinaryReader(data, self.mode))
        else:
            obj = record_type()
        return self.file_cache.setdefault(file_id, obj)
