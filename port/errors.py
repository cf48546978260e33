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
    """ACE dereferences null, e.g. a landblock it would have read from the cell DAT.

    The port also meets C#'s null where ACE does without a test of its own: a ported routine
    that calls a member of a field ACE leaves null (a BSP node's missing child) reads the member
    of Python's None. run_scene reports that AttributeError as this exception (`from_none`):
    .NET throws NullReferenceException for exactly that, and a port bug that reaches None where
    ACE has an object still differs from ACE's outcome."""

    dotnet_type = "NullReferenceException"

    @staticmethod
    @harness("Python's AttributeError on None as .NET's NullReferenceException")
    def from_none(e: AttributeError) -> "NullReferenceException":
        return NullReferenceException(f"Object reference not set to an instance of an object. (port: {e.name} of None)")


class InvalidOperationException(AceException):
    """ACE reads ``.Value`` of an empty ``Nullable`` (e.g. GetBlockOffset for landblock column 0xFF)."""

    dotnet_type = "InvalidOperationException"

    def __init__(self, where: str):
        super().__init__(f"Nullable object must have a value. ({where})")


class EndOfStreamException(AceException):
    """BinaryReader reads past the end of a DAT record."""

    dotnet_type = "EndOfStreamException"


class KeyNotFoundException(AceException):
    """A .NET Dictionary indexer misses, e.g. a BSP leaf naming a polygon the GfxObj does not hold."""

    dotnet_type = "KeyNotFoundException"


class ArgumentException(AceException):
    """A .NET Dictionary.Add of a key it already holds, e.g. a DAT record listing a polygon id twice."""

    dotnet_type = "ArgumentException"


class NotImplementedException(AceException):
    """ACE's DatLoader meets a layout it does not read (e.g. a CVertexArray of another vertex type)."""

    dotnet_type = "NotImplementedException"


class NotSupportedException(AceException):
    """The oracle's facade refuses what the harness does not model (a projectile's launch across landblocks);
    the port refuses it with the same verdict."""

    dotnet_type = "NotSupportedException"


class ArgumentOutOfRangeException(AceException):
    """A .NET List indexer or ``Enumerable.ElementAt`` past the end, e.g. ConstructVertices reading
    Height[0] of the empty CellLandblock ACE's DAT read gives for a landblock its DAT lacks, or
    InterpolationManager.UseTime's loop, which starts at ``ElementAt(PositionQueue.Count)``."""

    dotnet_type = "ArgumentOutOfRangeException"


class InvalidCastException(AceException):
    """A C# cast of an object to a class it is not, e.g. ``(EnvCell)`` of an outdoor cell an
    EnvCell's visible-cell list names."""

    dotnet_type = "InvalidCastException"


class ArithmeticException(AceException):
    """``Math.Sign`` of a NaN float, e.g. MotionTable.GetObjectSequence comparing the signs of a NaN
    speed and the substate's."""

    dotnet_type = "ArithmeticException"
