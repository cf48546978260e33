"""ObjCell: Init, AddObject, AddShadowObject, FindCollisions, FindEnvCollisions, FindObjCollisions, check_entry_restrictions, handle_move_restriction, find_transit_cells (the sphere and parts overloads), point_in_cell, get_block_water_type, get_water_depth, Equals, find_cell_list (the sphere, one-sphere and cylsphere overloads), GetVisible.

ACE's Common/ObjCell.cs: the fields and base behaviour every cell has. SortCell (sort_cell.py)
derives from it, and LandCell (land_cell.py) from SortCell, as in ACE. `EMPTY_CELL` is ACE's ObjCell.EmptyCell (id 0, FindCollisions -> Invalid), which
CheckOtherCells passes in as the "find me a current cell" marker.

find_cell_list outdoors: every cell the spheres touch is added to the CellArray (which is never
cleared), then the current cell is the LAST cell in .NET dictionary order whose terrain holds
sphere 0's center -- on a shared edge both cells hold it and the later one wins. Indoors: the
position's own EnvCell is added, then each cell's find_transit_cells adds the cells beyond its
portals (or the outdoor cells, through a portal to 0xFFFF); the first EnvCell holding sphere 0's
center wins at once. Unless the CellArray loads cells (a static's placement never does), cells
the position's EnvCell does not list as visible are then dropped.
"""

from __future__ import annotations

from acconform.flags import InsertType, PhysicsState, TransitionState
from acconform.numerics import Mode, Vector3

# The package, not its modules: find_cell_list reaches LandCell's static helpers, and LandCell
# derives from this module's ObjCell, so land_cell is looked up in the package when called
# (port/cell/__init__.py imports obj_cell, sort_cell, land_cell in that order).
from acconform.port import cell as _cells

from ..anchors import anchor
from ..constants import WATER_DEPTH_DRY, WATER_DEPTH_ENTIRELY_WATER
from ..errors import InvalidCastException
from ..frame import AFrame, Position
from .. import land_defs
from ..land_defs import WaterType


class ObjCell:
    """CObjCell: its id, frame, water type and the objects registered in it."""

    __slots__ = ("id", "water_type", "pos", "object_list", "shadow_object_list", "restriction_obj",
                 "seen_outside", "voyeur_table", "cur_landblock")

    @anchor("CObjCell::CObjCell", "ObjCell.cs:ObjCell(uint)")
    def __init__(self, cell_id: int = 0, mode: Mode | None = None):
        self.id = cell_id
        self.water_type = WaterType.NotWater
        self.restriction_obj = 0
        self.seen_outside = False
        self.cur_landblock = None  # set by Landblock.init_landcell (PostInit)
        # EmptyCell is built before any run has a mode; nothing reads its Pos
        self.pos = Position(0, AFrame.identity(mode)) if mode is not None else None
        self.init_obj_cell_state()

    @anchor("CObjCell::init", "ObjCell.cs:Init", "the lists; Pos is set by the constructor")
    def init_obj_cell_state(self) -> None:
        self.object_list: list = []
        self.shadow_object_list: list = []
        self.voyeur_table: list[int] = []

    @anchor(None, "ObjCell.cs:Equals")
    def equals(self, obj_cell) -> bool:
        if obj_cell is None:
            return False
        return self.id == obj_cell.id

    @anchor("CObjCell::add_shadow_object", "ObjCell.cs:AddShadowObject")
    def add_shadow_object(self, shadow_obj) -> None:
        """Appends to ShadowObjectList (FindObjCollisions walks it from the end). NumShadowObjects,
        which nothing in a transition reads, is not kept."""
        self.shadow_object_list.append(shadow_obj)
        shadow_obj.cell = self

    @anchor("CObjCell::add_object", "ObjCell.cs:AddObject")
    def add_object(self, obj) -> None:
        """Appends to ObjectList (NumObjects, which nothing here reads, is not kept). An object
        with an id would then be announced to the cell's voyeurs; none are ever registered here."""
        self.object_list.append(obj)
        if obj.id == 0 or obj.parent is not None or obj.state & PhysicsState.Hidden or self.voyeur_table is None:
            return
        if self.voyeur_table:
            raise NotImplementedError("voyeurs (ObjCell.VoyeurTable) are not ported")

    @anchor("CObjCell::remove_object", "ObjCell.cs:RemoveObject")
    def remove_object(self, obj) -> None:
        """List.Remove: the first entry that is `obj` (PhysicsObj has no Equals override: by
        reference), if any. NumObjects is not kept; update_all_voyeur has no voyeurs to tell."""
        for i, entry in enumerate(self.object_list):
            if entry is obj:
                del self.object_list[i]
                break
        self.update_all_voyeur(obj)

    @anchor("CObjCell::update_all_voyeur", "ObjCell.cs:update_all_voyeur")
    def update_all_voyeur(self, obj) -> None:
        if obj.id == 0 or obj.parent is not None or self.voyeur_table is None:
            return
        if self.voyeur_table:
            raise NotImplementedError("voyeurs (ObjCell.VoyeurTable) are not ported")

    @anchor("CObjCell::remove_shadow_object", "ObjCell.cs:remove_shadow_object")
    def remove_shadow_object(self, shadow_obj) -> None:
        """List.Remove by reference (ShadowObj has no Equals override); NumShadowObjects is not kept."""
        # multiple shadows? (ACE)
        for i, entry in enumerate(self.shadow_object_list):
            if entry is shadow_obj:
                del self.shadow_object_list[i]
                break
        shadow_obj.cell = None

    @anchor("CObjCell::check_collisions", "ObjCell.cs:check_collisions")
    def check_collisions(self, obj, lscape) -> bool:
        for shadow_obj in self.shadow_object_list:
            p_obj = shadow_obj.physics_obj
            if p_obj.parent is None and not p_obj.equals(obj) and p_obj.check_collision(obj, lscape):
                return True
        return False

    @anchor("CObjCell::find_collisions", "ObjCell.cs:FindCollisions")
    def find_collisions(self, transition) -> TransitionState:
        return TransitionState.Invalid

    @anchor("CObjCell::find_env_collisions", "ObjCell.cs:FindEnvCollisions")
    def find_env_collisions(self, transition) -> TransitionState:
        return TransitionState.Invalid

    @anchor("CObjCell::find_obj_collisions", "ObjCell.cs:FindObjCollisions")
    def find_obj_collisions(self, transition) -> TransitionState:
        path = transition.sphere_path
        if path.insert_type == InsertType.InitialPlacement:
            return TransitionState.OK

        # ACE walks the shadow list from the end ("for (int i = Count - 1; i >= 0; i--)")
        for i in range(len(self.shadow_object_list) - 1, -1, -1):
            shadow_obj = self.shadow_object_list[i]
            obj = shadow_obj.physics_obj
            if obj.parent is not None or obj.equals(transition.object_info.object):
                continue
            state = obj.find_obj_collisions(transition)
            if state != TransitionState.OK:
                # custom (ACE): placements ignore ethereal objects
                if path.insert_type == InsertType.Placement and obj.state & PhysicsState.Ethereal:
                    continue
                return state
        return TransitionState.OK

    @anchor(None, "ObjCell.cs:check_entry_restrictions")
    def check_entry_restrictions(self, transition) -> TransitionState:
        obj = transition.object_info.object
        begin_cell = transition.sphere_path.begin_cell
        if not obj.is_player or transition.collision_info.verified_restrictions or (
                begin_cell is not None and begin_cell.id == self.id):
            return TransitionState.OK

        if transition.object_info.object is None:
            return TransitionState.Collided

        weenie_obj = obj.weenie_obj
        if weenie_obj is not None:
            if obj.is_player:
                if self.restriction_obj != 0 and not weenie_obj.can_bypass_move_restrictions():
                    restriction_obj = obj.server_objects.get_object_a(self.restriction_obj)

                    if restriction_obj is None or restriction_obj.weenie_obj is None:
                        return TransitionState.Collided

                    if not restriction_obj.weenie_obj.can_move_into(weenie_obj):
                        self.handle_move_restriction(transition)
                        return TransitionState.Collided
                    else:
                        transition.collision_info.verified_restrictions = True
        return TransitionState.OK

    @anchor(None, "ObjCell.cs:handle_move_restriction")
    def handle_move_restriction(self, transition) -> bool:
        return False

    @anchor("CObjCell::find_transit_cells", "ObjCell.cs:find_transit_cells")
    def find_transit_cells(self, lscape, position, num_sphere, spheres, cell_array, path) -> None:
        pass

    @anchor("CObjCell::find_transit_cells", "ObjCell.cs:find_transit_cells(int, List<PhysicsPart>, CellArray)",
            "the parts overload: empty base")
    def find_transit_cells_parts(self, lscape, num_parts, parts, cell_array) -> None:
        pass

    @anchor("CObjCell::point_in_cell", "ObjCell.cs:point_in_cell")
    def point_in_cell(self, point) -> bool:
        return False

    @anchor("CObjCell::get_block_water_type", "ObjCell.cs:get_block_water_type")
    def get_block_water_type(self) -> WaterType:
        if self.cur_landblock is not None:
            return self.cur_landblock.water_type
        return WaterType.NotWater

    @anchor("CObjCell::get_water_depth", "ObjCell.cs:get_water_depth")
    def get_water_depth(self, point: Vector3):
        s = type(point.x)
        if self.water_type == WaterType.NotWater:
            return s(0.0)
        if self.water_type == WaterType.EntirelyWater:
            return s(WATER_DEPTH_ENTIRELY_WATER)
        if self.cur_landblock is not None:
            return self.cur_landblock.calc_water_depth(self.id, point)
        return s(WATER_DEPTH_DRY)


# ObjCell.EmptyCell
EMPTY_CELL = ObjCell()

@anchor("CObjCell::GetVisible", "ObjCell.cs:GetVisible")
def get_visible(lscape, cell_id: int):
    if cell_id == 0:
        return None
    return lscape.get_landcell(cell_id)


@anchor("CObjCell::find_cell_list", "ObjCell.cs:find_cell_list(Position, int, List<Sphere>, CellArray, ref ObjCell, SpherePath)")
def find_cell_list(lscape, position, num_sphere: int, spheres: list, cell_array, curr_cell, path):
    """The sphere overload; returns currCell after the call (C# ref)."""
    cell_array.num_cells = 0
    cell_array.added_outside = False

    visible_cell = get_visible(lscape, position.obj_cell_id)

    if (position.obj_cell_id & 0xFFFF) >= 0x100:
        if path is not None:
            path.hits_interior_cell = True
            if path.trace is not None:
                path.trace["find_cell_list:indoor"] += 1

        cell_array.add_cell(position.obj_cell_id, visible_cell)
    else:
        _cells.land_cell.add_all_outside_cells_replayed(lscape, position, num_sphere, spheres, cell_array)

    if visible_cell is not None and num_sphere != 0:
        i = 0
        while i < len(cell_array.cells):  # Count re-read each pass, as ACE's for loop does
            cell = cell_array.cells.value_at(i)
            i += 1
            if cell is None:
                continue
            cell.find_transit_cells(lscape, position, num_sphere, spheres, cell_array, path)

        if curr_cell is not None:
            curr_cell = None
            for cell in cell_array.cells.values():
                if cell is None:
                    continue
                block_offset = land_defs.get_block_offset(position.obj_cell_id, cell.id)
                local_point = spheres[0].center - block_offset
                if cell.point_in_cell(local_point):
                    curr_cell = cell
                    if (cell.id & 0xFFFF) >= 0x100:
                        if path is not None:
                            path.hits_interior_cell = True
                        return curr_cell
    if not cell_array.load_cells and (position.obj_cell_id & 0xFFFF) >= 0x100:
        cells = cell_array.cells.values()  # a copy (ToList), as ACE walks it while removing
        for cell in cells:
            if cell is None:
                continue

            if visible_cell.id == cell.id:
                continue

            found = False

            for stab in _visible_cells_of(visible_cell).values():
                if stab is None:
                    continue

                if cell.id == stab.id:
                    found = True
                    break
            if not found:
                cell_array.remove_cell(cell)
                if path is not None and path.trace is not None:
                    path.trace["find_cell_list:pruned"] += 1
    return curr_cell


def _visible_cells_of(visible_cell) -> dict:
    """``((EnvCell)visibleCell).VisibleCells``: the cast throws for any other cell."""
    if not isinstance(visible_cell, _cells.env_cell.EnvCell):
        raise InvalidCastException(f"cell {visible_cell.id:08X} is a {type(visible_cell).__name__}, not an EnvCell")
    return visible_cell.visible_cells


@anchor("CObjCell::find_cell_list", "ObjCell.cs:find_cell_list(Position, int, List<CylSphere>, CellArray, SpherePath)",
        "the cylsphere overload (a cylsphere static's placement)")
def find_cell_list_cyl(lscape, position, num_cyl_sphere: int, cyl_sphere: list, cell_array, path) -> None:
    """A sphere per cylsphere (at most 10): centre its low point in `position`'s frame (no scale),
    radius its radius; then the sphere overload with no current cell asked for."""
    from ..geom.sphere import Sphere

    if num_cyl_sphere > 10:
        num_cyl_sphere = 10

    spheres = []

    for i in range(num_cyl_sphere):
        sphere = Sphere()
        sphere.center = position.local_to_global(cyl_sphere[i].low_point)
        sphere.radius = cyl_sphere[i].radius
        spheres.append(sphere)

    find_cell_list(lscape, position, num_cyl_sphere, spheres, cell_array, None, path)


@anchor("CObjCell::find_cell_list", "ObjCell.cs:find_cell_list(Position, Sphere, CellArray, SpherePath)",
        "the one-sphere overload (calc_cross_cells of an object with neither a physics BSP nor a cylsphere)")
def find_cell_list_sphere(lscape, position, sphere, cell_array, path) -> None:
    """The sphere centred in `position`'s frame (no scale), its radius; then the sphere overload
    (through find_cell_list(Position, int, Sphere, ...): a list of that one sphere, one sphere
    counted) with no current cell asked for."""
    from ..geom.sphere import Sphere

    global_sphere = Sphere()
    global_sphere.center = position.local_to_global(sphere.center)
    global_sphere.radius = sphere.radius

    find_cell_list(lscape, position, 1, [global_sphere], cell_array, None, path)


@anchor("CObjCell::find_cell_list", "ObjCell.cs:find_cell_list(CellArray, ref ObjCell, SpherePath)")
def find_cell_list_path(lscape, cell_array, check_cell, path):
    """find_cell_list(cellArray, ref checkCell, path): the path's check position and global spheres."""
    return find_cell_list(lscape, path.check_pos, path.num_sphere, path.global_sphere, cell_array, check_cell, path)
