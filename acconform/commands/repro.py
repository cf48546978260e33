"""acconform repro FILE: replay a case on the port or --impl (and the live oracle where configured).

Prints the field-by-field difference. Exit 0 when the case no longer fails, 1 when it still
does, 2 for a bad file. Without a live ACE the oracle's side is the outcome stored in the case.
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
    from ..case import Case, load_document
    from ..compare import compare, render
    from ..errors import AcconformError, InvalidScene
    from ..numerics import runtime_named
    from ..oracle import live_configured
    from ..impl import make_backend
    from ..runner import guarded

    doc = load_document(args.file)
    if not isinstance(doc, Case):
        raise InvalidScene("format", "expected a case file (\"acconform.case/1\"); use `acconform show` for other files", args.file)
    mode = args.mode or doc.mode
    if live_configured(args.ace):  # the port computes as the ACE it is compared with
        from ..oracle.config import resolve

        runtime = resolve(args.ace, args.runtime).runtime
    else:  # ... as the ACE that answered the case
        runtime = runtime_named(doc.versions.runtime)
        if args.runtime is not None and args.runtime != runtime:
            raise AcconformError(f"--runtime {args.runtime}: this case holds the answer of ACE on {runtime}, and "
                                 f"without a live ACE nothing answers as {args.runtime} (configure ACE, or drop --runtime)")
    backend = make_backend(args.impl, mode, args.timeout)
    backend.runtime = runtime
    try:
        port = guarded(backend, doc.scene)
    finally:
        getattr(backend, "close", lambda: None)()
    if live_configured(args.ace):
        from ..oracle import require_live

        oracle = guarded(require_live(args.ace, args.runtime).run, doc.scene)
        source = "live ACE"
    else:
        oracle = doc.oracle
        source = "the oracle outcome recorded in the case (no ACE configured)"
    diffs = compare(port, oracle, mode)
    who = f"implementation {backend.name!r}" if args.impl else "port"
    print(f"{args.file}: {who} (mode {mode}, {runtime} arithmetic) vs {source}")
    if not diffs:
        print("no longer fails: every field agrees")
        return 0
    print(f"still fails: {len(diffs)} field{'s' if len(diffs) != 1 else ''} differ")
    for line in render(diffs):
        print(f"  {line}")
    return 1
