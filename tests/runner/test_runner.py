"""The runner: clean pairs pass, planted differences are found, shrunk, saved and replayable."""

from __future__ import annotations

import dataclasses
import warnings


from acconform.case import Case, load_document
from acconform.outcome import Outcome
from acconform.runner import run_campaign
from acconform.strategies import sample_scenes

warnings.simplefilter("ignore", RuntimeWarning)


def fake_port(scene):
    """A stand-in backend: a cheap deterministic function of the scene."""
    m = scene.mover
    end = m.end or m.begin  # a tick scene has no end
    return Outcome(ok=True, cell=end.cell, origin=end.frame.origin, walkable=bool(m.contact_plane),
                   object_info_state=m.transient_state)


def buggy_when_long(scene):
    """Wrong whenever the path leaves its start cell: a bug Hypothesis should shrink to a tiny scene."""
    o = fake_port(scene)
    if (scene.mover.end or scene.mover.begin).cell != scene.mover.begin.cell:
        return dataclasses.replace(o, walkable=not o.walkable)
    return o


def test_a_clean_pair_finds_no_difference(tmp_path):
    r = run_campaign(fake_port, fake_port, n=40, seed=1, failures_dir=tmp_path, database=None)
    assert r.ok and r.cases == 40 and not list(tmp_path.iterdir())


def test_a_campaign_times_its_drawing_beside_each_backend_and_a_replay_draws_nothing():
    r = run_campaign(fake_port, fake_port, n=20, seed=1, failures_dir=None, database=None)
    assert set(r.timings) == {"draw", "port", "oracle", "compare"} and r.timings["draw"] > 0
    replayed = run_campaign(fake_port, fake_port, replay=list(sample_scenes(None, 5, 1)), failures_dir=None)
    assert "draw" not in replayed.timings and replayed.timings["port"] > 0


def test_a_difference_is_found_shrunk_and_written_as_a_replayable_case(tmp_path):
    r = run_campaign(buggy_when_long, fake_port, n=300, seed=2, failures_dir=tmp_path, database=None)
    assert len(r.found) == 1
    f = r.found[0]
    assert f.shrunk and f.signature == ("walkable",)
    case = load_document(f.path)
    assert isinstance(case, Case)
    assert case.scene == f.case.scene and case.differences == ("walkable: port=True oracle=False",) or \
        case.differences == ("walkable: port=False oracle=True",)
    assert case.seed == "2" and case.mode == "exact" and case.versions.acconform
    # shrunk: a landblock and at most its 3x3 neighbourhood, at most one object, one sphere, a short hop
    # (a path across a border also carries the next landblock ahead, which ACE's cell search reaches)
    assert len(case.scene.landblocks) <= 9 and len(case.scene.objects) <= 1 and len(case.scene.mover.spheres) == 1


def test_keep_going_shrinks_each_new_kind_of_difference(tmp_path):
    def two_bugs(scene):
        o = buggy_when_long(scene)
        return dataclasses.replace(o, step_up=True) if len(scene.mover.spheres) == 2 else o

    r = run_campaign(two_bugs, fake_port, n=400, seed=3, failures_dir=tmp_path, database=None, keep_going=True)
    sigs = {f.signature for f in r.found}
    assert ("step_up",) in sigs and ("walkable",) in sigs


def test_the_same_seed_finds_the_same_shrunk_case(tmp_path):
    a = run_campaign(buggy_when_long, fake_port, n=300, seed=5, failures_dir=None, database=None)
    b = run_campaign(buggy_when_long, fake_port, n=300, seed=5, failures_dir=None, database=None)
    assert a.found[0].case.scene == b.found[0].case.scene and a.cases == b.cases


def test_worker_processes_split_the_campaign_and_stop_at_the_first_difference(tmp_path):
    r = run_campaign(fake_port, fake_port, n=60, seed=1, failures_dir=None, database=None, workers=2)
    assert r.ok and r.cases == 60
    r = run_campaign(buggy_when_long, fake_port, n=300, seed=2, failures_dir=tmp_path, database=None, workers=2)
    assert len(r.found) == 1 and r.found[0].path.exists()


def kept(db) -> list:
    """The failing scenes a default campaign (all kinds, exact) keeps in the directory database `db`."""
    from acconform.runner import SavedFailures, failure_key
    from acconform.strategies import check_kinds

    return SavedFailures(db, failure_key(check_kinds(None), "exact")).scenes()


def test_the_example_database_replays_a_saved_failure_first(tmp_path):
    db = tmp_path / "db"
    first = run_campaign(buggy_when_long, fake_port, n=300, seed=7, failures_dir=None, database=db)
    again = run_campaign(buggy_when_long, fake_port, n=300, seed=99, failures_dir=None, database=db)
    assert kept(db) == [first.found[0].case.scene] and again.found[0].case.scene == first.found[0].case.scene


def test_a_shards_failure_is_replayed_first_by_another_shard_sharing_its_hypothesis_database(tmp_path):
    from hypothesis.database import DirectoryBasedExampleDatabase

    from acconform.runner import example_database

    db = tmp_path / "shared"
    assert isinstance(example_database(db), DirectoryBasedExampleDatabase)
    first = run_campaign(buggy_when_long, fake_port, n=300, seed=7, failures_dir=tmp_path / "f1", database=db,
                         shard=(1, 2))
    seen = []

    def watched(scene):
        seen.append(scene)
        return buggy_when_long(scene)

    second = run_campaign(watched, fake_port, n=300, seed=7, failures_dir=tmp_path / "f2", database=db, shard=(2, 2))
    shrunk = first.found[0].case.scene
    assert seen[0] == shrunk, "the other shard's failing scene is the first one run"
    assert second.found[0].case.scene == shrunk and second.cases == 1
    # the shrunk case files users reproduce are still written, by each shard
    assert len(list((tmp_path / "f1").glob("case-*.json"))) == len(list((tmp_path / "f2").glob("case-*.json"))) == 1


def test_a_campaign_can_share_failures_through_a_github_artifact_read_only_beside_its_own_directory():
    from hypothesis.database import GitHubArtifactDatabase, MultiplexedDatabase, ReadOnlyDatabase

    from acconform.runner import DEFAULT_DATABASE, example_database

    db = example_database("github:someorg/someport/acconform-failures")
    assert isinstance(db, MultiplexedDatabase)
    local, shared = db._wrapped
    assert local.path == DEFAULT_DATABASE and isinstance(shared, ReadOnlyDatabase)
    assert shared._wrapped == GitHubArtifactDatabase("someorg", "someport", "acconform-failures")


def test_a_kept_failing_scene_that_passes_now_is_forgotten(tmp_path):
    db = tmp_path / "db"
    first = run_campaign(buggy_when_long, fake_port, n=300, seed=7, failures_dir=None, database=db)
    assert len(kept(db)) == 1
    fixed = run_campaign(fake_port, fake_port, n=20, seed=8, failures_dir=None, database=db)
    assert fixed.ok and first.found and not kept(db)


def test_an_unwritable_database_loses_no_difference(tmp_path, capsys):
    db = tmp_path / "db"
    db.write_text("a file where the directory should be")
    r = run_campaign(buggy_when_long, fake_port, n=300, seed=7, failures_dir=tmp_path / "f", database=db)
    assert len(r.found) == 1 and r.found[0].path.exists()
    assert "cannot keep the failing scene" in capsys.readouterr().err


def test_replay_compares_recorded_scenes_without_shrinking(tmp_path):
    scenes = list(sample_scenes(None, 10, 1))
    r = run_campaign(buggy_when_long, fake_port, replay=scenes, failures_dir=tmp_path, keep_going=True)
    assert r.source == "replay" and r.cases == 10
    assert all(not f.shrunk for f in r.found)
    assert len(r.found) == sum((s.mover.end or s.mover.begin).cell != s.mover.begin.cell for s in scenes)


def test_a_backend_that_raises_gives_an_error_outcome_not_a_crash(tmp_path):
    def crashes(scene):
        raise ZeroDivisionError("boom")

    r = run_campaign(crashes, fake_port, n=20, seed=1, failures_dir=None, database=None)
    assert "error" in r.found[0].signature and r.found[0].case.port.error == "ZeroDivisionError: boom"


def test_a_progress_bar_goes_to_stderr(capsys):
    run_campaign(fake_port, fake_port, n=30, seed=1, failures_dir=None, database=None, progress=True)
    err = capsys.readouterr().err
    assert "30/30 cases" in err and "0 differences" in err


def test_a_difference_hypothesis_cannot_replay_is_written_as_drawn_and_says_so(tmp_path):
    # the campaign draws outside Hypothesis and hands a difference over as its choices; a backend
    # that differs once only (state, not the scene) fails the draw but not Hypothesis' replay
    calls = {"n": 0}

    def once(scene):
        calls["n"] += 1
        o = fake_port(scene)
        return dataclasses.replace(o, walkable=not o.walkable) if calls["n"] == 3 else o

    r = run_campaign(once, fake_port, n=20, seed=1, failures_dir=tmp_path, database=None)
    assert len(r.found) == 1 and r.found[0].signature == ("walkable",)
    shrink = r.found[0].case.shrink
    assert shrink.against == "none" and "did not differ" in shrink.note
    assert shrink.bytes_before == shrink.bytes_after > 0 and load_document(r.found[0].path).scene == r.found[0].case.scene


def test_the_second_half_of_a_round_climbs_toward_the_closest_boundary(monkeypatch):
    # past TARGET_AFTER of the budget about half the scenes are the closest scene yet with one choice moved
    from acconform import runner

    nudges = []
    real = runner._nudged

    class Traced:
        trace_boundaries = False
        last_trace = None
        runs = 0

        def __call__(self, scene):
            self.runs += 1
            self.last_trace = type("T", (), {"closest": {"b": abs(scene.mover.begin.frame.origin[0] - 96.0)}})()
            return fake_port(scene)

    port = Traced()
    monkeypatch.setattr(runner, "_nudged", lambda *a: nudges.append(port.runs) or real(*a))
    r = runner.run_campaign(port, fake_port, n=200, seed=4, failures_dir=None, database=None)
    assert r.ok and r.cases == 200
    assert min(nudges) >= 100 and 30 <= len(nudges) <= 70


def test_an_implementation_that_takes_scenes_ahead_is_sent_the_next_scene_before_the_current_one_runs():
    # a process works on the next scene while the harness draws and compares (acconform.protocol
    # Implementation.prefetch); the scenes compared are those a port without it is given
    events = []

    class Ahead:
        def prefetch(self, scene):
            events.append(("sent", scene))

        def __call__(self, scene):
            events.append(("ran", scene))
            return fake_port(scene)

    plain = []
    run_campaign(lambda s: plain.append(s) or fake_port(s), fake_port, n=30, seed=5, failures_dir=None, database=None)
    r = run_campaign(Ahead(), fake_port, n=30, seed=5, failures_dir=None, database=None)
    ran = [s for what, s in events if what == "ran"]
    sent = [s for what, s in events if what == "sent"]
    assert r.ok and r.cases == 30 and ran == plain and sent == plain  # each scene sent once, none beyond the budget
    for i in range(len(ran) - 1):  # scene i + 1 went out before scene i ran
        assert events.index(("sent", ran[i + 1])) < events.index(("ran", ran[i]))
