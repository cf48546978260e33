"""AnimationFrame: Unpack(reader, numParts) -- one frame per part, then the frame's hooks (ACE.DatLoader Entity/AnimationFrame.cs).

Each hook is read by AnimationHook.ReadHook (port/dat/animation_hook.py); a hook of a type ACE does
not read is added as null, as ACE adds it.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ..anchors import anchor
from .animation_hook import AnimationHook
from .frame import Frame
from .unpackable_extensions import unpack_list_fixed


@dataclass(slots=True)
class AnimationFrame:
    frames: list = field(default_factory=list)  # Frame per part
    hooks: list = field(default_factory=list)  # AnimationHook (or None)

    @staticmethod
    @anchor(None, "ACE.DatLoader/Entity/AnimationFrame.cs:Unpack")
    def unpack(reader, num_parts: int) -> "AnimationFrame":
        a = AnimationFrame()
        a.frames = unpack_list_fixed(reader, Frame.unpack, num_parts)
        num_hooks = reader.read_uint32()
        for _ in range(num_hooks):
            hook = AnimationHook.read_hook(reader)
            a.hooks.append(hook)
        return a
