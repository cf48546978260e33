"""ACE's own functions on plain data: Polygon, Sphere, LandDefs, LandblockStruct/Landblock, AFrame, Position.

`AceFunctions()` loads the configured ACE build (oracle/config.py, oracle/runtime.py) and calls
single ACE routines -- not whole transitions -- with plain Python values in and plain values
out, for the per-function differential tests (tests/port/functions). Every value that comes
back is a Python bool, int, float (``float(System.Single)``: exactly the float32; a C# double
stays a double), tuple or None; no .NET object leaves this module. Vectors are ``(x, y, z)``,
planes ``(nx, ny, nz, d)``, spheres ``(center, radius)``, frames ``((x, y, z), (w, x, y, z))``
with the orientation written (w, x, y, z) as the scene files do.

Polygons are built as ACE builds terrain polygons: ``Polygon(idx, numPoints, CullMode)``, each
vertex a ``Vertex(Vector3)``, then ``make_plane()``. ACE's ref/out parameters come back in the
returned tuple. An exception ACE throws is returned as ``("error", "<.NET type name>")`` where
the routine is specified to throw (e.g. ``.Value`` of an empty ``Vector2?``), so a test can
compare it with the port's exception.

Every ACE member used here is listed in oracle/members.py and checked when ACE loads.
"""

from __future__ import annotations

from ..errors import OracleUnavailable
from . import config
from . import runtime as _rt


def _v(x) -> tuple[float, float, float]:
    return (float(x.X), float(x.Y), float(x.Z))


class AceFunctions:
    """Single ACE routines called from Python. One instance per process (the runtime is per process)."""

    def __init__(self, ace=None, runtime: str | None = None):
        location = config.resolve(ace, runtime)
        if location is None:
            raise OracleUnavailable(f"no ACE assembly configured for the function oracle; {config.HOW_TO_SET}")
        self.ace = _rt.load(location)
        label = config.ace_label()
        self.ace_version = f"{label} ({self.ace.ace_version})" if label else self.ace.ace_version
        self.runtime_version = self.ace.runtime_version

        import clr  # noqa: F401
        from ACE.DatLoader.FileTypes import CellLandblock
        from ACE.Entity.Enum import CullMode, Sidedness
        from ACE.Server.Physics import PhysicsEngine, Polygon, Ray, Sphere
        from ACE.Server.Physics.Animation import AFrame, SpherePath
        from ACE.Server.Physics.Common import (
            Landblock,
            LandDefs,
            LScape,
            ObjectMaint,
            Position,
            SmartBox,
        )
        from ACE.Server.Physics.Entity import Vertex
        from System import Array, Byte, Single
        from System import Exception as NetException
        from System.Collections.Generic import List
        from System.IO import BinaryReader, MemoryStream
        from System.Numerics import Plane, Quaternion, Vector3

        # named explicitly (not locals()): a linter that drops "unused" imports cannot break it
        self._n = {
            "Array": Array, "Byte": Byte, "Single": Single, "List": List, "BinaryReader": BinaryReader,
            "MemoryStream": MemoryStream, "Plane": Plane, "Quaternion": Quaternion, "Vector3": Vector3,
            "CellLandblock": CellLandblock, "CullMode": CullMode, "Sidedness": Sidedness,
            "PhysicsEngine": PhysicsEngine, "Polygon": Polygon, "Ray": Ray, "Sphere": Sphere, "AFrame": AFrame,
            "SpherePath": SpherePath, "LandDefs": LandDefs, "Landblock": Landblock, "LScape": LScape,
            "ObjectMaint": ObjectMaint, "Position": Position, "SmartBox": SmartBox, "Vertex": Vertex,
        }
        self._net_exception = NetException
        self._landblocks: dict = {}  # key -> ACE Landblock, for get_z / get_landcell / calc_water_depth

    # ---------------------------------------------------------------- building ACE values
    def _vec(self, v):
        return self._n["Vector3"](float(v[0]), float(v[1]), float(v[2]))

    def _sphere(self, s):
        return self._n["Sphere"](self._vec(s[0]), float(s[1]))

    def _quat(self, q):
        w, x, y, z = q
        return self._n["Quaternion"](float(x), float(y), float(z), float(w))

    def _frame(self, f):
        return self._n["AFrame"](self._vec(f[0]), self._quat(f[1]))

    def _position(self, p):
        cell, frame = p
        return self._n["Position"](int(cell), self._frame(frame))

    def polygon(self, vertices, sides_type: int = 0):
        """ACE's terrain constructor with the given vertices, then make_plane (a .NET Polygon)."""
        n = self._n
        poly = n["Polygon"](0, len(vertices), n["CullMode"](int(sides_type)))
        for k, v in enumerate(vertices):
            poly.Vertices[k] = n["Vertex"](self._vec(v))
            poly.VertexIDs[k] = k
        poly.make_plane()
        return poly

    def _error(self, e) -> tuple[str, str]:
        inner = e
        while inner.GetType().Name == "TargetInvocationException" and inner.InnerException is not None:
            inner = inner.InnerException
        return ("error", str(inner.GetType().Name))

    # ---------------------------------------------------------------- Polygon
    def make_plane(self, vertices) -> tuple[float, float, float, float]:
        p = self.polygon(vertices).Plane
        return (*_v(p.Normal), float(p.D))

    def point_in_poly2D(self, vertices, point, side: int) -> bool:
        return bool(self.polygon(vertices).point_in_poly2D(self._vec(point), self._n["Sidedness"](int(side))))

    def point_in_polygon(self, vertices, point) -> bool:
        return bool(self.polygon(vertices).point_in_polygon(self._vec(point)))

    def find_crossed_edge(self, vertices, sphere, up, normal) -> tuple[bool, tuple]:
        ok, out = self.polygon(vertices).find_crossed_edge(self._sphere(sphere), self._vec(up), self._vec(normal))
        return bool(ok), _v(out)

    def polygon_hits_sphere(self, vertices, sphere, contact) -> tuple[bool, tuple]:
        ok, out = self.polygon(vertices).polygon_hits_sphere(self._sphere(sphere), self._vec(contact))
        return bool(ok), _v(out)

    def polygon_hits_sphere_precise(self, vertices, sphere, contact) -> tuple[bool, tuple]:
        ok, out = self.polygon(vertices).polygon_hits_sphere_precise(self._sphere(sphere), self._vec(contact))
        return bool(ok), _v(out)

    def hits_sphere(self, vertices, sphere) -> bool:
        return bool(self.polygon(vertices).hits_sphere(self._sphere(sphere)))

    def pos_hits_sphere(self, vertices, sphere, movement, contact) -> tuple[bool, tuple, bool]:
        """(result, contactPoint after, whether hitPoly was set to this polygon; it starts null)."""
        poly = self.polygon(vertices)
        ok, out, hit_poly = poly.pos_hits_sphere(self._sphere(sphere), self._vec(movement), self._vec(contact), None)
        return bool(ok), _v(out), hit_poly is not None and hit_poly.Equals(poly)

    def walkable_hits_sphere(self, vertices, walkable_allowance, sphere, up) -> bool:
        path = self._n["SpherePath"]()
        path.WalkableAllowance = float(walkable_allowance)
        return bool(self.polygon(vertices).walkable_hits_sphere(path, self._sphere(sphere), self._vec(up)))

    def check_walkable(self, vertices, sphere, up, small: bool) -> bool:
        return bool(self.polygon(vertices).check_walkable(self._sphere(sphere), self._vec(up), bool(small)))

    def check_small_walkable(self, vertices, sphere, up) -> bool:
        return bool(self.polygon(vertices).check_small_walkable(self._sphere(sphere), self._vec(up)))

    def adjust_sphere_to_plane(self, vertices, walk_interp, sphere, movement) -> tuple[bool, float, tuple]:
        """(result, path.WalkInterp after, validPos.Center after)."""
        path = self._n["SpherePath"]()
        path.WalkInterp = float(walk_interp)
        s = self._sphere(sphere)
        ok = self.polygon(vertices).adjust_sphere_to_plane(path, s, self._vec(movement))
        return bool(ok), float(path.WalkInterp), _v(s.Center)

    def adjust_sphere_to_poly(self, vertices, sphere, curr_pos, movement) -> float:
        """A C# double."""
        return float(self.polygon(vertices).adjust_sphere_to_poly(self._sphere(sphere), self._vec(curr_pos), self._vec(movement)))

    def adjust_to_placement_poly(self, vertices, hit_sphere, other_sphere, radius, center_solid, solid_check):
        """(hitSphere.Center after, otherSphere.Center after or None)."""
        hit = self._sphere(hit_sphere)
        other = self._sphere(other_sphere) if other_sphere is not None else None
        self.polygon(vertices).adjust_to_placement_poly(hit, other, float(radius), bool(center_solid), bool(solid_check))
        return _v(hit.Center), (_v(other.Center) if other is not None else None)

    def polygon_hits_ray(self, vertices, sides_type: int, ray, time) -> tuple[bool, float]:
        """ray = (point, dir, length); returns (hit, time after)."""
        r = self._n["Ray"](self._vec(ray[0]), self._vec(ray[1]), float(ray[2]))
        ok, t = self.polygon(vertices, sides_type).polygon_hits_ray(r, float(time))
        return bool(ok), float(t)

    # ---------------------------------------------------------------- Sphere
    def find_time_of_collision(self, movement, sphere_pos, rad_sum) -> float:
        """A C# double."""
        return float(self._n["Sphere"].FindTimeOfCollision(self._vec(movement), self._vec(sphere_pos), float(rad_sum)))

    def collides_with_sphere(self, other, radsum) -> bool:
        return bool(self._n["Sphere"].CollidesWithSphere(self._vec(other), float(radsum)))

    def sphere_intersects(self, a, b) -> bool:
        return bool(self._sphere(a).Intersects(self._sphere(b)))

    def sphere_intersects_ray(self, sphere, ray) -> tuple[bool, float]:
        """(hit, timeOfIntersection: a C# double)."""
        r = self._n["Ray"](self._vec(ray[0]), self._vec(ray[1]), float(ray[2]))
        ok, t = self._sphere(sphere).SphereIntersectsRay(r, 0.0)
        return bool(ok), float(t)

    # ---------------------------------------------------------------- LandDefs
    def get_block_offset(self, cell_from: int, cell_to: int):
        try:
            return _v(self._n["LandDefs"].GetBlockOffset(int(cell_from), int(cell_to)))
        except self._net_exception as e:
            return self._error(e)

    def adjust_to_outside(self, block_cell_id: int, loc) -> tuple[bool, int, tuple]:
        ok, cell, out = self._n["LandDefs"].AdjustToOutside(int(block_cell_id), self._vec(loc))
        return bool(ok), int(cell), _v(out)

    def _lcoord(self, v):
        return None if v is None else (float(v.X), float(v.Y))

    def blockid_to_lcoord(self, cell_id: int):
        return self._lcoord(self._n["LandDefs"].blockid_to_lcoord(int(cell_id)))

    def gid_to_lcoord(self, cell_id: int, env_check: bool = True):
        return self._lcoord(self._n["LandDefs"].gid_to_lcoord(int(cell_id), bool(env_check)))

    def get_outside_lcoord(self, block_cell_id: int, x, y):
        return self._lcoord(self._n["LandDefs"].get_outside_lcoord(int(block_cell_id), float(x), float(y)))

    def lcoord_to_gid(self, x, y) -> int:
        return int(self._n["LandDefs"].lcoord_to_gid(float(x), float(y)))

    def inbound_valid_cellid(self, cell_id: int) -> bool:
        return bool(self._n["LandDefs"].inbound_valid_cellid(int(cell_id)))

    def cell_in_range(self, cell_id: int) -> bool:
        return bool(self._n["LandDefs"].cell_in_range(int(cell_id)))

    def in_block(self, pos, radius) -> bool:
        return bool(self._n["LandDefs"].InBlock(self._vec(pos), float(radius)))

    # ---------------------------------------------------------------- LandblockStruct / Landblock
    def _landblock(self, lb_id: int, heights, terrain, table):
        """A PostInit'ed ACE Landblock from CellLandblock bytes, registered in the client LScape."""
        import struct

        n = self._n
        key = (int(lb_id) | 0xFFFF, tuple(heights), tuple(terrain), tuple(table))
        plb = self._landblocks.get(key)
        if plb is None:
            if len(self._landblocks) > 256:
                self._landblocks.clear()
            self._engine(server=True)  # Generate reads PhysicsEngine.Instance.Server (the server skips UVs)
            values = n["List"][n["Single"]]()
            for h in table:
                values.Add(float(h))
            n["LandDefs"].LandHeightTable = values
            data = struct.pack("<II81H", key[0], 0, *terrain) + bytes(heights) + b"\0"
            clb = n["CellLandblock"]()
            clb.Unpack(n["BinaryReader"](n["MemoryStream"](n["Array"][n["Byte"]](bytearray(data)))))
            plb = n["Landblock"](clb)
            n["Landblock"].UseSceneFiles = False  # no region DAT: no generated scenery (as the live oracle)
            plb.PostInit()
            self._landblocks[key] = plb
        return plb

    def landblock_struct(self, lb_id: int, heights, terrain, table) -> dict:
        """What LandblockStruct(CellLandblock) + Landblock builds: vertex origins, polygon vertex ids
        and planes, the split per cell, cell ids and origins, water per cell and for the block."""
        plb = self._landblock(lb_id, heights, terrain, table)
        vertices = [_v(v.Origin) for v in plb.VertexArray.Vertices]
        polygons = []
        for p in plb.Polygons:
            polygons.append((tuple(int(i) for i in p.VertexIDs), (*_v(p.Plane.Normal), float(p.Plane.D)), int(p.PosSurface)))
        cells = []
        for i in range(int(plb.SideCellCount) ** 2):
            c = plb.LandCells[i]
            cells.append((int(c.ID), _v(c.Pos.Frame.Origin), int(c.WaterType)))
        return {
            "vertices": vertices, "polygons": polygons, "sw_to_ne_cut": [bool(b) for b in plb.SWtoNEcut],
            "cells": cells, "water_type": int(plb.WaterType), "min_z": float(plb.MinZ), "max_z": float(plb.MaxZ),
        }

    def calc_water_depth(self, landblock, block_cell_id: int, point):
        """landblock = (id, heights, terrain, table)."""
        plb = self._landblock(*landblock)
        try:
            return float(plb.calc_water_depth(int(block_cell_id), self._vec(point)))
        except self._net_exception as e:
            return self._error(e)

    def _engine(self, server: bool):
        """A PhysicsEngine instance (ACE's static PhysicsEngine.Instance) in server or client mode."""
        n = self._n
        eng = n["PhysicsEngine"].Instance
        if eng is None:
            eng = n["PhysicsEngine"](n["ObjectMaint"](), n["SmartBox"]())
        eng.Server = bool(server)
        return eng

    def _client_lscape(self, plb):
        """GetCell reads the static LScape: a client engine with only this landblock loaded
        (the live oracle clears LScape and makes its own engine for every scene)."""
        n = self._n
        self._engine(server=False)
        n["LScape"].Landblocks.Clear()
        n["LScape"].Landblocks[plb.ID | 0xFFFF] = plb

    def get_z(self, landblock, points) -> list[float]:
        """Landblock.GetZ for each point (one landblock setup for the batch)."""
        plb = self._landblock(*landblock)
        self._client_lscape(plb)
        try:
            return [float(plb.GetZ(self._vec(p))) for p in points]
        finally:
            self._n["LScape"].Landblocks.Clear()
            self._engine(server=True)  # ACE's server default, as the live oracle leaves it

    def get_landcell(self, landblock, cell_ids) -> list:
        """Landblock.get_landcell for each id: the cell's ID, None, or ("error", type)."""
        plb = self._landblock(*landblock)
        out = []
        for cid in cell_ids:
            try:
                c = plb.get_landcell(int(cid))
                out.append(None if c is None else int(c.ID))
            except self._net_exception as e:
                out.append(self._error(e))
        return out

    # ---------------------------------------------------------------- AFrame / Position
    def frame_local_to_global(self, frame, point) -> tuple:
        return _v(self._frame(frame).LocalToGlobal(self._vec(point)))

    def frame_global_to_local(self, frame, point) -> tuple:
        return _v(self._frame(frame).GlobalToLocal(self._vec(point)))

    def frame_local_to_global_vec(self, frame, point) -> tuple:
        return _v(self._frame(frame).LocalToGlobalVec(self._vec(point)))

    def frame_global_to_local_vec(self, frame, point) -> tuple:
        return _v(self._frame(frame).GlobalToLocalVec(self._vec(point)))

    def frame_combine(self, a, b) -> tuple:
        f = self._n["AFrame"].Combine(self._frame(a), self._frame(b))
        q = f.Orientation
        return (_v(f.Origin), (float(q.W), float(q.X), float(q.Y), float(q.Z)))

    def position_get_offset(self, a, b):
        try:
            return _v(self._position(a).GetOffset(self._position(b)))
        except self._net_exception as e:
            return self._error(e)

    def position_local_to_local(self, a, b, offset):
        try:
            return _v(self._position(a).LocalToLocal(self._position(b), self._vec(offset)))
        except self._net_exception as e:
            return self._error(e)

    def position_local_to_global_from(self, a, b, point):
        """Position.LocalToGlobal(Position pos, Vector3 point): b's local point in a's block."""
        try:
            return _v(self._position(a).LocalToGlobal(self._position(b), self._vec(point)))
        except self._net_exception as e:
            return self._error(e)

    # ---------------------------------------------------------------- Trajectory, Trajectory2 (the launch solvers)
    def _trajectory(self):
        from ACE.Server.Physics import Trajectory, Trajectory2

        return Trajectory, Trajectory2

    def solve_quadric(self, c0, c1, c2) -> tuple:
        """(num, s0, s1): C# doubles."""
        r = self._trajectory()[0].SolveQuadric(float(c0), float(c1), float(c2), 0.0, 0.0)
        return (int(r[0]), float(r[1]), float(r[2]))

    def solve_cubic(self, c0, c1, c2, c3) -> tuple:
        r = self._trajectory()[0].SolveCubic(float(c0), float(c1), float(c2), float(c3), 0.0, 0.0, 0.0)
        return (int(r[0]), *(float(x) for x in r[1:]))

    def solve_quartic(self, c0, c1, c2, c3, c4) -> tuple:
        r = self._trajectory()[0].SolveQuartic(float(c0), float(c1), float(c2), float(c3), float(c4), 0.0, 0.0, 0.0, 0.0)
        return (int(r[0]), *(float(x) for x in r[1:]))

    def ballistic_range(self, speed, gravity, initial_height) -> float:
        return float(self._trajectory()[0].ballistic_range(float(speed), float(gravity), float(initial_height)))

    def solve_ballistic_arc(self, proj_pos, proj_speed, target, gravity) -> tuple:
        """(num, s0, s1, t0, t1): the fixed-target overload."""
        z = self._vec((0, 0, 0))
        r = self._trajectory()[0].solve_ballistic_arc(self._vec(proj_pos), float(proj_speed), self._vec(target),
                                                      float(gravity), z, z, 0.0, 0.0)
        return (int(r[0]), _v(r[1]), _v(r[2]), float(r[3]), float(r[4]))

    def solve_ballistic_arc_moving(self, proj_pos, proj_speed, target, target_velocity, gravity) -> tuple:
        """(num, s0, s1, time): the moving-target overload."""
        z = self._vec((0, 0, 0))
        r = self._trajectory()[0].solve_ballistic_arc(self._vec(proj_pos), float(proj_speed), self._vec(target),
                                                      self._vec(target_velocity), float(gravity), z, z, 0.0)
        return (int(r[0]), _v(r[1]), _v(r[2]), float(r[3]))

    def solve_ballistic_arc_fixed_gravity(self, proj_pos, lateral_speed, target) -> tuple:
        """SolveBallisticArc: (ok, velocity, time)."""
        z = self._vec((0, 0, 0))
        r = self._trajectory()[0].SolveBallisticArc(self._vec(proj_pos), float(lateral_speed), self._vec(target), z, 0.0)
        return (bool(r[0]), _v(r[1]), float(r[2]))

    def solve_ballistic_arc_lateral_max_height(self, proj_pos, lateral_speed, target, max_height) -> tuple:
        """(ok, fire_velocity, gravity)."""
        z = self._vec((0, 0, 0))
        r = self._trajectory()[0].solve_ballistic_arc_lateral(self._vec(proj_pos), float(lateral_speed), self._vec(target),
                                                              float(max_height), z, 0.0)
        return (bool(r[0]), _v(r[1]), float(r[2]))

    def solve_ballistic_arc_lateral(self, proj_pos, lateral_speed, target, target_velocity, gravity) -> tuple:
        """(ok, fire_velocity, time, impact_point): the moving-target overload."""
        z = self._vec((0, 0, 0))
        r = self._trajectory()[0].solve_ballistic_arc_lateral(self._vec(proj_pos), float(lateral_speed), self._vec(target),
                                                              self._vec(target_velocity), float(gravity), z, 0.0, z)
        return (bool(r[0]), _v(r[1]), float(r[2]), _v(r[3]))

    def calculate_trajectory(self, start_pos, end_pos, target_velocity, speed, gravity: bool) -> tuple:
        return _v(self._trajectory()[1].CalculateTrajectory(self._vec(start_pos), self._vec(end_pos),
                                                             self._vec(target_velocity), float(speed), bool(gravity)))


__all__ = ["AceFunctions"]
