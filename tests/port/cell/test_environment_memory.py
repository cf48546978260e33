"""The Environments the port remembers across runs (port/db_obj.py ENVIRONMENTS) change no outcome,
and their key holds every input Environment.Unpack reads: the record's bytes and the mode."""

from __future__ import annotations

import numpy as np
import pytest

from acconform import dat
from acconform.numerics import EXACT, FAST
from acconform.port import db_obj
from acconform.port.dat.portal_dat import PortalDat
from acconform.port.run import run_scene
from acconform.scene import Environment
from dungeon_scenes import SCENES as DUNGEON_SCENES
from indoor_rooms import ENV_ID, SCENES as ROOM_SCENES, room_struct, two_rooms

SCENES = [s for s, _ in list(ROOM_SCENES.values()) + list(DUNGEON_SCENES.values())]


@pytest.mark.anchor("DBObj.cs:GetEnvironment")
@pytest.mark.parametrize("mode", ["exact", "fast"])
def test_remembered_environments_give_the_outcomes_a_fresh_unpack_gives(mode):
    fresh = []
    for s in SCENES:
        db_obj.clear_environments()
        fresh.append(run_scene(s, mode))
    twice = [run_scene(s, mode) for s in SCENES] + [run_scene(s, mode) for s in SCENES]
    assert twice == fresh + fresh


def _environment(env: Environment, mode):
    return db_obj.get_environment(PortalDat({env.id: dat.environment_record(env).data}, mode, True), env.id)


@pytest.mark.anchor("DBObj.cs:GetEnvironment")
def test_the_memory_is_keyed_by_the_records_bytes_and_the_mode():
    db_obj.clear_environments()
    env, _ = two_rooms()
    a = _environment(env, EXACT)
    assert _environment(env, EXACT) is a
    raised = _environment(Environment(ENV_ID, (room_struct(floor=0.5, back_wall=True), env.cell_structs[1])), EXACT)
    fast = _environment(env, FAST)
    assert raised is not a and _heights(raised) != _heights(a) and np.float32(0.5) in _heights(raised)
    assert fast is not a and {type(z) for z in _heights(fast)} == {np.float64}


def _heights(environment) -> set:
    return {v.origin.z for v in environment.cells[0].vertex_array.vertices.values()}


@pytest.mark.anchor("DBObj.cs:GetEnvironment")
def test_an_environment_the_run_does_not_hold_is_an_empty_one_and_is_not_remembered_across_runs():
    db_obj.clear_environments()
    portal_dat = PortalDat({}, EXACT, True)
    environment = db_obj.get_environment(portal_dat, ENV_ID)
    assert environment.cells == {} and portal_dat.file_cache[ENV_ID] is environment  # ReadFromDat's new Environment()
    assert db_obj.ENVIRONMENTS == {}
