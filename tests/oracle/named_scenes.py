"""The named tick scenes (issue 19): dereth's 13 required trace-gate scenarios under dereth's own names
(dereth-network/dereth, core/physics/src/trace.rs, REQUIRED_SCENARIOS, each with the behaviour dereth
says it exercises), the acceptance list's six, and issue 20's two through a house (in at its door,
down its cellar hatch), as scene data.

NAMED is the list (name, behaviour, builder); `python tests/oracle/named_scenes.py --write` writes each
scene to examples/named/<name>.json, where `acconform run examples/named/<name>.json` runs it (on the
port, or --impl). ACE's answers for them, on mono and on .NET 10, are in
tests/oracle/data/ace_named_outcomes.json (tests/oracle/test_named_scenes.py records and checks them).
Every scene is engine mode server, as ACE's server runs (docs/oracle.md, the engine-mode row for tick scenes), the mover the
hand-written scenes' sphere (r 0.48, step heights 0.4) on flat terrain at z = 20 unless said otherwise.

A walk by root motion (the Sequence's velocity) sets TransientState to Contact|OnWalkable|Active before
every tick, as a MovementManager would keep it Active (the mover has none: docs/oracle.md, the managers
row); a push is one `velocity` input (friction then slows it); a fall starts in the air, Active only.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

from acconform.flags import PhysicsState, TransientState
from acconform.scene import (ContactPlane, EnvCell, Frame, Landblock, Mover, PlaneRec, Position, Scene, SphereRec,
                             SphereShape, StaticObject, Ticks, TickStep, validate_scene)
from acconform.strategies.shapes import box, wedge

ROOT = Path(__file__).resolve().parents[2]
HOME = ROOT / "examples" / "named"

A9B4 = 0xA9B40000
GROUND = 20.0
START = 1000.0
WALKING = int(TransientState.Contact | TransientState.OnWalkable | TransientState.Active)
AIRBORNE = int(TransientState.Active)
STATIC_BSP = int(PhysicsState.Static | PhysicsState.HasPhysicsBSP)
GRAVITY = int(PhysicsState.Gravity)
EDGE_SLIDE = int(PhysicsState.Gravity | PhysicsState.EdgeSlide)
DEEP_SEA = 0x14 << 2  # terrain word: TerrainType.WaterDeepSea in bits 2-6


def cell_at(x: float, y: float, lb: int = A9B4) -> int:
    return lb | (int(x // 24) * 8 + int(y // 24) + 1)


def land(lb: int = A9B4, height=lambda x, y: 10, terrain=lambda x, y: 0) -> Landblock:
    return Landblock(lb | 0xFFFF, tuple(height(i // 9, i % 9) for i in range(81)),
                     tuple(terrain(i // 9, i % 9) for i in range(81)))


def mover(origin, lb: int = A9B4, state: int = EDGE_SLIDE, transient: int = WALKING, velocity=(0.0, 0.0, 0.0),
          cell: int | None = None, ground: float | None = GROUND, step_up: float = 0.4) -> Mover:
    cell = cell if cell is not None else cell_at(origin[0], origin[1], lb)
    plane = ContactPlane(cell, PlaneRec((0.0, 0.0, 1.0), -ground)) if ground is not None else None
    return Mover(spheres=(SphereRec((0.0, 0.0, 0.48), 0.48),), begin=Position(cell, Frame(tuple(origin))), end=None,
                 step_up_height=step_up, step_down_height=0.4, state=state, transient_state=transient,
                 velocity=velocity, contact_plane=plane)


def static(ident: int, origin, shape, lb: int = A9B4) -> StaticObject:
    return StaticObject(ident, Position(cell_at(origin[0], origin[1], lb), Frame(tuple(origin))), shape, STATIC_BSP)


def walk(n: int, dt: float, v) -> tuple[TickStep, ...]:
    """n ticks of a root-motion walk at local velocity v, kept on the ground and Active."""
    return (TickStep(dt, transient_state=WALKING, sequence_velocity=tuple(v)),) + \
        tuple(TickStep(dt, transient_state=WALKING) for _ in range(n - 1))


def idle(n: int, dt: float, first: TickStep | None = None) -> tuple[TickStep, ...]:
    return ((first,) if first is not None else ()) + tuple(TickStep(dt) for _ in range(n - (first is not None)))


def scene(name, landblocks, m, steps, objects=(), driver="update_object", **kw) -> Scene:
    return validate_scene(Scene(tuple(landblocks), m, tuple(objects), engine_mode="server", name=name,
                                ticks=Ticks(driver, START, tuple(steps)), **kw))


def slope(degrees: float, length: float, width: float = 6.0):
    return wedge(length, width, length * math.tan(math.radians(degrees)))


# ---------------------------------------------------------------- dereth's 13


def walk_up_48_degree_slope():
    """A 48 degree ramp (normal.z = cos 48 deg, just over FloorZ = cos 48.4 deg: walkable) from x = 13 to 19;
    the mover walks up it by root motion at 3 m/s, 20 fps."""
    ramp = static(0x70000001, (16.0, 12.0, GROUND), slope(48.0, 6.0))
    return scene("walk_up_48_degree_slope", [land()], mover((10.0, 12.0, GROUND)), walk(40, 0.05, (3.0, 0.0, 0.0)),
                 [ramp])


def _sled(name: str, degrees: float):
    """A 16 m sledding ramp of `degrees` (rising +x from x = 12); the mover, Sledding, drops 0.3 m onto it
    at x = 25 moving downhill at 8 m/s and sleds."""
    shape = slope(degrees, 16.0)
    top = 13.0 / 16.0 * 16.0 * math.tan(math.radians(degrees))
    ramp = static(0x70000001, (20.0, 12.0, GROUND), shape)
    m = mover((25.0, 12.0, GROUND + top + 0.3), state=int(PhysicsState.Gravity | PhysicsState.Sledding),
              transient=AIRBORNE, velocity=(-8.0, 0.0, 0.0), ground=None)
    return scene(name, [land()], m, idle(40, 0.05), [ramp])


def sled_9_degree_slope():
    return _sled("sled_9_degree_slope", 9.0)


def sled_11_degree_slope():
    return _sled("sled_11_degree_slope", 11.0)


def _lip(name: str, height: float):
    """A 2 x 4 m slab `height` high from x = 13 to 15; the mover walks over (or into) it at 3 m/s, 20 fps."""
    slab = static(0x70000001, (14.0, 12.0, GROUND), box(2.0, 4.0, height))
    return scene(name, [land()], mover((11.0, 12.0, GROUND)), walk(30, 0.05, (3.0, 0.0, 0.0)), [slab])


def step_onto_4cm_lip():
    return _lip("step_onto_4cm_lip", 0.04)


def step_onto_lip_1mm_over_step_up_height():
    return _lip("step_onto_lip_1mm_over_step_up_height", 0.4 + 0.001)


def walk_off_narrow_ledge():
    """A beam 8 m long, 0.8 m wide, 2 m high; the mover (EdgeSlide) walks along it and drifts toward its
    side, pushed at (1.5, 1.5, 0) m/s every tick, 20 fps."""
    beam = static(0x70000001, (12.0, 12.0, GROUND), box(8.0, 0.8, 2.0))
    m = mover((10.0, 12.0, GROUND + 2.0), ground=GROUND + 2.0)
    return scene("walk_off_narrow_ledge", [land()], m,
                 tuple(TickStep(0.05, velocity=(1.5, 1.5, 0.0)) for _ in range(20)), [beam])


def swim_into_deep_sea():
    """A9B4 is dry land and AAB4 east of it deep sea throughout (every terrain word WaterDeepSea: an
    entirely-water landblock); the mover walks east at 3 m/s from 4 m short of the shore line into it."""
    sea = land(0xAAB40000, terrain=lambda x, y: DEEP_SEA)
    return scene("swim_into_deep_sea", [land(), sea], mover((188.0, 12.0, GROUND)), walk(40, 0.05, (3.0, 0.0, 0.0)))


def cross_landblock_boundary_diagonally():
    """Four landblocks meeting at A9B4's north-east corner; the mover walks at (2, 2, 0) m/s through the
    corner itself, 20 fps."""
    lbs = [land(lb) for lb in (A9B4, 0xAAB40000, 0xA9B50000, 0xAAB50000)]
    return scene("cross_landblock_boundary_diagonally", lbs, mover((189.0, 189.0, GROUND)),
                 walk(40, 0.05, (2.0, 2.0, 0.0)))


DUNGEON = 0x01D90000


def walk_through_portal_into_dungeon():
    """tests/oracle/indoor_scenes.py's two rooms (a dungeon landblock, EnvCells 0x0100 and 0x0101 joined by
    a portal in their shared wall): the mover walks from room A through the portal into room B at 3 m/s."""
    from acconform.scene import CellPortalRec
    from oracle.indoor_scenes import DUNGEON as DUNGEON_LB, ENVIRONMENT, FLOOR_Z, ROOM_A, ROOM_B

    a = EnvCell(DUNGEON | 0x0100, Frame(ROOM_A), ENVIRONMENT.id, 1, (CellPortalRec(0, 0x0101, 0),), (0x0101,))
    b = EnvCell(DUNGEON | 0x0101, Frame(ROOM_B), ENVIRONMENT.id, 2, (CellPortalRec(0, 0x0100, 0),), (0x0100,))
    m = mover((49.0, 48.0, FLOOR_Z), cell=a.id, ground=FLOOR_Z)
    return scene("walk_through_portal_into_dungeon", [DUNGEON_LB], m, walk(40, 0.05, (3.0, 0.0, 0.0)),
                 environments=(ENVIRONMENT,), env_cells=(a, b))


def collide_with_moving_object():
    """ACE moves one object at a time: during the mover's update_object every other object stands where
    its own last update left it. The scene's object is that snapshot: a 1 m sphere at x = 15 the mover,
    pushed at 3 m/s every tick, walks into (docs/oracle.md, the moving-object row)."""
    ball = StaticObject(0x70000002, Position(cell_at(15.0, 12.0), Frame((15.0, 12.0, GROUND))),
                        SphereShape(SphereRec((0.0, 0.0, 0.5), 1.0)))
    return scene("collide_with_moving_object", [land()], mover((12.0, 12.0, GROUND)),
                 tuple(TickStep(0.05, velocity=(3.0, 0.0, 0.0)) for _ in range(20)), [ball])


def _same_walk(name: str, fps: int):
    """Two seconds of the same walk up a gentle ramp (terrain rising 2 m per 24 m along x) at 3 m/s,
    ticked at `fps`: at 250 fps each tick is under TickRate (1/30 s), at 4 fps over MaxQuantum (0.1 s)."""
    ramp = land(height=lambda x, y: 10 + x)
    return scene(name, [ramp], mover((30.0, 12.0, 22.5), ground=22.5), walk(2 * fps, 1.0 / fps, (3.0, 0.0, 0.0)))


def same_walk_at_250fps():
    return _same_walk("same_walk_at_250fps", 250)


def same_walk_at_30fps():
    return _same_walk("same_walk_at_30fps", 30)


def same_walk_at_4fps():
    return _same_walk("same_walk_at_4fps", 4)


# ---------------------------------------------------------------- the acceptance list's six


def fall_landing_on_lower_floor():
    """An upper floor (a slab 3 m high, x 8..16) beside a lower one (1 m high, x 16..24): the mover, pushed
    off the upper floor's edge at 6 m/s (no EdgeSlide), falls 2 m onto the lower floor."""
    upper = static(0x70000001, (12.0, 12.0, GROUND), box(8.0, 6.0, 3.0))
    lower = static(0x70000002, (20.0, 12.0, GROUND), box(8.0, 6.0, 1.0))
    m = mover((15.0, 12.0, GROUND + 3.0), state=GRAVITY, velocity=(6.0, 0.0, 0.0), ground=GROUND + 3.0)
    return scene("fall_landing_on_lower_floor", [land()], m, idle(30, 0.05), [upper, lower])


def _ledge(name: str, state: int):
    """A slab 2 m high (x 8..16); the mover, pushed toward its edge at 6 m/s from x = 15, with or without
    EdgeSlide."""
    slab = static(0x70000001, (12.0, 12.0, GROUND), box(8.0, 6.0, 2.0))
    m = mover((15.0, 12.0, GROUND + 2.0), state=state, velocity=(6.0, 0.0, 0.0), ground=GROUND + 2.0)
    return scene(name, [land()], m, idle(30, 0.05), [slab])


def walk_off_ledge_with_edge_slide():
    return _ledge("walk_off_ledge_with_edge_slide", EDGE_SLIDE)


def walk_off_ledge_without_edge_slide():
    return _ledge("walk_off_ledge_without_edge_slide", GRAVITY)


def bounce_with_elasticity():
    """A throw: the mover leaves the ground at (4, 0, 3) m/s, lands 0.7 s later with the normal part of its
    velocity reflected and scaled by its Setup's elasticity (0.05: handle_all_collisions), and runs on into
    a 60 degree ramp (not walkable, from x = 14) that it slides against without a bounce."""
    ramp = static(0x70000001, (16.0, 12.0, GROUND), slope(60.0, 4.0))
    m = mover((10.0, 12.0, GROUND), state=GRAVITY, transient=AIRBORNE, velocity=(4.0, 0.0, 3.0), ground=None)
    return scene("bounce_with_elasticity", [land()], m, idle(30, 0.05), [ramp])


def remainder_carried_across_ticks():
    """A fall from 3 m while drifting at 1 m/s, ticked every 0.12 s: each tick runs one MaxQuantum (0.1 s)
    and keeps the rest (0.02 s, under MinQuantum) for the next, which then runs a remainder step."""
    m = mover((12.0, 12.0, GROUND + 3.0), state=GRAVITY, transient=AIRBORNE, velocity=(1.0, 0.0, 0.0), ground=None)
    return scene("remainder_carried_across_ticks", [land()], m, idle(12, 0.12))


def huge_quantum_skip():
    """A fall from 30 m (starting at 0.5 m/s down) ticked every 1/16 s (exact in double, so the clock's differences are too), with one
    tick of exactly HugeQuantum (2 s: run, in 20 MaxQuanta) and one of 2.5 s (over it: skipped)."""
    m = mover((12.0, 12.0, GROUND + 30.0), state=GRAVITY, transient=AIRBORNE, velocity=(0.0, 0.0, -0.5),
              ground=None)
    dts = [0.0625] * 3 + [2.0] + [0.0625] * 2 + [2.5] + [0.0625] * 8
    return scene("huge_quantum_skip", [land()], m, [TickStep(dt) for dt in dts])


def block_dist_refusal():
    """The legacy player path (driver request_pos) across three landblocks in a row, A9B4, AAB4 and ACB4
    (ABB4 between the last two is not needed: nothing reaches it): a RequestPos in the same cell, one
    across the border into the next landblock (GetBlockDist 1: run), one two landblocks further (ACB4,
    GetBlockDist 2: refused, nothing moves), one back in AAB4. UpdateObjectInternal's own GetBlockDist
    test cannot refuse (docs/oracle.md, the GetBlockDist row)."""
    lbs = [land(lb) for lb in (A9B4, 0xAAB40000, 0xACB40000)]
    m = mover((188.0, 12.0, GROUND))

    def rp(x, lb):
        return Position(cell_at(x, 12.0, lb), Frame((x, 12.0, GROUND)))

    steps = [TickStep(0.1, request_pos=p) for p in (rp(189.5, A9B4), rp(2.0, 0xAAB40000), rp(2.0, 0xACB40000),
                                                     rp(3.0, 0xAAB40000))]
    return scene("block_dist_refusal", lbs, m, steps, driver="request_pos")


def skid_from_over_max_velocity():
    """The mover starts on the ground at 60 m/s (a scene's start velocity is the field, unclamped):
    UpdatePhysicsInternal clamps it to MaxVelocity (50) and then applies friction, tick after tick."""
    m = mover((12.0, 12.0, GROUND), state=GRAVITY, velocity=(60.0, 0.0, 0.0))
    return scene("skid_from_over_max_velocity", [land(), land(0xAAB40000)], m, idle(10, 0.05))


# ---------------------------------------------------------------- through a house (issue 20's ticks)

HOUSE_ORIGIN = (100.0, 100.0, GROUND)


def _house(room):
    """A house on the flat ground (strategies/buildings.py's, laid out by hand): its door 1.2 m wide and
    2.2 m high in the -x wall at x = 100 (the shell 0.2 m thick outside it), a vestibule 2 m long and
    2 m wide behind it (EnvCell 0x0100), then `room` (0x0101) through a doorway like it. The
    building's one portal leads into the vestibule, PortalSide on. (Building, the EnvCells' Environment
    and EnvCells)."""
    from acconform.flags import CullMode
    from acconform.scene import OUTSIDE_CELL, Building, BuildingPortalRec
    from acconform.strategies import buildings as bl
    from acconform.strategies import dungeon as dg

    door = dg.Door(1.2, 2.2, 0.0, OUTSIDE_CELL)
    inner = dg.Door(1.2, 2.2, 0.0, 1)
    d = dg.lay_out(A9B4 >> 16, [dg.Piece("room", 2.0, 2.0, 2.6), room], [inner], door, (), 0.0, HOUSE_ORIGIN)
    built = dg.build(d)
    entry = next(k for k, (which, _) in enumerate(built.geometry[0].portal_doors) if which == "entry")
    shell = bl.shell(d, built, door, 0.2, 0.2, int(CullMode.Clockwise), -0.5 - room.pit_depth)
    portal = BuildingPortalRec(dg.FIRST_CELL, entry, 0, tuple(c.id & 0xFFFF for c in built.env_cells))
    building = Building(A9B4 | 0xFFFF, Frame(HOUSE_ORIGIN, dg.yaw_quat(0.0)), shell, (portal,))
    return building, built.environment, built.env_cells


def walk_into_house_over_ticks():
    """From the grass 2.5 m before the door, root motion at 3 m/s for 40 ticks of 0.05 s: through the
    door (0.12 m to spare either side of the mover) and the vestibule into the room (x 102..105)."""
    from acconform.strategies.dungeon import Piece

    building, env, cells = _house(Piece("room", 3.0, 2.0, 2.6))
    m = mover((97.5, 100.0, GROUND))
    return scene("walk_into_house_over_ticks", [land()], m, walk(40, 0.05, (3.0, 0.0, 0.0)), buildings=(building,),
                 environments=(env,), env_cells=cells)


def fall_down_cellar_hatch():
    """The room 4 m long (x 102..106) with a hatch in its floor from its middle, 1.5 m long, over a
    cellar 2.5 m deep (a pit in the room's cell); the mover (no EdgeSlide) in the room 0.8 m short of
    the hatch, its velocity set to 2 m/s toward it for 12 ticks of 0.05 s, then left to fall."""
    from acconform.strategies.dungeon import Piece

    room = Piece("pit", 4.0, 2.0, 2.6, "pit", feature_at=0.0, pit_length=1.5, pit_depth=2.5)
    building, env, cells = _house(room)
    m = mover((103.2, 100.0, GROUND), state=GRAVITY, cell=cells[1].id)
    steps = tuple(TickStep(0.05, velocity=(2.0, 0.0, 0.0)) for _ in range(12)) + idle(28, 0.05)
    return scene("fall_down_cellar_hatch", [land()], m, steps, buildings=(building,), environments=(env,),
                 env_cells=cells)


# ---------------------------------------------------------------- the list

NAMED: tuple[tuple[str, str, object], ...] = (
    ("walk_up_48_degree_slope", "the walkable-floor threshold", walk_up_48_degree_slope),
    ("sled_9_degree_slope", "the slope friction branch", sled_9_degree_slope),
    ("sled_11_degree_slope", "the slope friction branch", sled_11_degree_slope),
    ("step_onto_4cm_lip", "step-up onto a low edge", step_onto_4cm_lip),
    ("step_onto_lip_1mm_over_step_up_height", "step-up refused just over the step height",
     step_onto_lip_1mm_over_step_up_height),
    ("walk_off_narrow_ledge", "the edge-slide halving probe", walk_off_narrow_ledge),
    ("swim_into_deep_sea", "deep water collides rather than swims", swim_into_deep_sea),
    ("cross_landblock_boundary_diagonally", "landblock-edge cell continuity", cross_landblock_boundary_diagonally),
    ("walk_through_portal_into_dungeon", "portal cell expansion into a dungeon", walk_through_portal_into_dungeon),
    ("collide_with_moving_object", "cached velocity goes to zero on collision", collide_with_moving_object),
    ("same_walk_at_250fps", "frame-rate quantum clamping", same_walk_at_250fps),
    ("same_walk_at_30fps", "frame-rate quantum clamping", same_walk_at_30fps),
    ("same_walk_at_4fps", "frame-rate quantum clamping", same_walk_at_4fps),
    ("fall_landing_on_lower_floor", "a fall lands on the floor below", fall_landing_on_lower_floor),
    ("walk_off_ledge_with_edge_slide", "EdgeSlide keeps the mover on the ledge", walk_off_ledge_with_edge_slide),
    ("walk_off_ledge_without_edge_slide", "without EdgeSlide the mover falls off", walk_off_ledge_without_edge_slide),
    ("bounce_with_elasticity", "handle_all_collisions' elastic bounce", bounce_with_elasticity),
    ("remainder_carried_across_ticks", "update_object keeps a remainder under MinQuantum", remainder_carried_across_ticks),
    ("huge_quantum_skip", "update_object skips a tick over HugeQuantum", huge_quantum_skip),
    ("block_dist_refusal", "UpdateObjectInternalServer refuses a RequestPos two landblocks away", block_dist_refusal),
    ("skid_from_over_max_velocity", "the velocity clamp comes before friction", skid_from_over_max_velocity),
    ("walk_into_house_over_ticks", "a walk in through a building's door: its portal, its cells", walk_into_house_over_ticks),
    ("fall_down_cellar_hatch", "a fall through a hatch in a house's floor into its cellar", fall_down_cellar_hatch),
)
DERETH = tuple(name for name, _, _ in NAMED[:13])


def build() -> dict[str, Scene]:
    return {name: make() for name, _, make in NAMED}


def load() -> dict[str, Scene]:
    """The scene files as written in examples/named/."""
    from acconform.case import load_document

    return {name: load_document(HOME / f"{name}.json") for name, _, _ in NAMED}


if __name__ == "__main__":
    sys.path.insert(0, str(ROOT / "tests"))
    if sys.argv[1:] != ["--write"]:
        sys.exit(__doc__)
    HOME.mkdir(parents=True, exist_ok=True)
    for name, s in build().items():
        (HOME / f"{name}.json").write_text(s.dumps() + "\n")
    print(f"{len(NAMED)} named scenes -> {HOME}")
