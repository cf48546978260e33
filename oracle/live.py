"""The live oracle: ACE's own physics, run on a scene through pythonnet.

`LiveOracle(assembly, runtime=None)` finds and loads ACE (oracle/config.py, oracle/runtime.py),
then runs each scene in one call into acconform's C# facade (oracle/facade/Facade.cs, compiled
against the user's ACE on first use), the one place where a scene becomes ACE's objects. Every
scene starts from fresh ACE global state; an exception ACE raises is the verdict `Outcome(error=...)`.
Loading says what it is doing through `say` (oracle/loading.py; None: silent) and keeps each step's
seconds in `load_seconds`.
"""

from __future__ import annotations

import ctypes
import struct

from .. import __version__, deep
from ..case import Versions
from ..errors import OracleError, OracleUnavailable
from ..outcome import Outcome
from ..scene import Scene
from . import config
from . import runtime as _rt
from .loading import Loading, Say, to_stderr
from .pack import pack_scene, unpack_outcome


class LiveOracle:
    name = "live"

    def __init__(self, assembly=None, runtime: str | None = None, say: Say | None = to_stderr, extra_sources=()):
        location = config.resolve(assembly, runtime)
        if location is None:
            raise OracleUnavailable(f"no ACE assembly configured for the live oracle; {config.HOW_TO_SET}")
        self.location = location
        loading = Loading(say)
        self.ace = _rt.load(location, loading)
        label = config.ace_label()
        ace = f"{label} ({self.ace.ace_version})" if label else self.ace.ace_version
        self.versions = Versions(acconform=__version__, ace=ace, runtime=self.ace.runtime_version)
        who = self.ace.identity
        self.ace_line = who.line if who is not None else None  # which ACE this is, in one line (oracle/identity.py)
        self.ace_note = who.note if who is not None else None  # said beside differences when it is not the port's ACE
        if say is not None and self.ace_line:
            say(self.ace_line)
        self._facade, self.facade_status = _load_facade(self.ace, loading, extra_sources)
        if self._facade is None:
            raise OracleUnavailable(f"the C# facade is unavailable: {self.facade_status}")
        self._buffers()
        self.load_seconds = dict(loading.seconds)  # step -> seconds (oracle/loading.py), for a campaign's summary
        if say is not None:
            say(loading.summary())
        entry = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_int)
        self._run_pinned = entry(int(self._facade.RunPinnedAddress))
        self._run_many_pinned = entry(int(self._facade.RunManyPinnedAddress))
        self.last_ace_micros = 0.0  # ACE's in-runtime FindValidPosition time for the last scene
        self.last_case_micros = 0.0  # the whole scene inside .NET (build, transition, read back)
        self.last_landblocks_built = 0  # landblocks the facade built for the last scene
        self.last_landblocks_reused = 0  # ... and took from its cache (same bytes, same height table)
        self.last_build_micros = 0.0  # time building them (CellLandblock.Unpack, new Landblock, PostInit)
        self.last_transition_micros = 0.0  # PhysicsObj.transition's own work (MakeTransition .. CleanupTransition)

    def unsupported(self, scene: Scene) -> str | None:
        """Why this ACE cannot run `scene` (the campaign skips it, naming why), or None. An ACE whose
        physics clock is wall time (oracle/identity.py, before ACE #4110) gives a tick scene update
        times of whenever it ran: the facade cannot set its clock, so its answer is not a function
        of the scene."""
        who = self.ace.identity
        if scene.ticks is not None and who is not None and who.wall_clock:
            return "this ACE runs tick scenes on wall time (PhysicsTimer before ACE #4110)"
        return None

    def run(self, scene: Scene) -> Outcome:
        return self.run_timed(scene)[0]

    def run_timed(self, scene: Scene) -> tuple[Outcome, float]:
        """(Outcome, ACE's in-runtime FindValidPosition time in microseconds)."""
        data = deep.retrying(pack_scene, scene)  # a BSP thousands of levels deep packs on a deep stack
        n = self._call(self._run_pinned, data)
        outcome, us, case_us, counts = unpack_outcome(self._out, 0) if n <= self._out_cap else self._overflow(n)
        self.last_ace_micros, self.last_case_micros = us, case_us
        (self.last_landblocks_built, self.last_landblocks_reused, self.last_build_micros,
         self.last_transition_micros) = counts
        return outcome, us

    def player_answers(self, skills, extents) -> tuple[float, float | None, list[tuple[bool, float]]]:
        """What ACE's WeenieObject answers for the mover's Player with `skills` (acconform.scene.MoverSkills), set as
        a scene's are (Facade.PlayerAnswers): InqRunRate's rate, InqBurden (None for null) and, per extent,
        InqJumpVelocity's (bool, velocity_z). Floats are the float32 values."""
        from System import Array, Single

        out = list(self._facade.PlayerAnswers(
            skills.run, skills.jump, skills.stamina, skills.strength, skills.encumbrance_val,
            skills.augmentation_increased_carrying_capacity, Array[Single]([float(e) for e in extents])))
        burden = None if out[1] != out[1] else float(out[1])
        return float(out[0]), burden, [(out[2 + 2 * i] == 1.0, float(out[3 + 2 * i])) for i in range(len(extents))]

    # -------------------------------------------------------------- the pinned buffers
    def _buffers(self) -> None:
        """Addresses of the facade's pinned input and output arrays (they move only when they grow)."""
        f = self._facade
        self._in_addr, self._in_cap = int(f.InputAddress), int(f.InputCapacity)
        self._out_addr, self._out_cap = int(f.OutputAddress), int(f.OutputCapacity)
        self._out = (ctypes.c_char * self._out_cap).from_address(self._out_addr)

    def _call(self, method, data: bytes) -> int:
        """Copy `data` into the facade's input array (one memmove), call `method(len)`; returns the
        outcome's length in the output array."""
        n = len(data)
        if n > self._in_cap:
            self._facade.EnsureInput(n)
            self._buffers()
        ctypes.memmove(self._in_addr, data, n)
        out = method(n)  # a native entry point (Facade.Init): ctypes, not a pythonnet call
        if out < 0:  # the facade catches ACE's exceptions itself; this is the facade failing
            raise OracleError(f"the oracle facade failed outside ACE: {self._facade.LastNativeError}")
        return out

    def _overflow(self, n: int):
        self._buffers()  # the facade grew its output array for a long outcome (an error message)
        return unpack_outcome(self._out, 0)

    def run_many(self, scenes) -> list[tuple[Outcome, float]]:
        """Several scenes in one crossing of the .NET boundary (the facade's batch call); each scene
        still starts from fresh ACE state. Returns (Outcome, ACE's FindValidPosition microseconds)."""
        scenes = list(scenes)
        parts = [struct.pack("<i", len(scenes))]
        for s in scenes:
            d = deep.retrying(pack_scene, s)
            parts.append(struct.pack("<i", len(d)))
            parts.append(d)
        total = self._call(self._run_many_pinned, b"".join(parts))
        if total > self._out_cap:
            self._buffers()
        buf, out, pos = self._out, [], 0
        for _ in scenes:
            (n,) = struct.unpack_from("<i", buf, pos)
            outcome, us, _case, _counts = unpack_outcome(buf, pos + 4)
            out.append((outcome, us))
            pos += 4 + n
        return out

    def stepped_trace(self, scene: Scene):
        """(ACE's outcome, ACE's own steps as trace records): the scene run as usual, then again with
        the facade driving FindTransitionalPosition's loop step by step through ACE's public methods
        (Facade.Stepped), a `step` record (acconform.trace) taken at the start of each pass. Refused
        (SteppedTraceRefused, naming why) when the stepped run does not end in exactly ACE's own
        outcome, or the scene has no single transition to step (a tick scene)."""
        from ..compare import compare

        if scene.ticks is not None:
            raise SteppedTraceRefused("a tick scene: ACE's transitions run inside its own update_object, not stepped")
        plain = self.run(scene)
        self._facade.Stepped = True
        try:
            stepped = self.run(scene)
            data = bytes(self._facade.Steps())
        finally:
            self._facade.Stepped = False
        diffs = compare(stepped, plain, "exact")
        if diffs:
            raise SteppedTraceRefused(f"the stepped run does not end in ACE's own outcome ({diffs[0]}; "
                                      f"{len(diffs)} field{'s' if len(diffs) != 1 else ''} differ)")
        return plain, unpack_steps(data)

    def set_landblock_cache(self, enabled: bool) -> None:
        """Reuse built landblocks across scenes (default on); off rebuilds every landblock per scene."""
        self._facade.CacheLandblocks = bool(enabled)
        self._facade.ClearCache()

    def __repr__(self):
        return f"LiveOracle({str(self.location.assembly)!r}, runtime={self.location.runtime!r})"


class SteppedTraceRefused(OracleError):
    """ACE's stepped trace cannot stand for ACE's run of this scene (the reason says why)."""


def unpack_steps(data: bytes) -> tuple:
    """Facade.Steps(): int count, then per pass of the loop its step number and the transition."""
    from ..outcome import ContactPlaneState, NormalState, PlaneState
    from ..trace import PathState, TraceRecord

    pos = 0

    def take(fmt):
        nonlocal pos
        v = struct.unpack_from("<" + fmt, data, pos)
        pos += struct.calcsize("<" + fmt)
        return v

    def plane():
        valid, cell, water, nx, ny, nz, d = take("BIBffff")
        return ContactPlaneState(bool(valid), cell, bool(water), (nx, ny, nz), d)

    if not data:
        return ()
    (count,) = take("i")
    out = []
    for _ in range(count):
        step, check_cell, cx, cy, cz, cur_cell, ux, uy, uz, ox, oy, oz = take("iIfffIffffff")
        contact, last = plane(), plane()
        cv, cnx, cny, cnz = take("Bfff")
        sv, snx, sny, snz = take("Bfff")
        (has_walkable,) = take("B")
        walkable = PlaneState(take("fff"), take("f")[0]) if has_walkable else None
        step_up, step_down, collide, neg = take("BBBB")
        fsf, state = take("iI")
        out.append(TraceRecord("Transition.cs:FindTransitionalPosition", "step", step=step, path=PathState(
            check_cell, (cx, cy, cz), cur_cell, (ux, uy, uz), (ox, oy, oz), contact, last,
            NormalState(bool(cv), (cnx, cny, cnz)), NormalState(bool(sv), (snx, sny, snz)), walkable,
            bool(step_up), bool(step_down), bool(collide), bool(neg), fsf, state)))
    return tuple(out)


def _load_facade(ace, loading: Loading, extra_sources=()):
    """(the facade's class, initialised, or None; how it was obtained or why not)."""
    from .facade_build import build

    dll, status = build(ace, loading, extra_sources)
    if dll is None:
        return None, status
    with loading.step("facade", f"loading the C# facade ({status})"):
        try:
            import clr

            clr.AddReference(str(dll))
            from Acconform.Oracle import Facade  # type: ignore[import-not-found]
        except Exception as e:
            return None, f"cannot load the compiled facade {dll}: {type(e).__name__}: {e}"
        Facade.Init()
    return Facade, status
