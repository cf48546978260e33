"""EnvCell: EnvCell(DatLoader EnvCell), PostInit, FindEnvCollisions, FindCollisions, build_visible_cells, find_visible_child_cell, GetVisible, find_transit_cells (the parts and sphere overloads), check_building_transit (the sphere and parts overloads), init_static_objects, point_in_cell, handle_move_restriction.

ACE's Common/EnvCell.cs: an indoor cell (0xXXYY0100 and up), an ObjCell (obj_cell.py) over a
CellStruct (cell_struct.py) taken from its Environment record. Built by DBObj.GetEnvCell
(port/db_obj.py) from the cell DAT's EnvCell record when LScape.get_landcell first asks for it
(the only constructor ACE calls: its empty one, `EnvCell()` and the `Init` it runs, is called
nowhere in ACE, so it is not ported);
the landblock caches it, then PostInit resolves its visible cells (each one through
LScape.get_landcell, so building a cell builds every cell it sees) and places its static objects
(the record's stabs: makeObject with id 0, add_obj_to_cell at the stab's frame).

Quirks kept from ACE:
- VisibleCells is keyed by the SHORT cell id (0x0100...), but build_visible_cells tests the
  full id before adding, so a short id listed twice throws ArgumentException (except in
  landblock 0x0000, where both ids are the same).
- find_transit_cells adds an unloaded neighbour under its SHORT id (portal.OtherCellId), with no
  cell; the spheres are taken into the cell's frame with Pos.Frame only (no block offset).
- A static whose object gets no cell (no PartArray) would be destroyed (DestroyObject, not
  ported: a scene's statics always have parts).

The static LScape and DAT managers ACE reaches are the run's `lscape` (and its `portal_dat`),
passed in as the other cells do.
"""

from __future__ import annotations

from acconform.flags import InsertType, ObjectInfoState, TransitionState
from acconform.numerics import dot

from ..anchors import anchor
from ..bbox import BBox
from ..constants import EPSILON
from ..errors import InvalidCastException, KeyNotFoundException
from ..frame import AFrame, Position
from ..geom.bsp import BoundingType
from ..geom.sphere import Sphere
from ..dat.unpackable_extensions import dictionary_add
from ..vec import Sidedness, intersect_box
from . import cell_struct as cell_struct_module
from .obj_cell import ObjCell
from . import land_cell

# CellPortal.OtherCellId for a portal that leads outside (ushort.MaxValue)
OUTSIDE_CELL_ID = 0xFFFF


def _polygon(polygons: dict, key: int):
    """``CellStructure.Polygons[key]``: the .NET indexer throws on a missing key."""
    polygon = polygons.get(key)
    if polygon is None:
        raise KeyNotFoundException(f"The given key '{key}' was not present in the dictionary.")
    return polygon


class EnvCell(ObjCell):
    __slots__ = ("num_surfaces", "cell_structure", "cell_structure_id", "num_portals", "portals",
                 "num_static_objects", "static_object_ids", "static_object_frames", "static_objects",
                 "visible_cell_ids", "visible_cells", "flags", "environment_id", "_env_cell", "environment",
                 "shadow_object_ids", "num_stabs")

    @classmethod
    @anchor("CEnvCell::UnPack", "EnvCell.cs:EnvCell(DatLoader.FileTypes.EnvCell)", "the DAT constructor")
    def from_dat(cls, env_cell, portal_dat) -> "EnvCell":
        """`portal_dat` is DatManager.PortalDat (GetEnvironment); its mode is the run's."""
        from .. import db_obj

        mode = portal_dat.mode
        c = cls.__new__(cls)
        ObjCell.__init__(c, 0, mode)  # : base()
        EnvCell._clear(c)
        c._env_cell = env_cell

        c.flags = env_cell.flags
        c.id = env_cell.id
        c.shadow_object_ids = env_cell.surfaces
        c.pos = Position(c.id, AFrame.from_dat(env_cell.position))
        c.portals = env_cell.cell_portals
        c.num_portals = len(c.portals)
        c.static_object_ids = []
        c.static_object_frames = []
        c.num_static_objects = len(env_cell.static_objects)
        for static_obj in env_cell.static_objects:
            c.static_object_ids.append(static_obj.id)
            c.static_object_frames.append(AFrame.from_dat(static_obj.frame))
        c.num_stabs = len(c.static_object_ids)
        c.visible_cell_ids = env_cell.visible_cells
        c.restriction_obj = env_cell.restriction_obj
        c.seen_outside = env_cell.seen_outside

        c.environment_id = env_cell.environment_id

        if c.environment_id != 0:
            c.environment = db_obj.get_environment(portal_dat, c.environment_id)

        c.cell_structure_id = env_cell.cell_structure  # environment can contain multiple? (ACE)

        if c.environment is not None and c.environment.cells is not None:
            cell_struct = c.environment.cells.get(c.cell_structure_id)
            if cell_struct is not None:
                c.cell_structure = cell_struct_module.remembered(portal_dat, c.environment_id, c.cell_structure_id,
                                                                 cell_struct)  # new CellStruct(cellStruct)

        c.num_surfaces = len(env_cell.surfaces)
        return c

    def _clear(self) -> None:
        """The fields C# leaves at their defaults before the DAT constructor's body runs."""
        self.num_surfaces = 0
        self.cell_structure = None
        self.cell_structure_id = 0
        self.num_portals = 0
        self.portals = None
        self.num_static_objects = 0
        self.static_object_ids = None
        self.static_object_frames = None
        self.static_objects = None
        self.visible_cell_ids = None
        self.visible_cells = None
        self.flags = 0
        self.environment_id = 0
        self._env_cell = None
        self.environment = None
        self.shadow_object_ids = None
        self.num_stabs = 0

    def __repr__(self) -> str:
        return f"EnvCell({self.id:08X})"

    @anchor(None, "EnvCell.cs:PostInit")
    def post_init(self, lscape) -> None:
        self.build_visible_cells(lscape)
        self.init_static_objects(lscape)

    @anchor("CEnvCell::find_env_collisions", "EnvCell.cs:FindEnvCollisions")
    def find_env_collisions(self, transition) -> TransitionState:
        transit_state = self.check_entry_restrictions(transition)

        if transit_state != TransitionState.OK:
            return transit_state

        path = transition.sphere_path
        path.obstruction_ethereal = False

        if self.cell_structure.physics_bsp is not None:
            one = transition.mode.scalar(1.0)
            path.cache_local_space_sphere(self.pos, one)

            if path.insert_type == InsertType.InitialPlacement:
                transit_state = self.cell_structure.physics_bsp.placement_insert(transition)
            else:
                transit_state = self.cell_structure.physics_bsp.find_collisions(transition, one)

            if transit_state != TransitionState.OK and not transition.object_info.state & ObjectInfoState.Contact:
                transition.collision_info.collided_with_environment = True
            if transition.trace is not None:
                transition.trace["env_cell:physics_bsp"] += 1
        return transit_state

    @anchor("CEnvCell::find_collisions", "EnvCell.cs:FindCollisions")
    def find_collisions(self, transition) -> TransitionState:
        transition_state = self.find_env_collisions(transition)
        if transition_state == TransitionState.OK:
            transition_state = self.find_obj_collisions(transition)
        return transition_state

    @anchor("CEnvCell::build_visible_cells", "EnvCell.cs:build_visible_cells")
    def build_visible_cells(self, lscape) -> None:
        self.visible_cells = {}

        for visible_cell_id in self.visible_cell_ids:
            block_cell_id = (self.id & 0xFFFF0000) | visible_cell_id
            if block_cell_id in self.visible_cells:
                continue
            cell = lscape.get_landcell(block_cell_id)
            if cell is not None and not isinstance(cell, EnvCell):
                raise InvalidCastException(f"cell {block_cell_id:08X} is a {type(cell).__name__}, not an EnvCell")
            dictionary_add(self.visible_cells, visible_cell_id, cell)

    @anchor("CEnvCell::find_visible_child_cell", "EnvCell.cs:find_visible_child_cell")
    def find_visible_child_cell(self, origin, search_cells: bool):
        if self.point_in_cell(origin):
            return self

        if search_cells:
            for visible_cell in self.visible_cells.values():
                if visible_cell is None:
                    continue

                env_cell = self.get_visible(visible_cell.id & 0xFFFF)
                if env_cell is not None and env_cell.point_in_cell(origin):
                    return env_cell
        else:
            for portal in self.portals:
                env_cell = self.get_visible(portal.other_cell_id)
                if env_cell is not None and env_cell.point_in_cell(origin):
                    return env_cell
        return None

    @anchor("CEnvCell::GetVisible", "EnvCell.cs:GetVisible", "VisibleCells by its short cell id")
    def get_visible(self, cell_id: int):
        return self.visible_cells.get(cell_id)

    @anchor("CEnvCell::find_transit_cells", "EnvCell.cs:find_transit_cells(int, List<PhysicsPart>, CellArray)",
            "the parts overload (a static's placement)")
    def find_transit_cells_parts(self, lscape, num_parts: int, parts, cell_array) -> None:
        check_outside = False

        for portal in self.portals:
            portal_poly = _polygon(self.cell_structure.polygons, portal.polygon_id)

            for part in parts:
                if part is None:
                    continue
                sphere = part.gfx_obj.physics_sphere
                if sphere is None:
                    sphere = part.gfx_obj.drawing_sphere
                if sphere is None:
                    continue

                center = self.pos.local_to_local(part.pos, sphere.center)
                rad = sphere.radius + EPSILON

                dist = dot(center, portal_poly.plane.normal) + portal_poly.plane.d
                if portal.portal_side:
                    if dist < -rad:
                        continue
                else:
                    if dist > rad:
                        continue

                bbox = part.get_bounding_box()
                box = BBox()
                box.local_to_local(bbox, part.pos, self.pos)
                sidedness = intersect_box(portal_poly.plane, box)
                if (sidedness == Sidedness.Positive and not portal.portal_side
                        or sidedness == Sidedness.Negative and portal.portal_side):
                    continue

                if portal.other_cell_id == OUTSIDE_CELL_ID:
                    check_outside = True
                    break

                # LoadCells (ACE)
                other_cell = self.get_visible(portal.other_cell_id)
                if other_cell is None:
                    cell_array.add_cell(portal.other_cell_id, None)
                    break

                cell_box = BBox()
                cell_box.local_to_local(bbox, part.pos, other_cell.pos)
                if other_cell.cell_structure.box_intersects_cell(cell_box):
                    cell_array.add_cell(other_cell.id, other_cell)
                    break
        if check_outside:
            land_cell.add_all_outside_cells_parts(lscape, num_parts, parts, cell_array, self.id)

    @anchor("CEnvCell::find_transit_cells", "EnvCell.cs:find_transit_cells(Position, int, List<Sphere>, CellArray, SpherePath)")
    def find_transit_cells(self, lscape, position, num_sphere, spheres, cell_array, path) -> None:
        check_outside = False
        trace = path.trace if path is not None else None

        for portal in self.portals:
            portal_poly = _polygon(self.cell_structure.polygons, portal.polygon_id)

            if portal.other_cell_id == OUTSIDE_CELL_ID:
                for sphere in spheres:
                    rad = sphere.radius + EPSILON
                    center = self.pos.frame.global_to_local(sphere.center)

                    dist = dot(center, portal_poly.plane.normal) + portal_poly.plane.d
                    if -rad < dist < rad:
                        check_outside = True
                        if trace is not None:
                            trace["env_cell:outside_portal"] += 1
                        break
            else:
                other_cell = self.get_visible(portal.other_cell_id)
                if other_cell is not None:
                    for sphere in spheres:
                        center = other_cell.pos.frame.global_to_local(sphere.center)
                        _sphere = Sphere(center, sphere.radius)

                        bounding_type = other_cell.cell_structure.sphere_intersects_cell(_sphere)
                        if bounding_type != BoundingType.Outside:
                            cell_array.add_cell(other_cell.id, other_cell)
                            if trace is not None:
                                trace["env_cell:other_cell"] += 1
                            break
                else:
                    for sphere in spheres:
                        center = self.pos.frame.global_to_local(sphere.center)
                        _sphere = Sphere(center, sphere.radius + EPSILON)
                        portal_side = portal.portal_side
                        dist = dot(_sphere.center, portal_poly.plane.normal) + portal_poly.plane.d
                        if dist > -_sphere.radius and portal_side or dist < _sphere.radius and not portal_side:
                            cell_array.add_cell(portal.other_cell_id, None)
                            if trace is not None:
                                trace["env_cell:unloaded_cell"] += 1
                            break
        if check_outside:
            land_cell.add_all_outside_cells_replayed(lscape, position, num_sphere, spheres, cell_array)

    @anchor("CEnvCell::check_building_transit",
            "EnvCell.cs:check_building_transit(ushort, Position, int, List<Sphere>, CellArray, SpherePath)")
    def check_building_transit(self, portal_id: int, pos, num_sphere: int, spheres, cell_array, path) -> None:
        """A building's portal into this cell (BuildingObj.find_building_transit_cells): every
        sphere (all of them, not numSphere) that the cell's tree does not find Outside adds the
        cell and marks the path as touching an interior cell. The sphere's centre is taken into
        the cell's frame with Pos.Frame only (no block offset)."""
        # if (portalId == 0) return; (ACE)
        if portal_id == 0xFFFF:  # ushort.MaxValue
            return

        trace = path.trace if path is not None else None
        for sphere in spheres:
            glob_sphere = Sphere(self.pos.frame.global_to_local(sphere.center), sphere.radius)
            if self.cell_structure.sphere_intersects_cell(glob_sphere) == BoundingType.Outside:
                continue

            if path is not None:
                path.hits_interior_cell = True

            cell_array.add_cell(self.id, self)
            if trace is not None:
                trace["building:transit_cell"] += 1

    @anchor("CEnvCell::check_building_transit",
            "EnvCell.cs:check_building_transit(int, int, List<PhysicsPart>, CellArray)", "the parts overload")
    def check_building_transit_parts(self, lscape, portal_id: int, num_parts: int, parts, cell_array) -> None:
        # if (portalId == 0) return; (ACE)
        if portal_id == 0xFFFF:  # ushort.MaxValue
            return

        portal = self.portals[portal_id]
        portal_poly = self.cell_structure.portals[portal_id]

        for part in parts:
            if part is None:
                continue

            bounding_sphere = None
            if part.gfx_obj.physics_sphere is not None:
                bounding_sphere = part.gfx_obj.physics_sphere
            else:
                bounding_sphere = part.gfx_obj.drawing_sphere

            if bounding_sphere is None:
                continue

            center = self.pos.local_to_local(part.pos, bounding_sphere.center)
            rad = bounding_sphere.radius + EPSILON

            diff = dot(center, portal_poly.plane.normal) + portal_poly.plane.d
            if portal.portal_side:
                if diff > rad:
                    continue
            else:
                if diff < -rad:
                    continue

            box = BBox()
            box.local_to_local(part.get_bounding_box(), part.pos, self.pos)
            intersect = intersect_box(portal_poly.plane, box)
            if (intersect == Sidedness.Crossing or intersect == Sidedness.Positive and portal.portal_side
                    or intersect == Sidedness.Negative and not portal.portal_side):
                if not self.cell_structure.box_intersects_cell(box):
                    continue

                cell_array.add_cell(self.id, self)
                self.find_transit_cells_parts(lscape, num_parts, parts, cell_array)
                return

    @anchor("CEnvCell::init_static_objects", "EnvCell.cs:init_static_objects")
    def init_static_objects(self, lscape) -> None:
        from ..physics_obj import PhysicsObj

        if self.static_objects is not None:
            for static_obj in self.static_objects:
                if not static_obj.is_completely_visible():
                    static_obj.calc_cross_cells_static(lscape)
        else:
            self.static_objects = []

            for i in range(self.num_static_objects):
                static_obj = PhysicsObj.make_object(self.static_object_ids[i], 0, False, lscape.portal_dat)
                static_obj.dat_object = True
                static_obj.add_obj_to_cell(self, self.static_object_frames[i], lscape)
                if static_obj.cur_cell is None:  # a stab of a Setup with no parts: no PartArray, so enter_cell left it out
                    static_obj.destroy_object()
                    continue

                self.static_objects.append(static_obj)

    @anchor("CEnvCell::point_in_cell", "EnvCell.cs:point_in_cell")
    def point_in_cell(self, point) -> bool:
        local_point = self.pos.frame.global_to_local(point)
        return self.cell_structure.point_in_cell(local_point)

    @anchor("CEnvCell::handle_move_restriction", "EnvCell.cs:handle_move_restriction")
    def handle_move_restriction(self, transition) -> bool:
        return True
