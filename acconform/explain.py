"""Explaining a difference: the first record where an implementation's trace parts from the reference's.

`explain(scene, ace, ace_source, backend, mode, runtime)` traces the scene on the implementation
(an `Implementation` with the protocol's `trace` feature, or the built-in port) and on the
reference, and names the first divergence (acconform.trace.first_divergence): tick, step, record,
routine (ACE's method and the retail name), field, both values and the ulps between them.

With ACE configured, the reference is ACE's own trace at the port's grain, from the instrumented
ACE (oracle/instrumented.py; `traced_ace`), compared from the statics' placement and the run's start on
the records that carry state (trace.against_ace): the port's own differences from ACE are explained this
way too.
Without ACE, the reference is the port's trace, and only where the port's outcome is ACE's for this
scene (`ace`: the recorded answer): for any such scene the port's trace is the trace of a run that
ends as ACE's does. Where the port itself differs from ACE there is then no reference trace, and the
explanation says so instead of naming a divergence.
"""

from __future__ import annotations

from dataclasses import dataclass

from .compare import _show, compare
from .outcome import Outcome
from .scene import Scene
from .trace import Divergence, TraceRecord, first_divergence

BEFORE = 4  # records shown before the first divergence, on each side


@dataclass(frozen=True, slots=True)
class Explanation:
    implementation: str  # its name ("acconform port" for the built-in one)
    reference: str  # which trace is the reference and why it may be
    outcome_differs: bool  # the implementation's outcome differs from ACE's
    divergence: Divergence | None
    note: str  # why no divergence is named, when none is
    ours: tuple[TraceRecord, ...] = ()  # the reference trace (the port's)
    theirs: tuple[TraceRecord, ...] = ()  # the implementation's trace
    implementation_outcome: Outcome | None = None
    known: object = None  # a divergences.Known row the first divergence matches, or None
    reference_name: str = "port"  # whose trace `ours` is: the port's, or ACE's stepped trace


def retail_name(ace: str) -> str | None:
    from .port.anchors import load_all

    for a in load_all().values():
        if a.ace == ace and a.retail:
            return a.retail
    return None


def _implementation_name(backend) -> str:
    return backend.name if getattr(backend, "command", None) else "acconform port"


def explain(scene: Scene, ace: Outcome, ace_source: str, backend, mode: str = "exact",
            runtime: str = "coreclr", live=None, traced_ace=None) -> Explanation:
    """Trace `scene` on `backend` and on the port, and name where they first part (module docstring).
    With `traced_ace` (oracle.instrumented.TracedAce: ACE configured), the reference is ACE's own trace at
    the port's grain (`_against_ace`). Else, where the port itself differs from ACE and `live` (a
    LiveOracle) is given, the reference is ACE's own stepped trace (LiveOracle.stepped_trace), compared
    at its grain: each step."""
    from .port.run import traced_run
    from .port.tracing import record_kinds

    name = _implementation_name(backend)
    if traced_ace is not None:
        return _against_ace(scene, ace, ace_source, backend, mode, runtime, traced_ace)
    ours_outcome, ours = traced_run(scene, mode, runtime)
    if getattr(backend, "command", None) is None:  # the built-in port itself: its outcome is ACE's or not
        differs = bool(compare(ours_outcome, ace, mode))
        if differs and live is not None:
            return _against_ace_steps(scene, live, name, ours, ours_outcome)
        note = ("the port's outcome differs from ACE's here, so the port's trace is no reference; ACE's own "
                "stepped trace needs a live ACE (--ace)" if differs else "the port's outcome is ACE's: nothing to explain")
        return Explanation(name, f"the port against {ace_source}", differs, None, note, ours, ours, ours_outcome)
    theirs_outcome, theirs, anchors = backend.run_traced(scene)
    differs = bool(compare(theirs_outcome, ace, mode))
    port_vs_ace = compare(ours_outcome, ace, mode)
    if port_vs_ace:
        return Explanation(name, f"none: the port's outcome differs from {ace_source} ({port_vs_ace[0]})",
                           differs, None, "the port differs from ACE here: its trace is no reference", ours,
                           theirs or (), theirs_outcome)
    reference = f"the port's trace (checked: the port's outcome for this case equals {ace_source})"
    if theirs is None:
        why = ("the implementation does not trace (its handshake lists no `trace` feature)"
               if not getattr(backend, "traces", False) else f"the implementation gave no trace ({theirs_outcome.error})")
        return Explanation(name, reference, differs, None, why, ours, (), theirs_outcome)
    d = first_divergence(ours, theirs, anchors, record_kinds())
    note = "" if d is not None else "the traces agree at the implementation's grain"
    known = None
    if d is not None:
        from .divergences import known_for

        known = known_for(d)
    return Explanation(name, reference, differs, d, note, ours, theirs, theirs_outcome, known)


def _against_ace(scene, ace: Outcome, ace_source: str, backend, mode: str, runtime: str, traced_ace) -> Explanation:
    """The implementation's trace (the port's, for the built-in port) against ACE's own, from the
    instrumented ACE (oracle/instrumented.py), compared from the statics' placement and the run's start on
    the records that carry state (trace.against_ace). The traced ACE run is checked to end in ACE's own outcome first."""
    from .port.run import traced_run
    from .trace import against_ace

    name = _implementation_name(backend)
    ace_outcome, ace_records = traced_ace.trace(scene)
    ace_differs = compare(ace_outcome, ace, "exact")
    if ace_differs:
        return Explanation(name, "none: the instrumented ACE's run does not end in ACE's answer", True, None,
                           f"the traced ACE run differs from {ace_source} ({ace_differs[0]})", ace_records, (), None)
    if getattr(backend, "command", None) is None:
        theirs_outcome, theirs = traced_run(scene, mode, runtime)
    else:
        theirs_outcome, theirs, _anchors = backend.run_traced(scene)
    differs = bool(compare(theirs_outcome, ace, mode))
    reference = (f"ACE's own trace (the instrumented ACE, checked: its run ends in {ace_source}), compared from the "
                 "statics' placement and the run's start on the records that carry state")
    if theirs is None:
        why = ("the implementation does not trace (its handshake lists no `trace` feature)"
               if not getattr(backend, "traces", False) else f"the implementation gave no trace ({theirs_outcome.error})")
        return Explanation(name, reference, differs, None, why, ace_records, (), theirs_outcome, None, "ACE")
    d = against_ace(ace_records, theirs, traced_ace.kinds, scene.ticks is not None, traced_ace.overloaded)
    known = known_here(d, backend)
    if d is not None:  # positions in the whole traces, for the records shown before it
        d = _positioned(d, ace_records, theirs)
    note = "" if d is not None else "the traces agree at the grain both write"
    return Explanation(name, reference, differs, d, note, ace_records, theirs, theirs_outcome, known, "ACE")


def known_here(d: Divergence | None, backend):
    """The known divergence (ACE versus retail) a first divergence from ACE's own trace falls in, for an
    implementation that may follow retail; None for the built-in port, which follows ACE: when it parts from an
    ACE, that ACE is not the one the port follows (a re-bugged build), whatever row the routine is in."""
    if d is None or getattr(backend, "command", None) is None:
        return None
    from .divergences import known_for

    return known_for(d)


def _positioned(d: Divergence, a_records, b_records) -> Divergence:
    """`d` with a_position and b_position the records' indices in the whole traces (against_ace compares
    filtered ones)."""
    from dataclasses import replace

    def at(records, r, fallback):
        if r is None:
            return len(records)
        for i, x in enumerate(records):
            if x is r:
                return i
        return fallback

    return replace(d, a_position=at(a_records, d.a, d.a_position), b_position=at(b_records, d.b, d.b_position))


def _against_ace_steps(scene, live, name, ours, ours_outcome) -> Explanation:
    from .oracle.live import SteppedTraceRefused

    try:
        _, steps = live.stepped_trace(scene)
    except SteppedTraceRefused as e:
        return Explanation(name, "none: ACE's stepped trace was refused", True, None,
                           f"ACE's stepped trace refused: {e}", (), ours, ours_outcome)
    d = first_divergence(steps, ours)
    known = None  # `ours` is the port's trace, which follows ACE (known_here)
    return Explanation(name, "ACE's stepped trace (checked: the stepped run ends in ACE's own outcome), compared "
                       "at its grain: each pass of FindTransitionalPosition's loop", True, d,
                       "" if d is not None else "the port's steps are ACE's: they part after the last step",
                       steps, ours, ours_outcome, known, "ACE")


def explain_case(case, backend, mode: str, runtime: str, ace: Outcome | None = None,
                 source: str = "the case's recorded answer", live=None, traced_ace=None) -> Explanation:
    """The one way a case's first divergence is found: check's triage, `explain`, `repro` and `report`
    all call this, so they name the same divergence for the same case. `ace`: ACE's answer (live
    ACE's, where configured), else the one recorded in the case. `traced_ace`: the instrumented ACE
    (ACE configured), whose own trace is then the reference."""
    return explain(case.scene, case.oracle if ace is None else ace, source, backend, mode, runtime, live, traced_ace)


def group_name(e: Explanation) -> str | None:
    """The first divergence as check's groups, explain's output and report's index name it
    (``first divergence: <routine> <field>``), or None when none is named."""
    return f"first divergence: {e.divergence.key()}" if e.divergence is not None else None


def triage(found, backend, mode: str, runtime: str, say=None, traced_ace=None) -> None:
    """Give each difference found its group: its first divergence (routine and field) where the
    implementation traces, else the fields it differs in (the built-in port: no reference trace unless
    `traced_ace`, the instrumented ACE, gives ACE's own)."""
    port = getattr(backend, "command", None) is None
    if (port and traced_ace is None) or (not port and not getattr(backend, "traces", False)):
        return
    for n, f in enumerate(found, 1):
        if say is not None:
            say(f"tracing difference {n} of {len(found)} for its first divergence")
        e = explain_case(f.case, backend, mode, runtime, traced_ace=traced_ace)
        if e.divergence is not None:
            f.group = group_name(e)
            f.known = e.known.name if e.known is not None else ""


def _value(field: str, v) -> str:
    leaf = field.rsplit(".", 1)[-1]
    return _show(leaf, v) if isinstance(v, (float, int)) and not isinstance(v, bool) else repr(v)


def _brief(r: TraceRecord | None) -> str:
    if r is None:
        return "(end of trace)"
    where = "".join(f" {k}{v}" for k, v in (("tick", r.tick), ("step", r.step)) if v is not None)
    if r.placing is not None:
        where += f" placing {r.placing:#x}"
    text = f"{r.event:<6} {r.anchor}{where}"
    if r.result is not None:
        text += f" -> {str(r.result)[:40]}"
    if r.path is not None:
        text += f"  check {r.path.check_cell:08X} {tuple(round(x, 4) for x in r.path.check_pos)}"
    if r.mover is not None:
        text += f"  at {r.mover.cell:08X} {tuple(round(x, 4) for x in r.mover.origin)}"
    return text


def placing_label(placing: int) -> str:
    """A placement's records as explain names them (as ticks and steps are named)."""
    return f"placing static {placing:#x}" if placing else "placing static 0 (a stab an EnvCell makes as it loads)"


def render(e: Explanation) -> list[str]:
    """The explanation as lines: the reference, the first divergence, the records before it on both sides."""
    ref_name = e.reference_name
    lines = [f"reference: {e.reference}"]
    d = e.divergence
    if d is None:
        lines.append(f"first divergence: none ({e.note})")
        return lines
    r = d.a or d.b
    retail = retail_name(d.routine)
    where = ", ".join(f"{k} {v}" for k, v in (("tick", d.tick), ("step", d.step)) if v is not None)
    if d.placing is not None:
        where = ", ".join(x for x in (where, placing_label(d.placing)) if x)
    where = where or "before the steps"
    lines.append(f"{group_name(e)} ({where}, record {d.a_position}: {r.event} of {r.anchor})")
    lines.append(f"  in: {d.routine}" + (f" (retail {retail})" if retail else ""))
    ulps = d.ulps
    lines.append(f"  field: {d.field}: {ref_name}={_value(d.field, d.a_value)} {e.implementation}="
                 f"{_value(d.field, d.b_value)}" + (f", {ulps} ulps apart" if ulps is not None else ""))
    if e.known is not None:
        lines.append(f"  known: ACE differs from retail here ({e.known.name}: {e.known.ace_does}; "
                     f"retail {e.known.retail_does})")
    lines.append(f"records before it ({ref_name} | {e.implementation}):")
    for side, records, pos in ((ref_name, e.ours, d.a_position), (e.implementation, e.theirs, d.b_position)):
        lines.append(f"  {side}:")
        for i in range(max(0, pos - BEFORE), min(pos + 1, len(records) + 1)):
            mark = ">" if i == pos else " "
            lines.append(f"   {mark}{i:>6} {_brief(records[i] if i < len(records) else None)}")
    return lines
