"""The pytest fixture a user's suite runs a campaign with (acconform/pytest_plugin.py, entry point pytest11)."""

import subprocess
import sys
from pathlib import Path

import pytest

PLANTED = Path(__file__).with_name("planted_impl.py")

USER_SUITE = '''
def test_port_matches_ace(acconform_campaign):
    result = acconform_campaign(n=200, seed=1, keep_going=True)
    assert result.ok, result.report()
'''


@pytest.mark.slow
def test_a_users_suite_runs_a_campaign_and_a_planted_bug_fails_it_with_the_case_files(tmp_path, no_ace):
    (tmp_path / "test_user.py").write_text(USER_SUITE)
    good = subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", str(tmp_path)],
                          capture_output=True, text=True, cwd=tmp_path)
    assert good.returncode == 0, good.stdout + good.stderr
    impl = f"{sys.executable} {PLANTED} step_down_two_halves_made_thirds"
    bad = subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", str(tmp_path),
                          "--acconform-impl", impl], capture_output=True, text=True, cwd=tmp_path)
    assert bad.returncode == 1, bad.stdout + bad.stderr
    assert "differences" in bad.stdout and "case-" in bad.stdout
