"""The oracle on CoreCLR (lane `live_oracle`, with ACE_ASSEMBLY at a .NET build of ACE).

pythonnet loads one runtime per process, so the CoreCLR lane is its own pytest invocation:
`ACE_ASSEMBLY=/path/to/net10/ACE.Server.dll pytest tests/oracle`. Every other live test in this
folder runs there too; these check what only CoreCLR has.
"""

import pytest

from acconform.oracle import dotnet_host, facade_build, runtime

from .scenes import PROBE

pytestmark = pytest.mark.live_oracle


@pytest.fixture(scope="session")
def coreclr(live):
    if live.location.runtime != "coreclr":
        pytest.skip("the configured ACE is a mono build; run this lane with ACE_ASSEMBLY at a .NET build "
                    "(its ACE.Server.runtimeconfig.json selects CoreCLR)")
    return live


def test_coreclr_runs_ace_on_the_installation_found_with_the_framework_the_build_asks_for(coreclr):
    root = runtime.dotnet_root()
    assert root is not None and root == coreclr.location.dotnet_root
    (name, asked), = dotnet_host.required_frameworks(coreclr.location.runtime_config)[0]
    running = coreclr.versions.runtime.removeprefix("coreclr .NET ")
    assert running in dotnet_host.installed_frameworks(root.path, name)
    assert running.split(".")[0] == asked.split(".")[0]


def test_on_coreclr_the_facade_is_compiled_offline_with_the_sdk_and_cached(coreclr, monkeypatch, tmp_path):
    cache, packages = tmp_path / "cache", tmp_path / "no-packages"
    monkeypatch.setenv("XDG_CACHE_HOME", str(cache))
    monkeypatch.setenv("NUGET_PACKAGES", str(packages))  # an empty package folder and no package source
    dll, how = facade_build.build(coreclr.ace)
    tfm = dotnet_host.framework_tfm(coreclr.location.runtime_config)
    assert dll is not None, how
    assert dll.is_file() and dll.is_relative_to(cache) and how.startswith(f"compiled with the .NET SDK ({tfm}) by its csc")
    assert not packages.exists() or not any(packages.iterdir())
    assert [p.name for p in dll.parent.iterdir()] == [dll.name]  # the throw-away project is gone
    again, how = facade_build.build(coreclr.ace)
    assert again == dll and how.startswith("cached")


def test_on_coreclr_the_facade_is_built_as_a_project_where_the_sdks_csc_cannot_be_run_directly(coreclr, monkeypatch,
                                                                                                    tmp_path):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    monkeypatch.setattr(facade_build, "_direct_compiler", lambda root, tfm: None)
    dll, how = facade_build.build(coreclr.ace)
    assert dll is not None and dll.is_file(), how
    assert "by its csc" not in how and [p.name for p in dll.parent.iterdir()] == [dll.name]


def test_on_coreclr_scenes_cross_into_net_through_native_entry_points(coreclr):
    assert coreclr.location.runtime == "coreclr" and coreclr._run_pinned is not None
    o = coreclr.run(PROBE["flat 1-step walk"])
    assert o.error is None and o.ok and o.cell == 0xA9B40001
    assert coreclr.last_case_micros > 0 and coreclr.last_transition_micros > 0


def test_on_coreclr_ace_runs_with_the_workstation_gc_of_a_guest_not_the_server_gc_its_build_asks_for(coreclr):
    from System import AppContext
    from System.Runtime import GCSettings

    # ACE's own build (7b47913's ACE.Server.csproj) asks for the server GC and concurrent collection
    assert not GCSettings.IsServerGC
    assert str(AppContext.GetData("System.GC.Concurrent")) == "false"


def test_on_coreclr_ace_runs_without_tiered_pgo_so_no_third_jit_tier_competes_for_the_cores(coreclr):
    from System import AppContext

    # the runtime's own default is on; the property is what CLRConfig reads for DOTNET_TieredPGO
    assert str(AppContext.GetData("System.Runtime.TieredPGO")) == "false"
