// Traces (docs/protocol.md, "Traces (feature `trace`)"; `acconform schema trace`): the records of what a
// run looked like inside, for `acconform explain` to find the first one where the port parts from
// acconform's. Record only what your port has: every part but Anchor and Event is optional.
using System.Numerics;
using System.Text.Json.Nodes;
using System.Text.Json.Serialization;

namespace Acconform.Adapter;

public sealed class Tracer
{
    public List<TraceRecord> Records { get; } = [];

    /// <summary>The routines (ACE's File.cs:Method) the port records at enter, exit or call, reached or
    /// not: one the reference ran and this run did not is then a divergence too.</summary>
    public IReadOnlyList<string>? Anchors { get; set; }

    public void Write(TraceRecord record) => Records.Add(record);

    /// <summary>At the start of each pass of FindTransitionalPosition's loop.</summary>
    public void Step(int step, PathState path, int? tick = null) =>
        Write(new TraceRecord("Transition.cs:FindTransitionalPosition", "step") { Step = step, Tick = tick, Path = path });

    /// <summary>After each step of a tick scene: the mover as the outcome's TickState.</summary>
    public void Tick(int tick, TickState mover) =>
        Write(new TraceRecord("PhysicsObj.cs:update_object", "tick") { Tick = tick, Mover = mover });

    public void Enter(string anchor, params JsonNode?[] args) => Write(new TraceRecord(anchor, "enter") { Args = [.. args] });

    public void Exit(string anchor, JsonNode? result) => Write(new TraceRecord(anchor, "exit") { Result = result });

    /// <summary>A float as a trace's args and results hold it: a number (-0 too), a non-finite one as its bit pattern.</summary>
    public static JsonNode Value(float x) => float.IsFinite(x) ? JsonValue.Create(x) : JsonValue.Create(Float32Converter.Bits(x));

    public static JsonNode Value(Vector3 v) => new JsonArray(Value(v.X), Value(v.Y), Value(v.Z));
}

public sealed record TraceRecord(string Anchor, string Event)  // Event: enter, exit, call, step, insert, tick
{
    [JsonIgnore(Condition = JsonIgnoreCondition.WhenWritingNull)] public int? Tick { get; init; }
    [JsonIgnore(Condition = JsonIgnoreCondition.WhenWritingNull)] public int? Step { get; init; }
    [JsonIgnore(Condition = JsonIgnoreCondition.WhenWritingNull)] public string? Within { get; init; }  // the caller's anchor
    [JsonIgnore(Condition = JsonIgnoreCondition.WhenWritingNull)] public IReadOnlyList<JsonNode?>? Args { get; init; }
    [JsonIgnore(Condition = JsonIgnoreCondition.WhenWritingNull)] public JsonNode? Result { get; init; }
    [JsonIgnore(Condition = JsonIgnoreCondition.WhenWritingNull)] public PathState? Path { get; init; }
    [JsonIgnore(Condition = JsonIgnoreCondition.WhenWritingNull)] public TickState? Mover { get; init; }
}

/// <summary>The transition at a record: SpherePath's positions, cells and flags, CollisionInfo's planes and normals.</summary>
public sealed record PathState
{
    public uint CheckCell { get; init; }
    public Vector3 CheckPos { get; init; }  // SpherePath.CheckPos.Frame.Origin
    public uint CurCell { get; init; }
    public Vector3 CurPos { get; init; }
    public Vector3 GlobalOffset { get; init; }
    public ContactPlane ContactPlane { get; init; } = new();
    public ContactPlane LastKnownContactPlane { get; init; } = new();
    public NormalState CollisionNormal { get; init; } = new();
    public NormalState SlidingNormal { get; init; } = new();
    public Plane? Walkable { get; init; }  // the walkable polygon's plane; null when there is none
    public bool StepUp { get; init; }
    public bool StepDown { get; init; }
    public bool Collide { get; init; }
    public bool NegPolyHit { get; init; }
    public int FramesStationaryFall { get; init; }
    public int ObjectInfoState { get; init; }  // the bits, not names
    // SpherePath's flags a placement or a building sets; optional: a port that leaves them null is not compared on them
    [JsonIgnore(Condition = JsonIgnoreCondition.WhenWritingNull)] public bool? PlacementAllowsSliding { get; init; }
    [JsonIgnore(Condition = JsonIgnoreCondition.WhenWritingNull)] public bool? BuildingCheck { get; init; }
    [JsonIgnore(Condition = JsonIgnoreCondition.WhenWritingNull)] public bool? HitsInteriorCell { get; init; }
}

/// <summary>The answer's "trace".</summary>
sealed record TraceDocument(IReadOnlyList<TraceRecord> Records,
    [property: JsonIgnore(Condition = JsonIgnoreCondition.WhenWritingNull)] IReadOnlyList<string>? Anchors)
{
    [JsonPropertyOrder(-1)]
    public string Format => "acconform.trace/1";
}
