"""The recorded oracle and the committed corpus: replay, round trip, and loud failure when absent."""

import gzip
import json

import pytest

from acconform.case import Record, Versions
from acconform.outcome import Outcome
from acconform.numerics import RUNTIMES, runtime_named
from acconform.oracle import CORPUS_ROOT, DEFAULT_RUNTIME, default_corpus, get_oracle
from acconform.oracle.recorded import CorpusMissing, CorpusWriter, RecordedOracle, UnrecordedScene, scene_key, shards

from .scenes import PROBE, off_the_map

MIN_CORPUS = 10_000


@pytest.mark.parametrize("runtime", sorted(RUNTIMES))
def test_committed_corpus_of_each_runtime_exists_and_is_large(runtime):
    """Fails (never skips) when a corpus is missing or small: CI's differential lane depends on it."""
    oracle = RecordedOracle(default_corpus(runtime))
    assert len(oracle) >= MIN_CORPUS, f"{default_corpus(runtime)} holds {len(oracle)} records, fewer than {MIN_CORPUS}"


def test_the_corpus_root_holds_one_corpus_per_runtime_and_the_default_is_coreclr():
    assert sorted(p.name for p in CORPUS_ROOT.iterdir() if p.is_dir()) == sorted(RUNTIMES)
    assert DEFAULT_RUNTIME == "coreclr" and default_corpus() == CORPUS_ROOT / "coreclr"


def test_the_coreclr_corpus_records_the_same_scenes_as_the_mono_corpus():
    """The two corpora pair up by scene key (the runtime difference table compares them)."""
    mono, coreclr = RecordedOracle(default_corpus("mono")), RecordedOracle(default_corpus("coreclr"))
    assert set(coreclr.index()) >= set(mono.index())


@pytest.mark.parametrize("runtime", sorted(RUNTIMES))
def test_committed_corpus_spans_every_scene_kind(runtime):
    kinds = {p.name.split("-")[0] for p in shards(default_corpus(runtime))}
    assert {"terrain", "bsp", "obstacles"} <= kinds


@pytest.mark.parametrize("runtime", sorted(RUNTIMES))
def test_committed_corpus_replays_its_own_scenes_and_names_its_ace_and_runtime(runtime):
    oracle = RecordedOracle(default_corpus(runtime))
    assert oracle.versions.ace and runtime_named(oracle.versions.runtime) == runtime
    seen = 0
    for entry in oracle.entries[::97]:  # (parsing only the records it replays)
        rec = oracle._record(entry)
        assert oracle.run(rec.scene) == rec.outcome
        seen += 1
    assert seen > 50


def test_record_then_replay_round_trips(tmp_path, isolated_config):
    outcome = Outcome(ok=True, cell=0xA9B40001, origin=(12.5, 12.0, 20.0))
    v = Versions("0.1.0", "test-ace", "mono 6.8")
    with CorpusWriter(tmp_path, shard_size=2) as w:
        for s in list(PROBE.values()) + [off_the_map()]:
            w.add(Record(s, outcome if s.name != off_the_map().name else Outcome(error="NullReferenceException: x"), v))
    assert len(shards(tmp_path)) == 3  # 5 terrain records, 2 per shard
    oracle = get_oracle(corpus=tmp_path)
    assert len(oracle) == 5 and oracle.versions == v
    assert oracle.run(PROBE["ramp walk uphill"]) == outcome
    assert oracle.run(off_the_map()).error.startswith("NullReferenceException")
    assert {s.name for s in oracle.scenes()} >= {off_the_map().name}


def _written(corpus, scenes):
    with CorpusWriter(corpus, shard_size=2) as w:
        for s in scenes:
            w.add(Record(s, Outcome(ok=True, cell=0xA9B40001)))


def test_the_key_index_is_kept_per_shard_and_read_back_the_same(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    _written(tmp_path / "c", list(PROBE.values()))
    fresh = RecordedOracle(tmp_path / "c").index()
    kept = sorted((tmp_path / "cache" / "acconform").glob("corpus-keys-*/*.json"))
    assert len(kept) == len(shards(tmp_path / "c")) >= 2
    assert sorted(k for f in kept for k in json.loads(f.read_text())) == sorted(fresh)
    again = RecordedOracle(tmp_path / "c")
    assert {k: e.where for k, e in again.index().items()} == {k: e.where for k, e in fresh.items()}
    assert all(again.run(s) == Outcome(ok=True, cell=0xA9B40001) for s in PROBE.values())


def test_a_shard_whose_bytes_changed_is_keyed_afresh_and_a_kept_list_of_the_wrong_length_is_ignored(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    scenes = list(PROBE.values())
    _written(tmp_path / "c", scenes[:2])
    RecordedOracle(tmp_path / "c").index()
    for f in (tmp_path / "cache" / "acconform").glob("corpus-keys-*/*.json"):
        f.write_text(json.dumps(["0" * 64]))  # one key for a shard of two records
    assert set(RecordedOracle(tmp_path / "c").index()) == {scene_key(s) for s in scenes[:2]}
    shard = shards(tmp_path / "c")[0]
    with gzip.open(shard, "wt") as f:  # the same shard name, another scene in it
        f.write(json.dumps({"format": "acconform.record/1", "scene": scenes[2].to_json(),
                            "outcome": Outcome(ok=True).to_json()}) + "\n")
    assert set(RecordedOracle(tmp_path / "c").index()) == {scene_key(scenes[2])}


def test_an_unwritable_cache_costs_only_the_keying(tmp_path, monkeypatch):
    (tmp_path / "cache").write_text("a file where the cache directory would be")
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    _written(tmp_path / "c", list(PROBE.values()))
    assert set(RecordedOracle(tmp_path / "c").index()) == {scene_key(s) for s in PROBE.values()}


def test_a_scene_is_found_whatever_its_name(tmp_path):
    s = PROBE["flat 1-step walk"]
    with CorpusWriter(tmp_path) as w:
        w.add(Record(s, Outcome(ok=True)))
    assert RecordedOracle(tmp_path).run(s.replace(name="renamed")).ok
    assert scene_key(s) == scene_key(s.replace(name="other"))


def test_a_handed_out_scene_asked_for_as_an_equal_copy_gets_its_own_answer(tmp_path):
    """Scenes handed out by `scenes()` are keyed only when `run` meets one it did not hand out
    (an equal copy, or one asked for late): the copy still gets its record's answer."""
    keys = [scene_key(s) for s in PROBE.values()]
    with CorpusWriter(tmp_path) as w:
        for i, s in enumerate(PROBE.values()):
            w.add(Record(s, Outcome(ok=True, cell=0xA9B40001 + i)))
    oracle = RecordedOracle(tmp_path)
    handed = list(oracle.scenes())
    assert len(handed) == len(keys) > 2
    assert oracle.run(handed[0]).cell == 0xA9B40001 + keys.index(scene_key(handed[0]))  # as handed out
    for scene in handed[1:]:
        copy = type(scene).from_json(scene.to_json())
        assert copy is not scene and oracle.run(copy).cell == 0xA9B40001 + keys.index(scene_key(scene))


def test_an_unrecorded_scene_raises_a_clear_error(tmp_path):
    with CorpusWriter(tmp_path) as w:
        w.add(Record(PROBE["flat 1-step walk"], Outcome(ok=True)))
    with pytest.raises(UnrecordedScene, match="no answer for scene 'into an unregistered landblock'.*acconform record"):
        RecordedOracle(tmp_path).run(off_the_map())


def test_a_missing_or_empty_corpus_fails_loudly(tmp_path):
    with pytest.raises(CorpusMissing, match="no recorded-oracle corpus"):
        RecordedOracle(tmp_path / "absent")
    with pytest.raises(CorpusMissing, match="holds no records"):
        RecordedOracle(tmp_path)


def test_shards_are_gzip_json_lines_of_records(tmp_path):
    with CorpusWriter(tmp_path) as w:
        w.add(Record(PROBE["flat 1-step walk"], Outcome(ok=True)))
    (shard,) = shards(tmp_path)
    assert shard.name == "terrain-0000.jsonl.gz"
    with gzip.open(shard, "rt") as f:
        doc = json.loads(f.readline())
    assert doc["format"] == "acconform.record/1"


@pytest.mark.live_oracle
def test_live_record_command_then_recorded_oracle_replays_the_same_outcomes(live, tmp_path):
    from acconform.cli import main

    files = []
    for i, s in enumerate(list(PROBE.values()) + [off_the_map()]):
        p = tmp_path / f"s{i}.json"
        p.write_text(s.dumps())
        files.append(str(p))
    assert main(["record", "-q", "--out", str(tmp_path / "corpus"), *files]) == 0
    rec = RecordedOracle(tmp_path / "corpus")
    for s in list(PROBE.values()) + [off_the_map()]:
        assert rec.run(s) == live.run(s)
    assert main(["record", "-q", "--out", str(tmp_path / "corpus"), *files]) == 0  # all skipped
    assert len(RecordedOracle(tmp_path / "corpus")) == 5


def _small_corpus(tmp_path, n_shards=2, per_shard=7):
    """A corpus of real records (the first of a committed shard's), a blank line after each."""
    src = [line for line in gzip.decompress(shards(default_corpus())[0].read_bytes()).decode().splitlines() if line]
    corpus = tmp_path / "c"
    corpus.mkdir()
    lines = iter(src)
    for k in range(n_shards):
        text = "\n\n".join(next(lines) for _ in range(per_shard)) + "\n"
        (corpus / f"terrain-{k:04d}.jsonl.gz").write_bytes(gzip.compress(text.encode()))
    return corpus


def test_a_loaded_corpus_reads_each_records_line_from_its_shard_in_any_order(tmp_path):
    from acconform.case import jsonl_lines

    corpus = _small_corpus(tmp_path)
    want = [line for s in shards(corpus) for _, line in jsonl_lines(s)]
    oracle = RecordedOracle(corpus)
    entries = oracle.entries
    assert [e.line for e in entries] == want  # in order: one pass through each shard
    assert [e.lineno for e in entries[:3]] == [1, 3, 5] and entries[1].where.endswith("terrain-0000.jsonl.gz line 3")
    order = [5, 0, 13, 2, 2, 9, 1, 0, 6, 12, 3]  # backwards: the pass starts again, then the shard is kept whole
    assert [entries[i].line for i in order] == [want[i] for i in order]


def test_a_forked_process_reads_records_without_moving_its_parents_place_in_a_shard(tmp_path):
    import os

    corpus = _small_corpus(tmp_path, n_shards=1, per_shard=300)  # more than the gzip reader's buffers hold
    oracle = RecordedOracle(corpus)
    e = oracle.entries
    assert e[0].line  # the parent's pass is open, at line 1
    r, w = os.pipe()
    pid = os.fork()
    if pid == 0:  # the child reads the rest of the shard through the inherited objects
        ok = all(x.line.startswith('{"format"') for x in e[1:])
        os.write(w, b"1" if ok else b"0")
        os._exit(0)
    os.waitpid(pid, 0)
    assert os.read(r, 1) == b"1"
    assert [x.doc()["scene"] for x in e[1:]] == [json.loads(x.line)["scene"] for x in RecordedOracle(corpus).entries[1:]]


def test_a_shard_cut_short_after_loading_names_the_record_it_no_longer_holds(tmp_path):
    from acconform.oracle.recorded import CorpusCorrupt

    corpus = _small_corpus(tmp_path, n_shards=1)
    oracle = RecordedOracle(corpus)
    shard = shards(corpus)[0]
    first = gzip.decompress(shard.read_bytes()).decode().split("\n", 1)[0] + "\n"
    shard.write_bytes(gzip.compress(first.encode()))
    assert oracle.entries[0].line == first
    with pytest.raises(CorpusCorrupt, match=r"terrain-0000\.jsonl\.gz line 13: no longer there"):
        oracle.entries[-1].line


def test_a_shard_truncated_after_loading_is_read_to_the_cut_once_and_each_later_record_named_unreadable(tmp_path, capsys,
                                                                                                        monkeypatch):
    import acconform.oracle.recorded as recorded
    from acconform.cli import main
    from acconform.oracle.recorded import CorpusCorrupt

    corpus = _small_corpus(tmp_path, n_shards=2, per_shard=40)
    shard = shards(corpus)[0]
    whole = shard.read_bytes()
    loaded = recorded.RecordedOracle

    def cut_after_loading(*a, **k):
        oracle = loaded(*a, **k)
        shard.write_bytes(whole[:len(whole) // 2])
        return oracle

    monkeypatch.setattr(recorded, "RecordedOracle", cut_after_loading)  # check loads the corpus, then it is cut
    assert main(["check", "--corpus", str(corpus), "-j", "1", "--no-progress", "--keep-going"]) == 0
    out, err = capsys.readouterr()
    replayed = int(out.split(" cases in ", 1)[0].rsplit("\n", 1)[-1])
    skipped = int(out.split("skipped ", 1)[1].split(" unreadable", 1)[0])
    assert replayed + skipped == 80 and 0 < skipped < 40 and "truncated after line" in out and "Traceback" not in err

    shard.write_bytes(whole)
    e = RecordedOracle(corpus).entries
    shard.write_bytes(whole[:len(whole) // 2])
    lines = e[0].shard
    for entry in (e[38], e[39]):  # the shard's last two records: past the cut
        with pytest.raises(CorpusCorrupt, match="truncated after line"):
            entry.line
    assert lines._passes == 1  # the cut is found once, not by a pass per record after it


def test_a_sample_replayed_by_the_built_in_port_reads_each_scene_once(tmp_path, capsys, monkeypatch):
    """`check -n` weighs its sample scene by scene only for an implementation that may pass one over;
    the built-in port runs every scene, so each sampled scene is parsed once, when it is replayed."""
    from acconform.cli import main
    from acconform.scene import Scene

    corpus = _small_corpus(tmp_path, n_shards=2, per_shard=10)
    parsed = []
    from_json = Scene.from_json
    monkeypatch.setattr(Scene, "from_json", staticmethod(lambda doc, path="": parsed.append(1) or from_json(doc, path)))
    assert main(["check", "--corpus", str(corpus), "-n", "6", "-j", "1", "--no-progress"]) == 0
    assert "6 cases in" in capsys.readouterr().out and len(parsed) == 6


def test_a_selection_passing_over_unsupported_scenes_takes_what_the_seeded_order_takes():
    """select reads the records it weighs in corpus order (one pass per shard), and takes or passes
    them over in the seeded order: the same records as weighing them one by one in that order."""
    import random
    from collections import Counter

    oracle = RecordedOracle(default_corpus())

    def unsupported(scene):
        return "odd" if len(scene.objects) % 2 else None

    for n, seed in ((12, 0), (40, 3)):
        skipped = Counter()
        got = oracle.select(n=n, seed=seed, unsupported=unsupported, skipped=skipped)
        # the reference: every kind's records weighed one at a time in the seeded order
        entries = oracle.entries
        by_kind = {}
        for i, e in enumerate(entries):
            by_kind.setdefault(e.kind, []).append(i)
        take = Counter(e.kind for e in got)
        rng = random.Random(seed)
        want, passed = set(), Counter()
        for kind in sorted(by_kind):
            taken = 0
            for i in rng.sample(by_kind[kind], len(by_kind[kind])):
                if taken == take[kind]:
                    break
                why = unsupported(oracle._hand_out(entries[i], keep=False))
                if why:
                    passed[why] += 1
                    continue
                want.add(i)
                taken += 1
        assert [e.where for e in got] == [entries[i].where for i in sorted(want)]
        assert skipped == passed and sum(take.values()) == n and skipped["odd"] > 0


def _tick_policy_corpus(corpus):
    """A corpus of tick scenes drawn as live campaigns of motion, movers, missiles and targets draw them
    (filed as "ticks", as `record` files them), and two terrain scenes."""
    from strategies import sample_scenes

    from .manager_scenes import scenes as manager_scenes

    drawn = {kind: list(sample_scenes((kind,), 11 if kind == "motion" else 3, 11))
             for kind in ("motion", "movers", "missiles", "targets")}
    drawn["motion"] += [manager_scenes()[name] for name in ("sticky_move_to_a_static", "turn_to_a_static")]  # aimed at a static
    _written(corpus, [s for ss in drawn.values() for s in ss] + list(PROBE.values())[:2])
    return drawn


def test_a_tick_policy_kind_replays_the_tick_records_whose_scene_needs_its_feature(tmp_path):
    """`check --kinds motion` without ACE: the corpus files motion scenes as "ticks"; the kind selects the
    tick records whose scene needs mover.motion (missiles: a projectile, targets: objects.targets, ...),
    those a live campaign of the kind draws among them, sampled or whole."""
    from acconform.protocol import of_kind

    drawn = _tick_policy_corpus(tmp_path / "c")
    oracle = RecordedOracle(tmp_path / "c")
    assert {e.kind for e in oracle.entries} == {"ticks", "terrain"}
    for kind, scenes in drawn.items():
        want = {s.name for s in oracle.scenes(oracle.select(kinds={"ticks"})) if of_kind(s, kind)}
        assert {s.name for s in scenes} <= want  # what a live campaign of the kind draws is of the kind
        assert {s.name for s in oracle.scenes(oracle.select(kinds={kind}))} == want
        assert {s.name for s in oracle.scenes(oracle.select(n=2, seed=1, kinds={kind}))} < want
        assert {s.name for s in oracle.scenes(oracle.select(n=100, seed=1, kinds={kind}))} == want
    # a MoveToObject or TurnToObject at a static is no target: its text names the input, its scene is parsed to tell
    aimed = [s for s in drawn["motion"] if any(t.move_to_object or t.turn_to_object for t in s.ticks.steps)]
    assert aimed and not any(of_kind(s, "targets") for s in aimed)
    assert not oracle.select(kinds={"doors"})
    # named together, each record is counted once; the kinds that need more features take theirs first
    both = oracle.select(kinds={"motion", "targets"})
    assert len(both) == len(set(both)) and len(oracle.select(n=4, seed=0, kinds={"motion", "targets"})) == 4


def test_check_of_a_tick_policy_kind_the_corpus_lacks_says_so_in_one_line(tmp_path, capsys, no_ace):
    from acconform.cli import main

    _tick_policy_corpus(tmp_path / "c")
    assert main(["check", "--corpus", str(tmp_path / "c"), "--kinds", "doors", "-n", "5", "--no-progress"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "holds no scenes of kinds doors" in err[0], err
