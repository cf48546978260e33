// The one thing a port implements. Host.Run(port) does the rest: the handshake, reading requests,
// writing outcomes and traces (docs/porting.md walks through it).
using System.Text.Json;
using System.Text.Json.Serialization;

namespace Acconform.Adapter;

public interface IPhysicsPort
{
    /// <summary>What the port runs: written once, as the handshake, before the first request.</summary>
    Handshake Hello { get; }

    /// <summary>The port's answer to one scene. An exception thrown here becomes the outcome's Error
    /// ("NullReferenceException: ..."), as ACE's exceptions are ACE's answer.</summary>
    Outcome Run(SceneRequest request);
}

/// <summary>docs/protocol.md, "The exchange": the scene kinds and features the port supports (a scene
/// needing another is never sent), and its modes ("exact": float32 bit for bit; "fast").</summary>
public sealed record Handshake(
    string Name,
    string Version,
    IReadOnlyList<string> Kinds,  // terrain, bsp, obstacles, indoor, buildings
    IReadOnlyList<string> Features,  // e.g. engine.client, mover.two_spheres, ..., dat, trace
    IReadOnlyList<string> Modes)
{
    [JsonPropertyOrder(-1)]
    public string Protocol => "acconform.protocol/1";
}

/// <summary>One request: the scene as JSON (`acconform schema scene`), and with the feature "dat" its
/// world as DAT records.</summary>
public sealed record SceneRequest
{
    public required long Id { get; init; }
    public string Mode { get; init; } = "exact";  // exact or fast
    public string Runtime { get; init; } = "coreclr";  // whose System.Numerics the answer is compared with: mono or coreclr
    public required JsonElement Scene { get; init; }  // the whole scene: engine mode, ticks, and everything else
    public DatWorld? Dat { get; init; }  // present when the handshake lists "dat"

    /// <summary>Whether acconform asked for a trace (`explain`); the port then records into Tracer.</summary>
    public bool Trace { get; init; }

    /// <summary>Where the port writes its trace records: set when Trace is asked and the handshake lists "trace".</summary>
    [JsonIgnore]
    public Tracer? Tracer { get; init; }

    public static SceneRequest Parse(string line) =>
        JsonSerializer.Deserialize<SceneRequest>(line, Json.Options) ?? throw new JsonException("expected a request object");
}
