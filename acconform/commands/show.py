"""acconform show FILE: a scene, case, record or outcome (or each record of a corpus shard), printed for a person to read."""

from __future__ import annotations


def add_arguments(p) -> None:
    p.add_argument("file", metavar="FILE", help="a scene, case, record or outcome file, or a corpus shard (.jsonl.gz)")


def run(args) -> int:
    from ..case import is_lines_file, iter_documents

    for i, (where, doc) in enumerate(iter_documents(args.file)):
        if is_lines_file(args.file):
            print(("\n" if i else "") + f"# {where}")
        for line in describe(doc):
            print(line)
    return 0


def _v(v) -> str:
    return "(" + ", ".join(f"{float(c):.9g}" for c in v) + ")"


def _id(n: int) -> str:
    return f"0x{n:08X}"


def describe_scene(scene) -> list[str]:
    from ..flags import PhysicsState, TransientState, flag_names
    from ..strategies.terrain import is_water_word

    out = [f"scene {scene.name!r}" if scene.name else "scene", f"  engine: {scene.engine_mode}"]
    table = scene.land_height_table
    for lb in scene.landblocks:
        if not lb.has_terrain:
            out.append(f"  landblock {_id(lb.id)}: no terrain")
            continue
        zs = [table[h] for h in lb.heights]
        water = sum(is_water_word(t) for t in lb.terrain)
        out.append(f"  landblock {_id(lb.id)}: heights {min(zs):g}..{max(zs):g} m, {water} water vertices")
    for env in scene.environments:
        out.append(f"  environment {_id(env.id)}: {len(env.cell_structs)} cell structures")
    for c in scene.env_cells:
        portals = ", ".join(f"0x{p.other_cell:04X}" for p in c.portals) or "none"
        out.append(f"  EnvCell {_id(c.id)} at {_v(c.frame.origin)} rot {_v(c.frame.orientation)}: structure "
                   f"{c.cell_structure} of {_id(c.environment)}, portals to {portals}, "
                   f"{len(c.visible_cells)} visible cells{', seen outside' if c.seen_outside else ''}")
    for o in scene.objects:
        s = o.shape
        if o.setup is not None:
            u = o.setup
            what = (f"setup of {len(u.parts)} BSP parts ({sum(len(p.shape.polygons) for p in u.parts)} polygons), "
                    f"{len(u.spheres)} spheres, {len(u.cylspheres)} cylspheres")
        elif s.kind == "bsp":
            what = f"bsp, {len(s.polygons)} polygons, bounding sphere r={s.sphere.radius:.6g}"
        elif s.kind == "sphere":
            what = f"sphere r={s.sphere.radius:.6g} at {_v(s.sphere.center)}"
        else:
            what = f"cylsphere r={s.radius:.6g} h={s.height:.6g}"
        out.append(f"  object {_id(o.id)} in {_id(o.position.cell)} at {_v(o.position.frame.origin)} "
                   f"rot {_v(o.position.frame.orientation)}: {what}")
    m = scene.mover
    out.append("  mover:")
    out.append("    spheres: " + ", ".join(f"r={s.radius:.6g} at {_v(s.center)}" for s in m.spheres)
               + (f", scale {m.scale:g}" if m.scale != 1.0 else ""))
    out.append(f"    step up {m.step_up_height:.9g}, step down {m.step_down_height:.9g}")
    out.append(f"    state {'|'.join(flag_names(PhysicsState, m.state)) or '0'}; "
               f"transient {'|'.join(flag_names(TransientState, m.transient_state)) or '0'}")
    out.append(f"    begin {_id(m.begin.cell)} {_v(m.begin.frame.origin)}")
    if m.placement is not None:
        from ..flags import SetPositionFlags

        out.append(f"    placed there first by ACE's SetPosition: flags {'|'.join(flag_names(SetPositionFlags, m.placement.flags)) or 'none'}"
                   + (", cell id by Position.GetCell" if m.placement.get_cell else ""))
    if m.end is not None:
        out.append(f"    end   {_id(m.end.cell)} {_v(m.end.frame.origin)}")
    if m.contact_plane is not None:
        cp = m.contact_plane
        out.append(f"    contact plane {_id(cp.cell)} n={_v(cp.plane.normal)} d={cp.plane.d:.9g}"
                   + (" (water)" if m.transient_state & TransientState.WaterContact else ""))
    if any(v != 0 for v in m.velocity):
        out.append(f"    velocity {_v(m.velocity)}")
    if scene.ticks is not None:
        out += describe_ticks(scene.ticks)
    return out


def describe_ticks(ticks) -> list[str]:
    """A tick scene's timeline: the driver, the clock, and each step with its inputs (a step the same as the
    step before, dt and inputs, is counted, not listed)."""
    from ..flags import PhysicsState, TransientState, flag_names
    from ..scene import TICK_INPUTS

    out = [f"  ticks: {len(ticks.steps)} by {ticks.driver}, clock from {ticks.start!r} to {ticks.times()[-1]!r}"]
    quiet, last = 0, None
    for i, step in enumerate(ticks.steps):
        inputs = []
        for name in TICK_INPUTS:
            v = getattr(step, name)
            if v is None:
                continue
            if name == "state":
                v = "|".join(flag_names(PhysicsState, v)) or "0"
            elif name == "transient_state":
                v = "|".join(flag_names(TransientState, v)) or "0"
            elif name == "request_pos":
                v = f"{_id(v.cell)} {_v(v.frame.origin)}"
            elif name == "door":
                v = f"{_id(v.object)} {'opens (ethereal)' if v.ethereal else 'closes'}"
            elif hasattr(v, "to_json"):  # the motion layer's inputs
                from ..codec import dumps_compact

                v = dumps_compact(v.to_json())
            elif isinstance(v, str):
                pass
            else:
                v = _v(v)
            inputs.append(f"{name} {v}")
        line = f"dt {step.dt!r}" + ("; " + "; ".join(inputs) if inputs else "")
        if line == last and "request_pos" not in line:
            quiet += 1
            continue
        if quiet:
            out.append(f"    ... {quiet} more step{'s' if quiet != 1 else ''} the same")
            quiet = 0
        out.append(f"    step {i}: {line}")
        last = line
    if quiet:
        out.append(f"    ... {quiet} more step{'s' if quiet != 1 else ''} the same")
    return out


def describe_outcome(o, label: str = "outcome") -> list[str]:
    from ..flags import ObjectInfoState, flag_names

    if o.error is not None:
        return [f"{label}: error {o.error}"]
    if o.ticks is not None:
        return describe_tick_outcome(o, label)
    cp = o.contact_plane
    placed = []
    if o.placement is not None:
        from ..flags import SetPositionError, TransientState

        p = o.placement
        placed = [f"{label} of the placement: {SetPositionError(p.result).name}, position {_id(p.cell)} {_v(p.origin)}, "
                  f"CurCell {_id(p.cur_cell) if p.cur_cell else 'none'}, "
                  f"transient {'|'.join(flag_names(TransientState, p.transient_state)) or '0'}, "
                  f"shadows in {', '.join(_id(c) for c in p.shadow_cells) or 'no cell'}"]
    return placed + [
        f"{label}: ok={o.ok} cell {_id(o.cell)} origin {_v(o.origin)}",
        f"  state {'|'.join(flag_names(ObjectInfoState, o.object_info_state)) or '0'}; "
        f"contact plane {'valid' if cp.valid else 'invalid'} {_id(cp.cell)} n={_v(cp.normal)} d={cp.d:.9g}",
        f"  collision normal {'valid' if o.collision_normal.valid else 'invalid'} {_v(o.collision_normal.vector)}; "
        f"sliding normal {'valid' if o.sliding_normal.valid else 'invalid'} {_v(o.sliding_normal.vector)}",
        f"  walkable={o.walkable} step_up={o.step_up} neg_poly_hit={o.neg_poly_hit} "
        f"collided_with_environment={o.collided_with_environment} frames_stationary_fall={o.frames_stationary_fall}",
    ]


def describe_tick_outcome(o, label: str) -> list[str]:
    """A tick scene's outcome: one line per tick (the mover after it), the placement first."""
    from ..flags import SetPositionError, TransientState, flag_names

    out = []
    if o.placement is not None:
        p = o.placement
        out.append(f"{label} of the placement: {SetPositionError(p.result).name}, position {_id(p.cell)} {_v(p.origin)}")
    out.append(f"{label}: {len(o.ticks)} ticks")
    for i, t in enumerate(o.ticks):
        if t.error is not None:
            out.append(f"  tick {i}: error {t.error}")
            continue
        out.append(f"  tick {i}: {'updated' if t.updated else 'not updated'} at {t.update_time!r}, {_id(t.cell)} "
                   f"{_v(t.origin)} v={_v(t.velocity)} a={_v(t.acceleration)} cached={_v(t.cached_velocity)} "
                   f"{'|'.join(flag_names(TransientState, t.transient_state)) or '0'}"
                   + (" jumped" if t.jumped_this_frame else ""))
    return out


def describe(doc) -> list[str]:
    from ..case import Case, Record
    from ..outcome import Outcome
    from ..scene import Scene

    if isinstance(doc, Scene):
        return describe_scene(doc)
    if isinstance(doc, Outcome):
        return describe_outcome(doc)
    if isinstance(doc, Record):
        v = doc.versions
        return describe_scene(doc.scene) + [f"recorded from ACE {v.ace or '?'} on {v.runtime or '?'}"] + describe_outcome(doc.outcome, "ACE")
    assert isinstance(doc, Case)
    v = doc.versions
    out = [f"case: mode {doc.mode}, seed {doc.seed or '?'}, acconform {v.acconform or '?'}, ACE {v.ace or '?'} on {v.runtime or '?'}"]
    from ..runner import tested_label

    tested = tested_label(doc.implementation)  # "impl" for an implementation under test, else "port"
    if doc.scene.ticks is not None:
        from ..compare import compare, first_tick_difference

        first = first_tick_difference(compare(doc.port, doc.oracle, doc.mode))
        if first is not None:
            tick = first.field.split("]", 1)[0].split("[", 1)[1]
            out.append(f"first differing tick: {tick} of {len(doc.scene.ticks.steps)}: {first.render(tested)}")
    from .check import shrink_label

    impl = doc.implementation
    if impl is not None:
        out.append(f"made by implementation {impl.handshake.get('name', '')!r}: {impl.command}"
                   + (f" (in {impl.cwd})" if impl.cwd else ""))
        if impl.stderr:
            out.append(f"its stderr ({len(impl.stderr)} characters):")
            out += [f"  | {line}" for line in impl.stderr.splitlines()]
    out.append(shrink_label(doc.shrink))
    out.append(f"{len(doc.differences)} difference{'s' if len(doc.differences) != 1 else ''}:")
    out += [f"  {d}" for d in doc.differences]
    return out + describe_scene(doc.scene) + describe_outcome(doc.port, tested) + describe_outcome(doc.oracle, "oracle")
