"""acconform runtime-diff: what the runtime alone changes in ACE's outcomes, mono against .NET 10.

Pairs the committed corpus of ACE on mono with the one of ACE on .NET 10 (CoreCLR) by scene key
(the same scenes, answered by ACE at the same commit built for each runtime) and prints, per scene
kind, in how many scenes each outcome field differs (exact, float32 bits).

With ``--attribute`` it also says which System.Numerics operation (or cast) causes each
difference: for every scene whose two answers differ, the port is run computing as .NET 10 does
(it reproduces ACE on .NET 10 bit for bit) with one operation at a time switched back to mono's
formula; an operation is credited with a scene when switching it alone makes the port's outcome
ACE on mono's. Scenes no single switch explains are counted apart (several operations together).

The output is Markdown: docs/oracle.md keeps it ("What the runtime alone changes").
"""

from __future__ import annotations

from collections import Counter, defaultdict
from contextlib import contextmanager

from ..protocol import CAMPAIGN_KINDS as KINDS


def add_arguments(p) -> None:
    p.add_argument("--mono", default=None, metavar="DIR", help="corpus of ACE on mono (default: the committed one)")
    p.add_argument("--coreclr", default=None, metavar="DIR", help="corpus of ACE on .NET 10 (default: the committed one)")
    p.add_argument("--attribute", action="store_true", help="also find the System.Numerics operation behind each "
                   "difference (runs the port once per operation on each differing scene)")
    p.add_argument("--no-progress", action="store_true", help="no progress lines on stderr")


# The operations whose formula differs between the runtimes (acconform.numerics.Runtime), as
# System.Numerics names them; "casts" is C#'s (int)/(uint) of a float (saturating on .NET 9+).
OPERATIONS = {
    "negate": "Vector3 unary minus",
    "transform_by_quaternion": "Vector3.Transform(Vector3, Quaternion)",
    "transform_by_matrix": "Vector3.Transform(Vector3, Matrix4x4)",
    "lerp": "Vector3.Lerp",
    "quat_multiply": "Quaternion.Multiply (operator *)",
    "quat_inverse": "Quaternion.Inverse",
    "quat_normalize": "Quaternion.Normalize",
    "quat_lerp": "Quaternion.Lerp",
    "quat_create_from_yaw_pitch_roll": "Quaternion.CreateFromYawPitchRoll",
    "casts": "(int) / (uint) casts of a float",
}


def field_group(path: str) -> str:
    """A difference's field without its component index: ``origin[2]`` -> ``origin``."""
    return path.split("[", 1)[0]


def pair(mono, coreclr, progress=None):
    """(key, kind) of every scene both corpora hold, in the mono corpus's order. Keying parses
    every record of both; `progress` (a runner.Progress) hears how many."""
    total = len(mono) + len(coreclr)
    m = mono.index(None if progress is None else lambda done, _: progress.update(done))
    c = coreclr.index(None if progress is None else lambda done, _: progress.update(len(mono) + done))
    if progress is not None:
        progress.close(total)
    return [(key, e.kind) for key, e in m.items() if key in c]


def _progress(args, total: int, unit: str, label: str):
    from ..runner import Progress

    return Progress(total, not getattr(args, "no_progress", True), unit=unit,
                    label=f"acconform runtime-diff: {label} ")


def field_table(mono, coreclr, pairs, progress=None) -> tuple[dict, dict, Counter]:
    """({field: {kind: scenes}}, {kind: scenes differing}, {kind: scenes paired})."""
    from ..compare import compare

    fields: dict[str, Counter] = defaultdict(Counter)
    differing: Counter = Counter()
    paired: Counter = Counter()
    for i, (key, kind) in enumerate(pairs):
        if progress is not None:
            progress.update(i)
        paired[kind] += 1
        diffs = compare(mono._record(key).outcome, coreclr._record(key).outcome)
        if diffs:
            differing[kind] += 1
            for g in {field_group(d.field) for d in diffs}:
                fields[g][kind] += 1
    if progress is not None:
        progress.close(len(pairs))
    return fields, differing, paired


@contextmanager
def mono_operation(op: str):
    """The port's .NET 10 arithmetic (numerics.NET10) with `op` computed by mono's formula.

    Harness-only and process-wide: the diagnosis swaps one operation of the NET10 runtime (every
    call the port makes through a .NET 10 quaternion or mode reaches it) and restores it on exit;
    the landblock pool is emptied both ways, since landblocks are built with the arithmetic.
    Quaternions mono's formula returns are made .NET 10 ones again, so the switch stays one
    operation's and does not turn the rest of the run into mono's."""
    from .. import numerics
    from ..port.land.lscape import clear_landblock_cache

    net10, mono = numerics.NET10, numerics.MONO
    clear_landblock_cache()
    if op == "casts":
        saved = numerics.Runtime.to_int32, numerics.Runtime.to_uint32
        to_int32, to_uint32 = saved
        numerics.Runtime.to_int32 = lambda self, x: to_int32(mono if self is net10 else self, x)
        numerics.Runtime.to_uint32 = lambda self, x: to_uint32(mono if self is net10 else self, x)
        try:
            yield
        finally:
            numerics.Runtime.to_int32, numerics.Runtime.to_uint32 = saved
            clear_landblock_cache()
        return
    original, formula = getattr(net10, op), getattr(mono, op)

    def switched(*args):
        r = formula(*args)
        if type(r) is numerics.Quaternion:
            return numerics.Net10Quaternion(r.x, r.y, r.z, r.w)
        return r

    object.__setattr__(net10, op, switched)  # a frozen dataclass: the swap is this diagnosis's alone
    mul = numerics.Net10Quaternion.__mul__
    if op == "quat_multiply":
        numerics.Net10Quaternion.__mul__ = lambda a, b: switched(a, b)
    try:
        yield
    finally:
        object.__setattr__(net10, op, original)
        numerics.Net10Quaternion.__mul__ = mul
        clear_landblock_cache()


def attribute(mono, coreclr, pairs, progress=None, differing=None) -> tuple[dict, Counter, Counter]:
    """({operation: {kind: scenes it alone explains}}, {kind: scenes no single switch explains},
    {kind: scenes where the port on .NET 10 arithmetic is not ACE on .NET 10 (should be none)}).

    `progress(done)` (optional, e.g. a runner.Progress's update) hears the port runs done, of
    (operations + 1) x the differing scenes; `differing` (optional) is those scenes' (key, kind)."""
    from ..compare import compare
    from ..port.run import run_scene

    todo = differing if differing is not None else [
        (key, kind) for key, kind in pairs if compare(mono._record(key).outcome, coreclr._record(key).outcome)]
    tick = progress or (lambda done: None)
    runs = 0
    scenes = {key: mono._record(key).scene for key, _ in todo}
    port_wrong: Counter = Counter()
    for key, kind in todo:
        if compare(run_scene(scenes[key], runtime="coreclr"), coreclr._record(key).outcome):
            port_wrong[kind] += 1
        runs += 1
        tick(runs)
    explained: dict[str, Counter] = {op: Counter() for op in OPERATIONS}
    by_scene: dict[str, int] = Counter()
    for op in OPERATIONS:
        with mono_operation(op):
            for key, kind in todo:
                if not compare(run_scene(scenes[key], runtime="coreclr"), mono._record(key).outcome):
                    explained[op][kind] += 1
                    by_scene[key] += 1
                runs += 1
                tick(runs)
    several = Counter(kind for key, kind in todo if not by_scene[key])
    return explained, several, port_wrong


def _row(name: str, counts, paired=None) -> str:
    cells = [counts.get(k, 0) for k in KINDS]
    total = sum(cells)
    return f"| {name} | " + " | ".join(str(c) for c in cells) + f" | {total} |"


def render(mono, coreclr, pairs, attribution=None, table=None) -> list[str]:
    fields, differing, paired = table or field_table(mono, coreclr, pairs)
    out = [f"ACE {mono.versions.ace} on {mono.versions.runtime} against ACE {coreclr.versions.ace} on "
           f"{coreclr.versions.runtime}: {len(pairs)} scenes paired by scene key.", "",
           "| outcome field | " + " | ".join(KINDS) + " | all |", "|---|" + "---:|" * (len(KINDS) + 1),
           _row("scenes paired", paired), _row("**scenes whose outcome differs**", differing)]
    for g in sorted(fields, key=lambda g: (-sum(fields[g].values()), g)):
        out.append(_row(f"`{g}`", fields[g]))
    if attribution is not None:
        explained, several, port_wrong = attribution
        out += ["", "Scenes each operation alone explains (switching it back to mono's formula in the port's "
                ".NET 10 arithmetic makes the outcome ACE on mono's):", "",
                "| operation | " + " | ".join(KINDS) + " | all |", "|---|" + "---:|" * (len(KINDS) + 1)]
        for op in sorted(explained, key=lambda op: (-sum(explained[op].values()), op)):
            out.append(_row(OPERATIONS[op], explained[op]))
        out.append(_row("no single operation (several together)", several))
        if sum(port_wrong.values()):
            out.append(_row("**port on .NET 10 arithmetic is not ACE on .NET 10**", port_wrong))
    return out


def run(args) -> int:
    import warnings

    from ..errors import AcconformError
    from ..numerics import runtime_named
    from ..oracle import default_corpus
    from ..oracle.recorded import RecordedOracle

    warnings.simplefilter("ignore", RuntimeWarning)
    mono = RecordedOracle(args.mono or default_corpus("mono"))
    coreclr = RecordedOracle(args.coreclr or default_corpus("coreclr"))
    for oracle, want in ((mono, "mono"), (coreclr, "coreclr")):
        got = runtime_named(oracle.versions.runtime)
        if got != want:
            raise AcconformError(f"--{want}: the corpus {oracle.corpus_dir} holds answers of ACE on {got}, not {want}")
    pairs = pair(mono, coreclr, _progress(args, len(mono) + len(coreclr), "records", "pairing by scene key"))
    if not pairs:
        raise AcconformError(f"the corpora {mono.corpus_dir} and {coreclr.corpus_dir} share no scene (record the "
                             f"same scenes on both runtimes: `acconform record MONO_CORPUS/*.jsonl.gz`)")
    table = field_table(mono, coreclr, pairs, _progress(args, len(pairs), "scenes", "comparing outcomes"))
    attribution = None
    if args.attribute:
        from ..compare import compare

        differing = [(key, kind) for key, kind in pairs
                     if compare(mono._record(key).outcome, coreclr._record(key).outcome)]
        bar = _progress(args, len(differing) * (len(OPERATIONS) + 1), "runs",
                        f"switching each of {len(OPERATIONS)} operations on {len(differing)} scenes")
        attribution = attribute(mono, coreclr, pairs, bar.update, differing)
        bar.close(len(differing) * (len(OPERATIONS) + 1))
    print("\n".join(render(mono, coreclr, pairs, attribution, table)))
    return 0
