"""JSON Schemas for scenes and outcomes, generated from the records, never kept by hand.

`scene_schema()` and `outcome_schema()` infer a JSON Schema (draft 2020-12) from the JSON the
records themselves write (`Scene.to_json`, `Outcome.to_json`) for a fixed, seeded sample of
generated scenes of every kind and their outcomes on the port, so a field added to a record
appears in the schema with no edit here. The rules, from the codec (acconform/codec.py):
objects keep every key seen (required: those in every sample); an object with a ``kind`` or
``type`` string is one of a set of named definitions (so the BSP tree is recursive); a list of
numbers of one length everywhere is a fixed-length vector; ``0x`` + 8 hex digits is an id; an
outcome's floats may be written as their float32 bit pattern (``"0x80000000"``; a non-finite one
always is). `acconform schema scene|outcome` prints them; docs/protocol.md says how they are used.
`dat_schema()` is a request's ``"dat"`` (the protocol's feature `dat`), inferred the same way from
what acconform sends for the sample (`acconform schema dat`); a record's ``type`` names its
definition.

`outcome_fields_markdown()` is docs/protocol.md's table of outcome fields: each field's path and
JSON type from the outcome schema, its unit and meaning from the record's own field metadata
(acconform/outcome.py), so the table cannot drift from what is written (`acconform schema outcome
--fields` prints it; tests/test_protocol_doc.py checks the doc holds it).
"""

from __future__ import annotations

import re
from collections import defaultdict

DRAFT = "https://json-schema.org/draft/2020-12/schema"
SAMPLE_SEED = 0
SAMPLE_PER_KIND = 40
TRACE_SAMPLE_PER_KIND = 3  # a trace has thousands of records: a few scenes show every shape
HEX_ID = re.compile(r"^0x[0-9A-F]{8}$")
NONFINITE = {"type": "string", "pattern": "^0x[0-9A-Fa-f]{8}$",
             "description": "a float32's bit pattern (\"0x80000000\" is -0.0); a non-finite float32 is always written so"}
DISCRIMINATORS = ("kind", "type")


class _Inferrer:
    def __init__(self, nonfinite_floats: bool):
        self.nonfinite = nonfinite_floats
        self.defs: dict[str, list[dict]] = defaultdict(list)

    def infer(self, values: list) -> dict:
        groups: dict[str, list] = defaultdict(list)
        for v in values:
            kind = ("null" if v is None else "boolean" if isinstance(v, bool) else "integer" if isinstance(v, int)
                    else "number" if isinstance(v, float) else "string" if isinstance(v, str)
                    else "array" if isinstance(v, list) else "object")
            groups[kind].append(v)
        if "integer" in groups and "number" in groups:
            groups["number"] += groups.pop("integer")
        schemas = [self._one(kind, vs) for kind, vs in groups.items()]
        if self.nonfinite and "number" in groups and "string" not in groups:
            schemas.append(dict(NONFINITE))
        return schemas[0] if len(schemas) == 1 else {"anyOf": schemas}

    def _one(self, kind: str, vs: list) -> dict:
        if kind == "object":
            return self._object(vs)
        if kind == "array":
            items = [x for v in vs for x in v]
            s: dict = {"type": "array"}
            if items:
                s["items"] = self.infer(items)
            lengths = {len(v) for v in vs}
            if len(lengths) == 1 and items and all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in items):
                s["minItems"] = s["maxItems"] = lengths.pop()
            return s
        if kind == "string":
            if all(HEX_ID.match(v) for v in vs):
                return {"type": "string", "pattern": "^0x[0-9A-Fa-f]{8}$", "description": "a uint32 id in hex"}
            return {"type": "string"}
        return {"type": kind}

    def _object(self, vs: list[dict]) -> dict:
        for key in DISCRIMINATORS:
            if all(isinstance(v.get(key), str) for v in vs):
                names = []
                for value in sorted({v[key] for v in vs}):
                    name = f"{key}:{value}"
                    self.defs[name] += [v for v in vs if v[key] == value]
                    names.append(name)
                refs = [{"$ref": f"#/$defs/{n}"} for n in names]
                return refs[0] if len(refs) == 1 else {"oneOf": refs}
        return self._plain(vs)

    def _plain(self, vs: list[dict], discriminator: str | None = None) -> dict:
        keys: list[str] = []
        for v in vs:
            keys += [k for k in v if k not in keys]
        props = {}
        for k in keys:
            if k == discriminator:
                props[k] = {"const": vs[0][k]}
            else:
                props[k] = self.infer([v[k] for v in vs if k in v])
        return {"type": "object", "properties": props, "required": [k for k in keys if all(k in v for v in vs)],
                "additionalProperties": False}

    def _widen(self, node, families) -> None:
        if isinstance(node, list):
            for x in node:
                self._widen(x, families)
        elif isinstance(node, dict):
            refs = [node["$ref"]] if "$ref" in node else [r.get("$ref") for r in node.get("oneOf", [])]
            if refs and all(isinstance(r, str) for r in refs):
                family = refs[0].rsplit("/", 1)[1].split(":", 1)[0]
                node.clear()
                node["oneOf"] = [{"$ref": f"#/$defs/{n}"} for n in families[family]]
                if len(node["oneOf"]) == 1:
                    node.update(node.pop("oneOf")[0])
                return
            for v in node.values():
                self._widen(v, families)

    def finish(self, root: dict, title: str, fmt: str | tuple[str, ...]) -> dict:
        """`fmt`: the format string the documents carry, or the several a reader reads."""
        out_defs: dict[str, dict] = {}
        while len(out_defs) < len(self.defs):  # a definition's own samples may add definitions
            for name in list(self.defs):
                if name not in out_defs:
                    out_defs[name] = {}
                    out_defs[name] = self._plain(self.defs[name], name.split(":", 1)[0])
        # a position that holds one member of a family (type: leaf) may hold any member (type: node)
        families: dict[str, list[str]] = defaultdict(list)
        for name in sorted(self.defs):
            families[name.split(":", 1)[0]].append(name)
        self._widen(root, families)
        for d in out_defs.values():
            self._widen(d, families)
        # samples gathered after a definition was built (deeper BSP levels) are merged in
        changed = True
        while changed:
            changed = False
            for name, samples in list(self.defs.items()):
                s = self._plain(samples, name.split(":", 1)[0])
                if s != out_defs.get(name):
                    out_defs[name] = s
                    changed = True
        for d in out_defs.values():
            self._widen(d, families)
        root["properties"]["format"] = {"const": fmt} if isinstance(fmt, str) else {"enum": list(fmt)}
        return {"$schema": DRAFT, "title": title, **root, "$defs": dict(sorted(out_defs.items()))}


def _sample():
    from .port.run import run_scene
    from .strategies import GEOMETRY_KINDS, sample_scenes

    scenes = []
    for kind in GEOMETRY_KINDS:  # tick scenes: _tick_scenes below, every input once
        scenes += list(sample_scenes((kind,), SAMPLE_PER_KIND, SAMPLE_SEED))
    scenes += _every_optional_field(scenes[0]) + _setup_scenes(scenes) + _cell_record_scenes(scenes)
    return scenes, [run_scene(s) for s in scenes]


def _port_root(node):
    """The cell tree with its root tagged PORT (scene/8 `portal`; a missing child made a leaf)."""
    from dataclasses import replace

    from .scene import CellBSPLeaf, CellBSPNode

    if not isinstance(node, CellBSPNode):
        return node
    return replace(node, portal=True, front=node.front or CellBSPLeaf(), back=node.back or CellBSPLeaf())


def _cell_record_scenes(scenes):
    """A scene/8 variant of the first sampled scene with buildings (strategies/cell_records.py's shapes): every EnvCell
    restricted to the mover and its landblock's restriction table, a visible cell and a building portal below
    0x0100, its cell structures without a drawing BSP and their cell trees' roots tagged PORT, so each of those fields
    is written."""
    from dataclasses import replace

    from .scene import BuildingPortalRec
    from .staging import MOVER_ID

    for scene in scenes:
        if scene.buildings and scene.env_cells:
            b = scene.buildings[0]
            cells = tuple(replace(c, restriction_obj=MOVER_ID, visible_cells=(*c.visible_cells, 0x0041))
                          for c in scene.env_cells)
            landblocks = tuple(replace(lb, restrictions=(((b.landblock & 0xFFFF0000) | 1, MOVER_ID),))
                               if lb.id == b.landblock else lb for lb in scene.landblocks)
            building = replace(b, portals=(*b.portals, BuildingPortalRec(0x0000, 0xFFFF)))
            envs = tuple(replace(e, cell_structs=tuple(replace(c, drawing_bsp=False, cell_bsp=_port_root(c.cell_bsp))
                                                       for c in e.cell_structs)) for e in scene.environments)
            return [replace(scene, env_cells=cells, landblocks=landblocks, buildings=(building, *scene.buildings[1:]),
                            environments=envs, name="cell records")]
    return []


def _setup_scenes(scenes):
    """Scene/7 variants of the first sampled scene with a BSP static: that static made a Setup of two
    parts (the second turned, lifted and given per-part scales in the other variant) with spheres and
    cylspheres, and a scene/8 one of the latter with a DefaultScript), so every field of a setup is written."""
    from dataclasses import replace

    from .scene import BSPShape, CylSphereShape, Frame, PartRec, SetupRec, SphereRec

    for scene in scenes:
        for i, o in enumerate(scene.objects):
            if isinstance(o.shape, BSPShape):
                plain = SetupRec((PartRec(o.shape), PartRec(o.shape, Frame((1.0, 0.0, 0.5), (0.0, 0.0, 0.0, 1.0)))))
                full = SetupRec(tuple(replace(p, scale=(1.0, 1.0, 2.0)) for p in plain.parts),
                                (SphereRec((0.0, 0.0, 0.5), 0.5),), (CylSphereShape((0.0, 0.0, 0.0), 0.5, 1.0),),
                                (0xFFFFFFFF, 0))
                objects = list(scene.objects)
                return [replace(scene, objects=tuple(objects[:i] + [replace(o, shape=None, setup=s)] + objects[i + 1:]))
                        for s in (plain, full, replace(full, default_script=0x33000001),
                                  replace(plain, default_animation=(Frame((0.0, 0.0, 0.5)),
                                                                    Frame((1.0, 0.0, 1.0), (0.0, 0.0, 0.0, 1.0)))))]
    return []


def _tick_scenes(scene):
    """Tick scenes (scene/4) made from a sampled scene: each driver, every input of a step once."""
    from dataclasses import replace

    from .flags import PhysicsState, TransientState
    from .scene import Ticks, TickStep

    m = replace(scene.mover, end=None)
    every = TickStep(1 / 30, state=int(PhysicsState.Gravity), transient_state=int(TransientState.Active),
                     velocity=(0.0, 1.0, 0.0), local_velocity=(0.0, 1.0, 0.0), omega=(0.0, 0.0, 1.0),
                     jump=(0.0, 0.0, 4.0), sequence_velocity=(0.0, 3.0, 0.0), sequence_omega=(0.0, 0.0, 0.5))
    return [replace(scene, engine_mode="client", mover=m, name="ticks", ticks=Ticks("update_object", 1000.0, (every, TickStep(0.25)))),
            replace(scene, engine_mode="client", mover=m, ticks=Ticks("request_pos", 0.0, (
                TickStep(0.1, request_pos=scene.mover.begin),))),
            _motion_scene(scene, m), _door_scene(scene, m), _movers_scene(scene, m), _missiles_scene(scene, m)]


def _movers_scene(scene, m):
    """A scene with other movers (scene/8, objects.moving): one of each weenie class at the mover's start (a
    PK player with every optional field), each given every input of a step once, and a child held by the mover
    (objects.children: its parent, the mover's holding location, its sorting sphere); then (objects.targets) the
    mover's stick_to at the monster and the NPC destroyed; the mover's motion table the motion scene's, which the object
    has too (objects.motion_tables), the server executing On on it; its DAT records drawn (scene/8 drawing)."""
    from dataclasses import replace

    from .flags import PhysicsState, PlayerKillerStatus, TransientState
    from .scene import ChildOf, Frame, HoldingLocation, OtherInputs, OtherMover, SphereRec, Ticks, TickStep

    body = (SphereRec((0.0, 0.0, 0.5), 0.5),)
    others = (OtherMover(0x50000002, "player", body + (SphereRec((0.0, 0.0, 1.2), 0.5),), m.begin, 0.4, 0.4, scale=1.5,
                         velocity=(0.0, 1.0, 0.0), player_killer_status=int(PlayerKillerStatus.PK)),
              OtherMover(0x80000001, "monster", body, m.begin, 0.4, 0.4), OtherMover(0x80000002, "creature", body, m.begin, 0.4, 0.4),
              OtherMover(0x80000003, "object", body, m.begin, 0.0, 0.0),
              OtherMover(0x80000004, "object", body, None, 0.0, 0.0, sorting_sphere=SphereRec((0.0, 0.0, 0.5), 0.6),
                         parent=ChildOf(0x50000001, 1, 0)))
    m = replace(m, holding_locations=(HoldingLocation(1, 1, Frame((0.4, 0.1, 1.0))),), default_script=0x33000001,
                resting_frame=Frame((0.0, 0.0, 0.5)), free_heading=True)
    every = OtherInputs(0x50000002, state=int(PhysicsState.Gravity), transient_state=int(TransientState.Active),
                        velocity=(0.0, 1.0, 0.0), local_velocity=(0.0, 1.0, 0.0), omega=(0.0, 0.0, 1.0), jump=(0.0, 0.0, 4.0),
                        sequence_velocity=(0.0, 3.0, 0.0), sequence_omega=(0.0, 0.0, 0.5))
    # the child dropped, then held again by the frame form (part 0 and a frame)
    held = OtherInputs(0x80000004, unparent=True, parent=ChildOf(0x50000001, 0, 0, 0, Frame((0.4, 0.1, 1.0))))
    # objects.motion_tables: the object has the scene's table (the motion scene's) and the server opens it (a Chest's On)
    from .motion_enums import MotionCommand

    m = replace(m, motion_table=_motion_scene(scene, m).mover.motion_table)
    others = others[:3] + (replace(others[3], motion_table=True),) + others[4:]
    opened = OtherInputs(0x80000003, execute_motion=int(MotionCommand.On))
    return replace(scene, mover=m, name="movers", others=others, drawing=True,
                   ticks=Ticks("update_object", 1000.0, (TickStep(1 / 30, others=(every, OtherInputs(0x80000001))),
                                                          # objects.targets: a melee swing's stick_to, a destroyed NPC
                                                          TickStep(1 / 30, stick_to=0x80000001,
                                                                   others=(OtherInputs(0x80000002, destroy=True),)),
                                                          TickStep(1 / 30, others=(held, opened)))))


def _missiles_scene(scene, m):
    """A scene with projectiles (scene/8, missiles; a server engine): a monster at the mover's start, an arrow it
    launches at the mover and a spell the mover casts at it (an arc, tracking, under trajectory_alt_solver), both at tick 0, every launch field
    written; a tumbling thrown weapon, a Ring spell cast at no one and a sphereless crate that reports no collisions."""
    from dataclasses import replace

    from .scene import Launch, OtherMover, SphereRec, Ticks, TickStep

    body = (SphereRec((0.0, 0.0, 0.5), 0.5),)
    x, y, z = m.begin.frame.origin
    others = (OtherMover(0x80000001, "monster", body, m.begin, 0.4, 0.4),
              OtherMover(0x80000010, "ammunition", (SphereRec((0.0, 0.0, 0.0), 0.05),), m.begin, 0.0, 0.0,
                         launch=Launch(0, 0x80000001, 0x50000001, 20.0, (x, y, z + 1.2), (1.0, 0.0, 0.0, 0.0), False)),
              OtherMover(0x80000011, "spell_projectile", (SphereRec((0.0, 0.0, 0.0), 0.15),), m.begin, 0.0, 0.0,
                         launch=Launch(0, 0x50000001, 0x80000001, 15.0, (x, y, z + 1.2), arc=True, tracking=True, alt_solver=True)),
              # a thrown weapon that tumbles (its Setup with a MissileFlight placement), a Ring spell 3818 cast at no
              # one, a crate of BSP parts (no spheres) whose weenie carries ReportCollisions false
              OtherMover(0x80000012, "missile", (SphereRec((0.0, 0.0, 0.0), 0.1),), m.begin, 0.0, 0.0,
                         launch=Launch(0, 0x80000001, 0x50000001, 12.0, (x, y, z + 1.2), (1.0, 0.0, 0.0, 0.0),
                                       rotation_speed=1.0), missile_flight=True),
              OtherMover(0x80000013, "spell_projectile", (SphereRec((0.0, 0.0, 0.0), 0.15),), m.begin, 0.0, 0.0,
                         launch=Launch(0, 0x50000001, None, 10.0, (x, y, z + 1.2), spell="ring_3818")),
              OtherMover(0x80000014, "object", (), m.begin, 0.0, 0.0, report_collisions=False))
    return replace(scene, engine_mode="server", mover=m, name="missiles", others=others,
                   ticks=Ticks("update_object", 1000.0, (TickStep(1 / 30),)))


def _door_scene(scene, m):
    """A door scene (scene/7, doors): an outdoor static at the mover's start (when it starts outdoors) closed
    by the tick input door."""
    from dataclasses import replace

    from .scene import DoorInput, SphereRec, SphereShape, StaticObject, Ticks, TickStep

    if m.begin.cell & 0xFFFF >= 0x100:
        return replace(scene, mover=m, ticks=Ticks("update_object", 1000.0, (TickStep(1 / 30),)))
    door = StaticObject(0x7F000002, m.begin, SphereShape(SphereRec((0.0, 0.0, 0.5), 0.5)))
    return replace(scene, mover=m, name="door", objects=scene.objects + (door,),
                   ticks=Ticks("update_object", 1000.0, (TickStep(1 / 30, door=DoorInput(door.id, False)),)))


def _motion_scene(scene, m):
    """A motion scene (scene/6, mover.motion): a table with every optional field, a step with every motion field."""
    from dataclasses import replace

    from .motion_enums import HoldKey, MotionCommand as MC
    from .motion_scene import AnimationSpec, AnimRef, HookSpec, MotionDataSpec, MotionEntry, MotionInput, MotionTableSpec
    from .scene import Frame, Ticks, TickStep

    nc = int(MC.NonCombat)
    data = MotionDataSpec((AnimRef(0, 30.0, 0, -1),), (0.0, 3.0, 0.0), (0.0, 0.0, 1.0), 1)
    table = MotionTableSpec(nc, ((nc, int(MC.Ready)),),
                            (AnimationSpec((Frame((0.0, 0.1, 0.0)),), False, (HookSpec(0, "AnimationDone", 1),)),),
                            (MotionEntry(nc, int(MC.Ready), data),), (MotionEntry(nc, int(MC.Ready), data, int(MC.WalkForward)),),
                            (MotionEntry(nc, int(MC.TurnRight), data),), 0)
    run, key = int(HoldKey.Run), int(HoldKey.None_)
    motion = MotionInput(run, nc, int(MC.WalkForward), key, 1.0, int(MC.SideStepRight), key, 1.0, int(MC.TurnRight), key, 1.0)
    # the server's calls into the managers: every input once, the MovementParameters with every field, the target a
    # static the scene gains (an outdoor sphere at the mover's start)
    from .motion_enums import MovementParamFlags as MPF
    from .motion_scene import CommandInput, MovementParams, MoveToInput, ObjectMoveInput
    from .scene import MoverSkills, SphereRec, SphereShape, StaticObject

    params = MovementParams(int(MPF.Sticky | MPF.CanWalk), 0.5, 0.1, 15.0, 1.5, 15.0, 90.0, run)
    ball = StaticObject(0x7F000001, m.begin, SphereShape(SphereRec((0.0, 0.0, 0.5), 0.5)))
    managers = TickStep(1 / 30, stop="cancel_moveto", do_motion=CommandInput(int(MC.WalkForward), key),
                        stop_motion=CommandInput(int(MC.WalkForward), key), move_to=MoveToInput(params, m.begin),
                        move_to_object=ObjectMoveInput(ball.id, params), turn_to_heading=MoveToInput(params),
                        turn_to_object=ObjectMoveInput(ball.id, params))
    objects = scene.objects + (ball,) if m.begin.cell & 0xFFFF < 0x100 else scene.objects
    steps = (TickStep(1 / 30, motion=motion),) + ((managers,) if objects is not scene.objects else ())
    # the Player's skills (scene/8), every field other than the database-free Player's so each is written
    skills = MoverSkills(run=300, jump=250, stamina=0, strength=100, encumbrance_val=20000,
                         augmentation_increased_carrying_capacity=1)
    # the server's motion-table queries (scene/8 motion_queries): every function, with and without its optional fields
    from .scene import MotionQuery

    walk, ready = int(MC.WalkForward), int(MC.Ready)
    queries = (MotionQuery("GetAttackFrames", nc, walk), MotionQuery("GetAnimationLength", nc, walk),
               MotionQuery("GetAnimationLength", nc, walk, ready, 1.5), MotionQuery("GetRunSpeed"),
               MotionQuery("GetTurnSpeed"), MotionQuery("Dat.GetAnimationLength", 0, walk),
               MotionQuery("Dat.GetAnimationLength", nc, walk, ready))
    # another mover with the mover's motion table (scene/8 others[].motion_table, objects.motion_tables)
    from .scene import OtherMover

    others = (OtherMover(0x80000005, "monster", (SphereRec((0.0, 0.0, 0.5), 0.5),), m.begin, 0.4, 0.4, motion_table=True),)
    return replace(scene, mover=replace(m, motion_table=table, skills=skills), name="motion", objects=objects,
                   ticks=Ticks("update_object", 1000.0, steps), motion_queries=queries, others=others)


def _tick_outcomes() -> list:
    """A tick scene's outcome: a TickState of every field, and a tick ended by an error; a motion
    scene's (outcome/5): a tick with the motion layer, once with every part and once with none; and one with
    other movers (outcome/6): their placements, each tick's CollisionTable and their states."""
    from dataclasses import replace

    from .outcome import CommandState, MotionTickState, Outcome, PlaneState, TickState

    state = TickState(True, 1000.1, 0xA9B40001, 0xA9B40001, (12.0, 12.5, 20.0), (1.0, 0.0, 0.0, 0.0), (0.0, 2.0, 0.0),
                      (0.0, 0.0, -9.8), (0.0, 0.0, 0.0), (0.0, 2.0, 0.0), 0x400, 0x83, 0xA9B40001,
                      PlaneState((0.0, 0.0, 1.0), -20.0), (0.0, 0.0, 0.0), False, (0xA9B40001,))
    walk = CommandState(0x8000003D, 0x45000005, 1.0, 0x6500000F, 1.0, 0x6500000D, 1.0)
    motion = MotionTickState(walk, walk, 0x03000001, 1.5, (0.0, 3.0, 0.0), (0.0, 0.0, 1.0), 0, False)
    bare = MotionTickState(None, None, None, 0.0, (0.0, 0.0, 0.0), (0.0, 0.0, 0.0), None, False)
    from .outcome import AttackFrameState, CollisionState, MotionAnswerState, PlacementState

    placed = PlacementState(0, 0xA9B40001, (12.0, 12.5, 20.0), (1.0, 0.0, 0.0, 0.0), 0xA9B40001, 0x83, (0xA9B40001,))
    touched = (CollisionState(0x80000001, 1000.1, False),)
    movers = replace(state, collisions=touched, others=(replace(state, id=0x80000001, collisions=touched),))
    return [Outcome(static_cells=(), ticks=(state, TickState(error="NullReferenceException: an example"))),
            Outcome(static_cells=(), ticks=(replace(state, motion=motion), replace(state, motion=bare))),
            Outcome(static_cells=(), ticks=(movers,), other_placements=(placed,)),
            Outcome(static_cells=(), ticks=(state,), motion_answers=(
                MotionAnswerState(value=0.5), MotionAnswerState(attack_frames=()),
                MotionAnswerState(attack_frames=(AttackFrameState(0.25, 1, 0, -0.5, 1.0, 0.5, 1.0, 2.0, 1.5),)),
                MotionAnswerState(error="NullReferenceException: an example")))]


def _every_optional_field(scene):
    """Variants of a sampled scene that write the fields samples may leave out (name, a height
    table, a sliding normal, a velocity) or omit ones they always write."""
    from dataclasses import replace

    m = scene.mover
    return [replace(scene, name="every optional field", land_height_table=tuple(1.0 * i for i in range(256)),
                    mover=replace(m, sliding_normal=(0.0, 0.0, 1.0), velocity=(0.0, 0.0, -1.0))),
            replace(scene, name="")]


def schemas() -> tuple[dict, dict]:
    """(scene schema, outcome schema), inferred from the records' JSON for the fixed sample."""
    from .outcome import (FORMAT as OUTCOME_FORMAT, FORMAT_V2 as OUTCOME_FORMAT_V2, FORMAT_V3 as OUTCOME_FORMAT_V3,
                          FORMAT_V4 as OUTCOME_FORMAT_V4, FORMAT_V5 as OUTCOME_FORMAT_V5, Outcome)
    from .scene import (FORMAT as SCENE_FORMAT, FORMAT_V1 as SCENE_FORMAT_V1, FORMAT_V2 as SCENE_FORMAT_V2,
                        FORMAT_V3 as SCENE_FORMAT_V3, FORMAT_V4 as SCENE_FORMAT_V4, FORMAT_V5 as SCENE_FORMAT_V5,
                        FORMAT_V6 as SCENE_FORMAT_V6, FORMAT_V7 as SCENE_FORMAT_V7)

    scenes, outcomes = _sample()
    scenes += _tick_scenes(scenes[0])
    s = _Inferrer(nonfinite_floats=False)
    # an outdoor scene is written as /1, an indoor one as /2, one with a placement as /3, a tick scene as /4,
    # one with buildings as /5, one placed through enter_world as /6, one with a static's setup as /7, one with
    # other movers as /8
    scene = s.finish(s._plain([x.to_json() for x in scenes]), "acconform scene",
                     (SCENE_FORMAT_V1, SCENE_FORMAT_V2, SCENE_FORMAT_V3, SCENE_FORMAT_V4, SCENE_FORMAT_V5,
                      SCENE_FORMAT_V6, SCENE_FORMAT_V7, SCENE_FORMAT))
    o = _Inferrer(nonfinite_floats=True)
    docs = ([x.to_json() for x in outcomes] + [Outcome(error="NullReferenceException: an example").to_json()]
            + [x.to_json() for x in _tick_outcomes()])
    outcome = o.finish(o._plain(docs), "acconform outcome",
                       (OUTCOME_FORMAT_V2, OUTCOME_FORMAT_V3, OUTCOME_FORMAT_V4, OUTCOME_FORMAT_V5, OUTCOME_FORMAT))
    return scene, outcome


def trace_schema() -> dict:
    """The schema of a trace (acconform.trace/1), inferred from the port's traces of a fixed sample:
    TRACE_SAMPLE_PER_KIND seeded scenes of every kind and the tick scenes made from the first."""
    from .port.run import traced_run
    from .strategies import ALL_KINDS, sample_scenes
    from .trace import FORMAT, OPTIONAL_PATH_FLAGS, trace_to_json

    scenes = []
    for kind in ALL_KINDS:
        scenes += list(sample_scenes((kind,), TRACE_SAMPLE_PER_KIND, SAMPLE_SEED))
    scenes += _tick_scenes(scenes[0])
    t = _Inferrer(nonfinite_floats=True)
    schema = t.finish(t._plain([trace_to_json(traced_run(s)[1]) for s in scenes]), "acconform trace", FORMAT)
    path = schema["properties"]["records"]["items"]["properties"]["path"]
    for node in path.get("anyOf", [path]):
        if node.get("type") == "object":  # the port writes SpherePath's optional flags always; a trace may leave them out
            node["required"] = [name for name in node["required"] if name not in OPTIONAL_PATH_FLAGS]
    return schema


def dat_schema() -> dict:
    """The schema of a request's "dat" (acconform.dat/1), inferred from what acconform sends for the fixed
    sample of scenes of every kind, the variants writing every optional field, and the tick scenes."""
    from .dat import dat_world
    from .protocol import DAT_FORMAT, DAT_TYPES, dat_json
    from .strategies import GEOMETRY_KINDS, sample_scenes

    scenes = []
    for kind in GEOMETRY_KINDS:
        scenes += list(sample_scenes((kind,), SAMPLE_PER_KIND, SAMPLE_SEED))
    scenes += _every_optional_field(scenes[0]) + _tick_scenes(scenes[0])
    d = _Inferrer(nonfinite_floats=False)
    schema = d.finish(d._plain([dat_json(dat_world(s)) for s in scenes]), "acconform DAT records", DAT_FORMAT)
    for dat, types in DAT_TYPES.items():  # each DAT's list holds its own types only (finish widens to every type)
        schema["properties"][dat]["items"] = {"oneOf": [{"$ref": f"#/$defs/type:{name}"} for name in types]}
    return schema


# ---------------------------------------------------------------- the outcome's fields as a table

FIELDS_BEGIN = "<!-- outcome fields: generated by `acconform schema outcome --fields`; do not edit -->"
FIELDS_END = "<!-- end of outcome fields -->"


def _json_type(node: dict) -> str:
    """A schema node as the few words a porter reads: float32, float32[3], id, boolean, ..."""
    options = node.get("anyOf", [node])
    if any(o.get("type") == "number" for o in options):  # a float's bit pattern: said once, above the table
        options = [o for o in options if not (o.get("type") == "string" and o.get("pattern") == NONFINITE["pattern"])]
    return " or ".join(_one_type(o) for o in options)


def _one_type(o: dict) -> str:
    if o.get("type") == "array":
        item = _json_type(o["items"]) if "items" in o else "value"
        n = o.get("minItems")
        return f"{item}[{n}]" if n is not None and n == o.get("maxItems") else f"list of {item}"
    if o.get("type") == "number":
        return "float32"
    if o.get("type") == "string" and o.get("description") == "a uint32 id in hex":
        return "id"
    if "enum" in o or "const" in o:
        return " or ".join(f'"{v}"' for v in o.get("enum", [o.get("const")]))
    return str(o.get("type", "value"))


def _inner_record(hint):
    """The record a field holds: itself, inside an Optional, or as the items of a tuple."""
    import typing
    from dataclasses import is_dataclass

    if is_dataclass(hint):
        return hint
    for t in typing.get_args(hint):
        if t is not Ellipsis and (r := _inner_record(t)) is not None:
            return r
    return None


def outcome_fields_markdown(outcome_schema: dict | None = None) -> str:
    """docs/protocol.md's table: every field an outcome writes (the schema's), with its JSON type,
    unit and meaning (each dataclass field's metadata; a field without one raises)."""
    from dataclasses import fields as dc_fields, is_dataclass
    import typing

    from .outcome import Outcome

    schema = outcome_schema if outcome_schema is not None else schemas()[1]
    rows = ["| field | JSON type | unit | what it holds |", "|---|---|---|---|"]

    def walk(node: dict, record, prefix: str):
        meta = {f.name: f for f in dc_fields(record)}
        hints = typing.get_type_hints(record)
        for name, sub in node["properties"].items():
            path = prefix + name
            if name == "format":
                rows.append(f"| `{path}` | {_json_type(sub)} |  | the outcome format: /6 with other movers, /5 with ticks carrying `motion`, /4 with ticks, /3 with a placement |")
                continue
            if name not in meta or "what" not in meta[name].metadata:
                raise ValueError(f"outcome field {path} has no unit and meaning (acconform/outcome.py, _field)")
            m = meta[name].metadata
            rows.append(f"| `{path}` | {_json_type(sub)} | {m['unit']} | {m['what']} |")
            inner = _inner_record(hints[name])
            obj = next((o for o in sub.get("anyOf", [sub]) if o.get("type") == "object"), None)
            items = next((o["items"] for o in sub.get("anyOf", [sub]) if o.get("type") == "array"
                          and isinstance(o.get("items"), dict) and o["items"].get("type") == "object"), None)
            if inner is not None and obj is not None:
                walk(obj, inner, path + ".")
            elif inner is not None and items is not None:
                walk(items, inner, path + "[].")

    walk(schema, Outcome, "")
    return "\n".join(rows)
