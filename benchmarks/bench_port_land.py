"""Time per call of the port's terrain routines in exact and fast mode.

    python benchmarks/bench_port_land.py [--number N]

Landblock construction (81 vertices, 128 planes, 64 cells), LScape.get_landcell,
LandCell.find_terrain_poly and Landblock.GetZ on a hilly landblock.
"""

from __future__ import annotations

import argparse
import random
import timeit

from acconform.numerics import EXACT, FAST
from acconform.scene import DEFAULT_LAND_HEIGHT_TABLE, Frame, Landblock as LandblockRec, Mover, Position, Scene, SphereRec
from acconform.port.land.landblock import Landblock
from acconform.port.land.lscape import LScape


def make_scene() -> Scene:
    rng = random.Random(7)
    rec = LandblockRec(0xA9B4FFFF, tuple(rng.randrange(40, 60) for _ in range(81)), tuple(0 for _ in range(81)))
    pos = Position(0xA9B40001, Frame((12.0, 12.0, 100.0)))
    mover = Mover((SphereRec((0.0, 0.0, 0.5), 0.5),), pos, pos, 0.5, 0.5)
    return Scene((rec,), mover)


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--number", type=int, default=2000)
    n = ap.parse_args().number
    scene = make_scene()
    rng = random.Random(1)
    for mode in (EXACT, FAST):
        world = LScape(scene, mode)
        lb = world.get_landblock(0xA9B4FFFF)
        points = [mode.vec(rng.uniform(0, 191.9), rng.uniform(0, 191.9), 100) for _ in range(64)]
        cells = [lb.get_cell(world, p) for p in points]
        ids = [c.id for c in cells]
        it = iter(range(10**12))

        def pick(seq):
            return seq[next(it) % len(seq)]

        rows = {
            "Landblock construction": (lambda: Landblock(scene.landblocks[0], DEFAULT_LAND_HEIGHT_TABLE, mode), max(1, n // 20)),
            "LScape.get_landcell": (lambda: world.get_landcell(pick(ids)), n),
            "LandCell.find_terrain_poly": (lambda: (lambda i: cells[i].find_terrain_poly(points[i]))(next(it) % 64), n),
            "Landblock.GetZ": (lambda: lb.get_z(world, pick(points)), n),
        }
        for name, (fn, count) in rows.items():
            t = timeit.timeit(fn, number=count) / count
            print(f"{mode.name:5s}  {name:28s} {t * 1e6:10.2f} us/call")


if __name__ == "__main__":
    main()
