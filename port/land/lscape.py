"""LScape: get_landblock, get_landcell -- the per-run world that stands in for ACE's static LScape/LandblockManager.

ACE keeps loaded landblocks in statics (LScape.Landblocks on the client, LandblockManager on
the server) and loads a missing one from the cell DAT. A run here builds one LScape from the
scene. ACE builds and PostInits every landblock up front; here a landblock is built on the
first get_landblock that asks for it (most scenes list landblocks a transition never enters),
into a dict keyed by landblock id (0xXXYYFFFF). That is observably the same because building is
deterministic and independent of the other landblocks, with two exceptions kept eager: a
landblock whose construction throws (an id past the world edge, where blockid_to_lcoord has
no value) is built up front, so the run fails as ACE's does; and a landblock with buildings is
built up front (constructed in the scene's order, then PostInit'd, as the facade's BuildScene
does), since its PostInit places its buildings (SortCell.add_building), records a traced run
writes: built on first use, they fell inside the run, where ACE's trace has none. Building is deterministic, so built landblocks are pooled across
runs (`LandblockPool`), keyed by everything they are built from (id, heights, terrain, land
height table, mode): a run checks one out of the pool (no other LScape can hold it meanwhile),
its cells' per-run object lists are reset (shadow objects never leak between scenes), and
`release()` hands it back when the run is over. Where ACE would load a landblock the scene does not
list, ACE reads its DAT, which has no such file: an empty CellLandblock, whose construction throws
ArgumentOutOfRangeException, and get_landblock runs the same construction (port/errors.py), which
run_scene reports as the same verdict. Indoor cells (EnvCells, 0x0100 and up) are built as
ACE builds them: get_landcell reads the EnvCell record from the run's cell DAT
(`lscape.cell_dat`, with `lscape.portal_dat` for its Environment: port/run.py sets both), caches
it in the landblock's cells and then PostInits it. A pooled landblock never keeps EnvCells
(they come from the run's DATs, which the pool key does not hold): `release` drops them. A
landblock with buildings (its CellLandblock's HasObjects, acconform/dat.has_objects) is built
from the run's DATs too (its LandblockInfo, its buildings' models, and the EnvCells a building
remembers in get_building_cells), so it is built for the run and never pooled.
"""

from __future__ import annotations

from collections import OrderedDict

from acconform.numerics import Mode
from acconform.port.anchors import anchor, harness, remembers
from acconform.port import db_obj, land_defs
from acconform.port.cell.land_cell import LandCell, is_built
from acconform.port.land.landblock import Landblock
from acconform.port.land.landblock_struct import LandblockStruct
from acconform.port.land.landblock_manager import LandblockManager, ServerLandblock


class LandblockPool:
    """Idle built landblocks, at most `size`, least recently released dropped first.

    A landblock is in the pool only while no LScape holds it: `checkout` takes it out (or
    builds one), `release` puts it back. What a run may change in a landblock is the ObjCell
    state of its cells (objects and shadow objects registered in them) and its ServerObjects
    (a placed mover); checkout resets those (LandCell.reset_for_pool), so a pooled landblock
    reads as a new one.
    Terrain (vertices, polygons and planes, cell ids and frames, water) is never changed
    after construction.
    """

    def __init__(self, size: int = 256):
        self.size = size
        self.idle: OrderedDict[tuple, Landblock] = OrderedDict()

    @staticmethod
    @harness("the landblock pool's key: everything a landblock is built from")
    def key(record, land_height_table, mode: Mode) -> tuple:
        return (record.id, tuple(record.heights), tuple(record.terrain), tuple(land_height_table), mode)

    @harness("takes a built landblock out of the pool (its cells' ObjCell state reset) or builds one")
    def checkout(self, record, land_height_table, mode: Mode) -> Landblock:
        landblock = self.idle.pop(self.key(record, land_height_table, mode), None)
        if landblock is None:
            landblock = Landblock(record, land_height_table, mode)
            landblock.post_init()
            return landblock
        for cell in landblock.land_cells.values():
            if is_built(cell):  # an unbuilt cell has no run's state
                cell.reset_for_pool()
        landblock.server_objects = []  # the last run's mover (Landblock.add_server_object)
        landblock.adjacents = None  # the last run's LandblockManager.SetAdjacents (as built: null)
        return landblock

    @harness("hands a landblock back to the pool, without the EnvCells the run loaded into it")
    def release(self, key: tuple, landblock: Landblock) -> None:
        """The run's EnvCells (LandCells keyed by their low word, 0x100 and up, as LScape.get_landcell
        adds them) leave: the next run loads its own from its cell DAT. Whatever their statics left
        in the outdoor cells goes at checkout (LandCell.reset_for_pool)."""
        for cell_id in [k for k in landblock.land_cells if k >= 0x100]:
            del landblock.land_cells[cell_id]
        self.idle.pop(key, None)
        self.idle[key] = landblock
        while len(self.idle) > self.size:
            self.idle.popitem(last=False)

    @harness("empties the landblock pool")
    def clear(self) -> None:
        self.idle.clear()


POOL = LandblockPool()
_UNSEEN = object()


@harness("empties the module's landblock pool")
def clear_landblock_cache() -> None:
    """Drop every pooled landblock (benchmarks start cold with it)."""
    POOL.clear()


class LScape:
    """The scene's outdoor world for one run (no globals: make one per run)."""

    def __init__(self, scene, mode: Mode, portal_dat=None, cell_dat=None, with_objects=None):
        """`portal_dat` and `cell_dat` are the run's DAT databases (port/run.py makes them first: a
        landblock with buildings reads them when it is built). `scene` gives the landblocks and the
        land height table; `with_objects`, the ids of the landblocks whose CellLandblock says
        HasObjects (default: the scene's, dat.has_objects)."""
        from acconform.dat import has_objects

        self.mode = mode
        self.land_height_table = scene.land_height_table
        self.landblocks: dict[int, Landblock] = {}  # the ones built so far
        self.landcells: dict[int, LandCell | None] = {}  # get_landcell's answers so far (see there)
        self.outside_cells: dict[tuple, list] = {}  # land_cell.add_all_outside_cells_replayed's memory
        self.cell_dat = cell_dat  # DatManager.CellDat: the run's cell DAT
        self.portal_dat = portal_dat  # DatManager.PortalDat: the run's portal DAT
        self.adjust_cells: dict = {}  # AdjustCell.AdjustCells (port/adjust_cell.py), per run
        self.records = {record.id | 0xFFFF: record for record in scene.landblocks}
        self.has_objects = (set(with_objects) if with_objects is not None else
                            {landblock_id for landblock_id in self.records if has_objects(scene, landblock_id)})
        for landblock_id, record in self.records.items():
            if land_defs.blockid_to_lcoord(record.id) is None:  # Landblock(...) throws: fail now, as ACE
                self.build_landblock(landblock_id)
        # server mode: LandblockManager loads the scene's landblocks in the scene's order (their adjacents)
        self.landblock_manager = None
        if portal_dat is not None and portal_dat.server:
            self.landblock_manager = LandblockManager()
            for landblock_id, record in self.records.items():
                # the server Landblock's constructor reads its CellLandblock and LandblockInfo through the cell DAT,
                # which keeps them in its FileCache (a record the scene lacks: an empty one of that type)
                info = None
                if cell_dat is not None:  # (a test's world without DATs reads none)
                    db_obj.get_cell_landblock(cell_dat, landblock_id)
                    info = db_obj.get_landblock_info(cell_dat, (record.id & 0xFFFF0000) | 0xFFFE)
                self.landblock_manager.get_landblock(record.id, lambda: ServerLandblock(record, info, self))
        # a landblock with buildings is built now, before anything is placed, as the oracle's facade builds the scene's
        # landblocks (BuildScene: each constructed in the scene's order, then each PostInit'd): its PostInit places
        # its buildings (init_buildings: BuildingObj.add_to_cell, SortCell.add_building), which is the world's
        # building, not the work of whichever get_landcell first reaches the landblock in the run or in a static's
        # placement (the traces compared with ACE's own would part there for no bug)
        built = [self.construct_landblock(landblock_id) for landblock_id in self.records
                 if landblock_id in self.has_objects and landblock_id not in self.landblocks]
        for landblock in built:
            landblock.post_init(self)

    @harness("a scene landblock built (new Landblock, PostInit) or taken from the pool on first use")
    def build_landblock(self, landblock_id: int) -> Landblock:
        """``new Landblock(CellLandblock)`` then PostInit (pooled unless it has buildings), on first use;
        in server mode it takes the adjacents LandblockManager's SetAdjacents gave it (pSync)."""
        if landblock_id in self.has_objects:
            landblock = self.construct_landblock(landblock_id)
            landblock.post_init(self)
            return landblock
        landblock = POOL.checkout(self.records[landblock_id], self.land_height_table, self.mode)
        self.landblocks[landblock_id] = landblock
        self.take_adjacents(landblock_id, landblock)
        return landblock

    @harness("a scene landblock with buildings constructed (new Landblock, before its PostInit), for this run only")
    def construct_landblock(self, landblock_id: int) -> Landblock:
        """``new Landblock(CellLandblock)`` of a landblock with buildings (it reads its LandblockInfo from the run's
        cell DAT, so it is never pooled), registered before its PostInit as LScape.get_landblock registers it, with
        the adjacents LandblockManager's SetAdjacents gave it in server mode."""
        landblock = Landblock(self.records[landblock_id], self.land_height_table, self.mode, True, self.cell_dat)
        self.landblocks[landblock_id] = landblock
        self.take_adjacents(landblock_id, landblock)
        return landblock

    @harness("a landblock built on first use takes what LandblockManager.SetAdjacents' pSync gave it")
    def take_adjacents(self, landblock_id: int, landblock: Landblock) -> None:
        manager = getattr(self, "landblock_manager", None)  # None while __init__ builds an unplaceable one
        if manager is None:
            return
        server = manager.landblocks.get(((landblock_id >> 24) & 0xFF, (landblock_id >> 16) & 0xFF))
        if server is not None and server.physics_adjacents is not None:
            landblock.set_adjacents(server.physics_adjacents)

    @harness("the run is over: its landblocks go back to the pool")
    def release(self) -> None:
        """The run is over: hand the landblocks back to the pool (this LScape is unusable after)."""
        for landblock_id, landblock in self.landblocks.items():
            if landblock_id in self.has_objects:
                continue  # built for this run only
            POOL.release(LandblockPool.key(self.records[landblock_id], self.land_height_table, self.mode), landblock)
        self.landblocks = {}
        self.landcells = {}
        self.outside_cells = {}
        self.adjust_cells = {}
        self.records = {}
        self.landblock_manager = None

    @anchor("LScape::get_landblock", "LScape.cs:get_landblock")
    def get_landblock(self, block_cell_id: int) -> Landblock:
        landblock_id = block_cell_id | 0xFFFF
        landblock = self.landblocks.get(landblock_id)
        if landblock is None:
            if landblock_id in self.records:
                return self.build_landblock(landblock_id)
            # a landblock the scene does not hold: ACE reads it from its cell DAT, which has no such file, so
            # DBObj.GetCellLandblock gives an empty CellLandblock, and `new Landblock(it)` first runs its base
            # constructor, whose ConstructVertices reads Height[0] of an empty list
            empty = db_obj.get_cell_landblock(self.cell_dat, landblock_id)
            LandblockStruct(empty.id, empty.height, empty.terrain, self.land_height_table, self.mode)
            raise AssertionError("a LandblockStruct of an empty CellLandblock was built")
        return landblock

    def _get_landcell_every_time(self, block_cell_id: int):
        """get_landcell as ACE writes it, nothing remembered (what a traced run runs)."""
        return self._get_landcell(block_cell_id)

    @anchor("LScape::get_landcell", "LScape.cs:get_landcell")
    @remembers(_get_landcell_every_time)
    def get_landcell(self, block_cell_id: int):
        """The cell with that id (a LandCell, or an EnvCell built on first use). Unlike Landblock.get_landcell, ACE does not check the
        slot's id here; the slot comes from gid_to_lcoord without the env check.

        The answer for an id never changes during a run (a built landblock's cells are fixed),
        so it is remembered per run: the transition asks for the same few cells thousands of
        times. A failing lookup (a landblock not in the scene) raises every time. A traced run
        looks it up every time (anchors.remembers), so its trace holds get_landblock's calls."""
        cell = self.landcells.get(block_cell_id, _UNSEEN)
        if cell is not _UNSEEN:
            return cell
        cell = self.landcells[block_cell_id] = self._get_landcell(block_cell_id)
        return cell

    def _get_landcell(self, block_cell_id: int):
        """LScape.get_landcell as ACE writes it (get_landcell remembers its answers)."""
        landblock = self.get_landblock(block_cell_id)
        cell_id = block_cell_id & 0xFFFF
        if cell_id < 0x100:
            lcoord = land_defs.gid_to_lcoord(block_cell_id, False)
            if lcoord is None:
                return None
            land_cell_idx = (int(lcoord[1]) % 8) + (int(lcoord[0]) % 8) * landblock.side_cell_count
            return landblock.land_cells.get(land_cell_idx)
        # indoor cells
        if cell_id in landblock.land_cells:
            return landblock.land_cells[cell_id]

        cell = db_obj.get_env_cell(self.cell_dat, self.portal_dat, block_cell_id)
        landblock.land_cells.setdefault(cell_id, cell)  # TryAdd
        env_cell = cell
        env_cell.post_init(self)
        return cell
