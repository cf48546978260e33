"""Terrain strategies: height fields made of features, terrain words (water), and exact ground z.

A terrain is drawn as a *field* over global vertex coordinates (one vertex every 24 m), built
from features placed relative to the mover (cliffs, ramps, plateaus, pits, water, noise) and
then sliced into whichever landblocks the mover can reach, so neighbouring landblocks always
agree on their shared edge vertices.

Slopes around FloorZ. A land triangle whose vertices follow height indices with per-vertex
gradient (i, j) (default land height table 2.0 * idx, cells 24 m) has normal z
``1 / sqrt(1 + (2i/24)^2 + (2j/24)^2)``; it is walkable (nz >= FloorZ = 0.66417414...) iff
``i^2 + j^2 <= 182`` (the bound is 576 * (1/FloorZ^2 - 1) / 4 = 182.43). The nearest gradients
on either side are i^2 + j^2 = 181 ((10, 9): nz = 0.66564) and 185 ((13, 4), (11, 8):
nz = 0.66157); along one axis 13 (26 m a cell, nz = 0.67828) is walkable and 14 (28 m,
nz = 0.65079) is not. `STRADDLING_GRADIENTS` lists them; tests pin the arithmetic.

Water: ACE reads a vertex's terrain type as ``word >> 2 & 0x1F`` and types 0x10..0x14
(WaterRunning .. WaterDeepSea) are water (LandblockStruct.SurfChar); a cell with every corner
water is EntirelyWater, with some PartiallyWater (LandblockStruct.CalcCellWater). A block
that is entirely water collides everything, so water regions are kept smaller than a block.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from hypothesis import strategies as st

from acconform.numerics import to_f32
from acconform.scene import DEFAULT_LAND_HEIGHT_TABLE, Landblock

CELL = 24.0
BLOCK = 192.0
FLOOR_Z = 0.66417414618662751  # PhysicsGlobals.FloorZ as C# writes it (float32 0x3F2A0751)

# terrain words: bits 0-1 road, 2-6 terrain type, 11-15 scenery
GRASSLAND = 0x1 << 2
WATER_TYPES = (0x10, 0x11, 0x12, 0x13, 0x14)
LAND_TYPES = (0x0, 0x1, 0x3, 0x5, 0x7, 0xA, 0xD)


def is_water_word(word: int) -> bool:
    return 0x10 <= (word >> 2 & 0x1F) <= 0x14


def walkable_index_gradient(i: int, j: int, step: float = 2.0) -> bool:
    """Whether a land triangle with height-index gradient (i, j) per 24 m is walkable (exact, doubles)."""
    nz = 1.0 / math.sqrt(1.0 + (step * i / CELL) ** 2 + (step * j / CELL) ** 2)
    return nz >= FLOOR_Z


# (i, j) index gradients nearest FloorZ on both sides, walkable first then not.
STRADDLING_GRADIENTS: tuple[tuple[int, int], ...] = (
    (10, 9), (9, 10), (13, 0), (0, 13), (13, 3), (12, 6),   # walkable: i^2+j^2 in 169..181
    (13, 4), (4, 13), (11, 8), (8, 11), (14, 0), (0, 14),   # not walkable: 185..196
)


# ---------------------------------------------------------------- the field


@dataclass(frozen=True, slots=True)
class Feature:
    """One height or terrain-word feature over global vertex coordinates (gx, gy).

    kind: "step" (half-plane a*gx + b*gy >= c raised by k), "ramp" (inside the box, heights follow
    gradient (i, j) from the box's low corner, outside clamped to its edge values), "box"
    (plateau k > 0 or pit k < 0 inside [x0, x1] x [y0, y1]), "water" (terrain type inside the box).
    """

    kind: str
    x0: int = 0
    y0: int = 0
    x1: int = 0
    y1: int = 0
    a: int = 0
    b: int = 0
    c: int = 0
    k: int = 0
    i: int = 0
    j: int = 0
    water_type: int = 0x11


@dataclass(frozen=True, slots=True)
class Field:
    base: int
    features: tuple[Feature, ...]
    noise: int = 0  # amplitude in height indices
    noise_seed: int = 0
    land_type: int = 0x1

    def height(self, gx: int, gy: int) -> int:
        h = self.base
        for f in self.features:
            if f.kind == "step":
                if f.a * gx + f.b * gy >= f.c:
                    h += f.k
            elif f.kind == "box":
                if f.x0 <= gx <= f.x1 and f.y0 <= gy <= f.y1:
                    h += f.k
            elif f.kind == "ramp":
                cx = min(max(gx, f.x0), f.x1) - f.x0
                cy = min(max(gy, f.y0), f.y1) - f.y0
                h += f.i * cx + f.j * cy
        if self.noise:
            h += _hash(self.noise_seed, gx, gy) % (2 * self.noise + 1) - self.noise
        return min(max(h, 0), 255)

    def word(self, gx: int, gy: int) -> int:
        t = self.land_type
        for f in self.features:
            if f.kind == "water" and f.x0 <= gx <= f.x1 and f.y0 <= gy <= f.y1:
                t = f.water_type
        return t << 2

    def landblock(self, bx: int, by: int) -> Landblock:
        heights = []
        terrain = []
        for x in range(9):
            for y in range(9):
                gx, gy = bx * 8 + x, by * 8 + y
                heights.append(self.height(gx, gy))
                terrain.append(self.word(gx, gy))
        return Landblock((bx << 24) | (by << 16) | 0xFFFF, tuple(heights), tuple(terrain))


def _hash(seed: int, x: int, y: int) -> int:
    h = (seed * 0x9E3779B1 + x * 0x85EBCA77 + y * 0xC2B2AE3D) & 0xFFFFFFFF
    h ^= h >> 15
    h = (h * 0x2C1B3C6D) & 0xFFFFFFFF
    h ^= h >> 12
    return h


# ---------------------------------------------------------------- exact ground


def sw_to_ne_cut(bx: int, by: int, cx: int, cy: int) -> bool:
    """Which diagonal splits land cell (cx, cy) of landblock (bx, by) (LandblockStruct.ConstructPolygons).

    The split is a function of the global cell coordinate: uint32 arithmetic on the seeds, then
    ``splitDir * 2.3283064e-10 < 0.5`` (a double compare) picks the SE-NW cut (False).
    """
    lx = (bx * 8 + cx) & 0xFFFFFFFF
    ly = by * 8 + cy
    seed_a = (lx * 214614067) & 0xFFFFFFFF
    seed_b = (lx * 1109124029) & 0xFFFFFFFF
    magic_a = (seed_a + 1813693831) & 0xFFFFFFFF
    split = (ly * magic_a - seed_b - 1369149221) & 0xFFFFFFFF
    return not (split * 2.3283064e-10 < 0.5)


def cell_triangle(lb: Landblock, table, x: float, y: float):
    """The three vertices (landblock-local, metres) of the land triangle under local (x, y)."""
    cx = min(int(x // CELL), 7)
    cy = min(int(y // CELL), 7)
    fx, fy = x - cx * CELL, y - cy * CELL

    def v(ix, iy):
        return (float((cx + ix) * CELL), float((cy + iy) * CELL), float(table[lb.heights[(cx + ix) * 9 + cy + iy]]))

    bx, by = lb.id >> 24, (lb.id >> 16) & 0xFF
    if sw_to_ne_cut(bx, by, cx, cy):
        # triangles (00, 10, 11) and (00, 11, 01): split along the SW-NE diagonal
        return (v(0, 0), v(1, 0), v(1, 1)) if fx >= fy else (v(0, 0), v(1, 1), v(0, 1))
    # triangles (00, 10, 01) and (11, 01, 10): split along the SE-NW diagonal
    return (v(0, 0), v(1, 0), v(0, 1)) if fx + fy <= CELL else (v(1, 1), v(0, 1), v(1, 0))


def triangle_plane(tri):
    """Unit upward normal and d (n . p + d = 0) of a triangle, in doubles."""
    (x0, y0, z0), (x1, y1, z1), (x2, y2, z2) = tri
    ux, uy, uz = x1 - x0, y1 - y0, z1 - z0
    vx, vy, vz = x2 - x0, y2 - y0, z2 - z0
    nx, ny, nz = uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx
    if nz < 0:
        nx, ny, nz = -nx, -ny, -nz
    n = math.sqrt(nx * nx + ny * ny + nz * nz)
    nx, ny, nz = nx / n, ny / n, nz / n
    return (nx, ny, nz), -(nx * x0 + ny * y0 + nz * z0)


def ground(lb: Landblock, x: float, y: float, table=DEFAULT_LAND_HEIGHT_TABLE):
    """(z, normal, d) of the terrain at landblock-local (x, y), z rounded to float32, normal and d too."""
    normal, d = triangle_plane(cell_triangle(lb, table, x, y))
    z = -(normal[0] * x + normal[1] * y + d) / normal[2]
    return to_f32(z), tuple(to_f32(c) for c in normal), to_f32(d)


# ---------------------------------------------------------------- strategies


def landblock_coords(lo: int = 0x01, hi: int = 0xFD):
    """A landblock (x, y), away from column/row 0xFF (GetBlockOffset throws there in ACE)."""
    return st.tuples(st.integers(lo, hi), st.integers(lo, hi))


# height index deltas: small bumps, the FloorZ straddle (13/14), cliffs
STEP_DELTAS = st.one_of(
    st.sampled_from((13, 14, -13, -14, 12, 15, -12, -15)),
    st.integers(-40, 40),
    st.sampled_from((30, -30, 60, -60, 1, -1)),
)


DIRECTIONS = st.sampled_from(((1, 0), (0, 1), (-1, 0), (0, -1), (1, 1), (1, -1), (-1, 1), (-1, -1)))
CLIFF_DOWN = st.integers(-24, -14)  # tan 1.17 .. 2.0 over one cell: unwalkable, yet a step-down can reach it


@st.composite
def features_near(draw, gx: int, gy: int, tilt: bool = False):
    """Terrain features whose edges pass within a cell or two of global vertex (gx, gy).

    Each optional feature is switched on by a draw that shrinks to off (0), so a shrunk scene
    keeps only the features its difference needs. `tilt` always tilts the neighbourhood (a
    sloped contact plane on both sides of a block border).
    """
    out = []
    n = draw(st.integers(0, 3))
    if tilt:
        i, j = draw(st.integers(1, 3)) * draw(st.sampled_from((1, -1))), draw(st.integers(-3, 3))
        if draw(st.booleans()):
            i, j = j, i
        out.append(Feature("ramp", x0=gx - 16, y0=gy - 16, x1=gx + 16, y1=gy + 16, i=i, j=j))
    if draw(st.integers(0, 2)) == 2:
        # policy: a cliff edge (a down step steeper than FloorZ but within reach of a step-down)
        a, b = draw(DIRECTIONS)
        d = draw(st.integers(-1, 2))
        out.append(Feature("step", a=a, b=b, c=a * (gx + d) + b * (gy + d), k=draw(CLIFF_DOWN)))
    if draw(st.integers(0, 2)) >= 1:
        # policy (2 in 3): a slope just either side of FloorZ starting at the next vertex over
        i, j = draw(st.sampled_from(STRADDLING_GRADIENTS))
        si, sj = draw(st.sampled_from((1, -1))), draw(st.sampled_from((1, -1)))
        x0, y0 = gx + draw(st.integers(-1, 1)), gy + draw(st.integers(-1, 1))
        out.append(Feature("ramp", x0=x0, y0=y0, x1=x0 + 2, y1=y0 + 2, i=si * i, j=sj * j))
    if not tilt and draw(st.integers(0, 2)) == 2:
        # policy: tilt the whole neighbourhood gently, so block borders have sloped contact planes
        out.append(Feature("ramp", x0=gx - 16, y0=gy - 16, x1=gx + 16, y1=gy + 16,
                           i=draw(st.integers(-3, 3)), j=draw(st.integers(-3, 3))))
    for _ in range(n):
        kind = draw(st.sampled_from(("step", "ramp", "box", "water", "step", "ramp")))
        dx, dy = draw(st.integers(-1, 2)), draw(st.integers(-1, 2))
        if kind == "step":
            a, b = draw(st.sampled_from(((1, 0), (0, 1), (-1, 0), (0, -1), (1, 1), (1, -1), (-1, 1), (-1, -1))))
            c = a * (gx + dx) + b * (gy + dy)
            out.append(Feature("step", a=a, b=b, c=c, k=draw(STEP_DELTAS)))
        elif kind == "ramp":
            i, j = draw(st.one_of(st.sampled_from(STRADDLING_GRADIENTS), st.tuples(st.integers(-6, 6), st.integers(-6, 6))))
            si, sj = draw(st.sampled_from((1, -1))), draw(st.sampled_from((1, -1)))
            w, h = draw(st.integers(1, 4)), draw(st.integers(1, 4))
            x0, y0 = gx + dx - draw(st.integers(0, w)), gy + dy - draw(st.integers(0, h))
            out.append(Feature("ramp", x0=x0, y0=y0, x1=x0 + w, y1=y0 + h, i=si * i, j=sj * j))
        elif kind == "box":
            w, h = draw(st.integers(0, 3)), draw(st.integers(0, 3))
            x0, y0 = gx + dx - draw(st.integers(0, w + 1)), gy + dy - draw(st.integers(0, h + 1))
            out.append(Feature("box", x0=x0, y0=y0, x1=x0 + w, y1=y0 + h, k=draw(STEP_DELTAS)))
        else:
            w, h = draw(st.integers(0, 4)), draw(st.integers(0, 4))
            x0, y0 = gx + dx - draw(st.integers(0, w)), gy + dy - draw(st.integers(0, h))
            out.append(Feature("water", x0=x0, y0=y0, x1=x0 + w, y1=y0 + h, water_type=draw(st.sampled_from(WATER_TYPES))))
    return tuple(out)


@st.composite
def fields_near(draw, gx: int, gy: int, flat: bool = False, tilt: bool = False):
    """A terrain field with features around global vertex (gx, gy); `flat` keeps it level or
    gently tilted (for objects), `tilt` always tilts it (see features_near)."""
    base = draw(st.integers(60, 140))
    land_type = draw(st.sampled_from(LAND_TYPES))
    if flat:
        if not draw(st.booleans()):
            return Field(base, (), 0, 0, land_type)
        i, j = draw(st.integers(-3, 3)), draw(st.integers(-3, 3))
        return Field(base, (Feature("ramp", x0=gx - 12, y0=gy - 12, x1=gx + 12, y1=gy + 12, i=i, j=j),), 0, 0, land_type)
    feats = draw(features_near(gx, gy, tilt))
    noise = draw(st.sampled_from((0, 0, 0, 1, 2, 5)))
    seed = draw(st.integers(0, 2**16)) if noise else 0
    return Field(base, feats, noise, seed, land_type)
