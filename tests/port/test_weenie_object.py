"""WeenieObject's answers from its Player (port/weenie_object.py): InqRunRate, InqBurden, InqJumpVelocity read
the Player's skills, vitals, attributes and burden (scene/8 mover.skills)."""

import math

import numpy as np
import pytest

from acconform.flags import PlayerKillerStatus
from acconform.numerics import EXACT
from acconform.port.animation.movement_system import get_jump_height
from acconform.port.weenie_object import DUMMY_OBJECT, Player, WeenieObject
from acconform.scene import DEFAULT_SKILLS, MoverSkills

f = np.float32


def weenie(**skills) -> WeenieObject:
    return WeenieObject.of(Player.of_skills(0x50000001, PlayerKillerStatus.NPK, MoverSkills(**skills)))


@pytest.mark.anchor("WeenieObject.cs:InqRunRate")
def test_the_run_rate_is_the_players_run_skills_and_ignores_its_burden():
    assert weenie().inq_run_rate(f(0.0)) == (True, f(1.0))  # the database-free Player's
    assert weenie(run=300).inq_run_rate(f(0.0)) == (True, f(2.65))
    assert weenie(run=300, strength=1, encumbrance_val=10**6).inq_run_rate(f(0.0)) == (True, f(2.65))
    assert weenie(run=800).inq_run_rate(f(0.0)) == (True, f(4.5)) == weenie(run=1 << 24).inq_run_rate(f(0.0))


@pytest.mark.anchor("WeenieObject.cs:InqBurden")
def test_the_burden_is_the_load_over_the_capacity_strength_and_augmentations_give():
    assert weenie().inq_burden(EXACT) == f(0.0)
    assert weenie(strength=100, encumbrance_val=15000).inq_burden(EXACT) == f(1.0)
    # one augmentation: 30 per point of strength more; six count as five (150)
    assert weenie(strength=100, encumbrance_val=18000, augmentation_increased_carrying_capacity=1).inq_burden(EXACT) == f(1.0)
    assert weenie(strength=10, encumbrance_val=3000, augmentation_increased_carrying_capacity=6).inq_burden(EXACT) == f(1.0)
    assert weenie(strength=10, encumbrance_val=-5).inq_burden(EXACT) == f(0.0)
    # 150 * 14,316,558 wraps below zero in C#'s int: no capacity, the burden 3
    assert weenie(strength=14316558, encumbrance_val=1).inq_burden(EXACT) == f(3.0)
    assert type(weenie().inq_burden(EXACT)) is np.float32
    assert DUMMY_OBJECT.inq_burden(EXACT) is None


@pytest.mark.anchor("WeenieObject.cs:InqJumpVelocity")
def test_the_jump_velocity_comes_from_the_jump_skill_and_burden_and_none_without_stamina():
    ok, vz = weenie(jump=250, stamina=10).inq_jump_velocity(f(1.0))
    height = get_jump_height(f(0.0), 250, f(1.0), f(1.0))
    assert ok and type(vz) is np.float32 and vz == f(math.sqrt(float(height) * 19.6))
    assert weenie(jump=250, stamina=0).inq_jump_velocity(f(1.0)) == weenie(jump=0).inq_jump_velocity(f(1.0))
    # a burden of 2 or more leaves no height but the floor, 0.35
    floor = weenie(jump=250, stamina=10, strength=100, encumbrance_val=30000).inq_jump_velocity(f(1.0))
    assert floor == (True, f(math.sqrt(float(f(0.35)) * 19.6)))
    assert DUMMY_OBJECT.inq_jump_velocity(f(1.0)) == (False, f(0.0))


def test_the_default_player_is_the_database_free_players():
    from dataclasses import fields

    made, plain = Player.of_skills(0, PlayerKillerStatus.NPK, DEFAULT_SKILLS), Player()
    assert [getattr(made, f.name) for f in fields(Player)] == [getattr(plain, f.name) for f in fields(Player)]
