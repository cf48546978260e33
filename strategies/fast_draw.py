"""Drawing a scene without Hypothesis' engine, as a choice sequence Hypothesis can replay and shrink.

A scene is about 80 choices, and Hypothesis' engine costs about 20 us a choice beyond the
choice itself (spans, the data tree, the choice nodes, the observer): half a live campaign's
worker time went there (benchmarks/bench_runner.py). `FastData` stands in for Hypothesis'
ConjectureData while a strategy draws: the strategies' own `do_draw` run unchanged (composites,
sampled_from, one_of, floats of width 32, ...), every choice comes from Hypothesis' own provider
(`HypothesisProvider`, with what it derives from a draw's bounds kept: the same distribution of
each fresh choice, boundary constants, near-bound weights), and nothing else is kept but the
choices made. Those choices are a choice sequence in Hypothesis' sense:
`ConjectureData.for_choices(choices)` draws the same scene from them, so a difference found this
way is handed to Hypothesis, which shrinks it as it would have shrunk one of its own (runner.py);
`tests/strategies/test_fast_draw.py` checks that replay scene for scene.

What it leaves out is Hypothesis' mutation of earlier scenes during generation (copying a
span's choices over another span with the same label, up to 5 times after each fresh scene).
Tried here with spans recorded: the project's mutants took a median 138 scenes to find against
40 without it (fresh scenes are 1 in 6 with it), though its scenes cost the port a third less.
The campaign's climb toward exact boundaries (runner.py) replays the closest scene yet with one
choice moved instead.
"""

from __future__ import annotations

import math
from random import Random

from hypothesis.control import _current_build_context
from hypothesis.internal.conjecture.choice import choice_permitted
from hypothesis.internal.conjecture.providers import INTEGERS_DISTRIBUTION, SIGNALING_NAN, HypothesisProvider
from hypothesis.internal.floats import clamp, float_to_int, make_float_clamper, next_down, next_up
from hypothesis.strategies._internal.lazy import unwrap_strategies


class Invalid(Exception):
    """A draw Hypothesis would have marked invalid (a filter that gave up): draw again."""


class _Discard(dict):
    """known_object_printers of a build context nobody prints from."""

    def __missing__(self, key):
        return []


class _BuildContext:
    """What strategies ask of Hypothesis' build context while drawing (printing aids only)."""

    known_object_printers = _Discard()
    is_final = False
    data = None  # the FastData drawing (strategies built mid-draw ask its provider)

    def record_call(self, *args, **kwargs) -> None:
        pass


class _ArgLabel:
    frozen = False  # a draw never outlives its scene

    __slots__ = ()

    def __enter__(self):
        return {}

    def __exit__(self, *exc) -> None:
        return None


_ARG_LABEL = _ArgLabel()
_TYPES = {"integer": int, "float": float, "boolean": bool}
_CONTEXT = _BuildContext()


class FastData:
    """The part of ConjectureData a strategy's do_draw uses, recording only the choices."""

    frozen = False  # a draw never outlives its scene

    __slots__ = ("provider", "choices", "prefix", "events", "depth", "_last_rejected_filter",
                 "_sampled_from_all_strategies_elements_message", "__weakref__")

    def __init__(self, provider: HypothesisProvider, prefix: tuple = ()):
        self.provider = provider
        self.prefix = prefix  # choices replayed first (an earlier scene's, one of them changed)
        self.choices: list = []
        self.events: dict = {}
        self.depth = 1  # never at Hypothesis' top level (that one times and observes draws)
        self._last_rejected_filter = None
        provider._cd = self

    def draw(self, strategy, label=None, observe_as=None):
        strategy.validate()
        return unwrap_strategies(strategy).do_draw(self)

    def _replayed(self, choice_type: str, constraints: dict):
        """The prefix's next choice when this draw can take it (Hypothesis' own test, as its replay
        of a choice sequence applies it); None when it cannot or the prefix is used up."""
        i = len(self.choices)
        if i < len(self.prefix):
            v = self.prefix[i]
            if type(v) is _TYPES[choice_type] and choice_permitted(v, constraints):
                return v
        return None

    def draw_integer(self, min_value=None, max_value=None, *, weights=None, shrink_towards=0, forced=None,
                     observe=True):
        if forced is None and observe and self.prefix:
            forced = self._replayed("integer", {"min_value": min_value, "max_value": max_value})
        if forced is None:
            forced = self.provider.draw_integer(min_value, max_value, weights=weights, shrink_towards=shrink_towards)
        if observe:
            self.choices.append(forced)
        return forced

    def draw_float(self, min_value=-float("inf"), max_value=float("inf"), *, allow_nan=True,
                   smallest_nonzero_magnitude=5e-324, forced=None, observe=True):
        constraints = {"min_value": min_value, "max_value": max_value, "allow_nan": allow_nan,
                       "smallest_nonzero_magnitude": smallest_nonzero_magnitude}
        if forced is None and observe and self.prefix:
            forced = self._replayed("float", constraints)
        if forced is None:
            forced = self.provider.draw_float(**constraints)
        if observe:
            self.choices.append(forced)
        return forced

    def draw_boolean(self, p=0.5, *, forced=None, observe=True):
        if forced is None and observe and self.prefix:
            forced = self._replayed("boolean", {"p": p})
        if forced is None:
            forced = self.provider.draw_boolean(p)
        if observe:
            self.choices.append(forced)
        return forced

    def choice(self, values, *, forced=None, observe=True):
        return values[self.draw_integer(0, len(values) - 1, forced=None if forced is None else values.index(forced),
                                        observe=observe)]

    def start_span(self, label) -> None:
        self.depth += 1  # many() checks that its elements' spans nest

    def stop_span(self, *, discard: bool = False) -> None:
        self.depth -= 1

    def track_arg_label(self, label):
        return _ARG_LABEL

    def mark_invalid(self, why=None, location=None):
        raise Invalid(why)

    def last_rejected_filter_location(self):
        return None


class _Provider(HypothesisProvider):
    """HypothesisProvider with what it works out from a draw's bounds alone kept per bounds: its
    boundary floats and float clamper, its integer distribution's CDF at the bounds. Scenes draw
    from a few hundred bounds again and again, and working them out each time cost a tenth of an
    outdoor scene's drawing. The same random numbers are taken and the same choices made
    (tests/strategies/test_fast_draw.py draws beside HypothesisProvider, choice for choice)."""

    KEPT = 4096  # bounds drawn from earlier draws' values keep coming: what is kept is cleared past this

    def __init__(self, seed: int):
        super().__init__(None)
        self._random = Random(seed)
        self._floats: dict = {}
        self._integers: dict = {}

    def draw_integer(self, min_value=None, max_value=None, *, weights=None, shrink_towards=0) -> int:
        if weights is not None or min_value is None or max_value is None:
            return super().draw_integer(min_value, max_value, weights=weights, shrink_towards=shrink_towards)
        constant = self._maybe_draw_constant("integer", {"min_value": min_value, "max_value": max_value,
                                                         "weights": None, "shrink_towards": shrink_towards})
        if constant is not None:
            return constant
        key = (min_value, max_value)
        if key not in self._integers:
            if len(self._integers) >= self.KEPT:
                self._integers.clear()
            try:
                lo, hi = INTEGERS_DISTRIBUTION.cdf(min_value - 0.5), INTEGERS_DISTRIBUTION.cdf(max_value + 0.5)
            except OverflowError:
                lo = hi = 0.0
            # None: bounds too wide for the CDF to sample between, so Hypothesis draws uniformly
            self._integers[key] = (lo, hi - lo) if hi - lo >= 1e-13 else None
        span = self._integers[key]
        if span is None:
            return self._random.randint(min_value, max_value)
        lo, width = span
        while (p := lo + self._random.random() * width) in {0, 1}:
            pass  # pragma: no cover
        return clamp(min_value, round(INTEGERS_DISTRIBUTION.inverse_cdf(p)), max_value)

    def draw_float(self, *, min_value=-math.inf, max_value=math.inf, allow_nan=True,
                   smallest_nonzero_magnitude: float) -> float:
        constraints = {"min_value": min_value, "max_value": max_value, "allow_nan": allow_nan,
                       "smallest_nonzero_magnitude": smallest_nonzero_magnitude}
        constant = self._maybe_draw_constant("float", constraints, p=0.15)
        if constant is not None:
            return constant
        key = (float_to_int(min_value), float_to_int(max_value), allow_nan, smallest_nonzero_magnitude)
        known = self._floats.get(key)
        if known is None:
            if len(self._floats) >= self.KEPT:
                self._floats.clear()
            weird = [f for f in (0.0, -0.0, math.inf, -math.inf, math.nan, -math.nan, SIGNALING_NAN, -SIGNALING_NAN,
                                 min_value, next_up(min_value), min_value + 1, max_value - 1, next_down(max_value),
                                 max_value)
                     if choice_permitted(f, constraints)]
            known = self._floats[key] = (weird, make_float_clamper(min_value, max_value, allow_nan=allow_nan,
                                                                  smallest_nonzero_magnitude=smallest_nonzero_magnitude))
        weird, clamper = known
        if weird and self._random.random() < 0.05:
            return self._random.choice(weird)
        result = self._draw_float()
        if allow_nan and math.isnan(result):
            clamped = result  # pragma: no cover
        else:
            clamped = clamper(result)
        if float_to_int(clamped) != float_to_int(result) and not (math.isnan(result) and allow_nan):
            result = clamped
        return result


class FastDrawer:
    """Draws values of one strategy from a seeded Random, each with its choice sequence."""

    def __init__(self, strategy, seed: int):
        self.strategy = strategy
        self.provider = _Provider(seed)

    def draw(self, prefix: tuple = ()):
        """(value, choices): a fresh value, or with `prefix` the value those choices draw (a choice
        the draw cannot take, or any past the prefix's end, drawn fresh). A draw Hypothesis would
        mark invalid is drawn again, fresh."""
        token = _current_build_context.value
        _current_build_context.value = _CONTEXT
        try:
            while True:
                data = _CONTEXT.data = FastData(self.provider, prefix)
                try:
                    return data.draw(self.strategy), tuple(data.choices)
                except Invalid:
                    prefix = ()
        finally:
            _current_build_context.value = token
            _CONTEXT.data = None

