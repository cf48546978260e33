"""acconform runtime-diff: the two runtimes' corpora paired by scene, fields counted per kind, and
the System.Numerics operation behind each difference found by switching one at a time."""

from __future__ import annotations

from dataclasses import replace

import pytest

from acconform import numerics
from acconform.case import Record, Versions
from acconform.cli import main
from acconform.commands.runtime_diff import OPERATIONS, attribute, field_group, mono_operation, pair
from acconform.oracle import default_corpus
from acconform.oracle.recorded import CorpusWriter, RecordedOracle, scene_key
from acconform.outcome import NormalState, Outcome
from acconform.protocol import CAMPAIGN_KINDS
from acconform.port.run import run_scene
from acconform.strategies import sample_scenes

MONO = Versions("0.1.0", "test", "mono 6.8.0.105")
CORECLR = Versions("0.1.0", "test", "coreclr .NET 10.0.12")


def _corpora(tmp_path, scenes, coreclr_outcome):
    """A mono and a coreclr corpus of `scenes`; the coreclr answer of each is coreclr_outcome(scene, mono's)."""
    with CorpusWriter(tmp_path / "mono") as m, CorpusWriter(tmp_path / "coreclr") as c:
        for s in scenes:
            o = run_scene(s, runtime="mono")
            m.add(Record(s, o, MONO))
            c.add(Record(s, coreclr_outcome(s, o), CORECLR))
    return tmp_path / "mono", tmp_path / "coreclr"


def test_a_field_is_counted_once_per_scene_and_kind_without_its_component_index(tmp_path, capsys):
    scenes = list(sample_scenes(("terrain",), 4, 3))
    flipped = scene_key(scenes[1])

    def coreclr(s, o):  # one scene's collision normal gains -0 components, as .NET 10's negation makes
        if scene_key(s) != flipped:
            return o
        return replace(o, collision_normal=NormalState(o.collision_normal.valid, (-0.0, -0.0, -0.0)))

    mono, cc = _corpora(tmp_path, scenes, coreclr)
    assert main(["runtime-diff", "--mono", str(mono), "--coreclr", str(cc)]) == 0
    out = capsys.readouterr().out
    others = " 0 |" * (len(CAMPAIGN_KINDS) - 1)  # the terrain column, then every other kind's
    assert f"| scenes paired | 4 |{others} 4 |" in out
    assert f"| **scenes whose outcome differs** | 1 |{others} 1 |" in out
    assert f"| `collision_normal.vector` | 1 |{others} 1 |" in out and "`origin`" not in out
    assert field_group("contact_plane.normal[2]") == "contact_plane.normal"


def test_the_committed_corpora_pair_up_scene_for_scene():
    mono, coreclr = RecordedOracle(default_corpus("mono")), RecordedOracle(default_corpus("coreclr"))
    assert len(pair(mono, coreclr)) == len(mono) >= 10_000


def test_corpora_of_the_wrong_runtime_or_without_shared_scenes_are_refused_in_one_line(tmp_path, capsys):
    mono, cc = _corpora(tmp_path, list(sample_scenes(("terrain",), 2, 3)), lambda s, o: o)
    assert main(["runtime-diff", "--mono", str(cc), "--coreclr", str(mono)]) == 2
    assert "holds answers of ACE on coreclr, not mono" in capsys.readouterr().err
    other = tmp_path / "other"
    with CorpusWriter(other) as w:
        for s in sample_scenes(("bsp",), 2, 5):
            w.add(Record(s, Outcome(ok=True), CORECLR))
    assert main(["runtime-diff", "--mono", str(mono), "--coreclr", str(other)]) == 2
    assert "share no scene" in capsys.readouterr().err


@pytest.mark.parametrize("op", sorted(OPERATIONS))
def test_switching_an_operation_to_mono_computes_mono_s_formula_and_restores_net10_after(op):
    before = {f: getattr(numerics.NET10, f) for f in OPERATIONS if f != "casts"}
    with mono_operation(op):
        if op == "casts":
            assert numerics.NET10.to_int32(float("nan")) == -2147483648  # mono's cvttsd2si answer
        else:
            assert getattr(numerics.NET10, op) is not before[op]
    assert {f: getattr(numerics.NET10, f) for f in before} == before
    assert numerics.NET10.to_int32(float("nan")) == 0 and numerics.Net10Quaternion.__mul__.__name__ == "__mul__"


def test_attribution_credits_the_operation_whose_mono_formula_gives_mono_s_answer(tmp_path):
    """The coreclr corpus holds the port's .NET 10 answers: where they differ from mono's, some
    switch (or several) must explain the difference, and the port reproduces each .NET 10 answer."""
    scenes = list(sample_scenes(("bsp",), 40, 21))
    mono, cc = _corpora(tmp_path, scenes, lambda s, o: run_scene(s, runtime="coreclr"))
    m, c = RecordedOracle(mono), RecordedOracle(cc)
    explained, several, port_wrong = attribute(m, c, pair(m, c))
    differing = sum(1 for key, _ in pair(m, c) if m._record(key).outcome != c._record(key).outcome)
    assert differing > 0, "seed 21 draws no bsp scene whose answer differs between the runtimes: pick another"
    assert not port_wrong
    assert sum(explained["transform_by_quaternion"].values()) + sum(several.values()) >= 1
