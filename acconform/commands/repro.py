"""acconform repro FILE: replay a case on the port or --impl (and the live oracle where configured).

Prints the field-by-field difference, with, on top, the first divergence (`acconform explain`)
when the implementation traces (the protocol's `trace` feature). Exit 0 when the case no longer fails, 1 when it still
does, 2 for a bad file. Without a live ACE the oracle's side is the outcome stored in the case.

A case made with --impl names its implementation (command, directory, handshake): `repro`
starts that command again, in that directory, and says so; when it does not start, `repro`
gives no verdict (exit 2) rather than replay the built-in port in its place. --impl CMD replays
the case on another implementation.
"""

from __future__ import annotations


def add_arguments(p) -> None:
    p.add_argument("file", metavar="FILE", help="a case file (from acconform check)")
    p.add_argument("--mode", choices=("exact", "fast"), default=None, help="override the case's mode")
    p.add_argument("--ace", default=None, help="ACE assembly for the live oracle")
    from . import add_runtime_argument

    add_runtime_argument(p, "the ACE compared with (the live oracle's runtime; without ACE the case's answer "
                         "is one runtime's, and only that one can replay it); the port computes its arithmetic")
    from ..impl import add_arguments as impl_arguments

    impl_arguments(p)


def run(args) -> int:
    from ..case import CASE_FORMAT, Case, load_document
    from ..compare import compare, render
    from ..errors import InvalidScene
    from ..runner import guarded, tested_label

    doc = load_document(args.file)
    if not isinstance(doc, Case):
        raise InvalidScene("format", f"expected a case file ({CASE_FORMAT!r}); use `acconform show` for other files", args.file)
    mode = args.mode or doc.mode
    runtime = _runtime(args, doc)
    backend, said = _backend(args, doc, mode)
    backend.runtime = runtime
    try:
        port = guarded(backend, doc.scene)
        oracle, source = ace_answer(args, doc)
        first = None
        if compare(port, oracle, mode) and getattr(backend, "traces", False):  # the first divergence on top
            from ..explain import explain_case, render as render_explanation

            first = render_explanation(explain_case(doc, backend, mode, runtime, oracle, source))
    finally:
        getattr(backend, "close", lambda: None)()
    diffs = compare(port, oracle, mode)
    who = f"implementation {backend.name!r}" if getattr(backend, "command", None) else "port"
    print(f"{args.file}: {who} (mode {mode}, {runtime} arithmetic) vs {source}")
    for line in said + (first or []):
        print(line)
    if not diffs:
        print("no longer fails: every field agrees")
        return 0
    print(f"still fails: {len(diffs)} field{'s' if len(diffs) != 1 else ''} differ")
    for line in render(diffs, tested_label(backend)):  # impl=... for an implementation under test
        print(f"  {line}")
    return 1


def _runtime(args, doc) -> str:
    """The runtime the case is replayed as: the live ACE's, else the one whose answer the case holds."""
    from ..errors import AcconformError
    from ..numerics import runtime_named
    from ..oracle import live_configured

    if live_configured(args.ace):  # the port computes as the ACE it is compared with
        from ..oracle.config import resolve

        return resolve(args.ace, args.runtime).runtime
    runtime = runtime_named(doc.versions.runtime)  # ... as the ACE that answered the case
    if args.runtime is not None and args.runtime != runtime:
        raise AcconformError(f"--runtime {args.runtime}: this case holds the answer of ACE on {runtime}, and "
                             f"without a live ACE nothing answers as {args.runtime} (configure ACE, or drop --runtime)")
    return runtime


def ace_answer(args, doc):
    """(ACE's outcome for the case's scene, where it comes from): live ACE where configured, else the
    answer recorded in the case (said so, and whose it is when the case was shrunk against the port)."""
    from ..oracle import live_configured
    from ..runner import guarded

    if live_configured(args.ace):
        from ..oracle import require_live

        return guarded(require_live(args.ace, args.runtime).run, doc.scene), "live ACE"
    source = "the oracle outcome recorded in the case (no ACE configured)"
    if doc.shrink.against == "port":
        source += "; it is the built-in port's, which stood in for ACE when the case was shrunk"
    return doc.oracle, source


def _backend(args, doc, mode):
    """(the implementation to replay on, lines saying which and why): --impl, else the one the case
    names, else the built-in port. A named implementation that does not start is exit 2."""
    from pathlib import Path

    from ..case import CASE_FORMAT_V1
    from ..errors import AcconformError
    from ..impl import make_backend
    from ..protocol import Implementation, ImplementationError

    made_by = doc.implementation
    if args.impl is not None:
        said = []
        if made_by is not None and made_by.command != args.impl:
            said.append(f"note: the case was made by implementation {made_by.handshake.get('name', '')!r} "
                        f"({made_by.command}); replaying on --impl instead")
        elif made_by is None:
            said.append("note: the case was made by the built-in port; replaying on --impl instead")
        return make_backend(args.impl, mode, args.timeout), said
    if made_by is None:
        said = []
        if doc.format == CASE_FORMAT_V1:
            said.append("note: an acconform.case/1 file does not say which implementation made it; replaying on "
                        "the built-in port (pass --impl CMD if another made it)")
        return make_backend(None, mode), said
    name = made_by.handshake.get("name", "") or made_by.command
    cwd = made_by.cwd if made_by.cwd and Path(made_by.cwd).is_dir() else None
    try:
        backend = Implementation(made_by.command, mode=mode, timeout=args.timeout, cwd=cwd)
    except ImplementationError as e:
        raise AcconformError(f"no verdict: the case was made by implementation {name!r} ({made_by.command}), "
                             f"which does not start here ({e}); pass --impl CMD to replay it on another") from None
    said = [f"replaying on the implementation the case names: {made_by.command!r}"
            + (f" in {cwd}" if cwd else " (its directory is gone: started here)")]
    now, then = backend.hello, made_by.handshake
    changed = [k for k in ("name", "version", "kinds", "features", "modes") if then and now.get(k) != then.get(k)]
    if changed:
        said.append("note: its handshake changed since the case was made: "
                    + ", ".join(f"{k} {then.get(k)!r} -> {now.get(k)!r}" for k in changed))
    return backend, said
