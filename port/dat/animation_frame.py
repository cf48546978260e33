"""AnimationFrame: Unpack(reader, numParts) -- one frame per part, then hooks (ACE.DatLoader Entity/AnimationFrame.cs).

Animation hooks (AnimationHook.ReadHook) are not ported: a record with hooks stops the port
(NotImplementedError, a port gap), which acconform/dat.py never writes.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ..anchors import anchor
from .frame import Frame
from .unpackable_extensions import unpack_list_fixed


@dataclass(slots=True)
class AnimationFrame:
    frames: list = field(default_factory=list)  # Frame per part
    hooks: list = field(default_factory=list)

    @staticmethod
    @anchor(None, "ACE.DatLoader/Entity/AnimationFrame.cs:Unpack")
    def unpack(reader, num_parts: int) -> "AnimationFrame":
        a = AnimationFrame()
        a.frames = unpack_list_fixed(reader, Frame.unpack, num_parts)
        num_hooks = reader.read_uint32()
        if num_hooks:
            raise NotImplementedError("animation hooks (AnimationHook.ReadHook) are not ported")
        return a
