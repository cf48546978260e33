"""Helpers shared by the strategy tests."""

import dataclasses


# the tick clock's fields, doubles by design (Timers.PortalYearTicks and its steps are C# doubles)
DOUBLE_FIELDS = {("Ticks", "start"), ("TickStep", "dt")}


def floats_in(rec):
    """Every float32 field's value held anywhere in a record (dataclasses, tuples); the tick
    clock's doubles are not among them."""
    if isinstance(rec, float):
        yield rec
    elif dataclasses.is_dataclass(rec):
        for f in dataclasses.fields(rec):
            if (type(rec).__name__, f.name) not in DOUBLE_FIELDS:
                yield from floats_in(getattr(rec, f.name))
    elif isinstance(rec, tuple):
        for v in rec:
            yield from floats_in(v)
