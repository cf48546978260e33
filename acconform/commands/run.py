"""acconform run SCENE: one scene through the port (or an implementation) and its outcome printed.

Prints the outcome as an ``acconform.outcome/1`` document (`--readable`: as `acconform show`
prints it). When ACE is configured (ACE_ASSEMBLY or the config file) the scene is also run on live
ACE and compared as `check` compares (the port computing as the runtime ACE runs on): the verdict
follows the outcome (on stderr, so stdout stays one outcome document; on stdout with --readable).
Exit 0 when the scene ran (a physics exception is part of the outcome) and agrees with ACE where
ACE is configured, 1 when it differs from ACE, 2 for a bad file or an implementation that does
not start.
"""

from __future__ import annotations


def add_arguments(p) -> None:
    p.add_argument("file", metavar="SCENE", help="a scene file (or a case or record: its scene is run)")
    p.add_argument("--mode", choices=("exact", "fast"), default="exact")
    from ..impl import add_arguments as impl_arguments

    impl_arguments(p)
    p.add_argument("--readable", action="store_true", help="print the outcome for a person, not as JSON")
    from . import add_runtime_argument

    add_runtime_argument(p, "whose System.Numerics arithmetic the port (or --impl) computes, as ACE on that runtime")


def run(args) -> int:
    from ..case import load_document
    from ..codec import dumps
    from ..impl import make_backend
    from ..scene import Scene

    doc = load_document(args.file)
    scene = doc if isinstance(doc, Scene) else getattr(doc, "scene", None)
    if scene is None:
        from ..errors import InvalidScene

        raise InvalidScene("format", "expected a scene, case or record file (an outcome has no scene to run)", args.file)
    from . import runtime_or_default

    from ..oracle import live_configured
    from ..oracle.config import resolve

    ace = resolve(None, args.runtime) if live_configured() else None  # checked on disk before anything runs
    backend = make_backend(args.impl, args.mode, args.timeout)
    backend.runtime = ace.runtime if ace is not None else runtime_or_default(args.runtime)
    try:
        why = backend.unsupported(scene)
        if why:  # sent anyway, its answer would be about a scene it says it cannot run
            from ..errors import AcconformError

            listed = "kinds" if why.startswith("kind") else "features"
            raise AcconformError(f"{args.file}: implementation {backend.name!r} does not support this scene's {why} "
                                 f"(its handshake lists {listed} {', '.join(backend.hello[listed]) or 'none'}); "
                                 "nothing was sent")
        outcome = backend(scene)
    finally:
        getattr(backend, "close", lambda: None)()
    if args.readable:
        from .show import describe_outcome

        print("\n".join(describe_outcome(outcome)))
    else:
        print(dumps(outcome.to_json()))
    return 0 if ace is None else _verdict(scene, outcome, backend, args)


def _verdict(scene, outcome, backend, args) -> int:
    """The scene on live ACE, compared with `outcome` as `check` compares; 1 when they differ."""
    import sys

    from ..compare import compare, render
    from ..oracle import require_live
    from ..runner import guarded

    oracle = require_live(None, args.runtime)
    diffs = compare(outcome, guarded(oracle.run, scene), args.mode)
    who = f"implementation {backend.name!r}" if args.impl else "port"
    out = sys.stdout if args.readable else sys.stderr
    print(f"{who} vs live ACE ({oracle.versions.runtime}), mode {args.mode}: "
          + (("1 field differs" if len(diffs) == 1 else f"{len(diffs)} fields differ") if diffs else "every field agrees"), file=out)
    for line in render(diffs, "impl" if args.impl else "port"):
        print(f"  {line}", file=out)
    return 1 if diffs else 0
