"""GenericObject: ACE's concrete plain WorldObject (WorldObjects/GenericObject.cs) -- an object that moves and is no creature.

It overrides nothing the physics reaches (only ActOnUse), so every body is WorldObject's; the oracle's
stand-in makes the same class.
"""

from __future__ import annotations

from dataclasses import dataclass

from .world_object import WorldObject


@dataclass(slots=True, eq=False, kw_only=True)
class GenericObject(WorldObject):
    pass


__all__ = ["GenericObject"]
