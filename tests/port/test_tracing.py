"""Traces of a port run (port/tracing.py, acconform/trace.py): the same outcome traced or not,
nothing left wrapped after a traced run, a record at every step, insert attempt and tick, records
that survive their JSON, and a first divergence that names the record, field and ulps."""

from __future__ import annotations

import json
from dataclasses import replace
from pathlib import Path

import pytest

from acconform.case import load_document
from acconform.port import anchors
from acconform.port.run import run_scene, traced_run
from acconform.trace import FORMAT, TraceRecord, first_divergence, trace_from_json, trace_to_json

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = {p.stem: load_document(p) for p in sorted((ROOT / "examples").glob("*.json"))}


def scene_of(name):
    doc = EXAMPLES[name]
    return getattr(doc, "scene", doc)


@pytest.mark.anchor("CTransition::find_transitional_position")
@pytest.mark.parametrize("name", sorted(EXAMPLES))
def test_a_traced_run_has_the_outcome_of_an_untraced_one(name):
    outcome, records = traced_run(scene_of(name))
    assert outcome == run_scene(scene_of(name))
    assert records


@pytest.mark.anchor("CEnvCell::UnPack")
def test_a_traced_run_records_the_same_whatever_the_process_built_before_it():
    # the Environments, CellStructs and GfxObjs an earlier run built from the same bytes are not reused
    cold = traced_run(scene_of("two_rooms"))[1]
    run_scene(scene_of("two_rooms"))
    assert traced_run(scene_of("two_rooms"))[1] == cold


@pytest.mark.anchor("CTransition::step_up")
def test_after_a_traced_run_every_anchored_routine_is_its_own_function_again():
    traced_run(scene_of("cliff_edge_slide"))
    from acconform.port.transition.transition import Transition
    from acconform.port.physics_obj import PhysicsObj

    import sys

    def is_wrapper(value):
        raw = getattr(value, "__func__", value)
        return getattr(getattr(raw, "__code__", None), "co_filename", "").endswith("tracing.py") and hasattr(raw, "__wrapped__")

    assert is_wrapper(next(iter(anchors.FUNCTIONS.values()))) is False
    seen = 0
    for mod_name, mod in list(sys.modules.items()):
        if mod_name.startswith("acconform.port"):
            for name, value in vars(mod).items():
                assert not is_wrapper(value), f"{mod_name}.{name} is still wrapped"
                if isinstance(value, type):
                    for attr, v in vars(value).items():
                        seen += 1
                        assert not is_wrapper(v), f"{mod_name}.{name}.{attr} is still wrapped"
    assert seen > 400 and Transition.step_up is anchors.FUNCTIONS[f"{Transition.__module__}.Transition.step_up"]
    assert PhysicsObj.update_object is anchors.FUNCTIONS[f"{PhysicsObj.__module__}.PhysicsObj.update_object"]


@pytest.mark.anchor("CTransition::find_transitional_position")
def test_every_pass_of_the_step_loop_and_every_insert_attempt_writes_a_record_with_its_step():
    scene = scene_of("cliff_edge_slide")
    _, records = traced_run(scene)
    steps = [r for r in records if r.event == "step"]
    assert [r.step for r in steps] == list(range(len(steps))) and len(steps) > 1
    assert all(r.path is not None for r in steps)
    inserts = [r for r in records if r.event == "insert"]
    assert len(inserts) >= len(steps) and all(r.step is not None for r in inserts)
    names = {r.anchor for r in records if r.event == "enter"}
    assert {"Transition.cs:TransitionalInsert", "Transition.cs:AdjustOffset", "Transition.cs:ValidateTransition",
            "Transition.cs:StepDown"} <= names


@pytest.mark.anchor("CPhysicsObj::update_object")
def test_a_tick_scene_writes_one_tick_record_per_tick_with_the_mover_after_it():
    scene = scene_of("tick_walk")
    outcome, records = traced_run(scene)
    ticks = [r for r in records if r.event == "tick"]
    assert [r.mover for r in ticks] == list(outcome.ticks)
    inside = [r for r in records if r.event == "enter" and r.anchor == "PhysicsObj.cs:UpdateObjectInternal"]
    assert inside and {r.tick for r in inside} <= set(range(len(ticks)))
    assert all(r.mover is not None for r in inside)


def test_a_jump_is_traced_with_the_jumpers_state_at_handle_action_jumps_entry_and_exit():
    """Player.HandleActionJump (harness glue, anchored to ACE's method) writes enter and exit records with the
    jumper as a TickState: a PK player's jump while running keeps UpdateTime, so a planted jump bug that sets it
    is named there (tests/runner/explain_mutants.py's motion_jump_update_time_as_ordinary), not a tick later."""
    import sys

    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "oracle"))
    import motion_scenes

    _, records = traced_run(motion_scenes.pk_player_jumps_while_running())
    jump = [r for r in records if r.anchor == "ACE.Server/WorldObjects/Player.cs:HandleActionJump"]
    assert [r.event for r in jump] == ["enter", "exit"]
    enter, exit_ = jump
    assert enter.mover.update_time == exit_.mover.update_time  # FastTick: the mover moves, UpdateTime kept
    assert not exit_.mover.transient_state & 1  # Contact cleared
    assert exit_.mover.velocity != enter.mover.velocity


def test_update_time_is_compared_as_the_double_it_is_even_below_float32s_resolution():
    """ACE's clock is a double: at 123,456,789 s (a float32 ulp of 8 s) a 1/30 s difference in UpdateTime is a
    divergence of the trace, as it is of the outcome (acconform/compare.py), not a tick later in the control flow."""
    import math

    scene = scene_of("tick_walk")
    _, records = traced_run(scene)
    i = next(k for k, r in enumerate(records) if r.mover is not None)
    later = replace(records[i], mover=replace(records[i].mover, update_time=math.nextafter(records[i].mover.update_time, math.inf)))
    d = first_divergence(records, records[:i] + (later,) + tuple(records[i + 1:]))
    assert d is not None and d.field == "mover.update_time" and d.a_position == i


@pytest.mark.anchor("CPhysicsObj::add_obj_to_cell")
@pytest.mark.parametrize("kind, placed", [("obstacles", 0x70000000), ("indoor", 0)])
def test_a_statics_placement_is_traced_each_record_labelled_with_the_static_it_places(kind, placed):
    # an outdoor static keeps the scene's id; a stab of an EnvCell is made by the cell with id 0, as ACE makes it
    from acconform.strategies import sample_scenes

    scene = next(iter(sample_scenes((kind,), 1, 3)))
    _, records = traced_run(scene)
    labelled = [i for i, r in enumerate(records) if r.placing is not None]
    assert {records[i].placing for i in labelled} == {placed}
    # one unbroken run of records per static, ending with add_obj_to_cell's own record; none of the mover's
    assert labelled == list(range(labelled[0], labelled[-1] + 1))
    assert records[labelled[-1]].anchor == "PhysicsObj.cs:add_obj_to_cell"
    assert "PhysicsObj.cs:calc_cross_cells_static" in {records[i].anchor for i in labelled}
    assert all(r.mover is None for r in records if r.placing is not None)
    assert records[-1].placing is None and any(r.path is not None for r in records[labelled[-1] + 1:])


def test_trace_records_survive_their_json():
    _, records = traced_run(scene_of("placement_wall_push"))
    doc = json.loads(json.dumps(trace_to_json(records)))
    assert doc["format"] == FORMAT
    assert trace_from_json(doc) == records


def test_the_first_divergence_names_the_record_the_field_both_values_and_the_ulps():
    _, records = traced_run(scene_of("cliff_edge_slide"))
    assert first_divergence(records, records) is None
    i = next(i for i, r in enumerate(records) if r.event == "exit" and r.anchor == "Transition.cs:StepDown")
    path = records[i].path
    x = path.check_pos[2]
    import numpy as np

    nudged = float(np.nextafter(np.float32(x), np.float32(np.inf)))
    other = list(records)
    other[i] = replace(records[i], path=replace(path, check_pos=(path.check_pos[0], path.check_pos[1], nudged)))
    d = first_divergence(records, other)
    assert (d.index, d.field, d.a_value, d.b_value, d.ulps) == (i, "path.check_pos[2]", x, nudged, 1)
    assert d.routine == "Transition.cs:StepDown"


def test_a_trace_without_sphere_paths_optional_flags_reads_and_is_not_compared_on_them():
    from acconform.trace import OPTIONAL_PATH_FLAGS

    _, records = traced_run(scene_of("placement_wall_push"))
    bare = tuple(replace(r, path=replace(r.path, **dict.fromkeys(OPTIONAL_PATH_FLAGS))) if r.path else r
                 for r in records)
    doc = json.loads(json.dumps(trace_to_json(bare)))
    assert not any(OPTIONAL_PATH_FLAGS & set(r.get("path", {})) for r in doc["records"])
    assert trace_from_json(doc) == bare
    assert first_divergence(records, bare) is None and first_divergence(bare, records) is None


@pytest.mark.anchor("CPhysicsObj::CheckPositionInternal")
def test_a_path_whose_placement_sliding_flag_differs_parts_on_that_flag():
    _, records = traced_run(scene_of("placement_wall_push"))
    i = next(i for i, r in enumerate(records) if r.path is not None and not r.path.placement_allows_sliding)
    other = list(records)
    other[i] = replace(records[i], path=replace(records[i].path, placement_allows_sliding=True))
    d = first_divergence(records, other)
    assert (d.index, d.field, d.a_value, d.b_value) == (i, "path.placement_allows_sliding", False, True)


def test_a_trace_at_the_grain_of_steps_parts_from_the_port_at_the_first_differing_step():
    _, records = traced_run(scene_of("cliff_edge_slide"))
    steps = [r for r in records if r.event == "step"]
    assert first_divergence(records, steps) is None
    late = list(steps)
    late[2] = replace(late[2], path=replace(late[2].path, frames_stationary_fall=7))
    d = first_divergence(records, late)
    assert (d.index, d.step, d.field) == (2, 2, "path.frames_stationary_fall")


def test_a_routine_the_other_side_declares_but_never_ran_is_a_divergence():
    _, records = traced_run(scene_of("cliff_edge_slide"))
    skipped = [r for r in records if r.anchor != "Transition.cs:StepDown"]
    assert first_divergence(records, skipped) is None  # StepDown then is below the other side's grain
    d = first_divergence(records, skipped, frozenset({"Transition.cs:StepDown"}))
    assert d.field == "anchor" and d.a.anchor == "Transition.cs:StepDown"


def test_a_routine_only_the_other_side_entered_parts_where_it_entered_it_in_the_routine_both_were_running():
    from acconform.port.tracing import PATH_FILES, record_kinds

    _, records = traced_run(scene_of("cliff_edge_slide"))
    i = next(i for i, r in enumerate(records) if r.event == "enter" and r.anchor == "Transition.cs:StepDown")
    ran = {r.anchor for r in records}
    never = sorted(a for a, e in record_kinds() if e == "enter" and a not in ran and a.split(":")[0] in PATH_FILES)[0]
    other = records[:i] + (replace(records[i], anchor=never),) + records[i:]
    late = first_divergence(records, other)  # at the port's grain of this run only, the record is not seen
    assert late is None or late.index > i
    d = first_divergence(records, other, reference_kinds=record_kinds())
    assert (d.index, d.field, d.b.anchor) == (i, "anchor", never)
    assert d.routine == records[i].within  # StepDown's caller went on differently


def test_records_that_part_inside_a_callee_name_the_innermost_routine_both_sides_were_still_running():
    _, records = traced_run(scene_of("cliff_edge_slide"))
    i = next(i for i, r in enumerate(records) if r.event == "enter" and r.anchor == "Transition.cs:StepDown")
    j = next(j for j in range(i + 1, len(records)) if records[j].anchor == "Transition.cs:StepDown"
             and records[j].event == "exit")
    inner = next(k for k in range(i + 1, j) if records[k].within != "Transition.cs:StepDown")  # a callee's callee
    other = records[:inner] + records[j:]  # StepDown's body cut short inside a routine it called
    d = first_divergence(records, other)
    assert d.field == "anchor" and d.routine == "Transition.cs:StepDown"


def test_records_that_part_inside_a_routine_handed_different_arguments_name_the_caller_that_handed_them():
    _, records = traced_run(scene_of("cliff_edge_slide"))
    # a routine written as one call record at its exit, after its callees' records: its arguments are seen late
    j = next(j for j, r in enumerate(records) if r.event == "call" and r.args and records[j - 1].within == r.anchor
             and r.within is not None)
    k = j - 1
    while records[k - 1].within == records[j].anchor:
        k -= 1
    stray = replace(records[k], anchor=next(r.anchor for r in records if r.event == "call"
                                           and r.anchor not in (records[k].anchor, records[j].anchor)))
    handed = replace(records[j], args=list(records[j].args) + [1.0])
    other = records[:k] + (stray,) + records[k + 1:j] + (handed,) + records[j + 1:]
    d = first_divergence(records, other)
    assert (d.index, d.field) == (k, "anchor")
    assert d.routine == records[j].within  # not the routine it ran in: the one that called it so


@pytest.mark.anchor("BBox.cs:LocalToGlobal")
def test_a_bounding_box_is_traced_by_its_corners():
    from acconform.port.bbox import BBox
    from acconform.port.tracing import plain
    from acconform.numerics import Vector3

    assert plain(BBox(Vector3(1.0, 2.0, 3.0), Vector3(4.0, 5.0, 6.5))) == [1.0, 2.0, 3.0, 4.0, 5.0, 6.5]


@pytest.mark.anchor("CMotionTable::get_link")
def test_a_motion_link_is_traced_by_its_animations_so_a_link_of_the_wrong_state_parts_where_it_is_looked_up():
    import numpy as np

    from acconform.numerics import Vector3
    from acconform.port.dat.anim_data import AnimData
    from acconform.port.dat.motion_data import MotionData
    from acconform.port.tracing import plain

    def link(anim_id):
        return MotionData(bitfield=1, flags=2, anims=[AnimData(anim_id, 0, -1, np.float32(30.0))],
                          velocity=Vector3(0.0, 0.5, 0.0), omega=Vector3(0.0, 0.0, 0.0))

    assert plain(link(0x03000001)) == [1, 2, [[0x03000001, 0, -1, 30.0]], [0.0, 0.5, 0.0], [0.0, 0.0, 0.0]]
    look_up = TraceRecord("MotionTable.cs:get_link", "call", within="MotionTable.cs:GetObjectSequence",
                          args=[0x3D, 0x41000003, 1.0, 0x45000005, 1.0], result=plain(link(0x03000001)))
    d = first_divergence((look_up,), (replace(look_up, result=plain(link(0x03000002))),))
    assert (d.routine, d.field) == ("MotionTable.cs:get_link", "result[2][0][0]")


def test_a_missing_record_is_a_divergence_of_the_anchor_and_a_short_trace_ends_in_one():
    _, records = traced_run(scene_of("cliff_edge_slide"))
    i = next(i for i, r in enumerate(records) if r.event == "enter" and r.anchor == "Transition.cs:StepDown")
    d = first_divergence(records, records[:i] + records[i + 1:])
    assert d.field == "anchor" and d.index == i and d.a == records[i] and d.b == records[i + 1]
    d = first_divergence(records, records[:i])
    assert d.field == "anchor" and d.b is None and d.index == i and d.a_position >= i


def test_a_trace_names_a_known_event_or_is_refused_naming_the_field():
    from acconform.errors import InvalidScene

    bad = {"format": FORMAT, "records": [{"anchor": "Transition.cs:StepUp", "event": "left"}]}
    with pytest.raises(InvalidScene, match=r"records\[0\]\.event"):
        trace_from_json(bad)


def test_every_anchor_in_a_trace_is_a_registered_ace_method():
    known = {a.ace for a in anchors.load_all().values()}
    _, records = traced_run(scene_of("two_rooms"))
    assert {r.anchor for r in records} <= known
    assert isinstance(records[0], TraceRecord)
