"""The DAT records a scene's static objects are made from: scene object -> DatLoader-layout bytes.

ACE builds a static object from portal DAT records: `PhysicsObj.makeObject(did, ...)` reads a
`GfxObj` (0x01xxxxxx) or a `Setup` (0x02xxxxxx) through `DatManager.PortalDat.ReadFromDat`, and
ACE's constructors (`GfxObj(DatLoader GfxObj)`, `BSPTree(DatLoader BSPTree, polys, vertices)`,
`Setup(SetupModel)`, `PartArray.CreateMesh/CreateSetup`) turn them into physics objects. A scene
carries no DAT, so this module writes, for each static, the records ACE would read, in the exact
byte layout of ACE.DatLoader's `Unpack` (FileTypes/GfxObj.cs, FileTypes/SetupModel.cs,
Entity/CVertexArray.cs, SWVertex.cs, Polygon.cs, BSPTree.cs, BSPNode.cs, BSPLeaf.cs, Sphere.cs,
CylSphere.cs, Plane.cs). The oracle unpacks them with ACE's own `Unpack`; the port reads them with
its port of DatLoader (port/dat/). This is data encoding only: no physics, no rule.

What each shape becomes (`static_records(obj, index)`):

- **BSP**: one GfxObj, id ``0x01000001 + index``; `makeObject` takes that id (DivineType 6 ->
  `PartArray.CreateMesh` -> `Setup.MakeSimpleSetup`). Flags `HasPhysics`; no surfaces; vertex array
  type 1 holding every polygon's vertices in scene order, deduplicated by exact float32 bits (first
  appearance), ids 0..n-1, no UVs, zero normals; physics polygons keyed by their scene index
  (Stippling ``NoPos|NoNeg``: no UV indices; surfaces 0); the physics BSP tree in pre-order, an
  internal node tagged ``BPIN`` (front = PosNode, then back = NegNode), a leaf ``LEAF`` with its
  pre-order leaf ordinal as LeafIndex. The shape's own `sphere` is not written: ACE takes
  GfxObj.PhysicsSphere from the tree's root. SortCenter (0, 0, 0).
- **sphere / cylsphere**: a Setup, id ``0x02000001 + index``, with the shape's sphere or cylsphere
  and one part (a Setup with no part gets no PartArray in ACE: `PartArray.InitParts` fails). The
  part is a GfxObj, id ``0x01000001 + index``, with no physics and no drawing whose vertices are the
  8 corners of the shape's axis-aligned box in object space (what `GfxObj.Init` bounds and
  `find_bbox_cell_list` reads for a sphere): corner k = (k&1 ? hi.x : lo.x, k&2 ? hi.y : lo.y,
  k&4 ? hi.z : lo.z), sphere lo/hi = centre -/+ radius, cylsphere x, y = low point -/+ radius and
  z = low point z .. + height (float32 arithmetic). No placement frames, so the part sits at the
  object's position (`PartArray.UpdateParts`); Height, Radius, step heights 0; sorting and
  selection spheres zero.

- **setup** (scene/7, a Setup of several parts; `setup_records`): each part a physics GfxObj
  written as a BSP static's, id ``0x01F00000 + 16 index + k`` for part k (`PART_GFX_OBJ_BASE`; at
  most 16 parts, index below 0xE000, so these ids end below the others' parts), then a Setup,
  id ``0x02000001 + index``, naming the parts in order: flags HasParent with a `parent_index` (scene/8:
  then one uint per part, the DAT's ParentIndex, which ACE's physics never reads) and HasDefaultScale when
  the parts have scales (then each part's scale, in order), one placement frame keyed 0 (Placement.Default, which
  `PartArray.SetPlacementFrame` falls back to when 0x65 is absent) holding each part's frame and no
  hooks, the Setup's cylspheres and spheres, Height, Radius and step heights 0 as every static's.
  With a `default_animation` (scene/8) the Setup's DefaultAnimation is an Animation, id
  ``0x03F00000 + index`` (`STATIC_ANIMATION_BASE`, above the mover's table's), of one frame holding those
  part frames (one per part) and no PosFrames or hooks.

The mover (`mover_records(mover)`) is made the same way, from a Setup, id ``0x02000000``, with
the mover's spheres and step heights, Height and Radius 0 (ACE's transition never reads a Setup's
Height or Radius: only MoveToManager and StickyManager do), flags AllowFreeHeading (0x4) when the mover has
`free_heading` (scene/8) and 0 otherwise, and one part, a GfxObj mesh, id
``0x01000000``, with no vertices (nothing reads the mover's own bounding box in a transition). Its
HoldingLocations (scene/8 `holding_locations`) are written in the order given; another mover's Setup
(`other_records`) likewise, with its sorting sphere (`sorting_sphere`, zero when none: a child's cells).
With a `setup` (scene/8 `others[].setup`) its parts are written as a static's Setup's, GfxObj ids
``0x01FE0000 + 16 index + k`` (`OTHER_PART_GFX_OBJ_BASE`; index below 0x1000, so they end below the buildings'
shells) before its Setup, with their placement frame (keyed 0), DefaultScale and the setup's cylspheres.

**Drawn** (scene/8 `drawing`): every polygon is written with Stippling 0 and its UV indices (vertex i's index
i; a Clockwise polygon's negative ones too), a BSP GfxObj (`gfx_obj_physics`) with flags HasPhysics|HasDrawing|
HasDIDDegrade, one surface (DRAWING_SURFACE), its physics polygons again as its drawing polygons, a drawing BSP over
them (`drawing_bsp_node`, no portals) and DRAWING_DID_DEGRADE, and an EnvCell with one surface. A mesh part (no
polygons) stays as it is.

Records are listed parts first; every record of a scene has a distinct id (the index is the
object's place in the scene's list).

**Indoors** (`environment_record`, `env_cell_record`, `landblock_info_record`; `cell_dat_records`
gathers a scene's cell DAT records, `scene_records` all of them): an `Environment` (portal DAT, its scene id
``0x0D00XXXX``) holds its cell structures keyed by index (FileTypes/Environment.cs,
Entity/CellStruct.cs): per structure one vertex array holding its polygons' and then its physics
polygons' vertices, deduplicated by exact float32 bits as above; polygons and physics polygons keyed
by their scene index (Stippling ``NoPos|NoNeg``, surfaces 0); the portal polygon ids; the cell BSP
in BSPType.Cell's layout (a node: its tag and splitting plane, then its children, no sphere; the tag
says which children follow: ``BPIN`` both, ``BPIn`` the front only, ``BpIN`` the back only, and
``Bpnn`` none -- a tag DatLoader's switch does not list, so it reads no child (``BPnn`` would read a
front child); a leaf ``LEAF`` and its pre-order LeafIndex); the physics BSP as a GfxObj's; then
(hasDrawingBSP 1; 0 and no tree for scene/8 `drawing_bsp: false`) a drawing BSP derived from the polygons and portals (`drawing_bsp`: ACE builds
CellStruct.DrawingBSP from it and its physics never reads it; every portal polygon is in a ``PORT``
node, as in retail's Environments). An `EnvCell` (cell DAT, id = the cell's id; FileTypes/EnvCell.cs): flags SeenOutside
(0x1) and HasStaticObjs (0x2, when it has stabs), no surfaces, the environment's low word, the
structure index, the frame, the portals (flags, polygon, other cell, other portal), the visible
cells, and its stabs: the scene's static objects whose position.cell is this cell, in scene order,
each the id `static_records` gives it and the object's frame (Entity/Stab.cs); then (flag HasRestrictionObj
0x8, scene/8 `restriction_obj`) its restriction object. A `LandblockInfo` (cell DAT, ``0xXXYYFFFE``; FileTypes/LandblockInfo.cs) is written for
each landblock that has EnvCells or buildings: NumCells = the number of its EnvCells (ACE's
AdjustCell loads 0x0100 .. 0x0100 + NumCells - 1 to find the cell holding a point), no objects,
its buildings, PackMask 0 (1 with scene/8 `restrictions`: then the RestrictionTables). A landblock's CellLandblock says HasObjects exactly when it has
buildings (`has_objects`; `cell_landblock` writes it), so ACE's Landblock constructor
reads the Info of a landblock with buildings and PostInit builds them (init_buildings); a
dungeon's Info is read only by AdjustCell, as before.

**Buildings** (`building_records(building, index)`, in the Info `building_info`): the shell is a
GfxObj, id ``0x01FF0000 + index`` (`BUILDING_GFX_OBJ_BASE`; index = the building's place in
the scene's list), written as a BSP static's (`gfx_obj_physics`); its BuildInfo (Entity/BuildInfo.cs)
holds that id as ModelId, the frame, NumLeaves and the portals, each a CBldPortal
(Entity/CBldPortal.cs: flags, OtherCellId, OtherPortalId, the stab count and stabs as ushorts, then
zero bytes to the next multiple of 4 counted from the record's start, as AlignBoundary reads).

**Landblocks** (`cell_landblock`, FileTypes/CellLandblock.cs): Id ``0xXXYYFFFF``, HasObjects (a
uint32, 1 with buildings), the 81 terrain words, the 81 height bytes, zero to a multiple of 4.

**A scene's world as records** (`dat_world`, the protocol's feature `dat`, docs/protocol.md): every
record above in two lists, one per DAT, in the order ACE's facade builds from them (cell: the
CellLandblocks, LandblockInfos, EnvCells; portal: the buildings' shells, Environments, each static's
records, the mover's), with what ACE's facade takes for the statics and the mover that no record
holds (`DatStatic`, `DatMover`) and the land height table.

**Motion tables and animations** (`motion_table_record`, `animation_record`; the motion layer, not yet in
any scene): a `MotionTable` (portal DAT 0x09xxxxxx; FileTypes/MotionTable.cs with Entity/MotionData.cs
and AnimData.cs) and an `Animation` (0x03xxxxxx; FileTypes/Animation.cs with Entity/AnimationFrame.cs,
Frame.cs and the hooks of Entity/AnimationHook.cs), from the plain records `MotionDataRec`,
`AnimDataRec`, `AnimationFrameRec` and `HookRec`. A Setup names them by `setup(...,
default_animation=, default_motion_table=)`; both 0 by default, so existing records keep their bytes.
"""

from __future__ import annotations

import struct
from dataclasses import dataclass

import numpy as np

from .scene import (DEFAULT_SKILLS, MoverSkills, BSPLeaf, ChildOf, BSPShape, Building, CellBSPLeaf, CellStructRec, ContactPlane, CylSphereShape, EnvCell,
                    Environment, Frame, Landblock, Mover, OtherMover, Placement, PolygonRec, Position, Scene, SetupRec, SphereShape,
                    StaticObject,
                    ENV_CELL_FIRST, newell_normal)
from .flags import CullMode
from .staging import MOVER_ID
from .motion_scene import ANIMATION_BASE, HOOKS, MOTION_TABLE_ID, cycle_key

GFX_OBJ_BASE = 0x01000001  # GfxObj id of static object 0 (portal DAT type 0x01: MasterDBMap.DivineType 6)
SETUP_BASE = 0x02000001  # Setup id of static object 0 (portal DAT type 0x02: DivineType 7)
MAX_OBJECTS = 0xEFFFFF  # ids stay inside their DAT type's range, below the parts' and the buildings'
STATIC_ANIMATION_BASE = 0x03F00000  # the DefaultAnimation of static i's Setup of several parts (scene/8)
PART_GFX_OBJ_BASE = 0x01F00000  # GfxObj id of part 0 of static 0's Setup of several parts (scene/7 `setup`)
MAX_PARTS = 16  # each static has 16 part ids: part k of static i is PART_GFX_OBJ_BASE + 16 i + k (scene.MAX_SETUP_PARTS)
MAX_SETUP_OBJECTS = 0xE000  # a static with a setup has an index below this (its parts' ids end below the others')
OTHER_PART_GFX_OBJ_BASE = 0x01FE0000  # GfxObj id of part 0 of other mover 0's Setup of several parts (scene/8 others[].setup)
MAX_SETUP_OTHERS = 0x1000  # an other with a setup has an index below this (its parts' ids end below the buildings')
BUILDING_GFX_OBJ_BASE = 0x01FF0000  # GfxObj id of building 0's shell
MAX_BUILDINGS = 0xFFFF
MOVER_GFX_OBJ_ID = 0x01000000  # the mover's part
MOVER_SETUP_ID = 0x02000000  # the mover's Setup
OTHER_SETUP_BASE = 0x02F00000  # the Setup of other mover k (scene/8 `others`): above every static's Setup id
MAX_OTHERS = 0xFFFF

# ACE.Entity.Enum.GfxObjFlags, StipplingType, SetupFlags
GFX_HAS_PHYSICS = 0x1
GFX_HAS_DRAWING = 0x2
GFX_HAS_DID_DEGRADE = 0x8
# scene/8 `drawing`: what the records carry for drawing (nothing of ACE's physics reads it): a GfxObj's one surface
# and its degrade table, an EnvCell's one surface (its low word; DatLoader ORs 0x08000000 in)
DRAWING_SURFACE = 0x08000001
DRAWING_DID_DEGRADE = 0x11000001
SETUP_HAS_PARENT = 0x1
SETUP_HAS_DEFAULT_SCALE = 0x2
SETUP_ALLOW_FREE_HEADING = 0x4
DEFAULT_PLACEMENT = 0  # ACE.Entity.Enum.Placement.Default: the key PartArray.SetPlacementFrame falls back to
RESTING_PLACEMENT = 0x65  # Placement.Resting: the key PartArray.CreateSetup's (and InitObjectEnd's) SetPlacementFrame(0x65) asks for first
MISSILE_FLIGHT_PLACEMENT = 52  # Placement.MissileFlight: SetupModel.Unpack's HasMissileFlightPlacement (no physics reads it)
STIPPLING_NO_POS = 0x4
STIPPLING_NO_NEG = 0x8
VERTEX_TYPE = 1  # CVertexArray.Unpack reads only type 1

# BSPNode.cs: node type tags, read as 4 ASCII bytes then reversed (so written as these little-endian uint32s)
TAG_BPIN = 0x4250494E  # "BPIN": PosNode then NegNode
TAG_LEAF = 0x4C454146  # "LEAF"
TAG_BPIn = 0x4250496E  # "BPIn": PosNode only
TAG_BpIN = 0x4270494E  # "BpIN": NegNode only
TAG_Bpnn = 0x42706E6E  # "Bpnn": not in DatLoader's switch, so no child is read
TAG_PORT = 0x504F5254  # "PORT": a portal node (BSPPortal.cs): both children always, then (drawing) its portal polygons

# ACE.Entity.Enum.EnvCellFlags
ENV_CELL_SEEN_OUTSIDE = 0x1
ENV_CELL_HAS_STATIC_OBJS = 0x2
ENV_CELL_HAS_RESTRICTION_OBJ = 0x8  # scene/8 env_cells[].restriction_obj
LANDBLOCK_INFO = 0xFFFE  # a landblock's LandblockInfo is 0xXXYYFFFE in the cell DAT

_u16 = struct.Struct("<H")
_u32 = struct.Struct("<I")
_i32 = struct.Struct("<i")
_3f = struct.Struct("<3f")
_4f = struct.Struct("<4f")
_LEAF_HEAD = struct.Struct("<Ii")  # a cell or drawing tree's leaf: its tag and LeafIndex


@dataclass(frozen=True, slots=True)
class DatRecord:
    """One portal DAT file: its id and the bytes `DatDatabase.ReadFromDat` would unpack."""

    id: int
    kind: str  # the DatLoader FileType class: "GfxObj", "SetupModel", "Environment", "MotionTable", "Animation" (portal DAT); "CellLandblock",
    # "EnvCell", "LandblockInfo" (cell DAT)
    data: bytes


@dataclass(frozen=True, slots=True)
class ObjectRecords:
    """What one object (a static or the mover) is made from: `did` is the id `PhysicsObj.makeObject` takes, and
    `records` every record reachable from it (parts first)."""

    did: int
    records: tuple[DatRecord, ...]


def compressed_u32(n: int) -> bytes:
    """BinaryReaderExtensions.ReadCompressedUInt32's layout: 1, 2 or 4 bytes."""
    if n < 0 or n > 0x3FFFFFFF:
        raise ValueError(f"{n} does not fit a compressed uint32")
    if n < 0x80:
        return bytes((n,))
    if n < 0x4000:
        return bytes((0x80 | (n >> 8), n & 0xFF))
    return bytes((0xC0 | (n >> 24), (n >> 16) & 0xFF)) + _u16.pack(n & 0xFFFF)


def vertex_array(vertices) -> bytes:
    """CVertexArray: VertexType 1, count, then per vertex its ushort id and an SWVertex
    (numUVs 0, origin, normal (0, 0, 0))."""
    out = [_i32.pack(VERTEX_TYPE), _u32.pack(len(vertices))]
    for i, v in enumerate(vertices):
        out.append(_u16.pack(i) + _u16.pack(0) + _3f.pack(*v) + _3f.pack(0.0, 0.0, 0.0))
    return b"".join(out)


def _vertex_array_packed(origins: list[bytes]) -> bytes:
    """`vertex_array` for origins already packed as three float32s."""
    tail = _u16.pack(0)
    zero = _3f.pack(0.0, 0.0, 0.0)
    return b"".join([_i32.pack(VERTEX_TYPE), _u32.pack(len(origins))]
                    + [_u16.pack(i) + tail + o + zero for i, o in enumerate(origins)])


def polygon(poly: PolygonRec, ids: list[int], drawing: bool = False) -> bytes:
    """DatLoader Polygon: NumPts, Stippling (NoPos|NoNeg: no UV indices), SidesType, PosSurface,
    NegSurface, vertex ids. With `drawing` (scene/8) Stippling 0 (none), so the positive UV indices follow
    (the i-th vertex's UV index i, one byte each) and, for a Clockwise polygon, the negative ones likewise."""
    n = len(ids)
    if not drawing:
        return struct.pack(f"<BBihh{n}h", n, STIPPLING_NO_POS | STIPPLING_NO_NEG, int(poly.sides_type), 0, 0, *ids)
    uv = bytes(i & 0xFF for i in range(n))
    return (struct.pack(f"<BBihh{n}h", n, 0, int(poly.sides_type), 0, 0, *ids) + uv
            + (uv if poly.sides_type == CullMode.Clockwise else b""))


def sphere(center, radius) -> bytes:
    return _4f.pack(*center, radius)


def bsp_node(node, out: list, leaves: list) -> None:
    """The physics BSP tree in DatLoader's layout, pre-order (BSPNode.Unpack / BSPLeaf.Unpack with
    BSPType.Physics: internal nodes carry no polygon ids). `leaves` counts leaves for LeafIndex."""
    if isinstance(node, BSPLeaf):
        polys = node.polygons
        out.append(struct.pack(f"<Iii4fI{len(polys)}H", TAG_LEAF, len(leaves), 1 if node.solid else 0,
                               *node.sphere.center, node.sphere.radius, len(polys), *polys))
        leaves.append(node)
        return
    out.append(_u32.pack(TAG_BPIN) + _4f.pack(*node.plane.normal, node.plane.d))
    bsp_node(node.front, out, leaves)
    bsp_node(node.back, out, leaves)
    out.append(sphere(node.sphere.center, node.sphere.radius))


def _shared_vertices(polygons) -> tuple[list[bytes], list[list[int]]]:
    """The polygons' vertices deduplicated by exact float32 bits (-0.0 and 0.0 differ), ids in order
    of first appearance: (packed origins, each polygon's vertex ids)."""
    index: dict[bytes, int] = {}
    vertices = []
    poly_ids = []
    pack3 = _3f.pack
    for p in polygons:
        ids = []
        for v in p.vertices:
            key = pack3(*v)
            i = index.get(key)
            if i is None:
                i = index[key] = len(vertices)
                vertices.append(key)
            ids.append(i)
        poly_ids.append(ids)
    return vertices, poly_ids


def gfx_obj_physics(gfx_id: int, shape: BSPShape, drawing: bool = False) -> bytes:
    """FileTypes/GfxObj: a physics-only GfxObj from a scene BSP shape. With `drawing` (scene/8; a shape with
    polygons) it is drawn too: flags HasPhysics|HasDrawing|HasDIDDegrade, one surface (DRAWING_SURFACE), the
    polygons with UV indices (`polygon`), and after the SortCenter the same polygons as its drawing polygons, keyed
    alike, a drawing BSP over them (`drawing_bsp_node`, no portals: ACE's GfxObj takes its DrawingSphere from the
    root's sphere, and Setup.MakeSimpleSetup a BSP static's SortingSphere from that), and DRAWING_DID_DEGRADE."""
    drawing = drawing and bool(shape.polygons)
    vertices, poly_ids = _shared_vertices(shape.polygons)
    flags = GFX_HAS_PHYSICS | (GFX_HAS_DRAWING | GFX_HAS_DID_DEGRADE if drawing else 0)
    polys = [_u16.pack(k) + polygon(p, ids, drawing) for k, (p, ids) in enumerate(zip(shape.polygons, poly_ids))]
    out = [_u32.pack(gfx_id), _u32.pack(flags),
           compressed_u32(1) + _u32.pack(DRAWING_SURFACE) if drawing else compressed_u32(0),
           _vertex_array_packed(vertices), compressed_u32(len(shape.polygons))] + polys
    bsp_node(shape.root, out, [])
    out.append(_3f.pack(0.0, 0.0, 0.0))  # SortCenter
    if drawing:
        out.append(compressed_u32(len(shape.polygons)))
        out += polys
        drawing_bsp_node(shape, 0, len(shape.polygons), {}, out, [], [_box(p) for p in shape.polygons])
        out.append(_u32.pack(DRAWING_DID_DEGRADE))
    return b"".join(out)


def box_corners(lo, hi) -> list[tuple[float, float, float]]:
    """The 8 corners of an axis-aligned box, corner k = (k&1 ? hi.x : lo.x, k&2 ? hi.y : lo.y, k&4 ? hi.z : lo.z)."""
    return [(hi[0] if k & 1 else lo[0], hi[1] if k & 2 else lo[1], hi[2] if k & 4 else lo[2]) for k in range(8)]


def shape_box(shape) -> tuple[tuple[float, float, float], tuple[float, float, float]]:
    """(lo, hi) of a sphere's or cylsphere's axis-aligned box in object space, in float32."""
    f = np.float32
    if isinstance(shape, SphereShape):
        c, r = shape.sphere.center, f(shape.sphere.radius)
        return tuple(float(f(x) - r) for x in c), tuple(float(f(x) + r) for x in c)
    lx, ly, lz = (f(x) for x in shape.low_point)
    r, h = f(shape.radius), f(shape.height)
    return (float(lx - r), float(ly - r), float(lz)), (float(lx + r), float(ly + r), float(lz + h))


def gfx_obj_mesh(gfx_id: int, vertices) -> bytes:
    """FileTypes/GfxObj with no physics and no drawing: only its vertex array (GfxObj.Init bounds it)."""
    return b"".join((_u32.pack(gfx_id), _u32.pack(0), compressed_u32(0), vertex_array(vertices), _3f.pack(0.0, 0.0, 0.0)))


def setup(setup_id: int, parts: list[int], spheres=(), cylspheres=(), step_up: float = 0.0, step_down: float = 0.0,
          placement=None, default_scale=None, default_animation: int = 0, default_motion_table: int = 0,
          default_script: int = 0, holding_locations=(), placement_key: int = DEFAULT_PLACEMENT,
          sorting_sphere=((0.0, 0.0, 0.0), 0.0), parent_index=None, free_heading: bool = False) -> bytes:
    """FileTypes/SetupModel: flags (HasDefaultScale when `default_scale` is given, HasParent when
    `parent_index` is, AllowFreeHeading when `free_heading`, else 0), the parts, the ParentIndex (one uint per part, with HasParent),
    the DefaultScale (one vector per part), the HoldingLocations (`holding_locations`: (location id, part
    id, scene Frame) triples in the order given, which is the Dictionary's; none by default; a part id
    at or past the parts holds at the object's Position, and -1 throws in UpdateChild), no connection points, the placement
    frames (none, or with `placement` (a scene Frame per part) one: key `placement_key`, Placement.Default
    (0) unless given, its AnimationFrame's frames and no hooks), the cylspheres ((low point, radius, height)) and spheres
    ((centre, radius)), Height and Radius 0, the step heights, the sorting sphere ((centre, radius), zero by
    default: what a child's calc_cross_cells finds its cells with) and a zero selection sphere, no
    lights, the DefaultAnimation, DefaultScript and DefaultMotionTable given (0, none, by default), no sound
    table or script table."""
    flags = ((SETUP_HAS_DEFAULT_SCALE if default_scale is not None else 0) | (SETUP_HAS_PARENT if parent_index is not None else 0)
             | (SETUP_ALLOW_FREE_HEADING if free_heading else 0))
    out = [_u32.pack(setup_id), _u32.pack(flags), _u32.pack(len(parts))]
    out += [_u32.pack(p) for p in parts]
    if parent_index is not None:  # HasParent: ParentIndex, one uint per part (ACE's physics never reads it)
        if len(parent_index) != len(parts):
            raise ValueError(f"a ParentIndex has one entry per part: {len(parent_index)} for {len(parts)} parts")
        out += [_u32.pack(i) for i in parent_index]
    if default_scale is not None:
        if len(default_scale) != len(parts):
            raise ValueError(f"a DefaultScale has one vector per part: {len(default_scale)} for {len(parts)} parts")
        out += [_3f.pack(*v) for v in default_scale]
    out.append(_i32.pack(len(holding_locations)))  # HoldingLocations: Dictionary<int, LocationType>
    for location_id, part_id, f in holding_locations:
        out.append(_i32.pack(location_id) + _i32.pack(part_id) + frame(f))
    out.append(_i32.pack(0))  # ConnectionPoints
    if placement is None:
        out.append(_i32.pack(0))  # PlacementFrames
    else:
        if len(placement) != len(parts):
            raise ValueError(f"a placement frame has one frame per part: {len(placement)} for {len(parts)} parts")
        out.append(_i32.pack(1) + _i32.pack(placement_key))
        out += [frame(f) for f in placement]
        out.append(_u32.pack(0))  # the AnimationFrame's hooks
    out.append(_u32.pack(len(cylspheres)))
    for low, radius, height in cylspheres:
        out.append(_3f.pack(*low) + struct.pack("<2f", radius, height))
    out.append(_u32.pack(len(spheres)))
    for center, radius in spheres:
        out.append(sphere(center, radius))
    out.append(_4f.pack(0.0, 0.0, step_up, step_down))  # Height, Radius, StepUpHeight, StepDownHeight
    out.append(sphere(*sorting_sphere) + sphere((0.0, 0.0, 0.0), 0.0))  # SortingSphere, SelectionSphere
    out.append(_i32.pack(0))  # Lights
    # DefaultAnimation, DefaultScript, DefaultMotionTable, DefaultSoundTable, DefaultScriptTable
    out.append(_u32.pack(default_animation) + _u32.pack(default_script) + _u32.pack(default_motion_table) + _u32.pack(0) * 2)
    return b"".join(out)


def static_records(obj: StaticObject, index: int, drawing: bool = False) -> ObjectRecords:
    """The DAT records static object number `index` (0-based, scene order) is made from (`drawing`: the scene's,
    scene/8: a BSP GfxObj drawn too, `gfx_obj_physics`)."""
    if not 0 <= index < MAX_OBJECTS:
        raise ValueError(f"static object index {index} outside 0..{MAX_OBJECTS - 1}")
    if obj.setup is not None:
        return setup_records(obj.setup, index, drawing)
    shape = obj.shape
    gfx_id = GFX_OBJ_BASE + index
    if isinstance(shape, BSPShape):
        return ObjectRecords(gfx_id, (DatRecord(gfx_id, "GfxObj", gfx_obj_physics(gfx_id, shape, drawing)),))
    setup_id = SETUP_BASE + index
    part = DatRecord(gfx_id, "GfxObj", gfx_obj_mesh(gfx_id, box_corners(*shape_box(shape))))
    if isinstance(shape, SphereShape):
        body = setup(setup_id, [gfx_id], spheres=[(shape.sphere.center, shape.sphere.radius)])
    elif isinstance(shape, CylSphereShape):
        body = setup(setup_id, [gfx_id], cylspheres=[(shape.low_point, shape.radius, shape.height)])
    else:
        raise TypeError(f"static object {obj.id:#010x}: unknown shape {type(shape).__name__}")
    return ObjectRecords(setup_id, (part, DatRecord(setup_id, "SetupModel", body)))


def setup_records(rec: SetupRec, index: int, drawing: bool = False) -> ObjectRecords:
    """A static's Setup of several parts (scene/7 `setup`), static number `index`: each part's physics
    GfxObj (`gfx_obj_physics`), id ``PART_GFX_OBJ_BASE + 16 index + k`` for part k, then the Setup, id
    ``SETUP_BASE + index``, naming them in order, with their frames as its default placement, their
    scales as its DefaultScale (when the parts have one), the Setup's spheres and cylspheres and its
    DefaultScript (scene/8); with a `default_animation` (scene/8) the Setup's DefaultAnimation, Animation
    ``STATIC_ANIMATION_BASE + index``, follows: one frame holding those part frames. `drawing` (scene/8): the parts'
    GfxObjs are drawn too (`gfx_obj_physics`)."""
    if not 0 <= index < MAX_SETUP_OBJECTS:
        raise ValueError(f"a static with a setup has an index in 0..{MAX_SETUP_OBJECTS - 1}, got {index}")
    if not 0 <= len(rec.parts) <= MAX_PARTS:
        raise ValueError(f"a static's setup has 0..{MAX_PARTS} parts, got {len(rec.parts)}")
    ids = [PART_GFX_OBJ_BASE + MAX_PARTS * index + k for k in range(len(rec.parts))]
    parts = tuple(DatRecord(i, "GfxObj", gfx_obj_physics(i, p.shape, drawing)) for i, p in zip(ids, rec.parts))
    setup_id = SETUP_BASE + index
    scaled = bool(rec.parts) and rec.parts[0].scale is not None
    body = setup(setup_id, ids, spheres=[(s.center, s.radius) for s in rec.spheres],
                 cylspheres=[(c.low_point, c.radius, c.height) for c in rec.cylspheres],
                 placement=[p.frame for p in rec.parts] if rec.parts else None,
                 default_scale=[p.scale for p in rec.parts] if scaled else None,
                 parent_index=rec.parent_index, default_script=rec.default_script,
                 default_animation=0 if rec.default_animation is None else STATIC_ANIMATION_BASE + index)
    records = parts + (DatRecord(setup_id, "SetupModel", body),)
    if rec.default_animation is not None:
        frames = tuple((f.origin, f.orientation) for f in rec.default_animation)
        records += (animation_record(STATIC_ANIMATION_BASE + index, len(frames), [AnimationFrameRec(frames)]),)
    return ObjectRecords(setup_id, records)


def mover_records(mover: Mover) -> ObjectRecords:
    """The DAT records the mover is made from: its Setup (did) and the Setup's one part; with a motion
    table (scene/6), the Setup names it (DefaultMotionTable; and the table's default_animation, scene/8, as its
    DefaultAnimation) and its MotionTable and Animations follow; its DefaultScript is the mover's
    default_script (scene/8), and its resting_frame (scene/8) its one placement frame, keyed Resting; its flags
    say AllowFreeHeading when the mover has free_heading (scene/8)."""
    part = DatRecord(MOVER_GFX_OBJ_ID, "GfxObj", gfx_obj_mesh(MOVER_GFX_OBJ_ID, []))
    table = mover.motion_table
    body = setup(MOVER_SETUP_ID, [MOVER_GFX_OBJ_ID], spheres=[(s.center, s.radius) for s in mover.spheres],
                 step_up=mover.step_up_height, step_down=mover.step_down_height,
                 default_motion_table=MOTION_TABLE_ID if table is not None else 0,
                 default_animation=ANIMATION_BASE + table.default_animation
                 if table is not None and table.default_animation is not None else 0,
                 default_script=mover.default_script,
                 placement=None if mover.resting_frame is None else [mover.resting_frame], placement_key=RESTING_PLACEMENT,
                 holding_locations=holding_location_triples(mover.holding_locations), free_heading=mover.free_heading)
    records = (part, DatRecord(MOVER_SETUP_ID, "SetupModel", body))
    if table is not None:
        records += motion_records(table)
    return ObjectRecords(MOVER_SETUP_ID, records)


def other_records(other: OtherMover, index: int) -> ObjectRecords:
    """Other mover `index`'s Setup (OTHER_SETUP_BASE + index): its spheres and step heights over the mover's
    one empty part (MOVER_GFX_OBJ_ID, written with the mover's records), its holding locations and its sorting
    sphere (zero when it gives none: the bytes of a Setup before children)."""
    if index > MAX_OTHERS:
        raise ValueError(f"at most {MAX_OTHERS + 1} other movers have a Setup id")
    did = OTHER_SETUP_BASE + index
    sorting = other.sorting_sphere
    rec = other.setup
    parts, placement, scale, cylspheres = (), None, None, ()
    if rec is not None:  # scene/8 others[].setup: its parts as a static's Setup writes them (`setup_records`)
        if not 0 <= index < MAX_SETUP_OTHERS:
            raise ValueError(f"another mover with a setup has an index in 0..{MAX_SETUP_OTHERS - 1}, got {index}")
        if len(rec.parts) > MAX_PARTS:
            raise ValueError(f"a setup has at most {MAX_PARTS} parts, got {len(rec.parts)}")
        ids = [OTHER_PART_GFX_OBJ_BASE + MAX_PARTS * index + k for k in range(len(rec.parts))]
        parts = tuple(DatRecord(i, "GfxObj", gfx_obj_physics(i, p.shape)) for i, p in zip(ids, rec.parts))
        placement = [p.frame for p in rec.parts] if rec.parts and rec.placement else None
        scale = [p.scale for p in rec.parts] if rec.parts and rec.parts[0].scale is not None else None
        cylspheres = [(c.low_point, c.radius, c.height) for c in rec.cylspheres]
    placement_key = 0
    if other.missile_flight:  # scene/8: the one part's placement frame keyed MissileFlight (an arrow's Setup)
        placement, placement_key = [Frame((0.0, 0.0, 0.0))], MISSILE_FLIGHT_PLACEMENT
    body = setup(did, [MOVER_GFX_OBJ_ID] if rec is None else [p.id for p in parts],
                 spheres=[(s.center, s.radius) for s in other.spheres], cylspheres=cylspheres,
                 step_up=other.step_up_height, step_down=other.step_down_height,
                 placement=placement, placement_key=placement_key, default_scale=scale,
                 holding_locations=holding_location_triples(other.holding_locations),
                 sorting_sphere=((0.0, 0.0, 0.0), 0.0) if sorting is None else (sorting.center, sorting.radius))
    return ObjectRecords(did, parts + (DatRecord(did, "SetupModel", body),))


def holding_location_triples(locations) -> list:
    """A scene's HoldingLocation records as `setup` takes them: (location id, part id, Frame)."""
    return [(h.location, h.part, h.frame) for h in locations]


_IDENTITY_PART = ((0.0, 0.0, 0.0), (1.0, 0.0, 0.0, 0.0))


def motion_records(table) -> tuple:
    """A scene's motion table (acconform.motion_scene.MotionTableSpec) as DAT records: the MotionTable
    (MOTION_TABLE_ID), then animation i as Animation ANIMATION_BASE + i, with its PosFrames (none when
    its root_motion is off) and, for the mover's one part, an identity frame per frame with its hooks."""
    def data(entry) -> MotionDataRec:
        d = entry.data
        return MotionDataRec(tuple(AnimDataRec(ANIMATION_BASE + a.animation, a.low_frame, a.high_frame, a.framerate)
                                   for a in d.anims), d.bitfield, d.velocity, d.omega)

    links: dict = {}
    for e in table.links:
        links.setdefault(cycle_key(e.style, e.motion), {})[e.to] = data(e)
    out = [motion_table_record(MOTION_TABLE_ID, table.default_style, dict(table.style_defaults),
                               {cycle_key(e.style, e.motion): data(e) for e in table.cycles},
                               {cycle_key(e.style, e.motion): data(e) for e in table.modifiers}, links)]
    for i, a in enumerate(table.animations):
        frames = tuple((f.origin, f.orientation) for f in a.pos_frames)
        hooks = [tuple(HookRec(HOOKS[h.hook][0], h.direction, HOOKS[h.hook][1]) for h in a.hooks if h.frame == k)
                 for k in range(len(frames))]
        out.append(animation_record(ANIMATION_BASE + i, 1, [AnimationFrameRec((_IDENTITY_PART,), hooks[k]) for k in range(len(frames))],
                                    frames if a.root_motion else None))
    return tuple(out)


def cell_bsp_node(node, out: list, leaves: list) -> None:
    """A cell BSP tree in DatLoader's BSPType.Cell layout, pre-order: a node's tag (which children
    follow) and splitting plane, then its children; a leaf's tag and LeafIndex (pre-order ordinal)."""
    if isinstance(node, CellBSPLeaf):
        out.append(_LEAF_HEAD.pack(TAG_LEAF, len(leaves)))
        leaves.append(node)
        return
    front, back = node.front is not None, node.back is not None
    tag = TAG_BPIN if front and back else TAG_BPIn if front else TAG_BpIN if back else TAG_Bpnn
    if node.portal:  # scene/8: PORT, read as BPIN in a cell tree (both children)
        tag = TAG_PORT
    out.append(_u32.pack(tag) + _4f.pack(*node.plane.normal, node.plane.d))
    if front:
        cell_bsp_node(node.front, out, leaves)
    if back:
        cell_bsp_node(node.back, out, leaves)


def _pack_4f(*xs: float) -> bytes:
    """Four doubles as float32s; one beyond float32's range is written as infinity (C#'s cast),
    where struct.pack would raise."""
    try:
        return _4f.pack(*xs)
    except OverflowError:
        with np.errstate(over="ignore"):
            return _4f.pack(*(float(np.float32(x)) for x in xs))


def _polygon_plane(poly: PolygonRec) -> tuple[float, float, float, float]:
    """The plane a polygon lies in, in doubles: its Newell normal normalised and d = -normal . its
    first vertex ((0, 0, 0), 0 for a polygon spanning no area, which a scene's validation refuses)."""
    nx, ny, nz = newell_normal(poly.vertices)
    length = (nx * nx + ny * ny + nz * nz) ** 0.5
    if length == 0.0:
        return 0.0, 0.0, 0.0, 0.0
    nx, ny, nz = nx / length, ny / length, nz / length
    x, y, z = poly.vertices[0]
    return nx, ny, nz, -(nx * x + ny * y + nz * z)


def _box(poly: PolygonRec) -> tuple[float, ...]:
    """The axis-aligned box (min x, y, z, max x, y, z) around a polygon's vertices."""
    xs, ys, zs = zip(*poly.vertices)
    return min(xs), min(ys), min(zs), max(xs), max(ys), max(zs)


def _joined(a: tuple, b: tuple | None) -> tuple:
    """The box around boxes a and b (None: empty)."""
    if b is None:
        return a
    return (a[0] if a[0] <= b[0] else b[0], a[1] if a[1] <= b[1] else b[1], a[2] if a[2] <= b[2] else b[2],
            a[3] if a[3] >= b[3] else b[3], a[4] if a[4] >= b[4] else b[4], a[5] if a[5] >= b[5] else b[5])


def drawing_bsp_node(rec: CellStructRec, lo: int, hi: int, portal_indices: dict, out: list, leaves: list,
                     boxes: list):
    """The drawing tree over polygon ids lo .. hi - 1 in DatLoader's BSPType.Drawing layout (see
    `drawing_bsp`): an empty range is a leaf (its tag and pre-order LeafIndex); otherwise the node of
    the middle id k: its tag and plane, the front tree (ids below k), the back tree (ids above k),
    its sphere, then ``BPIN``'s polygon ids (count, ids) or ``PORT``'s (polygon count, portal count,
    ids, then per portal its index and polygon id as two shorts). `boxes` holds each polygon's
    `_box`. Returns the box around the subtree's vertices (None for a leaf)."""
    if lo == hi:
        out.append(_LEAF_HEAD.pack(TAG_LEAF, len(leaves)))
        leaves.append(lo)
        return None
    k = (lo + hi) // 2
    portals = portal_indices.get(k, ())
    plane = _polygon_plane(rec.polygons[k])
    out.append(_u32.pack(TAG_PORT if portals else TAG_BPIN) + _pack_4f(*plane))
    front = drawing_bsp_node(rec, lo, k, portal_indices, out, leaves, boxes)
    back = drawing_bsp_node(rec, k + 1, hi, portal_indices, out, leaves, boxes)
    box = _joined(_joined(boxes[k], front), back)
    h0, h1, h2 = (box[3] - box[0]) / 2.0, (box[4] - box[1]) / 2.0, (box[5] - box[2]) / 2.0
    out.append(_pack_4f(box[0] + h0, box[1] + h1, box[2] + h2, (h0 ** 2 + h1 ** 2 + h2 ** 2) ** 0.5))
    if portals:
        out.append(_u32.pack(1) + _u32.pack(len(portals)) + _u16.pack(k)
                   + b"".join(struct.pack("<HH", j & 0xFFFF, k) for j in portals))
    else:
        out.append(_u32.pack(1) + _u16.pack(k))
    return box


def drawing_bsp(rec: CellStructRec, out: list) -> None:
    """The structure's drawing BSP, derived from its polygons and portals (ACE's CellStruct builds
    it over the polygons and its physics never reads it): a balanced tree over the polygon ids,
    one node per polygon (`drawing_bsp_node`), a lone leaf when there is none. A portal polygon's
    node is a ``PORT`` listing it with each of its indices in `portals`; every other node a
    ``BPIN``. A node's plane is its polygon's (`_polygon_plane`); its sphere is centred on the box
    around its subtree's vertices, with half the box's diagonal as radius; both in doubles, written
    as float32."""
    portal_indices: dict[int, list[int]] = {}
    for j, k in enumerate(rec.portals):
        portal_indices.setdefault(k, []).append(j)
    drawing_bsp_node(rec, 0, len(rec.polygons), portal_indices, out, [], [_box(p) for p in rec.polygons])


def _align(out: list, length: int) -> int:
    """BinaryReader.AlignBoundary: pad to the next multiple of 4 from the record's start; the new length."""
    pad = -length % 4
    if pad:
        out.append(bytes(pad))
    return length + pad


def cell_struct(rec: CellStructRec, out: list, length: int, drawing: bool = False) -> int:
    """Entity/CellStruct: appends the structure to `out` (the record so far is `length` bytes, for
    AlignBoundary) and returns the record's new length. `drawing` (scene/8): its polygons and physics polygons carry
    UV indices (`polygon`)."""
    vertices, poly_ids = _shared_vertices(rec.polygons + rec.physics_polygons)
    parts = [_u32.pack(len(rec.polygons)) + _u32.pack(len(rec.physics_polygons)) + _u32.pack(len(rec.portals)),
             _vertex_array_packed(vertices)]
    parts += [_u16.pack(k) + polygon(p, ids, drawing) for k, (p, ids) in enumerate(zip(rec.polygons, poly_ids))]
    parts += [_u16.pack(p) for p in rec.portals]
    length += sum(map(len, parts))
    out += parts
    length = _align(out, length)
    tail = []
    cell_bsp_node(rec.cell_bsp, tail, [])
    n = len(rec.polygons)
    tail += [_u16.pack(k) + polygon(p, ids, drawing) for k, (p, ids) in enumerate(zip(rec.physics_polygons, poly_ids[n:]))]
    bsp_node(rec.physics_bsp, tail, [])
    tail.append(_u32.pack(1 if rec.drawing_bsp else 0))  # hasDrawingBSP (scene/8 drawing_bsp: false writes 0, no tree)
    if rec.drawing_bsp:
        drawing_bsp(rec, tail)
    length += sum(map(len, tail))
    out += tail
    return _align(out, length)


def environment_record(env: Environment, drawing: bool = False) -> DatRecord:
    """FileTypes/Environment: its id, then its cell structures keyed by index (`drawing`: `cell_struct`'s)."""
    out = [_u32.pack(env.id), _u32.pack(len(env.cell_structs))]
    length = 8
    for k, rec in enumerate(env.cell_structs):
        out.append(_u32.pack(k))
        length = cell_struct(rec, out, length + 4, drawing)
    return DatRecord(env.id, "Environment", b"".join(out))


def frame(f) -> bytes:
    """Entity/Frame: origin, then the quaternion as w, x, y, z."""
    return _3f.pack(*f.origin) + _4f.pack(*f.orientation)


def env_cell_record(cell: EnvCell, stabs, drawing: bool = False) -> DatRecord:
    """FileTypes/EnvCell; `stabs` are (id, scene Frame) pairs, the cell's static objects. `drawing` (scene/8): one
    surface, DRAWING_SURFACE's low word (none otherwise)."""
    flags = (ENV_CELL_SEEN_OUTSIDE if cell.seen_outside else 0) | (ENV_CELL_HAS_STATIC_OBJS if stabs else 0) | (
        ENV_CELL_HAS_RESTRICTION_OBJ if cell.restriction_obj else 0)
    surfaces = (DRAWING_SURFACE & 0xFFFF,) if drawing else ()
    out = [struct.pack(f"<IIIBBH{len(surfaces)}HHH", cell.id, flags, cell.id, len(surfaces), len(cell.portals),
                       len(cell.visible_cells), *surfaces, cell.environment & 0xFFFF, cell.cell_structure), frame(cell.frame)]
    out += [struct.pack("<4H", p.flags, p.polygon, p.other_cell, p.other_portal) for p in cell.portals]
    out += [_u16.pack(v) for v in cell.visible_cells]
    if stabs:
        out.append(_u32.pack(len(stabs)))
        out += [_u32.pack(did) + frame(f) for did, f in stabs]
    if cell.restriction_obj:
        out.append(_u32.pack(cell.restriction_obj))
    return DatRecord(cell.id, "EnvCell", b"".join(out))


def building_records(building: Building, index: int, drawing: bool = False) -> ObjectRecords:
    """The DAT record building number `index` (0-based, scene order) is made from: its shell's GfxObj (`drawing`:
    drawn too, scene/8)."""
    if not 0 <= index < MAX_BUILDINGS:
        raise ValueError(f"building index {index} outside 0..{MAX_BUILDINGS - 1}")
    gfx_id = BUILDING_GFX_OBJ_BASE + index
    return ObjectRecords(gfx_id, (DatRecord(gfx_id, "GfxObj", gfx_obj_physics(gfx_id, building.shape, drawing)),))


def building_info(building: Building, index: int, out: list, length: int) -> int:
    """Entity/BuildInfo after `length` bytes of the record: ModelId, Frame, NumLeaves, the portals
    (a uint32 count, then each CBldPortal aligned to 4 from the record's start). Returns the new length."""
    head = _u32.pack(building_records(building, index).did) + frame(building.frame) + _u32.pack(building.num_leaves)
    head += _u32.pack(len(building.portals))
    out.append(head)
    length += len(head)
    for p in building.portals:
        body = struct.pack("<4H", p.flags, p.other_cell, p.other_portal, len(p.stab_list))
        body += b"".join(_u16.pack(c) for c in p.stab_list)
        out.append(body)
        length = _align(out, length + len(body))
    return length


def landblock_info_record(block: int, num_cells: int, buildings=(), restrictions=()) -> DatRecord:
    """FileTypes/LandblockInfo for landblock `block` (its high word): NumCells, no objects, its buildings
    ((index in the scene, Building) pairs), PackMask 0, or 1 with `restrictions` (scene/8 landblocks[].restrictions:
    (cell id, object id) pairs) and then its RestrictionTables as UnpackPackedHashTable reads one: a ushort count, a
    ushort bucket size (unread; retail's is a prime, here 89), the pairs."""
    info_id = (block << 16) | LANDBLOCK_INFO
    out = [struct.pack("<IIIHH", info_id, num_cells, 0, len(buildings), 1 if restrictions else 0)]
    length = 16
    for index, building in buildings:
        length = building_info(building, index, out, length)
    if restrictions:
        out.append(struct.pack("<HH", len(restrictions), 89))
        out += [struct.pack("<II", c, o) for c, o in restrictions]
    return DatRecord(info_id, "LandblockInfo", b"".join(out))


def has_objects(scene: Scene, landblock_id: int) -> bool:
    """CellLandblock.HasObjects of a scene landblock (0xXXYYFFFF): whether it has buildings."""
    return any(b.landblock == landblock_id for b in scene.buildings)


_CELL_LANDBLOCK = struct.Struct("<II81H")


def cell_landblock(lb: Landblock, objects: bool = False) -> bytes:
    """FileTypes/CellLandblock: Id, HasObjects (1 for a landblock with buildings: `has_objects`), the 81
    terrain words, the 81 heights, aligned to 4 (251 bytes + 1)."""
    return _CELL_LANDBLOCK.pack(lb.id | 0xFFFF, 1 if objects else 0, *lb.terrain) + bytes(lb.heights) + b"\0"


def cell_landblock_records(scene: Scene) -> tuple[DatRecord, ...]:
    """Each scene landblock's CellLandblock (cell DAT, 0xXXYYFFFF), in scene order."""
    return tuple(DatRecord(lb.id | 0xFFFF, "CellLandblock", cell_landblock(lb, has_objects(scene, lb.id | 0xFFFF)))
                 for lb in scene.landblocks)


def env_cell_stabs(scene: Scene) -> dict[int, list]:
    """Per EnvCell id, its stabs: (did, frame) of each static object whose position.cell is it, in scene order."""
    stabs: dict[int, list] = {}
    for index, obj in enumerate(scene.objects):
        if obj.position.cell & 0xFFFF >= ENV_CELL_FIRST:
            stabs.setdefault(obj.position.cell, []).append((static_records(obj, index).did, obj.position.frame))
    return stabs


def cell_dat_records(scene: Scene) -> tuple[DatRecord, ...]:
    """The scene's cell DAT records beside its CellLandblocks: each EnvCell, then the LandblockInfo of
    each landblock with EnvCells (in the order of their first cell), then of each other landblock
    with buildings (in the order of their first building)."""
    stabs = env_cell_stabs(scene)
    records = [env_cell_record(c, stabs.get(c.id, ()), scene.drawing) for c in scene.env_cells]
    counts: dict[int, int] = {}
    for c in scene.env_cells:
        counts[c.id >> 16] = counts.get(c.id >> 16, 0) + 1
    buildings: dict[int, list] = {}
    for index, b in enumerate(scene.buildings):
        buildings.setdefault(b.landblock >> 16, []).append((index, b))
    for block in buildings:
        counts.setdefault(block, 0)
    restrictions = {lb.id >> 16: lb.restrictions for lb in scene.landblocks}
    records += [landblock_info_record(block, n, buildings.get(block, ()), restrictions.get(block, ()))
                for block, n in counts.items()]
    return tuple(records)


def environment_records(scene: Scene) -> tuple[DatRecord, ...]:
    """The scene's Environment records (portal DAT)."""
    return tuple(environment_record(e, scene.drawing) for e in scene.environments)


def building_model_records(scene: Scene) -> tuple[DatRecord, ...]:
    """The scene's buildings' shells (portal DAT), in scene order."""
    return tuple(r for index, b in enumerate(scene.buildings) for r in building_records(b, index, scene.drawing).records)


@dataclass(frozen=True, slots=True)
class SceneRecords:
    """Every DAT record a scene's world is made from: the mover's, each static's (scene order), the
    portal DAT's others (Environments, then the buildings' shells) and the cell DAT's
    (`cell_dat_records`)."""

    mover: ObjectRecords
    statics: tuple[ObjectRecords, ...]
    portal: tuple[DatRecord, ...]
    cell: tuple[DatRecord, ...]
    others: tuple[ObjectRecords, ...] = ()  # each other mover's Setup (scene/8), in scene order


_written: list = []  # (scene, its records) for the last two scenes `scene_records` wrote


def scene_records(scene: Scene) -> SceneRecords:
    """The scene's DAT records, written once for the port, ACE's facade and a request's `dat`: a
    campaign hands each of them the same scene in turn, in one process, and an indoor scene's
    Environments cost more to write than ACE's whole case (docs/oracle.md). Scenes are immutable, so
    the last two scenes' records are kept (each with its scene, so its identity cannot pass to
    another): a campaign sends the next scene to an implementation before ACE runs the current one."""
    for written, records in _written:
        if written is scene:
            return records
    records = SceneRecords(mover_records(scene.mover),
                           tuple(static_records(o, index, scene.drawing) for index, o in enumerate(scene.objects)),
                           environment_records(scene) + building_model_records(scene),
                           cell_dat_records(scene),
                           tuple(other_records(o, index) for index, o in enumerate(scene.others)))
    _written.append((scene, records))
    del _written[:-2]
    return records


@dataclass(frozen=True, slots=True)
class DatStatic:
    """What ACE's facade takes for a static object beside its records: its PhysicsObj id, the id makeObject
    takes (`did`), its position, PhysicsState flags and scale."""

    id: int
    did: int
    position: Position
    state: int
    scale: float


@dataclass(frozen=True, slots=True)
class DatMover:
    """What ACE's facade takes for the mover beside its records (the Setup holds its spheres and step
    heights): the scene mover's other fields, its PhysicsObj id and the id makeObject takes."""

    id: int
    did: int
    scale: float
    state: int
    transient_state: int
    velocity: tuple[float, float, float]
    begin: Position
    end: Position | None
    contact_plane: ContactPlane | None
    sliding_normal: tuple[float, float, float] | None
    placement: Placement | None
    motion_table_id: int = 0  # the player's MotionTableId (its Setup names the same table; 0: none)
    player_killer_status: int = 2  # the Player's PlayerKillerStatus (NPK)
    skills: MoverSkills = DEFAULT_SKILLS  # the Player's skills, vitals, attributes and burden (the scene's)


@dataclass(frozen=True, slots=True)
class DatOther:
    """What ACE's facade takes for another mover (scene/8) beside its Setup record: its id, the Setup's id
    (`did`), the WorldObject's class (`weenie`), and the scene's other fields for it."""

    id: int
    did: int
    weenie: str
    scale: float
    state: int
    transient_state: int
    velocity: tuple[float, float, float]
    begin: Position | None  # None: a child (scene/8 `parent`)
    player_killer_status: int = 2  # NPK
    parent: ChildOf | None = None  # a child: its parent's id, location and placement
    launch: object = None  # a projectile's acconform.scene.Launch (weenie ammunition or spell_projectile)
    report_collisions: bool | None = None  # the WorldObject's PropertyBool.ReportCollisions (None: unset)
    motion_table_id: int = 0  # its WorldObject's MotionTableId (scene/8 others[].motion_table: MOTION_TABLE_ID)


@dataclass(frozen=True, slots=True)
class DatWorld:
    """A scene's world as DAT records (the protocol's `dat`): the cell and portal DATs' records in the
    order ACE's facade builds from them, the statics and the mover as the facade takes them, and the
    land height table (a Region's LandDefs.LandHeightTable; no Region record is written)."""

    land_height_table: tuple[float, ...]
    cell: tuple[DatRecord, ...]
    portal: tuple[DatRecord, ...]
    statics: tuple[DatStatic, ...]
    mover: DatMover
    others: tuple[DatOther, ...] = ()


def dat_world(scene: Scene) -> DatWorld:
    """The scene's world as records: cell = CellLandblocks (scene order), LandblockInfos, EnvCells;
    portal = the buildings' shells, Environments, each static's records (scene order, parts first),
    the mover's."""
    written = scene_records(scene)
    infos = tuple(r for r in written.cell if r.kind == "LandblockInfo")
    cells = tuple(r for r in written.cell if r.kind == "EnvCell")
    portal = building_model_records(scene) + environment_records(scene)
    portal += tuple(r for recs in written.statics for r in recs.records) + written.mover.records
    portal += tuple(r for recs in written.others for r in recs.records)
    m = scene.mover
    return DatWorld(
        scene.land_height_table, cell_landblock_records(scene) + infos + cells, portal,
        tuple(DatStatic(o.id, recs.did, o.position, o.state, o.scale) for o, recs in zip(scene.objects, written.statics)),
        DatMover(MOVER_ID, written.mover.did, m.scale, m.state, m.transient_state, m.velocity, m.begin, m.end,
                 m.contact_plane, m.sliding_normal, m.placement, m.motion_table_id, m.player_killer_status, m.skills),
        tuple(DatOther(o.id, recs.did, o.weenie, o.scale, o.state, o.transient_state, o.velocity, o.begin,
                       o.player_killer_status, o.parent, o.launch, o.report_collisions, o.motion_table_id)
              for o, recs in zip(scene.others, written.others)))


__all__ = ["building_info", "cell_landblock", "cell_landblock_records", "DatMover", "DatOther", "DatStatic", "DatWorld",
           "other_records", "OTHER_SETUP_BASE", "OTHER_PART_GFX_OBJ_BASE",
           "dat_world", "building_model_records", "building_records", "has_objects", "BUILDING_GFX_OBJ_BASE",
           "cell_dat_records", "environment_records", "env_cell_record", "environment_record", "landblock_info_record",
           "env_cell_stabs", "mover_records", "scene_records", "SceneRecords", "MOVER_GFX_OBJ_ID", "MOVER_SETUP_ID", "DatRecord", "ObjectRecords", "static_records", "setup_records", "GFX_OBJ_BASE", "PART_GFX_OBJ_BASE", "SETUP_BASE", "STATIC_ANIMATION_BASE", "compressed_u32",
           "TAG_BPIN", "TAG_LEAF", "TAG_PORT"]


# ---------------------------------------------------------------- motion tables and animations
# ACE.Entity.Enum.MotionDataFlags and AnimationFlags
MOTION_DATA_HAS_VELOCITY = 0x1
MOTION_DATA_HAS_OMEGA = 0x2
ANIMATION_POS_FRAMES = 0x1


@dataclass(frozen=True, slots=True)
class AnimDataRec:
    """Entity/AnimData: an animation id, its frame range (high -1: to the last frame) and framerate."""

    anim_id: int
    low_frame: int = 0
    high_frame: int = -1
    framerate: float = 30.0


@dataclass(frozen=True, slots=True)
class MotionDataRec:
    """Entity/MotionData: its animations, Bitfield (1: a cycle that clears the modifiers; 2: allowed only
    from the style's default substate), and the Velocity and Omega it gives (None: not written)."""

    anims: tuple = ()
    bitfield: int = 0
    velocity: tuple | None = None
    omega: tuple | None = None


@dataclass(frozen=True, slots=True)
class HookRec:
    """Entity/AnimationHook: its type and direction (AnimationHookDir: -1 backward, 0 both, 1 forward),
    then `fields`, the bytes its class's Unpack reads after them (none for AnimationDone and
    DefaultScript; e.g. an EtherealHook's int32)."""

    hook_type: int
    direction: int = 0
    fields: bytes = b""


@dataclass(frozen=True, slots=True)
class AnimationFrameRec:
    """Entity/AnimationFrame: a frame per part ((origin), (w, x, y, z)), then its hooks."""

    frames: tuple = ()
    hooks: tuple = ()


def _frame_pair(f) -> bytes:
    """Entity/Frame from ((x, y, z), (w, x, y, z))."""
    origin, orientation = f
    return _3f.pack(*origin) + _4f.pack(*orientation)


def motion_data(m: MotionDataRec) -> bytes:
    """Entity/MotionData: NumAnims, Bitfield and Flags bytes, then AlignBoundary's padding (one zero
    byte: every MotionData of a table starts on a multiple of 4 from the record's start), the
    AnimDatas (id, low, high, framerate), Velocity and Omega when flagged."""
    flags = (MOTION_DATA_HAS_VELOCITY if m.velocity is not None else 0) | (MOTION_DATA_HAS_OMEGA if m.omega is not None else 0)
    if len(m.anims) > 0xFF:
        raise ValueError(f"a MotionData holds at most 255 animations, not {len(m.anims)}")
    out = [bytes((len(m.anims), m.bitfield, flags, 0))]
    out += [struct.pack("<Iiif", a.anim_id, a.low_frame, a.high_frame, a.framerate) for a in m.anims]
    if m.velocity is not None:
        out.append(_3f.pack(*m.velocity))
    if m.omega is not None:
        out.append(_3f.pack(*m.omega))
    return b"".join(out)


def _motion_dict(d: dict) -> bytes:
    """Dictionary<uint, MotionData>.Unpack: a uint count, then key and MotionData, in the dict's order."""
    return b"".join([_u32.pack(len(d))] + [_u32.pack(k) + motion_data(v) for k, v in d.items()])


def motion_table_record(table_id: int, default_style: int, style_defaults: dict, cycles: dict, modifiers: dict = None,
                        links: dict = None) -> DatRecord:
    """FileTypes/MotionTable (portal DAT 0x09xxxxxx): Id, DefaultStyle, the style defaults (count, then
    style and substate pairs), Cycles and Modifiers (key -> MotionDataRec) and Links (key -> {motion ->
    MotionDataRec}), each dictionary in the given order. Keys are ``style << 16 | (motion & 0xFFFFFF)``."""
    modifiers = modifiers or {}
    links = links or {}
    out = [_u32.pack(table_id), _u32.pack(default_style), _u32.pack(len(style_defaults))]
    out += [_u32.pack(k) + _u32.pack(v) for k, v in style_defaults.items()]
    out.append(_motion_dict(cycles))
    out.append(_motion_dict(modifiers))
    out.append(_u32.pack(len(links)))
    for key, inner in links.items():
        out.append(_u32.pack(key) + _motion_dict(inner))
    return DatRecord(table_id, "MotionTable", b"".join(out))


def animation_hook(h: HookRec) -> bytes:
    return _u32.pack(h.hook_type & 0xFFFFFFFF) + _i32.pack(h.direction) + h.fields


def animation_record(anim_id: int, num_parts: int, part_frames, pos_frames=None) -> DatRecord:
    """FileTypes/Animation (portal DAT 0x03xxxxxx): Id, Flags (PosFrames when `pos_frames` is given),
    NumParts, NumFrames, the root-motion frames ((origin), (w, x, y, z)), one per frame, then per frame
    an AnimationFrameRec (a frame per part, then its hooks)."""
    if pos_frames is not None and len(pos_frames) != len(part_frames):
        raise ValueError(f"an Animation has one PosFrame per frame: {len(pos_frames)} for {len(part_frames)} frames")
    flags = ANIMATION_POS_FRAMES if pos_frames is not None else 0
    out = [struct.pack("<IIII", anim_id, flags, num_parts, len(part_frames))]
    if pos_frames is not None:
        out += [_frame_pair(f) for f in pos_frames]
    for pf in part_frames:
        if len(pf.frames) != num_parts:
            raise ValueError(f"an AnimationFrame has one frame per part: {len(pf.frames)} for {num_parts} parts")
        out += [_frame_pair(f) for f in pf.frames]
        out.append(_u32.pack(len(pf.hooks)))
        out += [animation_hook(h) for h in pf.hooks]
    return DatRecord(anim_id, "Animation", b"".join(out))
