"""ACE's own trace on the Python side (fast lane, no ACE): the instrumented ACE's recorder lines turned
into trace records (oracle/instrumented.py), and the comparison with a port-grain trace
(acconform.trace.against_ace)."""

import json
from dataclasses import replace

import pytest

from acconform.oracle.instrumented import FTP, TICK, kind, record_kinds, recorder_table, records_from
from acconform.outcome import ContactPlaneState, NormalState, Outcome, TickState
from acconform.trace import PathState, TraceRecord, against_ace, comparable, is_constructor, run_part

IDS = {0: "Transition.cs:FindTransitionalPosition", 1: "Transition.cs:AdjustOffset", 2: "Transition.cs:CliffSlide",
       3: "PhysicsObj.cs:update_object", 4: "LandDefs.cs:GetBlockOffset", 5: "AFrame.cs:AFrame()"}
PATH = [0x0A240008, [1.0, 2.0, 3.0], 0x0A240008, [1.0, 2.0, 2.5], [0.0, 0.0, -0.5],
        [True, 0x0A240008, False, [0.0, 0.0, 1.0], -2.0], [False, 0, False, [0.0, 0.0, 0.0], 0.0],
        [False, [0.0, 0.0, 0.0]], [True, [1.0, 0.0, 0.0]], None, False, True, False, False, 0, 0x101]
MOVER = [False, 0.0, 0x0A240008, 0x0A240008, [1.0, 2.0, 3.0], [1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0],
         [0.0, 0.0, -9.8], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0], 0x400, 1, 0, [[0.0, 0.0, 1.0], 0.0], [0.0, 0.0, 0.0],
         False, [0x0A240008]]


def line(*fields):
    return json.dumps(list(fields))


def defined(kind: str, snapshot) -> str:
    """The recorder's definition of a snapshot ("#p" a path, "#m" a mover), which records then name by its index."""
    return f"#{kind} " + json.dumps(snapshot) + "\n"


def path(**kw) -> PathState:
    base = PathState(1, (0.0, 0.0, 0.0), 1, (0.0, 0.0, 0.0), (0.0, 0.0, 0.0), ContactPlaneState(), ContactPlaneState(),
                     NormalState(), NormalState(), None, False, False, False, False, 0, 0)
    return replace(base, **kw)


def test_a_recorder_line_becomes_the_record_the_port_writes_with_its_transition_snapshot():
    text = defined("p", PATH) + line(2, "enter", -1, 1, 0, [0, [0.5, -0.0, 1.0]], None, 0, None, -1) + "\n"
    (r,) = records_from(text, IDS)
    assert (r.anchor, r.event, r.tick, r.step, r.within) == ("Transition.cs:CliffSlide", "enter", None, 1, FTP)
    assert r.args == [0, [0.5, -0.0, 1.0]] and str(r.args[1][1]) == "-0.0"
    assert r.path.check_cell == 0x0A240008 and r.path.cur_pos == (1.0, 2.0, 2.5)
    assert r.path.contact_plane == ContactPlaneState(True, 0x0A240008, False, (0.0, 0.0, 1.0), -2.0)
    assert r.path.sliding_normal == NormalState(True, (1.0, 0.0, 0.0)) and r.path.walkable is None
    assert r.path.object_info_state == 0x101 and r.path.step_down and not r.path.step_up


def test_a_step_record_is_named_after_find_transitional_position_whatever_method_opened_it():
    (r,) = records_from(defined("p", PATH) + line(1, "step", -1, 0, 0, None, None, 0, None, -1), IDS)
    assert (r.anchor, r.event, r.step) == (FTP, "step", 0)


def test_a_mover_routine_carries_the_mover_as_a_tick_state():
    (r,) = records_from(defined("m", MOVER) + line(3, "enter", 0, -1, -1, [0x50000001], None, None, 0, -1), IDS)
    assert isinstance(r.mover, TickState) and r.mover.acceleration == (0.0, 0.0, -9.8)
    assert r.mover.shadow_cells == (0x0A240008,) and r.within is None


def test_records_name_each_snapshot_by_its_index_among_the_definitions_of_its_kind():
    other = [0x0A240009] + PATH[1:]
    text = (defined("p", PATH) + defined("m", MOVER) + line(2, "enter", -1, -1, -1, [], None, 0, None, -1) + "\n"
            + defined("p", other) + line(2, "exit", -1, -1, -1, None, None, 1, None, -1) + "\n"
            + line(3, "exit", -1, -1, -1, None, None, None, 0, -1) + "\n" + line(2, "enter", -1, -1, -1, [], None, 0, None, -1))
    a, b, c, d = records_from(text, IDS)
    assert (a.path.check_cell, b.path.check_cell, d.path) == (0x0A240008, 0x0A240009, a.path)
    assert c.mover.cell == 0x0A240008 and c.path is None


def test_a_record_written_while_a_static_is_placed_carries_the_statics_id():
    ids = {**IDS, 6: "PhysicsObj.cs:add_obj_to_cell", 7: "BBox.cs:LocalToGlobal"}
    text = (line(7, "call", -1, -1, 6, [[0.0] * 6], None, None, None, 0x70000000) + "\n"
            + line(6, "call", -1, -1, -1, [0x70000000], None, None, None, 0x70000000) + "\n"
            + line(4, "call", -1, -1, -1, [1, 1], None, None, None, -1))
    a, b, c = records_from(text, ids)
    assert (a.placing, b.placing, c.placing) == (0x70000000, 0x70000000, None)
    assert recorder_table(ids).splitlines()[6] == "mo"  # add_obj_to_cell opens a placement


def test_a_tick_record_takes_the_outcomes_tick_and_a_tick_that_threw_writes_none():
    ticks = (TickState(cell=7), TickState(error="NullReferenceException: x"))
    outcome = Outcome(ticks=ticks)
    text = line(3, "tick", 0, -1, -1, None, None, None, None, -1) + "\n" + line(3, "tick", 1, -1, -1, None, None, None, None, -1)
    (r,) = records_from(text, IDS, outcome)
    assert (r.anchor, r.event, r.tick, r.mover) == (TICK, "tick", 0, ticks[0])


def test_the_recorders_table_gives_each_method_the_ports_record_kind_and_the_calls_that_open_a_step():
    assert [kind(IDS[i]) for i in range(6)] == ["p", "p", "p", "m", "c", "c"]
    assert recorder_table(IDS).splitlines() == ["pf", "pa", "p-", "mu", "c-", "c-"]
    assert (IDS[2], "enter") in record_kinds(IDS) and (IDS[4], "call") in record_kinds(IDS)
    assert (IDS[4], "enter") not in record_kinds(IDS)


def test_constructors_are_known_by_their_anchor():
    assert is_constructor("AFrame.cs:AFrame()") and is_constructor("PlacementType.cs:PlacementType")
    assert is_constructor("BSPTree.cs:BSPTree(DatLoader.Entity.BSPTree, Dictionary<ushort, Polygon>, CVertexArray)")
    assert not is_constructor("AFrame.cs:Combine") and not is_constructor("ACE.DatLoader/Entity/Plane.cs:Unpack")


@pytest.mark.parametrize("a, b, expected", [
    (1.0, 1.0, True), (0, -0.0, True), (True, False, True), ("Transition", 0, False), (None, 1.0, False),
    (True, 1, False), ([1.0], 1.0, False)])
def test_an_argument_is_compared_with_aces_only_where_both_hold_a_value_of_one_shape(a, b, expected):
    assert comparable(True, a, b) is expected
    assert comparable(False, a, b) is False


def rec(anchor, event, p=None, within=None, args=None, result=None, tick=None, step=None, mover=None, placing=None):
    return TraceRecord(anchor, event, tick, step, within, args, result, p, mover, placing)


KINDS = frozenset({("Transition.cs:InitObject", "enter"), ("Transition.cs:InitObject", "exit"),
                   ("Transition.cs:CliffSlide", "enter"), ("Transition.cs:CliffSlide", "exit"),
                   ("LandDefs.cs:GetBlockOffset", "call"), ("AFrame.cs:AFrame()", "call"),
                   ("ObjCell.cs:ObjCell(uint)", "enter"), ("ObjCell.cs:ObjCell(uint)", "exit"),
                   ("ObjCell.cs:Init", "enter"), ("ObjCell.cs:Init", "exit")})


def test_against_ace_names_the_routine_whose_exit_state_differs():
    ace = (rec("Transition.cs:InitObject", "enter", path()), rec("Transition.cs:CliffSlide", "enter", path()),
           rec("Transition.cs:CliffSlide", "exit", path(collide=True)))
    port = ace[:2] + (rec("Transition.cs:CliffSlide", "exit", path(collide=False)),)
    d = against_ace(ace, port, KINDS, ticks=False)
    assert (d.routine, d.field, d.a_value, d.b_value) == ("Transition.cs:CliffSlide", "path.collide", True, False)


def test_against_ace_skips_the_world_building_helper_calls_and_constructors_each_side_orders_its_own_way():
    ace = (rec("LandDefs.cs:GetBlockOffset", "call", result=[0.0, 1.0, 0.0]),  # world building: before the run
           rec("Transition.cs:InitObject", "enter", path()),
           rec("AFrame.cs:AFrame()", "call", within="Transition.cs:InitObject"),
           rec("LandDefs.cs:GetBlockOffset", "call", within="Transition.cs:InitObject", result=[0.0, 0.0, 0.0]),
           rec("Transition.cs:InitObject", "exit", path(step_up=True)))
    port = (rec("PhysicsObj.cs:transition", "enter"), rec("Transition.cs:InitObject", "enter", path()),
            rec("ObjCell.cs:ObjCell(uint)", "enter", path()), rec("ObjCell.cs:Init", "enter", path(), "ObjCell.cs:ObjCell(uint)"),
            rec("ObjCell.cs:Init", "exit", path(), "ObjCell.cs:ObjCell(uint)"), rec("ObjCell.cs:ObjCell(uint)", "exit", path()),
            rec("Transition.cs:InitObject", "exit", path(step_up=True)))
    assert against_ace(ace, port, KINDS, ticks=False) is None
    worse = port[:-1] + (rec("Transition.cs:InitObject", "exit", path(step_up=False)),)
    assert against_ace(ace, worse, KINDS, ticks=False).field == "path.step_up"


def test_against_ace_compares_arguments_only_where_both_sides_pass_the_same_number():
    ace = (rec("Transition.cs:InitObject", "enter", path(), args=["Transition", 1.0]),)
    port = (rec("Transition.cs:InitObject", "enter", path(), args=["LScape", "Transition", 2.0]),)
    assert against_ace(ace, port, KINDS, ticks=False) is None
    port = (rec("Transition.cs:InitObject", "enter", path(), args=["Transition", 2.0]),)
    assert against_ace(ace, port, KINDS, ticks=False).field == "args[1]"


def test_run_part_drops_the_ports_tick_driver_and_what_the_harness_runs_after_the_last_tick():
    records = (rec("LandDefs.cs:GetBlockOffset", "call"), rec("PhysicsObj.cs:set_velocity", "call", tick=0),
               rec(TICK, "tick", tick=0), rec("PhysicsObj.cs:remove_shadows_from_cells", "call", tick=0),
               rec(TICK, "call"))
    assert [r.anchor for r in run_part(records, ticks=True)] == ["PhysicsObj.cs:set_velocity", TICK]


PLACED = 0x70000000
OUTSIDE = "LandCell.cs:add_all_outside_cells(int, List<PhysicsPart>, CellArray, uint)"
PLACING_KINDS = KINDS | {("PhysicsObj.cs:add_obj_to_cell", "call"), ("BBox.cs:LocalToGlobal", "call"),
                         ("BBox.cs:AdjustBBox", "call"), ("AFrame.cs:LocalToGlobal", "call"),
                         ("Polygon.cs:make_plane", "call"), (OUTSIDE, "enter"), (OUTSIDE, "exit"),
                         ("LandCell.cs:add_cell_block", "enter"), ("LandCell.cs:add_cell_block", "exit")}


def placement(*inner):
    """A static's placement as both sides write it: the records inside add_obj_to_cell, then its own call."""
    return tuple(replace(r, placing=PLACED) for r in (
        rec(OUTSIDE, "enter", within="PhysicsObj.cs:add_obj_to_cell", args=[1]), *inner,
        rec("LandCell.cs:add_cell_block", "enter", within=OUTSIDE, args=[20, 19, 20, 20]),
        rec("LandCell.cs:add_cell_block", "exit", within=OUTSIDE),
        rec(OUTSIDE, "exit", within="PhysicsObj.cs:add_obj_to_cell"),
        rec("PhysicsObj.cs:add_obj_to_cell", "call", args=[PLACED, 0x0A240008])))


RUN = (rec("Transition.cs:InitObject", "enter", path()), rec("Transition.cs:InitObject", "exit", path()))
BOX = [[-1.0, -1.0, -1.0, 1.0, 1.0, 1.0], [0x0A240008, 96.0, 96.0, 120.0]]


def test_run_part_reads_the_statics_placement_before_the_run_and_no_other_world_building():
    records = (rec("LandDefs.cs:GetBlockOffset", "call"),) + placement() + RUN
    kept = run_part(records, ticks=False)
    assert kept[0].anchor == OUTSIDE and kept[0].placing == PLACED and len(kept) == len(records) - 1


def test_the_ports_driver_is_no_caller_ace_has_its_records_are_called_from_outside_any_routine():
    records = tuple(replace(r, within="PhysicsObj.cs:transition") for r in RUN)
    assert [r.within for r in run_part(records, ticks=False)] == [None, None]


def test_against_ace_names_the_box_routine_that_carried_fewer_corners_into_the_cell():
    # ACE's LocalToGlobal returns after two corners; the port's goes on to widen the box by the others
    ace = placement(rec("BBox.cs:LocalToGlobal", "call", within=OUTSIDE, args=[[0.0] * 6] + BOX)) + RUN
    port = placement(rec("BBox.cs:AdjustBBox", "call", within="BBox.cs:LocalToGlobal", args=[[0.0] * 6, [1.0, 1.0, 1.0]]),
                     rec("BBox.cs:LocalToGlobal", "call", within=OUTSIDE, args=["BBox"] + BOX)) + RUN
    d = against_ace(ace, port, PLACING_KINDS, ticks=False)
    assert (d.routine, d.a.anchor, d.b.anchor, d.a.placing) == ("BBox.cs:LocalToGlobal", "BBox.cs:LocalToGlobal",
                                                              "BBox.cs:AdjustBBox", PLACED)


def test_against_ace_names_the_placement_routine_that_handed_a_box_routine_another_frame():
    ace = placement(rec("BBox.cs:LocalToGlobal", "call", within=OUTSIDE, args=[[0.0] * 6, BOX[0], [0x0A240008, 12.0, 12.0, 0.0]])) + RUN
    port = placement(rec("BBox.cs:LocalToGlobal", "call", within=OUTSIDE, args=["BBox"] + BOX)) + RUN
    d = against_ace(ace, port, PLACING_KINDS, ticks=False)
    assert (d.routine, d.field, d.a_value, d.b_value) == (OUTSIDE, "args[2][1]", 12.0, 96.0)


def test_a_placements_frame_helpers_are_not_compared_each_side_calls_them_where_its_code_does():
    ace = placement(rec("AFrame.cs:LocalToGlobal", "call", within=OUTSIDE, result=[1.0, 2.0, 3.0])) + RUN
    port = placement(rec("Polygon.cs:make_plane", "call", within=OUTSIDE)) + RUN
    assert against_ace(ace, port, PLACING_KINDS, ticks=False) is None


def test_what_the_ports_tick_driver_calls_is_called_from_outside_any_routine_as_aces_facade_calls_it():
    # server mode: run_ticks calls set_request_pos and update_object_server, where ACE's facade does
    server = (rec("PhysicsObj.cs:set_request_pos", "enter", within=TICK, tick=0),
              rec("PhysicsObj.cs:update_object_server", "enter", within=TICK, tick=0),
              rec("PhysicsObj.cs:UpdateObjectInternalServer", "enter", within="PhysicsObj.cs:update_object_server", tick=0),
              rec(TICK, "tick", tick=0), rec(TICK, "call"))
    assert [r.within for r in run_part(server, ticks=True)] == [None, None, "PhysicsObj.cs:update_object_server", None]
    # client mode: the mover's own update_object, called by the driver, keeps its callees
    client = (rec(TICK, "enter", within=TICK, tick=0), rec("PhysicsObj.cs:UpdateObjectInternal", "enter", within=TICK, tick=0),
              rec("PhysicsObj.cs:UpdateObjectInternal", "exit", within=TICK, tick=0), rec(TICK, "exit", within=TICK, tick=0),
              rec(TICK, "tick", tick=0))
    assert [r.within for r in run_part(client, ticks=True)] == [None, TICK, TICK, None, None]


def test_a_divergence_inside_a_server_tick_names_the_innermost_routine_both_ran_with_the_same_arguments():
    def tick(inner, driver):
        w = TICK if driver else None
        return (rec("PhysicsObj.cs:update_object_server", "enter", within=w, tick=0, args=[1]),
                rec("Transition.cs:TransitionalInsert", "enter", path(), "PhysicsObj.cs:update_object_server", [0, 3], tick=0),
                rec("Transition.cs:StepDown", "enter", path(), "Transition.cs:TransitionalInsert", tick=0),  # both step down
                rec("Transition.cs:StepDown", "exit", path(), "Transition.cs:TransitionalInsert", tick=0),
                *((rec(inner, "enter", path(), "Transition.cs:TransitionalInsert", tick=0),  # then the port slides, ACE returns
                   rec(inner, "exit", path(), "Transition.cs:TransitionalInsert", tick=0)) if inner else ()),
                rec("Transition.cs:TransitionalInsert", "exit", path(), "PhysicsObj.cs:update_object_server", tick=0),
                rec("PhysicsObj.cs:update_object_server", "exit", within=w, tick=0), rec(TICK, "tick", tick=0))
    kinds = frozenset((a, e) for a in ("Transition.cs:StepDown", "Transition.cs:EdgeSlide", "Transition.cs:TransitionalInsert")
                      for e in ("enter", "exit"))
    ace, port = tick(None, False), tick("Transition.cs:EdgeSlide", True) + (rec(TICK, "call"),)
    d = against_ace(ace, port, kinds | {("PhysicsObj.cs:update_object_server", "enter")}, ticks=True)
    assert (d.routine, d.a.anchor, d.a.event, d.b.anchor) == ("Transition.cs:TransitionalInsert",
                                                              "Transition.cs:TransitionalInsert", "exit", "Transition.cs:EdgeSlide")


def test_explain_says_which_static_was_being_placed_where_the_traces_part():
    from acconform.explain import Explanation, render

    ace = placement(rec("BBox.cs:LocalToGlobal", "call", within=OUTSIDE, args=[[0.0] * 6, BOX[0], [0x0A240008, 12.0, 12.0, 0.0]])) + RUN
    port = placement(rec("BBox.cs:LocalToGlobal", "call", within=OUTSIDE, args=["BBox"] + BOX)) + RUN
    d = against_ace(ace, port, PLACING_KINDS, ticks=False)
    lines = render(Explanation("acconform port", "ACE's own trace", True, d, "", ace, port, reference_name="ACE"))
    assert "(placing static 0x70000000, record " in lines[1]
    assert lines[-1].endswith("placing 0x70000000")
