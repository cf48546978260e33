"""MovementParamFlags, MovementParamFlagsHelper.Get, MovementParamFlagsHelper.Set.

ACE's Animation/MovementParamFlags.cs: a MovementParameters' eighteen bools as one uint bit set
(the Flags property reads and writes them through the helper). Plain ints, as acconform.flags'
hot flag sets are.
"""

from __future__ import annotations

from acconform.motion_enums import MovementParamFlags  # the scene's names (acconform/motion_scene.py) and the port's

from ..anchors import anchor


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
