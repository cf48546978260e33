"""CPolygon: Polygon (ctor x2, make_plane, adjust_sphere_to_plane, adjust_sphere_to_poly, adjust_to_placement_poly, check_small_walkable, check_walkable, find_crossed_edge, hits_sphere, point_in_poly2D, point_in_polygon, polygon_hits_ray, polygon_hits_sphere, polygon_hits_sphere_precise, pos_hits_sphere, walkable_hits_sphere); CVertex: Vertex (Sidedness is in port/vec.py, beside PlaneExtensions.intersect_box).

Ports ACE Polygon.cs and Common/Vertex.cs. A polygon plays two roles: terrain cells build it with
``Polygon(poly_id, num_points, sides_type)`` and then fill ``vertices[i]``/``vertex_ids[i]`` and call
``make_plane()``; GfxObj physics polygons come from a scene `PolygonRec` through
`Polygon.from_rec`, which, like ACE's DAT constructor, takes the vertices and computes the plane.

ACE's ``ref`` parameters are returned: e.g. ``polygon_hits_sphere_precise(sphere, contact_point)``
returns ``(hit, contact_point)`` where contact_point is unchanged when ACE leaves it untouched.
"""

from __future__ import annotations


from acconform.flags import CullMode
from acconform.numerics import D, Mode, Plane, Vector3, cross, dot, normalize

from ..anchors import anchor, harness
from ..errors import KeyNotFoundException
from ..constants import ADJUST_TO_PLANE_INTERP_LIMIT, EPSILON
from ..vec import Ray, Sidedness, compute_time_of_intersection, zero_like



class Vertex:
    """Common/Vertex.cs: an index, an origin and a normal. ``a - b`` is ``a.origin - b.origin``."""

    __slots__ = ("index", "origin", "normal")

    def __init__(self, origin: Vector3 | None = None, index: int = 0, normal: Vector3 | None = None):
        self.index = index
        self.origin = origin
        self.normal = normal

    @staticmethod
    @anchor(None, "Vertex.cs:Vertex(DatLoader.Entity.SWVertex)", "the DAT constructor")
    def from_dat(v) -> "Vertex":
        """``new Vertex(SWVertex)``: Origin and Normal; Index keeps its default 0."""
        return Vertex(v.origin, 0, v.normal)

    def __add__(self, o: "Vertex") -> Vector3:
        return self.origin + o.origin

    def __sub__(self, o: "Vertex") -> Vector3:
        return self.origin - o.origin

    def __mul__(self, o: "Vertex") -> Vector3:
        return self.origin * o.origin

    def __truediv__(self, o: "Vertex") -> Vector3:
        return Vector3(self.origin.x / o.origin.x, self.origin.y / o.origin.y, self.origin.z / o.origin.z)

    def __eq__(self, v) -> bool:
        return (
            isinstance(v, Vertex) and self.index == v.index and self.origin == v.origin and self.normal == v.normal
        )

    __hash__ = None

    def __repr__(self) -> str:
        return f"Vertex({self.origin!r}, index={self.index})"


class Polygon:
    """Polygon.cs. Fields: vertices, vertex_ids, poly_id, num_points, sides_type, plane."""

    __slots__ = ("vertices", "vertex_ids", "poly_id", "num_points", "sides_type", "pos_surface", "neg_surface", "plane")

    @anchor("CPolygon::CPolygon", "Polygon.cs:Polygon", "the terrain constructor (idx, numPoints, cullMode)")
    def __init__(self, poly_id: int, num_points: int, sides_type: int):
        self.init()
        self.poly_id = poly_id
        self.num_points = num_points
        self.sides_type = sides_type
        self.vertex_ids: list[int] = [-1] * num_points
        self.vertices: list[Vertex | None] = [None] * num_points
        self.plane: Plane | None = None

    @classmethod
    @anchor("CPolygon::UnPack", "Polygon.cs:Polygon(DatLoader.Entity.Polygon, CVertexArray)", "the DAT constructor")
    def from_dat(cls, polygon, vertex_array) -> "Polygon":
        """``new Polygon(DatLoader.Entity.Polygon, CVertexArray)``: no Init (PolyID stays 0), the
        DAT vertices by id (VertexCache is off: a new Vertex each), then make_plane, run when the
        plane is first read (make_plane_when_read: no one moves a DAT polygon's vertices, and most
        of a cell's or an object's planes are never read in a run)."""
        p = cls.__new__(cls)
        p.poly_id = 0
        p.neg_surface = polygon.neg_surface
        p.num_points = polygon.num_pts
        p.pos_surface = polygon.pos_surface
        p.sides_type = polygon.sides_type
        p.vertex_ids = polygon.vertex_ids
        p.vertices = []
        vertices = vertex_array.vertices
        for vertex_idx in p.vertex_ids:
            sw_vertex = vertices.get(vertex_idx & 0xFFFF)  # (ushort)vertexIdx
            if sw_vertex is None:
                raise KeyNotFoundException(f"The given key '{vertex_idx & 0xFFFF}' was not present in the dictionary.")
            p.vertices.append(Vertex.from_dat(sw_vertex))
        p.plane = None
        p.make_plane_when_read()
        return p

    @classmethod
    @harness("a polygon from a scene PolygonRec (tests and benchmarks build polygons this way)")
    def from_rec(cls, rec, mode: Mode) -> "Polygon":
        """As the DAT constructor would build it from the record's vertices (ids 0..n-1)."""
        p = cls.__new__(cls)
        p.poly_id = 0
        p.pos_surface = 0
        p.neg_surface = 0
        p.num_points = len(rec.vertices)
        p.sides_type = int(rec.sides_type)
        p.vertex_ids = list(range(p.num_points))
        p.vertices = [Vertex(mode.vec(*v), index=i) for i, v in enumerate(rec.vertices)]
        p.plane = None
        p.make_plane()
        return p

    @harness("make_plane when the plane is first read (a terrain polygon: see make_plane_when_read)")
    def make_plane_when_read(self) -> None:
        """Leaves the plane unset: the first read of ``plane`` runs make_plane then (`__getattr__`).
        Only for a polygon whose vertices no one moves afterwards (a landblock's terrain, a DAT
        polygon): its plane is a function of them, so computing it later gives the same bits, and
        most planes are never read (a transition touches a few of a landblock's 64 cells, and a
        few leaves of a cell's or an object's BSP)."""
        del self.plane

    def __getattr__(self, name: str):
        # an unset slot: only `plane` is ever left unset (make_plane_when_read)
        if name != "plane":
            raise AttributeError(f"'Polygon' object has no attribute {name!r}")
        self.make_plane()
        return self.plane

    @anchor(None, "Polygon.cs:Init")
    def init(self) -> None:
        self.poly_id = -1
        self.pos_surface = -1
        self.neg_surface = -1

    def __repr__(self) -> str:
        return f"Polygon(id={self.poly_id}, points={[v.origin if v else None for v in self.vertices]}, plane={self.plane!r})"

    @anchor("CPolygon::adjust_sphere_to_plane", "Polygon.cs:adjust_sphere_to_plane")
    def adjust_sphere_to_plane(self, path, valid_pos, movement: Vector3) -> bool:
        """Moves valid_pos (a Sphere, mutated) back onto the plane; sets path.walk_interp."""
        dp_pos = dot(valid_pos.center, self.plane.normal) + self.plane.d
        dp_move = dot(movement, self.plane.normal)

        if dp_move <= EPSILON:
            if dp_move >= -EPSILON:
                return False
            dist = dp_pos - valid_pos.radius
        else:
            dist = -valid_pos.radius - dp_pos

        i_dist = dist / dp_move
        interp = (1.0 - i_dist) * path.walk_interp
        if interp >= path.walk_interp or interp < ADJUST_TO_PLANE_INTERP_LIMIT:
            return False

        valid_pos.center = valid_pos.center - movement * i_dist
        path.walk_interp = interp
        return True

    @anchor("CPolygon::adjust_sphere_to_poly", "Polygon.cs:adjust_sphere_to_poly")
    def adjust_sphere_to_poly(self, check_pos, curr_pos: Vector3, movement: Vector3):
        """Returns a C# double (the float32 results widen): 1.0, 0.0 or (dist - dpPos) / dpMove."""
        dp_pos = dot(curr_pos, self.plane.normal) + self.plane.d
        if abs(dp_pos) < check_pos.radius:
            return D(1.0)

        dp_move = dot(movement, self.plane.normal)
        if abs(dp_move) < EPSILON:
            return D(0.0)

        dist = check_pos.radius
        if movement.length_squared() <= dist * dist:
            dist *= -1.0

        return D((dist - dp_pos) / dp_move)

    @anchor("CPolygon::adjust_to_placement_poly", "Polygon.cs:adjust_to_placement_poly")
    def adjust_to_placement_poly(self, hit_sphere, other_sphere, radius, center_solid: bool, solid_check: bool) -> None:
        """Pushes hit_sphere (and other_sphere, when given) out along the plane normal (mutated)."""
        dp = dot(hit_sphere.center, self.plane.normal) + self.plane.d
        if solid_check and (center_solid or dp <= 0.0):
            radius *= -1.0
        diff = radius - dp
        adjusted = self.plane.normal * diff
        hit_sphere.center = hit_sphere.center + adjusted
        if other_sphere is not None:
            other_sphere.center = other_sphere.center + adjusted

    @anchor("CPolygon::check_small_walkable", "Polygon.cs:check_small_walkable")
    def check_small_walkable(self, sphere, up: Vector3) -> bool:
        return self.check_walkable(sphere, up, True)

    @anchor("CPolygon::check_walkable", "Polygon.cs:check_walkable")
    def check_walkable(self, sphere, up: Vector3, small: bool = False) -> bool:
        angle_up = dot(self.plane.normal, up)
        if angle_up < EPSILON:
            return False

        result = True

        center = sphere.center - up * ((dot(self.plane.normal, sphere.center) + self.plane.d) / angle_up)
        radsum = sphere.radius * sphere.radius
        if small:
            radsum *= 0.25

        vertices = self.vertices
        prev_idx = self.num_points - 1
        for i in range(len(vertices)):
            vertex = vertices[i]
            last_vertex = vertices[prev_idx]
            prev_idx = i

            edge = vertex - last_vertex
            disp = center - last_vertex.origin
            cross_ = cross(self.plane.normal, edge)
            diff = dot(disp, cross_)

            if diff < 0.0:
                if cross_.length_squared() * radsum < diff * diff:
                    return False

                disp_edge = dot(disp, edge)
                if disp_edge >= 0.0 and disp_edge <= edge.length_squared():
                    return True

                return False

            if disp.length_squared() <= radsum:
                return True

        return result

    @anchor("CPolygon::find_crossed_edge", "Polygon.cs:find_crossed_edge")
    def find_crossed_edge(self, sphere, up: Vector3, normal: Vector3) -> tuple[bool, Vector3]:
        """``find_crossed_edge(sphere, up, ref normal)``: returns (found, normal after the call)."""
        angle_up = dot(self.plane.normal, up)
        if abs(angle_up) < EPSILON:
            return False, normal

        angle = (dot(self.plane.normal, sphere.center) + self.plane.d) / angle_up
        center = sphere.center - up * angle

        vertices = self.vertices
        prev_idx = self.num_points - 1
        for i in range(len(vertices)):
            vertex = vertices[i]
            last_vertex = vertices[prev_idx]
            prev_idx = i

            edge = vertex - last_vertex
            disp = center - last_vertex.origin
            cross_ = cross(self.plane.normal, edge)

            if dot(disp, cross_) < 0.0:
                normal = cross_ * (1.0 / cross_.length())
                return True, normal
        return False, normal

    @anchor("CPolygon::hits_sphere", "Polygon.cs:hits_sphere")
    def hits_sphere(self, sphere, trace=None) -> bool:
        contact_point = zero_like(sphere.radius)
        hit, _ = self.polygon_hits_sphere_precise(sphere, contact_point, trace)
        return hit

    @anchor("CPolygon::make_plane", "Polygon.cs:make_plane")
    def make_plane(self) -> None:
        vertices = self.vertices
        normal = zero_like(vertices[0].origin.x)

        # calculate plane normal: a fan of cross products from vertex 0
        spread_idx = 1
        for _ in range(self.num_points - 2, 0, -1):
            v1 = vertices[spread_idx] - vertices[0]
            spread_idx += 1
            v2 = vertices[spread_idx] - vertices[0]
            normal = normal + cross(v1, v2)
        normal = normalize(normal)

        # calculate distance
        dist_sum = type(normal.x)(0.0)
        for spread in range(self.num_points):
            dist_sum += dot(normal, vertices[spread].origin)

        dist = -(dist_sum / self.num_points)
        self.plane = Plane(normal, dist)

    @anchor("CPolygon::point_in_poly2D", "Polygon.cs:point_in_poly2D")
    def point_in_poly2D(self, point: Vector3, side: Sidedness) -> bool:
        vertices = self.vertices
        positive = side == Sidedness.Positive
        prev_idx = 0
        for i in range(self.num_points - 1, -1, -1):
            prev_vertex = vertices[prev_idx].origin
            vertex = vertices[i].origin

            # diff = vertex - prevVertex; its z is never read
            diff_x = vertex.x - prev_vertex.x
            diff_y = vertex.y - prev_vertex.y

            diff_cross = (diff_y * vertex.x) - (diff_x * vertex.y) + (diff_x * point.y) - (diff_y * point.x)

            if not positive:
                if diff_cross < 0.0:
                    return False
            else:
                if diff_cross > 0.0:
                    return False
            prev_idx = i
        return True

    @anchor("CPolygon::point_in_polygon", "Polygon.cs:point_in_polygon")
    def point_in_polygon(self, point: Vector3) -> bool:
        last_vertex = self.vertices[self.num_points - 1]
        for vertex in self.vertices:
            cross_ = cross(self.plane.normal, vertex - last_vertex)
            dp = dot(cross_, point - last_vertex.origin)
            if dp < 0.0:
                return False
            last_vertex = vertex
        return True

    @anchor("CPolygon::polygon_hits_ray", "Polygon.cs:polygon_hits_ray")
    def polygon_hits_ray(self, ray: Ray, time) -> tuple[bool, object]:
        """``polygon_hits_ray(ray, ref time)``: returns (hit, time after the call)."""
        if self.sides_type == CullMode.Landblock and dot(self.plane.normal, ray.dir) > 0.0:
            return False, time

        ok, time = compute_time_of_intersection(self.plane, ray, time)
        if not ok:
            return False, time

        return self.point_in_polygon(ray.point + ray.dir * time), time

    @anchor("CPolygon::polygon_hits_sphere", "Polygon.cs:polygon_hits_sphere")
    def polygon_hits_sphere(self, sphere, contact_point: Vector3) -> tuple[bool, Vector3]:
        """``polygon_hits_sphere(sphere, ref contactPoint)``: returns (hit, contact_point)."""
        dp_pos = dot(sphere.center, self.plane.normal) + self.plane.d
        rad = sphere.radius - EPSILON

        if abs(dp_pos) > rad:
            return False, contact_point

        diff = rad * rad - dp_pos * dp_pos
        result = True

        contact_point = sphere.center - self.plane.normal * dp_pos

        vertices = self.vertices
        prev_idx = self.num_points - 1
        for i in range(len(vertices)):
            vertex = vertices[i]
            last_vertex = vertices[prev_idx]
            prev_idx = i

            edge = vertex - last_vertex
            disp = contact_point - last_vertex.origin
            cross_ = cross(self.plane.normal, edge)
            dp = dot(disp, cross_)
            if dp < 0.0:
                if cross_.length_squared() * diff < dp * dp:
                    return False, contact_point

                disp_edge = dot(disp, edge)
                if disp_edge >= 0.0 and disp_edge <= edge.length_squared():
                    return True, contact_point

                result = False

            if disp.length_squared() <= diff:
                return True, contact_point

        return result, contact_point

    @anchor("CPolygon::polygon_hits_sphere_precise", "Polygon.cs:polygon_hits_sphere_precise")
    def polygon_hits_sphere_precise(self, sphere, contact_point: Vector3, trace=None) -> tuple[bool, Vector3]:
        """``polygon_hits_sphere_precise(sphere, ref contactPoint)``: returns (hit, contact_point).
        `trace` (not ACE's: the run's branches.Trace or None) counts the plane_tangent,
        polygon_edge and polygon_vertex boundaries where their comparisons are made.

        The loop structure is ACE's: the outer loop only looks for the first edge the contact
        point lies outside of; from there the inner loop re-runs every edge from the start and
        always returns (the two loops share prev_idx, as in ACE).
        """
        if self.num_points == 0:
            return True, contact_point

        plane = self.plane
        dp_pos = dot(plane.normal, sphere.center) + plane.d
        rad = sphere.radius - EPSILON
        if trace is not None:
            trace.boundary("plane_tangent", abs(dp_pos), rad)
        if abs(dp_pos) > rad:
            return False, contact_point

        diff = rad * rad - dp_pos * dp_pos
        contact_point = sphere.center - plane.normal * dp_pos

        vertices = self.vertices
        prev_idx = self.num_points - 1
        for i in range(len(vertices)):
            vertex = vertices[i]
            last_vertex = vertices[prev_idx]
            prev_idx = i

            edge = vertex - last_vertex
            disp = contact_point - last_vertex.origin
            cross_ = cross(plane.normal, edge)

            if dot(disp, cross_) >= 0.0:
                continue

            # inner loop
            prev_idx = self.num_points - 1
            for j in range(len(vertices)):
                vertex = vertices[j]
                last_vertex = vertices[prev_idx]
                prev_idx = j

                edge = vertex - last_vertex
                disp = contact_point - last_vertex.origin
                cross_ = cross(plane.normal, edge)
                disp_dot = dot(disp, cross_)

                if disp_dot < 0.0:
                    if trace is not None:
                        trace.boundary("polygon_edge", cross_.length_squared() * diff, disp_dot * disp_dot)
                    if cross_.length_squared() * diff < disp_dot * disp_dot:
                        return False, contact_point

                    disp_edge = dot(disp, edge)
                    if disp_edge >= 0.0 and disp_edge <= edge.length_squared():
                        return True, contact_point

                if trace is not None:
                    trace.boundary("polygon_vertex", disp.length_squared(), diff)
                if disp.length_squared() <= diff:
                    return True, contact_point
            return False, contact_point
        return True, contact_point

    @anchor("CPolygon::pos_hits_sphere", "Polygon.cs:pos_hits_sphere")
    def pos_hits_sphere(self, sphere, movement: Vector3, contact_point: Vector3, hit_poly, trace=None) -> tuple[bool, Vector3, "Polygon | None"]:
        """``pos_hits_sphere(sphere, movement, ref contactPoint, ref hitPoly)``.

        Returns (result, contact_point, hit_poly). hit_poly becomes this polygon whenever the
        sphere touches it, even when the result is False because the movement is not into the
        front face (dot(movement, normal) >= 0): BSP callers test ``hit_poly is not None``.
        """
        hit, contact_point = self.polygon_hits_sphere_precise(sphere, contact_point, trace)

        if hit:
            hit_poly = self

        dist = dot(movement, self.plane.normal)
        if dist >= 0.0:
            return False, contact_point, hit_poly

        return hit, contact_point, hit_poly

    @anchor("CPolygon::walkable_hits_sphere", "Polygon.cs:walkable_hits_sphere")
    def walkable_hits_sphere(self, path, sphere, up: Vector3) -> bool:
        dp = dot(up, self.plane.normal)
        if path.trace is not None:
            path.trace.walkable(dp, path.walkable_allowance)
        if dp <= path.walkable_allowance:
            return False
        contact_point = zero_like(sphere.radius)
        hit, _ = self.polygon_hits_sphere_precise(sphere, contact_point, path.trace)
        return hit
