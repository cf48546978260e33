"""Tick scenes (acconform.scene/4): the records round-trip bit for bit, and every malformed tick field
is refused with one line naming it."""

import copy
import json
import struct
import subprocess
import sys
from pathlib import Path

import pytest

from acconform.case import parse_document
from acconform.codec import Reader
from acconform.errors import InvalidScene
from acconform.flags import PhysicsState, TransientState
from acconform.scene import FORMAT_V4 as FORMAT, FORMAT_V3, Frame, Position, Scene, Ticks, TickStep, validate_scene

ROOT = Path(__file__).parent.parent
EXAMPLES = ROOT / "examples"
JUMP = json.loads((EXAMPLES / "tick_jump.json").read_text())
REQUEST = json.loads((EXAMPLES / "tick_request_pos.json").read_text())


def changed(doc, mutate):
    doc = copy.deepcopy(doc)
    mutate(doc)
    return doc


def refused(doc) -> str:
    with pytest.raises(InvalidScene) as e:
        parse_document(doc)
    return str(e.value)


def _bits(x: float) -> int:
    return struct.unpack("<Q", struct.pack("<d", x))[0]


@pytest.mark.parametrize("name", ["tick_fall.json", "tick_walk.json", "tick_jump.json", "tick_request_pos.json"])
def test_the_example_tick_scenes_are_valid_scene_4_documents_and_round_trip(name):
    doc = json.loads((EXAMPLES / name).read_text())
    s = Scene.from_json(doc)
    assert s.ticks is not None and s.mover.end is None and "end" not in doc["mover"]
    assert doc["format"] == s.format == FORMAT == "acconform.scene/4"
    assert Scene.from_json(json.loads(s.dumps())) == s and validate_scene(s) == s


def test_every_step_input_round_trips_and_doubles_keep_their_bits():
    steps = (TickStep(0.1 + 0.2, state=int(PhysicsState.Gravity | PhysicsState.Sledding), transient_state=0,
                      velocity=(0.0, -0.0, 1.5), local_velocity=(1.0, 2.0, 3.0), omega=(0.0, 0.0, 0.25),
                      jump=(0.0, 0.5, 6.0), sequence_velocity=(0.0, 3.0, 0.0), sequence_omega=(0.0, 0.0, -1.0)),
             TickStep(5e-324), TickStep(0.0), TickStep(1 / 3))
    scene = Scene.from_json(JUMP)
    scene = scene.replace(ticks=Ticks("update_object", 2 ** 40 + 0.1, steps))
    back = validate_scene(scene)
    assert back == scene
    assert [_bits(s.dt) for s in back.ticks.steps] == [_bits(s.dt) for s in steps]
    assert _bits(back.ticks.start) == _bits(2 ** 40 + 0.1)
    assert back.ticks.steps[0].velocity[1] == 0.0 and str(back.ticks.steps[0].velocity[1]) == "-0.0"
    assert back.ticks.steps[0].transient_state == 0  # an empty flag list is an input (TransientState = 0)
    assert back.ticks.steps[1].state is None  # an absent one is not


def test_times_sums_the_steps_in_double_arithmetic_once():
    t = Ticks("update_object", 1000.0, tuple(TickStep(0.1) for _ in range(3)))
    want, clock = [], 1000.0
    for _ in range(3):
        clock = clock + 0.1
        want.append(clock)
    assert t.times() == tuple(want) and t.times()[2] != 1000.3  # 1000.3000000000001: the sum, not a product


def test_the_f64_reader_reads_a_double_bit_for_bit_and_refuses_what_is_not_a_finite_number():
    assert _bits(Reader(0.1 + 0.2).f64()) == _bits(0.30000000000000004)
    assert Reader(3).f64() == 3.0 and type(Reader(3).f64()) is float
    for bad, says in ((True, "expected a number, got a boolean"), ("0.5", "expected a number"),
                      (float("inf"), "expected a finite number"), (10 ** 400, "outside a double's range")):
        with pytest.raises(InvalidScene, match=says):
            Reader(bad, "ticks.start").f64()


def test_a_scene_without_ticks_is_still_written_in_the_oldest_format_that_holds_it():
    placed = json.loads((EXAMPLES / "placement_wall_push.json").read_text())
    assert Scene.from_json(placed).to_json()["format"] == FORMAT_V3 == "acconform.scene/3"
    flat = json.loads((EXAMPLES / "flat_walk.json").read_text())
    assert Scene.from_json(flat).dumps() == Scene.from_json(dict(flat, format=FORMAT)).dumps()


@pytest.mark.parametrize("doc, mutate, says", [
    (JUMP, lambda d: d["ticks"].update(driver="update_object_server"),
     "ticks.driver: unknown driver 'update_object_server' (known: update_object, request_pos)"),
    (JUMP, lambda d: d["ticks"]["steps"][3].update(dt=-0.01),
     "ticks.steps[3].dt: a tick's dt is the time the clock advances: 0 or more seconds, got -0.01"),
    (JUMP, lambda d: d["ticks"]["steps"][0].update(dt=float("nan")), "ticks.steps[0].dt: expected a finite number, got nan"),
    (JUMP, lambda d: d["ticks"]["steps"][0].update(dt=float("inf")), "ticks.steps[0].dt: expected a finite number, got inf"),
    (JUMP, lambda d: d["ticks"]["steps"][0].update(dt="0.1"), "ticks.steps[0].dt: expected a number, got the string '0.1'"),
    (JUMP, lambda d: d["ticks"]["steps"][0].pop("dt"), "ticks.steps[0].dt: missing required field"),
    (JUMP, lambda d: d["ticks"].update(start=float("-inf")), "ticks.start: expected a finite number, got -inf"),
    (JUMP, lambda d: d["ticks"].pop("start"), "ticks.start: missing required field"),
    (JUMP, lambda d: d["ticks"].update(steps=[]), "ticks.steps: a tick scene needs at least one step (one per tick)"),
    (JUMP, lambda d: d["ticks"].update(steps={"dt": 0.1}), "ticks.steps: expected a list, got an object"),
    (JUMP, lambda d: d["ticks"].update(start=1.7e308, steps=[{"dt": 1e308}, {"dt": 1e308}]),
     "ticks.steps: the clock overflows: start plus the steps' dt reaches inf"),
    (JUMP, lambda d: d["ticks"]["steps"][1].update(velocity=[1, 2]), "ticks.steps[1].velocity: expected 3 values, got 2"),
    (JUMP, lambda d: d["ticks"]["steps"][1].update(jump=[0, 0, 1e39]), "ticks.steps[1].jump[2]: 1e+39 is outside float32's range"),
    (JUMP, lambda d: d["ticks"]["steps"][1].update(sequence_omega=None, state=["Flying"]),
     "ticks.steps[1].state[0]: unknown PhysicsState flag 'Flying'"),
    (JUMP, lambda d: d["ticks"]["steps"][1].update(transient_state=["Grounded"]),
     "ticks.steps[1].transient_state[0]: unknown TransientState flag 'Grounded'"),
    (JUMP, lambda d: d["ticks"]["steps"][1].update(speed=3), "ticks.steps[1]: unknown field 'speed'"),
    (JUMP, lambda d: d["ticks"].update(clock="wall"), "ticks: unknown field 'clock'"),
    (JUMP, lambda d: d["ticks"]["steps"][2].update(request_pos={"cell": "0xA9B40001", "origin": [12, 13, 20]}),
     "ticks.steps[2].request_pos: driver update_object moves the mover by its own velocity and root motion: "
     "a RequestPos belongs to driver request_pos"),
    (REQUEST, lambda d: d["ticks"]["steps"][4].pop("request_pos"),
     "ticks.steps[4].request_pos: missing: driver request_pos moves the mover to a RequestPos on every tick"),
    (REQUEST, lambda d: d["ticks"]["steps"][4]["request_pos"].update(cell="0xA9B50001"),
     "ticks.steps[4].request_pos.cell: landblock A9B5 of cell A9B50001 is not defined in landblocks (defined: A9B4)"),
    (REQUEST, lambda d: d["ticks"]["steps"][4]["request_pos"].update(cell="0xA9B40100"),
     "ticks.steps[4].request_pos.cell: EnvCell A9B40100 is not defined in env_cells"),
    (REQUEST, lambda d: d["ticks"]["steps"][4]["request_pos"].update(cell="0xA9B4FFFF"),
     "ticks.steps[4].request_pos.cell: cell A9B4FFFF is neither an outdoor land cell"),
    (REQUEST, lambda d: d["ticks"]["steps"][4]["request_pos"].update(orientation=[0, 0, 0, 0]),
     "ticks.steps[4].request_pos.orientation: a zero quaternion is not a rotation"),
    (JUMP, lambda d: d["mover"].update(end={"cell": "0xA9B40001", "origin": [12, 13, 20]}),
     "mover.end: a tick scene's mover has no end: its ticks move it (omit end)"),
    (JUMP, lambda d: d.update(format="acconform.scene/3"),
     "ticks: ticks need format 'acconform.scene/4' or later (older formats have no ticks)"),
    (JUMP, lambda d: d.pop("ticks"), "mover.end: missing required field"),
], ids=["unknown driver", "negative dt", "nan dt", "infinite dt", "dt a string", "no dt", "infinite start", "no start",
        "empty steps", "steps not a list", "clock overflow", "short vector", "vector out of float32", "unknown state flag",
        "unknown transient flag", "unknown step field", "unknown ticks field", "request_pos for update_object",
        "request_pos missing", "request_pos landblock undefined", "request_pos EnvCell undefined", "request_pos bad cell id",
        "request_pos zero quaternion", "tick scene with an end", "older format", "no ticks and no end"])
def test_a_bad_tick_scene_is_refused_with_one_line_naming_the_field(doc, mutate, says):
    message = refused(changed(doc, mutate))
    assert says in message and "\n" not in message, message


def test_a_tick_scene_built_in_code_with_an_end_is_refused_by_validate_scene_and_runs_in_either_engine_mode():
    scene = Scene.from_json(JUMP)
    assert validate_scene(scene.replace(engine_mode="server")).engine_mode == "server"
    assert validate_scene(scene.replace(engine_mode="client")).engine_mode == "client"
    from dataclasses import replace

    with pytest.raises(InvalidScene, match="a tick scene's mover has no end"):
        validate_scene(scene.replace(mover=replace(scene.mover, end=Position(0xA9B40001, Frame((1.0, 2.0, 3.0))))))


def test_validate_refuses_a_bad_tick_scene_with_exit_2_and_one_line(tmp_path):
    bad = tmp_path / "bad_ticks.json"
    bad.write_text(json.dumps(changed(JUMP, lambda d: d["ticks"]["steps"][5].update(dt=-1.0))))
    r = subprocess.run([sys.executable, "-m", "acconform.cli", "validate", str(bad)], capture_output=True, text=True, cwd=ROOT)
    assert r.returncode == 2 and "Traceback" not in r.stderr
    assert r.stderr.strip().count("\n") == 0 and "ticks.steps[5].dt" in r.stderr and str(bad) in r.stderr, r.stderr
