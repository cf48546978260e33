"""acconform.port.transition: ACE's Transition machinery (Transition, SpherePath, CollisionInfo, ObjectInfo, CellArray).

Importing the package also gives LandCell its collision methods (land_cell_collision).
"""

from ..land import land_cell_collision as _land_cell_collision  # noqa: F401  (attaches LandCell methods)
