"""A JavaScript implementation speaks the protocol: tests/impl/recorded_answers.js answers each scene
with ACE's recorded outcome, looked up in the corpus it is given (by the scene's text as sent, else by
the recorded oracle's scene key), as recorded or built with JSON.stringify writing -0 as its bit
pattern. Through `acconform check --impl` it agrees with the corpus; the whole corpus is the slow
lane (and a step of .ci/run where node is installed)."""

from __future__ import annotations

import gzip
import json
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from acconform.oracle import default_corpus
from acconform.oracle.recorded import SHARD_RE, shards

JS = Path(__file__).with_name("recorded_answers.js")
NODE = shutil.which("node")
pytestmark = pytest.mark.skipif(NODE is None, reason="node is not installed: the JavaScript implementation "
                                "(tests/impl/recorded_answers.js) runs where it is")
PER_KIND = 40


def check(*args, cwd):
    return subprocess.run([sys.executable, "-m", "acconform.cli", "check", "--no-progress", "-j", "1", *args],
                          capture_output=True, text=True, cwd=cwd)


@pytest.fixture(scope="module")
def small_corpus(tmp_path_factory):
    """The first PER_KIND records of each kind of the coreclr corpus, as written, and how many of
    ACE's answers among them hold a -0.0."""
    d = tmp_path_factory.mktemp("corpus")
    negative_zeros = 0
    for kind in ("terrain", "bsp", "obstacles", "indoor", "buildings"):
        shard = next(s for s in shards(default_corpus("coreclr")) if SHARD_RE.match(s.name)["kind"] == kind)
        with gzip.open(shard, "rt") as f:
            lines = [line for _, line in zip(range(PER_KIND), f)]
        negative_zeros += sum("-0.0" in json.dumps(json.loads(line)["outcome"]) for line in lines)
        with gzip.open(d / f"{kind}-0000.jsonl.gz", "wt") as f:
            f.writelines(lines)
    return d, negative_zeros


def test_the_javascript_implementation_agrees_with_ace_on_a_corpus_through_the_protocol(small_corpus, tmp_path, no_ace):
    corpus, negative_zeros = small_corpus
    assert negative_zeros >= 10  # ACE answers -0.0 in these, so a -0 lost on the way would show
    r = check("--corpus", str(corpus), "--impl", f"node {JS} {corpus}", "--json", str(tmp_path / "s.json"),
              "--failures", str(tmp_path / "f"), cwd=tmp_path)
    assert r.returncode == 0, r.stdout + r.stderr
    s = json.loads((tmp_path / "s.json").read_text())
    assert s["cases"]["compared"] == 5 * PER_KIND and s["differences"]["total"] == 0, s["cases"]
    assert s["implementation"]["name"] == "recorded-answers.js"


def test_answers_built_with_json_stringify_and_negative_zero_as_its_bit_pattern_agree_with_ace(small_corpus, tmp_path,
                                                                                                no_ace):
    corpus, _ = small_corpus
    r = check("--corpus", str(corpus), "--impl", f"node {JS} --stringify {corpus}", "--json", str(tmp_path / "s.json"),
              "--failures", str(tmp_path / "f"), cwd=tmp_path)
    assert r.returncode == 0, r.stdout + r.stderr
    s = json.loads((tmp_path / "s.json").read_text())
    assert s["cases"]["compared"] == 5 * PER_KIND and s["differences"]["total"] == 0, s["cases"]


def test_negative_zero_written_as_json_stringify_writes_it_is_caught(small_corpus, tmp_path, no_ace):
    """The mistake the bit pattern avoids: JSON.stringify(-0) is "0", which is +0."""
    corpus, _ = small_corpus
    # (not shrunk: a smaller scene is one the corpus lacks, which the implementation cannot answer)
    r = check("--corpus", str(corpus), "--impl", f"node {JS} --plain-zero {corpus}", "--keep-going", "--shrink-budget", "0",
              "--json", str(tmp_path / "s.json"), "--failures", str(tmp_path / "f"), cwd=tmp_path)
    assert r.returncode == 1, r.stdout + r.stderr
    s = json.loads((tmp_path / "s.json").read_text())
    assert s["differences"]["total"] >= 1
    case = json.loads(Path(s["differences"]["cases"][0]["file"]).read_text())
    assert any("-0.0" in line for line in case["differences"]), case["differences"]


def test_a_scene_the_corpus_lacks_ends_the_javascript_implementation_with_one_line(small_corpus, tmp_path, no_ace):
    corpus, _ = small_corpus
    other = default_corpus("coreclr") / "terrain-0001.jsonl.gz"  # not among the small corpus's records
    from acconform.case import Record
    from acconform.protocol import CRASH, Implementation

    with gzip.open(other, "rt") as f:
        scene = Record.from_json(json.loads(f.readline())).scene
    impl = Implementation(f"node {JS} {corpus}")
    try:
        out = impl(scene)
    finally:
        impl.close()
    assert out.error.startswith(f"{CRASH}: the process exited with code 3") and "no recorded answer for scene" in out.error


@pytest.mark.slow
def test_the_javascript_implementation_agrees_with_the_whole_coreclr_corpus(tmp_path, no_ace):
    corpus = default_corpus("coreclr")
    r = subprocess.run([sys.executable, "-m", "acconform.cli", "check", "--no-progress", "--impl", f"node {JS} {corpus}",
                        "--json", str(tmp_path / "s.json"), "--failures", str(tmp_path / "f")],
                       capture_output=True, text=True, cwd=tmp_path)
    assert r.returncode == 0, r.stdout + r.stderr
    s = json.loads((tmp_path / "s.json").read_text())
    records = sum(1 for shard in shards(corpus) for _ in gzip.open(shard, "rt"))
    assert s["cases"]["compared"] == records and s["differences"]["total"] == 0
