"""The porter's kit for C# (adapters/csharp/, docs/porting.md) speaks the protocol: its sample port,
built with `dotnet` outside the repository, gets a verdict from `acconform check --impl` -- a
difference naming fields, since it answers every scene wrongly on purpose, and never a protocol
error -- and the kit's own `dotnet test` passes (`slow`, and a step of .ci/run). Skipped with a
reason without dotnet. The sample port's handshake lists what acconform knows (read from its source, no dotnet)."""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ADAPTER = Path(__file__).resolve().parents[2] / "adapters" / "csharp"
DOTNET = shutil.which("dotnet")
needs_dotnet = pytest.mark.skipif(DOTNET is None, reason="dotnet is not installed: the C# kit (adapters/csharp) "
                                  "builds with the .NET 10 SDK")
# dotnet finds its NuGet cache under HOME, which `no_ace` moves: the builds keep the environment the tests started with
ENV = dict(os.environ)


def dotnet(*args, artifacts: Path) -> subprocess.CompletedProcess:
    """`dotnet ARGS` with every bin/ and obj/ under `artifacts`, none in the repository."""
    return subprocess.run([DOTNET, *args, "--artifacts-path", str(artifacts), "--nologo"], capture_output=True, text=True,
                          env=ENV, timeout=600)


@pytest.fixture(scope="module")
def sample_port(tmp_path_factory) -> Path:
    build = tmp_path_factory.mktemp("csharp")
    r = dotnet("build", str(ADAPTER / "SamplePort" / "SamplePort.csproj"), "-o", str(build / "out"),
               artifacts=build / "artifacts")
    assert r.returncode == 0, r.stdout + r.stderr
    return build / "out" / "SamplePort.dll"


@needs_dotnet
def test_the_sample_port_gets_a_verdict_naming_the_fields_it_answers_wrongly(sample_port, tmp_path, no_ace):
    r = subprocess.run([sys.executable, "-m", "acconform.cli", "check", "--impl", f"dotnet {sample_port}", "-n", "20",
                        "--no-progress", "--json", str(tmp_path / "s.json"), "--failures", str(tmp_path / "f")],
                       capture_output=True, text=True, cwd=tmp_path)
    assert r.returncode == 1, r.stdout + r.stderr
    s = json.loads((tmp_path / "s.json").read_text())
    assert s["implementation"]["name"] == "sample-port"
    assert s["differences"]["total"] >= 1
    assert {"ok", "origin"} <= set(s["differences"]["by_field"]), s["differences"]["by_field"]
    case = json.loads(Path(s["differences"]["cases"][0]["file"]).read_text())
    outcomes = [v for v in case.values() if isinstance(v, dict) and "ok" in v]  # the implementation's and ACE's
    assert len(outcomes) == 2 and all(o["error"] is None for o in outcomes), case  # an answer, not a protocol error


@needs_dotnet
@pytest.mark.slow  # building the test project and xunit's run: 100 s on a loaded machine (a step of .ci/run)
def test_the_kits_own_dotnet_tests_pass(tmp_path):
    r = dotnet("test", str(ADAPTER / "Acconform.Adapter.Tests"), artifacts=tmp_path / "artifacts")
    assert r.returncode == 0, r.stdout + r.stderr
    assert "Failed:     0" in r.stdout


@needs_dotnet
def test_building_leaves_no_bin_or_obj_in_the_repository(sample_port):
    assert not [p for p in ADAPTER.rglob("*") if p.name in ("bin", "obj")]


def test_the_sample_ports_handshake_lists_every_kind_and_only_features_acconform_knows():
    """Its comment says: every kind, and some of the features (a porter adds the rest from docs/protocol.md)."""
    from acconform.protocol import CAPABILITIES, FEATURES, KINDS

    source = (ADAPTER / "SamplePort" / "Program.cs").read_text()

    def listed(name):
        return re.findall(r'"([^"]+)"', re.search(name + r": \[(.*?)\]", source, re.S).group(1))
    assert listed("Kinds") == list(KINDS)
    features = listed("Features")
    assert features and set(features) <= set(FEATURES) | set(CAPABILITIES), set(features) - set(FEATURES) - set(CAPABILITIES)
    assert len(set(features)) == len(features)
