// How acconform's JSON holds numbers (docs/protocol.md, "Floats"): every float is a float32, written
// as a JSON number that reads back to it or as its IEEE-754 bit pattern ("0x80000000" is -0.0); every
// id is "0x" + 8 hex digits. These converters are the only place that knows it.
using System.Globalization;
using System.Numerics;
using System.Text.Json;
using System.Text.Json.Serialization;

namespace Acconform.Adapter;

/// <summary>A float32: a finite non-zero value or +0 as a JSON number (the shortest decimal that reads back
/// to it), -0 and non-finite values as their bit pattern. Reads both forms.</summary>
public sealed class Float32Converter : JsonConverter<float>
{
    public override float Read(ref Utf8JsonReader reader, Type typeToConvert, JsonSerializerOptions options) =>
        reader.TokenType == JsonTokenType.String ? FromBits(reader.GetString()!) : reader.GetSingle();

    public override void Write(Utf8JsonWriter writer, float value, JsonSerializerOptions options)
    {
        // JSON -0 is negative zero to acconform, but not to every JSON tool between here and there
        if (float.IsFinite(value) && !(value == 0 && float.IsNegative(value)))
            writer.WriteNumberValue(value);
        else
            writer.WriteStringValue(Bits(value));
    }

    /// <summary>"0x" + the 8 hex digits of the float's bits: Bits(0.1f) is "0x3dcccccd".</summary>
    public static string Bits(float value) => $"0x{BitConverter.SingleToUInt32Bits(value):x8}";

    public static float FromBits(string text) => BitConverter.UInt32BitsToSingle((uint)Hex.Parse(text, 8, "a float32 bit pattern"));
}

/// <summary>A double (a tick's update_time): the shortest round-trip decimal, a non-finite one as its
/// 16-hex-digit bit pattern.</summary>
public sealed class Float64Converter : JsonConverter<double>
{
    public override double Read(ref Utf8JsonReader reader, Type typeToConvert, JsonSerializerOptions options) =>
        reader.TokenType == JsonTokenType.String
            ? BitConverter.UInt64BitsToDouble(Hex.Parse(reader.GetString()!, 16, "a double's bit pattern"))
            : reader.GetDouble();

    public override void Write(Utf8JsonWriter writer, double value, JsonSerializerOptions options)
    {
        if (double.IsFinite(value))
            writer.WriteNumberValue(value);
        else
            writer.WriteStringValue($"0x{BitConverter.DoubleToUInt64Bits(value):x16}");
    }
}

/// <summary>Every uint in these records is an id (a cell, a DAT file): "0xA9B40001".</summary>
public sealed class HexIdConverter : JsonConverter<uint>
{
    public override uint Read(ref Utf8JsonReader reader, Type typeToConvert, JsonSerializerOptions options) =>
        (uint)Hex.Parse(reader.GetString() ?? throw new JsonException("expected an id, \"0x\" + 8 hex digits"), 8, "an id");

    public override void Write(Utf8JsonWriter writer, uint value, JsonSerializerOptions options) =>
        writer.WriteStringValue($"0x{value:X8}");
}

/// <summary>A Vector3 as [x, y, z].</summary>
public sealed class Vector3Converter : JsonConverter<Vector3>
{
    public override Vector3 Read(ref Utf8JsonReader reader, Type typeToConvert, JsonSerializerOptions options)
    {
        var v = Floats.Read(ref reader, 3);
        return new Vector3(v[0], v[1], v[2]);
    }

    public override void Write(Utf8JsonWriter writer, Vector3 value, JsonSerializerOptions options) =>
        Floats.Write(writer, value.X, value.Y, value.Z);
}

/// <summary>A Quaternion as [w, x, y, z], acconform's (and retail's Frame's) order.</summary>
public sealed class QuaternionConverter : JsonConverter<Quaternion>
{
    public override Quaternion Read(ref Utf8JsonReader reader, Type typeToConvert, JsonSerializerOptions options)
    {
        var q = Floats.Read(ref reader, 4);
        return new Quaternion(q[1], q[2], q[3], q[0]);
    }

    public override void Write(Utf8JsonWriter writer, Quaternion value, JsonSerializerOptions options) =>
        Floats.Write(writer, value.W, value.X, value.Y, value.Z);
}

/// <summary>A System.Numerics Plane as {"normal": [x, y, z], "d": d}.</summary>
public sealed class PlaneConverter : JsonConverter<Plane>
{
    public override Plane Read(ref Utf8JsonReader reader, Type typeToConvert, JsonSerializerOptions options)
    {
        var p = JsonSerializer.Deserialize<PlaneJson>(ref reader, options) ?? throw new JsonException("expected a plane");
        return new Plane(p.Normal, p.D);
    }

    public override void Write(Utf8JsonWriter writer, Plane value, JsonSerializerOptions options) =>
        JsonSerializer.Serialize(writer, new PlaneJson(value.Normal, value.D), options);

    sealed record PlaneJson(Vector3 Normal, float D);
}

/// <summary>A Position as acconform writes it, flat: {"cell": id, "origin": [...], "orientation": [w, x, y, z]}.</summary>
public sealed class PositionConverter : JsonConverter<Position>
{
    public override Position Read(ref Utf8JsonReader reader, Type typeToConvert, JsonSerializerOptions options)
    {
        var p = JsonSerializer.Deserialize<PositionJson>(ref reader, options) ?? throw new JsonException("expected a position");
        return new Position(p.Cell, new Frame(p.Origin, p.Orientation));
    }

    public override void Write(Utf8JsonWriter writer, Position value, JsonSerializerOptions options) =>
        JsonSerializer.Serialize(writer, new PositionJson(value.ObjCellID, value.Frame.Origin, value.Frame.Orientation), options);

    sealed record PositionJson(uint Cell, Vector3 Origin, Quaternion Orientation);
}

/// <summary>The serializer settings every document of the protocol is read and written with.</summary>
public static class Json
{
    /// <summary>A BSP or a cell tree nests one JSON level per node; acconform sends trees thousands deep.</summary>
    public const int MaxDepth = 100_000;

    public static readonly JsonSerializerOptions Options = new()
    {
        PropertyNamingPolicy = JsonNamingPolicy.SnakeCaseLower,  // ObjectInfoState <-> "object_info_state"
        MaxDepth = MaxDepth,
        RespectNullableAnnotations = true,  // a field missing or null where the record says it cannot be: a JsonException
        RespectRequiredConstructorParameters = true,
        Converters =
        {
            new Float32Converter(), new Float64Converter(), new HexIdConverter(), new Vector3Converter(),
            new QuaternionConverter(), new PlaneConverter(), new PositionConverter(),
        },
    };

    public static readonly JsonDocumentOptions DocumentOptions = new() { MaxDepth = MaxDepth };
}

static class Floats
{
    static readonly Float32Converter F32 = new();

    public static float[] Read(ref Utf8JsonReader reader, int n)
    {
        if (reader.TokenType != JsonTokenType.StartArray)
            throw new JsonException($"expected a list of {n} floats");
        var values = new float[n];
        for (var i = 0; i < n; i++)
        {
            if (!reader.Read() || reader.TokenType == JsonTokenType.EndArray)
                throw new JsonException($"expected a list of {n} floats, got {i}");
            values[i] = F32.Read(ref reader, typeof(float), Json.Options);
        }
        if (!reader.Read() || reader.TokenType != JsonTokenType.EndArray)
            throw new JsonException($"expected a list of {n} floats, got more");
        return values;
    }

    public static void Write(Utf8JsonWriter writer, params ReadOnlySpan<float> values)
    {
        writer.WriteStartArray();
        foreach (var v in values)
            F32.Write(writer, v, Json.Options);
        writer.WriteEndArray();
    }
}

static class Hex
{
    /// <summary>"0x" + exactly `digits` hex digits; a JsonException naming `what` otherwise.</summary>
    public static ulong Parse(string text, int digits, string what)
    {
        if (text.Length != 2 + digits || !text.StartsWith("0x", StringComparison.OrdinalIgnoreCase)
            || !ulong.TryParse(text.AsSpan(2), NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture, out var bits))
            throw new JsonException($"expected {what}, \"0x\" + {digits} hex digits, got \"{text}\"");
        return bits;
    }
}
