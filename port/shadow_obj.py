"""ShadowObj: ShadowObj (the constructor) -- an object's entry in the shadow list of a cell it overlaps.

ACE's Common/ShadowObj.cs. ObjCell.FindObjCollisions walks a cell's ShadowObjectList (from the
end) and asks each entry's PhysicsObj for collisions; PhysicsObj.add_shadows_to_cell makes the
entries (port/physics_obj.py).
"""

from __future__ import annotations

from dataclasses import dataclass

from .anchors import anchor


@dataclass(slots=True, eq=False)
class ShadowObj:
    physics_obj: object  # the PhysicsObj
    cell: object  # the ObjCell (ObjCell.AddShadowObject sets it again)

    @staticmethod
    @anchor("CShadowObj::CShadowObj", "ShadowObj.cs:ShadowObj")
    def create(physics_obj, cell) -> "ShadowObj":
        return ShadowObj(physics_obj, cell)
