"""The per-function differential specs: for each ACE routine, an input generator biased to
boundaries, the port's answer and ACE's answer (through acconform.oracle.functions), both as
plain data, and the codec that records them (tests/port/functions/data/ace_functions.json.gz).

A spec's generator returns ``(context, inputs)``: `context` is JSON data shared by the inputs
(landblocks and land height tables; None for most functions), each input a list of JSON values.
`port(context, args)` and `ace(fns, context, args)` return the same plain shape: bools, ints,
floats (float32 values as Python floats, exact; C# doubles as doubles), tuples and None, with an
exception ACE is specified to throw as ``("error", "<.NET exception name>")``.
"""

from __future__ import annotations

import gzip
import json
import math
import random
import struct
import warnings
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from types import SimpleNamespace

import numpy as np
from acconform.port.constants import EPSILON, FLOOR_Z, LANDING_Z
from acconform.port.errors import AceException
from acconform.port.frame import AFrame, Position
from acconform.port.geom import sphere as port_sphere
from acconform.port.geom.polygon import Polygon, Sidedness, Vertex
from acconform.port import land_defs
from acconform.port.vec import Ray

from acconform.codec import write_f32
from acconform.numerics import EXACT, Mode, Plane, Quaternion, Vector3, f32_from_bits, get_mode
from acconform.scene import DEFAULT_LAND_HEIGHT_TABLE

# ACE's recorded answers per runtime ACE ran on: mono 6.8, and .NET 10 (CoreCLR)
DATA = {"mono": Path(__file__).resolve().parent / "data" / "ace_functions.json.gz",
        "coreclr": Path(__file__).resolve().parent / "data" / "ace_functions_net10.json.gz"}
F = np.float32


def f32(x) -> float:
    return float(np.float32(x))


def up_ulp(x, k=1) -> float:
    v = np.float32(x)
    for _ in range(k):
        v = np.nextafter(v, np.float32(np.inf))
    return float(v)


def down_ulp(x, k=1) -> float:
    v = np.float32(x)
    for _ in range(k):
        v = np.nextafter(v, np.float32(-np.inf))
    return float(v)


# ---------------------------------------------------------------- plain data and comparison


def plain(x):
    """A port value as plain data (the shape AceFunctions returns)."""
    if x is None or isinstance(x, (bool, str)):
        return x
    if isinstance(x, np.bool_):
        return bool(x)
    if isinstance(x, (int, np.integer)):
        return int(x)
    if isinstance(x, (float, np.floating)):
        return float(x)
    if isinstance(x, Vector3):
        return (float(x.x), float(x.y), float(x.z))
    if isinstance(x, Plane):
        return (float(x.normal.x), float(x.normal.y), float(x.normal.z), float(x.d))
    if isinstance(x, Quaternion):
        return (float(x.w), float(x.x), float(x.y), float(x.z))
    if isinstance(x, dict):
        return {k: plain(v) for k, v in x.items()}
    if isinstance(x, (tuple, list)):
        return tuple(plain(v) for v in x)
    raise TypeError(f"no plain form for {type(x).__name__}: {x!r}")


def _key(x):
    if isinstance(x, float):
        return ("f", struct.pack("<d", x)) if not math.isnan(x) else ("nan",)
    if isinstance(x, (tuple, list)):
        return tuple(_key(v) for v in x)
    if isinstance(x, dict):
        return tuple(sorted((k, _key(v)) for k, v in x.items()))
    return (type(x).__name__, x)


def same(a, b) -> bool:
    """Equal as ACE's bits: floats by their bit pattern (so -0.0 != 0.0), bools are not ints."""
    return _key(plain(a)) == _key(plain(b))


# ---------------------------------------------------------------- the recorded-data codec


def enc(x):
    """JSON for a plain value: float32 values as their shortest decimal (codec.write_f32),
    non-finite float32 as "0x<bits>", a double that is no float32 as "d:<repr>"."""
    if isinstance(x, float):
        v = np.float32(x)
        if math.isnan(x) or float(v) == x:
            return write_f32(v)
        return "d:" + repr(x)
    if isinstance(x, (tuple, list)):
        return [enc(v) for v in x]
    if isinstance(x, dict):
        return {k: enc(v) for k, v in x.items()}
    return x


def dec(x):
    if isinstance(x, float):
        return float(np.float32(x))
    if isinstance(x, str):
        if x.startswith("0x"):
            return f32_from_bits(int(x, 16))
        if x.startswith("d:"):
            return float(x[2:])
        return x
    if isinstance(x, list):
        return tuple(dec(v) for v in x)
    if isinstance(x, dict):
        return {k: dec(v) for k, v in x.items()}
    return x


def save(doc: dict, path: Path) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    raw = json.dumps(enc(doc), separators=(",", ":"), allow_nan=False).encode()
    path.write_bytes(gzip.compress(raw, 9, mtime=0))


def load(path: Path) -> dict:
    doc = json.loads(gzip.decompress(path.read_bytes()))
    return {"versions": doc["versions"], "functions": {name: dec(entry) for name, entry in doc["functions"].items()}}


# ---------------------------------------------------------------- port values from plain data


def vec(v) -> Vector3:
    return EXACT.vec(*v)


def sph(s) -> port_sphere.Sphere:
    return port_sphere.Sphere(vec(s[0]), F(s[1]))


def port_polygon(vertices, sides_type: int = 0) -> Polygon:
    """As ACE builds a terrain polygon: Polygon(idx, n, cullMode), the vertices, make_plane."""
    p = Polygon(0, len(vertices), sides_type)
    for k, v in enumerate(vertices):
        p.vertices[k] = Vertex(vec(v), index=0)
        p.vertex_ids[k] = k
    p.make_plane()
    return p


def frame(f, m: Mode = EXACT) -> AFrame:
    """An AFrame whose quaternion computes as `m`'s runtime does."""
    w, x, y, z = f[1]
    return AFrame(vec(f[0]), m.quat(x, y, z, w))


def position(p, m: Mode = EXACT) -> Position:
    return Position(int(p[0]), frame(p[1], m))


def ace_error(fn):
    """The port's answer, or ("error", name) where the port raises ACE's exception."""
    try:
        return fn()
    except AceException as e:
        return ("error", type(e).__name__)
    except IndexError:  # List<T> indexer past the end: ArgumentOutOfRangeException in ACE
        return ("error", "ArgumentOutOfRangeException")


# ---------------------------------------------------------------- input pieces biased to boundaries


def rnd(rng: random.Random, lo=-10.0, hi=10.0) -> float:
    """A float32 with a short decimal form (three places: the recorded data stays small); the
    values built from it (centres on a plane's normal, rotated points) carry every bit."""
    return f32(round(rng.uniform(lo, hi), 3))


def unit(rng: random.Random) -> tuple:
    while True:
        v = [rng.gauss(0, 1) for _ in range(3)]
        n = math.sqrt(sum(c * c for c in v))
        if n > 1e-3:
            return tuple(f32(c / n) for c in v)


def polygon_vertices(rng: random.Random) -> list:
    """Convex and concave polygons, terrain-like triangles, axis-aligned squares, slopes near
    FloorZ, degenerate ones (a zero-length edge, collinear points), both windings."""
    kind = rng.randrange(9)
    if kind == 0:  # terrain triangle on a 24-unit grid with integer-ish heights
        x0, y0 = rng.randrange(0, 8) * 24.0, rng.randrange(0, 8) * 24.0
        h = [rng.choice([0.0, 2.0, 4.0, 10.0, rng.randrange(0, 256) * 2.0]) for _ in range(3)]
        if rng.random() < 0.5:
            h = [h[0]] * 3
        vs = [(x0, y0, h[0]), (x0 + 24.0, y0, h[1]), (x0 + 24.0, y0 + 24.0, h[2])]
    elif kind == 1:  # axis-aligned square (floor, wall or ceiling)
        s = rng.choice([1.0, 2.0, 24.0, 0.5])
        z = rnd(rng, -2, 2)
        vs = [(0.0, 0.0, z), (s, 0.0, z), (s, s, z), (0.0, s, z)]
        if rng.random() < 0.3:
            vs = [(0.0, v[0], v[1]) for v in vs]  # a wall in the y-z plane
    elif kind == 2:  # a slope whose normal z sits near FloorZ / LandingZ
        nz = rng.choice([FLOOR_Z, LANDING_Z, up_ulp(FLOOR_Z), down_ulp(FLOOR_Z), 0.7, 0.5])
        rise = f32(math.sqrt(max(0.0, 1 - nz * nz)) / nz) if nz > 0 else 1.0
        vs = [(0.0, 0.0, 0.0), (2.0, 0.0, f32(2.0 * rise)), (2.0, 2.0, f32(2.0 * rise)), (0.0, 2.0, 0.0)]
    elif kind == 3:  # zero-length edge (a repeated vertex)
        a, b = (rnd(rng), rnd(rng), rnd(rng)), (rnd(rng), rnd(rng), rnd(rng))
        c = (rnd(rng), rnd(rng), rnd(rng))
        vs = [a, b, b, c]
    elif kind == 4:  # collinear points: no plane (make_plane divides by zero)
        a = (rnd(rng), rnd(rng), rnd(rng))
        vs = [a, (a[0] + 1, a[1], a[2]), (a[0] + 2, a[1], a[2])]
    elif kind == 5:  # regular polygon in a random plane
        n = rng.randrange(3, 7)
        r = rnd(rng, 0.2, 5)
        c = (rnd(rng), rnd(rng), rnd(rng))
        ax, ay = unit(rng), unit(rng)
        vs = [tuple(f32(c[i] + r * (math.cos(2 * math.pi * k / n) * ax[i] + math.sin(2 * math.pi * k / n) * ay[i]))
                    for i in range(3)) for k in range(n)]
    elif kind == 6:  # tiny polygon
        c = (rnd(rng), rnd(rng), rnd(rng))
        e = rng.choice([EPSILON, 1e-3, 1e-5])
        vs = [c, (f32(c[0] + e), c[1], c[2]), (c[0], f32(c[1] + e), c[2])]
    else:  # random triangle / quad (possibly concave or twisted)
        vs = [(rnd(rng), rnd(rng), rnd(rng)) for _ in range(rng.choice([3, 3, 4, 5]))]
    if rng.random() < 0.5:
        vs = vs[::-1]
    return [tuple(f32(c) for c in v) for v in vs]


def point_near(rng: random.Random, vs: list) -> tuple:
    """A vertex, a point on an edge, an edge's extension, the centroid, or anywhere."""
    kind = rng.randrange(6)
    a = vs[rng.randrange(len(vs))]
    b = vs[(vs.index(a) + 1) % len(vs)]
    if kind == 0:
        return a
    if kind == 1:
        t = rng.choice([0.5, 0.25, 0.0, 1.0, rng.random()])
        return tuple(f32(a[i] + (b[i] - a[i]) * t) for i in range(3))
    if kind == 2:
        t = rng.choice([-1.0, 2.0, 1.5, -0.5])
        return tuple(f32(a[i] + (b[i] - a[i]) * t) for i in range(3))
    if kind == 3:
        return tuple(f32(sum(v[i] for v in vs) / len(vs)) for i in range(3))
    if kind == 4:
        return tuple(f32(c + rng.choice([EPSILON, -EPSILON, 1e-6, -1e-6, 0.0])) for c in a)
    return (rnd(rng, -20, 30), rnd(rng, -20, 30), rnd(rng, -20, 30))


def radius(rng: random.Random) -> float:
    return f32(rng.choice([0.5, 0.48, 0.25, 1.0, 2.0, EPSILON, 0.0, rng.uniform(0.01, 3)]))


def is_level(vs: list) -> bool:
    """All vertices at one height: make_plane gives the normal (0, 0, +-1) exactly."""
    return all(v[2] == vs[0][2] for v in vs) and len({(v[0], v[1]) for v in vs}) >= 3


def sphere_at_vertex(rng: random.Random, vs: list) -> tuple:
    """A sphere centred in a level polygon's plane, beside a vertex along x or y, at exactly the
    distance the tests compare with: radius - EPSILON (polygon_hits_sphere's rad), the radius
    (check_walkable's radsum), half of it (check_small_walkable's radsum * 0.25), or an ulp off."""
    r = f32(rng.choice([0.5, 0.25, 1.0, 2.0, 0.48]))
    rad_eps = f32(F(r) - F(EPSILON))
    d = rng.choice([rad_eps, up_ulp(rad_eps), down_ulp(rad_eps), r, up_ulp(r), down_ulp(r), f32(r / 2),
                    up_ulp(r / 2), down_ulp(r / 2)])
    v = vs[rng.randrange(len(vs))]
    if rng.random() < 0.5:
        # off a corner by a 3-4-5 offset (exact in binary): the vertex-distance test decides
        k = rng.choice([0.125, 0.0625, 0.25])
        t = 5 * k
        r = rng.choice([radius_for_rad(t), t, 2 * t])  # rad, radsum (r * r), small radsum (r * r * 0.25) == t * t
        a, b = rng.choice([(3 * k, 4 * k), (4 * k, 3 * k)])
        a, b = a * rng.choice([1, -1]), b * rng.choice([1, -1])
        c = (f32(v[0] + a), f32(v[1] + b), v[2])
        if rng.random() < 0.3:
            c = (rng.choice([up_ulp, down_ulp])(c[0]), c[1], c[2])
        return (c, f32(r))
    dx, dy = rng.choice([(1, 0), (-1, 0), (0, 1), (0, -1)])
    return ((f32(v[0] + dx * d), f32(v[1] + dy * d), v[2]), r)


def radius_for_rad(t: float) -> float:
    """A float32 r with r - EPSILON == t exactly in float32 (t itself when none is near)."""
    r = F(t) + F(EPSILON)
    for _ in range(8):
        if r - F(EPSILON) == F(t):
            return float(r)
        r = np.nextafter(r, np.float32(np.inf)) if r - F(EPSILON) < F(t) else np.nextafter(r, np.float32(-np.inf))
    return t


def sphere_near(rng: random.Random, vs: list) -> tuple:
    """A sphere whose center sits on the plane's normal line through a point near the polygon,
    at the radius (tangent), radius - EPSILON (the precise test's boundary), an ulp either side,
    inside, on the plane or behind it."""
    if is_level(vs) and rng.random() < 0.4:
        return sphere_at_vertex(rng, vs)
    p = port_polygon(vs)
    n = p.plane.normal
    r = radius(rng)
    base = point_near(rng, vs)
    rad_eps = f32(F(r) - F(EPSILON))
    d = rng.choice([r, rad_eps, up_ulp(rad_eps), down_ulp(rad_eps), f32(r + EPSILON), f32(r - 2 * EPSILON),
                    0.0, -r, f32(-rad_eps), f32(r * rng.uniform(-1.5, 1.5)), f32(rng.uniform(-5, 5))])
    if not all(math.isfinite(float(c)) for c in (n.x, n.y, n.z)):
        return ((base[0], base[1], f32(base[2] + d)), r)
    center = tuple(f32(F(base[i]) + F(d) * c) for i, c in enumerate((n.x, n.y, n.z)))
    return (center, r)


def up_vector(rng: random.Random, vs: list) -> tuple:
    kind = rng.randrange(5)
    if kind <= 1:
        return (0.0, 0.0, 1.0)
    if kind == 2:
        return plain(port_polygon(vs).plane.normal)
    if kind == 3 and is_level(vs):  # dot(normal, up) exactly +-EPSILON, an ulp either side, or 0
        e = rng.choice([EPSILON, -EPSILON, up_ulp(EPSILON), down_ulp(EPSILON), -up_ulp(EPSILON), 0.0])
        return (rnd(rng, -1, 1), rnd(rng, -1, 1), e)
    if kind == 3:  # nearly perpendicular to the plane normal: angle_up near EPSILON
        n = port_polygon(vs).plane.normal
        t = unit(rng)
        return tuple(f32(c) for c in (t[0] + EPSILON * float(n.x), t[1] + EPSILON * float(n.y), t[2] + EPSILON * float(n.z)))
    return unit(rng)


def movement(rng: random.Random, vs: list) -> tuple:
    n = plain(port_polygon(vs).plane.normal)
    kind = rng.randrange(6)
    s = f32(rng.choice([1.0, 0.1, 0.5, 2.0, EPSILON]))
    if kind == 0:
        return tuple(f32(-s * c) for c in n)
    if kind == 1:
        return tuple(f32(s * c) for c in n)
    if kind == 2:  # in the plane: dot(movement, normal) about 0
        t = unit(rng)
        d = sum(a * b for a, b in zip(t, n)) if all(math.isfinite(c) for c in n) else 0.0
        return tuple(f32(t[i] - d * n[i]) for i in range(3))
    if kind == 3:
        return (0.0, 0.0, 0.0)
    if kind == 4:
        return tuple(f32(c * EPSILON * rng.choice([1, -1, 0.5, 2])) for c in n)
    return (rnd(rng, -2, 2), rnd(rng, -2, 2), rnd(rng, -2, 2))


def cell_id(rng: random.Random) -> int:
    bx = rng.choice([0x00, 0x01, 0x7F, 0x80, 0xA9, 0xFE, 0xFF, rng.randrange(256)])
    by = rng.choice([0x00, 0x01, 0x7F, 0x80, 0xB4, 0xFE, 0xFF, rng.randrange(256)])
    low = rng.choice([0x0000, 0x0001, 0x0008, 0x0009, 0x0040, 0x0041, 0x00FF, 0x0100, 0x0101, 0xFFFD, 0xFFFE,
                      0xFFFF, rng.randrange(1, 65), rng.randrange(0x10000)])
    return (bx << 24) | (by << 16) | low


def coord(rng: random.Random, span=192.0) -> float:
    return f32(rng.choice([
        0.0, -0.0, EPSILON, -EPSILON, f32(EPSILON / 2), -f32(EPSILON / 2), span, up_ulp(span), down_ulp(span), -span,
        24.0, up_ulp(24.0), down_ulp(24.0), 12.0, down_ulp(12.0), -12.0, -24.0, 2 * span, 100000.0,
        rng.uniform(-span, 2 * span), rng.uniform(-3 * span, 3 * span), rng.randrange(-8, 17) * 24.0,
    ]))


def quaternion(rng: random.Random) -> tuple:
    """(w, x, y, z): identity, quarter turns about z, random unit ones, a few not normalised."""
    kind = rng.randrange(5)
    if kind == 0:
        return (1.0, 0.0, 0.0, 0.0)
    if kind == 1:
        h = f32(math.sqrt(0.5))
        return rng.choice([(h, 0.0, 0.0, h), (h, 0.0, 0.0, -h), (0.0, 0.0, 0.0, 1.0), (-1.0, 0.0, 0.0, 0.0)])
    if kind == 2:
        q = [rng.gauss(0, 1) for _ in range(4)]
        n = math.sqrt(sum(c * c for c in q))
        return tuple(f32(c / n * rng.choice([1.0, 1.01, 0.5])) for c in q)
    a = rng.uniform(-math.pi, math.pi)
    return (f32(math.cos(a / 2)), 0.0, 0.0, f32(math.sin(a / 2)))


def a_frame(rng: random.Random) -> tuple:
    return ((coord(rng), coord(rng), rnd(rng, -50, 300)), quaternion(rng))


# ---------------------------------------------------------------- generators


def _n_times(fn):
    def gen(rng, n):
        return None, [fn(rng) for _ in range(n)]

    return gen


def g_make_plane(rng):
    return [polygon_vertices(rng)]


def g_point_in_poly2d(rng):
    vs = polygon_vertices(rng)
    return [vs, point_near(rng, vs), rng.choice([0, 1, 2])]


def g_point_in_polygon(rng):
    vs = polygon_vertices(rng)
    return [vs, point_near(rng, vs)]


def g_sphere_contact(rng):
    vs = polygon_vertices(rng)
    return [vs, sphere_near(rng, vs), (rnd(rng), rnd(rng), rnd(rng)) if rng.random() < 0.3 else (0.0, 0.0, 0.0)]


def g_hits_sphere(rng):
    vs = polygon_vertices(rng)
    return [vs, sphere_near(rng, vs)]


def g_find_crossed_edge(rng):
    vs = polygon_vertices(rng)
    return [vs, sphere_near(rng, vs), up_vector(rng, vs), unit(rng) if rng.random() < 0.3 else (0.0, 0.0, 0.0)]


def g_pos_hits_sphere(rng):
    vs = polygon_vertices(rng)
    return [vs, sphere_near(rng, vs), movement(rng, vs), (0.0, 0.0, 0.0)]


def g_walkable_hits_sphere(rng):
    vs = polygon_vertices(rng)
    up = up_vector(rng, vs)
    p = port_polygon(vs)
    dp = f32(up[0] * float(p.plane.normal.x) + up[1] * float(p.plane.normal.y) + up[2] * float(p.plane.normal.z)) \
        if math.isfinite(float(p.plane.normal.x)) else 0.5
    allowance = rng.choice([FLOOR_Z, LANDING_Z, dp, up_ulp(dp), down_ulp(dp), f32(rng.uniform(-1, 1))])
    return [vs, allowance, sphere_near(rng, vs), up]


def g_check_walkable(rng):
    vs = polygon_vertices(rng)
    return [vs, sphere_near(rng, vs), up_vector(rng, vs), rng.random() < 0.5]


def g_check_small_walkable(rng):
    vs = polygon_vertices(rng)
    return [vs, sphere_near(rng, vs), up_vector(rng, vs)]


def g_adjust_sphere_to_plane_exact(rng):
    """A level square and a vertical move placed so that interp = (1 - dist / dpMove) * WalkInterp
    lands exactly on -0.5 (the limit), on WalkInterp itself (a tangent start), or beside them."""
    z0 = f32(rng.choice([0.0, 1.0, -2.0, 10.5]))
    vs = [(0.0, 0.0, z0), (4.0, 0.0, z0), (4.0, 4.0, z0), (0.0, 4.0, z0)]
    if rng.random() < 0.5:
        vs = vs[::-1]
    normal_z = plain(port_polygon(vs).plane.normal)[2]
    r = f32(rng.choice([0.5, 0.25, 1.0]))
    m = f32(rng.choice([1.0, 0.5, 2.0]))
    wi = f32(rng.choice([1.0, 0.5]))
    i_dist = rng.choice([1 + 0.5 / wi, 1 + 0.5 / wi + 2 ** -20, 1 + 0.5 / wi - 2 ** -20, 0.0, 1.0, 0.5])
    down = rng.random() < 0.5  # moving against the normal (dpMove < 0) or with it
    mz = -m * normal_z if down else m * normal_z
    # dpPos = normal_z * (cz - z0): against the normal dist = dpPos - r = dpMove * iDist,
    # with it dist = -r - dpPos = dpMove * iDist
    dp_pos = -m * i_dist + r if down else -r - m * i_dist
    cz = f32(z0 + dp_pos * normal_z)
    return [vs, wi, ((2.0, 2.0, cz), r), (0.0, 0.0, f32(mz))]


def g_adjust_sphere_to_plane(rng):
    if rng.random() < 0.3:
        return g_adjust_sphere_to_plane_exact(rng)
    vs = polygon_vertices(rng)
    wi = f32(rng.choice([1.0, 1.0, 0.5, rng.random(), EPSILON, 0.0, -0.4]))
    return [vs, wi, sphere_near(rng, vs), movement(rng, vs)]


def g_adjust_sphere_to_poly(rng):
    vs = polygon_vertices(rng)
    s = sphere_near(rng, vs)
    curr = sphere_near(rng, vs)[0] if rng.random() < 0.7 else s[0]
    return [vs, s, curr, movement(rng, vs)]


def g_adjust_to_placement_poly(rng):
    vs = polygon_vertices(rng)
    other = sphere_near(rng, vs) if rng.random() < 0.5 else None
    return [vs, sphere_near(rng, vs), other, radius(rng), rng.random() < 0.5, rng.random() < 0.5]


def g_polygon_hits_ray(rng):
    vs = polygon_vertices(rng)
    start = point_near(rng, vs)
    d = movement(rng, vs)
    start = tuple(f32(start[i] - d[i] * rng.choice([1.0, 0.5, 2.0, -1.0])) for i in range(3))
    time = f32(rng.choice([1.0, 0.0, rng.random(), 10.0]))
    return [vs, rng.choice([0, 1, 2]), [start, d, f32(rng.uniform(0, 5))], time]


def g_find_time_of_collision(rng):
    r = radius(rng)
    mv = rng.choice([unit(rng), (0.0, 0.0, 0.0), tuple(f32(c * 0.01) for c in unit(rng)), (rnd(rng), rnd(rng), rnd(rng))])
    # the other sphere at exactly radsum, an ulp either side, inside, or anywhere
    dirn = unit(rng)
    dist = rng.choice([r, up_ulp(r), down_ulp(r), f32(r * 2), f32(r / 2), rnd(rng, 0, 5), f32(math.sqrt(r * r + EPSILON))])
    pos = tuple(f32(c * dist) for c in dirn)
    if rng.random() < 0.3:  # head-on: movement toward/away from the other sphere
        mv = tuple(f32(-c * rng.choice([1.0, 3.0, -1.0])) for c in pos)
    return [mv, pos, r]


def g_collides_with_sphere(rng):
    r = radius(rng)
    d = rng.choice([r, up_ulp(r), down_ulp(r), 0.0, rnd(rng, 0, 3)])
    u = rng.choice([(1.0, 0.0, 0.0), (0.0, 0.0, -1.0), unit(rng)])
    return [tuple(f32(c * d) for c in u), r]


def g_sphere_intersects(rng):
    a = ((rnd(rng), rnd(rng), rnd(rng)), radius(rng))
    b_r = radius(rng)
    d = rng.choice([f32(a[1] + b_r), up_ulp(f32(a[1] + b_r)), down_ulp(f32(a[1] + b_r)), 0.0, rnd(rng, 0, 4)])
    u = rng.choice([(1.0, 0.0, 0.0), unit(rng)])
    return [a, (tuple(f32(a[0][i] + d * u[i]) for i in range(3)), b_r)]


def g_sphere_intersects_ray(rng):
    s = ((rnd(rng), rnd(rng), rnd(rng)), radius(rng))
    d = rng.choice([unit(rng), (0.0, 0.0, 0.0), tuple(f32(c * 0.001) for c in unit(rng)), (rnd(rng), rnd(rng), rnd(rng))])
    off = rng.choice([s[1], up_ulp(s[1]), down_ulp(s[1]), 0.0, rnd(rng, 0, 5)])
    u = unit(rng)
    start = tuple(f32(s[0][i] + off * u[i] - d[i] * rng.choice([0.0, 1.0, 3.0])) for i in range(3))
    return [s, [start, d, f32(rng.uniform(0, 5))]]


def g_block_offset(rng):
    a = cell_id(rng)
    b = cell_id(rng) if rng.random() < 0.7 else (a & 0xFFFF0000) | rng.randrange(0x10000)
    if rng.random() < 0.3:  # a neighbouring block
        bx = ((a >> 24) + rng.choice([-1, 0, 1])) & 0xFF
        by = (((a >> 16) & 0xFF) + rng.choice([-1, 0, 1])) & 0xFF
        b = (bx << 24) | (by << 16) | (b & 0xFFFF)
    return [a, b]


def g_adjust_to_outside(rng):
    return [cell_id(rng), (coord(rng), coord(rng), rnd(rng, -5, 5))]


def g_cell(rng):
    return [cell_id(rng)]


def g_cell_low(rng):
    """A whole cell id or just its low word (cell_in_range is called with both)."""
    c = cell_id(rng)
    return [c & 0xFFFF if rng.random() < 0.7 else c]


def g_gid_to_lcoord(rng):
    return [cell_id(rng), rng.random() < 0.7]


def g_get_outside_lcoord(rng):
    x, y = coord(rng), coord(rng)
    if rng.random() < 0.03:
        x = rng.choice([float("nan"), float("inf"), float("-inf")])
    return [cell_id(rng), x, y]


def g_lcoord_to_gid(rng):
    def c():
        return f32(rng.choice([0.0, -0.0, -1.0, -0.5, f32(-EPSILON), 0.5, 7.0, 8.0, 2039.0, down_ulp(2040.0), 2040.0,
                               2040.5, 4e9, -4e9, float("nan"), rng.uniform(0, 2040), rng.uniform(-100, 2200),
                               float(rng.randrange(0, 2040))]))
    return [c(), c()]


def g_in_block(rng):
    r = radius(rng)
    return [(rng.choice([r, up_ulp(r), down_ulp(r), coord(rng), f32(192 - r)]),
             rng.choice([r, coord(rng), f32(192 - r), down_ulp(f32(192 - r))]), rnd(rng)), r]


def g_frame_point(rng):
    return [a_frame(rng), (coord(rng), coord(rng), rnd(rng, -50, 50))]


def g_frame_combine(rng):
    return [a_frame(rng), a_frame(rng)]


def _pos(rng, near=None):
    if near is not None and rng.random() < 0.6:
        bx = ((near >> 24) + rng.choice([-1, 0, 1, 2])) & 0xFF
        by = (((near >> 16) & 0xFF) + rng.choice([-1, 0, 1])) & 0xFF
        cell = (bx << 24) | (by << 16) | rng.randrange(1, 65)
    else:
        cell = cell_id(rng)
    return [cell, a_frame(rng)]


def g_position_pair(rng):
    a = _pos(rng)
    return [a, _pos(rng, a[0])]


def g_position_pair_point(rng):
    a = _pos(rng)
    return [a, _pos(rng, a[0]), (coord(rng), coord(rng), rnd(rng, -5, 5))]


# landblocks: a shared context (height tables and landblocks), inputs name them by index

TABLE_RANDOM = tuple(f32(i * 1.7 + (i % 7) * 0.13) for i in range(256))


def landblocks_context(rng: random.Random, count: int) -> dict:
    lbs = []
    for k in range(count):
        bx = rng.choice([0x00, 0x01, 0x7F, 0x80, 0xFE, rng.randrange(255)])
        by = rng.choice([0x00, 0x01, 0x7F, 0x80, 0xFE, rng.randrange(255)])
        if k < 3:  # the split-rule boundary cell (657, 1857) sits in landblock (82, 232)
            bx, by = (82, 232) if k == 0 else (0x00, 0x00) if k == 1 else (0xFE, 0xFE)
        kind = rng.randrange(4)
        if kind == 0:
            heights = [0] * 81
        elif kind == 1:
            heights = [rng.randrange(256) for _ in range(81)]
        elif kind == 2:
            heights = [min(255, (i // 9) * 3 + (i % 9)) for i in range(81)]
        else:
            heights = [rng.choice([0, 10, 200, 255]) for _ in range(81)]
        terrain = [(rng.choice([0x00, 0x04, 0x10, 0x14, 0x11, 0x1F, rng.randrange(32)]) << 2) | rng.randrange(4)
                   for _ in range(81)]
        if rng.random() < 0.2:
            terrain = [(0x10 << 2)] * 81  # entirely water
        lbs.append([(bx << 24) | (by << 16) | 0xFFFF, heights, terrain, rng.randrange(2)])
    return {"tables": [list(DEFAULT_LAND_HEIGHT_TABLE), list(TABLE_RANDOM)], "landblocks": lbs}


def gen_landblock_struct(rng, n):
    ctx = landblocks_context(rng, n)
    return ctx, [[i] for i in range(n)]


def _lb_inputs(point_fn, lb_count=16):
    def gen(rng, n):
        ctx = landblocks_context(rng, lb_count)
        return ctx, [[rng.randrange(lb_count), *point_fn(rng, ctx)] for _ in range(n)]

    return gen


def _terrain_point(rng, ctx=None):
    x = rng.choice([coord(rng), f32(rng.uniform(0, 192)), rng.randrange(0, 9) * 24.0, f32(rng.randrange(0, 17) * 12.0)])
    y = rng.choice([coord(rng), f32(rng.uniform(0, 192)), rng.randrange(0, 9) * 24.0, x])  # x == y: the diagonal
    return [(x, y, rnd(rng, -10, 600))]


def _water_depth_args(rng, ctx):
    low = rng.randrange(1, 65) if rng.random() < 0.85 else rng.choice([0, 65, 0x100, 0xFFFF])
    return [low, _terrain_point(rng)[0]]


def _landcell_args(rng, ctx):
    low = rng.randrange(1, 65) if rng.random() < 0.8 else rng.choice([0, 65, 0x100, 0xFFFF])
    return [low, rng.random() < 0.8]


# ---------------------------------------------------------------- port and ACE adapters


class _PortLandblocks:
    """Port Landblocks (and a one-landblock LScape for GetZ) built once per context entry."""

    def __init__(self):
        self.cache: dict = {}

    def get(self, ctx, i, m: Mode):
        lb_id, heights, terrain, t = ctx["landblocks"][i]
        table = ctx["tables"][t]
        key = (lb_id, tuple(heights), tuple(terrain), tuple(table), m)
        if key not in self.cache:
            if len(self.cache) > 64:
                self.cache.clear()
            from acconform.port.land.lscape import LScape

            from acconform.scene import Frame, Mover, Scene, SphereRec
            from acconform.scene import Landblock as LbRec
            from acconform.scene import Position as PosRec

            rec = LbRec(lb_id, tuple(heights), tuple(terrain))
            pos = PosRec((lb_id & 0xFFFF0000) | 1, Frame((12.0, 12.0, 0.0)))
            scene = Scene((rec,), Mover((SphereRec((0.0, 0.0, 0.5), 0.5),), pos, pos, 0.5, 0.5), land_height_table=tuple(table))
            lscape = LScape(scene, m)
            self.cache[key] = (lscape.get_landblock(lb_id), lscape)
        return self.cache[key]


PORT_LB = _PortLandblocks()


def _ace_lb(ctx, i):
    lb_id, heights, terrain, t = ctx["landblocks"][i]
    return (lb_id, heights, terrain, ctx["tables"][t])


def port_landblock_struct(ctx, args, m):
    lb, _ = PORT_LB.get(ctx, args[0], m)
    # the cells first: a land cell (its polygons, its SWtoNEcut entry) is built when first read
    cells = [(c.id, c.pos.frame.origin, int(c.water_type)) for c in (lb.land_cells[i] for i in range(64))]
    return {
        "vertices": [v.origin for v in lb.vertex_array],
        "polygons": [(tuple(p.vertex_ids), p.plane, p.pos_surface) for p in lb.polygons],
        "sw_to_ne_cut": list(lb.sw_to_ne_cut),
        "cells": cells,
        "water_type": int(lb.water_type), "min_z": lb.min_z, "max_z": lb.max_z,
    }


def port_get_z(ctx, args, m):
    lb, lscape = PORT_LB.get(ctx, args[0], m)
    return lb.get_z(lscape, vec(args[1]))


def port_get_landcell(ctx, args, m):
    lb, _ = PORT_LB.get(ctx, args[0], m)
    low, same_block = args[1], args[2]
    cid = (lb.id & 0xFFFF0000 if same_block else (lb.id + 0x01000000) & 0xFFFF0000) | low

    def call():
        c = lb.get_landcell(cid)
        return None if c is None else c.id

    return ace_error(call)


def ace_get_landcell(fns, ctx, args):
    lb_id = ctx["landblocks"][args[0]][0]
    cid = (lb_id & 0xFFFF0000 if args[2] else (lb_id + 0x01000000) & 0xFFFF0000) | args[1]
    return fns.get_landcell(_ace_lb(ctx, args[0]), [cid])[0]


def port_calc_water_depth(ctx, args, m):
    lb, _ = PORT_LB.get(ctx, args[0], m)
    return ace_error(lambda: lb.calc_water_depth((lb.id & 0xFFFF0000) | args[1], vec(args[2])))


def ace_calc_water_depth(fns, ctx, args):
    lb_id = ctx["landblocks"][args[0]][0]
    return fns.calc_water_depth(_ace_lb(ctx, args[0]), (lb_id & 0xFFFF0000) | args[1], args[2])


def _pos_hits(a, m):
    vs, s, mv, c = a
    p = port_polygon(vs)
    ok, cp, hp = p.pos_hits_sphere(sph(s), vec(mv), vec(c), None)
    return (ok, cp, hp is p)


def _walkable_hits(a, m):
    vs, allowance, s, up = a
    return port_polygon(vs).walkable_hits_sphere(SimpleNamespace(walkable_allowance=F(allowance), trace=None), sph(s), vec(up))


def _adjust_to_plane(a, m):
    vs, wi, s, mv = a
    path = SimpleNamespace(walk_interp=F(wi))
    valid = sph(s)
    ok = port_polygon(vs).adjust_sphere_to_plane(path, valid, vec(mv))
    return (ok, path.walk_interp, valid.center)


def _placement(a, m):
    vs, hit, other, r, center_solid, solid_check = a
    h = sph(hit)
    o = sph(other) if other is not None else None
    port_polygon(vs).adjust_to_placement_poly(h, o, F(r), center_solid, solid_check)
    return (h.center, o.center if o is not None else None)


def _combined(f: AFrame) -> tuple:
    return (f.origin, f.orientation)


def _ray(r):
    return Ray(vec(r[0]), vec(r[1]), F(r[2]))


def _lcoord(v):
    return None if v is None else (float(v[0]), float(v[1]))


@dataclass(frozen=True)
class Spec:
    name: str
    anchor: str  # the retail (or ACE) anchor the function is registered under
    generate: Callable  # (rng, n) -> (context, inputs)
    port: Callable  # (context, args, mode) -> plain-able answer; the mode carries the runtime
    ace: Callable  # (AceFunctions, context, args) -> plain answer
    live_n: int = 2000
    record_n: int = 600


def _simple(name, anchor, gen, port, ace_name=None, **kw):
    ace_name = ace_name or name
    return Spec(name, anchor, _n_times(gen), lambda ctx, a, m: port(a, m), lambda fns, ctx, a: getattr(fns, ace_name)(*a), **kw)


SPECS: dict[str, Spec] = {s.name: s for s in [
    # Polygon
    _simple("make_plane", "CPolygon::make_plane", g_make_plane, lambda a, m: port_polygon(a[0]).plane),
    _simple("point_in_poly2D", "CPolygon::point_in_poly2D", g_point_in_poly2d,
            lambda a, m: port_polygon(a[0]).point_in_poly2D(vec(a[1]), Sidedness(a[2]))),
    _simple("point_in_polygon", "CPolygon::point_in_polygon", g_point_in_polygon,
            lambda a, m: port_polygon(a[0]).point_in_polygon(vec(a[1]))),
    _simple("find_crossed_edge", "CPolygon::find_crossed_edge", g_find_crossed_edge,
            lambda a, m: port_polygon(a[0]).find_crossed_edge(sph(a[1]), vec(a[2]), vec(a[3]))),
    _simple("polygon_hits_sphere", "CPolygon::polygon_hits_sphere", g_sphere_contact,
            lambda a, m: port_polygon(a[0]).polygon_hits_sphere(sph(a[1]), vec(a[2]))),
    _simple("polygon_hits_sphere_precise", "CPolygon::polygon_hits_sphere_precise", g_sphere_contact,
            lambda a, m: port_polygon(a[0]).polygon_hits_sphere_precise(sph(a[1]), vec(a[2]))),
    _simple("hits_sphere", "CPolygon::hits_sphere", g_hits_sphere, lambda a, m: port_polygon(a[0]).hits_sphere(sph(a[1]))),
    _simple("pos_hits_sphere", "CPolygon::pos_hits_sphere", g_pos_hits_sphere, _pos_hits),
    _simple("walkable_hits_sphere", "CPolygon::walkable_hits_sphere", g_walkable_hits_sphere, _walkable_hits),
    _simple("check_walkable", "CPolygon::check_walkable", g_check_walkable,
            lambda a, m: port_polygon(a[0]).check_walkable(sph(a[1]), vec(a[2]), a[3])),
    _simple("check_small_walkable", "CPolygon::check_small_walkable", g_check_small_walkable,
            lambda a, m: port_polygon(a[0]).check_small_walkable(sph(a[1]), vec(a[2]))),
    _simple("adjust_sphere_to_plane", "CPolygon::adjust_sphere_to_plane", g_adjust_sphere_to_plane, _adjust_to_plane),
    _simple("adjust_sphere_to_poly", "CPolygon::adjust_sphere_to_poly", g_adjust_sphere_to_poly,
            lambda a, m: port_polygon(a[0]).adjust_sphere_to_poly(sph(a[1]), vec(a[2]), vec(a[3]))),
    _simple("adjust_to_placement_poly", "CPolygon::adjust_to_placement_poly", g_adjust_to_placement_poly, _placement),
    _simple("polygon_hits_ray", "CPolygon::polygon_hits_ray", g_polygon_hits_ray,
            lambda a, m: port_polygon(a[0], a[1]).polygon_hits_ray(_ray(a[2]), F(a[3]))),
    # Sphere
    _simple("find_time_of_collision", "CSphere::find_time_of_collision", g_find_time_of_collision,
            lambda a, m: port_sphere.find_time_of_collision(vec(a[0]), vec(a[1]), F(a[2]))),
    _simple("collides_with_sphere", "CSphere::collides_with_sphere", g_collides_with_sphere,
            lambda a, m: port_sphere.collides_with_sphere(vec(a[0]), F(a[1]))),
    _simple("sphere_intersects", "CSphere::intersects", g_sphere_intersects, lambda a, m: sph(a[0]).intersects(sph(a[1]))),
    _simple("sphere_intersects_ray", "CSphere::sphere_intersects_ray", g_sphere_intersects_ray,
            lambda a, m: sph(a[0]).sphere_intersects_ray(_ray(a[1]))),
    # LandDefs
    _simple("get_block_offset", "LandDefs::get_block_offset", g_block_offset,
            lambda a, m: ace_error(lambda: land_defs.get_block_offset(a[0], a[1]))),
    _simple("adjust_to_outside", "LandDefs::adjust_to_outside", g_adjust_to_outside,
            lambda a, m: land_defs.adjust_to_outside(a[0], vec(a[1]), m.runtime)),
    _simple("blockid_to_lcoord", "LandDefs::blockid_to_lcoord", g_cell, lambda a, m: _lcoord(land_defs.blockid_to_lcoord(a[0]))),
    _simple("gid_to_lcoord", "LandDefs::gid_to_lcoord", g_gid_to_lcoord, lambda a, m: _lcoord(land_defs.gid_to_lcoord(a[0], a[1]))),
    _simple("get_outside_lcoord", "LandDefs::get_outside_lcoord", g_get_outside_lcoord,
            lambda a, m: _lcoord(land_defs.get_outside_lcoord(a[0], F(a[1]), F(a[2])))),
    _simple("lcoord_to_gid", "LandDefs::lcoord_to_gid", g_lcoord_to_gid, lambda a, m: land_defs.lcoord_to_gid(F(a[0]), F(a[1]), m.runtime)),
    _simple("inbound_valid_cellid", "LandDefs::inbound_valid_cellid", g_cell, lambda a, m: land_defs.inbound_valid_cellid(a[0])),
    _simple("cell_in_range", "LandDefs::cell_in_range", g_cell_low, lambda a, m: land_defs.cell_in_range(a[0])),
    _simple("in_block", "LandDefs::in_block", g_in_block, lambda a, m: land_defs.in_block(vec(a[0]), F(a[1]))),
    # LandblockStruct / Landblock
    Spec("landblock_struct", "CLandBlockStruct::ConstructPolygons", gen_landblock_struct, port_landblock_struct,
         lambda fns, ctx, a: fns.landblock_struct(*_ace_lb(ctx, a[0])), live_n=48, record_n=12),
    Spec("calc_water_depth", "CLandBlockStruct::calc_water_depth", _lb_inputs(_water_depth_args), port_calc_water_depth,
         ace_calc_water_depth),
    Spec("get_z", "CLandBlock::GetZ", _lb_inputs(_terrain_point), port_get_z,
         lambda fns, ctx, a: fns.get_z(_ace_lb(ctx, a[0]), [a[1]])[0]),
    Spec("get_landcell", "CLandBlock::get_landcell", _lb_inputs(_landcell_args), port_get_landcell, ace_get_landcell),
    # AFrame / Position
    _simple("frame_local_to_global", "AFrame::local_to_global", g_frame_point, lambda a, m: frame(a[0], m).local_to_global(vec(a[1]))),
    _simple("frame_global_to_local", "AFrame::global_to_local", g_frame_point, lambda a, m: frame(a[0], m).global_to_local(vec(a[1]))),
    _simple("frame_local_to_global_vec", "AFrame::local_to_global_vec", g_frame_point,
            lambda a, m: frame(a[0], m).local_to_global_vec(vec(a[1]))),
    _simple("frame_global_to_local_vec", "AFrame::global_to_local_vec", g_frame_point,
            lambda a, m: frame(a[0], m).global_to_local_vec(vec(a[1]))),
    _simple("frame_combine", "AFrame::combine", g_frame_combine,
            lambda a, m: _combined(AFrame.combine(frame(a[0], m), frame(a[1], m)))),
    _simple("position_get_offset", "Position::get_offset", g_position_pair,
            lambda a, m: ace_error(lambda: position(a[0], m).get_offset(position(a[1], m)))),
    _simple("position_local_to_local", "Position::local_to_local", g_position_pair_point,
            lambda a, m: ace_error(lambda: position(a[0], m).local_to_local(position(a[1], m), vec(a[2])))),
    _simple("position_local_to_global_from", "Position::local_to_global", g_position_pair_point,
            lambda a, m: ace_error(lambda: position(a[0], m).local_to_global_from(position(a[1], m), vec(a[2])))),
]}


def generate(spec: Spec, seed: str, n: int):
    """(context, inputs) for a spec, deterministic in (spec name, seed, n)."""
    rng = random.Random(f"{spec.name}/{seed}")
    with warnings.catch_warnings(), np.errstate(all="ignore"):  # degenerate polygons divide by zero
        warnings.simplefilter("ignore", RuntimeWarning)
        ctx, inputs = spec.generate(rng, n)
    # through the codec, so live and recorded runs see exactly the recorded values
    return dec(enc(ctx)), [dec(enc(list(a))) for a in inputs]


def port_answer(spec: Spec, ctx, args, runtime: str = "mono"):
    """The port's answer computing as ACE on `runtime` ("mono" or "coreclr") does."""
    return plain(spec.port(ctx, args, get_mode("exact", runtime)))


def differences(spec: Spec, ctx, inputs, answers, limit: int = 5, runtime: str = "mono") -> tuple[int, list[str]]:
    """(how many inputs differ, the first `limit` described: input, port, ACE), the port computing
    as ACE on `runtime` does."""
    count, shown = 0, []
    for args, want in zip(inputs, answers):
        try:
            got = port_answer(spec, ctx, args, runtime)
        except Exception as e:  # noqa: BLE001 -- the port crashed where ACE answered: a difference too
            got = ("port raised", f"{type(e).__name__}: {e}")
        if not same(got, want):
            count += 1
            if len(shown) < limit:
                shown.append(f"{spec.name}{tuple(args)!r}: port {got!r}, ACE {want!r}")
    return count, shown
