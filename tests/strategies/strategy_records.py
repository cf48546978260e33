"""Helpers shared by the strategy tests."""

import dataclasses


def floats_in(rec):
    """Every float held anywhere in a record (dataclasses, tuples)."""
    if isinstance(rec, float):
        yield rec
    elif dataclasses.is_dataclass(rec):
        for f in dataclasses.fields(rec):
            yield from floats_in(getattr(rec, f.name))
    elif isinstance(rec, tuple):
        for v in rec:
            yield from floats_in(v)
