"""Setup: Setup(SetupModel) -- the parts of an object's Setup the physics reads (spheres, cylspheres, step heights, AllowFreeHeading).

ACE's Physics/Setup.cs over DatLoader's SetupModel (``_dat``). Scenes carry no DAT: the run
builds the Setup the oracle unpacks from a SetupModel it writes (oracle/pack.py, Facade.cs
MakeSetup): no parts, no DefaultScale, flags 0 (so AllowFreeHeading is false); spheres and
cylspheres from the scene; a static object's step heights are 0.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from .anchors import anchor


@dataclass(slots=True, eq=False)
class Setup:
    num_cylsphere: int = 0
    cyl_sphere: list = field(default_factory=list)  # CylSphere
    num_sphere: int = 0
    sphere: list = field(default_factory=list)  # Sphere
    # _dat fields
    step_up_height: object = 0.0
    step_down_height: object = 0.0
    height: object = 0.0
    radius: object = 0.0
    allow_free_heading: bool = False
    default_scale: list = field(default_factory=list)  # Vector3 per part (empty: flags 0)

    @staticmethod
    @anchor("CSetup::UnPack", "Setup.cs:Setup(SetupModel)")
    def create(spheres: list, cyl_spheres: list, height, radius, step_up_height, step_down_height) -> "Setup":
        """``new Setup(setupModel)``: the lists copied, the counts taken from them."""
        setup = Setup(cyl_sphere=list(cyl_spheres), sphere=list(spheres), step_up_height=step_up_height,
                      step_down_height=step_down_height, height=height, radius=radius)
        setup.num_cylsphere = len(setup.cyl_sphere)
        setup.num_sphere = len(setup.sphere)
        return setup
