"""Children (issue 41; scene/8 `others[].parent`, feature objects.children): named scenes of a mover carrying a
child, each answered by ACE on both runtimes and kept in tests/oracle/data/ace_child_outcomes.json, recorded by

    ACE_ASSEMBLY=/path/to/ACE.Server.dll python tests/oracle/child_scenes.py --record

once with a mono build and once with a .NET 10 build. The carrier is the hand-written player (sphere r 0.48,
entered into the world by enter_world) or a monster of the same body, on flat land at z = 20, pushed by a velocity
(and turned by an omega) held every tick (30 fps). The child is a GenericObject (weenie object) with a small
sphere and a sorting sphere, held at a holding location of its carrier's Setup: past its one part (the frame is
in the carrier's Position, PhysicsObj.UpdateChild) or by the part itself. It is parented as the client parents a
wielded item (SetPlacementFrame, set_parent) and never stepped: its carrier's UpdateChild moves it.
"""

from __future__ import annotations

import sys
from dataclasses import replace
from pathlib import Path

from acconform.flags import ParentLocation
from acconform.scene import (ChildOf, Frame, HoldingLocation, OtherInputs, OtherMover, Placement, SphereRec,
                             TickStep)
from acconform.staging import MOVER_ID
from acconform.strategies.shapes import box

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from oracle.mover_scenes import BODY, DT, MONSTER, THING, other  # noqa: E402
from oracle.named_scenes import GROUND, WALKING, land, mover, scene, static  # noqa: E402

DATA = Path(__file__).resolve().parent / "data" / "ace_child_outcomes.json"
SWORD = 0x80000010
QUARTER_TURN = (0.70710677, 0.0, 0.0, 0.70710677)  # 90 degrees about z
# a right hand 0.4 m out to the side, 1 m up, turned a quarter; past the Setup's one part (1): in the Position
RIGHT_HAND = HoldingLocation(int(ParentLocation.RightHand), 1, Frame((0.4, 0.1, 1.0), QUARTER_TURN))
# a shield held by the Setup's one part (0). A server never moves the part of an object without a physics BSP
# (set_frame's "custom for server"): its frame stays the Position makeAnimObject gave the part (the origin of the
# carrier's cell), so the holding frame is written in landblock coordinates, beside the carrier's start
SHIELD_BY_PART = HoldingLocation(int(ParentLocation.Shield), 0, Frame((60.3, 60.2, 20.9), QUARTER_TURN))


def child(ident: int = SWORD, parent: int = MOVER_ID, location: int = int(ParentLocation.RightHand),
          placement: int = 0) -> OtherMover:
    """A held object: a GenericObject with a small sphere and a sorting sphere (its cells: calc_cross_cells)."""
    return OtherMover(ident, "object", (SphereRec((0.0, 0.0, 0.1), 0.1),), None, 0.0, 0.0,
                      sorting_sphere=SphereRec((0.0, 0.0, 0.5), 0.6), parent=ChildOf(parent, location, placement))


def _carrier(origin, *holding: HoldingLocation):
    return replace(mover(origin), placement=Placement(via="enter_world"), holding_locations=tuple(holding))


def _steps(n: int, velocity, omega=None, others=()) -> tuple[TickStep, ...]:
    return tuple(TickStep(DT, velocity=velocity, omega=omega, others=others) for _ in range(n))


def player_walks_carrying_a_child():
    """The player walks north carrying a sword in its right hand (held past its parts: in its Position); the sword
    follows it every tick."""
    return scene("player_walks_carrying_a_child", [land()], _carrier((60.0, 60.0, GROUND), RIGHT_HAND),
                 _steps(30, (0.0, 3.0, 0.0)), others=(child(),))


def player_turns_carrying_a_child():
    """The player turns on the spot (omega about z) while walking slowly: the sword swings round it, its frame the
    player's turned frame combined with the hand's."""
    return scene("player_turns_carrying_a_child", [land()], _carrier((60.0, 60.0, GROUND), RIGHT_HAND),
                 _steps(40, (0.0, 0.5, 0.0), (0.0, 0.0, 1.5)), others=(child(),))


def player_carries_a_child_across_a_cell_border():
    """The player walks east over the border of two outdoor cells (x = 72) with the sword held out to its side:
    the child changes cell with its parent (change_cell takes the children along) and its shadows follow its
    sorting sphere."""
    return scene("player_carries_a_child_across_a_cell_border", [land()], _carrier((70.5, 60.0, GROUND), RIGHT_HAND),
                 _steps(30, (3.0, 0.0, 0.0)), others=(child(),))


def monster_walks_carrying_a_child():
    """A monster walks west carrying the sword at its right hand (its own Setup's holding location) past the
    standing player."""
    carrier = replace(other(MONSTER, "monster", (66.0, 62.0, GROUND)), holding_locations=(RIGHT_HAND,))
    return scene("monster_walks_carrying_a_child", [land()], _carrier((60.0, 58.0, GROUND)),
                 _steps(30, (0.0, 0.0, 0.0), others=(OtherInputs(MONSTER, velocity=(-3.0, 0.0, 0.0)),)),
                 others=(carrier, child(parent=MONSTER)))


def player_walks_with_a_child_held_by_a_part():
    """The player holds a shield by its Setup's one part: the shield's frame is the part's frame combined with the
    holding frame, and a server never moves the part of an object without a physics BSP (PhysicsObj.set_frame), so
    the shield stays where it was put while the player walks away."""
    return scene("player_walks_with_a_child_held_by_a_part", [land()], _carrier((60.0, 60.0, GROUND), SHIELD_BY_PART),
                 _steps(30, (0.0, 3.0, 0.0)), others=(child(location=int(ParentLocation.Shield)),))


def player_carrying_a_child_walks_into_a_wall():
    """The player carrying the sword walks into a wall and stops against it (the child is no collider: ObjCell's
    FindObjCollisions passes an object with a Parent); the sword stays in its hand."""
    wall = static(0x70000001, (60.0, 62.0, GROUND), box(8.0, 0.4, 3.0))
    return scene("player_carrying_a_child_walks_into_a_wall", [land()], _carrier((60.0, 60.0, GROUND), RIGHT_HAND),
                 _steps(30, (0.0, 3.0, 0.0)), [wall], others=(child(),))


def player_carrying_a_child_bumps_a_moving_object():
    """The player carrying the sword walks into a GenericObject walking at it; they stop each with the other in its
    CollisionTable, the sword in neither."""
    return scene("player_carrying_a_child_bumps_a_moving_object", [land()], _carrier((60.0, 60.0, GROUND), RIGHT_HAND),
                 _steps(40, (0.0, 3.0, 0.0), others=(OtherInputs(THING, velocity=(0.0, -3.0, 0.0)),)),
                 others=(child(), other(THING, "object", (60.0, 64.0, GROUND))))


def child_at_a_location_its_parent_lacks():
    """The sword is to be held at the left hand, which the player's Setup has no holding location for: set_parent
    refuses it (add_child finds no HoldingLocation) and the sword stays out of the world, where it was made."""
    return scene("child_at_a_location_its_parent_lacks", [land()], _carrier((60.0, 60.0, GROUND), RIGHT_HAND),
                 _steps(5, (0.0, 3.0, 0.0)), others=(child(location=int(ParentLocation.LeftHand)),))


def _handing(at: int, *inputs: OtherInputs, n: int = 30, velocity=(0.0, 2.0, 0.0), theirs=(), stop: bool = False):
    """`n` steps of the carrier walking at `velocity` (standing from step `at` on if `stop`); at step `at` the
    children inputs `inputs` (with `theirs`, the others' inputs every step). ChildList.RemoveChild leaves NumObjects
    one past its lists, so a holder that lost a child throws ArgumentOutOfRangeException at its next move within a
    cell (SetPositionInternal's loop to NumObjects): ACE's answer, that tick's error."""
    return tuple(TickStep(DT, velocity=(0.0, 0.0, 0.0) if stop and k >= at else velocity,
                          others=tuple(theirs) + (inputs if k == at else ())) for k in range(n))


def player_moves_a_child_to_its_other_hand():
    """At tick 10 the server moves the sword from the player's right hand to its shield slot (a ParentEvent: the
    client's SetPlacementFrame and set_parent again): set_parent's unset_parent takes it off the right hand
    (ChildList.RemoveChild, clear_transient_states) before the player walks on holding it by its part."""
    return scene("player_moves_a_child_to_its_other_hand", [land()],
                 _carrier((60.0, 60.0, GROUND), RIGHT_HAND, SHIELD_BY_PART),
                 _handing(10, OtherInputs(SWORD, parent=ChildOf(MOVER_ID, int(ParentLocation.Shield)))),
                 others=(child(),))


def player_hands_a_child_to_a_monster():
    """At tick 8 the sword passes from the walking player's right hand to the right hand of a monster walking beside
    it (set_parent to another holder: the player's ChildList loses it, the monster's gains it)."""
    carrier = replace(other(MONSTER, "monster", (62.0, 60.0, GROUND)), holding_locations=(RIGHT_HAND,))
    return scene("player_hands_a_child_to_a_monster", [land()], _carrier((60.0, 60.0, GROUND), RIGHT_HAND),
                 _handing(8, OtherInputs(SWORD, parent=ChildOf(MONSTER, int(ParentLocation.RightHand))),
                          theirs=(OtherInputs(MONSTER, velocity=(0.0, 2.0, 0.0)),)),
                 others=(carrier, child()))


def player_drops_a_child_and_walks_into_it():
    """At tick 5 the sword leaves the player's hand (a PickupEvent's unset_parent: no parent, its cell kept) 0.4 m to
    its side; the player then walks sideways into it: a child no more, it is a collider (ObjCell's
    FindObjCollisions)."""
    return scene("player_drops_a_child_and_walks_into_it", [land()], _carrier((60.0, 60.0, GROUND), RIGHT_HAND),
                 _handing(5, OtherInputs(SWORD, unparent=True), velocity=(1.5, 0.0, 0.0)), others=(child(),))


def player_drops_a_child_and_picks_it_up_again():
    """Unparented at tick 4 (the player stops: its ChildList's count is one past its list now), held again at tick 12
    (a second set_parent with no parent to leave; FindChildIndex finds it before the stale index)."""
    steps = _handing(4, OtherInputs(SWORD, unparent=True), stop=True)
    steps = steps[:12] + (replace(steps[12], others=(OtherInputs(SWORD, parent=ChildOf(MOVER_ID, int(
        ParentLocation.RightHand))),)),) + steps[13:]
    return scene("player_drops_a_child_and_picks_it_up_again", [land()], _carrier((60.0, 60.0, GROUND), RIGHT_HAND),
                 steps, others=(child(),))


def hidden_monster_takes_a_child():
    """A monster made Hidden (PhysicsState.Hidden set by a tick's state input) takes the sword from the player:
    set_parent to a hidden parent sets the child's NoDraw (PartArray.SetNoDrawInternal); handed back at tick 14,
    unset_parent clears its Hidden. Both stand from the hand-over on (a holder that lost a child throws at its next
    move)."""
    carrier = replace(other(MONSTER, "monster", (62.0, 60.0, GROUND)), holding_locations=(RIGHT_HAND,))
    hidden = int(carrier.state) | 0x00004000
    steps = _handing(6, OtherInputs(SWORD, parent=ChildOf(MONSTER, int(ParentLocation.RightHand))), n=20, stop=True)
    steps = ((replace(steps[0], others=(OtherInputs(MONSTER, state=hidden),)),) + steps[1:14]
             + (replace(steps[14], others=(OtherInputs(SWORD, parent=ChildOf(MOVER_ID, int(ParentLocation.RightHand))),)),)
             + steps[15:])
    return scene("hidden_monster_takes_a_child", [land()], _carrier((60.0, 60.0, GROUND), RIGHT_HAND), steps,
                 others=(carrier, child()))


def arrow_carrying_a_child_is_launched():
    """A child held by an arrow before its launch (set_parent to a holder out of the world: no cell to change to);
    the launch's enter_world runs prepare_to_enter_world over the arrow's children, and the arrow's flight carries
    the child (its holding location past the arrow's one part: in its Position)."""
    from oracle.missile_scenes import ARROW, arrow

    flight = replace(arrow((60.0, 60.0, GROUND), MONSTER), holding_locations=(RIGHT_HAND,))
    target = other(MONSTER, "monster", (60.0, 70.0, GROUND))
    return scene("arrow_carrying_a_child_is_launched", [land()], _carrier((60.0, 60.0, GROUND)),
                 _steps(30, (0.0, 0.0, 0.0)), others=(target, flight, child(0x80000020, parent=ARROW)))


def _by_frame(part: int, frame=Frame((60.3, 60.2, 20.9), QUARTER_TURN), parent: int = MOVER_ID) -> ChildOf:
    return ChildOf(parent, 0, 0, part, frame)


def player_walks_with_a_child_attached_by_its_part_and_a_frame():
    """The sword attached by the frame form, set_parent(player, part 0, frame) (the client's call for an object
    attached to a part: ParticleEmitter.SetParenting): the part's frame combined with the given one, in landblock
    coordinates as SHIELD_BY_PART's (a server never moves the part)."""
    return scene("player_walks_with_a_child_attached_by_its_part_and_a_frame", [land()], _carrier((60.0, 60.0, GROUND)),
                 _steps(10, (0.0, 3.0, 0.0)), others=(replace(child(), parent=_by_frame(0)),))


def child_attached_past_its_parents_parts_by_a_frame():
    """The frame form at part 1, past the player's one part: add_child(obj, partIdx, frame) refuses a part at or past
    NumParts (only -1 means the Position there), so set_parent answers false: GeneralFailure."""
    return scene("child_attached_past_its_parents_parts_by_a_frame", [land()], _carrier((60.0, 60.0, GROUND)),
                 _steps(5, (0.0, 3.0, 0.0)), others=(replace(child(), parent=_by_frame(1)),))


def child_attached_at_part_minus_one_by_a_frame():
    """The frame form at part -1 (add_child's "the Position"): accepted, but UpdateChild, which reads -1 as a part
    index below NumParts, indexes Parts[-1] and throws ArgumentOutOfRangeException: ACE's answer."""
    return scene("child_attached_at_part_minus_one_by_a_frame", [land()], _carrier((60.0, 60.0, GROUND)),
                 _steps(5, (0.0, 3.0, 0.0)), others=(replace(child(), parent=_by_frame(-1, Frame((0.0, 0.4, 1.0)))),))


def player_moves_a_child_from_its_hand_to_its_part_by_a_frame():
    """Held in the right hand, then at tick 6 attached by the frame form to the player's part (set_parent's frame
    form: unset_parent, leave_world, change_cell, UpdateChild); the player stands from then on (it lost a child)."""
    return scene("player_moves_a_child_from_its_hand_to_its_part_by_a_frame", [land()],
                 _carrier((60.0, 60.0, GROUND), RIGHT_HAND),
                 _handing(6, OtherInputs(SWORD, parent=_by_frame(0)), n=15, stop=True), others=(child(),))


NAMED_FRAME = (player_walks_with_a_child_attached_by_its_part_and_a_frame, child_attached_past_its_parents_parts_by_a_frame,
               child_attached_at_part_minus_one_by_a_frame, player_moves_a_child_from_its_hand_to_its_part_by_a_frame)

NAMED_HANDING = (player_moves_a_child_to_its_other_hand, player_hands_a_child_to_a_monster,
                 player_drops_a_child_and_walks_into_it, player_drops_a_child_and_picks_it_up_again,
                 hidden_monster_takes_a_child, arrow_carrying_a_child_is_launched)

NAMED = (player_walks_carrying_a_child, player_turns_carrying_a_child, player_carries_a_child_across_a_cell_border,
         monster_walks_carrying_a_child, player_walks_with_a_child_held_by_a_part,
         player_carrying_a_child_walks_into_a_wall, player_carrying_a_child_bumps_a_moving_object,
         child_at_a_location_its_parent_lacks) + NAMED_HANDING + NAMED_FRAME


def scenes() -> dict:
    return {f.__name__: f() for f in NAMED}


if __name__ == "__main__" and "--record" in sys.argv:
    from oracle.live_answers import record_outcomes

    record_outcomes(scenes(), DATA, "child scene")
