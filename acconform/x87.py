"""Mono's ``Math.Sin`` and ``Math.Cos``: the x87 FSIN and FCOS instructions, run on this CPU.

Mono's amd64 JIT compiles ``Math.Sin(double)`` and ``Math.Cos(double)`` to an intrinsic
(mini-amd64.c's EMIT_SSE2_FPFUNC): the SSE double is stored below the stack pointer, loaded onto
the x87 stack, FSIN or FCOS runs in extended precision, and FSTP rounds the result back to a double
(a second rounding). The x87 reduces its argument with a 66-bit pi, so near the zeros of sine and
cosine its answers are off from the correctly rounded cos() of libm -- which is what .NET 10
(CoreCLR's Math.Cos calls the C runtime) and mono's own reflection path return. Found by the
Trajectory differential: SolveCubic's ``-t * Math.Cos(phi + Math.PI / 3)`` near pi/2, three ulps
apart from libm's. FSIN/FCOS also return an argument of magnitude 2^63 or more unchanged.

No Python library computes FSIN/FCOS, so this module runs those exact instructions: a 25-byte
x86-64 function (the same store, load, op, store, load sequence mono emits) in an executable page,
called through ctypes. The answers are this CPU's x87 answers, as mono's on this machine are (x87
implementations of different vendors may differ in the last extended-precision bit; after the
rounding to double that almost never shows).
"""

from __future__ import annotations

import ctypes
import mmap
import platform

from .errors import AcconformError

# movsd [rsp-8], xmm0 ; fld qword [rsp-8] ; <op> ; fstp qword [rsp-8] ; movsd xmm0, [rsp-8] ; ret
_PROLOGUE = bytes.fromhex("f20f114424f8" "dd4424f8")
_EPILOGUE = bytes.fromhex("dd5c24f8" "f20f104424f8" "c3")
_FSIN = bytes.fromhex("d9fe")
_FCOS = bytes.fromhex("d9ff")

_page = None
_functions: dict = {}


def _load():
    global _page
    if platform.machine().lower() not in ("x86_64", "amd64"):
        raise AcconformError(
            f"mono's Math.Sin/Math.Cos are x87 FSIN/FCOS, which this {platform.machine()} machine lacks: "
            "run mono-runtime comparisons on x86-64")
    page = mmap.mmap(-1, mmap.PAGESIZE, prot=mmap.PROT_READ | mmap.PROT_WRITE | mmap.PROT_EXEC)
    proto = ctypes.CFUNCTYPE(ctypes.c_double, ctypes.c_double)
    base = ctypes.addressof(ctypes.c_char.from_buffer(page))
    offset = 0
    for name, op in (("sin", _FSIN), ("cos", _FCOS)):
        code = _PROLOGUE + op + _EPILOGUE
        page[offset:offset + len(code)] = code
        _functions[name] = proto(base + offset)
        offset += 32
    _page = page  # kept alive: the functions point into it


def fsin(x: float) -> float:
    """Mono's ``Math.Sin(x)``: x87 FSIN, rounded to double."""
    if not _functions:
        _load()
    return _functions["sin"](float(x))


def fcos(x: float) -> float:
    """Mono's ``Math.Cos(x)``: x87 FCOS, rounded to double."""
    if not _functions:
        _load()
    return _functions["cos"](float(x))


__all__ = ["fcos", "fsin"]
