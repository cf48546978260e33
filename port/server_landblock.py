"""Landblock (ACE.Server.Entity.Landblock): the server landblock a launched projectile joins -- AddWorldObjectInternal's bookkeeping, RemoveWorldObject, GetObject.

Harness glue around ACE's physics, as the oracle's stand-in Landblock has it: a landblock holds its
WorldObjects in worldObjects (after its next tick's ProcessPendingWorldObjectAdditionsAndRemovals, which each
scene tick runs before its physics, as Landblock.TickPhysics does) or pendingAdditions (added since: a launch, or
a relocation after the tick's physics). RemoveWorldObject(Internal) is ACE's as far as the physics reaches: the object found
in neither table is left alone (a warning); found, it leaves the table, its CurrentLandblock is
cleared and its PhysicsObj destroyed (DestroyObject). GetObject answers null, as the stand-in's does
(no scene's WeenieObject.DoCollisionEnd finds its target).
"""

from __future__ import annotations

from .anchors import harness


class Landblock:
    """A server landblock: its id and the two tables (worldObjects and pendingRemovals are .NET collections
    in ACE; the order is never read here)."""

    __slots__ = ("id", "world_objects", "pending_additions", "pending_removals")

    def __init__(self, landblock_id: int):
        self.id = landblock_id
        self.world_objects: dict = {}
        self.pending_additions: dict = {}
        self.pending_removals: list = []

    @harness("Landblock.ProcessPendingWorldObjectAdditionsAndRemovals' tables: pending additions into worldObjects, pending removals out")
    def process_pending_world_object_additions_and_removals(self) -> None:
        """TickPhysics' first step (ACE's private method, which the stand-in lacks: the facade writes it so too). Its
        players, creature, heartbeat and generator lists and the KeepAlive weenie are no physics."""
        if self.pending_additions:
            for key, value in self.pending_additions.items():
                self.world_objects[key] = value
            self.pending_additions.clear()

        if self.pending_removals:
            for object_guid in self.pending_removals:
                self.world_objects.pop(object_guid, None)
            self.pending_removals.clear()

    @harness("Landblock.AddWorldObjectInternal's last step for an object that entered: pendingAdditions[wo.Guid] = wo")
    def add_pending(self, wo) -> None:
        self.pending_additions[wo.guid] = wo

    @harness("Landblock.RemoveWorldObject -> RemoveWorldObjectInternal's physics: CurrentLandblock = null, DestroyObject")
    def remove_world_object(self, object_id: int, adjacency_move: bool = False, from_pickup: bool = False,
                            show_error: bool = True) -> None:
        wo = self.world_objects.get(object_id)
        if wo is not None:
            self.pending_removals.append(object_id)
        else:
            wo = self.pending_additions.pop(object_id, None)
            if wo is None:
                # log.Warn($"RemoveWorldObjectInternal: Couldn't find {objectId.Full:X8}") when showError (ACE)
                return

        wo.current_landblock = None

        if not adjacency_move:
            # really remove it - send message to client to remove object (ACE): the broadcast is no physics
            wo.physics_obj.destroy_object()

    @harness("Landblock.GetObject as the oracle's stand-in answers it: null")
    def get_object(self, guid: int):
        return None


__all__ = ["Landblock"]
