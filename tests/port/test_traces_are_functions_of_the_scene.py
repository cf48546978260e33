"""A trace is a function of the scene alone (issue 43): no answer a routine remembers, no cache and no
scene the process ran before changes what a traced run records. A sample of corpus scenes of every
kind (tick scenes too) is traced in corpus order, again in a shuffled order after untraced runs of all
of them in another order, and in a fresh process in reverse order; every trace is the same, record for
record. Within one run, a routine that remembers an answer (anchors.remembers) records computing it
each time it is asked, as ACE computes it: the scenes here ask each of them the same question twice."""

from __future__ import annotations

import hashlib
import json
import random
import subprocess
import sys
from collections import Counter
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).parent / "cell"))  # indoor_rooms: rooms of one Environment

from acconform.port.run import run_scene, traced_run
from acconform.trace import trace_to_json

KINDS = ["terrain", "bsp", "obstacles", "indoor", "buildings", "ticks"]
RUNTIME = "coreclr"
N = 18


def sample(kind=None):
    from acconform.oracle import default_corpus
    from acconform.oracle.recorded import RecordedOracle

    oracle = RecordedOracle(default_corpus(RUNTIME))
    entries = oracle.select(n=N, seed=3, runtime=RUNTIME, kinds=KINDS)
    return [oracle._record(e).scene for e in entries if kind is None or e.kind == kind]


def digest(scene) -> str:
    records = traced_run(scene, "exact", RUNTIME)[1]
    return hashlib.sha256(json.dumps(trace_to_json(records), sort_keys=True).encode()).hexdigest()


FRESH = """
import json, sys
sys.path.insert(0, {here!r})
from test_traces_are_functions_of_the_scene import digest, sample
scenes = sample()
print(json.dumps({{i: digest(scenes[i]) for i in reversed(range(len(scenes)))}}))
"""


@pytest.mark.anchor("LandDefs::get_block_offset")
@pytest.mark.anchor("CLandCell::find_terrain_poly")
@pytest.mark.anchor("LScape::get_landcell")
@pytest.mark.anchor("CLandCell::add_all_outside_cells")
@pytest.mark.anchor("DBObj.cs:GetEnvironment")
@pytest.mark.anchor("CCellStruct::UnPack")
def test_a_trace_is_the_same_whatever_the_process_ran_before_and_in_a_fresh_process():
    scenes = sample()
    assert len(scenes) == N
    first = [digest(s) for s in scenes]
    order = list(range(N))
    random.Random(1).shuffle(order)
    for i in reversed(order):  # untraced runs fill every memory the port keeps across runs
        run_scene(scenes[i], "exact", None, RUNTIME)
    shuffled = {i: digest(scenes[i]) for i in order}
    assert [i for i in range(N) if shuffled[i] != first[i]] == []
    out = subprocess.run([sys.executable, "-c", FRESH.format(here=str(Path(__file__).parent))],
                         capture_output=True, text=True, check=True).stdout
    fresh = {int(k): v for k, v in json.loads(out.strip().splitlines()[-1]).items()}
    assert [i for i in range(N) if fresh[i] != first[i]] == []


@pytest.mark.anchor("LandDefs::get_block_offset")
def test_a_traced_run_records_block_offsets_computed_even_after_untraced_runs_remembered_them():
    from acconform.port import land_defs

    scene = next(s for s in sample("terrain") if len(s.landblocks) > 1)
    run_scene(scene, "exact", None, RUNTIME)
    records = traced_run(scene, "exact", RUNTIME)[1]
    offsets = [k for k, r in enumerate(records) if r.anchor == "LandDefs.cs:GetBlockOffset"]
    crossing = [k for k in offsets if records[k].result != [0.0, 0.0, 0.0]]
    assert crossing, "the scene's transition crosses no landblock border"
    for k in crossing:  # each offset between two landblocks computed: its two blockid_to_lcoord calls just before
        assert [r.anchor for r in records[k - 2:k]] == ["LandDefs.cs:blockid_to_lcoord"] * 2
    assert land_defs._BLOCK_OFFSETS  # the untraced run's memory is still there, only the traced run bypassed it


def _asked_again(records, anchor: str) -> bool:
    """Whether the run calls `anchor` twice with the same arguments (an untraced run answers it from memory)."""
    asked = Counter(json.dumps(r.args) for r in records if r.anchor == anchor and r.event in ("enter", "call"))
    return bool(asked) and max(asked.values()) > 1


def _runs_asking_again(anchor: str) -> list:
    """(scene, its traced records) for the terrain and tick samples whose run asks `anchor` the same twice."""
    runs = [(scene, traced_run(scene, "exact", RUNTIME)[1]) for scene in sample("terrain") + sample("ticks")]
    return [(scene, records) for scene, records in runs if _asked_again(records, anchor)]


def _calls_within(records, outer: str, inner: str) -> list[int]:
    """For each call of `outer` (its enter..exit span), how many `inner` records ran inside it."""
    counts, depth = [], 0
    for r in records:
        if r.anchor == outer:
            if r.event == "enter":
                depth += 1
                counts.append(0)
            elif r.event == "exit":
                depth -= 1
        elif r.anchor == inner and depth and r.event in ("enter", "call"):
            counts[-1] += 1
    return counts


@pytest.mark.anchor("CLandCell::find_terrain_poly")
def test_a_traced_run_tests_the_terrain_triangles_each_time_a_cell_is_asked_for_a_point_again():
    runs = _runs_asking_again("LandCell.cs:find_terrain_poly")
    assert runs, "no scene asks a cell for the same point twice"
    for scene, records in runs:
        counts = _calls_within(records, "LandCell.cs:find_terrain_poly", "Polygon.cs:point_in_poly2D")
        assert counts and min(counts) >= 1, scene.name


@pytest.mark.anchor("LScape::get_landcell")
def test_a_traced_run_looks_a_cell_up_in_its_landblock_each_time_it_is_asked_for_again():
    runs = _runs_asking_again("LScape.cs:get_landcell")
    assert runs, "no scene asks for the same cell twice"
    for scene, records in runs:
        asked = sum(1 for r in records if r.anchor == "LScape.cs:get_landcell")
        looked_up = sum(1 for r in records if r.anchor == "LScape.cs:get_landblock" and r.within == "LScape.cs:get_landcell")
        assert looked_up == asked, scene.name


@pytest.mark.anchor("CLandCell::add_all_outside_cells")
def test_a_traced_run_gathers_the_outside_cells_each_time_a_land_cell_finds_its_transit_cells():
    adds = "LandCell.cs:add_all_outside_cells(Position, int, List<Sphere>, CellArray)"
    runs = _runs_asking_again(adds)
    assert runs, "no scene gathers the same outside cells twice"
    for scene, records in runs:
        assert min(_calls_within(records, "LandCell.cs:find_transit_cells", adds)) == 1, scene.name


@pytest.mark.anchor("DBObj.cs:GetEnvironment")
def test_a_traced_run_reads_the_environment_from_the_dat_for_each_cell_built_from_it():
    from indoor_rooms import SCENES as ROOM_SCENES

    scene = ROOM_SCENES["back-wall"][0]
    assert len({c.environment for c in scene.env_cells}) < len(scene.env_cells)  # two cells of one Environment
    records = traced_run(scene, "exact", RUNTIME)[1]
    asked = [k for k, r in enumerate(records) if r.anchor == "DBObj.cs:GetEnvironment"]
    read = [k for k, r in enumerate(records) if r.anchor.endswith(":ReadFromDat") and r.within == "DBObj.cs:GetEnvironment"]
    assert len(asked) == len(scene.env_cells) and len(read) == len(asked)


@pytest.mark.anchor("CCellStruct::UnPack")
def test_a_traced_run_builds_a_cell_struct_for_each_cell_of_one_structure():
    from acconform import dat
    from acconform.numerics import EXACT
    from acconform.port.cell import cell_struct
    from acconform.port.dat.binary_reader import BinaryReader
    from acconform.port.dat.environment import Environment as DatEnvironment
    from acconform.port.dat.portal_dat import PortalDat
    from acconform.port.tracing import Recorder, installed
    from indoor_rooms import two_rooms

    env, _ = two_rooms()
    data = dat.environment_record(env).data
    portal_dat = PortalDat({env.id: data}, EXACT, True)
    struct = DatEnvironment.unpack(BinaryReader(data, EXACT)).cells[0]
    untraced = cell_struct.remembered(portal_dat, env.id, 0, struct)
    assert cell_struct.remembered(portal_dat, env.id, 0, struct) is untraced  # what an untraced run shares
    with installed(Recorder()) as recorder:
        a = cell_struct.remembered(portal_dat, env.id, 0, struct)
        b = cell_struct.remembered(portal_dat, env.id, 0, struct)
    built = [r for r in recorder.records if r.anchor == "CellStruct.cs:CellStruct(DatLoader.Entity.CellStruct)"]
    assert len(built) == 2 and a is not b and a is not untraced
