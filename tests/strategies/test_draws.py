"""strategies/draws.py stands in for Hypothesis' own strategies: same choices, same spans, same scenes.

Most generated examples are mutations of earlier ones, made by copying choices between spans
with the same label, so a stand-in must reproduce the spans and labels too: these tests draw a
few hundred examples (generation, mutations included) from a stand-in and from the strategy it
replaces under the same seed and require the very same values. Plus: Field.landblock (numpy)
agrees with the vertex-by-vertex definition.
"""

from __future__ import annotations

import pytest
from hypothesis import HealthCheck, Phase, given, settings
from hypothesis import seed as hseed
from hypothesis import strategies as st

from acconform.numerics import to_f32
from acconform.strategies import draws as dr
from acconform.strategies import shapes as sh
from acconform.strategies import terrain as tr
from acconform.strategies.determinism import pinned_constants


def _examples(strategy, n=300, seed=5):
    out = []

    @hseed(seed)
    @settings(max_examples=n, database=None, phases=[Phase.generate], deadline=None,
              suppress_health_check=list(HealthCheck))
    @given(strategy)
    def collect(x):
        out.append(x)

    with pinned_constants():
        collect()
    return out


A = st.sampled_from((0.0, 0.5, 1.0))
B = sh.f32s(0.0, 1.0)
C = sh.f32s(1.0, 6.0)
STAND_IN = dr.OneOf(A, dr.f32(0.0, 1.0), dr.f32(1.0, 6.0))
NESTED = dr.OneOf(dr.OneOf(st.just(0.0), st.integers(-3, 3)), st.sampled_from((7, 8)))
OTHER = dr.OneOf(st.integers(0, 9), dr.f32(2.0, 3.0))


@st.composite
def _with_stand_ins(draw):
    # the same OneOf twice (their spans share a label: mutations copy between them), nested ones
    return (dr.take(draw, STAND_IN), draw(dr.BOOLEANS), dr.take(draw, STAND_IN), dr.take(draw, NESTED),
            draw(dr.f32(-5.0, 5.0)), dr.take(draw, OTHER))


@st.composite
def _with_hypothesis_strategies(draw):
    return (draw(st.one_of(A, B, C)), draw(st.booleans()), draw(st.one_of(A, B, C)),
            draw(st.one_of(st.one_of(st.just(0.0), st.integers(-3, 3)), st.sampled_from((7, 8)))),
            draw(sh.f32s(-5.0, 5.0)), draw(st.one_of(st.integers(0, 9), sh.f32s(2.0, 3.0))))


def test_one_of_and_f32_stand_ins_draw_what_the_hypothesis_strategies_draw():
    for seed in (1, 2):
        assert _examples(_with_stand_ins(), seed=seed) == _examples(_with_hypothesis_strategies(), seed=seed)


SITE = dr.Site("test: a one_of known during the draw")


@st.composite
def _dynamic_stand_in(draw):
    k, r = draw(st.integers(0, 3)), draw(sh.f32s(0.1, 1.5))  # (an integer: the index must not group with it)
    return k, r, dr.one_of(draw, SITE, lambda d: d(sh.f32s(r, 2 * r)), NESTED, lambda d: d(st.sampled_from((r, 3 * r))))


@st.composite
def _dynamic_one_of(draw):
    k, r = draw(st.integers(0, 3)), draw(sh.f32s(0.1, 1.5))
    return k, r, draw(st.one_of(sh.f32s(r, 2 * r), st.one_of(st.one_of(st.just(0.0), st.integers(-3, 3)),
                                                          st.sampled_from((7, 8))), st.sampled_from((r, 3 * r))))


def test_a_one_of_built_during_the_draw_draws_what_one_of_draws():
    got = _examples(_dynamic_stand_in())
    assert got == _examples(_dynamic_one_of())
    assert {type(v) for _, _, v in got} == {float, int}, "every branch is drawn"


def test_in_span_leaves_nothing_pending_when_its_body_fails():
    @st.composite
    def failing(draw):
        try:
            dr.in_span(draw, dr.label("test"), lambda d: 1 / 0)
        except ZeroDivisionError:
            pass
        return dr.in_span(draw, dr.label("test"), lambda d: d(st.just(3)))

    assert set(_examples(failing(), n=5)) == {3}
    assert dr._pending.calls == []


@st.composite
def _fields_and_blocks(draw):
    flat, tilt = draw(st.sampled_from(sorted(tr.FIELDS)))
    gx, gy = draw(st.integers(8, 2030)), draw(st.integers(8, 2030))
    return draw(tr.FIELDS[flat, tilt]).moved(gx, gy), (gx + draw(st.integers(-12, 12))) // 8, (
        gy + draw(st.integers(-12, 12))) // 8


@settings(max_examples=300, deadline=None, database=None, suppress_health_check=list(HealthCheck))
@given(_fields_and_blocks())
def test_a_landblock_slice_matches_the_field_vertex_by_vertex(case):
    field, bx, by = case
    lb = field.landblock(bx, by)
    assert lb.id == (bx << 24) | (by << 16) | 0xFFFF
    assert lb.heights == tuple(field.height(bx * 8 + x, by * 8 + y) for x in range(9) for y in range(9))
    assert lb.terrain == tuple(field.word(bx * 8 + x, by * 8 + y) for x in range(9) for y in range(9))
    assert all(type(h) is int for h in lb.heights + lb.terrain)


@pytest.mark.parametrize("feature", [
    tr.Feature("step", a=1, b=-1, c=3, k=-20), tr.Feature("box", x0=-1, y0=2, x1=1, y1=2, k=60),
    tr.Feature("ramp", x0=-2, y0=-1, x1=2, y1=3, i=13, j=-4), tr.Feature("water", x0=0, y0=0, x1=4, y1=1)])
def test_a_moved_feature_is_the_same_feature_elsewhere(feature):
    field, moved = tr.Field(100, (feature,), 2, 77), tr.Field(100, (feature.moved(40, -9),), 2, 77)
    for x in range(-6, 7):
        for y in range(-6, 7):
            assert moved.word(x + 40, y - 9) == field.word(x, y)
            # the noise is global (not moved), so compare the noiseless fields' heights
            assert tr.Field(100, moved.features).height(x + 40, y - 9) == tr.Field(100, field.features).height(x, y)


def test_f32_is_floats_of_width_32():
    xs = _examples(st.tuples(dr.f32(0.1, 1.5), dr.f32(-3.0, 3.0)), n=100)
    assert all(to_f32(v) == v and lo <= v <= hi for pair in xs for v, (lo, hi) in zip(pair, ((0.1, 1.5), (-3, 3))))
