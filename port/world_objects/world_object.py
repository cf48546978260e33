"""WorldObject: OnCollideObject, OnCollideObjectEnd, OnCollideEnvironment; the members of ACE's WorldObject the physics reads.

ACE's WorldObjects/WorldObject.cs (and WorldObject_Properties.cs for the property-backed members). A
plain WorldObject (not a creature) is an object that moves: WeenieObject(WorldObject) gives it neither
IsCreature nor IsPlayer. Each property-backed member holds what ACE's getter answers for an object
without the property unless the scene sets it: ItemType None (``GetProperty(PropertyInt.ItemType) ??
0``), Attackable true (``GetProperty(PropertyBool.Attackable) ?? true``), ReportCollisions null (a
``bool?`` with no default: OnCollideObject's ``ReportCollisions == false`` is then false),
PlayerKillerStatus NPK.
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
    report_collisions: bool | None = None
    player_killer_status: PlayerKillerStatus = PlayerKillerStatus.NPK  # WorldObject_Properties.cs; read for creatures
    # ProjectileTarget: a thrown weapon's or a missile's target (WorldObject.cs); null for every object here
    projectile_target: object = None
    # CurrentLandblock: the server landblock that holds the object; a scene's WorldObjects are on none (the
    # oracle adds them to no Landblock), so WeenieObject.DoCollisionEnd finds no target through it
    current_landblock: object = None
    scatter_pos: object = None  # ScatterPos: none for an object walking in the world
    teleporting: bool = False  # Teleporting
    encumbrance_val: int | None = 0  # EncumbranceVal (an int?; a Container's is 0 from its constructor on)

    @anchor(None, "ACE.Server/WorldObjects/WorldObject.cs:OnCollideObject")
    def on_collide_object(self, target: "WorldObject") -> None:
        # thrown weapons (ACE)
        if self.projectile_target is None:
            return

        raise NotImplementedError("ProjectileCollisionHelper.OnCollideObject (a thrown weapon's collision) is not ported")

    @anchor(None, "ACE.Server/WorldObjects/WorldObject.cs:OnCollideObjectEnd")
    def on_collide_object_end(self, target: "WorldObject") -> None:
        # empty base (ACE)
        pass

    @anchor(None, "ACE.Server/WorldObjects/WorldObject.cs:OnCollideEnvironment")
    def on_collide_environment(self) -> None:
        # thrown weapons (ACE)
        if self.projectile_target is None:
            return

        raise NotImplementedError("ProjectileCollisionHelper.OnCollideEnvironment (a thrown weapon's collision) is not ported")


__all__ = ["WorldObject"]
