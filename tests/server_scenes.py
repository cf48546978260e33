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
