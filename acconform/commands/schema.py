"""acconform schema scene|outcome|trace|dat: the JSON Schema of a record, generated from the records (acconform/schema.py).

`acconform schema outcome --fields` prints the table of outcome fields (path, JSON type, unit,
meaning) that docs/protocol.md holds, generated the same way.
"""

from __future__ import annotations


def add_arguments(p) -> None:
    p.add_argument("record", choices=("scene", "outcome", "trace", "dat"),
                   help="which record's schema to print (dat: a request's DAT records, feature dat)")
    p.add_argument("--fields", action="store_true", help="outcome only: print the Markdown table of its fields, "
                   "their types and units (docs/protocol.md's), not the schema")


def run(args) -> int:
    import json

    from ..errors import AcconformError
    from ..schema import FIELDS_BEGIN, FIELDS_END, dat_schema, outcome_fields_markdown, schemas, trace_schema

    if args.fields and args.record != "outcome":
        raise AcconformError("--fields lists an outcome's fields: use `acconform schema outcome --fields`")
    if args.record in ("trace", "dat"):
        print(json.dumps(trace_schema() if args.record == "trace" else dat_schema(), indent=1))
        return 0
    scene, outcome = schemas()
    if args.fields:
        print("\n".join((FIELDS_BEGIN, outcome_fields_markdown(outcome), FIELDS_END)))
        return 0
    print(json.dumps(scene if args.record == "scene" else outcome, indent=1))
    return 0
