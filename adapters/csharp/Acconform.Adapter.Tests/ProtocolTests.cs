using System.Numerics;
using System.Text;
using System.Text.Json;
using System.Text.Json.Nodes;
using Acconform.Adapter;

public class ProtocolTests
{
    sealed class Port(Func<SceneRequest, Outcome> run, params string[] features) : IPhysicsPort
    {
        public Handshake Hello { get; } = new("test-port", "1.0", ["terrain", "bsp"], features, ["exact"]);

        public Outcome Run(SceneRequest request) => run(request);
    }

    const string Dat = """
        {"format": "acconform.dat/1", "land_height_table": [0.0, 2.0],
         "cell": [{"id": "0xA9B4FFFF", "type": "CellLandblock", "data": "AQID/w=="}],
         "portal": [{"id": "0x01000000", "type": "GfxObj", "data": ""}],
         "statics": [{"id": "0x70000001", "did": "0x02000001", "scale": 1.5, "state": ["Static"],
                      "position": {"cell": "0xA9B40001", "origin": [12.0, -0.0, 20.0], "orientation": [1.0, 0.0, 0.0, 0.0]}}],
         "mover": {"id": "0x50000001", "did": "0x02000000", "scale": 1.0, "state": ["Gravity"], "transient_state": [],
                   "velocity": [0.0, 0.0, -0.5], "contact_plane": {"cell": "0xA9B40001", "plane": {"normal": [0, 0, 1], "d": -20}},
                   "begin": {"cell": "0xA9B40001", "origin": [12.0, 12.0, 20.0], "orientation": [1.0, 0.0, 0.0, 0.0]}}}
        """;

    static string Request(string extra = "") =>
        """{"id": 7, "mode": "exact", "runtime": "mono", "scene": {"format": "acconform.scene/1", "name": "x"}""" + extra + "}";

    static JsonObject Answer(IPhysicsPort port, string line) => JsonNode.Parse(Host.Answer(port, line))!.AsObject();

    [Fact]
    public void The_handshake_is_the_first_line_and_each_request_gets_one_flushed_line()
    {
        var output = new StringWriter();
        Host.Serve(new Port(_ => new Outcome()), new StringReader(Request() + "\n\n" + Request() + "\n"), output);
        var lines = output.ToString().Split('\n');
        Assert.Equal("""{"protocol":"acconform.protocol/1","name":"test-port","version":"1.0","kinds":["terrain","bsp"],"features":[],"modes":["exact"]}""",
            lines[0]);
        Assert.Equal(4, lines.Length);  // the handshake, two answers, and the last newline
        Assert.Equal("", lines[3]);
    }

    [Fact]
    public void A_request_is_read_with_its_scene_raw_and_its_dat_records_decoded()
    {
        var r = SceneRequest.Parse(Request($""", "dat": {Dat}"""));
        Assert.Equal((7L, "exact", "mono", false), (r.Id, r.Mode, r.Runtime, r.Trace));
        Assert.Equal("x", r.Scene.GetProperty("name").GetString());
        var dat = r.Dat!;
        Assert.Equal((0xA9B4FFFFu, "CellLandblock"), (dat.Cell[0].Id, dat.Cell[0].Type));
        Assert.Equal(new byte[] { 1, 2, 3, 255 }, dat.Cell[0].Data);  // base64 "AQID/w=="
        Assert.Empty(dat.Portal[0].Data);
        Assert.Equal([0f, 2f], dat.LandHeightTable);
        var s = dat.Statics[0];
        Assert.Equal((0x70000001u, 0x02000001u, 1.5f, 0xA9B40001u), (s.Id, s.Did, s.Scale, s.Position.ObjCellID));
        Assert.Equal(0x80000000u, BitConverter.SingleToUInt32Bits(s.Position.Frame.Origin.Y));
        Assert.Equal(Quaternion.Identity, s.Position.Frame.Orientation);
        Assert.Equal(new Plane(0, 0, 1, -20), dat.Mover.ContactPlane!.Plane);
        Assert.Equal(new Vector3(0, 0, -0.5f), dat.Mover.Velocity);
        Assert.Null(dat.Mover.End);
        Assert.Null(dat.Mover.Placement);
    }

    [Fact]
    public void A_scene_nested_twenty_thousand_levels_deep_is_read()
    {
        var depth = 20_000;
        var tree = new StringBuilder().Insert(0, "{\"pos\":", depth).Append("null").Append('}', depth);
        var r = SceneRequest.Parse($$"""{"id": 1, "scene": {{tree}}}""");
        Assert.Equal(JsonValueKind.Object, r.Scene.GetProperty("pos").ValueKind);
    }

    [Fact]
    public void An_outcome_is_written_with_every_field_the_schema_requires_in_its_order()
    {
        var answer = Answer(new Port(_ => new Outcome
        {
            Cell = 0xA9B40001, Origin = new Vector3(12f, -0f, 0.1f), ObjectInfoState = ["Contact", "OnWalkable"],
            SlidingNormal = new NormalState { Valid = true, Vector = new Vector3(0, 0, float.NaN) },
            StaticCells = [[0xA9B40001, 0xA9B40002]],
        }), Request());
        Assert.Equal(["id", "outcome"], answer.Select(kv => kv.Key));
        Assert.Equal(7, (int)answer["id"]!);
        var o = answer["outcome"]!.AsObject();
        Assert.Equal(["format", "ok", "cell", "origin", "orientation", "object_info_state", "contact_plane",
                      "last_known_contact_plane", "collision_normal", "sliding_normal", "collided_with_environment",
                      "frames_stationary_fall", "velocity", "check_cell", "walkable", "step_up", "neg_poly_hit", "error",
                      "static_cells"], o.Select(kv => kv.Key));
        Assert.Equal("acconform.outcome/2", (string)o["format"]!);
        Assert.Equal("0xA9B40001", (string)o["cell"]!);
        Assert.Equal("""[12,"0x80000000",0.1]""", o["origin"]!.ToJsonString());
        Assert.Equal("[1,0,0,0]", o["orientation"]!.ToJsonString());  // [w, x, y, z]
        Assert.Equal("""{"valid":false,"cell":"0x00000000","is_water":false,"normal":[0,0,0],"d":0}""", o["contact_plane"]!.ToJsonString());
        Assert.Equal("""{"valid":true,"vector":[0,0,"0xffc00000"]}""", o["sliding_normal"]!.ToJsonString());
        Assert.Null(o["error"]);
        Assert.True(o.ContainsKey("error"));
        Assert.Equal("""[["0xA9B40001","0xA9B40002"]]""", o["static_cells"]!.ToJsonString());
    }

    [Fact]
    public void A_placement_makes_the_outcome_3_and_ticks_make_it_4()
    {
        var placed = Answer(new Port(_ => new Outcome { Placement = new Placement { Result = "Collided" } }), Request());
        Assert.Equal("acconform.outcome/3", (string)placed["outcome"]!["format"]!);
        var ticked = Answer(new Port(_ => new Outcome
        {
            Ticks = [new TickState { UpdateTime = 1000.05, ContactPlane = new Plane(0, 0, 1, -20), State = ["Gravity"] }],
        }), Request())["outcome"]!;
        Assert.Equal("acconform.outcome/4", (string)ticked["format"]!);
        Assert.Equal("""{"normal":[0,0,1],"d":-20}""", ticked["ticks"]![0]!["contact_plane"]!.ToJsonString());
        Assert.Equal(1000.05, (double)ticked["ticks"]![0]!["update_time"]!);
        Assert.False(ticked["ticks"]![0]!.AsObject().ContainsKey("error"));
        var movers = Answer(new Port(_ => new Outcome
        {
            Ticks = [new TickState
            {
                Collisions = [new CollisionRecord(0x80000001, 1000.05, false)],
                Others = [new TickState { Id = 0x80000001, Collisions = [new CollisionRecord(0x50000001, 1000.05, false)] }],
            }],
            OtherPlacements = [new Placement()],
        }), Request())["outcome"]!;
        Assert.Equal("acconform.outcome/6", (string)movers["format"]!);
        Assert.Equal("""{"id":"0x80000001","touched_time":1000.05,"ethereal":false}""", movers["ticks"]![0]!["collisions"]![0]!.ToJsonString());
        var other = movers["ticks"]![0]!["others"]![0]!.AsObject();
        Assert.Equal("id", other.First().Key);
        Assert.Equal("0x80000001", (string)other["id"]!);
        Assert.False(movers["ticks"]![0]!.AsObject().ContainsKey("id"));
        Assert.Single(movers["other_placements"]!.AsArray());
    }

    [Fact]
    public void An_exception_in_the_port_is_the_outcome_error_with_every_other_field_at_its_default()
    {
        var o = Answer(new Port(_ => throw new NullReferenceException("no cell 0xA9B40100")), Request())["outcome"]!.AsObject();
        Assert.Equal("NullReferenceException: no cell 0xA9B40100", (string)o["error"]!);
        Assert.Equal(19, o.Count);
    }

    [Fact]
    public void A_request_that_cannot_be_read_is_answered_with_an_error_naming_why()
    {
        var o = Answer(new Port(_ => new Outcome()), """{"id": 3, "mode": "exact"}""");
        Assert.Equal(3, (int)o["id"]!);
        Assert.StartsWith("InvalidRequest: ", (string)o["outcome"]!["error"]!);
        Assert.Contains("scene", (string)o["outcome"]!["error"]!);
        var numberId = Answer(new Port(_ => new Outcome()), Request(", \"dat\": " + Dat.Replace("\"0xA9B4FFFF\"", "42")));
        Assert.Equal(7, (int)numberId["id"]!);
        Assert.StartsWith("InvalidRequest: ", (string)numberId["outcome"]!["error"]!);
    }

    [Fact]
    public void A_traced_request_is_answered_with_the_records_the_port_wrote_and_its_declared_routines()
    {
        var port = new Port(r =>
        {
            r.Tracer!.Anchors = ["Polygon.cs:hits_sphere"];
            r.Tracer.Step(0, new PathState { CurCell = 0xA9B40001, Walkable = new Plane(0, 0, 1, -20) });
            r.Tracer.Step(1, new PathState { CurCell = 0xA9B40001, PlacementAllowsSliding = false, HitsInteriorCell = true });
            r.Tracer.Enter("Polygon.cs:hits_sphere", Tracer.Value(-0f), Tracer.Value(float.NaN));
            r.Tracer.Exit("Polygon.cs:hits_sphere", true);
            return new Outcome();
        }, "trace");
        var trace = Answer(port, Request(""", "trace": true"""))["trace"]!;
        Assert.Equal("acconform.trace/1", (string)trace["format"]!);
        Assert.Equal("""["Polygon.cs:hits_sphere"]""", trace["anchors"]!.ToJsonString());
        var records = trace["records"]!.AsArray();
        Assert.Equal(["step", "step", "enter", "exit"], records.Select(r => (string)r!["event"]!));
        Assert.Equal(("Transition.cs:FindTransitionalPosition", 0), ((string)records[0]!["anchor"]!, (int)records[0]!["step"]!));
        Assert.Equal("0xA9B40001", (string)records[0]!["path"]!["cur_cell"]!);
        Assert.Equal("""{"normal":[0,0,1],"d":-20}""", records[0]!["path"]!["walkable"]!.ToJsonString());
        // SpherePath's optional flags: left null, not written (and not compared); given, written by their snake_case names
        Assert.False(records[0]!["path"]!.AsObject().ContainsKey("building_check"));
        var flags = records[1]!["path"]!.AsObject();
        Assert.Equal((false, true), ((bool)flags["placement_allows_sliding"]!, (bool)flags["hits_interior_cell"]!));
        Assert.False(flags.ContainsKey("building_check"));
        Assert.Equal("""[-0,"0xffc00000"]""", records[2]!["args"]!.ToJsonString());
        Assert.False(records[2]!.AsObject().ContainsKey("path"));
    }

    [Fact]
    public void A_port_without_the_trace_feature_gets_no_tracer_and_writes_no_trace()
    {
        var answer = Answer(new Port(r => new Outcome { Error = r.Tracer is null ? null : "traced" }), Request(""", "trace": true"""));
        Assert.False(answer.ContainsKey("trace"));
        Assert.Null(answer["outcome"]!["error"]);
    }

    [Flags]
    enum ObjectInfoState : uint { Contact = 0x1, OnWalkable = 0x2, EdgeSlide = 0x200 }

    [Fact]
    public void Flag_names_are_the_set_members_in_value_order() =>
        Assert.Equal(["Contact", "EdgeSlide"], Flags.Names(ObjectInfoState.EdgeSlide | ObjectInfoState.Contact));
}
