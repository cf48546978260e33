"""The protocol's feature `dat`: a request carries the scene's world as DAT records, and the built-in
port builds its world from them alone (docs/protocol.md, "DAT records").

The records an implementation gets are exactly those ACE's facade installs (oracle/pack.py's bytes,
parsed back here), each one reads with the port's DatLoader (port/dat/), and the built-in port
answers every corpus kind the same from the records as from the scene.
"""

from __future__ import annotations

import base64
import json
import struct
import subprocess
import sys
from dataclasses import replace
from pathlib import Path

import pytest

from acconform import dat
from acconform.codec import dumps_compact
from acconform.errors import InvalidScene
from acconform.numerics import get_mode
from acconform.oracle.pack import _RECORD_KIND, pack_scene
from acconform.oracle.recorded import RecordedText, scene_kind
from acconform.outcome import Outcome
from acconform.port.dat.animation import Animation
from acconform.port.dat.binary_reader import BinaryReader
from acconform.port.dat.cell_landblock import CellLandblock
from acconform.port.dat.env_cell import EnvCell
from acconform.port.dat.environment import Environment
from acconform.port.dat.gfx_obj import GfxObj
from acconform.port.dat.landblock_info import LandblockInfo
from acconform.port.dat.motion_table import MotionTable
from acconform.port.dat.setup_model import SetupModel
from acconform.port.run import run_scene
from acconform.protocol import DAT_FORMAT, Implementation, dat_from_json, dat_json, handshake
from acconform.scene import Scene

ROOT = Path(__file__).resolve().parents[2]
KINDS = ("terrain", "bsp", "obstacles", "indoor", "buildings", "ticks")
PER_KIND = 4
READERS = {"CellLandblock": CellLandblock, "LandblockInfo": LandblockInfo, "EnvCell": EnvCell,
           "Environment": Environment, "GfxObj": GfxObj, "SetupModel": SetupModel, "MotionTable": MotionTable,
           "Animation": Animation}

# An implementation that writes each request line to a log and answers with an error outcome (every field).
RECORDER = """
import json, sys
features = sys.argv[2].split(",") if sys.argv[2] else []
print(json.dumps({"protocol": "acconform.protocol/1", "name": "recorder", "version": "1",
                  "kinds": ["terrain", "bsp", "obstacles", "indoor", "buildings"],
                  "features": features, "modes": ["exact"]}), flush=True)
with open(sys.argv[1], "a") as log:
    for line in sys.stdin:
        log.write(line)
        log.flush()
        outcome = json.loads(%r)
        outcome["error"] = "RecorderException: no physics here"
        print(json.dumps({"id": json.loads(line)["id"], "outcome": outcome}), flush=True)
""" % json.dumps(Outcome(error="x").to_json())


@pytest.fixture(scope="module")
def corpus_scenes() -> dict[str, list[Scene]]:
    from acconform.oracle import default_corpus
    from acconform.oracle.recorded import RecordedOracle

    oracle = RecordedOracle(default_corpus())
    out: dict[str, list[Scene]] = {}
    for kind in KINDS:
        entries = oracle.select(n=PER_KIND, seed=3, kinds=(kind,))
        out[kind] = list(oracle.scenes(entries))
    assert all(len(out[k]) == PER_KIND for k in KINDS), {k: len(v) for k, v in out.items()}
    return out


def _all(corpus_scenes) -> list[Scene]:
    return [s for k in KINDS for s in corpus_scenes[k]]


def _recorder(tmp_path: Path, features: str) -> tuple[Implementation, Path]:
    script = tmp_path / "recorder.py"
    script.write_text(RECORDER)
    log = tmp_path / f"requests-{features or 'none'}.jsonl"
    return Implementation(f"{sys.executable} {script} {log} '{features}'"), log


def _requests(log: Path) -> list[dict]:
    return [json.loads(line) for line in log.read_text().splitlines()]


def _facade_records(scene) -> tuple[bytes, list[tuple[str, int, bytes]]]:
    """What ACE's facade installs from oracle/pack.py's bytes for `scene` (Facade.cs BuildScene): the land
    height table's bytes and every DAT record as (type, id, bytes), CellLandblocks included. The tick block
    (its inputs, of every kind) is skipped by its length as oracle/pack.py writes it."""
    from acconform.oracle.pack import _ticks

    packed = pack_scene(scene)
    kinds = {v: k for k, v in _RECORD_KIND.items()}
    at = 5 + len(_ticks(scene.ticks, scene.others))  # PackVersion and engine mode, then the ticks
    table = packed[at:at + 1024]
    at += 1024
    out = []

    def record_list():
        nonlocal at
        (n,) = struct.unpack_from("<i", packed, at)
        at += 4
        for _ in range(n):
            kind, rid, length = struct.unpack_from("<BIi", packed, at)
            at += 9
            out.append((kinds[kind], rid, packed[at:at + length]))
            at += length

    (n,) = struct.unpack_from("<i", packed, at)
    at += 4
    for _ in range(n):
        (length,) = struct.unpack_from("<i", packed, at)
        data = packed[at + 4:at + 4 + length]
        out.append(("CellLandblock", struct.unpack_from("<I", data)[0], data))
        at += 4 + length
    record_list()
    (n,) = struct.unpack_from("<i", packed, at)
    at += 4
    for _ in range(n):
        at += 48  # id, position, state, scale, did
        record_list()
    record_list()  # the mover's
    from acconform.oracle.pack import _CHILD, _LAUNCH, _MOVER, _OTHER

    at += _MOVER.size
    (n,) = struct.unpack_from("<i", packed, at)
    at += 4
    for _ in range(n):  # the other movers' (scene/8): each one's Setup, then its fixed record, child, launch,
        record_list()     # ReportCollisions property byte and (pack 18) MotionTableId
        at += _OTHER.size + _CHILD.size
        at += _LAUNCH.size if packed[at] else 1
        at += 1 + 4
    return table, out


def test_the_builtin_port_lists_dat_in_its_handshake():
    assert "dat" in handshake()["features"]


def test_an_implementation_without_dat_is_never_sent_records(tmp_path, corpus_scenes):
    impl, log = _recorder(tmp_path, "ticks,buildings,indoor.statics,mover.placement,engine.client,water")
    try:
        for scene in _all(corpus_scenes)[::3]:
            assert impl.run(scene).error.startswith("RecorderException")
    finally:
        impl.close()
    requests = _requests(log)
    assert requests and all("dat" not in r for r in requests)


def test_an_implementation_with_dat_gets_the_records_dat_py_writes_with_every_scene(tmp_path, corpus_scenes):
    features = "dat,ticks,buildings,indoor.statics,mover.placement,engine.client,water,mover.two_spheres,mover.scaled,object.scaled"
    impl, log = _recorder(tmp_path, features)
    scenes = _all(corpus_scenes)
    try:
        for scene in scenes:
            impl.run(scene)
    finally:
        impl.close()
    requests = _requests(log)
    assert len(requests) == len(scenes)
    for request, scene in zip(requests, scenes):
        assert request["dat"]["format"] == DAT_FORMAT
        assert dat_from_json(request["dat"]) == dat.dat_world(scene)
        assert Scene.from_json(request["scene"]) == scene  # the scene is still sent whole


def test_a_recorded_scene_sent_as_its_text_carries_its_records_too(tmp_path, corpus_scenes):
    impl, log = _recorder(tmp_path, "dat")
    scene = corpus_scenes["bsp"][0]
    try:
        impl.run_text(RecordedText(dumps_compact(scene.to_json()), "{}"))
    finally:
        impl.close()
    (request,) = _requests(log)
    assert dat_from_json(request["dat"]) == dat.dat_world(scene)


@pytest.mark.parametrize("kind", KINDS)
def test_the_records_are_byte_for_byte_what_aces_facade_installs(corpus_scenes, kind):
    for scene in corpus_scenes[kind]:
        doc = json.loads(dumps_compact(dat_json(dat.dat_world(scene))))
        sent = [(r["type"], int(r["id"], 16), base64.b64decode(r["data"])) for r in doc["cell"] + doc["portal"]]
        table, installed = _facade_records(scene)
        assert sorted(sent) == sorted(installed)
        assert len({(t, i) for t, i, _ in sent}) == len(sent)
        assert struct.pack("<256f", *(float(h) for h in doc["land_height_table"])) == table
        assert [r["type"] for r in doc["cell"]] == sorted((r["type"] for r in doc["cell"]),
                                                          key=("CellLandblock", "LandblockInfo", "EnvCell").index)


@pytest.mark.parametrize("kind", KINDS)
def test_every_record_reads_to_its_end_with_the_ports_dat_loader(corpus_scenes, kind):
    mode = get_mode("exact", "coreclr")
    for scene in corpus_scenes[kind]:
        world = dat.dat_world(scene)
        for record in world.cell + world.portal:
            reader = BinaryReader(record.data, mode)
            unpacked = READERS[record.kind].unpack(reader)
            assert unpacked.id == record.id and reader.position == len(record.data), (record.kind, hex(record.id))


@pytest.mark.parametrize("kind", KINDS)
def test_the_builtin_port_answers_the_same_from_the_records_as_from_the_scene(corpus_scenes, kind):
    for scene in corpus_scenes[kind]:
        world = dat_from_json(json.loads(dumps_compact(dat_json(dat.dat_world(scene)))))
        assert run_scene(scene, runtime="coreclr", world=world) == run_scene(scene, runtime="coreclr")


def test_given_records_the_builtin_port_builds_the_world_from_them_not_from_the_scene(corpus_scenes):
    """The scene's world emptied (no statics, no cells, no buildings, a flat landblock): the answer
    is still the one for the world the records hold."""
    differs = 0
    for kind in ("terrain", "bsp", "obstacles", "indoor", "buildings"):
        for scene in corpus_scenes[kind]:
            flat = tuple(replace(lb, heights=(0,) * 81, terrain=(0,) * 81) for lb in scene.landblocks)
            bare = replace(scene, landblocks=flat, objects=(), env_cells=(), environments=(), buildings=())
            assert run_scene(bare, world=dat.dat_world(scene)) == run_scene(scene)
            differs += run_scene(bare) != run_scene(scene)
    assert differs >= 15  # the emptied scenes answer otherwise by themselves


def test_acconform_serve_answers_a_request_with_records_from_the_records(corpus_scenes):
    """Each request's scene emptied of its world (as far as it still validates: a mover in an EnvCell
    needs the cell), its records those of the whole scene: `acconform serve` answers as for the
    whole scene."""
    scenes, lines = [], []
    for scene in _all(corpus_scenes):
        flat = tuple(replace(lb, heights=(0,) * 81, terrain=(0,) * 81) for lb in scene.landblocks)
        bare = replace(scene, landblocks=flat, objects=())
        try:
            Scene.from_json(bare.to_json())
        except InvalidScene:
            continue
        rid = len(scenes)
        scenes.append(scene)
        lines.append(dumps_compact({"id": rid, "mode": "exact", "runtime": "coreclr", "scene": bare.to_json(),
                                    "dat": dat_json(dat.dat_world(scene))}))
    r = subprocess.run([sys.executable, "-m", "acconform.cli", "serve"], input="\n".join(lines) + "\n",
                       capture_output=True, text=True, cwd=ROOT, timeout=300)
    hello, *answers = [json.loads(line) for line in r.stdout.splitlines()]
    assert "dat" in hello["features"] and len(answers) == len(scenes) >= 12, r.stderr
    for rid, (answer, scene) in enumerate(zip(answers, scenes)):
        assert answer["id"] == rid
        assert Outcome.from_json(answer["outcome"]) == run_scene(scene, runtime="coreclr")


def test_an_implementation_with_dat_runs_the_corpus_through_acconform_serve_with_no_difference(corpus_scenes):
    impl = Implementation(f"{sys.executable} -m acconform.cli serve", cwd=str(ROOT))
    try:
        assert impl.takes_dat
        for scene in _all(corpus_scenes):
            assert impl.run(scene) == run_scene(scene, runtime=impl.runtime)
    finally:
        impl.close()


def test_a_request_with_a_bad_record_names_the_field():
    doc = dat_json(dat.dat_world(Scene.loads((ROOT / "examples" / "flat_walk.json").read_text())))
    doc["portal"][0]["type"] = "EnvCell"
    with pytest.raises(InvalidScene, match=r"dat\.portal\[0\]\.type: 'EnvCell' is not a portal DAT type"):
        dat_from_json(doc)
    doc["portal"][0].update(type="GfxObj", data="not base64!")
    with pytest.raises(InvalidScene, match=r"dat\.portal\[0\]\.data: not base64"):
        dat_from_json(doc)


def test_the_records_carry_the_movers_skills_and_the_builtin_port_takes_them_from_there():
    """mover.skills (scene/8) travels in the dat feature's mover, written only where it is not the database-free
    Player's; the built-in port's Player takes it from the records, as it takes the PlayerKillerStatus."""
    sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
    from oracle.motion_scenes import scenes

    from acconform.scene import DEFAULT_SKILLS

    scene = scenes()["skilled_player_jumps_while_running"]
    doc = json.loads(dumps_compact(dat_json(dat.dat_world(scene))))
    assert doc["mover"]["skills"] == scene.mover.to_json()["skills"]
    world = dat_from_json(doc)
    assert world.mover.skills == scene.mover.skills
    plain = scene.replace(mover=replace(scene.mover, skills=DEFAULT_SKILLS))
    assert "skills" not in dat_json(dat.dat_world(plain))["mover"]
    assert run_scene(plain, runtime="mono", world=world) == run_scene(scene, runtime="mono") != run_scene(plain, runtime="mono")
    doc["mover"]["skills"]["strength"] = 0
    with pytest.raises(InvalidScene, match=r"dat\.mover\.skills\.strength: expected an integer in \[1, 16777216\]"):
        dat_from_json(doc)
