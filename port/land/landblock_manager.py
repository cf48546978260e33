"""LandblockManager: GetLandblock (a landblock's load), GetAdjacents, GetAdjacentIDs, GetAdjacentID, SetAdjacents; the server Landblock: IsDungeon.

ACE's Managers/LandblockManager.cs and Entity/Landblock.cs (the server landblock, which holds the
physics one). A running server loads a landblock through GetLandblock: the server Landblock goes
into the table, its Init PostInits the physics landblock, then SetAdjacents(landblock, true, true)
gives it (server side and, pSync, physics side) the neighbours loaded before it, and gives each of
those (server side only: traverse calls SetAdjacents(adjacent, false) without pSync) this one.
The physics landblock's adjacents are what Landblock.GetServerObjects(true) reads: null (and a
NullReferenceException) for a landblock no LandblockManager loaded.

A scene's landblocks are loaded in the scene's order, in server mode only (in client mode ACE's
LScape.Landblocks holds them and nothing sets adjacents), as the oracle's facade loads them
(Facade.LoadServerLandblock). Two things differ from ACE in how, never in what: the port builds a
physics landblock when it is first used (port/land/lscape.py), so pSync keeps the list on the
server landblock and the LScape gives it to the physics landblock when it builds it
(`physics_adjacents`); and the physics landblock keeps the server landblocks of its adjacents and
reads each one's physics landblock when iterated (ACE keeps the physics landblocks themselves):
an adjacent the run never built has no server objects, so reading it builds nothing.
"""

from __future__ import annotations

from enum import IntEnum

from acconform.port.anchors import anchor, harness


class Adjacency(IntEnum):
    """ACE's Entity/Adjacency.cs."""
    NorthWest = 0
    North = 1
    NorthEast = 2
    East = 3
    SouthEast = 4
    South = 5
    SouthWest = 6
    West = 7


class ServerLandblock:
    """ACE's server Landblock (Entity/Landblock.cs) with what the physics reads of it: Id (x, y),
    CellLandblock's heights, LandblockInfo, Adjacents and IsDungeon."""

    __slots__ = ("raw", "landblock_x", "landblock_y", "height", "landblock_info", "adjacents", "is_dungeon_cache",
                 "physics_adjacents", "lscape")

    @harness("a server Landblock as ACE's DAT-reading constructor leaves it, from the scene's record and its LandblockInfo (or None)")
    def __init__(self, record, landblock_info, lscape):
        self.raw = record.id | 0xFFFF  # Id.Raw | 0xFFFF
        self.landblock_x = (record.id >> 24) & 0xFF
        self.landblock_y = (record.id >> 16) & 0xFF
        self.height = record.heights  # CellLandblock.Height
        self.landblock_info = landblock_info
        self.adjacents: list = []  # Adjacents = new List<Landblock>()
        self.is_dungeon_cache = None  # isDungeon
        self.physics_adjacents = None  # what SetAdjacents' pSync gave the physics landblock (see the module)
        self.lscape = lscape

    @anchor(None, "ACE.Server/Entity/Landblock.cs:IsDungeon", "a property in ACE")
    def is_dungeon(self) -> bool:
        # return cached value
        if self.is_dungeon_cache is not None:
            return self.is_dungeon_cache

        # hack for NW island
        if self.landblock_x < 0x08 and self.landblock_y > 0xF8:
            self.is_dungeon_cache = False
            return self.is_dungeon_cache

        # a dungeon landblock is determined by:
        # - all heights being 0
        # - having at least 1 EnvCell (0x100+)
        # - contains no buildings
        for height in self.height:
            if height != 0:
                self.is_dungeon_cache = False
                return self.is_dungeon_cache
        info = self.landblock_info
        self.is_dungeon_cache = info is not None and info.num_cells > 0 and info.buildings is not None and len(info.buildings) == 0
        return self.is_dungeon_cache

    @harness("PhysicsLandblock.SetAdjacents at pSync: kept for the physics landblock, given to it now if the run built it (else when it does)")
    def set_physics_adjacents(self, landblocks: list) -> None:
        self.physics_adjacents = list(landblocks)
        physics = self.lscape.landblocks.get(self.raw)
        if physics is not None:
            physics.set_adjacents(self.physics_adjacents)

    @harness("the server objects of this landblock's physics landblock: none when the run never built it")
    def server_objects(self) -> list:
        physics = self.lscape.landblocks.get(self.raw)
        return physics.server_objects if physics is not None else []


class LandblockManager:
    """LandblockManager's static table (`landblocks[255, 255]`) for one run: (x, y) -> ServerLandblock."""

    def __init__(self):
        self.landblocks: dict[tuple[int, int], ServerLandblock] = {}

    @anchor(None, "ACE.Server/Managers/LandblockManager.cs:GetLandblock", "a landblock not loaded: table, Init, SetAdjacents")
    def get_landblock(self, landblock_id: int, new_landblock) -> ServerLandblock:
        """GetLandblock(id, loadAdjacents: false): the loaded landblock of `landblock_id`, or, for one not
        loaded yet, `new_landblock()` (``new Landblock(landblockId)``, whose constructor reads the DAT: here,
        the scene's record) in the table, then SetAdjacents; Init (the physics landblock's PostInit) is left
        to the LScape, which builds it on first use."""
        set_adjacents = False

        key = ((landblock_id >> 24) & 0xFF, (landblock_id >> 16) & 0xFF)
        landblock = self.landblocks.get(key)

        if landblock is None:
            # load up this landblock
            landblock = self.landblocks[key] = new_landblock()
            set_adjacents = True

        # cache adjacencies
        if set_adjacents:
            self.set_adjacents(landblock, True, True)
        return landblock

    @anchor(None, "ACE.Server/Managers/LandblockManager.cs:GetAdjacents")
    def get_adjacents(self, landblock: ServerLandblock) -> list:
        adjacent_ids = self.get_adjacent_ids(landblock)

        adjacents = []

        for adjacent_id in adjacent_ids:
            adjacent = self.landblocks.get(adjacent_id)
            if adjacent is not None:
                adjacents.append(adjacent)

        return adjacents

    @anchor(None, "ACE.Server/Managers/LandblockManager.cs:GetAdjacentIDs")
    def get_adjacent_ids(self, landblock: ServerLandblock) -> list:
        adjacents = []

        if landblock.is_dungeon():
            return adjacents  # dungeons have no adjacents

        north = self.get_adjacent_id(landblock, Adjacency.North)
        south = self.get_adjacent_id(landblock, Adjacency.South)
        west = self.get_adjacent_id(landblock, Adjacency.West)
        east = self.get_adjacent_id(landblock, Adjacency.East)
        northwest = self.get_adjacent_id(landblock, Adjacency.NorthWest)
        northeast = self.get_adjacent_id(landblock, Adjacency.NorthEast)
        southwest = self.get_adjacent_id(landblock, Adjacency.SouthWest)
        southeast = self.get_adjacent_id(landblock, Adjacency.SouthEast)

        for adjacent in (north, south, west, east, northwest, northeast, southwest, southeast):
            if adjacent is not None:
                adjacents.append(adjacent)

        return adjacents

    @staticmethod
    @anchor(None, "ACE.Server/Managers/LandblockManager.cs:GetAdjacentID")
    def get_adjacent_id(landblock: ServerLandblock, adjacency: Adjacency) -> tuple[int, int] | None:
        """The (x, y) of the LandblockId, or None (C#'s null LandblockId?)."""
        lbx = landblock.landblock_x
        lby = landblock.landblock_y

        if adjacency == Adjacency.North:
            lby += 1
        elif adjacency == Adjacency.South:
            lby -= 1
        elif adjacency == Adjacency.West:
            lbx -= 1
        elif adjacency == Adjacency.East:
            lbx += 1
        elif adjacency == Adjacency.NorthWest:
            lby += 1
            lbx -= 1
        elif adjacency == Adjacency.NorthEast:
            lby += 1
            lbx += 1
        elif adjacency == Adjacency.SouthWest:
            lby -= 1
            lbx -= 1
        else:  # Adjacency.SouthEast (the last of the enum's eight: ACE's switch has no default)
            lby -= 1
            lbx += 1

        if lbx < 0 or lbx > 254 or lby < 0 or lby > 254:
            return None

        return (lbx, lby)

    @anchor(None, "ACE.Server/Managers/LandblockManager.cs:SetAdjacents")
    def set_adjacents(self, landblock: ServerLandblock, traverse: bool = True, p_sync: bool = False) -> None:
        landblock.adjacents = self.get_adjacents(landblock)

        if p_sync:
            landblock.set_physics_adjacents(landblock.adjacents)

        if traverse:
            for adjacent in landblock.adjacents:
                self.set_adjacents(adjacent, False)
