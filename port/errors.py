"""The .NET exceptions ACE throws where the port must stop the same way: AceException and its subclasses.

An ACE crash is a verdict, not a port bug: the oracle reports ACE's exception as
``"<.NET type name>: <message>"`` and run_scene reports a port exception from this family the same
way (``dotnet_type`` is the .NET name), so the comparator can match the types. The messages are
the port's own (they say why); only the type is ACE's.
"""

from __future__ import annotations

from .anchors import harness


class AceException(Exception):
    """Where ACE throws: `dotnet_type` is the .NET exception's type name (Exception.GetType().Name)."""

    dotnet_type = "Exception"

    @harness("formats the exception as the oracle reports ACE's: '<.NET type>: <message>'")
    def verdict(self) -> str:
        """The outcome's error string: ``"<dotnet_type>: <message>"``."""
        return f"{self.dotnet_type}: {self}"


class NullReferenceException(AceException):
    """ACE dereferences null, e.g. a landblock it would have read from the cell DAT."""

    dotnet_type = "NullReferenceException"


class InvalidOperationException(AceException):
    """ACE reads ``.Value`` of an empty ``Nullable`` (e.g. GetBlockOffset for landblock column 0xFF)."""

    dotnet_type = "InvalidOperationException"

    def __init__(self, where: str):
        super().__init__(f"Nullable object must have a value. ({where})")
