"""Frame: Unpack -- an origin and a quaternion written (w, x, y, z) (ACE.DatLoader Entity/Frame.cs)."""

from __future__ import annotations

from dataclasses import dataclass

from acconform.numerics import Quaternion, Vector3

from ..anchors import anchor


@dataclass(slots=True)
class Frame:
    origin: Vector3 | None = None
    orientation: Quaternion | None = None

    @staticmethod
    @anchor(None, "ACE.DatLoader/Entity/Frame.cs:Unpack")
    def unpack(reader) -> "Frame":
        f = Frame()
        f.origin = reader.read_vector3()
        qw = reader.read_single()
        qx = reader.read_single()
        qy = reader.read_single()
        qz = reader.read_single()
        f.orientation = reader.mode.quat(qx, qy, qz, qw)  # new Quaternion(qx, qy, qz, qw), in the run's runtime
        return f

    @staticmethod
    @anchor(None, "ACE.DatLoader/Entity/Frame.cs:Frame()")
    def empty(mode) -> "Frame":
        """``new Frame()``: origin zero, orientation identity."""
        return Frame(mode.vec(0, 0, 0), mode.quat(0, 0, 0, 1))
