"""Transition and placement scenes of the recorded corpus with one thing varied (issue 24), for
`acconform record`.

    python tests/runner/transition_variant_scenes.py OUT_DIR [-n 100] [--seed 2425] [--only NAMES]

The placement strategies (strategies/set_position.py) place a mover that is neither Static nor
Active, so PhysicsObj.prepare_to_enter_world's arms for those flags were never taken; the obstacle
strategies never make a sphere or cylsphere static both non-static and ethereal beside a
two-sphere mover, so the second sphere's test in the ethereal-obstruction arm of
Sphere.IntersectsSphere / CylSphere.IntersectsSphere was never reached; and no scene lies at the
world's edge, where LandDefs' range tests refuse a land coordinate below 0 or past the last
landblock (a west edge at landblock column 0x00; an east one at 0xFE; a neighbour in column 0xFF is
past LandLength and makes ACE's Landblock constructor throw); and no sphere or cylsphere obstacle stood
where Transition.CheckWalkable's probe looks (the step-down below an EdgeSlide mover leaving a BSP
ledge or step), so the probe's arm of Sphere.IntersectsSphere / CylSphere.IntersectsSphere (and the
step-down past a Missile obstacle) was never taken; nor did a placement that may slide place a mover
whose sphere is 4 m or more across in radius (FindPlacementPos gives up before its first step); nor
did a mover start on a vertical contact plane (AdjustOffset's SnapToPlane leaves the offset as it is),
or Sliding with a sliding normal (get_object_info's InitSlidingNormal).
Each variant below is
applied to N records of the coreclr corpus drawn with `--seed` from its pool, one scene file each,
named after the record with the variant appended (the tick scenes have tick_variant_scenes.py).
"""

from __future__ import annotations

import random
from dataclasses import replace

from tick_variant_scenes import arguments, drawn_records, write_variants


VARIANT_SHARDS = ("obstacles-0009", "buildings-0004", "bsp-0008", "obstacles-0010", "terrain-0008", "bsp-0011", "buildings-0011", "terrain-0011")  # the corpus shards this script's scenes were recorded into


def variants():
    """(name, pool, scene -> scene): "placement" draws from the placement records, "statics" from
    the transition records with statics outdoors and a one-sphere mover, "outdoor" from the outdoor
    transition records."""
    from acconform.flags import PhysicsState as P, SetPositionFlags, TransientState as T
    from acconform.scene import SphereRec
    from acconform.numerics import to_f32

    CELL = 24.0  # an outdoor cell's side (port/constants.py's CELL_LENGTH)

    def mover(**kw):
        return lambda s: replace(s, mover=replace(s.mover, **{k: f(s.mover) for k, f in kw.items()}))

    def head_sphere(m):
        """A second sphere of the same radius stacked above the first (strategies/scenes.py's form)."""
        low = m.spheres[0]
        return (low, replace(low, center=(0.0, 0.0, to_f32(low.radius * 2.6))))

    def ethereal_obstacles(s):
        return replace(s, objects=tuple(replace(o, state=(o.state & ~P.Static) | P.Ethereal) for o in s.objects))

    def at_world_edge(bx: int, by: int, dx: float, dy: float):
        """The scene moved whole to the landblock column/row (bx, by) (its landblocks, mover and
        statics keep their places relative to each other), the mover's end `dx`, `dy` metres from
        its begin: off the world's edge (land coordinates below 0, or past 2040 where the
        landblock ids end; a landblock west of column 0x00 wraps to 0xFF, as a uint cell id does)."""
        def apply(s):
            b = s.mover.begin.cell
            shift = ((bx - (b >> 24)) << 24) + ((by - (b >> 16 & 0xFF)) << 16)

            def cell(c: int) -> int:
                return (c + shift) & 0xFFFFFFFF

            m = s.mover
            o = m.begin.frame.origin
            mover = replace(m, begin=replace(m.begin, cell=cell(m.begin.cell)),
                            end=replace(m.begin, cell=cell(m.begin.cell),
                                        frame=replace(m.begin.frame, origin=(o[0] + dx, o[1] + dy, o[2]))),
                            contact_plane=m.contact_plane and replace(m.contact_plane, cell=cell(m.contact_plane.cell)))
            return replace(s, mover=mover, landblocks=tuple(replace(lb, id=cell(lb.id)) for lb in s.landblocks),
                           objects=tuple(replace(o, position=replace(o.position, cell=cell(o.position.cell)))
                                         for o in s.objects))
        return apply

    def probe_obstacles(dz: tuple[float, float], two_spheres: bool):
        """An EdgeSlide mover (two spheres if `two_spheres`) and a Static sphere and cylsphere placed at
        random (seeded by the scene's name and place) within 0.9 m of the mover's end across and `dz`
        above it; one in three Missile too (a creature to Sphere.IntersectsSphere). An obstacle whose
        place would leave the end's outdoor cell is left out."""
        from acconform.scene import CylSphereShape, Frame, Position, SphereShape, StaticObject

        def apply(s):
            rng = random.Random(f"{s.name}:{s.mover.end.cell}:{s.mover.end.frame.origin}")
            m = s.mover
            end = m.end.frame.origin
            objects = list(s.objects)
            for k in range(2):
                x, y = (to_f32(end[i] + rng.uniform(-0.9, 0.9)) for i in range(2))
                z = to_f32(end[2] + rng.uniform(*dz))
                radius = to_f32(rng.choice((0.2, 0.3, 0.5)))
                shape = (SphereShape(SphereRec((0.0, 0.0, 0.0), radius)) if k == 0
                         else CylSphereShape((0.0, 0.0, 0.0), radius, to_f32(rng.choice((0.5, 1.0)))))
                state = P.Static | (P.Missile if rng.random() < 1 / 3 else 0)
                if (x // CELL, y // CELL) == (end[0] // CELL, end[1] // CELL):
                    cell = (m.end.cell & 0xFFFF0000) | int(x // CELL) * 8 + int(y // CELL) + 1
                    objects.append(StaticObject(0x71000000 + k, Position(cell, Frame((x, y, z))), shape, int(state)))
            mover = replace(m, state=m.state | P.EdgeSlide, spheres=head_sphere(m) if two_spheres else m.spheres)
            return replace(s, mover=mover, objects=tuple(objects))
        return apply

    def vertical_contact_plane(s):
        """The mover's contact plane turned vertical (normal +x, through its begin) and its end 1 m
        along +x: the first step's offset leaves the plane."""
        m = s.mover
        o = m.begin.frame.origin
        plane = replace(m.contact_plane.plane, normal=(1.0, 0.0, 0.0), d=to_f32(-o[0]))
        end = replace(m.begin, frame=replace(m.begin.frame, origin=(to_f32(o[0] + 1.0), o[1], o[2])))
        return replace(s, mover=replace(m, contact_plane=replace(m.contact_plane, plane=plane), end=end))

    return [
        ("placement_active", "placement", mover(transient_state=lambda m: m.transient_state | T.Active)),
        ("placement_static", "placement", mover(state=lambda m: m.state | P.Static)),
        ("two_spheres_ethereal_obstacles", "statics", lambda s: ethereal_obstacles(mover(spheres=head_sphere)(s))),
        ("world_edge_west", "outdoor", at_world_edge(0x00, 0x80, -200.0, 0.0)),
        ("world_edge_east", "outdoor", at_world_edge(0xFE, 0x80, 200.0, 0.0)),
        # issue 24, third round (bsp-0011)
        ("probe_obstacles", "ledges", probe_obstacles((-0.9, 1.0), False)),
        ("probe_obstacles_two_spheres", "ledges", probe_obstacles((0.2, 1.0), True)),
        ("placement_large_sphere", "placement", lambda s: mover(
            spheres=lambda m: (SphereRec((0.0, 0.0, 4.0), 4.0),), scale=lambda m: 1.0,
            placement=lambda m: replace(m.placement, flags=m.placement.flags | SetPositionFlags.Slide))(s)),
        ("vertical_contact_plane", "contact", vertical_contact_plane),
        ("sliding", "contact", mover(transient_state=lambda m: m.transient_state | T.Sliding,
                                     sliding_normal=lambda m: (-1.0, 0.0, 0.0))),
    ]


def main(argv=None) -> int:
    a = arguments(__doc__, 100, 2425, argv)
    # the drawn transition records, not the variants of them written here before
    scenes = drawn_records(lambda where: "/ticks-" not in where, VARIANT_SHARDS)
    pools = {
        "placement": [(k, s) for k, s in scenes if s.mover.placement is not None],
        # an EnvCell's statics are DAT stabs, which carry no state: the obstacle variant is outdoors
        "statics": [(k, s) for k, s in scenes if s.objects and not s.env_cells and s.mover.placement is None
                    and len(s.mover.spheres) == 1],
        # outdoors, one landblock column either side of the mover's (so that moving the scene to the
        # world's edge keeps every landblock id a landblock id)
        "outdoor": [(k, s) for k, s in scenes if not s.env_cells and not s.buildings and s.mover.placement is None
                    and all(abs((lb.id >> 24) - (s.mover.begin.cell >> 24)) <= 1 for lb in s.landblocks)],
        # outdoors on the ground, with a contact plane, in the middle of a cell (1 m along +x stays in it)
        "contact": [(k, s) for k, s in scenes if not s.env_cells and not s.buildings and not s.objects
                    and s.mover.placement is None and s.mover.contact_plane is not None
                    and 2.0 < s.mover.begin.frame.origin[0] % 24.0 < 22.0],
        # an outdoor mover on a BSP ledge, step or slope (strategies/objects.py's policies), whose
        # step-down probes below it (the probe looks only under a mover standing on a BSP polygon)
        "ledges": [(k, s) for k, s in scenes if s.name.startswith(("bsp:ledge", "bsp:stairs", "bsp:slope", "bsp:touch"))
                   and s.mover.end is not None and not s.env_cells and s.mover.placement is None
                   and len(s.mover.spheres) == 1],
    }
    written = write_variants(a, variants(), pools)
    print(f"{written} scenes in {a.out} ({', '.join(f'{len(p)} {k}' for k, p in pools.items())} records)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
