// acconform's trace recorder (MIT), compiled into the facade of an instrumented ACE copy only (oracle/instrumented.py):
// the instrumented methods call it at their entry and exits (Acconform.Trace.Hooks, injected by Instrument.cs), and it
// writes the records the port's tracing writes (port/tracing.py), one JSON array a line:
//     [anchor id, event, tick, step, within id, args, result, path, mover, placing]
// (-1 or null where the port's record leaves the field out). acconform/oracle/instrumented.py turns them into
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
        void TickDone() { Write(tickId, "tick", null, null, null, null); }

        Frame Top => running.Count > 0 ? running[running.Count - 1] : null;

        public override void Enter(int id, object[] args)
        {
            var kind = kinds[id];
            var frame = new Frame { Id = id };
            if (kind[0] == 'p')
            {
                foreach (var a in args)
                    if (a is Transition) { transition = (Transition)a; break; }
                if (kind[1] == 'f') step = -1;
                var top = Top;
                if (kind[1] == 'a' && top != null && kinds[top.Id][1] == 'f')  // a pass of FindTransitionalPosition's loop
                {
                    step = steps++;
                    Write(ftpId, "step", null, null, transition, null);
                }
                if (kind[1] == 'i' && top != null && kinds[top.Id][1] == 't')  // a TransitionalInsert attempt
                    Write(tiId, "insert", null, null, transition, null);
                if (kind[1] == 'f') steps = 0;
                Write(id, "enter", Json(args), null, transition, null);
            }
            else if (kind[0] == 'm' && args.Length > 0 && args[0] is PhysicsObj && ((PhysicsObj)args[0]).ID == MoverId &&
                     ((PhysicsObj)args[0]).Position != null)
            {
                frame.Mover = (PhysicsObj)args[0];
                Write(id, "enter", Json(args), null, null, frame.Mover);
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
            for (var k = at + 1; k < running.Count; k++)  // a placement left by an exception ends with it
                if (running[k].Places) { placing = running[k].Outer; break; }
            running.RemoveRange(at, running.Count - at);
            var kind = kinds[id];
            var answer = refs == null ? Json(result) : Json(refs);
            if (kind[0] == 'p')
            {
                if (kind[1] == 'f') step = -1;
                Write(id, "exit", null, answer, transition, null);
            }
            else if (frame.Mover != null)
                Write(id, "exit", null, answer, null, frame.Mover);
            else
                Write(id, "call", frame.Args, answer, null, null);
            if (frame.Places) placing = frame.Outer;
        }

        // The snapshots are taken first, into builders of their own: a getter they read may be an instrumented method,
        // whose records go before this one (and must not land inside it).
        void Write(int id, string ev, string args, string result, Transition path, PhysicsObj mover)
        {
            string pathText = null, moverText = null;
            if (path != null)
            {
                var b = Borrow();
                try { if (Path(b, path)) pathText = b.ToString(); } finally { depth--; }
            }
            if (mover != null)
            {
                var b = Borrow();
                try { Mover(b, mover); moverText = b.ToString(); } finally { depth--; }
            }
            var within = Top;
            sb.Append('[').Append(id).Append(",\"").Append(ev).Append("\",").Append(tick).Append(',').Append(step).Append(',')
              .Append(within != null ? within.Id : -1).Append(',').Append(args ?? "null").Append(',').Append(result ?? "null")
              .Append(',').Append(pathText ?? "null").Append(',').Append(moverText ?? "null").Append(',').Append(placing).Append("]\n");
            Records++;
            if (!keep && sb.Length > Dropped) sb.Clear();
        }

        // ------------------------------------------------------------------ snapshots
        /// <summary>acconform.trace.PathState's fields, in order, appended to s; false (nothing written) when the
        /// transition has no path yet.</summary>
        static bool Path(StringBuilder s, Transition t)
        {
            if (t == null || t.SpherePath == null || t.CollisionInfo == null) return false;
            var sp = t.SpherePath;
            var ci = t.CollisionInfo;
            s.Append('[').Append(sp.CheckCell != null ? sp.CheckCell.ID : 0u).Append(',');
            V(s, sp.CheckPos != null ? sp.CheckPos.Frame.Origin : Vector3.Zero).Append(',');
            s.Append(sp.CurCell != null ? sp.CurCell.ID : 0u).Append(',');
            V(s, sp.CurPos != null ? sp.CurPos.Frame.Origin : Vector3.Zero).Append(',');
            V(s, sp.GlobalOffset).Append(',');
            Contact(s, ci.ContactPlaneValid, ci.ContactPlaneCellID, ci.ContactPlaneIsWater, ci.ContactPlane).Append(',');
            Contact(s, ci.LastKnownContactPlaneValid, ci.LastKnownContactPlaneCellID, ci.LastKnownContactPlaneIsWater,
                    ci.LastKnownContactPlane).Append(',');
            s.Append('[').Append(B(ci.CollisionNormalValid)).Append(','); V(s, ci.CollisionNormal).Append("],");
            s.Append('[').Append(B(ci.SlidingNormalValid)).Append(','); V(s, ci.SlidingNormal).Append("],");
            if (sp.Walkable != null) { s.Append('['); V(s, sp.Walkable.Plane.Normal).Append(','); F(s, sp.Walkable.Plane.D).Append("],"); }
            else s.Append("null,");
            s.Append(B(sp.StepUp)).Append(',').Append(B(sp.StepDown)).Append(',').Append(B(sp.Collide)).Append(',')
             .Append(B(sp.NegPolyHit)).Append(',').Append(ci.FramesStationaryFall).Append(',')
             .Append(t.ObjectInfo != null ? (uint)t.ObjectInfo.State : 0u).Append(',')
             .Append(B(sp.PlacementAllowsSliding)).Append(',').Append(B(sp.BuildingCheck)).Append(',')
             .Append(B(sp.HitsInteriorCell)).Append(']');
            return true;
        }

        static StringBuilder Contact(StringBuilder s, bool valid, uint cell, bool water, Plane plane)
        {
            s.Append('[').Append(B(valid)).Append(',').Append(cell).Append(',').Append(B(water)).Append(',');
            V(s, plane.Normal).Append(',');
            return F(s, plane.D).Append(']');
        }

        /// <summary>acconform.outcome.TickState's fields, in order (`updated` false, as tracing.tick_state(obj, False)).</summary>
        static void Mover(StringBuilder s, PhysicsObj obj)
        {
            s.Append("[false,");
            D(s, obj.UpdateTime).Append(',').Append(obj.Position.ObjCellID).Append(',').Append(obj.CurCell != null ? obj.CurCell.ID : 0u).Append(',');
            V(s, obj.Position.Frame.Origin).Append(',');
            var q = obj.Position.Frame.Orientation;
            s.Append('['); F(s, q.W).Append(','); F(s, q.X).Append(','); F(s, q.Y).Append(','); F(s, q.Z).Append("],");
            V(s, obj.Velocity).Append(','); V(s, obj.Acceleration).Append(','); V(s, obj.Omega).Append(',');
            V(s, obj.CachedVelocity).Append(',');
            s.Append((uint)obj.State).Append(',').Append((uint)obj.TransientState).Append(',').Append(obj.ContactPlaneCellID).Append(',');
            s.Append('['); V(s, obj.ContactPlane.Normal).Append(','); F(s, obj.ContactPlane.D).Append("],");
            V(s, obj.SlidingNormal).Append(',').Append(B(obj.JumpedThisFrame)).Append(",[");
            var first = true;
            if (obj.ShadowObjects != null)
                foreach (var id in obj.ShadowObjects.Keys) { if (!first) s.Append(','); s.Append(id); first = false; }
            s.Append("]]");
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

        void Plain(StringBuilder s, object v, int depth)
        {
            // (if and casts, not a type switch: mono's mcs does not parse type patterns)
            if (v == null) { s.Append("null"); return; }
            if (v is bool) { s.Append(B((bool)v)); return; }
            if (v is string) { Str(s, (string)v); return; }
            if (v is Enum) { s.Append(Convert.ToInt64(v, CultureInfo.InvariantCulture)); return; }
            if (v is float) { F(s, (float)v); return; }
            if (v is double) { D(s, (double)v); return; }
            if (v is int || v is uint || v is short || v is ushort || v is byte || v is sbyte || v is long || v is ulong)
            {
                s.Append(Convert.ToString(v, CultureInfo.InvariantCulture));
                return;
            }
            if (v is Quaternion)
            {
                var q = (Quaternion)v;
                s.Append('['); F(s, q.W).Append(','); F(s, q.X).Append(','); F(s, q.Y).Append(','); F(s, q.Z).Append(']');
                return;
            }
            if (v is Vector3) { V(s, (Vector3)v); return; }
            if (v is Vector2) { var w = (Vector2)v; s.Append('['); F(s, w.X).Append(','); F(s, w.Y).Append(']'); return; }
            var sph = v as Sphere;
            if (sph != null)
            {
                s.Append('['); F(s, sph.Center.X).Append(','); F(s, sph.Center.Y).Append(','); F(s, sph.Center.Z).Append(',');
                F(s, sph.Radius).Append(']');
                return;
            }
            if (v is Plane)
            {
                var p = (Plane)v;
                s.Append('['); F(s, p.Normal.X).Append(','); F(s, p.Normal.Y).Append(','); F(s, p.Normal.Z).Append(','); F(s, p.D).Append(']');
                return;
            }
            var fr = v as AFrame;
            if (fr != null)
            {
                s.Append('['); F(s, fr.Origin.X).Append(','); F(s, fr.Origin.Y).Append(','); F(s, fr.Origin.Z).Append(',');
                F(s, fr.Orientation.W).Append(','); F(s, fr.Orientation.X).Append(','); F(s, fr.Orientation.Y).Append(',');
                F(s, fr.Orientation.Z).Append(']');
                return;
            }
            var box = v as BBox;
            if (box != null)
            {
                s.Append('['); F(s, box.Min.X).Append(','); F(s, box.Min.Y).Append(','); F(s, box.Min.Z).Append(',');
                F(s, box.Max.X).Append(','); F(s, box.Max.Y).Append(','); F(s, box.Max.Z).Append(']');
                return;
            }
            var pos = v as Position;
            if (pos != null)
            {
                s.Append('[').Append(pos.ObjCellID).Append(','); F(s, pos.Frame.Origin.X).Append(','); F(s, pos.Frame.Origin.Y)
                 .Append(','); F(s, pos.Frame.Origin.Z).Append(']');
                return;
            }
            var list = v as IList;
            if (list != null)
            {
                if (depth >= 3) { s.Append('"').Append(list.Count).Append(" items\""); return; }
                s.Append('[');
                for (var k = 0; k < list.Count && k < 16; k++)
                {
                    if (k > 0) s.Append(',');
                    Plain(s, list[k], depth + 1);
                }
                s.Append(']');
                return;
            }
            var id = IdOf(v);
            if (id != null) { Plain(s, id, depth + 1); return; }
            Str(s, v.GetType().Name);
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
                    if (f != null) get = o => f.GetValue(o);
                    else get = o => p.GetValue(o, null);
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
