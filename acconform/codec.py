"""JSON reading and writing shared by scenes, outcomes, cases and records.

Floats: every float is a float32. It is written as the shortest decimal that reads back as the
same float32 (numpy's repr), and read by rounding to the nearest float32, so a float32 survives
the trip bit for bit (tests/test_codec.py draws every finite pattern class). Non-finite values,
legal only in outcomes, are written as their bit pattern, e.g. "0x7fc00000"; an outcome's float
may be read from its bit pattern whatever its value ("0x80000000" is -0.0).
An implementation's answer (the protocol) is read strictly (`loads_answer`, `Reader(..., exact=True)`):
JSON ``-0`` is negative zero, and a number that names no float32 -- neither a float32's exact value
nor a decimal of at most 9 significant digits, as every float32 can be written (a double with more
digits, e.g. 0.30000000000000004) -- is refused naming the field, never rounded without a word.
Cell and object ids are written as hex strings ("0xA9B40001") and read from hex strings or ints.
Doubles (a tick scene's clock: ``ticks.start`` and each step's ``dt``) are written as Python's
``repr`` of the double (the shortest decimal that reads back as the same double) and read back
bit for bit by `Reader.f64`; they are always finite.
"""

from __future__ import annotations

import json
import math
import struct
from contextvars import ContextVar
from typing import Any

import numpy as np

from .errors import InvalidScene
from .numerics import to_f32s


_WRITTEN: dict[float, float] = {}  # write_f32's answers for nonzero finite Python floats (by value)
_WRITTEN_LIMIT = 1 << 16


def write_f32(x) -> float | str:
    if type(x) is float:
        written = _WRITTEN.get(x)  # a scene writes the same few hundred values again and again
        if written is not None:
            return written
    v = np.float32(x)
    f = float(v)  # exact: a float32's value is a double's (math's tests cost a tenth of numpy's on a scalar)
    if not math.isfinite(f):
        return f"0x{int(v.view(np.uint32)):08x}"
    if f == 0:  # kept out of the memo: -0.0 and 0.0 are one key
        return math.copysign(0.0, f)
    # float(repr) keeps the shortest digits: json then prints them unchanged.
    written = float(str(v))
    if type(x) is float:  # the answer is a function of x's value (x is nonzero and finite here)
        if len(_WRITTEN) >= _WRITTEN_LIMIT:
            _WRITTEN.clear()
        _WRITTEN[x] = written
    return written


def write_f64(x) -> float:
    """A finite double, as the shortest decimal that reads back as the same double (json writes
    a Python float with its repr)."""
    v = float(x)
    if not math.isfinite(v):
        raise ValueError(f"a double written to JSON must be finite, got {v}")
    return v


_WRITTEN_VECS: dict[bytes, list] = {}  # write_vec's answers for 3-vectors of Python floats, by their bits
_F64x3 = struct.Struct("=3d")


def write_vec(v) -> list:
    if len(v) == 3 and type(v[0]) is float and type(v[1]) is float and type(v[2]) is float:
        key = _F64x3.pack(*v)  # the bits: -0.0 and 0.0 are two keys (a vertex recurs, in a scene and across)
        written = _WRITTEN_VECS.get(key)
        if written is None:
            if len(_WRITTEN_VECS) >= _WRITTEN_LIMIT:
                _WRITTEN_VECS.clear()
            written = _WRITTEN_VECS[key] = [write_f32(c) for c in v]
        return list(written)
    return [write_f32(c) for c in v]


def write_id(n: int) -> str:
    return f"0x{n:08X}"


# ---------------------------------------------------------------- records written straight to text
# A scene goes to an implementation (and into its hash) as compact JSON. A dungeon's or a building's
# cell structures and BSPs are most of that text, and building their dicts for json to walk costs
# three times what writing their text costs. So while `compact` writes, the records that hold them
# (Environment, BSPShape; a tick scene's Ticks) write their own text (`json_text`) and answer to_json() with a placeholder
# string, which `compact` replaces in json's text. That text is byte for byte what dumps_compact
# writes of their to_json() (tests/test_codec.py: every kind of scene, and the corpus).


class _Writing:
    __slots__ = ("texts",)

    def __init__(self):
        self.texts: list[str] = []


_TEXT: ContextVar[_Writing | None] = ContextVar("acconform_codec_text", default=None)


def as_text(record) -> str | None:
    """While `compact` writes: the record's text (``record.json_text()``) is kept, and a placeholder
    for it answered. Else None."""
    writing = _TEXT.get()
    if writing is None:
        return None
    writing.texts.append(record.json_text())
    return f"\x00{len(writing.texts) - 1}\x00"


def compact(make) -> str:
    """``dumps_compact(make())``, where the records make() writes may write their own text (`as_text`)."""
    writing = _Writing()
    token = _TEXT.set(writing)
    try:
        doc = make()
    finally:
        _TEXT.reset(token)
    text = dumps_compact(doc)
    holders = [f'"\\u0000{k}\\u0000"' for k in range(len(writing.texts))]  # json's text of each placeholder
    if any(text.count(h) != 1 for h in holders):  # a string of the doc's own looks like one: json writes all
        return dumps_compact(make())
    for holder, record_text in zip(holders, writing.texts):
        text = text.replace(holder, record_text, 1)
    return text


_ascii = json.encoder.encode_basestring_ascii  # how json writes a key or a string (ensure_ascii)


_TEXTS: dict[float, str] = {}  # f32_text's answers for nonzero finite Python floats (by value): the
# float's repr is most of the cost of a value write_f32 remembers (0.1 ms of an indoor scene's 0.4)


def f32_text(x) -> str:
    """The JSON text of write_f32(x)."""
    if type(x) is float and x != 0.0 and x == x:  # -0.0 and 0.0 are one key; a NaN finds none
        text = _TEXTS.get(x)
        if text is None:
            if len(_TEXTS) >= _WRITTEN_LIMIT:
                _TEXTS.clear()
            text = _TEXTS[x] = _scalar_text(write_f32(x))
        return text
    return _scalar_text(write_f32(x))


def _scalar_text(w) -> str:
    return float.__repr__(w) if type(w) is float else _ascii(w)


_VEC_TEXTS: dict[bytes, str] = {}  # vec_text's answers for 3-vectors of Python floats, by their bits


def vec_text(v) -> str:
    """The JSON text of write_vec(v)."""
    if len(v) == 3 and type(v[0]) is float and type(v[1]) is float and type(v[2]) is float:
        key = _F64x3.pack(*v)
        text = _VEC_TEXTS.get(key)
        if text is None:
            if len(_VEC_TEXTS) >= _WRITTEN_LIMIT:
                _VEC_TEXTS.clear()
            text = _VEC_TEXTS[key] = "[" + ",".join(map(f32_text, v)) + "]"
        return text
    return "[" + ",".join(map(f32_text, v)) + "]"


def ints_text(seq) -> str:
    """The JSON text of a list of ints."""
    return "[" + ",".join(map(int.__repr__, seq)) + "]"


def dumps(obj: Any) -> str:
    return json.dumps(obj, indent=1, allow_nan=False)


# what JSON the codec writes holds no cycles (records and outcomes are trees), so the encoder
# skips its check for them (a sixth of the time of a large scene)
dumps_compact = json.JSONEncoder(separators=(",", ":"), allow_nan=False, check_circular=False).encode


F32_MAX = float(np.finfo(np.float32).max)
# every float32 has a decimal of at most this many significant digits that reads back to it
# (C's "%.9g", .NET's "G9"; the shortest form has fewer)
F32_DIGITS = 9


def _parse_int(text: str):
    return -0.0 if text == "-0" else int(text)


def loads_answer(text: str) -> Any:
    """JSON as an implementation writes it: ``-0`` read as negative zero (json reads it as the integer 0)."""
    return json.loads(text, parse_int=_parse_int)


_NAMED: dict[float, bool] = {}  # names_a_float32's answers for floats that are not float32s (by value)


def names_a_float32(v: float | int, r: float) -> bool:
    """Whether the number `v` read from JSON names the float32 `r` it rounds to: `r` exactly, or
    written in at most F32_DIGITS significant digits (what a double computation's 17 digits are not)."""
    if v == r:
        return True
    if isinstance(v, int):
        return len(str(abs(v)).rstrip("0")) <= F32_DIGITS
    named = _NAMED.get(v)  # an answer's floats recur, tick after tick and answer after answer
    if named is None:
        if len(_NAMED) >= _WRITTEN_LIMIT:
            _NAMED.clear()
        named = _NAMED[v] = len(repr(v).lstrip("-").split("e", 1)[0].replace(".", "").strip("0")) <= F32_DIGITS
    return named


class Reader:
    """Walks a parsed JSON document, checking types and naming the field path in every error."""

    __slots__ = ("value", "_path", "_parent", "_key", "exact")

    def __init__(self, value: Any, path: str = "", parent: "Reader | None" = None, key=None, exact: bool = False):
        self.value = value
        # exact: a float must name a float32 (an implementation's answer), not be rounded to one
        self.exact = parent.exact if parent is not None else exact
        # a child's path string is built only when asked for (an error message): reading a scene
        # makes a Reader per number, and formatting every path was a third of the reading time
        self._path = path if parent is None else None
        self._parent = parent
        self._key = key

    @property
    def path(self) -> str:
        if self._path is None:
            self._path = self._parent._child_path(self._key)
        return self._path

    def fail(self, problem: str):
        raise InvalidScene(self.path, problem)

    def _child_path(self, key) -> str:
        if isinstance(key, int):
            return f"{self.path}[{key}]"
        return f"{self.path}.{key}" if self.path else key

    def obj(self, allowed: set[str] | frozenset[str]) -> "Reader":
        if not isinstance(self.value, dict):
            self.fail(f"expected an object, got {_kind(self.value)}")
        if self.value.keys() <= allowed:  # the common case, without building sets
            return self
        unknown = sorted(set(self.value) - set(allowed))
        if unknown:
            self.fail(f"unknown field {unknown[0]!r} (allowed: {', '.join(sorted(allowed))})")
        return self

    def has(self, key: str) -> bool:
        return key in self.value and self.value[key] is not None

    def given(self, key: str) -> bool:
        """Whether the optional field `key` (one with a default when left out) is given. A null
        there is refused naming the field: null is no value, and leaving the field out is how a
        file asks for the default (``"velocity": null`` is not ``[0, 0, 0]``)."""
        if key not in self.value:
            return False
        if self.value[key] is None:
            raise InvalidScene(self._child_path(key), "null is not a value here; leave the field out for its default")
        return True

    def __getitem__(self, key) -> "Reader":
        if isinstance(key, str):
            if key not in self.value:
                raise InvalidScene(self._child_path(key), "missing required field")
        return Reader(self.value[key], "", self, key)

    def get(self, key: str) -> "Reader | None":
        if key not in self.value or self.value[key] is None:
            return None
        return Reader(self.value[key], "", self, key)

    def list(self, count: int | None = None, min_count: int | None = None, max_count: int | None = None) -> list["Reader"]:
        if not isinstance(self.value, list):
            self.fail(f"expected a list, got {_kind(self.value)}")
        n = len(self.value)
        if count is not None and n != count:
            self.fail(f"expected {count} values, got {n}")
        if min_count is not None and n < min_count:
            self.fail(f"expected at least {min_count} values, got {n}")
        if max_count is not None and n > max_count:
            self.fail(f"expected at most {max_count} values, got {n}")
        return [Reader(v, "", self, i) for i, v in enumerate(self.value)]

    def f32(self, allow_nonfinite: bool = False) -> float:
        """A float32. `allow_nonfinite` (an outcome's floats): also non-finite, and any float32 may
        be given as its bit pattern ("0x80000000")."""
        v = self.value
        if type(v) is float and -F32_MAX < v < F32_MAX:  # the common case: rounds to a finite float32
            r = float(np.float32(v))
            if self.exact and r != v and not names_a_float32(v, r):
                self._not_a_float32(v, r)
            return r
        if isinstance(v, str) and allow_nonfinite and v.lower().startswith("0x"):
            try:
                bits = int(v, 16)
            except ValueError:
                self.fail(f"expected a number or a float32 bit pattern, got {v!r}")
            if not 0 <= bits <= 0xFFFFFFFF:
                self.fail(f"a float32 bit pattern has at most 8 hex digits, got {v!r}")
            return float(np.uint32(bits).view(np.float32))
        if isinstance(v, bool) or not isinstance(v, (int, float)):
            self.fail(f"expected a number{' or a float32 bit pattern' if allow_nonfinite else ''}, got {_kind(v)}")
        if not math.isfinite(v):
            self.fail(f"expected a finite number, got {v}")
        with np.errstate(over="ignore"):
            r = np.float32(v)
        if not np.isfinite(r) and not allow_nonfinite:
            self.fail(f"{v} is outside float32's range")
        if self.exact and np.isfinite(r) and not names_a_float32(v, float(r)):
            self._not_a_float32(v, float(r))
        return float(r)

    def f64(self) -> float:
        """A finite double (the shortest round-trip decimal `write_f64` writes reads back bit for bit)."""
        v = self.value
        if isinstance(v, bool) or not isinstance(v, (int, float)):
            self.fail(f"expected a number, got {_kind(v)}")
        try:
            d = float(v)
        except OverflowError:
            self.fail(f"{v} is outside a double's range")
        if not math.isfinite(d):
            self.fail(f"expected a finite number, got {v}")
        return d

    def _not_a_float32(self, v, r: float):
        f = np.float32(r)
        self.fail(f"{v!r} is not a float32 (the nearest is {str(f)}): write a float32 exactly, in at most "
                  f"{F32_DIGITS} significant digits, or as its bit pattern '0x{int(f.view(np.uint32)):08x}'")

    def f32s(self, count: int, allow_nonfinite: bool = False) -> tuple[float, ...]:
        """A list of `count` float32s (``tuple(r.f32(allow_nonfinite) for r in self.list(count))``)."""
        v = self.value
        if type(v) is list and len(v) == count and count in (3, 4):  # the common case, without a Reader per number
            for x in v:
                if type(x) is not float or not -F32_MAX < x < F32_MAX:
                    break
            else:
                rounded = to_f32s(v)  # each rounded to float32 (C's (float) cast)
                if not self.exact or all(map(names_a_float32, v, rounded)):  # exact: each names its float32
                    return rounded
        return tuple(r.f32(allow_nonfinite) for r in self.list(count=count))

    def vec3(self) -> tuple[float, float, float]:
        return self.f32s(3)

    def vec3s(self) -> list[tuple[float, float, float]]:
        """A list of vec3s (``[r.vec3() for r in self.list()]``)."""
        if not isinstance(self.value, list):
            self.fail(f"expected a list, got {_kind(self.value)}")
        return [Reader(v, "", self, i).vec3() for i, v in enumerate(self.value)]

    def ints(self, lo: int, hi: int, count: int | None = None) -> tuple[int, ...]:
        """A list of integers in [lo, hi] (``tuple(r.int_(lo, hi) for r in self.list(count))``), read
        without a Reader per number when they all are; a bad one fails as int_ names it."""
        v = self.value
        if type(v) is list and (count is None or len(v) == count) and all(
                type(n) is int and lo <= n <= hi for n in v):
            return tuple(v)
        return tuple(r.int_(lo, hi) for r in self.list(count=count))

    def int_(self, lo: int | None = None, hi: int | None = None) -> int:
        v = self.value
        if type(v) is not int:  # bool is a subclass of int, not int itself
            self.fail(f"expected an integer, got {_kind(v)}")
        if (lo is not None and v < lo) or (hi is not None and v > hi):
            self.fail(f"expected an integer in [{lo}, {hi}], got {v}")
        return v

    def id_(self) -> int:
        v = self.value
        if isinstance(v, str):
            try:
                n = int(v, 16) if v.lower().startswith("0x") else int(v)
            except ValueError:
                self.fail(f"expected an id like '0xA9B40001', got {v!r}")
        elif isinstance(v, int) and not isinstance(v, bool):
            n = v
        else:
            self.fail(f"expected an id like '0xA9B40001', got {_kind(v)}")
        if not 0 <= n <= 0xFFFFFFFF:
            self.fail(f"id {v!r} does not fit in 32 bits")
        return n

    def bool_(self) -> bool:
        if not isinstance(self.value, bool):
            self.fail(f"expected true or false, got {_kind(self.value)}")
        return self.value

    def str_(self) -> str:
        if not isinstance(self.value, str):
            self.fail(f"expected a string, got {_kind(self.value)}")
        return self.value

    def enum_(self, enum) -> int:
        """One member of `enum`, by its name."""
        name = self.str_()
        if name not in enum.__members__:
            self.fail(f"unknown {enum.__name__} {name!r} (known: {', '.join(enum.__members__)})")
        return int(enum[name])

    def flags(self, enum) -> int:
        members = enum.__members__  # a copy per call for a FlagSet: taken once
        value = 0
        for r in self.list():
            name = r.str_()
            if name not in members:
                r.fail(f"unknown {enum.__name__} flag {name!r} (known: {', '.join(members)})")
            value |= int(members[name])
        return value


def _kind(v: Any) -> str:
    if v is None:
        return "null"
    if isinstance(v, bool):
        return "a boolean"
    if isinstance(v, (int, float)):
        return f"the number {v}"
    if isinstance(v, str):
        return f"the string {v!r}"
    if isinstance(v, list):
        return f"a list of {len(v)}"
    return "an object" if isinstance(v, dict) else type(v).__name__


def parse_json_text(text: str, source: str | None = None) -> Any:
    from . import deep

    try:
        return deep.loads(text)
    except deep.TooDeep as e:
        raise e.in_file(source) if source else e from None
    except json.JSONDecodeError as e:
        raise InvalidScene("", f"not valid JSON: {e.msg} at line {e.lineno} column {e.colno}", source) from None


def json_line(line: str, where: str) -> Any:
    """One line of a JSON-lines file, parsed; InvalidScene naming `where` when it is not JSON."""
    from . import deep

    try:
        return deep.loads(line)
    except deep.TooDeep as e:
        raise e.in_file(where) from None
    except ValueError as e:
        raise InvalidScene("", f"not JSON ({e})", where) from None
