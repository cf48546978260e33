"""PortalDat: the run's DatManager.PortalDat (a PortalDatDatabase: ACE.DatLoader/PortalDatDatabase.cs).

A DatDatabase (port/dat/dat_database.py) of the portal records acconform/dat.py wrote for the
scene (its objects' and the mover's GfxObjs and Setups, its Environments). It also carries the
run's stand-ins for the other statics DAT loading reads: GfxObjCache's dictionary (`gfx_objs`)
and PhysicsEngine.Instance.Server (`server`), ServerObjectManager's table of objects by id
(`server_objects`), and the physics clock every PhysicsObj made from
these records reads (`timer`: the run's port/physics_timer.PhysicsTimer, for the static
PhysicsTimer.CurrentTime; a PortalDat made without one gets a clock at 0.0, which a scene without
ticks never observes).
"""

from __future__ import annotations

from ..managers.server_object_manager import ServerObjectManager
from ..physics_timer import PhysicsTimer
from ..anchors import harness
from .dat_database import DatDatabase


class PortalDat(DatDatabase):
    __slots__ = ("server", "gfx_objs", "timer", "server_objects", "walk_speed", "run_speed", "turn_speed", "attack_frames")

    def __init__(self, records: dict[int, bytes], mode, server: bool, timer: PhysicsTimer | None = None):
        super().__init__(records, mode)
        self.server = server
        self.timer = timer if timer is not None else PhysicsTimer()
        self.server_objects = ServerObjectManager()  # ACE's static ServerObjectManager: the run's objects by id
        self.gfx_objs: dict = {}  # GfxObjCache.GfxObjs
        # Physics MotionTable's static WalkSpeed, RunSpeed, TurnSpeed (table id -> float) and DatLoader
        # MotionTable's attackFrameCache: ACE keeps them for the process, a run keeps them for itself
        self.walk_speed: dict = {}
        self.run_speed: dict = {}
        self.turn_speed: dict = {}
        self.attack_frames: dict = {}

    @staticmethod
    @harness("the kind of portal DAT record an id names")
    def kind_of(file_id: int) -> str:
        """0x01 GfxObj, 0x02 Setup, 0x03 Animation, 0x09 MotionTable, 0x0D Environment (the retail ranges
        acconform/dat.py writes in)."""
        return {0x01: "GfxObj", 0x02: "SetupModel", 0x03: "Animation", 0x09: "MotionTable",
                0x0D: "Environment"}.get(file_id >> 24, "")
