"""Missiles and spell projectiles (issue 41; scene/8 `others[].launch`, feature missiles, pack 14). The launch's
fields and their refusals, the pack bytes, the dat form (fast lane); each named scene of
tests/oracle/missile_scenes.py answered by the port as ACE answered it on both runtimes (recorded: fast lane) and
by live ACE again (live lane)."""

from __future__ import annotations

import json
import struct
import sys
from pathlib import Path

import pytest

from acconform.compare import compare
from acconform.dat import dat_world
from acconform.errors import InvalidScene
from acconform.flags import PhysicsState
from acconform.oracle.pack import PACK_VERSION, pack_scene
from acconform.protocol import dat_from_json, dat_json, scene_features
from acconform.scene import FORMAT, Scene

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from oracle.live_answers import recorded_outcomes  # noqa: E402
from oracle.missile_scenes import ARROW, DATA, LAUNCH_TICK, MONSTER, SPELL, scenes  # noqa: E402

SCENES = scenes()
WALL_SHOT = "arrow_into_a_wall"
MISSILE_BITS = int(PhysicsState.Missile | PhysicsState.AlignPath | PhysicsState.PathClipped)


def _doc(name: str = WALL_SHOT) -> dict:
    return json.loads(SCENES[name].dumps())


def _projectile(outcome, ident=ARROW):
    """Per tick, the projectile's TickState."""
    return [next(o for o in t.others if o.id == ident) for t in outcome.ticks]


@pytest.mark.parametrize("name", sorted(SCENES))
def test_each_missile_scene_reads_back_as_the_same_scene_in_format_8_and_needs_missiles(name):
    scene = SCENES[name]
    assert Scene.loads(scene.dumps()) == scene
    assert scene.format == FORMAT and {"objects.moving", "missiles"} <= set(scene_features(scene))


def _launch(d, k=-1):
    return d["others"][k]["launch"]


@pytest.mark.parametrize("edit, where, problem", [
    (lambda d: d["others"][0].pop("launch"), r"others\[0\]\.launch", "needs a launch"),
    (lambda d: d["others"][0].__setitem__("weenie", "monster"), r"others\[0\]\.launch", "a launch is a projectile's"),
    (lambda d: _launch(d).__setitem__("tick", 30), r"others\[0\]\.launch\.tick", r"30 steps \(0\.\.29\), got 30"),
    (lambda d: _launch(d).__setitem__("speed", 0), r"others\[0\]\.launch\.speed", "positive"),
    (lambda d: _launch(d).__setitem__("launcher", "0x80000099"), r"others\[0\]\.launch\.launcher", "no mover has id 0x80000099"),
    (lambda d: _launch(d).__setitem__("launcher", "0x70000001"), r"others\[0\]\.launch\.launcher", "no mover has id 0x70000001"),
    (lambda d: _launch(d).__setitem__("target", "0x80000010"), r"others\[0\]\.launch\.target", "is a projectile"),
    (lambda d: _launch(d).__setitem__("target", "0x50000001"), r"others\[0\]\.launch\.target", "its own target"),
    (lambda d: _launch(d).__setitem__("arc", True), r"others\[0\]\.launch", "unknown field .arc."),
    (lambda d: d["engine"].__setitem__("mode", "client"), r"engine\.mode", "must be server"),
    (lambda d: d["others"][0].__setitem__("player_killer_status", "PK"), r"others\[0\]\.player_killer_status",
     "only from a Creature"),
    (lambda d: d["ticks"]["steps"][3].__setitem__("others", [{"id": "0x80000010", "velocity": [0, 1, 0]}]),
     r"steps\[3\]\.others\[0\]\.id", "is a projectile"),
])
def test_a_bad_launch_is_refused_naming_the_field(edit, where, problem):
    doc = _doc()
    edit(doc)
    with pytest.raises(InvalidScene, match=where + ".*" + problem):
        Scene.from_json(doc)


@pytest.mark.parametrize("edit, where, problem", [
    (lambda d: _launch(d, 0).pop("target"), r"others\[0\]\.launch", "names its target"),
    (lambda d: _launch(d, 0).__setitem__("spell", "wall"), r"others\[0\]\.launch", "unknown field .spell."),
    (lambda d: d["others"][0].__setitem__("report_collisions", False), r"others\[0\]\.report_collisions",
     "launch sets its ReportCollisions"),
    (lambda d: _launch(d, 0).__setitem__("rotation_speed", "fast"), r"others\[0\]\.launch\.rotation_speed", ""),
])
def test_an_arrows_launch_names_its_target_and_its_projectile_takes_no_spell_kind_nor_report_property(edit, where, problem):
    doc = _doc()
    edit(doc)
    with pytest.raises(InvalidScene, match=where + ".*" + problem):
        Scene.from_json(doc)


@pytest.mark.parametrize("edit, where, problem", [
    (lambda d: _launch(d, 1).__setitem__("spell", "fireball"), r"others\[1\]\.launch\.spell", "unknown spell kind"),
    (lambda d: _launch(d, 1).__setitem__("spell", "ring"), r"others\[1\]\.launch\.arc", "is no Arc"),
    (lambda d: d["others"][0].__setitem__("spheres", []), r"others\[0\]\.spheres", ""),
    (lambda d: d["others"][0].__setitem__("report_collisions", True), r"others\[0\]\.report_collisions",
     "state needs ReportCollisions"),
])
def test_a_spells_kind_a_monsters_spheres_and_a_report_property_against_its_state_are_checked(edit, where, problem):
    doc = _doc("arc_spell_at_a_monster")
    edit(doc)
    with pytest.raises(InvalidScene, match=where + ".*" + problem):
        Scene.from_json(doc)


def test_an_untargeted_spell_a_spell_kind_a_thrown_weapon_and_a_quiet_sphereless_crate_read_back_and_need_their_features():
    doc = _doc("arc_spell_at_a_monster")
    _launch(doc, 1).pop("target")
    _launch(doc, 1).update(arc=False, spell="ring_3818", rotation_speed=1.5)
    scene = Scene.from_json(doc)
    la = scene.others[1].launch
    assert la.target is None and la.spell == "ring_3818" and la.rotation_speed == 1.5
    assert Scene.loads(scene.dumps()) == scene
    assert {"missiles.untargeted", "missiles.spells", "missiles.rotation_speed"} <= set(scene_features(scene))
    doc = _doc()
    doc["others"][0]["weenie"] = "missile"
    assert "missiles.thrown" in scene_features(Scene.from_json(doc))
    plain = Scene.from_json(_doc())
    assert not {"missiles.untargeted", "missiles.spells", "missiles.rotation_speed", "missiles.thrown",
                "objects.report_collisions", "objects.sphereless"} & set(scene_features(plain))


def test_a_static_in_an_env_cell_is_no_target():
    from dataclasses import replace

    from acconform.scene import validate_scene

    scene = SCENES[WALL_SHOT]
    wall = scene.objects[0]
    indoor = replace(wall, position=replace(wall.position, cell=(wall.position.cell & 0xFFFF0000) | 0x0100))
    with pytest.raises(InvalidScene, match=r"others\[0\]\.launch\.target.*EnvCell"):
        validate_scene(scene.replace(objects=(indoor,)))


def test_a_projectiles_launch_packs_after_its_record():
    assert PACK_VERSION == 18
    scene = SCENES["arc_spell_at_a_monster"]
    la = scene.others[1].launch
    # ... lead_target, arc, tracking, alt_solver, rotation_speed (none), the spell's kind (plain), then the
    # ReportCollisions property byte (unset)
    record = struct.pack("<BiIIf3f4fBBBBfBB", 1, LAUNCH_TICK, 0x50000001, MONSTER, 15.0, *la.origin, 1.0, 0.0, 0.0, 0.0,
                         1, 1, 0, 0, 0.0, 0, 0)
    data = pack_scene(scene)
    assert record in data
    # the monster has no launch: its record ends in byte 0, right before the arc spell's DAT records
    assert data.count(record) == 1


def test_the_dat_form_carries_the_launch_and_reads_back():
    world = dat_world(SCENES["spell_projectile_hits_a_player"])
    doc = json.loads(json.dumps(dat_json(world)))
    assert doc["others"][1]["weenie"] == "spell_projectile" and doc["others"][1]["launch"]["arc"] is False
    assert "launch" not in doc["others"][0]
    assert dat_from_json(doc) == world


@pytest.mark.parametrize("runtime", ["mono", "coreclr"])
def test_the_port_answers_each_missile_scene_as_ace_did_every_tick(runtime):
    from acconform.port.run import run_scene

    ace = recorded_outcomes(DATA, runtime)
    for name, scene in SCENES.items():
        assert compare(run_scene(scene, runtime=runtime), ace[name], "exact") == [], name


def test_ace_leaves_a_projectile_out_of_the_world_until_its_launch_then_flies_it_as_a_missile():
    arrow = _projectile(recorded_outcomes(DATA, "mono")[WALL_SHOT])
    assert all(t.cur_cell == 0 and not t.updated for t in arrow[:LAUNCH_TICK])
    assert arrow[LAUNCH_TICK].cur_cell != 0 and arrow[LAUNCH_TICK].state & MISSILE_BITS == MISSILE_BITS


def test_ace_destroys_an_arrow_that_strikes_a_wall_and_steps_it_no_more():
    arrow = _projectile(recorded_outcomes(DATA, "mono")[WALL_SHOT])
    gone = next(i for i, t in enumerate(arrow) if i > LAUNCH_TICK and t.cur_cell == 0)
    assert 69.0 < arrow[gone].origin[1] < 69.8  # at the wall's near face (y = 69.8)
    assert not arrow[gone].state & PhysicsState.Missile
    assert all(t == arrow[gone] for t in arrow[gone + 1:])  # destroyed: no tick moves it again


def test_ace_flies_an_arrow_through_an_open_door_and_stops_it_at_a_closed_one():
    ace = recorded_outcomes(DATA, "mono")
    through = _projectile(ace["arrow_through_an_open_door"])
    stopped = _projectile(ace["arrow_into_a_closed_door"])
    assert max(t.origin[1] for t in through) > 69.0  # on to the wall
    assert max(t.origin[1] for t in stopped) < 65.0  # short of the door's far face


def test_ace_removes_an_arrow_from_the_world_when_it_strikes_its_target():
    for name in ("arrow_at_a_monster_standing_at_a_wall", "monster_runs_into_an_arrow_at_it"):
        ace = recorded_outcomes(DATA, "mono")[name]
        arrow = _projectile(ace)
        monster = _projectile(ace, MONSTER)
        gone = next(i for i, t in enumerate(arrow) if i > LAUNCH_TICK and t.cur_cell == 0)
        assert not arrow[gone].state & MISSILE_BITS, name  # an object hit clears all three bits
        assert arrow[gone].origin[1] < monster[gone].origin[1], name


def test_ace_makes_a_spell_that_hits_a_player_ethereal_inert_and_still_in_the_world():
    spell = _projectile(recorded_outcomes(DATA, "mono")["spell_projectile_hits_a_player"], SPELL)
    last = spell[-1]
    for bit in (PhysicsState.Ethereal, PhysicsState.IgnoreCollisions, PhysicsState.NoDraw, PhysicsState.Cloaked):
        assert last.state & bit
    assert last.velocity == (0.0, 0.0, 0.0) and last.cur_cell != 0
    assert last.origin[1] < 62.0  # at the player


def _across_landblocks():
    """The player at the north edge of A9B4 shoots at a monster just over the border, in A9B5."""
    from oracle.missile_scenes import BODY, GROUND, WALKING, EDGE_SLIDE, _player, _steps, arrow, scene
    from oracle.named_scenes import cell_at, land
    from acconform.scene import Frame, OtherMover, Position

    north = 0xA9B50000
    monster = OtherMover(MONSTER, "monster", BODY, Position(cell_at(60.0, 3.0, north), Frame((60.0, 3.0, GROUND))), 0.4,
                         0.4, state=EDGE_SLIDE, transient_state=WALKING)
    return scene("across_landblocks", [land(), land(north)], _player((60.0, 186.0, GROUND)), _steps(6),
                 others=(monster, arrow((60.0, 186.0, GROUND), MONSTER)))


ACROSS = "NotSupportedException: acconform: a launch across landblocks (ACE.Entity.Position.ToGlobal) is not modelled"


def test_a_launch_across_landblocks_is_the_launch_ticks_error_on_both_sides():
    """ACE.Entity.Position.ToGlobal (CalculateProjectileVelocity's cross-landblock arm) is not modelled: the port and
    the facade refuse the launch with one verdict, which ends the scene at that tick."""
    from acconform.port.run import run_scene

    out = run_scene(_across_landblocks(), runtime="mono")
    assert [t.error for t in out.ticks] == [None] * LAUNCH_TICK + [ACROSS]


@pytest.mark.live_oracle
def test_live_ace_refuses_a_launch_across_landblocks_as_the_port_does(live):
    from acconform.port.run import run_scene

    scene = _across_landblocks()
    ace = live.run(scene)
    assert ace.ticks[-1].error == ACROSS
    assert compare(run_scene(scene, runtime=live.location.runtime), ace, "exact") == []


@pytest.mark.live_oracle
@pytest.mark.parametrize("name", sorted(SCENES))
def test_live_ace_answers_each_missile_scene_as_recorded_and_as_the_port(live, name):
    from acconform.port.run import run_scene

    ace = live.run(SCENES[name])
    assert compare(ace, recorded_outcomes(DATA, live.location.runtime)[name], "exact") == [], name
    assert compare(run_scene(SCENES[name], runtime=live.location.runtime), ace, "exact") == [], name


def _alt_solver(scene):
    """The scene with its projectile's launch under the server's trajectory_alt_solver."""
    from dataclasses import replace

    return replace(scene, others=tuple(replace(o, launch=replace(o.launch, alt_solver=True)) if o.launch is not None else o
                                       for o in scene.others))


ALT_SOLVER_SCENES = ("monster_runs_into_an_arrow_at_it", "arrow_into_a_wall", "arc_spell_at_a_monster")


@pytest.mark.parametrize("name", ALT_SOLVER_SCENES)
def test_a_launch_under_trajectory_alt_solver_takes_trajectory2s_velocity_and_needs_its_feature(name):
    from acconform.port.run import run_scene

    def velocity(out, ident):
        return next(o for o in out.ticks[LAUNCH_TICK].others if o.id == ident).velocity

    plain = SCENES[name]
    alt = _alt_solver(plain)
    ident = next(o.id for o in plain.others if o.launch is not None)
    assert "missiles.alt_solver" in scene_features(alt) and "missiles.alt_solver" not in scene_features(plain)
    assert Scene.from_json(alt.to_json()) == alt and pack_scene(alt) != pack_scene(plain)
    assert velocity(run_scene(alt, runtime="coreclr"), ident) != velocity(run_scene(plain, runtime="coreclr"), ident)


@pytest.mark.live_oracle
@pytest.mark.parametrize("name", ALT_SOLVER_SCENES)
def test_live_ace_answers_a_launch_under_trajectory_alt_solver_as_the_port(live, name):
    from acconform.port.run import run_scene

    scene = _alt_solver(SCENES[name])
    assert compare(run_scene(scene, runtime=live.location.runtime), live.run(scene), "exact") == [], name


def test_an_arrows_missile_flight_placement_reads_back_needs_its_feature_and_sets_its_setups_flag():
    from acconform.dat import scene_records
    from acconform.numerics import EXACT
    from acconform.port.dat.binary_reader import BinaryReader
    from acconform.port.dat.setup_model import SetupModel

    doc = _doc()
    doc["others"][0]["missile_flight"] = True
    scene = Scene.from_json(doc)
    assert scene.others[0].missile_flight and Scene.loads(scene.dumps()) == scene
    assert "missiles.missile_flight" in scene_features(scene)
    assert "missiles.missile_flight" not in scene_features(Scene.from_json(_doc()))

    def setup_of(s):
        rec = next(r for r in scene_records(s).others[0].records if r.kind == "SetupModel")
        return SetupModel.unpack(BinaryReader(rec.data, EXACT))

    flown, plain = setup_of(scene), setup_of(Scene.from_json(_doc()))
    assert flown.has_missile_flight_placement and list(flown.placement_frames) == [52]
    assert not plain.has_missile_flight_placement and not plain.placement_frames


def test_a_missile_flight_placement_is_an_arrows_or_a_thrown_weapons():
    doc = _doc("arc_spell_at_a_monster")
    doc["others"][1]["missile_flight"] = True
    with pytest.raises(InvalidScene, match=r"others\[1\]\.missile_flight.*arrow's or a thrown weapon's"):
        Scene.from_json(doc)
