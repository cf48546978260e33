"""BSPTREE/BSPNODE/BSPLEAF: BSPTree (adjust_to_plane, box_intersects_cell_bsp, check_walkable, collide_with_pt, find_collisions, NegPolyHit, placement_insert, placement_insert_inner, point_inside_cell_bsp, slide_sphere, sphere_intersects_cell_bsp, step_sphere_down, step_sphere_up), BSPNode and BSPLeaf (box_intersects_cell_bsp, box_intersects_cell_bsp_inner, find_walkable, hits_walkable, point_inside_cell_bsp, point_intersects_solid, sphere_intersects_cell_bsp, sphere_intersects_poly, sphere_intersects_solid, sphere_intersects_solid_poly).

Ports ACE BSP/BSPTree.cs, BSPNode.cs and BSPLeaf.cs. The tree is built by ACE's DAT constructors
(`from_dat`) from the GfxObj record DatLoader read (port/dat/): every node that names a polygon
gets its own Polygon (ACE's PolygonCache is off), and the root is always a BSPNode, so a DAT
leaf at the root becomes a childless node. Where ACE then calls a method on a missing child
(e.g. find_walkable on such a root), Python meets None as .NET meets null: run_scene reports it
as NullReferenceException (port/errors.py).

ACE's ``ref`` parameters are returned, in order after the result:
``find_walkable -> (polygon, changed)``, ``sphere_intersects_poly -> (hit, polygon, contact_point)``,
``sphere_intersects_solid_poly -> (hit, center_solid, hit_poly)``.
"""

from __future__ import annotations

from enum import IntEnum

from acconform.flags import ObjectInfoState, TransitionState
from acconform.numerics import D, Mode, Plane, Vector3, cast_float, dot

from ..anchors import anchor
from ..dat import bsp_leaf as dat_bsp_leaf
from ..errors import KeyNotFoundException
from ..constants import CELL_BSP_SLACK, EPSILON, LANDING_Z
from ..vec import Side, get_side, plane_local_to_global, zero_like
from .polygon import Polygon
from .sphere import Sphere

# SpherePath.cs InsertType.Placement
INSERT_TYPE_PLACEMENT = 1
# BSPTree.cs adjust_to_plane: 15 tries (hard-coded in ACE), bisection stops below 0.02 (double)
ADJUST_TO_PLANE_ITERATIONS = 15
ADJUST_TO_PLANE_MIN_SPAN = 0.02
# BSPTree.cs placement_insert: 20 tries (hard-coded in ACE)
PLACEMENT_ITERATIONS = 20


class BSPTreeType(IntEnum):
    Drawing = 0x0
    Physics = 0x1
    Cell = 0x2


class BoundingType(IntEnum):
    Outside = 0x0
    PartiallyInside = 0x1
    EntirelyInside = 0x2


class BSPNode:
    """BSPNode.cs: sphere, splitting_plane, polygons, pos_node (front), neg_node (back)."""

    __slots__ = ("sphere", "splitting_plane", "type", "num_polys", "polygons", "pos_node", "neg_node")

    @classmethod
    @anchor("BSPNODE::UnPackChild", "BSPNode.cs:BSPNode(DatLoader.Entity.BSPNode, Dictionary<ushort, Polygon>, CVertexArray)",
            "the DAT constructor")
    def from_dat(cls, node, polys: dict, vertex_array, mode: Mode) -> "BSPNode":
        """``new BSPNode(node, polys, vertexArray)``: a node of any DAT kind (a DAT leaf too, when it
        is the tree's root) becomes a BSPNode. `mode` types the default splitting plane."""
        n = cls.__new__(cls)
        n._init_from_dat(node, polys, vertex_array, mode)
        return n

    def _init_from_dat(self, node, polys: dict, vertex_array, mode: Mode) -> None:
        """BSPNode(DatLoader.Entity.BSPNode, ...)'s body (BSPLeaf's DAT constructor runs it as base)."""
        self.sphere = None
        if node.sphere is not None:
            self.sphere = Sphere.from_dat(node.sphere)
        # SplittingPlane is a struct: a DAT leaf has none, so it stays default(Plane) (0, 0, 0), 0
        self.splitting_plane = Plane(mode.vec(0, 0, 0), mode.scalar(0.0))
        if node.splitting_plane is not None:
            self.splitting_plane = node.splitting_plane.to_numerics()
        self.type = BSPTreeType.Drawing  # Type is never set: default(BSPTreeType)
        self.num_polys = 0
        self.polygons = None
        if node.in_polys is not None:
            self.num_polys = len(node.in_polys)
            self.polygons = []
            for poly in node.in_polys:
                dat_poly = polys.get(poly)
                if dat_poly is None:
                    raise KeyNotFoundException(f"The given key '{poly}' was not present in the dictionary.")
                self.polygons.append(Polygon.from_dat(dat_poly, vertex_array))  # PolygonCache is off
        self.pos_node = None
        if node.pos_node is not None:
            if not isinstance(node.pos_node, dat_bsp_leaf.BSPLeaf):
                self.pos_node = BSPNode.from_dat(node.pos_node, polys, vertex_array, mode)
            else:
                self.pos_node = BSPLeaf.from_dat(node.pos_node, polys, vertex_array, mode)
        self.neg_node = None
        if node.neg_node is not None:
            if not isinstance(node.neg_node, dat_bsp_leaf.BSPLeaf):
                self.neg_node = BSPNode.from_dat(node.neg_node, polys, vertex_array, mode)
            else:
                self.neg_node = BSPLeaf.from_dat(node.neg_node, polys, vertex_array, mode)

    def __repr__(self) -> str:
        return f"BSPNode(plane={self.splitting_plane!r}, sphere={self.sphere!r})"

    @anchor("BSPNODE::box_intersects_cell_bsp", "BSPNode.cs:box_intersects_cell_bsp")
    def box_intersects_cell_bsp(self, box) -> bool:
        """Walks the front (PosNode) chain only; false as soon as the box's Min is behind a
        node's plane and so are all eight corners."""
        corners = box.get_corners()
        node = self
        while node is not None:
            dist = dot(box.min, node.splitting_plane.normal) + node.splitting_plane.d
            if dist >= -EPSILON:
                node = node.pos_node
                continue

            if self.box_intersects_cell_bsp_inner(node, corners):
                return False
            node = node.pos_node
        return True

    @anchor(None, "BSPNode.cs:box_intersects_cell_bsp_inner")
    def box_intersects_cell_bsp_inner(self, node: "BSPNode", corners: list) -> bool:
        for corner in corners:
            if get_side(node.splitting_plane, corner) != Side.Behind:
                return False
        return True

    @anchor("BSPNODE::find_walkable", "BSPNode.cs:find_walkable")
    def find_walkable(self, path, valid_pos: Sphere, polygon, movement: Vector3, up: Vector3, changed: bool):
        """``find_walkable(path, validPos, ref polygon, movement, up, ref changed)``: returns
        (polygon, changed); valid_pos is moved in place by the polygons that adjust it."""
        if not self.sphere.intersects(valid_pos):
            return polygon, changed

        dist = dot(self.splitting_plane.normal, valid_pos.center) + self.splitting_plane.d
        reach = valid_pos.radius - EPSILON

        if dist >= reach:
            return self.pos_node.find_walkable(path, valid_pos, polygon, movement, up, changed)
        if dist <= -reach:
            return self.neg_node.find_walkable(path, valid_pos, polygon, movement, up, changed)
        found, changed = self.pos_node.find_walkable(path, valid_pos, polygon, movement, up, changed)
        last, changed = self.neg_node.find_walkable(path, valid_pos, found, movement, up, changed)
        if path.trace is not None and found is not polygon and last is not found:
            path.trace["boundary:bsp_split_walkable"] += 1
        return last, changed

    @anchor("BSPNODE::hits_walkable", "BSPNode.cs:hits_walkable")
    def hits_walkable(self, path, valid_pos: Sphere, up: Vector3) -> bool:
        if not self.sphere.intersects(valid_pos):
            return False

        dist = dot(self.splitting_plane.normal, valid_pos.center) + self.splitting_plane.d
        reach = valid_pos.radius - EPSILON

        if dist >= reach:
            return self.pos_node.hits_walkable(path, valid_pos, up)
        if dist <= -reach:
            return self.neg_node.hits_walkable(path, valid_pos, up)
        if self.pos_node.hits_walkable(path, valid_pos, up):
            return True
        if self.neg_node.hits_walkable(path, valid_pos, up):
            return True
        return False

    @anchor("BSPNODE::point_inside_cell_bsp", "BSPNode.cs:point_inside_cell_bsp")
    def point_inside_cell_bsp(self, point: Vector3) -> bool:
        side = get_side(self.splitting_plane, point)
        if side == Side.Front or side == Side.Close:
            if self.pos_node is not None:
                return self.pos_node.point_inside_cell_bsp(point)
            return True
        return False

    @anchor("BSPNODE::point_intersects_solid", "BSPNode.cs:point_intersects_solid")
    def point_intersects_solid(self, point: Vector3) -> bool:
        if dot(point, self.splitting_plane.normal) + self.splitting_plane.d > 0.0:
            return self.pos_node.point_intersects_solid(point)
        return self.neg_node.point_intersects_solid(point)

    @anchor("BSPNODE::sphere_intersects_cell_bsp", "BSPNode.cs:sphere_intersects_cell_bsp")
    def sphere_intersects_cell_bsp(self, cur_sphere: Sphere) -> BoundingType:
        dist = dot(self.splitting_plane.normal, cur_sphere.center) + self.splitting_plane.d
        check_rad = cur_sphere.radius + CELL_BSP_SLACK

        if dist <= -check_rad:
            return BoundingType.Outside

        if dist >= check_rad:
            if self.pos_node is not None:
                return self.pos_node.sphere_intersects_cell_bsp(cur_sphere)
            return BoundingType.EntirelyInside

        if self.pos_node is not None:
            if self.pos_node.sphere_intersects_cell_bsp(cur_sphere) != BoundingType.Outside:
                return BoundingType.PartiallyInside
            return BoundingType.Outside

        return BoundingType.PartiallyInside

    @anchor("BSPNODE::sphere_intersects_poly", "BSPNode.cs:sphere_intersects_poly")
    def sphere_intersects_poly(self, check_pos: Sphere, movement: Vector3, polygon, contact_point: Vector3, trace=None):
        """Returns (hit, polygon, contact_point): ACE's two ref parameters after the call."""
        if not self.sphere.intersects(check_pos):
            return False, polygon, contact_point

        dist = dot(self.splitting_plane.normal, check_pos.center) + self.splitting_plane.d
        reach = check_pos.radius - EPSILON

        if dist >= reach:
            return self.pos_node.sphere_intersects_poly(check_pos, movement, polygon, contact_point, trace)
        if dist <= -reach:
            return self.neg_node.sphere_intersects_poly(check_pos, movement, polygon, contact_point, trace)

        if self.pos_node is not None:
            hit, polygon, contact_point = self.pos_node.sphere_intersects_poly(check_pos, movement, polygon, contact_point, trace)
            if hit:
                return True, polygon, contact_point

        if self.neg_node is not None:
            hit, polygon, contact_point = self.neg_node.sphere_intersects_poly(check_pos, movement, polygon, contact_point, trace)
            if hit:
                return True, polygon, contact_point

        return False, polygon, contact_point

    @anchor("BSPNODE::sphere_intersects_solid", "BSPNode.cs:sphere_intersects_solid")
    def sphere_intersects_solid(self, check_pos: Sphere, center_check: bool, trace=None) -> bool:
        if not self.sphere.intersects(check_pos):
            return False

        dist = dot(self.splitting_plane.normal, check_pos.center) + self.splitting_plane.d
        reach = check_pos.radius - EPSILON

        if dist >= reach:
            return self.pos_node.sphere_intersects_solid(check_pos, center_check, trace)
        if dist <= -reach:
            return self.neg_node.sphere_intersects_solid(check_pos, center_check, trace)

        if dist < 0.0:
            if self.pos_node.sphere_intersects_solid(check_pos, False, trace):
                return True
            return self.neg_node.sphere_intersects_solid(check_pos, center_check, trace)
        if self.pos_node.sphere_intersects_solid(check_pos, center_check, trace):
            return True
        return self.neg_node.sphere_intersects_solid(check_pos, False, trace)

    @anchor("BSPNODE::sphere_intersects_solid_poly", "BSPNode.cs:sphere_intersects_solid_poly")
    def sphere_intersects_solid_poly(self, check_pos: Sphere, radius, center_solid: bool, hit_poly, center_check: bool, trace=None):
        """Returns (hit, center_solid, hit_poly): ACE's two ref parameters after the call."""
        if not self.sphere.intersects(check_pos):
            return False, center_solid, hit_poly

        dist = dot(self.splitting_plane.normal, check_pos.center) + self.splitting_plane.d
        reach = radius - EPSILON

        if dist >= reach:
            return self.pos_node.sphere_intersects_solid_poly(check_pos, radius, center_solid, hit_poly, center_check, trace)
        if dist <= -reach:
            return self.neg_node.sphere_intersects_solid_poly(check_pos, radius, center_solid, hit_poly, center_check, trace)

        if dist <= 0.0:
            _, center_solid, hit_poly = self.neg_node.sphere_intersects_solid_poly(
                check_pos, radius, center_solid, hit_poly, center_check, trace)
            if hit_poly is not None:
                return center_solid, center_solid, hit_poly
            return self.pos_node.sphere_intersects_solid_poly(check_pos, radius, center_solid, hit_poly, False, trace)

        _, center_solid, hit_poly = self.pos_node.sphere_intersects_solid_poly(
            check_pos, radius, center_solid, hit_poly, center_check, trace)
        if hit_poly is not None:
            return center_solid, center_solid, hit_poly
        return self.neg_node.sphere_intersects_solid_poly(check_pos, radius, center_solid, hit_poly, False, trace)


class BSPLeaf(BSPNode):
    """BSPLeaf.cs: a node with polygons, a Solid flag and a leaf index; no splitting plane."""

    __slots__ = ("leaf_idx", "solid")

    @classmethod
    @anchor(None, "BSPLeaf.cs:BSPLeaf(DatLoader.Entity.BSPLeaf, Dictionary<ushort, Polygon>, CVertexArray)", "the DAT constructor")
    def from_dat(cls, node, polys: dict, vertex_array, mode: Mode) -> "BSPLeaf":
        leaf = cls.__new__(cls)
        leaf._init_from_dat(node, polys, vertex_array, mode)  # : base(node, polys, vertexArray)
        leaf.leaf_idx = node.leaf_index
        leaf.solid = node.solid == 1
        return leaf

    def __repr__(self) -> str:
        return f"BSPLeaf({self.leaf_idx}, polys={self.num_polys}, solid={self.solid})"

    @anchor("BSPLEAF::find_walkable", "BSPLeaf.cs:find_walkable")
    def find_walkable(self, path, valid_pos: Sphere, hit_poly, movement: Vector3, up: Vector3, changed: bool):
        if self.num_polys == 0 or not self.sphere.intersects(valid_pos):
            return hit_poly, changed

        for polygon in self.polygons:
            walkable = polygon.walkable_hits_sphere(path, valid_pos, up)
            adjusted = False
            if walkable:
                adjusted = polygon.adjust_sphere_to_plane(path, valid_pos, movement)

            if walkable and adjusted:
                changed = True
                hit_poly = polygon
        return hit_poly, changed

    @anchor("BSPLEAF::hits_walkable", "BSPLeaf.cs:hits_walkable")
    def hits_walkable(self, path, valid_pos: Sphere, up: Vector3) -> bool:
        if self.num_polys == 0 or not self.sphere.intersects(valid_pos):
            return False

        for polygon in self.polygons:
            if polygon.walkable_hits_sphere(path, valid_pos, up) and polygon.check_small_walkable(valid_pos, up):
                return True
        return False

    @anchor("BSPLEAF::point_intersects_solid", "BSPLeaf.cs:point_intersects_solid")
    def point_intersects_solid(self, point: Vector3) -> bool:
        return self.num_polys != 0

    @anchor("BSPLEAF::sphere_intersects_poly", "BSPLeaf.cs:sphere_intersects_poly")
    def sphere_intersects_poly(self, check_pos: Sphere, movement: Vector3, hit_poly, contact_point: Vector3, trace=None):
        if self.num_polys == 0 or not self.sphere.intersects(check_pos):
            return False, hit_poly, contact_point

        for polygon in self.polygons:
            hit, contact_point, hit_poly = polygon.pos_hits_sphere(check_pos, movement, contact_point, hit_poly, trace)
            if hit:
                return True, hit_poly, contact_point
        return False, hit_poly, contact_point

    @anchor("BSPLEAF::sphere_intersects_solid", "BSPLeaf.cs:sphere_intersects_solid")
    def sphere_intersects_solid(self, check_pos: Sphere, check_center: bool, trace=None) -> bool:
        if self.num_polys == 0:
            return False
        if check_center and self.solid:
            return True
        if not self.sphere.intersects(check_pos):
            return False

        for polygon in self.polygons:
            if polygon.hits_sphere(check_pos, trace):
                return True
        return False

    @anchor("BSPLEAF::sphere_intersects_solid_poly", "BSPLeaf.cs:sphere_intersects_solid_poly")
    def sphere_intersects_solid_poly(self, check_pos: Sphere, radius, center_solid: bool, hit_poly, check_center: bool, trace=None):
        if self.num_polys == 0:
            return False, center_solid, hit_poly

        if check_center and self.solid:
            center_solid = True

        if not self.sphere.intersects(check_pos):
            return center_solid, center_solid, hit_poly

        for polygon in self.polygons:
            if polygon.hits_sphere(check_pos, trace):
                return True, center_solid, polygon
        return center_solid, center_solid, hit_poly


class BSPTree:
    """BSPTree.cs: root_node."""

    __slots__ = ("root_node",)

    def __init__(self, root_node: BSPNode):
        self.root_node = root_node

    @classmethod
    @anchor("BSPTREE::UnPack", "BSPTree.cs:BSPTree(DatLoader.Entity.BSPTree, Dictionary<ushort, Polygon>, CVertexArray)",
            "the DAT constructor")
    def from_dat(cls, bsp, polys: dict, vertex_array, mode: Mode) -> "BSPTree":
        """``RootNode = new BSPNode(bsp.RootNode, polys, vertexArray)``: the root is a BSPNode even
        when the DAT root is a leaf (then no query descends from it: a childless node)."""
        return cls(BSPNode.from_dat(bsp.root_node, polys, vertex_array, mode))

    @anchor("BSPTREE::box_intersects_cell_bsp", "BSPTree.cs:box_intersects_cell_bsp")
    def box_intersects_cell_bsp(self, box) -> bool:
        return self.root_node.box_intersects_cell_bsp(box)

    @anchor(None, "BSPTree.cs:GetSphere")
    def get_sphere(self) -> Sphere:
        return self.root_node.sphere

    @anchor("BSPTREE::adjust_to_plane", "BSPTree.cs:adjust_to_plane")
    def adjust_to_plane(self, check_pos: Sphere, cur_pos: Vector3, hit_poly: Polygon, contact_point: Vector3) -> bool:
        """Moves check_pos (mutated) along its movement. The times are C# doubles.

        As ACE writes it, the first loop only ever leaves with lower == upper == 1.0 (or gives
        up), so the bisection stops at once and this returns False."""
        movement = check_pos.center - cur_pos
        lower_time = D(0.0)
        upper_time = D(1.0)

        max_iterations = ADJUST_TO_PLANE_ITERATIONS
        for i in range(max_iterations):
            touch_time = hit_poly.adjust_sphere_to_poly(check_pos, cur_pos, movement)
            if touch_time == 1.0:
                check_pos.center = cur_pos + movement * cast_float(movement.x, touch_time)

                hit, hit_poly, contact_point = self.root_node.sphere_intersects_poly(check_pos, movement, hit_poly, contact_point)
                if not hit:
                    lower_time = touch_time
                    break
                upper_time = touch_time

            if i == max_iterations - 1:
                return False

        for _j in range(max_iterations):
            average_time = (lower_time + upper_time) * 0.5

            check_pos.center = cur_pos + movement * cast_float(movement.x, average_time)

            hit, hit_poly, contact_point = self.root_node.sphere_intersects_poly(check_pos, movement, hit_poly, contact_point)
            if not hit:
                upper_time = (lower_time + upper_time) * 0.5
            else:
                lower_time = (lower_time + upper_time) * 0.5

            if upper_time - lower_time < ADJUST_TO_PLANE_MIN_SPAN:
                return False

        return True

    @anchor("BSPTREE::check_walkable", "BSPTree.cs:check_walkable")
    def check_walkable(self, path, check_pos: Sphere, scale) -> TransitionState:
        valid_pos = check_pos.copy()
        return TransitionState.Collided if self.root_node.hits_walkable(path, valid_pos, path.local_space_z) else TransitionState.OK

    @anchor("BSPTREE::collide_with_pt", "BSPTree.cs:collide_with_pt")
    def collide_with_pt(self, transition, check_pos: Sphere, cur_pos: Vector3, hit_poly: Polygon, contact_point: Vector3, scale) -> TransitionState:
        obj = transition.object_info
        path = transition.sphere_path
        collisions = transition.collision_info
        collision_normal = path.local_space_pos.local_to_global_vec(hit_poly.plane.normal)

        if not obj.state & ObjectInfoState.PerfectClip:
            collisions.set_collision_normal(collision_normal)
            return TransitionState.Collided

        valid_pos = check_pos.copy()

        if not self.adjust_to_plane(valid_pos, cur_pos, hit_poly, contact_point):
            return TransitionState.Collided

        collisions.set_collision_normal(collision_normal)

        adjusted = valid_pos.center - check_pos.center
        offset = path.local_space_pos.local_to_global_vec(adjusted) * scale

        path.add_offset_to_check_pos(offset)

        return TransitionState.Adjusted

    @anchor("BSPTREE::find_collisions", "BSPTree.cs:find_collisions")
    def find_collisions(self, transition, scale) -> TransitionState:
        path = transition.sphere_path
        collisions = transition.collision_info

        center = path.local_space_curr_center[0].center
        local_sphere = path.local_space_sphere[0]

        local_sphere_ = path.local_space_sphere[1] if path.num_sphere > 1 else None

        movement = local_sphere.center - center

        if path.insert_type == INSERT_TYPE_PLACEMENT or path.obstruction_ethereal:
            clear_cell = True
            if path.building_check:
                clear_cell = not path.hits_interior_cell

            if self.root_node.sphere_intersects_solid(local_sphere, clear_cell, trace=path.trace) or (
                path.num_sphere > 1 and self.root_node.sphere_intersects_solid(local_sphere_, clear_cell, trace=path.trace)
            ):
                return TransitionState.Collided
            return TransitionState.OK

        if path.check_walkable:
            return self.check_walkable(path, local_sphere, scale)

        if path.step_down:
            return self.step_sphere_down(transition, local_sphere, scale)

        hit_poly = None

        if path.collide:
            changed = False
            valid_pos = local_sphere.copy()

            hit_poly, changed = self.root_node.find_walkable(path, valid_pos, hit_poly, movement, path.local_space_z, changed)

            if changed:
                offset = valid_pos.center - local_sphere.center
                collision_normal = path.local_space_pos.local_to_global_vec(offset) * scale
                path.add_offset_to_check_pos(collision_normal)

                contact_plane = plane_local_to_global(hit_poly.plane, path.check_pos, path.local_space_pos, hit_poly.plane)
                contact_plane = Plane(contact_plane.normal, contact_plane.d * scale)

                collisions.set_contact_plane(contact_plane, False)
                collisions.contact_plane_cell_id = path.check_pos.obj_cell_id
                path.set_walkable(valid_pos, hit_poly, path.local_space_z, path.local_space_pos, scale)

                return TransitionState.Adjusted
            return TransitionState.OK

        contact_point = zero_like(local_sphere.radius)
        obj = transition.object_info

        if obj.state & ObjectInfoState.Contact:
            hit, hit_poly, contact_point = self.root_node.sphere_intersects_poly(local_sphere, movement, hit_poly, contact_point, trace=path.trace)
            if hit:
                return self.step_sphere_up(transition, hit_poly.plane.normal)

            if path.num_sphere > 1:
                hit_poly_ = None

                hit, hit_poly_, contact_point = self.root_node.sphere_intersects_poly(local_sphere_, movement, hit_poly_, contact_point, trace=path.trace)
                if hit:
                    return self.slide_sphere(transition, hit_poly_.plane.normal)

                if hit_poly_ is not None:
                    return self.neg_poly_hit(path, hit_poly_, False)
                if hit_poly is not None:
                    return self.neg_poly_hit(path, hit_poly, True)
            return TransitionState.OK

        hit, hit_poly, contact_point = self.root_node.sphere_intersects_poly(local_sphere, movement, hit_poly, contact_point, trace=path.trace)
        if hit or hit_poly is not None:
            if obj.state & ObjectInfoState.PathClipped:
                return self.collide_with_pt(transition, local_sphere, center, hit_poly, contact_point, scale)

            collision_normal = path.local_space_pos.local_to_global_vec(hit_poly.plane.normal)
            path.walkable_allowance = type(local_sphere.radius)(LANDING_Z)
            path.set_collide(collision_normal)

            return TransitionState.Adjusted
        elif path.num_sphere > 1:
            hit, hit_poly, contact_point = self.root_node.sphere_intersects_poly(local_sphere_, movement, hit_poly, contact_point, trace=path.trace)
            if hit or hit_poly is not None:
                collision_normal = path.local_space_pos.local_to_global_vec(hit_poly.plane.normal)
                collisions.set_collision_normal(collision_normal)

                return TransitionState.Collided
        return TransitionState.OK

    @anchor(None, "BSPTree.cs:NegPolyHit")
    def neg_poly_hit(self, path, hit_poly: Polygon, step_up: bool) -> TransitionState:
        collision_normal = path.local_space_pos.local_to_global_vec(hit_poly.plane.normal)
        path.set_neg_poly_hit(step_up, collision_normal)
        return TransitionState.OK

    @anchor("BSPTREE::placement_insert", "BSPTree.cs:placement_insert")
    def placement_insert(self, transition) -> TransitionState:
        """Note: hit_poly is not reset between tries (ACE's), so a polygon hit on one try makes
        later tries' internal nodes return early."""
        path = transition.sphere_path

        valid_pos = path.local_space_sphere[0].copy()
        rad = valid_pos.radius

        valid_pos_ = None
        if path.num_sphere > 1:
            valid_pos_ = path.local_space_sphere[1].copy()

        clear_cell = True
        if path.building_check:
            clear_cell = not path.hits_interior_cell

        hit_poly = None

        for i in range(PLACEMENT_ITERATIONS):
            center_solid = False
            hit, center_solid, hit_poly = self.root_node.sphere_intersects_solid_poly(valid_pos, rad, center_solid, hit_poly, clear_cell, trace=path.trace)
            if hit:
                if hit_poly is not None:
                    hit_poly.adjust_to_placement_poly(valid_pos, valid_pos_, rad, center_solid, clear_cell)
                    continue
            else:
                if path.num_sphere >= 2:
                    hit, center_solid, hit_poly = self.root_node.sphere_intersects_solid_poly(valid_pos_, rad, center_solid, hit_poly, clear_cell, trace=path.trace)
                    if hit:
                        if hit_poly is not None:
                            hit_poly.adjust_to_placement_poly(valid_pos_, valid_pos, rad, center_solid, clear_cell)
                            continue
                    else:
                        return self.placement_insert_inner(valid_pos, path, i)
                else:
                    return self.placement_insert_inner(valid_pos, path, i)
            rad *= 2
        return TransitionState.Collided

    @anchor(None, "BSPTree.cs:placement_insert_inner")
    def placement_insert_inner(self, valid_pos: Sphere, path, i: int) -> TransitionState:
        if i == 0:
            return TransitionState.OK

        adjust = valid_pos.center - path.local_space_sphere[0].center
        offset = path.local_space_pos.local_to_global_vec(adjust)
        path.add_offset_to_check_pos(offset)
        return TransitionState.Adjusted

    @anchor("BSPTREE::point_inside_cell_bsp", "BSPTree.cs:point_inside_cell_bsp")
    def point_inside_cell_bsp(self, origin: Vector3) -> bool:
        return self.root_node.point_inside_cell_bsp(origin)

    @anchor("BSPTREE::slide_sphere", "BSPTree.cs:slide_sphere")
    def slide_sphere(self, transition, collision_normal: Vector3) -> TransitionState:
        path = transition.sphere_path
        glob_normal = path.local_space_pos.local_to_global_vec(collision_normal)
        state, _glob_normal = path.global_sphere[0].slide_sphere(transition, glob_normal, path.global_curr_center[0].center)
        return state

    @anchor("BSPTREE::sphere_intersects_cell_bsp", "BSPTree.cs:sphere_intersects_cell_bsp")
    def sphere_intersects_cell_bsp(self, sphere: Sphere) -> BoundingType:
        return self.root_node.sphere_intersects_cell_bsp(sphere)

    @anchor("BSPTREE::step_sphere_down", "BSPTree.cs:step_sphere_down")
    def step_sphere_down(self, transition, check_pos: Sphere, scale) -> TransitionState:
        path = transition.sphere_path
        collisions = transition.collision_info

        step_down_amount = -(path.step_down_amt * path.walk_interp)

        movement = path.local_space_z * step_down_amount * (1.0 / scale)
        valid_pos = check_pos.copy()
        changed = False
        poly_hit = None

        poly_hit, changed = self.root_node.find_walkable(path, valid_pos, poly_hit, movement, path.local_space_z, changed)

        if changed:
            adjusted = valid_pos.center - check_pos.center
            offset = path.local_space_pos.local_to_global_vec(adjusted) * scale
            path.check_pos.frame.origin = path.check_pos.frame.origin + offset
            path.cache_global_sphere(offset)

            contact_plane = plane_local_to_global(poly_hit.plane, path.check_pos, path.local_space_pos, poly_hit.plane)

            collisions.contact_plane_valid = True
            # ACE sets ContactPlane.Normal, then ContactPlane.D (a struct field): one new Plane here
            collisions.contact_plane = Plane(contact_plane.normal, contact_plane.d * scale)

            collisions.contact_plane_is_water = False
            collisions.contact_plane_cell_id = path.check_pos.obj_cell_id

            path.set_walkable(valid_pos, poly_hit, path.local_space_z, path.local_space_pos, scale)

            return TransitionState.Adjusted

        return TransitionState.OK

    @anchor("BSPTREE::step_sphere_up", "BSPTree.cs:step_sphere_up")
    def step_sphere_up(self, transition, collision_normal: Vector3) -> TransitionState:
        path = transition.sphere_path
        glob_normal = path.local_space_pos.local_to_global_vec(collision_normal)

        if transition.step_up(glob_normal):
            return TransitionState.OK
        return path.step_up_slide(transition)
