"""strategies/doors.py: the door policy's scenes (kind doors), drawn as a campaign draws them."""

from __future__ import annotations

import pytest

from acconform.scene import FORMAT as FORMAT_V8, FORMAT_V7 as FORMAT, validate_scene

N = 120


@pytest.fixture(scope="module")
def door_scenes():
    from hypothesis import strategies as st

    from acconform.strategies import ticks as tk
    from acconform.strategies.determinism import pinned_constants
    from acconform.strategies.fast_draw import FastDrawer

    with pinned_constants():
        drawer = FastDrawer(st.composite(lambda draw: tk.draw_tick_scene(draw, None, "door"))(), 41)
        return [drawer.draw()[0] for _ in range(N)]


def test_every_door_scene_validates_in_format_7_with_its_mover_entering_the_world(door_scenes):
    for s in door_scenes:
        # /8 only for what any tick scene's mover may draw since: its Setup's DefaultScript or resting frame
        extras = bool(s.mover.default_script) or s.mover.resting_frame is not None
        assert validate_scene(s) == s and (s.format == FORMAT or extras and s.format == FORMAT_V8)
        assert s.mover.placement is not None and s.mover.placement.via == "enter_world"


def test_door_scenes_close_and_open_at_the_tick_the_mover_reaches_the_door_and_around_it(door_scenes):
    ways = {s.name.split(":")[2] for s in door_scenes}
    whens = {s.name.split(":")[3] for s in door_scenes}
    assert ways == {"closes", "opens"} and whens == {"inside", "before", "after", "drawn"}
    closes = [s for s in door_scenes if s.name.split(":")[2] == "closes"]
    assert any(sum(1 for t in s.ticks.steps if t.door) == 2 for s in closes)  # a second close: the poll


def test_the_doors_kind_is_a_campaign_kind_the_port_runs():
    from acconform.impl import BuiltinPort
    from acconform.strategies import check_kinds

    assert check_kinds("doors") == ("doors",) and "doors" in BuiltinPort.kinds
