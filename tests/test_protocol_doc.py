"""docs/protocol.md's table of outcome fields is the one generated from the records, and is current."""

from dataclasses import fields, is_dataclass
import typing

import pytest

from acconform.outcome import Outcome
from acconform.schema import _inner_record, FIELDS_BEGIN, FIELDS_END, outcome_fields_markdown, schemas
from pathlib import Path

DOC = Path(__file__).resolve().parent.parent / "docs" / "protocol.md"


def _record_fields(record, prefix=""):
    """Every field of the record, nested ones too; a tick's `others` entries are TickStates without a motion
    layer, others or an error of their own."""
    hints = typing.get_type_hints(record)
    for f in fields(record):
        if prefix.endswith("others[].") and f.name in ("motion", "others", "error"):
            continue
        if f.name == "id" and prefix.endswith("ticks[]."):  # only an entry of `others` names its mover
            continue
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


def _block_after(marker: str) -> str:
    """The fenced JSON block following `marker` in docs/protocol.md, its indentation removed."""
    text = DOC.read_text()
    assert text.count(marker) == 1, marker
    block = text.split(marker, 1)[1].split("```json\n", 1)[1].split("```", 1)[0]
    return "\n".join(line.strip() for line in block.splitlines())


def _flat_walk():
    from acconform.scene import Scene

    return Scene.loads((DOC.parent.parent / "examples" / "flat_walk.json").read_text())


def test_the_protocol_doc_gives_a_complete_answer_with_every_outcome_field_as_the_port_answers_flat_walk():
    import json

    from acconform.port.run import run_scene

    answer = json.loads(_block_after("<!-- complete outcome:"))
    outcome = Outcome.from_json(answer["outcome"], "outcome")  # every field, each a float32
    assert set(answer["outcome"]) == {"format"} | {f.name for f in fields(Outcome)} - {"placement", "ticks", "other_placements", "motion_answers"}
    assert outcome == run_scene(_flat_walk(), runtime="coreclr") == run_scene(_flat_walk(), runtime="mono")


def test_the_protocol_doc_gives_an_error_answer_carrying_every_field_as_aces_error_outcome_holds_them():
    import json

    answer = json.loads(_block_after("<!-- error outcome:"))
    outcome = Outcome.from_json(answer["outcome"], "outcome")
    assert set(answer["outcome"]) == {"format"} | {f.name for f in fields(Outcome)} - {"placement", "ticks", "other_placements", "motion_answers"}
    assert outcome == Outcome(error=outcome.error) and outcome.error.startswith("NullReferenceException: ")


def test_the_protocol_doc_s_dat_example_is_what_acconform_sends_for_flat_walk():
    import json

    from acconform import dat
    from acconform.protocol import DAT_TYPES, dat_json

    sent = dat_json(dat.dat_world(_flat_walk()))
    shown = _block_after("<!-- dat example:").replace('[0.0, 2.0, 4.0, ..., 510.0]', json.dumps(sent["land_height_table"]))
    assert json.loads(shown) == json.loads(json.dumps(sent))
    text = DOC.read_text().split("## DAT records (feature `dat`)", 1)[1].split("\n## ", 1)[0]
    assert all(f"`{name}`" in text for names in DAT_TYPES.values() for name in names)
