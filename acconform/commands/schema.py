"""acconform schema scene|outcome: the JSON Schema of a record, generated from the records (acconform/schema.py)."""

from __future__ import annotations


def add_arguments(p) -> None:
    p.add_argument("record", choices=("scene", "outcome"), help="which record's schema to print")


def run(args) -> int:
    import json

    from ..schema import schemas

    scene, outcome = schemas()
    print(json.dumps(scene if args.record == "scene" else outcome, indent=1))
    return 0
