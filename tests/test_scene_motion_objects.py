"""Objects with a motion table and the server's ExecuteMotion (scene/8 `others[].motion_table` and
`ticks.steps[].others[].execute_motion`, feature objects.motion_tables): the JSON form, its refusals, the pack, and
what the port does with them (ACE's answers for such scenes are shard ticks-0072's)."""

from __future__ import annotations

import copy
import struct
from dataclasses import replace

import pytest

from acconform.errors import InvalidScene
from acconform.motion_enums import MotionCommand as MC
from acconform.motion_scene import MOTION_TABLE_ID
from acconform.protocol import scene_features
from acconform.scene import OtherInputs, Scene


@pytest.fixture(scope="module")
def drawn():
    """The first scene benchmarks/motion_objects_scenes.py draws with an object of the table executing motions."""
    from hypothesis import strategies as st

    from strategies.determinism import pinned_constants
    from strategies.fast_draw import FastDrawer
    from strategies.motion import draw_motion_objects
    from strategies.ticks import _clock

    @st.composite
    def objects(draw):
        return draw_motion_objects(draw, _clock)

    drawer = FastDrawer(objects(), 72 * 1000003)
    with pinned_constants():
        for _ in range(40):
            s = drawer.draw()[0]
            if any(o.motion_table and o.weenie == "object" for o in s.others) and any(
                    i.execute_motion is not None for step in s.ticks.steps for i in step.others):
                return s
    raise AssertionError("no drawn scene has an object with the table executing a motion")


def _first_execute(scene: Scene) -> tuple[int, int]:
    return next((k, j) for k, step in enumerate(scene.ticks.steps) for j, i in enumerate(step.others)
                if i.execute_motion is not None)


def test_an_object_with_the_table_and_its_executed_motions_round_trip_through_json(drawn):
    again = Scene.from_json(copy.deepcopy(drawn.to_json()))
    assert again == drawn
    doc = drawn.to_json()
    assert any(o.get("motion_table") is True for o in doc["others"])
    k, j = _first_execute(drawn)
    assert doc["ticks"]["steps"][k]["others"][j]["execute_motion"].startswith("0x")


def test_a_scene_with_either_field_needs_objects_motion_tables_and_one_without_does_not(drawn):
    assert "objects.motion_tables" in scene_features(drawn)
    plain = drawn.replace(others=tuple(replace(o, motion_table=False) for o in drawn.others),
                          ticks=replace(drawn.ticks, steps=tuple(
                              replace(s, others=tuple(replace(i, execute_motion=None) for i in s.others))
                              for s in drawn.ticks.steps)))
    assert "objects.motion_tables" not in scene_features(plain)


def test_execute_motion_of_ready_is_refused_naming_the_field(drawn):
    doc = drawn.to_json()
    k, j = _first_execute(drawn)
    doc["ticks"]["steps"][k]["others"][j]["execute_motion"] = f"0x{int(MC.Ready):08X}"
    with pytest.raises(InvalidScene, match=r"execute_motion.*no physics for Ready"):
        Scene.from_json(doc)


def test_an_others_motion_table_is_refused_when_the_mover_has_none(drawn):
    doc = drawn.to_json()
    del doc["mover"]["motion_table"]
    for step in doc["ticks"]["steps"]:  # the mover's own motion inputs need its table too
        for name in ("motion", "stop", "do_motion", "stop_motion", "move_to", "move_to_object", "turn_to_heading",
                     "turn_to_object"):
            step.pop(name, None)
    with pytest.raises(InvalidScene, match=r"motion_table.*the mover has none"):
        Scene.from_json(doc)


def test_a_projectile_has_no_motion_table(drawn):
    doc = drawn.to_json()
    o = next(o for o in doc["others"] if o.get("motion_table"))
    o["weenie"] = "ammunition"
    with pytest.raises(InvalidScene, match=r"motion_table|launch"):
        Scene.from_json(doc)


def test_the_pack_carries_the_table_id_and_the_executed_command_under_mask_bit_11(drawn):
    from acconform.oracle.pack import _other_inputs

    o = next(o for o in drawn.others if o.motion_table)
    assert o.motion_table_id == MOTION_TABLE_ID
    k, j = _first_execute(drawn)
    step = drawn.ticks.steps[k]
    packed = b"".join(_other_inputs(step, {x.id: n for n, x in enumerate(drawn.others)}))
    inputs = step.others[j]
    mask_at = packed.index(struct.pack("<i", [x.id for x in drawn.others].index(inputs.id)), 4)
    (mask,) = struct.unpack_from("<I", packed, mask_at + 4)
    assert mask & 2048 and struct.pack("<I", inputs.execute_motion) in packed


def test_the_port_answers_a_drawn_scene_without_an_error_in_any_tick(drawn):
    from acconform.port.run import run_scene

    out = run_scene(drawn, "exact", runtime="coreclr")
    assert out.ticks and all(t.error is None for t in out.ticks)
    assert all(t.others is not None for t in out.ticks)


def test_a_non_creature_with_the_table_sets_no_velocity_when_it_enters_its_default_state_and_a_creature_does(drawn):
    """MotionInterp.LeaveGround returns for a WeenieObject that is no creature: enter_default_state (run by
    MakeMovementManager, from SetMotionTableID) sets no velocity on a GenericObject, so it stays not Active there; the
    player's (a creature with Gravity) sets its leave-ground velocity."""
    from acconform.port import physics_obj as po
    from acconform.port.run import run_scene

    calls = {}
    made, set_velocity = po.PhysicsObj.make_movement_manager, po.PhysicsObj.set_velocity
    inside = []

    def spy_made(self, init_motion):
        inside.append(self)
        try:
            made(self, init_motion)
        finally:
            inside.pop()

    def spy_velocity(self, *args):
        if inside and inside[-1] is self:
            calls[self.weenie_obj.is_creature] = calls.get(self.weenie_obj.is_creature, 0) + 1
        return set_velocity(self, *args)

    po.PhysicsObj.make_movement_manager, po.PhysicsObj.set_velocity = spy_made, spy_velocity
    try:
        run_scene(drawn, "exact", runtime="coreclr")
    finally:
        po.PhysicsObj.make_movement_manager, po.PhysicsObj.set_velocity = made, set_velocity
    assert calls.get(True, 0) >= 1 and calls.get(False, 0) == 0
