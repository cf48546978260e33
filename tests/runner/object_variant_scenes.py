"""Scenes of the recorded corpus with one thing about an object varied (issue 24, the fourth round),
for `acconform record`.

    python tests/runner/object_variant_scenes.py OUT_DIR [-n 20] [--seed 2426] [--only NAMES]

No scene set PhysicsState.ParticleEmitter, which a scene's state may carry: ACE then keeps a
ShadowObj under key 1 in CurCell's place that no cell's shadow list holds
(PhysicsObj.add_particle_shadow_to_cell), leaves the parts' frames and cell ids alone, and throws
ArgumentException when it adds that shadow a second time (a mover's second step). No static stood
so far off its landblock that LandDefs.AdjustToOutside fails (its cell id 0 then makes ACE's
Landblock.get_landcell throw: gid_to_lcoord(0).Value), or in the next landblock's ground (ACE's
init_static_objs drops it: get_landcell finds another id in the slot). No EnvCell held two statics
of different shapes (the harness reads the second one's shadows past the first), nor did a static
stand in an EnvCell ACE never loads. No tick mover began with an orientation of length 2 (set_frame
zeroes it, and NaN frames follow: a transition ending in no cell, change_cell_server from no cell,
handle_visible_cells' EnvCell arm, and in landblock 0x018A a next transition with no begin cell),
and no mover was in Contact and StationaryStuck (the stationary fall's Contact arm).
Each variant below is applied to N records of the coreclr corpus drawn with `--seed` from its pool,
one scene file each, named after the record with the variant appended (tick_variant_scenes.py's
helpers).
"""

from __future__ import annotations

from dataclasses import replace

from tick_variant_scenes import arguments, drawn_records, write_variants


VARIANT_SHARDS = ("bsp-0013", "buildings-0013", "indoor-0013", "obstacles-0013", "ticks-0013")  # the corpus shards this script's scenes were recorded into


def variants():
    """(name, pool, scene -> scene): "statics" draws from the outdoor transition records with
    statics, "placement" from the placement records, "ticks" and "tick_statics" from the tick
    records (with statics outdoors), "request_pos_indoor" from the request_pos tick records with a
    RequestPos in an EnvCell, "gravity_moves" from the transition records of a mover with Gravity,
    "indoor_statics" from the records with a static in an EnvCell."""
    from acconform.flags import PhysicsState as P, TransientState as T
    from acconform.scene import Position, SphereRec, SphereShape, StaticObject

    PE = P.ParticleEmitter

    def mover_state(flag):
        return lambda s: replace(s, mover=replace(s.mover, state=s.mover.state | flag))

    def mover_transient(flags):
        return lambda s: replace(s, mover=replace(s.mover, transient_state=s.mover.transient_state | flags))

    def statics_state(flag):
        return lambda s: replace(s, objects=tuple(replace(o, state=o.state | flag) for o in s.objects))

    def first_static_moved(dx: float):
        """The first static `dx` metres along +x from where it stood (its cell id kept)."""
        def apply(s):
            o = s.objects[0]
            f = o.position.frame
            moved = replace(o, position=replace(o.position, frame=replace(
                f, origin=(f.origin[0] + dx, f.origin[1], f.origin[2]))))
            return replace(s, objects=(moved,) + s.objects[1:])
        return apply

    def free_id(s, base: int) -> int:
        used = {o.id for o in s.objects}
        return next(i for i in range(base, base + 1000) if i not in used)

    def second_indoor_static(s):
        """Beside the first static in an EnvCell, a sphere static of another shape (radius 0.1 m, 2 m
        above it): the cell makes both from its stab list."""
        o = next(o for o in s.objects if o.position.cell & 0xFFFF >= 0x100)
        f = o.position.frame
        twin = StaticObject(free_id(s, 0x72000000), replace(o.position, frame=replace(
            f, origin=(f.origin[0], f.origin[1], f.origin[2] + 2.0))), SphereShape(SphereRec((0.0, 0.0, 0.0), 0.1)))
        return replace(s, objects=s.objects + (twin,))

    def static_in_each_cell(s):
        """A small sphere static at the centre frame of every EnvCell without one (ACE makes it only
        when the cell loads)."""
        have = {o.position.cell for o in s.objects}
        add = []
        for c in s.env_cells:
            if c.id not in have:
                add.append(StaticObject(free_id(s, 0x73000000 + len(add) * 0x1000), Position(c.id, c.frame),
                                        SphereShape(SphereRec((0.0, 0.0, 0.0), 0.1))))
        return replace(s, objects=s.objects + tuple(add))

    def unnormalized_mover(s):
        """The mover's begin orientation doubled (length 2): set_frame gives it the zero quaternion."""
        b = s.mover.begin
        q = tuple(2.0 * c for c in b.frame.orientation)
        return replace(s, mover=replace(s.mover, begin=replace(b, frame=replace(b.frame, orientation=q))))

    def in_landblock_018a(s):
        """The scene moved whole to landblock 0x018A (its landblocks, mover, statics and RequestPos
        keep their places relative to each other), where UpdateObjectInternalServer answers false
        unless CurCell is in the RequestPos's landblock: a mover a transition left in no cell
        stays there, and its next tick's transition has no begin cell."""
        b = s.mover.begin.cell
        shift = ((0x01 - (b >> 24)) << 24) + ((0x8A - (b >> 16 & 0xFF)) << 16)

        def cell(c: int) -> int:
            return (c + shift) & 0xFFFFFFFF

        def pos(p):
            return p and replace(p, cell=cell(p.cell))
        m = s.mover
        mover = replace(m, begin=pos(m.begin), end=pos(m.end),
                        contact_plane=m.contact_plane and replace(m.contact_plane, cell=cell(m.contact_plane.cell)))
        steps = tuple(replace(st, request_pos=pos(st.request_pos)) for st in s.ticks.steps)
        return replace(s, mover=mover, landblocks=tuple(replace(lb, id=cell(lb.id)) for lb in s.landblocks),
                       objects=tuple(replace(o, position=pos(o.position)) for o in s.objects),
                       env_cells=tuple(replace(c, id=cell(c.id)) for c in s.env_cells),
                       buildings=tuple(replace(b, landblock=cell(b.landblock)) for b in s.buildings),
                       ticks=replace(s.ticks, steps=steps))

    return [
        ("particle_statics", "statics", statics_state(PE)),
        ("particle_statics_ticks", "tick_statics", statics_state(PE)),
        ("particle_mover_placement", "placement", mover_state(PE)),
        ("particle_mover_ticks", "ticks", mover_state(PE)),
        ("static_far_off", "statics", first_static_moved(50000.0)),
        ("static_next_block", "statics", first_static_moved(192.0)),
        ("second_indoor_static", "indoor_statics", second_indoor_static),
        ("static_in_each_cell", "indoor_statics", static_in_each_cell),
        ("unnormalized_mover", "ticks", unnormalized_mover),
        ("unnormalized_mover_indoor", "request_pos_indoor", unnormalized_mover),
        ("unnormalized_mover_018a", "request_pos_indoor", lambda s: unnormalized_mover(in_landblock_018a(s))),
        # a mover in Contact and StationaryStuck (FramesStationaryFall 3 from the start): the
        # stationary fall's contact plane set without a collision normal
        ("contact_stationary_stuck", "gravity_moves", mover_transient(T.Contact | T.StationaryStuck)),
    ]


def main(argv=None) -> int:
    from acconform.flags import PhysicsState as P

    from tick_variant_scenes import VARIANT_SHARDS as TICK_SHARDS
    from transition_variant_scenes import VARIANT_SHARDS as TRANSITION_SHARDS

    a = arguments(__doc__, 20, 2426, argv)
    # the drawn records, not the variants of them written before
    scenes = drawn_records(lambda where: True, VARIANT_SHARDS + TICK_SHARDS + TRANSITION_SHARDS)
    ticks = [(k, s) for k, s in scenes if s.ticks is not None]
    moves = [(k, s) for k, s in scenes if s.ticks is None]
    outdoor_statics = lambda s: s.objects and all(o.position.cell & 0xFFFF < 0x100 for o in s.objects) and not s.env_cells
    pools = {
        # an EnvCell's statics are DAT stabs, which carry no state: the state variants are outdoors
        "statics": [(k, s) for k, s in moves if outdoor_statics(s) and s.mover.placement is None],
        "placement": [(k, s) for k, s in moves if s.mover.placement is not None],
        "ticks": ticks,
        "tick_statics": [(k, s) for k, s in ticks if outdoor_statics(s)],
        "request_pos_indoor": [(k, s) for k, s in ticks if s.ticks.driver == "request_pos"
                               and any(st.request_pos.cell & 0xFFFF >= 0x100 for st in s.ticks.steps)],
        "gravity_moves": [(k, s) for k, s in moves if s.mover.placement is None and s.mover.state & P.Gravity],
        "indoor_statics": [(k, s) for k, s in moves if any(o.position.cell & 0xFFFF >= 0x100 for o in s.objects)],
    }
    written = write_variants(a, variants(), pools)
    print(f"{written} scenes in {a.out} ({', '.join(f'{len(p)} {k}' for k, p in pools.items())} records)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
