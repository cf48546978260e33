"""SortCell: FindCollisions, find_transit_cells (the sphere and parts overloads).

ACE's Common/SortCell.cs: an ObjCell that may hold a building (LandCell derives from it):
Landblock.init_buildings sets `building` (a BuildingObj, port/cell/building_obj.py) on the outdoor
cell the building stands in, and the overrides hand the cell's collisions and transit cells to it.
get_object (a building's objects) and remove_building (destroy_buildings) are not reached by a
transition and are not ported.
"""

from __future__ import annotations

from acconform.flags import TransitionState
from acconform.numerics import Mode

from ..anchors import anchor
from .obj_cell import ObjCell


class SortCell(ObjCell):
    __slots__ = ("building",)

    @anchor("CSortCell::CSortCell", "SortCell.cs:SortCell(uint)")
    def __init__(self, cell_id: int, mode: Mode):
        super().__init__(cell_id, mode)
        self.building = None

    @anchor("CSortCell::find_collisions", "SortCell.cs:FindCollisions")
    def find_collisions(self, transition) -> TransitionState:
        if self.building is not None:
            return self.building.find_building_collisions(transition)
        else:
            return TransitionState.OK

    @anchor("CSortCell::add_building", "SortCell.cs:add_building")
    def add_building(self, building) -> None:
        self.building = building

    @anchor("CSortCell::find_transit_cells", "SortCell.cs:find_transit_cells")
    def find_transit_cells(self, lscape, position, num_sphere, spheres, cell_array, path) -> None:
        if self.building is not None:
            self.building.find_building_transit_cells(lscape, position, num_sphere, spheres, cell_array, path)

    @anchor("CSortCell::find_transit_cells", "SortCell.cs:find_transit_cells(int, List<PhysicsPart>, CellArray)",
            "the parts overload")
    def find_transit_cells_parts(self, lscape, num_parts, parts, cell_array) -> None:
        if self.building is not None:
            self.building.find_building_transit_cells_parts(lscape, num_parts, parts, cell_array)

    @anchor("CSortCell::has_building", "SortCell.cs:has_building")
    def has_building(self) -> bool:
        return self.building is not None
