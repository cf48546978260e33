"""The transition scenes drawn for stop 50's shards (strategies/scenes.py): a free-heading mover (scene/8
mover.free_heading), drawn DAT records (scene/8 drawing) and a multipart static of more than 10 cylspheres."""

from __future__ import annotations

import pytest
from hypothesis import strategies as st

from acconform.flags import PhysicsState
from acconform.strategies.determinism import pinned_constants
from acconform.strategies.fast_draw import FastDrawer
from acconform.strategies.scenes import draw_drawing_scene, draw_free_heading_scene, draw_many_cylspheres_scene


def _draw(draw, n: int, seed: int = 5):
    drawer = FastDrawer(st.composite(draw)(), seed)
    with pinned_constants():
        return [drawer.draw()[0] for _ in range(n)]


@pytest.fixture(scope="module")
def free_heading_scenes():
    return _draw(lambda d: draw_free_heading_scene(d, ("bsp",)), 24)


def test_every_free_heading_scene_has_a_free_heading_mover_and_some_turn_in_place(free_heading_scenes):
    assert all(s.mover.free_heading and s.name.endswith(":free-heading") for s in free_heading_scenes)
    in_place = [s for s in free_heading_scenes if s.mover.end.frame.origin == s.mover.begin.frame.origin]
    turned = [s for s in free_heading_scenes if s.mover.end.frame.orientation != s.mover.begin.frame.orientation]
    assert 0 < len(in_place) < len(free_heading_scenes) and turned


def test_every_drawing_scene_says_drawing_and_some_run_in_the_client_engine_mode():
    scenes = _draw(lambda d: draw_drawing_scene(d, ("bsp",)), 16)
    assert all(s.drawing for s in scenes) and {s.engine_mode for s in scenes} == {"server", "client"}


def test_a_many_cylspheres_scene_has_a_static_setup_of_more_than_ten_cylspheres_without_has_physics_bsp():
    for s in _draw(draw_many_cylspheres_scene, 6):
        setups = [o for o in s.objects if o.setup is not None and len(o.setup.cylspheres) > 10]
        assert setups and all(o.state == int(PhysicsState.Static) for o in setups)
