"""Where the ACE assembly is and which .NET runtime runs it.

Resolution order: the explicit argument (``--ace PATH``), then the ``ACE_ASSEMBLY`` environment
variable, then ``ace_assembly`` in the user config file (``$XDG_CONFIG_HOME/acconform/config.toml``,
default ``~/.config/acconform/config.toml``). PATH is ACE.Server.dll or the directory holding it.
The runtime is ``--runtime`` / ``ACE_RUNTIME`` / config ``runtime`` when given, else chosen from
the build: a .NET build output carries ``ACE.Server.runtimeconfig.json`` beside the assembly and
needs CoreCLR; anything else is run on mono. For CoreCLR the .NET installation is found as the
dotnet host finds it and checked to have the framework the runtimeconfig asks for
(oracle/dotnet_host.py).
"""

from __future__ import annotations

import os
import struct
import tomllib
from dataclasses import dataclass
from pathlib import Path

from ..errors import OracleUnavailable
from . import dotnet_host

ENV_VAR = "ACE_ASSEMBLY"
ENV_RUNTIME = "ACE_RUNTIME"
CONFIG_KEY = "ace_assembly"
RUNTIMES = ("mono", "coreclr")
ASSEMBLY_NAME = "ACE.Server.dll"
HOW_TO_SET = (f"set --ace PATH, the {ENV_VAR} environment variable, or {CONFIG_KEY} in "
              "~/.config/acconform/config.toml to ACE.Server.dll or the directory holding it")


def config_path() -> Path:
    base = os.environ.get("XDG_CONFIG_HOME") or os.path.join(os.path.expanduser("~"), ".config")
    return Path(base) / "acconform" / "config.toml"


def cache_dir() -> Path:
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "acconform"


@dataclass(frozen=True, slots=True)
class AceLocation:
    assembly: Path  # the ACE.Server.dll file
    source: str  # where the setting came from, e.g. "--ace", "ACE_ASSEMBLY", "/home/u/.config/acconform/config.toml"
    runtime: str  # "mono" or "coreclr"
    runtime_source: str  # "--runtime", "ACE_RUNTIME", the config file, or "detected"
    dotnet_root: dotnet_host.DotnetRoot | None = None  # CoreCLR: the installation that runs it


    @property
    def directory(self) -> Path:
        return self.assembly.parent

    @property
    def runtime_config(self) -> Path:
        return self.assembly.with_name("ACE.Server.runtimeconfig.json")


def _read_config(path: Path) -> dict:
    try:
        with open(path, "rb") as f:
            return tomllib.load(f)
    except FileNotFoundError:
        return {}
    except (OSError, tomllib.TOMLDecodeError) as e:
        raise OracleUnavailable(f"cannot read the acconform config file {path}: {e}") from None


def configured_setting(ace: str | os.PathLike | None = None) -> tuple[str, str] | None:
    """(value, source) of the first ACE setting in resolution order, or None when nothing is set."""
    if ace:
        return str(ace), "--ace"
    env = os.environ.get(ENV_VAR)
    if env:
        return env, ENV_VAR
    cfg_file = config_path()
    value = _read_config(cfg_file).get(CONFIG_KEY)
    if value:
        if not isinstance(value, str):
            raise OracleUnavailable(f"{cfg_file}: {CONFIG_KEY} must be a string path, got {value!r}")
        return value, str(cfg_file)
    return None


def resolve(ace: str | os.PathLike | None = None, runtime: str | None = None) -> AceLocation | None:
    """The configured ACE build, checked on disk (no runtime loaded); None when none is configured."""
    setting = configured_setting(ace)
    if setting is None:
        return None
    value, source = setting
    assembly = _assembly_file(Path(os.path.expanduser(value)), source)
    rt, rt_source = _choose_runtime(assembly, runtime)
    return AceLocation(assembly, source, rt, rt_source, _coreclr_root(assembly) if rt == "coreclr" else None)


def _coreclr_root(assembly: Path) -> dotnet_host.DotnetRoot:
    """The .NET installation that will run the build, checked to have the framework it asks for."""
    root = dotnet_host.find_root()
    problem = dotnet_host.framework_problem(assembly.with_name("ACE.Server.runtimeconfig.json"), root)
    if problem:
        raise OracleUnavailable(f"cannot run {assembly} on CoreCLR: {problem}")
    return root


def _assembly_file(path: Path, source: str) -> Path:
    if not path.exists():
        raise OracleUnavailable(f"ACE assembly not found: {path} (from {source}) does not exist; {HOW_TO_SET}")
    if path.is_dir():
        candidate = path / ASSEMBLY_NAME
        if not candidate.is_file():
            raise OracleUnavailable(f"no {ASSEMBLY_NAME} in the directory {path} (from {source}); point it at an "
                                    f"ACE build output holding {ASSEMBLY_NAME}; {HOW_TO_SET}")
        path = candidate
    elif path.name.lower() != ASSEMBLY_NAME.lower() and path.resolve().name.lower() != ASSEMBLY_NAME.lower():
        # another of the build's assemblies (ACE.Common.dll, ...): the oracle loads ACE.Server.dll
        # beside it, which may be a different build or none; say which file to give
        raise OracleUnavailable(f"{path} (from {source}) is not {ASSEMBLY_NAME}: give {ASSEMBLY_NAME} or the "
                                f"directory holding it (e.g. {path.absolute().parent / ASSEMBLY_NAME})")
    problem = dotnet_assembly_problem(path)
    if problem:
        raise OracleUnavailable(f"{path} (from {source}) is not a .NET assembly: {problem}; {HOW_TO_SET}")
    return path.resolve()


def dotnet_assembly_problem(path: Path) -> str | None:
    """Why `path` is not a managed (.NET) PE file, or None when it is one. Reads only the headers."""
    try:
        with open(path, "rb") as f:
            head = f.read(4096)
    except OSError as e:
        return f"cannot read it ({e.strerror})"
    if head[:2] != b"MZ":
        return "it has no PE/COFF 'MZ' header"
    if len(head) < 0x40:
        return "it is truncated"
    pe = struct.unpack_from("<I", head, 0x3C)[0]
    if pe + 24 > len(head) or head[pe:pe + 4] != b"PE\0\0":
        return "it has no PE signature"
    opt = pe + 24
    magic = struct.unpack_from("<H", head, opt)[0]
    dirs = opt + (96 if magic == 0x10B else 112 if magic == 0x20B else -1)
    if dirs < opt:
        return f"unknown PE optional header magic 0x{magic:x}"
    clr = dirs + 14 * 8  # data directory 14: the CLR runtime header
    if clr + 8 > len(head) or struct.unpack_from("<II", head, clr) == (0, 0):
        return "it is a native executable without a CLR header"
    return None


def _choose_runtime(assembly: Path, forced: str | None) -> tuple[str, str]:
    if forced:
        choice, source = forced, "--runtime"
    elif os.environ.get(ENV_RUNTIME):
        choice, source = os.environ[ENV_RUNTIME], ENV_RUNTIME
    else:
        cfg = _read_config(config_path()).get("runtime")
        if cfg:
            choice, source = cfg, str(config_path())
        else:
            has_rc = assembly.with_name("ACE.Server.runtimeconfig.json").is_file()
            return ("coreclr" if has_rc else "mono"), "detected"
    if choice not in RUNTIMES:
        raise OracleUnavailable(f"unknown runtime {choice!r} (from {source}); known: {', '.join(RUNTIMES)}")
    rc = assembly.with_name("ACE.Server.runtimeconfig.json")
    if choice == "coreclr" and not rc.is_file():
        raise OracleUnavailable(f"runtime coreclr (from {source}) needs {rc.name} beside {assembly} (a .NET build "
                                "output has one); this build looks like a mono/.NET Framework build: use --runtime mono")
    if choice == "mono" and rc.is_file():
        raise OracleUnavailable(f"runtime mono (from {source}) cannot run {assembly}: {rc.name} beside it marks a "
                                ".NET (CoreCLR) build; use --runtime coreclr")
    return choice, source


def ace_label() -> str:
    """A human label for the ACE build (e.g. its git commit), from ACE_VERSION or config ``ace_version``;
    recorded beside the assembly version and hash, which an mcs build leaves at 0.0.0.0."""
    v = os.environ.get("ACE_VERSION")
    if v:
        return v
    v = _read_config(config_path()).get("ace_version")
    return v if isinstance(v, str) else ""
