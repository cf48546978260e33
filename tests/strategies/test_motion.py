"""The tick policy motion (strategies/motion.py, issue 40): drawn motion tables and MoveToState keys."""

from __future__ import annotations

import re
from collections import Counter

import pytest

from acconform.motion_enums import HoldKey, MotionCommand as MC
from acconform.port.run import run_scene
from acconform.protocol import scene_features
from acconform.scene import validate_scene
from acconform.staging import MOVER_ID
from acconform.strategies import sample_scenes
from acconform.strategies import ticks as tk

N = 120


@pytest.fixture(scope="module")
def motion_scenes():
    """N motion scenes drawn as a campaign draws them (FastDrawer: each choice uniform, seed 40), so the
    shares below are the policy's own, not Hypothesis's preference for small choices."""
    from hypothesis import strategies as st

    from acconform.strategies.determinism import pinned_constants
    from acconform.strategies.fast_draw import FastDrawer

    with pinned_constants():
        drawer = FastDrawer(st.composite(lambda draw: tk.draw_tick_scene(draw, None, "motion"))(), 40)
        return [drawer.draw()[0] for _ in range(N)]


def _inputs(scenes):
    return [s.motion for sc in scenes for s in sc.ticks.steps if s.motion is not None]


def test_every_motion_scene_validates_has_a_table_and_starts_with_a_motion_or_manager_input(motion_scenes):
    first_inputs = ("motion", "do_motion", "move_to", "move_to_object", "turn_to_heading", "turn_to_object")
    for s in motion_scenes:
        assert validate_scene(s) == s
        if s.mover.motion_table is None:  # a queried scene's mover without a table (draw_motion_queries' TABLELESS)
            assert ":tableless" in s.name and s.motion_queries
        else:
            assert any(getattr(s.ticks.steps[0], name) is not None for name in first_inputs)
        assert s.ticks.driver == "update_object" and s.name.startswith("ticks:motion:")


def test_about_half_the_motion_scenes_drive_the_managers_with_every_input_and_stop(motion_scenes):
    managed = [s for s in motion_scenes if ":managed:" in s.name]
    assert 0.3 * N < len(managed) < 0.7 * N
    steps = [st for s in managed for st in s.ticks.steps]
    for name in ("move_to", "move_to_object", "turn_to_heading", "turn_to_object", "do_motion", "stop_motion"):
        assert any(getattr(st, name) is not None for st in steps), name
    assert {st.stop for st in steps} >= {"stop_completely", "cancel_moveto", "move_to_manager_cancel"}
    sticky = [st.move_to_object for st in steps if st.move_to_object is not None and st.move_to_object.params.flags & 0x80]
    assert sticky
    exact = [s for s in managed if ":move_to_exact" in s.name]
    assert exact


def test_turn_and_sidestep_cycles_are_allowed_only_from_the_default_substate(motion_scenes):
    """Bitfield bit 2 on them: else ACE's GetObjectSequence and re_modify recurse until its stack overflows."""
    cycles = [c for s in motion_scenes if s.mover.motion_table is not None for c in s.mover.motion_table.cycles
              if c.motion in (int(MC.TurnRight), int(MC.SideStepRight))]
    assert cycles and all(c.data.bitfield & 2 for c in cycles)


def test_the_keys_cover_forward_backward_run_sidestep_turn_hold_keys_and_stops(motion_scenes):
    ins = _inputs(motion_scenes)
    forwards = Counter(m.forward for m in ins)
    assert {int(MC.WalkForward), int(MC.WalkBackwards), int(MC.RunForward)} <= set(forwards)
    assert {int(MC.SideStepRight), int(MC.SideStepLeft)} <= {m.sidestep for m in ins}
    assert {int(MC.TurnRight), int(MC.TurnLeft)} <= {m.turn for m in ins}
    assert {int(HoldKey.Run), int(HoldKey.None_)} <= {m.hold_key for m in ins}
    assert any(not (m.forward or m.sidestep or m.turn) for m in ins)  # a stop
    assert len({m.forward_speed for m in ins}) > 3


def test_tables_vary_links_modifiers_and_framerates(motion_scenes):
    tables = [s.mover.motion_table for s in motion_scenes if s.mover.motion_table is not None]
    assert any(t.links for t in tables) and any(t.modifiers for t in tables) and any(not t.modifiers for t in tables)
    rates = {a.framerate for t in tables for e in t.cycles for a in e.data.anims}
    assert len(rates) >= 5


def test_some_tables_play_an_animation_from_a_frame_before_the_first(motion_scenes):
    """One AnimData in 40 has a negative LowFrame (set_animation_id keeps it): its frames before 0 have no
    PartFrame, what get_part_frame's range test and execute_hooks' null arm need (shard ticks-0064)."""
    refs = [a for s in motion_scenes for t in (s.mover.motion_table,) if t is not None  # a queried scene may have none
            for e in (*t.cycles, *t.links, *t.modifiers) for a in e.data.anims]
    negative = [a for a in refs if a.low_frame < 0]
    assert negative and {a.low_frame for a in negative} <= {-1, -2, -5}
    assert len(negative) < len(refs) / 10


def test_a_ticks_campaign_draws_motion_scenes():
    names = [s.name for s in sample_scenes(("ticks",), 200, 40)]
    assert any(n.startswith("ticks:motion:") for n in names)


def test_the_port_runs_motion_scenes_and_a_walk_moves_the_mover(motion_scenes):
    moved = 0
    for s in motion_scenes[:30]:
        out = run_scene(s)
        last = out.ticks[-1]
        moved += last.origin != s.mover.begin.frame.origin or last.cell != s.mover.begin.cell
    assert moved >= 10


def test_the_players_skills_are_drawn_default_or_at_the_values_where_aces_formulas_change(motion_scenes):
    """mover.skills (scene/8): the database-free Player's in about half the scenes, else a run skill of 0, below or
    at GetRunRate's 800, a stamina of 0 now and then, and the burden's boundaries among the loads."""
    from acconform.scene import DEFAULT_SKILLS, FORMAT

    skills = [sc.mover.skills for sc in motion_scenes]
    drawn = [s for s in skills if s != DEFAULT_SKILLS]
    assert 0.3 < len(drawn) / len(skills) < 0.7
    runs = {s.run for s in drawn}
    assert any(r >= 800 for r in runs) and any(0 < r < 800 for r in runs)
    assert any(s.stamina == 0 for s in drawn) and any(s.encumbrance_val in (15000, 30000) for s in drawn)
    assert all(sc.format == FORMAT for sc in motion_scenes if sc.mover.skills != DEFAULT_SKILLS)


# ---------------------------------------------------------------- a moving target (draw_managed_chase)

@pytest.fixture(scope="module")
def chase_scenes():
    """80 scenes of the campaign kind targets (draw_managed_chase), as `acconform record --kinds targets` draws them."""
    return list(sample_scenes(("targets",), 80, 49))


def test_the_targets_kind_is_offered_only_to_an_implementation_with_motion_moving_others_and_targets():
    from acconform.impl import BuiltinPort
    from acconform.protocol import Implementation
    from acconform.strategies import DEFAULT_KINDS, check_kinds

    assert check_kinds("targets") == ("targets",) and "targets" in BuiltinPort.kinds
    assert "targets" not in DEFAULT_KINDS  # drawn only when named, as missiles are
    need = ["ticks", "mover.motion", "objects.moving", "objects.targets"]
    for lacking in need:
        impl = object.__new__(Implementation)
        impl.hello = {"kinds": ["terrain"], "features": [f for f in need if f != lacking]}
        assert "targets" not in impl.kinds, lacking
    impl.hello = {"kinds": ["terrain"], "features": need}
    assert "targets" in impl.kinds


def test_targets_scenes_hold_float32s_only_so_their_json_round_trip_is_exact(chase_scenes):
    import json

    from acconform.scene import Scene

    for sc in chase_scenes:  # a double in a scene (0.6, not 0.6f) changes its text, and its key, on re-reading
        text = json.dumps(sc.to_json())
        assert json.dumps(Scene.from_json(json.loads(text)).to_json()) == text, sc.name


def test_a_targets_scene_needs_objects_targets_and_runs_in_either_engine_mode():
    from hypothesis import strategies as st

    from acconform.protocol import scene_features
    from acconform.strategies.determinism import pinned_constants
    from acconform.strategies.fast_draw import FastDrawer
    from acconform.strategies.scenes import scenes_of

    with pinned_constants():
        drawer = FastDrawer(scenes_of("targets"), 7)
        drawn = []
        while len(drawn) < 200 and (len(drawn) < 20 or len({sc.engine_mode for sc in drawn}) < 2):
            drawn.append(drawer.draw()[0])  # a few in ten are in client mode: draw until both modes are seen
    assert all("objects.targets" in scene_features(sc) for sc in drawn)
    assert {sc.engine_mode for sc in drawn} == {"server", "client"}


def test_every_chase_scene_validates_and_aims_the_servers_calls_at_its_moving_other(chase_scenes):
    from acconform.protocol import scene_features

    for sc in chase_scenes:
        validate_scene(sc)
        assert len(sc.others) == 1 + (":switch@" in sc.name) and "objects.targets" in scene_features(sc), sc.name
        first = sc.ticks.steps[0]
        if first.turn_to_heading is not None:  # wrap_turn: a turn in place first, then the target from tick 1
            assert ":wrap_turn" in sc.name and sc.mover.begin.frame.orientation == (1.0, 0.0, 0.0, 0.0), sc.name
            first = sc.ticks.steps[1]
            if first.move_to_object is None or first.move_to_object.object == MOVER_ID:
                assert any(o.destroy for o in first.others), sc.name
                continue
        aims = [first.stick_to] + [m.object for m in (first.move_to_object, first.turn_to_object) if m is not None]
        assert sc.others[0].id in aims, sc.name
        assert set(aims) - {None, sc.others[0].id} <= {MOVER_ID}, sc.name  # self_first: a MoveTo at itself before


def test_some_chase_scenes_take_the_legacy_player_path_always_in_server_mode(chase_scenes):
    """The driver request_pos (update_object_server: UpdateObjectInternalServer runs the mover's managers), the
    client's reports walking toward the target; a client-mode PhysicsObj has no RequestPos, so never client mode."""
    legacy = [sc for sc in chase_scenes if sc.ticks.driver == "request_pos"]
    assert 5 <= len(legacy) < len(chase_scenes) / 2
    assert all(sc.engine_mode == "server" and ":request_pos" in sc.name for sc in legacy)
    assert all(s.request_pos is not None for sc in legacy for s in sc.ticks.steps)


def test_chase_scenes_draw_every_goal_target_walk_and_a_destroyed_target(chase_scenes):
    names = " ".join(sc.name for sc in chase_scenes)
    for part in (":move_to_object:", ":sticky:", ":turn_to_object:", ":stick", ":no-table", "destroyed@", ":stand:",
                 ":away", ":toward", ":across", ":stopgo", ":monster", ":charge", ":ranged", ":drawn", ":backoff",
                 ":wrap_turn"):
        assert part in names, part
    steps = [s for sc in chase_scenes for s in sc.ticks.steps]
    assert {s.stop for s in steps} >= {"stop_completely", "cancel_moveto", "move_to_manager_cancel"}
    # nothing is aimed at a target after the server destroyed it but a melee swing's stick_to (stick_gone)
    assert "+stick_gone@" in names
    for sc in chase_scenes:
        gone = next((i for i, s in enumerate(sc.ticks.steps) if any(o.destroy for o in s.others)), None)
        if gone is not None:  # but the mover's own aims, and a TurnToObject at the gone target (turn_at_gone)
            after = [m for s in sc.ticks.steps[gone:] for m in (s.move_to_object, s.turn_to_object) if m is not None]
            others = {MOVER_ID} | {o.id for o in sc.others[1:]}  # itself, or the next target (switch)
            assert all(m.object in others for m in after) or ":turn_at_gone@" in sc.name, sc.name
            sticks = [i for i, s in enumerate(sc.ticks.steps) if i >= gone and s.stick_to not in (None, MOVER_ID)]
            assert all(i > gone and f"+stick_gone@{i}:" in sc.name for i in sticks), sc.name


def test_some_chase_scenes_aim_at_the_mover_itself_at_their_gone_target_or_chase_without_a_motion_table(chase_scenes):
    """The later aims picked by the scene's name (LATER_AIMS): a MoveToObject, a TurnToObject or a stick_to at the
    mover's own id, a TurnToObject at a target the server destroyed; and a tableless mover's MoveTo or turn first."""
    names = " ".join(sc.name for sc in chase_scenes)
    for part in (":self_move_to_object@", ":self_turn_to_object@", ":self_stick@", ":tableless_"):
        assert part in names, part
    for sc in chase_scenes:
        own = [s for s in sc.ticks.steps if MOVER_ID in (s.stick_to, *(m.object for m in (s.move_to_object, s.turn_to_object) if m))]
        assert bool(own) == bool(re.search(r":self_(move_to_object|turn_to_object|stick|first)@", sc.name)), sc.name
        if ":tableless_" in sc.name:
            assert sc.mover.motion_table is None and "objects.targets" in scene_features(sc), sc.name


def test_the_port_takes_the_managers_arms_of_an_aim_at_itself_and_of_a_tableless_chase(chase_scenes):
    """A MoveTo or turn at the mover itself ends at once (MoveToObject's CleanUp, no set_target); a tableless mover's
    MoveToObject makes its MovementManager (ACE's common block), which clears Active."""
    import dataclasses

    from acconform.motion_scene import MovementParams, ObjectMoveInput

    sc = next(sc for sc in chase_scenes if sc.mover.motion_table is not None and sc.ticks.driver == "update_object"
              and len(sc.ticks.steps) >= 3)
    steps = list(sc.ticks.steps)
    steps[1] = dataclasses.replace(steps[1], move_to_object=ObjectMoveInput(MOVER_ID, MovementParams()),
                                   turn_to_object=None, stop=None)
    ticks = run_scene(sc.replace(ticks=dataclasses.replace(sc.ticks, steps=tuple(steps)))).ticks
    assert not any(t.error for t in ticks) and not ticks[1].motion.is_moving_to
    tableless = next(sc for sc in chase_scenes if ":tableless_" in sc.name)
    validate_scene(tableless)
    out = run_scene(tableless)
    assert out.error is None and len(out.ticks) == len(tableless.ticks.steps)


def test_the_port_runs_chase_scenes_and_a_sticky_follower_moves(chase_scenes):
    moved = 0
    for sc in chase_scenes[:12]:
        ticks = run_scene(sc).ticks
        assert len(ticks) == len(sc.ticks.steps) and not any(t.error for t in ticks), sc.name
        moved += ticks[-1].origin != ticks[0].origin
    assert moved


def test_the_keys_carry_styles_and_the_substates_actions_and_emotes_a_client_may_send(motion_scenes):
    """RawMotionState.SetState's and MotionInterp.DoMotion's arms for a style (a combat style the table lacks:
    DoMotion's combat refusals) and a forward command that is no walk (Crouch, Sitting, Sleeping: the
    refusals and motion_allows_jump; Dead, Falling; an action or emote)."""
    ins = _inputs(motion_scenes)
    assert {int(MC.HandCombat), int(MC.Magic)} & {m.style for m in ins}
    odd = {int(MC.Crouch), int(MC.Sitting), int(MC.Sleeping), int(MC.Dead), int(MC.Falling), int(MC.Reload),
           int(MC.Cheer), int(MC.Twitch1)}
    assert len(odd & {m.forward for m in ins}) >= 2
    keys = {st.do_motion.motion for s in motion_scenes for st in s.ticks.steps if st.do_motion is not None}
    assert keys & {int(MC.Crouch), int(MC.Sitting), int(MC.Sleeping), int(MC.HandCombat), int(MC.Dead)}


def test_some_tables_have_actions_and_some_managed_scenes_ask_for_them_on_successive_ticks(motion_scenes):
    """Links from Ready to Twitch1 and Cheer (retail's tables keep actions as links): the actions' arms of
    Raw- and InterpretedMotionState (AddAction, RemoveAction as MotionDone ends one) and DoMotion's
    TooManyActions once six are pending."""
    actions = {int(MC.Twitch1), int(MC.Cheer)}
    with_actions = [s for s in motion_scenes if s.mover.motion_table is not None
                    and actions <= {e.to for e in s.mover.motion_table.links}]
    assert 0.2 * N < len(with_actions) < 0.8 * N
    bursts = [s for s in motion_scenes if ":actions+x" in s.name]
    assert bursts
    assert all(s.ticks.steps[0].do_motion.motion in actions for s in bursts)
    assert max(sum(st.do_motion is not None for st in s.ticks.steps) for s in bursts) >= 2


@pytest.fixture(scope="module")
def layer_scenes():
    """60 scenes of draw_motion_layer_ticks (MotionInterp's rarer arms, ticks-0065), drawn as its benchmark does."""
    from hypothesis import strategies as st

    from acconform.strategies import draws as dr
    from acconform.strategies.determinism import pinned_constants
    from acconform.strategies.fast_draw import FastDrawer
    from acconform.strategies.motion import draw_motion_layer_ticks
    from acconform.strategies.scenes import draw_scene

    @st.composite
    def layer(draw):
        kind, sub = draw(st.sampled_from(tk.SITES["motion"]))
        return draw_motion_layer_ticks(draw, draw_scene(draw, kind, sub), tk._clock).replace(engine_mode=draw(dr.ENGINE_MODES))

    with pinned_constants():
        drawer = FastDrawer(layer(), 65)
        return [drawer.draw()[0] for _ in range(60)]


def test_layer_scenes_clear_gravity_refuse_in_combat_press_keys_and_leave_some_movers_without_a_table(layer_scenes):
    from acconform.scene import TABLELESS_INPUTS

    arms = Counter(s.name.split(":layer:")[1].split(":")[0].split("+")[0] for s in layer_scenes)
    assert set(arms) == {"float", "refusal", "keys", "tableless", "modifier"}
    for s in layer_scenes:
        assert validate_scene(s) == s
        steps = s.ticks.steps
        if ":layer:float" in s.name:
            assert any(st.state is not None and not st.state & 0x400 for st in steps)  # Gravity cleared at a tick
        if ":layer:refusal" in s.name:
            assert steps[0].motion.style in (int(MC.HandCombat), int(MC.SwordCombat), int(MC.Magic))
            assert any(st.do_motion is not None and st.do_motion.motion in (int(MC.Sleeping), int(MC.Crouch), int(MC.Sitting),
                                                                             int(MC.Cheer)) for st in steps)
        if ":layer:modifier" in s.name:  # a modifier that is no substate, in the table and pressed
            pure = {int(MC.Jump), int(MC.StopTurning)}
            assert any(e.motion in pure for e in s.mover.motion_table.modifiers)
            assert any(st.do_motion is not None and st.do_motion.motion in pure or st.stop_motion is not None
                       and st.stop_motion.motion in pure for st in steps)
        if ":layer:tableless" in s.name:
            assert s.mover.motion_table is None
            assert all(name in TABLELESS_INPUTS for st in steps for name in ("motion", "stop", "do_motion", "stop_motion",
                                                                              "move_to", "turn_to_heading")
                       if getattr(st, name) is not None)
        else:
            assert s.mover.motion_table is not None


def test_a_share_of_motion_scenes_asks_the_servers_motion_table_queries_of_every_kind(motion_scenes):
    """scene/8 motion_queries (draw_motion_queries): about one motion scene in three, every function, the five-argument
    GetAnimationLength and both DatLoader overloads, speeds of 0, negative and one ulp from 1, a query asked again (the
    static caches' answer), tables with AttackHooks, and now and then a mover without a table (MotionTableId 0)."""
    queried = [s for s in motion_scenes if s.motion_queries]
    assert 0.15 * N < len(queried) < 0.5 * N
    qs = [q for s in queried for q in s.motion_queries]
    from acconform.scene import MOTION_QUERY_FUNCTIONS

    assert {q.function for q in qs} == set(MOTION_QUERY_FUNCTIONS)
    assert any(q.function == "GetAnimationLength" and q.current_motion is not None for q in qs)
    assert {q.current_motion is None for q in qs if q.function == "Dat.GetAnimationLength"} == {True, False}
    speeds = {q.speed for q in qs}
    import numpy as np

    one = np.float32(1.0)
    below, above = (float(np.nextafter(one, np.float32(x))) for x in (0.0, 2.0))
    assert {0.0, -1.5, below, above, None} <= speeds
    assert any(len(set(s.motion_queries)) < len(s.motion_queries) for s in queried)
    assert any(":attacks" in s.name for s in queried)
    assert any(h.hook == "Attack" for s in queried if s.mover.motion_table is not None
               for a in s.mover.motion_table.animations for h in a.hooks)
