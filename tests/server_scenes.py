"""Scenes of issue 44's server-mode tests, shared by the port's (tests/port/land/) and the live oracle's
(tests/oracle/) tests."""

from __future__ import annotations

import dataclasses
from pathlib import Path

from acconform.case import load_document
from acconform.scene import Frame, Position, TickStep

ROOT = Path(__file__).resolve().parents[1]


def request_pos_scene(mode: str):
    """tick_request_pos from 10 m up, then a RequestPos 10 m under the next cell's terrain: the transition
    stops on the first cell's ground, and set_current_pos changes the mover's cell (change_cell_server ->
    enter_cell_server -> handle_visible_cells -> Landblock.GetServerObjects(true))."""
    scene = load_document(ROOT / "examples" / "tick_request_pos.json")
    up = Position(0xA9B40001, Frame((12.0, 12.0, 30.0)))
    under = Position(0xA9B40009, Frame((30.0, 12.0, 10.0)))
    steps = scene.ticks.steps[:3] + (TickStep(0.1, request_pos=up), TickStep(0.1, request_pos=under),
                                     TickStep(0.1, request_pos=up))
    return scene.replace(engine_mode=mode, ticks=dataclasses.replace(scene.ticks, steps=steps))


def transition_scene():
    """examples/flat_walk.json: one transition of the player over flat terrain."""
    return load_document(ROOT / "examples" / "flat_walk.json")


def failed_entry_scene():
    """The player entering the world over the deep sea (examples/named/swim_into_deep_sea.json's landblock AAB4,
    every terrain word WaterDeepSea): LandCell.find_env_collisions answers Collided everywhere there, so
    enter_world's SetPosition finds no place and the mover keeps the position store_position gave it."""
    from acconform.scene import Placement

    scene = load_document(ROOT / "examples" / "named" / "swim_into_deep_sea.json")
    begin = Position(0xAAB40001, Frame((12.0, 12.0, 20.0)))
    mover = dataclasses.replace(scene.mover, begin=begin, placement=Placement(via="enter_world"))
    return scene.replace(mover=mover, ticks=dataclasses.replace(scene.ticks, steps=scene.ticks.steps[:2]))


def landblock_info_as_env_cell_scene():
    """The player entering the world at cell id A9B4FFFE in server mode: the server Landblock's constructor read
    the LandblockInfo under that id (an empty one: the scene has no EnvCells), and get_landcell reads the same
    id as an EnvCell: ACE's (T) cast in ReadFromDat."""
    from acconform.scene import Placement

    scene = transition_scene()
    begin = dataclasses.replace(scene.mover.begin, cell=0xA9B4FFFE)
    return scene.replace(engine_mode="server",
                         mover=dataclasses.replace(scene.mover, begin=begin, placement=Placement(via="enter_world")))
