"""acconform validate FILE...: read each scene, case, record or outcome file and report it."""

from __future__ import annotations

import sys


def add_arguments(p) -> None:
    p.add_argument("files", nargs="+", metavar="FILE", help="acconform JSON files (scene, case, record, outcome)")
    p.add_argument("-q", "--quiet", action="store_true", help="print only problems")


def run(args) -> int:
    from ..case import Case, Record, load_document
    from ..errors import InvalidScene
    from ..scene import Scene

    bad = 0
    for f in args.files:
        try:
            doc = load_document(f)
        except InvalidScene as e:
            bad += 1
            print(f"acconform validate: error: {e}", file=sys.stderr)
            continue
        if not args.quiet:
            kind = {Scene: "scene", Case: "case", Record: "record"}.get(type(doc), "outcome")
            scene = getattr(doc, "scene", doc if isinstance(doc, Scene) else None)
            label = f" {scene.name!r}" if scene is not None and scene.name else ""
            print(f"ok {f}: {kind}{label}")
    return 2 if bad else 0
