"""Drawing outside Hypothesis' engine: the choices a FastDrawer records are a choice sequence
Hypothesis replays to the same scene, which is what lets a campaign hand a difference to
Hypothesis' shrinker (acconform/runner.py)."""

import math
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



def test_the_drawers_provider_takes_the_same_random_numbers_and_makes_the_same_choices_as_hypothesis():
    # _Provider keeps what a draw works out from its bounds alone; Hypothesis' provider works it out
    # each time. From one seed they must agree choice for choice, over the bounds scenes draw from
    # and the edges: half-open and one-value integer ranges, signed-zero and huge float bounds
    from random import Random

    from hypothesis.internal.conjecture.providers import HypothesisProvider

    from acconform.strategies.fast_draw import _Provider

    ints = [(0, 1), (0, 7), (-3, 3), (5, 5), (0, 1000), (-(2 ** 40), 2 ** 40), (None, 4), (2, None), (None, None)]
    floats = [(-1.0, 1.0), (0.0, 0.5), (-0.0, 0.0), (-0.0, -0.0), (1e-30, 3.4e38), (-math.inf, math.inf), (2.5, 2.5),
              (-100.0, -1e-3)]
    mine, theirs = _Provider(11), HypothesisProvider(None)
    theirs._random = Random(11)
    mine._cd = theirs._cd = object()  # what an unbounded integer draw asserts is there
    pick = random.Random(2)
    for _ in range(20000):
        if pick.random() < 0.5:
            lo, hi = pick.choice(ints)
            a, b = mine.draw_integer(lo, hi), theirs.draw_integer(lo, hi)
        else:
            lo, hi = pick.choice(floats)
            kw = {"min_value": lo, "max_value": hi, "allow_nan": lo == -math.inf and pick.random() < 0.5,
                  "smallest_nonzero_magnitude": pick.choice((5e-324, 1.1754943508222875e-38))}
            a, b = mine.draw_float(**kw), theirs.draw_float(**kw)
        assert repr(a) == repr(b)
