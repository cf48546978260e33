"""Scene -> packed bytes for the facade, packed bytes -> Outcome. Pure Python (no .NET).

The layout is read by oracle/facade/Facade.cs (BuildScene / WriteOutcome); both sides change
together and carry PACK_VERSION. All floats travel as float32, so the facade sees exactly the
scene's values. The conventions both sides apply when staging a scene live in acconform.staging.
"""

from __future__ import annotations

import struct

from ..flags import TransientState
from ..outcome import ContactPlaneState, NormalState, Outcome
from ..scene import BSPLeaf, CylSphereShape, Landblock, Scene, SphereShape
from ..staging import mover_setup_dims, shadow_cells

PACK_VERSION = 1
SHAPE_KIND = {"sphere": 0, "cylsphere": 1, "bsp": 2}

_f = struct.Struct("<f")
_4f = struct.Struct("<4f")
_3f = struct.Struct("<3f")


def landblock_bytes(lb: Landblock) -> bytes:
    """The CellLandblock DAT layout: Id, HasObjects 0, 81 terrain words, 81 heights, 4-byte aligned."""
    b = struct.pack("<II", lb.id | 0xFFFF, 0) + struct.pack("<81H", *lb.terrain) + bytes(lb.heights)
    return b + b"\0" * ((4 - len(b) % 4) % 4)


def _pos(p) -> bytes:
    return struct.pack("<I", p.cell) + _3f.pack(*p.frame.origin) + _4f.pack(*p.frame.orientation)


def _node(n, out: list) -> None:
    if isinstance(n, BSPLeaf):
        out.append(struct.pack("<BB", 0, 1 if n.solid else 0))
        out.append(_3f.pack(*n.sphere.center) + _f.pack(n.sphere.radius))
        out.append(struct.pack(f"<i{len(n.polygons)}i", len(n.polygons), *n.polygons))
    else:
        out.append(b"\x01" + _3f.pack(*n.plane.normal) + _f.pack(n.plane.d))
        out.append(_3f.pack(*n.sphere.center) + _f.pack(n.sphere.radius))
        _node(n.front, out)
        _node(n.back, out)


def pack_scene(scene: Scene) -> bytes:
    out = [struct.pack("<iB", PACK_VERSION, 1 if scene.engine_mode == "server" else 0),
           struct.pack("<256f", *scene.land_height_table),
           struct.pack("<i", len(scene.landblocks))]
    for lb in scene.landblocks:
        b = landblock_bytes(lb)
        out.append(struct.pack("<i", len(b)) + b)
    ids = [lb.id for lb in scene.landblocks]
    out.append(struct.pack("<i", len(scene.objects)))
    for o in scene.objects:
        out.append(struct.pack("<I", o.id) + _pos(o.position) + struct.pack("<IfB", o.state, o.scale, SHAPE_KIND[o.shape.kind]))
        s = o.shape
        if isinstance(s, SphereShape):
            out.append(_3f.pack(*s.sphere.center) + _f.pack(s.sphere.radius))
        elif isinstance(s, CylSphereShape):
            out.append(_3f.pack(*s.low_point) + struct.pack("<ff", s.radius, s.height))
        else:
            out.append(struct.pack("<i", len(s.polygons)))
            for p in s.polygons:
                out.append(struct.pack("<ii", p.sides_type, len(p.vertices)))
                out.extend(_3f.pack(*v) for v in p.vertices)
            _node(s.root, out)
            out.append(_3f.pack(*s.sphere.center) + _f.pack(s.sphere.radius))
        cells = shadow_cells(o, ids)
        out.append(struct.pack(f"<i{len(cells)}I", len(cells), *cells))
    m = scene.mover
    out.append(struct.pack("<i", len(m.spheres)))
    out.extend(_3f.pack(*s.center) + _f.pack(s.radius) for s in m.spheres)
    height, radius = mover_setup_dims(scene)
    out.append(struct.pack("<5f", height, radius, m.step_up_height, m.step_down_height, m.scale))
    out.append(struct.pack("<II", m.state, m.transient_state) + _3f.pack(*m.velocity))
    cp = m.contact_plane
    if cp is None:
        out.append(struct.pack("<BI4f", 0, 0, 0, 0, 0, 0))
    else:
        out.append(struct.pack("<BI", 1, cp.cell) + _3f.pack(*cp.plane.normal) + _f.pack(cp.plane.d))
    sn = m.sliding_normal
    out.append(struct.pack("<B", 0) + _3f.pack(0, 0, 0) if sn is None else struct.pack("<B", 1) + _3f.pack(*sn))
    out.append(_pos(m.begin) + _pos(m.end))
    return b"".join(out)


_OUT = struct.Struct("<BI3f4fI" + "BIB3ff" * 2 + "B3f" * 2 + "Bi3fIBBBd")


def unpack_outcome(data: bytes) -> tuple[Outcome, float, float]:
    """(Outcome, ACE's in-runtime FindValidPosition time, the facade's whole-case time), times in
    microseconds, from the facade's bytes."""
    if data[0] == 0xEE:
        (n,) = struct.unpack_from("<i", data, 1)
        msg = data[5:5 + n].decode("utf-8", "replace")
        us, case_us = struct.unpack_from("<dd", data, 5 + n)
        return Outcome(error=msg), us, case_us
    if data[0] != 1:
        raise ValueError(f"unknown outcome tag {data[0]}")
    v = _OUT.unpack_from(data, 1)
    (ok, cell, ox, oy, oz, qw, qx, qy, qz, ois,
     cpv, cpc, cpw, cpx, cpy, cpz, cpd,
     lkv, lkc, lkw, lkx, lky, lkz, lkd,
     cnv, cnx, cny, cnz, snv, snx, sny, snz,
     cwe, fsf, vx, vy, vz, chk, walk, stepup, neg, us) = v
    (case_us,) = struct.unpack_from("<d", data, 1 + _OUT.size)
    return Outcome(
        ok=bool(ok), cell=cell, origin=(ox, oy, oz), orientation=(qw, qx, qy, qz), object_info_state=ois,
        contact_plane=ContactPlaneState(bool(cpv), cpc, bool(cpw), (cpx, cpy, cpz), cpd),
        last_known_contact_plane=ContactPlaneState(bool(lkv), lkc, bool(lkw), (lkx, lky, lkz), lkd),
        collision_normal=NormalState(bool(cnv), (cnx, cny, cnz)),
        sliding_normal=NormalState(bool(snv), (snx, sny, snz)),
        collided_with_environment=bool(cwe), frames_stationary_fall=fsf, velocity=(vx, vy, vz),
        check_cell=chk, walkable=bool(walk), step_up=bool(stepup), neg_poly_hit=bool(neg)), us, case_us


def frames_stationary_fall(transient_state: int) -> int:
    """PhysicsObj.transition's seeding of CollisionInfo.FramesStationaryFall."""
    if transient_state & TransientState.StationaryStuck:
        return 3
    if transient_state & TransientState.StationaryStop:
        return 2
    if transient_state & TransientState.StationaryFall:
        return 1
    return 0
