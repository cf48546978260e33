"""MovementSystem: GetJumpHeight, GetRunRate, JumpStaminaCost, GetJumpPower.

ACE's Animation/MovementSystem.cs: a creature's jump height and run rate from its skills and
burden (WeenieObject.InqJumpVelocity and InqRunRate ask these), and a player's jump stamina cost
and power (Player.HandleActionJump). Floats are the run's scalars (taken from the burden); C#'s
uint/int operands convert to float where they meet one; GetRunRate's result is a double.
"""

from __future__ import annotations

from acconform.numerics import D, cs_ceiling, wrap_i32

from ..anchors import anchor
from ..constants import JUMP_BASE_HEIGHT, JUMP_SKILL_HEIGHT, MAX_RUN_RATE, MIN_JUMP_HEIGHT, RUN_SKILL_FOR_MAX_RATE
from ..encumbrance_system import get_burden_mod


def _clamp(value, lo, hi):
    # Math.Clamp(float, float, float): NaN passes through (neither test holds)
    if value < lo:
        return lo
    elif value > hi:
        return hi
    return value


@anchor(None, "MovementSystem.cs:GetJumpHeight")
def get_jump_height(burden, jump_skill: int, power, scaling):
    """`jump_skill` is a uint: it meets the float `1300.0f` (and then 22.2f) as a float."""
    s = type(burden)
    power = _clamp(power, s(0.0), s(1.0))

    skill = s(jump_skill)
    result = get_burden_mod(burden) * (skill / (skill + 1300.0) * JUMP_SKILL_HEIGHT + JUMP_BASE_HEIGHT) * power / scaling

    if result < MIN_JUMP_HEIGHT:
        result = s(MIN_JUMP_HEIGHT)

    return result


@anchor(None, "MovementSystem.cs:GetRunRate")
def get_run_rate(burden, run_skill: int, scaling):
    """A double, as ACE returns it (WeenieObject.InqRunRate casts it back to float). `run_skill` is
    an int: compared with `800.0f` and divided as a float; `runSkill + 200` is int arithmetic."""
    s = type(burden)
    load_mod = get_burden_mod(burden)

    if s(run_skill) >= RUN_SKILL_FOR_MAX_RATE:  # max run speed? (ACE)
        return D(MAX_RUN_RATE)
    else:
        return D(((load_mod * (s(run_skill) / s(wrap_i32(run_skill + 200)) * 11.0) + 4.0) / scaling) / 4.0)


@anchor(None, "MovementSystem.cs:JumpStaminaCost")
def jump_stamina_cost(power, burden, pk: bool, runtime) -> int:
    """`runtime` (acconform.numerics.Runtime) makes C#'s (int) casts."""
    if pk:
        return runtime.to_int32((power + 1.0) * 100.0)
    else:
        return runtime.to_int32(cs_ceiling((burden + 0.5) * power * 8.0 + 2.0))


@anchor(None, "MovementSystem.cs:GetJumpPower")
def get_jump_power(stamina: int, burden, pk: bool):
    """`stamina` is a uint, converted to float where it meets one."""
    s = type(burden)
    if pk:
        return s(stamina) / 100.0 - 1.0
    else:
        return (s(stamina) - 2.0) / (burden * 8.0 + 4.0)


__all__ = ["get_jump_height", "get_run_rate", "jump_stamina_cost", "get_jump_power"]
