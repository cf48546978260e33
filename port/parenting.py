"""The harness's parenting call: a child PhysicsObj held by a parent (a mover) at a holding location.

ACE's server never parents one PhysicsObj to another: a wielded item gets only the WorldObject
properties Placement, ParentLocation and Location (WorldObjects/Creature_Equipment.cs TrySetChild /
GetPlacementLocation), which CreateObject sends to the client, and the client parents the item's
physics object (retail's CPhysicsObj::set_parent(parent, location) with the placement frame). The
one set_parent call in ACE's server, ParticleEmitter.SetParenting, has no caller. The harness makes
the client's calls on ACE's own PhysicsObj (oracle/facade/Facade.cs: `SetParent`, called by EnterOthers for a scene's child) and on the
port's, the same ones in the same order: the child's placement frame (SetPlacementFrame), then
set_parent at the location. From then on the parent carries the child: every set_frame of the
parent (its own, SetPositionInternal's, add_obj_to_cell's, a tick's) runs UpdateChildrenInternal.

What a child needs: its own Setup (any; its placement frames if `placement` should choose one), and
a parent whose Setup has a HoldingLocation keyed `parent_location` (ParentLocation: RightHand 1,
LeftHand 2, Shield 3, ... ACE.Entity.Enum.ParentLocation) naming a part and a frame in that part
(a part id at or past the Setup's parts: the frame is in the parent's Position).
"""

from __future__ import annotations

from .anchors import harness
from .frame import AFrame
from .physics_obj import PhysicsObj


@harness("a child held by a parent at a holding location, as the client parents a wielded item (the oracle's facade SetParent)")
def set_parent(child: PhysicsObj, parent: PhysicsObj, parent_location: int, placement: int, lscape) -> bool:
    """``child.SetPlacementFrame(placement, false)`` then ``child.set_parent(parent, parent_location)``;
    returns set_parent's answer (False: the parent has no PartArray, no such holding location, or is
    the child). `lscape` is the run's world (ACE's static LScape)."""
    child.set_placement_frame(placement, False)
    return child.set_parent(parent, parent_location, lscape)


@harness("a child held as its scene says: at a location, or by the frame form (the oracle's facade HoldChild)")
def hold_child(child: PhysicsObj, parent: PhysicsObj, of, lscape) -> bool:
    """`of`: a scene ChildOf. At a location: `set_parent` above; with `part` and `frame`: ACE's
    ``set_parent(parent, partIdx, frame)`` (the client's call for an object attached to a part,
    ParticleEmitter.SetParenting) with a new AFrame of the scene's frame, no placement frame."""
    if of.part is not None:
        return child.set_parent_frame(parent, of.part, AFrame.from_record(of.frame, lscape.mode), lscape)
    return set_parent(child, parent, of.location, of.placement, lscape)


@harness("a held item moved by the server, as the client handles it (the oracle's facade ApplyOtherInputs' last inputs)")
def apply_parenting_inputs(child: PhysicsObj, inputs, holders: dict, lscape) -> None:
    """A tick's children inputs (scene/8 ticks.steps[].others[]): `unparent`, a PickupEvent's
    ``child.unset_parent()``; then `parent`, a ParentEvent's SetPlacementFrame and set_parent at the
    holder's location, or the frame form (`hold_child`; its answer is not kept: the child's state says it). `holders`:
    id -> PhysicsObj (the mover and the others)."""
    if inputs.unparent:
        child.unset_parent()
    if inputs.parent is not None:
        hold_child(child, holders[inputs.parent.id], inputs.parent, lscape)
