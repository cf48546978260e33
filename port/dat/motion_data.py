"""MotionData: Unpack -- a motion table entry: its animations, Bitfield, and the Velocity and Omega it gives (ACE.DatLoader Entity/MotionData.cs)."""

from __future__ import annotations

from dataclasses import dataclass, field

from acconform.numerics import Vector3

from ..anchors import anchor
from .anim_data import AnimData
from .unpackable_extensions import unpack_list_fixed

# ACE.Entity.Enum.MotionDataFlags (byte)
MOTION_DATA_HAS_VELOCITY = 0x1
MOTION_DATA_HAS_OMEGA = 0x2


@dataclass(slots=True, eq=False)
class MotionData:
    bitfield: int = 0  # bit 0: clears the modifiers (a cycle); bit 1: allowed only from the style's default substate
    flags: int = 0
    anims: list = field(default_factory=list)  # AnimData
    velocity: Vector3 | None = None  # Vector3's default (0, 0, 0) when the flag is absent
    omega: Vector3 | None = None

    @staticmethod
    @anchor(None, "ACE.DatLoader/Entity/MotionData.cs:Unpack")
    def unpack(reader) -> "MotionData":
        m = MotionData()
        zero = reader.mode.vec(0, 0, 0)
        m.velocity = m.omega = zero
        num_anims = reader.read_byte()
        m.bitfield = reader.read_byte()
        m.flags = reader.read_byte()
        reader.align_boundary()

        m.anims = unpack_list_fixed(reader, AnimData.unpack, num_anims)

        if (m.flags & MOTION_DATA_HAS_VELOCITY) != 0:
            m.velocity = reader.read_vector3()

        if (m.flags & MOTION_DATA_HAS_OMEGA) != 0:
            m.omega = reader.read_vector3()
        return m
