"""DatDatabase: ReadFromDat -- a DAT's records by id, as DatManager's databases hand them to DBObj (ACE.DatLoader/DatDatabase.cs).

ACE reads a record's bytes from its DAT file and unpacks it with the record type's ``Unpack``
(DatDatabase.ReadFromDat<T>, caching the result in its FileCache). Scenes carry no DAT files: a
run's database holds the bytes acconform/dat.py wrote for the scene, keyed by id, and unpacks on
request; nothing is cached across runs (a database lives for one run). An id the scene wrote no
record for throws NullReferenceException, as ACE's does in the oracle: its databases there have a
FileCache and no file table (``AllFiles``), so ReadFromDat meets null in GetReaderForFile -- the
same verdict as a landblock the scene does not list (docs/oracle.md's audit).
"""

from __future__ import annotations

from ..anchors import anchor
from ..errors import NullReferenceException
from .binary_reader import BinaryReader


class DatDatabase:
    """The records of one run: id -> bytes; `file_cache` is DatDatabase.FileCache (id -> unpacked record)."""

    __slots__ = ("records", "file_cache", "mode")

    def __init__(self, records: dict[int, bytes], mode):
        self.records = records
        self.file_cache: dict = {}
        self.mode = mode

    @anchor(None, "ACE.DatLoader/DatDatabase.cs:ReadFromDat")
    def read_from_dat(self, file_id: int, record_type):
        """``ReadFromDat<T>(fileId)``: `record_type` is T (e.g. dat.gfx_obj.GfxObj)."""
        result = self.file_cache.get(file_id)
        if result is not None:
            return result
        data = self.records.get(file_id)
        if data is None:  # GetReaderForFile: AllFiles.TryGetValue on the oracle's null file table
            raise NullReferenceException(f"DAT record {file_id:08X} is not in the scene (ACE's DatDatabase has no file table)")
        return self.file_cache.setdefault(file_id, record_type.unpack(BinaryReader(data, self.mode)))
