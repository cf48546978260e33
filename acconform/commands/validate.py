"""acconform validate FILE...: read each scene, case, record or outcome file (or corpus shard) and report it.

A JSON-lines shard (``.jsonl.gz``, as the corpus stores records) is checked line by line; each
bad line is reported naming the shard and the line.
"""

from __future__ import annotations

import sys


def add_arguments(p) -> None:
    p.add_argument("files", nargs="+", metavar="FILE", help="acconform JSON files (scene, case, record, outcome) "
                   "or corpus shards (.jsonl.gz)")
    p.add_argument("-q", "--quiet", action="store_true", help="print only problems")


def _kind(doc) -> str:
    from ..case import Case, Record
    from ..scene import Scene

    return {Scene: "scene", Case: "case", Record: "record"}.get(type(doc), "outcome")


def run(args) -> int:
    from ..case import is_lines_file, jsonl_lines, load_document, parse_document
    from ..codec import json_line
    from ..errors import InvalidScene

    bad = 0
    for f in args.files:
        if not is_lines_file(f):
            try:
                doc = load_document(f)
            except InvalidScene as e:
                bad += 1
                print(f"acconform validate: error: {e}", file=sys.stderr)
                continue
            if not args.quiet:
                scene = getattr(doc, "scene", doc if _kind(doc) == "scene" else None)
                label = f" {scene.name!r}" if scene is not None and scene.name else ""
                print(f"ok {f}: {_kind(doc)}{label}")
            continue
        # a shard: every line, going on past a bad one
        good, kinds, bad_here = 0, set(), 0
        try:
            for lineno, line in jsonl_lines(f):
                where = f"{f} line {lineno}"
                try:
                    kinds.add(_kind(parse_document(json_line(line, where), where)))
                    good += 1
                except InvalidScene as e:
                    bad_here += 1
                    print(f"acconform validate: error: {e}", file=sys.stderr)
        except InvalidScene as e:  # the gzip stream itself
            bad_here += 1
            print(f"acconform validate: error: {e}", file=sys.stderr)
        bad += bad_here
        if not args.quiet and not bad_here:
            print(f"ok {f}: {good} {'/'.join(sorted(kinds)) or 'document'}s")
    return 2 if bad else 0
