"""ACE's flag enums that scenes and outcomes name (ACE.Entity PhysicsState, PhysicsEngine.cs
TransientStateFlags, ObjectInfo.cs ObjectInfoState, CullMode, SetPosition.cs SetPositionFlags and
SetPositionError, ACE.Entity.Enum PlayerKillerStatus); values are ACE's.

The three flag sets are read in the port's hottest loops (``state & PhysicsState.Missile``), so
they are plain classes whose attributes are plain ints: a test is one int ``&``, where an
``enum.IntFlag`` member goes through Python-level ``__and__`` and ``__new__`` (~20x slower).
A `FlagSet` class still answers like an enum for the JSON helpers and the scene codec:
``PhysicsState["Static"]`` and iteration give `Flag` members (ints with ``.name``/``.value``),
``PhysicsState.__members__`` maps names to them, and ``flag_names``/``flags_from_names`` below
convert to and from the JSON form.
"""

from enum import IntEnum


class Flag(int):
    """One named flag of a FlagSet: an int that also has ``.name`` and ``.value`` (as an enum member)."""

    __slots__ = ()

    @property
    def value(self) -> int:
        return int(self)

    @property
    def name(self) -> str:
        return self._names[int(self)]

    def __repr__(self) -> str:
        return f"<{self._owner}.{self.name}: {int(self)}>"


class FlagSet(type):
    """Metaclass of a flag table: int class attributes, enum-like lookup by name and iteration."""

    def __new__(mcls, name, bases, ns):
        cls = super().__new__(mcls, name, bases, ns)
        names = {v: k for k, v in ns.items() if not k.startswith("_") and type(v) is int}
        member = type(f"{name}Flag", (Flag,), {"__slots__": (), "_names": names, "_owner": name})
        cls._members = {k: member(v) for v, k in sorted(names.items())}
        return cls

    @property
    def __members__(cls) -> dict:
        return dict(cls._members)

    def __getitem__(cls, name: str) -> Flag:
        return cls._members[name]

    def __iter__(cls):
        return iter(cls._members.values())

    def __len__(cls) -> int:
        return len(cls._members)

    def __contains__(cls, value) -> bool:
        return value in cls._members.values()


class PhysicsState(metaclass=FlagSet):
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


class TransientState(metaclass=FlagSet):
    Contact = 0x1
    OnWalkable = 0x2
    Sliding = 0x4
    WaterContact = 0x8
    StationaryFall = 0x10
    StationaryStop = 0x20
    StationaryStuck = 0x40
    Active = 0x80
    CheckEthereal = 0x100


class SetPositionFlags(metaclass=FlagSet):
    """SetPosition.cs SetPositionFlags: what PhysicsObj.SetPosition is asked to do."""

    Placement = 0x1
    Teleport = 0x2
    Restore = 0x4
    Slide = 0x10
    DontCreateCells = 0x20
    Scatter = 0x100
    RandomScatter = 0x200
    Line = 0x400
    SendPositionEvent = 0x1000


class SetPositionError(IntEnum):
    """SetPosition.cs SetPositionError: PhysicsObj.SetPosition's answer."""

    OK = 0x0
    GeneralFailure = 0x1
    NoValidPosition = 0x2
    NoCell = 0x3
    Collided = 0x4
    InvalidArguments = 0x100


class Quadrant(IntEnum):
    """ACE.Entity.Enum.Quadrant: where a missile struck (Position.DetermineQuadrant, AtkCollisionProfile.Location)."""

    None_ = 0x0
    High = 0x1
    Medium = 0x2
    Low = 0x4
    Left = 0x8
    Right = 0x10
    Front = 0x20
    Back = 0x40


class PlayerKillerStatus(IntEnum):
    """ACE.Entity.Enum.PlayerKillerStatus (a [Flags] enum in ACE; a player holds one of them)."""

    Undef = 0x00
    Protected = 0x01
    NPK = 0x02
    PK = 0x04
    Unprotected = 0x08
    RubberGlue = 0x10
    Free = 0x20
    PKLite = 0x40


PLAYER_KILLER_STATUS_NPK = int(PlayerKillerStatus.NPK)


class ParentLocation(IntEnum):
    """ACE.Entity.Enum.ParentLocation: the key of a Setup's HoldingLocations a child is held at (set_parent's
    location; a server sends it to the client as a wielded item's ParentLocation)."""

    None_ = 0
    RightHand = 1
    LeftHand = 2
    Shield = 3
    Belt = 4
    Quiver = 5
    Hearldry = 6  # sic, ACE's spelling
    Mouth = 7
    LeftWeapon = 8
    LeftUnarmed = 9


class ObjectInfoState(metaclass=FlagSet):
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


class InsertType(IntEnum):
    """SpherePath.InsertType: how a sphere path enters the world (SpherePath.cs)."""
    Transition = 0x0
    Placement = 0x1
    InitialPlacement = 0x2


_NAMES_OF: dict[tuple, tuple[str, ...]] = {}  # flag_names' answers: a handful of values recur in every outcome


def flag_names(enum: FlagSet, value: int) -> list[str]:
    """The member names set in `value`, in value order (the JSON form of a flag set)."""
    key = (enum, int(value))
    names = _NAMES_OF.get(key)
    if names is None:
        if len(_NAMES_OF) >= 4096:
            _NAMES_OF.clear()
        names = _NAMES_OF[key] = tuple(m.name for m in enum if m.value & value and m.value.bit_count() == 1)
    return list(names)


def flags_from_names(enum: FlagSet, names) -> int:
    """Inverse of flag_names; raises KeyError naming the first unknown name."""
    value = 0
    for n in names:
        value |= enum[n].value
    return value
