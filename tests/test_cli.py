"""The acconform command: help, validate, and exit codes with no tracebacks."""

import json
import subprocess
import sys
from pathlib import Path

import pytest

from acconform.cli import COMMANDS, main

ROOT = Path(__file__).parent.parent


def run_cli(*args):
    return subprocess.run([sys.executable, "-m", "acconform.cli", *args], capture_output=True, text=True, cwd=ROOT)


def test_help_lists_every_subcommand():
    r = run_cli("--help")
    assert r.returncode == 0
    for name in COMMANDS:
        assert name in r.stdout


def test_validate_accepts_the_examples(capsys):
    files = sorted(str(p) for p in (ROOT / "examples").glob("*.json"))
    assert files, "examples/ must hold scenes"
    assert main(["validate", *files]) == 0
    assert capsys.readouterr().out.count("ok ") == len(files)


def test_validate_refuses_a_bad_file_with_exit_2_naming_file_and_field(tmp_path):
    doc = json.loads((ROOT / "examples" / "flat_walk.json").read_text())
    doc["landblocks"][0]["heights"] = [1, 2, 3]
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps(doc))
    r = run_cli("validate", str(bad), str(ROOT / "examples" / "flat_walk.json"))
    assert r.returncode == 2
    assert f"{bad}: landblocks[0].heights: expected 81 values, got 3" in r.stderr
    assert "Traceback" not in r.stderr
    assert "ok " in r.stdout  # the good file is still reported


@pytest.mark.parametrize(
    "content, message",
    [("{not json", "not valid JSON"), ("[1, 2]", 'expected a JSON object with a "format" field'), ("{}", "format: missing required field")],
)
def test_validate_explains_files_that_are_not_scenes(tmp_path, content, message):
    f = tmp_path / "x.json"
    f.write_text(content)
    r = run_cli("validate", str(f))
    assert r.returncode == 2 and message in r.stderr and "Traceback" not in r.stderr


def test_validate_names_a_missing_file(tmp_path):
    r = run_cli("validate", str(tmp_path / "nope.json"))
    assert r.returncode == 2 and "nope.json: no such file" in r.stderr


def test_no_command_is_a_usage_error_on_stderr_naming_the_commands():
    # as argparse answers any missing required argument; `acconform --help` is the way to ask for help
    r = run_cli()
    assert r.returncode == 2 and r.stdout == ""
    usage, last = r.stderr.strip().splitlines()
    assert usage.startswith("usage: acconform ")
    assert last.startswith("acconform: error: choose a command: validate, check, ") and all(c in last for c in COMMANDS)
