"""JSON reading and writing shared by scenes, outcomes, cases and records.

Floats: every float is a float32. It is written as the shortest decimal that reads back as the
same float32 (numpy's repr), and read by rounding to the nearest float32, so a float32 survives
the trip bit for bit (tests/test_codec.py draws every finite pattern class). Non-finite values,
legal only in outcomes, are written as their bit pattern, e.g. "0x7fc00000".
Cell and object ids are written as hex strings ("0xA9B40001") and read from hex strings or ints.
"""

from __future__ import annotations

import json
import math
from typing import Any

import numpy as np

from .errors import InvalidScene


def write_f32(x) -> float | str:
    v = np.float32(x)
    if not np.isfinite(v):
        return f"0x{int(v.view(np.uint32)):08x}"
    # float(repr) keeps the shortest digits: json then prints them unchanged.
    return float(str(v)) if v != 0 else (-0.0 if np.signbit(v) else 0.0)


def write_vec(v) -> list:
    return [write_f32(c) for c in v]


def write_id(n: int) -> str:
    return f"0x{n:08X}"


def dumps(obj: Any) -> str:
    return json.dumps(obj, indent=1, allow_nan=False)


def dumps_compact(obj: Any) -> str:
    return json.dumps(obj, separators=(",", ":"), allow_nan=False)


F32_MAX = float(np.finfo(np.float32).max)


class Reader:
    """Walks a parsed JSON document, checking types and naming the field path in every error."""

    __slots__ = ("value", "_path", "_parent", "_key")

    def __init__(self, value: Any, path: str = "", parent: "Reader | None" = None, key=None):
        self.value = value
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
        v = self.value
        if type(v) is float and -F32_MAX < v < F32_MAX:  # the common case: rounds to a finite float32
            return float(np.float32(v))
        if isinstance(v, str) and allow_nonfinite and v.lower().startswith("0x"):
            try:
                bits = int(v, 16)
            except ValueError:
                self.fail(f"expected a number or a float32 bit pattern, got {v!r}")
            return float(np.uint32(bits & 0xFFFFFFFF).view(np.float32))
        if isinstance(v, bool) or not isinstance(v, (int, float)):
            self.fail(f"expected a number, got {_kind(v)}")
        if not math.isfinite(v):
            self.fail(f"expected a finite number, got {v}")
        with np.errstate(over="ignore"):
            r = np.float32(v)
        if not np.isfinite(r) and not allow_nonfinite:
            self.fail(f"{v} is outside float32's range")
        return float(r)

    def vec3(self) -> tuple[float, float, float]:
        a, b, c = (r.f32() for r in self.list(count=3))
        return (a, b, c)

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

    def flags(self, enum) -> int:
        value = 0
        for r in self.list():
            name = r.str_()
            if name not in enum.__members__:
                r.fail(f"unknown {enum.__name__} flag {name!r} (known: {', '.join(enum.__members__)})")
            value |= enum[name].value
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
        return deep.retrying(json.loads, text)
    except deep.TooDeep as e:
        raise e.in_file(source) if source else e from None
    except json.JSONDecodeError as e:
        raise InvalidScene("", f"not valid JSON: {e.msg} at line {e.lineno} column {e.colno}", source) from None


def json_line(line: str, where: str) -> Any:
    """One line of a JSON-lines file, parsed; InvalidScene naming `where` when it is not JSON."""
    from . import deep

    try:
        return deep.retrying(json.loads, line)
    except deep.TooDeep as e:
        raise e.in_file(where) from None
    except ValueError as e:
        raise InvalidScene("", f"not JSON ({e})", where) from None
