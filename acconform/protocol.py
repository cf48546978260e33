"""The implementation protocol: any port, in any language, run by the harness as a process.

``acconform.protocol/1`` is JSON lines over the stdin/stdout of one long-running process
(docs/protocol.md is the reference a porter reads):

1. The implementation starts and writes one handshake line::

       {"protocol": "acconform.protocol/1", "name": "my-port", "version": "1.2",
        "kinds": ["terrain", "bsp", "obstacles", "indoor"], "features": ["engine.client", ...],
        "modes": ["exact"]}

2. For each scene the harness writes one request line and the implementation answers with one
   response line carrying the same id::

       {"id": 7, "mode": "exact", "scene": {... acconform.scene/2 ...}}
       {"id": 7, "outcome": {... acconform.outcome/1 ...}}

   To an implementation listing the feature ``dat`` the request also carries ``"dat"``: the
   scene's world as the DAT records ACE's DatLoader reads (`dat_json`, docs/protocol.md).

   A physics exception is an outcome with ``error`` set (``"NullReferenceException: ..."``).
3. The harness closes stdin when it is done; the implementation exits.

`Implementation` is the harness side: a backend (``scene -> Outcome``) that starts the process,
checks its handshake, and turns a crash, a hang past `timeout`, or a malformed answer into an
outcome whose ``error`` names what happened -- a verdict for that case, never a harness crash --
and starts a fresh process for the next scene. `serve` is the implementation side for the
built-in port (``acconform serve``).
"""

from __future__ import annotations

import base64
import binascii
import json
import os
import selectors
from collections import deque
import shlex
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable

from . import __version__, deep
from .codec import Reader, compact, dumps_compact, loads_answer, write_f32, write_id, write_vec
from .dat import DatMover, DatOther, DatRecord, DatStatic, DatWorld, dat_world
from .errors import AcconformError, InvalidScene
from .flags import PLAYER_KILLER_STATUS_NPK, PhysicsState, PlayerKillerStatus, TransientState, flag_names
from .numerics import RUNTIMES
from .oracle import DEFAULT_RUNTIME
from .oracle.recorded import RecordedText, geometry_kind
from .outcome import Outcome
from .scene import DEFAULT_SKILLS, PROJECTILE_WEENIES, WEENIE_CLASSES, ChildOf, ContactPlane, Launch, MoverSkills, Placement, Position, Scene, mover_start_json
from .staging import MOVER_ID

PROTOCOL = "acconform.protocol/1"
KINDS: tuple[str, ...] = ("terrain", "bsp", "obstacles", "indoor", "buildings")
# A campaign's kinds (`--kinds`, a corpus shard's): the worlds above, and "ticks", tick scenes over any
# of those worlds, offered to an implementation that lists the world's kind and the feature `ticks`. The
# campaign kinds of one tick policy (motion, doors, movers, missiles, targets: strategies.EXTRA_KINDS) are drawn
# only when named; Implementation.kinds offers each by the features it needs.
CAMPAIGN_KINDS: tuple[str, ...] = KINDS + ("ticks",)
MODES: tuple[str, ...] = ("exact", "fast")

# Verdict prefixes: the `error` of the outcome the harness records when the implementation fails.
CRASH = "ImplementationCrash"
TIMEOUT = "ImplementationTimeout"
PROTOCOL_ERROR = "ImplementationProtocolError"
KEPT = " (the case file keeps the whole stderr)"


def _water(scene: Scene) -> bool:
    from .strategies.terrain import is_water_word

    return any(is_water_word(t) for lb in scene.landblocks for t in lb.terrain)


# Scene features an implementation may leave out (it lists the ones it supports in its
# handshake); a scene needing one it did not list is skipped and counted, never run.
def _gone_target(scene: Scene) -> bool:
    """Whether a tick's move_to_object or turn_to_object names another mover destroyed at an earlier tick."""
    if scene.ticks is None:
        return False
    gone = set()
    for step in scene.ticks.steps:
        if any(m is not None and m.object in gone for m in (step.move_to_object, step.turn_to_object)):
            return True
        gone |= {o.id for o in step.others if o.destroy}
    return False


def _no_cell(cell: int) -> bool:
    """A cell id LScape.get_landcell answers null for in a loaded landblock (gid_to_lcoord's cell_in_range fails)."""
    low = cell & 0xFFFF
    return low == 0 or 0x41 <= low <= 0xFF


FEATURES: dict[str, tuple[Callable[[Scene], bool], str]] = {
    "engine.client": (lambda s: s.engine_mode == "client", "the client engine mode (default: server)"),
    "mover.two_spheres": (lambda s: len(s.mover.spheres) == 2, "a mover with two Setup spheres"),
    "mover.scaled": (lambda s: s.mover.scale != 1.0, "a mover whose scale is not 1"),
    "object.scaled": (lambda s: any(o.scale != 1.0 for o in s.objects), "a static object whose scale is not 1"),
    "water": (_water, "terrain with water vertices"),
    "indoor.statics": (lambda s: any(o.position.cell & 0xFFFF >= 0x100 for o in s.objects),
                       "static objects inside EnvCells (DAT stabs, placed when ACE loads the cell)"),
    "mover.placement": (lambda s: s.mover.placement is not None,
                        "the mover placed by ACE before the transition or the ticks: PhysicsObj.SetPosition with the "
                        "placement's flags (scene/3, outcome/3)"),
    "mover.enter_world": (lambda s: s.mover.placement is not None and s.mover.placement.via == "enter_world",
                          "the placement through PhysicsObj.enter_world, as a server's WorldObject enters its landblock "
                          "(WorldObject.AddPhysicsObj; scene/6: placement.via); needs mover.placement too"),
    "ticks": (lambda s: s.ticks is not None,
              "a tick scene: ACE's per-tick update (update_object or the RequestPos path) moves the mover once per "
              "step, answered with one TickState per step (scene/4, outcome/4)"),
    "buildings": (lambda s: bool(s.buildings),
                  "buildings: a landblock's LandblockInfo with BuildInfos (a shell GfxObj, its frame and portals into "
                  "its EnvCells), built by ACE's Landblock.init_buildings (scene/5)"),
    "mover.motion": (lambda s: s.has_motion,
                     "the motion layer: the mover's motion table (MotionTable and Animation DAT records its Setup names, "
                     "made as WorldObject.InitPhysicsObj makes a player with that MotionTableId) and the tick input "
                     "motion, a MoveToState's RawMotionState, and the server's calls into the managers: the tick inputs "
                     "stop, do_motion, stop_motion, move_to, move_to_object, turn_to_heading and turn_to_object "
                     "(scene/6: mover.motion_table, ticks.steps[].motion and the others)"),
    "mover.player_killer_status": (lambda s: s.mover.player_killer_status != PLAYER_KILLER_STATUS_NPK,
                                   "the mover's Player has a PlayerKillerStatus other than NPK (scene/6: "
                                   "mover.player_killer_status): its WeenieObject's IsPK/IsPKLite answers, and a PK or "
                                   "PKLite player's jump takes HandleActionJump's FastTick branch"),
    "mover.skills": (lambda s: s.mover.skills != DEFAULT_SKILLS,
                     "the mover's Player has skills, vitals, attributes or a burden other than the database-free "
                     "Player's (scene/8: mover.skills): GetCreatureSkill(Skill.Run/Jump).Current, Stamina.Current, "
                     "Strength.Current, EncumbranceVal and AugmentationIncreasedCarryingCapacity, what "
                     "WeenieObject.InqRunRate, InqJumpVelocity and InqBurden read"),
    "dat.drawing": (lambda s: s.drawing,
                    "the DAT records carry what a client draws (scene/8: drawing): polygons' UV indices, a BSP GfxObj's "
                    "drawing polygons, drawing BSP (its root sphere is GfxObj.DrawingSphere, a BSP static's "
                    "SortingSphere), surface and degrade table, an EnvCell's surface"),
    "dat.restrictions": (lambda s: s.has_restrictions,
                         "housing barriers (scene/8: env_cells[].restriction_obj, landblocks[].restrictions): an "
                         "EnvCell's RestrictionObj (flag HasRestrictionObj) and a LandblockInfo's RestrictionTables "
                         "(PackMask 1, given to its land cells by Landblock.init_static_objs), which "
                         "ObjCell.check_entry_restrictions asks ServerObjectManager for when the player enters the cell"),
    "dat.outdoor_words": (lambda s: s.has_outdoor_words,
                          "a visible cell or a building portal's other cell below 0x0100 (scene/8): LScape.get_landcell "
                          "gives a LandCell (EnvCell's and BldPortal's cast throws) or null (no land coordinate)"),
    "mover.free_heading": (lambda s: s.mover.free_heading,
                           "the mover's Setup has the flag AllowFreeHeading (scene/8: mover.free_heading): "
                           "PhysicsObj.get_object_info sets ObjectInfoState.FreeRotate, so a transition takes the end's "
                           "orientation at once (Transition.FindTransitionalPosition)"),
    "setup.multipart": (lambda s: any(o.setup is not None for o in s.objects),
                        "a static object made from a Setup of several parts (each a BSP GfxObj at its placement frame, "
                        "with or without a per-part DefaultScale) and the Setup's spheres and cylspheres (scene/7)"),
    "setup.multipart_movers": (lambda s: any(o.setup is not None for o in s.others),
                               "another mover made from a Setup of several parts (scene/8: others[].setup, the parts and "
                               "cylspheres of a static's setup, with the other's own spheres): ACE's PartArray over several "
                               "PhysicsParts, each moved to its placement frame by UpdateParts every tick (needs "
                               "objects.moving)"),
    "setup.no_parts": (lambda s: any(o.setup is not None and not o.setup.parts for o in s.objects + s.others),
                       "a static's or another mover's Setup with no parts (scene/8: setup.parts []): ACE's "
                       "PartArray.InitParts fails, so makeObject's PhysicsObj has no PartArray (a static is then in no "
                       "cell, an other's enter_world fails)"),
    "doors": (lambda s: s.has_doors,
              "the tick input door: an outdoor static, named by id, opens or closes at a tick with the physics of ACE's "
              "server Door (Open: PhysicsState.Ethereal set on its State; FinalizeClose: cleared, then "
              "ethereal_check_for_collisions sets it again when an object overlaps the door, a default server's "
              "allow_door_hold) (scene/7: ticks.steps[].door)"),
    "objects.moving": (lambda s: bool(s.others),
                       "other moving objects (scene/8: others, ticks.steps[].others): each a server WorldObject (a "
                       "Player, a Creature that is or is not a monster, or a GenericObject) with its own id, Setup, "
                       "state and inputs, entered into the world after the mover (enter_world) and stepped by "
                       "update_object after it each tick, in the order they entered; answered with their placements "
                       "and, per tick, their states and every mover's CollisionTable (outcome/6)"),
    "objects.children": (lambda s: any(o.parent is not None for o in s.others) or s.ticks is not None and any(
                             i.parent is not None or i.unparent for step in s.ticks.steps for i in step.others),
                         "children (scene/8: others[].parent, the holders' holding_locations, others[].sorting_sphere): "
                         "another mover held by the mover or an earlier other at a holding location of its Setup, "
                         "parented as the client parents a wielded item (SetPlacementFrame, then set_parent) instead "
                         "of entering the world, never stepped itself and carried by its parent's UpdateChild each "
                         "tick; the tick inputs others[].unparent (unset_parent) and others[].parent "
                         "(SetPlacementFrame, set_parent: held anew); needs objects.moving too"),
    "objects.targets": (lambda s: s.ticks is not None and any(
                            step.stick_to is not None or any(o.destroy for o in step.others) or any(t is not None and t.object in {o.id for o in s.others} | {MOVER_ID}
                                                             for t in (step.move_to_object, step.turn_to_object))
                            for step in s.ticks.steps),
                        "the tick input stick_to (scene/8: a melee swing's PhysicsObj.stick_to_object(the target's id), "
                        "Monster_Melee / Player_Melee) or a move_to_object or turn_to_object whose target is another "
                        "mover (its id among others') or the mover itself, found as the server finds a creature or player "
                        "(ServerObjectManager, set_object_guid): a MoveTo, a sticky follow or a turn at a moving target, "
                        "TargetManager's voyeur updates between the two PhysicsObjs; and another mover destroyed at a tick "
                        "(scene/8 ticks.steps[].others[].destroy: WorldObject.Destroy's PhysicsObj.DestroyObject)"),
    "objects.motion_tables": (lambda s: any(o.motion_table for o in s.others),
                              "another mover (a creature) whose MotionTableId is the mover's table (scene/8: "
                              "others[].motion_table): InitPhysicsObj's SetMotionTableID makes its MotionTableManager "
                              "and MovementManager (EnterDefaultState), update_object animates it, and a Destroy's "
                              "exit_world and leave_world reach them (needs mover.motion and objects.moving)"),
    "objects.gone_targets": (lambda s: _gone_target(s),
                             "a move_to_object at another mover the server destroyed at an earlier tick (scene/8 "
                             "ticks.steps[].move_to_object naming a destroyed other): its WorldObject keeps its "
                             "PhysicsObj after Destroy, out of ServerObjectManager, and the server still passes it "
                             "(Monster_Navigation.StartTurn's AttackTarget.PhysicsObj): TargetManager finds no target "
                             "(needs objects.targets)"),
    "ticks.no_cell_requests": (lambda s: s.ticks is not None and any(
                                   step.request_pos is not None and _no_cell(step.request_pos.cell) for step in s.ticks.steps),
                               "a RequestPos (driver request_pos) into no cell: its id's low word is 0x0000 or "
                               "0x0041..0x00FF, which Player.ValidateMovement lets through in the mover's landblock and "
                               "LScape.get_landcell answers null for, so UpdatePlayerPosition makes no update (scene/8 "
                               "ticks.steps[].request_pos.cell)"),
    "missiles": (lambda s: any(o.launch is not None for o in s.others),
                 "projectiles (scene/8: others[] of weenie ammunition or spell_projectile with a launch): made at the "
                 "start, launched at their step by ACE's launch code (Creature.GetProjectileVelocity or "
                 "WorldObject.CalculateProjectileVelocity, SetProjectilePhysicsState or SpellProjectile.Setup, "
                 "Landblock.AddWorldObject, IsProjectileVisible) and stepped by WorldObject.UpdateObjectPhysics; a hit "
                 "runs ProjectileCollisionHelper or SpellProjectile.ProjectileImpact (needs objects.moving)"),
    "missiles.alt_solver": (lambda s: any(o.launch is not None and o.launch.alt_solver for o in s.others),
                            "a launch under the server property trajectory_alt_solver (scene/8: launch.alt_solver): "
                            "the velocity by Trajectory2.CalculateTrajectory instead of Trajectory's solvers (needs "
                            "missiles)"),
    "missiles.thrown": (lambda s: any(o.weenie == "missile" for o in s.others),
                        "a thrown weapon (scene/8: others[] of weenie missile, ACE's Missile): launched as an arrow "
                        "(Creature.LaunchProjectile), it keeps WorldObject's OnCollideObject and OnCollideEnvironment, "
                        "ProjectileCollisionHelper's only with a ProjectileTarget (needs missiles)"),
    "missiles.missile_flight": (lambda s: any(o.missile_flight for o in s.others),
                                "an arrow's or thrown weapon's Setup with a placement frame keyed MissileFlight (scene/8: "
                                "others[].missile_flight): SetupModel.Unpack's HasMissileFlightPlacement, "
                                "SetProjectilePhysicsState's Placement MissileFlight (needs missiles)"),
    "missiles.untargeted": (lambda s: any(o.launch is not None and o.launch.target is None for o in s.others),
                            "a spell launched at no target (scene/8: a launch without target): "
                            "WorldObject.CalculateProjectileVelocity's forward vector, no ProjectileTarget (needs missiles)"),
    "objects.sphereless": (lambda s: any(not o.spheres for o in s.others),
                           "another mover of weenie object whose Setup has no spheres (scene/8: others[].spheres []): "
                           "enter_world's SetPosition on PhysicsObj.SetPosition's dummy sphere, UpdateObjectInternal's arm "
                           "for an object with none"),
    "objects.motion_tables": (lambda s: any(o.motion_table for o in s.others) or s.ticks is not None and any(
        i.execute_motion is not None for step in s.ticks.steps for i in step.others),
                              "another mover with the scene's motion table (scene/8: others[].motion_table, a Chest's or "
                              "an NPC's MotionTableId) or given WorldObject.ExecuteMotion's physics at a tick "
                              "(ticks.steps[].others[].execute_motion; needs objects.moving)"),
    "objects.report_collisions": (lambda s: any(o.report_collisions is not None for o in s.others),
                                  "another mover whose WorldObject carries the property ReportCollisions (scene/8: "
                                  "others[].report_collisions): a Player's or a Creature's OnCollideObject with one whose "
                                  "property is false returns at once"),
    "missiles.spells": (lambda s: any(o.launch is not None and o.launch.spell != "plain" for o in s.others),
                        "a spell of a kind SpellProjectile.Setup tells apart (scene/8: launch.spell rolling_death, wall, "
                        "ring or ring_3818): Ethereal left for Rolling Death, ScriptedCollision cleared for some wall "
                        "spells and Ring spells, set for Ring spell 3818 (needs missiles)"),
    "missiles.rotation_speed": (lambda s: any(o.launch is not None and o.launch.rotation_speed != 0 for o in s.others),
                                "a projectile with a RotationSpeed (scene/8: launch.rotation_speed, a weenie property of "
                                "some arrows, bolts, thrown weapons and spells): SetProjectilePhysicsState or "
                                "SpellProjectile.Setup clears AlignPath and sets Omega = (2 pi RotationSpeed, 0, 0) "
                                "(needs missiles)"),
    "motion.queries": (lambda s: bool(s.motion_queries),
                       "the server's queries on the mover's motion table (scene/8: motion_queries), asked in order after "
                       "the last tick as ACE's WorldObjects ask them to time attacks, casts, emotes, pickups and deaths: "
                       "the physics MotionTable's static GetAttackFrames, GetAnimationLength (both overloads), "
                       "GetRunSpeed and GetTurnSpeed (with ACE's static RunSpeed and TurnSpeed caches, a fresh server's "
                       "at the scene's start) and the DatLoader MotionTable's GetAnimationLength; answered in "
                       "outcome/6's motion_answers"),
}


# The campaign kinds of one tick policy (strategies.EXTRA_KINDS): the features an implementation lists to run
# each (Implementation.kinds); the last is the kind's own, the one a scene of the kind needs (`of_kind`).
KIND_FEATURES: dict[str, tuple[str, ...]] = {
    "motion": ("ticks", "mover.motion"),
    "doors": ("ticks", "doors"),
    "movers": ("ticks", "objects.moving"),
    "missiles": ("ticks", "objects.moving", "missiles"),
    "targets": ("ticks", "mover.motion", "objects.moving", "objects.targets"),
}


def of_kind(scene: Scene, kind: str) -> bool:
    """Whether a tick scene is of the tick-policy kind: it needs the kind's own feature. A recorded corpus
    files these scenes as "ticks"; a replay of --kinds motion (doors, movers, missiles, targets) runs the
    tick records this holds for, as a live campaign of that kind draws only such scenes."""
    return scene.ticks is not None and FEATURES[KIND_FEATURES[kind][-1]][0](scene)


# Features an implementation may offer that no scene needs: it lists them in its handshake too.
CAPABILITIES: dict[str, str] = {
    "trace": "answers a request carrying \"trace\": true with its outcome and a \"trace\" of records "
             "(acconform.trace/1): `acconform explain` finds the first record where it parts from the port",
    "dat": "takes with every request the scene's world as DAT records (\"dat\": acconform.dat/1), to build it "
           "with its own DAT loader",
}


# ---------------------------------------------------------------- the scene's DAT records (feature `dat`)

DAT_FORMAT = "acconform.dat/1"
# the DatLoader FileType classes each DAT's records may be
DAT_TYPES = {"cell": ("CellLandblock", "LandblockInfo", "EnvCell"),
             "portal": ("GfxObj", "SetupModel", "Environment", "MotionTable", "Animation")}


def _record_json(rec: DatRecord) -> dict:
    return {"id": write_id(rec.id), "type": rec.kind, "data": base64.b64encode(rec.data).decode("ascii")}


def dat_json(world: DatWorld) -> dict:
    """A request's ``"dat"``: the scene's world (dat.dat_world) as JSON (docs/protocol.md, "DAT records")."""
    m = world.mover
    mover = mover_start_json(m, {"id": write_id(m.id), "did": write_id(m.did), "scale": write_f32(m.scale)},
                             explicit_via=True)
    if m.motion_table_id:
        mover["motion_table_id"] = write_id(m.motion_table_id)
    if m.player_killer_status != PLAYER_KILLER_STATUS_NPK:
        mover["player_killer_status"] = PlayerKillerStatus(m.player_killer_status).name
    if m.skills != DEFAULT_SKILLS:
        mover["skills"] = m.skills.to_json()
    return {"format": DAT_FORMAT,
            "land_height_table": [write_f32(h) for h in world.land_height_table],
            "cell": [_record_json(r) for r in world.cell],
            "portal": [_record_json(r) for r in world.portal],
            "statics": [{"id": write_id(s.id), "did": write_id(s.did), "position": s.position.to_json(),
                         "state": flag_names(PhysicsState, s.state), "scale": write_f32(s.scale)} for s in world.statics],
            "mover": mover,
            **({"others": [_other_json(o) for o in world.others]} if world.others else {})}


def _other_json(o: DatOther) -> dict:
    d = {"id": write_id(o.id), "did": write_id(o.did), "weenie": o.weenie, "scale": write_f32(o.scale),
         "state": flag_names(PhysicsState, o.state), "transient_state": flag_names(TransientState, o.transient_state),
         "velocity": write_vec(o.velocity)}
    if o.begin is not None:
        d["begin"] = o.begin.to_json()
    if o.player_killer_status != PLAYER_KILLER_STATUS_NPK:
        d["player_killer_status"] = PlayerKillerStatus(o.player_killer_status).name
    if o.parent is not None:
        d["parent"] = o.parent.to_json()
    if o.launch is not None:
        d["launch"] = o.launch.to_json(o.weenie == "spell_projectile")
    if o.report_collisions is not None:
        d["report_collisions"] = o.report_collisions
    if o.motion_table_id:
        d["motion_table_id"] = write_id(o.motion_table_id)
    return d


def _records_from_json(r: Reader, dat: str) -> tuple[DatRecord, ...]:
    out = []
    seen = set()
    for item in r.list():
        item.obj({"id", "type", "data"})
        rid = item["id"].id_()
        if rid in seen:
            item["id"].fail(f"a second {dat} DAT record {write_id(rid)}: ids are distinct within a DAT")
        seen.add(rid)
        kind = item["type"].str_()
        if kind not in DAT_TYPES[dat]:
            item["type"].fail(f"{kind!r} is not a {dat} DAT type (one of {', '.join(DAT_TYPES[dat])})")
        try:
            data = base64.b64decode(item["data"].str_(), validate=True)
        except binascii.Error as e:
            item["data"].fail(f"not base64: {e}")
        out.append(DatRecord(rid, kind, data))
    return tuple(out)


def dat_from_json(doc, path: str = "dat") -> DatWorld:
    """A request's ``"dat"`` read back; InvalidScene naming the field otherwise."""
    r = Reader(doc, path).obj({"format", "land_height_table", "cell", "portal", "statics", "mover", "others"})
    if r["format"].value != DAT_FORMAT:
        r["format"].fail(f"{r['format'].value!r}; this acconform reads {DAT_FORMAT!r}")
    statics = []
    for s in r["statics"].list():
        s.obj({"id", "did", "position", "state", "scale"})
        statics.append(DatStatic(s["id"].id_(), s["did"].id_(), Position.from_json(s["position"]),
                                 s["state"].flags(PhysicsState), s["scale"].f32()))
    m = r["mover"].obj({"id", "did", "scale", "state", "transient_state", "velocity", "begin", "end", "contact_plane",
                        "sliding_normal", "placement", "motion_table_id", "player_killer_status", "skills"})
    status = m["player_killer_status"].enum_(PlayerKillerStatus) if m.given("player_killer_status") \
        else PLAYER_KILLER_STATUS_NPK
    mover = DatMover(m["id"].id_(), m["did"].id_(), m["scale"].f32(), m["state"].flags(PhysicsState),
                     m["transient_state"].flags(TransientState), m["velocity"].vec3(), Position.from_json(m["begin"]),
                     Position.from_json(m["end"]) if m.has("end") else None,
                     ContactPlane.from_json(m["contact_plane"]) if m.has("contact_plane") else None,
                     m["sliding_normal"].vec3() if m.has("sliding_normal") else None,
                     Placement.from_json(m["placement"]) if m.has("placement") else None,
                     m["motion_table_id"].id_() if m.given("motion_table_id") else 0, status,
                     MoverSkills.from_json(m["skills"]) if m.given("skills") else DEFAULT_SKILLS)
    others = []
    for o in (r["others"].list() if r.given("others") else ()):
        o.obj({"id", "did", "weenie", "scale", "state", "transient_state", "velocity", "begin", "player_killer_status",
               "parent", "launch", "report_collisions", "motion_table_id"})
        weenie = o["weenie"].str_()
        if weenie not in WEENIE_CLASSES:
            o["weenie"].fail(f"unknown weenie {weenie!r} (known: {', '.join(WEENIE_CLASSES)})")
        parent = ChildOf.from_json(o["parent"]) if o.given("parent") else None
        if parent is not None and o.given("begin"):
            o["begin"].fail("a child enters the world with its parent (set_parent, not enter_world): omit begin")
        launch = None
        if weenie in PROJECTILE_WEENIES:
            if not o.given("launch"):
                o.fail(f"a projectile (weenie {weenie}) needs its launch")
            launch = Launch.from_json(o["launch"], weenie == "spell_projectile")
        elif o.given("launch"):
            o["launch"].fail(f"a launch is a projectile's, not a {weenie}'s")
        others.append(DatOther(o["id"].id_(), o["did"].id_(), weenie, o["scale"].f32(), o["state"].flags(PhysicsState),
                               o["transient_state"].flags(TransientState), o["velocity"].vec3(),
                               None if parent is not None else Position.from_json(o["begin"]),
                               o["player_killer_status"].enum_(PlayerKillerStatus) if o.given("player_killer_status")
                               else PLAYER_KILLER_STATUS_NPK, parent, launch,
                               o["report_collisions"].bool_() if o.given("report_collisions") else None,
                               o["motion_table_id"].id_() if o.given("motion_table_id") else 0))
    return DatWorld(r["land_height_table"].f32s(256),
                    _records_from_json(r["cell"], "cell"), _records_from_json(r["portal"], "portal"),
                    tuple(statics), mover, tuple(others))


def scene_features(scene: Scene, names=FEATURES) -> list[str]:
    """The features among `names` (default: all) the scene needs, in FEATURES' order; an
    implementation's unsupported() asks only of those it lacks (none, for most)."""
    return [name for name in names if FEATURES[name][0](scene)]


class ImplementationError(AcconformError):
    """The implementation cannot be used at all (it does not start, or its handshake is wrong)."""


def handshake(name: str = "acconform", version: str = __version__) -> dict:
    """The built-in port's handshake: every kind, every feature, both modes."""
    return {"protocol": PROTOCOL, "name": name, "version": version, "kinds": list(KINDS),
            "features": list(FEATURES) + list(CAPABILITIES), "modes": list(MODES)}


def check_handshake(doc, command: str) -> dict:
    """The handshake, checked; ImplementationError naming the field otherwise."""
    def bad(problem):
        return ImplementationError(f"implementation {command!r}: bad handshake: {problem} "
                                   f"(docs/protocol.md describes it)")

    if not isinstance(doc, dict):
        raise bad("expected a JSON object")
    if doc.get("protocol") != PROTOCOL:
        raise bad(f"protocol {doc.get('protocol')!r}; this acconform speaks {PROTOCOL!r}")
    for key, known in (("kinds", KINDS), ("features", tuple(FEATURES) + tuple(CAPABILITIES)), ("modes", MODES)):
        v = doc.get(key)
        if not isinstance(v, list) or not all(isinstance(x, str) for x in v):
            raise bad(f"{key!r} must be a list of strings")
        unknown = [x for x in v if x not in known]
        if unknown:
            raise bad(f"unknown {key} {', '.join(map(repr, unknown))} (known: {', '.join(known)})")
    if not doc["kinds"]:
        raise bad("'kinds' is empty: the implementation supports no scene kind")
    if not doc["modes"]:
        raise bad("'modes' is empty")
    return {"protocol": PROTOCOL, "name": str(doc.get("name", "")), "version": str(doc.get("version", "")),
            "kinds": doc["kinds"], "features": doc["features"], "modes": doc["modes"]}


class _Failed(Exception):
    """The process failed on this scene; args[0] is the verdict text."""


TRACED_TIMEOUT = 30  # a traced request may take this many times --timeout: a trace costs 20-30x a plain run


class Implementation:
    """An implementation under test, run as a process speaking acconform.protocol/1.

    A backend: ``impl(scene) -> Outcome`` (also ``impl.run``). `unsupported(scene)` names why a
    scene cannot be run (its kind or a feature missing from the handshake), or returns None.
    The handshake is read at construction, so a command that does not start fails at once
    (ImplementationError, exit 2). Each process id gets its own child process: forked campaign
    workers start their own on first use. `restarts` counts the processes started after a failure.
    """

    per_process = True

    def __init__(self, command: str, *, mode: str = "exact", timeout: float = 10.0, start_timeout: float = 60.0,
                 cwd: str | None = None):
        if mode not in MODES:
            raise AcconformError(f"unknown mode {mode!r}: choose exact or fast")
        self.command = command
        self.cwd = cwd or os.getcwd()  # where it runs (a case records it: `repro` starts it there again)
        try:
            self.argv = shlex.split(command)
        except ValueError as e:  # an unbalanced quote
            raise ImplementationError(f"--impl {command!r}: cannot split into a command and its arguments "
                                      f"({str(e).lower()}); check the quotes") from None
        if not self.argv:
            raise ImplementationError("--impl needs a command, e.g. --impl 'acconform serve'")
        self.mode = mode
        self.runtime = DEFAULT_RUNTIME  # the ACE compared with: whose System.Numerics arithmetic to match
        self.timeout = timeout
        self.start_timeout = start_timeout
        self.restarts = 0
        self.failures: dict[str, int] = {}
        self._proc = None
        self._pid = None
        self._buf = bytearray()
        self._out = bytearray()  # requests' bytes the process's stdin has not taken yet
        self._next_id = 0
        self._inflight: deque[tuple[int, Scene]] = deque()  # requests sent, answers not yet read, in order
        self._answers: dict[int, Outcome] = {}
        self._traces: dict[int, tuple] = {}  # request id -> (trace records, declared anchors) its answer carried
        self._traced: set[int] = set()  # request ids sent with "trace": true
        self._stderr_of: dict[int, str] = {}  # request id -> the process's stderr when it failed on it
        self.last_stderr = ""  # of the scene `run` answered last: its stderr if it failed, else ""
        self._sel = None
        self.hello = self._start()
        if mode not in self.hello["modes"]:
            self.close()
            raise ImplementationError(f"implementation {command!r} does not support mode {mode!r} "
                                      f"(its handshake lists {', '.join(self.hello['modes'])})")

    @property
    def name(self) -> str:
        return self.hello["name"] or self.argv[0]

    @property
    def kinds(self) -> tuple[str, ...]:
        """The campaign kinds it can run: its handshake's, "ticks" when it lists the feature, and "motion"
        (motion tick scenes) when it lists ticks and mover.motion, "missiles" when it lists ticks, objects.moving and
        missiles, "targets" when it lists ticks, mover.motion, objects.moving and objects.targets."""
        features = self.hello["features"]
        return (tuple(self.hello["kinds"]) + (("ticks",) if "ticks" in features else ())
                + tuple(kind for kind, needs in KIND_FEATURES.items() if set(needs) <= set(features)))

    @property
    def runs_every_scene(self) -> bool:
        """Whether its handshake lists every kind and every feature: no scene is skipped, so a scene
        need not be read to be sent (a replay sends a recorded scene as its text: `run_text`)."""
        return set(KINDS) <= set(self.hello["kinds"]) and set(FEATURES) <= set(self.hello["features"])

    def unsupported(self, scene: Scene) -> str | None:
        kind = geometry_kind(scene)  # a tick scene's too: the ticks themselves are a feature
        if kind not in self.hello["kinds"]:
            return f"kind {kind}"
        missing = scene_features(scene, [f for f in FEATURES if f not in self.hello["features"]])
        return f"feature {missing[0]}" if missing else None

    # ------------------------------------------------------------ process

    def _start(self) -> dict:
        self._stderr = tempfile.TemporaryFile()
        try:
            self._proc = subprocess.Popen(self.argv, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                          stderr=self._stderr, bufsize=0, cwd=self.cwd,
                                          start_new_session=True)  # Ctrl-C in the terminal is the harness's
        except OSError as e:
            raise ImplementationError(f"cannot start implementation {self.command!r}: {e.strerror or e}") from None
        self._pid = os.getpid()
        self._buf = bytearray()
        self._out = bytearray()
        self._sel = selectors.DefaultSelector()
        self._sel.register(self._proc.stdout.fileno(), selectors.EVENT_READ)
        os.set_blocking(self._proc.stdin.fileno(), False)
        try:
            line = self._readline(self.start_timeout)
        except _Failed as e:
            self._kill()
            why = e.args[0]
            if why.startswith(TIMEOUT):  # a process that never speaks the protocol, or starts too slowly
                why = (f"none within {self.start_timeout:g} s, so it was stopped (--timeout sets the wait); an "
                       f"{PROTOCOL} implementation writes its handshake line first (docs/protocol.md)")
            raise ImplementationError(f"implementation {self.command!r} sent no handshake: {why.replace(KEPT, '')}") from None
        try:
            doc = json.loads(line)
        except ValueError:
            self._kill()
            raise ImplementationError(f"implementation {self.command!r}: bad handshake: not JSON: "
                                      f"{line[:120]!r}") from None
        try:
            return check_handshake(doc, self.command)
        except ImplementationError:
            self._kill()
            raise

    def _stderr_text(self) -> str:
        """The process's whole stderr so far, bounded as a case keeps it (case.bound_stderr)."""
        from .case import bound_stderr

        try:
            self._stderr.seek(0)
            return bound_stderr(self._stderr.read().decode("utf-8", "replace"))
        except (OSError, ValueError):
            return ""

    def case_implementation(self):
        """What a case records of this implementation: command, directory, handshake, and the
        stderr of the scene answered last when the process failed on it."""
        from .case import ImplementationRun

        return ImplementationRun(self.command, self.cwd, dict(self.hello), self.last_stderr)

    def _stderr_tail(self) -> str:
        """For the one-line verdict: the last stderr line naming an error (an ``Error:``, an
        exception, a panic), else the last line. The case file keeps the whole stderr."""
        try:
            self._stderr.seek(0, os.SEEK_END)
            size = self._stderr.tell()
            self._stderr.seek(max(0, size - 4096))
            lines = [l.strip() for l in self._stderr.read().decode("utf-8", "replace").splitlines() if l.strip()]
        except (OSError, ValueError):
            return ""
        if not lines:
            return ""
        named = [l for l in lines if any(w in l for w in ("Error", "Exception", "panic", "Traceback", "FATAL"))]
        return f"; stderr: {(named or lines)[-1][:200]}{KEPT}"

    def _readline(self, timeout: float) -> str:
        """The next answer line, writing what is left of the requests sent meanwhile (a big scene
        waits in `_out` while the process works on the one before it)."""
        deadline = time.monotonic() + timeout
        fd = self._proc.stdout.fileno()
        while True:
            nl = self._buf.find(b"\n")
            if nl >= 0:
                line = bytes(self._buf[:nl])
                del self._buf[:nl + 1]
                return line.decode("utf-8", "replace")
            left = deadline - time.monotonic()
            events = self._sel.select(left) if left > 0 else []
            if not events:
                raise _Failed(f"{TIMEOUT}: no answer within {timeout:g} s; the process was killed and restarted")
            for key, _ in events:
                if key.fd != fd:
                    self._flush()
                    continue
                data = os.read(fd, 1 << 16)
                if not data:  # it closed its stdout: it exits, or it lives on and can never answer
                    try:
                        code = self._proc.wait(max(deadline - time.monotonic(), 0.1))
                    except subprocess.TimeoutExpired:
                        raise _Failed(f"{CRASH}: the process closed its output and did not exit within "
                                      f"{timeout:g} s; it was killed and restarted{self._stderr_tail()}") from None
                    raise _Failed(f"{CRASH}: the process exited with code {code}{self._stderr_tail()}")
                self._buf += data

    def _kill(self) -> None:
        p, self._proc = self._proc, None
        self._out = bytearray()
        if p is None:
            return
        if self._sel is not None:
            self._sel.close()
            self._sel = None
        if self._pid == os.getpid():
            for f in (p.stdin, p.stdout):
                try:
                    f.close()
                except OSError:
                    pass
            if p.poll() is None:
                p.kill()
            p.wait()
        else:  # a forked worker: the process belongs to the parent; drop our copies of its pipes
            for f in (p.stdin, p.stdout):
                try:
                    os.close(f.fileno())
                except (OSError, ValueError):
                    pass
        try:
            self._stderr.close()
        except OSError:
            pass

    def close(self) -> None:
        """End the process: close its stdin (it exits), kill it if it lingers."""
        p = self._proc
        if p is not None and self._pid == os.getpid():
            try:
                p.stdin.close()
                p.wait(timeout=2)
            except (OSError, subprocess.TimeoutExpired):
                pass
        self._kill()

    def __del__(self):
        try:
            self.close()
        except Exception:  # noqa: BLE001 - interpreter shutdown
            pass

    # ------------------------------------------------------------ one scene

    def __call__(self, scene: Scene) -> Outcome:
        return self.run(scene)

    def run(self, scene: Scene) -> Outcome:
        """The implementation's outcome for `scene` (sent now, unless `prefetch` sent it already)."""
        why = self._ensure()
        if why is not None:
            self.last_stderr = ""
            return self._verdict(why)
        return self._answer(scene)

    def run_text(self, recorded: RecordedText) -> Outcome | None:
        """The implementation's outcome for a recorded scene sent as its JSON text; None when the
        answer is the recorded outcome's text itself (ACE's answer, so nothing to read or compare)."""
        why = self._ensure()
        if why is not None:
            self.last_stderr = ""
            return self._verdict(why)
        return self._answer(recorded)

    def _answer(self, scene: "Scene | RecordedText") -> Outcome | None:
        rid = next((r for r, s in self._inflight if s is scene), None)
        if rid is None:
            rid = self._send(scene)
        while rid not in self._answers:
            self._read_answer()
        for old in [r for r in self._answers if r < rid]:  # answers to prefetched scenes never asked for
            del self._answers[old]
            self._stderr_of.pop(old, None)
        self.last_stderr = self._stderr_of.pop(rid, "")
        return self._answers.pop(rid)

    @property
    def traces(self) -> bool:
        """Whether its handshake lists the `trace` feature."""
        return "trace" in self.hello["features"]

    @property
    def takes_dat(self) -> bool:
        """Whether its handshake lists the `dat` feature: each request then carries the scene's DAT records."""
        return "dat" in self.hello["features"]

    def run_traced(self, scene: Scene):
        """(outcome, trace records, the routines its trace declares) for `scene`, asked with
        ``"trace": true``; records and routines are None when the implementation does not trace (no
        `trace` feature) or failed on the scene, the routines None when its trace declares none."""
        if not self.traces:
            return self.run(scene), None, None
        why = self._ensure()
        if why is not None:
            return self._verdict(why), None, None
        while self._inflight:  # answers to scenes sent ahead come first
            self._read_answer()
        self._answers.clear()
        self._next_id += 1
        rid = self._next_id
        self._inflight.append((rid, scene))
        self._traced.add(rid)
        self._send(scene, rid)
        while rid not in self._answers:
            self._read_answer()
        self._traced.discard(rid)
        records, anchors = self._traces.pop(rid, (None, None))
        return self._answers.pop(rid), records, anchors

    def prefetch(self, scene: "Scene | RecordedText") -> None:
        """Send `scene` ahead, so the implementation works on it while the harness compares the
        previous answer (a replay knows its next scene; a campaign draws it ahead). At most two
        requests are in flight. A
        recorded scene's text is sent only to an implementation that `runs_every_scene`."""
        if (len(self._inflight) < 2 and self._ensure() is None
                and (self.runs_every_scene if isinstance(scene, RecordedText) else self.unsupported(scene) is None)):
            self._send(scene)

    def _ensure(self) -> str | None:
        """A process for this process id (forked workers start their own); a verdict text if none starts."""
        if self._proc is None or self._pid != os.getpid():
            if self._pid != os.getpid():  # a forked worker: the parent's process and requests are not ours
                self._kill()
                self._inflight.clear()
                self._answers.clear()
            try:
                self._start()
            except ImplementationError as e:
                return f"{CRASH}: could not restart: {e}"
        return None

    def _send(self, scene: "Scene | RecordedText", rid: int | None = None) -> int:
        if rid is None:
            self._next_id += 1
            rid = self._next_id
            self._inflight.append((rid, scene))
        if isinstance(scene, RecordedText):  # the scene's JSON as the harness wrote it when it was recorded
            records = ""
            if self.takes_dat:  # the records are written from the scene, so it is read here (a deep BSP on the deep stack)
                records = ',"dat":' + deep.retrying(lambda: compact(lambda: dat_json(dat_world(Scene.loads(scene.scene)))))
            self._write(f'{{"id":{rid},"mode":"{self.mode}","runtime":"{self.runtime}","scene":{scene.scene}{records}}}\n'
                        .encode("utf-8"))
            return rid
        extra = {"trace": True} if rid in self._traced else {}
        # the scene's JSON and records inside the retry: a BSP thousands of levels deep needs the deep stack to write
        request = deep.retrying(lambda: compact(lambda: {"id": rid, "mode": self.mode, "runtime": self.runtime,
                                                         "scene": scene.to_json(), **extra, **self._dat(scene)})) + "\n"
        self._write(request.encode("utf-8"))
        return rid

    def _dat(self, scene: Scene) -> dict:
        """A request's ``"dat"`` for an implementation that takes it (`takes_dat`), else nothing."""
        return {"dat": dat_json(dat_world(scene))} if self.takes_dat else {}

    def _write(self, data: bytes) -> None:
        """Send a request without ever blocking: a process busy with the request before it (or hung)
        stops reading, and a request longer than the pipe holds would otherwise hold the harness,
        or be cut off half-written, the next one's text appended to it. What does not fit waits in
        `_out` and is written as the pipe drains, while the harness waits for answers (`_readline`)."""
        self._out += data
        self._flush()

    def _flush(self) -> None:
        """Write what the pipe takes of `_out`; watch the pipe for room while anything is left. A
        process that has gone shows up when its answer is read (its exit code)."""
        fd = self._proc.stdin.fileno()
        try:
            while self._out:
                del self._out[:os.write(fd, self._out)]
        except BlockingIOError:
            pass
        except (BrokenPipeError, ConnectionResetError):
            self._out.clear()
        watching = fd in self._sel.get_map()
        if self._out and not watching:
            self._sel.register(fd, selectors.EVENT_WRITE)
        elif not self._out and watching:
            self._sel.unregister(fd)

    def _read_answer(self) -> None:
        """Read the answer to the oldest request in flight, or give it a verdict and restart. The
        answer to a recorded scene's text that is the recorded outcome's text, byte for byte, is
        stored as None: it is ACE's answer as recorded, so there is nothing to read or compare."""
        rid, sent = self._inflight[0]
        try:
            line = self._readline(self.timeout * (TRACED_TIMEOUT if rid in self._traced else 1))
        except _Failed as e:
            return self._fail_head(e.args[0])
        if isinstance(sent, RecordedText):
            head = f'{{"id":{rid},"outcome":'
            if (line.startswith(head) and line.endswith("}") and len(line) == len(head) + len(sent.outcome) + 1
                    and line[len(head):-1] == sent.outcome):
                self._inflight.popleft()
                self._answers[rid] = None
                return
        try:
            doc = loads_answer(line)  # -0 is negative zero
            if not isinstance(doc, dict):
                raise ValueError("not a JSON object")
            if doc.get("id") != rid:
                raise ValueError(f"answer id {doc.get('id')!r}, expected {rid}")
            if "outcome" not in doc:
                raise ValueError("no \"outcome\" field")
            outcome = Outcome.from_json(doc["outcome"], "outcome")  # a float must name a float32
            if rid in self._traced:
                if "trace" not in doc:
                    raise ValueError("no \"trace\" field, though the request asked for one (feature trace)")
                from .trace import trace_anchors, trace_from_json

                self._traces[rid] = (trace_from_json(doc["trace"], "trace", exact=True), trace_anchors(doc["trace"]))
        except (ValueError, InvalidScene) as e:
            return self._fail_head(f"{PROTOCOL_ERROR}: malformed answer ({e}): {line[:120]!r}")
        self._inflight.popleft()
        self._answers[rid] = outcome

    def _fail_head(self, text: str) -> None:
        """The oldest request's verdict; a fresh process gets the requests still in flight."""
        rid, _ = self._inflight.popleft()
        self._answers[rid] = self._verdict(text)
        self._stderr_of[rid] = self._stderr_text()
        rest = list(self._inflight)
        self._inflight.clear()
        self._kill()
        self.restarts += 1
        why = self._ensure()
        for r, scene in rest:
            if why is not None:
                self._answers[r] = self._verdict(why)
            else:
                self._inflight.append((r, scene))
                self._send(scene, r)

    def _verdict(self, text: str) -> Outcome:
        kind = text.split(":", 1)[0]
        self.failures[kind] = self.failures.get(kind, 0) + 1
        return Outcome(error=text)


# ---------------------------------------------------------------- the implementation side


def serve(run_scene: Callable[[Scene, str, str], Outcome], stdin=None, stdout=None, hello: dict | None = None,
          default_runtime: str = DEFAULT_RUNTIME, run_traced=None, trace_anchors=None, run_dat=None) -> int:
    """Answer protocol requests from `stdin` on `stdout` until stdin closes (the built-in port's side);
    a request that names no runtime is computed as `default_runtime`. `run_traced(scene, mode,
    runtime) -> (outcome, records)` answers a request with ``"trace": true`` (feature `trace`), its
    trace declaring `trace_anchors` (the routines it records) when given. `run_dat(scene, world,
    mode, runtime) -> outcome` answers a request carrying ``"dat"`` (feature `dat`: `world` is the
    request's records, read by `dat_from_json`).

    A request that cannot be read is answered with an outcome whose error says why (the harness
    counts it as the implementation's verdict); the loop goes on.
    """
    stdin = stdin or sys.stdin.buffer
    stdout = stdout or sys.stdout.buffer
    stdout.write((dumps_compact(hello or handshake()) + "\n").encode("utf-8"))
    stdout.flush()
    for raw in stdin:
        if not raw.strip():
            continue
        rid = None
        try:
            req = deep.retrying(json.loads, raw)
            rid = req.get("id") if isinstance(req, dict) else None
            if not isinstance(req, dict) or "scene" not in req:
                raise ValueError("expected {\"id\": ..., \"mode\": ..., \"scene\": {...}}")
            mode, runtime = req.get("mode", "exact"), req.get("runtime", default_runtime)
            if mode not in MODES:
                raise ValueError(f"unknown mode {mode!r}")
            if runtime not in RUNTIMES:
                raise ValueError(f"unknown runtime {runtime!r} (known: {', '.join(RUNTIMES)})")
            scene = deep.retrying(Scene.from_json, req["scene"], "scene")
            records = None
            if req.get("trace") is True and run_traced is not None:
                outcome, records = run_traced(scene, mode, runtime)
            elif "dat" in req and run_dat is not None:
                outcome = run_dat(scene, dat_from_json(req["dat"]), mode, runtime)
            else:
                outcome = run_scene(scene, mode, runtime)
        except (ValueError, InvalidScene) as e:
            outcome, records = Outcome(error=f"InvalidRequest: {e}"), None
        answer = {"id": rid, "outcome": outcome.to_json()}
        if records is not None:
            from .trace import trace_to_json

            answer["trace"] = trace_to_json(records, trace_anchors)
        stdout.write((dumps_compact(answer) + "\n").encode("utf-8"))
        stdout.flush()
    return 0
