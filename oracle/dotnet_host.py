"""Finding a .NET installation the way the dotnet host does: its root, shared frameworks and SDKs.

Plain file-system logic, no pythonnet, so every rule is tested with fake installations:

- `find_root`: ``DOTNET_ROOT_X64`` / ``DOTNET_ROOT`` (the architecture-specific one first), else the
  directory of the real path of ``dotnet`` on PATH, else the location registered in
  ``/etc/dotnet/install_location_x64`` / ``/etc/dotnet/install_location``, else the default
  install locations. A candidate counts only when it holds ``host/fxr`` (hostfxr, what pythonnet
  loads).
- `framework_problem`: whether the root has a shared framework version that the build's
  ``runtimeconfig.json`` accepts under the host's roll-forward rules.
- `sdk_versions`: the SDKs under the root (what ``dotnet build`` would use).
"""

from __future__ import annotations

import json
import os
import platform
import shutil
import sys
from dataclasses import dataclass
from pathlib import Path

from ..errors import OracleUnavailable

_ARCH = {"x86_64": "x64", "amd64": "x64", "aarch64": "arm64", "arm64": "arm64"}.get(platform.machine().lower(), "x64")
ENV_ROOTS = (f"DOTNET_ROOT_{_ARCH.upper()}", "DOTNET_ROOT")
INSTALL_LOCATION_FILES = (Path(f"/etc/dotnet/install_location_{_ARCH}"), Path("/etc/dotnet/install_location"))
# the host's compiled-in default (Microsoft's packages), then the one distributions patch in
DEFAULT_ROOTS = ((Path("/usr/local/share/dotnet"),) if sys.platform == "darwin"
                 else (Path("/usr/share/dotnet"), Path("/usr/lib/dotnet")))
NETCORE_APP = "Microsoft.NETCore.App"
ROLL_FORWARD = ("LatestPatch", "Minor", "LatestMinor", "Major", "LatestMajor", "Disable")


@dataclass(frozen=True, slots=True)
class DotnetRoot:
    path: Path
    found_by: str  # "DOTNET_ROOT", "dotnet on PATH (/usr/bin/dotnet)", "/etc/dotnet/install_location", "default location"


def _has_hostfxr(root: Path) -> bool:
    fxr = root / "host" / "fxr"
    return fxr.is_dir() and any(fxr.iterdir())


def find_root() -> DotnetRoot:
    """The .NET root the host would use, or OracleUnavailable naming every place looked at."""
    looked = []
    for var in ENV_ROOTS:
        value = os.environ.get(var)
        if value:
            root = Path(value)
            if not _has_hostfxr(root):
                raise OracleUnavailable(f"{var}={value} holds no .NET host (no host/fxr there); point {var} at a "
                                        ".NET installation (the directory holding dotnet, host/ and shared/) or unset it")
            return DotnetRoot(root, var)
    looked.append(f"{' / '.join(ENV_ROOTS)} unset")
    cli = shutil.which("dotnet")
    if cli:
        root = Path(cli).resolve().parent
        if _has_hostfxr(root):
            return DotnetRoot(root, f"dotnet on PATH ({cli})")
        looked.append(f"{cli} resolves to {root}, which has no host/fxr")
    else:
        looked.append("no dotnet on PATH")
    for f in INSTALL_LOCATION_FILES:
        try:
            lines = f.read_text().splitlines()
        except OSError:
            continue
        root = Path(lines[0].strip()) if lines and lines[0].strip() else None
        if root is not None and _has_hostfxr(root):
            return DotnetRoot(root, str(f))
        looked.append(f"{f} names {root}, which has no host/fxr")
    for root in DEFAULT_ROOTS:
        if _has_hostfxr(root):
            return DotnetRoot(root, "default location")
    looked.append(f"nothing in {', '.join(str(r) for r in DEFAULT_ROOTS)}")
    raise OracleUnavailable(f"no .NET runtime found ({'; '.join(looked)}): install the .NET runtime the ACE build "
                            "targets, set DOTNET_ROOT, or use --runtime mono with a mono build")


def _version(text: str) -> tuple[int, int, int, str] | None:
    core, _, pre = text.partition("-")
    parts = core.split(".")
    if len(parts) != 3 or not all(p.isdigit() for p in parts):
        return None
    return int(parts[0]), int(parts[1]), int(parts[2]), pre


def installed_frameworks(root: Path, name: str) -> list[str]:
    d = root / "shared" / name
    if not d.is_dir():
        return []
    found = [(v, p.name) for p in d.iterdir() if p.is_dir() and (v := _version(p.name)) is not None]
    return [n for _, n in sorted(found)]


def _accepts(policy: str, want: tuple, have: tuple) -> bool:
    if have[3] and not want[3]:
        return False  # the host rolls forward to a pre-release only from a pre-release
    if policy == "Disable":
        return have == want
    if have[:3] < want[:3]:
        return False
    if policy == "LatestPatch":
        return have[:2] == want[:2]
    if policy in ("Minor", "LatestMinor"):
        return have[0] == want[0]
    return True  # Major, LatestMajor


def required_frameworks(runtime_config: Path) -> tuple[list[tuple[str, str]], str]:
    """([(framework name, version)], roll-forward policy) from a runtimeconfig.json."""
    try:
        opts = json.loads(runtime_config.read_text())["runtimeOptions"]
    except (OSError, ValueError, KeyError, TypeError) as e:
        raise OracleUnavailable(f"cannot read {runtime_config}: {type(e).__name__}: {e}; rebuild ACE "
                                "(a .NET build writes it beside ACE.Server.dll)") from None
    fws = opts.get("frameworks") or ([opts["framework"]] if opts.get("framework") else [])
    if not fws:
        raise OracleUnavailable(f"{runtime_config} names no shared framework (a self-contained build?); the oracle "
                                "loads ACE into the installed .NET runtime: build ACE framework-dependent")
    policy = os.environ.get("DOTNET_ROLL_FORWARD") or opts.get("rollForward") or "Minor"
    try:
        return [(f["name"], f["version"]) for f in fws], policy
    except (KeyError, TypeError):
        raise OracleUnavailable(f"{runtime_config}: a framework entry lacks its name or version") from None


def framework_problem(runtime_config: Path, root: DotnetRoot) -> str | None:
    """Why the root cannot run the build (a framework it asks for is not installed), or None."""
    frameworks, policy = required_frameworks(runtime_config)
    if policy not in ROLL_FORWARD:
        return f"{runtime_config.name} asks for roll-forward {policy!r}; the host knows {', '.join(ROLL_FORWARD)}"
    for name, version in frameworks:
        want = _version(version)
        if want is None:
            return f"{runtime_config.name} asks for {name} version {version!r}, which is not a version"
        have = installed_frameworks(root.path, name)
        if not any(_accepts(policy, want, _version(h)) for h in have):
            return (f"the ACE build asks for {name} {version} ({runtime_config}, roll-forward {policy}) but the .NET "
                    f"at {root.path} (found by {root.found_by}) has {', '.join(have) if have else 'no ' + name}: "
                    f"install .NET {want[0]}.{want[1]} or point DOTNET_ROOT at an installation that has it")
    return None


def framework_tfm(runtime_config: Path) -> str:
    """The target framework moniker of the build (``net10.0``): its runtimeconfig's ``tfm``, else
    the Microsoft.NETCore.App version it asks for."""
    try:
        tfm = json.loads(runtime_config.read_text())["runtimeOptions"].get("tfm")
    except (OSError, ValueError, KeyError, TypeError):
        tfm = None
    if isinstance(tfm, str) and tfm.startswith("net"):
        return tfm
    frameworks, _ = required_frameworks(runtime_config)
    version = dict(frameworks).get(NETCORE_APP, frameworks[0][1])
    return "net" + ".".join(version.split(".")[:2])


def sdk_versions(root: Path) -> list[str]:
    d = root / "sdk"
    if not d.is_dir():
        return []
    return sorted(p.name for p in d.iterdir() if (p / "dotnet.dll").is_file())


def dotnet_cli(root: Path) -> Path:
    exe = "dotnet.exe" if sys.platform == "win32" else "dotnet"
    return root / exe
