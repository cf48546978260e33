"""Missile: ACE's WorldObjects/Missile.cs -- a thrown weapon; it keeps WorldObject's OnCollideObject and OnCollideEnvironment (the helper only with a ProjectileTarget)."""

from __future__ import annotations

from dataclasses import dataclass

from .stackable import Stackable


@dataclass(slots=True, eq=False, kw_only=True)
class Missile(Stackable):
    pass


__all__ = ["Missile"]
