"""Building scenes of the recorded corpus with the shell or the mover varied (issue 24), for
`acconform record`.

    python tests/runner/building_variant_scenes.py OUT_DIR [-n 12] [--seed 2426] [--only NAMES]

strategies/buildings.py draws a shell whose physics BSP has no solid leaf, a doorway taller than
the mover, and a mover that enters the house by walking or is placed inside it; so no recorded
scene told apart the branches of ACE that only a solid shell or a low lintel reach:

- BSPTree.find_collisions and placement_insert clear a building's solid leaves only while
  SpherePath.BuildingCheck (set by BuildingObj.find_building_collisions) and HitsInteriorCell are
  both set, and they read the solid leaves only for a placement. HitsInteriorCell is set by
  find_cell_list when the check position's cell or the cell holding sphere 0's centre is an EnvCell,
  and otherwise only by EnvCell.check_building_transit, for every sphere of the path that reaches a
  building's cell. `doorway_placement` places the mover in the doorway between the shell's face
  and the house's first cell, overlapping that cell, in an outdoor cell beside the one holding the
  building (the first InsertIntoCell, before any cell list, then meets no building), the shell
  solid inside; `doorway_placement_head_ahead` does so with a two-sphere mover whose second sphere,
  ahead of the first, alone reaches the house's cell.
- LandCell.FindCollisions tests the terrain before the building: the terrain's ValidateWalkable
  sets the contact plane of a mover on the ground even when the building then answers Collided,
  which the BSP does for a mover out of contact whose second sphere alone hits a polygon.
  `low_lintel_airborne` lowers the shell's lintel between the mover's two spheres' tops and walks
  a two-sphere mover out of contact (on the ground) in through the door.
- A cylsphere static finds its cells through ObjCell.find_cell_list's cylsphere overload, with no
  SpherePath: the drawn statics in a house's doorway are boxes (the parts overloads).
  `cylsphere_static_in_doorway` makes the doorway's static a cylsphere (EnvCell.check_building_transit
  without a path); `cylsphere_static_in_house` stands it in the house's first cell under that
  cell's id (find_cell_list from an EnvCell without a path).
- No drawn placement lies outside the world: `placement_off_the_world` places the mover 10 m west
  of its edge, where AdjustToOutside gives cell id 0 and GetVisible finds no cell.

Each variant is applied to N records of the coreclr corpus's buildings shards drawn with `--seed`
from its pool, one scene file each, named after the record with the variant appended.
"""

from __future__ import annotations

from dataclasses import replace

from tick_variant_scenes import arguments, drawn_records, write_variants

VARIANT_SHARDS = ("buildings-0005", "buildings-0006")  # the corpus shards this script's scenes were recorded into


def variants():
    """(name, pool, scene -> scene): "yaw0" draws from the "in" records of a house of yaw 0,
    "two_spheres" from the "in" records with a two-sphere mover and the floor at the ground, "static"
    from the records with a static in the doorway, "placement" from the placement records."""
    from acconform.numerics import to_f32
    from acconform.scene import BSPLeaf, BSPNode, BSPShape, CylSphereShape, Frame, Placement, Position, SphereRec
    from acconform.strategies import dungeon as dg
    from acconform.strategies import shapes as sh
    from acconform.strategies.terrain import BLOCK, CELL, cell_of, split_global

    def solid_inside(shape: BSPShape) -> BSPShape:
        """The shell's tree as a chain over its distinct planes (each node's front a leaf of the
        polygons reaching its front side), the leaf behind them all, inside the house, solid."""
        polys = shape.polygons
        planes = []
        for p in polys:
            pl = dg.plane_of(p.vertices)
            if not any(dg._coplanar(pl, q) for q in planes):
                planes.append(pl)
        every = tuple(range(len(polys)))
        sphere = sh.bounding_sphere([v for p in polys for v in p.vertices])
        node = BSPLeaf(every, True, sphere)
        for pl in reversed(planes):
            front = tuple(i for i in every
                          if max(dg.plane_distance(pl, v) for v in polys[i].vertices) > -dg.SPLIT_TOL)
            node = BSPNode(pl, sphere, BSPLeaf(front, False, sh.bounding_sphere(
                [v for i in front for v in polys[i].vertices])), node)
        return replace(shape, root=node)

    def wall(s) -> float:
        """The shell's thickness outside the cells (its -x face is at house-frame x = -wall)."""
        return -min(v[0] for p in s.buildings[0].shape.polygons for v in p.vertices)

    def moved(frame: Frame, t) -> Frame:
        return replace(frame, origin=tuple(to_f32(a + b) for a, b in zip(frame.origin, t)))

    def outdoor(s, p) -> Position:
        """A point of the building's landblock (possibly past its edges) in the outdoor cell holding it."""
        home = s.buildings[0].landblock
        bx, by, lx, ly = split_global((home >> 24) * BLOCK + p[0], (home >> 16 & 0xFF) * BLOCK + p[1])
        return Position(cell_of(bx, by, lx, ly), Frame((lx, ly, to_f32(p[2]))))

    def doorway(head_ahead: bool):
        def apply(s):
            """The house moved along x so that the cell border nearest its door crosses the doorway a
            quarter of the wall outside the door's inner face (the building stays in the cell past
            the border), its shell solid inside; the mover placed (no flags, engine client) half the
            wall outside the inner face, on the floor's level, so that it reaches the house's first
            cell; with `head_ahead`, as two spheres of 0.4 wall side by side along x, the first
            short of the cell."""
            b = s.buildings[0]
            w = wall(s)
            ox = b.frame.origin[0]
            border = min(max(round(ox / CELL) * CELL, CELL), BLOCK - CELL)
            t = (border + 0.25 * w - ox, 0.0, 0.0)
            frame = moved(b.frame, t)
            o = frame.origin
            s = replace(s, buildings=(replace(b, frame=frame, shape=solid_inside(b.shape)),),
                        env_cells=tuple(replace(c, frame=moved(c.frame, t)) for c in s.env_cells))
            m = s.mover
            spheres = m.spheres
            if head_ahead:
                r = to_f32(min(m.spheres[0].radius, 0.4 * w))
                spheres = (SphereRec((0.0, 0.0, r), r), SphereRec((to_f32(0.5 * w + 0.6 * r), 0.0, r), r))
            begin = outdoor(s, (to_f32(o[0] - 0.5 * w), o[1], o[2]))
            mover = replace(m, spheres=spheres, begin=begin, end=replace(m.end, frame=moved(m.end.frame, t)),
                            placement=Placement(0, False), contact_plane=None, transient_state=0)
            return replace(s, mover=mover, engine_mode="client")
        return apply

    def low_lintel_airborne(s):
        """The shell's piece above the doorway lowered to halfway between the tops of the mover's two
        spheres (the tree rebuilt as strategies/buildings.shell builds it); the mover out of contact."""
        b = s.buildings[0]
        w = wall(s)
        lo, hi = sorted(c.center[2] + c.radius for c in s.mover.spheres)
        z = to_f32((lo + hi) / 2)
        polys = []
        for p in b.shape.polygons:
            ys = sorted({v[1] for v in p.vertices})
            zs = [v[2] for v in p.vertices]
            if all(v[0] == to_f32(-w) for v in p.vertices) and min(zs) > 0 and len(ys) == 2 and ys[0] < 0 < ys[1]:
                p = replace(p, vertices=tuple((v[0], v[1], z if v[2] == min(zs) else v[2]) for v in p.vertices))
            polys.append(p)
        shape = BSPShape(tuple(polys), dg.physics_bsp([(p, False) for p in polys], 3),
                         sh.bounding_sphere([v for p in polys for v in p.vertices]))
        return replace(s, buildings=(replace(b, shape=shape),),
                       mover=replace(s.mover, contact_plane=None, transient_state=0))

    def cylsphere_static(inside: bool):
        def apply(s):
            """The doorway's static made a cylsphere (radius 0.5, height 1) where it stands, or with
            `inside` at the centre of the house's first cell, under that cell's id."""
            o = s.objects[0]
            at = o.position
            if inside:
                c = s.env_cells[0]
                at = Position(c.id, c.frame)
            return replace(s, objects=(replace(o, position=at, shape=CylSphereShape((0.0, 0.0, 0.0), 0.5, 1.0)),))
        return apply

    def placed_off_the_world(s):
        """The mover placed 10 m west of the world's edge (its begin's x in its landblock's frame
        that far below landblock column 0x00): LandDefs.AdjustToOutside refuses it, so
        AdjustPosition's GetVisible meets cell id 0."""
        m = s.mover
        o = m.begin.frame.origin
        x = to_f32(-(m.begin.cell >> 24) * BLOCK - 10.0)
        return replace(s, mover=replace(m, begin=replace(m.begin, frame=replace(m.begin.frame, origin=(x,) + o[1:]))))

    return [
        ("doorway_placement", "yaw0", doorway(False)),
        ("doorway_placement_head_ahead", "yaw0", doorway(True)),
        ("low_lintel_airborne", "two_spheres", low_lintel_airborne),
        ("cylsphere_static_in_doorway", "static", cylsphere_static(False)),
        ("cylsphere_static_in_house", "static", cylsphere_static(True)),
        ("placement_off_the_world", "placement", placed_off_the_world),
    ]


def main(argv=None) -> int:
    a = arguments(__doc__, 12, 2426, argv)
    # the drawn building records, not the variants of them written here or by the other scripts
    scenes = drawn_records(lambda where: "/buildings-" in where, ("buildings-0003", "buildings-0004") + VARIANT_SHARDS)
    walks_in = [(k, s) for k, s in scenes if s.name.split(":")[1] == "in"]
    pools = {
        "yaw0": [(k, s) for k, s in walks_in if s.buildings[0].frame.orientation == (1.0, 0.0, 0.0, 0.0)],
        "two_spheres": [(k, s) for k, s in walks_in if len(s.mover.spheres) == 2
                        and s.mover.begin.frame.origin[2] == s.buildings[0].frame.origin[2]],
        "static": [(k, s) for k, s in scenes if s.name.split(":")[1] == "static"],
        "placement": [(k, s) for k, s in scenes if s.name.split(":")[1] == "placement"],
    }
    written = write_variants(a, variants(), pools)
    print(f"{written} scenes in {a.out} ({', '.join(f'{len(p)} {k}' for k, p in pools.items())} records)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
