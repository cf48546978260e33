"""Hand-made scenes the oracle tests share: the four probe cases (/work/acebuild/probe_output.txt,
measured with ACE commit 7b47913 on mono 6.8), a BSP wall, obstacles, and an unregistered landblock."""

from acconform.flags import CullMode, PhysicsState
from acconform.scene import (BSPLeaf, BSPNode, BSPShape, ContactPlane, CylSphereShape, Frame, Landblock, Mover,
                             PlaneRec, PolygonRec, Position, Scene, SphereRec, SphereShape, StaticObject,
                             validate_scene)

LB = 0xA9B40000


def cell_at(x, y, lb=LB):
    return lb | (int(x // 24) * 8 + int(y // 24) + 1)


def landblock(height_fn, lb=LB):
    return Landblock(lb | 0xFFFF, tuple(height_fn(i // 9, i % 9) for i in range(81)), (0,) * 81)


def walk(height_fn, start, end, ground_z, mode="server", objects=(), name="", landblocks=None):
    mover = Mover(spheres=(SphereRec((0.0, 0.0, 0.48), 0.48),),
                  begin=Position(cell_at(*start[:2]), Frame(start)), end=Position(cell_at(*end[:2]), Frame(end)),
                  step_up_height=0.4, step_down_height=0.4,
                  contact_plane=ContactPlane(cell_at(*start[:2]), PlaneRec((0.0, 0.0, 1.0), -ground_z)))
    lbs = landblocks if landblocks is not None else (landblock(height_fn),)
    return validate_scene(Scene(lbs, mover, objects, engine_mode=mode, name=name))


def flat(x, y):
    return 10  # z = 20 m


def cliff(x, y):
    return 100 if x <= 3 else 0  # 200 m drop between vertex columns 3 and 4


def ramp(x, y):
    return 10 + x


PROBE = {
    "flat 1-step walk": walk(flat, (12.0, 12.0, 20.0), (12.4, 12.0, 20.0), 20.0),
    "flat ~11-step walk (5 m)": walk(flat, (12.0, 12.0, 20.0), (17.0, 12.0, 20.0), 20.0),
    "cliff edge walk (EdgeSlide)": walk(cliff, (70.0, 12.0, 200.0), (75.0, 12.0, 200.0), 200.0),
    "ramp walk uphill": walk(ramp, (30.0, 12.0, 22.5), (35.0, 12.0, 22.5 + 5 * 2 / 24), 22.5),
}


def wall(x=14.0, cell=LB | 1, ident=0x70000010, facing_mover=True):
    """A 4 m wide, 3 m high wall in the object's local plane x = 0; facing -x (towards a mover coming
    from smaller x) when `facing_mover`. ACE's BSP polygons are one-sided: Polygon.pos_hits_sphere
    ignores a hit when the movement is along the normal."""
    verts = ((0.0, -2.0, 3.0), (0.0, 2.0, 3.0), (0.0, 2.0, 0.0), (0.0, -2.0, 0.0))
    if not facing_mover:
        verts = tuple(reversed(verts))
    poly = PolygonRec(verts, int(CullMode.None_))
    sph = SphereRec((0.0, 0.0, 1.5), 2.6)
    nx = -1.0 if facing_mover else 1.0
    root = BSPNode(PlaneRec((nx, 0.0, 0.0), 0.0), sph, BSPLeaf((0,), False, sph), BSPLeaf((0,), False, sph))
    return StaticObject(ident, Position(cell, Frame((x, 12.0, 20.0))), BSPShape((poly,), root, sph),
                        int(PhysicsState.Static | PhysicsState.HasPhysicsBSP))


def post(x=15.0):
    return StaticObject(0x70000001, Position(cell_at(x, 12.0), Frame((x, 12.0, 20.0))), CylSphereShape((0.0, 0.0, 0.0), 0.5, 2.0))


def boulder(x=15.0):
    return StaticObject(0x70000002, Position(cell_at(x, 12.0), Frame((x, 12.0, 20.0))), SphereShape(SphereRec((0.0, 0.0, 0.5), 1.0)))


def off_the_map():
    """A walk across A9B4's north edge into A9B5, which the scene does not define: ACE tries to load
    A9B5 from the cell DAT and throws (no DATs); the oracle reports that as the outcome."""
    start = (12.0, 190.0, 20.0)
    mover = Mover(spheres=(SphereRec((0.0, 0.0, 0.48), 0.48),),
                  begin=Position(cell_at(12.0, 190.0), Frame(start)),
                  end=Position(0xA9B50001, Frame((12.0, 4.0, 20.0))),
                  step_up_height=0.4, step_down_height=0.4,
                  contact_plane=ContactPlane(cell_at(12.0, 190.0), PlaneRec((0.0, 0.0, 1.0), -20.0)))
    return validate_scene(Scene((landblock(flat),), mover, name="into an unregistered landblock"))


def _turn(deg):
    import math

    import numpy as np

    t = math.radians(deg) / 2
    return (float(np.float32(math.cos(t))), 0.0, 0.0, float(np.float32(math.sin(t))))


def three_part_setup(x=15.0, state=int(PhysicsState.Static | PhysicsState.HasPhysicsBSP), scales=None, spheres=(),
                     cylspheres=(), default_animation=None):
    """A static made from a Setup of three box parts (scene/7): a 1 x 2 x 1.5 m block 1.25 m to the
    right, a 1 x 1 x 0.8 m block turned 30 degrees 1 m to the left, a 0.5 m post turned 45 degrees
    lifted 0.5 m; `scales` the parts' DefaultScale, and the Setup's spheres and cylspheres (and, scene/8, its
    DefaultAnimation's one frame per part)."""
    from acconform.scene import PartRec, SetupRec
    from acconform.strategies.shapes import box

    scales = scales or (None, None, None)
    parts = (PartRec(box(1.0, 2.0, 1.5), Frame((0.0, -1.25, 0.0)), scales[0]),
             PartRec(box(1.0, 1.0, 0.8), Frame((0.5, 1.0, 0.0), _turn(30)), scales[1]),
             PartRec(box(0.5, 0.5, 2.0), Frame((0.0, 0.0, 0.5), _turn(45)), scales[2]))
    return StaticObject(0x70000020, Position(cell_at(x, 12.0), Frame((x, 12.0, 20.0))), None, state, 1.0,
                        SetupRec(parts, spheres, cylspheres, default_animation=default_animation))


# named multi-part scenes (issue 41): the mover walking 5 m along +x into a three-part Setup, at `dy` off its axis
MULTIPART = {
    "multipart: into the turned part's corner": walk(flat, (12.0, 13.0, 20.0), (17.0, 13.0, 20.0), 20.0,
                                                      objects=(three_part_setup(),)),
    "multipart: onto a part scaled 0.5 high": walk(flat, (12.0, 13.0, 20.0), (17.0, 13.0, 20.0), 20.0, objects=(
        three_part_setup(scales=((1.0, 1.0, 1.5), (2.0, 1.0, 0.5), (1.0, 1.0, 1.0))),)),
    "multipart: two spheres, no BSP flag": walk(flat, (12.0, 12.0, 20.0), (17.0, 12.0, 20.0), 20.0, objects=(
        three_part_setup(state=int(PhysicsState.Static), spheres=(SphereRec((0.0, -1.0, 0.5), 0.6),
                                                                  SphereRec((0.0, 1.0, 0.5), 0.4))),)),
    "multipart: cylspheres hide the sphere": walk(flat, (12.0, 12.0, 20.0), (17.0, 12.0, 20.0), 20.0, objects=(
        three_part_setup(state=int(PhysicsState.Static), spheres=(SphereRec((0.0, 0.0, 0.5), 0.6),),
                         cylspheres=(CylSphereShape((0.0, -1.0, 0.0), 0.5, 1.0), CylSphereShape((0.0, 1.0, 0.0), 0.3, 2.0))),)),
    # scene/8: the Setup's DefaultAnimation holds every part 20 m aside, so its frame, not the placement, places them
    "multipart: a DefaultAnimation holds the parts aside": walk(flat, (12.0, 13.0, 20.0), (17.0, 13.0, 20.0), 20.0, objects=(
        three_part_setup(default_animation=(Frame((0.0, -21.25, 0.0)), Frame((0.5, -19.0, 0.0), _turn(30)),
                                            Frame((0.0, -20.0, 0.5), _turn(45)))),)),
}
