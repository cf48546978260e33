"""ci/: the GitHub Actions workflow and the shell job say what acconform accepts."""

import re
import shlex
import subprocess
from pathlib import Path

from acconform.cli import build_parser

CI = Path(__file__).resolve().parent.parent / "ci"


def _check_commands(text: str) -> list[str]:
    """Every `acconform check ...` command in the workflow, folded (>-) blocks joined."""
    text = re.sub(r">-\n((?:\s{10,}.*\n)+)", lambda m: " ".join(m.group(1).split()) + "\n", text)
    return [line.split("run:", 1)[1].strip() for line in text.splitlines() if "run: acconform check" in line]


def test_every_check_command_in_the_workflow_parses_and_none_asks_for_fast_mode():
    text = (CI / "github-actions.yml").read_text()
    commands = _check_commands(text)
    assert len(commands) == 2, commands
    for cmd in commands:
        argv = shlex.split(cmd.replace("${{ github.run_number }}", "7"))[1:]
        args = build_parser().parse_args(argv)
        assert args.impl == "$PORT_CMD" and args.json and args.junit and args.mode == "exact"
    assert "--mode fast" not in text


def test_the_live_lane_takes_ace_from_a_job_it_needs_and_that_job_names_the_artifact():
    text = (CI / "github-actions.yml").read_text()
    live = text.split("\n  live:", 1)[1]
    assert "needs: ace" in live and "name: ace-server-build" in live
    ace = text.split("# Your ACE build job", 1)[1].split("\n  live:", 1)[0]
    assert '"ace-server-build"' in ace and "uses:" in ace


def test_the_shell_job_is_valid_bash_and_installs_without_editable_mode():
    sh = CI / "differential.sh"
    assert subprocess.run(["bash", "-n", str(sh)]).returncode == 0
    assert " -e " not in sh.read_text()
