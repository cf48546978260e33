"""SortCell: FindCollisions, find_transit_cells (the sphere and parts overloads).

ACE's Common/SortCell.cs: an ObjCell that may hold a building (LandCell derives from it).
Buildings are not in scenes yet, so a cell's Building is always null and both overrides do nothing
but what ACE does with no building.
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
            raise NotImplementedError("buildings (BuildingObj.find_building_collisions) are not ported")
        return TransitionState.OK

    @anchor("CSortCell::find_transit_cells", "SortCell.cs:find_transit_cells")
    def find_transit_cells(self, lscape, position, num_sphere, spheres, cell_array, path) -> None:
        if self.building is not None:
            raise NotImplementedError("buildings (BuildingObj.find_building_transit_cells) are not ported")

    @anchor("CSortCell::find_transit_cells", "SortCell.cs:find_transit_cells(int, List<PhysicsPart>, CellArray)",
            "the parts overload")
    def find_transit_cells_parts(self, lscape, num_parts, parts, cell_array) -> None:
        if self.building is not None:
            raise NotImplementedError("buildings (BuildingObj.find_building_transit_cells) are not ported")
