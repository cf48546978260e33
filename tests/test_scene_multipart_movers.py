"""Another mover of several parts (scene/8 `others[].setup`, feature setup.multipart_movers) and a Setup of no parts
(`"parts": []`, feature setup.no_parts): the JSON form, its refusals, the DAT records acconform/dat.py writes for
it, and what the port does with it (ACE's answers for such scenes are shard ticks-0070's)."""

from __future__ import annotations

import copy
import sys
from dataclasses import replace
from pathlib import Path

import pytest

from acconform import dat
from acconform.errors import InvalidScene
from acconform.flags import PhysicsState, SetPositionError
from acconform.protocol import scene_features
from acconform.scene import FORMAT, Frame, PartRec, Position, Scene, SetupRec, StaticObject
from acconform.strategies.shapes import box
from tests.test_scene_setup import read_setup_full

sys.path.insert(0, str(Path(__file__).resolve().parent))
from oracle.mover_scenes import THING, _player, _steps, other  # noqa: E402
from oracle.named_scenes import GROUND, cell_at, land, scene  # noqa: E402

# a wall of two boxes 2 m wide across the player's path, 2 m before the object's origin
WALL = (PartRec(box(2.0, 0.5, 2.0), Frame((-1.0, -2.0, 0.0))), PartRec(box(2.0, 0.5, 2.0), Frame((1.0, -2.0, 0.0))))
BSP = int(PhysicsState.Gravity | PhysicsState.HasPhysicsBSP)


def walk_at(setup: SetupRec, state: int = BSP):
    """The player walks north (3 m/s, 40 ticks) at a standing GenericObject of no spheres 4 m ahead."""
    thing = replace(other(THING, "object", (60.0, 64.0, GROUND), state=state), spheres=(), setup=setup)
    return scene("multipart", [land()], _player((60.0, 60.0, GROUND)), _steps(40, (0.0, 3.0, 0.0), {}), others=(thing,))


def _hit(out) -> bool:
    return any(c.id == THING for t in out.ticks for c in t.collisions)


def refused(doc) -> str:
    with pytest.raises(InvalidScene) as e:
        Scene.from_json(doc)
    return str(e.value)


def test_an_other_of_several_parts_is_scene_8_reads_back_and_needs_its_feature():
    s = walk_at(SetupRec(WALL))
    text = s.dumps()
    assert s.to_json()["format"] == FORMAT and Scene.loads(text) == s and Scene.loads(text).dumps() == text
    assert "setup.multipart_movers" in scene_features(s) and "setup.no_parts" not in scene_features(s)
    assert "setup.no_parts" in scene_features(walk_at(SetupRec(())))


def test_an_others_setup_gives_no_spheres_of_its_own_and_a_static_has_no_placement_false():
    doc = copy.deepcopy(walk_at(SetupRec(WALL)).to_json())
    doc["others"][0]["setup"]["spheres"] = [{"center": [0, 0, 1], "radius": 1}]
    assert "others[0].setup.spheres: another mover's setup gives parts and cylspheres only" in refused(doc)
    doc = copy.deepcopy(walk_at(SetupRec(WALL)).to_json())
    doc["others"][0]["setup"]["placement"] = False
    assert "others[0].setup.parts[0]: a Setup with placement false has no frames for its parts" in refused(doc)
    static = StaticObject(0x70000020, Position(cell_at(60.0, 64.0), Frame((60.0, 64.0, GROUND))), None,
                          setup=SetupRec(WALL))
    doc = copy.deepcopy(walk_at(SetupRec(WALL)).replace(objects=(static,)).to_json())
    doc["objects"][0]["setup"]["placement"] = False
    assert "objects[0].setup.placement: a static's Setup has its placement frame" in refused(doc)


def test_an_others_setup_is_its_part_gfx_objs_then_its_setup_naming_them_at_their_frames():
    o = walk_at(SetupRec(WALL)).others[0]
    recs = dat.other_records(o, 2)
    ids = [dat.OTHER_PART_GFX_OBJ_BASE + 32, dat.OTHER_PART_GFX_OBJ_BASE + 33]
    assert [(r.id, r.kind) for r in recs.records] == [(ids[0], "GfxObj"), (ids[1], "GfxObj"),
                                                     (dat.OTHER_SETUP_BASE + 2, "SetupModel")]
    got = read_setup_full(recs.records[-1].data)
    assert got["parts"] == ids and [f[0] for f in got["placements"][0]] == [(-1.0, -2.0, 0.0), (1.0, -2.0, 0.0)]
    bare = read_setup_full(dat.other_records(replace(o, setup=SetupRec(tuple(PartRec(p.shape) for p in WALL),
                                                                       placement=False)), 2).records[-1].data)
    assert bare["parts"] == ids and bare["placements"] == {}
    assert read_setup_full(dat.other_records(replace(o, setup=SetupRec(())), 2).records[-1].data)["parts"] == []


def test_an_others_parts_stand_at_their_frames_so_the_player_stops_at_them():
    """UpdateParts puts each part at the object's frame combined with its placement frame: the wall 2 m before the
    object stops the player short of it (its front face at y 61.75); the same parts 20 m aside let it walk on."""
    from acconform.port.run import run_scene

    stopped = run_scene(walk_at(SetupRec(WALL)))
    aside = run_scene(walk_at(SetupRec(tuple(replace(p, frame=Frame((p.frame.origin[0] + 20.0, -2.0, 0.0)))
                                             for p in WALL))))
    assert stopped.ticks[-1].origin[1] < 61.75 - 0.48 + 1e-3 and _hit(stopped)
    assert aside.ticks[-1].origin[1] > 63.0 and not _hit(aside)


def test_parts_with_no_placement_frame_are_never_moved_to_the_object_so_the_player_walks_through():
    """With no placement frame GetCurrAnimFrame is null and UpdateParts moves a part only when the Setup has one:
    both parts stay where PhysicsPart made them, so nothing stands in the player's way."""
    from acconform.port.run import run_scene

    out = run_scene(walk_at(SetupRec(tuple(PartRec(p.shape) for p in WALL), placement=False)))
    assert out.ticks[-1].origin[1] > 63.0 and not _hit(out)


def test_an_other_of_no_parts_has_no_part_array_and_never_enters_the_world():
    from acconform.port.run import run_scene

    out = run_scene(walk_at(SetupRec(())))
    assert SetPositionError(out.other_placements[0].result).name == "GeneralFailure"
    assert out.other_placements[0].cur_cell == 0


def test_a_child_of_no_parts_is_held_and_carried_though_it_has_no_part_array():
    """A sword whose Setup has no parts is made with no PartArray; set_parent still holds it (SetPlacementFrame
    answers without a PartArray) and UpdateChild carries it with the walking player (ACE answers so in ticks-0070)."""
    from acconform.port.run import run_scene
    from oracle.child_scenes import player_walks_carrying_a_child

    s = player_walks_carrying_a_child()
    (sword,) = s.others
    out = run_scene(s.replace(others=(replace(sword, setup=SetupRec(())),)))
    assert SetPositionError(out.other_placements[0].result).name == "OK"
    first, last = (t.others[0] for t in (out.ticks[0], out.ticks[-1]))
    assert last.origin[1] - first.origin[1] > 2.4  # 30 ticks at 3 m/s, the first tick's move before it
