"""acconform.port.cell: the cells ACE keeps in Physics/Common (ObjCell, SortCell, LandCell, CellStruct, EnvCell).

Imported in class order, base first: obj_cell's find_cell_list reaches land_cell through this
package when it runs.
"""

from . import obj_cell, sort_cell, land_cell, cell_struct, env_cell  # noqa: F401
