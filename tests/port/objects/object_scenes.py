"""The static-object scenes, as data: name -> (scene, the behaviour it exercises).

Hand-made scenes on flat ground (landblock 0xA9B4, height index 10 -> z = 20 m): BSP walls,
floors, ramps, stairs, ledges, platforms, posts and boxes, sphere and cylsphere obstacles, plus
the sampled scenes in data/sampled_object_scenes.json (drawn by acconform.strategies and kept
because they reach a branch no hand-made scene does). ACE's answers for all of them are in
data/ace_object_outcomes.json (real ACE on mono through the live oracle); test_object_walks.py
checks the port against them bit for bit and that together they reach every branch.

Both sides make a static with ACE's makeObject (which sets HasPhysicsBSP through
CacheHasPhysicsBSP) and then overwrite State with the scene's flags, as WorldObject.InitPhysicsObj
does, so a BSP object collides only with HasPhysicsBSP in its scene state: BSP here is always
`BSP_STATE` except in the scene that pins the pass-through.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np

from acconform.flags import CullMode, PhysicsState, TransientState
from acconform.numerics import to_f32
from acconform.scene import (BSPLeaf, BSPNode, BSPShape, ContactPlane, CylSphereShape, Frame, Landblock, Mover,
                             PlaneRec, PolygonRec, Position, Scene, SphereRec, SphereShape, StaticObject)

LB = 0xA9B40000
GROUND = 20.0  # height index 10 in the default table
ONE_SPHERE = (SphereRec((0.0, 0.0, 0.48), 0.48),)
TWO_SPHERES = (SphereRec((0.0, 0.0, 0.48), 0.48), SphereRec((0.0, 0.0, 1.35), 0.48))
WALK_STATE = int(PhysicsState.EdgeSlide | PhysicsState.Gravity)
NO_EDGE_SLIDE = int(PhysicsState.Gravity)
GROUNDED = int(TransientState.Contact | TransientState.OnWalkable)
BSP_STATE = int(PhysicsState.Static | PhysicsState.HasPhysicsBSP)
STATIC = int(PhysicsState.Static)


def f(x: float) -> float:
    return to_f32(x)


def cell_id(block: int, x: float, y: float) -> int:
    return block | (int(x // 24) * 8 + int(y // 24) + 1)


def flat_landblock(block: int = LB, index: int = 10) -> Landblock:
    return Landblock(block | 0xFFFF, (index,) * 81, (0,) * 81)


# ---------------------------------------------------------------- shapes (frozen here, not drawn)


def _plane(verts) -> PlaneRec:
    a, b, c = (np.array(v, dtype=np.float64) for v in verts[:3])
    n = np.cross(b - a, c - a)
    n = n / np.linalg.norm(n)
    return PlaneRec(tuple(f(x) for x in n), f(-float(np.dot(n, a))))


def _bound(points) -> SphereRec:
    pts = np.array(points, dtype=np.float64)
    c = (pts.min(axis=0) + pts.max(axis=0)) / 2
    r = float(np.sqrt(((pts - c) ** 2).sum(axis=1)).max()) * 1.001 + 0.001
    return SphereRec(tuple(f(x) for x in c), f(r))


def solid(faces) -> BSPShape:
    """A convex solid: faces CCW from outside; a chain of nodes on the face planes, a solid leaf."""
    polys = tuple(PolygonRec(tuple(tuple(f(c) for c in p) for p in face), int(CullMode.Clockwise)) for face in faces)
    sphere = _bound([p for poly in polys for p in poly.vertices])
    node = BSPLeaf(tuple(range(len(polys))), True, sphere)
    for poly in reversed(polys):
        node = BSPNode(_plane(poly.vertices), sphere, BSPLeaf((), False, sphere), node)
    return BSPShape(polys, node, sphere)


def box(sx, sy, sz, z0=0.0) -> BSPShape:
    x0, x1, y0, y1, z1 = -sx / 2, sx / 2, -sy / 2, sy / 2, z0 + sz
    return solid([
        [(x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)],
        [(x0, y0, z0), (x0, y1, z0), (x1, y1, z0), (x1, y0, z0)],
        [(x1, y0, z0), (x1, y1, z0), (x1, y1, z1), (x1, y0, z1)],
        [(x0, y0, z0), (x0, y0, z1), (x0, y1, z1), (x0, y1, z0)],
        [(x0, y1, z0), (x0, y1, z1), (x1, y1, z1), (x1, y1, z0)],
        [(x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1)],
    ])


def wedge(sx, sy, sz) -> BSPShape:
    """A ramp rising along +x from 0 at x = -sx/2 to sz at x = +sx/2."""
    x0, x1, y0, y1 = -sx / 2, sx / 2, -sy / 2, sy / 2
    return solid([
        [(x0, y0, 0.0), (x1, y0, sz), (x1, y1, sz), (x0, y1, 0.0)],
        [(x0, y0, 0.0), (x0, y1, 0.0), (x1, y1, 0.0), (x1, y0, 0.0)],
        [(x1, y0, 0.0), (x1, y1, 0.0), (x1, y1, sz), (x1, y0, sz)],
        [(x0, y1, 0.0), (x1, y1, sz), (x1, y1, 0.0)],
        [(x0, y0, 0.0), (x1, y0, 0.0), (x1, y0, sz)],
    ])


def prism(n, radius, height) -> BSPShape:
    ring = [(f(radius * math.cos(2 * math.pi * k / n)), f(radius * math.sin(2 * math.pi * k / n))) for k in range(n)]
    faces = [[(x, y, height) for x, y in ring], [(x, y, 0.0) for x, y in reversed(ring)]]
    for k in range(n):
        (ax, ay), (bx, by) = ring[k], ring[(k + 1) % n]
        faces.append([(ax, ay, 0.0), (bx, by, 0.0), (bx, by, height), (ax, ay, height)])
    return solid(faces)


# ---------------------------------------------------------------- scenes


def obj(i: int, shape, x: float, y: float, z: float = GROUND, state: int = BSP_STATE, yaw_deg: float = 0.0,
        scale: float = 1.0, block: int = LB) -> StaticObject:
    h = math.radians(yaw_deg) / 2
    q = (f(math.cos(h)), 0.0, 0.0, f(math.sin(h))) if yaw_deg else (1.0, 0.0, 0.0, 0.0)
    return StaticObject(0x70000000 + i, Position(cell_id(block, x, y), Frame((f(x), f(y), f(z)), q)), shape, state,
                        f(scale))


def walk(name, start, end, objects, *, spheres=ONE_SPHERE, state=WALK_STATE, transient=GROUNDED, step_up=0.4,
         step_down=0.4, contact=True, floor_z=None, blocks=None) -> Scene:
    """A mover at `start` (standing on a level plane at its z unless airborne) walking to `end`."""
    start = tuple(f(c) for c in start)
    end = tuple(f(c) for c in end)
    z = f(floor_z) if floor_z is not None else start[2]
    c0 = cell_id(LB, start[0], start[1])
    cp = ContactPlane(c0, PlaneRec((0.0, 0.0, 1.0), f(-z))) if contact else None
    mover = Mover(spheres=spheres, begin=Position(c0, Frame(start)),
                  end=Position(cell_id(LB, min(max(end[0], 0.0), 191.0), min(max(end[1], 0.0), 191.0)), Frame(end)),
                  step_up_height=f(step_up), step_down_height=f(step_down), state=state, transient_state=transient,
                  contact_plane=cp)
    return Scene(blocks or (flat_landblock(),), mover, tuple(objects), name=name)


SCENES: dict[str, tuple[Scene, str]] = {}


def add(scene: Scene, behaviour: str) -> None:
    SCENES[scene.name] = (scene, behaviour)


G = GROUND
WALL = box(0.5, 6.0, 3.0)
add(walk("wall-head-on", (96, 96, G), (102, 96, G), [obj(0, WALL, 100, 96)]),
    "walks into a BSP wall: step-up tried and failed, stops against it")
add(walk("wall-without-bsp-flag", (96, 96, G), (102, 96, G), [obj(0, WALL, 100, 96, state=STATIC)]),
    "a BSP object whose state lacks HasPhysicsBSP is passed through (ACE's sphere path finds no spheres)")
add(walk("wall-slanted", (96, 96, G), (102, 98, G), [obj(0, WALL, 100, 96, yaw_deg=30)]),
    "walks into a wall turned 30 degrees: slides along it")
add(walk("wall-two-spheres", (96, 96, G), (102, 96, G), [obj(0, WALL, 100, 96)], spheres=TWO_SPHERES),
    "a two-sphere mover into a wall")
add(walk("wall-ethereal", (96, 96, G), (102, 96, G), [obj(0, WALL, 100, 96, state=BSP_STATE | int(PhysicsState.Ethereal))]),
    "an ethereal Static wall still blocks: FindObjCollisions_Inner lets only non-static ethereal objects through")
add(walk("wall-scaled", (96, 96, G), (102, 96, G), [obj(0, WALL, 100, 96, scale=1.5)]),
    "a wall at scale 1.5 (GfxObjScale through SetScaleStatic)")
add(walk("wall-airborne", (96, 96, G + 1.0), (102, 96, G + 0.5), [obj(0, WALL, 100, 96)], transient=0, contact=False),
    "airborne into a wall: SetCollide, then the collide path resets the check position")
add(walk("stair-step-up", (96, 96, G), (100, 96, G), [obj(0, box(2.0, 4.0, 0.3), 99, 96)]),
    "walks onto a 0.3 m stair with step-up height 0.4: steps up")
add(walk("lip-1mm-over-step-height", (96, 96, G), (100, 96, G), [obj(0, box(2.0, 4.0, 0.401), 99, 96)]),
    "a lip 1 mm over the step-up height (0.4) is still stepped onto: the sphere's reach adds to it")
add(walk("lip-1mm-over-step-reach", (96, 96, G), (100, 96, G), [obj(0, box(2.0, 4.0, 0.601), 99, 96)]),
    "a lip 1 mm over the height ACE really steps (0.5999996 m here, found by bisection): step-up fails")
add(walk("lip-1mm-under-step-reach", (96, 96, G), (100, 96, G), [obj(0, box(2.0, 4.0, 0.599), 99, 96)]),
    "a lip 1 mm under the height ACE really steps: step-up succeeds")
add(walk("stairs-two-steps", (94, 96, G), (101, 96, G),
         [obj(0, box(2.0, 4.0, 0.25), 97, 96), obj(1, box(2.0, 4.0, 0.5), 99, 96)]),
    "two stairs in a row")
PLATFORM = box(4.0, 4.0, 0.5)
add(walk("platform-edge-precipice-slide", (100.5, 96, G + 0.5), (103, 97, G + 0.5), [obj(0, PLATFORM, 100, 96)]),
    "walks off a platform's edge with EdgeSlide: precipice slide along the crossed edge")
add(walk("platform-edge-head-on", (100.5, 96, G + 0.5), (103, 96, G + 0.5), [obj(0, PLATFORM, 100, 96)]),
    "walks straight off a platform's edge with EdgeSlide")
add(walk("platform-edge-no-edge-slide", (100.5, 96, G + 0.5), (103, 96, G + 0.5), [obj(0, PLATFORM, 100, 96)],
         state=NO_EDGE_SLIDE),
    "walks off a platform without EdgeSlide: steps down to the ground")
add(walk("ledge-high", (100.5, 96, G + 2.0), (103, 97, G + 2.0), [obj(0, box(4.0, 4.0, 2.0), 100, 96)]),
    "walks off a 2 m ledge with EdgeSlide")
add(walk("ledge-rotated", (100.5, 96, G + 2.0), (103, 97.5, G + 2.0), [obj(0, box(4.0, 4.0, 2.0), 100, 96, yaw_deg=45)]),
    "walks off a ledge turned 45 degrees")
add(walk("platform-landing", (97, 96, G + 1.5), (99.5, 96, G + 0.3), [obj(0, PLATFORM, 100, 96)], transient=0,
         contact=False),
    "falls onto a platform: SetCollide, then lands on the walkable top")
add(walk("floor-walk", (97, 96, G), (103, 96, G), [obj(0, box(4.0, 4.0, 0.05), 100, 96)]),
    "walks over a 5 cm floor slab")
add(walk("ramp-up", (95, 96, G), (101, 96, G), [obj(0, wedge(6.0, 3.0, 2.0), 100, 96)]),
    "walks up a BSP ramp")
add(walk("ramp-steep", (95, 96, G), (101, 96, G), [obj(0, wedge(3.0, 3.0, 4.0), 100, 96)]),
    "walks into a ramp too steep to walk")
add(walk("post-glance", (96, 96.1, G), (102, 96.1, G), [obj(0, prism(6, 0.2, 3.0), 100, 96)]),
    "walks into a thin post off-centre")
add(walk("box-corner", (96, 95, G), (102, 98, G), [obj(0, box(2.0, 2.0, 2.0), 100, 97)]),
    "walks diagonally into a box's corner")
add(walk("sphere-obstacle", (96, 96, G), (102, 96, G), [obj(0, SphereShape(SphereRec((0.0, 0.0, 0.5), 1.0)), 100, 96,
                                                             state=STATIC)]),
    "walks into a sphere obstacle")
add(walk("sphere-obstacle-glance", (96, 96.6, G), (102, 96.6, G),
         [obj(0, SphereShape(SphereRec((0.0, 0.0, 0.5), 1.0)), 100, 96, state=STATIC)]),
    "glances off a sphere obstacle")
add(walk("cylsphere-obstacle", (96, 96, G), (102, 96, G),
         [obj(0, CylSphereShape((0.0, 0.0, 0.0), 0.6, 2.0), 100, 96, state=STATIC)]),
    "walks into a cylsphere obstacle")
add(walk("cylsphere-low-step", (96, 96, G), (102, 96, G),
         [obj(0, CylSphereShape((0.0, 0.0, 0.0), 1.0, 0.3), 100, 96, state=STATIC)]),
    "walks onto a low cylsphere")
add(walk("sphere-airborne", (96, 96, G + 2.0), (100, 96, G + 1.0), [obj(0, SphereShape(SphereRec((0.0, 0.0, 0.5), 1.0)),
                                                                        100, 96, state=STATIC)], transient=0,
         contact=False),
    "falls onto a sphere obstacle")
add(walk("objects-in-two-cells", (118, 96, G), (122, 96, G), [obj(0, WALL, 121, 96)]),
    "a wall straddling a cell boundary (shadow objects in both cells)")
add(walk("landblock-missing", (186, 96, G), (194, 96, G), []),
    "walks east into a landblock the scene does not list: NullReferenceException")


# ---------------------------------------------------------------- sampled scenes

SAMPLED_FILE = Path(__file__).parent / "data" / "sampled_object_scenes.json"
if SAMPLED_FILE.exists():
    for _name, _entry in json.loads(SAMPLED_FILE.read_text())["scenes"].items():
        add(Scene.from_json(_entry["scene"]).replace(name=_name), _entry["behaviour"])
