"""WorldObject: OnCollideObject, OnCollideObjectEnd, OnCollideEnvironment, Destroy; the members of ACE's WorldObject the physics reads.

ACE's WorldObjects/WorldObject.cs (and WorldObject_Properties.cs for the property-backed members). A
plain WorldObject (not a creature) is an object that moves: WeenieObject(WorldObject) gives it neither
IsCreature nor IsPlayer. Each property-backed member holds what ACE's getter answers for an object
without the property unless the scene sets it: ItemType None (``GetProperty(PropertyInt.ItemType) ??
0``), Attackable true (``GetProperty(PropertyBool.Attackable) ?? true``), ReportCollisions null (a
``bool?`` with no default: OnCollideObject's ``ReportCollisions == false`` is then false),
PlayerKillerStatus NPK.

A projectile's members (ProjectileSource, ProjectileTarget: WorldObjects, compared by identity as C#
compares references; PhysicsObj; CurrentLandblock, a port/server_landblock.py Landblock; HitMsg,
IsDestroyed, physicsCreationTime) are WorldObject's in ACE and so here.
"""

from __future__ import annotations

from dataclasses import dataclass

from acconform.flags import PlayerKillerStatus

from ..anchors import anchor


@dataclass(slots=True, eq=False, kw_only=True)
class WorldObject:
    guid: int = 0  # Guid (ObjectGuid.Full): real ACE's constructors set it from the Biota's Id or the given ObjectGuid
    item_type: int = 0  # ItemType (ACE.Entity.Enum.ItemType: None 0, Creature 0x10, ...)
    attackable: bool = True
    report_collisions: bool | None = None  # PropertyBool.ReportCollisions
    ethereal: bool | None = None  # PropertyBool.Ethereal (PhysicsObj.SetPositionInternal sets it on a spell projectile)
    player_killer_status: PlayerKillerStatus = PlayerKillerStatus.NPK  # WorldObject_Properties.cs; read for creatures
    # ProjectileSource / ProjectileTarget: a projectile's launcher and target WorldObjects (WorldObject.cs); null for
    # every object that is no projectile
    projectile_source: object = None
    projectile_target: object = None
    # CurrentLandblock: the server landblock that holds the object. A scene's movers are on none (the oracle adds
    # them to no Landblock), so WeenieObject.DoCollisionEnd finds no target through them; a launched projectile is
    # on its launcher's (Landblock.AddWorldObject), whose GetObject finds nothing either (the stand-in's answer)
    current_landblock: object = None
    physics_obj: object = None  # PhysicsObj: set for a projectile (the launch code reads it); None after AddPhysicsObj fails
    rotation_speed: float | None = None  # PropertyFloat.RotationSpeed (a double)
    physics_creation_time: float = 0.0  # physicsCreationTime: PhysicsTimer.CurrentTime when the WorldObject was made
    hit_msg: bool = False  # HitMsg
    is_destroyed: bool = False  # IsDestroyed
    scatter_pos: object = None  # ScatterPos: none for an object walking in the world
    teleporting: bool = False  # Teleporting
    encumbrance_val: int | None = 0  # EncumbranceVal (an int?; a Container's is 0 from its constructor on)
    ignore_house_barriers: bool = False  # IgnoreHouseBarriers (PropertyBool; a developer's command sets it)

    @anchor(None, "ACE.Server/WorldObjects/WorldObject.cs:OnCollideObject")
    def on_collide_object(self, target: "WorldObject") -> None:
        from .projectile_collision_helper import ProjectileCollisionHelper

        # thrown weapons (ACE)
        if self.projectile_target is None:
            return

        ProjectileCollisionHelper.on_collide_object(self, target)

    @anchor(None, "ACE.Server/WorldObjects/WorldObject.cs:OnCollideObjectEnd")
    def on_collide_object_end(self, target: "WorldObject") -> None:
        # empty base (ACE)
        pass

    @anchor(None, "ACE.Server/WorldObjects/WorldObject.cs:OnCollideEnvironment")
    def on_collide_environment(self) -> None:
        from .projectile_collision_helper import ProjectileCollisionHelper

        # thrown weapons (ACE)
        if self.projectile_target is None:
            return

        ProjectileCollisionHelper.on_collide_environment(self)

    @anchor(None, "ACE.Server/WorldObjects/WorldObject.cs:Destroy",
            "its physics: once (IsDestroyed), CurrentLandblock?.RemoveWorldObject(Guid); the rest (events, the "
            "biota, a container's items, the wielder) is no physics")
    def destroy(self) -> None:
        if self.is_destroyed:
            return

        self.is_destroyed = True

        if self.current_landblock is not None:
            self.current_landblock.remove_world_object(self.guid)


__all__ = ["WorldObject"]
