"""strategies/movers.py: the movers policy's scenes (kind movers), drawn as a campaign draws them."""

from __future__ import annotations

import json
import re

import numpy as np
import pytest

from acconform.scene import FORMAT, Scene, validate_scene

N = 150
MOVER_ID = 0x50000001


def _draw(n: int, seed: int, policy=None):
    from hypothesis import strategies as st

    from acconform.strategies import ticks as tk
    from acconform.strategies.determinism import pinned_constants
    from acconform.strategies.fast_draw import FastDrawer
    from acconform.strategies.movers import draw_movers_ticks

    with pinned_constants():
        drawer = FastDrawer(st.composite(lambda draw: tk.draw_tick_scene(draw, None, "movers"))(), seed) if policy is None \
            else FastDrawer(st.composite(lambda draw: draw_movers_ticks(draw, tk._clock, policy))(), seed)
        return [drawer.draw()[0] for _ in range(n)]


@pytest.fixture(scope="module")
def mover_scenes():
    return _draw(N, 41)


def test_every_movers_scene_validates_in_format_8_round_trips_and_keeps_ids_in_their_ranges(mover_scenes):
    for s in mover_scenes:
        assert validate_scene(s) == s and s.format == FORMAT
        assert Scene.from_json(json.loads(s.dumps())) == s
        assert s.mover.placement is not None and s.mover.placement.via == "enter_world"
        in_world = [o for o in s.others if o.parent is None]  # a carry's children enter with their holders
        assert len(in_world) <= 3 and 1 <= len(s.others) <= 5 and (in_world or s.mover.holding_locations)
        for o in s.others:
            assert o.id != MOVER_ID
            assert (0x50000002 <= o.id <= 0x5FFFFFFF) if o.weenie == "player" else (0x80000001 <= o.id <= 0xFFFFFFFE)
        assert len({lb.id for lb in s.landblocks}) <= 4


def test_every_policy_weenie_and_input_kind_is_drawn(mover_scenes):
    from acconform.strategies.movers import POLICY_NAMES

    policies = {s.name.split(":")[1] for s in mover_scenes}
    assert policies == set(POLICY_NAMES)
    assert {o.weenie for s in mover_scenes for o in s.others} == {"player", "creature", "monster", "object"}
    inputs = {f for s in mover_scenes for t in s.ticks.steps for o in t.others
              for f in ("velocity", "local_velocity", "sequence_velocity", "jump", "state") if getattr(o, f) is not None}
    assert inputs == {"velocity", "local_velocity", "sequence_velocity", "jump", "state"}
    assert any(len(o.spheres) == 2 for s in mover_scenes for o in s.others)
    assert any(o.scale != 1.0 for s in mover_scenes for o in s.others)
    assert {s.name.split(":")[2] for s in mover_scenes if s.name.startswith("movers:corner")} == {"box", "house"}


def test_player_pairs_take_every_player_killer_status(mover_scenes):
    from acconform.flags import PlayerKillerStatus

    statuses = {o.player_killer_status for s in mover_scenes for o in s.others if o.weenie == "player"}
    assert statuses | {s.mover.player_killer_status for s in mover_scenes} == {int(p) for p in PlayerKillerStatus}


@pytest.mark.parametrize("policy", ["touch", "approach"])
def test_touches_put_the_centres_exactly_the_float32_radius_sum_apart_or_one_ulp_off(policy):
    from acconform.numerics import f32_bits
    from acconform.port.constants import EPSILON

    f = np.float32
    seen = set()
    for s in _draw(60, 5, policy):
        touch = s.name.split(":")[3 if policy == "approach" else 2]
        seen.add(touch)
        o = s.others[0]
        rm, ro = f(s.mover.spheres[0].radius), f(o.spheres[0].radius) * f(o.scale)
        radsum = rm + ro - f(EPSILON) if touch.startswith("ace") else rm + ro
        a, b = s.mover.begin.frame.origin, o.begin.frame.origin
        if policy == "approach":  # the walker's k steps, then the distance
            k, step = int(s.name.split(":")[6][2:]), f(float(s.name.split(":")[8][1:]) * s.ticks.steps[0].dt)
            walker_first = s.name.split(":")[2] == "mover"
            a, b = (a, b) if walker_first else (b, a)
            a = (a[0], f(a[1]) + f(k) * step * f(1 if b[1] > a[1] else -1), a[2])
        dist = f(abs(f(b[0]) - f(a[0])) + abs(f(b[1]) - f(a[1])))  # along one axis
        assert (a[0] == b[0] or a[1] == b[1]) and a[2] == b[2]
        shift = -1 if touch.endswith("-1ulp") else 1 if touch.endswith("+1ulp") else 0
        assert f32_bits(float(radsum)) == f32_bits(float(dist)) + shift, (s.name, dist, radsum)
        # the spheres' centres at one height
        assert [sp.center[2] * o.scale for sp in o.spheres] == [sp.center[2] for sp in s.mover.spheres]
    assert seen == {"sum", "sum-1ulp", "sum+1ulp", "ace", "ace-1ulp", "ace+1ulp"}


def test_a_drawn_head_on_scene_collides_in_the_port():
    from acconform.port.run import run_scene

    for s in _draw(40, 3, "head_on"):
        o = s.others[0]
        if o.weenie != "monster" or len(s.others) > 1 or "ethereal" in s.name:
            continue
        out = run_scene(s)
        if out.error is None and any(c.id == o.id for t in out.ticks for c in (t.collisions or ())):
            return
    pytest.fail("no head-on scene of a player and a monster collided in the port")


def test_an_approach_meets_its_standing_pair_exactly_at_the_drawn_tick_in_the_port():
    """ACE's radsum (the sum less EPSILON) met at tick k: the walker's CollisionTable names the other at
    that tick and not before (`<=`); an ulp short of it, only a tick later."""
    from acconform.port.run import run_scene

    checked = 0
    for s in _draw(80, 9, "approach"):
        p = s.name.split(":")
        o = s.others[0]
        if p[2] != "mover" or p[3] not in ("ace", "ace-1ulp") or o.weenie == "player":
            continue
        k = int(p[6][2:])
        out = run_scene(s)
        first = next(i for i, t in enumerate(out.ticks) if any(c.id == o.id for c in (t.collisions or ())))
        assert first == (k - 1 if p[3] == "ace" else k), s.name
        checked += 1
    assert checked >= 3


def _rotate(q, v):
    w, x, y, z = q
    u = np.array([x, y, z])
    v = np.array(v, dtype=float)
    return v + 2 * np.cross(u, np.cross(u, v) + w * v)


def test_carry_scenes_hold_children_at_their_holders_locations_and_stay_valid():
    from acconform.scene import validate_scene

    scenes = _draw(60, 13, "carry")
    kinds, carriers = set(), set()
    for s in scenes:
        assert validate_scene(s) == s and Scene.from_json(json.loads(s.dumps())) == s
        p = s.name.split(":")
        carriers.add(p[2])
        kinds |= {k.split("-")[0] for k in p[6].split("/")}
        ids = [MOVER_ID] + [o.id for o in s.others]
        children = [o for o in s.others if o.parent is not None]
        assert 1 <= len(children) <= 2
        for c, kind in zip(children, p[6].split("/")):  # its holder comes first, and holds the location unless "missing"
            assert ids.index(c.parent.id) < ids.index(c.id) and c.begin is None
            holder = s.mover if c.parent.id == MOVER_ID else next(o for o in s.others if o.id == c.parent.id)
            assert getattr(holder, "parent", None) is None
            if "-frame" in kind:  # the frame form: part 0 (a part0 child) or part 1 (refused), no location
                assert c.parent.part == (0 if kind.startswith("part0") else 1) and c.parent.frame is not None
                continue
            hold = [h for h in holder.holding_locations if h.location == c.parent.location]
            assert (not hold) if kind.startswith("missing") else hold[0].part == 0 if kind.startswith("part0") else hold[0].part >= 1
        # a child's only inputs are the handing arm's (unparent, parent: HANDINGS), and only with its name's suffix
        moved = [o for t in s.ticks.steps for o in t.others if o.id in {c.id for c in children}]
        assert all(o.unparent or o.parent is not None for o in moved) and bool(moved) == ("@" in s.name)
        assert all(o.velocity is None and o.state is None for o in moved)
    assert carriers == {"mover", "monster", "player", "creature"} and kinds == {"position", "part0", "missing"}


def test_carry_scenes_move_a_child_at_a_tick_in_every_handing_way_and_stay_valid():
    """HANDINGS: a child dropped (unset_parent), dropped and picked up again, moved to another location of its
    holder, handed to the other holder; the input at the tick its name says."""
    hows = set()
    for s in _draw(80, 17, "carry"):
        if "@" not in s.name:
            continue
        how, at = re.search(r":(drop-pick|drop|other-hand|hand-over)@(\d+)", s.name).groups()
        hows.add(how)
        first = next(o for o in s.others if o.parent is not None)
        row = {o.id: o for o in s.ticks.steps[int(at)].others}
        assert first.id in row and (row[first.id].unparent == how.startswith("drop"))
        assert (row[first.id].parent is not None) == (how in ("other-hand", "hand-over"))
    assert hows == {"drop", "drop-pick", "other-hand", "hand-over"}


def test_a_drawn_carry_scene_s_child_follows_its_walking_holder_in_the_port():
    """A child held past its holder's parts sits at the holder's frame combined with the holding frame, every tick:
    as the holder walks, the child's origin moves with it."""
    from acconform.port.run import run_scene

    f = np.float32
    checked = 0
    for s in _draw(160, 21, "carry"):
        p = s.name.split(":")
        if p[2] != "mover" or not p[3].startswith("walk") or p[5] != "1c" or p[6] != "position" or "@" in s.name:
            continue
        child = next(o for o in s.others if o.parent is not None)
        hold = next(h for h in s.mover.holding_locations if h.location == child.parent.location)
        out = run_scene(s)
        assert out.error is None, s.name
        seen = []
        for t in out.ticks:
            c = next(o for o in t.others if o.id == child.id)
            if c.cell >> 16 != t.cell >> 16:
                continue
            want = np.array(t.origin) + _rotate(t.orientation, hold.frame.origin)
            assert np.allclose(c.origin, want, atol=1e-3), (s.name, c.origin, want)
            seen.append((t.origin, c.origin))
        assert seen[0][0] != seen[-1][0] and seen[0][1] != seen[-1][1], s.name  # both moved
        checked += 1
    assert checked >= 3


def test_movers_scenes_are_the_same_for_a_seed():
    assert [s.dumps() for s in _draw(20, 77)] == [s.dumps() for s in _draw(20, 77)]
    assert [s.dumps() for s in _draw(10, 78, "carry")] == [s.dumps() for s in _draw(10, 78, "carry")]


def test_the_movers_kind_is_a_campaign_kind_the_port_runs():
    from acconform.errors import AcconformError
    from acconform.impl import BuiltinPort
    from acconform.strategies import check_kinds, sample_scenes

    assert check_kinds("movers") == ("movers",) and "movers" in BuiltinPort.kinds
    assert all(s.others for s in sample_scenes(("movers",), 5, 1))
    with pytest.raises(AcconformError, match="unknown scene kind 'mover' .*movers"):
        check_kinds("mover")


def _world(n: int, seed: int, arm: str):
    from hypothesis import strategies as st

    from acconform.strategies import ticks as tk
    from acconform.strategies.determinism import pinned_constants
    from acconform.strategies.fast_draw import FastDrawer
    from acconform.strategies.movers import draw_world_arm

    with pinned_constants():
        drawer = FastDrawer(st.composite(lambda draw: draw_world_arm(draw, tk._clock, arm))(), seed)
        return [s for s in (drawer.draw()[0] for _ in range(n)) if s.name.split(":")[2] != "none"]


def test_world_arms_change_what_their_names_say_and_stay_valid():
    from acconform.flags import PhysicsState

    for arm in ("hidden-holder", "static-other", "frame-minus-one", "frame-unlaunched", "emitter-child", "off-cell",
                "static-mover"):
        scenes = _world(12, 67, arm)
        assert scenes, arm
        for s in scenes:
            assert s.name.startswith(f"world:{arm}:") and validate_scene(s) == s
            assert Scene.from_json(json.loads(s.dumps())) == s
            holders = {MOVER_ID: s.mover, **{o.id: o for o in s.others}}
            children = [o for o in s.others if o.parent is not None]
            if arm == "hidden-holder":  # a Hidden holder whose child a tick moves
                moved = {o.id for st_ in s.ticks.steps for o in st_.others if o.unparent or o.parent is not None}
                assert any(c.id in moved and holders[c.parent.id].state & PhysicsState.Hidden for c in children)
            elif arm == "static-other":
                assert any(o.state & PhysicsState.Static for o in s.others if o.parent is None)
            elif arm == "frame-minus-one":
                assert any(c.parent.part == -1 for c in children)
            elif arm == "frame-unlaunched":  # held by a projectile by the frame form
                assert any(c.parent.frame is not None and holders[c.parent.id].launch is not None for c in children)
            elif arm == "emitter-child":
                assert any(c.state & PhysicsState.ParticleEmitter for c in children)
            elif arm == "off-cell":  # a RequestPos naming the next cell along y, its origin still in the mover's
                assert s.ticks.driver == "request_pos" and s.ticks.steps[-1].request_pos.cell == s.mover.begin.cell + (
                    1 if (s.mover.begin.cell & 0xFFFF) % 8 else -1)
            else:
                assert s.mover.state & PhysicsState.Static and s.mover.motion_table is not None
