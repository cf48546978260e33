"""LandCell: find_terrain_poly, point_in_cell, FindCollisions, FindEnvCollisions, find_transit_cells (the sphere and parts overloads), handle_move_restriction, add_all_outside_cells (the sphere and parts overloads), add_outside_cell, check_add_cell_boundary, add_cell_block.

ACE's Common/LandCell.cs. LandCell derives from SortCell (sort_cell.py) -> ObjCell (obj_cell.py),
as in ACE (PartCell, which holds nothing the physics reads, is left out). FindEnvCollisions tests sphere 0 only (its low point
picks the triangle) against the terrain. The static helpers take the run's LScape as their first
argument where ACE reaches the static LScape. add_all_outside_cells(numParts, parts, ...) (the
static-object overload, a static's placement) reads the parts' bounding boxes (port/bbox.py).
"""

from __future__ import annotations

from acconform.flags import ObjectInfoState, PhysicsState, TransitionState
from acconform.numerics import Mode, Vector3, cast_float, cs_floor, wrap_u32
from acconform.port.anchors import anchor, harness, remembers
from acconform.port.bbox import BBox
from acconform.port.frame import Position
from acconform.port.geom.polygon import Polygon
from acconform.port.vec import Sidedness
from acconform.port.geom.sphere import Sphere
from acconform.port import land_defs
from acconform.port.land_defs import WaterType
from acconform.port.cell.sort_cell import SortCell


TERRAIN_POLYS_LIMIT = 256  # remembered points per cell before the cell forgets them all


class LandCell(SortCell):
    """One 24 m outdoor cell: two terrain triangles over the ObjCell state the physics reads."""

    # `_steps`: the construction an unbuilt cell still owes (see unbuilt_land_cell); unset once built
    __slots__ = ("polygons", "in_view", "terrain_polys", "_steps")

    @anchor("CLandCell::CLandCell", "LandCell.cs:LandCell(uint)")
    def __init__(self, cell_id: int, mode: Mode):
        super().__init__(cell_id, mode)
        # LandCell.Init: always 2 polygons
        self.polygons: list[Polygon | None] = [None, None]
        self.in_view = False
        self.terrain_polys: dict = {}  # find_terrain_poly's answers (the port's, not ACE's: see there)

    @harness("a pooled LandCell back to what its constructor left (its terrain kept)")
    def reset_for_pool(self) -> None:
        """What a run may change in a built cell is its ObjCell/SortCell state (objects and
        shadow objects registered in it) and the port's terrain-poly memory; the terrain, id,
        frame and water type are fixed after construction."""
        self.init_obj_cell_state()
        self.building = None
        self.in_view = False
        self.terrain_polys = {}

    def __repr__(self) -> str:
        return f"LandCell(0x{self.id:08X}, water={self.water_type.name})"

    def _terrain_poly(self, origin: Vector3) -> int:
        """find_terrain_poly's loop: the index of the first triangle holding origin's (x, y), else -1."""
        for i in range(2):
            if self.polygons[i].point_in_poly2D(origin, Sidedness.Positive):
                return i
        return -1

    def _find_terrain_poly_every_time(self, origin: Vector3, walkable: Polygon | None = None) -> tuple[bool, Polygon | None]:
        """find_terrain_poly, nothing remembered (what a traced run runs)."""
        i = self._terrain_poly(origin)
        return (True, self.polygons[i]) if i >= 0 else (False, walkable)

    @anchor("CLandCell::find_terrain_poly", "LandCell.cs:find_terrain_poly")
    @remembers(_find_terrain_poly_every_time)
    def find_terrain_poly(self, origin: Vector3, walkable: Polygon | None = None) -> tuple[bool, Polygon | None]:
        """find_terrain_poly(origin, ref walkable): returns (found, walkable).

        walkable is left as given when neither triangle holds the point (2D test, edges inside).

        The answer depends only on the cell's two triangles, fixed once the landblock is built,
        and on origin's x and y, so the cell remembers it for the run (about 70% of calls in a
        transition repeat an earlier point; the pool empties it at checkout, which bounds it). Keys are values:
        -0 and +0 meet, which is safe because a zero coordinate only ever adds or subtracts a zero
        product in point_in_poly2D's cross term, which is then compared with 0; a NaN never
        meets itself (unless it is the same object, whose answer is the same). A traced run
        computes it every time (anchors.remembers), so its trace holds point_in_poly2D's calls.
        """
        key = (origin.x, origin.y)
        i = self.terrain_polys.get(key)
        if i is None:
            i = self._terrain_poly(origin)
            if len(self.terrain_polys) >= TERRAIN_POLYS_LIMIT:
                self.terrain_polys.clear()
            self.terrain_polys[key] = i
        if i >= 0:
            return True, self.polygons[i]
        return False, walkable

    @anchor("CLandCell::point_in_cell", "LandCell.cs:point_in_cell")
    def point_in_cell(self, point: Vector3) -> bool:
        found, _ = self.find_terrain_poly(point, None)
        return found

    @anchor("CLandCell::find_collisions", "LandCell.cs:FindCollisions")
    def find_collisions(self, transition) -> TransitionState:
        transit_state = self.find_env_collisions(transition)
        if transit_state == TransitionState.OK:
            transit_state = SortCell.find_collisions(self, transition)  # base.FindCollisions
            if transit_state == TransitionState.OK:
                transit_state = self.find_obj_collisions(transition)
        return transit_state


    @anchor("CLandCell::find_env_collisions", "LandCell.cs:FindEnvCollisions")
    def find_env_collisions(self, transition) -> TransitionState:
        transit_state = self.check_entry_restrictions(transition)
        if transit_state != TransitionState.OK:
            return transit_state

        path = transition.sphere_path
        block_offset = land_defs.get_block_offset(path.check_pos.obj_cell_id, self.id)
        local_point = transition.sphere_path.global_low_point - block_offset

        found, walkable = self.find_terrain_poly(local_point, None)
        if not found:
            return transit_state

        obj_info = transition.object_info
        if (self.get_block_water_type() == WaterType.EntirelyWater
                and not obj_info.state & ObjectInfoState.IsViewer and not obj_info.object.state & PhysicsState.Missile):
            if transition.trace is not None:
                transition.trace["land_cell:entirely_water_block"] += 1
            return TransitionState.Collided

        water_depth = self.get_water_depth(local_point)

        check_pos = Sphere(path.global_sphere[0].center, path.global_sphere[0].radius)
        check_pos.center = check_pos.center - land_defs.get_block_offset(path.check_pos.obj_cell_id, self.id)

        return obj_info.validate_walkable(check_pos, walkable.plane, self.water_type != WaterType.NotWater,
                                          water_depth, transition, self.id)


    @anchor("CLandCell::find_transit_cells", "LandCell.cs:find_transit_cells")
    def find_transit_cells(self, lscape, position, num_sphere, spheres, cell_array, path) -> None:
        """The run's world `lscape` comes first, standing in for ACE's static LScape."""
        add_all_outside_cells_replayed(lscape, position, num_sphere, spheres, cell_array)
        SortCell.find_transit_cells(self, lscape, position, num_sphere, spheres, cell_array, path)


    @anchor("CLandCell::find_transit_cells", "LandCell.cs:find_transit_cells(int, List<PhysicsPart>, CellArray)",
            "the parts overload (a static's placement)")
    def find_transit_cells_parts(self, lscape, num_parts: int, parts, cell_array) -> None:
        """The run's world `lscape` comes first, standing in for ACE's static LScape."""
        add_all_outside_cells_parts(lscape, num_parts, parts, cell_array, self.id)
        SortCell.find_transit_cells_parts(self, lscape, num_parts, parts, cell_array)

    @anchor("CLandCell::handle_move_restriction", "LandCell.cs:handle_move_restriction")
    def handle_move_restriction(self, transition) -> bool:
        offset = self.pos.get_offset(transition.sphere_path.cur_pos)
        s = type(offset.x)
        half = land_defs.HALF_SQUARE_LENGTH
        if offset.y >= -half:
            if offset.y <= half:
                offset = offset.with_y(s(0.0))
                offset = offset.with_x(s(-1.0) if offset.x < -half else s(1.0))
            else:
                offset = Vector3(s(0.0), s(1.0), offset.z)
        else:
            offset = Vector3(s(0.0), s(-1.0), offset.z)
        normal = Vector3(offset.x, offset.y, s(0.0))
        transition.collision_info.set_collision_normal(normal)
        return True


# ---------------------------------------------------------------- cells built when first read


class _UnbuiltLandCell(LandCell):
    """A LandCell its landblock has made but not yet built: the first read or write of any of its
    fields or methods builds it (`_build`), and it is a plain LandCell from then on (its class is
    swapped; the layout is LandCell's). Equality, hashing and dictionary keys go by identity, so a
    cell held unbuilt in a CellArray or a memory is the same cell once built."""

    __slots__ = ()

    def __getattribute__(self, name: str):
        _build(self)
        return object.__getattribute__(self, name)

    def __setattr__(self, name: str, value) -> None:
        _build(self)
        object.__setattr__(self, name, value)


_STEPS = LandCell._steps  # the slot's descriptor: reads and writes it without the unbuilt class's hooks


def _build(cell: LandCell) -> None:
    """Runs the steps an unbuilt cell owes, in the order its landblock's construction made them."""
    steps = _STEPS.__get__(cell)
    object.__setattr__(cell, "__class__", LandCell)
    del cell._steps
    for owner, name, args in steps:
        if owner is None:
            setattr(cell, name, args)  # a field assignment
        else:
            getattr(owner if owner is not _SELF else cell, name)(*args)  # looked up now: tracing may wrap it


_SELF = object()  # a step's owner: the cell itself


@harness("a LandCell whose construction (the constructor, then what its landblock does to it) runs when it is first read")
def unbuilt_land_cell(cell_id: int, mode: Mode) -> LandCell:
    """``new LandCell(cellID)``, run when the cell is first read, with every step `when_built` or
    `assign_when_built` adds after it. A landblock makes 64 cells and a transition reads a few: the
    rest are never built. Every step reads only what its landblock fixed at construction (its
    vertices, polygons and ids), so building later builds the same cell (pinned in
    tests/port/land/test_landblock_struct.py)."""
    cell = _UnbuiltLandCell.__new__(_UnbuiltLandCell)
    _STEPS.__set__(cell, [(_SELF, "__init__", (cell_id, mode))])
    return cell


@harness("whether a LandCell is built (an unbuilt one builds when first read)")
def is_built(cell) -> bool:
    return type(cell) is not _UnbuiltLandCell


@harness("owner.name(*args) on a LandCell's behalf: now if the cell is built, else when it is built")
def when_built(cell: LandCell, owner, name: str, *args) -> None:
    if type(cell) is _UnbuiltLandCell:
        _STEPS.__get__(cell).append((owner, name, args))
    else:
        getattr(owner, name)(*args)


@harness("cell.field = value: now if the cell is built, else when it is built")
def assign_when_built(cell: LandCell, field: str, value) -> None:
    if type(cell) is _UnbuiltLandCell:
        _STEPS.__get__(cell).append((None, field, value))
    else:
        setattr(cell, field, value)


# ---------------------------------------------------------------- static helpers


class _AddedCells:
    """Stands in for the CellArray while add_all_outside_cells runs: records its add_cell calls."""

    __slots__ = ("added_outside", "adds")

    def __init__(self):
        self.added_outside = False
        self.adds: list = []

    @harness("records an add_cell call for add_all_outside_cells_replayed")
    def add_cell(self, cell_id: int, cell) -> None:
        self.adds.append((cell_id, cell))


def _add_all_outside_cells_every_time(lscape, position: Position, num_sphere: int, spheres, cell_array) -> None:
    """add_all_outside_cells called as ACE calls it, nothing remembered (what a traced run runs); through
    the module's name, so a traced run's wrapper writes its records."""
    add_all_outside_cells(lscape, position, num_sphere, spheres, cell_array)


@harness("add_all_outside_cells with its add_cell calls remembered per run and replayed")
@remembers(_add_all_outside_cells_every_time)
def add_all_outside_cells_replayed(lscape, position: Position, num_sphere: int, spheres, cell_array) -> None:
    """add_all_outside_cells, answered from the run's memory when it has seen the same inputs.

    With spheres, ACE's routine is a function of the position's cell id and each sphere's x, y
    and radius (and of the world, fixed during a run): it only calls add_cell, on cells looked
    up by id. find_cell_list calls it once and then once more per cell found (every
    find_transit_cells repeats it, AddedOutside never being set), so ~90% of calls repeat an
    earlier one. Replaying the same add_cell calls in the same order leaves the CellArray (and
    its .NET entry order) exactly as running it again would. Keys hold the coordinates' values:
    -0 and +0 meet as equal, which is safe because AdjustToOutside snaps |x|, |y| < EPSILON to
    +0 first; a NaN never matches, so it always runs. With no spheres the routine moves
    `position` itself, so that form always runs; so does a call that throws (its adds are
    applied, then the exception goes on, as if it had run in place).
    Replayed into a CellArray that already holds the same call's cells (the array remembers the
    last key it replayed until a cell is removed), it adds nothing, so it is skipped. A traced run
    calls add_all_outside_cells every time (anchors.remembers), so its trace holds each call's records.
    """
    if cell_array.added_outside:
        return
    if num_sphere == 0:
        add_all_outside_cells(lscape, position, num_sphere, spheres, cell_array)
        return
    key = (position.obj_cell_id, tuple([(s.center.x, s.center.y, s.radius) for s in spheres]))
    if cell_array.replayed == key:
        return
    adds = lscape.outside_cells.get(key)
    if adds is None:
        recorder = _AddedCells()
        try:
            add_all_outside_cells(lscape, position, num_sphere, spheres, recorder)
        except BaseException:
            for cell_id, cell in recorder.adds:
                cell_array.add_cell(cell_id, cell)
            raise
        adds = lscape.outside_cells[key] = recorder.adds
    for cell_id, cell in adds:
        cell_array.add_cell(cell_id, cell)
    cell_array.replayed = key


@anchor("CLandCell::add_all_outside_cells", "LandCell.cs:add_all_outside_cells(Position, int, List<Sphere>, CellArray)")
def add_all_outside_cells(lscape, position: Position, num_sphere: int, spheres, cell_array) -> None:
    """Add the outdoor cells the spheres touch. With no spheres, `position` itself is moved
    to the outside (AdjustToOutside(position) mutates it, as in ACE).

    Note ACE loops over every sphere in the list (not num_sphere of them), stops at the
    first one AdjustToOutside rejects, and never sets cell_array.added_outside here.
    """
    if cell_array.added_outside:
        return

    if num_sphere != 0:
        for sphere in spheres:
            ok, cell_point, center = land_defs.adjust_to_outside(position.obj_cell_id, sphere.center, lscape.mode.runtime)
            if not ok:
                break

            point_x = center.x - cast_float(center.x, cs_floor(center.x / 24.0)) * 24.0
            point_y = center.y - cast_float(center.y, cs_floor(center.y / 24.0)) * 24.0
            min_rad = sphere.radius
            max_rad = 24.0 - min_rad

            lcoord = land_defs.gid_to_lcoord(cell_point)
            if lcoord is not None:
                add_outside_cell_lcoord(lscape, cell_array, lcoord)
                check_add_cell_boundary(lscape, cell_array, (point_x, point_y), lcoord, min_rad, max_rad)
    else:
        if not land_defs.adjust_to_outside_pos(position):
            return
        lcoord = land_defs.gid_to_lcoord(position.obj_cell_id)
        if lcoord is not None:
            add_outside_cell_lcoord(lscape, cell_array, lcoord)


@anchor("CLandCell::add_all_outside_cells", "LandCell.cs:add_all_outside_cells(int, List<PhysicsPart>, CellArray, uint)",
        "the parts overload (a static's placement)")
def add_all_outside_cells_parts(lscape, num_parts: int, parts, cell_array, id: int) -> None:
    """The cells of `id`'s landblock that the parts' bounding boxes reach (add_cell_block).

    Each part's box (GfxObj.Init, over its vertices; Scale is not applied) is carried into the
    placing part's cell landblock by BBox.LocalToGlobal, and the block of cells from the lowest
    to the highest box corner (relative to the part's own cell, always including it) is added.
    Sets AddedOutside, so only the first cell of find_bbox_cell_list's walk adds anything.
    """
    if cell_array.added_outside:
        return

    cell_array.added_outside = True

    if num_parts == 0:
        return

    runtime = lscape.mode.runtime
    min_x = 0
    min_y = 0
    max_x = 0
    max_y = 0

    for i in range(num_parts):
        cur_part = parts[i]

        loc = cur_part.pos.copy()  # new Position(curPart.Pos)

        if not land_defs.adjust_to_outside_pos(loc):
            continue

        _lcoord = land_defs.gid_to_lcoord(loc.obj_cell_id)

        if _lcoord is None:
            continue

        lcoord = _lcoord

        lx = ((loc.obj_cell_id & 0xFFFF) - 1) // 8  # uint arithmetic: low word >= 1 here
        ly = ((loc.obj_cell_id & 0xFFFF) - 1) % 8

        for j in range(num_parts):
            other_part = parts[j]

            if other_part is None:
                continue

            # add if missing: otherPart.Always2D, checks degrades.degradeMode != 1 (ACE)

            bbox = BBox()
            bbox.local_to_global(other_part.get_bounding_box(), other_part.pos, loc)

            min_cx = runtime.to_int32(cs_floor(bbox.min.x / 24.0))
            min_cy = runtime.to_int32(cs_floor(bbox.min.y / 24.0))

            max_cx = runtime.to_int32(cs_floor(bbox.max.x / 24.0))
            max_cy = runtime.to_int32(cs_floor(bbox.max.y / 24.0))

            min_x = min(min_cx - lx, min_x)
            min_y = min(min_cy - ly, min_y)

            max_x = max(max_cx - lx, max_x)
            max_y = max(max_cy - ly, max_y)

        add_cell_block(lscape, min_x + int(lcoord[0]), min_y + int(lcoord[1]), max_x + int(lcoord[0]),
                       max_y + int(lcoord[1]), cell_array, id)


@anchor("CLandCell::add_cell_block", "LandCell.cs:add_cell_block")
def add_cell_block(lscape, min_x: int, min_y: int, max_x: int, max_y: int, cell_array, id: int) -> None:
    for i in range(min_x, max_x + 1):
        for j in range(min_y, max_y + 1):
            if i < 0 or j < 0 or i >= land_defs.LAND_LENGTH or j >= land_defs.LAND_LENGTH:
                continue
            ui, uj = i, j
            cell_id = wrap_u32((((uj >> 3) | 32 * (ui & 0xFFFFFFF8)) << 16) | ((uj & 7) + 8 * (ui & 7) + 1))
            # FIXME! (ACE): only cells in id's own landblock
            if id >> 16 != cell_id >> 16:
                continue
            cell = lscape.get_landcell(cell_id)
            cell_array.add_cell(cell_id, cell)


@anchor("CLandCell::add_outside_cell", "LandCell.cs:add_outside_cell(CellArray, float, float)")
def add_outside_cell(lscape, cell_array, _x, _y) -> None:
    """``(uint)_x``: on mono a negative coordinate wraps to a huge uint and is skipped."""
    runtime = lscape.mode.runtime
    x = runtime.to_uint32(_x)
    y = runtime.to_uint32(_y)
    if x < 2040 and y < 2040:  # (x >= 0 && y >= 0 hold for uint)
        cell_id = wrap_u32((((y >> 3) | 32 * (x & 0xFFFFFFF8)) << 16) | ((y & 7) + 8 * (x & 7) + 1))
        land_cell = lscape.get_landcell(cell_id)  # LandCell.Get
        if land_cell is not None:
            cell_array.add_cell(cell_id, land_cell)


@anchor("CLandCell::add_outside_cell", "LandCell.cs:add_outside_cell(CellArray, Vector2)")
def add_outside_cell_lcoord(lscape, cell_array, lcoord) -> None:
    add_outside_cell(lscape, cell_array, lcoord[0], lcoord[1])


@anchor("CLandCell::check_add_cell_boundary", "LandCell.cs:check_add_cell_boundary")
def check_add_cell_boundary(lscape, cell_array, point, lcoord, min_rad, max_rad) -> None:
    """Add the neighbours a sphere at `point` (x, y within its cell) reaches into."""
    x, y = lcoord
    px, py = point
    if px > max_rad:
        add_outside_cell(lscape, cell_array, x + 1, y)
        if py > max_rad:
            add_outside_cell(lscape, cell_array, x + 1, y + 1)
        if py < min_rad:
            add_outside_cell(lscape, cell_array, x + 1, y - 1)
    if px < min_rad:
        add_outside_cell(lscape, cell_array, x - 1, y)
        if py > max_rad:
            add_outside_cell(lscape, cell_array, x - 1, y + 1)
        if py < min_rad:
            add_outside_cell(lscape, cell_array, x - 1, y - 1)
    if py > max_rad:
        add_outside_cell(lscape, cell_array, x, y + 1)
    if py < min_rad:
        add_outside_cell(lscape, cell_array, x, y - 1)
