"""Checking port arithmetic against System.Numerics on both runtimes ACE runs on -- mono 6.8 and
.NET 10 (CoreCLR) -- live through pythonnet, or replayed from recorded answers (float32 bit
patterns, 8 hex digits each; an int answer is its 32-bit two's complement) when the runtime is absent.

A test module describes its ops as ``OPS = {name: (number of float32 inputs, port function)}``,
where the port function takes the numerics `Mode` (which carries the runtime) and the inputs,
plus a ``net_op(sn, name, inputs)`` that asks System.Numerics the same question; this module does
the rest: `system_numerics` (a live runtime or a visible skip), `mismatches`, `replay` of a
recorded op, `record` of a new data file (``python <test file> --record [--runtime coreclr]``),
and the live CoreCLR lane, which records fresh answers in a child process (pythonnet starts one
runtime per process, and the test process may already run mono).
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import tempfile
import zlib
from pathlib import Path

import pytest

from acconform.numerics import f32_bits, f32_from_bits, get_mode

DATA_DIR = Path(__file__).resolve().parents[1] / "data"
# the runtime's name in data file names: numerics_mono*.json, numerics_net10*.json
DATA_NAMES = {"mono": "mono", "coreclr": "net10"}
RECORD_SALT = 0x5EED  # recorded inputs use seed crc32(name) ^ RECORD_SALT; live lanes use crc32(name)


def data_path(runtime: str, suffix: str = "") -> Path:
    return DATA_DIR / f"numerics_{DATA_NAMES[runtime]}{suffix}.json"


def bits(vals) -> list[int]:
    return [v & 0xFFFFFFFF if isinstance(v, int) else f32_bits(v) for v in vals]


def _dotnet_root() -> str | None:
    """Where the dotnet host lives ($DOTNET_ROOT, else the `dotnet` on PATH, else the usual place)."""
    if os.environ.get("DOTNET_ROOT"):
        return os.environ["DOTNET_ROOT"]
    exe = shutil.which("dotnet")
    if exe:
        return str(Path(os.path.realpath(exe)).parent)
    return "/usr/share/dotnet" if Path("/usr/share/dotnet").is_dir() else None


def _load(runtime: str) -> None:
    from pythonnet import load

    if runtime == "mono":
        import warnings

        with warnings.catch_warnings():  # clr_loader warns on every mono before 6.12; 6.8 runs these fine
            warnings.filterwarnings("ignore", message="Hosting Mono versions before", category=UserWarning)
            load("mono")
        return
    cfg = Path(tempfile.mkdtemp(prefix="acconform-numerics-")) / "numerics.runtimeconfig.json"
    cfg.write_text(json.dumps({"runtimeOptions": {"tfm": "net10.0", "framework": {
        "name": "Microsoft.NETCore.App", "version": "10.0.0"}}}))
    load("coreclr", runtime_config=str(cfg), dotnet_root=_dotnet_root())


def system_numerics(runtime: str = "mono"):
    """System.Numerics of `runtime` started in this process (pythonnet), or skip saying what is missing."""
    try:
        _load(runtime)
        import clr

        if runtime == "mono":
            clr.AddReference("System.Numerics.Vectors")
            clr.AddReference("System.Core")
        import System
        import System.Numerics as sn
    except Exception as e:  # pragma: no cover - depends on the machine
        pytest.skip(f"pythonnet with a {runtime} runtime is needed for live System.Numerics checks ({e})")
    loaded = "mono" if System.Type.GetType("Mono.Runtime") is not None else "coreclr"
    if loaded != runtime:
        pytest.skip(f"this process already runs {loaded}; {runtime} is checked in its own process")
    return sn


def mismatches(port, mode, cases, expected) -> list[tuple]:
    """(inputs, the runtime's bits, port's bits) for every case where `port` disagrees with `expected`."""
    import numpy as np

    bad = []
    with np.errstate(all="ignore"):
        for a, want in zip(cases, expected):
            got = bits(port(mode, a))
            if got != list(want):
                bad.append((a, [hex(b) for b in want], [hex(b) for b in got]))
    return bad


def assert_matches_live_mono(ops: dict, name: str, inputs, net_op, n: int = 3000) -> None:
    """The port's op `name` under mono's arithmetic equals mono's System.Numerics on `n` fresh inputs."""
    sn = system_numerics("mono")
    cases = inputs(name, n, seed=zlib.crc32(name.encode()))
    bad = mismatches(ops[name][1], get_mode("exact", "mono"), cases, [bits(net_op(sn, name, a)) for a in cases])
    assert not bad, f"{len(bad)}/{len(cases)} differ from mono, first: {bad[:3]}"


def live_coreclr_answers(script: Path, n: int = 3000) -> dict:
    """Fresh .NET 10 answers for every op of `script` (a test module), recorded in a child process
    on the live-lane seeds; skips (with the child's reason) when CoreCLR cannot start."""
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "live.json"
        env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(Path(__file__).resolve().parent),
                                                          os.environ.get("PYTHONPATH", "")]))
        proc = subprocess.run([sys.executable, str(script), "--record", "--runtime", "coreclr", "--live",
                               "--out", str(out), "-n", str(n)], capture_output=True, text=True, timeout=900, env=env)
        if proc.returncode != 0 or not out.exists():
            reason = (proc.stdout + proc.stderr).strip().splitlines()
            pytest.skip(f"CoreCLR (.NET 10) could not answer live: {reason[-1] if reason else proc.returncode}")
        return json.loads(out.read_text())


def assert_matches_answers(ops: dict, name: str, doc: dict, runtime: str, what: str) -> None:
    """The port's op `name`, computing as `runtime` does, equals the answers in `doc`, bit for bit."""
    cases, expected = replay(doc, name, ops[name][0])
    bad = mismatches(ops[name][1], get_mode("exact", runtime), cases, expected)
    assert not bad, f"{len(bad)}/{len(cases)} differ from {what}, first: {bad[:3]}"


def assert_matches_recorded(ops: dict, name: str, path: Path, script: str, runtime: str) -> None:
    """The port's op `name` under `runtime`'s arithmetic equals that runtime's recorded answers."""
    assert_matches_answers(ops, name, load_recorded(path, script, runtime), runtime, f"recorded {runtime} answers")


def load_recorded(path: Path, script: str, runtime: str = "mono") -> dict:
    """The recorded document; a missing file fails (a replay lane with no data must not pass)."""
    if not path.exists():
        flag = "" if runtime == "mono" else f" --runtime {runtime}"
        pytest.fail(f"{path} is missing: record it with `python {script} --record{flag}` (needs {runtime})")
    return json.loads(path.read_text())


def unpack(hexstr: str, width: int) -> list[list[int]]:
    vals = [int(hexstr[i:i + 8], 16) for i in range(0, len(hexstr), 8)]
    return [vals[i:i + width] for i in range(0, len(vals), width)]


def replay(doc: dict, name: str, n_inputs: int) -> tuple[list[list[float]], list[list[int]]]:
    """One recorded op: (input floats per case, the runtime's output bits per case)."""
    rec = doc["ops"][name]
    cases = [[f32_from_bits(b) for b in row] for row in unpack(rec["inputs"], n_inputs)]
    expected = unpack(rec["outputs"], len(rec["outputs"]) // 8 // len(cases))
    assert len(cases) == rec["count"] and len(cases) >= 500
    return cases, expected


def record(path: Path, ops: dict, inputs, net_op, about: str, runtime: str = "mono", n: int = 600,
           live: bool = False) -> None:
    """Ask `runtime`'s System.Numerics every op's question for `n` inputs (``inputs(name, n, seed)``)
    and write `path`; `live` uses the live lanes' seeds instead of the recorded ones."""
    sn = system_numerics(runtime)
    import System

    doc = {"about": about, "runtime": _runtime_version(System, runtime), "ops": {}}
    for name in sorted(ops):
        seed = zlib.crc32(name.encode()) ^ (0 if live else RECORD_SALT)
        cases = inputs(name, n, seed=seed)
        outs = [bits(net_op(sn, name, a)) for a in cases]
        doc["ops"][name] = {
            "count": n,
            "inputs": "".join(f"{b:08x}" for a in cases for b in bits(a)),
            "outputs": "".join(f"{b:08x}" for o in outs for b in o),
        }
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(doc, indent=1) + "\n")
    print(f"wrote {path}")


def _runtime_version(System, runtime: str) -> str:
    if runtime == "mono":
        from System.Reflection import BindingFlags

        m = System.Type.GetType("Mono.Runtime").GetMethod("GetDisplayName", BindingFlags.NonPublic | BindingFlags.Static)
        return f"mono {str(m.Invoke(None, None)).split(' ')[0]}"
    from System.Runtime.InteropServices import RuntimeInformation

    return f"coreclr {RuntimeInformation.FrameworkDescription}"


def main(argv, default_path, ops, inputs, net_op, about: str) -> None:
    """A test module's command line: ``--record [--runtime mono|coreclr] [--out PATH] [-n N] [--live]``."""
    import argparse

    ap = argparse.ArgumentParser()
    ap.add_argument("--record", action="store_true", required=True)
    ap.add_argument("--runtime", choices=sorted(DATA_NAMES), default="mono")
    ap.add_argument("--out", default=None)
    ap.add_argument("-n", type=int, default=600)
    ap.add_argument("--live", action="store_true", help="the live lanes' seeds (fresh inputs), for the live CoreCLR lane")
    args = ap.parse_args(argv)
    try:
        record(Path(args.out) if args.out else default_path(args.runtime), ops, inputs, net_op,
               about.format(runtime=args.runtime), args.runtime, args.n, args.live)
    except pytest.skip.Exception as e:
        print(f"cannot record: {e.msg}", file=sys.stderr)
        sys.exit(3)
