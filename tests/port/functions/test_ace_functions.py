"""Per-function differential tests: single port routines against ACE's own, bit for bit.

Two lanes over the same specs (fn_specs.SPECS: Polygon, Sphere, LandDefs, LandblockStruct /
Landblock, AFrame, Position):

* live (``live_oracle``): fresh inputs (seed "live", about 2,000 per function) through the
  configured ACE and through the port; skipped with a reason when no ACE is configured.
* replay (every push): the inputs and ACE's answers recorded (by record_ace_functions.py) from
  ACE on mono (data/ace_functions.json.gz) and on .NET 10 (data/ace_functions_net10.json.gz),
  each through the port computing as that runtime does. Missing data fails: this lane never
  passes vacuously.
"""

from __future__ import annotations

import functools
import json
import math
import warnings

import fn_specs
import numpy as np
import pytest
from fn_specs import SPECS, differences, generate, plain, same

from acconform.errors import OracleUnavailable
from acconform.numerics import runtime_named


RUNTIMES = sorted(fn_specs.DATA)


def _params():
    return [pytest.param(name, marks=pytest.mark.anchor(spec.anchor), id=name) for name, spec in sorted(SPECS.items())]


@pytest.fixture(autouse=True)
def _quiet_numpy():
    """Degenerate polygons divide by zero in float32 exactly as ACE does; numpy only warns."""
    with warnings.catch_warnings(), np.errstate(all="ignore"):
        warnings.simplefilter("ignore", RuntimeWarning)
        yield


@pytest.fixture(scope="module")
def ace_functions():
    """ACE's single routines on the configured ACE (ACE_ASSEMBLY / --ace / config), or a visible skip."""
    from acconform.oracle import live_configured
    from acconform.oracle.functions import AceFunctions

    if not live_configured():
        pytest.skip("no ACE configured: set ACE_ASSEMBLY=/path/to/ACE.Server.dll to run the live-oracle lane")
    try:
        return AceFunctions()
    except OracleUnavailable as e:
        pytest.fail(f"ACE is configured but the function oracle cannot load: {e}")


@functools.lru_cache(maxsize=2)
def recorded(runtime: str) -> dict:
    """ACE's recorded answers from an ACE on `runtime` ("mono" or "coreclr")."""
    path = fn_specs.DATA[runtime]
    if not path.is_file():
        pytest.fail(f"{path} is missing: record it with ACE_ASSEMBLY=/path/to/ACE.Server.dll (a {runtime} build) "
                    "python tests/port/functions/record_ace_functions.py")
    return fn_specs.load(path)


# ---------------------------------------------------------------- live lane


@pytest.mark.live_oracle
@pytest.mark.parametrize("name", _params())
def test_port_matches_live_ace_bit_for_bit_on_generated_inputs(name, ace_functions):
    spec = SPECS[name]
    ctx, inputs = generate(spec, "live", spec.live_n)
    answers = [plain(spec.ace(ace_functions, ctx, a)) for a in inputs]
    count, shown = differences(spec, ctx, inputs, answers, runtime=runtime_named(ace_functions.runtime_version))
    assert count == 0, f"{count} of {len(inputs)} inputs differ:\n" + "\n".join(shown)


@pytest.mark.live_oracle
@pytest.mark.anchor("CPolygon::make_plane")
def test_recorded_answers_are_what_the_configured_ace_answers(ace_functions):
    """Every third recorded input through this ACE: recorded data from another build shows up here."""
    stale = []
    for name, entry in sorted(recorded(runtime_named(ace_functions.runtime_version))["functions"].items()):
        spec = SPECS[name]
        for args, want in list(zip(entry["inputs"], entry["answers"]))[::3]:
            got = plain(spec.ace(ace_functions, entry["context"], args))
            if not same(got, want):
                stale.append(f"{name}{tuple(args)!r}: recorded {want!r}, this ACE {got!r}")
                break
    assert stale == [], "re-record with record_ace_functions.py:\n" + "\n".join(stale)


# ---------------------------------------------------------------- replay lane (no ACE)


@pytest.mark.parametrize("runtime", RUNTIMES)
def test_recorded_data_has_ace_answers_for_every_function(runtime):
    doc = recorded(runtime)
    assert set(doc["functions"]) == set(SPECS)
    assert doc["versions"]["ace"] and runtime_named(doc["versions"]["runtime"]) == runtime
    for name, entry in doc["functions"].items():
        assert len(entry["inputs"]) == len(entry["answers"]) >= SPECS[name].record_n, name


@pytest.mark.parametrize("runtime", RUNTIMES)
@pytest.mark.parametrize("name", _params())
def test_port_matches_recorded_ace_answers_bit_for_bit(name, runtime):
    entry = recorded(runtime)["functions"][name]
    count, shown = differences(SPECS[name], entry["context"], entry["inputs"], entry["answers"], runtime=runtime)
    assert count == 0, f"{count} of {len(entry['inputs'])} recorded inputs differ:\n" + "\n".join(shown)


@pytest.mark.parametrize("name", _params())
def test_recorded_inputs_reach_more_than_one_answer(name):
    """A generator that only ever reaches one outcome would check nothing: each function's
    recorded answers take at least two distinct values (both results of a predicate)."""
    answers = recorded("mono")["functions"][name]["answers"]
    assert len({repr(fn_specs._key(a)) for a in answers}) >= 2


@pytest.mark.parametrize("name", ["point_in_poly2D", "polygon_hits_sphere_precise", "check_walkable",
                                  "adjust_sphere_to_plane", "walkable_hits_sphere", "pos_hits_sphere"])
def test_recorded_predicates_answer_both_ways_often(name):
    answers = recorded("mono")["functions"][name]["answers"]
    firsts = [a[0] if isinstance(a, tuple) else a for a in answers]
    assert min(firsts.count(True), firsts.count(False)) >= len(firsts) // 20, name


# ---------------------------------------------------------------- the comparator and the codec


def test_comparison_tells_negative_zero_from_zero_bools_from_ints_and_float32_ulps():
    assert same((True, 0.0), (True, 0.0))
    assert not same(-0.0, 0.0)
    assert not same(True, 1)
    assert not same(1.0, fn_specs.up_ulp(1.0))
    assert same(float("nan"), float("nan"))
    assert same(np.float32(0.1), float(np.float32(0.1)))
    assert not same(np.float64(0.1), float(np.float32(0.1)))  # a double is not its float32 rounding
    assert same(("error", "InvalidOperationException"), ("error", "InvalidOperationException"))
    assert not same(None, ("error", "InvalidOperationException"))


@pytest.mark.parametrize("value", [0.1, -0.0, 1e-45, 3.4028234663852886e38, float("inf"), 2.0 / 3.0, -1.0,
                                   0.49750620126724243, float(np.float32(0.1)), 2147483648, True, None, "error"])
def test_codec_keeps_float32_values_doubles_and_specials_exactly(value):
    back = fn_specs.dec(json.loads(json.dumps(fn_specs.enc(value), allow_nan=False)))
    if isinstance(value, float) and math.isnan(value):
        assert math.isnan(back)
    else:
        assert same(back, value) and type(back) is type(value)


def test_codec_writes_float32_values_in_their_shortest_form():
    assert fn_specs.enc(float(np.float32(0.1))) == 0.1
    assert fn_specs.enc(2.0 / 3.0) == "d:" + repr(2.0 / 3.0)
    assert fn_specs.enc(float("inf")) == "0x7f800000"


def test_generated_inputs_are_deterministic_and_float32_exact():
    for name in ("make_plane", "get_outside_lcoord", "landblock_struct", "frame_combine"):
        spec = SPECS[name]
        a = generate(spec, "x", 20)
        assert same(a, generate(spec, "x", 20))

    def floats(x):
        if isinstance(x, float):
            yield x
        elif isinstance(x, (tuple, list)):
            for v in x:
                yield from floats(v)

    _, inputs = generate(SPECS["polygon_hits_sphere_precise"], "x", 200)
    assert all(math.isnan(f) or float(np.float32(f)) == f for f in floats(inputs))
