"""Two objects with WorldObjects touching (issue 41): PhysicsObj's collision table (a .NET Dictionary),
report_object_collision and its profiles, report_object_collision_end, and WeenieObject's side
(WeenieObject(WorldObject), InqCollisionProfile, DoCollision, DoCollisionEnd) with the port's
WorldObjects (port/world_objects/). tests/port/test_object_collisions_live.py runs the same routines
on ACE's own classes."""

from __future__ import annotations

import math

import pytest

from acconform.flags import PhysicsState, PlayerKillerStatus, TransientState
from acconform.numerics import EXACT
from acconform.port.managers.server_object_manager import ServerObjectManager
from acconform.port.obj_collision_profile import ObjCollisionProfile, ObjCollisionProfileFlags as F
from acconform.port.physics_obj import PhysicsObj
from acconform.port.physics_timer import PhysicsTimer
from acconform.port.transition.cell_array import NetDictionary
from acconform.port.weenie_object import DUMMY_OBJECT, WeenieObject
from acconform.port.world_objects import Creature, GenericObject, Player


class Landblock:
    """A server landblock double: records the guids DoCollisionEnd looks up, and holds `objects`."""

    def __init__(self, objects=()):
        self.asked, self.objects = [], {o.guid: o for o in objects}

    def get_object(self, guid):
        self.asked.append(guid)
        return self.objects.get(guid)


class Recorded:
    """Records a WorldObject's OnCollide* calls (as (what, its guid, the target's guid))."""

    def on_collide_object(self, target):
        CALLS.append(("object", self.guid, target.guid))

    def on_collide_object_end(self, target):
        CALLS.append(("end", self.guid, target.guid))

    def on_collide_environment(self):
        CALLS.append(("environment", self.guid))


CALLS: list = []


class RecordedPlayer(Recorded, Player):
    __slots__ = ()


class RecordedCreature(Recorded, Creature):
    __slots__ = ()


class RecordedObject(Recorded, GenericObject):
    __slots__ = ()


@pytest.fixture(autouse=True)
def _clear_calls():
    CALLS.clear()


def obj(world_object=None, timer=None, server_objects=None, state=None) -> PhysicsObj:
    """A PhysicsObj as `new PhysicsObj()` makes it, filed under its WorldObject's guid (or 0x7000_0000 + n)."""
    o = PhysicsObj.create(EXACT, timer or PhysicsTimer(0.0), server_objects=server_objects)
    o.set_object_guid(world_object.guid if world_object is not None else 0x7000_0000)
    if world_object is not None:
        o.set_weenie_obj(WeenieObject.of(world_object))
    if state is not None:
        o.state = state
    return o


# ---------------------------------------------------------------- the .NET Dictionary the table is


def test_setting_a_present_key_keeps_its_place_and_a_new_key_takes_the_last_freed_slot():
    d = NetDictionary()
    for k in (1, 2, 3, 4):
        d.set(k, str(k))
    d.set(2, "two")
    assert d.items() == [(1, "1"), (2, "two"), (3, "3"), (4, "4")]
    d.remove(1)
    d.remove(3)
    d.set(5, "5")  # slot of 3, freed last
    d.set(6, "6")  # slot of 1
    d.set(7, "7")  # a new entry at the end
    assert d.keys() == [6, 2, 5, 4, 7]


# ---------------------------------------------------------------- the collision table


@pytest.mark.anchor("CPhysicsObj::track_object_collision")
@pytest.mark.anchor("CPhysicsObj::report_collision_end")
def test_the_collision_table_ends_records_in_net_order_after_a_removal():
    """B, C (ethereal), D touched at 100; C ends at 100.25 and E takes its slot; B and D end after a
    second; B touched again takes D's slot (freed last): the forced end then walks E before B."""
    timer, server = PhysicsTimer(100.0), ServerObjectManager()
    lb = Landblock()
    me = obj(Player(guid=0x5000_0001, current_landblock=lb), timer, server)
    b, c, d, e = (obj(Creature(guid=0x8000_0000 + n), timer, server) for n in (2, 3, 4, 5))
    c.state |= PhysicsState.Ethereal
    for o in (b, c, d):
        assert me.track_object_collision(o, False) is True
    timer.set(100.25)
    me.report_collision_end(False)
    assert me.collision_table.keys() == [b.id, d.id] and lb.asked == [c.id]
    me.track_object_collision(e, False)
    assert me.collision_table.keys() == [b.id, e.id, d.id]
    timer.set(101.25)
    me.report_collision_end(False)
    assert me.collision_table.keys() == [e.id]  # E touched 1.0 s ago: not > 1.0f
    me.track_object_collision(b, False)
    assert me.collision_table.keys() == [e.id, b.id]  # D's slot (2), freed after B's (0), is taken first
    lb.asked.clear()
    me.report_collision_end(True)
    assert len(me.collision_table) == 0 and lb.asked == [e.id, b.id]


@pytest.mark.anchor("CPhysicsObj::track_object_collision")
def test_touching_an_object_again_renews_its_record_in_place():
    timer = PhysicsTimer(5.0)
    me, a, b = obj(Player(guid=0x5000_0001), timer), obj(Creature(guid=2), timer), obj(Creature(guid=3), timer)
    me.track_object_collision(a, False)
    me.track_object_collision(b, False)
    timer.set(5.75)
    a.state |= PhysicsState.Ethereal
    me.track_object_collision(a, False)
    assert me.collision_table.keys() == [a.id, b.id]
    assert me.collision_table[a.id].touched_time == 5.75 and me.collision_table[a.id].ethereal


# ---------------------------------------------------------------- report_object_collision


@pytest.mark.anchor("CPhysicsObj::report_object_collision")
def test_report_object_collision_builds_both_profiles_when_both_report_collisions(monkeypatch):
    built = []
    real = PhysicsObj.build_collision_profile

    def recording(self, other, am_i_in_contact, velocity_collide):
        built.append((self.id, other.id, am_i_in_contact, velocity_collide.to_tuple()))
        return real(self, other, am_i_in_contact, velocity_collide)

    monkeypatch.setattr(PhysicsObj, "build_collision_profile", recording)
    me = obj(RecordedPlayer(guid=0x5000_0001))
    other = obj(RecordedCreature(guid=0x8000_0002, is_monster=True))
    me.velocity, other.velocity = EXACT.vec(1.5, 0, 0), EXACT.vec(0, -0.25, 0)
    other.transient_state = TransientState.Contact
    assert me.report_object_collision(other, False) is True
    assert built == [(me.id, other.id, False, (1.5, 0.25, 0.0)), (other.id, me.id, True, (1.5, 0.25, 0.0))]
    # the first tells the Player it touched the monster; the second asks the monster about itself: dropped
    assert CALLS == [("object", 0x5000_0001, 0x8000_0002)]


@pytest.mark.anchor("CPhysicsObj::report_object_collision")
def test_report_object_collision_reports_only_the_sides_that_report_collisions(monkeypatch):
    me = obj(RecordedPlayer(guid=0x5000_0001), state=int(PhysicsState.Gravity))
    other = obj(RecordedCreature(guid=0x8000_0002))
    assert me.report_object_collision(other, False) is True  # the other reports
    assert CALLS == []  # ... about itself only
    other.state &= ~PhysicsState.ReportCollisions
    assert me.report_object_collision(other, False) is False
    me.state |= PhysicsState.ReportCollisions
    other.state |= PhysicsState.IgnoreCollisions
    assert me.report_object_collision(other, False) is False and CALLS == []


@pytest.mark.anchor("CPhysicsObj::report_object_collision")
def test_a_static_without_a_world_object_drops_both_calls_and_the_missile_flags_clear():
    me = obj(RecordedPlayer(guid=0x5000_0001))
    me.state |= PhysicsState.Missile | PhysicsState.AlignPath | PhysicsState.PathClipped
    static = obj(None)
    # a missile builds an AtkCollisionProfile (Position.DetermineQuadrant), whose DoCollision the static's missing
    # WorldObject drops; the missile bits clear all the same
    assert me.report_object_collision(static, False) is True
    assert not me.state & (PhysicsState.Missile | PhysicsState.AlignPath | PhysicsState.PathClipped) and CALLS == []
    me.state |= PhysicsState.AlignPath
    static.state |= PhysicsState.IgnoreCollisions
    assert me.report_object_collision(static, False) is True  # the static reports: collided, its call dropped
    assert me.state & PhysicsState.AlignPath and CALLS == []


@pytest.mark.anchor("CPhysicsObj::build_collision_profile")
def test_a_collision_profile_carries_the_other_id_the_relative_velocity_and_the_world_objects_flags():
    me = obj(Player(guid=0x5000_0001, item_type=0x10))
    other = obj(GenericObject(guid=0x8000_0002, attackable=False))
    other.state |= PhysicsState.Missile
    other.transient_state = TransientState.Contact
    p = me.build_collision_profile(other, True, EXACT.vec(1, 2, 3))
    assert (p.id, p.velocity.to_tuple(), p.item_type) == (other.id, (1.0, 2.0, 3.0), 0x10)
    assert p.flags == F.Missile | F.Contact | F.MyContact | F.Creature | F.Player | F.Attackable
    q = other.build_collision_profile_for(me, EXACT.vec(0, 0, 0), False, False, False)
    assert q.flags == F.Undefined and q.item_type == 0
    r = obj(None).build_collision_profile(me, False, EXACT.vec(0, 0, 0))
    assert r.flags == F.Undefined  # DummyObject: no WorldObject, the profile as made


# ---------------------------------------------------------------- report_object_collision_end


@pytest.mark.anchor("CPhysicsObj::report_object_collision_end")
def test_a_collision_end_asks_both_world_objects_when_both_report_collisions():
    server = ServerObjectManager()
    creature = RecordedCreature(guid=0x8000_0002)
    mine, theirs = Landblock([creature]), Landblock()
    player = RecordedPlayer(guid=0x5000_0001, current_landblock=mine)
    creature.current_landblock = theirs
    me, other = obj(player, server_objects=server), obj(creature, server_objects=server)
    assert me.report_object_collision_end(other.id) is True
    assert mine.asked == [other.id] and theirs.asked == [me.id]
    assert CALLS == [("end", 0x5000_0001, 0x8000_0002)]  # the Player's landblock holds the creature
    other.state |= PhysicsState.ReportCollisionsAsEnvironment
    assert me.report_object_collision_end(other.id) is True and len(mine.asked) == 1
    assert me.report_object_collision_end(0x1234) is True and len(mine.asked) == 1  # no such object


# ---------------------------------------------------------------- WeenieObject


@pytest.mark.anchor("WeenieObject.cs:WeenieObject(WorldObject)")
def test_a_weenie_object_knows_players_monsters_npcs_and_plain_objects_apart():
    p = WeenieObject.of(Player(guid=1, player_killer_status=PlayerKillerStatus.PK))
    assert (p.is_player, p.is_creature, p.is_monster, p.player_killer_status) == (True, True, False, PlayerKillerStatus.PK)
    assert p.is_pk() and not p.is_pk_lite() and not p.is_impenetrable()
    m = WeenieObject.of(Creature(guid=2, is_monster=True, faction1_bits=4, foe_type=31))
    assert (m.is_player, m.is_creature, m.is_monster, m.is_faction_mob, m.foe_type) == (False, True, True, True, 31)
    assert m.player_killer_status == PlayerKillerStatus.NPK and not m.is_pk()  # IsPK asks IsPlayer first
    npc = WeenieObject.of(Creature(guid=3, player_killer_status=PlayerKillerStatus.Free))
    assert (npc.is_creature, npc.is_monster, npc.is_faction_mob) == (True, False, False) and not npc.is_impenetrable()
    thing = WeenieObject.of(GenericObject(guid=4))
    assert not (thing.is_creature or thing.is_player or thing.is_monster)
    assert thing.player_killer_status == PlayerKillerStatus.Undef  # a non-creature's stays default


@pytest.mark.anchor("WeenieObject.cs:InqRunRate")
def test_a_creatures_run_skill_sets_its_run_rate_as_a_players_does():
    import numpy as np

    for wo in (Creature(run_skill=300), Player(run_skill=300)):
        ok, rate = WeenieObject.of(wo).inq_run_rate(np.float32(1.0))
        assert ok and rate > np.float32(1.0)
    assert WeenieObject.of(GenericObject()).inq_run_rate(np.float32(7.0))[1] == np.float32(1.0)


@pytest.mark.anchor("WeenieObject.cs:DoCollision(ObjCollisionProfile, ObjectGuid, PhysicsObj)")
def test_do_collision_with_self_or_without_a_world_object_returns_minus_one():
    prof = ObjCollisionProfile.create(0, EXACT.vec(0, 0, 0), False, False, False)
    me = obj(RecordedPlayer(guid=0x5000_0001))
    other = obj(RecordedObject(guid=0x8000_0002))
    same_guid = obj(RecordedCreature(guid=0x5000_0001))
    assert me.weenie_obj.do_collision_obj(prof, me.id, me) == -1
    assert me.weenie_obj.do_collision_obj(prof, me.id, same_guid) == -1  # Guids equal: "self"
    assert me.weenie_obj.do_collision_obj(prof, me.id, obj(None)) == -1
    assert DUMMY_OBJECT.do_collision_obj(prof, 0, other) == -1
    assert CALLS == []
    assert me.weenie_obj.do_collision_obj(prof, me.id, other) == 0
    assert other.weenie_obj.do_collision_obj(prof, other.id, me) == 0
    assert CALLS == [("object", 0x5000_0001, 0x8000_0002), ("object", 0x8000_0002, 0x5000_0001)]


@pytest.mark.anchor("WeenieObject.cs:DoCollision(EnvCollisionProfile, ObjectGuid, PhysicsObj)")
def test_the_environment_tells_a_creature_or_object_but_a_player_takes_falling_damage():
    for wo, calls in ((RecordedPlayer(guid=1), []), (RecordedCreature(guid=2), [("environment", 2)]),
                      (RecordedObject(guid=3), [("environment", 3)])):
        CALLS.clear()
        o = obj(wo)
        assert o.report_environment_collision(True) is True and CALLS == calls
        assert o.report_environment_collision(True) is False  # CollidingWithEnvironment


@pytest.mark.anchor("WeenieObject.cs:InqCollisionProfile")
def test_the_profile_marks_creatures_players_and_attackable_objects():
    def flags(wo):
        p = ObjCollisionProfile.create(9, EXACT.vec(0, 0, 0), False, False, False)
        WeenieObject.of(wo).inq_collision_profile(p)
        return p.flags, p.item_type

    assert flags(Player(item_type=0x10)) == (F.Creature | F.Player | F.Attackable, 0x10)
    assert flags(Creature(attackable=False)) == (F.Creature, 0)
    assert flags(GenericObject()) == (F.Attackable, 0)  # Attackable: GetProperty(...) ?? true


# ---------------------------------------------------------------- the WorldObjects' own bodies


@pytest.mark.anchor("ACE.Server/WorldObjects/Player.cs:OnCollideObject")
@pytest.mark.anchor("ACE.Server/WorldObjects/Creature.cs:OnCollideObject")
def test_a_target_that_reports_no_collisions_is_left_before_any_thrown_weapon_branch():
    thrown = GenericObject(guid=9, projectile_target=Creature(guid=3))
    thrown.physics_obj = obj(thrown)
    for toucher in (Player(guid=1), Creature(guid=2)):
        thrown.physics_obj.set_active(True)
        thrown.hit_msg = False
        thrown.report_collisions = False
        toucher.on_collide_object(thrown)  # returns at `ReportCollisions == false`
        assert thrown.physics_obj.is_active() and not thrown.hit_msg
        thrown.report_collisions = None  # no property: not false
        toucher.on_collide_object(thrown)
        # a player runs ProjectileCollisionHelper.OnCollideObject(thrown, player): not its target, so the
        # environment's hit (set_active(false), HitMsg); a Creature has no thrown weapon branch
        assert thrown.hit_msg is isinstance(toucher, Player)
        assert thrown.physics_obj.is_active() is not isinstance(toucher, Player)


@pytest.mark.anchor("ACE.Server/WorldObjects/WorldObject.cs:OnCollideObject")
@pytest.mark.anchor("ACE.Server/WorldObjects/WorldObject.cs:OnCollideEnvironment")
def test_a_plain_object_reacts_to_collisions_only_as_a_thrown_weapon():
    GenericObject(guid=1).on_collide_object(Player(guid=2))  # no ProjectileTarget: returns before touching anything
    GenericObject(guid=1).on_collide_environment()
    thrown = GenericObject(guid=1, projectile_target=Player(guid=2))
    thrown.physics_obj = obj(thrown)
    thrown.physics_obj.set_active(True)
    thrown.on_collide_environment()  # ProjectileCollisionHelper.OnCollideEnvironment: on no landblock, set inactive
    assert not thrown.physics_obj.is_active() and thrown.hit_msg


@pytest.mark.anchor("CPhysicsObj::report_collision_end")
def test_the_collision_record_lifetime_is_compared_in_double():
    """``deltaTime > 1.0f``: a double against 1.0f widened, so a hair over one second ends the record."""
    timer = PhysicsTimer(0.0)
    me, a = obj(Player(guid=0x5000_0001), timer), obj(Creature(guid=2), timer)
    me.track_object_collision(a, False)
    timer.set(1.0)
    me.report_collision_end(False)
    assert me.collision_table.keys() == [a.id]
    timer.set(math.nextafter(1.0, 2.0))
    me.report_collision_end(False)
    assert len(me.collision_table) == 0


# ---------------------------------------------------------------- a missile's profile (issue 41)


def _at(o: PhysicsObj, x, y, z, yaw_degrees=0.0, cell=0xA9B40013):
    from acconform.port.frame import AFrame, Position

    half = math.radians(yaw_degrees) / 2
    o.position = Position(cell, AFrame(EXACT.vec(x, y, z), EXACT.quat(0.0, 0.0, math.sin(half), math.cos(half))))
    return o


@pytest.mark.anchor("Position.cs:DetermineQuadrant")
def test_a_quadrant_is_left_or_right_front_or_back_and_a_third_of_the_height():
    from acconform.flags import Quadrant as Q

    target = _at(obj(Creature(guid=2)), 10.0, 10.0, 0.0)
    h = EXACT.scalar(1.8)
    for (x, y, z), want in (((10.5, 10.3, 0.1), Q.Right | Q.Front | Q.Low), ((9.5, 9.7, 1.5), Q.Left | Q.Back | Q.High),
                            ((10.0, 10.0, 0.9), Q.Right | Q.Front | Q.Medium)):  # x = 0 is Right, y = 0 Front
        assert target.position.determine_quadrant(h, _at(obj(), x, y, z).position) == want
    # in the target's own frame (LocalToLocal): turned 90 degrees about z, its front (+y) faces the world's -x, so a
    # point at world offset (0.5, 0.2) is 0.5 behind it and 0.2 to its right
    turned = _at(obj(Creature(guid=3)), 10.0, 10.0, 0.0, yaw_degrees=90.0)
    assert turned.position.determine_quadrant(h, _at(obj(), 10.5, 10.2, 0.1).position) == Q.Right | Q.Back | Q.Low


@pytest.mark.anchor("CPhysicsObj::build_collision_profile")
@pytest.mark.anchor("AtkCollisionProfile.cs:AtkCollisionProfile(uint, int, Quadrant)")
def test_a_missiles_profile_is_an_attack_profile_of_the_struck_objects_id_no_part_and_the_quadrant():
    from acconform.flags import Quadrant as Q
    from acconform.port.atk_collision_profile import AtkCollisionProfile

    arrow = _at(obj(GenericObject(guid=0x8000_0010)), 10.2, 9.5, 1.7)
    arrow.state |= PhysicsState.Missile
    target = _at(obj(Creature(guid=0x8000_0001)), 10.0, 10.0, 0.0)
    p = arrow.build_collision_profile(target, False, EXACT.vec(0, 20, 0))
    assert isinstance(p, AtkCollisionProfile)
    # target's GetHeight is its Setup's (0 here: a PhysicsObj with no part array), so any z >= 0 is High
    assert (p.id, p.part, p.location) == (target.id, -1, Q.Right | Q.Back | Q.High)
    assert p.velocity is None and p.flags == 0  # ACE's constructor sets only ID, Part and Location
