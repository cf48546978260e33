// The protocol's loop (docs/protocol.md, "The exchange"): one JSON line in, one JSON line out, flushed.
using System.Text;
using System.Text.Json;
using System.Text.Json.Serialization;

namespace Acconform.Adapter;

public static class Host
{
    /// <summary>Serves the port on the process's stdin and stdout until stdin closes. Whatever the port
    /// writes to Console.Out goes to stderr: stdout carries the protocol alone.</summary>
    public static int Run(IPhysicsPort port)
    {
        var stdout = new StreamWriter(Console.OpenStandardOutput(), new UTF8Encoding(false)) { NewLine = "\n" };
        Console.SetOut(Console.Error);
        Serve(port, new StreamReader(Console.OpenStandardInput(), new UTF8Encoding(false)), stdout);
        return 0;
    }

    public static void Serve(IPhysicsPort port, TextReader input, TextWriter output)
    {
        output.WriteLine(JsonSerializer.Serialize(port.Hello, Json.Options));
        output.Flush();
        while (input.ReadLine() is { } line)
        {
            if (line.Trim().Length == 0)
                continue;
            output.WriteLine(Answer(port, line));
            output.Flush();
        }
    }

    /// <summary>The answer line to one request line: the port's outcome (and trace, when asked); a request
    /// that cannot be read is answered with an outcome whose error says why.</summary>
    public static string Answer(IPhysicsPort port, string line)
    {
        SceneRequest request;
        try
        {
            request = SceneRequest.Parse(line);
        }
        catch (Exception e)  // JsonException, or a converter's InvalidOperationException: the line is bad input either way
        {
            return JsonSerializer.Serialize(new AnswerLine(IdOf(line), new Outcome { Error = $"InvalidRequest: {e.Message}" }, null),
                Json.Options);
        }
        if (request.Trace && port.Hello.Features.Contains("trace"))
            request = request with { Tracer = new Tracer() };
        Outcome outcome;
        try
        {
            outcome = port.Run(request);
        }
        catch (Exception e)
        {
            outcome = Outcome.Failed(e);
        }
        var trace = request.Tracer is { } t ? new TraceDocument(t.Records, t.Anchors) : null;
        return JsonSerializer.Serialize(new AnswerLine(request.Id, outcome, trace), Json.Options);
    }

    static long? IdOf(string line)
    {
        try
        {
            using var doc = JsonDocument.Parse(line, Json.DocumentOptions);
            return doc.RootElement.TryGetProperty("id", out var id) && id.TryGetInt64(out var n) ? n : null;
        }
        catch (JsonException)
        {
            return null;
        }
    }

    sealed record AnswerLine(long? Id, Outcome Outcome,
        [property: JsonIgnore(Condition = JsonIgnoreCondition.WhenWritingNull)] TraceDocument? Trace);
}
