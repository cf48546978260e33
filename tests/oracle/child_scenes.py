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


NAMED = (player_walks_carrying_a_child, player_turns_carrying_a_child, player_carries_a_child_across_a_cell_border,
         monster_walks_carrying_a_child, player_walks_with_a_child_held_by_a_part,
         player_carrying_a_child_walks_into_a_wall, player_carrying_a_child_bumps_a_moving_object,
         child_at_a_location_its_parent_lacks)


def scenes() -> dict:
    return {f.__name__: f() for f in NAMED}


if __name__ == "__main__" and "--record" in sys.argv:
    from oracle.live_answers import record_outcomes

    record_outcomes(scenes(), DATA, "child scene")
