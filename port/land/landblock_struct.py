"""LandblockStruct: Generate, InitPVArrays, ConstructVertices, TransAdjust, AdjustPlanes, ConstructPolygons, AddPolygon, FSplitNESW, CalcWater, CalcCellWater, calc_water_depth.

ACE's Common/LandblockStruct.cs as the server builds it (PhysicsEngine.Instance.Server):
ConstructUVs, GetCellRotation, GetPalCode and the UV/palette tables are the client's texture code
and are not ported (Generate skips ConstructUVs on the server). FinalizePVArrays only swaps in
cached vertices/polygons when VertexCache/PolygonCache are Enabled, which ACE leaves false: not
ported. Init's 64 throwaway LandCells (replaced by InitPVArrays before anyone sees them) are
not built either.

The 64 LandCells are made unbuilt (land_cell.unbuilt_land_cell): what InitPVArrays,
ConstructPolygons and CalcWater do to a cell (its constructor, its two polygons, id, frame and
water type) runs when the cell is first read, in that order; the landblock's own fields (vertices,
water type) are built at once.

The land height table is ACE's static LandDefs.LandHeightTable; here it comes with the
constructor (the scene carries it), converted to the run's scalar type.
"""

from __future__ import annotations

from acconform.flags import CullMode
from acconform.numerics import Mode, Vector3, cs_fmod, wrap_i32, wrap_u32

from ..constants import WATER_DEPTH_PARTIAL_WATER, WATER_DEPTH_DRY
from ..errors import ArgumentOutOfRangeException
from acconform.port.anchors import anchor, harness
from acconform.port.geom.polygon import Polygon, Vertex
from acconform.port import land_defs
from acconform.port.cell.land_cell import LandCell, assign_when_built, unbuilt_land_cell, when_built
from acconform.port.land_defs import Direction, WaterType

# SurfChar: 1 for the five water terrain types (0x10..0x14), indexed by (terrain >> 2) & 0x1F
SURF_CHAR = (0,) * 16 + (1,) * 5 + (0,) * 11

# ConstructPolygons' split test: `splitDir * 2.3283064e-10 < 0.5f`, a uint times a double literal,
# compared in double. The literal is a little below 2^-32, so the first branch also takes
# splitDir from 2^31 to 2^31 + 33 (pinned in tests/port/land/test_landblock_struct.py).
SPLIT_SCALE = 2.3283064e-10


@anchor(None, "LandblockStruct.cs:ConstructPolygons", note="the split test `splitDir * 2.3283064e-10 < 0.5f`")
def split_cuts_se_to_nw(split_dir: int) -> bool:
    """ConstructPolygons' branch test, named so its boundary can be tested: no land cell's hash
    comes within 440 of 2^31 (the nearest is cell (657, 1857) at 2^31 + 440), so the double
    rounding that lets 2^31..2^31+33 through is invisible in the world, but pinned anyway."""
    return split_dir * SPLIT_SCALE < 0.5  # uint * double literal, compared in double


_HEIGHT_TABLES: dict = {}  # (table, mode) -> the table in the mode's scalar type


@harness("the land height table in the run's scalar type, converted once per table and mode")
def height_table_in_mode(table: tuple, mode: Mode) -> tuple:
    converted = _HEIGHT_TABLES.get((table, mode))
    if converted is None:
        if len(_HEIGHT_TABLES) >= 64:
            _HEIGHT_TABLES.clear()
        converted = _HEIGHT_TABLES[(table, mode)] = tuple(mode.scalar(h) for h in table)
    return converted


class LandblockStruct:
    """The terrain mesh of one landblock: 81 vertices, 128 triangles, 64 LandCells."""

    def __init__(self, landblock_id: int, height, terrain, land_height_table, mode: Mode, lazy: bool = False):
        """``LandblockStruct(CellLandblock)``: Init, take Height and Terrain, Generate(id, 1, Unknown).

        Note that ACE's `ID` is still 0 here (the Landblock subclass sets it after this
        constructor), so InitPVArrays names the cells 0..63 until ConstructPolygons renames them.

        `lazy` (a landblock without terrain: an indoor scene's) defers Init and Generate until a
        terrain field is first read (`__getattr__`); until then `land_cells` holds only the
        EnvCells the run loads. Building is deterministic and reads nothing but the constructor's
        inputs, so building later gives the same terrain: no outcome can tell (pinned in
        tests/port/land/test_landblock_struct.py).
        """
        self.mode = mode
        self.land_height_table = height_table_in_mode(tuple(land_height_table), mode)
        self.id = 0
        self.height = tuple(height)
        self.terrain = tuple(terrain)
        if lazy:
            self.land_cells: dict = {}
            self._deferred = landblock_id
            return
        self.init()
        # originally called from LScape.update_block()
        self.generate(landblock_id, 1, Direction.Unknown)

    def __getattr__(self, name: str):
        """A terrain field of a lazy landblock, read for the first time: build the terrain now, as the
        constructor would have (ID 0 while generating), its cells going into `land_cells` ahead of
        the EnvCells already there (ACE adds its EnvCells after the terrain's cells)."""
        landblock_id = self.__dict__.pop("_deferred", None)
        if landblock_id is None:
            raise AttributeError(f"{type(self).__name__!r} object has no attribute {name!r}")
        cells, landblock_id_now = self.land_cells, self.id
        self.id = 0
        self.init()
        self.generate(landblock_id, 1, Direction.Unknown)
        self.id = landblock_id_now
        terrain, indoor = self.land_cells, dict(cells)
        cells.clear()
        cells.update(terrain)
        cells.update(indoor)
        self.land_cells = cells
        self.terrain_generated(terrain)
        return getattr(self, name)

    @harness("a lazy landblock's terrain was just built (Landblock: what PostInit did to the cells)")
    def terrain_generated(self, cells: dict) -> None:
        pass

    @harness("whether the terrain is built (a lazy landblock's is built when first read)")
    def terrain_built(self) -> bool:
        return "_deferred" not in self.__dict__

    @anchor(None, "LandblockStruct.cs:Init")
    def init(self) -> None:
        self.trans_dir = Direction.Unknown
        self.water_type = WaterType.NotWater
        self.side_vertex_count = 0
        self.side_poly_count = 0
        self.side_cell_count = 0
        self.vertex_array: list[Vertex] = []
        self.polygons: list[Polygon] = []
        self.sw_to_ne_cut: list[bool] = []
        self.land_cells: dict[int, LandCell] = {}

    @anchor("CLandBlockStruct::AddPolygon", "LandblockStruct.cs:AddPolygon")
    def add_polygon(self, poly_idx: int, _v0: int, _v1: int, _v2: int) -> Polygon:
        """The polygon is InitPVArrays' ``new Polygon(idx, 3, CullMode.Landblock)``, made here: each
        index is added once, by ConstructPolygons right after InitPVArrays (a scene never regenerates),
        and only when its cell is first read."""
        polygon = self.polygons[poly_idx] = Polygon(poly_idx, 3, CullMode.Landblock)
        v0, v1, v2 = _v0, _v1, _v2  # (short) casts: indices below 81

        polygon.vertices[0] = self.vertex_array[v0]
        polygon.vertices[1] = self.vertex_array[v1]
        polygon.vertices[2] = self.vertex_array[v2]

        polygon.vertex_ids[0] = v0
        polygon.vertex_ids[1] = v1
        polygon.vertex_ids[2] = v2

        polygon.make_plane_when_read()  # make_plane(), run when the plane is first read: the vertices are final

        polygon.pos_surface = 0
        if polygon.vertices[0].origin.z != 0 or polygon.vertices[1].origin.z != 0 or polygon.vertices[2].origin.z != 0:
            polygon.pos_surface = 1
        return polygon

    @anchor("CLandBlockStruct::AdjustPlanes", "LandblockStruct.cs:AdjustPlanes")
    def adjust_planes(self) -> None:
        for x in range(self.side_poly_count):
            for y in range(self.side_poly_count):
                for poly_idx in range(2):
                    self.polygons[(x * self.side_poly_count + y) * 2 + poly_idx].make_plane()

    @anchor("CLandBlockStruct::calc_cell_water", "LandblockStruct.cs:CalcCellWater")
    def calc_cell_water(self, x: int, y: int) -> tuple[bool, bool]:
        """CalcCellWater(x, y, out cellHasWater, out cellFullyFlooded): returns both."""
        cell_has_water = False
        cell_fully_flooded = True
        vpc = land_defs.VERTEX_PER_CELL
        for vx in range(x * vpc, vpc * (x + 1) + 1):
            for vy in range(y * vpc, vpc * (y + 1) + 1):
                terrain_idx = vx * self.side_vertex_count + vy
                if SURF_CHAR[self.terrain[terrain_idx] >> 2 & 0x1F] == 1:
                    cell_has_water = True
                else:
                    cell_fully_flooded = False
        return cell_has_water, cell_fully_flooded

    @anchor("CLandBlockStruct::calc_water", "LandblockStruct.cs:CalcWater")
    def calc_water(self) -> None:
        has_water = False
        waterblock = True
        if self.side_cell_count == land_defs.BLOCK_SIDE:
            for x in range(self.side_cell_count):
                for y in range(self.side_cell_count):
                    cell_has_water, cell_fully_flooded = self.calc_cell_water(x, y)
                    cell = self.land_cells[x * self.side_cell_count + y]  # its field set when it is built
                    if cell_has_water:
                        has_water = True
                        if cell_fully_flooded:
                            assign_when_built(cell, "water_type", WaterType.EntirelyWater)
                        else:
                            assign_when_built(cell, "water_type", WaterType.PartiallyWater)
                            waterblock = False
                    else:
                        assign_when_built(cell, "water_type", WaterType.NotWater)
                        waterblock = False
        if has_water:
            self.water_type = WaterType.EntirelyWater if waterblock else WaterType.PartiallyWater
        else:
            self.water_type = WaterType.NotWater

    @anchor("CLandBlockStruct::ConstructPolygons", "LandblockStruct.cs:ConstructPolygons")
    def construct_polygons(self, landblock_id: int) -> None:
        lcoord = land_defs.value_of(land_defs.blockid_to_lcoord(landblock_id), "LandblockStruct.ConstructPolygons")
        lx, ly = int(lcoord[0]), int(lcoord[1])
        vpc = land_defs.VERTEX_PER_CELL

        poly_num = 1
        # (uint)((int)lcoord.X * VertexPerCell * 214614067): int overflow, then reinterpreted
        seed_a = wrap_u32(wrap_i32(lx * vpc * 214614067))
        seed_b = wrap_u32(wrap_i32(lx * vpc * 1109124029))
        vertex_cnt = 0

        for x in range(self.side_cell_count):
            lcoord_x = lcoord[0] + x
            origin_y = 1
            col_vertex_cnt = 0
            origin_x = poly_num

            for y in range(self.side_cell_count):
                # the cell's polygons, id and frame: built when the cell is first read (land_cell.unbuilt_land_cell)
                when_built(self.land_cells[x * self.side_cell_count + y], self, "construct_cell_polygons",
                           x, y, lcoord_x, ly, seed_a, seed_b, vertex_cnt, col_vertex_cnt, origin_x, origin_y)

                origin_y += 2
                col_vertex_cnt += vpc
            vertex_cnt += vpc
            seed_b = wrap_u32(seed_b + 1109124029 * vpc)
            seed_a = wrap_u32(seed_a + 214614067 * vpc)
            poly_num += 2

    @harness("ConstructPolygons' work on one cell (the body of its loop over y), run when the cell is first read")
    def construct_cell_polygons(self, x: int, y: int, lcoord_x, ly: int, seed_a: int, seed_b: int,
                                vertex_cnt: int, col_vertex_cnt: int, origin_x: int, origin_y: int) -> None:
        """ACE's lines, with the loop's counters as construct_polygons had them for this cell. Its
        SWtoNEcut entry is set here too, so only a built cell's is (nothing in ACE's physics reads them)."""
        vpc = land_defs.VERTEX_PER_CELL
        lcoord_y = ly + y
        magic_b = seed_b
        magic_a = wrap_u32(seed_a + 1813693831)

        for i in range(vpc):
            idx_i = vertex_cnt + i
            idx_j = col_vertex_cnt

            for j in range(vpc):
                # int * uint is long arithmetic in C#; the (uint) cast keeps the low 32 bits
                split_dir = wrap_u32((ly * vpc + idx_j) * magic_a - magic_b - 1369149221)
                poly_idx = (vpc * i + j) * 2

                cell_idx = x * self.side_cell_count + y
                vert_idx = idx_i * self.side_vertex_count + idx_j
                first_vertex = (idx_i * self.side_poly_count + idx_j) * 2
                next_vert_idx = (idx_i + 1) * self.side_vertex_count + idx_j

                lcell = self.land_cells[cell_idx]

                if split_cuts_se_to_nw(split_dir):
                    #  2    1---0
                    #  | \   \  |
                    #  |  \   \ |
                    #  0---1    2
                    self.sw_to_ne_cut[cell_idx] = False
                    lcell.polygons[poly_idx] = self.add_polygon(first_vertex, vert_idx, next_vert_idx, vert_idx + 1)
                    lcell.polygons[poly_idx + 1] = self.add_polygon(
                        first_vertex + 1, next_vert_idx + 1, vert_idx + 1, next_vert_idx
                    )
                else:
                    #     2   2---1
                    #    / |  |  /
                    #   /  |  | /
                    #  0---1  0
                    self.sw_to_ne_cut[cell_idx] = True
                    lcell.polygons[poly_idx] = self.add_polygon(first_vertex, vert_idx, next_vert_idx, next_vert_idx + 1)
                    lcell.polygons[poly_idx + 1] = self.add_polygon(first_vertex + 1, vert_idx, next_vert_idx + 1, vert_idx + 1)
                idx_j += 1
            magic_a = wrap_u32(magic_a + 214614067)
            magic_b = wrap_u32(magic_b + 1109124029)

        cell_id = wrap_u32(land_defs.lcoord_to_gid(lcoord_x, lcoord_y, self.mode.runtime))
        land_cell = self.land_cells[x * self.side_cell_count + y]
        land_cell.id = cell_id
        land_cell.pos.obj_cell_id = cell_id
        s = self.mode.scalar
        origin = land_cell.pos.frame.origin
        origin = origin.with_x(s(origin_x * land_defs.HALF_SQUARE_LENGTH))
        origin = origin.with_y(s(origin_y * land_defs.HALF_SQUARE_LENGTH))
        land_cell.pos.frame.origin = origin

    @anchor("CLandBlockStruct::ConstructVertices", "LandblockStruct.cs:ConstructVertices")
    def construct_vertices(self) -> None:
        cell_scale = land_defs.BLOCK_SIDE // self.side_cell_count
        cell_size = land_defs.BLOCK_LENGTH // self.side_poly_count
        s = self.mode.scalar
        for x in range(self.side_vertex_count):
            cell_x = x * cell_size
            for y in range(self.side_vertex_count):
                cell_y = y * cell_size
                vertex_idx = x * self.side_vertex_count + y
                vertex = self.vertex_array[vertex_idx]
                if vertex_idx >= len(self.height):  # List<byte> Height's indexer
                    raise ArgumentOutOfRangeException(f"Height[{vertex_idx}] of {len(self.height)} heights")
                z_height = self.land_height_table[self.height[vertex_idx]]
                vertex.origin = Vector3(s(cell_x), s(cell_y), z_height * cell_scale)

    @anchor("CLandBlockStruct::FSplitNESW", "LandblockStruct.cs:FSplitNESW", note="not called by ACE's physics")
    def f_split_nesw(self, x: int, y: int) -> bool:
        """``x*y*0xCCAC033 - x*0x421BE3BD`` wraps as int; ``(y*0x6C1AC587 - 0x519B8F25) / 2147483648``
        is int / uint, i.e. long division (truncating): -1 only for int.MinValue, else 0."""
        a = wrap_i32(x * y * 0xCCAC033 - x * 0x421BE3BD)
        b = wrap_i32(y * 0x6C1AC587 - 0x519B8F25)
        q = -1 if b == -2147483648 else 0
        split = a + q
        return split % 2 != 0

    @anchor("CLandBlockStruct::Generate", "LandblockStruct.cs:Generate")
    def generate(self, landblock_id: int, cell_scale: int, trans_adj: Direction) -> bool:
        cell_width = land_defs.BLOCK_SIDE // cell_scale

        if cell_width == self.side_cell_count and self.trans_dir == trans_adj:
            return False

        cell_regen = False
        if cell_width != self.side_cell_count:
            cell_regen = True
            # (ACE calls Destroy() first when SideCellCount > 0; a scene never regenerates.)
            self.side_cell_count = cell_width
            self.side_vertex_count = self.side_cell_count * land_defs.VERTEX_PER_CELL + 1
            self.side_poly_count = self.side_cell_count * land_defs.VERTEX_PER_CELL
            self.init_pv_arrays()

        self.trans_dir = trans_adj
        self.construct_vertices()

        if self.trans_dir != Direction.Inside and 1 < self.side_cell_count < land_defs.BLOCK_SIDE:
            raise NotImplementedError("LandblockStruct.TransAdjust: only reached for cellScale > 1 (client LOD)")

        if not cell_regen:
            self.adjust_planes()
        else:
            self.construct_polygons(landblock_id)
            # ConstructUVs(landblockID) runs only when !PhysicsEngine.Instance.Server (client textures)

        self.calc_water()
        # FinalizePVArrays: a no-op while VertexCache/PolygonCache are disabled (ACE's default)
        return cell_regen

    @anchor("CLandBlockStruct::InitPVArrays", "LandblockStruct.cs:InitPVArrays")
    def init_pv_arrays(self) -> None:
        num_squares = self.side_poly_count * self.side_poly_count
        num_verts = self.side_vertex_count * self.side_vertex_count
        num_cells = self.side_cell_count * self.side_cell_count

        self.vertex_array = [Vertex(index=i) for i in range(num_verts)]
        self.polygons = [None] * (num_squares * 2)  # each new Polygon(...) made by add_polygon, with its cell
        self.sw_to_ne_cut = [False] * num_squares
        # new LandCell(...), built when first read (most of a landblock's cells never are)
        self.land_cells = {i: unbuilt_land_cell(wrap_u32((self.id & land_defs.BLOCK_MASK) + i), self.mode)
                           for i in range(num_cells)}

    @anchor("CLandBlockStruct::calc_water_depth", "LandblockStruct.cs:calc_water_depth")
    def calc_water_depth(self, block_cell_id: int, point: Vector3):
        """0.44999999f where the terrain corner nearest `point` is water, else 0.1f.

        ``point.X % 24.0f`` is C#'s float remainder (sign of the dividend), so a negative x
        never reaches 12 and picks the west corner.
        """
        cell_id = (wrap_i32(block_cell_id) & 0xFFFF) - 1
        cell_x = int(cell_id / 8)  # C# int division truncates
        cell_y = cell_id - cell_x * 8  # C# % keeps the dividend's sign
        terrain_idx = cell_x * land_defs.VERTEX_DIM + cell_y
        if cs_fmod(point.x, 24.0) >= 12.0:
            terrain_idx += 9
        if cs_fmod(point.y, 24.0) >= 12.0:
            terrain_idx += 1
        if not 0 <= terrain_idx < len(self.terrain):
            raise IndexError(f"Terrain[{terrain_idx}]: index out of range (ArgumentOutOfRangeException in ACE)")
        terrain = self.terrain[terrain_idx]
        surf_char_idx = terrain >> 2 & 0x1F
        has_water = SURF_CHAR[surf_char_idx]
        s = type(point.x)
        return s(WATER_DEPTH_PARTIAL_WATER) if has_water != 0 else s(WATER_DEPTH_DRY)
