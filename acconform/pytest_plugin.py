"""A pytest fixture so a user's own suite can run an acconform campaign.

Installed with acconform (entry point ``pytest11``), so no conftest is needed::

    def test_my_port_matches_ace(acconform_campaign):
        result = acconform_campaign(impl="./build/my-port --acconform", n=500, seed=1)
        assert result.ok, result.report()

`acconform_campaign(impl=None, n=None, seed=0, kinds=None, mode="exact", keep_going=False,
timeout=10.0)` runs the port (or `impl`, an acconform.protocol/1 command) against live ACE when
one is configured (ACE_ASSEMBLY / the config file), else against the recorded corpus (``n``
then samples it, stratified by kind). Case files go to the test's tmp_path. ``--acconform-impl
CMD`` on the pytest command line sets the default `impl`.
"""

from __future__ import annotations

from dataclasses import dataclass

import pytest


def pytest_addoption(parser):
    parser.getgroup("acconform").addoption("--acconform-impl", default=None, metavar="CMD",
                                           help="default implementation for the acconform_campaign fixture")


@dataclass
class CampaignResult:
    """A campaign's Result with its JSON summary; `report()` is the text an assertion shows."""

    result: object
    summary: dict

    @property
    def ok(self) -> bool:
        return self.summary["ok"]

    def report(self) -> str:
        d = self.summary["differences"]
        lines = [f"{self.summary['cases']['compared']} cases compared, {d['total']} differences"]
        for c in d["cases"]:
            lines.append(f"  {c['file']} ({c['kind']}): " + "; ".join(c["differences"][:5]))
        return "\n".join(lines)


@pytest.fixture
def acconform_campaign(request, tmp_path):
    from .impl import make_backend
    from .numerics import runtime_named
    from .oracle import get_oracle, live_configured
    from .report import Campaign, summary
    from .runner import run_campaign
    from .protocol import CAMPAIGN_KINDS
    from .strategies import check_kinds, kind_supported

    started = []

    def campaign(impl=None, n=None, seed=0, kinds=None, mode="exact", keep_going=False, timeout=10.0):
        impl = impl or request.config.getoption("acconform_impl")
        port = make_backend(impl, mode, timeout)
        started.append(port)
        kinds = tuple(k for k in check_kinds(kinds) if kind_supported(k, getattr(port, "kinds", CAMPAIGN_KINDS)))
        oracle = get_oracle()
        port.runtime = runtime_named(oracle.versions.runtime)  # the port computes as the ACE it is compared with
        replay = None
        if not live_configured():
            replay = list(oracle.scenes(oracle.select(n=n, seed=seed, kinds=set(kinds))))
        r = run_campaign(port, oracle.run, kinds=kinds, n=n or 1000, seed=seed, mode=mode, keep_going=keep_going,
                         failures_dir=tmp_path / "failures", database=None, workers=1, replay=replay)
        info = {"name": port.name, "version": (port.hello or {}).get("version", ""), "command": impl or ""}
        c = Campaign("recorded" if replay is not None else "live", mode, seed, kinds, info, str(tmp_path / "failures"))
        return CampaignResult(r, summary(r, c))

    yield campaign
    for port in started:
        getattr(port, "close", lambda: None)()
