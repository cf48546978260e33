"""EncumbranceSystem: EncumbranceCapacity, GetBurden, GetBurdenMod.

ACE's Physics/Common/EncumbranceSystem.cs: a creature's carrying capacity from its strength and
augmentations, its burden (load over capacity, a float, usually 0 to 3) and what the burden leaves
of its run and jump (MovementSystem). `int` arithmetic is C#'s (wrapping); the floats take the
run's scalar type from the burden they are given.
"""

from __future__ import annotations

from acconform.numerics import wrap_i32

from .anchors import anchor


@anchor(None, "EncumbranceSystem.cs:EncumbranceCapacity")
def encumbrance_capacity(strength: int, num_augs: int) -> int:
    if strength <= 0:
        return 0

    bonus_burden = wrap_i32(30 * num_augs)

    if bonus_burden >= 0:
        if bonus_burden > 150:
            bonus_burden = 150

        return wrap_i32(wrap_i32(150 * strength) + wrap_i32(strength * bonus_burden))
    else:
        return wrap_i32(150 * strength)


@anchor(None, "EncumbranceSystem.cs:GetBurden")
def get_burden(capacity: int, encumbrance: int, mode):
    """A float in the run's scalar type (`mode`): ``(float)encumbrance / capacity`` is a float32
    division (the int capacity converted to float)."""
    s = mode.scalar
    if capacity <= 0:
        return s(3.0)

    if encumbrance >= 0:
        return s(encumbrance) / s(capacity)
    else:
        return s(0.0)


@anchor(None, "EncumbranceSystem.cs:GetBurdenMod")
def get_burden_mod(burden):
    s = type(burden)
    if burden < 1.0:
        return s(1.0)

    if burden < 2.0:
        return 2.0 - burden
    else:
        return s(0.0)


__all__ = ["encumbrance_capacity", "get_burden", "get_burden_mod"]
