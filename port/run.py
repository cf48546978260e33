"""run_scene: one scene through the port's PhysicsObj.transition, read back as an Outcome.

The world (LScape) and the mover (PhysicsObj) are built from the scene the way the oracle builds
ACE's; the outcome reads the same fields the oracle reads. A Python exception inside the port
becomes ``Outcome(error=...)``: a verdict, not a crash. Pass a ``collections.Counter`` as
`trace` to count the branches the run took (names in acconform.port.transition.branches).
"""

from __future__ import annotations

import numpy as np

from acconform.numerics import Plane, get_mode
from acconform.outcome import ContactPlaneState, NormalState, Outcome
from acconform.scene import Scene

from .anchors import anchor
from .frame import Position
from .geom.sphere import Sphere
from .land.lscape import LScape
from .physics_obj import PhysicsObj
from . import transition as _transition  # noqa: F401  (gives LandCell its collision methods)

# the id the mover gets (ACE's PhysicsObj.ID; only compared for equality with static objects)
MOVER_ID = 0x50000001


def _vec(v) -> tuple[float, float, float]:
    return (float(v.x), float(v.y), float(v.z))


def _plane_state(valid: bool, cell: int, is_water: bool, plane: Plane) -> ContactPlaneState:
    return ContactPlaneState(bool(valid), int(cell), bool(is_water), _vec(plane.normal), float(plane.d))


def build_mover(scene: Scene, lscape: LScape) -> PhysicsObj:
    """The mover as a PhysicsObj: Setup spheres and step heights, flags, contact plane, velocity."""
    mode = lscape.mode
    m = scene.mover
    s = mode.scalar
    if m.contact_plane is not None:
        contact_plane = Plane(mode.vec(*m.contact_plane.plane.normal), s(m.contact_plane.plane.d))
        contact_cell = m.contact_plane.cell
    else:
        contact_plane = Plane(mode.vec(0, 0, 0), s(0.0))
        contact_cell = 0
    position = Position.from_record(m.begin, mode)
    return PhysicsObj(
        id=MOVER_ID,
        state=m.state,
        position=position,
        cur_cell=lscape.get_landcell(m.begin.cell),
        transient_state=m.transient_state,
        velocity=mode.vec(*m.velocity),
        contact_plane=contact_plane,
        contact_plane_cell_id=contact_cell,
        sliding_normal=mode.vec(*(m.sliding_normal or (0.0, 0.0, 0.0))),
        scale=s(m.scale),
        spheres=[Sphere(mode.vec(*sp.center), s(sp.radius)) for sp in m.spheres],
        setup_step_up_height=s(m.step_up_height),
        setup_step_down_height=s(m.step_down_height),
    )


@anchor(None, "PhysicsObj.cs:transition", "the scene -> outcome driver around PhysicsObj.transition")
def run_scene(scene: Scene, mode: str = "exact", trace=None) -> Outcome:
    """Run the scene's transition in the port; `trace` (a Counter) is incremented in place."""
    try:
        with np.errstate(all="ignore"):  # IEEE results (inf, NaN) are C#'s too; no warnings
            return _run(scene, get_mode(mode), trace)
    except Exception as e:  # a port exception is a verdict
        return Outcome(error=f"{type(e).__name__}: {e}")


def _run(scene: Scene, mode, trace) -> Outcome:
    if scene.objects:
        raise NotImplementedError("static objects in scenes are not ported yet")
    lscape = LScape(scene, mode)
    mover = build_mover(scene, lscape)
    old_pos = mover.position.copy()
    new_pos = Position.from_record(scene.mover.end, mode)
    trans, ok = mover.transition(old_pos, new_pos, False, lscape, trace)

    sp = trans.sphere_path
    ci = trans.collision_info
    q = sp.cur_pos.frame.orientation
    return Outcome(
        ok=bool(ok),
        cell=sp.cur_cell.id if sp.cur_cell is not None else 0,
        origin=_vec(sp.cur_pos.frame.origin),
        orientation=(float(q.w), float(q.x), float(q.y), float(q.z)),
        object_info_state=int(trans.object_info.state),
        contact_plane=_plane_state(ci.contact_plane_valid, ci.contact_plane_cell_id, ci.contact_plane_is_water,
                                   ci.contact_plane),
        last_known_contact_plane=_plane_state(ci.last_known_contact_plane_valid, ci.last_known_contact_plane_cell_id,
                                              ci.last_known_contact_plane_is_water, ci.last_known_contact_plane),
        collision_normal=NormalState(bool(ci.collision_normal_valid), _vec(ci.collision_normal)),
        sliding_normal=NormalState(bool(ci.sliding_normal_valid), _vec(ci.sliding_normal)),
        collided_with_environment=bool(ci.collided_with_environment),
        frames_stationary_fall=int(ci.frames_stationary_fall),
        velocity=_vec(mover.velocity),
        check_cell=sp.check_cell.id if sp.check_cell is not None else 0,
        walkable=sp.walkable is not None,
        step_up=bool(sp.step_up),
        neg_poly_hit=bool(sp.neg_poly_hit),
    )
