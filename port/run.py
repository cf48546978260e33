"""run_scene: one scene through the port's PhysicsObj.transition, read back as an Outcome.

The world (LScape) and the mover (PhysicsObj) are built from the scene the way the oracle builds
ACE's; the outcome reads the same fields the oracle reads. A Python exception inside the port
becomes ``Outcome(error=...)``: a verdict, not a crash. An AceException (port/errors.py: where
ACE itself throws) reads ``"<.NET type>: <message>"``, as the oracle formats ACE's exceptions.
Static objects are built and registered as the oracle builds them (the conventions are
acconform.staging: shadow_cells, mover_setup_dims, MOVER_ID). Pass a ``collections.Counter`` as
`trace` to count the branches the run took (names in acconform.port.transition.branches).
"""

from __future__ import annotations

import numpy as np

from acconform.numerics import Plane, get_mode
from acconform.outcome import ContactPlaneState, NormalState, Outcome
from acconform.staging import MOVER_ID, mover_setup_dims, shadow_cells
from acconform.scene import CylSphereShape, Scene, SphereShape, StaticObject

from .anchors import anchor, harness
from .errors import AceException
from .frame import Position
from .geom.cyl_sphere import CylSphere
from .geom.sphere import Sphere
from .gfx_obj import GfxObj
from .land.lscape import LScape
from .part_array import PartArray, PhysicsPart
from .physics_obj import PhysicsObj
from .setup import Setup
from . import transition as _transition  # noqa: F401  (gives LandCell its collision methods)

# the mover's PhysicsObj.ID, as the oracle's: player range, so PhysicsObj.IsPlayer is true


def _vec(v) -> tuple[float, float, float]:
    return (float(v.x), float(v.y), float(v.z))


def _plane_state(valid: bool, cell: int, is_water: bool, plane: Plane) -> ContactPlaneState:
    return ContactPlaneState(bool(valid), int(cell), bool(is_water), _vec(plane.normal), float(plane.d))


@harness("builds the mover's PhysicsObj from the scene, as the oracle builds ACE's")
def build_mover(scene: Scene, lscape: LScape) -> PhysicsObj:
    """The mover as the oracle builds it: a PhysicsObj with a PartArray over a Setup of its spheres,
    Height/Radius (staging.mover_setup_dims) and step heights; SetScaleStatic; flags, velocity,
    contact plane, sliding normal, position and cell."""
    mode = lscape.mode
    m = scene.mover
    s = mode.scalar
    if m.contact_plane is not None:
        contact_plane = Plane(mode.vec(*m.contact_plane.plane.normal), s(m.contact_plane.plane.d))
        contact_cell = m.contact_plane.cell
    else:
        contact_plane = Plane(mode.vec(0, 0, 0), s(0.0))
        contact_cell = 0
    height, radius = mover_setup_dims(scene)
    obj = PhysicsObj(id=MOVER_ID, state=0, position=None)
    setup = Setup.create([Sphere(mode.vec(*sp.center), s(sp.radius)) for sp in m.spheres], [], s(height), s(radius),
                         s(m.step_up_height), s(m.step_down_height))
    obj.part_array = PartArray(owner=obj, setup=setup, num_parts=0, parts=[], scale=mode.vec(1, 1, 1))
    obj.set_scale_static(s(m.scale))
    obj.state = m.state
    obj.transient_state = m.transient_state
    obj.velocity = mode.vec(*m.velocity)
    obj.contact_plane = contact_plane
    obj.contact_plane_cell_id = contact_cell
    obj.sliding_normal = mode.vec(*(m.sliding_normal or (0.0, 0.0, 0.0)))
    obj.position = Position.from_record(m.begin, mode)
    obj.cur_cell = lscape.get_landcell(m.begin.cell)
    return obj


@harness("builds a static object's PhysicsObj from a scene record, as the oracle's Facade.BuildStatic")
def build_static(record: StaticObject, landblock_ids: list[int], lscape: LScape) -> PhysicsObj:
    """A scene StaticObject as the oracle builds it (Facade.cs BuildStatic): a PhysicsObj whose
    PartArray's Setup holds the sphere or cylsphere; a BSP shape is one PhysicsPart (GfxObj with
    PhysicsBSP and PhysicsSphere, Pos = the object's position). State is the scene's flags as
    given (the oracle sets State directly; ACE's makeObject would also CacheHasPhysicsBSP).
    Registered as a shadow object in `shadow_cells`' cells, in that order."""
    mode = lscape.mode
    s = mode.scalar
    obj = PhysicsObj(id=record.id, state=0, position=None)
    shape = record.shape
    spheres, cyl_spheres, gfx = [], [], None
    if isinstance(shape, SphereShape):
        spheres.append(Sphere.from_rec(shape.sphere, mode))
    elif isinstance(shape, CylSphereShape):
        cyl_spheres.append(CylSphere.from_rec(shape, mode))
    else:
        gfx = GfxObj.from_shape(shape, mode)
    setup = Setup.create(spheres, cyl_spheres, s(0.0), s(0.0), s(0.0), s(0.0))
    obj.part_array = PartArray(owner=obj, setup=setup, num_parts=0, parts=[], scale=mode.vec(1, 1, 1))
    pos = Position.from_record(record.position, mode)
    if gfx is not None:
        part = PhysicsPart(gfx_obj=gfx, gfx_obj_scale=mode.vec(1, 1, 1), physics_obj=obj, pos=pos.copy())
        obj.part_array.parts.append(part)
        obj.part_array.num_parts = 1
    obj.state = record.state
    obj.position = pos.copy()
    obj.set_scale_static(s(record.scale))
    for k, cell_id in enumerate(shadow_cells(record, landblock_ids)):
        cell = lscape.get_landcell(cell_id)
        if k == 0:
            obj.cur_cell = cell
        obj.add_shadows_to_cell(cell)
    return obj


@anchor(None, "PhysicsObj.cs:transition", "the scene -> outcome driver around PhysicsObj.transition")
def run_scene(scene: Scene, mode: str = "exact", trace=None, runtime: str = "mono") -> Outcome:
    """Run the scene's transition in the port, computing as ACE on `runtime` ("mono" or "coreclr",
    .NET 10) does; `trace` (a Counter) is incremented in place."""
    numerics = get_mode(mode, runtime)  # an unknown mode or runtime is misuse, not a verdict
    try:
        with np.errstate(all="ignore"):  # IEEE results (inf, NaN) are C#'s too; no warnings
            return _run(scene, numerics, trace)
    except AceException as e:  # where ACE throws: its .NET type, as the oracle reports ACE's
        return Outcome(error=e.verdict())
    except Exception as e:  # any other port exception is a verdict too (a port bug or gap)
        return Outcome(error=f"{type(e).__name__}: {e}")


def _run(scene: Scene, mode, trace) -> Outcome:
    lscape = LScape(scene, mode)
    try:
        return _run_in(scene, mode, trace, lscape)
    finally:
        lscape.release()


def _run_in(scene: Scene, mode, trace, lscape: LScape) -> Outcome:
    landblock_ids = [lb.id for lb in scene.landblocks]
    for record in scene.objects:
        build_static(record, landblock_ids, lscape)
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
