// A sample port: it answers every scene with the same wrong outcome, so that `acconform check --impl`
// gives a first verdict (a difference, naming the fields). Replace Run's body with your port: build the
// world from request.Dat with your DAT loader, run the transition, fill the Outcome (docs/porting.md).
using System.Numerics;
using Acconform.Adapter;

return Host.Run(new SamplePort());

sealed class SamplePort : IPhysicsPort
{
    public Handshake Hello { get; } = new(
        Name: "sample-port",
        Version: "0.1.0",
        // every kind, and the features of a port of the transition, the mover's placement and its plain ticks, with
        // the DAT records and traces. acconform knows more (docs/protocol.md, "The exchange", lists them all: the
        // motion layer, doors, other movers, children, targets, missiles, motion queries, ...): add each one your
        // port runs, take out what it does not run yet. A scene needing a feature not listed is skipped and counted.
        Kinds: ["terrain", "bsp", "obstacles", "indoor", "buildings"],
        Features: ["engine.client", "mover.two_spheres", "mover.scaled", "object.scaled", "water", "indoor.statics",
                   "mover.placement", "mover.enter_world", "ticks", "buildings", "setup.multipart", "dat", "trace"],
        Modes: ["exact"]);

    public Outcome Run(SceneRequest request)
    {
        DatWorld dat = request.Dat!;  // with "dat" in Features, every request carries it
        // Your port here: e.g.
        //   var world = MyDatLoader.Build(dat.LandHeightTable, dat.Cell, dat.Portal, dat.Statics);
        //   var mover = world.MakeObject(dat.Mover.Did, dat.Mover.Id); ...; mover.Transition(dat.Mover.Begin, dat.Mover.End)
        // with "trace" in Features, `acconform explain` asks for a trace: here one step record, at the start
        // of FindTransitionalPosition's first pass, holding the mover's begin position and nothing else
        var begin = dat.Mover.Begin;
        request.Tracer?.Step(0, new PathState
        {
            CheckCell = begin.ObjCellID, CheckPos = begin.Frame.Origin, CurCell = begin.ObjCellID, CurPos = begin.Frame.Origin,
        });
        return new Outcome
        {
            Ok = false,  // ACE finds a valid position in most scenes: this is wrong on purpose
            Cell = begin.ObjCellID,
            Origin = Vector3.Zero,
            Orientation = Quaternion.Identity,
            StaticCells = [.. dat.Statics.Select(_ => Array.Empty<uint>())],
        };
    }
}
