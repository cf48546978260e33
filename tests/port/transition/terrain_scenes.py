"""The terrain scenes issue 5 requires, as data: name -> (scene, the behaviour it exercises).

ACE's answers for them are recorded in data/ace_terrain_outcomes.json (real ACE on mono, read
the way the oracle reads an outcome); test_terrain_walks.py checks the port against them bit
for bit, and test_branches.py checks that together they reach every branch in branches.py.
Landblock 0xA9B4 (plus 0xAAB4 and 0xA9B5 for border walks); default height table 2.0 * i
unless a scene carries its own.
"""

from __future__ import annotations

from acconform.flags import PhysicsState, TransientState
from acconform.numerics import to_f32
from acconform.scene import (DEFAULT_LAND_HEIGHT_TABLE, ContactPlane, Frame, Landblock, Mover, PlaneRec, Position,
                             Scene, SphereRec)

LB = 0xA9B40000
EAST = 0xAAB40000  # x + 1
NORTH = 0xA9B50000  # y + 1
WATER_WORD = 0x10 << 2
ONE_SPHERE = (SphereRec((0.0, 0.0, 0.48), 0.48),)
TWO_SPHERES = (SphereRec((0.0, 0.0, 0.48), 0.48), SphereRec((0.0, 0.0, 1.35), 0.48))
WALK_STATE = int(PhysicsState.EdgeSlide | PhysicsState.Gravity)
NO_EDGE_SLIDE = int(PhysicsState.Gravity)
GROUNDED = int(TransientState.Contact | TransientState.OnWalkable)


def f(x: float) -> float:
    return to_f32(x)


def cell_id(block: int, x: float, y: float) -> int:
    return block | (int(x // 24) * 8 + int(y // 24) + 1)


def landblock(block: int, height=lambda x, y: 10, terrain=lambda x, y: 0) -> Landblock:
    return Landblock(block | 0xFFFF, tuple(height(i // 9, i % 9) for i in range(81)),
                     tuple(terrain(i // 9, i % 9) for i in range(81)))


def walk(name, blocks, start, end, *, normal=(0.0, 0.0, 1.0), spheres=ONE_SPHERE, state=WALK_STATE,
         transient=GROUNDED, step_up=0.4, step_down=0.4, table=DEFAULT_LAND_HEIGHT_TABLE, end_block=None,
         contact=True, velocity=(0.0, 0.0, 0.0), sliding=(-1.0, 0.0, 0.0)) -> Scene:
    """A mover standing at `start` on a plane with `normal` through `start`, walking to `end`."""
    start = tuple(f(c) for c in start)
    end = tuple(f(c) for c in end)
    b0 = blocks[0].id & 0xFFFF0000
    b1 = end_block if end_block is not None else b0
    n = tuple(f(c) for c in normal)
    d = f(-(n[0] * start[0] + n[1] * start[1] + n[2] * (start[2])))
    cp = ContactPlane(cell_id(b0, start[0], start[1]), PlaneRec(n, d)) if contact else None
    mover = Mover(spheres=spheres, begin=Position(cell_id(b0, start[0], start[1]), Frame(start)),
                  end=Position(cell_id(b1, end[0], end[1]), Frame(end)), step_up_height=f(step_up),
                  step_down_height=f(step_down), state=state, transient_state=transient,
                  contact_plane=cp, velocity=velocity,
                  sliding_normal=tuple(f(c) for c in sliding) if transient & TransientState.Sliding else None)
    return Scene(tuple(blocks), mover, land_height_table=tuple(table), name=name)


def _table(values: dict[int, float]) -> tuple[float, ...]:
    t = list(DEFAULT_LAND_HEIGHT_TABLE)
    for i, v in values.items():
        t[i] = f(v)
    return tuple(t)


flat = landblock(LB)
cliff = landblock(LB, lambda x, y: 100 if x <= 3 else 0)
ramp = landblock(LB, lambda x, y: 10 + x)
hills = landblock(LB, lambda x, y: 10 + (3 * x * x + 5 * y + x * y) % 9)
# index 1 is the high side; the slope runs along x: vertex x <= 3 at index 1, beyond at 0 (+ table)
def slope_table(rise: float):
    return _table({0: 100.0, 1: 100.0 + rise})


# the steep slope's terrain plane normal as the port's LandblockStruct computes it (float32)
STEEP_TERRAIN_NORMAL = (0.7486273050308228, 0.0, 0.6629910469055176)


step_block = landblock(LB, lambda x, y: 1 if x <= 3 else 0)
water = landblock(LB, terrain=lambda x, y: WATER_WORD)
shore = landblock(LB, terrain=lambda x, y: WATER_WORD if x >= 4 else 0)
# a narrow ledge: a ridge one vertex wide (x == 4) falling away on both sides
ledge = landblock(LB, lambda x, y: 100 if x == 4 else 0)

RISE_WALKABLE = 26.9  # over 24 m: normal z 0.6658 > FloorZ
RISE_STEEP = 27.1  # normal z 0.6620 < FloorZ


def _slope_normal(rise: float):
    import math

    length = math.sqrt(rise * rise + 24.0 * 24.0)
    return (rise / length, 0.0, 24.0 / length)


SCENES: dict[str, tuple[Scene, str]] = {}


def add(scene: Scene, behaviour: str) -> None:
    SCENES[scene.name] = (scene, behaviour)


add(walk("flat-short", [flat], (12, 12, 20), (12.4, 12, 20)), "one step on flat ground (ACE fact)")
add(walk("flat-11-steps", [flat], (12, 12, 20), (17, 12, 20)), "float32 accumulation over 11 steps (ACE fact)")
add(walk("cliff-edge-slide", [cliff], (70, 12, 200), (75, 12, 200)), "stops at a cliff edge via the back-probe (ACE fact)")
add(walk("ramp-uphill", [ramp], (30, 12, 22.5), (35, 12, 22.5 + 5 * 2 / 24), normal=(-0.08304548, 0.0, 0.99654579)),
    "walks up a ramp, lifted onto it each step (ACE fact)")
add(walk("ramp-downhill", [ramp], (35, 12, 22.5 + 11 * 2 / 24), (30, 12, 22.5 + 6 * 2 / 24),
         normal=(-0.08304548, 0.0, 0.99654579)), "walks down a ramp, stepping down each step")
add(walk("hills-diagonal", [hills], (50, 50, 40), (56, 57, 40)), "walks over irregular hills (contact plane from a wrong start)")
add(walk("cliff-no-edge-slide", [cliff], (70, 12, 200), (75, 12, 200), state=NO_EDGE_SLIDE),
    "walks off a cliff without EdgeSlide: no slide, leaves the ground")
add(walk("cliff-diagonal", [cliff], (70, 12, 200), (74, 15, 200)), "stops at a cliff edge walking at an angle")
add(walk("cliff-airborne", [cliff], (70, 12, 200), (75, 12, 200), transient=0, contact=False),
    "an airborne mover crosses the cliff edge freely")
def slope_z(rise: float, x: float) -> float:
    """Height on the x-slope between vertex x=3 (72 m, 100 + rise) and x=4 (96 m, 100)."""
    return 100.0 + rise * (96.0 - x) / 24.0


add(walk("slope-walkable-up", [step_block], (80, 12, slope_z(RISE_WALKABLE, 80)), (76, 12, slope_z(RISE_WALKABLE, 76)),
         normal=_slope_normal(RISE_WALKABLE), table=slope_table(RISE_WALKABLE)),
    "walks up a slope just walkable (normal z just above FloorZ)")
add(walk("slope-walkable-down", [step_block], (76, 12, slope_z(RISE_WALKABLE, 76)), (80, 12, slope_z(RISE_WALKABLE, 80)),
         normal=_slope_normal(RISE_WALKABLE), table=slope_table(RISE_WALKABLE)),
    "walks down a slope just walkable, stepping down")
add(walk("slope-steep-down", [step_block], (76, 12, slope_z(RISE_STEEP, 76)), (80, 12, slope_z(RISE_STEEP, 80)),
         normal=_slope_normal(RISE_STEEP), table=slope_table(RISE_STEEP)),
    "walks down a slope just steeper than FloorZ: cliff slide")
add(walk("slope-steep-up", [step_block], (80, 12, slope_z(RISE_STEEP, 80)), (76, 12, slope_z(RISE_STEEP, 76)),
         normal=_slope_normal(RISE_STEEP), table=slope_table(RISE_STEEP)),
    "tries to walk up a slope just steeper than FloorZ")
add(walk("slope-steep-exact-plane", [step_block], (76, 12, slope_z(RISE_STEEP, 76)), (80, 12, slope_z(RISE_STEEP, 80)),
         normal=STEEP_TERRAIN_NORMAL, table=slope_table(RISE_STEEP)),
    "on a steep slope whose contact plane is the terrain's own: cliff slide between parallel planes")
add(walk("slope-steep-onto", [step_block], (100, 12, 100), (94, 12, 100), table=slope_table(RISE_STEEP)),
    "walks from flat ground into a slope steeper than FloorZ")
add(walk("slope-walkable-onto", [step_block], (100, 12, 100), (94, 12, 100), table=slope_table(RISE_WALKABLE)),
    "walks from flat ground up a slope just walkable")
add(walk("gentle-descent-step-down", [step_block], (90, 12, slope_z(0.3, 90)), (97, 12, 100),
         table=slope_table(0.3), normal=_slope_normal(0.3)), "steps down off a gentle slope onto flat ground")
add(walk("rise-1mm-over-step-up", [step_block], (100, 12, 100), (94, 12, 100), table=slope_table(0.401)),
    "terrain rising 1 mm more than the step-up height over one cell (terrain lifts the mover anyway)")
add(walk("drop-1mm-over-step-down", [step_block], (95.9, 12, slope_z(0.401, 95.9)), (97.5, 12, 100),
         table=slope_table(0.401), normal=_slope_normal(0.401)),
    "terrain falling 1 mm more than the step-down height over one cell")
add(walk("narrow-ledge", [ledge], (96, 12, 200), (96, 16, 200)), "walks along a one-vertex ridge")
add(walk("narrow-ledge-off", [ledge], (96, 12, 200), (99, 12, 200)), "walks off a one-vertex ridge")
add(walk("water-entirely", [water], (12, 12, 20), (14, 12, 20)), "an entirely-water landblock blocks walking")
add(walk("water-shore", [shore], (90, 12, 20), (100, 12, 20)), "walks from land into partial water")
add(walk("cell-border-x", [flat], (23, 12, 20), (25, 12, 20)), "crosses a cell border in x")
add(walk("cell-corner", [flat], (23, 23, 20), (25, 25, 20)), "crosses a cell corner")
add(walk("landblock-border-east", [flat, landblock(EAST)], (191, 12, 20), (1, 12, 20), end_block=EAST),
    "crosses a landblock border eastwards (end given in the next block's frame)")
add(walk("landblock-corner", [flat, landblock(EAST), landblock(NORTH), landblock(0xAAB50000)],
         (191, 191, 20), (1, 1, 20), end_block=0xAAB50000), "crosses a landblock corner")
add(walk("two-spheres-flat", [flat], (12, 12, 20), (17, 12, 20), spheres=TWO_SPHERES), "a two-sphere mover walks")
add(walk("two-spheres-cliff", [cliff], (70, 12, 200), (75, 12, 200), spheres=TWO_SPHERES, step_down=1.2),
    "a two-sphere mover at a cliff edge, step-down above 2r halves")
add(walk("big-step-down-halves", [cliff], (70, 12, 200), (75, 12, 200), step_down=1.2),
    "one sphere, step-down above 2r: reduced to r/2")
for dt, tag in ((1 / 250, "250"), (1 / 30, "30"), (1 / 4, "4")):
    add(walk(f"ramp-frame-1-{tag}", [ramp], (30, 12, 22.5), (30 + 4 * dt, 12, 22.5),
             normal=(-0.08304548, 0.0, 0.99654579)), f"a 4 m/s walk up a ramp for 1/{tag} s")
add(walk("no-move", [flat], (12, 12, 20), (12, 12, 20)), "begin == end: no steps")
add(walk("stationary-fall", [flat], (12, 12, 25), (12, 12, 25), transient=0, contact=False),
    "standing in the air: FramesStationaryFall counts")
add(walk("leaving-contact", [flat], (12, 12, 20), (12.4, 12, 20.5), velocity=(0.0, 0.0, 3.0)),
    "velocity away from the contact plane: only a last-known contact plane")
add(walk("sliding-into-wall", [flat], (12, 12, 20), (12.4, 12.4, 20), transient=int(GROUNDED | TransientState.Sliding)),
    "a sliding normal from the last frame turns the offset")
for flags, tag in ((0, "0"), (int(TransientState.StationaryFall), "1"), (int(TransientState.StationaryStop), "2"),
                   (int(TransientState.StationaryStuck), "3")):
    add(walk(f"stationary-fall-seed-{tag}", [water], (12, 12, 25), (12.3, 12, 25), transient=flags, contact=False),
        f"airborne into an entirely-water block, FramesStationaryFall seeded {tag}: counts up, stops the walk")
add(walk("airborne-sliding-normal", [flat], (12, 12, 25), (12.4, 12, 25), transient=int(TransientState.Sliding),
         contact=False), "airborne with a sliding normal: the offset loses its component into it")
add(walk("sliding-normal-against-contact", [flat], (12, 12, 20), (12.4, 12, 20.3),
         transient=int(GROUNDED | TransientState.Sliding), sliding=(0.0, 0.0, -1.0)),
    "a sliding normal opposite the contact normal: no slide direction, the offset vanishes")
add(walk("too-far", [flat], (12, 12, 20), (12, 12, 20), end_block=0xACB40000),
    "a walk longer than 1000 sphere radii is refused")
add(walk("steep-contact-plane-over-plateau", [step_block], (70, 12, slope_z(RISE_STEEP, 70) + 0.01), (74, 12, 100),
         normal=_slope_normal(RISE_STEEP), table=slope_table(RISE_STEEP)),
    "a mover above a plateau holding a steep contact plane: cliff slide with the normal flipped")
