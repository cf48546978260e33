"""A target gone from the world and a RequestPos into no cell (issue 40; shard ticks-0073, strategies/world_exit.py):
scene/8 others[].motion_table (feature objects.motion_tables, pack 18), a move_to_object at a destroyed other
(objects.gone_targets) and a RequestPos whose cell LScape.get_landcell cannot find (ticks.no_cell_requests). The
fields, their refusals and pack bytes, and the port answering the shard's scenes of each arm as ACE did on both
runtimes (recorded: fast lane)."""

from __future__ import annotations

import gzip
import json
import struct
from dataclasses import replace
from pathlib import Path

import pytest

from acconform import dat
from acconform.compare import compare
from acconform.errors import InvalidScene
from acconform.motion_scene import MOTION_TABLE_ID
from acconform.oracle.pack import PACK_VERSION, pack_scene
from acconform.outcome import Outcome
from acconform.protocol import dat_from_json, dat_json, scene_features
from acconform.scene import MOTION_INPUTS, Scene, validate_scene

CORPUS = Path(__file__).resolve().parents[1] / "data" / "corpus"
ARMS = ("gone_chase", "no_cell", "table_exit", "unentered")


def _records(runtime: str, per_arm: int = 2) -> dict[str, list[tuple[Scene, Outcome]]]:
    """The first `per_arm` records of each arm in the runtime's ticks-0073."""
    got = {arm: [] for arm in ARMS}
    with gzip.open(CORPUS / runtime / "ticks-0073.jsonl.gz", "rt") as f:
        for line in f:
            doc = json.loads(line)
            arm = doc["scene"]["name"].split(":")[1]
            if len(got[arm]) < per_arm:
                got[arm].append((Scene.from_json(doc["scene"]), Outcome.from_json(doc["outcome"])))
            if all(len(v) == per_arm for v in got.values()):
                break
    return got


RECORDS = _records("mono")


def _scene(arm: str) -> Scene:
    return RECORDS[arm][0][0]


def test_a_request_pos_into_no_cell_reads_back_and_needs_ticks_no_cell_requests():
    scene = _scene("no_cell")
    cells = [s.request_pos.cell & 0xFFFF for s in scene.ticks.steps]
    assert any(c == 0 or 0x41 <= c <= 0xFF for c in cells)
    assert "ticks.no_cell_requests" in scene_features(scene) and Scene.from_json(scene.to_json()) == scene


def test_a_request_pos_into_no_cell_makes_no_update_that_tick():
    scene, outcome = RECORDS["no_cell"][0]
    at = next(i for i, s in enumerate(scene.ticks.steps) if s.request_pos.cell & 0xFFFF < 0x100
              and not 1 <= s.request_pos.cell & 0xFFFF <= 0x40)
    if at < len(outcome.ticks):
        assert outcome.ticks[at].updated is False


def test_a_request_pos_into_no_cell_of_a_landblock_the_scene_lacks_is_refused():
    scene = _scene("no_cell")
    steps = list(scene.ticks.steps)
    r = steps[0].request_pos
    steps[0] = replace(steps[0], request_pos=replace(r, cell=((r.cell >> 16) + 0x0100 & 0xFFFF) << 16 | 0x0041))
    with pytest.raises(InvalidScene, match=r"request_pos\.cell.*not defined in landblocks"):
        validate_scene(scene.replace(ticks=replace(scene.ticks, steps=tuple(steps))))


def test_a_move_to_object_or_turn_to_object_at_a_destroyed_other_needs_objects_gone_targets():
    scene = _scene("gone_chase")
    assert "objects.gone_targets" in scene_features(scene)
    gone = {o.id for s in scene.ticks.steps for o in s.others if o.destroy}
    kept = tuple(replace(s, move_to_object=None) if s.move_to_object is not None and s.move_to_object.object in gone
                 else s for s in scene.ticks.steps)
    assert "objects.gone_targets" not in scene_features(scene.replace(ticks=replace(scene.ticks, steps=kept)))
    # a TurnToObject at it is the same call with the same target (Monster_Navigation.StartTurn passes the destroyed
    # WorldObject's PhysicsObj to either), so it needs the feature too
    turned = tuple(replace(s, turn_to_object=s.move_to_object, move_to_object=None) if s.move_to_object is not None
                   and s.move_to_object.object in gone else s for s in scene.ticks.steps)
    assert "objects.gone_targets" in scene_features(scene.replace(ticks=replace(scene.ticks, steps=turned)))


def test_an_others_motion_table_reads_back_and_needs_objects_motion_tables():
    scene = _scene("table_exit")
    other = next(o for o in scene.others if o.motion_table)
    assert other.motion_table_id == MOTION_TABLE_ID and "objects.motion_tables" in scene_features(scene)
    assert Scene.from_json(scene.to_json()) == scene


def test_an_others_motion_table_needs_the_movers_table():
    scene = _scene("table_exit")
    # the steps' motion inputs need the mover's table too: leave them out, so the other's is the one refused
    steps = tuple(replace(s, **{n: None for n in MOTION_INPUTS}) for s in scene.ticks.steps)
    tableless = scene.replace(mover=replace(scene.mover, motion_table=None), ticks=replace(scene.ticks, steps=steps))
    with pytest.raises(InvalidScene, match=r"others\[0\]\.motion_table.*the mover has none"):
        validate_scene(tableless)


def test_an_others_motion_table_id_packs_after_its_report_collisions_byte():
    assert PACK_VERSION == 18
    scene = _scene("table_exit")
    with_table = pack_scene(scene)
    without = pack_scene(scene.replace(others=tuple(replace(o, motion_table=False) for o in scene.others)))
    assert len(with_table) == len(without)
    # the packs differ in one u32, the table id 0x09000000 (its first byte differing is its last, little-endian)
    at = next(i for i, (x, y) in enumerate(zip(with_table, without)) if x != y) - 3
    # the other's record ends: its ReportCollisions byte (0: unset), then its MotionTableId (0 without the table)
    assert with_table[at - 1:at + 4] == struct.pack("<BI", 0, MOTION_TABLE_ID)
    assert without[at - 1:at + 4] == struct.pack("<BI", 0, 0) and with_table[at + 4:] == without[at + 4:]


def test_an_others_motion_table_id_travels_in_the_dat_form():
    scene = _scene("table_exit")
    world = dat.dat_world(scene)
    assert any(o.motion_table_id == MOTION_TABLE_ID for o in world.others)
    assert dat_from_json(json.loads(json.dumps(dat_json(world)))) == world


@pytest.mark.parametrize("runtime", ["mono", "coreclr"])
@pytest.mark.parametrize("arm", ARMS)
def test_the_port_answers_the_shards_scenes_of_each_arm_as_ace_did(runtime, arm):
    from acconform.port.run import run_scene

    records = RECORDS if runtime == "mono" else _records(runtime)
    for scene, ace in records[arm]:
        assert compare(run_scene(scene, runtime=runtime), ace, "exact") == [], scene.name


def test_the_port_answers_an_other_with_a_motion_table_from_its_dat_records_as_ace_did():
    from acconform.port.run import run_scene

    scene, ace = RECORDS["table_exit"][0]
    assert compare(run_scene(scene, runtime="mono", world=dat.dat_world(scene)), ace, "exact") == []
