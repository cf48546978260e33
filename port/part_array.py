"""PartArray and PhysicsPart: PartArray (AddPartsShadow, AllowsFreeHeading, CacheHasPhysicsBSP, FindObjCollisions, GetCylSphere, GetNumCylsphere, GetNumSphere, GetSphere, GetStepDownHeight, GetStepUpHeight, SetScaleInternal), PhysicsPart (FindObjCollisions).

ACE's Physics/PartArray.cs and Physics/PhysicsPart.cs, the members a transition reaches. A
PhysicsPart is here beside its array (it is only ever reached through it). Scenes carry no DAT:
the run builds the PartArray the oracle builds (Facade.cs MakePartArray: Owner, Setup, no parts;
a BSP object gets one PhysicsPart whose GfxObj holds the BSP and whose Pos is the object's
position).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from acconform.flags import TransitionState
from acconform.numerics import Vector3

from .anchors import anchor
from .setup import Setup


@dataclass(slots=True, eq=False)
class PhysicsPart:
    gfx_obj: object = None  # port.gfx_obj.GfxObj
    gfx_obj_scale: Vector3 | None = None
    physics_obj: object = None
    pos: object = None  # frame.Position

    @anchor("CPhysicsPart::find_obj_collisions", "PhysicsPart.cs:FindObjCollisions")
    def find_obj_collisions(self, transition) -> TransitionState:
        if self.gfx_obj is not None and self.gfx_obj.physics_bsp is not None:
            transition.sphere_path.cache_local_space_sphere(self.pos, self.gfx_obj_scale.z)
            return self.gfx_obj.find_obj_collisions(transition, self.gfx_obj_scale.z)
        return TransitionState.OK  # should be invalid? (ACE)


@dataclass(slots=True, eq=False)
class PartArray:
    owner: object = None  # the PhysicsObj
    setup: Setup | None = None
    num_parts: int = 0
    parts: list = field(default_factory=list)  # PhysicsPart
    scale: Vector3 | None = None  # Vector3.One from the constructor; set by SetScaleInternal

    @anchor("CPartArray::AddPartsShadow", "PartArray.cs:AddPartsShadow")
    def add_parts_shadow(self, obj_cell, num_shadow_parts: int) -> None:
        """ACE calls PartCell.AddPart per part, which returns at once (its body is commented
        out in ACE): nothing happens."""
        return None

    @anchor("CPartArray::AllowsFreeHeading", "PartArray.cs:AllowsFreeHeading")
    def allows_free_heading(self) -> bool:
        return self.setup.allow_free_heading

    @anchor("CPartArray::CacheHasPhysicsBSP", "PartArray.cs:CacheHasPhysicsBSP")
    def cache_has_physics_bsp(self) -> bool:
        """The PartArray's own State bits (0x10000) are not read by a transition; only the answer is."""
        for part in self.parts:
            if part.gfx_obj.physics_bsp is not None:
                return True
        return False

    @anchor("CPartArray::FindObjCollisions", "PartArray.cs:FindObjCollisions")
    def find_obj_collisions(self, transition) -> TransitionState:
        for part in self.parts:
            result = part.find_obj_collisions(transition)
            if result != TransitionState.OK:
                return result
        return TransitionState.OK

    @anchor("CPartArray::GetCylSphere", "PartArray.cs:GetCylSphere")
    def get_cyl_sphere(self) -> list:
        return self.setup.cyl_sphere

    @anchor("CPartArray::GetNumCylsphere", "PartArray.cs:GetNumCylsphere")
    def get_num_cylsphere(self) -> int:
        return self.setup.num_cylsphere

    @anchor("CPartArray::GetNumSphere", "PartArray.cs:GetNumSphere")
    def get_num_sphere(self) -> int:
        return self.setup.num_sphere

    @anchor("CPartArray::GetSphere", "PartArray.cs:GetSphere")
    def get_sphere(self) -> list:
        return self.setup.sphere

    @anchor("CPartArray::GetStepDownHeight", "PartArray.cs:GetStepDownHeight")
    def get_step_down_height(self):
        return self.setup.step_down_height * self.scale.z

    @anchor("CPartArray::GetStepUpHeight", "PartArray.cs:GetStepUpHeight")
    def get_step_up_height(self):
        return self.setup.step_up_height * self.scale.z

    @anchor("CPartArray::SetScaleInternal", "PartArray.cs:SetScaleInternal")
    def set_scale_internal(self, new_scale: Vector3) -> bool:
        self.scale = new_scale
        for i in range(self.num_parts):
            part = self.parts[i]
            if part is not None:
                if self.setup is not None and len(self.setup.default_scale) > i:
                    part.gfx_obj_scale = self.setup.default_scale[i] * new_scale
                else:
                    part.gfx_obj_scale = new_scale
        return True
