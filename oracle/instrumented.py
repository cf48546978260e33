"""The instrumented ACE: ACE's own trace at the port's grain, from a rewritten copy of the user's build.

At run time, acconform's instrumenter (oracle/instrument/Instrument.cs, our own C#, built once into
the user cache against Mono.Cecil from NuGet) writes a copy of the user's ACE.Entity.dll,
ACE.DatLoader.dll and ACE.Server.dll in which every method the port anchors (port/anchors.py) calls a recorder at its
entry and its returns. The copy lives in ``$XDG_CACHE_HOME/acconform/instrumented/<key>`` (key: the
ACE assemblies' hash, the instrumenter's and recorder's source, the anchors, the runtime), beside the
build's other files (links to them); nothing of ACE enters the repository. The recorder
(oracle/instrument/Recorder.cs) is compiled into that copy's facade and writes the records the
port's tracing writes (port/tracing.py); `records_from` turns them into acconform.trace records.

pythonnet loads one runtime and one ACE.Server per process, so a traced ACE run happens in a worker
process (`TracedAce`, `python -m acconform.oracle.instrumented`) that loads the copy; plain runs stay
on the plain ACE, untouched. docs/oracle.md ("The instrumented ACE") says where ACE's grain and the
port's differ.
"""

from __future__ import annotations

import gc
import hashlib
import json
import os
import shutil
import subprocess
import sys
from collections import Counter
from dataclasses import replace
from pathlib import Path

from ..errors import OracleUnavailable
from ..outcome import ContactPlaneState, NormalState, Outcome, PlaneState, TickState
from ..trace import PathState, TraceRecord
from .config import AceLocation, cache_dir
from .loading import Loading, to_stderr

SOURCE_DIR = Path(__file__).with_name("instrument")
INSTRUMENTER = SOURCE_DIR / "Instrument.cs"
RECORDER = SOURCE_DIR / "Recorder.cs"
CECIL = ("Mono.Cecil", "0.11.6")  # the instrumenter's one package (MIT), from the user's NuGet
REWRITTEN = ("ACE.Entity.dll", "ACE.DatLoader.dll", "ACE.Server.dll")
FTP = "Transition.cs:FindTransitionalPosition"
TI = "Transition.cs:TransitionalInsert"
TICK = "PhysicsObj.cs:update_object"
PLACE = "PhysicsObj.cs:add_obj_to_cell"
# the calls that open the port's per-step points (Recorder.cs): a pass of FTP's loop, a TI attempt; and a static's
# placement, whose records carry the static's ID
ROLES = {FTP: "f", TI: "t", "Transition.cs:AdjustOffset": "a", "Transition.cs:InsertIntoCell": "i", TICK: "u", PLACE: "o"}


class InstrumentationUnavailable(OracleUnavailable):
    """The instrumented ACE cannot be made here (no compiler, no Mono.Cecil, the rewrite failed)."""


def anchors() -> list[str]:
    """Every ACE method the port anchors, once each, sorted."""
    from ..port.anchors import load_all

    return sorted({a.ace for a in load_all().values()})


def kind(anchor: str) -> str:
    """What the port's tracing writes for a routine of this anchor (port/tracing.py `_wrap`): p, m or c."""
    from ..port.tracing import MOVER_FILE, writes_path

    file = anchor.split(":", 1)[0]
    return "p" if writes_path(anchor) else "m" if file == MOVER_FILE else "c"


def instrumentation_hash() -> str:
    """What makes one instrumented copy of a build differ from another: the instrumenter's and the recorder's source
    and the anchors it instruments."""
    return _hash(INSTRUMENTER.read_bytes(), RECORDER.read_bytes(), "\n".join(anchors()))


def _hash(*parts) -> str:
    h = hashlib.sha256()
    for p in parts:
        h.update(p if isinstance(p, bytes) else str(p).encode())
    return h.hexdigest()[:20]


def _run(cmd, what: str, timeout: int = 600, **kw) -> None:
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, **kw)
    except (OSError, subprocess.TimeoutExpired) as e:
        raise InstrumentationUnavailable(f"{what} failed to run: {e}") from None
    if p.returncode != 0:
        out = (p.stdout + p.stderr).strip()
        errors = [ln.strip() for ln in out.splitlines() if "error" in ln.lower()]
        raise InstrumentationUnavailable(f"{what} failed: {'; '.join(dict.fromkeys(errors)) or out}"[:800])


def _dotnet_env(root) -> dict:
    return dict(os.environ, DOTNET_ROOT=str(root), DOTNET_CLI_TELEMETRY_OPTOUT="1", DOTNET_NOLOGO="1",
                DOTNET_SKIP_FIRST_TIME_EXPERIENCE="1", MSBUILDDISABLENODEREUSE="1", DOTNET_CLI_UI_LANGUAGE="en")


def _dotnet_root():
    from . import dotnet_host

    return dotnet_host.find_root().path


_PROJECT = """<Project Sdk="Microsoft.NET.Sdk">
  <PropertyGroup>
    <TargetFramework>{tfm}</TargetFramework>
    <OutputType>Exe</OutputType>
    <AssemblyName>Instrument</AssemblyName>
    <Nullable>disable</Nullable>
    <ImplicitUsings>disable</ImplicitUsings>
    <EnableDefaultCompileItems>false</EnableDefaultCompileItems>
    <RollForward>Major</RollForward>
  </PropertyGroup>
  <ItemGroup>{compile}</ItemGroup>
  <ItemGroup><PackageReference Include="{name}" Version="{version}" /></ItemGroup>
</Project>
"""


def _cecil_lib() -> Path:
    """Mono.Cecil's net40 assemblies from the NuGet packages folder, restored there first when absent
    (a throw-away project's `dotnet restore` from the user's NuGet sources)."""
    packages = Path(os.environ.get("NUGET_PACKAGES") or Path.home() / ".nuget" / "packages")
    lib = packages / CECIL[0].lower() / CECIL[1] / "lib" / "net40"
    if (lib / "Mono.Cecil.dll").is_file():
        return lib
    root = _dotnet_root()
    proj = cache_dir() / "instrument" / f"restore-{os.getpid()}"
    proj.mkdir(parents=True, exist_ok=True)
    try:
        (proj / "Restore.csproj").write_text(_PROJECT.format(tfm="netstandard2.0", compile="", name=CECIL[0], version=CECIL[1]))
        _run(["dotnet", "restore", str(proj), "-nologo"], f"dotnet restore of {CECIL[0]} {CECIL[1]}",
             env=_dotnet_env(root), cwd=proj)
    finally:
        shutil.rmtree(proj, ignore_errors=True)
    if not (lib / "Mono.Cecil.dll").is_file():
        raise InstrumentationUnavailable(f"{CECIL[0]} {CECIL[1]} is not in {packages} after a restore")
    return lib


def instrumenter(runtime: str, loading: Loading) -> list[str]:
    """The command that runs the instrumenter, built once per runtime's toolchain into the user cache:
    mono, mcs against Mono.Cecil.dll from NuGet; CoreCLR, a throw-away project with a PackageReference."""
    out = cache_dir() / "instrument" / f"{runtime}-{_hash(INSTRUMENTER.read_bytes(), *CECIL)}"
    if runtime == "mono":
        exe = out / "Instrument.exe"
        if not exe.is_file():
            with loading.step("instrumenter build", f"compiling acconform's instrumenter with mcs (once, into {out})"):
                mcs = shutil.which("mcs")
                if mcs is None:
                    raise InstrumentationUnavailable("no mcs on PATH (Debian/Ubuntu: apt-get install mono-mcs)")
                lib = _cecil_lib()
                tmp = out.with_name(out.name + f".tmp-{os.getpid()}")
                tmp.mkdir(parents=True, exist_ok=True)
                for dll in ("Mono.Cecil.dll", "Mono.Cecil.Rocks.dll"):
                    shutil.copy2(lib / dll, tmp / dll)
                _run([mcs, "-optimize+", "-debug-", f"-out:{tmp / 'Instrument.exe'}", f"-r:{tmp / 'Mono.Cecil.dll'}",
                      f"-r:{tmp / 'Mono.Cecil.Rocks.dll'}", str(INSTRUMENTER)], "mcs (the instrumenter)")
                shutil.rmtree(out, ignore_errors=True)
                tmp.replace(out)
        return [shutil.which("mono") or "mono", str(exe)]
    dll = out / "Instrument.dll"
    root = _dotnet_root()
    if not dll.is_file():
        with loading.step("instrumenter build", f"building acconform's instrumenter with the .NET SDK (once, into {out})"):
            proj = out.with_name(out.name + f".project-{os.getpid()}")
            shutil.rmtree(proj, ignore_errors=True)
            proj.mkdir(parents=True)
            try:
                from . import dotnet_host

                sdks = dotnet_host.sdk_versions(root)
                if not sdks:
                    raise InstrumentationUnavailable(f"no .NET SDK in {root}: install the SDK to build the instrumenter")
                tfm = "net" + ".".join(sdks[-1].split(".")[:1]) + ".0"
                (proj / "Instrument.csproj").write_text(_PROJECT.format(
                    tfm=tfm, compile=f'<Compile Include="{INSTRUMENTER}" />', name=CECIL[0], version=CECIL[1]))
                _run([str(dotnet_host.dotnet_cli(root)), "build", str(proj), "-c", "Release", "-o", str(proj / "out"),
                      "-nologo", "-nodeReuse:false", "-p:UseSharedCompilation=false", "-v:q"],
                     "dotnet build (the instrumenter)", env=_dotnet_env(root), cwd=proj)
                shutil.rmtree(out, ignore_errors=True)
                (proj / "out").replace(out)
            finally:
                shutil.rmtree(proj, ignore_errors=True)
    from . import dotnet_host

    return [str(dotnet_host.dotnet_cli(root)), str(dll)]


def instrumented_copy(location: AceLocation, loading: Loading | None = None) -> tuple[AceLocation, dict[int, str]]:
    """(the location of the instrumented copy of `location`'s build, anchor by instrumented method id),
    written once into the user cache."""
    loading = loading or Loading(None)
    src = location.directory
    names = anchors()
    digest = hashlib.sha256()
    for f in REWRITTEN:
        digest.update((src / f).read_bytes())
    key = _hash(digest.hexdigest(), location.runtime, INSTRUMENTER.read_bytes(), "\n".join(names))
    out = cache_dir() / "instrumented" / key
    map_file = out / "anchors.map"
    if not map_file.is_file():
        command = instrumenter(location.runtime, loading)
        tmp = out.with_name(out.name + f".tmp-{os.getpid()}")
        shutil.rmtree(tmp, ignore_errors=True)
        tmp.mkdir(parents=True)
        with loading.step("instrument", f"writing an instrumented copy of {src / 'ACE.Server.dll'} into {out}"):
            (tmp / "anchors.txt").write_text("\n".join(names) + "\n")
            _run(command + [str(src), str(tmp), str(tmp / "anchors.txt"), str(tmp / "anchors.map")], "the instrumenter")
            for f in src.iterdir():  # the build's other files, linked (copied where links cannot be made)
                if f.name in REWRITTEN or not f.is_file():
                    continue
                try:
                    os.symlink(f.resolve(), tmp / f.name)
                except OSError:
                    shutil.copy2(f, tmp / f.name)
            shutil.rmtree(out, ignore_errors=True)
            tmp.replace(out)
    ids: dict[int, str] = {}
    for line in map_file.read_text().splitlines():
        parts = line.split("\t")
        if parts[0].isdigit():
            ids[int(parts[0])] = parts[1]
    return replace(location, assembly=out / "ACE.Server.dll", source=f"instrumented copy of {location.assembly}"), ids


def unresolved(location: AceLocation) -> list[str]:
    """The anchors the instrumenter found no method for in this build (read from its map)."""
    copy, _ = instrumented_copy(location)
    return [ln.split("\t", 1)[1] for ln in (copy.directory / "anchors.map").read_text().splitlines()
            if ln.startswith("unresolved\t")]


def record_kinds(ids: dict[int, str]) -> frozenset:
    """Every (anchor, event) kind the instrumented ACE can write (the counterpart of tracing.record_kinds)."""
    out = {(FTP, "step"), (TI, "insert"), (TICK, "tick")}
    for a in ids.values():
        k = kind(a)
        out.update((a, e) for e in (("enter", "exit") if k == "p" else ("enter", "exit", "call") if k == "m" else ("call",)))
    return frozenset(out)


def recorder_table(ids: dict[int, str]) -> str:
    """Recorder.Install's table: per instrumented method id, its kind and role."""
    return "\n".join(kind(ids[i]) + ROLES.get(ids[i], "-") for i in range(len(ids))) + "\n"


# ---------------------------------------------------------------- records


def _v(x) -> tuple[float, float, float]:
    return (float(x[0]), float(x[1]), float(x[2]))


def _path(p) -> PathState:
    def contact(c):
        return ContactPlaneState(bool(c[0]), int(c[1]), bool(c[2]), _v(c[3]), float(c[4]))

    return PathState(int(p[0]), _v(p[1]), int(p[2]), _v(p[3]), _v(p[4]), contact(p[5]), contact(p[6]),
                     NormalState(bool(p[7][0]), _v(p[7][1])), NormalState(bool(p[8][0]), _v(p[8][1])),
                     PlaneState(_v(p[9][0]), float(p[9][1])) if p[9] is not None else None,
                     bool(p[10]), bool(p[11]), bool(p[12]), bool(p[13]), int(p[14]), int(p[15]),
                     *(bool(x) for x in p[16:19]))


def _mover(m) -> TickState:
    q = m[5]
    return TickState(updated=bool(m[0]), update_time=float(m[1]), cell=int(m[2]), cur_cell=int(m[3]), origin=_v(m[4]),
                     orientation=(float(q[0]), float(q[1]), float(q[2]), float(q[3])), velocity=_v(m[6]),
                     acceleration=_v(m[7]), omega=_v(m[8]), cached_velocity=_v(m[9]), state=int(m[10]),
                     transient_state=int(m[11]), contact_plane_cell=int(m[12]),
                     contact_plane=PlaneState(_v(m[13][0]), float(m[13][1])), sliding_normal=_v(m[14]),
                     jumped_this_frame=bool(m[15]), shadow_cells=tuple(int(x) for x in m[16]))


def records_from(text: str, ids: dict[int, str], outcome: Outcome | None = None) -> tuple[TraceRecord, ...]:
    """The recorder's lines as acconform.trace records; a tick record's mover is the outcome's tick.

    A record's path and mover are indices of the snapshots the recorder defines once each ("#p" and "#m" lines,
    Recorder.cs): each is read once, then every record line as one JSON array -- one parse, not one a line. The
    collector is off meanwhile: the many lists and floats read would set it off again and again, for nothing to
    collect (it cost more than the reading)."""
    enabled = gc.isenabled()
    gc.disable()
    try:
        return _records_from(text, ids, outcome)
    finally:
        if enabled:
            gc.enable()


def _records_from(text: str, ids: dict[int, str], outcome: Outcome | None) -> tuple[TraceRecord, ...]:
    out = []
    ticks = getattr(outcome, "ticks", None) or ()
    lines = text.split("\n")
    if lines and not lines[-1]:
        lines.pop()
    defined = [ln for ln in lines if ln[:1] == "#"]
    if defined:
        lines = [ln for ln in lines if ln[:1] != "#"]
    paths = [_path(p) for p in json.loads("[" + ",".join(ln[3:] for ln in defined if ln[1] == "p") + "]")]
    movers = [_mover(m) for m in json.loads("[" + ",".join(ln[3:] for ln in defined if ln[1] == "m") + "]")]
    get = ids.get
    for i, event, tick, step, within, args, result, path, mover, placing in json.loads("[" + ",".join(lines) + "]"):
        anchor = FTP if event == "step" else TI if event == "insert" else TICK if event == "tick" else ids[i]
        if event == "tick":
            mover = ticks[tick] if 0 <= tick < len(ticks) else None
            if mover is None or mover.error is not None:
                continue  # the port writes no tick record after a tick that threw
        elif mover is not None:
            mover = movers[mover]
        if path is not None:
            path = paths[path]
        out.append(TraceRecord(anchor, event, tick if tick >= 0 else None, step if step >= 0 else None,
                               get(within) if within >= 0 else None, args, result, path, mover,
                               placing if placing >= 0 else None))
    return tuple(out)


# ---------------------------------------------------------------- the worker


class TracedAce:
    """ACE's own traces, from the instrumented copy of `ace`'s build loaded in a worker process.

    `trace(scene)` -> (ACE's outcome, its records); `run(scene)` -> the outcome, recorder off.
    `kinds`: every kind of record the copy can write. The worker starts on first use."""

    def __init__(self, ace=None, runtime: str | None = None, say=to_stderr):
        from .config import HOW_TO_SET, resolve

        self.location = resolve(ace, runtime)
        if self.location is None:
            raise OracleUnavailable(f"no ACE assembly configured; {HOW_TO_SET}")
        self.say = say
        self._proc = None
        self.ids: dict[int, str] = {}
        self.kinds: frozenset = frozenset()
        self.overloaded: frozenset = frozenset()  # anchors instrumented on several ACE overloads

    def _start(self):
        if self._proc is not None and self._proc.poll() is None:
            return
        copy, self.ids = instrumented_copy(self.location, Loading(self.say))
        self.kinds = record_kinds(self.ids)
        counts = Counter(self.ids.values())
        self.overloaded = frozenset(a for a, n in counts.items() if n > 1)
        env = dict(os.environ)
        root = str(Path(__file__).resolve().parent.parent)
        env["PYTHONPATH"] = root + (os.pathsep + env["PYTHONPATH"] if env.get("PYTHONPATH") else "")
        self._proc = subprocess.Popen(
            [sys.executable, "-m", "acconform.oracle.instrumented", str(copy.assembly), copy.runtime],
            stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=None if self.say is not None else subprocess.DEVNULL,
            text=True, env=env, cwd=root)
        ready = self._proc.stdout.readline()
        if not ready:
            raise InstrumentationUnavailable("the instrumented ACE's worker ended before it was ready")
        doc = json.loads(ready)
        if "error" in doc:
            self.close()
            raise InstrumentationUnavailable(f"the instrumented ACE could not load: {doc['error']}")

    def _ask(self, op: str, scene) -> dict:
        self._start()
        self._proc.stdin.write(json.dumps({"op": op, "scene": scene.to_json()}) + "\n")
        self._proc.stdin.flush()
        line = self._proc.stdout.readline()
        if not line:
            self.close()
            raise InstrumentationUnavailable("the instrumented ACE's worker ended without an answer")
        doc = json.loads(line)
        if "error" in doc:
            raise InstrumentationUnavailable(f"the instrumented ACE's worker failed: {doc['error']}")
        return doc

    def run(self, scene) -> Outcome:
        return Outcome.from_json(self._ask("run", scene)["outcome"], "outcome")

    def counted(self, scene) -> tuple[Outcome, int]:
        """(ACE's outcome with the recorder on, how many records it wrote): a trace's cost without its transfer."""
        doc = self._ask("count", scene)
        return Outcome.from_json(doc["outcome"], "outcome"), doc["count"]

    def trace(self, scene) -> tuple[Outcome, tuple[TraceRecord, ...]]:
        outcome, text = self.trace_text(scene)
        return outcome, records_from(text, self.ids, outcome)

    def trace_text(self, scene) -> tuple[Outcome, str]:
        """(ACE's outcome, the recorder's lines as it wrote them)."""
        doc = self._ask("trace", scene)
        text = Path(doc["file"]).read_bytes().decode("utf-8")  # the worker's trace file (no string through pythonnet)
        if len(text) != doc["chars"]:
            raise InstrumentationUnavailable(f"the instrumented ACE's trace file {doc['file']} is not the trace it wrote")
        return Outcome.from_json(doc["outcome"], "outcome"), text

    def close(self) -> None:
        p, self._proc = self._proc, None
        if p is not None and p.poll() is None:
            try:
                p.stdin.close()
                p.wait(timeout=10)
            except (OSError, subprocess.TimeoutExpired):
                p.kill()

    def __del__(self):
        try:
            self.close()
        except Exception:
            pass


def _serve(assembly: str, runtime: str) -> int:
    """The worker: the instrumented copy loaded, its recorder installed; one JSON request a line on stdin,
    one answer a line on the stdout it was started with (what .NET or loading print goes to stderr)."""
    out = os.fdopen(os.dup(1), "w")
    os.dup2(2, 1)

    def answer(doc):
        out.write(json.dumps(doc) + "\n")
        out.flush()

    from .live import LiveOracle

    try:
        oracle = LiveOracle(assembly, runtime, say=to_stderr, extra_sources=(RECORDER,))
        from Acconform.Oracle import TraceRecorder  # type: ignore[import-not-found]

        ids = {}
        for line in (Path(assembly).parent / "anchors.map").read_text().splitlines():
            parts = line.split("\t")
            if parts[0].isdigit():
                ids[int(parts[0])] = parts[1]
        TraceRecorder.Install(recorder_table(ids))
        oracle.set_landblock_cache(False)  # a traced run starts cold, as the port's does
    except Exception as e:
        answer({"error": f"{type(e).__name__}: {e}"})
        return 1
    # a trace goes to the parent through this file (written by .NET, read by the parent: no string of it through
    # pythonnet and the pipe), removed when the worker ends
    import tempfile

    fd, trace_file = tempfile.mkstemp(prefix="acconform-trace-", suffix=".txt",
                                      dir="/dev/shm" if os.path.isdir("/dev/shm") else None)
    os.close(fd)
    answer({"ready": True})
    try:
        _requests(oracle, TraceRecorder, trace_file, answer)
    finally:
        try:
            os.unlink(trace_file)
        except OSError:
            pass
    return 0


def _requests(oracle, TraceRecorder, trace_file: str, answer) -> None:
    from ..scene import Scene

    for line in sys.stdin:
        try:
            req = json.loads(line)
            scene = Scene.from_json(req["scene"], "scene")
            if req["op"] == "trace":
                TraceRecorder.Start()
                try:
                    outcome = oracle.run(scene)
                finally:
                    chars = int(TraceRecorder.TakeTo(trace_file))
                answer({"outcome": outcome.to_json(), "file": trace_file, "chars": chars})
            elif req["op"] == "count":  # recorder on, the records counted and dropped (benchmarks/instrumented_corpus.py)
                TraceRecorder.StartCounting()
                try:
                    outcome = oracle.run(scene)
                finally:
                    TraceRecorder.Take()
                answer({"outcome": outcome.to_json(), "count": int(TraceRecorder.Count())})
            else:
                answer({"outcome": oracle.run(scene).to_json()})
        except Exception as e:
            answer({"error": f"{type(e).__name__}: {e}"})


if __name__ == "__main__":
    sys.exit(_serve(sys.argv[1], sys.argv[2]))
