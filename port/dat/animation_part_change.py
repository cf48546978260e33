"""AnimationPartChange: Unpack, Unpack(reader, partIndex) -- a part index and the GfxObj replacing it (ACE.DatLoader Entity/AnimationPartChange.cs)."""

from __future__ import annotations

from dataclasses import dataclass

from ..anchors import anchor

GFX_OBJ_TYPE = 0x01000000  # ReadAsDataIDOfKnownType's known type: a GfxObj id


@dataclass(slots=True)
class AnimationPartChange:
    part_index: int = 0  # a byte
    part_id: int = 0

    @staticmethod
    @anchor(None, "ACE.DatLoader/Entity/AnimationPartChange.cs:Unpack")
    def unpack(reader) -> "AnimationPartChange":
        c = AnimationPartChange()
        c.part_index = reader.read_byte()
        c.part_id = reader.read_as_data_id_of_known_type(GFX_OBJ_TYPE)
        return c

    @staticmethod
    @anchor(None, "ACE.DatLoader/Entity/AnimationPartChange.cs:Unpack(BinaryReader, ushort)")
    def unpack_with_index(reader, part_index: int) -> "AnimationPartChange":
        c = AnimationPartChange()
        c.part_index = part_index & 255
        c.part_id = reader.read_as_data_id_of_known_type(GFX_OBJ_TYPE)
        return c
