"""Loading a .NET runtime and ACE's assemblies through pythonnet, once per process.

This module, oracle/live.py and oracle/functions.py are the places that import pythonnet (`clr`). Every
failure here becomes one OracleUnavailable naming what was looked for, where, and what to set.
"""

from __future__ import annotations

import contextlib
import hashlib
import signal
import sys
import threading
from dataclasses import dataclass

from ..errors import OracleUnavailable
from . import dotnet_host
from .config import HOW_TO_SET, AceLocation
from .identity import ABSENT, SHAPES, AceIdentity, identify
from .loading import Loading
from .members import REQUIRED, check_members

ACE_ASSEMBLIES = ("ACE.Common", "ACE.Entity", "ACE.DatLoader", "ACE.Server")
PIP_HINT = "install the optional extra: pip install 'acconform[oracle]' (pythonnet >= 3.0.3)"

_state: dict = {}  # "runtime" -> name, "dir" -> Path once loaded


@dataclass(frozen=True, slots=True)
class LoadedAce:
    location: AceLocation
    ace_version: str  # "ACE.Server <assembly version> sha256:<12 hex>"
    runtime_version: str  # "mono 6.8.0.105" / "coreclr .NET 10.0.0"
    assembly_hash: str  # sha256 over the ACE assemblies (the facade cache key)
    identity: AceIdentity | None = None  # which ACE this is, and whether it is the one the port follows


def _sha256(paths) -> str:
    h = hashlib.sha256()
    for p in paths:
        h.update(p.name.encode())
        h.update(p.read_bytes())
    return h.hexdigest()


def load(location: AceLocation, loading: Loading | None = None) -> LoadedAce:
    """Start the runtime (once), reference ACE's assemblies, check every member the oracle uses and
    tell which ACE it is (oracle/identity.py: any ACE with the members loads), each a step of
    `loading` (said and timed)."""
    loading = loading or Loading(None)
    prev = _state.get("runtime")
    if prev is not None:
        if prev != location.runtime:
            raise OracleUnavailable(f"this process already runs .NET on {prev}; it cannot also load {location.runtime} "
                                    f"for {location.assembly} (pythonnet loads one runtime per process)")
        if _state["dir"] != location.directory:
            raise OracleUnavailable(f"this process already loaded ACE from {_state['dir']}; it cannot also load "
                                    f"{location.directory} (one ACE build per process)")
    else:
        where = f" from {location.dotnet_root.path}" if location.dotnet_root is not None else ""
        with loading.step("runtime", f"starting the {location.runtime} runtime{where}"):
            _start_runtime(location)
        with loading.step("assemblies", f"loading ACE's assemblies from {location.directory}"):
            _reference_assemblies(location)
        _state["runtime"] = location.runtime
        _state["dir"] = location.directory
        _state["dotnet_root"] = location.dotnet_root
    with loading.step("members", "checking that the ACE build has every member the oracle uses"):
        check_members(find_type, has_member, str(location.directory))
        files = [location.directory / f"{a}.dll" for a in ACE_ASSEMBLIES]
        version = _ace_version(location)
        shapes = {sh.change: shape_of(sh.type_name, sh.member) for sh in SHAPES}
        who = identify(location.runtime, version, _build_commit(), _build_date(), shapes)
        return LoadedAce(location, version, _runtime_version(location.runtime), _sha256(files), who)


def dotnet_root() -> dotnet_host.DotnetRoot | None:
    """The .NET installation this process runs ACE on (CoreCLR), or None."""
    return _state.get("dotnet_root")


# ACE's build asks for the server GC (a heap and a GC thread per core, concurrent background GC):
# right for a game server owning the machine, wrong for a guest in a campaign worker, where every
# worker (one per core) would own per-core heaps and threads that compete with the other workers'
# Python. The GC decides when memory is reclaimed, never what ACE computes. These runtime
# properties override the runtimeconfig's; DOTNET_gcServer / DOTNET_gcConcurrent in the
# environment still win over both (the GC reads them first).
GUEST_GC = (("System.GC.Server", "false"), ("System.GC.Concurrent", "false"))
# Tiered PGO adds an instrumented tier between tier 0 and tier 1 and re-JITs every hot method once
# more, on a background thread that competes with the campaign's other worker for the two cores
# (with it, the port's time per case rose 10-25% in CoreCLR workers and CoreCLR campaigns ran 0.79-1.23x
# mono's; without it, 0.97-1.12x, 2026-12-02, docs/oracle.md). PGO steers inlining, devirtualisation
# and block layout, never what a float operation computes: ACE's answers stay bit for bit the same
# (the whole corpus re-recorded without it gave every answer again). DOTNET_TieredPGO still wins.
GUEST_JIT = (("System.Runtime.TieredPGO", "false"),)


def _start_runtime(location: AceLocation) -> None:
    try:
        import pythonnet
    except ImportError:
        raise OracleUnavailable(f"the live oracle needs pythonnet: {PIP_HINT}") from None
    with _signals_kept():
        _load_pythonnet(pythonnet, location)
    _no_shutdown_at_exit(location.runtime)


@contextlib.contextmanager
def _signals_kept():
    """Ctrl-C and SIGTERM stay Python's after the runtime starts. CoreCLR installs handlers for both
    that notify its shutdown and send the signal again later, from another thread: a Ctrl-C became
    two KeyboardInterrupts, the second one at any point after the first was handled (in the summary,
    or after `check` returned 130, killing it with SIGINT), and a SIGTERM that ends a campaign's
    worker went through .NET's shutdown first. The runtime needs neither (its other handlers, such
    as SIGSEGV's for NullReferenceException, stay); mono installs none."""
    if threading.current_thread() is not threading.main_thread():  # only the main thread sets handlers
        yield
        return
    kept = {sig: signal.getsignal(sig) for sig in (signal.SIGINT, signal.SIGTERM)}
    try:
        yield
    finally:
        for sig, handler in kept.items():
            if handler is not None:  # None: set outside Python, which cannot restore it
                signal.signal(sig, handler)


def _load_pythonnet(pythonnet, location: AceLocation) -> None:
    try:
        if location.runtime == "coreclr":
            pythonnet.load("coreclr", runtime_config=str(location.runtime_config), dotnet_root=str(location.dotnet_root.path),
                           properties=dict(GUEST_GC + GUEST_JIT))
        else:
            import warnings

            with warnings.catch_warnings():
                # clr_loader warns on every mono older than 6.12; Debian's 6.8 runs ACE fine
                # (the whole live lane and the corpus were produced on it).
                warnings.filterwarnings("ignore", message="Hosting Mono versions before", category=UserWarning)
                pythonnet.load("mono")
    except Exception as e:  # pythonnet raises RuntimeError / clr_loader errors of several kinds
        hint = ("install mono (e.g. apt-get install mono-runtime) or use --runtime coreclr with a .NET build"
                if location.runtime == "mono" else
                f"install the .NET runtime named in {location.runtime_config} or use --runtime mono with a mono build")
        raise OracleUnavailable(f"cannot start the {location.runtime} runtime for {location.assembly} "
                                f"({location.runtime_source}): {type(e).__name__}: {e}; {hint}") from None


def _no_shutdown_at_exit(runtime: str) -> None:
    """Drop the exit hooks that shut the runtime down. pythonnet's shuts Python.NET down in full,
    collecting Python's and .NET's garbage in rounds until nothing more goes; clr_loader's for mono
    then runs `mono_jit_cleanup`, which finalizes every object left. Measured on mono after a
    20-case campaign: 11 s in the first or, without it, 10 s in the second, after the summary and
    before the exit (Ctrl-C's exit too, 42 s after a long run). The process is ending, and its
    memory and threads go with it; nothing either hook does is ever seen."""
    import atexit

    import pythonnet

    atexit.unregister(pythonnet.unload)
    if runtime == "mono":
        from clr_loader import mono

        release = getattr(mono, "_release", None)  # clr_loader's private hook (0.2, 0.3): another version may lack it
        if release is not None:
            atexit.unregister(release)


def _reference_assemblies(location: AceLocation) -> None:
    import clr  # noqa: F401  (pythonnet, after load)

    d = str(location.directory)
    if d not in sys.path:
        sys.path.append(d)
    for name in ACE_ASSEMBLIES:
        f = location.directory / f"{name}.dll"
        if not f.is_file():
            raise OracleUnavailable(f"{name}.dll is missing beside {location.assembly}; the oracle needs "
                                    f"{', '.join(a + '.dll' for a in ACE_ASSEMBLIES)} from one ACE build output; {HOW_TO_SET}")
        try:
            clr.AddReference(str(f))
        except Exception as e:
            raise OracleUnavailable(f"cannot load {f} on {location.runtime}: {_net_message(e)}; is it built for "
                                    f"{location.runtime}? ({HOW_TO_SET}, or force --runtime)") from None


def _net_message(e: BaseException) -> str:
    msg = str(e).strip().splitlines()
    return f"{type(e).__name__}: {msg[0] if msg else ''}"


def _build_commit() -> str | None:
    """ACE's ``ServerBuildInfo.Commit`` (the git commit its build stamps), or None when the build lacks it."""
    from System.Reflection import BindingFlags

    t = find_type("ACE.Server.ServerBuildInfo")
    f = t.GetField("Commit", BindingFlags.Public | BindingFlags.Static) if t is not None else None
    return str(f.GetValue(None)) if f is not None else None


def _build_date() -> str | None:
    """The date of ACE's build stamp (ServerBuildInfo.BuildYear/Month/Day), "2026-08-08", or None."""
    from System.Reflection import BindingFlags

    t = find_type("ACE.Server.ServerBuildInfo")
    if t is None:
        return None
    parts = [t.GetField(f, BindingFlags.Public | BindingFlags.Static) for f in ("BuildYear", "BuildMonth", "BuildDay")]
    if any(p is None for p in parts):
        return None
    y, m, d = (int(p.GetValue(None)) for p in parts)
    return f"{y:04d}-{m:02d}-{d:02d}"


def shape_of(type_name: str, member: str) -> str | None:
    """The type name of a field or property (e.g. "ConcurrentDictionary`2"), ABSENT when the type
    lacks the member, None when the type is not there."""
    from System.Reflection import BindingFlags

    t = find_type(type_name)
    if t is None:
        return None
    flags = BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.Static | BindingFlags.Instance
    f = t.GetField(member, flags)
    if f is not None:
        return str(f.FieldType.Name)
    p = t.GetProperty(member, flags)
    return str(p.PropertyType.Name) if p is not None else ABSENT


def find_type(full_name: str):
    """A System.Type by full name across the loaded assemblies, or None."""
    from System import AppDomain

    for asm in AppDomain.CurrentDomain.GetAssemblies():
        try:
            t = asm.GetType(full_name, False)
        except Exception:
            t = None
        if t is not None:
            return t
    return None


def has_member(t, name: str) -> bool:
    from System.Reflection import BindingFlags

    flags = BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.Static | BindingFlags.Instance
    if name == ".ctor":
        return len(t.GetConstructors(flags)) > 0
    return len(t.GetMember(name, flags)) > 0


def _ace_version(location: AceLocation) -> str:
    from System.Reflection import AssemblyName

    try:
        v = str(AssemblyName.GetAssemblyName(str(location.assembly)).Version)
    except Exception:
        v = "?"
    digest = hashlib.sha256(location.assembly.read_bytes()).hexdigest()[:12]
    return f"ACE.Server {v} sha256:{digest}"


def _runtime_version(runtime: str) -> str:
    from System import Type
    from System.Reflection import BindingFlags

    if runtime == "mono":
        t = Type.GetType("Mono.Runtime")
        m = t.GetMethod("GetDisplayName", BindingFlags.NonPublic | BindingFlags.Static) if t is not None else None
        shown = str(m.Invoke(None, None)).split(" ")[0] if m is not None else "?"
        return f"mono {shown}"
    from System.Runtime.InteropServices import RuntimeInformation

    return f"coreclr {RuntimeInformation.FrameworkDescription}"


def loaded_runtime() -> str | None:
    return _state.get("runtime")


def check_required(required, where: str = "the loaded ACE build") -> None:
    """Run the member checker on another table (tests use it to prove a missing member fails clearly)."""
    check_members(find_type, has_member, where, required)


__all__ = ["LoadedAce", "load", "find_type", "has_member", "check_required", "REQUIRED", "loaded_runtime"]
