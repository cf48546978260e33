"""acconform explain CASE: where the case's implementation first parts from the reference trace.

Traces the case's scene on its implementation (the one it names, or --impl; the feature `trace`
of docs/protocol.md) and on the port, after checking that the port's outcome equals ACE's for the
case (the answer recorded in the case, or live ACE where configured): the port's trace is then a
trace of a run that ends as ACE's does. Prints the first divergence -- tick, step, record, routine
(ACE's method and the retail name), field, both values and the ulps between them -- and the few
records before it on both sides, labelled "known" when a registered ACE-versus-retail divergence
(docs/divergences.md) is where it falls. --html FILE writes the same as one page with a top and a
side view of the scene. With a live ACE configured, the reference is ACE's own trace at the port's
grain, from the instrumented ACE (oracle/instrumented.py; docs/oracle.md "The instrumented ACE"),
for the port and for an implementation alike; where ACE cannot be instrumented here, the port is
explained against ACE's stepped trace (the facade drives FindTransitionalPosition's loop, each
step). Exit 1 while the case still fails, 0 when it no longer does, 2 for bad input.
"""

from __future__ import annotations


def add_arguments(p) -> None:
    p.add_argument("file", metavar="CASE", help="a case file (from acconform check)")
    p.add_argument("--html", default=None, metavar="FILE", help="also write one self-contained page: views of the "
                   "scene with both sides' spheres, the first divergence marked, the trace table")
    p.add_argument("--mode", choices=("exact", "fast"), default=None, help="override the case's mode")
    p.add_argument("--ace", default=None, help="ACE assembly for the live oracle")
    from . import add_runtime_argument

    add_runtime_argument(p, "the ACE compared with (see `acconform repro`)")
    from ..impl import add_arguments as impl_arguments

    impl_arguments(p)


def load_case(path: str):
    from ..case import CASE_FORMAT, Case, load_document
    from ..errors import InvalidScene

    doc = load_document(path)
    if not isinstance(doc, Case):
        raise InvalidScene("format", f"expected a case file ({CASE_FORMAT!r}); use `acconform show` for other files", path)
    return doc


def explain_case(args, doc, mode):
    """(the Explanation of case `doc` replayed as `mode`, lines saying which implementation and why,
    the runtime it computed as): explain's and report's one way to explain a case."""
    from ..explain import explain_case as explain
    from .repro import _backend, _runtime, ace_answer

    runtime = _runtime(args, doc)
    backend, said = _backend(args, doc, mode)
    backend.runtime = runtime
    try:
        ace, source = ace_answer(args, doc)
        from ..oracle import live_configured

        live = traced = None
        if live_configured(args.ace):  # ACE's own trace, from the instrumented ACE
            from ..errors import OracleUnavailable
            from ..oracle.instrumented import TracedAce

            traced = TracedAce(args.ace, args.runtime)
            try:
                return explain(doc, backend, mode, runtime, ace, source, None, traced), said, runtime
            except OracleUnavailable as e:  # no instrumented ACE here: as before, ACE's own steps for the port
                said = said + [f"no instrumented ACE ({e}); ACE's stepped trace instead"]
            finally:
                traced.close()
            if getattr(backend, "command", None) is None:
                from ..oracle import require_live

                live = require_live(args.ace, args.runtime)
        return explain(doc, backend, mode, runtime, ace, source, live), said, runtime
    finally:
        getattr(backend, "close", lambda: None)()


def run(args) -> int:
    from ..explain import render

    from ..paths import refuse_output_over_input

    refuse_output_over_input(args.html, [args.file], "--html")  # the page never replaces the case it explains
    doc = load_case(args.file)
    mode = args.mode or doc.mode
    if args.html is not None:
        from ..html import check_writable

        check_writable(args.html)
    e, said, runtime = explain_case(args, doc, mode)
    print(f"{args.file}: {e.implementation} (mode {mode}, {runtime} arithmetic)")
    for line in said + render(e):
        print(line)
    if args.html is not None:
        from ..html import explain_page, write_page

        print(f"wrote {write_page(args.html, explain_page(doc, e, args.file))}")
    return 1 if e.outcome_differs else 0
