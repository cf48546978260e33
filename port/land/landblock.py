"""Landblock: the constructor from CellLandblock, get_land_limits, PostInit, init_landcell, init_buildings, init_static_objs, get_landcell, GetCell, GetZ, get_terrain.

ACE's Common/Landblock.cs (a LandblockStruct). The scene's Landblock record stands in for the
DAT's CellLandblock (Id, Height bytes, Terrain words); HasObjects is set exactly for a landblock
the scene puts buildings on (acconform/dat.has_objects, which acconform/dat.cell_landblock writes),
and then the constructor reads the landblock's LandblockInfo from the run's cell DAT
(DBObj.GetLandblockInfo) and PostInit's init_buildings builds its buildings from it. The Info a
scene writes has no objects, so init_static_objs' Info branch places nothing (its restriction
table, scene/8 landblocks[].restrictions, gives land cells their RestrictionObj); get_land_scenes (scenery generated from the region DAT) is not ported: a scene lists its
objects explicitly (ACE's UseSceneFiles is off in the oracle). OnRoad/IsRoad, IsDungeon and the
server-object lists are not physics and are left out.

GetCell (and so GetZ) reaches ACE's static LScape; here the run's LScape is the first argument.
"""

from __future__ import annotations

from acconform.numerics import Mode, Vector3, wrap_i32, wrap_u32
from acconform.port.anchors import anchor, harness
from acconform.port.constants import EPSILON
from acconform.port import db_obj, land_defs
from acconform.port.frame import AFrame, Position
from acconform.port.cell.land_cell import LandCell, assign_when_built
from acconform.port.land_defs import Direction
from acconform.port.land.landblock_struct import LandblockStruct
from acconform.port.vec import dot2d


def _int_div(a: int, b: int) -> int:
    """C# int division: truncates toward zero."""
    q = abs(a) // abs(b)
    return q if (a < 0) == (b < 0) else -q


class Landblock(LandblockStruct):
    @anchor("CLandBlock::CLandBlock", "Landblock.cs:Landblock(CellLandblock)")
    def __init__(self, record, land_height_table, mode: Mode, has_objects: bool = False, cell_dat=None):
        """From a scene Landblock record (id 0xXXYYFFFF, 81 heights, 81 terrain words) and the
        CellLandblock's HasObjects; `cell_dat` is DatManager.CellDat, read only when HasObjects."""
        super().__init__(record.id, record.heights, record.terrain, land_height_table, mode, lazy=not record.has_terrain)
        # Landblock.Init
        self.dir = Direction.Unknown
        self.closest = (-1.0, -1.0)
        self.static_objects: list = []
        self.server_objects: list = []  # ServerObjects: the non-DAT objects in its cells (Landblock.add_server_object)
        self.adjacents = None  # set only by LandblockManager's SetAdjacents (port/land/landblock_manager.py)
        self.buildings: list = []

        self.stab_list = None  # StabList: never assigned in ACE (add_to_stablist leaves it null)

        self.id = record.id
        self.block_info_exists = has_objects  # CellLandblock.HasObjects
        self.info = None
        if self.block_info_exists:
            self.info = db_obj.get_landblock_info(cell_dat, wrap_u32(self.id - 1))
        self.block_coord = land_defs.value_of(land_defs.blockid_to_lcoord(record.id), "Landblock(CellLandblock)")
        self.get_land_limits()

    @anchor(None, "Landblock.cs:add_server_object")
    def add_server_object(self, obj) -> bool:
        if obj not in self.server_objects:
            self.server_objects.append(obj)
            return True
        return False

    @anchor(None, "Landblock.cs:SetAdjacents")
    def set_adjacents(self, landblocks: list) -> None:
        """`landblocks`: the server landblocks (port/land/landblock_manager.py). ACE keeps each one's
        PhysicsLandblock; the port keeps the server landblock and reads its physics landblock's
        server objects when GetServerObjects iterates (the port builds landblocks on first use, and
        one never built holds none)."""
        if self.adjacents is None:
            self.adjacents = []
        else:
            self.adjacents.clear()

        for landblock in landblocks:
            self.adjacents.append(landblock)

    @anchor(None, "Landblock.cs:GetServerObjects")
    def get_server_objects(self, include_adjacents: bool) -> list:
        """`adjacents` is null unless LandblockManager's SetAdjacents set it (server mode), so
        asking for them throws NullReferenceException where ACE's foreach meets the null list."""
        results = list(self.server_objects)

        if include_adjacents:
            if self.adjacents is None:
                from ..errors import NullReferenceException

                raise NullReferenceException("Object reference not set to an instance of an object. "
                                             "(port: Landblock.adjacents, set only by LandblockManager.SetAdjacents)")
            for adjacent in self.adjacents:
                results.extend(adjacent.server_objects())

        return results

    @anchor(None, "Landblock.cs:remove_server_object")
    def remove_server_object(self, obj) -> bool:
        for i, entry in enumerate(self.server_objects):
            if entry is obj:
                del self.server_objects[i]
                return True
        return False

    @anchor("CLandBlock::get_land_limits", "Landblock.cs:get_land_limits")
    def get_land_limits(self) -> None:
        self.min_z = self.land_height_table[min(self.height)]
        self.max_z = self.land_height_table[max(self.height)]

    @anchor(None, "Landblock.cs:PostInit")
    def post_init(self, lscape=None) -> None:
        """init_landcell, init_buildings, init_static_objs. `lscape` (the run's world, with its
        PortalDat) is read only by a landblock with Info. A landblock without terrain (built lazily)
        has no land cells yet: terrain_generated does init_landcell's work on them when they are
        built (a scene puts no building on one)."""
        self.post_init_done = True
        self.init_landcell()

        self.init_buildings(lscape)
        # a lazy landblock has no Info and no StaticObjects yet, so init_static_objs would do nothing
        # but read SideCellCount, which builds the terrain an indoor scene never reads
        if self.terrain_built() or self.info is not None:
            self.init_static_objs(lscape)

    @anchor("CLandBlock::init_buildings", "Landblock.cs:init_buildings")
    def init_buildings(self, lscape) -> None:
        from acconform.port.cell.building_obj import BuildingObj

        if self.info is None or self.side_cell_count != 8:
            return

        max_size, stab_num = 0, 0
        for info in self.info.buildings:
            building = BuildingObj.make_building(info.model_id, info.portals, info.num_leaves, lscape.portal_dat)
            position = Position(self.id, AFrame.from_dat(info.frame))
            land_defs.adjust_to_outside_pos(position)  # var outside = (ACE: the result is unused)
            cell = self.get_landcell(position.obj_cell_id)
            if cell is None:
                continue
            building.set_initial_frame(position.frame)

            # hack (ACE)
            building.part_array.parts[0].pos = position
            building.position = position
            cell.building = building

            building.add_to_cell(cell)  # SortCell? (ACE)
            self.buildings.append(building)
            self.stab_list, max_size, stab_num = building.add_to_stablist(self.stab_list, max_size, stab_num)

    @anchor("CLandBlock::init_static_objs", "Landblock.cs:init_static_objs")
    def init_static_objs(self, lscape) -> None:
        """At PostInit StaticObjects is empty (a scene's outdoor statics are placed after it, as the
        oracle places them). With Info, its Objects (a scene's Info holds none:
        acconform/dat.landblock_info_record) and RestrictionTables (scene/8 landblocks[].restrictions):
        each key with a land coordinate gives the land cell at that coordinate's low three bits its
        RestrictionObj (a key of another landblock's cell names this landblock's cell at the same
        place, as ACE's index does). UseSceneFiles is off."""
        if self.side_cell_count != 8:
            return
        if len(self.static_objects) > 0:
            raise NotImplementedError("adjust_scene_obj_height: a landblock's StaticObjects at PostInit")
        elif self.info is not None:
            if self.info.objects:
                raise NotImplementedError("LandblockInfo objects: a scene writes none")

            # RestrictionTables is never null (DatLoader's LandblockInfo makes it empty)
            for key, value in self.info.restriction_tables.items():
                lcoord = land_defs.gid_to_lcoord(key)

                if lcoord is None:
                    continue

                idx = (int(lcoord[1]) & 7) + (int(lcoord[0]) & 7) * self.side_cell_count

                assign_when_built(self.land_cells[idx], "restriction_obj", value)

    @harness("init_landcell's work on a lazy landblock's cells, built after PostInit")
    def terrain_generated(self, cells: dict) -> None:
        if self.__dict__.get("post_init_done"):
            for land_cell in cells.values():
                assign_when_built(land_cell, "cur_landblock", self)

    @anchor("CLandBlock::init_landcell", "Landblock.cs:init_landcell")
    def init_landcell(self) -> None:
        for land_cell in self.land_cells.values():
            assign_when_built(land_cell, "cur_landblock", self)  # now, or when the cell is built

    @anchor("CLandBlock::GetZ", "Landblock.cs:GetZ")
    def get_z(self, lscape, point: Vector3):
        """The terrain height under point (the plane's z at point's x, y), or point.z off the block."""
        cell = self.get_cell(lscape, point)
        if cell is None:
            return point.z
        found, walkable = cell.find_terrain_poly(point, None)
        if not found:
            return point.z
        adj_z = point.z
        n = walkable.plane.normal
        if abs(n.z) > EPSILON:
            adj_z = (dot2d(point, n) + walkable.plane.d) / n.z * -1
        return adj_z

    @anchor("CLandBlock::GetCell", "Landblock.cs:GetCell")
    def get_cell(self, lscape, point: Vector3) -> LandCell | None:
        """Note x or y exactly 192 passes ACE's range test: y = 192 names the next column's
        cell 0 (whose triangles do not hold the point), x = 192 names no land cell."""
        if point.x < 0 or point.y < 0 or point.x > 192 or point.y > 192:
            return None
        to_int32 = self.mode.runtime.to_int32
        cell_x = _int_div(to_int32(point.x), 24)  # (int)point.X / 24
        cell_y = _int_div(to_int32(point.y), 24)
        # (ID & 0xFFFF0000) | (uint)(cellX * 8 + cellY) + 1: `+` binds before `|`
        block_cell_id = (self.id & 0xFFFF0000) | wrap_u32(wrap_i32(cell_x * 8 + cell_y) + 1)
        return lscape.get_landcell(block_cell_id)

    @anchor("CLandBlock::get_landcell", "Landblock.cs:get_landcell")
    def get_landcell(self, cell_id: int) -> LandCell | None:
        """This block's cell with that id, None when the slot holds another id.

        Raises InvalidOperationException (port.errors) where ACE's ``gid_to_lcoord(cellID).Value`` throws.
        """
        lcoord = land_defs.value_of(land_defs.gid_to_lcoord(cell_id), "Landblock.get_landcell")
        idx = (int(lcoord[1]) & 7) + (int(lcoord[0]) & 7) * self.side_cell_count
        cell = self.land_cells[idx]
        return cell if cell.id == cell_id else None

    @anchor("CLandBlock::get_terrain", "Landblock.cs:get_terrain", note="ACE indexes X * 255 * 9 + Y with global lcoords")
    def get_terrain(self, cell_id: int, point: Vector3) -> int:
        """ACE's index uses the global land coordinate, so only landblock column 0 with a small y
        lands inside Terrain; anything else throws in ACE (IndexError here)."""
        lcoord = land_defs.value_of(land_defs.gid_to_lcoord(cell_id), "Landblock.get_terrain")
        idx = int(lcoord[0]) * 255 * 9 + int(lcoord[1])
        if not 0 <= idx < len(self.terrain):
            raise IndexError(f"Terrain[{idx}]: index out of range (ArgumentOutOfRangeException in ACE)")
        return self.terrain[idx]
