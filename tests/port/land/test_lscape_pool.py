"""LScape builds landblocks on first use and pools them across runs without leaking run state."""

from __future__ import annotations

import gzip
import json

import pytest

from acconform.case import parse_document
from acconform.numerics import EXACT
from acconform.oracle import default_corpus
from acconform.port.land.lscape import POOL, LScape, clear_landblock_cache
from acconform.port.run import run_scene


def _scenes_with_objects(n: int):
    paths = sorted(default_corpus().glob("obstacles-*.jsonl.gz"))
    if not paths:
        pytest.skip("no recorded obstacles in the default corpus")
    out = []
    with gzip.open(paths[0], "rt", encoding="utf-8") as f:
        for line in f:
            rec = parse_document(json.loads(line))
            if rec.scene.objects:
                out.append(rec.scene)
            if len(out) >= n:
                break
    return out


def test_a_landblock_is_built_only_when_first_asked_for():
    scene = _scenes_with_objects(1)[0]
    clear_landblock_cache()
    world = LScape(scene, EXACT)
    assert world.landblocks == {}
    lb_id = scene.landblocks[0].id
    assert world.get_landblock(lb_id) is world.landblocks[lb_id | 0xFFFF]
    world.release()


def test_pooled_landblocks_hold_no_shadow_objects_from_an_earlier_run():
    scenes = _scenes_with_objects(20)
    clear_landblock_cache()
    first = [run_scene(s) for s in scenes]
    assert POOL.idle, "runs hand their landblocks back to the pool"
    for landblock in POOL.idle.values():
        for cell in landblock.land_cells.values():
            cell.shadow_object_list.append("leaked")  # a pooled cell's state must be reset on checkout
    again = [run_scene(s) for s in scenes]
    clear_landblock_cache()
    cold = [run_scene(s) for s in scenes]
    assert again == first == cold


def test_two_worlds_of_one_scene_never_share_a_landblock():
    scene = _scenes_with_objects(1)[0]
    a, b = LScape(scene, EXACT), LScape(scene, EXACT)
    lb_id = scene.landblocks[0].id
    assert a.get_landblock(lb_id) is not b.get_landblock(lb_id)
    a.release()
    b.release()
