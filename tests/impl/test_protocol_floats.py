"""The protocol carries every float32: bit patterns for any float, JSON -0 as negative zero, and a
number that names no float32 refused as a protocol error naming the field (docs/protocol.md, "Floats")."""

from __future__ import annotations

import json
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest

from acconform.codec import Reader, loads_answer, names_a_float32
from acconform.errors import InvalidScene
from acconform.impl import BuiltinPort
from acconform.outcome import Outcome
from acconform.protocol import PROTOCOL_ERROR, Implementation, handshake
from acconform.case import load_document as load_scene

ROOT = Path(__file__).resolve().parents[2]

# An implementation that answers every request with the outcome text in the file it is given,
# written as is: the test controls every character of the answer.
ECHO = textwrap.dedent("""
    import json, sys
    answer = open(sys.argv[1]).read().strip()
    print(json.dumps(json.loads(sys.argv[2])), flush=True)
    for line in sys.stdin:
        if line.strip():
            sys.stdout.write('{"id": %d, "outcome": %s}\\n' % (json.loads(line)["id"], answer))
            sys.stdout.flush()
""")


def bits(x: float) -> int:
    return int(np.float32(x).view(np.uint32))


@pytest.fixture(scope="module")
def scene_and_outcome():
    scene = load_scene(ROOT / "examples" / "flat_walk.json")
    return scene, BuiltinPort(runtime="coreclr")(scene)


def answer_with(tmp_path, text: str):
    """Run an implementation that answers `text` (an outcome's JSON) and return the outcome the harness read."""
    script = tmp_path / "echo_impl.py"
    script.write_text(ECHO)
    (tmp_path / "answer.json").write_text(text)
    impl = Implementation(f"{sys.executable} {script} {tmp_path / 'answer.json'} '{json.dumps(handshake())}'")
    try:
        return impl(load_scene(ROOT / "examples" / "flat_walk.json"))
    finally:
        impl.close()


def with_raw(outcome: Outcome, path: tuple, raw: str) -> str:
    """The outcome's JSON with the value at `path` replaced by the text `raw`, character for character."""
    doc = outcome.to_json()
    node = doc
    for key in path[:-1]:
        node = node[key]
    node[path[-1]] = "@RAW@"
    return json.dumps(doc).replace('"@RAW@"', raw)


def test_every_float_of_an_outcome_may_be_its_bit_pattern(tmp_path, scene_and_outcome):
    _, outcome = scene_and_outcome
    doc = outcome.to_json()

    def as_bits(node):
        if isinstance(node, float):
            return f"0x{bits(node):08x}"
        if isinstance(node, list):
            return [as_bits(x) for x in node]
        if isinstance(node, dict):
            return {k: as_bits(v) for k, v in node.items()}
        return node

    text = json.dumps(as_bits(doc))
    assert text.count('"0x') > 20  # every float went as bits (ids are "0x" too, upper case)
    got = answer_with(tmp_path, text)
    assert got.error is None and got == outcome


def test_json_minus_zero_and_the_bit_pattern_0x80000000_are_negative_zero(tmp_path, scene_and_outcome):
    _, outcome = scene_and_outcome
    for raw in ("-0", "-0.0", '"0x80000000"'):
        got = answer_with(tmp_path, with_raw(outcome, ("contact_plane", "normal", 0), raw))
        assert got.error is None, got.error
        assert bits(got.contact_plane.normal[0]) == 0x80000000, raw
    got = answer_with(tmp_path, with_raw(outcome, ("contact_plane", "normal", 0), "0"))
    assert bits(got.contact_plane.normal[0]) == 0


def test_a_double_that_is_no_float32_is_a_protocol_error_naming_the_field(tmp_path, scene_and_outcome):
    _, outcome = scene_and_outcome
    got = answer_with(tmp_path, with_raw(outcome, ("contact_plane", "d"), "0.30000000000000004"))
    assert got.error.startswith(f"{PROTOCOL_ERROR}: malformed answer (outcome.contact_plane.d: 0.30000000000000004 "
                                "is not a float32 (the nearest is 0.3)"), got.error
    assert "'0x3e99999a'" in got.error
    got = answer_with(tmp_path, with_raw(outcome, ("velocity", 2), "-9.800000000000002"))
    assert got.error.startswith(f"{PROTOCOL_ERROR}: malformed answer (outcome.velocity[2]: "), got.error


@pytest.mark.parametrize("raw, value", [
    ("0.1", np.float32(0.1)),                      # the shortest round-trip form
    ("0.100000001", np.float32(0.1)),              # C's %.9g
    ("0.10000000149011612", np.float32(0.1)),      # the float32's exact value (JavaScript's Math.fround)
    ("16777216", np.float32(16777216)),
    ("1e-45", np.float32(1e-45)),                  # the smallest subnormal
    ("3.4028235e+38", np.finfo(np.float32).max),
])
def test_a_float32_written_exactly_or_in_nine_digits_is_read_bit_for_bit(raw, value):
    got = Reader(loads_answer(raw), "x", exact=True).f32(allow_nonfinite=True)
    assert bits(got) == bits(value)


@pytest.mark.parametrize("raw", ["0.30000000000000004", "0.1000000001", "123456789012", "1.00000011920929"])
def test_a_number_with_more_digits_than_a_float32_needs_is_refused(raw):
    with pytest.raises(InvalidScene, match=r"x: .* is not a float32"):
        Reader(loads_answer(raw), "x", exact=True).f32(allow_nonfinite=True)
    Reader(json.loads(raw), "x").f32()  # a file's float (not an answer) still reads, rounded as before


def test_a_bit_pattern_wider_than_32_bits_is_refused():
    with pytest.raises(InvalidScene, match="at most 8 hex digits"):
        Reader("0x180000000", "x").f32(allow_nonfinite=True)


def test_nine_significant_digits_name_any_float32():
    rng = np.random.default_rng(23)
    for b in rng.integers(0, 0x7F800000, 2000, dtype=np.uint32):
        f = np.uint32(b).view(np.float32)
        for text in (str(f), f"{float(f):.9g}", repr(float(f))):
            v = json.loads(text)
            assert names_a_float32(v, float(f)) and float(np.float32(v)) == float(f), text
