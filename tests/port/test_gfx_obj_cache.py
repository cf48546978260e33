"""The GfxObjs the port remembers across runs (port/gfx_obj_cache.py BUILT) change no outcome, and their
key holds every input GfxObj(DatLoader GfxObj) reads: the record's bytes, PhysicsEngine.Server, the mode."""

from __future__ import annotations

import numpy as np
import pytest

from acconform import dat
from acconform.numerics import EXACT, FAST
from acconform.port import gfx_obj_cache
from acconform.port.dat.portal_dat import PortalDat
from acconform.port.run import run_scene
from object_scenes import SCENES as OBJECT_SCENES, box
from straddle_scenes import SCENES as STRADDLE_SCENES

SCENES = [s for s, _ in list(STRADDLE_SCENES.values()) + list(OBJECT_SCENES.values())]


@pytest.mark.anchor("GfxObjCache.cs:Get")
@pytest.mark.parametrize("mode", ["exact", "fast"])
def test_remembered_gfx_objs_give_the_outcomes_a_fresh_build_gives(mode):
    fresh = []
    for s in SCENES:
        gfx_obj_cache.clear_built()
        fresh.append(run_scene(s, mode))
    twice = [run_scene(s, mode) for s in SCENES] + [run_scene(s, mode) for s in SCENES]
    assert twice == fresh + fresh


def _portal(shape, mode, server, gfx_id=dat.GFX_OBJ_BASE):
    return PortalDat({gfx_id: dat.gfx_obj_physics(gfx_id, shape)}, mode, server)


@pytest.mark.anchor("GfxObjCache.cs:Get")
def test_the_memory_is_keyed_by_the_bytes_the_server_flag_and_the_mode():
    gfx_obj_cache.clear_built()
    a = gfx_obj_cache.get(_portal(box(1.0, 1.0, 1.0), EXACT, True), dat.GFX_OBJ_BASE)
    assert gfx_obj_cache.get(_portal(box(1.0, 1.0, 1.0), EXACT, True), dat.GFX_OBJ_BASE) is a
    other_shape = gfx_obj_cache.get(_portal(box(2.0, 1.0, 1.0), EXACT, True), dat.GFX_OBJ_BASE)
    client = gfx_obj_cache.get(_portal(box(1.0, 1.0, 1.0), EXACT, False), dat.GFX_OBJ_BASE)
    fast = gfx_obj_cache.get(_portal(box(1.0, 1.0, 1.0), FAST, True), dat.GFX_OBJ_BASE)
    assert other_shape is not a and other_shape.gfx_bound_box.max.x == np.float32(1.0)
    assert client is not a and client.physics_polygons is not None and a.physics_polygons is None
    assert fast is not a and type(fast.gfx_bound_box.max.x) is np.float64


@pytest.mark.anchor("GfxObjCache.cs:Get")
def test_a_gfx_obj_the_run_lacks_is_named_as_not_ported_and_nothing_is_remembered():
    """ACE's DAT read gives an empty GfxObj (new T()), whose physics GfxObj the port does not build: a scene
    always carries its objects' records, only a dat request can leave one out."""
    gfx_obj_cache.clear_built()
    with pytest.raises(NotImplementedError, match="an empty GfxObj"):
        gfx_obj_cache.get(PortalDat({}, EXACT, True), dat.GFX_OBJ_BASE)
    assert gfx_obj_cache.BUILT == {}
