"""Time per call of port/geom's main predicates, in exact (float32) and fast (double) mode.

    python benchmarks/bench_port_geom.py [--number N]
"""

from __future__ import annotations

import argparse
import timeit

from acconform.numerics import EXACT, FAST, Plane
from acconform.port.geom.polygon import Polygon
from acconform.port.geom.sphere import Sphere
from acconform.scene import PolygonRec

QUAD = PolygonRec(((-1.0, -1.0, 0.0), (1.0, -1.0, 0.0), (1.0, 1.0, 0.0), (-1.0, 1.0, 0.0)))


class _Path:
    def __init__(self, mode):
        self.walkable_allowance = mode.scalar(0.66417414)
        self.walk_interp = mode.scalar(1.0)
        self.offsets = 0

    def add_offset_to_check_pos(self, offset, radius=None):
        self.offsets += 1


class _Collisions:
    def __init__(self, mode):
        self.contact_plane_valid = True
        self.contact_plane = Plane(mode.vec(0, 0, 1), mode.scalar(0))
        self.last_known_contact_plane = self.contact_plane

    def set_collision_normal(self, n):
        pass


class _Pos:
    obj_cell_id = 0xA9B40001


class _Transition:
    def __init__(self, mode):
        self.sphere_path = _Path(mode)
        self.sphere_path.cur_pos = self.sphere_path.check_pos = _Pos()
        self.collision_info = _Collisions(mode)


def cases(mode):
    poly = Polygon.from_rec(QUAD, mode)
    edge = Sphere(mode.vec(1.2, 0.3, 0.1), mode.scalar(0.5))  # beside an edge: the inner loop runs
    up, down, zero = mode.vec(0, 0, 1), mode.vec(0, 0, -1), mode.vec(0, 0, 0)
    path = _Path(mode)
    t = _Transition(mode)
    slider = Sphere(mode.vec(1, 1, 0), mode.scalar(0.5))
    return {
        "polygon_hits_sphere_precise": lambda: poly.polygon_hits_sphere_precise(edge, zero),
        "pos_hits_sphere": lambda: poly.pos_hits_sphere(edge, down, zero, None),
        "walkable_hits_sphere": lambda: poly.walkable_hits_sphere(path, edge, up),
        "find_crossed_edge": lambda: poly.find_crossed_edge(Sphere(mode.vec(1.5, 0.3, 0.1), mode.scalar(0.5)), up, zero),
        "slide_sphere": lambda: slider.slide_sphere(t, mode.vec(1, 0, 0), zero),
    }


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--number", type=int, default=20000)
    args = ap.parse_args()
    print(f"{'predicate':32} {'exact us/call':>14} {'fast us/call':>14}")
    exact, fast = cases(EXACT), cases(FAST)
    for name in exact:
        te = min(timeit.repeat(exact[name], number=args.number, repeat=3)) / args.number * 1e6
        tf = min(timeit.repeat(fast[name], number=args.number, repeat=3)) / args.number * 1e6
        print(f"{name:32} {te:14.2f} {tf:14.2f}")


if __name__ == "__main__":
    main()
