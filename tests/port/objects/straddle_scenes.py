"""Static objects straddling cell borders, landblock borders and landblock corners, as data: name -> (scene, behaviour).

ACE places a static with its own code (PhysicsObj.add_obj_to_cell): a BSP object or a sphere
through find_bbox_cell_list (the parts' vertex boxes, only cells of the object's own landblock:
add_cell_block's FIXME), a cylsphere through find_cell_list (its spheres, any landblock). So an
object reaching over a landblock border is not registered on the far side, and a mover coming
from there meets it only once its spheres reach the object's own landblock. Each scene puts one
object across a border and walks a mover into it, from the object's own cell or landblock
("own") and from the other side ("neighbour"): BSP boxes, spheres and cylspheres, small and
large, some turned 45 degrees. The world is four flat landblocks around the corner of 0xA9B4
(x and y east and north of it are 0xAA.. and 0x..B5). Then the shapes ACE's BSP code reads that
the validator used to refuse: a tree whose root is a leaf (ACE makes it a childless node) and
empty leaves whose bounding sphere has radius 0.

ACE's answers (live, ACE 7b47913 on mono) are in data/ace_straddle_outcomes.json; they include
`static_cells`, the cells ACE registered each object in, in order.
"""

from __future__ import annotations

import math

from acconform.scene import (BSPLeaf, BSPNode, BSPShape, ContactPlane, CylSphereShape, Frame, Mover, PlaneRec, Position,
                             Scene, SphereRec, SphereShape, StaticObject)
from object_scenes import BSP_STATE, GROUND, GROUNDED, ONE_SPHERE, STATIC, WALK_STATE, box, f, flat_landblock

HOME = (0xA9, 0xB4)  # the landblock the coordinates below are measured from (its south-west corner is 0, 0)
BLOCKS = tuple(flat_landblock(((HOME[0] + dx) << 24) | ((HOME[1] + dy) << 16)) for dx in (0, 1) for dy in (0, 1))
G = GROUND


def place(gx: float, gy: float) -> tuple[int, float, float]:
    """(cell id, x, y in that cell's landblock) of a point given relative to HOME's corner."""
    bx, by = math.floor(gx / 192), math.floor(gy / 192)
    lx, ly = f(gx - bx * 192), f(gy - by * 192)
    block = ((HOME[0] + bx) << 24) | ((HOME[1] + by) << 16)
    return block | (int(lx // 24) * 8 + int(ly // 24) + 1), lx, ly


def position(gx: float, gy: float, z: float, yaw_deg: float = 0.0) -> Position:
    cell, x, y = place(gx, gy)
    h = math.radians(yaw_deg) / 2
    q = (f(math.cos(h)), 0.0, 0.0, f(math.sin(h))) if yaw_deg else (1.0, 0.0, 0.0, 0.0)
    return Position(cell, Frame((x, y, f(z)), q))


def static(shape, gx: float, gy: float, *, yaw_deg: float = 0.0, state: int = BSP_STATE, scale: float = 1.0,
           z: float = G) -> StaticObject:
    return StaticObject(0x70000000, position(gx, gy, z, yaw_deg), shape, state, f(scale))


def walk_into(name: str, obj: StaticObject, start, end, *, z: float = G, contact: bool = True) -> Scene:
    begin = position(*start, z)
    cp = ContactPlane(begin.cell, PlaneRec((0.0, 0.0, 1.0), f(-z))) if contact else None
    mover = Mover(spheres=ONE_SPHERE, begin=begin, end=position(*end, z), step_up_height=f(0.4),
                  step_down_height=f(0.4), state=WALK_STATE, transient_state=GROUNDED if contact else 0,
                  contact_plane=cp)
    return Scene(BLOCKS, mover, (obj,), name=name)


SHAPES = {
    "bsp-small": (box(1.0, 1.0, 1.0), BSP_STATE),
    "bsp-large": (box(6.0, 6.0, 2.0), BSP_STATE),
    "sphere-small": (SphereShape(SphereRec((0.0, 0.0, 0.5), 0.6)), STATIC),
    "sphere-large": (SphereShape(SphereRec((0.0, 0.0, 0.5), 3.5)), STATIC),
    "cylsphere-small": (CylSphereShape((0.0, 0.0, 0.0), 0.4, 1.5), STATIC),
    "cylsphere-large": (CylSphereShape((0.0, 0.0, 0.0), 3.0, 2.0), STATIC),
}
# where the object stands (owned by the cell or landblock at its origin) and the two walks into it:
# from the origin's own side and from the other side of the border
BORDERS = {
    "cell-border": ((96.4, 60.0), (102.0, 60.0), (90.0, 60.0)),
    "block-border": ((191.4, 100.0), (184.0, 100.0), (199.0, 100.0)),
    "block-corner": ((191.4, 191.4), (185.0, 185.0), (198.0, 198.0)),
}
ROTATED = ("bsp-large", "sphere-large")

SCENES: dict[str, tuple[Scene, str]] = {}


def add(scene: Scene, behaviour: str) -> None:
    SCENES[scene.name] = (scene, behaviour)


for _shape_name, (_shape, _state) in SHAPES.items():
    for _border, (_at, _own, _other) in BORDERS.items():
        for _yaw in (0.0, 45.0) if _shape_name in ROTATED else (0.0,):
            _turn = "-rotated" if _yaw else ""
            _obj = static(_shape, *_at, yaw_deg=_yaw, state=_state)
            for _side, _start in (("own", _own), ("neighbour", _other)):
                _end = (2 * _at[0] - _start[0], 2 * _at[1] - _start[1])  # straight through the object's origin
                add(walk_into(f"{_shape_name}{_turn}-{_border}-from-{_side}", _obj, _start, _end),
                    f"a {_shape_name.replace('-', ' ')} object{' turned 45 degrees' if _yaw else ''} across a "
                    f"{_border.replace('-', ' ')}, walked into from the {_side} side")


def leaf_root_box(sx: float, sy: float, sz: float) -> BSPShape:
    """A box whose physics tree is one solid leaf holding every face (no splitting node)."""
    b = box(sx, sy, sz)
    return BSPShape(b.polygons, BSPLeaf(tuple(range(len(b.polygons))), True, b.sphere), b.sphere)


def zero_radius_empty_leaves(shape: BSPShape) -> BSPShape:
    """The same tree with every empty leaf's bounding sphere shrunk to radius 0 at the origin."""
    def walk(node):
        if isinstance(node, BSPLeaf):
            return BSPLeaf(node.polygons, node.solid, SphereRec((0.0, 0.0, 0.0), 0.0)) if not node.polygons else node
        return BSPNode(node.plane, node.sphere, walk(node.front), walk(node.back))
    return BSPShape(shape.polygons, walk(shape.root), shape.sphere)


add(walk_into("leaf-root-walk-through", static(leaf_root_box(2.0, 2.0, 2.0), 100.0, 100.0), (96.0, 100.0), (104.0, 100.0)),
    "a BSP object whose tree is a single leaf: ACE's root BSPNode has no children, so the mover walks through it")
add(walk_into("leaf-root-step-down", static(leaf_root_box(4.0, 4.0, 1.0), 100.0, 100.0), (99.0, 100.0), (101.0, 100.0),
              z=G + 1.0),
    "standing on a leaf-root box: step-down asks the childless root for a walkable (NullReferenceException in ACE)")
add(walk_into("zero-radius-empty-leaves", static(zero_radius_empty_leaves(box(2.0, 2.0, 2.0)), 100.0, 100.0),
              (96.0, 100.0), (104.0, 100.0)),
    "a box whose empty leaves' bounding spheres have radius 0 still stops the mover")
