"""GfxObj: PhysicsBSP, PhysicsSphere, FindObjCollisions -- the part of a GfxObj the physics reads.

ACE's Physics/Common/GfxObj.cs (namespace ACE.Server.Physics.Collision). Scenes carry no DAT:
`from_shape` builds the GfxObj the oracle builds from a scene BSPShape (a new GfxObj with
PhysicsBSP = new BSPTree(root) over polygons made with make_plane, and PhysicsSphere = the
shape's sphere; not PhysicsBSP.GetSphere(), which the DAT constructor would use).
"""

from __future__ import annotations

from dataclasses import dataclass

from acconform.flags import TransitionState
from acconform.numerics import Mode

from .anchors import anchor
from .constants import EPSILON
from .geom.bsp import BSPTree
from .geom.sphere import Sphere
from .transition.sphere_path import InsertType


@dataclass(slots=True, eq=False)
class GfxObj:
    physics_bsp: BSPTree | None = None
    physics_sphere: Sphere | None = None

    @staticmethod
    @anchor(None, "GfxObj.cs:GfxObj", "the oracle's GfxObj: new GfxObj(), PhysicsBSP and PhysicsSphere from a scene BSPShape")
    def from_shape(shape, mode: Mode) -> "GfxObj":
        return GfxObj(BSPTree.from_shape(shape, mode), Sphere.from_rec(shape.sphere, mode))

    @anchor("CGfxObj::find_obj_collisions", "GfxObj.cs:FindObjCollisions")
    def find_obj_collisions(self, transition, scale_z) -> TransitionState:
        path = transition.sphere_path

        # ACE: foreach over path.LocalSpaceSphere (NumSphere entries, cached by the caller)
        for local_space_sphere in path.local_space_sphere:
            offset = self.physics_sphere.center - local_space_sphere.center
            radsum = self.physics_sphere.radius + local_space_sphere.radius

            if offset.length_squared() - radsum * radsum < EPSILON:
                if path.insert_type == InsertType.InitialPlacement:
                    return self.physics_bsp.placement_insert(transition)
                else:
                    return self.physics_bsp.find_collisions(transition, scale_z)
        return TransitionState.OK
