"""Scenes of the recorded corpus with one DAT field or place varied (issue 24), for
`acconform record`.

    python tests/runner/cell_variant_scenes.py OUT_DIR [-n 3] [--seed 2425]

strategies/dungeon.py and strategies/buildings.py draw EnvCells whose visible cells are distinct
cells the scene defines, in landblocks other than 0x0000, buildings with no leaves, standing on their
landblock, whose portals each name a portal of their cell, and statics with a physics BSP in the
cells and doorways; the outdoor strategies never draw a scene at the world's edge. So no recorded
scene took: EnvCell.build_visible_cells' arms for a visible cell listed twice (skipped in landblock
0x0000, where a cell's full id equals its low word; elsewhere Dictionary.Add throws) and for one the
cell DAT does not hold (ReadFromDat throws), BuildingObj.makeBuilding's LeafCells, init_buildings'
building whose cell is not its landblock's, check_building_transit's portal 0xFFFF, the parts'
transit through portals for a part with no physics sphere (a sphere static in a cell or a doorway),
and LandCell.add_all_outside_cells / add_cell_block / add_outside_cell past the world's edge (a
mover heading over it, statics on it), and DatLoader's compressed counts of two bytes (a GfxObj of
128 physics polygons or more). Each variant below is applied to N records of the coreclr
corpus drawn with `--seed` (of those it applies to), one scene file each, named after the record
with the kind and the variant appended.
"""

from __future__ import annotations

import argparse
import json
import random
from dataclasses import replace
from pathlib import Path


def variants():
    """(name, kind of record it applies to, does it apply to a scene, scene -> scene)."""
    from acconform.scene import SphereRec, SphereShape

    def first_cell_with_visible(s):
        return next((i for i, c in enumerate(s.env_cells) if c.visible_cells), None)

    def visible(extra):
        def apply(s):
            i = first_cell_with_visible(s)
            cells = list(s.env_cells)
            cells[i] = replace(cells[i], visible_cells=cells[i].visible_cells + (extra(s, cells[i]),))
            return replace(s, env_cells=tuple(cells))
        return apply

    def statics_as(shape):
        return lambda s: replace(s, objects=tuple(replace(o, shape=shape(o)) for o in s.objects))

    sphere = statics_as(lambda o: SphereShape(SphereRec((0.0, 0.0, 0.5), 0.5)))

    def at_landblock_zero(s):
        """The one-landblock dungeon moved to landblock 0x0000 (its cells' ids with it)."""
        def cell(c):
            return c & 0xFFFF
        m = s.mover
        mover = replace(m, begin=replace(m.begin, cell=cell(m.begin.cell)),
                        end=None if m.end is None else replace(m.end, cell=cell(m.end.cell)),
                        contact_plane=None if m.contact_plane is None else replace(m.contact_plane,
                                                                                  cell=cell(m.contact_plane.cell)))
        return replace(s, landblocks=tuple(replace(lb, id=0x0000FFFF) for lb in s.landblocks), mover=mover,
                       env_cells=tuple(replace(c, id=cell(c.id)) for c in s.env_cells),
                       objects=tuple(replace(o, position=replace(o.position, cell=cell(o.position.cell)))
                                     for o in s.objects))

    def one_block_dungeon(s):
        return (len(s.landblocks) == 1 and s.ticks is None and not s.buildings
                and first_cell_with_visible(s) is not None)

    def buildings(**kw):
        return lambda s: replace(s, buildings=tuple(replace(b, **{k: f(b) for k, f in kw.items()}) for b in s.buildings))

    def to_the_world_edge(s, east=False):
        """The scene moved west (east) by whole landblocks until its west-most (east-most) one is
        in the world's first (last) column, x 0x00 (0xFE): ids change, coordinates within a
        landblock do not; a cell of a landblock the scene does not list stays put."""
        xs = [lb.id >> 24 for lb in s.landblocks]
        dx = (0xFE - max(xs) if east else -min(xs)) << 24
        listed = {lb.id >> 16 for lb in s.landblocks}

        def cell(c):
            return c + dx if c >> 16 in listed else c
        m = s.mover
        mover = replace(m, begin=replace(m.begin, cell=cell(m.begin.cell)),
                        end=replace(m.end, cell=cell(m.end.cell)),
                        contact_plane=None if m.contact_plane is None else replace(m.contact_plane,
                                                                                  cell=cell(m.contact_plane.cell)))
        return replace(s, landblocks=tuple(replace(lb, id=cell(lb.id)) for lb in s.landblocks), mover=mover,
                       objects=tuple(replace(o, position=replace(o.position, cell=cell(o.position.cell)))
                                     for o in s.objects))

    def edge_column(p, s, east):
        """In the scene's west-most (east-most) landblock, its first (last) column of cells."""
        xs = [lb.id >> 24 for lb in s.landblocks]
        low = p.cell & 0xFFFF
        return p.cell >> 24 == (max(xs) if east else min(xs)) and (0x39 <= low <= 0x40 if east else 1 <= low <= 8)

    def at_x(p, x):
        return replace(p, frame=replace(p.frame, origin=(x,) + tuple(p.frame.origin[1:])))

    def mover_over_the_edge(east):
        """At the world's edge, the mover starts 0.1 m from it and heads 0.5 m past it."""
        def apply(s):
            s = to_the_world_edge(s, east)
            m = s.mover
            return replace(s, mover=replace(m, begin=at_x(m.begin, 191.9 if east else 0.1),
                                            end=at_x(m.end, 192.4 if east else -0.4)))
        return apply

    def statics_on_the_edge(s):
        """At the world's west edge, every static in its first column of cells 0.3 m from it."""
        edge = [edge_column(o.position, s, False) for o in s.objects]
        s = to_the_world_edge(s)
        return replace(s, objects=tuple(replace(o, position=at_x(o.position, 0.3)) if e else o
                                        for o, e in zip(s.objects, edge)))

    def many_polygons(s):
        """Every BSP static's GfxObj with 130 more physics polygons (copies of its first, in no
        leaf): DatLoader reads their count as a compressed uint of two bytes (128 and up)."""
        return replace(s, objects=tuple(
            replace(o, shape=replace(o.shape, polygons=o.shape.polygons + (o.shape.polygons[0],) * 130))
            if o.shape.kind == "bsp" else o for o in s.objects))

    def outdoors(s):
        return s.ticks is None and not s.buildings and not s.env_cells and s.mover.end is not None

    def mover_at_the_edge(east):
        return lambda s: outdoors(s) and s.mover.placement is None and edge_column(s.mover.begin, s, east)

    def static_in_column_0(s):
        return outdoors(s) and any(edge_column(o.position, s, False) for o in s.objects)

    def in_cells(s):
        return any(o.position.cell & 0xFFFF >= 0x100 for o in s.objects)

    return [
        ("visible_cell_twice", "indoor", lambda s: first_cell_with_visible(s) is not None,
         visible(lambda s, c: c.visible_cells[0])),
        ("visible_cell_missing", "indoor", lambda s: first_cell_with_visible(s) is not None,
         visible(lambda s, c: 0x100 + sum(1 for e in s.env_cells if e.id >> 16 == c.id >> 16))),
        ("visible_cell_twice_at_block_0", "indoor", one_block_dungeon,
         lambda s: visible(lambda s, c: c.visible_cells[0])(at_landblock_zero(s))),
        ("leaf_cells", "buildings", lambda s: bool(s.buildings), buildings(num_leaves=lambda b: 3)),
        ("portals_to_no_portal", "buildings", lambda s: bool(s.buildings),
         buildings(portals=lambda b: tuple(replace(p, other_portal=0xFFFF) for p in b.portals))),
        ("off_its_landblock", "buildings", lambda s: bool(s.buildings),
         buildings(frame=lambda b: replace(b.frame, origin=(b.frame.origin[0] + 192.0,) + tuple(b.frame.origin[1:])))),
        ("over_the_world_edge", "terrain", mover_at_the_edge(False), mover_over_the_edge(False)),
        ("over_the_world_east_edge", "terrain", mover_at_the_edge(True), mover_over_the_edge(True)),
        ("statics_on_the_world_edge", "obstacles", static_in_column_0, statics_on_the_edge),
        ("sphere_statics", "indoor", in_cells, sphere),
        ("sphere_statics", "buildings", lambda s: bool(s.objects), sphere),
        ("many_polygons", "bsp", lambda s: outdoors(s) and any(o.shape.kind == "bsp" for o in s.objects),
         many_polygons),
    ]


def main(argv=None) -> int:
    from acconform.oracle import default_corpus
    from acconform.oracle.recorded import RecordedOracle
    from acconform.scene import Scene

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out", type=Path)
    ap.add_argument("-n", type=int, default=3, help="records per variant")
    ap.add_argument("--seed", type=int, default=2425)
    a = ap.parse_args(argv)
    a.out.mkdir(parents=True, exist_ok=True)
    oracle = RecordedOracle(default_corpus("coreclr"))
    names = tuple(f":{name}" for name, *_ in variants())
    by_kind = {}
    for e in sorted(oracle.entries, key=lambda e: e.key):
        for kind in ("indoor", "buildings", "terrain", "obstacles", "bsp"):
            if f"/{kind}-" in e.where:
                s = Scene.from_json(e.doc()["scene"])
                if not s.name.endswith(names):  # not a variant recorded before
                    by_kind.setdefault(kind, []).append((e.key, s))
    rng = random.Random(a.seed)
    written = 0
    for name, kind, applies, make in variants():
        pool = [(k, s) for k, s in by_kind[kind] if applies(s)]
        for key, s in rng.sample(pool, min(a.n, len(pool))):
            v = make(s)
            (a.out / f"{key[:16]}-{kind}-{name}.json").write_text(json.dumps(replace(v, name=f"{s.name}:{name}").to_json()))
            written += 1
    print(f"{written} scenes in {a.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
