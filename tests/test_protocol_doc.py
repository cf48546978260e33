"""docs/protocol.md's table of outcome fields is the one generated from the records, and is current."""

from dataclasses import fields, is_dataclass
import typing

import pytest

from acconform.outcome import Outcome
from acconform.schema import _inner_record, FIELDS_BEGIN, FIELDS_END, outcome_fields_markdown, schemas
from pathlib import Path

DOC = Path(__file__).resolve().parent.parent / "docs" / "protocol.md"


def _record_fields(record, prefix=""):
    hints = typing.get_type_hints(record)
    for f in fields(record):
        yield prefix + f.name, f
        inner = _inner_record(hints[f.name])
        if inner is not None:
            many = typing.get_origin(hints[f.name]) is tuple or any(
                typing.get_origin(t) is tuple for t in typing.get_args(hints[f.name]))
            yield from _record_fields(inner, prefix + f.name + ("[]." if many else "."))


def test_every_outcome_field_carries_its_unit_and_meaning():
    missing = [path for path, f in _record_fields(Outcome) if "what" not in f.metadata or "unit" not in f.metadata]
    assert not missing, f"give these fields a unit and meaning in acconform/outcome.py (_field): {missing}"


def test_the_protocol_doc_holds_the_generated_table_of_outcome_fields():
    text = DOC.read_text()
    assert text.count(FIELDS_BEGIN) == 1 and text.count(FIELDS_END) == 1
    held = text.split(FIELDS_BEGIN, 1)[1].split(FIELDS_END, 1)[0].strip()
    generated = outcome_fields_markdown(schemas()[1])
    assert held == generated, ("docs/protocol.md's outcome fields are stale: replace the table between its markers "
                               "with the output of `acconform schema outcome --fields`")
    rows = {line.split("`")[1] for line in generated.splitlines()[2:]}
    assert rows == {"format"} | {path for path, _ in _record_fields(Outcome)}  # every field, nested ones too
    assert "| `velocity` | float32[3] | m/s |" in generated and "| `contact_plane.d` | float32 | m |" in generated


def test_a_field_without_a_unit_and_meaning_stops_the_table():
    schema = {"properties": {"ok": {"type": "boolean"}, "surprise": {"type": "boolean"}}}
    with pytest.raises(ValueError, match="surprise has no unit and meaning"):
        outcome_fields_markdown(schema)
