"""Cheap draws: the choices and spans Hypothesis' own strategies make, without rebuilding them per draw.

A scene is ~75 choices and in a campaign its generation costs as much as running the port, so
what a draw costs *beyond its choice* matters. Most of that was building strategies:

- a strategy built inside a draw (``st.sampled_from((...))``, ``sh.f32s(lo, hi)``, a composite
  called with arguments) is built, validated and labelled again on every draw. Strategies are
  module constants instead, unwrapped once (`eager`: ``st.integers`` and friends return lazy
  strategies that every draw unwraps again), and composites take no arguments where they can
  (terrain is drawn around vertex (0, 0) and moved where it belongs).
- ``st.one_of`` builds a fresh filtered ``sampled_from`` of its branches on every draw. `OneOf`
  builds that ``sampled_from`` once and draws it inside a composite drawn under one_of's label.

What must not change is the *structure* of the draws, not only their choices. Most generated
scenes are mutations of an earlier one (after each fresh scene Hypothesis copies one span's
choices over another span with the same label, a few times), so which spans share a label
decides how scenes vary around the ones that reach a branch. Drawing a float32 as a bare double
and rounding it, or a one_of's branch as a plain integer index, left every fresh scene's
distribution as it was and still lost about half of the cliff slides over eight seeds. So each
draw here makes the spans and labels of the strategy it stands for: `f32` *is*
``st.floats(width=32)``, `OneOf` nests the ``sampled_from`` span and the branch's span in a span
labelled as one_of labelled it, and a one_of whose branches exist only during the draw
(`one_of`) gets spans with labels of their own, as one_of's were (made from its branches, no
other span shared them). With that, a seed draws byte-for-byte the scenes it drew before.

Campaigns now draw their fresh scenes outside the engine (fast_draw.py), where spans cost nothing
and mean nothing; what still reads them is Hypothesis' shrinker, which a found difference is handed
to, and which works span by span (a span deleted, two spans with one label made equal).
"""

from __future__ import annotations

import hashlib
import threading
from types import FunctionType

from hypothesis import strategies as st

from acconform.numerics import to_f32


def eager(strategy):
    """The strategy a lazy one stands for (Hypothesis unwraps it on each draw; do it once)."""
    while True:
        inner = getattr(strategy, "wrapped_strategy", None)
        if inner is None or inner is strategy:
            return strategy
        strategy = inner


def ints(lo: int, hi: int):
    """st.integers(lo, hi), unwrapped once."""
    return eager(st.integers(lo, hi))


def floats(lo: float, hi: float):
    """st.floats(lo, hi) (doubles), unwrapped once."""
    return eager(st.floats(lo, hi))


def f32(lo: float, hi: float):
    """Exact float32s in [lo, hi] (Hypothesis draws a double and rounds it), unwrapped once."""
    return eager(st.floats(to_f32(lo), to_f32(hi), width=32, allow_nan=False, allow_infinity=False))


BOOLEANS = eager(st.booleans())
# PhysicsEngine.Server for the kinds whose mover changes cell through PhysicsObj.change_cell (ticks, placements):
# ACE's server three times in four, the client's branches the fourth (a client port wants those)
ENGINE_MODES = eager(st.sampled_from(("server", "server", "server", "client")))
# how a placed mover is placed: as a server's WorldObject enters its landblock (enter_world) one time in two, else
# by SetPosition with drawn flags (a teleport's or a restore's placement, whose flags reach the no-Slide branches)
PLACEMENT_VIAS = eager(st.sampled_from(("enter_world", "set_position")))


def label(name: str) -> int:
    """A span label of our own (Hypothesis' labels are 64-bit ints), for draws no other span shares."""
    return int.from_bytes(hashlib.sha256(name.encode()).digest()[:8], "big")


@st.composite
def _one_of(draw, pick):
    return draw(draw(pick))


class OneOf:
    """st.one_of(*branches), drawn with `take`: the same spans (one_of's, its sampled_from of the
    branches, the branch's) and labels, the same choice (an index over the branches, nested
    one_ofs flattened, the first branch where shrinking goes), built once."""

    __slots__ = ("branches", "label", "strategy")

    def __init__(self, *branches):
        flat = []
        for b in branches:
            flat.extend(b.branches if type(b) is OneOf else (eager(b),))
        self.branches = tuple(flat)
        as_one_of = st.one_of(*(b.as_one_of() if type(b) is OneOf else b for b in branches))
        self.label = getattr(as_one_of, "label", None)  # one_of's label: its spans group as one_of's did
        self.strategy = eager(_one_of(st.sampled_from(self.branches)))

    def as_one_of(self):
        return st.one_of(*self.branches)


def take(draw, what):
    """Draw from a OneOf or a strategy."""
    if type(what) is OneOf:
        return draw(what.strategy, label=what.label)
    return draw(what)


class Site:
    """Where a one_of whose branches are built during the draw is drawn (see `one_of`)."""

    __slots__ = ("_indices", "index_label", "label")

    def __init__(self, name: str):
        self.label = label(name)
        self.index_label = label(name + ": branch")
        self._indices = {}

    def index(self, draw, n: int) -> int:
        s = self._indices.get(n)
        if s is None:
            s = self._indices[n] = ints(0, n - 1)
        return draw(s, label=self.index_label)


def one_of(draw, site: Site, *branches):
    """st.one_of(*branches) for branches known only during the draw: a branch is a strategy, a
    OneOf (flattened, as one_of flattens it) or a function of `draw` (one that builds its strategy
    only when chosen). The same choice (an index over the flattened branches, then the branch's)
    and the same spans: one_of's around them, the index's, the branch's. Their labels are the
    site's own (one_of's were made from its branches, so no other span shared them either)."""
    flat = []
    for b in branches:
        flat.extend(b.branches if type(b) is OneOf else (b,))

    def body(draw):
        b = flat[site.index(draw, len(flat))]
        return b(draw) if type(b) is FunctionType else draw(b)

    return in_span(draw, site.label, body)


_pending = threading.local()


@st.composite
def _call_pending(draw):
    return _pending.calls[-1](draw)


_CALL_PENDING = eager(_call_pending())


def in_span(draw, span_label: int, body):
    """body(draw), its draws inside a span labelled `span_label`: what a composite built for this
    one call would do, without building one (the strategy is a constant; body waits on a stack)."""
    calls = getattr(_pending, "calls", None)
    if calls is None:
        calls = _pending.calls = []
    calls.append(body)
    try:
        return draw(_CALL_PENDING, label=span_label)
    finally:
        calls.pop()


_INDICES: dict[int, object] = {}


def index(draw, n: int) -> int:
    """An index in [0, n): st.integers(0, n - 1) (prebuilt per n)."""
    s = _INDICES.get(n)
    if s is None:
        s = _INDICES[n] = ints(0, n - 1)
    return draw(s)
