"""ACE's flag enums that scenes and outcomes name (ACE.Entity PhysicsState, PhysicsEngine.cs
TransientStateFlags, ObjectInfo.cs ObjectInfoState, CullMode); values are ACE's."""

from enum import IntEnum, IntFlag


class PhysicsState(IntFlag):
    Static = 0x00000001
    Unused1 = 0x00000002
    Ethereal = 0x00000004
    ReportCollisions = 0x00000008
    IgnoreCollisions = 0x00000010
    NoDraw = 0x00000020
    Missile = 0x00000040
    Pushable = 0x00000080
    AlignPath = 0x00000100
    PathClipped = 0x00000200
    Gravity = 0x00000400
    LightingOn = 0x00000800
    ParticleEmitter = 0x00001000
    Unused2 = 0x00002000
    Hidden = 0x00004000
    ScriptedCollision = 0x00008000
    HasPhysicsBSP = 0x00010000
    Inelastic = 0x00020000
    HasDefaultAnim = 0x00040000
    HasDefaultScript = 0x00080000
    Cloaked = 0x00100000
    ReportCollisionsAsEnvironment = 0x00200000
    EdgeSlide = 0x00400000
    Sledding = 0x00800000
    Frozen = 0x01000000


class TransientState(IntFlag):
    Contact = 0x1
    OnWalkable = 0x2
    Sliding = 0x4
    WaterContact = 0x8
    StationaryFall = 0x10
    StationaryStop = 0x20
    StationaryStuck = 0x40
    Active = 0x80
    CheckEthereal = 0x100


class ObjectInfoState(IntFlag):
    Contact = 0x1
    OnWalkable = 0x2
    IsViewer = 0x4
    PathClipped = 0x8
    FreeRotate = 0x10
    PerfectClip = 0x40
    IsImpenetrable = 0x80
    IsPlayer = 0x100
    EdgeSlide = 0x200
    IgnoreCreatures = 0x400
    IsPK = 0x800
    IsPKLite = 0x1000


class CullMode(IntEnum):
    """A polygon's SidesType."""

    Landblock = 0x0
    None_ = 0x1
    Clockwise = 0x2
    CounterClockwise = 0x3


class TransitionState(IntEnum):
    Invalid = 0
    OK = 1
    Collided = 2
    Adjusted = 3
    Slid = 4


def flag_names(enum: type[IntFlag], value: int) -> list[str]:
    """The member names set in `value`, in value order (the JSON form of a flag set)."""
    return [m.name for m in enum if m.value & value and m.value.bit_count() == 1]


def flags_from_names(enum: type[IntFlag], names) -> int:
    """Inverse of flag_names; raises KeyError naming the first unknown name."""
    value = 0
    for n in names:
        value |= enum[n].value
    return value
