"""Exact boundaries by construction: float32 geometry solved so that ACE's own arithmetic lands
on a threshold's bit pattern, not near it (slopes at FloorZ and LandingZ, tangent obstacles).

A walkable test (`normal.z >= FloorZ`), a landing test (`>= LandingZ`) or a `>=`/`>` swap in
either changes behaviour only when the computed normal.z *is* the constant. Drawn at random, a
float32 slope hits that value about once in ten million polygons, so no campaign ever tests
that ulp. Here the slope is solved for: the rise of a ramp is searched over float32 bit
patterns, a few ulps either side of the analytic value, until the port's `Polygon.make_plane`
(the routine ACE's DAT polygon constructor runs, pinned against ACE) gives the target bits.

The port is the judge because the scene records only vertices: both sides compute the plane
from them, ACE with its own code and the port with its pinned copy, so a rise that makes the
port land on FloorZ makes ACE land there too (the per-function lane checks make_plane).
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np

from acconform.numerics import EXACT, Mode, f32_bits, f32_from_bits, to_f32
from acconform.port.constants import EPSILON, FLOOR_Z, LANDING_Z
from acconform.port.geom.polygon import Polygon
from acconform.scene import PolygonRec

# the normal.z thresholds and the ulps either side of each: name -> float32 bit pattern
Z_BOUNDARIES: dict[str, int] = {}
for _name, _z in (("floor_z", FLOOR_Z), ("landing_z", LANDING_Z)):
    _b = f32_bits(_z)
    Z_BOUNDARIES[_name] = _b
    Z_BOUNDARIES[f"{_name}-1ulp"] = _b - 1
    Z_BOUNDARIES[f"{_name}+1ulp"] = _b + 1

# how far (in ulps of the rise) from the analytic rise the search looks; every target above is
# found within 2 ulps for the runs the strategies draw (tests/strategies/test_boundaries.py)
SEARCH_ULPS = 16


def slope_polygon(sx: float, sy: float, sz: float) -> PolygonRec:
    """The sloped face of `shapes.wedge(sx, sy, sz)`: rising along +x from 0 to sz."""
    x0, x1, y0, y1 = to_f32(-sx / 2), to_f32(sx / 2), to_f32(-sy / 2), to_f32(sy / 2)
    return PolygonRec(((x0, y0, 0.0), (x1, y0, sz), (x1, y1, sz), (x0, y1, 0.0)))


def plane_normal_z_bits(poly: PolygonRec, mode: Mode = EXACT) -> int:
    """The bits of normal.z that ACE's DAT polygon constructor (make_plane) computes for `poly`."""
    return f32_bits(Polygon.from_rec(poly, mode).plane.normal.z)


@lru_cache(maxsize=None)
def slope_normal(sx: float, sy: float, sz: float, mode: Mode = EXACT) -> tuple[float, float, float]:
    """The slope's plane normal as ACE's DAT polygon constructor computes it (local frame)."""
    n = Polygon.from_rec(slope_polygon(sx, sy, sz), mode).plane.normal
    return float(n.x), float(n.y), float(n.z)


@lru_cache(maxsize=None)
def wedge_rise_for(sx: float, sy: float, target_bits: int, mode: Mode = EXACT) -> float | None:
    """A float32 rise sz for which `shapes.wedge(sx, sy, sz)`'s slope has normal.z == target_bits
    exactly (the rise nearest the analytic one), or None when none lies within SEARCH_ULPS."""
    z = f32_from_bits(target_bits)
    run = float(to_f32(sx / 2)) - float(to_f32(-sx / 2))
    base = f32_bits(to_f32(run * math.sqrt(1.0 / (z * z) - 1.0)))
    for k in sorted(range(-SEARCH_ULPS, SEARCH_ULPS + 1), key=abs):
        sz = f32_from_bits(base + k)
        if plane_normal_z_bits(slope_polygon(sx, sy, sz), mode) == target_bits:
            return sz
    return None


# the ramp sizes the boundary strategies draw from: run along the slope (sx) and width (sy)
RAMP_RUNS = (0.5, 0.75, 1.0, 1.5, 2.0, 3.0, 4.0, 5.0, 6.0, 8.0)
RAMP_WIDTHS = (1.0, 2.0, 3.3)


@lru_cache(maxsize=None)
def exact_wedges(target_bits: int, mode: Mode = EXACT) -> tuple[tuple[float, float, float], ...]:
    """Every (sx, sy, sz) from RAMP_RUNS x RAMP_WIDTHS whose slope lands exactly on target_bits.
    Some pairs have none: normalize's float32 output skips values (a rise one ulp up moves
    normal.z by more than one ulp), so the table keeps only the pairs that reach the target."""
    found = []
    for sx in RAMP_RUNS:
        for sy in RAMP_WIDTHS:
            sz = wedge_rise_for(sx, sy, target_bits, mode)
            if sz is not None:
                found.append((sx, sy, sz))
    return tuple(found)


# ACE's sledding threshold (PhysicsObj.calc_friction: a Sledding mover glides on a contact plane
# with `normal.z > 0.99999536f`) and an ulp either side, as wedge slopes (sx, sy, sz) through
# make_plane. Near 1 normalize skips most bit patterns (a one-cell terrain rise reaches the
# threshold itself but neither neighbour), so these were searched through the port, a few thousand
# ulps of sz around the analytic rise, and are kept as data; tests/strategies/test_ticks.py checks
# that each lands on its bits.
SLED_Z_BOUNDARIES: dict[str, int] = {"sledding_flat_z": 0x3F7FFFB2, "sledding_flat_z-1ulp": 0x3F7FFFB1,
                                     "sledding_flat_z+1ulp": 0x3F7FFFB3}
SLED_WEDGES: dict[str, tuple[tuple[float, float, float], ...]] = {
    "sledding_flat_z": ((1.0, 2.0, 0.003049326129257679), (2.0, 3.3, 0.006098652258515358),
                        (4.0, 2.0, 0.012197304517030716), (5.0, 3.3, 0.015246630646288395),
                        (8.0, 3.3, 0.024394609034061432)),
    "sledding_flat_z-1ulp": ((0.75, 1.0, 0.0023016082122921944), (1.5, 2.0, 0.004603216424584389),
                             (3.0, 3.3, 0.009206432849168777), (6.0, 2.0, 0.018412865698337555),
                             (8.0, 3.3, 0.024550486356019974)),
    "sledding_flat_z+1ulp": ((0.75, 1.0, 0.002272286918014288), (1.5, 2.0, 0.004544573836028576),
                             (3.0, 2.0, 0.009089147672057152), (5.0, 2.0, 0.015148579142987728),
                             (6.0, 2.0, 0.018178295344114304)),
}
# the one-cell terrain rise (table[1], boundaries.terrain_rise_for's search) whose normal.z is the threshold
SLED_TERRAIN_RISE = 0.0731838271021843


# ---------------------------------------------------------------- tangency
# Block-local coordinates in [64, 128) are the multiples of 2^-17 there, so a sum of such a
# coordinate and a length that is itself a multiple of 2^-17 is exact when it stays in range.
# A mover moving along an axis by such a length, in one step (no longer than its radius), checks
# its sphere exactly at its end; an obstacle centred exactly the radius sum beyond the end (the
# radius sum as ACE computes it, itself a multiple of 2^-17) is then exactly tangent there:
# disp is (radsum, 0, 0), disp.LengthSquared() == radsum * radsum bit for bit.
GRID = 2.0 ** -17
GRID_LO, GRID_HI = 64.0, 128.0


def on_grid(x) -> bool:
    return float(x) % GRID == 0.0


def sphere_radsum(mover_r, obstacle_r):
    """Sphere.IntersectsSphere's radius sum: glob_sphere.radius + radius - EPSILON (float32)."""
    return (np.float32(mover_r) + np.float32(obstacle_r)) - np.float32(EPSILON)


def cylsphere_radsum(mover_r, cyl_r):
    """CylSphere.IntersectsSphere's radius sum: radius - EPSILON + glob_sphere.radius (float32)."""
    return (np.float32(cyl_r) - np.float32(EPSILON)) + np.float32(mover_r)


@lru_cache(maxsize=4096)
def tangent_radius(kind: str, mover_r: float, want: float) -> tuple[float, float]:
    """(obstacle radius, radius sum): a float32 radius near `want` (at or above it, bar rounding)
    whose radius sum with a mover of radius mover_r, as ACE computes it for `kind` ("sphere" or
    "cylsphere"), is a multiple of GRID."""
    radsum = sphere_radsum if kind == "sphere" else cylsphere_radsum
    target = math.ceil(float(radsum(mover_r, want)) / GRID) * GRID
    for _ in range(64):
        # the radius whose sum lands on `target`, searched a few ulps around the real solution
        b = f32_bits(to_f32(target + float(EPSILON) - float(np.float32(mover_r))))
        for k in sorted(range(-4, 5), key=abs):
            r = f32_from_bits(b + k)
            if float(radsum(mover_r, r)) == target:
                return r, target
        target += GRID
    # a mover radius with bits below the sum's ulp can round every sum to even: only some
    # sums are reachable. A mover radius that is a multiple of GRID never has that problem.
    raise ValueError(f"no {kind} radius near {want} gives a radius sum on the grid with mover radius {mover_r}"
                     " (round the mover radius to a multiple of GRID)")


def grid_floor(x: float) -> float:
    """The multiple of GRID at or below x."""
    return math.floor(x / GRID) * GRID


# ---------------------------------------------------------------- terrain slopes
# A land cell whose two west (or south) corners sit at height index 0 and whose two east (north)
# corners at index 1 is one plane rising by table[1] - table[0] over 24 m, and both its
# triangles compute the same normal (each cross product is (-+24 dz, 0, 576) or its y twin,
# whatever the cut). With table[0] = 0 the rise is table[1] itself, so the scene's land height
# table (scene data: both sides build the landblock from it) is solved instead of a vertex.
TERRAIN_RUN = 24.0


def terrain_polygon(rise: float) -> PolygonRec:
    """A land triangle of a cell rising by `rise` along +x: (00, 10, 11) as LandblockStruct links it."""
    return PolygonRec(((0.0, 0.0, 0.0), (TERRAIN_RUN, 0.0, rise), (TERRAIN_RUN, TERRAIN_RUN, rise)))


@lru_cache(maxsize=None)
def terrain_rise_for(target_bits: int, mode: Mode = EXACT) -> float | None:
    """A float32 table[1] (with table[0] = 0) whose one-index rise over a land cell gives normal.z
    == target_bits exactly through make_plane, or None within SEARCH_ULPS of the analytic rise."""
    z = f32_from_bits(target_bits)
    base = f32_bits(to_f32(TERRAIN_RUN * math.sqrt(1.0 / (z * z) - 1.0)))
    for k in sorted(range(-SEARCH_ULPS, SEARCH_ULPS + 1), key=abs):
        rise = f32_from_bits(base + k)
        if plane_normal_z_bits(terrain_polygon(rise), mode) == target_bits:
            return rise
    return None


def exact_terrain_targets(mode: Mode = EXACT) -> tuple[tuple[str, float], ...]:
    """(boundary name, table[1]) for every Z_BOUNDARIES entry a one-cell terrain rise reaches."""
    return tuple((name, rise) for name, bits in Z_BOUNDARIES.items()
                 if (rise := terrain_rise_for(bits, mode)) is not None)


def exact_slope_table(rise: float) -> tuple[float, ...]:
    """The default land height table with table[0] = 0 (already) and table[1] = rise."""
    from acconform.scene import DEFAULT_LAND_HEIGHT_TABLE

    return (DEFAULT_LAND_HEIGHT_TABLE[0], float(rise)) + DEFAULT_LAND_HEIGHT_TABLE[2:]


# ---------------------------------------------------------------- a sphere's contact normal at a threshold
# Two tests compare the z of a unit contact normal on a sphere obstacle with the walkable allowance:
# Sphere.StepSphereDown's `disp.Z <= WalkableAllowance` (a walkable mover stepping up onto the
# sphere: the allowance is FloorZ) and SpherePath.IsWalkableAllowable's `zval > WalkableAllowance`
# (an airborne mover landing on the sphere's side: LandingZ). That z comes out of a double sqrt and
# a normalisation, so no closed form lands on the bits; these geometries were searched through the
# port (the horizontal offset on GRID near r_sum * sqrt(1 - z^2), then the obstacle radius ulp by
# ulp, `solve_sphere_contact`) and each hits its boundary exactly. On GRID every difference is
# exact, so a translation within GRID_LO..GRID_HI or a turn to another axis keeps the hit
# (tests/strategies/test_boundaries.py runs each through the port, moved and turned).
SPHERE_CONTACT_GROUND_INDEX = 50  # flat ground at table[50] = 100 m, inside GRID_LO..GRID_HI
SPHERE_CONTACT_GROUND_Z = 100.0
SPHERE_CONTACT_STEP_UP = 1.0

# (how, mover radius, obstacle radius, horizontal offset): "walk" steps up onto the sphere
# (StepSphereDown at FloorZ), "fall" drops past its side (IsWalkableAllowable at LandingZ)
SPHERE_CONTACTS: tuple[tuple[str, float, float, float], ...] = (
    ("walk", 0.25, 0.5000010132789612, 0.5606842041015625),
    ("walk", 0.5, 1.0000020265579224, 1.121368408203125),
    ("walk", 0.5, 0.5000048279762268, 0.7475814819335938),
    ("walk", 0.25, 0.9999983906745911, 0.9344711303710938),
    ("fall", 0.5, 0.500182032585144, 0.9963760375976562),
    ("fall", 0.5, 1.000177264213562, 1.4944686889648438),
)


def sphere_contact_layout(how: str, r: float, radius: float, dx: float, x0: float, y0: float, ax: int, ay: int):
    """Where everything goes for a SPHERE_CONTACTS entry, moved to block-local (x0, y0) on GRID and
    along axis (ax, ay): (begin (x, y, z), end (x, y, z), obstacle centre (x, y, z)); z values are
    the mover's origin (its sphere's centre is r above) over SPHERE_CONTACT_GROUND_Z."""
    gz = SPHERE_CONTACT_GROUND_Z
    radsum = float(np.float32(r) + np.float32(radius))
    rise = math.sqrt(max(radsum * radsum - dx * dx, 0.0))
    if how == "fall":
        oz = grid_round(gz + 0.5 * radsum)
        top = oz + rise  # the sphere centre's height where the two touch
        zb, ze = grid_round(top + 0.1 * r - r), grid_round(top - 0.1 * r - r)
        x1, y1 = x0, y0
    else:
        h = 0.1 * SPHERE_CONTACT_STEP_UP
        step = grid_round(0.5 * r)
        x1, y1 = x0 + ax * step, y0 + ay * step
        oz = grid_round(gz + r + h - rise)
        zb = ze = gz
    return (x0, y0, zb), (x1, y1, ze), (x1 + ax * dx, y1 + ay * dx, oz)


def grid_round(x: float) -> float:
    """The multiple of GRID nearest x."""
    return round(x / GRID) * GRID


# ---------------------------------------------------------------- step heights at the rise
# Sphere.StepSphereUp compares `StepUpHeight < radsum - disp.Z` (radsum the sum it was given plus
# EPSILON), CylSphere.StepSphereUp `StepUpHeight < checkPos.Radius + Height - disp.Z`. In a
# tangent scene (strategies/scenes.py `_tangent_scene`) every term is known in float32, so the
# step-up height can be the rise itself, bit for bit (the Setup's StepUpHeight * Scale.Z with
# scale 1 keeps it).
def tangent_step_up(kind: str, mover_r: float, radius: float, height: float, z0: float) -> float:
    """The StepUpHeight equal to the rise StepSphereUp computes for `_tangent_scene`'s obstacle:
    a sphere centred at the mover's sphere height (disp.Z == 0), or a cylsphere standing at z0."""
    f = np.float32
    if kind == "sphere":
        return float(f(sphere_radsum(mover_r, radius)) + f(EPSILON))
    disp_z = f(f(z0) + f(mover_r)) - f(z0)  # the mover's sphere centre less the cylinder's low point
    return float((f(mover_r) + f(height)) - disp_z)


# ---------------------------------------------------------------- a polygon touching the sphere
# Polygon.polygon_hits_sphere_precise takes rad = radius - EPSILON and compares: |dp_pos| > rad
# (the plane at exactly rad from the centre: "plane_tangent"), cross.LengthSquared() * diff <
# dispDot^2 (an edge exactly tangent to the circle the sphere cuts from the plane, diff = rad^2 -
# dp_pos^2: "polygon_edge") and disp.LengthSquared() <= diff (a vertex exactly on it:
# "polygon_vertex"). With a mover radius whose rad is on GRID, an axis-aligned box of dyadic
# sizes (make_plane's normals exactly an axis) and every coordinate on GRID, each of these is
# exact: a face rad ahead of the sphere's centre; the box's top at the centre's height with its
# edge rad ahead (dp_pos = 0, diff = rad^2, dispDot = rad * edge length); or a corner (a, b)
# off the centre with a^2 + b^2 == rad^2 (a Pythagorean triple scaled by a power of two).
TOUCH_RADS = (0.25, 0.3125, 0.375, 0.4375, 0.625, 0.75, 1.0)  # 0.5 has no such radius
# (rad, a, b): a^2 + b^2 == rad^2 exactly in float32
TOUCH_CORNERS = ((0.3125, 0.1875, 0.25), (0.625, 0.375, 0.5), (0.8125, 0.3125, 0.75), (1.25, 0.75, 1.0))
TOUCH_SIZES = (0.5, 1.0, 2.0, 4.0)


@lru_cache(maxsize=None)
def touch_radius(rad: float) -> float:
    """A float32 sphere radius r with r - EPSILON == rad exactly in float32 (rad on GRID)."""
    b = f32_bits(to_f32(rad + float(EPSILON)))
    for k in sorted(range(-8, 9), key=abs):
        r = f32_from_bits(b + k)
        if float(np.float32(r) - np.float32(EPSILON)) == rad:
            return r
    raise ValueError(f"no float32 radius r has r - EPSILON == {rad}")
