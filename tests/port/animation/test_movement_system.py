"""MovementSystem and EncumbranceSystem: run rate, jump height, jump stamina and power from skills
and burden; and the two player jump paths of port/run.py."""

import numpy as np
import pytest

from acconform.flags import TransientState
from acconform.numerics import D, EXACT, MONO
from acconform.port import encumbrance_system as es
from acconform.port.animation import movement_system as ms

f = np.float32


@pytest.mark.anchor("MovementSystem.cs:GetRunRate")
def test_run_rate_is_one_with_no_skill_grows_with_skill_and_is_four_and_a_half_from_800():
    assert ms.get_run_rate(f(0.0), 0, f(1.0)) == 1.0
    assert ms.get_run_rate(f(0.0), 200, f(1.0)) == 2.375
    assert ms.get_run_rate(f(0.0), 800, f(1.0)) == 4.5 and ms.get_run_rate(f(3.0), 799, f(1.0)) == 1.0
    rate = ms.get_run_rate(f(0.0), 300, f(1.0))
    assert type(rate) is np.float64 and rate == D(((f(300) / f(500) * f(11)) + f(4)) / f(4))


@pytest.mark.anchor("MovementSystem.cs:GetJumpHeight")
def test_jump_height_is_at_least_0_35_and_clamps_the_power():
    assert ms.get_jump_height(f(0.0), 0, f(0.0), f(1.0)) == f(0.35)
    full = ms.get_jump_height(f(0.0), 300, f(1.0), f(1.0))
    assert full == f(300) / (f(300) + f(1300)) * f(22.2) + f(0.05)
    assert ms.get_jump_height(f(0.0), 300, f(7.0), f(1.0)) == full
    assert ms.get_jump_height(f(2.5), 300, f(1.0), f(1.0)) == f(0.35)  # no jump left at 250% burden


@pytest.mark.anchor("MovementSystem.cs:JumpStaminaCost")
def test_a_pk_jump_costs_a_hundred_per_power_and_an_ordinary_one_rounds_up_with_burden():
    assert ms.jump_stamina_cost(f(1.0), f(0.0), True, MONO) == 200
    assert ms.jump_stamina_cost(f(1.0), f(0.0), False, MONO) == 6  # ceil(0.5 * 8 + 2)
    assert ms.jump_stamina_cost(f(0.1), f(1.0), False, MONO) == 4  # ceil(1.5 * 0.1 * 8 + 2) = ceil(3.2)


@pytest.mark.anchor("MovementSystem.cs:GetJumpPower")
def test_jump_power_inverts_the_stamina_cost():
    assert ms.get_jump_power(200, f(0.0), True) == f(1.0)
    assert ms.get_jump_power(6, f(0.0), False) == f(1.0)


@pytest.mark.anchor("EncumbranceSystem.cs:GetBurdenMod")
def test_burden_leaves_everything_below_100_percent_and_nothing_from_200():
    assert [es.get_burden_mod(f(b)) for b in (0.0, 0.99, 1.25, 2.0, 3.0)] == [f(1.0), f(1.0), f(0.75), f(0.0), f(0.0)]


@pytest.mark.anchor("EncumbranceSystem.cs:EncumbranceCapacity")
def test_capacity_is_150_per_strength_plus_30_per_aug_up_to_five_augs():
    assert es.encumbrance_capacity(100, 0) == 15000
    assert es.encumbrance_capacity(100, 2) == 15000 + 100 * 60
    assert es.encumbrance_capacity(100, 9) == 15000 + 100 * 150
    assert es.encumbrance_capacity(0, 5) == 0 and es.encumbrance_capacity(100, -1) == 15000


@pytest.mark.anchor("EncumbranceSystem.cs:GetBurden")
def test_burden_is_load_over_capacity_three_with_no_capacity_and_zero_for_a_negative_load():
    assert es.get_burden(15000, 7500, EXACT) == f(0.5)
    assert es.get_burden(0, 10, EXACT) == f(3.0) and es.get_burden(100, -5, EXACT) == f(0.0)
    assert type(es.get_burden(3, 1, EXACT)) is np.float32 and es.get_burden(3, 1, EXACT) == f(1) / f(3)


class _Timer:
    current_time = 12.5


class _Mover:
    """The calls the jumps make, recorded; moving or not as told."""

    def __init__(self, moving, status, pending=None):
        from acconform.port.weenie_object import Player, WeenieObject

        self.moving, self.update_time, self.timer, self.calls = moving, 1.0, _Timer(), []
        self.transient_state = TransientState.Contact | TransientState.OnWalkable | TransientState.WaterContact
        self.is_animating = True
        self.weenie_obj = WeenieObject.of(Player(player_killer_status=status))
        self.movement_manager = None
        if pending is not None:  # a MovementManager whose MotionInterpreter has these pending motions
            from types import SimpleNamespace
            self.movement_manager = SimpleNamespace(motion_interpreter=SimpleNamespace(pending_motions=pending))

    def is_moving_or_animating(self):
        return self.moving

    def calc_acceleration(self):
        self.calls.append("calc_acceleration")

    def set_on_walkable(self, on):
        self.calls.append(("set_on_walkable", on))

    def set_local_velocity(self, v, send):
        self.calls.append(("set_local_velocity", v.to_tuple(), send))

    def remove_link_animations(self):
        self.calls.append("remove_link_animations")


def test_a_pk_players_jump_keeps_the_update_time_while_moving_and_an_ordinary_players_always_sets_it():
    from acconform.flags import PlayerKillerStatus as PKS
    from acconform.port.run import handle_action_jump

    pk, pkl, ordinary = _Mover(True, PKS.PK), _Mover(True, PKS.PKLite), _Mover(True, PKS.NPK)
    for m in (pk, pkl, ordinary):
        handle_action_jump(m, EXACT.vec(0, 1, 5))
    assert pk.update_time == pkl.update_time == 1.0 and ordinary.update_time == 12.5
    assert pk.calls == ordinary.calls == [
        "calc_acceleration", ("set_on_walkable", False), ("set_local_velocity", (0.0, 1.0, 5.0), False),
        "remove_link_animations"]
    for m in (pk, ordinary):
        assert m.transient_state == TransientState.OnWalkable and not m.is_animating
    still = _Mover(False, PKS.PK)
    handle_action_jump(still, EXACT.vec(0, 0, 5))
    assert still.update_time == 12.5


def test_both_jumps_clear_the_motion_interpreters_pending_motions():
    from acconform.flags import PlayerKillerStatus as PKS
    from acconform.port.run import handle_action_jump

    for status in (PKS.PK, PKS.NPK):
        pending = ["a MotionNode"]
        handle_action_jump(_Mover(False, status, pending), EXACT.vec(0, 0, 5))
        assert pending == []