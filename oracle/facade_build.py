"""Compile oracle/facade/*.cs against the user's ACE assemblies, cached by their hash.

The facade is acconform's own C# (MIT), never ACE's. It is compiled on the user's machine when
the oracle loads and cached under the user cache directory (``$XDG_CACHE_HOME/acconform/facade``,
never in the repository), keyed by a hash of the ACE assemblies, the facade source and the
runtime. mono: ``mcs`` (Debian: mono-mcs). CoreCLR: the ``dotnet`` SDK builds a tiny class library
that references the ACE assemblies (written for users' .NET builds; not run on our machines).
When no compiler is present, or compiling fails, `build` returns None and the reason, and the
oracle falls back to the pure-pythonnet path (oracle/direct.py).
"""

from __future__ import annotations

import hashlib
import os
import shutil
import subprocess
from pathlib import Path

from .config import cache_dir
from .runtime import ACE_ASSEMBLIES, LoadedAce

SOURCE_DIR = Path(__file__).with_name("facade")
DLL_NAME = "Acconform.Oracle.Facade.dll"


def sources() -> list[Path]:
    return sorted(SOURCE_DIR.glob("*.cs"))


def cache_key(ace: LoadedAce) -> str:
    h = hashlib.sha256(ace.assembly_hash.encode())
    h.update(ace.location.runtime.encode())
    for s in sources():
        h.update(s.name.encode())
        h.update(s.read_bytes())
    return h.hexdigest()[:20]


def build(ace: LoadedAce) -> tuple[Path | None, str]:
    """(path of the compiled facade or None, how it was obtained or why not)."""
    out_dir = cache_dir() / "facade" / cache_key(ace)
    dll = out_dir / DLL_NAME
    if dll.is_file():
        return dll, f"cached {dll}"
    out_dir.mkdir(parents=True, exist_ok=True)
    if ace.location.runtime == "mono":
        return _build_mcs(ace, dll)
    return _build_dotnet(ace, dll)


def _build_mcs(ace: LoadedAce, dll: Path) -> tuple[Path | None, str]:
    mcs = shutil.which("mcs")
    if mcs is None:
        return None, "no mcs on PATH (Debian/Ubuntu: apt-get install mono-mcs)"
    d = ace.location.directory
    refs = ["System.Numerics.dll", "System.Numerics.Vectors.dll", "System.Runtime.Serialization.dll"]
    refs += [str(d / f"{a}.dll") for a in ACE_ASSEMBLIES]
    # compile under the final file name (it becomes the assembly name) in a private temp directory
    tmp_dir = dll.parent / f"tmp-{os.getpid()}"
    tmp_dir.mkdir(exist_ok=True)
    tmp = tmp_dir / DLL_NAME
    cmd = [mcs, "-target:library", "-optimize+", "-debug-", "-nowarn:0618", f"-out:{tmp}"]
    cmd += [f"-r:{r}" for r in refs] + [str(s) for s in sources()]
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
    except (OSError, subprocess.TimeoutExpired) as e:
        return None, f"mcs failed to run: {e}"
    if p.returncode != 0 or not tmp.is_file():
        shutil.rmtree(tmp_dir, ignore_errors=True)
        return None, "mcs could not compile the facade: " + (p.stdout + p.stderr).strip()[:600]
    tmp.replace(dll)
    shutil.rmtree(tmp_dir, ignore_errors=True)
    return dll, f"compiled with mcs into {dll}"


_CSPROJ = """<Project Sdk="Microsoft.NET.Sdk">
  <PropertyGroup>
    <TargetFramework>{tfm}</TargetFramework>
    <AssemblyName>Acconform.Oracle.Facade</AssemblyName>
    <Optimize>true</Optimize>
    <Nullable>disable</Nullable>
    <EnableDefaultCompileItems>false</EnableDefaultCompileItems>
  </PropertyGroup>
  <ItemGroup>
{compile}
  </ItemGroup>
  <ItemGroup>
{refs}
  </ItemGroup>
</Project>
"""


def _build_dotnet(ace: LoadedAce, dll: Path) -> tuple[Path | None, str]:
    """CoreCLR route (NOT exercised on our machines): a class library built with the dotnet SDK."""
    dotnet = shutil.which("dotnet")
    if dotnet is None:
        return None, "no dotnet SDK on PATH (install the .NET SDK matching the ACE build to get the fast facade)"
    import json

    try:
        rc = json.loads(ace.location.runtime_config.read_text())
        fw = rc["runtimeOptions"].get("framework") or rc["runtimeOptions"]["frameworks"][0]
        major_minor = ".".join(fw["version"].split(".")[:2])
        tfm = f"net{major_minor}"
    except (OSError, ValueError, KeyError, IndexError) as e:
        return None, f"cannot read the target framework from {ace.location.runtime_config}: {e}"
    proj_dir = dll.parent / "project"
    proj_dir.mkdir(parents=True, exist_ok=True)
    compile_items = "\n".join(f'    <Compile Include="{s}" />' for s in sources())
    refs = "\n".join(f'    <Reference Include="{a}"><HintPath>{ace.location.directory / (a + ".dll")}</HintPath>'
                     f"<Private>false</Private></Reference>" for a in ACE_ASSEMBLIES)
    (proj_dir / "Acconform.Oracle.Facade.csproj").write_text(_CSPROJ.format(tfm=tfm, compile=compile_items, refs=refs))
    try:
        p = subprocess.run([dotnet, "build", "-c", "Release", "-o", str(proj_dir / "out"), str(proj_dir)],
                           capture_output=True, text=True, timeout=600)
    except (OSError, subprocess.TimeoutExpired) as e:
        return None, f"dotnet build failed to run: {e}"
    built = proj_dir / "out" / DLL_NAME
    if p.returncode != 0 or not built.is_file():
        return None, "dotnet build could not compile the facade: " + (p.stdout + p.stderr).strip()[-600:]
    shutil.copyfile(built, dll)
    return dll, f"compiled with dotnet into {dll}"
