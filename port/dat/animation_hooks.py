"""The AnimationHook subclasses DatLoader reads (ACE.DatLoader Entity/AnimationHooks/*.cs): each Unpack reads the base's type and direction, then its own fields.

One module for ACE's folder of 24 small classes (each file holds one class of a few lines);
`HOOK_CLASSES` is AnimationHook.ReadHook's switch: the class made for each hook type
(AnimationDone and DefaultScript make a plain AnimationHook; CreateBlockingParticle is a
CreateParticleHook with no field of its own). ACE's physics reads none of these fields
(port/dat/animation_hook.py says what it does with hooks); they are read so that a frame's
later bytes are where ACE reads them.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from acconform.numerics import Vector3

from ..anchors import anchor
from .animation_hook import AnimationHook, AnimationHookType
from .animation_part_change import AnimationPartChange
from .attack_cone import AttackCone
from .frame import Frame


@dataclass(slots=True, eq=False)
class SoundHook(AnimationHook):
    id: int = 0

    @anchor(None, "ACE.DatLoader/Entity/AnimationHooks/SoundHook.cs:Unpack")
    def unpack(self, reader) -> None:
        AnimationHook.unpack(self, reader)
        self.id = reader.read_uint32()


@dataclass(slots=True, eq=False)
class SoundTableHook(AnimationHook):
    sound_type: int = 0

    @anchor(None, "ACE.DatLoader/Entity/AnimationHooks/SoundTableHook.cs:Unpack")
    def unpack(self, reader) -> None:
        AnimationHook.unpack(self, reader)
        self.sound_type = reader.read_uint32()


@dataclass(slots=True, eq=False)
class AttackHook(AnimationHook):
    attack_cone: AttackCone = field(default_factory=AttackCone)

    @anchor(None, "ACE.DatLoader/Entity/AnimationHooks/AttackHook.cs:Unpack")
    def unpack(self, reader) -> None:
        AnimationHook.unpack(self, reader)
        self.attack_cone = AttackCone.unpack(reader)


@dataclass(slots=True, eq=False)
class ReplaceObjectHook(AnimationHook):
    ap_change: AnimationPartChange = field(default_factory=AnimationPartChange)

    @anchor(None, "ACE.DatLoader/Entity/AnimationHooks/ReplaceObjectHook.cs:Unpack")
    def unpack(self, reader) -> None:
        AnimationHook.unpack(self, reader)
        # The structure of AnimationPartChange here is slightly different ... read in the 2-byte PartIndex (ACE)
        ap_change_part_index = reader.read_uint16()
        self.ap_change = AnimationPartChange.unpack_with_index(reader, ap_change_part_index)


@dataclass(slots=True, eq=False)
class EtherealHook(AnimationHook):
    ethereal: int = 0

    @anchor(None, "ACE.DatLoader/Entity/AnimationHooks/EtherealHook.cs:Unpack")
    def unpack(self, reader) -> None:
        AnimationHook.unpack(self, reader)
        self.ethereal = reader.read_int32()


@dataclass(slots=True, eq=False)
class TransparentPartHook(AnimationHook):
    part: int = 0
    start: object = 0.0
    end: object = 0.0
    time: object = 0.0

    @anchor(None, "ACE.DatLoader/Entity/AnimationHooks/TransparentPartHook.cs:Unpack")
    def unpack(self, reader) -> None:
        AnimationHook.unpack(self, reader)
        self.part = reader.read_uint32()
        self.start = reader.read_single()
        self.end = reader.read_single()
        self.time = reader.read_single()


@dataclass(slots=True, eq=False)
class LuminousHook(AnimationHook):
    start: object = 0.0
    end: object = 0.0
    time: object = 0.0

    @anchor(None, "ACE.DatLoader/Entity/AnimationHooks/LuminousHook.cs:Unpack")
    def unpack(self, reader) -> None:
        AnimationHook.unpack(self, reader)
        self.start = reader.read_single()
        self.end = reader.read_single()
        self.time = reader.read_single()


@dataclass(slots=True, eq=False)
class LuminousPartHook(AnimationHook):
    part: int = 0
    start: object = 0.0
    end: object = 0.0
    time: object = 0.0

    @anchor(None, "ACE.DatLoader/Entity/AnimationHooks/LuminousPartHook.cs:Unpack")
    def unpack(self, reader) -> None:
        AnimationHook.unpack(self, reader)
        self.part = reader.read_uint32()
        self.start = reader.read_single()
        self.end = reader.read_single()
        self.time = reader.read_single()


@dataclass(slots=True, eq=False)
class DiffuseHook(AnimationHook):
    start: object = 0.0
    end: object = 0.0
    time: object = 0.0

    @anchor(None, "ACE.DatLoader/Entity/AnimationHooks/DiffuseHook.cs:Unpack")
    def unpack(self, reader) -> None:
        AnimationHook.unpack(self, reader)
        self.start = reader.read_single()
        self.end = reader.read_single()
        self.time = reader.read_single()


@dataclass(slots=True, eq=False)
class DiffusePartHook(AnimationHook):
    part: int = 0
    start: object = 0.0
    end: object = 0.0
    time: object = 0.0

    @anchor(None, "ACE.DatLoader/Entity/AnimationHooks/DiffusePartHook.cs:Unpack")
    def unpack(self, reader) -> None:
        AnimationHook.unpack(self, reader)
        self.part = reader.read_uint32()
        self.start = reader.read_single()
        self.end = reader.read_single()
        self.time = reader.read_single()


@dataclass(slots=True, eq=False)
class ScaleHook(AnimationHook):
    end: object = 0.0
    time: object = 0.0

    @anchor(None, "ACE.DatLoader/Entity/AnimationHooks/ScaleHook.cs:Unpack")
    def unpack(self, reader) -> None:
        AnimationHook.unpack(self, reader)
        self.end = reader.read_single()
        self.time = reader.read_single()


@dataclass(slots=True, eq=False)
class CreateParticleHook(AnimationHook):
    emitter_info_id: int = 0
    part_index: int = 0
    offset: Frame = field(default_factory=Frame)
    emitter_id: int = 0

    @anchor(None, "ACE.DatLoader/Entity/AnimationHooks/CreateParticleHook.cs:Unpack")
    def unpack(self, reader) -> None:
        AnimationHook.unpack(self, reader)
        self.emitter_info_id = reader.read_uint32()
        self.part_index = reader.read_uint32()
        self.offset = Frame.unpack(reader)
        self.emitter_id = reader.read_uint32()


@dataclass(slots=True, eq=False)
class DestroyParticleHook(AnimationHook):
    emitter_id: int = 0

    @anchor(None, "ACE.DatLoader/Entity/AnimationHooks/DestroyParticleHook.cs:Unpack")
    def unpack(self, reader) -> None:
        AnimationHook.unpack(self, reader)
        self.emitter_id = reader.read_uint32()


@dataclass(slots=True, eq=False)
class StopParticleHook(AnimationHook):
    emitter_id: int = 0

    @anchor(None, "ACE.DatLoader/Entity/AnimationHooks/StopParticleHook.cs:Unpack")
    def unpack(self, reader) -> None:
        AnimationHook.unpack(self, reader)
        self.emitter_id = reader.read_uint32()


@dataclass(slots=True, eq=False)
class NoDrawHook(AnimationHook):
    no_draw: int = 0

    @anchor(None, "ACE.DatLoader/Entity/AnimationHooks/NoDrawHook.cs:Unpack")
    def unpack(self, reader) -> None:
        AnimationHook.unpack(self, reader)
        self.no_draw = reader.read_uint32()


@dataclass(slots=True, eq=False)
class DefaultScriptPartHook(AnimationHook):
    part_index: int = 0

    @anchor(None, "ACE.DatLoader/Entity/AnimationHooks/DefaultScriptPartHook.cs:Unpack")
    def unpack(self, reader) -> None:
        AnimationHook.unpack(self, reader)
        self.part_index = reader.read_uint32()


@dataclass(slots=True, eq=False)
class CallPESHook(AnimationHook):
    pes: int = 0
    pause: object = 0.0

    @anchor(None, "ACE.DatLoader/Entity/AnimationHooks/CallPESHook.cs:Unpack")
    def unpack(self, reader) -> None:
        AnimationHook.unpack(self, reader)
        self.pes = reader.read_uint32()
        self.pause = reader.read_single()


@dataclass(slots=True, eq=False)
class TransparentHook(AnimationHook):
    start: object = 0.0
    end: object = 0.0
    time: object = 0.0

    @anchor(None, "ACE.DatLoader/Entity/AnimationHooks/TransparentHook.cs:Unpack")
    def unpack(self, reader) -> None:
        AnimationHook.unpack(self, reader)
        self.start = reader.read_single()
        self.end = reader.read_single()
        self.time = reader.read_single()


@dataclass(slots=True, eq=False)
class SoundTweakedHook(AnimationHook):
    sound_id: int = 0
    priority: object = 0.0
    probability: object = 0.0
    volume: object = 0.0

    @anchor(None, "ACE.DatLoader/Entity/AnimationHooks/SoundTweakedHook.cs:Unpack")
    def unpack(self, reader) -> None:
        AnimationHook.unpack(self, reader)
        self.sound_id = reader.read_uint32()
        self.priority = reader.read_single()
        self.probability = reader.read_single()
        self.volume = reader.read_single()


@dataclass(slots=True, eq=False)
class SetOmegaHook(AnimationHook):
    axis: Vector3 | None = None

    @anchor(None, "ACE.DatLoader/Entity/AnimationHooks/SetOmegaHook.cs:Unpack")
    def unpack(self, reader) -> None:
        AnimationHook.unpack(self, reader)
        self.axis = reader.read_vector3()


@dataclass(slots=True, eq=False)
class TextureVelocityHook(AnimationHook):
    u_speed: object = 0.0
    v_speed: object = 0.0

    @anchor(None, "ACE.DatLoader/Entity/AnimationHooks/TextureVelocityHook.cs:Unpack")
    def unpack(self, reader) -> None:
        AnimationHook.unpack(self, reader)
        self.u_speed = reader.read_single()
        self.v_speed = reader.read_single()


@dataclass(slots=True, eq=False)
class TextureVelocityPartHook(AnimationHook):
    part_index: int = 0
    u_speed: object = 0.0
    v_speed: object = 0.0

    @anchor(None, "ACE.DatLoader/Entity/AnimationHooks/TextureVelocityPartHook.cs:Unpack")
    def unpack(self, reader) -> None:
        AnimationHook.unpack(self, reader)
        self.part_index = reader.read_uint32()
        self.u_speed = reader.read_single()
        self.v_speed = reader.read_single()


@dataclass(slots=True, eq=False)
class SetLightHook(AnimationHook):
    lights_on: int = 0

    @anchor(None, "ACE.DatLoader/Entity/AnimationHooks/SetLightHook.cs:Unpack")
    def unpack(self, reader) -> None:
        AnimationHook.unpack(self, reader)
        self.lights_on = reader.read_int32()


@dataclass(slots=True, eq=False)
class CreateBlockingParticle(CreateParticleHook):
    """A CreateParticleHook by another type: it inherits Unpack."""


# AnimationHook.ReadHook's switch: hook type -> the class it makes; any other type makes null
HOOK_CLASSES: dict = {
    AnimationHookType.Sound: SoundHook,
    AnimationHookType.SoundTable: SoundTableHook,
    AnimationHookType.Attack: AttackHook,
    AnimationHookType.ReplaceObject: ReplaceObjectHook,
    AnimationHookType.Ethereal: EtherealHook,
    AnimationHookType.TransparentPart: TransparentPartHook,
    AnimationHookType.Luminous: LuminousHook,
    AnimationHookType.LuminousPart: LuminousPartHook,
    AnimationHookType.Diffuse: DiffuseHook,
    AnimationHookType.DiffusePart: DiffusePartHook,
    AnimationHookType.Scale: ScaleHook,
    AnimationHookType.CreateParticle: CreateParticleHook,
    AnimationHookType.DestroyParticle: DestroyParticleHook,
    AnimationHookType.StopParticle: StopParticleHook,
    AnimationHookType.NoDraw: NoDrawHook,
    AnimationHookType.DefaultScriptPart: DefaultScriptPartHook,
    AnimationHookType.CallPES: CallPESHook,
    AnimationHookType.Transparent: TransparentHook,
    AnimationHookType.SoundTweaked: SoundTweakedHook,
    AnimationHookType.SetOmega: SetOmegaHook,
    AnimationHookType.TextureVelocity: TextureVelocityHook,
    AnimationHookType.TextureVelocityPart: TextureVelocityPartHook,
    AnimationHookType.SetLight: SetLightHook,
    AnimationHookType.CreateBlockingParticle: CreateBlockingParticle,
    # The following HookTypes have no additional properties (ACE)
    AnimationHookType.AnimationDone: AnimationHook,
    AnimationHookType.DefaultScript: AnimationHook,
}
