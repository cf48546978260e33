"""strategies/missiles.py: the missiles kind's scenes (an arrow or a spell launched at a tick), drawn as a campaign
draws them, and what the port does with them."""

from __future__ import annotations

import collections

import pytest

from acconform.scene import FORMAT, validate_scene

N = 150


@pytest.fixture(scope="module")
def missile_scenes():
    from acconform.strategies import sample_scenes

    return list(sample_scenes(("missiles",), N, 41))


def _projectile(scene):
    return next(o for o in scene.others if o.launch is not None)


def test_every_missile_scene_validates_in_format_8_with_one_launch_inside_its_ticks(missile_scenes):
    for s in missile_scenes:
        assert validate_scene(s) == s and s.format == FORMAT and s.engine_mode == "server"
        launched = [o for o in s.others if o.launch is not None]
        assert len(launched) == 1 and launched[0].launch.tick < len(s.ticks.steps)
        assert len({o.begin.cell >> 16 for o in s.others if o.parent is None} | {s.mover.begin.cell >> 16}) == 1


def test_some_missile_scenes_carry_a_child_held_by_the_projectile_before_its_launch(missile_scenes):
    """CARRIED: a child held by the projectile (past its part or by it), after it in `others`, named in the name."""
    carried = [s for s in missile_scenes if ":carries-" in s.name]
    assert carried and {s.name.rsplit("-", 1)[1] for s in carried} <= {"position", "part"}
    for s in carried:
        child = s.others[-1]
        projectile = _projectile(s)
        assert child.parent.id == projectile.id and child.begin is None and projectile.holding_locations
        assert [h.location for h in projectile.holding_locations] == [child.parent.location]


POLICIES = {"creature_at_wall", "through_door", "graze_cylsphere", "moving_target", "wall", "bystander"}


def _unarmed(name: str) -> list[str]:
    """A missile scene's name without its launch arm (missiles:ARM:policy:...): missiles:policy:projectile:launcher..."""
    parts = name.split(":")
    return parts if parts[1] in POLICIES else parts[:1] + parts[2:]


def test_the_missiles_kind_draws_the_launch_arms_and_the_arms_drawn_by_name_as_a_share(missile_scenes):
    """A campaign of --kinds missiles meets draw_launch_scene's arms and the ones it leaves to be named, not only the
    policies (scenes_of: one scene in six each)."""
    from acconform.strategies.missiles import ARMS

    arms = collections.Counter(s.name.split(":")[1] for s in missile_scenes if s.name.split(":")[1] not in POLICIES)
    assert "report" in arms and len(set(arms) & set(ARMS.elements)) >= 4, arms
    assert any(_projectile(s).launch.alt_solver for s in missile_scenes)  # the arms' trajectory_alt_solver
    assert len(set(arms) & {"run_into", "spin", "trap", "thrown", "untargeted", "spells", "quiet", "sphereless"}) >= 4, arms
    assert N / 6 < sum(arms.values()) < N / 2, arms


def test_missile_scenes_draw_every_policy_both_projectiles_both_launchers_and_both_orders(missile_scenes):
    names = [_unarmed(s.name) for s in missile_scenes]
    assert {n[1] for n in names} == {"creature_at_wall", "through_door", "graze_cylsphere", "moving_target", "wall",
                                     "bystander"}
    assert {n[2] for n in names} == {"arrow", "spell"} and {n[3] for n in names} == {"player", "monster"}
    firsts = {s.others[0].launch is not None for s in missile_scenes if len(s.others) > 1}
    assert firsts == {True, False}  # the projectile stepped before the monsters, and after them
    spells = [_projectile(s).launch for s in missile_scenes if _projectile(s).weenie == "spell_projectile"]
    assert {la.arc for la in spells} == {True, False} and {la.tracking for la in spells} == {True, False}


def test_bystander_scenes_draw_every_role_and_way_and_npk_and_pk_players(missile_scenes):
    names = [s.name.split(":") for s in missile_scenes if s.name.startswith("missiles:bystander:")]
    assert {n[4] for n in names} == {"mover_crosses", "other_crosses", "mover_is_target", "other_is_target"}
    assert {n[5] for n in names} == {"across", "toward", "away"}
    assert {"npk", "pk"} <= {n[6] for n in names} and {"npk", "pk"} <= {n[7] for n in names}
    for s in missile_scenes:
        if s.name.startswith("missiles:bystander:"):
            players = {o.id for o in s.others if o.weenie == "player"}
            assert _projectile(s).launch.target != _projectile(s).launch.launcher and players <= {0x50000002}


def test_in_the_port_a_bystander_player_ignores_a_missile_aimed_at_someone_else(missile_scenes, monkeypatch):
    """ObjectInfo.MissileIgnore's arm no other policy takes: a player's transition meets a Missile whose
    ProjectileTarget is set and is someone else, and passes it (True); a crossing player that is the target does
    not (False)."""
    from acconform.flags import PhysicsState
    from acconform.port.run import run_scene
    from acconform.port.transition.object_info import ObjectInfo

    original = ObjectInfo.missile_ignore
    seen = []

    def spy(self, collide_obj):
        ignored = original(self, collide_obj)
        if collide_obj.state & PhysicsState.Missile and self.object.is_player:
            seen.append((ignored, collide_obj.projectile_target is self.object))
        return ignored

    monkeypatch.setattr(ObjectInfo, "missile_ignore", spy)
    arms = collections.Counter()
    for s in [s for s in missile_scenes if s.name.startswith("missiles:bystander:")][:16]:
        seen.clear()
        assert run_scene(s, runtime="coreclr").error is None
        arms[s.name.split(":")[4]] += any(ignored for ignored, _ in seen)
        arms["target"] += any(mine and not ignored for ignored, mine in seen)
        assert not any(mine and ignored for ignored, mine in seen)
    assert arms["mover_crosses"] >= 2 and arms["other_crosses"] >= 1 and arms["target"] >= 1, arms
    assert arms["mover_is_target"] == arms["other_is_target"] == 0, arms


def test_the_port_flies_most_missile_scenes_projectiles_into_something(missile_scenes):
    """A campaign that never hit anything would test the flight alone: most projectiles end destroyed (an arrow's
    hit) or without their Missile bit (a spell's impact, an arrow that struck a door or post)."""
    from acconform.port.run import run_scene

    ends = collections.Counter()
    for s in missile_scenes[:60]:
        out = run_scene(s, runtime="coreclr")
        proj = _projectile(s)
        last = next(o for o in out.ticks[-1].others if o.id == proj.id)
        ends["gone" if last.cur_cell == 0 else "hit" if not last.state & 0x8 else "flying"] += 1
    assert ends["gone"] + ends["hit"] > 2 * ends["flying"], ends


def test_the_missiles_kind_is_a_campaign_kind_the_port_runs_and_an_implementation_needs_the_feature():
    from acconform.impl import BuiltinPort
    from acconform.protocol import Implementation
    from acconform.strategies import check_kinds

    assert check_kinds("missiles") == ("missiles",) and "missiles" in BuiltinPort.kinds
    impl = object.__new__(Implementation)
    impl.hello = {"kinds": ["terrain"], "features": ["ticks", "objects.moving"]}
    assert "missiles" not in impl.kinds
    impl.hello["features"].append("missiles")
    assert "missiles" in impl.kinds


@pytest.fixture(scope="module")
def launch_scenes():
    from hypothesis import strategies as st

    from acconform.strategies.determinism import pinned_constants
    from acconform.strategies.fast_draw import FastDrawer
    from acconform.strategies.missiles import draw_launch_scene

    drawer = FastDrawer(st.composite(draw_launch_scene)(), 51 * 1000003)
    with pinned_constants():
        return [drawer.draw()[0] for _ in range(120)]


def test_launch_arm_scenes_validate_and_draw_every_arm_and_the_alternate_solver(launch_scenes):
    from acconform.scene import Scene

    arms = collections.Counter(s.name.split(":")[1] for s in launch_scenes)
    assert set(arms) == {"alt_solver", "out_of_range", "overhead", "fast_target", "tiny_target", "timeout", "report"}
    for s in launch_scenes:
        assert validate_scene(s) == s and Scene.from_json(s.to_json()) == s  # alt_solver survives the JSON form
    alt = [_projectile(s).launch.alt_solver for s in launch_scenes]
    assert any(alt) and not all(alt)
    assert all(_projectile(s).launch.alt_solver for s in launch_scenes if s.name.split(":")[1] == "alt_solver")


def test_a_timeout_scene_flies_a_spell_past_its_thirty_seconds_and_an_overhead_one_spawns_over_its_target(launch_scenes):
    timeouts = [s for s in launch_scenes if s.name.split(":")[1] == "timeout"]
    for s in timeouts:
        la = _projectile(s).launch
        assert sum(t.dt for t in s.ticks.steps) > 30.0 and not la.arc and not la.tracking and la.speed * 31 < 140
    for s in (s for s in launch_scenes if s.name.split(":")[1] == "overhead"):
        la = _projectile(s).launch
        target = next(o for o in (s.mover, *s.others) if getattr(o, "id", 0x50000001) == la.target)
        assert la.origin[:2] == target.begin.frame.origin[:2]


def test_a_scene_without_alt_solver_writes_no_such_key_and_needs_no_new_feature(missile_scenes):
    from acconform.protocol import scene_features

    for s in [s for s in missile_scenes if not _projectile(s).launch.alt_solver][:20]:
        la = _projectile(s).to_json()["launch"]
        assert "alt_solver" not in la and "missiles.alt_solver" not in scene_features(s)


def _arm_scenes(arm: str, n: int = 16, seed: int = 62):
    """`n` scenes of a launch arm drawn only by name (draw_missile_scene(draw, arm)), as tests/runner/launch_scenes.py
    --only draws them."""
    from hypothesis import strategies as st

    from acconform.strategies.determinism import pinned_constants
    from acconform.strategies.fast_draw import FastDrawer
    from acconform.strategies.missiles import draw_missile_scene

    drawer = FastDrawer(st.composite(lambda draw: draw_missile_scene(draw, arm))(), seed * 1000003)
    with pinned_constants():
        return [drawer.draw()[0] for _ in range(n)]


def test_the_spin_and_thrown_arms_give_projectiles_a_rotation_speed_and_thrown_ones_weenie_missile():
    from acconform.protocol import scene_features
    from acconform.scene import Scene

    spin = _arm_scenes("spin")
    assert any(_projectile(s).launch.rotation_speed != 0 for s in spin)
    for s in spin:
        la = _projectile(s).launch
        assert ("missiles.rotation_speed" in scene_features(s)) == (la.rotation_speed != 0)
        assert Scene.from_json(s.to_json()) == s
    thrown = _arm_scenes("thrown")
    assert all(_projectile(s).weenie == "missile" and "missiles.thrown" in scene_features(s) for s in thrown)
    assert {_projectile(s).launch.rotation_speed != 0 for s in thrown} == {True, False}


def test_the_trap_and_untargeted_arms_cast_from_an_object_and_at_no_one():
    from acconform.protocol import scene_features
    from acconform.scene import Scene

    for s in _arm_scenes("trap"):
        la = _projectile(s).launch
        launcher = next(o for o in s.others if o.id == la.launcher)
        assert launcher.weenie == "object" and _projectile(s).weenie == "spell_projectile"
    untargeted = _arm_scenes("untargeted")
    for s in untargeted:
        assert _projectile(s).launch.target is None and "missiles.untargeted" in scene_features(s)
        assert "target" not in _projectile(s).to_json()["launch"] and Scene.from_json(s.to_json()) == s


def test_the_spells_arm_draws_every_spell_kind_and_never_an_arcing_wall_or_ring():
    from acconform.protocol import scene_features
    from acconform.scene import SPELL_KINDS

    scenes = _arm_scenes("spells", 40)
    kinds = collections.Counter(_projectile(s).launch.spell for s in scenes)
    assert set(kinds) == set(SPELL_KINDS[1:])
    for s in scenes:
        la = _projectile(s).launch
        assert "missiles.spells" in scene_features(s) and not (la.arc and la.spell in ("wall", "ring", "ring_3818"))


def test_the_quiet_and_sphereless_arms_push_a_crate_that_reports_nothing_or_has_no_spheres():
    from acconform.flags import PhysicsState
    from acconform.protocol import scene_features
    from acconform.scene import Scene

    for s in _arm_scenes("quiet"):
        crate = next(o for o in s.others if o.weenie == "object")
        assert crate.report_collisions is False and not crate.state & PhysicsState.ReportCollisions
        assert "objects.report_collisions" in scene_features(s) and Scene.from_json(s.to_json()) == s
    for s in _arm_scenes("sphereless"):
        crate = next(o for o in s.others if o.weenie == "object")
        assert crate.spheres == () and "objects.sphereless" in scene_features(s) and Scene.from_json(s.to_json()) == s


def test_the_border_arms_spawn_across_a_cell_line_a_landblocks_edge_and_the_worlds():
    """draw_border_scene: the spawn point's outdoor cell (ACE.Entity.Position.SetLandCell) is never the launcher's, and
    the world-edge launches leave the world's landblocks (the Location is clamped); a spawn point 0.8 m back, on the line
    itself, is the launcher's cell when it faces west or south."""
    from hypothesis import strategies as st

    from acconform.strategies.determinism import pinned_constants
    from acconform.strategies.fast_draw import FastDrawer
    from acconform.strategies.missiles import draw_border_scene

    drawer = FastDrawer(st.composite(draw_border_scene)(), 68 * 1000003)
    with pinned_constants():
        scenes = [drawer.draw()[0] for _ in range(40)]
    arms = {s.name.split(":")[1] for s in scenes}
    assert arms == {"cell_border", "block_border", "world_edge"}
    for s in scenes:
        p = _projectile(s)
        x, y, _ = p.launch.origin
        spawn = int(x // 24) * 8 + int(y // 24) + 1 if 0 <= x < 192 and 0 <= y < 192 else None
        assert spawn != p.begin.cell & 0xFFFF or x % 24 == 0 or y % 24 == 0
        if s.name.split(":")[1] == "world_edge":
            assert any(b.id >> 24 in (0x00, 0xFE) or (b.id >> 16) & 0xFF in (0x00, 0xFE) for b in s.landblocks)
