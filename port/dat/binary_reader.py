"""BinaryReader and BinaryReaderExtensions: AlignBoundary, ReadCompressedUInt32, ReadAsDataIDOfKnownType, ReadVector3 (and the .NET BinaryReader reads they use).

ACE.DatLoader's BinaryReaderExtensions.cs over System.IO.BinaryReader (little-endian). Floats are
read as the float32 the DAT holds and handed to the run's mode (exact: float32, fast: float64 of
the same value).
"""

from __future__ import annotations

import struct

from acconform.numerics import Mode, Vector3

from ..anchors import anchor, harness
from ..errors import EndOfStreamException

_U8 = struct.Struct("<B")
_U16 = struct.Struct("<H")
_I16 = struct.Struct("<h")
_U32 = struct.Struct("<I")
_I32 = struct.Struct("<i")
_F32 = struct.Struct("<f")
_F32x3 = struct.Struct("<3f")


class BinaryReader:
    """System.IO.BinaryReader over a byte string; `position` is BaseStream.Position."""

    __slots__ = ("data", "position", "mode")

    def __init__(self, data: bytes, mode: Mode):
        self.data = data
        self.position = 0
        self.mode = mode

    def _take(self, st: struct.Struct):
        if self.position + st.size > len(self.data):
            raise EndOfStreamException("Unable to read beyond the end of the stream.")
        v = st.unpack_from(self.data, self.position)
        self.position += st.size
        return v

    @harness(".NET BinaryReader.ReadByte")
    def read_byte(self) -> int:
        return self._take(_U8)[0]

    @harness(".NET BinaryReader.ReadBytes")
    def read_bytes(self, count: int) -> bytes:
        b = self.data[self.position:self.position + count]
        self.position += len(b)
        return bytes(b)

    @harness(".NET BinaryReader.ReadUInt16")
    def read_uint16(self) -> int:
        return self._take(_U16)[0]

    @harness(".NET BinaryReader.ReadInt16")
    def read_int16(self) -> int:
        return self._take(_I16)[0]

    @harness(".NET BinaryReader.ReadUInt32")
    def read_uint32(self) -> int:
        return self._take(_U32)[0]

    @harness(".NET BinaryReader.ReadInt32")
    def read_int32(self) -> int:
        return self._take(_I32)[0]

    @harness(".NET BinaryReader.ReadSingle, in the run's mode")
    def read_single(self):
        return self.mode.scalar(self._take(_F32)[0])

    @anchor(None, "ACE.DatLoader/BinaryReaderExtensions.cs:AlignBoundary")
    def align_boundary(self) -> None:
        """To the next DWORD boundary of the record's stream (a position past the end is allowed:
        the next read fails)."""
        align_delta = self.position % 4

        if align_delta != 0:
            self.position += 4 - align_delta

    @anchor(None, "ACE.DatLoader/BinaryReaderExtensions.cs:ReadCompressedUInt32")
    def read_compressed_uint32(self) -> int:
        b0 = self.read_byte()
        if (b0 & 0x80) == 0:
            return b0
        b1 = self.read_byte()
        if (b0 & 0x40) == 0:
            return ((b0 & 0x7F) << 8) | b1
        s = self.read_uint16()
        return (((((b0 & 0x3F) << 8) | b1) << 16) | s) & 0xFFFFFFFF

    @anchor(None, "ACE.DatLoader/BinaryReaderExtensions.cs:ReadAsDataIDOfKnownType")
    def read_as_data_id_of_known_type(self, known_type: int) -> int:
        """A ushort, or two when its top bit is set (the high word's low 14 bits, then the low word),
        added to the known type (uint arithmetic)."""
        value = self.read_uint16()

        if (value & 0x8000) != 0:
            lower = self.read_uint16()
            higher = (value & 0x3FFF) << 16

            return (known_type + (higher | lower)) & 0xFFFFFFFF

        return (known_type + value) & 0xFFFFFFFF

    @anchor(None, "ACE.DatLoader/BinaryReaderExtensions.cs:ReadVector3")
    def read_vector3(self) -> Vector3:
        x, y, z = self._take(_F32x3)
        s = self.mode.scalar
        return Vector3(s(x), s(y), s(z))
