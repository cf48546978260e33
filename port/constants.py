"""PhysicsGlobals and the other float32 constants the collision code uses (ACE PhysicsGlobals.cs).

Each value is the exact float32 C# stores, written as a Python float so that it takes the
run's scalar type (see acconform.numerics); tests pin every one by its bit pattern.
"""

from acconform.numerics import f32_from_bits

# PhysicsGlobals.EPSILON = 0.0002f
EPSILON = f32_from_bits(0x3951B717)
# PhysicsGlobals.EpsilonSq = EPSILON * EPSILON, folded by the C# compiler in float32
EPSILON_SQ = f32_from_bits(0x332BCC76)
# PhysicsGlobals.FloorZ = 0.66417414618662751f: cos(48.4 deg); one ulp decides standing vs sliding
FLOOR_Z = f32_from_bits(0x3F2A0751)
# PhysicsGlobals.LandingZ = 0.0871557f: cos(85 deg), the walkable allowance when landing
LANDING_Z = f32_from_bits(0x3DB27EB0)
# PhysicsGlobals.DummySphereRadius = 0.1f; DummySphere = Sphere((0, 0, 0.1), 0.1)
DUMMY_SPHERE_RADIUS = f32_from_bits(0x3DCCCCCD)
# PhysicsGlobals.Gravity = -9.8f
GRAVITY = f32_from_bits(0xC11CCCCD)
# PhysicsGlobals.DefaultStepHeight = 0.01f
DEFAULT_STEP_HEIGHT = f32_from_bits(0x3C23D70A)
# Transition.cs StepDown/CheckWalkable literal 0.039999999f: the probe distance for edges
STEP_DOWN_PROBE = f32_from_bits(0x3D23D70A)
# Position.ThresholdMed = 1.0f / 3.0f and ThresholdHigh = 2.0f / 3.0f (DetermineQuadrant's height bands)
THRESHOLD_MED = f32_from_bits(0x3EAAAAAB)
THRESHOLD_HIGH = f32_from_bits(0x3F2AAAAB)
# LandDefs: BlockLength 192, CellLength 24, 8 cells a side, 9 vertices a side
BLOCK_LENGTH = 192.0
CELL_LENGTH = 24.0
SIDE_CELL_COUNT = 8
VERTEX_PER_CELL = 1
SIDE_VERTEX_COUNT = 9

# Sphere.cs / CylSphere.cs IntersectsSphere and StepSphereDown: `timecheck < -0.1f`
STEP_INTERP_LIMIT = f32_from_bits(0xBDCCCCCD)
# Polygon.cs adjust_sphere_to_plane: `interp < -0.5f`, the furthest a walkable adjustment may reach back
ADJUST_TO_PLANE_INTERP_LIMIT = f32_from_bits(0xBF000000)
# BSPNode.cs sphere_intersects_cell_bsp: `curSphere.Radius + 0.01f`
CELL_BSP_SLACK = f32_from_bits(0x3C23D70A)
# LandblockStruct.cs calc_water_depth: 0.44999999f where the nearest terrain corner is water, else 0.1f
WATER_DEPTH_PARTIAL_WATER = f32_from_bits(0x3EE66666)
# ObjCell.cs get_water_depth: 0.89999998f in a cell that is entirely water
WATER_DEPTH_ENTIRELY_WATER = f32_from_bits(0x3F666666)
# both: 0.1f on dry land
WATER_DEPTH_DRY = f32_from_bits(0x3DCCCCCD)
# PhysicsGlobals.DefaultScale = 1.0f
DEFAULT_SCALE = f32_from_bits(0x3F800000)
# PhysicsObj.cs InitPartArrayObject: SetTranslucencyInternal(0.25f) for an ethereal anim object
TRANSLUCENCY_ETHEREAL = f32_from_bits(0x3E800000)
# Transition.cs FindPlacementPos: the spiral search's reach `adjustDist = 4.0f`, halved (`2.0f`) for a
# sphere under `0.125f` (a "fake sphere"), whose radius is otherwise taken as at least `0.48f`
PLACEMENT_ADJUST_DIST = f32_from_bits(0x40800000)
PLACEMENT_FAKE_ADJUST_RAD = f32_from_bits(0x40000000)
PLACEMENT_FAKE_SPHERE_RADIUS = f32_from_bits(0x3E000000)
PLACEMENT_MIN_RADIUS = f32_from_bits(0x3EF5C28F)
# PhysicsObj.cs CheckPositionInternal: a placement moved less than `0.05f` in x and in y is kept
PLACEMENT_CLOSE = f32_from_bits(0x3D4CCCCD)
# QuaternionExtensions.IsValid: `Math.Abs(length - 1.0f) > PhysicsGlobals.EPSILON * 5.0f`, folded in float32
QUAT_VALID_SLACK = f32_from_bits(0x3A83126E)
# PhysicsGlobals.DefaultElasticity = 0.05f (PhysicsObj() sets Elasticity to it)
DEFAULT_ELASTICITY = f32_from_bits(0x3D4CCCCD)

# ---- the motion interpreter (Animation/MotionInterp.cs CMotionInterp's const floats)
# BackwardsFactor = 6.4999998e-1f: walking backward is walking forward at -0.65 of the speed
BACKWARDS_FACTOR = f32_from_bits(0x3F266666)
# MaxSidestepAnimRate = 3.0f, RunAnimSpeed = 4.0f, RunTurnFactor = 1.5f, SidestepAnimSpeed = 1.25f,
# SidestepFactor = 0.5f, WalkAnimSpeed = 3.1199999f
MAX_SIDESTEP_ANIM_RATE = f32_from_bits(0x40400000)
RUN_ANIM_SPEED = f32_from_bits(0x40800000)
RUN_TURN_FACTOR = f32_from_bits(0x3FC00000)
SIDESTEP_ANIM_SPEED = f32_from_bits(0x3FA00000)
SIDESTEP_FACTOR = f32_from_bits(0x3F000000)
WALK_ANIM_SPEED = f32_from_bits(0x4047AE14)
# adjust_motion's `SidestepFactor * (WalkAnimSpeed / SidestepAnimSpeed)`: const fields, folded by the C#
# compiler in float32 (3.1199999f / 1.25f, then * 0.5f)
SIDESTEP_SPEED_SCALE = f32_from_bits(0x3F9FBE76)
# MovementParameters.Default_DistanceToObject = 0.6f; Default_WalkRunThreshold = 1.0f (ACE's; 15.0f is
# commented out beside it)
DEFAULT_DISTANCE_TO_OBJECT = f32_from_bits(0x3F19999A)
DEFAULT_WALK_RUN_THRESHOLD = f32_from_bits(0x3F800000)
# MovementSystem.GetJumpHeight: `jumpSkill / (jumpSkill + 1300.0f) * 22.2f + 0.05f`, at least `0.35f`
JUMP_SKILL_HEIGHT = f32_from_bits(0x41B1999A)
JUMP_BASE_HEIGHT = f32_from_bits(0x3D4CCCCD)
MIN_JUMP_HEIGHT = f32_from_bits(0x3EB33333)
# WeenieObject.InqJumpVelocity: `Math.Sqrt(height * 19.6)`, a double literal (2 * 9.8: v^2 = 2 g h)
JUMP_VELOCITY_FACTOR = 19.6
# MovementSystem.GetRunRate: `18.0f / 4.0f` (folded in float32) at a run skill of `800.0f` or more
MAX_RUN_RATE = f32_from_bits(0x40900000)
RUN_SKILL_FOR_MAX_RATE = f32_from_bits(0x44480000)

# ---- the tick (PhysicsObj.update_object and what it calls). All are C# `float`s; update_object
# compares and steps its `double` deltaTime against them, which widens each to double exactly, so
# each is written here once as its float32 value (a Python float: double where the code is double).
# PhysicsGlobals.MinQuantum = 1.0f / 30.0f, folded by the C# compiler in float32 (30 fps)
MIN_QUANTUM = f32_from_bits(0x3D088889)
# PhysicsGlobals.MaxQuantum = 0.1f (10 fps; ACE's, where retail's is 0.2f)
MAX_QUANTUM = f32_from_bits(0x3DCCCCCD)
# PhysicsGlobals.HugeQuantum = 2.0f (0.5 fps): a longer gap is skipped, not simulated
HUGE_QUANTUM = f32_from_bits(0x40000000)
# PhysicsObj.TickRate = 1.0f / 30.0f (a static float field, not a const; the same value as MinQuantum)
TICK_RATE = f32_from_bits(0x3D088889)
# PhysicsGlobals.MaxVelocity = 50.0f; MaxVelocitySquared = MaxVelocity * MaxVelocity (folded in float32)
MAX_VELOCITY = f32_from_bits(0x42480000)
MAX_VELOCITY_SQUARED = f32_from_bits(0x451C4000)
# PhysicsGlobals.SmallVelocity = 0.25f; SmallVelocitySquared = SmallVelocity * SmallVelocity
SMALL_VELOCITY = f32_from_bits(0x3E800000)
SMALL_VELOCITY_SQUARED = f32_from_bits(0x3D800000)
# PhysicsGlobals.DefaultFriction = 0.95f (PhysicsObj() sets Friction to it)
DEFAULT_FRICTION = f32_from_bits(0x3F733333)
# PhysicsObj.calc_friction: no friction when `Vector3.Dot(Velocity, ContactPlane.Normal) >= 0.25f`
FRICTION_LEAVING_ANGLE = f32_from_bits(0x3E800000)
# calc_friction, sledding: friction 1.0f below `velocity_mag2 < 1.5625f` (1.25 m/s squared) ...
SLEDDING_STOP_SPEED_SQUARED = f32_from_bits(0x3FC80000)
SLEDDING_STOP_FRICTION = f32_from_bits(0x3F800000)
# ... and 0.2f at `velocity_mag2 >= 6.25f` (2.5 m/s squared) on a plane with `Normal.Z > 0.99999536f`
# (ACE's sledding threshold; other ports use cos 10 degrees)
SLEDDING_GLIDE_SPEED_SQUARED = f32_from_bits(0x40C80000)
SLEDDING_FLAT_Z = f32_from_bits(0x3F7FFFB2)
SLEDDING_GLIDE_FRICTION = f32_from_bits(0x3E4CCCCD)
# CollisionRecord: report_collision_end ends a record touched more than `1.0f` second ago
COLLISION_RECORD_LIFETIME = f32_from_bits(0x3F800000)

# ---- the motion layer's managers (Physics/Managers). C# `float` literals that are not exact binary32.
# InterpolationManager: a node is reached within `0.05f`; a mover making less than `0.3f` of its
# speed's progress over five frames fails the node
INTERPOLATION_NODE_REACHED = f32_from_bits(0x3D4CCCCD)
INTERPOLATION_MIN_PROGRESS = f32_from_bits(0x3E99999A)
# InterpolationManager.LargeDistance = 999999.0f (exact; the OriginalDistance with no node)
INTERPOLATION_LARGE_DISTANCE = f32_from_bits(0x497423F0)
# StickyManager.StickyRadius = 0.3f: the gap a sticky mover keeps to its target's cylinder
STICKY_RADIUS = f32_from_bits(0x3E99999A)
# MoveToManager.HandleMoveToPosition: a velocity longer than `0.1f` re-times the target quantum
MOVE_TO_MIN_VELOCITY = f32_from_bits(0x3DCCCCCD)
# ConstraintManager.IsFullyConstrained: `ConstraintDistanceMax * 0.9f < ConstraintPosOffset`
CONSTRAINT_FULL_FRACTION = f32_from_bits(0x3F666666)
# float.MaxValue (MovementParameters.Default_FailDistance, MoveToManager's "no distance yet")
FLOAT_MAX_VALUE = f32_from_bits(0x7F7FFFFF)
