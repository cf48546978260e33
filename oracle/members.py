"""Every ACE type and member the oracle touches, in one table, checked when the oracle loads.

The facade (oracle/facade/Facade.cs) and oracle/functions.py use only these. `check_members` looks each type up by full name across the loaded assemblies and each
member by name (public or not, static or instance), so an ACE build that lacks one fails with
one message naming the type, the member and the assembly directory, instead of a .NET
traceback half-way through a scene.
"""

from __future__ import annotations

from ..errors import OracleUnavailable

# (type full name, members). ".ctor" is a constructor.
REQUIRED: tuple[tuple[str, tuple[str, ...]], ...] = (
    ("ACE.Server.Physics.PhysicsEngine", (".ctor", "Instance", "Server")),
    ("ACE.Server.Physics.TransientStateFlags", ("StationaryStuck", "StationaryStop", "StationaryFall")),
    ("ACE.Server.Physics.PhysicsGlobals", ("DummySphere",)),
    ("ACE.Server.Physics.Common.ObjectMaint", (".ctor",)),
    ("ACE.Server.Physics.Common.SmartBox", (".ctor",)),
    ("ACE.Server.Physics.Common.LScape", ("Landblocks", "get_landcell")),
    ("ACE.Server.Physics.Common.LandDefs", ("LandHeightTable",)),
    ("ACE.Server.Physics.Common.Landblock", (".ctor", "UseSceneFiles", "PostInit", "ID")),
    ("ACE.Server.Physics.Common.ObjCell", ("ID",)),
    ("ACE.Server.Physics.Common.Position", (".ctor", "ObjCellID", "Frame")),
    ("ACE.Server.Physics.Util.AdjustCell", ("AdjustCells",)),
    ("ACE.Server.Physics.Entity.VertexCache", ("Vertices",)),
    ("ACE.Server.Physics.Entity.PolygonCache", ("Polygons",)),
    ("ACE.Server.Physics.Entity.BSPCache", ("BSPTrees",)),
    ("ACE.Server.Physics.Entity.GfxObjCache", ("GfxObjs",)),
    ("ACE.Server.Physics.Entity.Vertex", (".ctor",)),
    ("ACE.Server.Physics.Managers.ServerObjectManager", ("ServerObjects",)),
    # server mode: ACE's LandblockManager table, its adjacency bookkeeping (Facade.LoadServerLandblock) and the
    # server landblock's auto-properties
    ("ACE.Server.Managers.LandblockManager", ("landblocks", "GetLandblock", "SetAdjacents", "GetAdjacents",
                                              "GetAdjacentIDs", "GetAdjacentID")),
    ("ACE.Server.Entity.Landblock", ("PhysicsLandblock", "<PhysicsLandblock>k__BackingField", "<Id>k__BackingField",
                                     "CellLandblock", "<CellLandblock>k__BackingField", "LandblockInfo",
                                     "<LandblockInfo>k__BackingField", "Adjacents", "IsDungeon")),
    ("ACE.Server.Physics.Common.Landblock", ("adjacents", "SetAdjacents", "GetServerObjects")),
    ("ACE.Entity.LandblockId", (".ctor", "LandblockX", "LandblockY")),
    # a projectile's Location (Facade.ProjectileLocation): ACE.Entity's Position, whose Pos setter finds its cell
    ("ACE.Entity.Position", (".ctor", "Pos", "Cell", "LandblockId")),
    ("ACE.Entity.Enum.PhysicsState", ("Static", "HasPhysicsBSP")),
    ("ACE.Entity.Enum.CullMode", ("Landblock", "Clockwise", "CounterClockwise")),
    ("ACE.DatLoader.FileTypes.CellLandblock", (".ctor", "Unpack", "Id")),
    # statics and the mover: their DAT records (acconform/dat.py), unpacked by ACE and kept where ACE looks for them
    ("ACE.DatLoader.FileTypes.SetupModel", (".ctor", "Unpack")),
    ("ACE.DatLoader.FileTypes.GfxObj", (".ctor", "Unpack")),
    ("ACE.DatLoader.FileTypes.FileType", ("Unpack",)),
    ("ACE.DatLoader.DatManager", ("PortalDat", "<PortalDat>k__BackingField", "CellDat", "<CellDat>k__BackingField")),
    ("ACE.DatLoader.DatDatabase", ("FileCache", "<FileCache>k__BackingField", "ReadFromDat", "<AllFiles>k__BackingField",
                                   "<Header>k__BackingField")),
    ("ACE.DatLoader.DatDatabaseHeader", (".ctor",)),
    ("ACE.DatLoader.DatFile", ()),
    ("ACE.DatLoader.PortalDatDatabase", ()),
    # indoors: Environments (portal DAT), EnvCells and LandblockInfos (cell DAT), loaded by ACE's LScape.get_landcell
    ("ACE.DatLoader.CellDatDatabase", ()),
    ("ACE.DatLoader.FileTypes.Environment", (".ctor", "Unpack", "Cells")),
    ("ACE.DatLoader.FileTypes.EnvCell", (".ctor", "Unpack", "CellPortals", "VisibleCells", "StaticObjects")),
    ("ACE.DatLoader.FileTypes.LandblockInfo", (".ctor", "Unpack", "NumCells")),
    ("ACE.Server.Physics.Common.EnvCell", ("StaticObjects",)),
    ("ACE.Server.Physics.PartArray", ("GetDataID",)),
    ("ACE.Server.Physics.PartArray", ("GetNumSphere", "GetSphere")),
    ("ACE.Server.Physics.PhysicsObj", ("PartArray", "State", "TransientState", "Velocity", "ContactPlane",
                                       "ContactPlaneCellID", "SlidingNormal", "Position", "CurCell", "Scale",
                                       "SetScaleStatic", "remove_shadows_from_cells", "get_object_info",
                                       "makeObject", "DatObject", "add_obj_to_cell", "leave_cell", "DestroyObject",
                                       "ShadowObjects")),
    # the mover, a player's PhysicsObj (Facade.BuildMover) entering the world (mover.placement: Facade.Place)
    ("ACE.Server.Physics.PhysicsObj", (".ctor", "makeAnimObject", "set_object_guid", "set_weenie_obj", "SetMotionTableID",
                                       "enter_world", "SetPosition", "set_request_pos", "update_object_server")),
    ("ACE.Server.Physics.Common.WeenieObject", (".ctor",)),
    # (and FastTick, read by reflection in Facade.PlayerFastTick: ACE of 2019 has none, and runs no tick scene)
    ("ACE.Server.WorldObjects.Player", ("LastContact", "PlayerKillerStatus")),
    # the Player's skills, vitals, attributes and burden (scene/8 mover.skills: Facade.SetPlayerSkills)
    ("ACE.Server.WorldObjects.Creature", ("GetCreatureSkill", "Stamina", "Strength")),
    ("ACE.Server.WorldObjects.Entity.CreatureSkill", ("InitLevel",)),
    ("ACE.Server.WorldObjects.Entity.CreatureVital", ("Current",)),
    ("ACE.Server.WorldObjects.Entity.CreatureAttribute", ("StartingValue",)),
    ("ACE.Server.WorldObjects.WorldObject", ("EncumbranceVal",)),
    ("ACE.Server.WorldObjects.Player", ("AugmentationIncreasedCarryingCapacity",)),
    ("ACE.Entity.ObjectGuid", (".ctor",)),
    ("ACE.Server.Physics.Common.Position", ("GetCell",)),
    ("ACE.Server.Physics.Common.SetPosition", (".ctor",)),
    ("ACE.Server.Physics.Common.SetPositionFlags", ("Slide", "DontCreateCells")),
    ("ACE.Server.Physics.Animation.ObjectInfoState", ("Default",)),
    # a tick scene (scene/4): the clock, the inputs, the two drivers and the mover read back after each tick (Facade.RunTicks)
    ("ACE.Server.Entity.Timers", ("PortalYearTicks",)),
    ("ACE.Server.Physics.Common.PhysicsTimer", ("CurrentTime",)),
    ("ACE.Server.Physics.PhysicsObj", ("update_object",
                                       "UpdateTime", "Acceleration", "Omega", "CachedVelocity", "JumpedThisFrame",
                                       "set_velocity", "set_local_velocity", "set_omega", "calc_acceleration",
                                       "set_on_walkable", "RemoveLinkAnimations", "IsAnimating", "IsMovingOrAnimating",
                                       # several movers (scene/8 others): every mover's table read after each tick
                                       "CollisionTable")),
    ("ACE.Server.Physics.Collision.CollisionRecord", ("TouchedTime", "Ethereal")),
    ("ACE.Server.Physics.PartArray", ("Sequence",)),
    # children (scene/8 `parent`): the client's calls that parent a wielded item (Facade.SetParent)
    ("ACE.Server.Physics.PhysicsObj", ("ID", "SetPlacementFrame", "set_parent", "unset_parent")),
    ("ACE.Server.Physics.Animation.Sequence", ("SetVelocity", "SetOmega")),
    # the motion layer (scene/6, mover.motion): the mover's MotionTable and Animation records, and a MoveToState
    ("ACE.DatLoader.FileTypes.MotionTable", (".ctor", "Unpack")),
    ("ACE.DatLoader.FileTypes.Animation", (".ctor", "Unpack")),
    ("ACE.Server.Physics.PhysicsObj", ("get_minterp", "MovementManager")),
    ("ACE.Server.Physics.Animation.MovementManager", ("MotionInterpreter",)),
    ("ACE.Server.Physics.Animation.MotionInterp", ("PendingMotions",)),
    ("ACE.Server.Physics.Animation.MotionInterp", ("RawState", "InterpretedState", "motion_allows_jump",
                                                   "apply_raw_movement")),
    ("ACE.Server.Physics.Animation.RawMotionState", ("SetState",)),
    # the server's calls into the managers (Facade.StopMovement, KeyMotion, MoveToPosition, TurnToHeading, ObjectMove,
    # and the tick input stick_to: a melee swing's stick_to_object)
    ("ACE.Server.Physics.PhysicsObj", ("StopCompletely", "cancel_moveto", "MovementManager", "DoMotion", "StopMotion",
                                       "MoveToPosition", "MoveToObject", "TurnToHeading", "TurnToObject",
                                       "stick_to_object")),
    ("ACE.Server.Physics.Animation.MovementManager", ("MoveToManager",)),
    ("ACE.Server.Physics.Animation.MoveToManager", ("CancelMoveTo", "FailProgressCount")),
    ("ACE.Server.Physics.Managers.ServerObjectManager", ("GetObjectA",)),
    ("ACE.Server.Physics.Animation.MovementParameters", (".ctor", "Flags", "DistanceToObject", "MinDistance",
                                                         "FailDistance", "Speed", "WalkRunThreshold", "DesiredHeading",
                                                         "HoldKeyToApply")),
    # the motion layer read back after each tick (Facade.WriteMotion; outcome/5's TickState.motion)
    ("ACE.Server.Physics.PhysicsObj", ("MovementManager", "IsMovingTo")),
    ("ACE.Server.Physics.Animation.MovementManager", ("MotionInterpreter", "MoveToManager")),
    ("ACE.Server.Physics.Animation.MoveToManager", ("MovementType",)),
    ("ACE.Server.Physics.Animation.InterpretedMotionState", ("CurrentStyle", "ForwardCommand", "ForwardSpeed",
                                                             "SideStepCommand", "SideStepSpeed", "TurnCommand", "TurnSpeed")),
    ("ACE.Server.Physics.Animation.RawMotionState", ("CurrentStyle", "ForwardCommand", "ForwardSpeed", "SideStepCommand",
                                                     "SideStepSpeed", "TurnCommand", "TurnSpeed")),
    ("ACE.Server.Physics.Animation.Sequence", ("CurrAnim", "FrameNumber", "Velocity", "Omega")),
    ("ACE.Server.Physics.Animation.AnimSequenceNode", ("Anim",)),
    ("ACE.Server.Physics.Animation.Animation", ("ID",)),
    ("ACE.Server.Network.Structure.RawMotionState", (".ctor", "CurrentHoldKey", "CurrentStyle", "ForwardCommand",
                                                     "ForwardHoldKey", "ForwardSpeed", "SidestepCommand",
                                                     "SidestepHoldKey", "SidestepSpeed", "TurnCommand", "TurnHoldKey",
                                                     "TurnSpeed")),
    ("ACE.Server.Physics.TransientStateFlags", ("Contact", "WaterContact")),
    ("ACE.Server.Physics.Polygon", (".ctor", "Vertices", "VertexIDs", "make_plane")),
    ("ACE.Server.Physics.Sphere", (".ctor", "Center", "Radius")),
    ("ACE.Server.Physics.Animation.AFrame", (".ctor", "Origin", "Orientation")),
    ("ACE.Server.Physics.Animation.Transition", ("MakeTransition", "InitObject", "InitSphere", "InitPath",
                                                 "FindValidPosition", "CleanupTransition", "SpherePath",
                                                 "CollisionInfo", "ObjectInfo")),
    ("ACE.Server.Physics.Animation.ObjectInfo", ("State",)),
    ("ACE.Server.Physics.Animation.SpherePath", ("CurCell", "CurPos", "CheckCell", "Walkable", "StepUp", "NegPolyHit")),
    ("ACE.Server.Physics.Collision.CollisionInfo", (
        "ContactPlaneValid", "ContactPlane", "ContactPlaneCellID", "ContactPlaneIsWater",
        "LastKnownContactPlaneValid", "LastKnownContactPlane", "LastKnownContactPlaneCellID",
        "LastKnownContactPlaneIsWater", "CollisionNormalValid", "CollisionNormal", "SlidingNormalValid",
        "SlidingNormal", "CollidedWithEnvironment", "FramesStationaryFall")),
    # oracle/functions.py: single ACE routines for the per-function differential tests
    ("ACE.Server.Physics.Polygon", (
        "Plane", "PosSurface", "Equals", "point_in_poly2D", "point_in_polygon", "find_crossed_edge",
        "polygon_hits_sphere", "polygon_hits_sphere_precise", "hits_sphere", "pos_hits_sphere",
        "walkable_hits_sphere", "check_walkable", "check_small_walkable", "adjust_sphere_to_plane",
        "adjust_sphere_to_poly", "adjust_to_placement_poly", "polygon_hits_ray")),
    ("ACE.Entity.Enum.Sidedness", ("Positive", "Negative")),
    ("ACE.Server.Physics.Entity.Vertex", ("Origin",)),
    ("ACE.Server.Physics.Ray", (".ctor",)),
    ("ACE.Server.Physics.Sphere", ("FindTimeOfCollision", "CollidesWithSphere", "Intersects", "SphereIntersectsRay")),
    ("ACE.Server.Physics.Animation.SpherePath", (".ctor", "WalkableAllowance", "WalkInterp")),
    ("ACE.Server.Physics.Common.LandDefs", (
        "GetBlockOffset", "AdjustToOutside", "blockid_to_lcoord", "gid_to_lcoord", "get_outside_lcoord",
        "lcoord_to_gid", "inbound_valid_cellid", "cell_in_range", "InBlock")),
    ("ACE.Server.Physics.Common.Landblock", (
        "GetZ", "get_landcell", "calc_water_depth", "VertexArray", "Polygons", "SWtoNEcut", "LandCells",
        "WaterType", "SideCellCount", "MinZ", "MaxZ")),
    ("ACE.Server.Physics.Common.VertexArray", ("Vertices",)),
    ("ACE.Server.Physics.Common.ObjCell", ("WaterType", "Pos")),
    ("ACE.Server.Physics.Animation.AFrame", ("LocalToGlobal", "GlobalToLocal", "LocalToGlobalVec", "GlobalToLocalVec",
                                             "Combine")),
    ("ACE.Server.Physics.Common.Position", ("GetOffset", "LocalToLocal", "LocalToGlobal")),
    # the launch solvers (tests/port/functions/test_trajectory_live.py)
    ("ACE.Server.Physics.Trajectory", ("IsZero", "SolveQuadric", "SolveCubic", "SolveQuartic", "ballistic_range",
                                       "solve_ballistic_arc", "SolveBallisticArc", "solve_ballistic_arc_lateral")),
    ("ACE.Server.Physics.Trajectory2", ("CalculateTrajectory",)),
    # projectiles (scene/8 others[].launch: Facade.SceneLaunch and the methods after it): the WorldObject members ACE's
    # launch and hit code uses, the projectile classes, and the server landblock's object tables
    ("ACE.Server.WorldObjects.WorldObject", ("PhysicsObj", "CurrentLandblock", "ProjectileSource", "ProjectileTarget",
                                             "Ethereal", "ReportCollisions", "IgnoreCollisions", "Missile", "AlignPath",
                                             "PathClipped", "GravityStatus", "AllowEdgeSlide", "RotationSpeed", "Destroy",
                                             "OnCollideEnvironment", "Guid")),
    ("ACE.Server.WorldObjects.Ammunition", ()),
    ("ACE.Server.WorldObjects.SpellProjectile", ("SpellType", "WorldEntryCollision")),
    ("ACE.Server.Entity.ProjectileSpellType", ("Bolt", "Arc")),
    ("ACE.Server.Entity.Landblock", ("pendingAdditions", "worldObjects", "pendingRemovals")),
    ("ACE.Server.Physics.PhysicsObj", ("ProjectileTarget", "CachedVelocity", "GetHeight", "transition", "set_active",
                                       "is_active", "IsAnimating", "InitialUpdates", "update_object", "Omega")),
    ("ACE.Server.Physics.Animation.AFrame", ("set_vector_heading",)),
)


# ACE's build stamp (ServerBuildInfo_Dynamic.cs, `ServerBuildInfo.Commit`) for the source the port follows
# (oracle/identity.py tells a build of it from any other ACE, which loads too).
# ACE's CI commits the stamp after each change: 7b47913 is such a commit and stamps its parent
# bab7a5c, where the physics is as of 7b47913. A build of 7b47913's tree carries bab7a5c; a build
# whose stamp was regenerated at build time carries 7b47913 itself.
ACE_COMMIT = "7b47913"
ACE_BUILD_COMMITS = ("bab7a5ca8552cb18f63e08b57234bd9137cd0249", "7b47913")


def check_members(find_type, has_member, where: str, required=REQUIRED) -> None:
    """Raise OracleUnavailable naming every type or member `required` lists that is absent.

    `find_type(full_name)` returns a type handle or None; `has_member(type, name)` says whether the
    member exists. Both are supplied by the runtime (oracle/runtime.py), so this logic is tested
    without .NET.
    """
    missing = []
    for type_name, members in required:
        t = find_type(type_name)
        if t is None:
            missing.append(f"type {type_name}")
            continue
        for m in members:
            if not has_member(t, m):
                missing.append(f"{type_name}.{m}")
    if missing:
        shown = ", ".join(missing[:8]) + (f" (and {len(missing) - 8} more)" if len(missing) > 8 else "")
        raise OracleUnavailable(
            f"the ACE build at {where} lacks what the oracle needs: {shown}. The port follows ACE's "
            f"physics as of commit {ACE_COMMIT}; point --ace / ACE_ASSEMBLY at an ACE build that has these "
            "members (see docs/oracle.md)")
