"""DatDatabase: ReadFromDat -- a DAT's records by id, as DatManager's databases hand them to DBObj (ACE.DatLoader/DatDatabase.cs).

ACE reads a record's bytes from its DAT file and unpacks it with the record type's ``Unpack``
(DatDatabase.ReadFromDat<T>, caching the result in its FileCache). Scenes carry no DAT files: a
run's database holds the bytes acconform/dat.py wrote for the scene, keyed by id, and unpacks on
request; nothing is cached across runs (a database lives for one run). An id the scene wrote no
record for reads as ACE's does in the oracle, whose databases hold the scene's records in their
FileCache and have an empty file table (``AllFiles``): GetReaderForFile finds no file, and
ReadFromDat caches and returns an empty record (``new T()``): for a landblock the scene does not
list, an empty CellLandblock (docs/oracle.md's audit).
"""

from __future__ import annotations

from ..anchors import anchor, harness
from ..errors import InvalidCastException
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
            if not isinstance(result, record_type):  # (T)result
                raise InvalidCastException(f"DAT record {file_id:08X} is a {type(result).__name__}, not a {record_type.__name__}")
            return result
        data = self.records.get(file_id)
        if data is None:
            # GetReaderForFile finds no such file (the oracle's DATs have an empty file table): ReadFromDat caches and
            # returns `new T()`
            empty = getattr(record_type, "empty", None)
            if empty is None:
                raise NotImplementedError(f"an empty {record_type.__name__} (DAT record {file_id:08X}, which the "
                                          f"scene lacks) is not ported")
            return self.file_cache.setdefault(file_id, empty(self.mode))
        kind = self.kind_of(file_id)
        if kind != record_type.__name__:
            # the oracle puts every record of the scene in the FileCache, unpacked as what it is, before any read
            raise InvalidCastException(f"DAT record {file_id:08X} is a {kind}, not a {record_type.__name__}")
        return self.file_cache.setdefault(file_id, record_type.unpack(BinaryReader(data, self.mode)))

    @staticmethod
    @harness("the kind of record an id names: the oracle's FileCache holds each scene record unpacked as what it is")
    def kind_of(file_id: int) -> str:
        """The DatLoader FileType a record of this id is (acconform/dat.py writes each kind in its retail id range)."""
        raise NotImplementedError
