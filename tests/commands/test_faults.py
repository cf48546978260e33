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
    assert lines[0].startswith("acconform check: recorded corpus: loading ")


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
    one_line_exit_2(cli("stress", "-n", "1", "--scene-timeout", "0"), "--scene-timeout must be positive")


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


def acconform(*args) -> list[str]:
    return [sys.executable, "-m", "acconform.cli", *map(str, args)]


def run_cli(argv, cwd=None):
    return subprocess.run(argv, capture_output=True, text=True, cwd=cwd or ROOT)


def closed_pipe(argv):
    """`argv` with its stdout a pipe the reader closed at once (`... | head -1` after the first line)."""
    p = subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=ROOT)
    p.stdout.close()
    err = p.stderr.read()
    return subprocess.CompletedProcess(argv, p.wait(), "", err)


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
    assert len(results) == len(CATALOGUE) >= 23


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
