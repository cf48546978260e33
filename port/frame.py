"""AFrame (Combine, GRotate, Rotate, GlobalToLocal, GlobalToLocalVec, LocalToGlobal, LocalToGlobalVec, InterpolateOrigin, InterpolateRotation, Subtract, set_heading, set_vector_heading, get_heading, set_rotate) and Position (GetOffset, LocalToLocal, LocalToGlobal, GlobalToLocalVec, GetCell, GetIndoorCell, GetOutdoorCell).

ACE's Animation/AFrame.cs and Common/Position.cs. Both are C# classes (reference types), so
they are mutable here too; their Vector3/Quaternion fields are immutable values. Copy with
`copy()` where ACE uses the copy constructor. `ToRadians`/`ToDegrees` (Extensions/FloatExtensions.cs)
are written out here because only set_heading needs them. The System.Numerics operations whose
formula differs between mono and .NET 10 are taken from the runtime the orientation was made
by (`orientation.runtime`, acconform.numerics.Runtime).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from acconform.numerics import D, MONO, Matrix4x4, Mode, Quaternion, Runtime, Vector3, cast_float, cs_fmod, cs_math, wrap_u32
from acconform.port.anchors import anchor, harness
from acconform.port.constants import CELL_LENGTH, EPSILON, QUAT_VALID_SLACK, THRESHOLD_HIGH, THRESHOLD_MED
from acconform.port import land_defs
from acconform.port.vec import normalize_check_small, zero_like

# C# literals used by the heading code, exact in float32
_F450 = 450.0
_F360 = 360.0


@anchor(None, "FloatExtensions.cs:ToRadians")
def to_radians(angle):
    """FloatExtensions.ToRadians: ``(float)(Math.PI / 180.0f * angle)`` (the product in double)."""
    return cast_float(angle, (math.pi / 180.0) * float(angle))


@anchor(None, "FloatExtensions.cs:ToDegrees")
def to_degrees(rads):
    """FloatExtensions.ToDegrees: ``(float)(180.0f / Math.PI * rads)``."""
    return cast_float(rads, (180.0 / math.pi) * float(rads))


_IDENTITY: dict = {}  # mode -> (zero Vector3, identity Quaternion), for AFrame.identity


@dataclass(slots=True, eq=False)
class AFrame:
    origin: Vector3
    orientation: Quaternion

    @staticmethod
    @anchor(None, "AFrame.cs:AFrame()", "the default constructor, in the run's mode")
    def identity(mode: Mode) -> "AFrame":
        """``new AFrame()``: origin zero, orientation identity, in the mode's scalar type (the
        mode's one zero vector and identity quaternion: both are immutable values)."""
        parts = _IDENTITY.get(mode)
        if parts is None:
            parts = _IDENTITY[mode] = (mode.vec(0, 0, 0), mode.quat(0, 0, 0, 1))
        return AFrame(*parts)

    @staticmethod
    @harness("builds an AFrame from a scene Frame record")
    def from_record(frame, mode: Mode) -> "AFrame":
        """From a scene Frame record (orientation written (w, x, y, z) as AC files do)."""
        w, x, y, z = frame.orientation
        return AFrame(mode.vec(*frame.origin), mode.quat(x, y, z, w))

    @staticmethod
    @anchor(None, "AFrame.cs:AFrame(DatLoader.Entity.Frame)", "the DAT constructor")
    def from_dat(frame) -> "AFrame":
        """The quaternion is built as mono's class whatever the run's runtime: it is only data.
        Its callers (PartArray.UpdateParts; PhysicsObj.add_child, whose holding frame UpdateChild
        combines) pass this frame as Combine's second frame, whose fields are read but whose
        runtime is never asked (the first frame's runtime computes)."""
        q = frame.orientation
        return AFrame(frame.origin, q.runtime.quaternion(q.x, q.y, q.z, q.w))

    @anchor(None, "AFrame.cs:IsValid")
    def is_valid(self) -> bool:
        """Origin.IsValid() && Orientation.IsValid() (Vector3Extensions / QuaternionExtensions):
        no NaN, and a quaternion's Length within EPSILON * 5 of 1."""
        if not self.is_valid_except_for_heading():
            return False
        q = self.orientation
        if math.isnan(q.x) or math.isnan(q.y) or math.isnan(q.z) or math.isnan(q.w):
            return False
        length = q.length()
        if math.isnan(length):
            return False
        if abs(length - type(length)(1.0)) > QUAT_VALID_SLACK:
            return False
        return True

    @anchor(None, "AFrame.cs:IsValidExceptForHeading")
    def is_valid_except_for_heading(self) -> bool:
        o = self.origin
        return not (math.isnan(o.x) or math.isnan(o.y) or math.isnan(o.z))

    @anchor(None, "AFrame.cs:AFrame(AFrame)", "the copy constructor")
    def copy(self) -> "AFrame":
        """``new AFrame(frame)``."""
        return AFrame(self.origin, self.orientation)

    @staticmethod
    @anchor("AFrame::combine", "AFrame.cs:Combine")
    def combine(a: "AFrame", b: "AFrame") -> "AFrame":
        rt = a.orientation.runtime  # System.Numerics as the run's runtime computes it
        return AFrame(a.origin + rt.transform_by_quaternion(b.origin, a.orientation), rt.quat_multiply(a.orientation, b.orientation))

    @anchor("AFrame::combine", "AFrame.cs:Combine(AFrame, AFrame, Vector3)")
    def combine_scaled(self, a: "AFrame", b: "AFrame", scale: Vector3) -> None:
        rt = a.orientation.runtime
        self.origin = a.origin + rt.transform_by_quaternion(b.origin * scale, a.orientation)
        self.orientation = rt.quat_multiply(a.orientation, b.orientation)

    @anchor("AFrame::global_to_local", "AFrame.cs:GlobalToLocal")
    def global_to_local(self, point: Vector3) -> Vector3:
        offset = point - self.origin
        return self.global_to_local_vec(offset)

    @anchor("AFrame::global_to_local_vec", "AFrame.cs:GlobalToLocalVec")
    def global_to_local_vec(self, point: Vector3) -> Vector3:
        rotate = Matrix4x4.create_from_quaternion(self.orientation).transpose()
        return self.orientation.runtime.transform_by_matrix(point, rotate)

    @anchor("AFrame::interpolate_origin", "AFrame.cs:InterpolateOrigin")
    def interpolate_origin(self, from_: "AFrame", to: "AFrame", t) -> None:
        self.origin = self.orientation.runtime.lerp(from_.origin, to.origin, t)

    @anchor("AFrame::interpolate_rotation", "AFrame.cs:InterpolateRotation")
    def interpolate_rotation(self, from_: "AFrame", to: "AFrame", t) -> None:
        self.orientation = self.orientation.runtime.quat_lerp(from_.orientation, to.orientation, t)

    @anchor("AFrame::IsQuaternionEqual", "AFrame.cs:IsQuaternionEqual")
    def is_quaternion_equal(self, frame: "AFrame") -> bool:
        return bool(self.orientation == frame.orientation)

    @anchor("AFrame::local_to_global", "AFrame.cs:LocalToGlobal")
    def local_to_global(self, point: Vector3) -> Vector3:
        return self.origin + self.local_to_global_vec(point)

    @anchor("AFrame::local_to_global_vec", "AFrame.cs:LocalToGlobalVec")
    def local_to_global_vec(self, point: Vector3) -> Vector3:
        return self.orientation.runtime.transform_by_quaternion(point, self.orientation)

    @anchor("AFrame::grotate", "AFrame.cs:GRotate")
    def grotate(self, rotation: Vector3) -> None:
        rt = self.orientation.runtime
        self.orientation = rt.quat_multiply(self.orientation, rt.quat_create_from_yaw_pitch_roll(rotation.x, rotation.y, rotation.z))
        self.orientation = rt.quat_normalize(self.orientation)

    @anchor("AFrame::rotate", "AFrame.cs:Rotate(Vector3)")
    def rotate_vec(self, rotation: Vector3) -> None:
        """ACE's overload Rotate(Vector3): the local rotation vector turned into global angles."""
        angles = self.orientation.runtime.transform_by_quaternion(rotation, self.orientation)
        self.grotate(angles)

    @anchor("AFrame::rotate", "AFrame.cs:Rotate(Quaternion)")
    def rotate(self, rotation: Quaternion) -> None:
        rt = self.orientation.runtime
        self.orientation = rt.quat_multiply(rotation, self.orientation)
        self.orientation = rt.quat_normalize(self.orientation)

    @anchor("AFrame::subtract", "AFrame.cs:Subtract")
    def subtract(self, frame: "AFrame") -> None:
        rt = self.orientation.runtime
        self.origin = self.origin - rt.transform_by_quaternion(frame.origin, frame.orientation)
        self.orientation = rt.quat_multiply(self.orientation, rt.quat_inverse(frame.orientation))

    @anchor("AFrame::get_heading", "AFrame.cs:get_heading")
    def get_heading(self):
        m = Matrix4x4.create_from_quaternion(self.orientation).m
        heading = cast_float(m[5], math.atan2(float(m[5]), float(m[4])))  # Atan2(M22, M21)
        return cs_fmod(_F450 - to_degrees(heading), _F360)

    @anchor("AFrame::get_vector_heading", "AFrame.cs:get_vector_heading")
    def get_vector_heading(self) -> Vector3:
        m = Matrix4x4.create_from_quaternion(self.orientation).m
        return Vector3(m[4], m[5], m[6])  # M21, M22, M23

    @anchor("AFrame::set_heading", "AFrame.cs:set_heading")
    def set_heading(self, degrees) -> None:
        rads = to_radians(degrees)
        m = Matrix4x4.create_from_quaternion(self.orientation).m
        heading = Vector3(
            cast_float(rads, cs_math(math.sin, float(rads))),
            cast_float(rads, cs_math(math.cos, float(rads))),
            m[6] + m[2],  # M23 + M13
        )
        self.set_vector_heading(heading)
        # ACE then computes get_heading() into an unused local; it has no effect.

    @anchor("AFrame::set_rotate", "AFrame.cs:set_rotate")
    def set_rotate(self, orientation: Quaternion) -> None:
        self.orientation = self.orientation.runtime.quat_normalize(orientation)

    @anchor("AFrame::set_vector_heading", "AFrame.cs:set_vector_heading")
    def set_vector_heading(self, heading: Vector3) -> None:
        small, normal = normalize_check_small(heading)
        if small:
            return
        z_deg = _F450 - to_degrees(cast_float(normal.y, math.atan2(float(normal.y), float(normal.x))))
        z_rot = -to_radians(cs_fmod(z_deg, _F360))
        x_rot = cast_float(normal.z, cs_math(math.asin, float(normal.z)))
        zero = type(x_rot)(0)
        self.set_rotate(self.orientation.runtime.quat_create_from_yaw_pitch_roll(x_rot, zero, z_rot))

    @anchor("AFrame::equals", "AFrame.cs:Equals", note="ACE compares the argument's orientation with itself")
    def equals(self, frame: "AFrame") -> bool:
        o, fo = self.origin, frame.origin
        if not (abs(fo.x - o.x) <= EPSILON and abs(fo.y - o.y) <= EPSILON and abs(fo.z - o.z) <= EPSILON):
            return False
        q = frame.orientation
        # ACE: Math.Abs(frame.Orientation.X - frame.Orientation.X) <= EPSILON ..., false only for NaN
        return bool(abs(q.x - q.x) <= EPSILON and abs(q.y - q.y) <= EPSILON
                    and abs(q.z - q.z) <= EPSILON and abs(q.w - q.w) <= EPSILON)


@dataclass(slots=True, eq=False)
class Position:
    obj_cell_id: int
    frame: AFrame

    @staticmethod
    @harness("builds a Position from a scene Position record")
    def from_record(pos, mode: Mode) -> "Position":
        """From a scene Position record."""
        return Position(pos.cell, AFrame.from_record(pos.frame, mode))

    @anchor(None, "Position.cs:Position(Position)", "the copy constructor")
    def copy(self) -> "Position":
        """``new Position(p)``: a new AFrame, same values."""
        return Position(self.obj_cell_id, self.frame.copy())

    @property
    def landblock(self) -> int:
        return self.obj_cell_id >> 16

    @anchor("Position::local_to_local", "Position.cs:LocalToLocal")
    def local_to_local(self, pos: "Position", offset: Vector3) -> Vector3:
        cell_offset = pos.frame.local_to_global(offset)
        block_offset = land_defs.get_block_offset(self.obj_cell_id, pos.obj_cell_id)
        return self.frame.global_to_local(block_offset + cell_offset)

    @anchor(None, "Position.cs:DetermineQuadrant")
    def determine_quadrant(self, height, position: "Position") -> int:
        """Where `position` (a missile's) is relative to this object of `height`: left or right, front or
        back, and low, medium or high (ACE.Entity.Enum.Quadrant bits)."""
        from acconform.flags import Quadrant

        hitpoint = self.local_to_local(position, zero_like(height))

        quadrant = int(Quadrant.Left if hitpoint.x < 0.0 else Quadrant.Right)

        quadrant |= Quadrant.Front if hitpoint.y >= 0.0 else Quadrant.Back

        s = type(height)
        if hitpoint.z < height * s(THRESHOLD_MED):
            quadrant |= Quadrant.Low
        elif hitpoint.z < height * s(THRESHOLD_HIGH):
            quadrant |= Quadrant.Medium
        else:
            quadrant |= Quadrant.High

        return quadrant

    @anchor("Position::local_to_global", "Position.cs:LocalToGlobal(Vector3)")
    def local_to_global(self, point: Vector3) -> Vector3:
        return self.frame.local_to_global(point)

    @anchor("Position::local_to_global", "Position.cs:LocalToGlobal(Position, Vector3)")
    def local_to_global_from(self, pos: "Position", point: Vector3) -> Vector3:
        """ACE's overload LocalToGlobal(Position pos, Vector3 point): pos's local point in self's block."""
        cell_offset = pos.frame.local_to_global(point)
        block_offset = land_defs.get_block_offset(self.obj_cell_id, pos.obj_cell_id)
        return block_offset + cell_offset

    @anchor("Position::local_to_global_vec", "Position.cs:LocalToGlobalVec")
    def local_to_global_vec(self, point: Vector3) -> Vector3:
        return self.frame.local_to_global_vec(point)

    @anchor("Position::global_to_local_vec", "Position.cs:GlobalToLocalVec")
    def global_to_local_vec(self, point: Vector3) -> Vector3:
        return self.frame.global_to_local_vec(point)

    @anchor("Position::distance", "Position.cs:Distance")
    def distance(self, pos: "Position"):
        return self.get_offset(pos).length()

    @anchor("Position::distance_squared", "Position.cs:DistanceSquared")
    def distance_squared(self, pos: "Position"):
        return self.get_offset(pos).length_squared()

    @anchor("Position::get_offset", "Position.cs:GetOffset(Position)")
    def get_offset(self, pos: "Position") -> Vector3:
        """``blockOffset + pos.Frame.Origin - Frame.Origin``, left to right."""
        block_offset = land_defs.get_block_offset(self.obj_cell_id, pos.obj_cell_id)
        return block_offset + pos.frame.origin - self.frame.origin

    @anchor("Position::get_offset", "Position.cs:GetOffset(Position, Vector3)")
    def get_offset_point(self, pos: "Position", rotation: Vector3) -> Vector3:
        """ACE's overload GetOffset(pos, rotation): `rotation` is a point local to pos."""
        block_offset = land_defs.get_block_offset(self.obj_cell_id, pos.obj_cell_id)
        return block_offset + pos.local_to_global(rotation) - self.frame.origin

    @anchor("Position::add_offset", "Position.cs:add_offset")
    def add_offset(self, offset: Vector3) -> None:
        self.frame.origin = self.frame.origin + offset

    @anchor("Position::adjust_to_outside", "Position.cs:adjust_to_outside")
    def adjust_to_outside(self) -> bool:
        return land_defs.adjust_to_outside_pos(self)

    @anchor("Position::subtract", "Position.cs:Subtract")
    def subtract(self, pos: "Position") -> AFrame:
        self.frame.subtract(pos.frame)
        return self.frame

    @staticmethod
    @anchor("Position::CylinderDistance", "Position.cs:CylinderDistance")
    def cylinder_distance(radius, height, pos: "Position", other_radius, other_height, other_pos: "Position"):
        """The gap between two upright cylinders standing at pos and other_pos (a double: ACE's
        Math.Sqrt of the float32 sum; negative when they overlap in both reach and height)."""
        offset = pos.get_offset(other_pos)
        reach = offset.length() - (radius + other_radius)

        if pos.frame.origin.z <= other_pos.frame.origin.z:
            diff_z = other_pos.frame.origin.z - (pos.frame.origin.z + height)
        else:
            diff_z = pos.frame.origin.z - (other_pos.frame.origin.z + other_height)

        if diff_z > 0 and reach > 0:
            return D(math.sqrt(diff_z * diff_z + reach * reach))
        elif diff_z < 0 and reach < 0:
            return -D(math.sqrt(diff_z * diff_z + reach * reach))
        else:
            return D(reach)

    @staticmethod
    @anchor(None, "Position.cs:CylinderDistanceNoZ")
    def cylinder_distance_no_z(radius, pos: "Position", other_radius, other_pos: "Position"):
        offset = pos.get_offset(other_pos)
        return offset.length() - (radius + other_radius)

    @anchor("Position::heading", "Position.cs:heading")
    def heading(self, position: "Position"):
        """The compass heading (degrees, 0 = +y, clockwise) from this position to `position`,
        ignoring height; 0 when they stand within EPSILON of each other in x and y."""
        dir_ = self.get_offset(position)
        dir_ = dir_.with_z(type(dir_.z)(0.0))

        small, dir_ = normalize_check_small(dir_)
        if small:
            return type(dir_.z)(0.0)

        return cs_fmod(_F450 - to_degrees(cast_float(dir_.y, math.atan2(float(dir_.y), float(dir_.x)))), _F360)

    @anchor("Position::heading_diff", "Position.cs:heading_diff")
    def heading_diff(self, position: "Position"):
        return self.heading(position) - self.frame.get_heading()

    @anchor("Position::get_cell", "Position.cs:GetCell")
    def get_cell(self, block_cell_id: int, runtime: Runtime = MONO, lscape=None) -> int:
        """`lscape` (the run's world, for AdjustCell) is needed only for an indoor cell."""
        # is originating cell indoor or outdoor? (ACE)
        if (block_cell_id & 0xFFFF) >= 0x100:
            return self.get_indoor_cell(block_cell_id, lscape)
        else:
            return self.get_outdoor_cell(block_cell_id, runtime)

    @anchor("Position::get_outdoor_cell", "Position.cs:GetOutdoorCell")
    def get_outdoor_cell(self, block_cell_id: int, runtime: Runtime = MONO) -> int:
        cell_x = runtime.to_uint32(self.frame.origin.x / CELL_LENGTH)
        cell_y = runtime.to_uint32(self.frame.origin.y / CELL_LENGTH)
        cell_id = wrap_u32(cell_x * land_defs.BLOCK_SIDE + cell_y + 1)
        return (block_cell_id & 0xFFFF0000) | cell_id

    @anchor("Position::get_indoor_cell", "Position.cs:GetIndoorCell")
    def get_indoor_cell(self, block_cell_id: int, lscape) -> int:
        """The EnvCell of the dungeon (AdjustCell) holding Frame.Origin, else ObjCellID."""
        from .adjust_cell import AdjustCell

        dungeon_id = block_cell_id >> 16

        adjust_cell = AdjustCell.get(dungeon_id, lscape)
        if adjust_cell is None:
            return self.obj_cell_id
        new_cell = adjust_cell.get_cell(self.frame.origin)
        if new_cell is None:
            return self.obj_cell_id
        return new_cell


__all__ = ["AFrame", "Position", "to_degrees", "to_radians"]
