"""Stackable: ACE's WorldObjects/Stackable.cs -- a WorldObject that stacks; it overrides nothing the physics reaches."""

from __future__ import annotations

from dataclasses import dataclass

from .world_object import WorldObject


@dataclass(slots=True, eq=False, kw_only=True)
class Stackable(WorldObject):
    pass


__all__ = ["Stackable"]
