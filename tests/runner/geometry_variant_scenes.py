"""Transition and placement scenes of the recorded corpus with an obstacle placed on the mover
(issue 24, the geometry modules' last arcs), for `acconform record`.

    python tests/runner/geometry_variant_scenes.py OUT_DIR [-n 4] [--seed 2426] [--only NAMES]

The obstacle strategies place obstacles at random, so none stood with its centre where a mover's
sphere centre is (within EPSILON, or exactly), nor right above it along the contact plane's
normal: the arms of Sphere.LandOnSphere, CollideWithPoint, SlideSphere (all three overloads) and
StepSphereUp that find the collision normal too small to normalise, zero, or parallel to the
contact plane's, were never taken. A cylsphere's normal is horizontal and longer than the radii's sum less EPSILON, or vertical: it is too small
only when the mover's sphere and the cylsphere have radii summing below 2 EPSILON, with the
sphere's centre just outside the sum's circle before the step that collides; these scenes make
such a mover (one sphere of radius 3.5e-4, or a second one above it) step across such a
cylsphere's axis, airborne, path-clipped (a Missile) or on the ground, so that
CylSphere.LandOnCylinder, CollideWithPoint, SlideSphere and StepSphereUp each meet that normal.
Nor did an obstacle meet a two-sphere mover's second sphere alone where Sphere.IntersectsSphere's
Collide arm (after a landing) or CylSphere.IntersectsSphere's ethereal arm tests it, nor did a
placement put a second sphere wholly inside a solid BSP leaf, touching none of its polygons
(BSPTree.placement_insert's second-sphere test with no polygon to push it out by), nor did a
mover step down less than EPSILON onto a cylsphere (CylSphere.StepSphereDown's too-short step),
nor was a mover placed with an orientation of length 2 (AFrame.IsValid's length test on mono,
where no tick record's RequestPos reaches set_frame unnormalised).

Each variant below is applied to N records of the coreclr corpus drawn with `--seed` from its
pool, one scene file each, named after the record with the variant appended.
"""

from __future__ import annotations

import math
from dataclasses import replace

from tick_variant_scenes import arguments, drawn_records, write_variants


VARIANT_SHARDS = ("obstacles-0012", "buildings-0012", "bsp-0012", "terrain-0012")  # the shards this script's scenes were recorded into

# a mover sphere's and a cylsphere's radii summing below 2 EPSILON (port/constants.py's EPSILON 0.0002);
# the mover's is more than EPSILON, else each of its steps is shorter than EPSILON and vanishes
SMALL, TINY = 3.5e-4, 1e-5


def _rotate(q, v):
    """v rotated by the unit quaternion q = (w, x, y, z) (float64: where an obstacle goes needs no
    exactness, the scene holds the float32 it rounds to)."""
    w, x, y, z = q
    n = math.sqrt(w * w + x * x + y * y + z * z) or 1.0
    w, x, y, z = w / n, x / n, y / n, z / n
    vx, vy, vz = v
    tx, ty, tz = 2 * (y * vz - z * vy), 2 * (z * vx - x * vz), 2 * (x * vy - y * vx)
    return (vx + w * tx + (y * tz - z * ty), vy + w * ty + (z * tx - x * tz), vz + w * tz + (x * ty - y * tx))


def variants():
    """(name, pool, scene -> scene): "ground" draws from the outdoor transition records of a mover
    on the ground in the middle of a cell, "indoor_placement" from the placements in an EnvCell,
    "placement" from the outdoor placements."""
    from acconform.flags import PhysicsState as P, TransientState as T
    from acconform.numerics import to_f32
    from acconform.scene import (BSPLeaf, BSPNode, CylSphereShape, Frame, PlaneRec, PolygonRec, Position,
                                 SphereRec, SphereShape, StaticObject)

    CELL = 24.0  # an outdoor cell's side (port/constants.py's CELL_LENGTH)

    def sphere_centre(m, k):
        """Mover sphere k's centre at its begin, in the landblock's frame."""
        o = m.begin.frame.origin
        c = _rotate(m.begin.frame.orientation, tuple(to_f32(x * m.scale) for x in m.spheres[k].center))
        return tuple(o[i] + c[i] for i in range(3))

    def static(s, at, shape, state=P.Static):
        """`s` with a static of `shape` whose frame's origin is `at` (in the mover's begin cell's landblock)."""
        x, y, z = (to_f32(v) for v in at)
        cell = (s.mover.begin.cell & 0xFFFF0000) | int(x // CELL) * 8 + int(y // CELL) + 1
        obj = StaticObject(0x72000000 + len(s.objects), Position(cell, Frame((x, y, z))), shape, int(state))
        return replace(s, objects=s.objects + (obj,))

    def airborne(m):
        return replace(m, transient_state=m.transient_state & ~(T.Contact | T.OnWalkable), contact_plane=None)

    def head_sphere(m):
        """A second sphere of the same radius stacked above the first (strategies/scenes.py's form)."""
        low = m.spheres[0]
        return (low, replace(low, center=(0.0, 0.0, to_f32(low.radius * 2.6))))

    def on_sphere(k: int, radius: float, above: float = 0.0, air: bool = False, state: int = 0, two: bool = False,
                  step_up: float | None = None):
        """A static sphere of `radius` centred on the mover's sphere k at its begin (`above` times the
        radii's sum along the contact plane's normal from it, else up); the mover airborne if `air`,
        with `state` added, two spheres if `two`, its step-up height `step_up` if given."""
        def apply(s):
            m = s.mover
            m = replace(m, state=m.state | state, spheres=head_sphere(m) if two else m.spheres,
                        step_up_height=m.step_up_height if step_up is None else step_up)
            if air:
                m = airborne(m)
            c = sphere_centre(m, k)
            lift = above * (m.spheres[k].radius * m.scale + radius)
            n = m.contact_plane.plane.normal if m.contact_plane is not None else (0.0, 0.0, 1.0)
            at = tuple(c[i] + lift * n[i] for i in range(3))
            return static(replace(s, mover=m), at, SphereShape(SphereRec((0.0, 0.0, 0.0), to_f32(radius))))
        return apply

    def onto_axis(height: float, below: float, air: bool = False, state: int = 0, head: bool = False,
                  step_up: float | None = None):
        """The mover made one sphere of radius SMALL 0.5 m up (clear of the ground; a second 1 m above
        it if `head`), taking one step of 2.6e-4 m along +x across the axis of a cylsphere of radius
        TINY and `height` whose low point is `below` under the (last) sphere's centre, 1.8e-4 m ahead
        of it: the radii's sum less EPSILON is 1.6e-4 m, so the step's end (8e-5 m past the axis)
        collides while the centre it left is outside that circle and within EPSILON of the axis."""
        def apply(s):
            m = s.mover
            spheres = (SphereRec((0.0, 0.0, 0.5), SMALL),) + ((SphereRec((0.0, 0.0, 1.5), SMALL),) if head else ())
            m = replace(m, spheres=spheres, scale=1.0, state=m.state | state,
                        step_up_height=m.step_up_height if step_up is None else step_up)
            if air:
                m = airborne(m)
            o = m.begin.frame.origin
            end = (to_f32(o[0] + 2.6e-4), o[1], o[2])
            m = replace(m, end=replace(m.begin, frame=replace(m.begin.frame, origin=end)))
            c = sphere_centre(m, len(spheres) - 1)
            shape = CylSphereShape((0.0, 0.0, 0.0), TINY, to_f32(height))
            return static(replace(s, mover=m), (c[0] + 1.8e-4, c[1], c[2] - below), shape)
        return apply

    def ethereal_cylsphere_on_head(s):
        """A two-sphere mover; a non-static ethereal cylsphere (radius 0.2, 0.1 m high) around its
        second sphere's centre at its begin, clear of the first sphere."""
        m = replace(s.mover, spheres=head_sphere(s.mover))
        c = sphere_centre(m, 1)
        shape = CylSphereShape((0.0, 0.0, 0.0), 0.2, 0.1)
        return static(replace(s, mover=m), (c[0], c[1], c[2] - 0.05), shape, state=P.Ethereal)

    def head_after_landing(s):
        """A two-sphere mover airborne, taking one step along +x as long as its first sphere's radius
        r: a static sphere of radius 0.3 ahead, level with the first sphere, 0.8 of the radii's sum
        from where the step ends (LandOnSphere sets Collide; the next insertion finds it touched on
        its side, too steep to land on: OK), and one of radius 0.05 on the second sphere's centre
        where the step ends (listed first: the cell's objects are tried from the last)."""
        m = replace(s.mover, spheres=head_sphere(s.mover))
        m = airborne(m)
        r = m.spheres[0].radius * m.scale
        b = m.begin.frame.origin
        m = replace(m, end=replace(m.begin, frame=replace(m.begin.frame, origin=(to_f32(b[0] + r), b[1], b[2]))))
        c0, c1 = sphere_centre(m, 0), sphere_centre(m, 1)
        s = static(replace(s, mover=m), (c1[0] + r, c1[1], c1[2]), SphereShape(SphereRec((0.0, 0.0, 0.0), 0.05)))
        return static(s, (c0[0] + r + 0.8 * (r + 0.3), c0[1], c0[2]), SphereShape(SphereRec((0.0, 0.0, 0.0), 0.3)))

    def tiny_step_down_onto_cylsphere(s):
        """The mover lifted 0.5 m off the ground (Contact and OnWalkable), walking 5 cm level along
        its contact plane (across the slope), its step-down height 1.9e-4 m (below EPSILON); a
        cylsphere (radius 0.5, 0.3 m high) under its first sphere, its top 0.95e-4 m further below
        than CylSphere.CollidesWithSphere reaches: the step finds no contact plane, so Transition
        steps down 1.9e-4 m, meets the cylsphere, and StepSphereDown finds the step too short to
        scale (StepDownAmt * WalkInterp below EPSILON)."""
        m = s.mover
        b = m.begin.frame.origin
        n = m.contact_plane.plane.normal
        across = math.hypot(n[0], n[1])
        dx, dy = (n[1] / across, -n[0] / across) if across > 1e-6 else (1.0, 0.0)  # cross(n, +z): level, in the plane
        up = (b[0], b[1], to_f32(b[2] + 0.5))
        end = (to_f32(up[0] + 0.05 * dx), to_f32(up[1] + 0.05 * dy), up[2])
        m = replace(m, step_down_height=1.9e-4, transient_state=m.transient_state | T.Contact | T.OnWalkable,
                    begin=replace(m.begin, frame=replace(m.begin.frame, origin=up)),
                    end=replace(m.begin, frame=replace(m.begin.frame, origin=end)))
        c = sphere_centre(m, 0)
        r = m.spheres[0].radius * m.scale
        height = 0.3
        low = c[2] - (r + height - 2e-4 + 0.95e-4)
        return static(replace(s, mover=m), (c[0], c[1], low), CylSphereShape((0.0, 0.0, 0.0), 0.5, height))

    def quaternion_times_2(s):
        """The mover's begin orientation doubled (length 2): the placement's set_frame finds the frame
        invalid except for its heading (AFrame.IsValid's length test)."""
        m = s.mover
        q = tuple(to_f32(2.0 * v) for v in m.begin.frame.orientation)
        return replace(s, mover=replace(m, begin=replace(m.begin, frame=replace(m.begin.frame, orientation=q))))

    def head_inside_solid(s):
        """A two-sphere mover (the second 2.4 radii above the first) whose EnvCell's structure is
        given a physics BSP of one node, the plane z = h of the cell's frame midway between the
        spheres' centres (normal down), with an empty leaf in front (below) and a solid leaf behind
        (above) holding one small triangle on the plane 3 m aside: the placement's first sphere is
        wholly in front, its second wholly behind, in the solid leaf's half and clear of the
        triangle's leaf sphere (BSPTree.placement_insert finds no hit for the first sphere, then the
        second's centre solid and no polygon to push it out by). The placement keeps the scene's
        cell (no GetCell)."""
        m = s.mover
        low = m.spheres[0]
        m = replace(m, placement=replace(m.placement, get_cell=False),
                    spheres=(low, replace(low, center=(low.center[0], low.center[1], to_f32(low.center[2] + 2.4 * low.radius)))))
        cell = next(c for c in s.env_cells if c.id == m.begin.cell)
        c = tuple((a + b) / 2 for a, b in zip(sphere_centre(m, 0), sphere_centre(m, 1)))
        o = cell.frame.origin
        w, x, y, z = cell.frame.orientation
        lx, ly, h = (to_f32(v) for v in _rotate((w, -x, -y, -z), tuple(c[i] - o[i] for i in range(3))))
        tx = to_f32(lx + 3.0)
        tri = PolygonRec(((tx, ly, h), (tx, to_f32(ly + 1.0), h), (to_f32(tx + 1.0), ly, h)))
        root = BSPNode(PlaneRec((0.0, 0.0, -1.0), h), SphereRec((lx, ly, h), 5.0),
                       BSPLeaf((), False, SphereRec((lx, ly, h), 0.0)),
                       BSPLeaf((0,), True, SphereRec((to_f32(tx + 0.25), to_f32(ly + 0.25), h), 0.75)))

        def env(e):
            if e.id != cell.environment:
                return e
            structs = list(e.cell_structs)
            structs[cell.cell_structure] = replace(structs[cell.cell_structure], physics_polygons=(tri,), physics_bsp=root)
            return replace(e, cell_structs=tuple(structs))
        return replace(s, mover=m, environments=tuple(env(e) for e in s.environments))

    return [
        # Sphere: the collision normal from the mover's sphere centre to the obstacle's is (nearly) zero
        ("sphere_on_centre_air", "ground", on_sphere(0, 0.5, air=True)),                      # LandOnSphere
        ("sphere_on_centre_clipped", "ground", on_sphere(0, 0.5, air=True, state=P.Missile)),  # CollideWithPoint
        ("sphere_on_head_air", "ground", on_sphere(1, 0.05, air=True, two=True)),             # CollideWithPoint, sphere 1
        ("sphere_on_head_ground", "ground", on_sphere(1, 0.05, two=True)),                    # SlideSphere(checkPos), sphere 1
        ("sphere_on_centre_ground", "ground", on_sphere(0, 2.0)),                             # StepSphereUp -> SlideSphere(disp)
        ("sphere_overhead_ground", "ground", on_sphere(0, 0.5, above=0.6, step_up=0.05)),     # SlideSphere(disp): normal along the plane's
        ("sphere_on_centre_step_up", "ground", on_sphere(0, 0.05, step_up=5.0)),             # StepSphereUp -> StepUpSlide: a zero normal
        ("sphere_on_head_after_landing", "ground", head_after_landing),                       # IntersectsSphere's collide arm, sphere 1
        ("cylsphere_ethereal_on_head", "ground", ethereal_cylsphere_on_head),                 # IntersectsSphere's ethereal arm, sphere 1
        # BSP: a placement whose second sphere is inside a solid leaf, touching no polygon
        ("placement_head_inside_solid", "indoor_placement", head_inside_solid),
        # CylSphere: radii summing below 2 EPSILON
        ("cylsphere_axis_air", "ground", onto_axis(1.0, 0.5, air=True)),                      # LandOnCylinder
        ("cylsphere_axis_clipped", "ground", onto_axis(1.0, 0.5, air=True, state=P.Missile)),  # CollideWithPoint
        ("cylsphere_axis_head_air", "ground", onto_axis(0.6, 0.3, air=True, head=True)),      # CollideWithPoint, sphere 1
        ("cylsphere_axis_ground_slide", "ground", onto_axis(1.0, 0.5, step_up=0.01)),         # StepSphereUp -> SlideSphere
        ("cylsphere_axis_head_ground", "ground", onto_axis(0.6, 0.3, head=True)),             # SlideSphere, sphere 1
        ("cylsphere_axis_ground_step", "ground", onto_axis(1.0, 0.9, step_up=0.5)),           # StepSphereUp's own normal
        ("cylsphere_tiny_step_down", "ground", tiny_step_down_onto_cylsphere),                # StepSphereDown: a step too short
        # AFrame.IsValid: a placed mover's orientation of length 2 (set_frame zeroes it), on mono too
        ("placement_quaternion_length_2", "placement", quaternion_times_2),
    ]


def main(argv=None) -> int:
    a = arguments(__doc__, 4, 2426, argv)
    # the drawn transition records, not the variants of them written here before
    scenes = drawn_records(lambda where: "/ticks-" not in where, VARIANT_SHARDS)

    def ground(s) -> bool:
        """Outdoors on the ground, one sphere, in the middle of a cell near the landblock's corner
        (float32 steps of 1e-5 m there), nothing else in the scene."""
        m = s.mover
        o = m.begin.frame.origin
        return (not s.env_cells and not s.buildings and not s.objects and m.placement is None and m.end is not None
                and m.contact_plane is not None and len(m.spheres) == 1 and (m.begin.cell & 0xFFFF) < 0x100
                and all(2.0 < o[i] % 24.0 < 22.0 and o[i] < 48.0 for i in range(2)))

    def indoor_placement(s) -> bool:
        """A placement of a one-sphere mover (radius below 1 m) in one of the scene's EnvCells."""
        m = s.mover
        return (m.placement is not None and len(m.spheres) == 1 and m.spheres[0].radius * m.scale < 1.0
                and any(c.id == m.begin.cell for c in s.env_cells))

    pools = {"ground": [(k, s) for k, s in scenes if ground(s)],
             "placement": [(k, s) for k, s in scenes if s.mover.placement is not None and not s.env_cells and not s.buildings],
             "indoor_placement": [(k, s) for k, s in scenes if indoor_placement(s)]}
    written = write_variants(a, variants(), pools)
    print(f"{written} scenes in {a.out} ({', '.join(f'{len(p)} {k}' for k, p in pools.items())} records)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
