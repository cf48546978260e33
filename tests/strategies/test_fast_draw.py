"""Drawing outside Hypothesis' engine: the choices a FastDrawer records are a choice sequence
Hypothesis replays to the same scene, which is what lets a campaign hand a difference to
Hypothesis' shrinker (acconform/runner.py)."""

import random

import pytest
from hypothesis.control import BuildContext
from hypothesis.internal.conjecture.data import ConjectureData

from acconform.protocol import CAMPAIGN_KINDS
from acconform.runner import _nudged
from acconform.scene import validate_scene
from acconform.strategies import scenes
from acconform.strategies.determinism import pinned_constants
from acconform.strategies.fast_draw import FastDrawer


def _replayed_by_hypothesis(strategy, choices):
    data = ConjectureData.for_choices(choices)
    with BuildContext(data, wrapped_test=None):
        value = data.draw(strategy)
    return value, data.choices


@pytest.mark.parametrize("kind", CAMPAIGN_KINDS)
def test_hypothesis_replays_a_fast_drawn_choice_sequence_to_the_same_scene(kind):
    strategy = scenes((kind,))
    with pinned_constants():
        drawer = FastDrawer(strategy, 5)
        for _ in range(40):
            scene, choices = drawer.draw()
            again, used = _replayed_by_hypothesis(strategy, choices)
            assert again.dumps() == scene.dumps()
            assert used == choices, "Hypothesis read exactly the choices drawn, no more and no fewer"


def test_a_drawer_replays_its_own_choices_and_draws_past_a_prefix_that_runs_out():
    strategy = scenes(None)
    with pinned_constants():
        drawer = FastDrawer(strategy, 9)
        drawn = [drawer.draw() for _ in range(20)]
        for scene, choices in drawn:
            again, used = drawer.draw(choices)
            assert again.dumps() == scene.dumps() and used == choices
        scene, choices = drawn[0]
        _, used = drawer.draw(choices[:3])
        assert used[:3] == choices[:3] and len(used) > 3


def test_a_nudged_choice_sequence_still_draws_a_valid_scene_that_hypothesis_replays():
    # the campaign's hill climbing moves one choice of the closest scene yet; a choice the draw
    # cannot take (out of its range, or of another type once an earlier choice changed a branch)
    # is drawn fresh, so every nudged draw is a well-formed scene with a replayable sequence
    strategy = scenes(None)
    rng = random.Random(3)
    with pinned_constants():
        drawer = FastDrawer(strategy, 17)
        base = [drawer.draw()[1] for _ in range(10)]
        for _ in range(150):
            scene, used = drawer.draw(_nudged(rng.choice(base), rng))
            validate_scene(scene)
            assert _replayed_by_hypothesis(strategy, used)[0].dumps() == scene.dumps()


def test_the_same_seed_draws_the_same_choices():
    strategy = scenes(None)
    with pinned_constants():
        a = [FastDrawer(strategy, 4).draw()[1] for _ in range(3)]
    assert a[0] == a[1] == a[2]

