"""Floats survive the JSON trip bit for bit; ids and flags read back as written."""

import json
import math
import struct

import numpy as np
from hypothesis import example, given, settings, strategies as st

from acconform.codec import Reader, write_f32
from acconform.errors import InvalidScene

finite_f32_bits = st.integers(0, 0xFFFFFFFF).filter(lambda b: (b >> 23) & 0xFF != 0xFF)


def _trip(bits: int, allow_nonfinite=False) -> int:
    x = struct.unpack("<f", struct.pack("<I", bits))[0]
    text = json.dumps({"v": write_f32(x)})
    back = Reader(json.loads(text)["v"], "v").f32(allow_nonfinite=allow_nonfinite)
    return struct.unpack("<I", struct.pack("<f", back))[0]


@settings(max_examples=3000)
@given(finite_f32_bits)
@example(0x00000000)  # +0
@example(0x80000000)  # -0
@example(0x00000001)  # smallest subnormal
@example(0x007FFFFF)  # largest subnormal
@example(0x00800000)  # smallest normal
@example(0x7F7FFFFF)  # largest finite
@example(0xFF7FFFFF)  # most negative finite
@example(0x3F2A0751)  # FloorZ
def test_every_finite_float32_round_trips_through_json_bit_for_bit(bits):
    assert _trip(bits) == bits


@given(st.integers(0, 0x7FFFFF))
def test_subnormals_of_both_signs_round_trip(mantissa):
    assert _trip(mantissa) == mantissa
    assert _trip(0x80000000 | mantissa) == 0x80000000 | mantissa


def test_non_finite_outcome_values_are_written_as_bit_patterns_and_read_back():
    for bits in (0x7F800000, 0xFF800000, 0x7FC00000, 0xFFC00000):
        x = np.uint32(bits).view(np.float32)
        w = write_f32(x)
        assert w == f"0x{bits:08x}"
        assert _trip(bits, allow_nonfinite=True) == bits


def test_written_floats_use_the_shortest_decimal():
    assert json.dumps(write_f32(np.float32(0.1))) == "0.1"
    assert json.dumps(write_f32(np.float32(-0.0))) == "-0.0"


def test_a_double_that_is_not_a_float32_reads_as_the_nearest_float32():
    got = Reader(0.1, "x").f32()
    assert got == float(np.float32(0.1)) and not math.isclose(got, 0.1, rel_tol=1e-12)


_doubles = st.floats(allow_nan=False, allow_infinity=False, min_value=-3.4028234e38, max_value=3.4028234e38)


@settings(max_examples=400)
@given(st.tuples(_doubles, _doubles, _doubles))
@example((0.1, -0.0, 1.401298464324817e-45))  # a decimal, -0, the smallest subnormal
@example((1.0000000596046448, 1.0000001788139343, 7.006492321624085e-46))  # ties to even; half the smallest subnormal
@example((3.4028235e38, -1.1754942106924411e-38, 5e-324))  # near the largest float32; the smallest normal; a double subnormal
def test_a_vector_reads_each_component_as_the_nearest_float32_as_a_single_number_does(v):
    """Reader.vec3's batched rounding (one struct pack of three) is f32()'s numpy rounding, bit for bit."""
    got = Reader(list(v), "v").vec3()
    want = tuple(Reader(x, "v").f32() for x in v)
    assert [struct.pack("<f", x) for x in got] == [struct.pack("<f", x) for x in want]


def _f32_of_bits(bits: int) -> float:
    return struct.unpack("<f", struct.pack("<I", bits))[0]


# what an implementation may write for one float of an answer: a float32 exactly, a short decimal
# naming one, a decimal naming none, an integer, a bit pattern, a value past float32's range
_answer_numbers = st.one_of(st.integers(0, 0xFFFFFFFF).map(_f32_of_bits).filter(math.isfinite),
                            st.sampled_from([0.1, 1e-45, 0.30000001, 0.123456789012, 3.4028236e38, -0.0, 7, -3,
                                             "0x7fc00000", "0x80000000", 1e300]),
                            _doubles)


@settings(max_examples=600)
@given(st.integers(3, 4).flatmap(lambda n: st.lists(_answer_numbers, min_size=n, max_size=n)), st.booleans(),
       st.booleans())
def test_a_batched_read_of_float32s_takes_and_refuses_what_one_at_a_time_does(values, exact, nonfinite):
    """Reader.f32s (an outcome's vectors and quaternions, a scene's vectors) gives f32()'s values,
    bit for bit, or the same refusal, in exact (an implementation's answer) and plain reading."""
    def read(how):
        try:
            got = how()
        except InvalidScene as e:
            return str(e)
        return [struct.pack("<f", x) for x in got]

    batched = read(lambda: Reader(list(values), "v", exact=exact).f32s(len(values), allow_nonfinite=nonfinite))
    one_by_one = read(lambda: [r.f32(nonfinite) for r in Reader(list(values), "v", exact=exact).list(count=len(values))])
    assert batched == one_by_one


@settings(max_examples=2000)
@given(st.integers(0, 0xFFFFFFFF), st.integers(0, 0xFFFFFFFF), st.integers(0, 0xFFFFFFFF))
@example(0x80000000, 0x00000000, 0x7FC00000)  # -0, +0, NaN
@example(0x7F800000, 0xFF800000, 0x00000001)  # both infinities, the smallest subnormal
def test_float_and_vector_texts_are_what_json_writes_of_their_written_values(a, b, c):
    """f32_text and vec_text (the text `compact` writes for records) are json's text of write_f32 and
    write_vec, bit patterns of non-finite values, signed zeros and a repeated value included."""
    from acconform.codec import dumps_compact, f32_text, vec_text, write_vec

    v = tuple(struct.unpack("<f", struct.pack("<I", bits))[0] for bits in (a, b, c))
    for _ in range(2):  # the second time from the memos
        assert [f32_text(x) for x in v] == [dumps_compact(write_f32(x)) for x in v]
        assert vec_text(v) == dumps_compact(write_vec(v))
        assert vec_text(v + (v[0],)) == dumps_compact(write_vec(v + (v[0],)))  # a quaternion: no memo


def test_compact_writes_every_kind_of_scene_as_json_writes_its_dict():
    """The records `compact` writes straight to text (Environment, BSPShape and what they hold, Ticks) give
    the bytes dumps_compact gives their to_json(), in generated scenes of every kind and in the
    committed corpus (leaf roots, cell structures without a physics BSP, recorded shapes)."""
    import gzip
    from pathlib import Path

    from acconform.case import parse_document
    from acconform.codec import compact, dumps_compact
    from acconform.protocol import CAMPAIGN_KINDS
    from acconform.strategies import sample_scenes

    scenes = [s for kind in CAMPAIGN_KINDS for s in sample_scenes((kind,), 12, 5)]
    corpus = Path(__file__).parent / "data" / "corpus" / "coreclr"
    for shard in sorted(corpus.glob("*.jsonl.gz")):
        with gzip.open(shard, "rt", encoding="utf-8") as f:
            scenes += [parse_document(json.loads(line)).scene for line, _ in zip(f, range(2))]
    assert len(scenes) > 100 and any(s.environments for s in scenes) and any(s.buildings for s in scenes)
    for scene in scenes:
        assert compact(scene.to_json) == dumps_compact(scene.to_json()), scene.name
    assert compact(lambda: {"scene": scenes[-1].to_json(), "id": 7}) == dumps_compact({"scene": scenes[-1].to_json(), "id": 7})


def test_compact_writes_a_scene_whose_name_looks_like_its_placeholder_as_json_does():
    """A string of the document's own that reads like the placeholder `compact` puts where a record's
    text goes is never taken for it."""
    from acconform.codec import compact, dumps_compact
    from acconform.strategies import sample_scenes

    scene = next(s for s in sample_scenes(("indoor",), 5, 1) if s.environments)
    for name in ("\x000\x00", "\x001\x00", "\\u00000\\u0000"):
        named = scene.replace(name=name)
        assert compact(named.to_json) == dumps_compact(named.to_json())
