"""Statics made from a Setup of several parts (scene/7), live against ACE (lane `live_oracle`; run it once
with a mono build and once with a .NET 10 build): the port matches ACE bit for bit on each named scene,
and ACE's answers say what each scene is for."""

import pytest

from acconform.compare import compare
from acconform.port.run import run_scene

from .scenes import MULTIPART

pytestmark = pytest.mark.live_oracle


@pytest.fixture(scope="module")
def answers(live):
    return {name: live.run(s) for name, s in MULTIPART.items()}


@pytest.mark.parametrize("name", list(MULTIPART))
def test_the_port_matches_ace_bit_for_bit_on_the_named_multipart_scene(live, answers, name):
    ace = answers[name]
    assert ace.error is None
    assert compare(run_scene(MULTIPART[name], runtime=live.location.runtime), ace, "exact") == []


def test_ace_stops_the_mover_at_the_turned_part_and_steps_it_up_the_part_scaled_half_as_high(answers):
    corner, scaled = answers["multipart: into the turned part's corner"], answers["multipart: onto a part scaled 0.5 high"]
    assert corner.origin[0] < 15.0 and corner.origin[2] == 20.0  # the 0.8 m part is over the step-up height
    assert scaled.origin[2] > 20.0  # ACE scales the part's BSP by its scale.z: 0.4 m high, stepped up


def test_ace_collides_with_the_setups_spheres_only_when_it_has_no_cylspheres(answers):
    spheres, cyls = answers["multipart: two spheres, no BSP flag"], answers["multipart: cylspheres hide the sphere"]
    assert spheres.origin[:2] != cyls.origin[:2]
    assert cyls.origin[0] == pytest.approx(17.0, abs=1e-5)  # between the cylspheres, through the ignored sphere


def test_ace_places_the_parts_at_the_setups_default_animation_not_its_placement(answers):
    corner, aside = answers["multipart: into the turned part's corner"], answers["multipart: a DefaultAnimation holds the parts aside"]
    assert corner.origin[0] < 15.0  # the same walk, the parts at their placement frames: stopped
    assert aside.origin[0] == pytest.approx(17.0, abs=1e-5) and not aside.collision_normal.valid  # walked past
