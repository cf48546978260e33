"""MovementParamFlags, MovementParamFlagsHelper.Get, MovementParamFlagsHelper.Set.

ACE's Animation/MovementParamFlags.cs: a MovementParameters' eighteen bools as one uint bit set
(the Flags property reads and writes them through the helper). Plain ints, as acconform.flags'
hot flag sets are.
"""

from __future__ import annotations

from acconform.flags import FlagSet

from ..anchors import anchor


class MovementParamFlags(metaclass=FlagSet):
    CanWalk = 0x00001
    CanRun = 0x00002
    CanSidestep = 0x00004
    CanWalkBackwards = 0x00008
    CanCharge = 0x00010
    FailWalk = 0x00020
    UseFinalHeading = 0x00040
    Sticky = 0x00080
    MoveAway = 0x00100
    MoveTowards = 0x00200
    UseSpheres = 0x00400
    SetHoldKey = 0x00800
    Autonomous = 0x01000
    ModifyRawState = 0x02000
    ModifyInterpretedState = 0x04000
    CancelMoveTo = 0x08000
    StopCompletely = 0x10000
    DisableJumpDuringLink = 0x20000


# (flag, MovementParameters field), in the helper's order
_FIELDS = (
    (MovementParamFlags.CanWalk, "can_walk"),
    (MovementParamFlags.CanRun, "can_run"),
    (MovementParamFlags.CanSidestep, "can_sidestep"),
    (MovementParamFlags.CanWalkBackwards, "can_walk_backwards"),
    (MovementParamFlags.CanCharge, "can_charge"),
    (MovementParamFlags.FailWalk, "fail_walk"),
    (MovementParamFlags.UseFinalHeading, "use_final_heading"),
    (MovementParamFlags.Sticky, "sticky"),
    (MovementParamFlags.MoveAway, "move_away"),
    (MovementParamFlags.MoveTowards, "move_towards"),
    (MovementParamFlags.UseSpheres, "use_spheres"),
    (MovementParamFlags.SetHoldKey, "set_hold_key"),
    (MovementParamFlags.Autonomous, "autonomous"),
    (MovementParamFlags.ModifyRawState, "modify_raw_state"),
    (MovementParamFlags.ModifyInterpretedState, "modify_interpreted_state"),
    (MovementParamFlags.CancelMoveTo, "cancel_move_to"),
    (MovementParamFlags.StopCompletely, "stop_completely"),
    (MovementParamFlags.DisableJumpDuringLink, "disable_jump_during_link"),
)


@anchor(None, "MovementParamFlags.cs:MovementParamFlagsHelper.Get")
def get(mvp) -> int:
    flags = 0
    for flag, name in _FIELDS:
        if getattr(mvp, name):
            flags |= flag
    return flags


@anchor(None, "MovementParamFlags.cs:MovementParamFlagsHelper.Set")
def set_(mvp, flags: int) -> None:
    for flag, name in _FIELDS:
        setattr(mvp, name, (flags & flag) == flag)


__all__ = ["MovementParamFlags", "get", "set_"]
