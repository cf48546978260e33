"""A small motion table and its animations, written as DAT records by acconform/dat.py, for the
MotionTable, Sequence and DAT-reader tests (fast lane) and the live differential against ACE.

One style (NonCombat) whose default substate is Ready, a second style (HandCombat) with its own Ready,
a Walk cycle with a velocity, a modifier with an omega, an action, and links Ready -> Walk, Ready ->
action, Ready -> HandCombat, Walk -> Ready, and the style's own (style << 16) links. Every animation
has one part and root motion (PosFrames: a step along y and a small turn about z per frame); one
frame carries hooks of each direction.
"""

from __future__ import annotations

import math

import numpy as np

from acconform import dat
from acconform.dat import AnimDataRec, AnimationFrameRec, HookRec, MotionDataRec
from acconform.motion_enums import MotionCommand as M, MotionStance as S
from acconform.port.dat.animation_hook import AnimationHookType as H
from acconform.port.dat.portal_dat import PortalDat

TABLE_ID = 0x09000001
NON_COMBAT = int(S.NonCombat)
HAND_COMBAT = int(S.HandCombat)
READY = int(M.Ready)
WALK = int(M.WalkForward)
RUN = int(M.RunForward)
ACTION = 0x10000057  # an action command (CommandMask.Action)
MODIFIER = 0x20000070  # a modifier command (CommandMask.Modifier)

A_READY, A_WALK, A_RUN, A_LINK_WALK, A_ACTION, A_LINK_STYLE, A_LINK_READY, A_HAND_READY = range(0x03000010, 0x03000018)


def key(style: int, motion: int) -> int:
    return ((style << 16) & 0xFFFFFFFF) | (motion & 0xFFFFFF)


def _turn(angle: float) -> tuple:
    """(w, x, y, z) of a turn about z, in float32."""
    h = np.float32(angle) / np.float32(2)
    return (float(np.float32(math.cos(h))), 0.0, 0.0, float(np.float32(math.sin(h))))


def animation(anim_id: int, frames: int, step: float, turn: float, hooks_at: int | None = None) -> dat.DatRecord:
    pos = [((0.0, step * (k + 1), 0.0), _turn(turn * (k + 1))) for k in range(frames)]
    part = ((0.0, 0.0, 0.5), (1.0, 0.0, 0.0, 0.0))
    part_frames = []
    for k in range(frames):
        hooks = ()
        if k == hooks_at:
            hooks = (HookRec(int(H.Ethereal), 1, np.int32(1).tobytes()),  # forward
                     HookRec(int(H.Sound), -1, np.uint32(7).tobytes()),  # backward
                     HookRec(int(H.AnimationDone), 0))  # both
        part_frames.append(AnimationFrameRec((part,), hooks))
    return dat.animation_record(anim_id, 1, part_frames, pos)


ANIMATIONS = (
    animation(A_READY, 4, 0.0, 0.01, hooks_at=1),
    animation(A_WALK, 5, 0.125, 0.0),
    animation(A_RUN, 3, 0.375, -0.02),
    animation(A_LINK_WALK, 3, 0.0625, 0.05, hooks_at=2),
    animation(A_ACTION, 6, 0.01, 0.1),
    animation(A_LINK_STYLE, 2, 0.0, 0.25),
    animation(A_LINK_READY, 2, -0.03125, 0.0),
    animation(A_HAND_READY, 3, 0.0, -0.01),
)


def table() -> dat.DatRecord:
    cycles = {
        key(NON_COMBAT, READY): MotionDataRec((AnimDataRec(A_READY, framerate=30.0),)),
        key(NON_COMBAT, WALK): MotionDataRec((AnimDataRec(A_WALK, framerate=30.0),), bitfield=1, velocity=(0.0, 3.12, 0.0)),
        key(NON_COMBAT, RUN): MotionDataRec((AnimDataRec(A_RUN, 0, 1, framerate=24.0),), velocity=(0.0, 11.7, 0.0)),
        key(HAND_COMBAT, READY): MotionDataRec((AnimDataRec(A_HAND_READY, framerate=20.0),)),
    }
    modifiers = {
        key(NON_COMBAT, MODIFIER): MotionDataRec((), omega=(0.0, 0.0, 1.5)),
    }
    links = {
        key(NON_COMBAT, READY): {
            WALK: MotionDataRec((AnimDataRec(A_LINK_WALK, framerate=30.0),), velocity=(0.0, 1.0, 0.0)),
            ACTION: MotionDataRec((AnimDataRec(A_ACTION, 1, 4, framerate=15.0),)),
            HAND_COMBAT: MotionDataRec((AnimDataRec(A_LINK_STYLE, framerate=10.0),)),
        },
        key(NON_COMBAT, WALK): {
            READY: MotionDataRec((AnimDataRec(A_LINK_READY, framerate=30.0),)),
        },
        key(NON_COMBAT, 0): {
            RUN: MotionDataRec((AnimDataRec(A_LINK_WALK, framerate=-30.0),)),
        },
    }
    return dat.motion_table_record(TABLE_ID, NON_COMBAT, {NON_COMBAT: READY, HAND_COMBAT: READY}, cycles, modifiers, links)


def records() -> dict[int, bytes]:
    return {r.id: r.data for r in (table(), *ANIMATIONS)}


def portal_dat(mode) -> PortalDat:
    return PortalDat(records(), mode, server=True)


# the motions the differential runs, in order: (command, speed)
SCRIPT = (
    (WALK, 1.0), (WALK, 1.5), (MODIFIER, 1.0), (READY, 1.0), (ACTION, 1.25), (WALK, -1.0), (RUN, 1.0),
    (MODIFIER, 0.5), (HAND_COMBAT, 1.0), (NON_COMBAT, 1.0), (WALK, 0.0), (READY, 2.0),
)
