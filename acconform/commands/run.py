"""acconform run SCENE: one scene through the port (or an implementation) and its outcome printed.

Prints the outcome as an ``acconform.outcome/1`` document (`--readable`: as `acconform show`
prints it). Exit 0 when the scene ran (a physics exception is part of the outcome), 2 for a bad
file or an implementation that does not start.
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

    backend = make_backend(args.impl, args.mode, args.timeout)
    backend.runtime = runtime_or_default(args.runtime)
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
    return 0
