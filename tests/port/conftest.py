"""tests/port: makes the shared helpers here (numerics_replay) importable from every subdirectory."""

import sys
from pathlib import Path

_HERE = str(Path(__file__).resolve().parent)
if _HERE not in sys.path:
    sys.path.insert(0, _HERE)
