"""Finding ACE: resolution order, runtime choice, and one clear message for each misconfiguration."""

import pytest

from acconform.errors import OracleUnavailable
from acconform.oracle import config, get_oracle, live_configured
from acconform.oracle.members import check_members

ACE_BIN = "/work/acebuild/bin"  # used only as a path on disk, never loaded here


def _fake_dll(path, managed=True):
    """A minimal PE file with (or without) a CLR header: enough for the header check."""
    import struct

    b = bytearray(0x200)
    b[0:2] = b"MZ"
    struct.pack_into("<I", b, 0x3C, 0x80)
    b[0x80:0x84] = b"PE\0\0"
    opt = 0x80 + 24
    struct.pack_into("<H", b, opt, 0x10B)
    if managed:
        struct.pack_into("<II", b, opt + 96 + 14 * 8, 0x2008, 0x48)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(bytes(b))
    return path


def test_explicit_path_wins_over_environment_and_config(isolated_config, monkeypatch, tmp_path):
    (tmp_path / "a").mkdir()
    a = _fake_dll(tmp_path / "a" / "ACE.Server.dll")
    b = tmp_path / "b"
    b.mkdir()
    _fake_dll(b / "ACE.Server.dll")
    c = tmp_path / "c"
    c.mkdir()
    _fake_dll(c / "ACE.Server.dll")
    cfg = tmp_path / "config" / "acconform"
    cfg.mkdir(parents=True)
    (cfg / "config.toml").write_text(f'ace_assembly = "{c}"\n')
    monkeypatch.setenv("ACE_ASSEMBLY", str(b))
    assert config.resolve(a).assembly == a.resolve()
    assert config.resolve(a).source == "--ace"
    loc = config.resolve()
    assert loc.assembly == (b / "ACE.Server.dll").resolve() and loc.source == "ACE_ASSEMBLY"
    monkeypatch.delenv("ACE_ASSEMBLY")
    loc = config.resolve()
    assert loc.assembly == (c / "ACE.Server.dll").resolve() and loc.source.endswith("config.toml")


def test_nothing_configured_resolves_to_none_and_get_oracle_falls_back_to_recorded(isolated_config, tmp_path):
    assert config.resolve() is None
    assert not live_configured()
    from acconform.oracle.recorded import CorpusMissing

    with pytest.raises(CorpusMissing, match="no recorded-oracle corpus"):
        get_oracle(corpus=tmp_path / "nowhere")


def test_a_missing_path_names_the_path_its_source_and_what_to_set(isolated_config, tmp_path):
    with pytest.raises(OracleUnavailable) as e:
        config.resolve(tmp_path / "nope.dll")
    msg = str(e.value)
    assert "nope.dll" in msg and "--ace" in msg and "ACE_ASSEMBLY" in msg


def test_a_directory_without_ace_server_dll_is_refused(isolated_config, tmp_path):
    with pytest.raises(OracleUnavailable, match=r"no ACE\.Server\.dll in the directory"):
        config.resolve(tmp_path)


def test_a_file_that_is_not_dotnet_is_refused(isolated_config, tmp_path):
    txt = tmp_path / "ACE.Server.dll"
    txt.write_text("not a binary")
    with pytest.raises(OracleUnavailable, match="not a .NET assembly.*MZ"):
        config.resolve(txt)
    native = _fake_dll(tmp_path / "native" / "ACE.Server.dll", managed=False)
    with pytest.raises(OracleUnavailable, match="native executable without a CLR header"):
        config.resolve(native)
    other = _fake_dll(tmp_path / "build" / "ACE.Common.dll")  # managed, but not the one the oracle loads
    with pytest.raises(OracleUnavailable, match="ACE.Common.dll .* is not ACE.Server.dll: give ACE.Server.dll"):
        config.resolve(other)


def test_runtime_is_chosen_from_the_build_or_forced(isolated_config, tmp_path, monkeypatch):
    from .test_dotnet_host import _fake_root

    monkeypatch.setenv("DOTNET_ROOT", str(_fake_root(tmp_path / "dotnet")))
    dll = _fake_dll(tmp_path / "ACE.Server.dll")
    assert config.resolve(dll).runtime == "mono"
    (tmp_path / "ACE.Server.runtimeconfig.json").write_text('{"runtimeOptions": {"framework": {"name": "Microsoft.NETCore.App", "version": "10.0.0"}}}')
    loc = config.resolve(dll)
    assert (loc.runtime, loc.runtime_source) == ("coreclr", "detected")
    with pytest.raises(OracleUnavailable, match="use --runtime coreclr"):
        config.resolve(dll, "mono")
    with pytest.raises(OracleUnavailable, match="unknown runtime 'java'"):
        config.resolve(dll, "java")


def test_coreclr_forced_on_a_mono_build_is_refused(isolated_config, tmp_path):
    dll = _fake_dll(tmp_path / "ACE.Server.dll")
    with pytest.raises(OracleUnavailable, match="needs ACE.Server.runtimeconfig.json"):
        config.resolve(dll, "coreclr")


def test_a_missing_type_or_member_is_named_with_the_build_it_was_looked_for_in():
    types = {"ACE.A": {"x", ".ctor"}}
    with pytest.raises(OracleUnavailable) as e:
        check_members(lambda n: types.get(n), lambda t, m: m in t, "/opt/ace",
                      (("ACE.A", (".ctor", "x", "bogus")), ("ACE.Missing", ("y",))))
    msg = str(e.value)
    assert "ACE.A.bogus" in msg and "type ACE.Missing" in msg and "/opt/ace" in msg and "ACE_ASSEMBLY" in msg


def test_the_record_command_exits_2_without_ace(isolated_config, capsys):
    from acconform.cli import main

    assert main(["record", "-n", "1"]) == 2
    err = capsys.readouterr().err
    assert "needs the live oracle" in err and "ACE_ASSEMBLY" in err
