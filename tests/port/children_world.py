"""A parent with holding locations and a child, as DAT records (acconform/dat.py) the port and ACE both read.

The parent's Setup has two parts with a default placement, a sphere (so a tick moves it), (so PartArray.UpdateParts places each
part) and three holding locations: RIGHT_HAND on part 1, SHIELD at part 7 (past its two parts: the
parent's Position) and BAD_PART on part -1 (a List index ACE's UpdateChild throws on). The child's
Setup has one part, no placement, and a sorting sphere of radius 1 (its cells when parented). test_children.py runs them through the port, test_children_live.py
through ACE's own PhysicsObj too.
"""

from __future__ import annotations

from acconform import dat
from acconform.scene import Frame

PARENT_SETUP = 0x02000100
PARENT_PARTS = (0x01000100, 0x01000101)
CHILD_SETUP = 0x02000200
CHILD_PART = 0x01000200
PARENT_ID = 0x80000010  # not a player's id (0x50000001..0x5FFFFFFF)
CHILD_ID = 0x80000020
OTHER_ID = 0x80000030

RIGHT_HAND = 1  # ACE.Entity.Enum.ParentLocation.RightHand
SHIELD = 3  # ParentLocation.Shield
BAD_PART = 9
MISSING = 2  # ParentLocation.LeftHand: no holding location there

CHILD_SORTING_SPHERE = ((0.0, 0.0, 0.5), 1.0)  # reaches the next cell from within 1 m of an edge
PART_FRAMES = (Frame((0.0, 0.0, 1.0)), Frame((0.5, 0.0, 1.5)))
HOLDING = ((RIGHT_HAND, 1, Frame((0.25, 0.0, 0.0))),
           (SHIELD, 7, Frame((0.0, 0.5, 0.0), (0.0, 0.0, 0.0, 1.0))),
           (BAD_PART, -1, Frame((0.0, 0.0, 0.0))))


def records() -> dict[int, bytes]:
    """id -> the record's bytes: the parent's two parts and Setup, the child's part and Setup."""
    out = {g: dat.gfx_obj_mesh(g, []) for g in PARENT_PARTS}
    out[PARENT_SETUP] = dat.setup(PARENT_SETUP, list(PARENT_PARTS), placement=list(PART_FRAMES),
                                  holding_locations=HOLDING, spheres=[((0.0, 0.0, 0.5), 0.5)])
    out[CHILD_PART] = dat.gfx_obj_mesh(CHILD_PART, [])
    out[CHILD_SETUP] = dat.setup(CHILD_SETUP, [CHILD_PART], spheres=[((0.0, 0.0, 0.25), 0.25)],
                                 sorting_sphere=CHILD_SORTING_SPHERE)
    return out


# the parent's moves: (origin, orientation as w, x, y, z); exact rotations (half and quarter turns
# about z with float32-exact components) and one that is not (an arbitrary unit quaternion)
MOVES = (((10.0, 20.0, 30.0), (1.0, 0.0, 0.0, 0.0)),
         ((10.0, 20.0, 30.0), (0.0, 0.0, 0.0, 1.0)),
         ((12.5, 21.25, 30.0), (0.70710677, 0.0, 0.0, 0.70710677)),
         ((13.0, 22.0, 30.5), (0.9238795, 0.0, 0.0, -0.38268343)),
         ((17.3, 25.1, 31.7), (0.5, 0.5, -0.5, 0.5)))
