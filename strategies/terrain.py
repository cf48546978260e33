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

Generation cost: features are drawn around vertex (0, 0) by strategies built once, then moved to
the mover's vertex (a strategy built per scene cost more than the draws it made), and a block is
sliced from the field in one numpy pass per feature (`Field.landblock`; `Field.height` and
`Field.word` stay the vertex-by-vertex definition, and tests pin the two together).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from hypothesis import strategies as st

from acconform.numerics import to_f32
from acconform.port.constants import FLOOR_Z
from acconform.scene import DEFAULT_LAND_HEIGHT_TABLE, Landblock

from . import draws as dr

CELL = 24.0
BLOCK = 192.0

# terrain words: bits 0-1 road, 2-6 terrain type, 11-15 scenery
GRASSLAND = 0x1 << 2
WATER_TYPES = (0x10, 0x11, 0x12, 0x13, 0x14)
LAND_TYPES = (0x0, 0x1, 0x3, 0x5, 0x7, 0xA, 0xD)


def cell_of(bx: int, by: int, lx: float, ly: float) -> int:
    """The id of the land cell of landblock (bx, by) holding the block-local point (lx, ly)."""
    cx = min(max(int(lx // CELL), 0), 7)
    cy = min(max(int(ly // CELL), 0), 7)
    return (bx << 24) | (by << 16) | (1 + cx * 8 + cy)


def split_global(gx: float, gy: float) -> tuple[int, int, float, float]:
    """(block x, block y, local x, local y) of a global point; locals are exact float32s in [0, 192)."""
    bx, by = int(gx // BLOCK), int(gy // BLOCK)
    lx, ly = to_f32(gx - bx * BLOCK), to_f32(gy - by * BLOCK)
    if lx >= BLOCK:  # rounding up to 192.0 belongs to the next block
        bx, lx = bx + 1, 0.0
    if ly >= BLOCK:
        by, ly = by + 1, 0.0
    return bx, by, lx, ly


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

    def moved(self, dx: int, dy: int) -> Feature:
        """The same feature shifted by (dx, dy) vertices."""
        return Feature(self.kind, self.x0 + dx, self.y0 + dy, self.x1 + dx, self.y1 + dy, self.a, self.b,
                       self.c + self.a * dx + self.b * dy, self.k, self.i, self.j, self.water_type)


# a landblock's 9 x 9 vertex offsets, x down the rows (heights are stored x-major)
_VX = np.arange(9, dtype=np.int64).reshape(9, 1)
_VY = np.arange(9, dtype=np.int64).reshape(1, 9)


@dataclass(frozen=True, slots=True)
class Field:
    """A height field: `height` and `word` define it vertex by vertex; `landblock` computes the
    same 81 values for a whole block at once (numpy, one pass per feature), which is what scene
    generation slices several times a scene. tests/strategies pins the two against each other."""

    base: int
    features: tuple[Feature, ...]
    noise: int = 0  # amplitude in height indices
    noise_seed: int = 0
    land_type: int = 0x1

    def moved(self, dx: int, dy: int) -> Field:
        """The same field shifted by (dx, dy) vertices (the noise stays put: it is global)."""
        return Field(self.base, tuple(f.moved(dx, dy) for f in self.features), self.noise, self.noise_seed,
                     self.land_type)

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
        lb_id = (bx << 24) | (by << 16) | 0xFFFF
        if not self.features and not self.noise:  # level ground
            return Landblock(lb_id, (min(max(self.base, 0), 255),) * 81, (self.land_type << 2,) * 81)
        gx, gy = _VX + bx * 8, _VY + by * 8
        h = np.full((9, 9), self.base, dtype=np.int64)
        t = None
        for f in self.features:
            if f.kind == "step":
                h += np.where(f.a * gx + f.b * gy >= f.c, f.k, 0)
            elif f.kind == "box":
                h += np.where((f.x0 <= gx) & (gx <= f.x1), f.k, 0) * ((f.y0 <= gy) & (gy <= f.y1))
            elif f.kind == "ramp":  # (np.clip is several times slower than this on 9 values)
                h += f.i * (np.minimum(np.maximum(gx, f.x0), f.x1) - f.x0)
                h += f.j * (np.minimum(np.maximum(gy, f.y0), f.y1) - f.y0)
            elif f.kind == "water":
                if t is None:
                    t = np.full((9, 9), self.land_type, dtype=np.int64)
                t[((f.x0 <= gx) & (gx <= f.x1)) & ((f.y0 <= gy) & (gy <= f.y1))] = f.water_type
        if self.noise:
            h += _hash(self.noise_seed, gx, gy) % (2 * self.noise + 1) - self.noise
        heights = tuple(np.minimum(np.maximum(h, 0), 255).ravel().tolist())
        terrain = (self.land_type << 2,) * 81 if t is None else tuple((t << 2).ravel().tolist())
        return Landblock(lb_id, heights, terrain)


def _hash(seed, x, y):
    """A 32-bit mix of (seed, x, y); x and y may be int64 arrays (every step stays below 2**63)."""
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
#
# Every strategy here is a module constant (see strategies/draws.py for why): features and fields
# are drawn around vertex (0, 0) and moved to the mover's vertex afterwards (`field_near`), so
# the strategy that draws them does not depend on where the mover is.


def landblock_coords(lo: int = 0x01, hi: int = 0xFD):
    """A landblock (x, y), away from column/row 0xFF (GetBlockOffset throws there in ACE)."""
    return st.tuples(st.integers(lo, hi), st.integers(lo, hi))


# height index deltas: small bumps, the FloorZ straddle (13/14), cliffs
STEP_DELTAS = dr.OneOf(
    st.sampled_from((13, 14, -13, -14, 12, 15, -12, -15)),
    dr.ints(-40, 40),
    st.sampled_from((30, -30, 60, -60, 1, -1)),
)


DIRECTIONS = st.sampled_from(((1, 0), (0, 1), (-1, 0), (0, -1), (1, 1), (1, -1), (-1, 1), (-1, -1)))
CLIFF_DOWN = dr.ints(-24, -14)  # tan 1.17 .. 2.0 over one cell: unwalkable, yet a step-down can reach it
SIGNS = st.sampled_from((1, -1))
GENTLE = dr.ints(-3, 3)  # a neighbourhood's tilt, in height indices per cell
STRADDLING = st.sampled_from(STRADDLING_GRADIENTS)
RAMP_GRADIENTS = dr.OneOf(STRADDLING, st.tuples(dr.ints(-6, 6), dr.ints(-6, 6)))
FEATURE_KINDS = st.sampled_from(("step", "ramp", "box", "water", "step", "ramp"))
WATER = st.sampled_from(WATER_TYPES)
FEATURE_COUNTS = dr.ints(0, 3)
THIRDS = dr.ints(0, 2)  # a policy's switch: on at 2 (or at 1 and 2), off where shrinking goes
STEEPNESS = dr.ints(1, 3)
NEAR = dr.ints(-1, 1)  # vertices from (0, 0)
OFFSETS = dr.ints(-1, 2)
RAMP_SIZES, BOX_SIZES, WATER_SIZES = dr.ints(1, 4), dr.ints(0, 3), dr.ints(0, 4)  # cells


@st.composite
def features_near(draw, tilt: bool = False) -> tuple[Feature, ...]:
    """Terrain features whose edges pass within a cell or two of vertex (0, 0).

    Each optional feature is switched on by a draw that shrinks to off (0), so a shrunk scene
    keeps only the features its difference needs. `tilt` always tilts the neighbourhood (a
    sloped contact plane on both sides of a block border).
    """
    out = []
    n = draw(FEATURE_COUNTS)
    if tilt:
        i, j = draw(STEEPNESS) * draw(SIGNS), draw(GENTLE)
        if draw(dr.BOOLEANS):
            i, j = j, i
        out.append(Feature("ramp", x0=-16, y0=-16, x1=16, y1=16, i=i, j=j))
    if draw(THIRDS) == 2:
        # policy: a cliff edge (a down step steeper than FloorZ but within reach of a step-down)
        a, b = draw(DIRECTIONS)
        d = draw(OFFSETS)
        out.append(Feature("step", a=a, b=b, c=a * d + b * d, k=draw(CLIFF_DOWN)))
    if draw(THIRDS) >= 1:
        # policy (2 in 3): a slope just either side of FloorZ starting at the next vertex over
        i, j = draw(STRADDLING)
        si, sj = draw(SIGNS), draw(SIGNS)
        x0, y0 = draw(NEAR), draw(NEAR)
        out.append(Feature("ramp", x0=x0, y0=y0, x1=x0 + 2, y1=y0 + 2, i=si * i, j=sj * j))
    if not tilt and draw(THIRDS) == 2:
        # policy: tilt the whole neighbourhood gently, so block borders have sloped contact planes
        out.append(Feature("ramp", x0=-16, y0=-16, x1=16, y1=16, i=draw(GENTLE), j=draw(GENTLE)))
    for _ in range(n):
        kind = draw(FEATURE_KINDS)
        dx, dy = draw(OFFSETS), draw(OFFSETS)
        if kind == "step":
            a, b = draw(DIRECTIONS)
            out.append(Feature("step", a=a, b=b, c=a * dx + b * dy, k=dr.take(draw, STEP_DELTAS)))
        elif kind == "ramp":
            i, j = dr.take(draw, RAMP_GRADIENTS)
            si, sj = draw(SIGNS), draw(SIGNS)
            w, h = draw(RAMP_SIZES), draw(RAMP_SIZES)
            x0, y0 = dx - dr.index(draw, w + 1), dy - dr.index(draw, h + 1)
            out.append(Feature("ramp", x0=x0, y0=y0, x1=x0 + w, y1=y0 + h, i=si * i, j=sj * j))
        elif kind == "box":
            w, h = draw(BOX_SIZES), draw(BOX_SIZES)
            x0, y0 = dx - dr.index(draw, w + 2), dy - dr.index(draw, h + 2)
            out.append(Feature("box", x0=x0, y0=y0, x1=x0 + w, y1=y0 + h, k=dr.take(draw, STEP_DELTAS)))
        else:
            w, h = draw(WATER_SIZES), draw(WATER_SIZES)
            x0, y0 = dx - dr.index(draw, w + 1), dy - dr.index(draw, h + 1)
            out.append(Feature("water", x0=x0, y0=y0, x1=x0 + w, y1=y0 + h, water_type=draw(WATER)))
    return tuple(out)


FEATURES = {tilt: dr.eager(features_near(tilt)) for tilt in (False, True)}
BASES = dr.ints(60, 140)
LAND = st.sampled_from(LAND_TYPES)
NOISE = st.sampled_from((0, 0, 0, 1, 2, 5))
NOISE_SEEDS = dr.ints(0, 2**16)


@st.composite
def _fields(draw, flat: bool, tilt: bool) -> Field:
    """A terrain field with features around vertex (0, 0); `flat` keeps it level or gently tilted
    (for objects), `tilt` always tilts it (see features_near)."""
    base = draw(BASES)
    land_type = draw(LAND)
    if flat:
        if not draw(dr.BOOLEANS):
            return Field(base, (), 0, 0, land_type)
        i, j = draw(GENTLE), draw(GENTLE)
        return Field(base, (Feature("ramp", x0=-12, y0=-12, x1=12, y1=12, i=i, j=j),), 0, 0, land_type)
    feats = draw(FEATURES[tilt])
    noise = draw(NOISE)
    seed = draw(NOISE_SEEDS) if noise else 0
    return Field(base, feats, noise, seed, land_type)


# one strategy per (flat, tilt) the scenes ask for: a field around vertex (0, 0)
FIELDS = {(flat, tilt): dr.eager(_fields(flat, tilt)) for flat, tilt in ((False, False), (False, True), (True, False))}


def field_near(draw, gx: int, gy: int, flat: bool = False, tilt: bool = False) -> Field:
    """Draw a field with features around global vertex (gx, gy) (flat and tilt as in _fields)."""
    return draw(FIELDS[flat, tilt]).moved(gx, gy)


def fields_near(gx: int, gy: int, flat: bool = False, tilt: bool = False):
    """field_near as a strategy."""
    return FIELDS[flat, tilt].map(lambda f: f.moved(gx, gy))
