"""Children (issue 41; scene/8 `others[].parent`, the holders' `holding_locations`, `others[].sorting_sphere`;
feature objects.children). The scene fields and their refusals, the pack bytes and the DAT form (fast lane); each
named scene of tests/oracle/child_scenes.py answered by the port as ACE answered it on both runtimes, every tick
(recorded: fast lane), and by live ACE again (live lane)."""

from __future__ import annotations

import json
import struct
import sys
from pathlib import Path

import numpy as np
import pytest

from acconform import dat
from acconform.compare import compare
from acconform.errors import InvalidScene
from acconform.flags import ParentLocation, SetPositionError
from acconform.oracle.pack import PACK_VERSION, pack_scene
from acconform.protocol import dat_from_json, dat_json, scene_features
from acconform.scene import FORMAT, FORMAT_V7, Scene
from acconform.staging import MOVER_ID

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from oracle.child_scenes import DATA, RIGHT_HAND, SWORD, scenes  # noqa: E402
from oracle.live_answers import recorded_outcomes  # noqa: E402
from oracle.mover_scenes import MONSTER, scenes as mover_scenes  # noqa: E402

SCENES = scenes()
WALK = "player_walks_carrying_a_child"
F = np.float32


def _doc(name: str = WALK) -> dict:
    return json.loads(SCENES[name].dumps())


@pytest.mark.parametrize("name", sorted(SCENES))
def test_each_child_scene_reads_back_as_the_same_scene_in_format_8_and_needs_objects_children(name):
    scene = SCENES[name]
    assert Scene.loads(scene.dumps()) == scene
    assert scene.format == FORMAT and {"objects.moving", "objects.children"} <= set(scene_features(scene))


def test_a_scene_of_movers_without_a_parent_does_not_need_objects_children():
    assert all("objects.children" not in scene_features(s) for s in mover_scenes().values())


def test_a_child_is_written_with_its_parent_and_no_begin_and_a_location_by_its_name():
    doc = _doc()
    sword = doc["others"][0]
    assert "begin" not in sword and sword["parent"] == {"id": "0x50000001", "location": "RightHand", "placement": 0}
    assert doc["mover"]["holding_locations"][0]["location"] == "RightHand" and doc["mover"]["holding_locations"][0]["part"] == 1
    assert sword["sorting_sphere"]["radius"] == 0.6


def test_a_location_may_be_a_number_and_a_location_ace_has_no_name_for_is_kept():
    doc = _doc()
    doc["others"][0]["parent"]["location"] = 1
    doc["mover"]["holding_locations"][0]["location"] = 40
    scene = Scene.from_json(doc)
    assert scene.others[0].parent.location == int(ParentLocation.RightHand) and scene.mover.holding_locations[0].location == 40
    assert Scene.loads(scene.dumps()) == scene


def _parent_comes_later(doc: dict) -> None:
    """A standing GenericObject after the sword, named as the sword's parent."""
    later = {k: v for k, v in doc["others"][0].items() if k != "parent"}
    later.update(id="0x80000011", begin={"cell": "0xA9B40013", "origin": [61, 61, 20]})
    doc["others"].append(later)
    doc["others"][0]["parent"]["id"] = "0x80000011"


@pytest.mark.parametrize("edit, where, problem", [
    (lambda d: d["others"][0]["parent"].__setitem__("id", "0x80000009"), r"others\[0\]\.parent\.id",
     "no mover before it has id 0x80000009"),
    (lambda d: d["others"][0]["parent"].__setitem__("id", "0x80000010"), r"others\[0\]\.parent\.id",
     "no mover before it has id 0x80000010"),
    # a parent that comes later: the child is parented when it is made, in `others` order
    (_parent_comes_later, r"others\[0\]\.parent\.id", "an earlier other"),
    (lambda d: d["others"][0].__setitem__("begin", {"cell": "0xA9B40013", "origin": [61, 61, 20]}),
     r"others\[0\]\.begin", "omit begin"),
    (lambda d: d["others"][0].pop("parent"), r"others\[0\]\.begin", "missing required field"),
    (lambda d: d["others"][0]["parent"].__setitem__("location", "Hand"), r"others\[0\]\.parent\.location",
     "unknown ParentLocation 'Hand'"),
    (lambda d: d["others"][0]["parent"].__setitem__("placement", "Default"), r"others\[0\]\.parent\.placement",
     "expected an integer"),
    (lambda d: d["mover"]["holding_locations"].append(dict(d["mover"]["holding_locations"][0])),
     r"mover\.holding_locations\[1\]\.location", "given twice"),
    (lambda d: d["mover"]["holding_locations"][0].__setitem__("part", 2 ** 31), r"mover\.holding_locations\[0\]\.part",
     "expected an integer in"),
    (lambda d: d["mover"]["holding_locations"][0].pop("frame"), r"mover\.holding_locations\[0\]\.frame",
     "missing required field"),
    (lambda d: d["others"][0]["sorting_sphere"].__setitem__("radius", -1), r"others\[0\]\.sorting_sphere\.radius",
     "radius of 0 or more"),
])
def test_a_bad_child_field_is_refused_naming_the_field(edit, where, problem):
    doc = _doc()
    edit(doc)
    with pytest.raises(InvalidScene, match=where + ".*" + problem):
        Scene.from_json(doc)


def test_holding_locations_need_format_8():
    doc = _doc()
    doc["format"] = FORMAT_V7
    doc.pop("others")
    for step in doc["ticks"]["steps"]:
        step.pop("others", None)
    with pytest.raises(InvalidScene, match=r"mover\.holding_locations.*needs format 'acconform.scene/8'"):
        Scene.from_json(doc)


def test_a_mover_with_holding_locations_and_no_others_is_format_8():
    scene = SCENES[WALK]
    alone = scene.replace(others=())
    assert alone.format == FORMAT and Scene.loads(alone.dumps()) == alone


def test_a_child_at_a_location_its_parents_setup_lacks_is_a_scene_ace_answers():
    scene = SCENES["child_at_a_location_its_parent_lacks"]
    assert scene.others[0].parent.location not in {h.location for h in scene.mover.holding_locations}
    placed = recorded_outcomes(DATA, "mono")["child_at_a_location_its_parent_lacks"].other_placements[0]
    assert placed.result == SetPositionError.GeneralFailure and placed.cur_cell == 0


def test_a_childs_parent_packs_at_the_end_of_its_record_and_the_holding_locations_in_the_setups():
    assert PACK_VERSION == 18
    scene = SCENES["monster_walks_carrying_a_child"]
    data = pack_scene(scene)
    child_tail = struct.pack("<3f", 0.0, 0.0, 0.0) + struct.pack("<I3f4f", 0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0) \
        + struct.pack("<BIii", 1, MONSTER, int(ParentLocation.RightHand), 0)
    assert child_tail in data
    monster_tail = struct.pack("<BIii", 0, 0, 0, 0)
    assert data.count(monster_tail) >= 1
    # the monster's Setup: one holding location, RightHand at part 1 and its frame
    h = RIGHT_HAND
    location = struct.pack("<iii", 1, h.location, h.part) + struct.pack("<3f4f", *h.frame.origin, *h.frame.orientation)
    written = dat.scene_records(scene)
    assert location in written.others[0].records[0].data and location in data
    # the sword's Setup: its sorting sphere after the step heights
    sword = scene.others[1]
    assert struct.pack("<4f", *sword.sorting_sphere.center, sword.sorting_sphere.radius) in written.others[1].records[0].data


def test_a_setup_without_holding_locations_or_sorting_sphere_keeps_its_bytes():
    plain = mover_scenes()["collide_with_a_moving_object"]
    rec = dat.scene_records(plain).others[0].records[0].data
    assert struct.pack("<i", 0) + struct.pack("<i", 0) + struct.pack("<i", 0) in rec  # no holding locations, points, frames
    assert dat.other_records(plain.others[0], 0).records[0].data == rec


def test_the_dat_form_carries_a_childs_parent_and_no_begin_and_reads_back():
    world = dat.dat_world(SCENES["monster_walks_carrying_a_child"])
    doc = json.loads(json.dumps(dat_json(world)))
    assert "begin" not in doc["others"][1] and doc["others"][1]["parent"]["id"] == "0x80000001"
    assert dat_from_json(doc) == world


@pytest.mark.parametrize("runtime", ["mono", "coreclr"])
def test_the_port_answers_each_child_scene_as_ace_did_every_tick(runtime):
    from acconform.port.run import run_scene

    ace = recorded_outcomes(DATA, runtime)
    assert set(ace) == set(SCENES)
    for name, scene in SCENES.items():
        assert compare(run_scene(scene, runtime=runtime), ace[name], "exact") == [], name


def test_the_port_answers_a_child_scene_from_its_dat_records_as_ace_did():
    from acconform.port.run import run_scene

    scene = SCENES["monster_walks_carrying_a_child"]
    ace = recorded_outcomes(DATA, "mono")["monster_walks_carrying_a_child"]
    assert compare(run_scene(scene, runtime="mono", world=dat.dat_world(scene)), ace, "exact") == []


def test_ace_holds_the_child_at_the_carriers_position_combined_with_the_hands_frame_every_tick():
    """The carrier never turns: the sword's origin is the carrier's plus the hand's offset (float32 sums) and its
    orientation the hand's, every tick; it is never stepped (updated false) and never in a CollisionTable."""
    outcome = recorded_outcomes(DATA, "mono")[WALK]
    for tick in outcome.ticks:
        sword = tick.others[0]
        assert sword.id == SWORD and not sword.updated and sword.collisions == ()
        assert sword.origin == tuple(float(F(a) + F(b)) for a, b in zip(tick.origin, RIGHT_HAND.frame.origin))
        assert sword.orientation == tuple(float(F(c)) for c in RIGHT_HAND.frame.orientation) and sword.cell == tick.cell
    assert outcome.ticks[-1].origin[1] > outcome.ticks[0].origin[1] + 2.0


def test_ace_takes_the_child_across_the_cell_border_with_its_carrier_and_shadows_both_cells():
    outcome = recorded_outcomes(DATA, "mono")["player_carries_a_child_across_a_cell_border"]
    first, last = outcome.ticks[0], outcome.ticks[-1]
    assert first.others[0].cur_cell == first.cur_cell == 0xA9B40013
    assert last.others[0].cur_cell == last.cur_cell == 0xA9B4001B
    assert set(last.others[0].shadow_cells) == {0xA9B40013, 0xA9B4001B}  # its sorting sphere reaches back over x = 72


def test_ace_leaves_a_child_held_by_a_part_where_the_part_was_on_a_server():
    outcome = recorded_outcomes(DATA, "mono")["player_walks_with_a_child_held_by_a_part"]
    assert len({t.others[0].origin for t in outcome.ticks}) == 1
    assert outcome.ticks[-1].origin != outcome.ticks[0].origin


def test_ace_stops_the_carrier_at_a_wall_and_its_child_with_it():
    outcome = recorded_outcomes(DATA, "mono")["player_carrying_a_child_walks_into_a_wall"]
    last = outcome.ticks[-1]
    assert last.origin[1] < 61.4 and last.others[0].origin[1] == float(F(last.origin[1]) + F(0.1))


@pytest.mark.live_oracle
@pytest.mark.parametrize("name", sorted(SCENES))
def test_live_ace_answers_each_child_scene_as_recorded_and_as_the_port(live, name):
    from acconform.port.run import run_scene

    ace = live.run(SCENES[name])
    assert compare(ace, recorded_outcomes(DATA, live.location.runtime)[name], "exact") == [], name
    assert compare(run_scene(SCENES[name], runtime=live.location.runtime), ace, "exact") == [], name


def test_the_shrinker_takes_a_child_away_with_its_parent():
    from acconform.scene import validate_scene
    from acconform.shrink import _fewer_others

    scene = SCENES["monster_walks_carrying_a_child"]
    for smaller in _fewer_others(scene):
        validate_scene(smaller)
    assert [o.id for o in list(_fewer_others(scene))[-1].others] == []  # the monster taken, its sword with it


# ------------------------------------------------------------------ a child moved at a tick (unparent, parent)
def test_a_childs_tick_inputs_read_back_and_need_objects_children():
    doc = json.loads(SCENES["player_drops_a_child_and_picks_it_up_again"].dumps())
    steps = doc["ticks"]["steps"]
    assert steps[4]["others"] == [{"id": "0x80000010", "unparent": True}]
    assert steps[12]["others"] == [{"id": "0x80000010", "parent": {"id": "0x50000001", "location": "RightHand",
                                                                   "placement": 0}}]
    scene = Scene.loads(json.dumps(doc))
    assert scene.ticks.steps[4].others[0].unparent and "objects.children" in scene_features(scene)


@pytest.mark.parametrize("holder, problem", [("0x80000010", "has id 0x80000010"), ("0x80000099", "has id 0x80000099")])
def test_a_child_held_anew_by_itself_or_by_no_mover_is_refused(holder, problem):
    doc = json.loads(SCENES["player_moves_a_child_to_its_other_hand"].dumps())
    doc["ticks"]["steps"][10]["others"][0]["parent"]["id"] = holder
    with pytest.raises(InvalidScene) as e:
        Scene.loads(json.dumps(doc))
    assert "ticks.steps[10].others[0].parent.id" in str(e.value) and problem in str(e.value)


def test_a_holder_that_would_be_held_is_refused():
    """The monster holding the sword may not be handed to the player: a holder is never held (UpdateChild would
    carry a child's own holder)."""
    doc = json.loads(SCENES["player_hands_a_child_to_a_monster"].dumps())
    doc["ticks"]["steps"][3]["others"][0]["parent"] = {"id": "0x50000001", "location": 1}  # the monster's inputs
    with pytest.raises(InvalidScene) as e:
        Scene.loads(json.dumps(doc))
    assert "would both hold and be held" in str(e.value)


def test_a_childs_tick_inputs_pack_as_bits_9_and_10_after_the_setters_and_destroys_bit_8():
    scene = SCENES["player_drops_a_child_and_picks_it_up_again"]
    from acconform.oracle.pack import _other_inputs

    drop, pick = (b"".join(_other_inputs(scene.ticks.steps[k], {SWORD: 0})) for k in (4, 12))
    assert drop == struct.pack("<iiI", 1, 0, 1 << 9)
    assert pick == struct.pack("<iiIBIii", 1, 0, 1 << 10, 1, MOVER_ID, int(ParentLocation.RightHand), 0)


def test_a_child_by_the_frame_form_packs_form_2_its_part_and_its_frame_and_reads_back():
    scene = SCENES["player_walks_with_a_child_attached_by_its_part_and_a_frame"]
    doc = json.loads(scene.dumps())
    assert doc["others"][0]["parent"] == {"id": "0x50000001", "part": 0, "frame": {
        "origin": [60.3, 60.2, 20.9], "orientation": [0.70710677, 0.0, 0.0, 0.70710677]}}
    assert Scene.loads(scene.dumps()) == scene
    packed = pack_scene(scene)
    want = struct.pack("<BIii", 2, MOVER_ID, 0, 0) + struct.pack("<3f4f", 60.3, 60.2, 20.9, 0.70710677, 0.0, 0.0, 0.70710677)
    assert want in packed
    doc["others"][0]["parent"] = {"id": "0x50000001", "part": 0}
    with pytest.raises(InvalidScene) as e:
        Scene.loads(json.dumps(doc))
    assert "both part and frame" in str(e.value)


def test_ace_refuses_the_frame_form_past_the_parts_and_throws_at_part_minus_one():
    for runtime in ("mono", "coreclr"):
        ace = recorded_outcomes(DATA, runtime)
        assert ace["child_attached_past_its_parents_parts_by_a_frame"].other_placements[0].result == (
            SetPositionError.GeneralFailure)
        assert ace["child_attached_at_part_minus_one_by_a_frame"].error.startswith("ArgumentOutOfRangeException")


def test_ace_throws_at_the_next_move_of_a_holder_that_lost_a_child():
    """ChildList.RemoveChild leaves NumObjects one past its lists: the player's next step within its cell walks its
    children to NumObjects (SetPositionInternal) and indexes past the end, on both runtimes."""
    for runtime in ("mono", "coreclr"):
        outcome = recorded_outcomes(DATA, runtime)["player_drops_a_child_and_walks_into_it"]
        assert len(outcome.ticks) == 6 and outcome.ticks[-1].error.startswith("ArgumentOutOfRangeException")
        assert all(t.error is None for t in outcome.ticks[:-1])


def test_ace_gives_a_child_taken_by_a_hidden_holder_no_draw_and_keeps_it_when_handed_back():
    """set_parent to a Hidden parent sets the child's NoDraw; unset_parent from it clears Hidden (not NoDraw)."""
    outcome = recorded_outcomes(DATA, "mono")["hidden_monster_takes_a_child"]
    sword = [t.others[1] for t in outcome.ticks]
    hand = tuple(float(F(a) + F(b)) for a, b in zip(outcome.ticks[6].others[0].origin, RIGHT_HAND.frame.origin))
    assert not sword[5].state & 0x20 and sword[6].state & 0x20 and sword[6].origin == hand  # NoDraw 0x20
    assert sword[14].state & 0x20 and sword[14].origin == tuple(float(F(a) + F(b)) for a, b in
                                                                zip(outcome.ticks[14].origin, RIGHT_HAND.frame.origin))


def test_ace_carries_a_child_an_arrow_held_before_its_launch():
    outcome = recorded_outcomes(DATA, "coreclr")["arrow_carrying_a_child_is_launched"]
    assert outcome.ticks[0].others[2].cur_cell == 0  # held by an arrow out of the world: no cell to change to
    flying = [t.others for t in outcome.ticks if t.others[1].cur_cell != 0]  # launched at tick 2, until it hits
    assert len(flying) > 3
    assert all(o[2].cur_cell == o[1].cur_cell for o in flying)  # its cell is the arrow's (change_cell takes it along)
    assert len({(o[1].origin, o[2].origin) for o in flying}) == len({o[1].origin for o in flying}) > 3  # moves with it
