"""The mover's Player's skills, vitals, attributes and burden (scene/8 mover.skills) as ACE's WeenieObject reads
them: InqRunRate, InqBurden and InqJumpVelocity asked of live ACE for a Player made and set as a scene's mover's
is (Facade.PlayerAnswers), against the port's WeenieObject, bit for bit. On ACE's server only InqRunRate reaches
a scene's answer (docs/oracle.md's audit): this asks the other two directly, at the values where the formulas
change."""

from __future__ import annotations

import numpy as np
import pytest

from acconform.flags import PlayerKillerStatus
from acconform.numerics import EXACT, f32_bits
from acconform.port.weenie_object import WeenieObject
from acconform.port.world_objects import Player
from acconform.scene import DEFAULT_SKILLS, MoverSkills

EXTENTS = (0.0, 0.25, 0.5, 1.0, 1.5, -0.5)
SKILLS = (
    DEFAULT_SKILLS,
    MoverSkills(run=300, jump=250, stamina=100, strength=100),
    MoverSkills(run=800, jump=18, stamina=1, strength=100, encumbrance_val=15000),
    MoverSkills(run=799, jump=19, stamina=5, strength=100, encumbrance_val=30000),
    MoverSkills(run=1 << 24, jump=1 << 24, stamina=0xFFFFFFFF, strength=1 << 24),
    MoverSkills(jump=1300, stamina=0, strength=100, encumbrance_val=20000),
    MoverSkills(jump=1300, stamina=9, strength=290, encumbrance_val=20000, augmentation_increased_carrying_capacity=1),
    MoverSkills(jump=500, stamina=7, strength=10, encumbrance_val=2600, augmentation_increased_carrying_capacity=6),
    MoverSkills(jump=500, stamina=7, strength=10, encumbrance_val=-1, augmentation_increased_carrying_capacity=-1),
    MoverSkills(jump=500, stamina=7, strength=14316558, encumbrance_val=1),
    MoverSkills(run=123, jump=777, stamina=3, strength=57, encumbrance_val=12345, augmentation_increased_carrying_capacity=3),
)


def port_answers(skills: MoverSkills):
    weenie = WeenieObject.of(Player.of_skills(0x50000001, PlayerKillerStatus.NPK, skills))
    f = np.float32
    _, rate = weenie.inq_run_rate(f(0.0))
    burden = weenie.inq_burden(EXACT)
    jumps = [weenie.inq_jump_velocity(f(e)) for e in EXTENTS]
    return (f32_bits(rate), None if burden is None else f32_bits(burden),
            [(bool(ok), f32_bits(vz)) for ok, vz in jumps])


@pytest.mark.live_oracle
@pytest.mark.anchor("WeenieObject.cs:InqJumpVelocity")
@pytest.mark.parametrize("skills", SKILLS, ids=lambda s: ",".join(f"{k}={v}" for k, v in s.to_json().items()) or "default")
def test_aces_weenie_object_answers_the_players_run_rate_burden_and_jump_velocity_as_the_port_does(live, skills):
    rate, burden, jumps = live.player_answers(skills, EXTENTS)
    ace = (f32_bits(rate), None if burden is None else f32_bits(burden), [(ok, f32_bits(vz)) for ok, vz in jumps])
    assert ace == port_answers(skills)


def test_the_cases_reach_every_branch_of_the_burden_and_the_jump_height():
    """Burden under 1, between 1 and 2, 2 and over, 3 with no capacity, 0 for a negative load; the jump height's
    floor and a stamina of 0."""
    burdens = {float(np.float32(WeenieObject.of(Player.of_skills(0x50000001, PlayerKillerStatus.NPK, s)).inq_burden(EXACT)))
               for s in SKILLS}
    assert {0.0, 1.0, 2.0, 3.0} <= burdens and any(1.0 < b < 2.0 for b in burdens)
    assert any(s.stamina == 0 and s.jump > 0 for s in SKILLS)
