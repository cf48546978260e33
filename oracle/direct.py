"""The pure-pythonnet path: the same scene building and transition as oracle/facade/Facade.cs,
driven object by object from Python. Used when no C# compiler is available; slower (every
member access crosses into .NET) but it needs nothing beyond pythonnet and ACE.

Keep this in step with Facade.cs: tests/oracle/test_live.py runs both on the same scenes and
requires identical outcomes.
"""

from __future__ import annotations

import struct
import time

from ..outcome import ContactPlaneState, NormalState, Outcome
from ..scene import BSPLeaf, CylSphereShape, Scene, SphereShape
from ..staging import MOVER_ID, mover_setup_dims, shadow_cells
from .pack import landblock_bytes


class DirectRunner:
    def __init__(self):
        import clr  # noqa: F401
        from System import Array, Byte, Single
        from System.Collections.Generic import List
        from System.IO import BinaryReader, MemoryStream
        from System.Numerics import Plane, Quaternion, Vector3
        from System.Reflection import BindingFlags
        from System.Runtime.Serialization import FormatterServices

        from ACE.DatLoader.FileTypes import CellLandblock, SetupModel
        from ACE.Entity import LandblockId
        from ACE.Entity.Enum import CullMode, PhysicsState
        from System import Exception as NetException
        from ACE.Server.Physics import TransientStateFlags
        from ACE.Server.Physics import PartArray, PhysicsEngine, PhysicsGlobals, PhysicsObj, PhysicsPart, Polygon, Setup, Sphere
        from ACE.Server.Physics.Animation import AFrame, Transition
        from ACE.Server.Physics.BSP import BSPLeaf as NetLeaf, BSPNode as NetNode, BSPTree, BSPTreeType
        from ACE.Server.Physics.Collision import GfxObj
        from ACE.Server.Physics.Common import LandDefs, Landblock, LScape, ObjectMaint, Position, SmartBox
        from ACE.Server.Physics.Entity import BSPCache, PolygonCache, Vertex, VertexCache
        from ACE.Server.Physics.Managers import ServerObjectManager
        from ACE.Server.Physics.Util import AdjustCell
        import ACE.Server.Entity as server_entity
        import ACE.Server.Managers as managers

        self.n = locals()
        self.cache_landblocks = True
        self.cache = {}
        nonpublic = BindingFlags.NonPublic
        lbm = clr.GetClrType(managers.LandblockManager)
        self._table = lbm.GetField("landblocks", nonpublic | BindingFlags.Static).GetValue(None)
        slb = clr.GetClrType(server_entity.Landblock)
        self._slb_type = slb
        self._slb_physics = slb.GetField("<PhysicsLandblock>k__BackingField", nonpublic | BindingFlags.Instance)
        self._slb_id = slb.GetField("<Id>k__BackingField", nonpublic | BindingFlags.Instance)
        self._used = []

    # ---------------------------------------------------------------- helpers
    def _reader(self, data: bytes):
        n = self.n
        return n["BinaryReader"](n["MemoryStream"](n["Array"][n["Byte"]](bytearray(data))))

    def _pos(self, p):
        n = self.n
        w, x, y, z = p.frame.orientation
        return n["Position"](p.cell, n["AFrame"](n["Vector3"](*p.frame.origin), n["Quaternion"](x, y, z, w)))

    def _setup(self, spheres, cyls, height, radius, up, down, sorting):
        b = struct.pack("<III", 0x02000001, 0, 0) + struct.pack("<iii", 0, 0, 0)
        b += struct.pack("<i", len(cyls)) + b"".join(struct.pack("<5f", *c) for c in cyls)
        b += struct.pack("<i", len(spheres)) + b"".join(struct.pack("<4f", *s) for s in spheres)
        b += struct.pack("<4f", height, radius, up, down) + struct.pack("<4f", *sorting) * 2
        b += struct.pack("<i", 0) + struct.pack("<5I", 0, 0, 0, 0, 0)
        model = self.n["SetupModel"]()
        model.Unpack(self._reader(b))
        return self.n["Setup"](model)

    def _part_array(self, owner, setup):
        n = self.n
        pa = n["PartArray"]()
        pa.Owner = owner
        pa.Setup = setup
        pa.NumParts = 0
        pa.Parts = n["List"][n["PhysicsPart"]]()
        return pa

    # ---------------------------------------------------------------- scene
    def _reset(self, server: bool):
        n = self.n
        eng = n["PhysicsEngine"](n["ObjectMaint"](), n["SmartBox"]())
        eng.Server = True
        n["LScape"].Landblocks.Clear()
        n["AdjustCell"].AdjustCells.Clear()
        n["VertexCache"].Vertices.Clear()
        n["PolygonCache"].Polygons.Clear()
        n["BSPCache"].BSPTrees.Clear()
        n["ServerObjectManager"].ServerObjects.Clear()
        for x, y in self._used:
            self._table.SetValue(None, x, y)
        self._used.clear()
        n["Landblock"].UseSceneFiles = False
        return eng

    def run(self, scene: Scene):
        t0 = time.perf_counter()
        us = 0.0
        statics = []
        try:
            obj, old, new = self._build(scene, statics)
            trans, ok, us = self._transition(obj, old, new)
            out = self._outcome(trans, ok, obj)
        except self.n["NetException"] as e:  # an ACE exception is the verdict
            inner = e
            while inner.GetType().Name == "TargetInvocationException" and inner.InnerException is not None:
                inner = inner.InnerException
            out = Outcome(error=f"{inner.GetType().Name}: {inner.Message}")
        except Exception as e:  # the bridge itself failed: not a verdict
            from ..errors import OracleError

            raise OracleError(f"the pure-pythonnet oracle path failed outside ACE: {type(e).__name__}: {e}") from None
        finally:
            for s in statics:
                s.remove_shadows_from_cells()
        return out, us, (time.perf_counter() - t0) * 1e6

    def _build(self, scene: Scene, statics: list):
        n = self.n
        server = scene.engine_mode == "server"
        eng = self._reset(server)
        table = n["List"][n["Single"]]()
        for h in scene.land_height_table:
            table.Add(h)
        n["LandDefs"].LandHeightTable = table
        built = []
        for lb in scene.landblocks:
            data = landblock_bytes(lb)
            key = (data, scene.land_height_table)
            plb = self.cache.get(key) if self.cache_landblocks else None
            if plb is None:
                clb = n["CellLandblock"]()
                clb.Unpack(self._reader(data))
                plb = n["Landblock"](clb)
                built.append(plb)
                if self.cache_landblocks:
                    if len(self.cache) > 2048:
                        self.cache.clear()
                    self.cache[key] = plb
            lid = lb.id | 0xFFFF
            n["LScape"].Landblocks[lid] = plb
            if server:
                ident = n["LandblockId"](lid)
                slb = n["FormatterServices"].GetUninitializedObject(self._slb_type)
                self._slb_physics.SetValue(slb, plb)
                if self._slb_id is not None:
                    self._slb_id.SetValue(slb, ident)
                self._table.SetValue(slb, int(ident.LandblockX), int(ident.LandblockY))
                self._used.append((int(ident.LandblockX), int(ident.LandblockY)))
        for plb in built:
            plb.PostInit()
        if not server:
            eng.Server = False
        ids = [lb.id for lb in scene.landblocks]
        for o in scene.objects:
            statics.append(self._static(o, ids))
        return self._mover(scene)

    def _node(self, node, polys):
        n = self.n
        if isinstance(node, BSPLeaf):
            leaf = n["NetLeaf"](n["BSPTreeType"].Physics)
            leaf.Solid = node.solid
            leaf.Sphere = n["Sphere"](n["Vector3"](*node.sphere.center), node.sphere.radius)
            leaf.NumPolys = len(node.polygons)
            leaf.Polygons = n["List"][n["Polygon"]]()
            for i in node.polygons:
                leaf.Polygons.Add(polys[i])
            return leaf
        net = n["NetNode"](n["BSPTreeType"].Physics)
        net.SplittingPlane = n["Plane"](n["Vector3"](*node.plane.normal), node.plane.d)
        net.Sphere = n["Sphere"](n["Vector3"](*node.sphere.center), node.sphere.radius)
        net.Polygons = n["List"][n["Polygon"]]()
        net.PosNode = self._node(node.front, polys)
        net.NegNode = self._node(node.back, polys)
        return net

    def _static(self, o, ids):
        n = self.n
        obj = n["PhysicsObj"]()
        obj.ID = o.id
        pos = self._pos(o.position)
        s = o.shape
        spheres, cyls, gfx = [], [], None
        if isinstance(s, SphereShape):
            spheres.append((*s.sphere.center, s.sphere.radius))
            bound = spheres[0]
        elif isinstance(s, CylSphereShape):
            lx, ly, lz = s.low_point
            cyls.append((lx, ly, lz, s.radius, s.height))
            # float32 arithmetic, as Facade.cs computes it
            import numpy as np
            h2 = np.float32(s.height) / np.float32(2)
            bound = (lx, ly, float(np.float32(lz) + h2), float(np.float32(s.radius) + h2))
        else:
            polys = []
            for i, p in enumerate(s.polygons):
                poly = n["Polygon"](i, len(p.vertices), n["CullMode"](p.sides_type))
                for k, v in enumerate(p.vertices):
                    poly.Vertices[k] = n["Vertex"](n["Vector3"](*v))
                    poly.VertexIDs[k] = k
                poly.make_plane()
                polys.append(poly)
            gfx = n["GfxObj"]()
            gfx.PhysicsBSP = n["BSPTree"](self._node(s.root, polys))
            gfx.PhysicsSphere = n["Sphere"](n["Vector3"](*s.sphere.center), s.sphere.radius)
            bound = (*s.sphere.center, s.sphere.radius)
        pa = self._part_array(obj, self._setup(spheres, cyls, 0, 0, 0, 0, bound))
        obj.PartArray = pa
        if gfx is not None:
            part = n["PhysicsPart"]()
            part.GfxObj = gfx
            part.GfxObjScale = n["Vector3"](1, 1, 1)
            part.PhysicsObj = obj
            part.Pos = n["Position"](pos)
            pa.Parts.Add(part)
            pa.NumParts = 1
        obj.State = n["PhysicsState"](o.state)
        obj.Position = n["Position"](pos)
        obj.SetScaleStatic(o.scale)
        for k, cell_id in enumerate(shadow_cells(o, ids)):
            cell = n["LScape"].get_landcell(cell_id)
            if k == 0:
                obj.CurCell = cell
            obj.add_shadows_to_cell(cell)
        return obj

    def _mover(self, scene: Scene):
        n = self.n
        m = scene.mover
        height, radius = mover_setup_dims(scene)
        spheres = [(*s.center, s.radius) for s in m.spheres]
        obj = n["PhysicsObj"]()
        obj.ID = MOVER_ID
        obj.PartArray = self._part_array(obj, self._setup(spheres, [], height, radius, m.step_up_height, m.step_down_height, spheres[0]))
        obj.SetScaleStatic(m.scale)
        obj.State = n["PhysicsState"](m.state)
        obj.TransientState = n["TransientStateFlags"](m.transient_state)
        obj.Velocity = n["Vector3"](*m.velocity)
        if m.contact_plane is not None:
            obj.ContactPlane = n["Plane"](n["Vector3"](*m.contact_plane.plane.normal), m.contact_plane.plane.d)
            obj.ContactPlaneCellID = m.contact_plane.cell
        if m.sliding_normal is not None:
            obj.SlidingNormal = n["Vector3"](*m.sliding_normal)
        begin = self._pos(m.begin)
        obj.Position = n["Position"](begin)
        obj.CurCell = n["LScape"].get_landcell(m.begin.cell)
        return obj, n["Position"](begin), self._pos(m.end)

    def _transition(self, obj, old, new):
        n = self.n
        from .pack import frames_stationary_fall

        trans = n["Transition"].MakeTransition()
        info = obj.get_object_info(trans, False)
        trans.InitObject(obj, info.State)
        if obj.PartArray is None or obj.PartArray.GetNumSphere() == 0:
            trans.InitSphere(1, n["PhysicsGlobals"].DummySphere, 1.0)
        else:
            trans.InitSphere(obj.PartArray.GetNumSphere(), obj.PartArray.GetSphere(), obj.Scale)
        trans.InitPath(obj.CurCell, old, new)
        fsf = frames_stationary_fall(int(obj.TransientState))
        if fsf:
            trans.CollisionInfo.FramesStationaryFall = fsf
        t0 = time.perf_counter()
        ok = trans.FindValidPosition()
        us = (time.perf_counter() - t0) * 1e6  # includes one pythonnet crossing
        trans.CleanupTransition()
        return trans, bool(ok), us

    def _outcome(self, trans, ok, obj) -> Outcome:
        sp, ci = trans.SpherePath, trans.CollisionInfo

        def v(x):
            return (float(x.X), float(x.Y), float(x.Z))

        def cp(valid, cell, water, plane):
            return ContactPlaneState(bool(valid), int(cell), bool(water), v(plane.Normal), float(plane.D))

        q = sp.CurPos.Frame.Orientation
        return Outcome(
            ok=ok, cell=int(sp.CurCell.ID) if sp.CurCell is not None else 0,
            origin=v(sp.CurPos.Frame.Origin), orientation=(float(q.W), float(q.X), float(q.Y), float(q.Z)),
            object_info_state=int(trans.ObjectInfo.State),
            contact_plane=cp(ci.ContactPlaneValid, ci.ContactPlaneCellID, ci.ContactPlaneIsWater, ci.ContactPlane),
            last_known_contact_plane=cp(ci.LastKnownContactPlaneValid, ci.LastKnownContactPlaneCellID,
                                        ci.LastKnownContactPlaneIsWater, ci.LastKnownContactPlane),
            collision_normal=NormalState(bool(ci.CollisionNormalValid), v(ci.CollisionNormal)),
            sliding_normal=NormalState(bool(ci.SlidingNormalValid), v(ci.SlidingNormal)),
            collided_with_environment=bool(ci.CollidedWithEnvironment),
            frames_stationary_fall=int(ci.FramesStationaryFall), velocity=v(obj.Velocity),
            check_cell=int(sp.CheckCell.ID) if sp.CheckCell is not None else 0,
            walkable=sp.Walkable is not None, step_up=bool(sp.StepUp), neg_poly_hit=bool(sp.NegPolyHit))
