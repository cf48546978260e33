// acconform's trace recorder (MIT), compiled into the facade of an instrumented ACE copy only (oracle/instrumented.py):
// the instrumented methods call it at their entry and exits (Acconform.Trace.Hooks, injected by Instrument.cs), and it
// writes the records the port's tracing writes (port/tracing.py), one JSON array a line:
//     [anchor id, event, tick, step, within id, args, result, path, mover, placing]
// (-1 or null where the port's record leaves the field out; path and mover: the index of a snapshot, defined by a
// line "#p <json>" or "#m <json>" before the first record that refers to it). acconform/oracle/instrumented.py turns them into
// acconform.trace records. What a record holds follows the port's rules, by the kind of the anchor's ACE file
// (the table Install is given): a transition routine ("p") writes enter and exit with the run's current Transition
// (the last one a routine was handed); a PhysicsObj routine ("m") on the mover writes enter and exit with the mover
// as a TickState, on another object one call; any other routine ("c") one call at its exit, with its arguments as
// they were at its entry. The per-step points the port marks with one line each are taken from the calls that
// open them: a pass of FindTransitionalPosition's loop opens with AdjustOffset, a TransitionalInsert attempt with
// InsertIntoCell, a tick with the facade's TickStarted. While PhysicsObj.add_obj_to_cell places a static object (any
// object but the mover: the facade's statics as it builds the scene, an EnvCell's stabs as the cell loads), each
// record carries that object's ID (`placing`), as the port's do.
using System;
using System.Collections;
using System.Collections.Generic;
using System.Globalization;
using System.Linq.Expressions;
using System.Numerics;
using System.Reflection;
using System.Runtime.InteropServices;
using System.Text;
using ACE.Server.Physics;
using ACE.Server.Physics.Animation;
using ACE.Server.Physics.Collision;
using ACE.Server.Physics.Common;

namespace Acconform.Oracle
{
    public sealed class TraceRecorder : Acconform.Trace.Hooks
    {
        const uint MoverId = 0x50000001;  // acconform.staging.MOVER_ID
        static TraceRecorder instance;

        sealed class Frame { public int Id; public string Args; public PhysicsObj Mover; public bool Places; public long Outer; }

        string[] kinds = new string[0];  // per anchor id: "p", "m" or "c", then the role: f(TP), a(djustOffset), t(I), i(nsertIntoCell),
        // o (add_obj_to_cell)
        int ftpId = -1, tiId = -1, tickId = -1;
        readonly StringBuilder sb = new StringBuilder(1 << 16);
        readonly List<Frame> running = new List<Frame>();
        readonly Dictionary<Type, Func<object, object>> idOf = new Dictionary<Type, Func<object, object>>();
        int tick = -1, step = -1, steps, ticksStarted;
        long placing = -1;  // the ID of the static object add_obj_to_cell is placing, -1 when none
        Transition transition;
        public int Records;
        bool keep = true;  // false: the records are counted, their text dropped as it grows (StartCounting)
        const int Dropped = 1 << 22;  // chars of text a counting run holds at most

        /// <summary>table: one line per anchor id, "kind role" (role "-" for none); ids are the instrumenter's.</summary>
        public static void Install(string table)
        {
            var r = new TraceRecorder();
            var lines = table.Split(new[] { '\n' }, StringSplitOptions.RemoveEmptyEntries);
            r.kinds = new string[lines.Length];
            for (var i = 0; i < lines.Length; i++)
            {
                r.kinds[i] = lines[i].Trim();
                if (r.kinds[i].EndsWith("f") && r.ftpId < 0) r.ftpId = i;
                if (r.kinds[i].EndsWith("t") && r.tiId < 0) r.tiId = i;
                if (r.kinds[i].EndsWith("u") && r.tickId < 0) r.tickId = i;
            }
            instance = r;
        }

        /// <summary>Start recording a run (the records of the previous one are dropped).</summary>
        public static void Start() { Begin(true); }

        /// <summary>Start a run whose records are written (their whole cost) and counted, their text not kept: a tick
        /// scene's trace can outgrow what one string holds.</summary>
        public static void StartCounting() { Begin(false); }

        static void Begin(bool keep)
        {
            var r = instance;
            r.keep = keep;
            r.sb.Clear();
            r.running.Clear();
            r.tick = r.step = -1;
            r.placing = -1;
            r.steps = r.ticksStarted = 0;
            r.transition = null;
            r.Records = 0;
            r.paths.Clear();
            r.movers.Clear();
            Facade.TickStarted = r.OnTick;
            Current = r;
        }

        /// <summary>How many records the last run wrote.</summary>
        public static int Count() => instance.Records;

        /// <summary>Stop recording and write the records, one a line, into the file at `path` (UTF-8): the worker hands a
        /// trace over that way, with no string made of it for Python. Returns how many characters it wrote.</summary>
        public static int TakeTo(string path)
        {
            var r = Stop();
            // in pieces through two reused buffers: a trace's text as one string (and its bytes as one array) is a
            // large-object allocation that set off a full collection of ACE's heap, tens of ms a trace
            var n = r.sb.Length;
            var encoder = Utf8.GetEncoder();  // (keeps a surrogate pair cut by a piece's end whole)
            using (var f = new System.IO.FileStream(path, System.IO.FileMode.Create, System.IO.FileAccess.Write, System.IO.FileShare.Read, 1 << 16))
            {
                for (var at = 0; at < n; at += Piece)
                {
                    var count = Math.Min(Piece, n - at);
                    r.sb.CopyTo(at, r.chars, 0, count);
                    var bytes = encoder.GetBytes(r.chars, 0, count, r.bytes, 0, at + count >= n);
                    f.Write(r.bytes, 0, bytes);
                }
            }
            return n;
        }

        const int Piece = 1 << 15;
        static readonly Encoding Utf8 = new UTF8Encoding(false);
        readonly char[] chars = new char[Piece];
        readonly byte[] bytes = new byte[Piece * 3 + 4];  // a char is at most 3 bytes of UTF-8 (a pair 4)

        /// <summary>Stop recording and hand over the records, one a line.</summary>
        public static string Take()
        {
            var r = Stop();
            return r.keep ? r.sb.ToString() : "";
        }

        static TraceRecorder Stop()
        {
            var r = instance;
            Current = null;
            Facade.TickStarted = null;
            if (r.ticksStarted > 0) r.TickDone();
            return r;
        }

        void OnTick(int index)
        {
            if (ticksStarted > 0) TickDone();
            if (index < 0) { ticksStarted = 0; return; }  // the ticks are over: the tick record of the last one is written
            ticksStarted++;
            tick = index;
        }

        // the "tick" record after a tick: its mover is the tick's TickState, filled in from the outcome by the Python side
        void TickDone() { Write(tickId, Ev.Tick, null, null, null, null); }

        Frame Top => running.Count > 0 ? running[running.Count - 1] : null;

        enum Ev { Enter, Exit, Call, Step, Insert, Tick }
        static readonly string[] Events = { "enter", "exit", "call", "step", "insert", "tick" };
        string[] prefixes = new string[0];
        readonly Stack<Frame> spare = new Stack<Frame>();  // frames reused: one a record was most of what a run allocated

        Frame NewFrame(int id)
        {
            var f = spare.Count > 0 ? spare.Pop() : new Frame();
            f.Id = id;
            f.Args = null;
            f.Mover = null;
            f.Places = false;
            f.Outer = 0;
            return f;
        }

        public override void Enter(int id, object[] args)
        {
            var kind = kinds[id];
            var frame = NewFrame(id);
            if (kind[0] == 'p')
            {
                foreach (var a in args)
                    if (a is Transition) { transition = (Transition)a; break; }
                if (kind[1] == 'f') step = -1;
                var top = Top;
                if (kind[1] == 'a' && top != null && kinds[top.Id][1] == 'f')  // a pass of FindTransitionalPosition's loop
                {
                    step = steps++;
                    Write(ftpId, Ev.Step, null, null, transition, null);
                }
                if (kind[1] == 'i' && top != null && kinds[top.Id][1] == 't')  // a TransitionalInsert attempt
                    Write(tiId, Ev.Insert, null, null, transition, null);
                if (kind[1] == 'f') steps = 0;
                Write(id, Ev.Enter, Json(args), null, transition, null);
            }
            else if (kind[0] == 'm' && args.Length > 0 && args[0] is PhysicsObj && ((PhysicsObj)args[0]).ID == MoverId &&
                     ((PhysicsObj)args[0]).Position != null)
            {
                frame.Mover = (PhysicsObj)args[0];
                Write(id, Ev.Enter, Json(args), null, null, frame.Mover);
            }
            else
                frame.Args = Json(args);
            if (kind[1] == 'o' && args.Length > 0 && args[0] is PhysicsObj && ((PhysicsObj)args[0]).ID != MoverId)
            {
                // a static's placement: this frame's records, and the ones inside it, carry the static's ID
                frame.Places = true;
                frame.Outer = placing;
                placing = ((PhysicsObj)args[0]).ID;
            }
            running.Add(frame);
        }

        public override void Exit(int id, object result, object[] refs)
        {
            // an exception that left methods without their exit: drop their frames
            var at = running.Count - 1;
            while (at >= 0 && running[at].Id != id) at--;
            if (at < 0) return;
            var frame = running[at];
            var left = false;
            for (var k = at + 1; k < running.Count; k++)
            {
                if (running[k].Places && !left) { placing = running[k].Outer; left = true; }  // a placement left by an exception ends with it
                spare.Push(running[k]);
            }
            running.RemoveRange(at, running.Count - at);
            var kind = kinds[id];
            var answer = refs == null ? Json(result) : Json(refs);
            if (kind[0] == 'p')
            {
                if (kind[1] == 'f') step = -1;
                Write(id, Ev.Exit, null, answer, transition, null);
            }
            else if (frame.Mover != null)
                Write(id, Ev.Exit, null, answer, null, frame.Mover);
            else
                Write(id, Ev.Call, frame.Args, answer, null, null);
            if (frame.Places) placing = frame.Outer;
            spare.Push(frame);
        }

        // The snapshots are taken first, each into a token buffer of its own depth: a getter they read may be an
        // instrumented method, whose records go before this one (and must not land inside it).
        void Write(int id, Ev ev, string args, string result, Transition path, PhysicsObj mover)
        {
            int pathRef = -1, moverRef = -1;
            if (path != null)
            {
                var t = BorrowTokens();
                try { if (Path(t, path)) pathRef = paths.Find(t, sb); } finally { tokenDepth--; }
            }
            if (mover != null)
            {
                var t = BorrowTokens();
                try { Mover(t, mover); moverRef = movers.Find(t, sb); } finally { tokenDepth--; }
            }
            var within = Top;
            var key = id * Events.Length + (int)ev;  // "[id,\"event\"," made once per anchor and event
            if (key >= prefixes.Length) Array.Resize(ref prefixes, Math.Max(key + 1, prefixes.Length * 2));
            var prefix = key >= 0 ? prefixes[key] : null;
            if (prefix == null)
            {
                prefix = "[" + id.ToString(CultureInfo.InvariantCulture) + ",\"" + Events[(int)ev] + "\",";
                if (key >= 0) prefixes[key] = prefix;
            }
            sb.Append(prefix);
            N(sb, tick).Append(',');
            N(sb, step).Append(',');
            N(sb, within != null ? within.Id : -1).Append(',').Append(args ?? "null").Append(',').Append(result ?? "null").Append(',');
            if (pathRef >= 0) N(sb, pathRef); else sb.Append("null");
            sb.Append(',');
            if (moverRef >= 0) N(sb, moverRef); else sb.Append("null");
            sb.Append(',');
            N(sb, placing).Append("]\n");
            Records++;
            if (!keep && sb.Length > Dropped) sb.Clear();
        }

        // ------------------------------------------------------------------ snapshots
        // A trace's tens of thousands of snapshots (a path at every entry and exit) are a few hundred distinct ones. A
        // snapshot is read as tokens (a kind and its raw bits) and looked up among the run's snapshots by value; a new
        // one is formatted once, into a definition line ("#p " or "#m " and its JSON) before the first record that
        // refers to it by its index. Formatting every snapshot was most of the recorder's cost.
        const byte TOpen = 1, TClose = 2, TFloat = 3, TDouble = 4, TUint = 5, TInt = 6, TBool = 7, TNull = 8;

        sealed class Tokens
        {
            public long[] V = new long[96];
            public byte[] K = new byte[96];
            public int N;

            public Tokens Add(byte kind, long value)
            {
                if (N == V.Length) { Array.Resize(ref V, N * 2); Array.Resize(ref K, N * 2); }
                K[N] = kind;
                V[N++] = value;
                return this;
            }

            public Tokens Open() => Add(TOpen, 0);
            public Tokens Close() => Add(TClose, 0);
            public Tokens F(float f) => Add(TFloat, new Bits { F = f }.I);
            public Tokens D(double d) => Add(TDouble, new Bits { D = d }.L);
            public Tokens U(uint u) => Add(TUint, u);
            public Tokens I(int i) => Add(TInt, i);
            public Tokens B(bool b) => Add(TBool, b ? 1 : 0);
            public Tokens V3(Vector3 v) => Open().F(v.X).F(v.Y).F(v.Z).Close();
        }

        /// <summary>One kind's snapshots of the run, by value; `Find` gives a snapshot's index, defining it first.</summary>
        sealed class Snapshots
        {
            readonly string prefix;
            readonly Dictionary<long, int> first = new Dictionary<long, int>();  // by hash: the first snapshot with it
            readonly List<long[]> values = new List<long[]>();
            readonly List<byte[]> kinds = new List<byte[]>();
            readonly List<int> next = new List<int>();  // the next snapshot with the same hash, -1 for none

            public Snapshots(string prefix) { this.prefix = prefix; }

            public void Clear() { first.Clear(); values.Clear(); kinds.Clear(); next.Clear(); }

            public int Find(Tokens t, StringBuilder sb)
            {
                long h = t.N;
                for (var i = 0; i < t.N; i++) h = (h ^ t.V[i] ^ ((long)t.K[i] << 56)) * 0x100000001b3L;
                int at, last = -1;
                if (first.TryGetValue(h, out at))
                    for (; at >= 0; last = at, at = next[at])
                        if (Same(values[at], kinds[at], t)) return at;
                var v = new long[t.N];
                var k = new byte[t.N];
                Array.Copy(t.V, v, t.N);
                Array.Copy(t.K, k, t.N);
                var index = values.Count;
                values.Add(v);
                kinds.Add(k);
                next.Add(-1);
                if (last >= 0) next[last] = index; else first[h] = index;
                sb.Append(prefix);
                Format(sb, t);
                sb.Append('\n');
                return index;
            }

            static bool Same(long[] v, byte[] k, Tokens t)
            {
                if (v.Length != t.N) return false;
                for (var i = 0; i < v.Length; i++)
                    if (v[i] != t.V[i] || k[i] != t.K[i]) return false;
                return true;
            }
        }

        readonly Snapshots paths = new Snapshots("#p "), movers = new Snapshots("#m ");
        readonly List<Tokens> tokenBuffers = new List<Tokens>();
        int tokenDepth;

        Tokens BorrowTokens()
        {
            if (tokenDepth == tokenBuffers.Count) tokenBuffers.Add(new Tokens());
            var t = tokenBuffers[tokenDepth++];
            t.N = 0;
            return t;
        }

        /// <summary>Tokens as JSON: the text the snapshot functions wrote before they wrote tokens.</summary>
        static void Format(StringBuilder s, Tokens t)
        {
            var first = true;
            for (var i = 0; i < t.N; i++)
            {
                var kind = t.K[i];
                if (kind == TClose) { s.Append(']'); first = false; continue; }
                if (!first) s.Append(',');
                first = false;
                switch (kind)
                {
                    case TOpen: s.Append('['); first = true; break;
                    case TFloat: F(s, new Bits { I = (int)t.V[i] }.F); break;
                    case TDouble: D(s, new Bits { L = t.V[i] }.D); break;
                    case TUint: N(s, (uint)t.V[i]); break;
                    case TInt: N(s, (int)t.V[i]); break;
                    case TBool: s.Append(t.V[i] != 0 ? "true" : "false"); break;
                    default: s.Append("null"); break;
                }
            }
        }

        /// <summary>acconform.trace.PathState's fields, in order; false (nothing written) when the transition has no
        /// path yet.</summary>
        static bool Path(Tokens s, Transition t)
        {
            if (t == null || t.SpherePath == null || t.CollisionInfo == null) return false;
            var sp = t.SpherePath;
            var ci = t.CollisionInfo;
            s.Open().U(sp.CheckCell != null ? sp.CheckCell.ID : 0u).V3(sp.CheckPos != null ? sp.CheckPos.Frame.Origin : Vector3.Zero)
             .U(sp.CurCell != null ? sp.CurCell.ID : 0u).V3(sp.CurPos != null ? sp.CurPos.Frame.Origin : Vector3.Zero)
             .V3(sp.GlobalOffset);
            Contact(s, ci.ContactPlaneValid, ci.ContactPlaneCellID, ci.ContactPlaneIsWater, ci.ContactPlane);
            Contact(s, ci.LastKnownContactPlaneValid, ci.LastKnownContactPlaneCellID, ci.LastKnownContactPlaneIsWater,
                    ci.LastKnownContactPlane);
            s.Open().B(ci.CollisionNormalValid).V3(ci.CollisionNormal).Close();
            s.Open().B(ci.SlidingNormalValid).V3(ci.SlidingNormal).Close();
            if (sp.Walkable != null) s.Open().V3(sp.Walkable.Plane.Normal).F(sp.Walkable.Plane.D).Close();
            else s.Add(TNull, 0);
            s.B(sp.StepUp).B(sp.StepDown).B(sp.Collide).B(sp.NegPolyHit).I(ci.FramesStationaryFall)
             .U(t.ObjectInfo != null ? (uint)t.ObjectInfo.State : 0u)
             .B(sp.PlacementAllowsSliding).B(sp.BuildingCheck).B(sp.HitsInteriorCell).Close();
            return true;
        }

        static void Contact(Tokens s, bool valid, uint cell, bool water, Plane plane)
        {
            s.Open().B(valid).U(cell).B(water).V3(plane.Normal).F(plane.D).Close();
        }

        /// <summary>acconform.outcome.TickState's fields, in order (`updated` false, as tracing.tick_state(obj, False)).</summary>
        static void Mover(Tokens s, PhysicsObj obj)
        {
            var q = obj.Position.Frame.Orientation;
            s.Open().B(false).D(obj.UpdateTime).U(obj.Position.ObjCellID).U(obj.CurCell != null ? obj.CurCell.ID : 0u)
             .V3(obj.Position.Frame.Origin).Open().F(q.W).F(q.X).F(q.Y).F(q.Z).Close()
             .V3(obj.Velocity).V3(obj.Acceleration).V3(obj.Omega).V3(obj.CachedVelocity)
             .U((uint)obj.State).U((uint)obj.TransientState).U(obj.ContactPlaneCellID)
             .Open().V3(obj.ContactPlane.Normal).F(obj.ContactPlane.D).Close()
             .V3(obj.SlidingNormal).B(obj.JumpedThisFrame).Open();
            if (obj.ShadowObjects != null)
                foreach (var id in obj.ShadowObjects.Keys) s.U(id);
            s.Close().Close();
        }

        // ------------------------------------------------------------------ values, as port/tracing.plain writes them
        // builders reused, one per depth: writing a value may call an instrumented getter (an ID), which writes records
        readonly List<StringBuilder> builders = new List<StringBuilder>();
        int depth;

        StringBuilder Borrow()
        {
            if (depth == builders.Count) builders.Add(new StringBuilder(1024));
            var b = builders[depth++];
            b.Clear();
            return b;
        }

        string Json(object v)
        {
            var b = Borrow();
            try { Plain(b, v, 0); return b.ToString(); } finally { depth--; }
        }

        // what Plain writes a value of a type as, found once a type (the type tests in port/tracing.plain's order)
        enum Shape : byte { Bool, String, Enum, Float, Double, SByte, Byte, Short, UShort, Int, UInt, Long, ULong, Quaternion,
                            Vector3, Vector2, Sphere, Plane, AFrame, BBox, Position, List, Other }

        readonly Dictionary<Type, Shape> shapes = new Dictionary<Type, Shape>();
        readonly Dictionary<Type, string> typeNames = new Dictionary<Type, string>();  // an object with no ID, as JSON

        static Shape ShapeOf(object v)
        {
            if (v is bool) return Shape.Bool;
            if (v is string) return Shape.String;
            if (v is Enum) return Shape.Enum;
            if (v is float) return Shape.Float;
            if (v is double) return Shape.Double;
            if (v is sbyte) return Shape.SByte;
            if (v is byte) return Shape.Byte;
            if (v is short) return Shape.Short;
            if (v is ushort) return Shape.UShort;
            if (v is int) return Shape.Int;
            if (v is uint) return Shape.UInt;
            if (v is long) return Shape.Long;
            if (v is ulong) return Shape.ULong;
            if (v is Quaternion) return Shape.Quaternion;
            if (v is Vector3) return Shape.Vector3;
            if (v is Vector2) return Shape.Vector2;
            if (v is Sphere) return Shape.Sphere;
            if (v is Plane) return Shape.Plane;
            if (v is AFrame) return Shape.AFrame;
            if (v is BBox) return Shape.BBox;
            if (v is Position) return Shape.Position;
            if (v is IList) return Shape.List;
            return Shape.Other;
        }

        void Plain(StringBuilder s, object v, int depth)
        {
            // (if and casts, not a type switch: mono's mcs does not parse type patterns)
            if (v == null) { s.Append("null"); return; }
            var type = v.GetType();
            Shape shape;
            if (!shapes.TryGetValue(type, out shape)) shapes[type] = shape = ShapeOf(v);
            switch (shape)
            {
                case Shape.Bool: s.Append(B((bool)v)); return;
                case Shape.String: Str(s, (string)v); return;
                case Shape.Enum: N(s, Convert.ToInt64(v, CultureInfo.InvariantCulture)); return;
                case Shape.Float: F(s, (float)v); return;
                case Shape.Double: D(s, (double)v); return;
                case Shape.SByte: N(s, (sbyte)v); return;
                case Shape.Byte: N(s, (byte)v); return;
                case Shape.Short: N(s, (short)v); return;
                case Shape.UShort: N(s, (ushort)v); return;
                case Shape.Int: N(s, (int)v); return;
                case Shape.UInt: N(s, (uint)v); return;
                case Shape.Long: N(s, (long)v); return;
                case Shape.ULong: s.Append(((ulong)v).ToString(CultureInfo.InvariantCulture)); return;
                case Shape.Quaternion:
                {
                    var q = (Quaternion)v;
                    s.Append('['); F(s, q.W).Append(','); F(s, q.X).Append(','); F(s, q.Y).Append(','); F(s, q.Z).Append(']');
                    return;
                }
                case Shape.Vector3: V(s, (Vector3)v); return;
                case Shape.Vector2: { var w = (Vector2)v; s.Append('['); F(s, w.X).Append(','); F(s, w.Y).Append(']'); return; }
                case Shape.Sphere:
                {
                    var sph = (Sphere)v;
                    s.Append('['); F(s, sph.Center.X).Append(','); F(s, sph.Center.Y).Append(','); F(s, sph.Center.Z).Append(',');
                    F(s, sph.Radius).Append(']');
                    return;
                }
                case Shape.Plane:
                {
                    var p = (Plane)v;
                    s.Append('['); F(s, p.Normal.X).Append(','); F(s, p.Normal.Y).Append(','); F(s, p.Normal.Z).Append(','); F(s, p.D).Append(']');
                    return;
                }
                case Shape.AFrame:
                {
                    var fr = (AFrame)v;
                    s.Append('['); F(s, fr.Origin.X).Append(','); F(s, fr.Origin.Y).Append(','); F(s, fr.Origin.Z).Append(',');
                    F(s, fr.Orientation.W).Append(','); F(s, fr.Orientation.X).Append(','); F(s, fr.Orientation.Y).Append(',');
                    F(s, fr.Orientation.Z).Append(']');
                    return;
                }
                case Shape.BBox:
                {
                    var box = (BBox)v;
                    s.Append('['); F(s, box.Min.X).Append(','); F(s, box.Min.Y).Append(','); F(s, box.Min.Z).Append(',');
                    F(s, box.Max.X).Append(','); F(s, box.Max.Y).Append(','); F(s, box.Max.Z).Append(']');
                    return;
                }
                case Shape.Position:
                {
                    var pos = (Position)v;
                    s.Append('[');
                    N(s, pos.ObjCellID).Append(','); F(s, pos.Frame.Origin.X).Append(','); F(s, pos.Frame.Origin.Y)
                     .Append(','); F(s, pos.Frame.Origin.Z).Append(']');
                    return;
                }
                case Shape.List:
                {
                    var list = (IList)v;
                    if (depth >= 3) { s.Append('"'); N(s, list.Count).Append(" items\""); return; }
                    s.Append('[');
                    for (var k = 0; k < list.Count && k < 16; k++)
                    {
                        if (k > 0) s.Append(',');
                        Plain(s, list[k], depth + 1);
                    }
                    s.Append(']');
                    return;
                }
            }
            var id = IdOf(v);
            if (id != null) { Plain(s, id, depth + 1); return; }
            string name;
            if (!typeNames.TryGetValue(type, out name))
            {
                var b = new StringBuilder();
                Str(b, type.Name);
                typeNames[type] = name = b.ToString();
            }
            s.Append(name);
        }

        /// <summary>An integer's digits, appended without a string made of them (mono's Append(int) makes one, with the
        /// current culture's lookup, for every number of every record).</summary>
        static readonly char[] digits = new char[20];  // (the recorder runs on one thread)

        static StringBuilder N(StringBuilder s, long n)
        {
            if (n >= 0 && n < 10) return s.Append((char)('0' + n));
            var neg = n < 0;
            var u = neg ? (ulong)(-(n + 1)) + 1 : (ulong)n;
            var at = digits.Length;
            do { digits[--at] = (char)('0' + (int)(u % 10)); u /= 10; } while (u != 0);
            if (neg) s.Append('-');
            return s.Append(digits, at, digits.Length - at);
        }

        /// <summary>A cell or object by its ID, a polygon by its PolyID, a BSP leaf by its LeafIdx, a BSP node by its
        /// plane (port/tracing.plain's order); null for anything else.</summary>
        object IdOf(object v)
        {
            var type = v.GetType();
            Func<object, object> get;
            if (!idOf.TryGetValue(type, out get))
            {
                const BindingFlags flags = BindingFlags.Public | BindingFlags.Instance;
                foreach (var name in new[] { "ID", "PolyID", "LeafIdx", "SplittingPlane" })
                {
                    var f = type.GetField(name, flags);
                    var p = f == null ? type.GetProperty(name, flags) : null;
                    var ft = f != null ? f.FieldType : p?.PropertyType;
                    if (ft == null) continue;
                    if (name != "SplittingPlane" && !(ft == typeof(uint) || ft == typeof(int) || ft == typeof(ushort) || ft == typeof(short))) continue;
                    // compiled, not reflection's GetValue: mono's costs a microsecond, on most arguments of most calls
                    var o = Expression.Parameter(typeof(object), "o");
                    var typed = Expression.Convert(o, type);
                    var member = f != null ? Expression.Field(typed, f) : Expression.Property(typed, p);
                    get = Expression.Lambda<Func<object, object>>(Expression.Convert(member, typeof(object)), o).Compile();
                    break;
                }
                idOf[type] = get;
            }
            return get?.Invoke(v);
        }

        static string B(bool b) => b ? "true" : "false";

        // A number's text, by its bits: formatting ("G17") is most of the recorder's cost, and a trace writes the same few
        // values over and over (a path's snapshot at every entry and exit). Bounded: emptied when full.
        [StructLayout(LayoutKind.Explicit)]
        struct Bits { [FieldOffset(0)] public float F; [FieldOffset(0)] public int I; [FieldOffset(0)] public double D; [FieldOffset(0)] public long L; }

        const int Remembered = 1 << 18;
        static readonly Dictionary<int, string> floatText = new Dictionary<int, string>();
        static readonly Dictionary<long, string> doubleText = new Dictionary<long, string>();

        static StringBuilder F(StringBuilder s, float f)
        {
            var bits = new Bits { F = f }.I;
            string text;
            if (!floatText.TryGetValue(bits, out text))
            {
                if (float.IsNaN(f) || float.IsInfinity(f)) text = "\"0x" + bits.ToString("x8") + "\"";
                else if (f == 0) text = bits < 0 ? "-0.0" : "0.0";  // mono prints -0 as "0"
                else text = Number(((double)f).ToString("G17", CultureInfo.InvariantCulture));
                if (floatText.Count >= Remembered) floatText.Clear();
                floatText[bits] = text;
            }
            return s.Append(text);
        }

        /// <summary>A float as JSON that reads back as a float: "-0" would read as the integer 0 and lose its sign.</summary>
        static string Number(string text)
        {
            if (text.IndexOf('.') < 0 && text.IndexOf('E') < 0 && text.IndexOf('e') < 0) return text + ".0";
            return text;
        }

        static StringBuilder D(StringBuilder s, double d)
        {
            var bits = new Bits { D = d }.L;
            string text;
            if (!doubleText.TryGetValue(bits, out text))
            {
                if (double.IsNaN(d) || double.IsInfinity(d)) text = "null";
                else if (d == 0) text = bits < 0 ? "-0.0" : "0.0";
                else text = Number(d.ToString("G17", CultureInfo.InvariantCulture));
                if (doubleText.Count >= Remembered) doubleText.Clear();
                doubleText[bits] = text;
            }
            return s.Append(text);
        }

        static StringBuilder V(StringBuilder s, Vector3 v)
        {
            s.Append('['); F(s, v.X).Append(','); F(s, v.Y).Append(','); return F(s, v.Z).Append(']');
        }

        static void Str(StringBuilder s, string str)
        {
            s.Append('"');
            foreach (var c in str)
            {
                if (c == '"' || c == '\\') s.Append('\\').Append(c);
                else if (c < ' ') s.Append("\\u").Append(((int)c).ToString("x4"));
                else s.Append(c);
            }
            s.Append('"');
        }
    }
}
