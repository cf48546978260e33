"""The comparator, field by field: every Outcome field is compared and reported with both values."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from acconform.compare import FAST_ABS, FAST_ULPS, Difference, compare, float_equal, ulp_distance
from acconform.case import parse_document
from acconform.errors import AcconformError, InvalidScene
from acconform.numerics import f32_from_bits
from acconform.outcome import ContactPlaneState, NormalState, Outcome

BASE = Outcome(ok=True, cell=0xA9B40021, origin=(10.0, 20.0, 30.5), object_info_state=3,
               contact_plane=ContactPlaneState(True, 0xA9B40021, False, (0.0, 0.0, 1.0), -30.0),
               last_known_contact_plane=ContactPlaneState(True, 0xA9B40021, False, (0.0, 0.0, 1.0), -30.0),
               check_cell=0xA9B40021, walkable=True, static_cells=((0xA9B40021, 0xA9B40022), (0xA9B40009,)))


def nudge(x: float, ulps: int = 1) -> float:
    return f32_from_bits(int(np.float32(x).view(np.uint32)) + ulps)


def fields_of(diffs):
    return [d.field for d in diffs]


def test_compare_finds_nothing_between_equal_outcomes():
    assert compare(BASE, BASE) == []
    assert compare(BASE, BASE, "fast") == []


def test_compare_reports_a_flipped_contact_plane_bit():
    other = dataclasses.replace(BASE, contact_plane=dataclasses.replace(BASE.contact_plane, valid=False))
    assert compare(BASE, other) == [Difference("contact_plane.valid", True, False)]
    assert compare(BASE, other, "fast") == [Difference("contact_plane.valid", True, False)]


@pytest.mark.parametrize("field,value", [
    ("ok", False), ("cell", 0xA9B40022), ("check_cell", 0), ("object_info_state", 1),
    ("collided_with_environment", True), ("frames_stationary_fall", 1), ("walkable", False),
    ("step_up", True), ("neg_poly_hit", True),
])
def test_compare_reports_each_discrete_field_in_every_mode(field, value):
    other = dataclasses.replace(BASE, **{field: value})
    for mode in ("exact", "fast"):
        assert compare(BASE, other, mode) == [Difference(field, getattr(BASE, field), value)]


@pytest.mark.parametrize("sub", ["contact_plane", "last_known_contact_plane"])
def test_compare_reports_each_contact_plane_field(sub):
    cp = getattr(BASE, sub)
    for name, value, want in [("cell", 1, f"{sub}.cell"), ("is_water", True, f"{sub}.is_water"),
                              ("normal", (0.0, 1.0, 1.0), f"{sub}.normal[1]"), ("d", -31.0, f"{sub}.d")]:
        other = dataclasses.replace(BASE, **{sub: dataclasses.replace(cp, **{name: value})})
        assert fields_of(compare(BASE, other)) == [want]


@pytest.mark.parametrize("sub", ["collision_normal", "sliding_normal"])
def test_compare_reports_each_normal_field(sub):
    other = dataclasses.replace(BASE, **{sub: NormalState(True, (0.0, 0.0, 0.0))})
    assert fields_of(compare(BASE, other)) == [f"{sub}.valid"]
    other = dataclasses.replace(BASE, **{sub: NormalState(False, (0.0, -0.5, 0.0))})
    assert fields_of(compare(BASE, other)) == [f"{sub}.vector[1]"]


def test_compare_lists_every_differing_vector_component_with_both_values():
    other = dataclasses.replace(BASE, origin=(nudge(10.0), 20.0, 31.0), velocity=(0.0, 0.0, -1.0),
                                orientation=(1.0, 0.0, 0.0, 1.0))
    diffs = compare(BASE, other)
    assert fields_of(diffs) == ["origin[0]", "origin[2]", "orientation[3]", "velocity[2]"]
    assert diffs[0].a == 10.0 and diffs[0].b == nudge(10.0)
    assert "origin[0]: port=10.0 (0x41200000) oracle=10.000001 (0x41200001)" == diffs[0].render()


def test_exact_mode_compares_floats_by_bits():
    assert not float_equal(0.0, -0.0, "exact")
    assert float_equal(math.nan, math.nan, "exact")
    assert not float_equal(math.nan, f32_from_bits(0x7FC00001), "exact")  # another NaN payload
    assert not float_equal(1.0, nudge(1.0), "exact")


def test_fast_mode_allows_the_documented_ulps_or_absolute_slack():
    assert float_equal(1000.0, nudge(1000.0, FAST_ULPS), "fast")
    assert not float_equal(1000.0, nudge(1000.0, FAST_ULPS + 1), "fast")
    assert float_equal(0.0, FAST_ABS * 0.99, "fast")
    assert float_equal(0.0, -0.0, "fast")
    assert float_equal(math.nan, f32_from_bits(0x7FC00001), "fast")
    assert not float_equal(math.inf, 3.4e38, "fast")
    assert ulp_distance(-0.0, 0.0) == 0 and ulp_distance(f32_from_bits(1), f32_from_bits(0x80000001)) == 2


def test_error_presence_always_counts_and_its_type_in_exact_mode_but_never_its_message():
    a = dataclasses.replace(BASE, error="NullReferenceException: landblock 7CBFFFFF is not in the scene")
    a2 = dataclasses.replace(BASE, error="NullReferenceException: Object reference not set to an instance")
    b = dataclasses.replace(BASE, error="AttributeError: y")
    assert fields_of(compare(BASE, a, "fast")) == ["error"]
    assert fields_of(compare(a, b, "exact")) == ["error"]
    assert compare(a, a2, "exact") == []
    assert compare(a, b, "fast") == []


def test_compare_refuses_an_unknown_mode():
    with pytest.raises(AcconformError, match="unknown comparison mode"):
        compare(BASE, BASE, "approximately")


def test_every_outcome_field_is_covered_by_a_field_test():
    # a new Outcome field must show up in a difference when it changes
    for f in dataclasses.fields(Outcome):
        v = getattr(BASE, f.name)
        if isinstance(v, bool):
            new = not v
        elif isinstance(v, int):
            new = v + 1
        elif f.name == "static_cells":
            new = v[:1]
        elif isinstance(v, tuple):
            new = tuple(c + 1.0 for c in v)
        elif isinstance(v, ContactPlaneState):
            new = dataclasses.replace(v, d=v.d + 1.0)
        elif isinstance(v, NormalState):
            new = dataclasses.replace(v, valid=not v.valid)
        else:
            new = "error"
        assert compare(BASE, dataclasses.replace(BASE, **{f.name: new})), f.name


@pytest.mark.parametrize("other", [
    ((0xA9B40022, 0xA9B40021), (0xA9B40009,)),  # same cells, another registration order
    ((0xA9B40021, 0xA9B40022, 0xA9B40029), (0xA9B40009,)),  # one more cell
    ((0xA9B40021, 0xA9B40022),),  # one static fewer
    ((0xA9B40021, 0xA9B40022), ()),  # a static registered nowhere
])
def test_compare_reports_static_cells_that_differ_in_order_or_content_in_every_mode(other):
    changed = dataclasses.replace(BASE, static_cells=other)
    for mode in ("exact", "fast"):
        assert compare(BASE, changed, mode) == [Difference("static_cells", BASE.static_cells, other)]
    assert compare(BASE, changed)[0].render() == (
        "static_cells: port=[[0xA9B40021, 0xA9B40022], [0xA9B40009]] oracle=" + "["
        + ", ".join("[" + ", ".join(f"0x{c:08X}" for c in cells) + "]" for cells in other) + "]")


def test_compare_skips_static_cells_that_one_side_did_not_record():
    unrecorded = dataclasses.replace(BASE, static_cells=None)
    assert compare(BASE, unrecorded) == [] and compare(unrecorded, BASE) == []
    assert compare(dataclasses.replace(unrecorded, ok=False), BASE) == [Difference("ok", False, True)]


def test_outcome_json_carries_static_cells_as_hex_ids_and_reads_them_back():
    doc = BASE.to_json()
    assert doc["format"] == "acconform.outcome/2"
    assert doc["static_cells"] == [["0xA9B40021", "0xA9B40022"], ["0xA9B40009"]]
    assert Outcome.from_json(doc) == BASE
    none = dataclasses.replace(BASE, static_cells=None)
    assert none.to_json()["static_cells"] is None and Outcome.from_json(none.to_json()) == none


def test_outcome_format_2_requires_static_cells_and_format_1_reads_as_not_recorded():
    doc = BASE.to_json()
    del doc["static_cells"]
    with pytest.raises(InvalidScene, match="static_cells.*missing required field"):
        Outcome.from_json(doc)
    v1 = dict(doc, format="acconform.outcome/1")
    old = parse_document(v1)
    assert old == dataclasses.replace(BASE, static_cells=None)
    with pytest.raises(InvalidScene, match="unknown field 'static_cells'"):
        Outcome.from_json(dict(v1, static_cells=[]))
    with pytest.raises(InvalidScene, match=r"static_cells\[0\]\[1\].*expected an id"):
        Outcome.from_json(dict(doc, static_cells=[["0xA9B40021", "wall"]]))
