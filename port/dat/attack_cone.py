"""AttackCone: Unpack -- an AttackHook's cone: part index, left and right (x, y), radius, height (ACE.DatLoader Entity/AttackCone.cs)."""

from __future__ import annotations

from dataclasses import dataclass

from ..anchors import anchor


@dataclass(slots=True)
class AttackCone:
    part_index: int = 0
    left_x: object = 0.0
    left_y: object = 0.0
    right_x: object = 0.0
    right_y: object = 0.0
    radius: object = 0.0
    height: object = 0.0

    @staticmethod
    @anchor(None, "ACE.DatLoader/Entity/AttackCone.cs:Unpack")
    def unpack(reader) -> "AttackCone":
        c = AttackCone()
        c.part_index = reader.read_uint32()
        c.left_x = reader.read_single()
        c.left_y = reader.read_single()
        c.right_x = reader.read_single()
        c.right_y = reader.read_single()
        c.radius = reader.read_single()
        c.height = reader.read_single()
        return c
