"""acconform: a property-based conformance harness for Asheron's Call movement physics.

The Python port (acconform.port) and ACE's own C# physics (acconform.oracle) both take a
Scene and return an Outcome (acconform.scene, acconform.outcome); the runner compares them.
"""

__version__ = "0.1.0"
