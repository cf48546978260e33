// A scene's world as DAT records (docs/protocol.md, "DAT records (feature `dat`)"): sent with each
// request to a port whose handshake lists "dat", so it builds its world with its own DAT loader.
using System.Numerics;

namespace Acconform.Adapter;

/// <summary>One DAT file: its id, the ACE.DatLoader FileType class whose Unpack reads it (CellLandblock,
/// LandblockInfo, EnvCell; Environment, GfxObj, SetupModel) and the bytes ReadFromDat hands Unpack.</summary>
public sealed record DatRecord(uint Id, string Type, byte[] Data);

/// <summary>The request's "dat": both DATs' records in the order ACE's facade builds from them, the
/// land height table, and what the facade sets on the statics and the mover that no record holds.</summary>
public sealed record DatWorld(
    string Format,  // "acconform.dat/1"
    IReadOnlyList<float> LandHeightTable,  // LandDefs.LandHeightTable: set it before building a landblock
    IReadOnlyList<DatRecord> Cell,  // CellLandblocks, LandblockInfos, EnvCells
    IReadOnlyList<DatRecord> Portal,  // buildings' shells, Environments, each static's records, the mover's
    IReadOnlyList<DatStatic> Statics,  // scene order; one standing in an EnvCell is also a stab of its record
    DatMover Mover,
    IReadOnlyList<DatOther>? Others = null);  // scene/8: the other movers, in the order they enter the world

/// <summary>Another mover (feature objects.moving): made as WorldObject.InitPhysicsObj makes its WorldObject's
/// PhysicsObj (Weenie "player", "creature", "monster": makeAnimObject(Did, true); "object": makeObject(Did, Id, true)),
/// then entered into the world at Begin by enter_world after the mover's placement.</summary>
public sealed record DatOther(
    uint Id,
    uint Did,
    string Weenie,
    float Scale,
    IReadOnlyList<string> State,
    IReadOnlyList<string> TransientState,
    Vector3 Velocity,
    Position Begin,
    string PlayerKillerStatus = "NPK");

/// <summary>A static object: PhysicsObj.makeObject(Did, Id, false), then SetScaleStatic, State, and
/// Landblock.init_static_objs' placement at Position.</summary>
public sealed record DatStatic(uint Id, uint Did, Position Position, IReadOnlyList<string> State, float Scale);

/// <summary>The mover: PhysicsObj.makeObject(Did, Id, true) (its SetupModel holds its spheres and step
/// heights), then the rest as the scene's mover writes it.</summary>
public sealed record DatMover(
    uint Id,
    uint Did,
    float Scale,
    IReadOnlyList<string> State,  // PhysicsState flag names
    IReadOnlyList<string> TransientState,  // TransientStateFlags names
    Vector3 Velocity,
    Position Begin,
    Position? End = null,  // null in a tick scene
    CellPlane? ContactPlane = null,  // ContactPlane and ContactPlaneCellID
    Vector3? SlidingNormal = null,
    PlacementRequest? Placement = null);  // the mover placed by ACE before the transition or the ticks

/// <summary>A plane and the cell it was found in (PhysicsObj.ContactPlane, ContactPlaneCellID).</summary>
public sealed record CellPlane(uint Cell, Plane Plane);

/// <summary>The placement a scene asks for: Via "enter_world" (PhysicsObj.enter_world, as a server's WorldObject
/// enters the world; its result is OK or GeneralFailure) or "set_position" (PhysicsObj.SetPosition with the
/// SetPositionFlags names in Flags), and whether get_cell replaces the cell first.</summary>
public sealed record PlacementRequest(string Via = "enter_world", IReadOnlyList<string>? Flags = null, bool GetCell = false);
