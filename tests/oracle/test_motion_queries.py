"""scene/8 motion_queries (feature motion.queries): the server's questions to the mover's motion table, asked after the
last tick, answered per scene as a fresh server answers them (ACE's static RunSpeed, TurnSpeed and attack-frame caches
cleared before each scene; the port's live in the scene's PortalDat)."""

import gzip
import json
from dataclasses import replace
from pathlib import Path

import pytest

from acconform.compare import compare
from acconform.outcome import Outcome
from acconform.port.run import run_scene
from acconform.scene import MotionQuery, Scene

SHARD = Path(__file__).parents[1] / "data" / "corpus" / "{runtime}" / "ticks-0069.jsonl.gz"


def _records(runtime="mono"):
    with gzip.open(str(SHARD).format(runtime=runtime), "rt") as f:
        return [(Scene.from_json(d["scene"]), Outcome.from_json(d["outcome"])) for d in map(json.loads, f)]


def _two_run_speeds(runtime="mono"):
    """Two recorded scenes whose tables run at different speeds, each asking only GetRunSpeed, twice."""
    seen = {}
    for scene, outcome in _records(runtime):
        for q, a in zip(scene.motion_queries, outcome.motion_answers):
            if q.function == "GetRunSpeed" and a.value and a.value not in seen:
                seen[a.value] = replace(scene, motion_queries=(MotionQuery("GetRunSpeed"),) * 2)
            if len(seen) == 2:
                return list(seen.items())
    raise AssertionError("the shard has no two tables of different run speeds")


def test_each_scene_asks_its_own_table_the_run_speed_even_after_another_scene_asked():
    (speed_a, a), (speed_b, b) = _two_run_speeds()
    for scene, speed in ((a, speed_a), (b, speed_b), (a, speed_a)):
        answers = run_scene(scene).motion_answers
        assert [x.value for x in answers] == [speed, speed]  # the second from the cache, the first's answer


def test_get_attack_frames_finds_an_attack_hook_at_its_frame_over_the_links_frame_count():
    for scene, outcome in _records():
        for q, a in zip(scene.motion_queries, outcome.motion_answers):
            if q.function == "GetAttackFrames" and a.attack_frames:
                frame = a.attack_frames[0]
                assert 0.0 <= frame.time < 1.0 and frame.part_index == 0 and frame.radius == 2.0
                assert compare(run_scene(scene), outcome) == []
                return
    raise AssertionError("no recorded GetAttackFrames found an attack hook")


def test_a_query_of_a_function_the_server_never_calls_is_refused_naming_it():
    from acconform.errors import InvalidScene

    scene, _ = _records()[0]
    doc = scene.to_json()
    doc["motion_queries"] = [{"function": "GetCycleLength", "stance": 0, "motion": 0}]
    with pytest.raises(InvalidScene, match=r"motion_queries\[0\]\.function: unknown motion query 'GetCycleLength'"):
        Scene.from_json(doc)
    doc["motion_queries"] = [{"function": "GetRunSpeed", "speed": 1.0}]
    with pytest.raises(InvalidScene, match="GetRunSpeed takes no speed"):
        Scene.from_json(doc)


@pytest.mark.live_oracle
def test_live_ace_answers_each_scenes_run_speed_from_its_own_table_in_one_batch(live):
    """ACE's RunSpeed cache is static and keyed by the motion table id every scene's mover shares: without the
    facade's clearing it before each scene, b would get a's run speed."""
    (speed_a, a), (speed_b, b) = _two_run_speeds(live.location.runtime)
    outcomes = [o for o, _ in live.run_many([a, b, a])]
    assert [[x.value for x in o.motion_answers] for o in outcomes] == [[speed_a] * 2, [speed_b] * 2, [speed_a] * 2]
    for scene, ace in zip((a, b, a), outcomes):
        assert compare(run_scene(scene, runtime=live.location.runtime), ace) == []
