// acconform oracle facade -- MIT licensed, part of acconform (not ACE code).
//
// Runs one acconform scene through ACE's physics in a single call: it takes the scene packed by
// acconform/oracle/pack.py, builds ACE's objects with ACE's own public API, runs the transition
// as PhysicsObj.transition does, and returns the outcome packed for pack.unpack_outcome. It is
// compiled on the user's machine against the user's ACE assemblies when the oracle loads, and
// cached outside the repository. It touches only members listed in oracle/members.py, which the
// oracle checks exist before compiling this file.
using System;
using System.Collections.Concurrent;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Numerics;
using System.Reflection;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using System.Runtime.Serialization;
using System.Text;

using ACE.DatLoader;
using ACE.DatLoader.FileTypes;
using LandblockId = ACE.Entity.LandblockId;
using ObjectGuid = ACE.Entity.ObjectGuid;
using DatGfxObj = ACE.DatLoader.FileTypes.GfxObj;
using ACE.Entity.Enum;
using ACE.Server.Physics;
using ACE.Server.Physics.Animation;
using ACE.Server.Physics.BSP;
using ACE.Server.Physics.Collision;
using ACE.Server.Physics.Common;
using ACE.Server.Physics.Entity;
using ACE.Server.Physics.Managers;
using ACE.Server.Physics.Util;

namespace Acconform.Oracle
{
    public static partial class Facade
    {
        public const int PackVersion = 18;

        /// <summary>Reuse built landblocks across scenes (keyed by their DAT bytes and the height table).
        /// A landblock's cells get the scene's static objects, which leave them after each scene.</summary>
        public static bool CacheLandblocks = true;
        public const int CacheLimit = 2048;
        static readonly Dictionary<ulong, LandblockEntry> landblockCache = new Dictionary<ulong, LandblockEntry>();
        static readonly List<PhysicsObj> sceneStatics = new List<PhysicsObj>();
        static readonly Dictionary<uint, ACE.Server.Physics.Common.Landblock> sceneLandblocks =
            new Dictionary<uint, ACE.Server.Physics.Common.Landblock>();
        static readonly List<uint> sceneRecords = new List<uint>();  // DAT ids this scene put in the portal FileCache
        static ConcurrentDictionary<uint, FileType> portalFiles;  // DatManager.PortalDat.FileCache
        static ConcurrentDictionary<uint, FileType> cellFiles;  // DatManager.CellDat.FileCache
        // per static, in scene order: its cell id and DAT id, and the PhysicsObj placed outdoors (null for a
        // static in an EnvCell: ACE makes that one when it loads the cell, EnvCell.init_static_objects)
        static readonly List<uint> staticCellIds = new List<uint>();
        static readonly List<uint> staticDids = new List<uint>();
        static readonly List<PhysicsObj> staticObjs = new List<PhysicsObj>();
        // for each static, in scene order: the ids of PhysicsObj.ShadowObjects (null until read after the transition)
        static List<List<uint>> staticCells;

        // the scene's placement (mover.placement): through enter_world or SetPosition (with its SetPositionFlags), and
        // whether Position.GetCell runs first
        static bool hasPlacement, placementEnterWorld, placementGetCell;
        static int placementFlags;
        // the mover once ACE's placement ran (it leaves its cells after the scene), and what the placement left
        static PhysicsObj placedMover;
        static bool placed;
        static int placedResult;
        static uint placedCell, placedCurCell, placedTransient;
        static Vector3 placedOrigin;
        static Quaternion placedOrientation;
        static readonly List<uint> placedShadowCells = new List<uint>();

        // a tick scene (scene/4): its driver (0 update_object, 1 request_pos), the clock when the mover is made,
        // and per step the absolute clock value (Ticks.times()) and the inputs applied before it
        sealed class TickStep
        {
            public double Time;
            public uint Mask;  // bit i: input i of acconform.scene.TICK_INPUTS is present
            public uint State, Transient;
            public Vector3 Velocity, LocalVelocity, Omega, Jump, SequenceVelocity, SequenceOmega;
            public ACE.Server.Physics.Common.Position RequestPos;
            public ACE.Server.Network.Structure.RawMotionState Motion;  // a MoveToState's RawMotionState
            // the server's calls into the managers (acconform/motion_scene.py): a stop (its index in STOPS), a
            // key's DoMotion / StopMotion, MoveTo a position or an object, turn to a heading or an object
            public uint Stop;
            public uint DoMotion, DoMotionHoldKey, StopMotion, StopMotionHoldKey;
            public ACE.Server.Physics.Common.Position MoveToPos;
            public MovementParameters MoveToParams, TurnToHeadingParams, MoveToObjectParams, TurnToObjectParams;
            public uint MoveToObjectId, TurnToObjectId, StickToId;
            public uint DoorId; public bool DoorEthereal;  // scene/7: a static opens (ethereal) or closes
            public List<OtherStep> Others;  // scene/8: the other movers' inputs, in the step's order (null: none)
        }

        // scene/8: another mover's inputs for one step: which (its index in `others`), a mask of the present inputs
        // (bit i: acconform.scene.OTHER_INPUTS[i]) and their values
        sealed class OtherStep
        {
            public int Index;
            public uint Mask;
            public uint State, Transient;
            public Vector3 Velocity, LocalVelocity, Omega, Jump, SequenceVelocity, SequenceOmega;
            public uint ParentId;  // bit 512: held anew by the mover or another other (bit 256: unset_parent first)
            public int ParentLocation, Placement;
            public byte ParentForm;
            public AFrame ParentFrame;
            public uint ExecuteMotion;  // bit 2048 (pack 18): WorldObject.ExecuteMotion's physics with this motion command
        }

        // scene/8: another mover as the scene gives it (OtherMover), its PhysicsObj and WorldObject once made, and
        // whether it entered the world (AddPhysicsObj's success: only then does a tick step it)
        sealed class Other
        {
            public uint Did, Id;
            public byte Weenie;  // acconform.scene.WEENIE_CLASSES: 0 player, 1 creature, 2 monster, 3 object
            public PlayerKillerStatus Pks;
            public float Scale;
            public PhysicsState State;
            public TransientStateFlags Transient;
            public Vector3 Velocity;
            public ACE.Server.Physics.Common.Position Begin;
            public PhysicsObj Obj;
            public ACE.Server.WorldObjects.WorldObject WorldObject;
            public bool Entered;
            public int PlacedResult;
            public uint PlacedCell, PlacedCurCell, PlacedTransient;
            public Vector3 PlacedOrigin;
            public Quaternion PlacedOrientation;
            public List<uint> PlacedShadowCells;
            // a child (scene/8 `parent`): held by the mover or an earlier other at a ParentLocation with a Placement
            public bool HasParent;
            public byte ParentForm;  // 1: at a location (set_parent(parent, location)); 2: the frame form, at ParentLocation's part
            public AFrame ParentFrame;
            public uint ParentId;
            public int ParentLocation, Placement;
            // a projectile (weenie 4 ammunition, 5 spell_projectile; pack 14): its launch, and once launched
            public bool HasLaunch, LeadTarget, Arc, Tracking, AltSolver;
            public float RotationSpeed;  // the projectile's RotationSpeed (a weenie property; 0: none, left null)
            public byte ReportCollisions;  // the WorldObject's PropertyBool.ReportCollisions: 0 unset, 1 false, 2 true
            public uint MotionTableId;  // the WorldObject's MotionTableId (pack 18, scene/8 others[].motion_table; 0: none)
            public byte SpellKind;  // acconform.scene.SPELL_KINDS: 0 plain, 1 Rolling Death, 2 a wall, 3 a Ring, 4 Ring spell 3818
            public int LaunchTick;
            public uint Launcher, Target;
            public float Speed;
            public Vector3 Origin;
            public Quaternion Orientation;
            public bool Launched;
            public double CreationTime;  // WorldObject.physicsCreationTime: the clock when the launch made it
        }
        static readonly List<Other> sceneOthers = new List<Other>();
        static bool errored;  // the scene ended in an exception (no placements written)
        static bool othersRead;  // the scene has other movers: the ticks carry them and the CollisionTables
        static bool hasTicks;
        static byte tickDriver;
        static double tickStart;
        static readonly List<TickStep> tickSteps = new List<TickStep>();
        static int ticksRun;  // -1: not a tick scene (or an error before the first tick)
        static uint moverMotionTableId;  // the mover's MotionTableId (0: none)
        // the scene's motion_queries (pack 17): function (byte), stance, motion, current motion (uint), whether it is
        // given (byte), speed (float: 1.0f when the scene gives none, C#'s default)
        static readonly List<Tuple<byte, uint, uint, uint, bool, float>> motionQueries = new List<Tuple<byte, uint, uint, uint, bool, float>>();
        static readonly MemoryStream answerStream = new MemoryStream(1024);
        static int answersRun;  // -1: no queries asked (none in the scene, or an error before they were asked)
        static FieldInfo attackFrameCacheField;  // the DatLoader MotionTable's private static attackFrameCache
        static ACE.Server.WorldObjects.Player moverPlayer;  // the mover's WorldObject (the last scene's until the next)
        static uint locationCell;  // the cell of the mover's WorldObject.Location (Player.UpdatePlayerPosition)
        static bool moverMotion;  // the mover has a motion table: each tick also carries its motion layer (WriteMotion)
        static Action<double> setPortalYearTicks;

        static readonly List<Tuple<int, int>> tableUsed = new List<Tuple<int, int>>();
        static bool tableCleared;
        static byte[] lastTableBytes;
        static int lastTableId;
        static readonly Dictionary<ulong, TableEntry> tableIds = new Dictionary<ulong, TableEntry>();

        static FieldInfo lbmTable;
        static FieldInfo serverLbPhysics;
        static FieldInfo serverLbId;
        static FieldInfo serverLbCellLandblock, serverLbInfo;
        static FieldInfo physicsAdjacents;  // the physics Landblock's private adjacents (null until SetAdjacents)
        static MethodInfo setAdjacents;  // LandblockManager's private static SetAdjacents(Landblock, bool, bool)

        sealed class LandblockEntry { public byte[] Bytes; public int Table; public ACE.Server.Physics.Common.Landblock Landblock; }
        sealed class TableEntry { public byte[] Bytes; public int Id; }

        // Counters for the last scene (written after the times in every outcome; see pack.unpack_outcome).
        static int landblocksBuilt, landblocksReused;
        static double buildMicros;
        static double transitionMicros;  // PhysicsObj.transition's work: MakeTransition .. CleanupTransition

        // ------------------------------------------------------------------ pinned buffers
        // Python copies a packed scene straight into InputAddress (ctypes.memmove) and reads the packed
        // outcome straight from OutputAddress: no per-element conversion and no base64 on either side.
        // The arrays stay pinned (GCHandle) until they are replaced by bigger ones.
        static byte[] inBuf, outBuf;
        static GCHandle inHandle, outHandle;
        static MemoryStream inStream;
        static BinaryReader inReader;
        static readonly MemoryStream outStream = new MemoryStream(4096);
        static readonly BinaryWriter outWriter = new BinaryWriter(outStream);
        public static long InputAddress, OutputAddress;
        public static int InputCapacity, OutputCapacity;

        /// <summary>Make the pinned input buffer hold at least n bytes (InputAddress may change).</summary>
        public static void EnsureInput(int n)
        {
            if (inBuf != null && inBuf.Length >= n) return;
            if (inHandle.IsAllocated) inHandle.Free();
            inBuf = new byte[Math.Max(n, inBuf == null ? 1 << 16 : 2 * inBuf.Length)];
            inHandle = GCHandle.Alloc(inBuf, GCHandleType.Pinned);
            InputAddress = inHandle.AddrOfPinnedObject().ToInt64();
            InputCapacity = inBuf.Length;
            inStream = new MemoryStream(inBuf, 0, inBuf.Length, false, true);
            inReader = new BinaryReader(inStream);
        }

        static void EnsureOutput(int n)
        {
            if (outBuf != null && outBuf.Length >= n) return;
            if (outHandle.IsAllocated) outHandle.Free();
            outBuf = new byte[Math.Max(n, outBuf == null ? 1 << 12 : 2 * outBuf.Length)];
            outHandle = GCHandle.Alloc(outBuf, GCHandleType.Pinned);
            OutputAddress = outHandle.AddrOfPinnedObject().ToInt64();
            OutputCapacity = outBuf.Length;
        }

        /// <summary>log4net's first use reads its settings through System.Configuration, which .NET
        /// (not mono) refuses outside an application: log4net catches that and prints the whole
        /// stack trace to stderr, once per process, before any of ACE's code runs. Its first use is
        /// made here, with .NET's stderr silenced; nothing of ACE's physics reads log4net.</summary>
        static void QuietLog4netStartup()
        {
            var logManager = Type.GetType("log4net.LogManager, log4net");
            if (logManager == null) return;
            var err = Console.Error;
            Console.SetError(TextWriter.Null);
            try { logManager.GetMethod("GetLogger", new[] { typeof(Type) })?.Invoke(null, new object[] { typeof(Facade) }); }
            catch (Exception) { }
            finally { Console.SetError(err); }
        }

        /// <summary>Allocate both pinned buffers and publish the native entry points (called once
        /// when the oracle loads).</summary>
        public static void Init()
        {
            QuietLog4netStartup();
            InstallDats();
            EnsureInput(1 << 16);
            EnsureOutput(1 << 12);
            runEntry = RunPinnedNative;
            runManyEntry = RunManyPinnedNative;
            RunPinnedAddress = Marshal.GetFunctionPointerForDelegate(runEntry).ToInt64();
            RunManyPinnedAddress = Marshal.GetFunctionPointerForDelegate(runManyEntry).ToInt64();
        }

        // ------------------------------------------------------------------ native entry points
        // A pythonnet call binds its method by reflection on every call (about 5 us); Python calls
        // these through ctypes instead (under 1 us): plain int in, int out, with the scene and the
        // outcome in the pinned buffers. The delegates live in static fields so the collector keeps
        // the thunks their addresses point to. No exception may cross into native code: RunInto
        // already turns ACE's into outcomes, anything else is kept in LastNativeError and -1 returned.
        [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
        public delegate int PinnedEntry(int length);
        static PinnedEntry runEntry, runManyEntry;
        public static long RunPinnedAddress, RunManyPinnedAddress;
        public static string LastNativeError = "";

        static int RunPinnedNative(int length)
        {
            try { return RunPinned(length); }
            catch (Exception e) { LastNativeError = e.ToString(); return -1; }
        }

        static int RunManyPinnedNative(int length)
        {
            try { return RunManyPinned(length); }
            catch (Exception e) { LastNativeError = e.ToString(); return -1; }
        }

        static int CopyOut()
        {
            var n = (int)outStream.Length;
            EnsureOutput(n);  // a bigger buffer has a new address; the caller sees n > its OutputCapacity
            Buffer.BlockCopy(outStream.GetBuffer(), 0, outBuf, 0, n);
            return n;
        }

        /// <summary>Run the packed scene in the first `length` bytes of the input buffer; the packed
        /// outcome is in the output buffer; returns its length.</summary>
        public static int RunPinned(int length)
        {
            outStream.SetLength(0);
            inStream.Position = 0;
            RunInto(inReader, length, outWriter);
            return CopyOut();
        }

        /// <summary>Several scenes from the input buffer (int count, then per scene int length + bytes);
        /// per outcome (int length + bytes) in the output buffer; returns the total length.</summary>
        public static int RunManyPinned(int length)
        {
            outStream.SetLength(0);
            inStream.Position = 0;
            var n = inReader.ReadInt32();
            var pos = 4;
            for (var i = 0; i < n; i++)
            {
                inStream.Position = pos;
                var len = inReader.ReadInt32();
                var lenAt = outStream.Position;
                outWriter.Write(0);
                inStream.Position = pos + 4;
                RunInto(inReader, len, outWriter);
                var end = outStream.Position;
                outStream.Position = lenAt;
                outWriter.Write((int)(end - lenAt - 4));
                outStream.Position = end;
                pos += 4 + len;
            }
            return CopyOut();
        }

        static void RunInto(BinaryReader r, int length, BinaryWriter w)
        {
            var outcome = (MemoryStream)w.BaseStream;
            var start = outcome.Position;
            double fvpMicros = 0;
            landblocksBuilt = landblocksReused = 0;
            buildMicros = transitionMicros = 0;
            staticCells = null;
            placed = false;
            errored = false;
            othersRead = false;
            sceneOthers.Clear();
            ticksRun = -1;
            ClearTicks();
            var total = Stopwatch.StartNew();
            try
            {
                var mover = BuildScene(r);
                var obj = mover.Item1;
                var oldPos = mover.Item2;
                if (hasPlacement)
                {
                    Place(obj, mover.Item2);
                    oldPos = new ACE.Server.Physics.Common.Position(obj.Position);
                }
                EnterOthers(obj);
                if (hasTicks)
                {
                    // a tick scene: ACE's per-tick update moves the mover (it enters cells: it leaves them after the scene)
                    placedMover = obj;
                    locationCell = obj.Position.ObjCellID;  // where it entered: its Location (SyncLocation)
                    RunTicks(obj);
                    AskMotionQueries();
                    w.Write((byte)(answersRun >= 0 ? 4 : 3));  // 4: the motion queries' answers after the ticks
                    w.Write(0.0);
                }
                else if (!hasPlacement || obj.CurCell != null)
                {
                    var ok = RunTransition(obj, oldPos, mover.Item3, out var trans, out fvpMicros);
                    WriteOutcome(w, ok, trans, obj, fvpMicros);
                }
                else
                    WriteNoTransition(w, obj);
                staticCells = ReadStaticCells();
                RemoveStatics();
                w.Write(total.Elapsed.TotalMilliseconds * 1000.0);
            }
            catch (Exception e)
            {
                staticCells = null;  // an error outcome carries no registration
                placed = false;  // nor a placement
                errored = true;  // nor the other movers' placements
                ticksRun = -1;  // nor ticks
                outcome.Position = start;
                outcome.SetLength(start);
                w.Write((byte)0xEE);
                var msg = ErrorBytes(e);
                w.Write(msg.Length);
                w.Write(msg);
                w.Write(fvpMicros);
                try { RemoveStatics(); }
                catch (Exception) { ClearCache(); sceneStatics.Clear(); }
                w.Write(total.Elapsed.TotalMilliseconds * 1000.0);
            }
            w.Write(landblocksBuilt);
            w.Write(landblocksReused);
            w.Write(buildMicros);
            w.Write(transitionMicros);
            WriteStaticCells(w, staticCells);
            WritePlacement(w);
            WriteOtherPlacements(w, errored);
            w.Write(ticksRun);
            if (ticksRun > 0) WriteTicks(w);
            if (!errored && answersRun >= 0)
            {
                w.Write(answersRun);
                w.Write(answerStream.GetBuffer(), 0, (int)answerStream.Length);
            }
        }

        // ------------------------------------------------------------------ motion queries (scene/8 motion_queries)

        /// <summary>int n, then per query: the function (byte: 0 GetAttackFrames, 1 GetAnimationLength, 2 GetRunSpeed,
        /// 3 GetTurnSpeed, 4 the DatLoader MotionTable's GetAnimationLength), stance, motion and current motion (uint), whether
        /// the current motion is given (byte), the speed (float).</summary>
        static void ReadMotionQueries(BinaryReader r)
        {
            var n = r.ReadInt32();
            for (var i = 0; i < n; i++)
            {
                var f = r.ReadByte();
                var stance = r.ReadUInt32();
                var motion = r.ReadUInt32();
                var current = r.ReadUInt32();
                var hasCurrent = r.ReadByte() != 0;
                motionQueries.Add(Tuple.Create(f, stance, motion, current, hasCurrent, r.ReadSingle()));
            }
        }

        /// <summary>Asks the scene's queries in order, after the last tick, as ACE's WorldObjects ask them (ACE's own static
        /// methods; DatManager.PortalDat.ReadFromDat for the DatLoader's), each answer into answerStream: byte 0 and a float,
        /// byte 1 and GetAttackFrames' list (int n, per entry its time, the AttackHook's Direction (int) and AttackCone:
        /// PartIndex (uint), LeftX, LeftY, RightX, RightY, Radius, Height), or byte 0xEE and what it threw (int length,
        /// UTF-8).</summary>
        static void AskMotionQueries()
        {
            if (motionQueries.Count == 0) return;
            var w = new BinaryWriter(answerStream);
            var id = moverMotionTableId;
            foreach (var q in motionQueries)
            {
                try
                {
                    var stance = (MotionStance)q.Item2;
                    var motion = (MotionCommand)q.Item3;
                    var current = (MotionCommand)q.Item4;
                    float v;
                    switch (q.Item1)
                    {
                        case 0:
                            var frames = ACE.Server.Physics.Animation.MotionTable.GetAttackFrames(id, stance, motion);
                            w.Write((byte)1);
                            w.Write(frames.Count);
                            foreach (var f in frames)
                            {
                                w.Write(f.Item1);
                                w.Write((int)f.Item2.Direction);
                                var c = f.Item2.AttackCone;
                                w.Write(c.PartIndex);
                                w.Write(c.LeftX); w.Write(c.LeftY); w.Write(c.RightX); w.Write(c.RightY);
                                w.Write(c.Radius); w.Write(c.Height);
                            }
                            continue;
                        case 1:
                            v = q.Item5 ? ACE.Server.Physics.Animation.MotionTable.GetAnimationLength(id, stance, current, motion, q.Item6)
                                        : ACE.Server.Physics.Animation.MotionTable.GetAnimationLength(id, stance, motion, q.Item6);
                            break;
                        case 2:
                            v = ACE.Server.Physics.Animation.MotionTable.GetRunSpeed(id);
                            break;
                        case 3:
                            v = ACE.Server.Physics.Animation.MotionTable.GetTurnSpeed(id);
                            break;
                        default:
                            var table = DatManager.PortalDat.ReadFromDat<ACE.DatLoader.FileTypes.MotionTable>(id);
                            v = q.Item5 ? table.GetAnimationLength(stance, motion, current) : table.GetAnimationLength(motion);
                            break;
                    }
                    w.Write((byte)0);
                    w.Write(v);
                }
                catch (Exception e)
                {
                    var msg = ErrorBytes(e);
                    w.Write((byte)0xEE);
                    w.Write(msg.Length);
                    w.Write(msg);
                }
            }
            w.Flush();
            answersRun = motionQueries.Count;
        }

        /// <summary>ACE's static motion-table caches, which outlive a scene in ACE (a server keeps them for the process):
        /// the physics MotionTable's WalkSpeed, RunSpeed and TurnSpeed and the DatLoader MotionTable's attackFrameCache
        /// (private: by reflection), all keyed by the motion table id that every scene's mover shares. Cleared before
        /// each scene, so each scene asks as a fresh server does.</summary>
        static void ClearMotionTableCaches()
        {
            if (!ACE.Server.Physics.Animation.MotionTable.WalkSpeed.IsEmpty) ACE.Server.Physics.Animation.MotionTable.WalkSpeed.Clear();
            if (!ACE.Server.Physics.Animation.MotionTable.RunSpeed.IsEmpty) ACE.Server.Physics.Animation.MotionTable.RunSpeed.Clear();
            if (!ACE.Server.Physics.Animation.MotionTable.TurnSpeed.IsEmpty) ACE.Server.Physics.Animation.MotionTable.TurnSpeed.Clear();
            if (attackFrameCacheField == null)
                attackFrameCacheField = typeof(ACE.DatLoader.FileTypes.MotionTable).GetField("attackFrameCache", BindingFlags.NonPublic | BindingFlags.Static);
            var cache = attackFrameCacheField.GetValue(null) as System.Collections.IDictionary;
            if (cache != null && cache.Count > 0) cache.Clear();
        }

        // ------------------------------------------------------------------ ticks
        /// <summary>Told each tick's index as it starts, and -1 after the last (the instrumented ACE's trace recorder; null
        /// otherwise).</summary>
        public static Action<int> TickStarted;

        /// <summary>Timers.PortalYearTicks, the clock PhysicsTimer.CurrentTime reads, through its internal setter
        /// (reflection): a tick scene's clock is scene data, never the wall clock.</summary>
        static void SetClock(double t)
        {
            if (setPortalYearTicks == null)
            {
                var setter = typeof(ACE.Server.Entity.Timers).GetProperty("PortalYearTicks", BindingFlags.Public | BindingFlags.Static)
                    .GetSetMethod(true);
                setPortalYearTicks = (Action<double>)Delegate.CreateDelegate(typeof(Action<double>), setter);
            }
            setPortalYearTicks(t);
        }

        /// <summary>byte 0: not a tick scene; or 1 (2: then the motion queries after the steps, ReadMotionQueries), the driver byte, the start (double), int n and per step: its
        /// absolute clock (double), the input mask, then the present inputs in TICK_INPUTS order.</summary>
        static void ReadTicks(BinaryReader r)
        {
            tickSteps.Clear();
            moverMotion = false;  // until the mover is made with a motion table
            motionQueries.Clear();
            answersRun = -1;
            answerStream.SetLength(0);
            var ticksTag = r.ReadByte();  // 0 no ticks, 1 ticks, 2 ticks and then the motion queries (pack 17)
            hasTicks = ticksTag != 0;
            if (!hasTicks) return;
            tickDriver = r.ReadByte();
            tickStart = r.ReadDouble();
            var n = r.ReadInt32();
            for (var i = 0; i < n; i++)
            {
                var s = new TickStep { Time = r.ReadDouble(), Mask = r.ReadUInt32() };
                if ((s.Mask & 1) != 0) s.State = r.ReadUInt32();
                if ((s.Mask & 2) != 0) s.Transient = r.ReadUInt32();
                if ((s.Mask & 4) != 0) s.Velocity = V3(r);
                if ((s.Mask & 8) != 0) s.LocalVelocity = V3(r);
                if ((s.Mask & 16) != 0) s.Omega = V3(r);
                if ((s.Mask & 32) != 0) s.Jump = V3(r);
                if ((s.Mask & 64) != 0) s.SequenceVelocity = V3(r);
                if ((s.Mask & 128) != 0) s.SequenceOmega = V3(r);
                if ((s.Mask & 256) != 0) s.RequestPos = Pos(r);
                if ((s.Mask & 512) != 0)
                {
                    var m = new ACE.Server.Network.Structure.RawMotionState();
                    m.CurrentHoldKey = (HoldKey)r.ReadUInt32();
                    m.CurrentStyle = (MotionStance)r.ReadUInt32();
                    m.ForwardCommand = (MotionCommand)r.ReadUInt32();
                    m.ForwardHoldKey = (HoldKey)r.ReadUInt32();
                    m.ForwardSpeed = r.ReadSingle();
                    m.SidestepCommand = (MotionCommand)r.ReadUInt32();
                    m.SidestepHoldKey = (HoldKey)r.ReadUInt32();
                    m.SidestepSpeed = r.ReadSingle();
                    m.TurnCommand = (MotionCommand)r.ReadUInt32();
                    m.TurnHoldKey = (HoldKey)r.ReadUInt32();
                    m.TurnSpeed = r.ReadSingle();
                    s.Motion = m;
                }
                if ((s.Mask & 1024) != 0) s.Stop = r.ReadUInt32();
                if ((s.Mask & 2048) != 0) { s.DoMotion = r.ReadUInt32(); s.DoMotionHoldKey = r.ReadUInt32(); }
                if ((s.Mask & 4096) != 0) { s.StopMotion = r.ReadUInt32(); s.StopMotionHoldKey = r.ReadUInt32(); }
                if ((s.Mask & 8192) != 0) { s.MoveToPos = Pos(r); s.MoveToParams = Params(r); }
                if ((s.Mask & 16384) != 0) { s.MoveToObjectId = r.ReadUInt32(); s.MoveToObjectParams = Params(r); }
                if ((s.Mask & 32768) != 0) s.TurnToHeadingParams = Params(r);
                if ((s.Mask & 65536) != 0) { s.TurnToObjectId = r.ReadUInt32(); s.TurnToObjectParams = Params(r); }
                if ((s.Mask & 131072) != 0) { s.DoorId = r.ReadUInt32(); s.DoorEthereal = r.ReadByte() != 0; }
                if ((s.Mask & 262144) != 0) s.StickToId = r.ReadUInt32();
                var nothers = r.ReadInt32();
                if (nothers > 0)
                {
                    s.Others = new List<OtherStep>(nothers);
                    for (var k = 0; k < nothers; k++)
                    {
                        var o = new OtherStep { Index = r.ReadInt32(), Mask = r.ReadUInt32() };
                        if ((o.Mask & 1) != 0) o.State = r.ReadUInt32();
                        if ((o.Mask & 2) != 0) o.Transient = r.ReadUInt32();
                        if ((o.Mask & 4) != 0) o.Velocity = V3(r);
                        if ((o.Mask & 8) != 0) o.LocalVelocity = V3(r);
                        if ((o.Mask & 16) != 0) o.Omega = V3(r);
                        if ((o.Mask & 32) != 0) o.Jump = V3(r);
                        if ((o.Mask & 64) != 0) o.SequenceVelocity = V3(r);
                        if ((o.Mask & 128) != 0) o.SequenceOmega = V3(r);
                        if ((o.Mask & 1024) != 0)
                        {
                            o.ParentForm = r.ReadByte(); o.ParentId = r.ReadUInt32(); o.ParentLocation = r.ReadInt32();
                            o.Placement = r.ReadInt32();
                            if (o.ParentForm == 2) o.ParentFrame = new AFrame(V3(r), Q(r));
                        }
                        if ((o.Mask & 2048) != 0) o.ExecuteMotion = r.ReadUInt32();
                        s.Others.Add(o);
                    }
                }
                tickSteps.Add(s);
            }
            if (ticksTag == 2) ReadMotionQueries(r);
        }

        /// <summary>Per step: the inputs (the mover's, then each other mover's in the step's order; the clock still at
        /// the previous tick's time), the launches of the step's projectiles (SceneLaunch, in `others` order), the clock
        /// set to the step's time, the driver for the mover, then update_object for each other mover in the world in the
        /// order they entered (a server landblock's worldObjects) and WorldObject.UpdateObjectPhysics's physics for each
        /// launched projectile its landblock still holds, then every mover read back. An exception ACE throws is that
        /// tick's error and ends the scene.</summary>
        static void RunTicks(PhysicsObj obj)
        {
            ticksRun = 0;
            foreach (var step in tickSteps)
            {
                TickStarted?.Invoke(ticksRun);
                bool updated;
                try
                {
                    movedObjects.Clear();
                    ApplyInputs(obj, step);
                    if (step.Others != null)
                        foreach (var o in step.Others) ApplyOtherInputs(sceneOthers[o.Index], o, obj);
                    foreach (var o in sceneOthers)
                        if (o.HasLaunch && o.LaunchTick == ticksRun) SceneLaunch(o, obj);
                    // Landblock.TickPhysics' first step, on each loaded landblock (the launches above are a server's actions,
                    // run after the previous tick's physics; it reads no clock)
                    foreach (var xy in tableUsed)
                        ProcessPendingWorldObjectAdditionsAndRemovals(LandblockTable()[xy.Item1, xy.Item2]);
                    SetClock(step.Time);
                    updated = tickDriver == 0 ? obj.update_object() : UpdatePlayerPosition(obj, step.RequestPos);
                    othersUpdated.Clear();
                    foreach (var o in sceneOthers)
                    {
                        if (!o.HasLaunch)
                            othersUpdated.Add(o.Entered && o.Obj.update_object());
                        else if (o.Launched && o.WorldObject.CurrentLandblock == null)
                        {
                            o.Launched = false;  // destroyed, or never entered: its landblock ticks it no more
                            othersUpdated.Add(false);
                        }
                        else
                        {
                            var landblockUpdate = o.Launched && UpdateObjectPhysics(o.WorldObject, o.CreationTime);
                            othersUpdated.Add(landblockUpdate);
                            if (landblockUpdate) movedObjects.Add(o.WorldObject);  // Landblock.TickPhysics' movedObjects
                        }
                    }
                    // LandblockManager.TickPhysics: after every landblock's physics, each object that changed landblocks
                    foreach (var moved in movedObjects)
                        RelocateObjectForPhysics(moved);
                }
                catch (Exception e)
                {
                    tickError = ErrorBytes(e);  // the last tick (Ticks.cs: WriteTicks)
                    ticksRun++;
                    return;
                }
                WriteTick(obj, updated);
                ticksRun++;
            }
            TickStarted?.Invoke(-1);  // the ticks are over
        }

        static readonly List<bool> othersUpdated = new List<bool>();
        static readonly List<ACE.Server.WorldObjects.WorldObject> movedObjects = new List<ACE.Server.WorldObjects.WorldObject>();

        /// <summary>port: Landblock.process_pending_world_object_additions_and_removals. Landblock's private
        /// ProcessPendingWorldObjectAdditionsAndRemovals (the stand-in lacks it), as far as its tables reach: each pending
        /// addition into worldObjects (worldObjects[key] = value), then each pending removal out of it, both lists emptied.
        /// Its players, creature, heartbeat and generator lists and the KeepAlive weenie are no physics.</summary>
        static void ProcessPendingWorldObjectAdditionsAndRemovals(ACE.Server.Entity.Landblock landblock)
        {
            var t = typeof(ACE.Server.Entity.Landblock);
            var worldObjects = (System.Collections.IDictionary)Need(t.GetField("worldObjects", AnyInstance), "worldObjects").GetValue(landblock);
            var pendingAdditions = (System.Collections.IDictionary)Need(t.GetField("pendingAdditions", AnyInstance), "pendingAdditions").GetValue(landblock);
            var pendingRemovals = (System.Collections.IList)Need(t.GetField("pendingRemovals", AnyInstance), "pendingRemovals").GetValue(landblock);
            if (pendingAdditions.Count > 0)
            {
                foreach (System.Collections.DictionaryEntry kvp in pendingAdditions)
                    worldObjects[kvp.Key] = kvp.Value;
                pendingAdditions.Clear();
            }
            if (pendingRemovals.Count > 0)
            {
                foreach (var objectGuid in pendingRemovals)
                    worldObjects.Remove(objectGuid);
                pendingRemovals.Clear();
            }
        }

        /// <summary>port: relocate_object_for_physics. LandblockManager.RelocateObjectForPhysics(wo, adjacencyMove: true) for
        /// a projectile whose UpdateObjectPhysics answered landblockUpdate (its Location's LandblockId is its CurCell's, as
        /// UpdateObjectPhysics sets it): the new block by GetLandblock(id, loadAdjacents: true), the old block's
        /// RemoveWorldObjectForPhysics(Guid, true) (the stand-in's RemoveWorldObject: RemoveWorldObjectInternal, ACE's own),
        /// then the new block's AddWorldObjectForPhysics (AddWorldObjectInternal's physics, which finds its CurCell set).
        /// GetLandblock(id, true) is ACE's own steps on the scene's landblocks: the new block found loaded, then
        /// SetAdjacents(landblock, true, true) (ACE's own), which gives its physics landblock its loaded neighbours anew;
        /// its loads of neighbours the scene lacks are left out (a real DAT's landblock with no server objects: what
        /// SetAdjacents would add is read only by ObjectMaint's visibility lists). IsDormant is never set in a scene (a
        /// server sets it after minutes without players), so a SpellProjectile is never destroyed here.</summary>
        static void RelocateObjectForPhysics(ACE.Server.WorldObjects.WorldObject wo)
        {
            var oldBlock = wo.CurrentLandblock;
            var cellId = wo.PhysicsObj.CurCell.ID;
            var newBlock = ACE.Server.Managers.LandblockManager.GetLandblock(new LandblockId(cellId | 0xFFFF), false);
            if (setAdjacents == null)
                setAdjacents = typeof(ACE.Server.Managers.LandblockManager).GetMethod("SetAdjacents", BindingFlags.NonPublic | BindingFlags.Static);
            setAdjacents.Invoke(null, new object[] { newBlock, true, true });

            // Remove from the old landblock -- force (ACE)
            if (oldBlock != null)
                oldBlock.RemoveWorldObject(wo.Guid, true);
            // Add to the new landblock (ACE)
            AddWorldObject(wo, newBlock, cellId, wo.PhysicsObj.Position.Frame.Origin, wo.PhysicsObj.Position.Frame.Orientation);
        }

        // ------------------------------------------------------------------ projectiles (issue 41)
        // The physics calls ACE's server code makes on a projectile, as port/missile_launch.py makes them: ACE's own
        // Physics code (Trajectory, PhysicsObj) wherever the stand-ins have it, the WorldObject members real ACE
        // names (the stand-ins' Ammunition, SpellProjectile, ProjectileCollisionHelper, Landblock.RemoveWorldObject),
        // and in acconform's words the WorldObject code around them that the stand-in builds lack (Creature_Missile.cs,
        // WorldObject_Magic.cs, SpellProjectile.Setup, Landblock.AddWorldObjectInternal, WorldObject.AddPhysicsObj,
        // WorldObject.IsProjectileVisible, WorldObject_Tick.cs UpdateObjectPhysics), kept to their physics.

        /// <summary>A projectile's launch at its step (port: missile_launch.scene_launch): the launcher and target by id
        /// (the mover, another mover, or an outdoor static: its PhysicsObj, no WorldObject); their landblocks must be one
        /// (a launch across landblocks would need ACE.Entity.Position.ToGlobal: NotSupportedException); the WorldObject is
        /// made now (physicsCreationTime: the clock now). An arrow: Creature.CalculateProjectileVelocity's aim point (the
        /// target's origin raised by Height / GetAimHeight, 2: a creature's, a player's at Medium) and
        /// GetProjectileVelocity from the scene's origin, then LaunchProjectile. A spell: WorldObject.CalculateProjectileVelocity
        /// (raised by Height * ProjHeight or ProjHeightArc), SpellProjectile.Setup, LaunchSpellProjectiles' physics state
        /// and AddObject. The Location is the launcher's (its Location: SyncLocation keeps it its PhysicsObj's) with Pos moved
        /// to the spawn point, which finds its own outdoor landblock and cell (ProjectileLocation).</summary>
        static void SceneLaunch(Other o, PhysicsObj mover)
        {
            var launcherObj = FindObj(o.Launcher, mover);
            var targetObj = o.Target != 0 ? FindObj(o.Target, mover) : null;  // 0: an untargeted spell
            if (targetObj != null && launcherObj.Position.Landblock != targetObj.Position.Landblock)
                throw new NotSupportedException("acconform: a launch across landblocks (ACE.Entity.Position.ToGlobal) is not modelled");
            o.Launched = true;
            o.CreationTime = PhysicsTimer.CurrentTime;
            var wo = o.WorldObject;
            var launcher = launcherObj.WeenieObj.WorldObject;
            var target = targetObj?.WeenieObj.WorldObject;
            var origin = o.Origin;
            var location = ProjectileLocation(launcherObj, origin);
            var landblock = LocationLandblock(location);
            var sp = wo as ACE.Server.WorldObjects.SpellProjectile;
            if (sp != null && targetObj == null)
            {
                // WorldObject.CalculateProjectileVelocity with no target (the launcher has no AttackTarget): launch along
                // forward vector, casterLoc.Rotation being the launcher's PhysicsObj's orientation
                var forward = Vector3.Transform(Vector3.UnitY, launcherObj.Position.Frame.Orientation) * o.Speed;
                SpellProjectileSetup(sp, o.SpellKind);
                SpellProjectileSetPhysicsState(sp, null, null, forward, location.Pos, o.Arc);
                LaunchSpellProjectile(sp, launcher, launcherObj, landblock, location.Cell, location.Pos,
                                      sp.PhysicsObj.Position.Frame.Orientation);
                return;
            }
            var endPos = targetObj.Position.Frame.Origin;
            var height = targetObj.GetHeight();
            if (sp != null)
            {
                endPos.Z += height * (o.Arc ? 5.0f / 6.0f : 2.0f / 3.0f);  // ProjHeightArc, ProjHeight
                var targetVelocity = o.Tracking ? targetObj.CachedVelocity : Vector3.Zero;
                var velocity = CalculateSpellProjectileVelocity(origin, endPos, o.Speed, targetVelocity, o.Arc, o.AltSolver);
                SpellProjectileSetup(sp, o.SpellKind);
                SpellProjectileSetPhysicsState(sp, target, targetObj, velocity, location.Pos, o.Arc);
                LaunchSpellProjectile(sp, launcher, launcherObj, landblock, location.Cell, location.Pos,
                                      sp.PhysicsObj.Position.Frame.Orientation);
                return;
            }
            endPos.Z += height / 2.0f;  // target.Height / GetAimHeight(target)
            var lead = o.LeadTarget || !(launcher is ACE.Server.WorldObjects.Player);
            var v = GetProjectileVelocity(origin, endPos, o.Speed, targetObj.CachedVelocity, true, lead, o.AltSolver, out _);
            LaunchProjectile(wo, launcher, launcherObj, target, targetObj, location.Pos, o.Orientation, landblock,
                             location.Cell, v);
        }

        /// <summary>port: projectile_location. The projectile's Location as ACE makes it: a copy of the launcher's
        /// (PositionExtensions.ACEPosition's `new Position(ObjCellID, Origin, Orientation)` of its PhysicsObj's Position,
        /// which its Location is: SyncLocation), then `Location.Pos = origin` (Creature.LaunchProjectile; `Pos +=` in
        /// LaunchSpellProjectiles), whose setter, ACE.Entity.Position.SetPosition, finds the outdoor landblock and
        /// cell of the spawn point anew (SetLandblock: moved onto the next landblock, or clamped at the world's
        /// edge; SetLandCell).</summary>
        static ACE.Entity.Position ProjectileLocation(PhysicsObj launcherObj, Vector3 origin)
        {
            var location = new ACE.Entity.Position(launcherObj.Position.ObjCellID, launcherObj.Position.Frame.Origin,
                                                   launcherObj.Position.Frame.Orientation);
            location.Pos = origin;
            return location;
        }

        /// <summary>port: location_landblock. LandblockManager.AddObject's GetLandblock(Location.LandblockId, false):
        /// ACE's own, which finds the scene's server landblock loaded (BuildScene loaded it); one the scene lacks ACE
        /// would load from a cell DAT without it: refused first.</summary>
        static ACE.Server.Entity.Landblock LocationLandblock(ACE.Entity.Position location)
        {
            var id = new LandblockId(location.Cell | 0xFFFF);
            if (LandblockTable()[id.LandblockX, id.LandblockY] == null)
                throw new NotSupportedException("acconform: a projectile's Location in a landblock the scene lacks (LandblockManager.GetLandblock would load it) is not modelled");
            return ACE.Server.Managers.LandblockManager.GetLandblock(location.LandblockId, false);
        }

        /// <summary>The PhysicsObj of the mover, another mover or a static by id.</summary>
        static PhysicsObj FindObj(uint id, PhysicsObj mover)
        {
            if (mover.ID == id) return mover;
            foreach (var o in sceneOthers) if (o.Id == id) return o.Obj;
            foreach (var s in staticObjs) if (s != null && s.ID == id) return s;
            throw new InvalidOperationException("acconform: no object has id " + id.ToString("X8"));
        }

        /// <summary>port: get_projectile_velocity. Creature.GetProjectileVelocity with a default server's properties
        /// (trajectory_alt_solver false unless `altSolver`): a moving target (CachedVelocity not zero) and a launcher that
        /// leads (a monster, or a player with LeadMissileTargets) takes the quartic solve_ballistic_arc when it has a
        /// solution; otherwise the fixed-target solve_ballistic_arc. Gravity is -PhysicsGlobals.Gravity (positive down),
        /// or 0.00001f without gravity.</summary>
        static Vector3 GetProjectileVelocity(Vector3 origin, Vector3 dest, float speed, Vector3 targetVelocity,
                                             bool useGravity, bool leadTarget, bool altSolver, out float time)
        {
            time = 0.0f;
            Vector3 s0;
            float t0;
            var gravity = useGravity ? -PhysicsGlobals.Gravity : 0.00001f;
            if (!targetVelocity.Equals(Vector3.Zero))
            {
                if (leadTarget)
                {
                    if (!altSolver)
                    {
                        var numSolutions = Trajectory.solve_ballistic_arc(origin, speed, dest, targetVelocity, gravity, out s0, out _, out time);
                        if (numSolutions > 0)
                            return s0;
                    }
                    else
                        return Trajectory2.CalculateTrajectory(origin, dest, targetVelocity, speed, useGravity);
                }
            }
            if (!altSolver)
            {
                Trajectory.solve_ballistic_arc(origin, speed, dest, gravity, out s0, out _, out t0, out _);
                time = t0;
                return s0;
            }
            return Trajectory2.CalculateTrajectory(origin, dest, Vector3.Zero, speed, useGravity);
        }

        /// <summary>port: calculate_spell_projectile_velocity. WorldObject.CalculateProjectileVelocity's solver from its
        /// start and end points, as ACE writes it.</summary>
        static Vector3 CalculateSpellProjectileVelocity(Vector3 startPos, Vector3 endPos, float speed, Vector3 targetVelocity,
                                                        bool arc, bool altSolver)
        {
            var dir = Vector3.Normalize(endPos - startPos);
            var useGravity = arc;
            var velocity = Vector3.Zero;
            if (useGravity || targetVelocity != Vector3.Zero)
            {
                var gravity = useGravity ? PhysicsGlobals.Gravity : 0.0f;
                if (!altSolver)
                    Trajectory.solve_ballistic_arc_lateral(startPos, speed, endPos, targetVelocity, gravity, out velocity, out _, out _);
                else
                    velocity = Trajectory2.CalculateTrajectory(startPos, endPos, targetVelocity, speed, useGravity);
                if (velocity == Vector3.Zero && useGravity && targetVelocity != Vector3.Zero)
                {
                    if (!altSolver)
                        Trajectory.solve_ballistic_arc_lateral(startPos, speed, endPos, Vector3.Zero, gravity, out velocity, out _, out _);
                    else
                        velocity = Trajectory2.CalculateTrajectory(startPos, endPos, Vector3.Zero, speed, useGravity);
                }
                if (velocity != Vector3.Zero)
                    return velocity;
            }
            return dir * speed;
        }

        /// <summary>WorldObject.PhysicsObj's setter is protected (real ACE's and the stand-in's): WorldObject.InitPhysicsObj
        /// sets it; the facade through the setter.</summary>
        static void SetPhysicsObj(ACE.Server.WorldObjects.WorldObject wo, PhysicsObj obj)
        {
            Need(typeof(ACE.Server.WorldObjects.WorldObject).GetProperty("PhysicsObj", AnyInstance), "PhysicsObj")
                .GetSetMethod(true).Invoke(wo, new object[] { obj });
        }

        /// <summary>WorldObject.CurrentLandblock's setter is internal: Landblock.AddWorldObjectInternal sets it; the facade
        /// through the setter.</summary>
        static void SetCurrentLandblock(ACE.Server.WorldObjects.WorldObject wo, ACE.Server.Entity.Landblock landblock)
        {
            Need(typeof(ACE.Server.WorldObjects.WorldObject).GetProperty("CurrentLandblock", AnyInstance), "CurrentLandblock")
                .GetSetMethod(true).Invoke(wo, new object[] { landblock });
        }

        /// <summary>port: set_projectile_physics_state. Creature.SetProjectilePhysicsState after InitPhysicsObj (EnterOthers
        /// made the PhysicsObj), through real ACE's WorldObject properties.</summary>
        static void SetProjectilePhysicsState(ACE.Server.WorldObjects.WorldObject proj, PhysicsObj targetObj, Vector3 velocity,
                                              Vector3 pos, Quaternion rotation)
        {
            proj.ReportCollisions = true;
            proj.Missile = true;
            proj.AlignPath = true;
            proj.PathClipped = true;
            proj.Ethereal = false;
            proj.IgnoreCollisions = false;
            proj.PhysicsObj.Position.Frame.Origin = pos;
            proj.PhysicsObj.Position.Frame.Orientation = rotation;
            proj.PhysicsObj.Velocity = velocity;
            proj.PhysicsObj.ProjectileTarget = targetObj;
            if ((proj.RotationSpeed ?? 0) != 0)
            {
                proj.AlignPath = false;
                proj.PhysicsObj.Omega = new Vector3((float)(Math.PI * 2 * proj.RotationSpeed), 0, 0);
            }
            proj.PhysicsObj.set_active(true);
        }

        /// <summary>port: spell_projectile_setup. SpellProjectile.Setup after InitPhysicsObj, the spell as the scene's kind
        /// says (`kind`, acconform.scene.SPELL_KINDS): Spell.Name "Rolling Death" (1) leaves Ethereal; a wall spell's
        /// weenie (7278, 7281, 7282, 23144: 2) clears ScriptedCollision; SpellType Ring clears it (3) or, spell 3818 (4),
        /// sets it.</summary>
        static void SpellProjectileSetup(ACE.Server.WorldObjects.SpellProjectile sp, byte kind)
        {
            sp.ReportCollisions = true;
            sp.Missile = true;
            sp.AlignPath = true;
            sp.PathClipped = true;
            sp.IgnoreCollisions = false;
            if (kind != 1)  // !Spell.Name.Equals("Rolling Death")
                sp.Ethereal = false;
            if (kind == 2)  // WeenieClassId 7278, 7281, 7282 or 23144: some wall spells have no scripted collisions
                sp.ScriptedCollision = false;
            sp.AllowEdgeSlide = false;
            if (sp.SpellType == ACE.Server.Entity.ProjectileSpellType.Ring)
            {
                if (kind == 4)  // spell.Id == 3818
                    sp.ScriptedCollision = true;
                else
                    sp.ScriptedCollision = false;
            }
            if ((sp.RotationSpeed ?? 0) != 0)
            {
                sp.AlignPath = false;
                sp.PhysicsObj.Omega = new Vector3((float)(Math.PI * 2 * sp.RotationSpeed), 0, 0);
            }
        }

        /// <summary>port: spell_projectile_set_physics_state. LaunchSpellProjectiles' Velocity and heading, ProjectileTarget,
        /// then SpellProjectile.SetProjectilePhysicsState(target, useGravity); a static target (no WorldObject) gives its
        /// PhysicsObj as the ProjectileTarget all the same.</summary>
        static void SpellProjectileSetPhysicsState(ACE.Server.WorldObjects.SpellProjectile sp, ACE.Server.WorldObjects.WorldObject target,
                                                   PhysicsObj targetObj, Vector3 velocity, Vector3 origin, bool useGravity)
        {
            var obj = sp.PhysicsObj;
            obj.Velocity = velocity;
            var dir = Vector3.Normalize(obj.Velocity);
            obj.Position.Frame.set_vector_heading(dir);
            var rotation = obj.Position.Frame.Orientation;
            sp.ProjectileTarget = target;
            if (useGravity)
                sp.GravityStatus = true;
            obj.Position.Frame.Origin = origin;
            obj.Position.Frame.Orientation = rotation;
            if (targetObj != null)
                obj.ProjectileTarget = targetObj;
            obj.set_active(true);
        }

        /// <summary>port: add_physics_obj. WorldObject.AddPhysicsObj's physics (AdjustDungeon: an outdoor scene's Location
        /// is its own cell).</summary>
        static bool AddPhysicsObj(ACE.Server.WorldObjects.WorldObject wo, uint cellId, Vector3 origin, Quaternion orientation)
        {
            if (wo.PhysicsObj.CurCell != null)
                return false;
            var cell = LScape.get_landcell(cellId);
            if (cell == null)
            {
                wo.PhysicsObj.DestroyObject();
                SetPhysicsObj(wo, null);
                return false;
            }
            wo.PhysicsObj.Position.ObjCellID = cell.ID;
            var location = new ACE.Server.Physics.Common.Position();
            location.ObjCellID = cell.ID;
            location.Frame.Origin = origin;
            location.Frame.Orientation = orientation;
            var success = wo.PhysicsObj.enter_world(location);
            if (!success || wo.PhysicsObj.CurCell == null)
            {
                wo.PhysicsObj.DestroyObject();
                SetPhysicsObj(wo, null);
                return false;
            }
            return true;
        }

        /// <summary>port: add_world_object. Landblock.AddWorldObjectInternal's physics: CurrentLandblock first, the guid
        /// filed again, AddPhysicsObj (failing: CurrentLandblock cleared), then pendingAdditions[Guid] = wo (the
        /// stand-in's and real ACE's private table).</summary>
        static bool AddWorldObject(ACE.Server.WorldObjects.WorldObject wo, ACE.Server.Entity.Landblock landblock, uint cellId,
                                   Vector3 origin, Quaternion orientation)
        {
            SetCurrentLandblock(wo, landblock);
            wo.PhysicsObj.set_object_guid(wo.Guid);
            if (wo.PhysicsObj.CurCell == null)
            {
                if (!AddPhysicsObj(wo, cellId, origin, orientation))
                {
                    SetCurrentLandblock(wo, null);
                    return false;
                }
            }
            var pending = (System.Collections.IDictionary)Need(typeof(ACE.Server.Entity.Landblock).GetField("pendingAdditions", AnyInstance),
                                                              "pendingAdditions").GetValue(landblock);
            pending[wo.Guid] = wo;
            return true;
        }

        /// <summary>port: is_projectile_visible. WorldObject.IsProjectileVisible, as ACE writes it.</summary>
        static bool IsProjectileVisible(ACE.Server.WorldObjects.WorldObject launcher, PhysicsObj launcherObj,
                                        ACE.Server.WorldObjects.WorldObject proj)
        {
            if (!(launcher is ACE.Server.WorldObjects.Creature) || (launcher.Ethereal ?? false))
                return true;
            if (launcherObj == null || proj.PhysicsObj == null)
                return false;
            var startPos = new ACE.Server.Physics.Common.Position(proj.PhysicsObj.Position);
            var targetPos = new ACE.Server.Physics.Common.Position(launcherObj.Position);
            targetPos.Frame.Origin.Z += launcherObj.GetHeight() - proj.PhysicsObj.GetHeight();
            var prevTarget = proj.PhysicsObj.ProjectileTarget;
            proj.PhysicsObj.ProjectileTarget = launcherObj;
            var transition = proj.PhysicsObj.transition(startPos, targetPos, false);
            proj.PhysicsObj.ProjectileTarget = prevTarget;
            if (transition == null) return false;
            foreach (var c in transition.CollisionInfo.CollideObject)
                if (c.ID == launcherObj.ID)
                    return true;
            return false;
        }

        /// <summary>port: launch_projectile. Creature.LaunchProjectile's physics.</summary>
        static bool LaunchProjectile(ACE.Server.WorldObjects.WorldObject proj, ACE.Server.WorldObjects.WorldObject launcher,
                                     PhysicsObj launcherObj, ACE.Server.WorldObjects.WorldObject target, PhysicsObj targetObj,
                                     Vector3 origin, Quaternion orientation, ACE.Server.Entity.Landblock landblock, uint cellId,
                                     Vector3 velocity)
        {
            if (float.IsNaN(velocity.X) || float.IsNaN(velocity.Y) || float.IsNaN(velocity.Z))
                return false;  // YourAttackMisfired
            proj.ProjectileSource = launcher;
            proj.ProjectileTarget = target;
            SetProjectilePhysicsState(proj, targetObj, velocity, origin, orientation);
            var success = AddWorldObject(proj, landblock, cellId, origin, orientation);
            if (!success || proj.PhysicsObj == null)
            {
                proj.Destroy();
                return false;
            }
            if (!IsProjectileVisible(launcher, launcherObj, proj))
            {
                proj.OnCollideEnvironment();
                proj.Destroy();
                return false;
            }
            return true;
        }

        /// <summary>port: launch_spell_projectile. LaunchSpellProjectiles' AddObject, WorldEntryCollision and (LaunchSpell's)
        /// IsProjectileVisible.</summary>
        static bool LaunchSpellProjectile(ACE.Server.WorldObjects.SpellProjectile sp, ACE.Server.WorldObjects.WorldObject caster,
                                          PhysicsObj casterObj, ACE.Server.Entity.Landblock landblock, uint cellId, Vector3 origin,
                                          Quaternion rotation)
        {
            sp.ProjectileSource = caster;
            if (!AddWorldObject(sp, landblock, cellId, origin, rotation))
            {
                sp.Destroy();
                return false;
            }
            if (sp.WorldEntryCollision)
                return false;
            if (!IsProjectileVisible(caster, casterObj, sp))
            {
                sp.OnCollideEnvironment();
                return false;
            }
            return true;
        }

        /// <summary>port: update_object_physics. WorldObject.UpdateObjectPhysics for a projectile (no Creature): nothing when
        /// inactive; a missile 30 s after its WorldObject was made is set inactive and destroyed; once its Missile bit is gone
        /// it runs only while animating or in its first two updates; update_object; no CurCell after: set_active(false),
        /// Destroy. Returns ACE's landblockUpdate.</summary>
        static bool UpdateObjectPhysics(ACE.Server.WorldObjects.WorldObject wo, double creationTime)
        {
            var obj = wo.PhysicsObj;
            if (obj == null || !obj.is_active())
                return false;
            if ((obj.State & PhysicsState.Missile) != 0)
            {
                if (creationTime + 30.0 <= PhysicsTimer.CurrentTime)
                {
                    obj.set_active(false);
                    wo.Destroy();
                    return false;
                }
            }
            else if (!(obj.IsAnimating || obj.InitialUpdates <= 1))
                return false;
            var cellBefore = obj.CurCell != null ? obj.CurCell.ID : 0;
            obj.update_object();
            if (obj.CurCell == null)
            {
                obj.set_active(false);
                wo.Destroy();
                return false;
            }
            return (cellBefore >> 16) != (obj.CurCell.ID >> 16);
        }


        static void ApplyOtherInputs(Other other, OtherStep s, PhysicsObj mover)
        {
            var obj = other.Obj;
            if ((s.Mask & 1) != 0) obj.State = (PhysicsState)s.State;
            if ((s.Mask & 2) != 0) obj.TransientState = (TransientStateFlags)s.Transient;
            if ((s.Mask & 4) != 0) obj.set_velocity(s.Velocity, false);
            if ((s.Mask & 8) != 0) obj.set_local_velocity(s.LocalVelocity, false);
            if ((s.Mask & 16) != 0) obj.set_omega(s.Omega, false);
            if ((s.Mask & 32) != 0) Jump(obj, (ACE.Server.WorldObjects.Player)other.WorldObject, s.Jump);
            if ((s.Mask & 64) != 0) obj.PartArray.Sequence.SetVelocity(s.SequenceVelocity);
            if ((s.Mask & 128) != 0) obj.PartArray.Sequence.SetOmega(s.SequenceOmega);
            // EmoteManager's Motion emote: an object moving to something (IsMovingTo) is skipped, else ExecuteMotion
            if ((s.Mask & 2048) != 0 && !obj.IsMovingTo()) ExecuteMotion(obj, s.ExecuteMotion);
            // children (issue 41): the client's calls when the server moves a held item, on ACE's own PhysicsObj: a
            // PickupEvent's unset_parent, a ParentEvent's SetPlacementFrame and set_parent (SetParent)
            if ((s.Mask & 512) != 0) obj.unset_parent();
            if ((s.Mask & 1024) != 0)
                HoldChild(obj, FindObj(s.ParentId, mover), s.ParentForm, s.ParentLocation, s.Placement, s.ParentFrame);
            if ((s.Mask & 256) != 0 && other.Entered)
            {
                // WorldObject.Destroy's physics: its landblock's RemoveWorldObject -> PhysicsObj.DestroyObject; the
                // landblock ticks it no more
                obj.DestroyObject();
                other.Entered = false;
            }
        }

        /// <summary>WorldObject.ExecuteMotion's physics (scene/8 others[].execute_motion, pack 18) for a motion command that
        /// is not Ready (the Motion's ForwardCommand, or its Stance when that is Ready): get_minterp, a new RawMotionState
        /// with ForwardCommand 0, CurrentHoldKey Run and CurrentStyle the command, UpdateTime when the object is not moving
        /// or animating, RawState = it, apply_raw_movement(true, true). The rest of ExecuteMotion (the animation length,
        /// CurrentMotionState, the broadcast) is no physics.</summary>
        static void ExecuteMotion(PhysicsObj obj, uint motionCommand)
        {
            var motionInterp = obj.get_minterp();
            var rawState = new ACE.Server.Physics.Animation.RawMotionState();
            rawState.ForwardCommand = 0;
            rawState.CurrentHoldKey = HoldKey.Run;
            rawState.CurrentStyle = motionCommand;
            if (!obj.IsMovingOrAnimating)
                obj.UpdateTime = PhysicsTimer.CurrentTime;
            motionInterp.RawState = rawState;
            motionInterp.apply_raw_movement(true, true);
        }

        static void ApplyInputs(PhysicsObj obj, TickStep s)
        {
            if ((s.Mask & 1) != 0) obj.State = (PhysicsState)s.State;
            if ((s.Mask & 2) != 0) obj.TransientState = (TransientStateFlags)s.Transient;
            if ((s.Mask & 4) != 0) obj.set_velocity(s.Velocity, false);
            if ((s.Mask & 8) != 0) obj.set_local_velocity(s.LocalVelocity, false);
            if ((s.Mask & 16) != 0) obj.set_omega(s.Omega, false);
            if ((s.Mask & 32) != 0) Jump(obj, moverPlayer, s.Jump);
            if ((s.Mask & 64) != 0) obj.PartArray.Sequence.SetVelocity(s.SequenceVelocity);
            if ((s.Mask & 128) != 0) obj.PartArray.Sequence.SetOmega(s.SequenceOmega);
            if ((s.Mask & 512) != 0) MoveToState(obj, s.Motion);
            if ((s.Mask & 1024) != 0) StopMovement(obj, s.Stop);
            if ((s.Mask & 2048) != 0) KeyMotion(obj, s.DoMotion, s.DoMotionHoldKey, true);
            if ((s.Mask & 4096) != 0) KeyMotion(obj, s.StopMotion, s.StopMotionHoldKey, false);
            if ((s.Mask & 8192) != 0) MoveToPosition(obj, s.MoveToPos, s.MoveToParams);
            if ((s.Mask & 16384) != 0) ObjectMove(obj, s.MoveToObjectId, s.MoveToObjectParams, false);
            if ((s.Mask & 32768) != 0) TurnToHeading(obj, s.TurnToHeadingParams);
            if ((s.Mask & 65536) != 0) ObjectMove(obj, s.TurnToObjectId, s.TurnToObjectParams, true);
            if ((s.Mask & 131072) != 0) Door(s.DoorId, s.DoorEthereal);
            // a melee swing's stick (Monster_Melee.MeleeAttack, Player_Melee.DoSwingMotion): the target's PhysicsObj.ID
            if ((s.Mask & 262144) != 0) obj.stick_to_object(s.StickToId);
        }

        /// <summary>The physics of ACE's server Door (WorldObjects/Door.cs) on the static ServerObjectManager filed
        /// under the id. Open: `Ethereal = true`, whose setter (SetPhysicsPropertyState -> SetPhysicsState) sets
        /// PhysicsState.Ethereal on PhysicsObj.State directly. FinalizeClose: `Ethereal = false` (the flag cleared),
        /// then, with allow_door_hold (PropertyManager's default, true), PhysicsObj.ethereal_check_for_collisions():
        /// an object overlapping the door sets `Ethereal = true` again (the door is held open).</summary>
        static void Door(uint doorId, bool ethereal)
        {
            var door = ServerObjectManager.GetObjectA(doorId);
            if (ethereal)
            {
                door.State |= PhysicsState.Ethereal;
                return;
            }
            door.State &= ~PhysicsState.Ethereal;
            if (door.ethereal_check_for_collisions())
                door.State |= PhysicsState.Ethereal;
        }

        /// <summary>A MovementParameters as ACE's constructor makes it, then every field the scene carries set:
        /// Flags, DistanceToObject, MinDistance, FailDistance, Speed, WalkRunThreshold, DesiredHeading,
        /// HoldKeyToApply.</summary>
        static MovementParameters Params(BinaryReader r)
        {
            var mvp = new MovementParameters();
            mvp.Flags = (MovementParamFlags)r.ReadUInt32();
            mvp.DistanceToObject = r.ReadSingle();
            mvp.MinDistance = r.ReadSingle();
            mvp.FailDistance = r.ReadSingle();
            mvp.Speed = r.ReadSingle();
            mvp.WalkRunThreshold = r.ReadSingle();
            mvp.DesiredHeading = r.ReadSingle();
            mvp.HoldKeyToApply = (HoldKey)r.ReadUInt32();
            return mvp;
        }

        /// <summary>The server's stops (acconform.motion_scene.STOPS): 0 PhysicsObj.StopCompletely (Creature_Death,
        /// Player_Tick's PK logout), 1 PhysicsObj.cancel_moveto (Player_Move2.StopExistingMoveToChains2,
        /// Player_Melee), 2 MoveToManager.CancelMoveTo(ActionCancelled) and FailProgressCount = 0
        /// (Monster_Navigation.CancelMoveTo, Creature_Navigation's MoveTo tick).</summary>
        static void StopMovement(PhysicsObj obj, uint stop)
        {
            if (stop == 0) obj.StopCompletely(true);
            else if (stop == 1) obj.cancel_moveto();
            else
            {
                obj.MovementManager.MoveToManager.CancelMoveTo(WeenieError.ActionCancelled);
                obj.MovementManager.MoveToManager.FailProgressCount = 0;
            }
        }

        /// <summary>Player.OnMoveToState_ClientMethod's physics calls for one key: a MovementParameters with
        /// HoldKeyToApply the current hold key, UpdateTime when not moving or animating, then DoMotion(motion, mvp)
        /// or StopMotion(motion, mvp, true).</summary>
        static void KeyMotion(PhysicsObj obj, uint motion, uint holdKey, bool press)
        {
            var mvp = new MovementParameters();
            mvp.HoldKeyToApply = (HoldKey)holdKey;
            if (!obj.IsMovingOrAnimating)
                obj.UpdateTime = PhysicsTimer.CurrentTime;
            if (press) obj.DoMotion(motion, mvp);
            else obj.StopMotion(motion, mvp, true);
        }

        /// <summary>Creature.MoveTo(Position)'s physics calls: UpdateTime when not moving or animating, then
        /// MoveToPosition(a copy of the position, mvp).</summary>
        static void MoveToPosition(PhysicsObj obj, ACE.Server.Physics.Common.Position pos, MovementParameters mvp)
        {
            if (!obj.IsMovingOrAnimating)
                obj.UpdateTime = PhysicsTimer.CurrentTime;
            obj.MoveToPosition(new ACE.Server.Physics.Common.Position(pos), mvp);
        }

        /// <summary>TurnToHeading (no WorldObject of ACE's server calls it: the calls of Creature.MoveTo around it,
        /// UpdateTime when not moving or animating).</summary>
        static void TurnToHeading(PhysicsObj obj, MovementParameters mvp)
        {
            if (!obj.IsMovingOrAnimating)
                obj.UpdateTime = PhysicsTimer.CurrentTime;
            obj.TurnToHeading(mvp);
        }

        /// <summary>Monster_Navigation.StartTurn's physics calls: MoveToObject / TurnToObject(the target's PhysicsObj,
        /// mvp), then UpdateTime = CurrentTime ("prevent initial snap"). The target is the static the server's
        /// ServerObjectManager filed under its id (set_object_guid, as WorldObject.InitPhysicsObj files it).</summary>
        static void ObjectMove(PhysicsObj obj, uint targetId, MovementParameters mvp, bool turn)
        {
            var target = ServerObjectManager.GetObjectA(targetId);
            // a MoveToObject or TurnToObject at another mover the server destroyed (feature objects.gone_targets): its
            // WorldObject keeps its PhysicsObj after Destroy, which Monster_Navigation.StartTurn still passes to either
            // (AttackTarget.PhysicsObj)
            if (target == null)
                foreach (var o in sceneOthers) if (o.Id == targetId) target = o.Obj;
            if (turn) obj.TurnToObject(target, mvp);
            else obj.MoveToObject(target, mvp);
            obj.UpdateTime = PhysicsTimer.CurrentTime;
        }

        /// <summary>The physics calls of a player's MoveToState (GameActionMoveToState.Handle): Player.OnMoveToState's
        /// FastTick path, then OnMoveToState_ServerMethod (ACE's default: client_movement_formula off; no standing long
        /// jump): UpdateTime when not moving or animating, the interpreter's RawState.SetState, then
        /// apply_raw_movement(true, whether motion_allows_jump(the interpreted forward command) is None).</summary>
        static void MoveToState(PhysicsObj obj, ACE.Server.Network.Structure.RawMotionState raw)
        {
            if (!obj.IsMovingOrAnimating)
                obj.UpdateTime = PhysicsTimer.CurrentTime;
            var minterp = obj.get_minterp();
            minterp.RawState.SetState(raw);
            var allowJump = minterp.motion_allows_jump(minterp.InterpretedState.ForwardCommand) == WeenieError.None;
            minterp.apply_raw_movement(true, allowJump);
        }

        /// <summary>The physics calls of Player.HandleActionJump with a local jump velocity (the JumpPack's), in both of
        /// its branches: the Player's FastTick (a PK or PKLite player) sets UpdateTime only when the mover is not moving or
        /// animating, the other branch always; then TransientState, calc_acceleration, set_on_walkable, set_local_velocity,
        /// RemoveLinkAnimations, MotionInterpreter.PendingMotions.Clear(), IsAnimating. A mover without a motion table has
        /// no MovementManager: IsMovingOrAnimating reaching it (every earlier term false) throws NullReferenceException,
        /// which counts as not moving, and PendingMotions has no interpreter to clear (docs/oracle.md's audit table).</summary>
        static void Jump(PhysicsObj obj, ACE.Server.WorldObjects.Player player, Vector3 velocity)
        {
            if (PlayerFastTick(player))
            {
                bool moving;
                try { moving = obj.IsMovingOrAnimating; }
                catch (NullReferenceException) { moving = false; }
                if (!moving)
                    obj.UpdateTime = PhysicsTimer.CurrentTime;
            }
            else
                obj.UpdateTime = PhysicsTimer.CurrentTime;
            obj.TransientState &= ~(TransientStateFlags.Contact | TransientStateFlags.WaterContact);
            obj.calc_acceleration();
            obj.set_on_walkable(false);
            obj.set_local_velocity(velocity, false);
            obj.RemoveLinkAnimations();
            if (obj.MovementManager != null)
                obj.MovementManager.MotionInterpreter.PendingMotions.Clear();
            obj.IsAnimating = false;
        }

        /// <summary>The Player's FastTick, read by reflection: ACE has it since 2020, and a build of before (ACE of 2019,
        /// whose tick scenes the oracle never runs: its physics clock is wall time) must still compile the facade.</summary>
        static bool PlayerFastTick(ACE.Server.WorldObjects.Player player)
        {
            var p = typeof(ACE.Server.WorldObjects.Player).GetProperty("FastTick");
            if (p == null)
                throw new MissingMemberException("ACE.Server.WorldObjects.Player", "FastTick");
            return (bool)p.GetValue(player);
        }

        /// <summary>The physics calls of Player.UpdatePlayerPosition for a requested position that moves (the legacy,
        /// non-FastTick path): LScape.get_landcell of its cell, then ACE's set_request_pos(origin, orientation, that
        /// cell, the cell of the player's Location: the last position update_object_server accepted, or where the
        /// mover entered) and update_object_server(); a mover left in no cell is put in that cell. A cell ACE cannot
        /// find makes no update (false).</summary>
        static bool UpdatePlayerPosition(PhysicsObj obj, ACE.Server.Physics.Common.Position requestPos)
        {
            var curCell = LScape.get_landcell(requestPos.ObjCellID);
            if (curCell == null)
                return false;
            obj.set_request_pos(requestPos.Frame.Origin, requestPos.Frame.Orientation, curCell, locationCell);
            var success = obj.update_object_server();
            if (obj.CurCell == null && curCell.ID >> 16 != 0x18A)
                obj.CurCell = curCell;
            if (success)
                locationCell = requestPos.ObjCellID;
            return success;
        }

        /// <summary>The mover's Player. ACE's server makes it from the character's Biota; a build whose Player has no
        /// constructor without arguments (ACE's own, built by ACE.Server.csproj) gets one without a character's database
        /// record: an uninitialized Player on which Creature's constructor runs with a fresh Biota (the mover's id,
        /// WeenieType Creature, weenie 1, no properties), as ACE's Player(Biota, ...) runs it before its own body (which
        /// reads the authentication database), then Player's field initializer the physics reads (LastContact = true).
        /// A build with neither constructor gets the uninitialized Player with LastContact alone.</summary>
        static ACE.Server.WorldObjects.Player MakePlayer(uint moverId)
        {
            bool fromBiota;
            var player = (ACE.Server.WorldObjects.Player)MakeWorldObject(typeof(ACE.Server.WorldObjects.Player),
                                                                         typeof(ACE.Server.WorldObjects.Creature), "Creature", moverId, out fromBiota);
            serverPlayer = fromBiota;
            player.LastContact = true;
            return player;
        }

        /// <summary>Another mover's WorldObject (scene/8), made as MakePlayer makes the mover's: a Player, a Creature
        /// (IsMonster set for a monster, as Creature.SetMonsterState caches it), a GenericObject, an Ammunition or a
        /// SpellProjectile (SpellType Bolt, or Arc for an arc), with its id, and a creature's PlayerKillerStatus set before
        /// its WeenieObject copies it.</summary>
        static ACE.Server.WorldObjects.WorldObject MakeWorldObject(Other o)
        {
            bool fromBiota;
            if (o.Weenie == 0)
            {
                var player = (ACE.Server.WorldObjects.Player)MakeWorldObject(typeof(ACE.Server.WorldObjects.Player),
                                                                             typeof(ACE.Server.WorldObjects.Creature), "Creature", o.Id, out fromBiota);
                player.LastContact = true;
                player.PlayerKillerStatus = o.Pks;
                return player;
            }
            if (o.Weenie == 3)
                return MakeWorldObject(typeof(ACE.Server.WorldObjects.GenericObject), typeof(ACE.Server.WorldObjects.GenericObject),
                                       "Generic", o.Id, out fromBiota);
            if (o.Weenie == 4)
                return MakeWorldObject(typeof(ACE.Server.WorldObjects.Ammunition), typeof(ACE.Server.WorldObjects.Ammunition),
                                       "Ammunition", o.Id, out fromBiota);
            if (o.Weenie == 6)  // a thrown weapon (WeenieType Missile)
                return MakeWorldObject(typeof(ACE.Server.WorldObjects.Missile), typeof(ACE.Server.WorldObjects.Missile),
                                       "Missile", o.Id, out fromBiota);
            if (o.Weenie == 5)
            {
                var sp = (ACE.Server.WorldObjects.SpellProjectile)MakeWorldObject(typeof(ACE.Server.WorldObjects.SpellProjectile),
                    typeof(ACE.Server.WorldObjects.SpellProjectile), "ProjectileSpell", o.Id, out fromBiota);
                sp.SpellType = o.SpellKind == 2 ? ACE.Server.Entity.ProjectileSpellType.Wall
                             : o.SpellKind >= 3 ? ACE.Server.Entity.ProjectileSpellType.Ring
                             : o.Arc ? ACE.Server.Entity.ProjectileSpellType.Arc : ACE.Server.Entity.ProjectileSpellType.Bolt;
                return sp;
            }
            var creature = (ACE.Server.WorldObjects.Creature)MakeWorldObject(typeof(ACE.Server.WorldObjects.Creature),
                                                                             typeof(ACE.Server.WorldObjects.Creature), "Creature", o.Id, out fromBiota);
            // a monster: Creature.SetMonsterState caches IsMonster = Attackable || TargetingTactic != None (Attackable: ACE's
            // default, true); an NPC is not Attackable, so not a monster
            creature.Attackable = o.Weenie == 2;
            creature.IsMonster = o.Weenie == 2;
            creature.PlayerKillerStatus = o.Pks;
            return creature;
        }

        /// <summary>A WorldObject of type `t` with the id `id`. A build whose type has a constructor without arguments
        /// (the stand-ins) makes it so, and its Guid (a get-only auto-property: real ACE's constructors set it from the
        /// Biota or the ObjectGuid they take) is set through its backing field. Otherwise (ACE's own build) an
        /// uninitialized object of `t` on which `biotaCtorOwner`'s constructor taking a Biota runs with a fresh Biota (the
        /// id, WeenieType `weenieType`, weenie 1, no properties), as ACE's Player(Biota, ...) runs Creature's before its
        /// own body (which reads the authentication database); then `Invincible` (see below).</summary>
        static ACE.Server.WorldObjects.WorldObject MakeWorldObject(Type t, Type biotaCtorOwner, string weenieType, uint id, out bool fromBiota)
        {
            var ctor = t.GetConstructor(AnyInstance, null, Type.EmptyTypes, null);
            fromBiota = false;
            if (ctor != null)
            {
                var made = (ACE.Server.WorldObjects.WorldObject)ctor.Invoke(null);
                var guid = typeof(ACE.Server.WorldObjects.WorldObject).GetField("<Guid>k__BackingField", AnyInstance);
                if (guid != null) guid.SetValue(made, new ObjectGuid(id));
                return made;
            }
            var wo = (ACE.Server.WorldObjects.WorldObject)FormatterServices.GetUninitializedObject(t);
            ConstructorInfo biotaCtor = null;
            foreach (var c in biotaCtorOwner.GetConstructors(AnyInstance))
                if (c.GetParameters().Length == 1 && c.GetParameters()[0].ParameterType.Name == "Biota") biotaCtor = c;
            if (biotaCtor != null)
            {
                PrepareServerPlayer();
                var biotaType = biotaCtor.GetParameters()[0].ParameterType;
                var biota = Activator.CreateInstance(biotaType);
                Need(biotaType.GetProperty("Id"), "Id").SetValue(biota, id);
                var wt = Need(biotaType.GetProperty("WeenieType"), "WeenieType");
                wt.SetValue(biota, Enum.Parse(wt.PropertyType, weenieType));
                Need(biotaType.GetProperty("WeenieClassId"), "WeenieClassId").SetValue(biota, 1u);
                var ints = Need(biotaType.GetProperty("PropertiesInt"), "PropertiesInt");
                ints.SetValue(biota, Activator.CreateInstance(typeof(Dictionary<,>).MakeGenericType(ints.PropertyType.GetGenericArguments())));
                biotaCtor.Invoke(wo, new[] { biota });
                // immortal, as a sentinel's @neversaydie makes a server's Player: an environment collision fast enough to
                // hurt runs HandleFallingDamage, whose TakeDamage_Falling then returns at once (Health, chat and death
                // reach the Player's Session, which this Player has none of; none of them is physics)
                Need(typeof(ACE.Server.WorldObjects.WorldObject).GetProperty("Invincible"), "Invincible").SetValue(wo, true);
                fromBiota = true;
            }
            return wo;
        }

        /// <summary>The scene's skills, vitals, attributes and burden (acconform.scene.MoverSkills) on the Player, through
        /// ACE's own members, as a server's play sets them on a Player it has made: each writes the Biota's record
        /// the Player was made from (CreatureSkill.InitLevel its PropertiesSkill, added Untrained by GetCreatureSkill;
        /// CreatureAttribute.StartingValue its PropertiesAttribute; CreatureVital.Current its PropertiesAttribute2nd's
        /// CurrentLevel, as UpdateVital does; EncumbranceVal and AugmentationIncreasedCarryingCapacity its properties,
        /// EncumbranceVal ephemeral as adding an item sets it). An Untrained skill whose SkillTable entry has no
        /// MinLevel 1 adds no formula, so each Current is the value given (a skill or attribute within 2^24, the
        /// attribute 1 or more: CreatureAttribute.GetCurrent's floor). Set after Creature's constructor, whose top-up
        /// of an empty vital to its MaxValue would otherwise turn a stamina of 0 into 1.</summary>
        static void SetPlayerSkills(ACE.Server.WorldObjects.Player player, uint run, uint jump, uint stamina, uint strength,
                                    int encumbranceVal, int carryingCapacityAugs)
        {
            player.GetCreatureSkill(Skill.Run, true).InitLevel = run;
            player.GetCreatureSkill(Skill.Jump, true).InitLevel = jump;
            player.Stamina.Current = stamina;
            player.Strength.StartingValue = strength;
            player.EncumbranceVal = encumbranceVal;
            player.AugmentationIncreasedCarryingCapacity = carryingCapacityAugs;
        }

        /// <summary>What the WeenieObject of a Player with these skills (SetPlayerSkills, on a Player made as the mover's
        /// is) answers the physics, which no scene on ACE's server reaches past InqRunRate: InqRunRate's rate, InqBurden
        /// (NaN for null), then per extent InqJumpVelocity's bool (1 or 0) and velocity_z. For the live tests of the
        /// port's WeenieObject (LiveOracle.player_answers).</summary>
        public static float[] PlayerAnswers(uint run, uint jump, uint stamina, uint strength, int encumbranceVal,
                                            int carryingCapacityAugs, float[] extents)
        {
            var player = MakePlayer(0x50000001);  // acconform.staging.MOVER_ID
            SetPlayerSkills(player, run, jump, stamina, strength, encumbranceVal, carryingCapacityAugs);
            var weenie = new WeenieObject(player);
            var answers = new float[2 + 2 * extents.Length];
            var rate = 0.0f;
            weenie.InqRunRate(ref rate);
            answers[0] = rate;
            answers[1] = weenie.InqBurden() ?? float.NaN;
            for (var i = 0; i < extents.Length; i++)
            {
                answers[2 + 2 * i] = weenie.InqJumpVelocity(extents[i], out var vz) ? 1.0f : 0.0f;
                answers[3 + 2 * i] = vz;
            }
            GC.KeepAlive(player);  // WeenieObject holds it by a WeakReference
            return answers;
        }

        /// <summary>A member the full build's Player needs (MakePlayer and the two below), or a MissingMemberException naming it.</summary>
        static T Need<T>(T member, string name) where T : MemberInfo
        {
            if (member == null)
                throw new MissingMemberException("this ACE build's Player has no parameterless constructor, and making one without a database needs the member " + name + ", which the build lacks");
            return member;
        }

        static readonly BindingFlags AnyInstance = BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic;
        static bool serverPlayer;  // the mover's Player was made by Creature's constructor (MakePlayer)
        static bool serverPlayerPrepared;

        /// <summary>What Creature's constructor and Player's static constructor read from a server's databases, given
        /// once. The world database: Player's static fields (Player_Location.cs) take the destinations of the portal
        /// weenies named below from DatabaseManager.World.GetCachedWeenie, with fixed Positions when it finds none; its
        /// private caches get "no such weenie" for each (name to class id 0xFFFFFFFF, that id to null), so no database is
        /// asked. The portal DAT: the vitals' formulas (SecondaryAttributeTable, read by CreatureVital), the skills'
        /// formulas for Jump and Run (SkillTable, read by GetCreatureSkill when the physics asks InqJumpVelocity and
        /// InqRunRate; the retail DAT's) and an empty SpellTable (read by the enchantment code), each on the facade's
        /// PortalDatDatabase, which has no DAT file to read them from.</summary>
        static void PrepareServerPlayer()
        {
            if (serverPlayerPrepared) return;
            Type databaseManager = null;
            foreach (var name in typeof(ACE.Server.WorldObjects.Player).Assembly.GetReferencedAssemblies())
                if (name.Name == "ACE.Database") databaseManager = Assembly.Load(name).GetType("ACE.Database.DatabaseManager");
            if (databaseManager == null)
                throw new InvalidOperationException("the ACE build's Player has no parameterless constructor and no ACE.Database.DatabaseManager was found");
            var world = Need(databaseManager.GetProperty("World", BindingFlags.Public | BindingFlags.Static), "World").GetValue(null);
            var names = (System.Collections.IDictionary)Need(world.GetType().GetField("weenieClassNameToClassIdCache", AnyInstance), "weenieClassNameToClassIdCache").GetValue(world);
            var weenies = (System.Collections.IDictionary)Need(world.GetType().GetField("weenieCache", AnyInstance), "weenieCache").GetValue(world);
            foreach (var portal in new[] { "portalmarketplace", "portalpkarenanew1", "portalpkarenanew2", "portalpkarenanew3",
                                           "portalpkarenanew4", "portalpkarenanew5", "portalpklarenanew1", "portalpklarenanew2",
                                           "portalpklarenanew3", "portalpklarenanew4", "portalpklarenanew5" })
                names[portal] = 0xFFFFFFFFu;
            weenies[0xFFFFFFFFu] = null;

            var portalDat = DatManager.PortalDat;
            var fields = BindingFlags.NonPublic | BindingFlags.Instance;
            var attributes = Need(typeof(PortalDatDatabase).GetField("<SecondaryAttributeTable>k__BackingField", fields), "<SecondaryAttributeTable>k__BackingField");
            if (attributes.GetValue(portalDat) == null) attributes.SetValue(portalDat, Activator.CreateInstance(attributes.FieldType));
            var spells = Need(typeof(PortalDatDatabase).GetField("<SpellTable>k__BackingField", fields), "<SpellTable>k__BackingField");
            if (spells.GetValue(portalDat) == null) spells.SetValue(portalDat, Activator.CreateInstance(spells.FieldType));
            var skills = Need(typeof(PortalDatDatabase).GetField("<SkillTable>k__BackingField", fields), "<SkillTable>k__BackingField");
            if (skills.GetValue(portalDat) == null)
            {
                var table = Activator.CreateInstance(skills.FieldType);
                var hash = Need(skills.FieldType.GetField("SkillBaseHash"), "SkillBaseHash");
                var skillBase = hash.FieldType.GetGenericArguments()[1];
                ConstructorInfo baseCtor = null;
                foreach (var c in skillBase.GetConstructors()) if (c.GetParameters().Length == 1) baseCtor = c;
                var formula = baseCtor.GetParameters()[0].ParameterType;
                ConstructorInfo formulaCtor = null;
                foreach (var c in formula.GetConstructors()) if (c.GetParameters().Length == 3) formulaCtor = c;
                var attr = formulaCtor.GetParameters()[0].ParameterType;
                var byId = (System.Collections.IDictionary)hash.GetValue(table);
                // (attribute 1, attribute 2, divisor): Jump (Strength + Coordination) / 2, Run Quickness / 1
                byId[(uint)Skill.Jump] = baseCtor.Invoke(new[] { formulaCtor.Invoke(new[] { Enum.Parse(attr, "Strength"), Enum.Parse(attr, "Coordination"), (object)2u }) });
                byId[(uint)Skill.Run] = baseCtor.Invoke(new[] { formulaCtor.Invoke(new[] { Enum.Parse(attr, "Quickness"), Enum.Parse(attr, "Undef"), (object)1u }) });
                skills.SetValue(portalDat, table);
            }
            serverPlayerPrepared = true;
        }

        /// <summary>On a Player made by MakePlayer's Creature constructor, what a server's WorldObject has when its
        /// PhysicsObj enters the world: its PhysicsObj (WorldObject.InitPhysicsObj sets it; Player.HandleFallingDamage
        /// reads its Velocity) and its Location (what AddPhysicsObj's caller gives it: the begin position; enter_world's
        /// enter_cell_server copies the physics position into it, WorldObject.SyncLocation).</summary>
        static void SetServerPlayerPhysics(ACE.Server.WorldObjects.Player player, PhysicsObj obj, ACE.Server.Physics.Common.Position begin)
        {
            if (!serverPlayer) return;
            var wo = typeof(ACE.Server.WorldObjects.WorldObject);
            Need(wo.GetProperty("PhysicsObj", AnyInstance), "PhysicsObj").GetSetMethod(true).Invoke(player, new object[] { obj });
            var location = Need(wo.GetProperty("Location", AnyInstance), "Location");
            var locationCtor = location.PropertyType.GetConstructor(new[] { typeof(uint), typeof(Vector3), typeof(Quaternion) });
            location.SetValue(player, locationCtor.Invoke(new object[] { begin.ObjCellID, begin.Frame.Origin, begin.Frame.Orientation }));
        }

        /// <summary>The mover's motion layer as it stands (acconform.outcome.MotionTickState; Ticks.cs writes one per tick),
        /// read with no call that makes or asks anything (not get_minterp, not get_state_velocity): byte (1: a MovementManager with a MotionInterpreter) and the InterpretedState's and the
        /// RawState's CurrentStyle, ForwardCommand, ForwardSpeed, SideStepCommand, SideStepSpeed, TurnCommand,
        /// TurnSpeed (zeros when none); byte (1: the Sequence has a CurrAnim with an Anim) and that Anim's ID; the
        /// Sequence's FrameNumber, Velocity and Omega; byte (1: a MoveToManager) and its MovementType; IsMovingTo().</summary>
        static void WriteMotion(BinaryWriter w, PhysicsObj obj)
        {
            var manager = obj.MovementManager;
            var minterp = manager != null ? manager.MotionInterpreter : null;
            w.Write((byte)(minterp != null ? 1 : 0));
            if (minterp != null)
            {
                var i = minterp.InterpretedState;
                WCommands(w, i.CurrentStyle, i.ForwardCommand, i.ForwardSpeed, i.SideStepCommand, i.SideStepSpeed, i.TurnCommand, i.TurnSpeed);
                var r = minterp.RawState;
                WCommands(w, r.CurrentStyle, r.ForwardCommand, r.ForwardSpeed, r.SideStepCommand, r.SideStepSpeed, r.TurnCommand, r.TurnSpeed);
            }
            else
            {
                WCommands(w, 0, 0, 0f, 0, 0f, 0, 0f);
                WCommands(w, 0, 0, 0f, 0, 0f, 0, 0f);
            }
            var seq = obj.PartArray.Sequence;
            var anim = seq.CurrAnim != null ? seq.CurrAnim.Value.Anim : null;
            w.Write((byte)(anim != null ? 1 : 0));
            w.Write(anim != null ? anim.ID : 0u);
            w.Write(seq.FrameNumber);
            W3(w, seq.Velocity);
            W3(w, seq.Omega);
            var moveTo = manager != null ? manager.MoveToManager : null;
            w.Write((byte)(moveTo != null ? 1 : 0));
            w.Write(moveTo != null ? (byte)moveTo.MovementType : (byte)0);
            w.Write((byte)(obj.IsMovingTo() ? 1 : 0));
        }

        static void WCommands(BinaryWriter w, uint style, uint forward, float forwardSpeed, uint sideStep, float sideStepSpeed, uint turn, float turnSpeed)
        {
            w.Write(style); w.Write(forward); w.Write(forwardSpeed); w.Write(sideStep); w.Write(sideStepSpeed);
            w.Write(turn); w.Write(turnSpeed);
        }

        /// <summary>byte 0 (no placement), or 1 then SetPositionError, Position.ObjCellID, its frame (origin, then
        /// w x y z), CurCell id (0: none), TransientState, int n and the n ids of ShadowObjects.</summary>
        static void WritePlacement(BinaryWriter w)
        {
            if (!placed) { w.Write((byte)0); return; }
            w.Write((byte)1);
            w.Write(placedResult);
            w.Write(placedCell);
            W3(w, placedOrigin);
            w.Write(placedOrientation.W); w.Write(placedOrientation.X); w.Write(placedOrientation.Y); w.Write(placedOrientation.Z);
            w.Write(placedCurCell);
            w.Write(placedTransient);
            w.Write(placedShadowCells.Count);
            foreach (var id in placedShadowCells) w.Write(id);
        }

        /// <summary>The mover placed by ACE. enter_world: the physics calls of WorldObject.AddPhysicsObj for a
        /// Location at the begin position (its cell id first replaced by ACE's Position.GetCell when the scene asks, as
        /// AdjustDungeon does): LScape.get_landcell of its cell (none: the mover is not entered, GeneralFailure), the
        /// mover's Position.ObjCellID set to that cell's id, then ACE's PhysicsObj.enter_world(Position(cell, frame));
        /// its bool is the result, OK or GeneralFailure. Otherwise ACE's public PhysicsObj.SetPosition(SetPosition(pos,
        /// flags)), as a teleport or a restore places a WorldObject.</summary>
        static void Place(PhysicsObj obj, ACE.Server.Physics.Common.Position begin)
        {
            var pos = new ACE.Server.Physics.Common.Position(begin);
            if (placementGetCell)
                pos.ObjCellID = pos.GetCell(pos.ObjCellID);
            placedMover = obj;
            SetPositionError result;
            if (placementEnterWorld)
            {
                var cell = LScape.get_landcell(pos.ObjCellID);
                if (cell == null)
                    result = SetPositionError.GeneralFailure;
                else
                {
                    obj.Position.ObjCellID = cell.ID;
                    var location = new ACE.Server.Physics.Common.Position(cell.ID, new AFrame(pos.Frame.Origin, pos.Frame.Orientation));
                    result = obj.enter_world(location) ? SetPositionError.OK : SetPositionError.GeneralFailure;
                }
            }
            else
                result = obj.SetPosition(new SetPosition(pos, (SetPositionFlags)placementFlags));

            placed = true;
            placedResult = (int)result;
            placedCell = obj.Position.ObjCellID;
            placedOrigin = obj.Position.Frame.Origin;
            placedOrientation = obj.Position.Frame.Orientation;
            placedCurCell = obj.CurCell != null ? obj.CurCell.ID : 0u;
            placedTransient = (uint)obj.TransientState;
            placedShadowCells.Clear();
            placedShadowCells.AddRange(obj.ShadowObjects.Keys);
        }

        /// <summary>Tag 2: the placement left the mover in no cell, so no transition runs: the mover's velocity
        /// (the rest of the outcome is the record's defaults on both sides), then the FindValidPosition time (0).</summary>
        static void WriteNoTransition(BinaryWriter w, PhysicsObj obj)
        {
            w.Write((byte)2);
            W3(w, obj.Velocity);
            w.Write(0.0);
        }

        /// <summary>int count (-1: not read, e.g. an error outcome), then per static: int n, n cell ids.</summary>
        static void WriteStaticCells(BinaryWriter w, List<List<uint>> cells)
        {
            if (cells == null) { w.Write(-1); return; }
            w.Write(cells.Count);
            foreach (var ids in cells)
            {
                w.Write(ids.Count);
                foreach (var id in ids) w.Write(id);
            }
        }

        public static void ClearCache()
        {
            landblockCache.Clear();
        }

        // ------------------------------------------------------------------ content keys
        /// <summary>FNV-1a over 8-byte words (then the tail): a cache key; entries keep their bytes and
        /// a hit is confirmed byte for byte, so a collision can only cost a rebuild, never a wrong answer.</summary>
        static ulong Hash(byte[] b, int off, int len)
        {
            ulong h = 14695981039346656037UL;
            var i = 0;
            for (; i + 8 <= len; i += 8) { h ^= BitConverter.ToUInt64(b, off + i); h *= 1099511628211UL; }
            for (; i < len; i++) { h ^= b[off + i]; h *= 1099511628211UL; }
            return h ^ (ulong)len;
        }

        static bool BytesEqual(byte[] a, byte[] b, int off, int len)
        {
            if (a.Length != len) return false;
            var i = 0;
            for (; i + 8 <= len; i += 8) if (BitConverter.ToUInt64(a, i) != BitConverter.ToUInt64(b, off + i)) return false;
            for (; i < len; i++) if (a[i] != b[off + i]) return false;
            return true;
        }

        static byte[] Slice(byte[] b, int off, int len)
        {
            var copy = new byte[len];
            Buffer.BlockCopy(b, off, copy, 0, len);
            return copy;
        }

        /// <summary>The harness's own cleanup, after the scene's answer is written: ChildList.RemoveChild leaves
        /// NumObjects one past its lists (a child held anew or unparented in a tick), and remove_shadows_from_cells,
        /// which loops to NumObjects, would throw before leave_cell takes the object out of its cell.</summary>
        static void CountChildren(PhysicsObj obj)
        {
            if (obj.Children != null) obj.Children.NumObjects = obj.Children.Objects.Count;
        }

        static void RemoveStatics()
        {
            // leave cached landblocks as they were built: a placed mover and this scene's statics leave their cells
            // again (ObjectList, ShadowObjectList, the landblock's ServerObjects), and the EnvCells ACE loaded into
            // them (Landblock.LandCells, keyed by the cell's low word) go, with the statics they placed; the next
            // scene's cell DAT loads its own
            if (placedMover != null)
            {
                var mover = placedMover;
                placedMover = null;
                CountChildren(mover);
                mover.remove_shadows_from_cells();
                mover.leave_cell(false);
            }
            foreach (var o in sceneOthers)
            {
                if (o.Obj == null) continue;
                CountChildren(o.Obj);
                o.Obj.remove_shadows_from_cells();
                o.Obj.leave_cell(false);
                o.Obj = null;
            }
            foreach (var obj in sceneStatics)
            {
                obj.remove_shadows_from_cells();
                obj.leave_cell(false);
            }
            sceneStatics.Clear();
            // the EnvCells the scene loaded: its own, or the empty ones ReadFromDat made for cell ids the scene lacks
            foreach (var lb in sceneLandblocks.Values)
            {
                var indoor = new List<int>();
                foreach (var key in lb.LandCells.Keys) if (key >= 0x100) indoor.Add(key);
                foreach (var key in indoor)
                {
                    var cell = lb.LandCells[key] as ACE.Server.Physics.Common.EnvCell;
                    if (cell != null && cell.StaticObjects != null)
                        foreach (var obj in cell.StaticObjects)
                        {
                            obj.remove_shadows_from_cells();
                            obj.leave_cell(false);
                        }
                    lb.LandCells.TryRemove(key, out _);
                }
            }
        }

        /// <summary>Each static's cells, read after the transition: an outdoor static's ShadowObjects keys; for a
        /// static in an EnvCell, those of the object of the loaded cell's StaticObjects whose PartArray.GetDataID is
        /// the static's DAT id (none when the cell was not loaded or ACE dropped the object).</summary>
        static List<List<uint>> ReadStaticCells()
        {
            var cells = new List<List<uint>>(staticDids.Count);
            for (var i = 0; i < staticDids.Count; i++)
            {
                var ids = new List<uint>();
                var cellId = staticCellIds[i];
                PhysicsObj obj = staticObjs[i];
                if ((cellId & 0xFFFF) >= 0x100)
                {
                    ACE.Server.Physics.Common.Landblock lb;
                    ObjCell cell;
                    if (sceneLandblocks.TryGetValue(cellId | 0xFFFF, out lb) && lb.LandCells.TryGetValue((int)(cellId & 0xFFFF), out cell))
                    {
                        var env = cell as ACE.Server.Physics.Common.EnvCell;
                        if (env != null && env.StaticObjects != null)
                            foreach (var made in env.StaticObjects)
                                if (made.PartArray != null && made.PartArray.GetDataID() == staticDids[i]) { obj = made; break; }
                    }
                }
                if (obj != null) ids.AddRange(obj.ShadowObjects.Keys);
                cells.Add(ids);
            }
            return cells;
        }

        // ------------------------------------------------------------------ the portal and cell DATs
        /// <summary>Make DatManager.PortalDat and DatManager.CellDat exist with no DAT file: each a PortalDatDatabase /
        /// CellDatDatabase made without its file-reading constructor whose FileCache (the auto-property's backing
        /// field) is a fresh dictionary. ACE's DatDatabase.ReadFromDat looks there first, so records the facade puts
        /// there are what DBObj.GetGfxObj / GetSetup / GetEnvironment (portal) and GetEnvCell and AdjustCell's
        /// LandblockInfo (cell) read; for an id the scene has no record for, the file table (AllFiles) is empty, as a DAT
        /// lacking the file: ReadFromDat logs it and caches and returns an empty record. LandDefs' static constructor reads the region's height table from PortalDat
        /// when one exists; it runs first, with none (the scene brings its own table).</summary>
        static void InstallDats()
        {
            RuntimeHelpers.RunClassConstructor(typeof(LandDefs).TypeHandle);
            if (DatManager.PortalDat == null) InstallDat(typeof(PortalDatDatabase), "<PortalDat>k__BackingField");
            if (DatManager.CellDat == null) InstallDat(typeof(CellDatDatabase), "<CellDat>k__BackingField");
            portalFiles = DatManager.PortalDat.FileCache;
            cellFiles = DatManager.CellDat.FileCache;
        }

        static void InstallDat(Type type, string backingField)
        {
            var db = FormatterServices.GetUninitializedObject(type);
            var fields = BindingFlags.NonPublic | BindingFlags.Instance;
            typeof(DatDatabase).GetField("<FileCache>k__BackingField", fields).SetValue(db, new ConcurrentDictionary<uint, FileType>());
            // an empty file table: GetReaderForFile finds no file for an id the scene lacks, and ReadFromDat gives new T()
            typeof(DatDatabase).GetField("<AllFiles>k__BackingField", fields).SetValue(db, new Dictionary<uint, DatFile>());
            typeof(DatDatabase).GetField("<Header>k__BackingField", fields).SetValue(db, new DatDatabaseHeader());
            typeof(DatManager).GetField(backingField, BindingFlags.NonPublic | BindingFlags.Static).SetValue(null, db);
        }

        // ------------------------------------------------------------------ global state
        /// <summary>Empties one of ACE's static tables whatever collection type the ACE build gives it (ACE changed
        /// some from Dictionary to ConcurrentDictionary over the years; both are an IDictionary).</summary>
        static void ClearIfAny(System.Collections.IDictionary table)
        {
            if (table.Count > 0) table.Clear();
        }

        public static void Reset(bool server)
        {
            var eng = new PhysicsEngine(new ObjectMaint(), new SmartBox());  // sets PhysicsEngine.Instance
            eng.Server = true;  // landblocks are built in server mode (LandblockStruct.ConstructUVs reads DATs)
            if (!LScape.Landblocks.IsEmpty) LScape.Landblocks.Clear();
            ClearIfAny(AdjustCell.AdjustCells);  // a ConcurrentDictionary since ACE #2727 (2020-10), a Dictionary before
            if (VertexCache.Vertices.Count > 0) VertexCache.Vertices.Clear();
            if (PolygonCache.Polygons.Count > 0) PolygonCache.Polygons.Clear();
            if (BSPCache.BSPTrees.Count > 0) BSPCache.BSPTrees.Clear();
            if (!GfxObjCache.GfxObjs.IsEmpty) GfxObjCache.GfxObjs.Clear();  // keyed by DAT id: ids repeat across scenes
            // the scene's records and the empty ones ReadFromDat made for ids the scene lacks
            if (!portalFiles.IsEmpty) portalFiles.Clear();
            sceneRecords.Clear();
            if (!cellFiles.IsEmpty) cellFiles.Clear();
            staticCellIds.Clear();
            staticDids.Clear();
            staticObjs.Clear();
            sceneLandblocks.Clear();
            if (!ServerObjectManager.ServerObjects.IsEmpty) ServerObjectManager.ServerObjects.Clear();
            var t = LandblockTable();
            if (!tableCleared)
            {
                Array.Clear(t, 0, t.Length);  // first scene: whatever the process put there before
                tableCleared = true;
            }
            foreach (var xy in tableUsed) t[xy.Item1, xy.Item2] = null;
            tableUsed.Clear();
            ACE.Server.Physics.Common.Landblock.UseSceneFiles = false;
            ClearMotionTableCaches();
        }

        static ACE.Server.Entity.Landblock[,] table2d;

        static ACE.Server.Entity.Landblock[,] LandblockTable()
        {
            // LandblockManager's private static readonly landblocks[255, 255]: the same array for the process
            if (table2d == null)
            {
                lbmTable = typeof(ACE.Server.Managers.LandblockManager).GetField("landblocks", BindingFlags.NonPublic | BindingFlags.Static);
                table2d = (ACE.Server.Entity.Landblock[,])lbmTable.GetValue(null);
            }
            return table2d;
        }

        /// <summary>What LandblockManager.GetLandblock does for a landblock it has not loaded, in ACE's order: the
        /// server Landblock in the table, its Init (the physics landblock's PostInit: BuildScene runs it), then ACE's
        /// own SetAdjacents(landblock, traverse: true, pSync: true), which gives the landblock (server and physics) the
        /// neighbours loaded before it and gives each of those (server side only) this one. A fresh server Landblock
        /// per scene, as ACE makes one per load.</summary>
        static void LoadServerLandblock(uint landblockId, ACE.Server.Physics.Common.Landblock physics, byte[] buf, int off, int len)
        {
            var id = new LandblockId(landblockId);
            var lb = MakeServerLandblock(id, physics, buf, off, len);
            LandblockTable()[id.LandblockX, id.LandblockY] = lb;
            tableUsed.Add(Tuple.Create((int)id.LandblockX, (int)id.LandblockY));
            if (setAdjacents == null)
                setAdjacents = typeof(ACE.Server.Managers.LandblockManager).GetMethod("SetAdjacents", BindingFlags.NonPublic | BindingFlags.Static);
            setAdjacents.Invoke(null, new object[] { lb, true, true });
        }

        /// <summary>A server Landblock as ACE's DAT-reading constructor leaves it, without running it (it would
        /// build a second physics landblock): Id, PhysicsLandblock = the scene's, CellLandblock = its DAT bytes
        /// unpacked by ACE, LandblockInfo = the scene's record for the landblock (0xXXYYFFFE) when it has one, else
        /// null (IsDungeon, the one reader, answers the same for null and for the empty Info a DAT lacking the
        /// record gives).</summary>
        static ACE.Server.Entity.Landblock MakeServerLandblock(LandblockId id, ACE.Server.Physics.Common.Landblock physics, byte[] buf, int off, int len)
        {
            var t = typeof(ACE.Server.Entity.Landblock);
            if (serverLbPhysics == null)
            {
                serverLbPhysics = t.GetField("<PhysicsLandblock>k__BackingField", BindingFlags.NonPublic | BindingFlags.Instance);
                serverLbId = t.GetField("<Id>k__BackingField", BindingFlags.NonPublic | BindingFlags.Instance);
                serverLbCellLandblock = t.GetField("<CellLandblock>k__BackingField", BindingFlags.NonPublic | BindingFlags.Instance);
                serverLbInfo = t.GetField("<LandblockInfo>k__BackingField", BindingFlags.NonPublic | BindingFlags.Instance);
            }
            var lb = (ACE.Server.Entity.Landblock)FormatterServices.GetUninitializedObject(t);
            serverLbPhysics.SetValue(lb, physics);
            serverLbId.SetValue(lb, id);
            var clb = new CellLandblock();
            clb.Unpack(new BinaryReader(new MemoryStream(buf, off, len, false)));
            cellFiles[id.Raw | 0xFFFF] = clb;  // where the constructor's ReadFromDat<CellLandblock> keeps it
            serverLbCellLandblock.SetValue(lb, clb);
            serverLbInfo.SetValue(lb, DatManager.CellDat.ReadFromDat<LandblockInfo>((uint)id.Landblock << 16 | 0xFFFE));
            // the object tables the constructor's field initializers make (a launched projectile joins pendingAdditions)
            foreach (var name in new[] { "worldObjects", "pendingAdditions", "pendingRemovals" })
            {
                var f = t.GetField(name, BindingFlags.NonPublic | BindingFlags.Instance);
                if (f != null && f.GetValue(lb) == null) f.SetValue(lb, Activator.CreateInstance(f.FieldType));
            }
            return lb;
        }

        /// <summary>A physics landblock as built: its adjacents null (only LandblockManager's SetAdjacents sets
        /// them). A cached landblock keeps what the last scene's SetAdjacents gave it, so every scene starts here.</summary>
        static void ClearAdjacents(ACE.Server.Physics.Common.Landblock physics)
        {
            if (physicsAdjacents == null)
                physicsAdjacents = typeof(ACE.Server.Physics.Common.Landblock).GetField("adjacents", BindingFlags.NonPublic | BindingFlags.Instance);
            physicsAdjacents.SetValue(physics, null);
        }

        // ------------------------------------------------------------------ scene
        static Vector3 V3(BinaryReader r) { return new Vector3(r.ReadSingle(), r.ReadSingle(), r.ReadSingle()); }
        static Quaternion Q(BinaryReader r)
        {
            var w = r.ReadSingle(); var x = r.ReadSingle(); var y = r.ReadSingle(); var z = r.ReadSingle();
            return new Quaternion(x, y, z, w);
        }
        static ACE.Server.Physics.Common.Position Pos(BinaryReader r)
        {
            var cell = r.ReadUInt32();
            var origin = V3(r);
            var q = Q(r);
            return new ACE.Server.Physics.Common.Position(cell, new AFrame(origin, q));
        }

        static Tuple<PhysicsObj, ACE.Server.Physics.Common.Position, ACE.Server.Physics.Common.Position> BuildScene(BinaryReader r)
        {
            if (r.ReadInt32() != PackVersion) throw new InvalidDataException("acconform facade: pack version mismatch");
            var server = r.ReadByte() != 0;
            Reset(server);
            ReadTicks(r);
            if (hasTicks)
                SetClock(tickStart);  // Timers.PortalYearTicks = ticks.start before anything is made

            var table = ReadHeightTable(r);
            LandDefs.LandHeightTable = table;

            var nlb = r.ReadInt32();
            var built = new List<ACE.Server.Physics.Common.Landblock>();
            var ms = (MemoryStream)r.BaseStream;
            var buf = ms.GetBuffer();
            // the CellLandblocks' bytes first; they are built after the DAT records are in the FileCaches: a
            // landblock with HasObjects reads its LandblockInfo (cell DAT) in its constructor and its buildings'
            // models (portal DAT) in PostInit (init_buildings)
            var slices = new List<Tuple<int, int>>(nlb);
            for (var i = 0; i < nlb; i++)
            {
                var len = r.ReadInt32();
                var off = (int)ms.Position;
                ms.Position = off + len;
                slices.Add(Tuple.Create(off, len));
            }

            // the Environments and buildings' models (portal DAT) and the EnvCells and LandblockInfos (cell DAT): ACE
            // loads each EnvCell when it first asks for it (LScape.get_landcell -> DBObj.GetEnvCell -> new EnvCell -> PostInit)
            var ndat = r.ReadInt32();
            for (var i = 0; i < ndat; i++)
                ReadRecord(r);

            var sw = Stopwatch.StartNew();
            foreach (var slice in slices)
            {
                var off = slice.Item1;
                var len = slice.Item2;
                ACE.Server.Physics.Common.Landblock lb = null;
                ulong key = 0;
                // a landblock with buildings (HasObjects, the uint after its id) is built from this scene's DAT records:
                // never cached
                var cacheable = CacheLandblocks && BitConverter.ToUInt32(buf, off + 4) == 0;
                if (cacheable)
                {
                    key = Hash(buf, off, len) ^ ((ulong)(uint)lastTableId * 0x9E3779B97F4A7C15UL);
                    LandblockEntry e;
                    if (landblockCache.TryGetValue(key, out e) && e.Table == lastTableId && BytesEqual(e.Bytes, buf, off, len))
                        lb = e.Landblock;
                }
                if (lb == null)
                {
                    var bytes = Slice(buf, off, len);
                    var clb = new CellLandblock();
                    clb.Unpack(new BinaryReader(new MemoryStream(bytes)));
                    lb = new ACE.Server.Physics.Common.Landblock(clb);
                    built.Add(lb);
                    if (cacheable)
                    {
                        if (landblockCache.Count >= CacheLimit) landblockCache.Clear();
                        landblockCache[key] = new LandblockEntry { Bytes = bytes, Table = lastTableId, Landblock = lb };
                    }
                }
                else landblocksReused++;
                var id = lb.ID | 0xFFFF;
                LScape.Landblocks[id] = lb;  // registered before PostInit, as LScape.get_landblock does
                sceneLandblocks[id] = lb;
                ClearAdjacents(lb);
                if (server) LoadServerLandblock(id, lb, buf, off, len);  // in the scene's order
            }
            foreach (var lb in built) lb.PostInit();
            landblocksBuilt = built.Count;
            buildMicros = sw.Elapsed.TotalMilliseconds * 1000.0;
            if (!server)
                PhysicsEngine.Instance.Server = false;

            var nobj = r.ReadInt32();
            for (var i = 0; i < nobj; i++)
                BuildStatic(r);

            return BuildMover(r);
        }

        static List<float> lastTableList;

        /// <summary>The scene's land height table; the same List as the last scene's when the values are
        /// bit-identical (ACE only reads it), and a small id naming its bits for the landblock cache key.</summary>
        static List<float> ReadHeightTable(BinaryReader r)
        {
            var ms = (MemoryStream)r.BaseStream;
            var buf = ms.GetBuffer();
            var off = (int)ms.Position;
            ms.Position = off + 256 * 4;
            if (lastTableBytes != null && BytesEqual(lastTableBytes, buf, off, 256 * 4))
                return lastTableList;
            var bytes = Slice(buf, off, 256 * 4);
            var table = new List<float>(256);
            for (var i = 0; i < 256; i++) table.Add(BitConverter.ToSingle(bytes, i * 4));
            var h = Hash(bytes, 0, bytes.Length);
            TableEntry e;
            if (!tableIds.TryGetValue(h, out e) || !BytesEqual(e.Bytes, bytes, 0, bytes.Length))
            {
                if (tableIds.Count >= CacheLimit) { tableIds.Clear(); landblockCache.Clear(); }
                // ids are never reused while a landblock built under an older table can still be cached
                e = new TableEntry { Bytes = bytes, Id = ++tableSerial };
                tableIds[h] = e;
            }
            lastTableBytes = bytes;
            lastTableList = table;
            lastTableId = e.Id;
            return table;
        }

        static int tableSerial;
        /// <summary>One DAT record (acconform/dat.py) unpacked by ACE's own Unpack into the portal FileCache.</summary>
        static void ReadRecord(BinaryReader r)
        {
            var kind = r.ReadByte();
            var id = r.ReadUInt32();
            var len = r.ReadInt32();
            var ms = (MemoryStream)r.BaseStream;
            var off = (int)ms.Position;
            ms.Position = off + len;
            FileType file;
            if (kind == 0) file = new DatGfxObj();
            else if (kind == 1) file = new SetupModel();
            else if (kind == 2) file = new ACE.DatLoader.FileTypes.Environment();
            else if (kind == 3) file = new ACE.DatLoader.FileTypes.EnvCell();
            else if (kind == 4) file = new LandblockInfo();
            else if (kind == 5) file = new ACE.DatLoader.FileTypes.MotionTable();
            else if (kind == 6) file = new ACE.DatLoader.FileTypes.Animation();
            else throw new InvalidDataException("acconform facade: unknown DAT record kind " + kind);
            file.Unpack(new BinaryReader(new MemoryStream(ms.GetBuffer(), off, len, false)));
            if (kind == 3 || kind == 4)
            {
                cellFiles[id] = file;
            }
            else
            {
                portalFiles[id] = file;
                sceneRecords.Add(id);
            }
        }

        static void BuildStatic(BinaryReader r)
        {
            var id = r.ReadUInt32();
            var pos = Pos(r);
            var state = (PhysicsState)r.ReadUInt32();
            var scale = r.ReadSingle();
            var did = r.ReadUInt32();
            var nrec = r.ReadInt32();
            for (var k = 0; k < nrec; k++) ReadRecord(r);

            staticCellIds.Add(pos.ObjCellID);
            staticDids.Add(did);
            if ((pos.ObjCellID & 0xFFFF) >= 0x100)
            {
                // a stab of its EnvCell's DAT record: ACE makes and places it when it loads the cell
                staticObjs.Add(null);
                return;
            }

            // WorldObject.InitPhysicsObj's steps: the object from its DAT id, then the scene's scale and state
            var obj = PhysicsObj.makeObject(did, id, false);
            obj.set_object_guid(new ObjectGuid(id));  // ServerObjectManager files it: a MoveTo's target is found there
            obj.SetScaleStatic(scale);
            obj.State = state;
            sceneStatics.Add(obj);
            staticObjs.Add(obj);

            // Landblock.init_static_objs' steps, on the landblock of the scene's cell
            obj.DatObject = true;
            var lb = sceneLandblocks[pos.ObjCellID | 0xFFFF];
            var position = new ACE.Server.Physics.Common.Position(lb.ID, pos.Frame);
            LandDefs.AdjustToOutside(position);
            var cell = lb.get_landcell(position.ObjCellID);
            if (cell == null)
            {
                obj.DestroyObject();
                return;
            }
            obj.add_obj_to_cell(cell, position.Frame);
        }

        static Tuple<PhysicsObj, ACE.Server.Physics.Common.Position, ACE.Server.Physics.Common.Position> BuildMover(BinaryReader r)
        {
            var nrec = r.ReadInt32();
            for (var k = 0; k < nrec; k++) ReadRecord(r);
            var did = r.ReadUInt32();
            var moverId = r.ReadUInt32();  // acconform.staging.MOVER_ID
            var scale = r.ReadSingle();
            var state = (PhysicsState)r.ReadUInt32();
            var ts = (TransientStateFlags)r.ReadUInt32();
            var velocity = V3(r);
            var hasContact = r.ReadByte() != 0;
            var cpCell = r.ReadUInt32();
            var cpNormal = V3(r);
            var cpD = r.ReadSingle();
            var hasSliding = r.ReadByte() != 0;
            var sliding = V3(r);
            var begin = Pos(r);
            var end = Pos(r);
            var placementKind = r.ReadByte();  // 0 none, 1 SetPosition, 2 enter_world
            hasPlacement = placementKind != 0;
            placementEnterWorld = placementKind == 2;
            placementFlags = r.ReadInt32();
            placementGetCell = r.ReadByte() != 0;
            var motionTableId = r.ReadUInt32();  // the player's MotionTableId (0: none); its Setup names the same table
            moverMotionTableId = motionTableId;  // what the scene's motion_queries ask about
            var playerKillerStatus = (PlayerKillerStatus)r.ReadUInt32();  // the Player's, set before its WeenieObject copies it
            var runSkill = r.ReadUInt32();  // the Player's skills, vitals, attributes and burden (SetPlayerSkills)
            var jumpSkill = r.ReadUInt32();
            var stamina = r.ReadUInt32();
            var strength = r.ReadUInt32();
            var encumbranceVal = r.ReadInt32();
            var carryingCapacityAugs = r.ReadInt32();

            // the mover from its Setup (spheres, step heights) by ACE, as WorldObject.InitPhysicsObj makes a Creature's
            // (a player's): makeAnimObject, its guid, the WeenieObject of its Player, its motion table, scale, state
            var obj = new PhysicsObj();
            obj.makeAnimObject(did, true);
            obj.set_object_guid(new ObjectGuid(moverId));
            moverPlayer = MakePlayer(moverId);  // held as a server's landblock holds its objects: WeenieObject keeps a WeakReference
            moverPlayer.PlayerKillerStatus = playerKillerStatus;
            SetPlayerSkills(moverPlayer, runSkill, jumpSkill, stamina, strength, encumbranceVal, carryingCapacityAugs);
            obj.set_weenie_obj(new WeenieObject(moverPlayer));
            SetServerPlayerPhysics(moverPlayer, obj, begin);
            obj.SetMotionTableID(motionTableId);
            moverMotion = motionTableId != 0;
            obj.SetScaleStatic(scale);
            obj.State = state;
            obj.TransientState = ts;
            obj.Velocity = velocity;
            if (hasContact)
            {
                obj.ContactPlane = new Plane(cpNormal, cpD);
                obj.ContactPlaneCellID = cpCell;
            }
            if (hasSliding) obj.SlidingNormal = sliding;
            if (!hasPlacement)
            {
                obj.Position = new ACE.Server.Physics.Common.Position(begin);
                obj.CurCell = LScape.get_landcell(begin.ObjCellID);
            }
            // with a placement, Position and CurCell stay as makeObject left them: Place places the mover
            ReadOthers(r);
            return Tuple.Create(obj, new ACE.Server.Physics.Common.Position(begin), end);
        }

        /// <summary>int n, then per other mover its DAT records (its Setup), then its Setup id, id, weenie class (byte),
        /// PlayerKillerStatus, scale, State, TransientState, Velocity and begin position, then byte 0 or a projectile's
        /// launch (byte 1, tick, launcher, target, speed, origin, orientation w x y z, lead_target, arc, tracking, alt_solver,
        /// rotation_speed, the spell's kind), then the ReportCollisions property (0 unset, 1 false, 2 true), then its
        /// WorldObject's MotionTableId (uint, pack 18). They are
        /// made and enter the world after the mover's placement (EnterOthers); a projectile enters at its launch.</summary>
        static void ReadOthers(BinaryReader r)
        {
            sceneOthers.Clear();
            var n = r.ReadInt32();
            othersRead = n > 0;
            for (var i = 0; i < n; i++)
            {
                var nrec = r.ReadInt32();
                for (var k = 0; k < nrec; k++) ReadRecord(r);
                var o = new Other
                {
                    Did = r.ReadUInt32(), Id = r.ReadUInt32(), Weenie = r.ReadByte(), Pks = (PlayerKillerStatus)r.ReadUInt32(),
                    Scale = r.ReadSingle(), State = (PhysicsState)r.ReadUInt32(), Transient = (TransientStateFlags)r.ReadUInt32(),
                    Velocity = V3(r), Begin = Pos(r),
                    ParentForm = r.ReadByte(), ParentId = r.ReadUInt32(), ParentLocation = r.ReadInt32(),
                    Placement = r.ReadInt32(),
                };
                o.HasParent = o.ParentForm != 0;
                if (o.ParentForm == 2) o.ParentFrame = new AFrame(V3(r), Q(r));
                o.HasLaunch = r.ReadByte() != 0;
                if (o.HasLaunch)
                {
                    o.LaunchTick = r.ReadInt32();
                    o.Launcher = r.ReadUInt32();
                    o.Target = r.ReadUInt32();
                    o.Speed = r.ReadSingle();
                    o.Origin = V3(r);
                    o.Orientation = Q(r);
                    o.LeadTarget = r.ReadByte() != 0;
                    o.Arc = r.ReadByte() != 0;
                    o.Tracking = r.ReadByte() != 0;
                    o.AltSolver = r.ReadByte() != 0;  // the server property trajectory_alt_solver
                    o.RotationSpeed = r.ReadSingle();  // the projectile's PropertyFloat.RotationSpeed (0: none)
                    o.SpellKind = r.ReadByte();  // what SpellProjectile.Setup reads of the spell: its name, weenie, SpellType
                }
                o.ReportCollisions = r.ReadByte();
                o.MotionTableId = r.ReadUInt32();  // pack 18
                sceneOthers.Add(o);
            }
        }

        /// <summary>Each other mover, in scene order, made as WorldObject.InitPhysicsObj makes its WorldObject's
        /// PhysicsObj (a creature's by new PhysicsObj() and makeAnimObject(setup, true), a GenericObject's by
        /// makeObject(setup, id, true); set_object_guid, set_weenie_obj(new WeenieObject(the WorldObject)),
        /// SetMotionTableID(its MotionTableId: 0, or the scene's table), SetScaleStatic, State), with the scene's TransientState and Velocity, then entered as
        /// WorldObject.AddPhysicsObj enters it: LScape.get_landcell of its begin cell, Position.ObjCellID = that cell's
        /// id, enter_world(Position(cell, frame)); it is in the world when that succeeded and left it in a cell. A child
        /// (scene/8 `parent`) is held by its parent instead (SetParent: the mover `mover`, or an earlier other): its
        /// placement's result is set_parent's answer, and no tick steps it (its parent's UpdateChild carries it). A
        /// projectile is made (a GenericObject's way, its WorldObject an Ammunition or SpellProjectile holding the
        /// PhysicsObj) and not entered: its placement reads it as made, GeneralFailure; its launch enters it.</summary>
        static void EnterOthers(PhysicsObj mover)
        {
            foreach (var o in sceneOthers)
            {
                PhysicsObj obj;
                if (o.Weenie >= 3)  // a GenericObject, an Ammunition, a SpellProjectile or a Missile: no creature
                    obj = PhysicsObj.makeObject(o.Did, o.Id, true);
                else
                {
                    obj = new PhysicsObj();
                    obj.makeAnimObject(o.Did, true);
                }
                o.Obj = obj;
                obj.set_object_guid(new ObjectGuid(o.Id));
                o.WorldObject = MakeWorldObject(o);
                if (o.HasLaunch && o.RotationSpeed != 0)
                    o.WorldObject.RotationSpeed = o.RotationSpeed;  // the weenie's PropertyFloat, read by the launch
                if (o.ReportCollisions != 0)  // the weenie's PropertyBool (no PhysicsObj yet: the property alone; State is the scene's)
                    o.WorldObject.ReportCollisions = o.ReportCollisions == 2;
                obj.set_weenie_obj(new WeenieObject(o.WorldObject));
                obj.SetMotionTableID(o.MotionTableId);  // the WorldObject's MotionTableId (0: none)
                obj.SetScaleStatic(o.Scale);
                obj.State = o.State;
                obj.TransientState = o.Transient;
                obj.Velocity = o.Velocity;
                o.Launched = false;
                if (o.HasLaunch)
                    SetPhysicsObj(o.WorldObject, obj);  // WorldObject.InitPhysicsObj's PhysicsObj = ...: the launch code reads it
                o.Entered = false;
                if (o.HasParent)
                {
                    var parent = o.ParentId == mover.ID ? mover : sceneOthers.Find(x => x.Id == o.ParentId).Obj;
                    var held = HoldChild(obj, parent, o.ParentForm, o.ParentLocation, o.Placement, o.ParentFrame);
                    o.PlacedResult = (int)(held ? SetPositionError.OK : SetPositionError.GeneralFailure);
                    ReadPlaced(o, obj);
                    continue;
                }
                var cell = o.HasLaunch ? null : LScape.get_landcell(o.Begin.ObjCellID);  // a projectile enters at its launch
                if (cell != null)
                {
                    obj.Position.ObjCellID = cell.ID;
                    var location = new ACE.Server.Physics.Common.Position(cell.ID, new AFrame(o.Begin.Frame.Origin, o.Begin.Frame.Orientation));
                    o.Entered = obj.enter_world(location) && obj.CurCell != null;
                }
                o.PlacedResult = (int)(o.Entered ? SetPositionError.OK : SetPositionError.GeneralFailure);
                ReadPlaced(o, obj);
            }
        }

        static void ReadPlaced(Other o, PhysicsObj obj)
        {
            o.PlacedCell = obj.Position.ObjCellID;
            o.PlacedOrigin = obj.Position.Frame.Origin;
            o.PlacedOrientation = obj.Position.Frame.Orientation;
            o.PlacedCurCell = obj.CurCell != null ? obj.CurCell.ID : 0u;
            o.PlacedTransient = (uint)obj.TransientState;
            o.PlacedShadowCells = new List<uint>(obj.ShadowObjects.Keys);
        }

        // ------------------------------------------------------------------ children (issue 41)
        /// <summary>A child held by a parent (a mover) at a holding location, as the client parents a wielded
        /// item: ACE's server never calls set_parent (a wielded item gets only Placement, ParentLocation and
        /// Location: Creature_Equipment.cs TrySetChild), so these are the calls its CreateObject asks the client
        /// to make, on ACE's own PhysicsObj: the child's placement frame, then set_parent at the location
        /// (PhysicsObj.set_parent(PhysicsObj, int): add_child at the Setup's HoldingLocation, unset_parent,
        /// leave_world, change_cell into the parent's cell, UpdateChild, recalc_cross_cells). The port's
        /// counterpart is port/parenting.py set_parent.</summary>
        /// <summary>A child held as the scene says (`form`): at a location (SetParent), or by the frame form,
        /// ACE's set_parent(parent, partIdx, frame) (the client's call for an object attached to a part:
        /// ParticleEmitter.SetParenting), `part` given in ParentLocation's place. The port's counterpart is
        /// port/parenting.py hold_child.</summary>
        static bool HoldChild(PhysicsObj child, PhysicsObj parent, byte form, int location, int placement, AFrame frame)
        {
            if (form == 2) return child.set_parent(parent, location, new AFrame(frame));
            return SetParent(child, parent, location, placement);
        }

        static bool SetParent(PhysicsObj child, PhysicsObj parent, int parentLocation, int placement)
        {
            child.SetPlacementFrame(placement, false);
            return child.set_parent(parent, parentLocation);
        }

        /// <summary>int -1 (no other movers, or an error), or n and per other mover its placement as WritePlacement
        /// writes the mover's (without the leading byte).</summary>
        static void WriteOtherPlacements(BinaryWriter w, bool error)
        {
            if (error || !othersRead) { w.Write(-1); return; }
            w.Write(sceneOthers.Count);
            foreach (var o in sceneOthers)
            {
                w.Write(o.PlacedResult);
                w.Write(o.PlacedCell);
                W3(w, o.PlacedOrigin);
                w.Write(o.PlacedOrientation.W); w.Write(o.PlacedOrientation.X); w.Write(o.PlacedOrientation.Y); w.Write(o.PlacedOrientation.Z);
                w.Write(o.PlacedCurCell);
                w.Write(o.PlacedTransient);
                w.Write(o.PlacedShadowCells.Count);
                foreach (var id in o.PlacedShadowCells) w.Write(id);
            }
        }

        // ------------------------------------------------------------------ transition
        static bool RunTransition(PhysicsObj obj, ACE.Server.Physics.Common.Position oldPos, ACE.Server.Physics.Common.Position newPos,
                                  out Transition trans, out double fvpMicros)
        {
            // PhysicsObj.transition(oldPos, newPos, adminMove: false), step by step, keeping the Transition.
            var whole = Stopwatch.StartNew();
            trans = Transition.MakeTransition();
            var info = obj.get_object_info(trans, false);
            trans.InitObject(obj, info.State);
            if (obj.PartArray == null || obj.PartArray.GetNumSphere() == 0)
                trans.InitSphere(1, PhysicsGlobals.DummySphere, 1.0f);
            else
                trans.InitSphere(obj.PartArray.GetNumSphere(), obj.PartArray.GetSphere(), obj.Scale);
            trans.InitPath(obj.CurCell, oldPos, newPos);
            var ts = obj.TransientState;
            if ((ts & TransientStateFlags.StationaryStuck) != 0) trans.CollisionInfo.FramesStationaryFall = 3;
            else if ((ts & TransientStateFlags.StationaryStop) != 0) trans.CollisionInfo.FramesStationaryFall = 2;
            else if ((ts & TransientStateFlags.StationaryFall) != 0) trans.CollisionInfo.FramesStationaryFall = 1;
            var sw = Stopwatch.StartNew();
            var ok = Stepped ? SteppedFindValidPosition(trans) : trans.FindValidPosition();
            sw.Stop();
            fvpMicros = sw.Elapsed.TotalMilliseconds * 1000.0;
            trans.CleanupTransition();
            transitionMicros = whole.Elapsed.TotalMilliseconds * 1000.0;
            return ok;
        }

        // ------------------------------------------------------------------ ACE's stepped trace
        /// <summary>When set, the transition's FindValidPosition runs as the loop below: ACE's own
        /// FindTransitionalPosition, driven step by step through its public methods (CalcNumSteps,
        /// AdjustOffset, SpherePath.AddOffsetToCheckPos, TransitionalInsert, ValidateTransition), with a
        /// snapshot of the transition at the start of each pass (Steps()). The Python side checks that a
        /// stepped run ends in exactly ACE's unstepped outcome before it uses the snapshots.</summary>
        public static bool Stepped;
        static readonly MemoryStream stepStream = new MemoryStream();
        static readonly BinaryWriter stepWriter = new BinaryWriter(stepStream);

        /// <summary>The snapshots of the last stepped run: int count, then per pass its fields.</summary>
        public static byte[] Steps() => stepStream.ToArray();

        static void WritePlane(BinaryWriter w, bool valid, uint cell, bool water, Plane plane)
        {
            w.Write((byte)(valid ? 1 : 0)); w.Write(cell); w.Write((byte)(water ? 1 : 0)); W3(w, plane.Normal); w.Write(plane.D);
        }

        static void Snapshot(Transition t, int step)
        {
            var sp = t.SpherePath;
            var ci = t.CollisionInfo;
            var w = stepWriter;
            w.Write(step);
            w.Write(sp.CheckCell != null ? sp.CheckCell.ID : 0u); W3(w, sp.CheckPos.Frame.Origin);
            w.Write(sp.CurCell != null ? sp.CurCell.ID : 0u); W3(w, sp.CurPos.Frame.Origin);
            W3(w, sp.GlobalOffset);
            WritePlane(w, ci.ContactPlaneValid, ci.ContactPlaneCellID, ci.ContactPlaneIsWater, ci.ContactPlane);
            WritePlane(w, ci.LastKnownContactPlaneValid, ci.LastKnownContactPlaneCellID, ci.LastKnownContactPlaneIsWater,
                       ci.LastKnownContactPlane);
            w.Write((byte)(ci.CollisionNormalValid ? 1 : 0)); W3(w, ci.CollisionNormal);
            w.Write((byte)(ci.SlidingNormalValid ? 1 : 0)); W3(w, ci.SlidingNormal);
            w.Write((byte)(sp.Walkable != null ? 1 : 0));
            if (sp.Walkable != null) { W3(w, sp.Walkable.Plane.Normal); w.Write(sp.Walkable.Plane.D); }
            w.Write((byte)(sp.StepUp ? 1 : 0)); w.Write((byte)(sp.StepDown ? 1 : 0));
            w.Write((byte)(sp.Collide ? 1 : 0)); w.Write((byte)(sp.NegPolyHit ? 1 : 0));
            w.Write(ci.FramesStationaryFall);
            w.Write((uint)t.ObjectInfo.State);
        }

        static bool SteppedFindValidPosition(Transition t)
        {
            stepStream.SetLength(0);
            stepWriter.Write(0);  // the count, written at the end
            var count = 0;
            var ok = t.SpherePath.InsertType == InsertType.Transition ? SteppedFindTransitionalPosition(t, ref count)
                                                                      : t.FindValidPosition();
            var end = stepStream.Position;
            stepStream.Position = 0;
            stepWriter.Write(count);
            stepStream.Position = end;
            return ok;
        }

        // Transition.FindTransitionalPosition's loop, its calls made one by one from here.
        static bool SteppedFindTransitionalPosition(Transition t, ref int count)
        {
            var sp = t.SpherePath;
            var ci = t.CollisionInfo;
            var oi = t.ObjectInfo;
            if (sp.BeginCell == null) return false;
            var transitionState = TransitionState.OK;
            var offset = Vector3.Zero;
            var offsetPerStep = Vector3.Zero;
            var numSteps = 0;
            t.CalcNumSteps(ref offset, ref offsetPerStep, ref numSteps);
            if (numSteps > 1000 && !oi.Object.IsSightObj) return false;
            if ((oi.State & ObjectInfoState.FreeRotate) != 0)
                sp.CurPos.Frame.set_rotate(sp.EndPos.Frame.Orientation);
            sp.SetCheckPos(sp.CurPos, sp.CurCell);
            var redo = 0;
            if (numSteps <= 0)
            {
                if ((oi.State & ObjectInfoState.FreeRotate) == 0)
                    sp.CurPos.Frame.set_rotate(sp.EndPos.Frame.Orientation);
                sp.CellArrayValid = true;
                sp.HitsInteriorCell = false;
                ObjCell empty = null;
                ObjCell.find_cell_list(t.CellArray, ref empty, sp);
                return true;
            }
            for (var step = 0; step < numSteps; step++)
            {
                Snapshot(t, step);
                count++;
                if ((oi.State & ObjectInfoState.IsViewer) != 0 && step == numSteps - 1)
                {
                    var offsetLen = offset.Length();
                    if (offsetLen > PhysicsGlobals.EPSILON)
                    {
                        redo = numSteps - 1;
                        offsetPerStep = offset * (offsetLen - sp.LocalSphere[0].Radius * (numSteps - 1)) / offsetLen;
                    }
                }
                sp.GlobalOffset = t.AdjustOffset(offsetPerStep);
                if ((oi.State & ObjectInfoState.IsViewer) == 0 &&
                    sp.GlobalOffset.LengthSquared() < PhysicsGlobals.EPSILON * PhysicsGlobals.EPSILON)
                    return step != 0 && transitionState == TransitionState.OK;
                if ((oi.State & ObjectInfoState.FreeRotate) == 0)
                {
                    redo = step + 1;
                    var delta = (float)redo / numSteps;
                    sp.CheckPos.Frame.InterpolateRotation(sp.BeginPos.Frame, sp.EndPos.Frame, delta);
                }
                ci.SlidingNormalValid = false;
                ci.ContactPlaneValid = false;
                ci.ContactPlaneIsWater = false;
                if (sp.InsertType != InsertType.Transition)
                {
                    var insert = t.TransitionalInsert(3);
                    transitionState = t.ValidatePlacementTransition(insert, ref redo);
                    if (transitionState == TransitionState.OK) return true;
                    if (!sp.PlacementAllowsSliding) return false;
                    sp.AddOffsetToCheckPos(sp.GlobalOffset);
                }
                else
                {
                    sp.AddOffsetToCheckPos(sp.GlobalOffset);
                    var transitionInsert = t.TransitionalInsert(3);
                    transitionState = t.ValidateTransition(transitionInsert, ref redo);
                    if (ci.FramesStationaryFall > 0) break;
                }
                if (ci.CollisionNormalValid && (oi.State & ObjectInfoState.PathClipped) != 0) break;
            }
            return transitionState == TransitionState.OK;
        }

        // ------------------------------------------------------------------ outcome
        static void W3(BinaryWriter w, Vector3 v) { w.Write(v.X); w.Write(v.Y); w.Write(v.Z); }

        /// <summary>What an error outcome says of `e`: its type's name and message as UTF-8, of the exception ACE threw
        /// (a reflective call's TargetInvocationException unwrapped to it).</summary>
        static byte[] ErrorBytes(Exception e)
        {
            while (e is TargetInvocationException && e.InnerException != null) e = e.InnerException;
            return Encoding.UTF8.GetBytes(e.GetType().Name + ": " + e.Message);
        }

        static void WriteOutcome(BinaryWriter w, bool ok, Transition trans, PhysicsObj obj, double fvpMicros)
        {
            var sp = trans.SpherePath;
            var ci = trans.CollisionInfo;
            w.Write((byte)1);
            w.Write((byte)(ok ? 1 : 0));
            w.Write(sp.CurCell != null ? sp.CurCell.ID : 0u);
            W3(w, sp.CurPos.Frame.Origin);
            var q = sp.CurPos.Frame.Orientation;
            w.Write(q.W); w.Write(q.X); w.Write(q.Y); w.Write(q.Z);
            w.Write((uint)trans.ObjectInfo.State);
            w.Write((byte)(ci.ContactPlaneValid ? 1 : 0)); w.Write(ci.ContactPlaneCellID);
            w.Write((byte)(ci.ContactPlaneIsWater ? 1 : 0)); W3(w, ci.ContactPlane.Normal); w.Write(ci.ContactPlane.D);
            w.Write((byte)(ci.LastKnownContactPlaneValid ? 1 : 0)); w.Write(ci.LastKnownContactPlaneCellID);
            w.Write((byte)(ci.LastKnownContactPlaneIsWater ? 1 : 0)); W3(w, ci.LastKnownContactPlane.Normal); w.Write(ci.LastKnownContactPlane.D);
            w.Write((byte)(ci.CollisionNormalValid ? 1 : 0)); W3(w, ci.CollisionNormal);
            w.Write((byte)(ci.SlidingNormalValid ? 1 : 0)); W3(w, ci.SlidingNormal);
            w.Write((byte)(ci.CollidedWithEnvironment ? 1 : 0));
            w.Write(ci.FramesStationaryFall);
            W3(w, obj.Velocity);
            w.Write(sp.CheckCell != null ? sp.CheckCell.ID : 0u);
            w.Write((byte)(sp.Walkable != null ? 1 : 0));
            w.Write((byte)(sp.StepUp ? 1 : 0));
            w.Write((byte)(sp.NegPolyHit ? 1 : 0));
            w.Write(fvpMicros);
        }
    }
}
