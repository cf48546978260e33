"""SetupModel: Unpack, CreateSimpleSetup -- a 0x02 Setup record: parts, placement frames, cylspheres, spheres, dimensions (ACE.DatLoader FileTypes/SetupModel.cs)."""

from __future__ import annotations

from dataclasses import dataclass, field

from ..anchors import anchor
from .cyl_sphere import CylSphere
from .light_info import LightInfo
from .location_type import LocationType
from .placement_type import PlacementType
from .sphere import Sphere
from .unpackable_extensions import dictionary_add, unpack_int_dict, unpack_list

# ACE.Entity.Enum.SetupFlags
SETUP_HAS_PARENT = 0x1
SETUP_HAS_DEFAULT_SCALE = 0x2
SETUP_ALLOW_FREE_HEADING = 0x4
SETUP_HAS_PHYSICS_BSP = 0x8
# ACE.Entity.Enum.Placement.MissileFlight
PLACEMENT_MISSILE_FLIGHT = 52


@dataclass(slots=True, eq=False)
class SetupModel:
    id: int = 0
    flags: int = 0
    allow_free_heading: bool = False
    has_physics_bsp: bool = False
    parts: list = field(default_factory=list)  # GfxObj ids
    parent_index: list = field(default_factory=list)
    default_scale: list = field(default_factory=list)  # Vector3 per part
    holding_locations: dict = field(default_factory=dict)
    connection_points: dict = field(default_factory=dict)
    placement_frames: dict = field(default_factory=dict)  # int -> PlacementType
    cyl_spheres: list = field(default_factory=list)
    spheres: list = field(default_factory=list)
    height: object = 0.0
    radius: object = 0.0
    step_up_height: object = 0.0
    step_down_height: object = 0.0
    sorting_sphere: Sphere = field(default_factory=Sphere)
    selection_sphere: Sphere = field(default_factory=Sphere)
    lights: dict = field(default_factory=dict)
    default_animation: int = 0
    default_script: int = 0
    default_motion_table: int = 0
    default_sound_table: int = 0
    default_script_table: int = 0
    has_missile_flight_placement: bool = False

    @staticmethod
    @anchor(None, "ACE.DatLoader/FileTypes/SetupModel.cs:Unpack")
    def unpack(reader) -> "SetupModel":
        s = SetupModel()
        s.id = reader.read_uint32()
        s.flags = reader.read_uint32()

        s.allow_free_heading = (s.flags & SETUP_ALLOW_FREE_HEADING) != 0
        s.has_physics_bsp = (s.flags & SETUP_HAS_PHYSICS_BSP) != 0

        num_parts = reader.read_uint32()
        for _ in range(num_parts):
            s.parts.append(reader.read_uint32())

        if s.flags & SETUP_HAS_PARENT:
            for _ in range(num_parts):
                s.parent_index.append(reader.read_uint32())

        if s.flags & SETUP_HAS_DEFAULT_SCALE:
            for _ in range(num_parts):
                s.default_scale.append(reader.read_vector3())

        s.holding_locations = unpack_int_dict(reader, LocationType.unpack)
        s.connection_points = unpack_int_dict(reader, LocationType.unpack)

        placements_count = reader.read_int32()
        for _ in range(placements_count):
            key = reader.read_int32()
            placement_type = PlacementType.unpack(reader, len(s.parts))
            dictionary_add(s.placement_frames, key, placement_type)
            if key == PLACEMENT_MISSILE_FLIGHT:
                s.has_missile_flight_placement = True

        s.cyl_spheres = unpack_list(reader, CylSphere.unpack)
        s.spheres = unpack_list(reader, Sphere.unpack)

        s.height = reader.read_single()
        s.radius = reader.read_single()
        s.step_up_height = reader.read_single()
        s.step_down_height = reader.read_single()

        s.sorting_sphere = Sphere.unpack(reader)
        s.selection_sphere = Sphere.unpack(reader)

        s.lights = unpack_int_dict(reader, LightInfo.unpack)

        s.default_animation = reader.read_uint32()
        s.default_script = reader.read_uint32()
        s.default_motion_table = reader.read_uint32()
        s.default_sound_table = reader.read_uint32()
        s.default_script_table = reader.read_uint32()
        return s

    @staticmethod
    @anchor(None, "ACE.DatLoader/FileTypes/SetupModel.cs:CreateSimpleSetup")
    def create_simple_setup(mode) -> "SetupModel":
        """`mode` gives the float fields (0f by default in C#) the run's scalar type."""
        setup = SetupModel()
        zero = mode.scalar(0.0)
        setup.height = setup.radius = setup.step_up_height = setup.step_down_height = zero
        setup.sorting_sphere = Sphere.create_dummy_sphere(mode)
        setup.selection_sphere = Sphere.create_dummy_sphere(mode)
        setup.allow_free_heading = True
        return setup
