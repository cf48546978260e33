"""ServerObjectManager: AddServerObject, RemoveServerObject, GetObjectA.

ACE's Managers/ServerObjectManager.cs: the server's table of PhysicsObjs by id, through which
PhysicsObj.GetObjectA finds the object a TargetManager, StickyManager or MoveToManager names. ACE's
is a static ConcurrentDictionary; the port has no statics, so a run owns one (as it owns its
PhysicsTimer) and its PhysicsObjs ask it. Only lookups read it (no one enumerates it), so a plain
dict keeps every answer ACE's gives.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ..anchors import anchor


@dataclass(slots=True, eq=False)
class ServerObjectManager:
    server_objects: dict = field(default_factory=dict)  # id -> PhysicsObj

    @anchor(None, "ServerObjectManager.cs:AddServerObject")
    def add_server_object(self, obj) -> None:
        if obj is not None:
            self.server_objects[obj.id] = obj

    @anchor(None, "ServerObjectManager.cs:RemoveServerObject")
    def remove_server_object(self, obj) -> None:
        if obj is not None:
            self.server_objects.pop(obj.id, None)

    @anchor(None, "ServerObjectManager.cs:GetObjectA")
    def get_object_a(self, object_id: int):
        """The object with that id, or None (TryGetValue's default)."""
        return self.server_objects.get(object_id)


__all__ = ["ServerObjectManager"]
