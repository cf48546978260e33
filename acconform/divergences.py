"""Known divergences, ACE versus retail, as data: where a first divergence is ACE's quirk, not a bug.

Each `Known` row names the ACE methods (``File.cs:Method``, as trace records name them) where an
implementation that follows retail parts from ACE, what ACE does, what retail does, where the row
comes from, and two checks that keep it true: text that must be (and must not be) in ACE's source
at the pinned commit, and in the port's source (the port follows ACE). tests/test_known_divergences.py
runs both checks and checks that docs/divergences.md holds the table `markdown()` writes.

`known_for(divergence)` is the row a first divergence (acconform.trace.Divergence) matches, if
any: `check` and `explain` then label it "known: ACE differs from retail here".
"""

from __future__ import annotations

from dataclasses import dataclass

ACE_COMMIT = "7b47913"
ACE_PHYSICS = "Source/ACE.Server/Physics/"


@dataclass(frozen=True, slots=True)
class SourceCheck:
    path: str  # under ACE's Source/ACE.Server/Physics/, or the port's port/
    present: tuple[str, ...]  # each must be in the file
    absent: tuple[str, ...] = ()  # none may be


@dataclass(frozen=True, slots=True)
class Known:
    name: str
    anchors: tuple[str, ...]  # ACE methods where a retail-following implementation parts from ACE
    ace_does: str
    retail_does: str
    source: str  # where the row comes from
    pinned_by: str  # the test that pins ACE's behaviour in the port
    ace: SourceCheck
    port: SourceCheck
    fields: tuple[str, ...] = ()  # the trace fields (prefixes) where it shows; empty: any field


DERETH = "dereth docs/CORRECTIONS.md, section 2"
DOCS = "docs/divergences.md (this project)"
REGISTRY_TEST = "tests/test_known_divergences.py::test_each_known_divergence_is_in_aces_source_and_in_the_port"

KNOWN: tuple[Known, ...] = (
    Known("terrain_never_walkable", ("LandCell.cs:FindEnvCollisions",),
          "terrain never sets `SpherePath.Walkable`, so a mover walking off a terrain edge goes through cliff slide "
          "or the back-probe; precipice slide happens only off BSP geometry",
          "the terrain polygon becomes the walkable polygon and the mover precipice-slides along its crossed edge "
          "(acdream's retail port does this)", DOCS,
          "tests/port/transition/test_divergences.py::test_terrain_never_sets_the_walkable_polygon_so_its_edges_never_precipice_slide",
          SourceCheck("Common/LandCell.cs", ("FindEnvCollisions",), ("Walkable =",)),
          SourceCheck("cell/land_cell.py", ("def find_env_collisions",), ("path.walkable =", "sp.walkable =")),
          ("path.walkable",)),
    Known("aframe_equals_orientation", ("AFrame.cs:Equals",),
          "`AFrame.Equals` compares the other frame's orientation with itself, so only origins count",
          "compares both frames' orientations", DOCS,
          "tests/port/test_frame.py::test_frame_equals_ignores_orientation_as_ace_does",
          SourceCheck("Animation/AFrame.cs", ("Math.Abs(frame.Orientation.X - frame.Orientation.X)",)),
          SourceCheck("frame.py", ("abs(q.x - q.x) <= EPSILON",)), ("result",)),
    Known("add_cell_block_own_landblock", ("LandCell.cs:add_cell_block", "PhysicsObj.cs:add_obj_to_cell"),
          "skips every cell outside the placing cell's landblock (ACE's `FIXME!`), so a BSP object or sphere placed "
          "through `find_bbox_cell_list` is registered only in its own landblock",
          "adds every cell of the rectangle inside the world (0..2039); no landblock test", DOCS,
          "tests/port/objects/test_straddle_scenes.py::test_a_bbox_placed_object_across_a_landblock_border_is_registered_only_in_its_own_landblock",
          SourceCheck("Common/LandCell.cs", ("// FIXME!", "if (id >> 16 != cellID >> 16)")),
          SourceCheck("cell/land_cell.py", ("if id >> 16 != cell_id >> 16:",))),
    Known("max_quantum", ("PhysicsObj.cs:update_object",),
          "`PhysicsGlobals.MaxQuantum = 0.1f` (10 fps; retail's 0.2f commented out as \"buggy with MoveToManager "
          "turning\"): a tick of 0.15 s is two sub-steps",
          "`MaxQuantum` 0.2 s (5 fps): the same tick is one sub-step", DOCS + "; " + DERETH + " (the quantum)",
          "tests/port/test_physics_obj_tick.py::test_a_tick_of_0_15_s_is_two_sub_steps_as_aces_max_quantum_is_0_1_not_retails_0_2",
          SourceCheck("PhysicsGlobals.cs", ("public const float MaxQuantum = 0.1f;", "//public const float MaxQuantum = 0.2f;")),
          SourceCheck("constants.py", ("MAX_QUANTUM = f32_from_bits(0x3DCCCCCD)",)),
          # another quantum shows as the arguments update_object hands its sub-steps; a different callee (another
          # mover stepped first, a step skipped) is no quantum of retail's
          ("args",)),
    Known("sledding_threshold", ("PhysicsObj.cs:calc_friction",),
          "takes the low-friction sledding branch (0.2) at 2.5 m/s or more when the contact plane is nearly flat: "
          "`ContactPlane.Normal.Z > 0.99999536f`",
          "takes it when the contact plane normal's Z is below cos(10 deg) = 0.98480775, on slopes steeper than "
          "about ten degrees: the test's direction and its constant differ", DERETH + " (ACE's friction branch)",
          REGISTRY_TEST,
          SourceCheck("PhysicsObj.cs", ("ContactPlane.Normal.Z > 0.99999536f",)),
          SourceCheck("constants.py", ("SLEDDING_FLAT_Z = f32_from_bits(0x3F7FFFB2)",))),
    Known("speed_cap", ("PhysicsObj.cs:UpdatePhysicsInternal",),
          "caps the velocity at `PhysicsGlobals.MaxVelocity` = 50 m/s in UpdatePhysicsInternal",
          "has no speed cap (a server addition: a client-side port that adds it refuses legitimate motion)",
          DERETH + " (ACE's movement limits)", REGISTRY_TEST,
          SourceCheck("PhysicsObj.cs", ("if (velocity_mag2 > PhysicsGlobals.MaxVelocitySquared)",)),
          SourceCheck("physics_obj.py", ("if velocity_mag2 > MAX_VELOCITY_SQUARED:",))),
    Known("static_cell_search", ("LandCell.cs:add_cell_block", "EnvCell.cs:find_transit_cells(int, List<PhysicsPart>, CellArray)",
                                 "PhysicsObj.cs:add_obj_to_cell"),
          "lists a static object only in its own landblock's land cells, follows a cell's portal only into a cell "
          "that cell itself sees, and finds the land cells a part's box covers from the part's own position",
          "lists a static in every loaded cell its boxes reach, in any landblock, through any portal, measuring the "
          "boxes from the static's land cell", DERETH + " (ACE's static cell search)", REGISTRY_TEST,
          SourceCheck("Common/LandCell.cs", ("if (id >> 16 != cellID >> 16)",)),
          SourceCheck("cell/land_cell.py", ("if id >> 16 != cell_id >> 16:",))),
    Known("terrain_split", ("LandblockStruct.cs:ConstructPolygons", "LandblockStruct.cs:FSplitNESW"),
          "its physics copy of the split (`FSplitNESW`) divides part of the hash by 2147483648; the polygons "
          "ACE's physics collides with are cut by ConstructPolygons' `splitDir * 2.3283064e-10 < 0.5f` (in "
          "double: the sign bit of the hash but for splitDir 2^31..2^31+33)",
          "the split is the sign bit of the 32-bit hash `x*y*0x0CCAC033 + y*0x6C1AC587 - x*0x421BE3BD - "
          "0x519B8F25` over the global cell coordinates, one rule for rendering and standing",
          DERETH + " (ACE's physics copy of the terrain split)", REGISTRY_TEST,
          SourceCheck("Common/LandblockStruct.cs", ("(y * 0x6C1AC587 - 0x519B8F25) / 2147483648", "2.3283064e-10")),
          SourceCheck("land/landblock_struct.py", ("split_dir * SPLIT_SCALE < 0.5", "2147483648"))),
)


def known_for(divergence) -> Known | None:
    """The registered row a first divergence matches: its routine is one of the row's ACE methods and
    its field one the row names (any, when it names none); None when no row does."""
    if divergence is None:
        return None
    return next((k for k in KNOWN if divergence.routine in k.anchors
                 and (not k.fields or any(divergence.field.startswith(f) for f in k.fields))), None)


TABLE_BEGIN = "<!-- known divergences: generated from acconform/divergences.py; do not edit -->"
TABLE_END = "<!-- end of known divergences -->"


def markdown() -> str:
    rows = ["| name | where (ACE) | ACE does | retail does | source | pinned by |", "|---|---|---|---|---|---|"]
    for k in KNOWN:
        rows.append(f"| `{k.name}` | {', '.join(f'`{a}`' for a in k.anchors)} | {k.ace_does} | {k.retail_does} | "
                    f"{k.source} | `{k.pinned_by}` |")
    return "\n".join(rows)
