"""AnimationHook: Unpack, ReadHook, AnimDoneHook -- an event an animation frame carries, read by its type (ACE.DatLoader Entity/AnimationHook.cs).

ReadHook peeks the hook's type, rewinds, and unpacks the hook's class for it (port/dat/animation_hooks.py,
ACE's Entity/AnimationHooks/). A type ACE's switch does not list (NoOp 0, Unknown, or any other number)
gives null -- ACE logs a warning -- and reads nothing past the peek, so the stream stays at the
hook's first byte and the frame's next read starts there, as in ACE. The null is added to the
frame's Hooks (AnimationFrame.Unpack), where Sequence.execute_hooks meets it.

What ACE's physics does with hooks: Sequence.execute_hooks hands a frame's hooks of the frame's
direction (or Both) to PhysicsObj.add_anim_hook, and Sequence.update_internal adds AnimDoneHook when
an animation ends with link animations before the cycle; PhysicsObj.process_hooks runs them through
Physics/Hooks/AnimHook.Execute, which acts on AnimationDone alone (PhysicsObj.Hook_AnimDone) and
ignores every other type (its Ethereal case is commented out in ACE).
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import IntEnum

from ..anchors import anchor


class AnimationHookType(IntEnum):
    """ACE.Entity.Enum.AnimationHookType."""

    Unknown = -1
    NoOp = 0
    Sound = 1
    SoundTable = 2
    Attack = 3
    AnimationDone = 4
    ReplaceObject = 5
    Ethereal = 6
    TransparentPart = 7
    Luminous = 8
    LuminousPart = 9
    Diffuse = 10
    DiffusePart = 11
    Scale = 12
    CreateParticle = 13
    DestroyParticle = 14
    StopParticle = 15
    NoDraw = 16
    DefaultScript = 17
    DefaultScriptPart = 18
    CallPES = 19
    Transparent = 20
    SoundTweaked = 21
    SetOmega = 22
    TextureVelocity = 23
    TextureVelocityPart = 24
    SetLight = 25
    CreateBlockingParticle = 26


class AnimationHookDir(IntEnum):
    """ACE.Entity.Enum.AnimationHookDir."""

    Unknown = -2
    Backward = -1
    Both = 0
    Forward = 1


@dataclass(slots=True, eq=False)
class AnimationHook:
    hook_type: int = 0
    direction: int = 0

    @anchor(None, "ACE.DatLoader/Entity/AnimationHook.cs:Unpack")
    def unpack(self, reader) -> None:
        """The virtual Unpack: the type (a uint, cast to the int enum) and the direction."""
        raw = reader.read_uint32()
        self.hook_type = raw - 0x100000000 if raw & 0x80000000 else raw
        self.direction = reader.read_int32()

    @staticmethod
    @anchor(None, "ACE.DatLoader/Entity/AnimationHook.cs:ReadHook")
    def read_hook(reader) -> "AnimationHook | None":
        from .animation_hooks import HOOK_CLASSES

        # We peek forward to get the hook type, then revert our position. (ACE)
        raw = reader.read_uint32()
        hook_type = raw - 0x100000000 if raw & 0x80000000 else raw
        reader.position -= 4

        make = HOOK_CLASSES.get(hook_type)
        if make is None:
            return None  # ACE: log.Warn("Not Implemented Hook type encountered"), hook = null

        hook = make()
        hook.unpack(reader)
        return hook


# AnimationHook.AnimDoneHook: made by the static constructor, type AnimationDone, direction Both (0)
ANIM_DONE_HOOK = AnimationHook(hook_type=AnimationHookType.AnimationDone, direction=AnimationHookDir.Both)
