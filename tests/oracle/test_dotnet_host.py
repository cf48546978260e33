"""Finding .NET for a CoreCLR build the way the dotnet host does, and one clear line when it cannot."""

import json

import pytest

from acconform.errors import OracleUnavailable
from acconform.oracle import config, dotnet_host, facade_build

from .test_config import _fake_dll


def _fake_root(path, frameworks=("10.0.12",), sdks=()):
    """A .NET installation as the host sees it: host/fxr, shared frameworks, SDKs."""
    (path / "host" / "fxr" / "10.0.12").mkdir(parents=True)
    (path / "host" / "fxr" / "10.0.12" / "libhostfxr.so").write_bytes(b"")
    for v in frameworks:
        (path / "shared" / "Microsoft.NETCore.App" / v).mkdir(parents=True)
    for v in sdks:
        (path / "sdk" / v).mkdir(parents=True)
        (path / "sdk" / v / "dotnet.dll").write_bytes(b"")
    (path / "dotnet").write_text("#!/bin/sh\n")
    (path / "dotnet").chmod(0o755)
    return path


def _fake_build(path, version="10.0.0", **options):
    path.mkdir(parents=True, exist_ok=True)
    dll = _fake_dll(path / "ACE.Server.dll")
    rc = {"runtimeOptions": {"tfm": "net" + ".".join(version.split(".")[:2]),
                             "framework": {"name": "Microsoft.NETCore.App", "version": version}, **options}}
    (path / "ACE.Server.runtimeconfig.json").write_text(json.dumps(rc))
    return dll


@pytest.fixture
def no_dotnet(isolated_config, monkeypatch, tmp_path):
    """No .NET anywhere the host looks: no DOTNET_ROOT, no dotnet on PATH, no registered or default location."""
    for var in dotnet_host.ENV_ROOTS + ("DOTNET_ROLL_FORWARD",):
        monkeypatch.delenv(var, raising=False)
    empty = tmp_path / "empty-path"
    empty.mkdir()
    monkeypatch.setenv("PATH", str(empty))
    monkeypatch.setattr(dotnet_host, "INSTALL_LOCATION_FILES", (tmp_path / "etc" / "install_location",))
    monkeypatch.setattr(dotnet_host, "DEFAULT_ROOTS", (tmp_path / "default-dotnet",))
    return tmp_path


def test_dotnet_root_comes_from_the_variable_then_path_then_etc_then_the_default_location(no_dotnet, monkeypatch):
    t = no_dotnet
    default = _fake_root(t / "default-dotnet")
    assert dotnet_host.find_root() == dotnet_host.DotnetRoot(default, "default location")
    registered = _fake_root(t / "registered")
    (t / "etc").mkdir()
    (t / "etc" / "install_location").write_text(f"{registered}\n")
    assert dotnet_host.find_root() == dotnet_host.DotnetRoot(registered, str(t / "etc" / "install_location"))
    on_path = _fake_root(t / "on-path")
    (t / "bin").mkdir()
    (t / "bin" / "dotnet").symlink_to(on_path / "dotnet")  # /usr/bin/dotnet -> /usr/share/dotnet/dotnet
    monkeypatch.setenv("PATH", str(t / "bin"))
    found = dotnet_host.find_root()
    assert found.path == on_path and found.found_by == f"dotnet on PATH ({t / 'bin' / 'dotnet'})"
    by_var = _fake_root(t / "by-var")
    monkeypatch.setenv("DOTNET_ROOT", str(by_var))
    assert dotnet_host.find_root() == dotnet_host.DotnetRoot(by_var, "DOTNET_ROOT")


def test_no_dotnet_anywhere_is_one_line_naming_every_place_looked_at(no_dotnet):
    with pytest.raises(OracleUnavailable) as e:
        dotnet_host.find_root()
    msg = str(e.value)
    assert "no .NET runtime found" in msg and "no dotnet on PATH" in msg and "default-dotnet" in msg
    assert "DOTNET_ROOT" in msg and "\n" not in msg


def test_a_dotnet_root_variable_without_a_host_is_refused(no_dotnet, monkeypatch):
    monkeypatch.setenv("DOTNET_ROOT", str(no_dotnet))
    with pytest.raises(OracleUnavailable, match=r"DOTNET_ROOT=.* holds no \.NET host"):
        dotnet_host.find_root()


def test_a_coreclr_build_on_a_machine_without_dotnet_fails_when_resolved_and_the_cli_exits_2(no_dotnet, capsys):
    dll = _fake_build(no_dotnet / "ace")
    with pytest.raises(OracleUnavailable, match="no .NET runtime found"):
        config.resolve(dll)
    from acconform.cli import main

    assert main(["record", "-n", "1", "--ace", str(dll)]) == 2
    err = capsys.readouterr().err.strip()
    assert "no .NET runtime found" in err and "Traceback" not in err and len(err.splitlines()) == 1


def test_a_build_asking_for_a_framework_that_is_not_installed_names_both_versions(no_dotnet, monkeypatch, capsys):
    root = _fake_root(no_dotnet / "dotnet", frameworks=("8.0.5", "9.0.1"))
    monkeypatch.setenv("DOTNET_ROOT", str(root))
    dll = _fake_build(no_dotnet / "ace", "10.0.0")
    with pytest.raises(OracleUnavailable) as e:
        config.resolve(dll)
    msg = str(e.value)
    assert "Microsoft.NETCore.App 10.0.0" in msg and "8.0.5, 9.0.1" in msg and "install .NET 10.0" in msg
    from acconform.cli import main

    assert main(["check", "-n", "1", "--ace", str(dll)]) == 2
    assert "asks for Microsoft.NETCore.App 10.0.0" in capsys.readouterr().err


def test_an_installed_framework_satisfies_the_build_and_is_recorded_in_its_location(no_dotnet, monkeypatch):
    root = _fake_root(no_dotnet / "dotnet", frameworks=("10.0.12",))
    monkeypatch.setenv("DOTNET_ROOT", str(root))
    loc = config.resolve(_fake_build(no_dotnet / "ace", "10.0.0"))
    assert loc.runtime == "coreclr" and loc.dotnet_root == dotnet_host.DotnetRoot(root, "DOTNET_ROOT")
    assert dotnet_host.framework_tfm(loc.runtime_config) == "net10.0"


@pytest.mark.parametrize(("policy", "installed", "accepted"), [
    ("Minor", "10.0.12", True),  # the default: a later patch
    ("Minor", "10.2.0", True),  # ... or a later minor of the same major
    ("Minor", "11.0.0", False),
    ("Minor", "9.9.9", False),
    ("LatestPatch", "10.1.0", False),
    ("LatestPatch", "10.0.3", True),
    ("Major", "11.0.0", True),
    ("Disable", "10.0.1", False),
    ("Disable", "10.0.0", True),
    ("Minor", "10.0.1-rc.1", False),  # never a pre-release for a release
])
def test_the_framework_check_follows_the_host_roll_forward_policy(no_dotnet, policy, installed, accepted):
    root = _fake_root(no_dotnet / "dotnet", frameworks=(installed,))
    rc = _fake_build(no_dotnet / "ace", "10.0.0", rollForward=policy).with_name("ACE.Server.runtimeconfig.json")
    problem = dotnet_host.framework_problem(rc, dotnet_host.DotnetRoot(root, "test"))
    assert (problem is None) == accepted, problem


def test_a_runtimeconfig_without_a_shared_framework_is_refused(no_dotnet):
    (no_dotnet / "ace").mkdir()
    rc = no_dotnet / "ace" / "ACE.Server.runtimeconfig.json"
    rc.write_text('{"runtimeOptions": {"includedFrameworks": [{"name": "Microsoft.NETCore.App", "version": "10.0.0"}]}}')
    with pytest.raises(OracleUnavailable, match="names no shared framework"):
        dotnet_host.required_frameworks(rc)
    rc.write_text("{not json")
    with pytest.raises(OracleUnavailable, match="cannot read"):
        dotnet_host.required_frameworks(rc)


def test_the_facade_needs_an_sdk_and_says_so_when_the_installation_has_the_runtime_only(no_dotnet, monkeypatch):
    root = _fake_root(no_dotnet / "dotnet")
    monkeypatch.setattr(facade_build, "dotnet_root", lambda: dotnet_host.DotnetRoot(root, "DOTNET_ROOT"))
    dll, why = facade_build._build_dotnet(None, no_dotnet / "facade.dll")
    assert dll is None and f"no .NET SDK in {root}" in why and "runtime only" in why
    assert dotnet_host.sdk_versions(_fake_root(no_dotnet / "with-sdk", sdks=("10.0.401",))) == ["10.0.401"]


def test_the_facade_is_compiled_by_the_newest_sdks_csc_against_the_newest_reference_pack_of_the_build_framework(tmp_path):
    root = _fake_root(tmp_path / "dotnet", sdks=("9.0.100", "10.0.401"))
    assert facade_build._direct_compiler(root, "net10.0") is None  # no Roslyn in the SDK: `dotnet build` instead
    for v in ("9.0.100", "10.0.401"):
        (root / "sdk" / v / "Roslyn" / "bincore").mkdir(parents=True)
        (root / "sdk" / v / "Roslyn" / "bincore" / "csc.dll").write_bytes(b"")
    assert facade_build._direct_compiler(root, "net10.0") is None  # no targeting pack
    for v, tfm in (("10.0.9", "net10.0"), ("10.0.12", "net10.0"), ("11.0.0", "net11.0")):
        (root / "packs" / "Microsoft.NETCore.App.Ref" / v / "ref" / tfm).mkdir(parents=True)
        (root / "packs" / "Microsoft.NETCore.App.Ref" / v / "ref" / tfm / "System.Runtime.dll").write_bytes(b"")
    csc, refs = facade_build._direct_compiler(root, "net10.0")
    assert csc == root / "sdk" / "10.0.401" / "Roslyn" / "bincore" / "csc.dll"  # 10.0.401, not "9.0.100" as text sorts
    assert refs == [root / "packs" / "Microsoft.NETCore.App.Ref" / "10.0.12" / "ref" / "net10.0" / "System.Runtime.dll"]
