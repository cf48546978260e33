"""Faults and bad input as a new user meets them: each one clear line and exit 2, losing nothing."""

from __future__ import annotations

import gzip
import json
import os
import shutil
import signal
import subprocess
import sys
import time
from collections import Counter
from pathlib import Path

import pytest

from acconform.oracle import default_corpus
from acconform.oracle.recorded import RecordedOracle, shards

ROOT = Path(__file__).resolve().parents[2]


def cli(*args, cwd=None, **kw):
    return subprocess.run([sys.executable, "-m", "acconform.cli", *args], capture_output=True, text=True,
                          cwd=cwd or ROOT, **kw)


def one_line_exit_2(r, *words):
    assert r.returncode == 2, r.stdout + r.stderr
    assert "Traceback" not in r.stderr
    last = r.stderr.strip().splitlines()[-1]
    for w in words:
        assert w in last, last
    return last


@pytest.fixture
def small_corpus(tmp_path):
    """Two shards: 40 good terrain records, and a bsp shard whose 3rd line is broken."""
    d = tmp_path / "corpus"
    d.mkdir()
    terrain = [line for _, line in zip(range(40), gzip.open(next(s for s in shards(default_corpus()) if s.name.startswith("terrain")), "rt"))]
    with gzip.open(d / "terrain-0000.jsonl.gz", "wt") as f:
        f.writelines(terrain)
    bsp = [line for _, line in zip(range(5), gzip.open(shards(default_corpus())[0], "rt"))]
    bsp[2] = '{"format": "acconform.record/1", "scene": \n'
    with gzip.open(d / "bsp-0000.jsonl.gz", "wt") as f:
        f.writelines(bsp)
    return d


def test_a_bad_json_line_in_a_shard_names_shard_and_line_and_keep_going_skips_and_counts_it(small_corpus, tmp_path, no_ace):
    r = cli("check", "--corpus", str(small_corpus), "--no-progress", "--failures", str(tmp_path / "f"))
    last = one_line_exit_2(r, "bsp-0000.jsonl.gz line 3", "not JSON")
    assert "no ACE assembly" not in last
    r = cli("check", "--corpus", str(small_corpus), "--no-progress", "--keep-going", "--failures", str(tmp_path / "f"))
    assert r.returncode == 0, r.stderr
    assert "44 cases" in r.stdout and "skipped 1 unreadable corpus record" in r.stdout and "line 3" in r.stdout


def test_a_truncated_shard_is_named_with_the_last_line_read(small_corpus, tmp_path, no_ace):
    (small_corpus / "bsp-0000.jsonl.gz").unlink()
    shard = small_corpus / "terrain-0000.jsonl.gz"
    shard.write_bytes(shard.read_bytes()[: shard.stat().st_size // 2])
    r = cli("check", "--corpus", str(small_corpus), "--no-progress", "--failures", str(tmp_path / "f"))
    one_line_exit_2(r, "terrain-0000.jsonl.gz", "truncated after line")
    r = cli("validate", str(shard))
    one_line_exit_2(r, "terrain-0000.jsonl.gz", "truncated")


def test_validate_and_show_read_corpus_shards():
    shard = shards(default_corpus())[0]
    r = cli("validate", str(shard))
    assert r.returncode == 0 and r.stdout.startswith(f"ok {shard}: ") and "records" in r.stdout
    r = cli("show", str(shard))
    assert r.returncode == 0 and f"# {shard} line 2" in r.stdout and "ACE:" in r.stdout


def test_show_into_a_closed_pipe_stops_quietly():
    shard = shards(default_corpus())[0]
    p = subprocess.run(f"{sys.executable} -m acconform.cli show {shard} | head -1", shell=True, capture_output=True,
                       text=True, cwd=ROOT)
    assert p.stdout.startswith("# ") and p.stderr == ""


def test_an_unwritable_failures_directory_is_refused_before_the_campaign(tmp_path, no_ace):
    blocker = tmp_path / "file"
    blocker.write_text("")
    r = cli("check", "-n", "5", "--seed", "1", "--no-progress", "--failures", str(blocker / "sub"))
    one_line_exit_2(r, "--failures", "cannot write there")
    assert "cases in" not in r.stdout


def test_a_case_that_cannot_be_written_where_asked_goes_to_a_temporary_directory(tmp_path):
    from acconform.outcome import Outcome
    from acconform.runner import Result, save_cases
    from acconform.strategies import sample_scenes
    from acconform.runner import Found, make_case
    from acconform.case import Versions

    scene = next(iter(sample_scenes(("terrain",), 1, 0)))
    result = Result(found=[Found(make_case(scene, Outcome(ok=True), Outcome(), [], 0, "exact", Versions()))])
    blocker = tmp_path / "file"
    blocker.write_text("")
    save_cases(result, blocker / "sub")  # the directory became unwritable during the campaign
    path = result.found[0].path
    assert path.is_file() and str(path.parent) in result.failures_fallback and str(blocker / "sub") in result.failures_fallback


def test_bench_json_to_a_bad_path_is_refused_before_the_run():
    r = cli("bench", "-n", "1", "--json", "/nonexistent-dir/figures.json")
    one_line_exit_2(r, "--json", "no directory /nonexistent-dir")
    assert "ms/scene" not in r.stdout


def test_coverage_with_no_cases_is_refused():
    one_line_exit_2(cli("coverage", "-n", "0"), "--cases must be at least 1")


def test_negative_worker_counts_are_refused(no_ace):
    one_line_exit_2(cli("check", "-j", "-3"), "--workers", "-3")


def test_a_negative_shrink_budget_is_refused(no_ace):
    one_line_exit_2(cli("check", "--shrink-budget", "-1"), "--shrink-budget", "-1")


def test_replay_refuses_options_it_would_ignore(no_ace):
    one_line_exit_2(cli("check", "--database", "db"), "--database", "replaying")
    one_line_exit_2(cli("check", "--seed", "4"), "--seed", "-n")
    one_line_exit_2(cli("check", "--runtime", "mono", "--corpus", str(default_corpus("coreclr")), "--no-progress"),
                    "--runtime mono", "coreclr .NET 10")
    one_line_exit_2(cli("check", "--runtime", "wasm", "--no-progress"), "unknown runtime 'wasm'", "coreclr, mono")


def test_replay_samples_n_cases_stratified_by_kind_with_the_seed():
    oracle = RecordedOracle(default_corpus())
    every = Counter(e.kind for e in oracle.select())
    a = oracle.select(n=300, seed=1)
    assert len(a) == 300 and a == oracle.select(n=300, seed=1) and a != oracle.select(n=300, seed=2)
    got = Counter(e.kind for e in a)
    for kind, n in every.items():
        assert abs(got[kind] - 300 * n / len(oracle)) <= 1, (got, every)
    assert Counter(e.kind for e in oracle.select(n=2, seed=0)).total() == 2
    assert set(oracle.select(runtime="coreclr")) == set(oracle.select()) and not oracle.select(runtime="mono")


def test_progress_is_printed_while_the_corpus_loads(tmp_path, no_ace):
    r = cli("check", "-n", "3", "--seed", "1", "--failures", str(tmp_path / "f"))
    assert r.returncode == 0, r.stderr
    lines = r.stderr.splitlines()
    loading = [ln for ln in lines if ln.startswith("acconform check: recorded corpus: ")]
    # piped: one line, after a heartbeat line every Progress.PIPE_EVERY seconds while a slow load goes on
    assert lines[:len(loading)] == loading and " records from " in loading[-1]
    assert all(" loading " in ln for ln in loading[:-1])


def test_ctrl_c_prints_a_partial_summary_and_no_worker_lines(tmp_path, no_ace):
    p = subprocess.Popen([sys.executable, "-m", "acconform.cli", "check", "-j", "2", "--failures", str(tmp_path / "f")],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=ROOT, start_new_session=True)
    for line in p.stderr:  # wait until the campaign runs
        if "cases/s" in line:
            break
    os.killpg(p.pid, signal.SIGINT)  # what Ctrl-C in a terminal does: the whole process group
    out, err = p.communicate(timeout=120)
    assert p.returncode == 130, out + err
    assert out.startswith("interrupted: ") and " cases in " in out
    assert "Traceback" not in err and "KeyboardInterrupt" not in err


def test_while_workers_run_the_first_ctrl_c_only_asks_them_to_stop_and_a_second_stops_at_once():
    # The first Ctrl-C must not raise in the waiting parent: an exception between a lock's acquire
    # and release (the shared counter's, the pool's result condition) hangs the campaign.
    from acconform.runner import _ctrl_c_as_a_flag

    before = signal.getsignal(signal.SIGINT)
    first = second = None
    try:
        with _ctrl_c_as_a_flag() as pressed:
            try:
                signal.raise_signal(signal.SIGINT)
            except KeyboardInterrupt:
                first = "raised"
            else:
                first = list(pressed)
            signal.raise_signal(signal.SIGINT)
    except KeyboardInterrupt:
        second = "raised"
    assert (first, second) == ([signal.SIGINT], "raised")
    assert signal.getsignal(signal.SIGINT) is before


def test_stress_without_ace_does_not_speak_of_ace_not_raising():
    from acconform.commands.stress import KindStats, render

    s = KindStats()
    s.raised_alone["ZeroDivisionError"] = 1
    text = "\n".join(render({"ulp_nudge": s}, with_oracle=False))
    assert "port raised (no ACE to compare with)" in text and "ACE did not" not in text


def test_coverage_anchors_names_every_anchor_once_and_never_reached_agrees_with_the_table():
    r = cli("coverage", "--anchors", "-n", "20")
    assert r.returncode == 0, r.stderr
    lines = r.stdout.splitlines()
    start = next(i for i, l in enumerate(lines) if l.startswith("retail anchor"))
    end = next(i for i, l in enumerate(lines) if l.endswith("anchors reached"))
    table = {}
    for l in lines[start + 1:end]:
        name, calls = l.split("  ", 1)[0], int(l.split()[-1])
        assert name not in table, f"{name} listed twice"
        table[name] = calls
    never = next(l for l in lines if l.startswith("never reached"))
    unreached = [n for n, c in table.items() if c == 0]
    assert unreached and never == f"never reached ({len(unreached)}): " + ", ".join(unreached)


def test_repro_gives_no_verdict_when_the_implementation_a_case_names_does_not_start(tmp_path, no_ace):
    from acconform.case import Case, ImplementationRun, write_document
    from acconform.impl import BuiltinPort
    from acconform.strategies import sample_scenes

    scene = next(iter(sample_scenes(("terrain",), 1, 1)))
    answer = BuiltinPort()(scene)
    gone = ImplementationRun(f"{sys.executable} {tmp_path / 'no-such-port.py'}", str(tmp_path), {"name": "js-port"})
    write_document(tmp_path / "case.json", Case(scene, answer, answer, implementation=gone))
    r = cli("repro", str(tmp_path / "case.json"))
    last = one_line_exit_2(r, "no verdict", "'js-port'", "no-such-port.py", "--impl")
    assert "no longer fails" not in r.stdout and "still fails" not in r.stdout, last


def test_stress_refuses_a_time_limit_that_is_not_positive():
    one_line_exit_2(cli("stress", "-n", "1", "--scene-timeout", "0"), "--scene-timeout", "above 0, got 0")


# ------------------------------------------------------------------ the fault catalogue (issue 23)
#
# Every fault a new user met, as data: what they typed and the words the one line must hold. Each
# entry builds its inputs in a temporary directory and returns the finished process, the exit code
# it must end with, and the words. `test_no_fault_in_the_catalogue_prints_a_traceback` runs them all.

EXAMPLES = ROOT / "examples"
PLANTED = ROOT / "tests" / "impl" / "planted_impl.py"


def nested_json(path: Path, depth: int) -> Path:
    path.write_text("[" * depth + "]" * depth)
    return path


def deep_bsp_scene(path: Path, depth: int) -> Path:
    """A recorded BSP scene whose tree is put `depth` nodes deeper: each new node's plane lies 1 km
    above the object, so every query walks down its back child to the recorded tree."""
    line = next(iter(gzip.open(shards(default_corpus())[0], "rt")))
    scene = json.loads(line)["scene"]
    shape = next(o["shape"] for o in scene["objects"] if o["shape"]["kind"] == "bsp")
    root, sphere = shape["root"], shape["root"]["sphere"]
    for _ in range(depth):
        root = {"type": "node", "plane": {"normal": [0.0, 0.0, 1.0], "d": -1000.0}, "sphere": sphere,
                "front": {"type": "leaf", "polygons": [], "solid": False, "sphere": sphere}, "back": root}
    shape["root"] = root
    from acconform import deep

    path.write_text(deep.call(json.dumps, scene))
    return path


def scene_with(path: Path, **mover) -> Path:
    doc = json.loads((EXAMPLES / "flat_walk.json").read_text())
    doc["mover"].update(mover)
    path.write_text(json.dumps(doc))
    return path


def case_with(path: Path, **fields) -> Path:
    from acconform.case import Case
    from acconform.outcome import Outcome
    from acconform.scene import Scene

    doc = Case(Scene.loads((EXAMPLES / "flat_walk.json").read_text()), Outcome(ok=True), Outcome()).to_json()
    doc.update(fields)
    path.write_text(json.dumps(doc))
    return path


def tampered_corpus(d: Path) -> Path:
    """Four recorded terrain scenes, ACE's answer to the second moved 1 m: replaying finds a difference."""
    d.mkdir()
    lines = [line for _, line in zip(range(4), gzip.open(next(s for s in shards(default_corpus())
                                                              if s.name.startswith("terrain")), "rt"))]
    doc = json.loads(lines[1])
    doc["outcome"]["origin"][0] += 1.0
    lines[1] = json.dumps(doc) + "\n"
    with gzip.open(d / "terrain-0000.jsonl.gz", "wt") as f:
        f.writelines(lines)
    return d


def read_only(directory: Path, argv: list[str]) -> list[str]:
    """`argv` run with `directory` read-only: a read-only bind mount in a user namespace (root cannot be
    kept out by permission bits), or the permission bits for anyone else."""
    if os.geteuid() != 0:
        directory.chmod(0o555)
        return argv
    if not shutil.which("unshare") or subprocess.run(["unshare", "-rm", "true"], capture_output=True).returncode:
        pytest.skip("running as root without `unshare -rm`: no way to make a directory read-only here")
    # cd again after the mount: a working directory entered before it would still be the writable one
    return ["unshare", "-rm", "sh", "-c", 'mount -o bind,ro "$0" "$0" && cd "$PWD" && exec "$@"', str(directory), *argv]


def on_a_full_disk(directory: Path, argv: list[str], full: bool = True) -> list[str]:
    """`argv` run with a 64 KiB tmpfs mounted on `directory`, filled up unless not `full` (then it
    fills as `argv` writes), in a user namespace as `read_only` makes one (a mount needs no root there)."""
    if not shutil.which("unshare") or subprocess.run(["unshare", "-rm", "true"], capture_output=True).returncode:
        pytest.skip("no `unshare -rm`: no way to mount a small full disk here")
    fill = '{ cat /dev/zero > "$0/fill"; } 2>/dev/null; ' if full else ""
    return ["unshare", "-rm", "sh", "-c", f'mount -t tmpfs -o size=64k tmpfs "$0" && {fill}cd "$PWD" && exec "$@"',
            str(directory), *argv]


def acconform(*args) -> list[str]:
    return [sys.executable, "-m", "acconform.cli", *map(str, args)]


def to_dev_full(argv: list[str]):
    """`argv` with its stdout the device that is always full (`... > /dev/full`)."""
    with open("/dev/full", "w") as full:
        r = subprocess.run(argv, stdout=full, stderr=subprocess.PIPE, text=True, cwd=ROOT)
    return subprocess.CompletedProcess(argv, r.returncode, "", r.stderr)


def run_cli(argv, cwd=None):
    return subprocess.run(argv, capture_output=True, text=True, cwd=cwd or ROOT)


def closed_pipe(argv):
    """`argv` with its stdout a pipe the reader closed at once (`... | head -1` after the first line)."""
    p = subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=ROOT)
    p.stdout.close()
    err = p.stderr.read()
    return subprocess.CompletedProcess(argv, p.wait(), "", err)


def parts(t: Path) -> tuple[Path, Path]:
    """The --json summaries of the two parts of one sharded campaign that found nothing."""
    part = {"format": "acconform.summary/1", "ok": True, "interrupted": False, "oracle": "recorded", "mode": "exact",
            "seed": 1, "kinds": ["bsp"], "implementation": {}, "versions": {"runtime": "coreclr"},
            "shard": {"part": 1, "parts": 2, "cases_asked": None, "workers": 1},
            "cases": {"run": 1, "compared": 1, "skipped": {}}, "differences": {"cases": []}, "timings": {}}
    (t / "p1.json").write_text(json.dumps(part))
    (t / "p2.json").write_text(json.dumps(dict(part, shard=dict(part["shard"], part=2))))
    return t / "p1.json", t / "p2.json"


def record_with(path: Path, edit) -> Path:
    """A one-shard corpus at `path`: four recorded terrain scenes, the second's record changed by `edit(doc)`."""
    path.mkdir()
    lines = [line for _, line in zip(range(4), gzip.open(next(s for s in shards(default_corpus())
                                                              if s.name.startswith("terrain")), "rt"))]
    doc = json.loads(lines[1])
    edit(doc)
    lines[1] = json.dumps(doc) + "\n"
    with gzip.open(path / "terrain-0000.jsonl.gz", "wt") as f:
        f.writelines(lines)
    return path


def closes_its_output(path: Path) -> str:
    """An implementation that writes its handshake, closes its stdout and lives on: the --impl command."""
    path.write_text("import json, os, sys, time\nfrom acconform.protocol import handshake\n"
                    "print(json.dumps(handshake()), flush=True)\nos.close(1)\ntime.sleep(60)\n")
    return f"{sys.executable} {path}"


def json_directory_removed(tmp: Path):
    """`check --json` whose directory is removed while the campaign runs."""
    out = tmp / "reports"
    out.mkdir()
    p = subprocess.Popen(acconform("check", "--corpus", tampered_corpus(tmp / "corpus"), "--no-progress", "-j", "1",
                                   "--failures", tmp / "f", "--json", out / "summary.json", "--junit", out / "junit.xml"),
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=ROOT)
    first = p.stderr.readline()  # "acconform check: port vs recorded corpus ...": the campaign has begun
    shutil.rmtree(out)
    stdout, stderr = p.communicate(timeout=300)
    return subprocess.CompletedProcess(p.args, p.returncode, stdout, first + stderr)


# name -> function(tmp) -> (finished process, exit code, words the stderr's last line holds; for
# exit 0 and 1, words stdout holds)
CATALOGUE = {
    "a deeply nested JSON file in validate": lambda t: (
        run_cli(acconform("validate", nested_json(t / "deep.json", 30_000))), 2, ["deep.json", "nested more than 20,000"]),
    "a deeply nested JSON file in run": lambda t: (
        run_cli(acconform("run", nested_json(t / "deep.json", 30_000))), 2, ["deep.json", "nested more than 20,000"]),
    "an unbalanced quote in --impl": lambda t: (
        run_cli(acconform("run", EXAMPLES / "flat_walk.json", "--impl", f"{sys.executable} 'x")), 2,
        ["--impl", "no closing quotation", "check the quotes"]),
    "record --out on an existing file": lambda t: (
        (t / "corpus").write_text(""), run_cli(acconform("record", EXAMPLES / "flat_walk.json", "--out", t / "corpus")))[1:]
        + (2, ["--out", "is a file, not a directory"]),
    "record --out on a read-only filesystem": lambda t: (
        run_cli(read_only(t, acconform("record", EXAMPLES / "flat_walk.json", "--out", t / "corpus"))), 2,
        ["--out", "cannot write there"]),
    "the --json directory removed during a run": lambda t: (
        json_directory_removed(t), 1, ["warning: could not write --json", "warning: could not write --junit"]),
    "check | head -1 after a difference": lambda t: (
        closed_pipe(acconform("check", "--corpus", tampered_corpus(t / "corpus"), "--no-progress", "--failures", t / "f")),
        1, []),
    "\"velocity\": null": lambda t: (
        run_cli(acconform("validate", scene_with(t / "s.json", velocity=None))), 2, ["mover.velocity", "null"]),
    "a case with \"seed\": null": lambda t: (
        run_cli(acconform("validate", case_with(t / "c.json", seed=None))), 2, ["seed", "null"]),
    "--kinds terrain,,bsp": lambda t: (
        run_cli(acconform("check", "--kinds", "terrain,,bsp")), 2, ["--kinds", "empty kind name"]),
    "-j above the core count": lambda t: (
        run_cli(acconform("check", "-j", (os.cpu_count() or 1) + 1)), 2, ["--workers", "cores"]),
    "--ace .../ACE.Common.dll": lambda t: (
        (t / "ACE.Common.dll").write_bytes(b"MZ"), run_cli(acconform("check", "--ace", t / "ACE.Common.dll")))[1:]
        + (2, ["ACE.Common.dll", "is not ACE.Server.dll", str(t / "ACE.Server.dll")]),
    "run --impl with an indoor scene for an implementation of terrain only": lambda t: (
        run_cli(acconform("run", EXAMPLES / "two_rooms.json", "--impl", f"{sys.executable} {PLANTED} none --kinds terrain")),
        2, ["kind indoor", "lists kinds terrain", "nothing was sent"]),
    "a misnamed shard": lambda t: (
        (t / "corpus").mkdir(), shutil.copy(shards(default_corpus())[0], t / "corpus" / "bsp.jsonl.gz"),
        run_cli(acconform("check", "--corpus", t / "corpus", "--no-progress")))[2:]
        + (2, ["bsp.jsonl.gz", "<kind>-NNNN.jsonl.gz", "rename it"]),
    "a missing handshake": lambda t: (
        run_cli(acconform("run", EXAMPLES / "flat_walk.json", "--timeout", "1", "--impl",
                          f"{sys.executable} -c 'import time; time.sleep(60)'")), 2,
        ["sent no handshake", "none within 10 s", "stopped"]),
    "a clean check in a read-only working directory": lambda t: (
        run_cli(read_only(t, acconform("check", "-n", "3", "--seed", "1", "--no-progress")), cwd=t), 0,
        ["3 cases in", "0 differences"]),
    # met before issue 23, kept here so that the count covers them
    "a bad JSON line in a shard": lambda t: (
        (t / "c").mkdir(), (t / "c" / "bsp-0000.jsonl.gz").write_bytes(gzip.compress(b'{"format": \n')),
        run_cli(acconform("check", "--corpus", t / "c", "--no-progress")))[2:] + (2, ["bsp-0000.jsonl.gz line 1", "not JSON"]),
    "a truncated shard": lambda t: (
        (t / "terrain-0000.jsonl.gz").write_bytes(shards(default_corpus())[0].read_bytes()[:5000]),
        run_cli(acconform("validate", t / "terrain-0000.jsonl.gz")))[1:] + (2, ["terrain-0000.jsonl.gz", "truncated"]),
    "an unwritable --failures": lambda t: (
        (t / "file").write_text(""), run_cli(acconform("check", "--failures", t / "file" / "sub")))[1:]
        + (2, ["--failures", "cannot write there", "is a file"]),
    "bench --json in no directory": lambda t: (
        run_cli(acconform("bench", "-n", "1", "--json", "/nonexistent-dir/figures.json")), 2, ["--json", "no directory"]),
    "coverage -n 0": lambda t: (run_cli(acconform("coverage", "-n", "0")), 2, ["--cases must be at least 1"]),
    "negative workers": lambda t: (run_cli(acconform("check", "-j", "-3")), 2, ["--workers", "-3"]),
    "a negative shrink budget": lambda t: (run_cli(acconform("check", "--shrink-budget", "-1")), 2, ["--shrink-budget"]),
    "--database while replaying": lambda t: (run_cli(acconform("check", "--database", "db")), 2, ["--database"]),
    # issue 42: tracebacks
    "merge --failures in a read-only directory": lambda t: (
        run_cli(read_only(t, acconform("merge", *parts(t), "--failures", t / "f"))), 2,
        ["--failures", "cannot write there", "Read-only file system"]),
    "merge --json in a read-only directory": lambda t: (
        run_cli(read_only(t, acconform("merge", *parts(t), "--json", t / "m.json"))), 2,
        ["--json", "cannot write there", "Read-only file system"]),
    "record --out on a full disk": lambda t: (
        run_cli(on_a_full_disk(t, acconform("record", "-n", 3, "--out", t / "corpus"))), 2,
        ["--out", "cannot write there", "No space left on device"]),
    "schema scene > /dev/full": lambda t: (
        to_dev_full(acconform("schema", "scene")), 2, ["cannot write to standard output", "No space left"]),
    "show scene.json > /dev/full": lambda t: (
        to_dev_full(acconform("show", EXAMPLES / "flat_walk.json")), 2, ["cannot write to standard output"]),
    "check --corpus small > /dev/full": lambda t: (
        to_dev_full(acconform("check", "--corpus", record_with(t / "c", lambda d: None), "--no-progress",
                              "--failures", t / "f")), 2, ["acconform check: error: cannot write to standard output"]),
    # data lost
    "merge P1 P2 --json P1": lambda t: (
        run_cli(acconform("merge", *parts(t), "--json", t / "p1.json")), 2, ["--json", "p1.json: is the input"]),
    "record F --out F": lambda t: (
        run_cli(acconform("record", scene_with(t / "s.json"), "--out", t / "s.json")), 2, ["--out", "is the input"]),
    "bench --json into the corpus it reads": lambda t: (
        run_cli(acconform("bench", "-n", 1, "--corpus", record_with(t / "c", lambda d: None),
                          "--json", t / "c" / "terrain-0000.jsonl.gz")), 2, ["--json", "inside the input directory"]),
    # hangs
    "an implementation that closes its output and lives on": lambda t: (
        run_cli(acconform("run", EXAMPLES / "flat_walk.json", "--timeout", 3, "--impl", closes_its_output(t / "c.py"))),
        0, ["ImplementationCrash", "closed its output and did not exit within 3 s"]),
    # wrong exit codes
    "a record whose outcome has a NaN origin": lambda t: (
        run_cli(acconform("check", "--corpus", record_with(t / "c", lambda d: d["outcome"]["origin"].__setitem__(
            0, float("nan"))), "--no-progress", "--failures", t / "f")), 2,
        ["terrain-0000.jsonl.gz line 2", "outcome.origin[0]", "nan"]),
    "a record with no outcome": lambda t: (
        run_cli(acconform("check", "--corpus", record_with(t / "c", lambda d: d.pop("outcome")), "--no-progress",
                          "--failures", t / "f")), 2, ["terrain-0000.jsonl.gz line 2", "outcome: missing required field"]),
    # unclear
    "bare acconform": lambda t: (run_cli(acconform()), 2, ["choose a command", "validate, check"]),
    "merge p1.json bad_nested.json": lambda t: (
        run_cli(acconform("merge", parts(t)[0], nested_json(t / "bad_nested.json", 30_000))), 2,
        ["bad_nested.json", "nested more than 20,000"]),
    # accepted silently
    **{f"check {' '.join(o)}": (lambda o: lambda t: (run_cli(acconform("check", *o)), 2, [o[0], o[1]]))(o)
       for o in (("-j", "0"), ("-j", "-2"), ("--timeout", "0"), ("--timeout", "-1"), ("--timeout", "nan"),
                 ("--timeout", "inf"))},
    "bench --timeout 0": lambda t: (run_cli(acconform("bench", "--timeout", 0)), 2, ["--timeout", "above 0", "got 0"]),
    "run --timeout 0": lambda t: (
        run_cli(acconform("run", EXAMPLES / "flat_walk.json", "--timeout", 0)), 2, ["--timeout", "above 0"]),
    "record --batch 0": lambda t: (run_cli(acconform("record", "-n", 1, "--batch", 0)), 2, ["--batch", "got 0"]),
    "record --batch -1": lambda t: (run_cli(acconform("record", "-n", 1, "--batch", -1)), 2, ["--batch", "got -1"]),
    **{f"{command} a case with {field} {value!r}": (lambda command, field, value: lambda t: (
        run_cli(acconform(command, case_with(t / "c.json", **{field: value}))), 2, ["c.json", field, repr(value)]))(
        command, field, value) for command in ("validate", "show") for field, value in (("mode", "weird"), ("seed", "zero"))},
    **{f"{command} a case recorded on java 8": (lambda command: lambda t: (
        run_cli(acconform(command, case_with(t / "c.json", versions={"acconform": "", "ace": "", "runtime": "java 8"}))),
        2, ["c.json", "versions.runtime", "'java 8'"]))(command) for command in ("validate", "show")},
    **{f"{command} a record holding a double": (lambda command: lambda t: (
        run_cli(acconform(command, record_with(t / "c", lambda d: d["outcome"]["origin"].__setitem__(
            0, 0.30000000000000004)) / "terrain-0000.jsonl.gz")), 2,
        ["line 2", "outcome.origin[0]", "0.30000000000000004 is not a float32"]))(command) for command in ("validate", "show")},
    **{f"{command} a 0-byte shard": (lambda command: lambda t: (
        (t / "terrain-0000.jsonl.gz").write_bytes(b""), run_cli(acconform(command, t / "terrain-0000.jsonl.gz")))[1:]
        + (2, ["terrain-0000.jsonl.gz", "empty"]))(command) for command in ("validate", "show")},
    "a BSP 20,001 levels deep": lambda t: (
        run_cli(acconform("validate", deep_bsp_scene(t / "deep.json", 20_001))), 2, ["deep.json", "nested more than 20,000"]),
}


def test_no_fault_in_the_catalogue_prints_a_traceback(tmp_path, no_ace):
    from concurrent.futures import ThreadPoolExecutor

    def one(item):
        name, make = item
        d = tmp_path / f"f{list(CATALOGUE).index(name)}"
        d.mkdir()
        try:
            r, code, words = make(d)
        finally:
            d.chmod(0o755)
        return name, r, code, words

    with ThreadPoolExecutor(2) as pool:  # the handshake wait is 10 s; the rest is mostly start-up
        results = list(pool.map(one, CATALOGUE.items()))
    tracebacks = [name for name, r, _, _ in results if "Traceback" in r.stderr or "Traceback" in r.stdout]
    assert not tracebacks, f"{len(tracebacks)} of {len(results)} faults print a traceback: {tracebacks}"
    for name, r, code, words in results:
        assert r.returncode == code, (name, r.returncode, r.stdout, r.stderr)
        text = r.stderr.strip().splitlines()[-1] if code == 2 else r.stdout
        for w in words:
            assert w in text, (name, w, text)
        assert "restarted" not in r.stderr, name
    assert len(results) == len(CATALOGUE) >= 59


@pytest.mark.anchor("BSPNODE::find_walkable")
def test_a_bsp_5000_levels_deep_validates_and_runs_as_the_tree_without_them(tmp_path):
    deep = deep_bsp_scene(tmp_path / "deep.json", 5000)
    shallow = deep_bsp_scene(tmp_path / "shallow.json", 0)
    r = cli("validate", str(deep))
    assert r.returncode == 0 and r.stdout.startswith(f"ok {deep}: scene"), r.stderr
    expected = cli("run", str(shallow))
    assert expected.returncode == 0, expected.stderr
    for how in ((), ("--impl", f"{sys.executable} -m acconform.cli serve")):
        r = cli("run", str(deep), *how)
        assert r.returncode == 0 and "Traceback" not in r.stderr, r.stderr
        assert r.stdout == expected.stdout, how


@pytest.mark.live_oracle
@pytest.mark.anchor("BSPNODE::find_walkable")
def test_ace_runs_a_bsp_5000_levels_deep_and_the_port_answers_as_it_does(tmp_path, live):
    from acconform.case import load_document
    from acconform.compare import compare
    from acconform.numerics import runtime_named
    from acconform.port.run import run_scene

    scene = load_document(deep_bsp_scene(tmp_path / "deep.json", 5000))
    ace = live.run(scene)
    assert ace.error is None
    assert compare(run_scene(scene, runtime=runtime_named(live.versions.runtime)), ace, "exact") == []


def test_a_json_file_nested_past_the_limit_is_refused_naming_the_file(tmp_path):
    from acconform.case import load_document
    from acconform.deep import MAX_DEPTH, TooDeep

    with pytest.raises(TooDeep, match=f"deep.json: nested more than {MAX_DEPTH:,} levels"):
        load_document(nested_json(tmp_path / "deep.json", 2 * MAX_DEPTH))


def test_null_is_refused_where_leaving_a_field_out_means_a_default():
    from acconform.case import Case
    from acconform.errors import InvalidScene
    from acconform.scene import Scene

    doc = json.loads((EXAMPLES / "flat_walk.json").read_text())
    for field_, value in (("velocity", [0.0, 0.0, 0.0]), ("state", ["Gravity"]), ("scale", 1.0)):
        bad = json.loads(json.dumps(doc))
        bad["mover"][field_] = None
        with pytest.raises(InvalidScene, match=f"mover.{field_}: null is not a value"):
            Scene.from_json(bad)
        bad["mover"][field_] = value
        Scene.from_json(bad)
    none = json.loads(json.dumps(doc))
    none["mover"]["sliding_normal"] = None  # left out, it is none: null says the same
    assert Scene.from_json(none).mover.sliding_normal is None
    from acconform.outcome import Outcome

    case = Case(Scene.from_json(doc), Outcome(ok=True), Outcome()).to_json()
    for field_ in ("seed", "mode", "differences", "versions"):
        with pytest.raises(InvalidScene, match=f"{field_}: null is not a value"):
            Case.from_json({**case, field_: None})


def test_kinds_with_an_empty_or_repeated_name_are_refused():
    from acconform.errors import AcconformError
    from acconform.strategies import check_kinds

    assert check_kinds("terrain, bsp") == ("terrain", "bsp")
    for kinds, words in (("terrain,,bsp", "empty kind name"), ("terrain,", "empty kind name"),
                         ("bsp,terrain,bsp", "'bsp' is named twice")):
        with pytest.raises(AcconformError, match=words):
            check_kinds(kinds)


def test_a_missing_handshake_stops_the_process_after_the_start_timeout_and_says_so():
    from acconform.protocol import Implementation, ImplementationError

    t0 = time.monotonic()
    with pytest.raises(ImplementationError) as e:
        Implementation(f"{sys.executable} -c 'import time; time.sleep(60)'", timeout=0.2, start_timeout=0.5)
    assert time.monotonic() - t0 < 10
    assert "sent no handshake: none within 0.5 s, so it was stopped" in str(e.value) and "restart" not in str(e.value)


def test_reports_whose_directory_went_away_during_a_run_are_written_to_a_named_file(tmp_path, no_ace):
    r = json_directory_removed(tmp_path)
    assert r.returncode == 1, r.stdout + r.stderr
    warnings = {line.split()[4]: line.rsplit(" ", 1)[1] for line in r.stdout.splitlines() if line.startswith("warning: could not write --")}
    assert set(warnings) == {"--json", "--junit"}, r.stdout
    assert json.loads(Path(warnings["--json"]).read_text())["differences"]
    import xml.etree.ElementTree as ET

    assert ET.parse(warnings["--junit"]).getroot().iter("failure")
    for f in warnings.values():
        Path(f).unlink()


def test_a_check_in_a_read_only_directory_puts_its_cases_in_a_named_temporary_directory(tmp_path, no_ace):
    corpus = tampered_corpus(tmp_path / "corpus")
    ro = tmp_path / "ro"
    ro.mkdir()
    try:
        r = run_cli(read_only(ro, acconform("check", "--corpus", corpus, "--no-progress")), cwd=ro)
    finally:
        ro.chmod(0o755)
    assert r.returncode == 1, r.stdout + r.stderr
    warning = next(line for line in r.stdout.splitlines() if line.startswith("warning: could not write to failures"))
    fallback = Path(warning.rsplit(" ", 1)[1])
    assert [p.name for p in fallback.glob("case-*.json")] and not (ro / "failures").exists()
    shutil.rmtree(fallback)


def test_check_into_a_pipe_its_reader_closed_keeps_the_verdicts_exit_code(tmp_path, no_ace):
    corpus = tampered_corpus(tmp_path / "corpus")
    r = closed_pipe(acconform("check", "--corpus", corpus, "--no-progress", "--failures", tmp_path / "f"))
    assert r.returncode == 1 and "Traceback" not in r.stderr and "BrokenPipe" not in r.stderr, r.stderr
    assert list((tmp_path / "f").glob("case-*.json"))  # the case is written all the same


# ------------------------------------------------------------------ issue 42: a test per class of fault


def test_writing_to_a_full_stdout_is_one_line_and_exit_2_whatever_the_command():
    # what is still buffered when the command ends fails too: at the explicit flush, not at exit
    for argv in (("schema", "scene"), ("schema", "outcome", "--fields"), ("show", EXAMPLES / "flat_walk.json"),
                 ("validate", EXAMPLES / "flat_walk.json")):
        r = to_dev_full(acconform(*argv))
        assert r.returncode == 2 and "Traceback" not in r.stderr and "Exception ignored" not in r.stderr, (argv, r.stderr)
        assert r.stderr.strip().splitlines()[-1] == (f"acconform {argv[0]}: error: cannot write to standard output "
                                                     "(No space left on device); its output is lost")


def test_a_corpus_writer_on_a_disk_that_fills_keeps_its_finished_shards_and_leaves_no_half_shard(tmp_path):
    script = tmp_path / "fill.py"
    script.write_text(f"""
import gzip, json, sys
from acconform.case import Record
from acconform.errors import AcconformError
from acconform.oracle.recorded import CorpusWriter
lines = [l for _, l in zip(range(200), gzip.open({str(shards(default_corpus())[0])!r}, "rt"))]
try:
    with CorpusWriter(sys.argv[1] + "/corpus", shard_size=5) as w:
        for line in lines:
            w.add(Record.from_json(json.loads(line)))
except AcconformError as e:
    print(e)
from acconform.oracle.recorded import RecordedOracle
from pathlib import Path
print(sorted(p.name for p in Path(sys.argv[1], "corpus").iterdir()))
print(len(RecordedOracle(sys.argv[1] + "/corpus")))
""")
    d = tmp_path / "disk"
    d.mkdir()
    r = run_cli(on_a_full_disk(d, [sys.executable, script, d], full=False))
    assert r.returncode == 0, r.stderr
    said, names, kept = r.stdout.strip().splitlines()
    assert said.startswith(f"{d}/corpus: cannot write a shard (No space left on device); the shards finished are kept")
    names = json.loads(names.replace("'", '"'))  # the printed list of the corpus's files
    assert names and all(n.endswith(".jsonl.gz") for n in names)  # no half-written .tmp left
    assert int(kept) == 5 * len(names) < 200


def test_no_command_writes_over_one_of_its_inputs(tmp_path):
    from acconform.errors import AcconformError
    from acconform.paths import refuse_output_over_input

    p1, p2 = parts(tmp_path)
    before = p1.read_bytes()
    one_line_exit_2(cli("merge", str(p1), str(p2), "--json", str(p1)), "--json", "is the input", "nothing was done")
    assert p1.read_bytes() == before
    (tmp_path / "link.json").symlink_to(p2)
    os.link(p2, tmp_path / "hard.json")
    corpus = record_with(tmp_path / "corpus", lambda d: None)
    for output, inputs, says in ((p1, [p1, p2], "is the input"), (tmp_path / "link.json", [p2], "is the input"),
                                 (tmp_path / "hard.json", [p2], "is the input"),
                                 (tmp_path / "." / "p1.json", [p1], "is the input"),
                                 (corpus / "terrain-0000.jsonl.gz", [corpus], "is inside the input directory"),
                                 (corpus / "new" / "summary.json", [corpus], "is inside the input directory")):
        with pytest.raises(AcconformError, match=f"--json {output}: {says}"):
            refuse_output_over_input(output, inputs, "--json")
    refuse_output_over_input(None, [p1], "--json")  # not asked for
    refuse_output_over_input(tmp_path / "merged.json", [p1, p2, corpus], "--json")
    refuse_output_over_input(tmp_path, [p1], "--out")  # a directory holding an input: record adds new shards there


def test_an_implementation_that_closes_its_output_and_lives_on_gets_a_verdict_within_its_timeout(tmp_path):
    from acconform.protocol import CRASH, Implementation
    from acconform.scene import Scene

    impl = Implementation(closes_its_output(tmp_path / "closer.py"), timeout=1.0, start_timeout=10)
    try:
        t0 = time.monotonic()
        outcome = impl.run(Scene.loads((EXAMPLES / "flat_walk.json").read_text()))
        took = time.monotonic() - t0
    finally:
        impl.close()
    assert outcome.error.startswith(f"{CRASH}: the process closed its output and did not exit within 1 s")
    assert took < 1.0 + 5, took  # its timeout, and a fresh process's start for the next scene


def test_a_record_without_a_readable_outcome_is_unreadable_not_a_difference(tmp_path, no_ace):
    for name, edit, says in (("nan", lambda d: d["outcome"]["origin"].__setitem__(0, float("nan")),
                              "outcome.origin[0]: expected a finite number, got nan"),
                             ("none", lambda d: d.pop("outcome"), "outcome: missing required field")):
        corpus = record_with(tmp_path / name, edit)
        failures = tmp_path / f"f-{name}"
        r = cli("check", "--corpus", str(corpus), "--no-progress", "--failures", str(failures))
        one_line_exit_2(r, f"{corpus}/terrain-0000.jsonl.gz line 2: {says}", "--keep-going")
        assert not failures.exists()  # no case written: nothing was compared
        r = cli("check", "--corpus", str(corpus), "--no-progress", "--keep-going", "--failures", str(failures))
        assert r.returncode == 0 and "3 compared" in r.stdout and "skipped 1 unreadable corpus record" in r.stdout, r.stdout


@pytest.mark.parametrize("argv, says", [
    (("check", "-j", "0"), "argument -j/--workers: must be at least 1, got 0"),
    (("check", "--timeout", "0"), "argument --timeout: must be a finite number of seconds above 0, got 0"),
    (("check", "--timeout", "nan"), "argument --timeout: must be a finite number of seconds above 0, got nan"),
    (("check", "--timeout", "inf"), "argument --timeout: must be a finite number of seconds above 0, got inf"),
    (("check", "--timeout", "soon"), "argument --timeout: expected a number of seconds, got 'soon'"),
    (("bench", "--timeout", "-1"), "argument --timeout: must be a finite number of seconds above 0, got -1"),
    (("record", "-n", "1", "--batch", "0"), "argument --batch: must be at least 1, got 0"),
    (("record", "-n", "1", "--batch", "x"), "argument --batch: expected a whole number of at least 1, got 'x'"),
])
def test_an_option_outside_its_domain_is_refused_by_name(argv, says, no_ace):
    one_line_exit_2(cli(*argv), says)


def test_a_value_outside_its_domain_in_a_file_is_refused_by_name(tmp_path):
    from acconform.case import iter_documents, load_document
    from acconform.codec import parse_json_text
    from acconform.deep import MAX_DEPTH, TooDeep
    from acconform.errors import InvalidScene

    for fields, says in (({"mode": "weird"}, "mode: expected one of exact, fast, got 'weird'"),
                         ({"seed": "zero"}, "seed: expected a whole number"),
                         ({"versions": {"runtime": "java 8"}}, "versions.runtime: unknown runtime 'java 8'")):
        with pytest.raises(InvalidScene, match=says):
            load_document(case_with(tmp_path / "c.json", **fields))
    for fields in ({"mode": "fast"}, {"seed": "-12"}, {"seed": ""},
                   {"versions": {"runtime": "coreclr .NET 10.0.12; mono 6.8.0.105"}}, {"versions": {"runtime": ""}}):
        load_document(case_with(tmp_path / "c.json", **fields))
    shard = record_with(tmp_path / "c", lambda d: d["outcome"]["velocity"].__setitem__(2, 0.1 + 0.2)) / "terrain-0000.jsonl.gz"
    with pytest.raises(InvalidScene, match=r"line 2: outcome.velocity\[2\]: 0.30000000000000004 is not a float32"):
        list(iter_documents(shard))
    (tmp_path / "empty.jsonl.gz").write_bytes(b"")
    with pytest.raises(InvalidScene, match="empty.jsonl.gz: empty: no document in it"):
        list(iter_documents(tmp_path / "empty.jsonl.gz"))
    parse_json_text("[" * MAX_DEPTH + "]" * MAX_DEPTH)  # as deep as the README allows: read
    with pytest.raises(TooDeep):
        parse_json_text("[" * (MAX_DEPTH + 1) + "]" * (MAX_DEPTH + 1))
