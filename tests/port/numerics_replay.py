"""Checking port arithmetic against mono's System.Numerics: live through pythonnet, or replayed
from recorded answers (float32 bit patterns, 8 hex digits each) when mono is absent.

A test module describes its ops as ``OPS = {name: (number of float32 inputs, port function)}``
plus a ``mono_op(sn, name, inputs)`` that asks System.Numerics the same question; this module
does the rest: `mono` (the live runtime or a visible skip), `mismatches`, `replay` of a recorded
op, and `record` of a new data file (``python <test file> --record``).
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from acconform.numerics import f32_bits, f32_from_bits


def bits(vals) -> list[int]:
    return [f32_bits(x) for x in vals]


def mono():
    """mono's System.Numerics (pythonnet), or skip the test saying what is missing."""
    try:
        from pythonnet import load

        load("mono")
        import clr

        clr.AddReference("System.Numerics.Vectors")
        import System.Numerics as sn
    except Exception as e:  # pragma: no cover - depends on the machine
        pytest.skip(f"pythonnet with a mono runtime is needed for live System.Numerics checks ({e})")
    return sn


def mismatches(port, cases, expected) -> list[tuple]:
    """(inputs, mono's bits, port's bits) for every case where `port` disagrees with `expected`."""
    bad = []
    for a, want in zip(cases, expected):
        got = bits(port(a))
        if got != list(want):
            bad.append((a, [hex(b) for b in want], [hex(b) for b in got]))
    return bad


def assert_matches_live_mono(ops: dict, name: str, inputs, mono_op, n: int = 3000) -> None:
    """The port's op `name` equals mono's System.Numerics on `n` fresh inputs, bit for bit."""
    import zlib

    sn = mono()
    cases = inputs(name, n, seed=zlib.crc32(name.encode()))
    bad = mismatches(ops[name][1], cases, [bits(mono_op(sn, name, a)) for a in cases])
    assert not bad, f"{len(bad)}/{len(cases)} differ from mono, first: {bad[:3]}"


def assert_matches_recorded_mono(ops: dict, name: str, path: Path, script: str) -> None:
    """The port's op `name` equals mono's recorded answers, bit for bit."""
    cases, expected = replay(load_recorded(path, script), name, ops[name][0])
    bad = mismatches(ops[name][1], cases, expected)
    assert not bad, f"{len(bad)}/{len(cases)} differ from recorded mono answers, first: {bad[:3]}"


def load_recorded(path: Path, script: str) -> dict:
    """The recorded document; a missing file fails (a replay lane with no data must not pass)."""
    if not path.exists():
        pytest.fail(f"{path} is missing: record it with `python {script} --record` (needs mono)")
    return json.loads(path.read_text())


def unpack(hexstr: str, width: int) -> list[list[int]]:
    vals = [int(hexstr[i:i + 8], 16) for i in range(0, len(hexstr), 8)]
    return [vals[i:i + width] for i in range(0, len(vals), width)]


def replay(doc: dict, name: str, n_inputs: int) -> tuple[list[list[float]], list[list[int]]]:
    """One recorded op: (input floats per case, mono's output bits per case)."""
    rec = doc["ops"][name]
    cases = [[f32_from_bits(b) for b in row] for row in unpack(rec["inputs"], n_inputs)]
    expected = unpack(rec["outputs"], len(rec["outputs"]) // 8 // len(cases))
    assert len(cases) == rec["count"] and len(cases) >= 500
    return cases, expected


def record(path: Path, ops: dict, inputs, mono_op, about: str, n: int = 600) -> None:
    """Ask mono every op's question for `n` inputs (``inputs(name, n, seed)``) and write `path`."""
    import zlib

    sn = mono()
    doc = {"about": about, "runtime": "mono", "ops": {}}
    for name in sorted(ops):
        cases = inputs(name, n, seed=zlib.crc32(name.encode()) ^ 0x5EED)
        outs = [bits(mono_op(sn, name, a)) for a in cases]
        doc["ops"][name] = {
            "count": n,
            "inputs": "".join(f"{b:08x}" for a in cases for b in bits(a)),
            "outputs": "".join(f"{b:08x}" for o in outs for b in o),
        }
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(doc, indent=1) + "\n")
    print(f"wrote {path}")
