"""Drawing a scene without Hypothesis' engine, as a choice sequence Hypothesis can replay and shrink.

A scene is about 80 choices, and Hypothesis' engine costs about 20 us a choice beyond the
choice itself (spans, the data tree, the choice nodes, the observer): half a live campaign's
worker time went there (benchmarks/bench_runner.py). `FastData` stands in for Hypothesis'
ConjectureData while a strategy draws: the strategies' own `do_draw` run unchanged (composites,
sampled_from, one_of, floats of width 32, ...), every choice comes from Hypothesis' own provider
(`HypothesisProvider`: the same distribution of each fresh choice, boundary constants, near-bound
weights), and nothing else is kept but the choices made. Those choices are a choice sequence in
Hypothesis' sense: `ConjectureData.for_choices(choices)` draws the same scene from them, so a
difference found this way is handed to Hypothesis, which shrinks it as it would have shrunk one
of its own (runner.py); `tests/strategies/test_fast_draw.py` checks that replay scene for scene.

What it leaves out is Hypothesis' mutation of earlier scenes during generation (copying a
span's choices over another span with the same label, up to 5 times after each fresh scene).
Tried here with spans recorded: the project's mutants took a median 138 scenes to find against
40 without it (fresh scenes are 1 in 6 with it), though its scenes cost the port a third less.
The campaign's climb toward exact boundaries (runner.py) replays the closest scene yet with one
choice moved instead.
"""

from __future__ import annotations

from random import Random

from hypothesis.control import _current_build_context
from hypothesis.internal.conjecture.providers import HypothesisProvider
from hypothesis.internal.conjecture.choice import choice_permitted
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


class FastDrawer:
    """Draws values of one strategy from a seeded Random, each with its choice sequence."""

    def __init__(self, strategy, seed: int):
        self.strategy = strategy
        self.provider = HypothesisProvider(None)
        self.provider._random = Random(seed)

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

