"""tests/port: makes the shared helpers here (numerics_replay, dat_shapes, lazy_planes) and the scene data in objects/ importable from every subdirectory."""

import sys
from pathlib import Path

_HERE = str(Path(__file__).resolve().parent)
for _p in (_HERE, str(Path(_HERE) / "objects")):
    if _p not in sys.path:
        sys.path.insert(0, _p)

