"""Compile oracle/facade/*.cs against the user's ACE assemblies, cached by their hash.

The facade is acconform's own C# (MIT), never ACE's. It is compiled on the user's machine when
the oracle loads and cached under the user cache directory (``$XDG_CACHE_HOME/acconform/facade``,
never in the repository), keyed by a hash of the ACE assemblies, the facade source and the
runtime. mono: ``mcs`` (Debian: mono-mcs). CoreCLR: the C# compiler of the SDK of the .NET
installation that runs ACE, run directly with the targeting pack's reference assemblies (about
1 s); where the installation's layout does not give them, the SDK builds a throw-away class library
referencing the ACE assemblies (6-15 s), for the target framework of their runtimeconfig, offline
(its project names no package source).
When no compiler is present, or compiling fails, `build` returns None and the reason, and the
live oracle refuses to start with that reason (the facade is the one scene builder). A build is a
step of the oracle's `Loading` (oracle/loading.py): said when it starts and every 2 s while the
compiler runs.
"""

from __future__ import annotations

import contextlib
import hashlib
import os
import shutil
import signal
import subprocess
import threading
from pathlib import Path

from . import dotnet_host
from .config import cache_dir
from .loading import Loading
from .runtime import ACE_ASSEMBLIES, LoadedAce, dotnet_root

SOURCE_DIR = Path(__file__).with_name("facade")
DLL_NAME = "Acconform.Oracle.Facade.dll"


def sources(extra=()) -> list[Path]:
    """The facade's C# files, and `extra` ones compiled into it (an instrumented ACE's recorder, oracle/instrumented.py)."""
    return sorted(SOURCE_DIR.glob("*.cs")) + [Path(p) for p in extra]


def cache_key(ace: LoadedAce, extra=()) -> str:
    h = hashlib.sha256(ace.assembly_hash.encode())
    h.update(ace.location.runtime.encode())
    for s in sources(extra):
        h.update(s.name.encode())
        h.update(s.read_bytes())
    return h.hexdigest()[:20]


def build(ace: LoadedAce, loading: Loading | None = None, extra=()) -> tuple[Path | None, str]:
    """(path of the compiled facade or None, how it was obtained or why not); compiling is the
    step "facade build" of `loading`. `extra`: more C# files compiled into it."""
    loading = loading or Loading(None)
    out_dir = cache_dir() / "facade" / cache_key(ace, extra)
    dll = out_dir / DLL_NAME
    if dll.is_file():
        return dll, f"cached {dll}"
    out_dir.mkdir(parents=True, exist_ok=True)
    compiler = "mcs" if ace.location.runtime == "mono" else "the .NET SDK"
    with loading.step("facade build", f"compiling the C# facade against this ACE build with {compiler}, once per "
                                      f"build (cached in {out_dir.parent})"):
        # the workers of a campaign load ACE at once: one compiles, the others wait for its facade
        # (two SDK builds at once on two cores take twice as long, for the same file)
        with open(out_dir.with_name(out_dir.name + ".lock"), "w") as lock, _terminated_as_an_exit():
            _wait_for(lock)
            if dll.is_file():
                return dll, f"compiled by another process into {dll}"
            return _build_mcs(ace, dll, extra) if ace.location.runtime == "mono" else _build_dotnet(ace, dll, extra)


@contextlib.contextmanager
def _terminated_as_an_exit():
    """SIGTERM raises SystemExit while the compiler runs, so the compiler is killed and its folder
    removed on the way out. A campaign ends a worker still loading ACE a second after Ctrl-C
    (runner.STOP_GRACE) with SIGTERM; by default the worker would die at once and leave the
    compiler running for its 10-30 s, deaf to Ctrl-C (a worker ignores SIGINT, and so do its
    children)."""
    if threading.current_thread() is not threading.main_thread():  # signal handlers are the main thread's
        yield
        return

    def exit_(signum, frame):
        raise SystemExit(128 + signum)

    previous = signal.signal(signal.SIGTERM, exit_)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, previous)


def _wait_for(lock) -> None:
    """Hold `lock` (an open file) exclusively, waiting for whoever holds it. Windows has no flock:
    there each process compiles its own, as before the lock."""
    try:
        import fcntl
    except ImportError:
        return
    fcntl.flock(lock, fcntl.LOCK_EX)


def _build_mcs(ace: LoadedAce, dll: Path, extra=()) -> tuple[Path | None, str]:
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
    cmd += [f"-r:{r}" for r in refs] + [str(s) for s in sources(extra)]
    try:  # the temporary directory goes however the build ends
        try:
            p = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
        except (OSError, subprocess.TimeoutExpired) as e:
            return None, f"mcs failed to run: {e}"
        if p.returncode != 0 or not tmp.is_file():
            return None, "mcs could not compile the facade: " + (p.stdout + p.stderr).strip()[:600]
        tmp.replace(dll)
        return dll, f"compiled with mcs into {dll}"
    finally:
        shutil.rmtree(tmp_dir, ignore_errors=True)


_CSPROJ = """<Project Sdk="Microsoft.NET.Sdk">
  <PropertyGroup>
    <TargetFramework>{tfm}</TargetFramework>
    <AssemblyName>Acconform.Oracle.Facade</AssemblyName>
    <OutputType>Library</OutputType>
    <Optimize>true</Optimize>
    <DebugType>none</DebugType>
    <Nullable>disable</Nullable>
    <ImplicitUsings>disable</ImplicitUsings>
    <EnableDefaultCompileItems>false</EnableDefaultCompileItems>
    <GenerateDependencyFile>false</GenerateDependencyFile>
    <NoWarn>$(NoWarn);CS0618;SYSLIB0050</NoWarn>
  </PropertyGroup>
  <ItemGroup>
{compile}
  </ItemGroup>
  <ItemGroup>
{refs}
  </ItemGroup>
</Project>
"""

# No package source: a class library needs no package, and the facade is built offline.
_NUGET_CONFIG = """<?xml version="1.0" encoding="utf-8"?>
<configuration>
  <packageSources>
    <clear />
  </packageSources>
</configuration>
"""


def _build_dotnet(ace: LoadedAce, dll: Path, extra=()) -> tuple[Path | None, str]:
    """The SDK's C# compiler run directly on the facade (`_build_csc`, about 1 s), or, where the
    installation's layout does not give it, a throw-away class library referencing the user's ACE
    assemblies, built with the SDK of the .NET installation that runs them (`dotnet build`, 6-15 s,
    most of it MSBuild starting and restoring), for the target framework their runtimeconfig names."""
    root = dotnet_root()
    sdks = dotnet_host.sdk_versions(root.path)
    if not sdks:
        return None, (f"no .NET SDK in {root.path} (found by {root.found_by}; it has the runtime only): install the "
                      "SDK there to compile the facade")
    tfm = dotnet_host.framework_tfm(ace.location.runtime_config)
    direct = _direct_compiler(root.path, tfm)
    if direct is not None:
        built, why = _build_csc(ace, dll, root.path, *direct, extra)
        if built is not None:
            return built, why
    proj_dir = dll.parent / f"project-{os.getpid()}"
    shutil.rmtree(proj_dir, ignore_errors=True)
    proj_dir.mkdir(parents=True)
    compile_items = "\n".join(f'    <Compile Include="{s}" />' for s in sources(extra))
    refs = "\n".join(f'    <Reference Include="{a}"><HintPath>{ace.location.directory / (a + ".dll")}</HintPath>'
                     f"<Private>false</Private></Reference>" for a in ACE_ASSEMBLIES)
    (proj_dir / "Acconform.Oracle.Facade.csproj").write_text(_CSPROJ.format(tfm=tfm, compile=compile_items, refs=refs))
    (proj_dir / "NuGet.Config").write_text(_NUGET_CONFIG)
    env = dict(os.environ, DOTNET_ROOT=str(root.path), DOTNET_CLI_TELEMETRY_OPTOUT="1", DOTNET_NOLOGO="1",
               DOTNET_SKIP_FIRST_TIME_EXPERIENCE="1", MSBUILDDISABLENODEREUSE="1", DOTNET_CLI_UI_LANGUAGE="en")
    # no build servers left running in the user's session: no node reuse, no shared compiler
    cmd = [str(dotnet_host.dotnet_cli(root.path)), "build", str(proj_dir), "-c", "Release", "-o", str(proj_dir / "out"),
           "-nologo", "-nodeReuse:false", "-p:UseSharedCompilation=false", "-v:q"]
    try:  # the project folder goes however the build ends (a Ctrl-C stops `dotnet build` with it)
        try:
            p = subprocess.run(cmd, capture_output=True, text=True, timeout=600, env=env, cwd=proj_dir)
        except (OSError, subprocess.TimeoutExpired) as e:
            return None, f"dotnet build failed to run: {e}"
        built = proj_dir / "out" / DLL_NAME
        if p.returncode != 0 or not built.is_file():
            errors = [ln.strip() for ln in (p.stdout + p.stderr).splitlines() if "error" in ln]
            return None, (f"dotnet build ({tfm}, SDK {', '.join(sdks)}) could not compile the facade: "
                          + ("; ".join(dict.fromkeys(errors)) or (p.stdout + p.stderr).strip())[:600])
        built.replace(dll)
        return dll, f"compiled with the .NET SDK ({tfm}) into {dll}"
    finally:
        shutil.rmtree(proj_dir, ignore_errors=True)


def _version_key(name: str) -> tuple:
    """"10.0.401" -> (10, 0, 401): SDK and pack folders compared as versions, not as text ("9.0" < "10.0")."""
    parts = []
    for p in name.split("-")[0].split("."):
        parts.append(int(p) if p.isdigit() else -1)
    return tuple(parts)


def _direct_compiler(root: Path, tfm: str) -> tuple[Path, list[Path]] | None:
    """The newest SDK's C# compiler (``sdk/<v>/Roslyn/bincore/csc.dll``) and the reference assemblies
    of `tfm` from the newest targeting pack that has them (``packs/Microsoft.NETCore.App.Ref/<v>/ref/<tfm>``):
    what `dotnet build` itself compiles with. None when the installation lacks either."""
    sdks = sorted(dotnet_host.sdk_versions(root), key=_version_key, reverse=True)
    csc = next((c for v in sdks if (c := root / "sdk" / v / "Roslyn" / "bincore" / "csc.dll").is_file()), None)
    packs = root / "packs" / "Microsoft.NETCore.App.Ref"
    if csc is None or not packs.is_dir():
        return None
    for v in sorted((p.name for p in packs.iterdir()), key=_version_key, reverse=True):
        refs = sorted((packs / v / "ref" / tfm).glob("*.dll"))
        if refs:
            return csc, refs
    return None


def _build_csc(ace: LoadedAce, dll: Path, root: Path, csc: Path, refs: list[Path], extra=()) -> tuple[Path | None, str]:
    """The facade compiled by `csc` against `refs` and the ACE assemblies, as `dotnet build` of the
    class library compiles it (optimized, no debug information, the same warnings off), in a private
    temporary folder; (None, why) when it fails, and the caller builds the project instead."""
    tmp_dir = dll.parent / f"csc-{os.getpid()}"
    tmp_dir.mkdir(exist_ok=True)
    tmp = tmp_dir / DLL_NAME
    args = ["-noconfig", "-nologo", "-target:library", "-optimize+", "-debug-", "-deterministic",
            "-nowarn:CS0618,SYSLIB0050", f"-out:{tmp}"]
    args += [f"-r:{r}" for r in refs]
    args += [f"-r:{ace.location.directory / (a + '.dll')}" for a in ACE_ASSEMBLIES]
    args += [str(src) for src in sources(extra)]
    rsp = tmp_dir / "facade.rsp"  # one argument a line, quoted: paths may hold spaces
    rsp.write_text("\n".join('"' + a.replace('"', '\\"') + '"' for a in args) + "\n")
    env = dict(os.environ, DOTNET_ROOT=str(root), DOTNET_CLI_TELEMETRY_OPTOUT="1", DOTNET_NOLOGO="1")
    try:
        try:
            p = subprocess.run([str(dotnet_host.dotnet_cli(root)), "exec", str(csc), f"@{rsp}"], capture_output=True,
                               text=True, timeout=300, env=env)
        except (OSError, subprocess.TimeoutExpired) as e:
            return None, f"csc failed to run: {e}"
        if p.returncode != 0 or not tmp.is_file():
            return None, "csc could not compile the facade: " + (p.stdout + p.stderr).strip()[:600]
        tmp.replace(dll)
        return dll, (f"compiled with the .NET SDK ({refs[0].parent.name}) by its csc, reference pack "
                     f"{refs[0].parents[2].name}, into {dll}")
    finally:
        shutil.rmtree(tmp_dir, ignore_errors=True)
