"""UnpackableExtensions: UnpackSmartArray and Unpack, the list and dictionary readers DatLoader's records use.

ACE.DatLoader's UnpackableExtensions.cs. Each reads a count, then the items (a key first for a
dictionary). A .NET Dictionary enumerates in insertion order while nothing is removed (these
never remove), which a Python dict mirrors; ``Add`` of a key it holds throws ArgumentException.
`make` builds one item from the reader (``new T(); item.Unpack(reader)``).
"""

from __future__ import annotations

from ..anchors import anchor, harness
from ..errors import ArgumentException


@harness(".NET Dictionary.Add: ArgumentException on a key already present")
def dictionary_add(d: dict, key, value) -> None:
    if key in d:
        raise ArgumentException(f"An item with the same key has already been added. Key: {key}")
    d[key] = value


@anchor(None, "ACE.DatLoader/UnpackableExtensions.cs:UnpackSmartArray(List<uint>)")
def unpack_smart_array_uint(reader) -> list[int]:
    total = reader.read_compressed_uint32()
    return [reader.read_uint32() for _ in range(total)]


@anchor(None, "ACE.DatLoader/UnpackableExtensions.cs:UnpackSmartArray(Dictionary<ushort, T>)")
def unpack_smart_array_ushort_dict(reader, make) -> dict:
    value: dict = {}
    total = reader.read_compressed_uint32()
    for _ in range(total):
        key = reader.read_uint16()
        item = make(reader)
        dictionary_add(value, key, item)
    return value


@anchor(None, "ACE.DatLoader/UnpackableExtensions.cs:Unpack(List<T>)")
def unpack_list(reader, make) -> list:
    total = reader.read_uint32()
    return [make(reader) for _ in range(total)]


@anchor(None, "ACE.DatLoader/UnpackableExtensions.cs:Unpack(List<T>, uint fixedQuantity)")
def unpack_list_fixed(reader, make, fixed_quantity: int) -> list:
    return [make(reader) for _ in range(fixed_quantity)]


@anchor(None, "ACE.DatLoader/UnpackableExtensions.cs:Unpack(Dictionary<ushort, T>, uint fixedQuantity)")
def unpack_ushort_dict_fixed(reader, make, fixed_quantity: int) -> dict:
    value: dict = {}
    for _ in range(fixed_quantity):
        key = reader.read_uint16()
        item = make(reader)
        dictionary_add(value, key, item)
    return value


@anchor(None, "ACE.DatLoader/UnpackableExtensions.cs:Unpack(Dictionary<int, T>)")
def unpack_int_dict(reader, make) -> dict:
    value: dict = {}
    total = reader.read_int32()
    for _ in range(total):
        key = reader.read_int32()
        item = make(reader)
        dictionary_add(value, key, item)
    return value


@anchor(None, "ACE.DatLoader/UnpackableExtensions.cs:Unpack(Dictionary<uint, T>)")
def unpack_uint_dict(reader, make) -> dict:
    value: dict = {}
    total = reader.read_uint32()
    for _ in range(total):
        key = reader.read_uint32()
        item = make(reader)
        dictionary_add(value, key, item)
    return value


@anchor(None, "ACE.DatLoader/UnpackableExtensions.cs:Unpack(Dictionary<uint, Dictionary<uint, T>>)")
def unpack_uint_dict_of_dicts(reader, make) -> dict:
    value: dict = {}
    total = reader.read_uint32()
    for _ in range(total):
        key = reader.read_uint32()
        values = unpack_uint_dict(reader, make)
        dictionary_add(value, key, values)
    return value


@anchor(None, "ACE.DatLoader/UnpackableExtensions.cs:UnpackPackedHashTable(Dictionary<uint, uint>)")
def unpack_packed_hash_table_uint(reader) -> dict:
    value: dict = {}
    total_objects = reader.read_uint16()
    reader.read_uint16()  # bucketSize, unused

    for _ in range(total_objects):
        key = reader.read_uint32()
        dictionary_add(value, key, reader.read_uint32())
    return value
