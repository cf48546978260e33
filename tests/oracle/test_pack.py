"""The packed boundary without ACE: the outcome reader builds the same records the dataclasses do."""

import math
import struct

from acconform.outcome import ContactPlaneState, NormalState, Outcome, PlacementState
from acconform.oracle.pack import _OUT, _frozen_maker, pack_scene, unpack_outcome

from .scenes import PROBE


def _cells(cells):
    if cells is None:
        return struct.pack("<i", -1)
    return struct.pack("<i", len(cells)) + b"".join(struct.pack(f"<i{len(c)}I", len(c), *c) for c in cells)


def _placement(p):
    """Facade.WritePlacement: byte 0, or 1 then the placement's fields."""
    """Facade.WritePlacement's bytes, then WriteOtherPlacements' for a scene without other movers (-1)."""
    none = struct.pack("<i", -1)
    if p is None:
        return b"\0" + none
    return b"\1" + struct.pack(f"<iI3f4fIIi{len(p.shadow_cells)}I", p.result, p.cell, *p.origin, *p.orientation,
                                p.cur_cell, p.transient_state, len(p.shadow_cells), *p.shadow_cells) + none


PLACED = PlacementState(2, 0xA9B40100, (63.0, 60.0, 20.0), (1.0, 0.0, 0.0, 0.0), 0, 0x83, (0xA9B40100, 0xA9B40101))


def _packed(cp_normal=(0.0, 0.0, 1.0), sliding=(0.0, 0.0, 0.0), neg=0, cells=(), placement=None):
    vals = (1, 1, 0xA9B40001, 12.5, 12.0, 20.0, 1.0, 0.0, 0.0, 0.0, 0x103,
            1, 0xA9B40001, 0, *cp_normal, -20.0,
            1, 0xA9B40001, 0, 0.0, 0.0, 1.0, -20.0,
            0, 0.0, 0.0, 0.0, 1, *sliding,
            1, 0, 0.0, 0.0, 0.0, 0xA9B40001, 1, 0, neg, 1.5, 12.0, 2, 1, 30.0, 4.5)
    return _OUT.pack(*vals) + _cells(cells) + _placement(placement)


def test_the_fast_record_maker_gives_records_equal_to_the_dataclass_constructor():
    make = _frozen_maker(ContactPlaneState)
    a, b = make(True, 5, False, (0.0, 0.0, 1.0), -20.0), ContactPlaneState(True, 5, False, (0.0, 0.0, 1.0), -20.0)
    assert a == b and hash(a) == hash(b) and type(a) is ContactPlaneState


def test_unpacking_reads_every_field_and_the_facade_counters():
    o, fvp, case, counts = unpack_outcome(bytearray(_packed()))
    assert o == Outcome(ok=True, cell=0xA9B40001, origin=(12.5, 12.0, 20.0), orientation=(1.0, 0.0, 0.0, 0.0),
                        object_info_state=0x103,
                        contact_plane=ContactPlaneState(True, 0xA9B40001, False, (0.0, 0.0, 1.0), -20.0),
                        last_known_contact_plane=ContactPlaneState(True, 0xA9B40001, False, (0.0, 0.0, 1.0), -20.0),
                        collision_normal=NormalState(), sliding_normal=NormalState(True, (0.0, 0.0, 0.0)),
                        collided_with_environment=True, check_cell=0xA9B40001, walkable=True, static_cells=())
    assert (fvp, case, counts) == (1.5, 12.0, (2, 1, 30.0, 4.5))


def test_unpacking_reads_each_statics_cells_in_order():
    cells = ((0xA9B40009, 0xA9B40001, 0xA9B40011), (), (0xA9B3003F,))
    assert unpack_outcome(_packed(cells=cells))[0].static_cells == cells
    assert unpack_outcome(_packed(cells=None))[0].static_cells is None


def test_shared_records_are_keyed_by_bits_so_negative_zero_stays_negative():
    plus = unpack_outcome(_packed(sliding=(0.0, 0.0, 0.0)))[0]
    minus = unpack_outcome(_packed(sliding=(-0.0, 0.0, 0.0)))[0]
    assert math.copysign(1.0, plus.sliding_normal.vector[0]) == 1.0
    assert math.copysign(1.0, minus.sliding_normal.vector[0]) == -1.0
    again = unpack_outcome(_packed(cp_normal=(-0.0, 0.0, 1.0)))[0]
    assert math.copysign(1.0, again.contact_plane.normal[0]) == -1.0 and again.last_known_contact_plane.normal[0] == 0.0
    assert math.copysign(1.0, again.last_known_contact_plane.normal[0]) == 1.0


def test_an_error_outcome_carries_the_message_and_the_counters():
    msg = "NullReferenceException: boom".encode()
    data = (b"\xee" + struct.pack("<i", len(msg)) + msg + struct.pack("<ddiidd", 0.0, 9.0, 1, 0, 5.0, 2.5) + _cells(None)
            + _placement(None))
    o, fvp, case, counts = unpack_outcome(data)
    assert o == Outcome(error="NullReferenceException: boom") and (case, counts) == (9.0, (1, 0, 5.0, 2.5))


def test_unpacking_reads_the_placement_after_the_statics_cells():
    o = unpack_outcome(_packed(cells=((0xA9B40009,),), placement=PLACED))[0]
    assert o.placement == PLACED and o.static_cells == ((0xA9B40009,),) and o.ok
    assert unpack_outcome(_packed())[0].placement is None


def test_a_placement_in_no_cell_unpacks_as_the_default_record_with_velocity_cells_and_placement():
    data = (struct.pack("<B3fd", 2, 0.0, -1.5, 0.25, 0.0) + struct.pack("<diidd", 9.0, 1, 0, 5.0, 2.5)
            + _cells(((0xA9B40001,),)) + _placement(PLACED))
    o, fvp, case, counts = unpack_outcome(data)
    assert o == Outcome(velocity=(0.0, -1.5, 0.25), static_cells=((0xA9B40001,),), placement=PLACED)
    assert (fvp, case, counts) == (0.0, 9.0, (1, 0, 5.0, 2.5))


def test_a_packed_scene_carries_its_placement_after_the_end_position():
    from dataclasses import replace

    from acconform.flags import SetPositionFlags
    from acconform.scene import Placement

    s = PROBE["flat 1-step walk"]
    plain = pack_scene(s)
    placed = pack_scene(s.replace(engine_mode="client", mover=replace(
        s.mover, placement=Placement(int(SetPositionFlags.Slide), True))))
    # then the player's MotionTableId (none) and its PlayerKillerStatus (NPK, 2), then its skills, then the other
    # movers: none
    assert plain[-42:-28] == struct.pack("<BiBII", 0, 0, 0, 0, 2) and plain[-4:] == struct.pack("<i", 0)
    assert placed[-42:-28] == struct.pack("<BiBII", 1, int(SetPositionFlags.Slide), 1, 0, 2)


def test_a_packed_mover_ends_with_its_players_skills_vitals_attributes_and_burden():
    from dataclasses import replace

    from acconform.scene import MoverSkills

    s = PROBE["flat 1-step walk"]
    # the database-free Player's: no skill, Stamina 1, Strength 1, no load, no augmentation; then no other movers
    assert pack_scene(s)[-28:] == struct.pack("<IIIIiii", 0, 0, 1, 1, 0, 0, 0)
    skilled = replace(s.mover, skills=MoverSkills(run=300, jump=250, stamina=0, strength=100, encumbrance_val=-7,
                                                  augmentation_increased_carrying_capacity=-1))
    packed = pack_scene(s.replace(mover=skilled))
    assert packed[-28:-4] == struct.pack("<IIIIii", 300, 250, 0, 100, -7, -1) and packed[:-28] == pack_scene(s)[:-28]


def test_packing_is_deterministic_and_shares_the_height_table_bytes():
    s = PROBE["ramp walk uphill"]
    assert pack_scene(s) == pack_scene(s)
    assert pack_scene(s.replace(land_height_table=tuple(x + 1.0 for x in s.land_height_table))) != pack_scene(s)


def test_a_packed_scene_carries_its_indoor_records_after_its_landblocks():
    from acconform import dat
    from acconform.oracle.pack import PACK_VERSION

    from .indoor_scenes import room_with_static

    scene = room_with_static()
    data = pack_scene(scene)
    version, _server, ticks = struct.unpack_from("<iBB", data)
    pos = 6 + 256 * 4
    (nlb,) = struct.unpack_from("<i", data, pos)
    pos += 4 + nlb * (4 + 252)
    (n,) = struct.unpack_from("<i", data, pos)
    pos += 4
    got = []
    for _ in range(n):
        kind, ident, length = struct.unpack_from("<BIi", data, pos)
        got.append((kind, ident, bytes(data[pos + 9:pos + 9 + length])))
        pos += 9 + length
    want = dat.environment_records(scene) + dat.cell_dat_records(scene)
    assert version == PACK_VERSION == 18 and nlb == 1 and ticks == 0
    assert got == [({"Environment": 2, "EnvCell": 3, "LandblockInfo": 4}[r.kind], r.id, r.data) for r in want]
    assert struct.unpack_from("<i", data, pos) == (1,)  # then the statics, as before
    assert struct.unpack_from("<i", pack_scene(PROBE["flat 1-step walk"]), 6 + 1024 + 4 + 256) == (0,)


def _tick_scene():
    from acconform.case import load_document

    from pathlib import Path

    return load_document(Path(__file__).parents[2] / "examples" / "tick_jump.json")


def test_a_packed_tick_scene_carries_each_steps_absolute_clock_and_inputs_right_after_the_header():
    from dataclasses import replace

    from acconform.flags import PhysicsState, TransientState
    from acconform.scene import Frame, Position, TickStep, Ticks

    scene = _tick_scene()
    scene = replace(scene, ticks=Ticks("request_pos", 1234.5, (
        TickStep(0.1, state=int(PhysicsState.Gravity), velocity=(1.0, 2.0, 3.0), jump=(0.0, 0.5, 4.0),
                 request_pos=Position(0xA9B40001, Frame((12.0, 12.5, 20.0)))),
        TickStep(0.2, transient_state=int(TransientState.Active), local_velocity=(0.0, 1.0, 0.0), omega=(0.0, 0.0, 1.0),
                 sequence_velocity=(0.0, 3.0, 0.0), sequence_omega=(0.0, 0.0, -1.0),
                 request_pos=Position(0xA9B40009, Frame((12.0, 24.5, 20.0), (0.0, 0.0, 0.0, 1.0)))))))
    data = pack_scene(scene)
    t1, t2 = scene.ticks.times()
    assert (t1, t2) == (1234.5 + 0.1, 1234.5 + 0.1 + 0.2)  # the record's double sums, packed as they are
    want = (struct.pack("<BBdi", 1, 1, 1234.5, 2)
            + struct.pack("<dI", t1, 1 | 4 | 32 | 256) + struct.pack("<I", int(PhysicsState.Gravity))
            + struct.pack("<3f3f", 1.0, 2.0, 3.0, 0.0, 0.5, 4.0) + struct.pack("<I3f4f", 0xA9B40001, 12.0, 12.5, 20.0, 1, 0, 0, 0)
            + struct.pack("<i", 0)  # no other mover's inputs
            + struct.pack("<dI", t2, 2 | 8 | 16 | 64 | 128 | 256) + struct.pack("<I", int(TransientState.Active))
            + struct.pack("<12f", 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 3.0, 0.0, 0.0, 0.0, -1.0)
            + struct.pack("<I3f4f", 0xA9B40009, 12.0, 24.5, 20.0, 0, 0, 0, 1) + struct.pack("<i", 0))
    assert data[5:5 + len(want)] == want
    assert data[5 + len(want):5 + len(want) + 1024] == struct.pack("<256f", *scene.land_height_table)
    # the mover has no end: an empty position is packed where a transition scene's end goes
    assert data[-42 - 32:-42] == struct.pack("<I3f4f", 0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0)


def _tick_bytes(t):
    if t.error is not None:
        msg = t.error.encode()
        return b"\1" + struct.pack("<i", len(msg)) + msg
    return b"\0" + _state_bytes(t) + b"\0"  # no other movers


def _state_bytes(t):
    """Facade.WriteState's bytes."""
    from acconform.oracle.pack import _TICK

    return _TICK.pack(t.updated, t.update_time, t.cell, t.cur_cell, *t.origin, *t.orientation, *t.velocity,
                      *t.acceleration, *t.omega, *t.cached_velocity, t.state, t.transient_state,
                      t.contact_plane_cell, *t.contact_plane.normal, t.contact_plane.d, *t.sliding_normal,
                      t.jumped_this_frame, len(t.shadow_cells)) + struct.pack(f"<{len(t.shadow_cells)}I", *t.shadow_cells) \
        + _motion_bytes(t.motion)


def _collision_bytes(table):
    return struct.pack("<i", len(table)) + b"".join(struct.pack("<IdB", c.id, c.touched_time, c.ethereal) for c in table)


def _tick_with_others_bytes(t):
    """Facade.WriteTick's bytes in a scene with other movers: the mover's state and CollisionTable, then per other
    mover its id, state and CollisionTable."""
    return (b"\0" + _state_bytes(t) + b"\1" + _collision_bytes(t.collisions) + struct.pack("<i", len(t.others))
            + b"".join(struct.pack("<I", o.id) + _state_bytes(o) + _collision_bytes(o.collisions) for o in t.others))


def _commands(c):
    return struct.pack("<IIfIfIf", *((0, 0, 0.0, 0, 0.0, 0, 0.0) if c is None else (
        c.current_style, c.forward_command, c.forward_speed, c.side_step_command, c.side_step_speed, c.turn_command,
        c.turn_speed)))


def _motion_bytes(m):
    """Facade.WriteMotion's bytes: 0 (no motion table), or 1 and the motion layer, zeros where a part is absent."""
    if m is None:
        return b"\0"
    return (b"\1" + struct.pack("<B", m.interpreted is not None) + _commands(m.interpreted) + _commands(m.raw)
            + struct.pack("<BIf3f3fBBB", m.animation is not None, m.animation or 0, m.frame_number, *m.sequence_velocity,
                          *m.sequence_omega, m.movement_type is not None, m.movement_type or 0, m.is_moving_to))


def test_unpacking_a_tick_scene_reads_every_tick_state_and_the_error_that_ended_it():
    from acconform.outcome import PlaneState, TickState

    ticks = (TickState(True, 1000.1, 0xA9B40001, 0xA9B40001, (12.0, 12.5, 20.0), (1.0, 0.0, 0.0, 0.0), (0.0, 2.0, -1.0),
                       (0.0, 0.0, -9.75), (0.0, 0.0, 0.5), (0.0, 2.0, 0.0), 0x400, 0x83, 0xA9B40001,
                       PlaneState((0.0, 0.0, 1.0), -20.0), (-0.0, 0.0, 0.0), True, (0xA9B40001, 0xA9B40009)),
             TickState(error="NullReferenceException: no cell"))
    data = (struct.pack("<Bd", 3, 0.0) + struct.pack("<diidd", 9.0, 1, 0, 5.0, 2.5) + _cells(()) + _placement(PLACED)
            + struct.pack("<i", 2) + b"".join(_tick_bytes(t) for t in ticks))
    o, fvp, case, counts = unpack_outcome(data)
    assert o == Outcome(static_cells=(), placement=PLACED, ticks=ticks)
    assert math.copysign(1.0, o.ticks[0].sliding_normal[0]) == -1.0
    assert (fvp, case, counts) == (0.0, 9.0, (1, 0, 5.0, 2.5))
    # a transition scene's outcome ends with -1: no ticks
    assert unpack_outcome(_packed() + struct.pack("<i", -1))[0].ticks is None


def test_unpacking_a_tick_with_other_movers_reads_each_ones_id_state_and_collision_table_keeping_negative_zero():
    from dataclasses import replace

    from acconform.outcome import CollisionState, PlaneState, TickState

    base = TickState(True, 1000.1, 0xA9B40001, 0xA9B40001, (12.0, 12.5, 20.0), (1.0, 0.0, 0.0, 0.0), (0.0, 2.0, 0.0),
                     (0.0, 0.0, 0.0), (0.0, 0.0, 0.0), (0.0, 2.0, 0.0), 0x400, 0x83, 0xA9B40001,
                     PlaneState((0.0, 0.0, 1.0), -20.0), (0.0, 0.0, 0.0), False, (0xA9B40001,))
    # vectors equal but for the sign of a zero: shared between ticks by their bits, so each keeps its own
    other = replace(base, origin=(14.0, 12.5, 20.0), velocity=(-0.0, 2.0, 0.0), sliding_normal=(-0.0, 0.0, 0.0),
                    shadow_cells=(0xA9B40001, 0xA9B40009), collisions=(CollisionState(0x50000001, 1000.1, False),),
                    id=0x80000001)
    quiet = replace(base, contact_plane=PlaneState((0.0, 0.0, 1.0), -0.0), collisions=(), id=0x80000002)
    mover = replace(base, collisions=(CollisionState(0x80000001, 1000.1, True),), others=(other, quiet))
    ticks = (mover, replace(mover, origin=(12.0, 12.625, 20.0), collisions=(), others=(quiet, other)))
    data = (struct.pack("<Bd", 3, 0.0) + struct.pack("<diidd", 9.0, 1, 0, 5.0, 2.5) + _cells(()) + _placement(None)
            + struct.pack("<i", 2) + b"".join(_tick_with_others_bytes(t) for t in ticks))
    o = unpack_outcome(data)[0]
    assert o.ticks == ticks
    signs = [(math.copysign(1.0, t.velocity[0]), math.copysign(1.0, t.sliding_normal[0]),
              math.copysign(1.0, t.contact_plane.d)) for t in o.ticks[1].others]
    assert signs == [(1.0, 1.0, -1.0), (-1.0, -1.0, -1.0)] and o.ticks[0].others[1].contact_plane.d == 0.0
    assert math.copysign(1.0, o.ticks[0].others[1].contact_plane.d) == -1.0


def test_unpacking_a_motion_scenes_ticks_reads_each_ticks_motion_layer_and_the_parts_it_lacks():
    from dataclasses import replace

    from acconform.outcome import CommandState, MotionTickState, PlaneState, TickState

    base = TickState(True, 1000.1, 0xA9B40001, 0xA9B40001, (12.0, 12.5, 20.0), (1.0, 0.0, 0.0, 0.0), (0.0, 2.0, 0.0),
                     (0.0, 0.0, 0.0), (0.0, 0.0, 0.0), (0.0, 2.0, 0.0), 0x400, 0x83, 0xA9B40001,
                     PlaneState((0.0, 0.0, 1.0), -20.0), (0.0, 0.0, 0.0), False, (0xA9B40001,))
    walk = CommandState(0x8000003D, 0x45000005, 1.0, 0x6500000F, 0.5, 0x6500000D, -1.0)
    stand = CommandState(0x8000003D, 0x41000003, 1.0, 0, 1.0, 0, 1.0)
    ticks = (replace(base, motion=MotionTickState(walk, stand, 0x03000004, 2.75, (0.0, 3.0, 0.0),
                                                  (0.0, 0.0, -1.5), 7, True)),
             replace(base, motion=MotionTickState(None, None, None, -0.0, (0.0, 0.0, 0.0), (0.0, 0.0, 0.0), None, False)))
    data = (struct.pack("<Bd", 3, 0.0) + struct.pack("<diidd", 9.0, 1, 0, 5.0, 2.5) + _cells(()) + _placement(None)
            + struct.pack("<i", 2) + b"".join(_tick_bytes(t) for t in ticks))
    o = unpack_outcome(data)[0]
    assert o.ticks == ticks
    assert math.copysign(1.0, o.ticks[1].motion.frame_number) == -1.0


def test_a_packed_motion_scene_carries_its_table_and_animations_with_the_movers_records_and_each_motion_input():
    import dataclasses

    from acconform.motion_scene import ANIMATION_BASE, MOTION_TABLE_ID

    from .motion_scenes import scenes

    scene = scenes()["player_walks_turns_and_stops"]
    data = pack_scene(scene)
    step = scene.ticks.steps[0].motion
    want = struct.pack("<dI", scene.ticks.times()[0], 512) + struct.pack(
        "<IIIIfIIfIIf", step.hold_key, step.style, step.forward, step.forward_hold_key, step.forward_speed, step.sidestep,
        step.sidestep_hold_key, step.sidestep_speed, step.turn, step.turn_hold_key, step.turn_speed)
    assert data[5 + 14:5 + 14 + len(want)] == want
    # the table, then the Player's status (NPK), its skills, no other movers
    assert data[-36:-28] == struct.pack("<II", MOTION_TABLE_ID, 2)
    pk = pack_scene(scene.replace(mover=dataclasses.replace(scene.mover, player_killer_status=4)))
    assert pk[:-32] == data[:-32] and pk[-32:-28] == struct.pack("<I", 4) and pk[-28:] == data[-28:]  # PK
    for kind, ident in ((5, MOTION_TABLE_ID), (6, ANIMATION_BASE), (6, ANIMATION_BASE + 4)):
        assert struct.pack("<BI", kind, ident) in data
