"""Staging: how a scene becomes engine objects, the conventions the oracle and the port share.

A scene does not carry everything ACE would read from its DAT files, so both sides apply the same
rules (documented in docs/oracle.md): the mover's id, its Setup's Height and Radius, and the cells a
static object is registered in as a shadow object. They live here, once, so they cannot drift.
"""

from __future__ import annotations

import math

from .scene import CylSphereShape, Scene, SphereShape, StaticObject

MOVER_ID = 0x50000001  # the mover is a player-range PhysicsObj (PhysicsObj.IsPlayer), as ACE's players are
CELL_SIZE = 24.0
BLOCK_SIZE = 192.0


def _rotate(q, v):
    w, x, y, z = q
    n = math.sqrt(w * w + x * x + y * y + z * z) or 1.0
    w, x, y, z = w / n, x / n, y / n, z / n
    vx, vy, vz = v
    # v + 2w(q x v) + 2 q x (q x v)
    cx, cy, cz = y * vz - z * vy, z * vx - x * vz, x * vy - y * vx
    cx2, cy2, cz2 = y * cz - z * cy, z * cx - x * cz, x * cy - y * cx
    return (vx + 2 * (w * cx + cx2), vy + 2 * (w * cy + cy2), vz + 2 * (w * cz + cz2))


def bounding_sphere(obj: StaticObject) -> tuple[tuple[float, float, float], float]:
    """The object's bounding sphere in its cell's landblock coordinates (centre, radius)."""
    shape = obj.shape
    if isinstance(shape, SphereShape):
        c, r = shape.sphere.center, shape.sphere.radius
    elif isinstance(shape, CylSphereShape):
        lx, ly, lz = shape.low_point
        c, r = (lx, ly, lz + shape.height / 2), shape.radius + shape.height / 2
    else:
        c, r = shape.sphere.center, shape.sphere.radius
    s = obj.scale
    rc = _rotate(obj.position.frame.orientation, (c[0] * s, c[1] * s, c[2] * s))
    o = obj.position.frame.origin
    return (o[0] + rc[0], o[1] + rc[1], o[2] + rc[2]), r * s


def shadow_cells(obj: StaticObject, landblock_ids) -> list[int]:
    """The outdoor cells a static object is registered in (as a shadow object), in order.

    Convention (the oracle's and the port's): the object's own cell first, then every other cell,
    in ascending id, of a landblock present in the scene whose 24 m x 24 m square the object's
    bounding sphere (`bounding_sphere`) reaches horizontally. ACE itself would find these with
    find_cell_list / find_bbox_cell_list from DAT bounding data that scenes do not carry.
    """
    own = obj.position.cell
    (cx, cy, _), r = bounding_sphere(obj)
    bx, by = (own >> 24) & 0xFF, (own >> 16) & 0xFF
    gx, gy = bx * BLOCK_SIZE + cx, by * BLOCK_SIZE + cy
    present = {lb >> 16 for lb in landblock_ids}
    cells = []
    for ix in range(math.floor((gx - r) / CELL_SIZE), math.floor((gx + r) / CELL_SIZE) + 1):
        for iy in range(math.floor((gy - r) / CELL_SIZE), math.floor((gy + r) / CELL_SIZE) + 1):
            if ix < 0 or iy < 0 or ix >= 255 * 8 or iy >= 255 * 8:
                continue
            # nearest point of the square to the centre
            nx = min(max(gx, ix * CELL_SIZE), (ix + 1) * CELL_SIZE)
            ny = min(max(gy, iy * CELL_SIZE), (iy + 1) * CELL_SIZE)
            if (nx - gx) ** 2 + (ny - gy) ** 2 > r * r:
                continue
            lb = ((ix // 8) << 8) | (iy // 8)
            if lb not in present:
                continue
            cell = (lb << 16) | ((ix % 8) * 8 + (iy % 8) + 1)
            if cell != own:
                cells.append(cell)
    return [own] + sorted(cells)


def mover_setup_dims(scene: Scene) -> tuple[float, float]:
    """Setup Height and Radius the oracle gives the mover: top of the highest sphere, largest radius."""
    sph = scene.mover.spheres
    return max(s.center[2] + s.radius for s in sph), max(s.radius for s in sph)
