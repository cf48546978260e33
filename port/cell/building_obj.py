"""BuildingObj: BuildingObj(), add_to_cell, add_to_stablist, find_building_collisions, find_building_transit_cells (the sphere and parts overloads), get_building_cells, add_cells_recursive, makeBuilding, GetMinZ.

ACE's Common/BuildingObj.cs: a PhysicsObj made from a building's model (a GfxObj or Setup whose
part 0 carries the shell's physics BSP), standing in one outdoor cell (SortCell.Building) of its
landblock; Landblock.init_buildings (port/land/landblock.py) makes and places it. Its portals
(port/cell/bld_portal.py) lead into the building's EnvCells. The building is in no cell's object
list: only the cell's SortCell overrides reach it. The static LScape and PortalDat ACE reaches are
the run's `lscape` (and its `portal_dat`), passed in as the other cells do. get_object (a
building's objects: ACE returns null) and remove (destroy_buildings, never called by a
transition) are not ported.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from acconform.flags import ObjectInfoState, TransitionState

from ..anchors import anchor
from ..physics_obj import PhysicsObj
from .bld_portal import BldPortal

FLOAT_MAX_VALUE = 3.4028234663852886e38  # float.MaxValue


@dataclass(slots=True, eq=False)
class BuildingObj(PhysicsObj):
    building_cells: list | None = None  # BuildingCells: null until get_building_cells
    portals: list = field(default_factory=list)  # BldPortal
    leaf_cells: list = field(default_factory=list)  # PartCell (never read by the physics: all null)
    shadow_list: list = field(default_factory=list)
    num_leaves: int = 0

    @property
    def landblock_id(self) -> int:
        """``LandblockID => CurCell.ID | 0xFFFF``."""
        return self.cur_cell.id | 0xFFFF

    @anchor("CBuildingObj::add_to_cell", "BuildingObj.cs:add_to_cell")
    def add_to_cell(self, new_cell) -> None:
        new_cell.add_building(self)
        self.set_cell_id(new_cell.id)
        self.cur_cell = new_cell

    @anchor("CBuildingObj::add_to_stablist", "BuildingObj.cs:add_to_stablist")
    def add_to_stablist(self, block_stab_list, max_size: int, stab_num: int):
        """The C# refs come back: (blockStabList, maxSize, stabNum)."""
        for portal in self.portals:
            block_stab_list, max_size, stab_num = portal.add_to_stablist(block_stab_list, max_size, stab_num)
        return block_stab_list, max_size, stab_num

    @anchor("CBuildingObj::find_building_collisions", "BuildingObj.cs:find_building_collisions")
    def find_building_collisions(self, transition) -> TransitionState:
        if self.part_array is None:
            return TransitionState.OK

        transition.sphere_path.building_check = True
        transition_state = self.part_array.parts[0].find_obj_collisions(transition)
        transition.sphere_path.building_check = False

        if transition_state != TransitionState.OK and not transition.object_info.state & ObjectInfoState.Contact:
            transition.collision_info.collided_with_environment = True

        if transition.trace is not None:
            if transition_state == TransitionState.OK:
                transition.trace["building:collisions"] += 1
            else:
                transition.trace["building:collided"] += 1
        return transition_state

    @anchor("CBuildingObj::find_building_transit_cells",
            "BuildingObj.cs:find_building_transit_cells(Position, int, List<Sphere>, CellArray, SpherePath)")
    def find_building_transit_cells(self, lscape, pos, num_sphere: int, sphere, cell_array, path) -> None:
        for portal in self.portals:
            other_cell = portal.get_other_cell(lscape, self.cur_cell.id)
            if other_cell is not None:
                other_cell.check_building_transit(portal.other_portal_id, pos, num_sphere, sphere, cell_array, path)

    @anchor("CBuildingObj::find_building_transit_cells",
            "BuildingObj.cs:find_building_transit_cells(int, List<PhysicsPart>, CellArray)", "the parts overload")
    def find_building_transit_cells_parts(self, lscape, num_parts: int, parts, cell_array) -> None:
        for portal in self.portals:
            other_cell = portal.get_other_cell(lscape, self.cur_cell.id)
            if other_cell is not None:
                other_cell.check_building_transit_parts(lscape, portal.other_portal_id, num_parts, parts, cell_array)

    @anchor(None, "BuildingObj.cs:get_building_cells")
    def get_building_cells(self, lscape) -> list:
        if self.building_cells is not None:
            return self.building_cells

        self.building_cells = []

        # entry points into the building, aka cells touching the outdoor landblock (ACE)
        for portal in self.portals:
            entrypoint = portal.get_other_cell(lscape, self.landblock_id)
            self.add_cells_recursive(entrypoint)
        return self.building_cells

    @anchor(None, "BuildingObj.cs:add_cells_recursive")
    def add_cells_recursive(self, cell) -> None:
        # List<EnvCell>.Contains: EnvCell is IEquatable<EnvCell>, equal by ID
        if cell is None or any(c.id == cell.id for c in self.building_cells):
            return

        self.building_cells.append(cell)

        for visible_cell in cell.visible_cells.values():
            self.add_cells_recursive(visible_cell)

    @staticmethod
    @anchor("CBuildingObj::makeBuilding", "BuildingObj.cs:makeBuilding")
    def make_building(building_id: int, portals, num_leaves: int, portal_dat) -> "BuildingObj | None":
        """`portal_dat` stands in for DatManager.PortalDat, PhysicsEngine.Server and the clock."""
        building = BuildingObj.create(portal_dat.mode, portal_dat.timer, portal_dat.server)

        if not building.init_object_begin(0, False) or not building.init_part_array_object(building_id, True, portal_dat):
            return None

        building.id = building_id

        building.num_leaves = num_leaves
        building.leaf_cells = []
        for _ in range(num_leaves):
            building.leaf_cells.append(None)

        building.portals = []
        for portal in portals:
            building.portals.append(BldPortal(portal))

        if not building.init_object_end():
            return None

        return building

    @anchor(None, "BuildingObj.cs:GetMinZ")
    def get_min_z(self, lscape):
        """The lowest vertex z over every cell structure of every building cell's Environment
        (in the structures' own frames, as ACE reads them). Only ACE.Server's position helpers
        (AdjustMapCoords) call it; no transition does."""
        self.get_building_cells(lscape)

        min_z = lscape.mode.scalar(FLOAT_MAX_VALUE)

        for building_cell in [c for c in self.building_cells if c.environment is not None]:
            if building_cell.environment is None:
                continue

            for cell_struct in building_cell.environment.cells.values():
                for vertex in cell_struct.vertex_array.vertices.values():
                    if vertex.origin.z < min_z:
                        min_z = vertex.origin.z
        return min_z
