"""GfxObj: GfxObj(DatLoader GfxObj), Init, FindObjCollisions -- a part's graphics object as the physics builds it from DAT.

ACE's Physics/Common/GfxObj.cs (namespace ACE.Server.Physics.Collision). The DAT constructor
takes the record DatLoader read (port/dat/gfx_obj.py): the physics BSP (BSPCache is off: a new
BSPTree), the physics sphere from the tree's root, and, in Init, the bounding box over the
vertices, which find_bbox_cell_list reads to place a static. On a client (PhysicsEngine's
Server false) ACE also builds every polygon of both polygon lists; the server does not.
"""

from __future__ import annotations

from dataclasses import dataclass

from acconform.flags import TransitionState
from acconform.numerics import Mode

from .anchors import anchor
from .bbox import BBox
from .constants import EPSILON
from .geom.bsp import BSPTree
from .geom.polygon import Polygon
from .geom.sphere import Sphere
from acconform.flags import InsertType


@dataclass(slots=True, eq=False)
class GfxObj:
    id: int = 0
    vertex_array: object = None  # dat.cvertex_array.CVertexArray
    polygons: dict | None = None
    physics_polygons: dict | None = None
    physics_sphere: Sphere | None = None
    physics_bsp: BSPTree | None = None
    sort_center: object = None
    drawing_sphere: Sphere | None = None
    drawing_bsp: BSPTree | None = None
    gfx_bound_box: BBox | None = None

    @staticmethod
    @anchor("CGfxObj::UnPack", "GfxObj.cs:GfxObj(DatLoader.FileTypes.GfxObj)", "the DAT constructor")
    def from_dat(gfx_obj, server: bool, mode: Mode) -> "GfxObj":
        """`server` is PhysicsEngine.Instance.Server (the scene's engine mode)."""
        g = GfxObj()
        if gfx_obj is None:
            return g

        g.id = gfx_obj.id
        g.vertex_array = gfx_obj.vertex_array

        if not server:
            g.polygons = {}
            for key, value in gfx_obj.polygons.items():
                g.polygons[key] = Polygon.from_dat(value, gfx_obj.vertex_array)  # PolygonCache is off

        if len(gfx_obj.physics_polygons) > 0:
            if not server:
                g.physics_polygons = {}
                for key, value in gfx_obj.physics_polygons.items():
                    g.physics_polygons[key] = Polygon.from_dat(value, gfx_obj.vertex_array)
            g.physics_bsp = BSPTree.from_dat(gfx_obj.physics_bsp, gfx_obj.physics_polygons, gfx_obj.vertex_array, mode)
            g.physics_sphere = g.physics_bsp.get_sphere()

        if not server:
            g.sort_center = gfx_obj.sort_center

        g.drawing_bsp = BSPTree.from_dat(gfx_obj.drawing_bsp, gfx_obj.polygons, gfx_obj.vertex_array, mode)
        g.drawing_sphere = g.drawing_bsp.get_sphere()

        g.init(mode)
        return g

    @anchor("CGfxObj::InitEnd", "GfxObj.cs:Init")
    def init(self, mode: Mode) -> None:
        """The bounding box over the vertices (first vertex, then AdjustBBox with each, the first
        again included); none -> both corners zero (`mode` types the zero)."""
        self.gfx_bound_box = BBox()
        vertices = self.vertex_array.vertices
        if vertices is not None and len(vertices) > 0:
            v = next(iter(vertices.values()))
            self.gfx_bound_box.min = v.origin
            self.gfx_bound_box.max = v.origin
            for vertex in vertices.values():
                self.gfx_bound_box.adjust_bbox(vertex.origin)
        else:
            self.gfx_bound_box.min = mode.vec(0, 0, 0)
            self.gfx_bound_box.max = mode.vec(0, 0, 0)

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
