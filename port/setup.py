"""Setup: Setup(), Setup(SetupModel), GetHoldingLocation, Get, MakeSimpleSetup -- an object's parts, spheres, cylspheres and dimensions.

ACE's Physics/Setup.cs over DatLoader's SetupModel (``_dat``). A static object's Setup comes from
its DAT record (`get`, or `make_simple_setup` for a bare GfxObj); the fields the physics reads
from ``_dat`` (step heights, Height, Radius, AllowFreeHeading, DefaultScale, the placement
frames, the holding locations, Id) are copied beside the lists the constructor builds. The mover's Setup comes from its
own record (acconform/dat.py mover_records) the same way.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from . import gfx_obj_cache
from .anchors import anchor
from .dat.setup_model import SetupModel
from .db_obj import get_setup
from .geom.cyl_sphere import CylSphere
from .geom.sphere import Sphere


@dataclass(slots=True, eq=False)
class Setup:
    num_cylsphere: int = 0
    cyl_sphere: list | None = None  # CylSphere
    num_sphere: int = 0
    sphere: list | None = None  # Sphere
    sorting_sphere: Sphere | None = None
    selection_sphere: Sphere | None = None
    num_parts: int = 0
    parts: list | None = None  # PhysicsPart (the Setup's own, which PartArray.InitParts copies)
    # _dat fields
    id: int = 0
    step_up_height: object = 0.0
    step_down_height: object = 0.0
    height: object = 0.0
    radius: object = 0.0
    allow_free_heading: bool = False
    default_scale: list = field(default_factory=list)  # Vector3 per part
    placement_frames: dict = field(default_factory=dict)  # int -> dat PlacementType
    holding_locations: dict = field(default_factory=dict)  # int (ParentLocation) -> dat LocationType
    default_animation: int = 0
    default_script: int = 0
    default_motion_table: int = 0

    def _copy_dat(self, dat: SetupModel) -> None:
        """``_dat = setupModel``: the SetupModel fields the physics reads."""
        self.id = dat.id
        self.step_up_height = dat.step_up_height
        self.step_down_height = dat.step_down_height
        self.height = dat.height
        self.radius = dat.radius
        self.allow_free_heading = dat.allow_free_heading
        self.default_scale = dat.default_scale
        self.placement_frames = dat.placement_frames
        self.holding_locations = dat.holding_locations
        self.default_animation = dat.default_animation
        self.default_script = dat.default_script
        self.default_motion_table = dat.default_motion_table

    @staticmethod
    @anchor("CSetup::UnPack", "Setup.cs:Setup(SetupModel)")
    def from_dat(setup_model: SetupModel, portal_dat) -> "Setup":
        """``new Setup(setupModel)``: a PhysicsPart per part id (each loads its GfxObj), the
        cylspheres and spheres, the sorting and selection spheres, then the counts."""
        from .part_array import PhysicsPart

        setup = Setup()
        setup._copy_dat(setup_model)
        setup.parts = []
        for part_id in setup_model.parts:
            setup.parts.append(PhysicsPart.create(portal_dat, part_id))  # static gfxobj + dynamic placement
        setup.cyl_sphere = []
        for cylsphere in setup_model.cyl_spheres:
            setup.cyl_sphere.append(CylSphere.from_dat(cylsphere))
        setup.sphere = []
        for sphere in setup_model.spheres:
            setup.sphere.append(Sphere.from_dat(sphere))
        setup.sorting_sphere = Sphere.from_dat(setup_model.sorting_sphere)
        setup.selection_sphere = Sphere.from_dat(setup_model.selection_sphere)
        setup.num_parts = len(setup_model.parts)
        setup.num_cylsphere = len(setup.cyl_sphere)
        setup.num_sphere = len(setup.sphere)
        return setup

    @anchor("CSetup::GetHoldingLocation", "Setup.cs:GetHoldingLocation")
    def get_holding_location(self, location_idx: int):
        """``_dat.HoldingLocations.TryGetValue``: the LocationType (part id, frame), or None."""
        return self.holding_locations.get(location_idx)

    @staticmethod
    @anchor(None, "Setup.cs:Get")
    def get(portal_dat, setup_id: int) -> "Setup":
        return Setup.from_dat(get_setup(portal_dat, setup_id), portal_dat)

    @staticmethod
    @anchor(None, "Setup.cs:MakeSimpleSetup")
    def make_simple_setup(portal_dat, gfx_obj_id: int) -> "Setup":
        """``new Setup()`` (a SetupModel.CreateSimpleSetup: AllowFreeHeading, dummy spheres, no
        cylsphere or sphere lists) with one part over the GfxObj, and an empty placement frame
        keyed by the GfxObj's id."""
        from .dat.placement_type import PlacementType
        from .part_array import PhysicsPart

        mode = portal_dat.mode
        setup = Setup()
        setup._copy_dat(SetupModel.create_simple_setup(mode))
        setup.placement_frames = {}  # the new SetupModel's own (empty) dictionary
        setup.num_parts = 1
        setup.parts = []
        gfx_obj = gfx_obj_cache.get(portal_dat, gfx_obj_id)
        if gfx_obj is not None:
            if gfx_obj.physics_sphere is not None:
                setup.sorting_sphere = gfx_obj.physics_sphere
            else:
                setup.sorting_sphere = gfx_obj.drawing_sphere
        part = PhysicsPart.create_empty(mode)
        part.gfx_obj = gfx_obj
        setup.parts.append(part)
        setup.placement_frames[gfx_obj_id] = PlacementType.create()
        return setup
