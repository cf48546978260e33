// What a port answers: acconform's outcome document (docs/protocol.md, "Outcome fields", is the
// reference for every field; `acconform schema outcome` prints its JSON Schema). Property names are
// the JSON names in PascalCase (Json.Options writes them snake_case); every field is written, `Error`
// as null when nothing was raised.
using System.Numerics;
using System.Text.Json.Serialization;

namespace Acconform.Adapter;

public sealed record Outcome
{
    /// <summary>acconform.outcome/6 with other movers, /4 with ticks, /3 with a placement, else /2.</summary>
    [JsonPropertyOrder(-1)]
    public string Format => OtherPlacements is not null ? "acconform.outcome/6" : Ticks is not null ? "acconform.outcome/4"
        : Placement is not null ? "acconform.outcome/3" : "acconform.outcome/2";

    public bool Ok { get; init; }  // FindValidPosition's answer
    public uint Cell { get; init; }  // SpherePath.CurCell's id
    public Vector3 Origin { get; init; }  // SpherePath.CurPos.Frame.Origin, within the cell's landblock
    public Quaternion Orientation { get; init; } = Quaternion.Identity;
    public IReadOnlyList<string> ObjectInfoState { get; init; } = [];  // flag names: Flags.Names(state)
    public ContactPlane ContactPlane { get; init; } = new();
    public ContactPlane LastKnownContactPlane { get; init; } = new();
    public NormalState CollisionNormal { get; init; } = new();
    public NormalState SlidingNormal { get; init; } = new();
    public bool CollidedWithEnvironment { get; init; }
    public int FramesStationaryFall { get; init; }
    public Vector3 Velocity { get; init; }
    public uint CheckCell { get; init; }
    public bool Walkable { get; init; }
    public bool StepUp { get; init; }
    public bool NegPolyHit { get; init; }

    /// <summary>What the port threw, its .NET type first ("NullReferenceException: ..."); null when nothing was.</summary>
    public string? Error { get; init; }

    /// <summary>Per static object, in scene order, the cells its PhysicsObj is registered in (ShadowObjects); null when unknown.</summary>
    public IReadOnlyList<IReadOnlyList<uint>>? StaticCells { get; init; }

    [JsonIgnore(Condition = JsonIgnoreCondition.WhenWritingNull)]
    public Placement? Placement { get; init; }  // only for a scene whose mover has a placement

    [JsonIgnore(Condition = JsonIgnoreCondition.WhenWritingNull)]
    public IReadOnlyList<TickState>? Ticks { get; init; }  // only for a tick scene, one per step

    /// <summary>Each other mover (scene/8 `others`) after it entered the world (enter_world: OK or GeneralFailure),
    /// in the scene's order; only for a scene with other movers (feature objects.moving).</summary>
    [JsonIgnore(Condition = JsonIgnoreCondition.WhenWritingNull)]
    public IReadOnlyList<Placement>? OtherPlacements { get; init; }

    /// <summary>The answer when the port threw: every field at its default, the exception in Error.</summary>
    public static Outcome Failed(Exception e) => new() { Error = $"{e.GetType().Name}: {e.Message}" };
}

/// <summary>CollisionInfo's (last known) contact plane.</summary>
public sealed record ContactPlane
{
    public bool Valid { get; init; }
    public uint Cell { get; init; }
    public bool IsWater { get; init; }
    public Vector3 Normal { get; init; }
    public float D { get; init; }
}

/// <summary>CollisionInfo's collision or sliding normal, un-normalised as ACE stores it.</summary>
public sealed record NormalState
{
    public bool Valid { get; init; }
    public Vector3 Vector { get; init; }
}

/// <summary>The mover after PhysicsObj.SetPositionInternal (a scene whose mover has a placement).</summary>
public sealed record Placement
{
    public string Result { get; init; } = "OK";  // a SetPositionError name
    public uint Cell { get; init; }
    public Vector3 Origin { get; init; }
    public Quaternion Orientation { get; init; } = Quaternion.Identity;
    public uint CurCell { get; init; }
    public IReadOnlyList<string> TransientState { get; init; } = [];
    public IReadOnlyList<uint> ShadowCells { get; init; } = [];
}

/// <summary>The mover's PhysicsObj after one step of a tick scene (or, in its Others, another mover's).</summary>
public sealed record TickState
{
    /// <summary>The other mover's id, in an entry of Others only.</summary>
    [JsonPropertyOrder(-1), JsonIgnore(Condition = JsonIgnoreCondition.WhenWritingNull)]
    public uint? Id { get; init; }

    public bool Updated { get; init; }
    public double UpdateTime { get; init; }  // PhysicsObj.UpdateTime: a double, bit-equal in every mode
    public uint Cell { get; init; }
    public uint CurCell { get; init; }
    public Vector3 Origin { get; init; }
    public Quaternion Orientation { get; init; } = Quaternion.Identity;
    public Vector3 Velocity { get; init; }
    public Vector3 Acceleration { get; init; }
    public Vector3 Omega { get; init; }
    public Vector3 CachedVelocity { get; init; }
    public IReadOnlyList<string> State { get; init; } = [];
    public IReadOnlyList<string> TransientState { get; init; } = [];
    public uint ContactPlaneCell { get; init; }
    public Plane ContactPlane { get; init; }
    public Vector3 SlidingNormal { get; init; }
    public bool JumpedThisFrame { get; init; }
    public IReadOnlyList<uint> ShadowCells { get; init; } = [];

    /// <summary>In a scene with other movers: the PhysicsObj's CollisionTable after the step, in its .NET
    /// Dictionary order (a removed record's slot is the next one filled).</summary>
    [JsonIgnore(Condition = JsonIgnoreCondition.WhenWritingNull)]
    public IReadOnlyList<CollisionRecord>? Collisions { get; init; }

    /// <summary>In a scene with other movers, on the mover's TickState: each other mover's, with its Id and
    /// Collisions, in the scene's order.</summary>
    [JsonIgnore(Condition = JsonIgnoreCondition.WhenWritingNull)]
    public IReadOnlyList<TickState>? Others { get; init; }

    [JsonIgnore(Condition = JsonIgnoreCondition.WhenWritingNull)]
    public string? Error { get; init; }  // what this step threw; later steps are not run
}

/// <summary>One record of a PhysicsObj's CollisionTable: the object touched, when (PhysicsTimer.CurrentTime, a
/// double, bit-equal in every mode) and whether it was ethereal then.</summary>
public sealed record CollisionRecord(uint Id, double TouchedTime, bool Ethereal);

/// <summary>Flag names as acconform writes them: the names of the set members of a [Flags] enum whose
/// members are ACE's (ObjectInfoState, TransientStateFlags, PhysicsState).</summary>
public static class Flags
{
    public static IReadOnlyList<string> Names<T>(T value) where T : struct, Enum
    {
        var bits = Convert.ToUInt64(value);
        return [.. Enum.GetValues<T>().Where(f => Convert.ToUInt64(f) is var b && BitOperations.IsPow2(b) && (bits & b) != 0)
            .Select(f => f.ToString())];
    }
}
