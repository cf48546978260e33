"""Every command that runs scenes takes --runtime mono|coreclr with one default (the ACE compared
with, else coreclr, .NET 10); a bad value is one line and exit 2; `run` computes the runtime's arithmetic."""

from __future__ import annotations

import gzip
import io
import json

import pytest

from acconform.case import Case, Record, Versions, write_document
from acconform.cli import COMMANDS, build_parser, main
from acconform.codec import dumps_compact
from acconform.commands import RUNTIME_CHOICES, runtime_or_default
from acconform.numerics import RUNTIMES
from acconform.oracle import DEFAULT_RUNTIME, default_corpus
from acconform.oracle.recorded import shards
from acconform.outcome import Outcome
from acconform.port.run import run_scene

# commands that run no scene and compare with no ACE (runtime-diff reads both runtimes' corpora; merge joins summaries)
NO_RUNTIME = {"validate", "show", "schema", "runtime-diff", "merge"}


def _subparsers():
    parser = build_parser()
    action = next(a for a in parser._actions if a.dest == "command")
    return action.choices


def test_every_command_that_runs_scenes_takes_the_same_runtime_option():
    assert set(RUNTIME_CHOICES) == set(RUNTIMES) and DEFAULT_RUNTIME == "coreclr"
    for name, sub in _subparsers().items():
        option = next((a for a in sub._actions if "--runtime" in a.option_strings), None)
        if name in NO_RUNTIME:
            assert option is None, name
            continue
        assert option is not None, f"`acconform {name}` takes no --runtime"
        assert option.type("mono") == "mono" and option.default is None, name
        assert "else coreclr (.NET 10" in option.help, name
    assert set(COMMANDS) - NO_RUNTIME == {"check", "repro", "explain", "report", "record", "coverage", "bench",
                                                  "stress", "run", "serve"}


@pytest.mark.parametrize("command", sorted(set(COMMANDS) - NO_RUNTIME))
def test_a_bad_runtime_is_one_line_and_exit_2(command, capsys):
    with pytest.raises(SystemExit) as e:
        main([command, "--runtime", "foo"])
    err = capsys.readouterr().err
    assert e.value.code == 2
    assert err.count("\n") == 1 and "Traceback" not in err, err
    assert f"acconform {command}: error: argument --runtime: unknown runtime 'foo': choose one of coreclr, mono" in err


def test_the_default_is_the_runtime_of_the_ace_compared_with_else_coreclr():
    class Oracle:
        versions = Versions("", "7b47913", "mono 6.8.0.105")

    assert runtime_or_default(None) == "coreclr"
    assert runtime_or_default(None, Oracle()) == "mono"
    assert runtime_or_default("coreclr", Oracle()) == "coreclr"


@pytest.fixture(scope="module")
def runtime_sensitive_record():
    """A .NET 10 record whose scene the port answers differently as mono: the first in the bsp shard."""
    shard = next(s for s in shards(default_corpus("coreclr")) if s.name.startswith("bsp-"))
    with gzip.open(shard, "rt") as f:
        for line in f:
            record = Record.from_json(json.loads(line))
            if run_scene(record.scene, runtime="mono") != record.outcome:
                return record
    pytest.fail(f"no scene in {shard} where mono's arithmetic changes the outcome")


def test_run_computes_the_runtimes_arithmetic_and_agrees_with_a_net10_record_by_default(runtime_sensitive_record, tmp_path, capsys):
    path = write_document(tmp_path / "record.json", runtime_sensitive_record)
    assert main(["run", str(path)]) == 0
    assert Outcome.from_json(json.loads(capsys.readouterr().out)) == runtime_sensitive_record.outcome
    assert main(["run", str(path), "--runtime", "mono"]) == 0
    mono = Outcome.from_json(json.loads(capsys.readouterr().out))
    assert mono != runtime_sensitive_record.outcome and mono == run_scene(runtime_sensitive_record.scene, runtime="mono")


def test_repro_without_ace_refuses_a_runtime_other_than_the_cases(runtime_sensitive_record, tmp_path, capsys, no_ace):
    r = runtime_sensitive_record
    case = Case(scene=r.scene, port=r.outcome, oracle=r.outcome, versions=r.versions)
    path = write_document(tmp_path / "case.json", case)
    assert main(["repro", str(path)]) == 0  # coreclr's arithmetic, as the case's ACE: agrees
    assert "coreclr arithmetic" in capsys.readouterr().out
    assert main(["repro", str(path), "--runtime", "mono"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "this case holds the answer of ACE on coreclr" in err


def test_serve_computes_a_request_without_a_runtime_as_its_runtime_option(runtime_sensitive_record):
    from acconform.protocol import serve

    scene = runtime_sensitive_record.scene
    request = (dumps_compact({"id": 1, "mode": "exact", "scene": scene.to_json()}) + "\n").encode()
    answers = {}
    for runtime in ("mono", "coreclr"):
        out = io.BytesIO()
        serve(lambda s, mode, rt: run_scene(s, mode=mode, runtime=rt), io.BytesIO(request), out, default_runtime=runtime)
        answers[runtime] = Outcome.from_json(json.loads(out.getvalue().splitlines()[1])["outcome"])
    assert answers["coreclr"] == runtime_sensitive_record.outcome
    assert answers["mono"] == run_scene(scene, runtime="mono") != answers["coreclr"]
