"""The outcome: what one transition left behind, read the same way from the port and from ACE.

Format ``acconform.outcome/1``. Fields mirror ACE's objects after PhysicsObj.transition's
steps (FindValidPosition and its set-up): SpherePath.CurPos/CurCell, ObjectInfo.State, the
CollisionInfo fields, the mover's velocity (ObjectInfo.StopVelocity zeroes it), and a few
SpherePath fields that expose the transition's own state. `error` holds what a side raised
(ACE exception or port exception) as a verdict; the other fields are then defaults.
"""

from __future__ import annotations

from dataclasses import dataclass, fields

from .codec import Reader, write_f32, write_id, write_vec
from .flags import ObjectInfoState, flag_names
from .scene import Frame, IDENTITY, Vec3, check_format

FORMAT = "acconform.outcome/1"
ZERO: Vec3 = (0.0, 0.0, 0.0)


def _vec_nf(r: Reader) -> Vec3:
    a, b, c = (x.f32(allow_nonfinite=True) for x in r.list(count=3))
    return (a, b, c)


@dataclass(frozen=True, slots=True)
class ContactPlaneState:
    valid: bool = False
    cell: int = 0
    is_water: bool = False
    normal: Vec3 = ZERO
    d: float = 0.0

    def to_json(self):
        return {"valid": self.valid, "cell": write_id(self.cell), "is_water": self.is_water,
                "normal": write_vec(self.normal), "d": write_f32(self.d)}

    @staticmethod
    def from_json(r: Reader) -> "ContactPlaneState":
        r.obj({"valid", "cell", "is_water", "normal", "d"})
        return ContactPlaneState(r["valid"].bool_(), r["cell"].id_(), r["is_water"].bool_(),
                                 _vec_nf(r["normal"]), r["d"].f32(allow_nonfinite=True))


@dataclass(frozen=True, slots=True)
class NormalState:
    valid: bool = False
    vector: Vec3 = ZERO

    def to_json(self):
        return {"valid": self.valid, "vector": write_vec(self.vector)}

    @staticmethod
    def from_json(r: Reader) -> "NormalState":
        r.obj({"valid", "vector"})
        return NormalState(r["valid"].bool_(), _vec_nf(r["vector"]))


@dataclass(frozen=True, slots=True)
class Outcome:
    ok: bool = False  # FindValidPosition's answer (PhysicsObj.transition returns null when False)
    cell: int = 0  # SpherePath.CurCell id
    origin: Vec3 = ZERO  # SpherePath.CurPos.Frame
    orientation: tuple[float, float, float, float] = IDENTITY
    object_info_state: int = 0
    contact_plane: ContactPlaneState = ContactPlaneState()
    last_known_contact_plane: ContactPlaneState = ContactPlaneState()
    collision_normal: NormalState = NormalState()
    sliding_normal: NormalState = NormalState()
    collided_with_environment: bool = False
    frames_stationary_fall: int = 0
    velocity: Vec3 = ZERO  # the mover's velocity afterwards (StopVelocity zeroes it)
    check_cell: int = 0  # SpherePath.CheckCell id (0 when none)
    walkable: bool = False  # SpherePath.Walkable is set
    step_up: bool = False  # SpherePath.StepUp
    neg_poly_hit: bool = False  # SpherePath.NegPolyHit
    error: str | None = None

    @property
    def frame(self) -> Frame:
        return Frame(self.origin, self.orientation)

    def to_json(self):
        d = {"format": FORMAT}
        for f in fields(self):
            v = getattr(self, f.name)
            if f.name in ("cell", "check_cell"):
                v = write_id(v)
            elif f.name in ("origin", "orientation", "velocity"):
                v = write_vec(v)
            elif f.name == "object_info_state":
                v = flag_names(ObjectInfoState, v)
            elif hasattr(v, "to_json"):
                v = v.to_json()
            d[f.name] = v
        return d

    @staticmethod
    def from_json(doc, path: str = "") -> "Outcome":
        r = Reader(doc, path)
        names = {f.name for f in fields(Outcome)}
        r.obj(names | {"format"})
        check_format(r, FORMAT)
        kw = {}
        for name in names:
            if not r.has(name):
                if name == "error":
                    continue
                r[name]  # raises InvalidScene: missing required field
            x = r[name]
            if name in ("cell", "check_cell"):
                kw[name] = x.id_()
            elif name in ("origin", "velocity"):
                kw[name] = _vec_nf(x)
            elif name == "orientation":
                kw[name] = tuple(c.f32(allow_nonfinite=True) for c in x.list(count=4))
            elif name == "object_info_state":
                kw[name] = x.flags(ObjectInfoState)
            elif name in ("contact_plane", "last_known_contact_plane"):
                kw[name] = ContactPlaneState.from_json(x)
            elif name in ("collision_normal", "sliding_normal"):
                kw[name] = NormalState.from_json(x)
            elif name == "frames_stationary_fall":
                kw[name] = x.int_(0, 3)
            elif name == "error":
                kw[name] = x.str_()
            else:
                kw[name] = x.bool_()
        return Outcome(**kw)
