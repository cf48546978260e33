"""Branch coverage of port/ by the recorded corpus alone (issue 24): each runtime's coverage kernel
(tests/data/corpus/<runtime>/coverage-kernel.json, a subset of the corpus taking every branch the
records traced to build it take) replayed under coverage.py stays at or above the floor recorded
beside it, and every branch listed as beyond ACE's reach (tests/data/unreachable-branches.json)
still resolves in today's source and is still not taken."""

import json
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
SCRIPT = ROOT / "benchmarks" / "corpus_coverage.py"
sys.path.insert(0, str(SCRIPT.parent))

import corpus_coverage  # noqa: E402


def test_every_listed_unreachable_branch_resolves_in_todays_source_with_its_reason():
    entries = corpus_coverage.load_unreachable()
    assert entries
    seen = set()
    for e in entries:
        assert e.get("reason") and e.get("ace"), f"{e['module']} {e['function']}: give the reason and ACE's lines"
        assert ("to" in e) != ("through" in e), f"{e['module']} {e['function']}: an entry has `to` or `through`"
        assert e.get("runtime", "mono") in ("coreclr", "mono"), f"{e['module']} {e['function']}: runtime coreclr or mono"
        assert e["kind"] in corpus_coverage.KINDS, f"{e['module']} {e['function']}: kind ace, harness or scene"
        arcs, lines = corpus_coverage.resolve(e)  # raises naming the snippet it cannot find
        assert arcs or lines
        key = (frozenset(arcs), frozenset(lines))
        assert key not in seen, f"{e['module']} {e['function']} from {e['from']!r} is listed twice"
        seen.add(key)


def test_an_entry_is_found_by_its_function_and_quoted_source_not_by_line_numbers(tmp_path):
    (tmp_path / "m.py").write_text("def f(x):\n    if x:\n        return 1\n    return 2\n")
    entry = {"module": "m.py", "function": "f", "from": "if x:", "to": "return 1"}
    assert corpus_coverage.resolve(entry, tmp_path) == ({"m.py:2->3"}, set())
    # lines inserted above the function move it; the entry still names the same branch
    (tmp_path / "m.py").write_text("import os\n\n\ndef f(x):\n    if x:\n        return 1\n    return 2\n")
    assert corpus_coverage.resolve(entry, tmp_path) == ({"m.py:5->6"}, set())
    region = {"module": "m.py", "function": "f", "from": "return 1", "through": "end"}
    assert corpus_coverage.resolve(region, tmp_path) == (set(), {("m.py", 6), ("m.py", 7)})
    # a `from` line that occurs twice is told apart by the line it follows ("after")
    (tmp_path / "m.py").write_text("def f(x, y):\n    a = x\n    if a:\n        return 1\n    a = y\n    if a:\n"
                                   "        return 2\n    return 3\n")
    twice = {"module": "m.py", "function": "f", "from": "if a:", "to": "return"}
    with pytest.raises(corpus_coverage.Unresolved, match="2 lines start 'if a:'"):
        corpus_coverage.resolve(twice, tmp_path)
    assert corpus_coverage.resolve({**twice, "after": "a = y"}, tmp_path) == ({"m.py:6->7"}, set())
    (tmp_path / "m.py").write_text("def f(x):\n    if x:\n        return 1\n    return 2\n")
    with pytest.raises(corpus_coverage.Unresolved, match="no line starting 'if y:'"):
        corpus_coverage.resolve({**entry, "from": "if y:"}, tmp_path)
    with pytest.raises(corpus_coverage.Unresolved, match="no function g"):
        corpus_coverage.resolve({**entry, "function": "g"}, tmp_path)


@pytest.mark.parametrize("runtime", ["coreclr", "mono"])
def test_each_runtime_has_a_coverage_kernel_with_a_floor(runtime):
    doc = json.loads(corpus_coverage.kernel_file(runtime).read_text())
    assert doc["format"] == corpus_coverage.KERNEL_FORMAT and doc["runtime"] == runtime
    assert 0 < len(doc["keys"]) < doc["corpus_records"]
    assert 0 < doc["floor_percent"] <= 100 * doc["taken"] / doc["branches"]


def test_an_entry_naming_a_runtime_holds_on_that_runtime_only(tmp_path):
    both = {"module": "m.py", "function": "f", "kind": "ace", "from": "if x:", "to": "return 1"}
    net10 = {**both, "from": "if y:", "runtime": "coreclr"}
    (tmp_path / "u.json").write_text(json.dumps({"branches": [both, net10]}))
    assert corpus_coverage.load_unreachable(tmp_path / "u.json", runtime="coreclr") == [both, net10]
    assert corpus_coverage.load_unreachable(tmp_path / "u.json", runtime="mono") == [both]
    assert corpus_coverage.load_unreachable(tmp_path / "u.json") == [both, net10]


def test_the_kernel_greedily_covers_every_arc_with_few_records():
    masks = {"a": 0b0011, "b": 0b0110, "c": 0b1100, "d": 0b1111, "e": 0b0001}
    assert corpus_coverage.greedy_kernel(masks) == ["d"]
    masks = {"a": 0b0011, "b": 0b0110, "c": 0b1100, "e": 0b0001}
    assert corpus_coverage.greedy_kernel(masks) == ["a", "c"]


@pytest.mark.slow
@pytest.mark.parametrize("runtime", ["coreclr", "mono"])
def test_the_corpus_keeps_its_branch_coverage_and_takes_no_listed_unreachable_branch(runtime):
    pytest.importorskip("coverage", reason="coverage.py measures the replay (pip install coverage)")
    r = subprocess.run([sys.executable, str(SCRIPT), "--kernel", "--runtime", runtime],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stdout[-3000:] + r.stderr[-3000:]
    assert "branch coverage of port/" in r.stdout


def test_write_kernel_refuses_a_with_shard_the_corpus_lacks_and_writes_nothing(tmp_path, capsys):
    """--with names shards to add to the candidates; a name that matches none was once taken
    silently, so the kernel left out every new shard. Nothing is written when it is refused."""
    kernel = tmp_path / "coverage-kernel.json"
    assert corpus_coverage.main(["--write-kernel", "-n", "1", "--corpus", str(tmp_path),
                                 "--with", "terrain-0042"]) == 2
    assert "--with terrain-0042: no such shard" in capsys.readouterr().err and not kernel.exists()


@pytest.mark.parametrize("kind", [None, "", "ACE", "unreachable"])
def test_the_list_refuses_an_entry_without_a_valid_kind_naming_it(tmp_path, kind):
    """Each entry says what rules its branch out (ace, harness or scene): one that does not is refused
    by name, not counted under some kind."""
    good = {"module": "m.py", "function": "f", "kind": "scene", "from": "if x:", "to": "return 1"}
    bad = {"module": "m.py", "function": "g", "from": "if y:", "to": "return 2"}
    if kind is not None:
        bad["kind"] = kind
    (tmp_path / "u.json").write_text(json.dumps({"branches": [good, bad]}))
    with pytest.raises(corpus_coverage.BadEntry, match=r"m\.py g from 'if y:' has (no kind|kind '.*'): give it one of ace, harness, scene"):
        corpus_coverage.load_unreachable(tmp_path / "u.json")


def test_kernel_refuses_a_list_entry_without_a_kind_before_replaying(tmp_path, monkeypatch, capsys):
    (tmp_path / "coverage-kernel.json").write_text(json.dumps({"keys": []}))
    (tmp_path / "u.json").write_text(json.dumps({"branches": [{"module": "m.py", "function": "g", "from": "if y:", "to": "exit"}]}))
    monkeypatch.setattr(corpus_coverage, "UNREACHABLE", tmp_path / "u.json")
    monkeypatch.setattr(corpus_coverage.load_unreachable, "__defaults__", (tmp_path / "u.json", None))
    monkeypatch.setattr(corpus_coverage, "measure", lambda *a, **k: pytest.fail("replayed before refusing the list"))
    assert corpus_coverage.main(["--kernel", "--corpus", str(tmp_path)]) == 2
    assert "m.py g from 'if y:' has no kind" in capsys.readouterr().err


def test_the_listed_branches_are_counted_by_kind(tmp_path, monkeypatch):
    """--kernel's line `listed by kind: ace A, harness H, scene S` counts the branches never taken that
    the entries of each kind explain: a {from, to} entry its one branch, a {from, through} entry every
    branch out of its lines; a branch the replay took is a problem, not counted."""
    (tmp_path / "m.py").write_text("def f(x, y):\n    if x:\n        return 1\n    if y:\n        if x:\n"
                                   "            return 2\n        return 3\n    return 4\n")
    monkeypatch.setattr(corpus_coverage, "_port_dir", lambda: tmp_path)
    entries = [{"module": "m.py", "function": "f", "kind": "ace", "from": "if x:", "after": "def f", "to": "return 1"},
               {"module": "m.py", "function": "f", "kind": "scene", "from": "if x:", "after": "if y:", "through": "return 2"},
               {"module": "m.py", "function": "f", "kind": "harness", "from": "if y:", "to": "return 4"}]

    class Data:
        def lines(self, path):
            return [2, 4, 8]

    class Cov:
        def get_data(self):
            return Data()

    missed = ["m.py:2->3", "m.py:4->5", "m.py:5->6", "m.py:5->7"]
    problems, unexplained, counts = corpus_coverage.check_unreachable_by_kind(Cov(), missed, entries)
    assert problems == ["m.py f from 'if y:': m.py:4->8 is taken now (or is no branch): take it out of unreachable-branches.json"]
    assert unexplained == ["m.py:4->5"]
    assert counts == {"ace": 1, "harness": 0, "scene": 2}
    assert corpus_coverage.kinds_line(counts) == "listed by kind: ace 1, harness 0, scene 2"


def test_the_motion_layers_scope_names_only_modules_and_methods_the_port_has():
    """The motion layer counted apart from the 95 % rule (issue 40) is data: each method it names resolves
    in today's port/, and its rooms match at least one module each."""
    root = corpus_coverage._port_dir()
    scope = corpus_coverage.motion_layer_lines(root)  # raises Unresolved for a method the port no longer has
    for module, methods in corpus_coverage.MOTION_LAYER_METHODS.items():
        assert scope[module], f"{module}: no lines for {methods}"
    for prefix in corpus_coverage.MOTION_LAYER_MODULES:
        assert any(name.startswith(prefix) and lines is None for name, lines in scope.items()), prefix


def test_the_world_that_moves_scope_names_only_modules_and_methods_the_port_has_and_none_of_the_motion_layers():
    """Issue 41's rooms counted apart from the 95 % rule are data too: each method resolves in today's port/,
    each room matches a module, and no line is in both scopes (a branch is counted apart once)."""
    root = corpus_coverage._port_dir()
    world = corpus_coverage.world_lines(root)
    for module, methods in corpus_coverage.WORLD_METHODS.items():
        assert world[module], f"{module}: no lines for {methods}"
    for prefix in corpus_coverage.WORLD_MODULES:
        assert any(name.startswith(prefix) and lines is None for name, lines in world.items()), prefix
    motion = corpus_coverage.motion_layer_lines(root)
    for module, lines in world.items():
        if module in motion:
            assert lines is not None and motion[module] is not None and not lines & motion[module], module
