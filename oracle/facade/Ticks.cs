// acconform oracle facade -- MIT licensed, part of acconform (not ACE code).
//
// A tick scene's states, written so that Python reads them whole (pack 18): Facade.cs runs the ticks, this file
// writes them for oracle/pack.py's `_ticks_and_end`.
using System;
using System.Collections.Generic;
using System.IO;
using System.Numerics;
using System.Runtime.InteropServices;

using ACE.Server.Physics;

namespace Acconform.Oracle
{
    public static partial class Facade
    {
        // Each tick's states go into fixed-size records, one per mover (the mover, then each other mover in scene
        // order), their vectors, ContactPlanes, ShadowObjects cell lists and CollisionTables as indices into tables of
        // the distinct ones of the scene (by bits: 0.0 and -0.0 apart), the mover's motion layers beside them. Python
        // reads all the records in one iter_unpack and makes each distinct vector, plane, cell list and table once
        // (oracle/pack.py, `_ticks_and_end`; docs/oracle.md on the cost).
        static readonly MemoryStream stateStream = new MemoryStream(1 << 14), collisionTableStream = new MemoryStream(256),
            motionStream = new MemoryStream(1024), vec3Stream = new MemoryStream(256), vec4Stream = new MemoryStream(256),
            planeStream = new MemoryStream(256);
        static readonly BinaryWriter stateWriter = new BinaryWriter(stateStream),
            collisionTableWriter = new BinaryWriter(collisionTableStream), motionWriter = new BinaryWriter(motionStream),
            vec3Writer = new BinaryWriter(vec3Stream), vec4Writer = new BinaryWriter(vec4Stream),
            planeWriter = new BinaryWriter(planeStream);
        static readonly Dictionary<Bits4, int> vec3Index = new Dictionary<Bits4, int>(), vec4Index = new Dictionary<Bits4, int>(),
            planeIndex = new Dictionary<Bits4, int>();
        static readonly Dictionary<CollisionKey, int> collisionIndex = new Dictionary<CollisionKey, int>();
        // the distinct ShadowObjects cell lists and CollisionTables (as indices of their records) a state names by index;
        // each object's last one is checked first (they mostly stay from tick to tick); table 0 is the empty table
        static readonly List<uint[]> cellSets = new List<uint[]>();
        static readonly List<int[]> collisionTables = new List<int[]>();
        static readonly Dictionary<PhysicsObj, int> lastCells = new Dictionary<PhysicsObj, int>(),
            lastTable = new Dictionary<PhysicsObj, int>();
        static readonly List<int> tableScratch = new List<int>();
        static int statesWritten;
        static byte[] tickError;  // what the last tick threw (it ended the scene), UTF-8; null: none

        [StructLayout(LayoutKind.Explicit)]
        struct FloatBits
        {
            [FieldOffset(0)] public float F;
            [FieldOffset(0)] public uint U;
        }

        static uint Bits(float f) { var b = new FloatBits(); b.F = f; return b.U; }

        /// <summary>Four floats' bits: a table key that keeps 0.0 and -0.0 (and each NaN) apart.</summary>
        struct Bits4 : IEquatable<Bits4>
        {
            public uint A, B, C, D;
            public Bits4(float a, float b, float c, float d) { A = Bits(a); B = Bits(b); C = Bits(c); D = Bits(d); }
            public bool Equals(Bits4 o) => A == o.A && B == o.B && C == o.C && D == o.D;
            public override bool Equals(object o) => o is Bits4 && Equals((Bits4)o);
            public override int GetHashCode() => (int)(((A * 31 + B) * 31 + C) * 31 + D);
        }

        /// <summary>A CollisionTable record's id, TouchedTime (by bits) and Ethereal: a key of the table of distinct ones.</summary>
        struct CollisionKey : IEquatable<CollisionKey>
        {
            public uint Id;
            public long Time;
            public bool Ethereal;
            public bool Equals(CollisionKey o) => Id == o.Id && Time == o.Time && Ethereal == o.Ethereal;
            public override bool Equals(object o) => o is CollisionKey && Equals((CollisionKey)o);
            public override int GetHashCode() => (int)Id * 31 + Time.GetHashCode() + (Ethereal ? 1 : 0);
        }

        static void ClearTicks()
        {
            foreach (var s in new[] { stateStream, collisionTableStream, motionStream, vec3Stream, vec4Stream, planeStream })
                s.SetLength(0);
            collisionIndex.Clear();
            vec3Index.Clear();
            vec4Index.Clear();
            planeIndex.Clear();
            cellSets.Clear();
            collisionTables.Clear();
            collisionTables.Add(new int[0]);
            lastCells.Clear();
            lastTable.Clear();
            statesWritten = 0;
            tickError = null;
        }

        static int Vec3(Vector3 v)
        {
            var key = new Bits4(v.X, v.Y, v.Z, 0f);
            int i;
            if (vec3Index.TryGetValue(key, out i)) return i;
            vec3Writer.Write(v.X); vec3Writer.Write(v.Y); vec3Writer.Write(v.Z);
            return vec3Index[key] = vec3Index.Count;
        }

        static int Quat(Quaternion q)
        {
            var key = new Bits4(q.W, q.X, q.Y, q.Z);
            int i;
            if (vec4Index.TryGetValue(key, out i)) return i;
            vec4Writer.Write(q.W); vec4Writer.Write(q.X); vec4Writer.Write(q.Y); vec4Writer.Write(q.Z);
            return vec4Index[key] = vec4Index.Count;
        }

        static int CollisionAt(uint id, double time, bool ethereal)
        {
            var key = new CollisionKey { Id = id, Time = BitConverter.DoubleToInt64Bits(time), Ethereal = ethereal };
            int i;
            if (collisionIndex.TryGetValue(key, out i)) return i;
            collisionTableWriter.Write(id); collisionTableWriter.Write(time); collisionTableWriter.Write((byte)(ethereal ? 1 : 0));
            return collisionIndex[key] = collisionIndex.Count;
        }

        /// <summary>The index of the object's ShadowObjects cell ids, in their order, among the scene's cell lists.</summary>
        static int CellsAt(PhysicsObj obj)
        {
            var cells = obj.ShadowObjects.Keys;
            int i;
            if (lastCells.TryGetValue(obj, out i) && cellSets[i].Length == cells.Count)
            {
                var set = cellSets[i];
                var k = 0;
                foreach (var cell in cells)
                    if (set[k++] != cell) { k = -1; break; }
                if (k == set.Length) return i;
            }
            var now = new uint[cells.Count];
            cells.CopyTo(now, 0);
            cellSets.Add(now);
            return lastCells[obj] = cellSets.Count - 1;
        }

        /// <summary>The index of the object's CollisionTable (its records' indices, in its order) among the scene's
        /// tables; 0: none or empty.</summary>
        static int TableAt(PhysicsObj obj)
        {
            var table = obj.CollisionTable;
            if (table == null || table.Count == 0) return 0;
            tableScratch.Clear();
            foreach (var kv in table) tableScratch.Add(CollisionAt(kv.Key, kv.Value.TouchedTime, kv.Value.Ethereal));
            int i;
            if (lastTable.TryGetValue(obj, out i) && collisionTables[i].Length == tableScratch.Count)
            {
                var last = collisionTables[i];
                var k = 0;
                while (k < last.Length && last[k] == tableScratch[k]) k++;
                if (k == last.Length) return i;
            }
            collisionTables.Add(tableScratch.ToArray());
            return lastTable[obj] = collisionTables.Count - 1;
        }

        static int PlaneAt(Vector3 n, float d)
        {
            var key = new Bits4(n.X, n.Y, n.Z, d);
            int i;
            if (planeIndex.TryGetValue(key, out i)) return i;
            planeWriter.Write(n.X); planeWriter.Write(n.Y); planeWriter.Write(n.Z); planeWriter.Write(d);
            return planeIndex[key] = planeIndex.Count;
        }

        /// <summary>A tick's states: the mover's record (and its motion layer when it has a motion table), then in a scene
        /// with other movers each other mover's in scene order; each CollisionTable only in a scene with other movers.</summary>
        static void WriteTick(PhysicsObj obj, bool updated)
        {
            WriteState(obj, updated, othersRead, 0);
            if (moverMotion) WriteMotion(motionWriter, obj);
            if (!othersRead) return;
            for (var k = 0; k < sceneOthers.Count; k++)
                WriteState(sceneOthers[k].Obj, othersUpdated[k], true, sceneOthers[k].Id);
        }

        /// <summary>One state record (acconform.outcome.TickState's fields in order): updated (byte), UpdateTime,
        /// Position.ObjCellID, CurCell id (0: none), origin, then the indices of the orientation (w x y z), Velocity,
        /// Acceleration, Omega and CachedVelocity, State, TransientState, ContactPlaneCellID, the ContactPlane's index
        /// (normal, d), SlidingNormal's index, JumpedThisFrame (byte), the index of its ShadowObjects cell ids among the
        /// scene's cell lists (CellsAt), of its CollisionTable among the scene's tables (TableAt; 0 unless `collisions`),
        /// and the state's id (another mover's; 0 for the mover).</summary>
        static void WriteState(PhysicsObj obj, bool updated, bool collisions, uint id)
        {
            var w = stateWriter;
            w.Write((byte)(updated ? 1 : 0));
            w.Write(obj.UpdateTime);
            w.Write(obj.Position.ObjCellID);
            w.Write(obj.CurCell != null ? obj.CurCell.ID : 0u);
            W3(w, obj.Position.Frame.Origin);
            w.Write(Quat(obj.Position.Frame.Orientation));
            w.Write(Vec3(obj.Velocity));
            w.Write(Vec3(obj.Acceleration));
            w.Write(Vec3(obj.Omega));
            w.Write(Vec3(obj.CachedVelocity));
            w.Write((uint)obj.State);
            w.Write((uint)obj.TransientState);
            w.Write(obj.ContactPlaneCellID);
            w.Write(PlaneAt(obj.ContactPlane.Normal, obj.ContactPlane.D));
            w.Write(Vec3(obj.SlidingNormal));
            w.Write((byte)(obj.JumpedThisFrame ? 1 : 0));
            w.Write(CellsAt(obj));
            w.Write(collisions ? TableAt(obj) : 0);
            w.Write(id);
            statesWritten++;
        }

        /// <summary>The tick block after int ticksRun (when above 0): byte 1 (a scene with other movers) or 0, int k (the
        /// other movers each tick carries), byte 1 (the mover's motion layers follow the collisions) or 0, byte 1 (the last tick threw)
        /// or 0, then int n and the n state records, int n and the n cell lists (each int m and m ids), int n
        /// and the n CollisionTables (each int m and the indices of its m records), int n and the n distinct collision
        /// records (id, TouchedTime, Ethereal), the motion
        /// layers (one per tick that did not throw), int n and the n distinct vectors (x y z), int n and the n distinct
        /// orientations (w x y z), int n and the n distinct planes (normal, d), and when the last tick threw, int length
        /// and its message.</summary>
        static void WriteTicks(BinaryWriter w)
        {
            w.Write((byte)(othersRead ? 1 : 0));
            var k = othersRead ? sceneOthers.Count : 0;
            w.Write(k);
            w.Write((byte)(moverMotion ? 1 : 0));
            w.Write((byte)(tickError != null ? 1 : 0));
            w.Write(statesWritten);
            Append(w, stateStream);
            w.Write(cellSets.Count);
            foreach (var set in cellSets)
            {
                w.Write(set.Length);
                foreach (var cell in set) w.Write(cell);
            }
            w.Write(collisionTables.Count);
            foreach (var t in collisionTables)
            {
                w.Write(t.Length);
                foreach (var i in t) w.Write(i);
            }
            w.Write(collisionIndex.Count);
            Append(w, collisionTableStream);
            Append(w, motionStream);
            w.Write(vec3Index.Count);
            Append(w, vec3Stream);
            w.Write(vec4Index.Count);
            Append(w, vec4Stream);
            w.Write(planeIndex.Count);
            Append(w, planeStream);
            if (tickError != null)
            {
                w.Write(tickError.Length);
                w.Write(tickError);
            }
        }

        static void Append(BinaryWriter w, MemoryStream s) { w.Write(s.GetBuffer(), 0, (int)s.Length); }
    }
}
