"""MotionTable: MotionTable(), MotionTable(DatLoader MotionTable), Allocator, DoObjectMotion, GetObjectSequence, Get, SetDefaultState, StopObjectCompletely, StopObjectMotion, StopSequenceMotion, add_motion, change_cycle_speed, combine_motion, subtract_motion, get_link, is_allowed, re_modify, GetAttackFrames, GetAnimationLength (two overloads), GetCycleLength, GetRunSpeed, GetTurnSpeed, GetMotionData, GetLinkData, GetAnimDist, HasDefaultScript -- which animations a motion plays, and the motion state it leaves.

ACE's Physics/Animation/MotionTable.cs. The table is the DAT record's dictionaries (shared, not
copied). A motion command's top bits say its kind (acconform.motion_enums.CommandMask): a style
(stance) change plays the link out of the current substate, the link into the new style and its
default cycle; a substate (a cycle: walking, running, turning) plays the link from the current
substate and the new cycle, or, when only the speed changes, rescales the cycle; an action plays
its link and returns to the cycle; a modifier adds its velocity and omega to the sequence's.
`get_link` finds the link between two states (backwards when a speed is negative).

C# details kept: ``x << 16`` on a uint drops the bits shifted past 32 (masked here);
``TryGetValue``'s out parameter is null when the key is missing (``dict.get``); ``Math.Sign`` of a
NaN speed throws ArithmeticException; the `ref uint numAnims` parameters are taken and returned
(``(result, num_anims)``), with ``(uint)`` counts wrapping (``- 1`` of none is 0xFFFFFFFF); the
action branch's count after a return through the default substate adds the first link's count
twice (ACE's ``motionData.Anims.Count`` for ``motionData_``'s). StopObjectCompletely loops until the
state has no modifiers, so a modifier StopSequenceMotion cannot remove keeps it looping, as in ACE.
The statics that ACE keeps for the process (WalkSpeed, RunSpeed, TurnSpeed) are the run's PortalDat's;
DatManager.PortalDat is the `portal_dat` passed in.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from acconform.motion_enums import CommandMask, MotionCommand
from acconform.numerics import wrap_u32

from ..anchors import anchor
from ..constants import EPSILON
from ..dat.animation import Animation as DatAnimation
from ..dat.animation_hook import AnimationHookType
from ..dat.motion_table import MotionTable as DatMotionTable
from ..errors import ArithmeticException
from .anim_data import AnimData
from .motion_state import MotionState

_STYLE = int(CommandMask.Style)
_SUBSTATE = int(CommandMask.SubState)
_MODIFIER = int(CommandMask.Modifier)
_ACTION = int(CommandMask.Action)


def _shl16(x: int) -> int:
    """C# ``x << 16`` on a uint."""
    return (x << 16) & 0xFFFFFFFF


def _sign(x) -> int:
    """Math.Sign(float): -1, 0 or 1; NaN throws ArithmeticException."""
    if math.isnan(x):
        raise ArithmeticException("Function does not accept floating point Not-a-Number values.")
    return int(x > 0) - int(x < 0)


@dataclass(slots=True, eq=False)
class MotionTable:
    id: int = 0
    style_defaults: dict | None = None
    cycles: dict | None = None  # uint -> DatLoader MotionData
    modifiers: dict | None = None
    links: dict | None = None  # uint -> {uint -> DatLoader MotionData}
    default_style: int = 0
    mode: object = None  # the run's mode (the 1.0f and 0f literals in its type)
    portal_dat: object = None  # DatManager.PortalDat (AnimSequenceNode and the static helpers read it)

    @staticmethod
    @anchor("CMotionTable::CMotionTable", "MotionTable.cs:MotionTable()")
    def create(mode=None, portal_dat=None) -> "MotionTable":
        return MotionTable(cycles={}, modifiers={}, mode=mode, portal_dat=portal_dat)

    @staticmethod
    @anchor("CMotionTable::CMotionTable", "MotionTable.cs:MotionTable(DatLoader.FileTypes.MotionTable)")
    def from_dat(mtable: DatMotionTable, portal_dat) -> "MotionTable":
        return MotionTable(mtable.id, mtable.style_defaults, mtable.cycles, mtable.modifiers, mtable.links,
                           mtable.default_style, portal_dat.mode, portal_dat)

    @anchor("CMotionTable::Allocator", "MotionTable.cs:Allocator")
    def allocator(self) -> "MotionTable":
        return MotionTable.create(self.mode, self.portal_dat)

    @anchor("CMotionTable::DoObjectMotion", "MotionTable.cs:DoObjectMotion")
    def do_object_motion(self, motion: int, curr_state: MotionState, sequence, speed_mod, num_anims: int) -> tuple[bool, int]:
        """Returns (result, num_anims): C#'s `ref uint numAnims`."""
        return self.get_object_sequence(motion, curr_state, sequence, speed_mod, num_anims, False)

    @anchor("CMotionTable::GetObjectSequence", "MotionTable.cs:GetObjectSequence")
    def get_object_sequence(self, motion: int, curr_state: MotionState, sequence, speed_mod, num_anims: int,
                            stop_modifiers: bool) -> tuple[bool, int]:
        """Returns (result, num_anims): C#'s `ref uint numAnims`. `speed_mod` is a float."""
        one = self.mode.scalar(1.0)
        num_anims = 0
        if curr_state.style == 0 or curr_state.substate == 0:
            return False, num_anims

        motion_data = None
        motion_data_ = None
        cycles = None

        substate = self.style_defaults.get(curr_state.style, 0)

        if motion == substate and not stop_modifiers and (curr_state.substate & _MODIFIER) != 0:
            return True, num_anims

        if (motion & _STYLE) != 0:
            if curr_state.style == motion:
                return True, num_anims

            if substate != curr_state.substate:
                motion_data = self.get_link(curr_state.style, curr_state.substate, curr_state.substate_mod, substate, speed_mod)

            if substate != 0:
                cycles = self.cycles.get(_shl16(motion) | (substate & 0xFFFFFF))
                if cycles is not None:
                    if (cycles.bitfield & 1) != 0:
                        curr_state.clear_modifiers()

                    link = self.get_link(curr_state.style, substate, curr_state.substate_mod, motion, speed_mod)
                    if link is None and curr_state.style != motion:
                        link = self.get_link(curr_state.style, substate, one, self.default_style, one)

                        default_style = self.style_defaults.get(self.default_style, 0)
                        motion_data_ = self.get_link(self.default_style, default_style, one, motion, one)
                    sequence.clear_physics()
                    sequence.remove_cyclic_anims()

                    self.add_motion(sequence, motion_data, speed_mod)
                    self.add_motion(sequence, link, speed_mod)
                    self.add_motion(sequence, motion_data_, speed_mod)
                    self.add_motion(sequence, cycles, speed_mod)

                    curr_state.substate = substate
                    curr_state.style = motion
                    curr_state.substate_mod = speed_mod

                    self.re_modify(sequence, curr_state)

                    num_anims = wrap_u32((len(motion_data.anims) if motion_data is not None else 0)
                                         + (len(link.anims) if link is not None else 0)
                                         + (len(motion_data_.anims) if motion_data_ is not None else 0)
                                         + (len(cycles.anims) if cycles is not None else 0) - 1)

                    return True, num_anims
        if (motion & _SUBSTATE) != 0:
            motion_id = motion & 0xFFFFFF

            motion_data = self.cycles.get(_shl16(curr_state.style) | motion_id)
            if motion_data is None:
                motion_data = self.cycles.get(_shl16(self.default_style) | motion_id)
            if motion_data is not None:
                if self.is_allowed(motion, motion_data, curr_state):
                    if (motion == curr_state.substate and sequence.has_anims()
                            and _sign(speed_mod) == _sign(curr_state.substate_mod)):
                        self.change_cycle_speed(sequence, motion_data, curr_state.substate_mod, speed_mod)
                        self.subtract_motion(sequence, motion_data, curr_state.substate_mod)
                        self.combine_motion(sequence, motion_data, speed_mod)
                        curr_state.substate_mod = speed_mod
                        return True, num_anims

                    if (motion_data.bitfield & 1) != 0:
                        curr_state.clear_modifiers()

                    link = self.get_link(curr_state.style, curr_state.substate, curr_state.substate_mod, motion, speed_mod)  # verify (ACE)
                    if link is None or _sign(speed_mod) != _sign(curr_state.substate_mod):
                        default_motion = self.style_defaults.get(curr_state.style, 0)
                        link = self.get_link(curr_state.style, curr_state.substate, curr_state.substate_mod, default_motion, one)
                        motion_data_ = self.get_link(curr_state.style, default_motion, one, motion, speed_mod)
                    sequence.clear_physics()
                    sequence.remove_cyclic_anims()

                    if motion_data_ is not None:
                        self.add_motion(sequence, link, curr_state.substate_mod)
                        self.add_motion(sequence, motion_data_, speed_mod)
                    else:
                        new_speed_mod = speed_mod
                        if curr_state.substate_mod < 0.0 and speed_mod > 0.0:
                            new_speed_mod = new_speed_mod * -1.0
                        self.add_motion(sequence, link, new_speed_mod)

                    self.add_motion(sequence, motion_data, speed_mod)

                    if curr_state.substate != motion and (curr_state.substate & _MODIFIER) != 0:
                        default_motion = self.style_defaults.get(curr_state.style, 0)
                        if default_motion != motion:
                            curr_state.add_modifier_no_check(curr_state.substate, curr_state.substate_mod)

                    curr_state.substate_mod = speed_mod
                    curr_state.substate = motion
                    self.re_modify(sequence, curr_state)

                    num_anims = wrap_u32((0 if motion_data is None else len(motion_data.anims))
                                         + (0 if link is None else len(link.anims))
                                         + (0 if motion_data_ is None else len(motion_data_.anims)) - 1)

                    return True, num_anims
        if (motion & _ACTION) != 0:
            cycle_key = _shl16(curr_state.style) | (curr_state.substate & 0xFFFFFF)
            motion_data = self.cycles.get(cycle_key)
            if motion_data is not None:
                link = self.get_link(curr_state.style, curr_state.substate, curr_state.substate_mod, motion, speed_mod)
                if link is not None:
                    curr_state.add_action(motion, speed_mod)
                    sequence.clear_physics()
                    sequence.remove_cyclic_anims()

                    self.add_motion(sequence, link, speed_mod)
                    self.add_motion(sequence, motion_data, curr_state.substate_mod)
                    self.re_modify(sequence, curr_state)

                    num_anims = len(link.anims)
                    return True, num_anims
                else:
                    substate = self.style_defaults.get(curr_state.style, 0)
                    motion_data = self.get_link(curr_state.style, curr_state.substate, curr_state.substate_mod, substate, one)
                    if motion_data is not None:
                        link = self.get_link(curr_state.style, substate, one, motion, speed_mod)
                        if link is not None and (cycles := self.cycles.get(cycle_key)) is not None:
                            motion_data_ = self.get_link(curr_state.style, substate, one, curr_state.substate, curr_state.substate_mod)
                            curr_state.add_action(motion, speed_mod)
                            sequence.clear_physics()
                            sequence.remove_cyclic_anims()
                            self.add_motion(sequence, motion_data, one)
                            self.add_motion(sequence, link, speed_mod)
                            self.add_motion(sequence, motion_data_, one)
                            self.add_motion(sequence, cycles, curr_state.substate_mod)
                            self.re_modify(sequence, curr_state)
                            num_anims = wrap_u32(len(motion_data.anims) + len(link.anims)
                                                 + (0 if motion_data_ is None else len(motion_data.anims)))
                            return True, num_anims
        if (motion & _MODIFIER) != 0:
            style_key = _shl16(curr_state.style)
            cycles = self.cycles.get(style_key | (curr_state.substate & 0xFFFFFF))
            if cycles is not None and (cycles.bitfield & 1) == 0:
                motion_data = self.modifiers.get(style_key | (motion & 0xFFFFFF))
                if motion_data is None:
                    motion_data = self.modifiers.get(motion & 0xFFFFFF)
                if motion_data is not None:
                    if not curr_state.add_modifier(motion, speed_mod):
                        _, num_anims = self.stop_sequence_motion(motion, one, curr_state, sequence, num_anims)
                        if not curr_state.add_modifier(motion, speed_mod):
                            return False, num_anims
                    self.combine_motion(sequence, motion_data, speed_mod)
                    return True, num_anims
        return False, num_anims

    @staticmethod
    @anchor("CMotionTable::Get", "MotionTable.cs:Get")
    def get(motion_table_id: int, portal_dat) -> "MotionTable":
        # return ObjCache.GetMotionTable(mtableID); (ACE)
        return MotionTable.from_dat(portal_dat.read_from_dat(motion_table_id, DatMotionTable), portal_dat)

    @anchor("CMotionTable::SetDefaultState", "MotionTable.cs:SetDefaultState")
    def set_default_state(self, state: MotionState, sequence, num_anims: int) -> tuple[bool, int]:
        """Returns (result, num_anims): C#'s `ref uint numAnims`, unchanged when it fails."""
        default_substate = self.style_defaults.get(self.default_style)
        if default_substate is None:
            return False, num_anims

        state.clear_modifiers()
        state.clear_actions()

        cycle = _shl16(self.default_style) | (default_substate & 0xFFFFFF)

        motion_data = self.cycles.get(cycle)
        if motion_data is None:
            return False, num_anims

        num_anims = wrap_u32(len(motion_data.anims) - 1)
        state.style = self.default_style
        state.substate = default_substate
        state.substate_mod = self.mode.scalar(1.0)

        sequence.clear_physics()
        sequence.clear_animations()

        self.add_motion(sequence, motion_data, state.substate_mod)
        return True, num_anims

    @anchor("CMotionTable::StopObjectCompletely", "MotionTable.cs:StopObjectCompletely")
    def stop_object_completely(self, curr_state: MotionState, sequence, num_anims: int) -> tuple[bool, int]:
        """Returns (result, num_anims): C#'s `ref uint numAnims`."""
        node = curr_state.modifiers.first
        speed = self.mode.scalar(1.0)
        success = False
        while node is not None:
            motion = node.value
            speed = motion.speed_mod
            stopped, num_anims = self.stop_sequence_motion(motion.id, motion.speed_mod, curr_state, sequence, num_anims)
            if stopped:
                success = True

            node = curr_state.modifiers.first
        speed = curr_state.substate_mod

        stopped, num_anims = self.stop_sequence_motion(curr_state.substate, speed, curr_state, sequence, num_anims)
        if not stopped:
            return success, num_anims
        else:
            return True, num_anims

    @anchor("CMotionTable::StopObjectMotion", "MotionTable.cs:StopObjectMotion")
    def stop_object_motion(self, motion: int, speed, curr_state: MotionState, sequence, num_anims: int) -> tuple[bool, int]:
        """Returns (result, num_anims): C#'s `ref uint numAnims`."""
        return self.stop_sequence_motion(motion, speed, curr_state, sequence, num_anims)

    @anchor("CMotionTable::StopSequenceMotion", "MotionTable.cs:StopSequenceMotion")
    def stop_sequence_motion(self, motion: int, speed, curr_state: MotionState, sequence, num_anims: int) -> tuple[bool, int]:
        """Returns (result, num_anims): C#'s `ref uint numAnims`."""
        num_anims = 0
        if (motion & _SUBSTATE) != 0 and curr_state.substate == motion:
            style = self.style_defaults.get(curr_state.style, 0)
            _, num_anims = self.get_object_sequence(style, curr_state, sequence, self.mode.scalar(1.0), num_anims, True)
            return True, num_anims
        if (motion & _MODIFIER) == 0:
            return False, num_anims

        modifier = curr_state.modifiers.first
        prev_mod = None

        while modifier is not None:
            if modifier.value.id == motion:
                key = _shl16(curr_state.style) | (motion & 0xFFFFFF)

                motion_data = self.modifiers.get(key)
                if motion_data is None:
                    motion_data = self.modifiers.get(motion & 0xFFFFFF)
                if motion_data is None:
                    return False, num_anims

                self.subtract_motion(sequence, motion_data, modifier.value.speed_mod)
                curr_state.remove_modifier(modifier)
                return True, num_anims
            prev_mod = modifier  # noqa: F841 (ACE keeps it and never reads it)
            modifier = modifier.next
        return False, num_anims

    @anchor("CMotionTable::add_motion", "MotionTable.cs:add_motion")
    def add_motion(self, sequence, motion_data, speed) -> None:
        if motion_data is None:
            return

        sequence.set_velocity(motion_data.velocity * speed)
        sequence.set_omega(motion_data.omega * speed)

        for i in range(len(motion_data.anims)):
            anim_data = AnimData.from_dat(motion_data.anims[i], speed)
            sequence.append_animation(anim_data)

    @anchor("CMotionTable::change_cycle_speed", "MotionTable.cs:change_cycle_speed")
    def change_cycle_speed(self, sequence, motion_data, substate_mod, speed_mod) -> None:
        if abs(substate_mod) > EPSILON:
            sequence.multiply_cyclic_animation_framerate(speed_mod / substate_mod)

        elif abs(speed_mod) < EPSILON:
            sequence.multiply_cyclic_animation_framerate(self.mode.scalar(0))

    @anchor("CMotionTable::combine_motion", "MotionTable.cs:combine_motion")
    def combine_motion(self, sequence, motion_data, speed) -> None:
        if motion_data is None:
            return

        sequence.combine_physics(motion_data.velocity * speed, motion_data.omega * speed)

    @anchor("CMotionTable::subtract_motion", "MotionTable.cs:subtract_motion")
    def subtract_motion(self, sequence, motion_data, speed) -> None:
        if motion_data is None:
            return

        sequence.subtract_physics(motion_data.velocity * speed, motion_data.omega * speed)

    @anchor("CMotionTable::get_link", "MotionTable.cs:get_link")
    def get_link(self, style: int, substate: int, substate_speed, motion: int, speed):
        """The MotionData linking `substate` to `motion` in `style`, or None."""
        if speed < 0.0 or substate_speed < 0.0:
            link = self.links.get(_shl16(style) | (motion & 0xFFFFFF))
            if link is not None:
                result = link.get(substate)
                if result is not None:
                    return result

            default_motion = self.style_defaults.get(style)
            if default_motion is not None:
                sublink = self.links.get(_shl16(style) | (substate & 0xFFFFFF))
                if sublink is not None:
                    return sublink.get(default_motion)
        else:
            link = self.links.get(_shl16(style) | (substate & 0xFFFFFF))
            if link is not None:
                result = link.get(motion)
                if result is not None:
                    return result

            sublink = self.links.get(_shl16(style))
            if sublink is not None:
                return sublink.get(motion)
        return None

    @anchor("CMotionTable::is_allowed", "MotionTable.cs:is_allowed")
    def is_allowed(self, motion: int, motion_data, state: MotionState) -> bool:
        if motion_data is None:
            return False

        if (motion_data.bitfield & 2) == 0 or motion == state.substate:
            return True

        style = self.style_defaults.get(state.style, 0)
        return style == state.substate

    @anchor("CMotionTable::re_modify", "MotionTable.cs:re_modify")
    def re_modify(self, sequence, pstate: MotionState) -> None:
        if pstate.modifiers.first is None:
            return

        state = MotionState.copy_of(pstate)

        while state.modifiers.first is not None:
            speed_mod = pstate.modifiers.first.value.speed_mod
            motion = pstate.modifiers.first.value.id

            pstate.remove_modifier(pstate.modifiers.first)  # second param null? (ACE)
            state.remove_modifier(state.modifiers.first)

            num_anims = 0
            self.get_object_sequence(motion, pstate, sequence, speed_mod, num_anims, False)

    @staticmethod
    @anchor(None, "MotionTable.cs:GetAttackFrames")
    def get_attack_frames(motion_table_id: int, stance: int, motion: int, portal_dat) -> list:
        if motion_table_id == 0:
            return _EMPTY_LIST

        motion_table = portal_dat.read_from_dat(motion_table_id, DatMotionTable)
        return motion_table.get_attack_frames(motion_table_id, stance, motion, portal_dat)

    @staticmethod
    @anchor(None, "MotionTable.cs:GetAnimationLength(uint, MotionStance, MotionCommand, float)")
    def get_animation_length(motion_table_id: int, stance: int, motion: int, portal_dat, speed=None):
        """`speed` defaults to 1.0f."""
        scalar = portal_dat.mode.scalar
        speed = scalar(1.0) if speed is None else speed
        if motion_table_id == 0:
            return scalar(0)

        motion_table = portal_dat.read_from_dat(motion_table_id, DatMotionTable)
        return motion_table.get_animation_length_nullable(stance, motion, None, portal_dat) / speed

    @staticmethod
    @anchor(None, "MotionTable.cs:GetAnimationLength(uint, MotionStance, MotionCommand, MotionCommand, float)")
    def get_animation_length_from(motion_table_id: int, stance: int, current_motion: int, motion: int, portal_dat, speed=None):
        """`speed` defaults to 1.0f."""
        scalar = portal_dat.mode.scalar
        speed = scalar(1.0) if speed is None else speed
        if motion_table_id == 0:
            return scalar(0)

        motion_table = portal_dat.read_from_dat(motion_table_id, DatMotionTable)

        anim_length = scalar(0.0)
        if (motion & _STYLE) != 0 and current_motion != MotionCommand.Ready:
            anim_length += motion_table.get_animation_length(stance, MotionCommand.Ready, current_motion, portal_dat) / speed
            current_motion = MotionCommand.Ready

        anim_length += motion_table.get_animation_length(stance, motion, current_motion, portal_dat) / speed
        return anim_length

    @staticmethod
    @anchor(None, "MotionTable.cs:GetCycleLength")
    def get_cycle_length(motion_table_id: int, stance: int, motion: int, portal_dat, speed=None):
        """`speed` defaults to 1.0f."""
        scalar = portal_dat.mode.scalar
        speed = scalar(1.0) if speed is None else speed
        if motion_table_id == 0:
            return scalar(0)

        motion_table = portal_dat.read_from_dat(motion_table_id, DatMotionTable)
        return motion_table.get_cycle_length(stance, motion, portal_dat) / speed

    @staticmethod
    @anchor(None, "MotionTable.cs:GetRunSpeed")
    def get_run_speed(motion_table_id: int, portal_dat):
        """Returns the distance per second for a running animation (ACE); remembered per run."""
        run_speed = portal_dat.run_speed.get(motion_table_id)
        if run_speed is not None:
            return run_speed

        run_motion = int(MotionCommand.RunForward)
        motion_data = MotionTable.get_motion_data(motion_table_id, run_motion, portal_dat)
        if motion_data is None:
            return portal_dat.mode.scalar(0.0)

        speed = MotionTable.get_anim_dist(motion_data, portal_dat)
        portal_dat.run_speed[motion_table_id] = speed
        return speed

    @staticmethod
    @anchor(None, "MotionTable.cs:GetTurnSpeed")
    def get_turn_speed(motion_table_id: int, portal_dat):
        """Returns the rotational velocity / omega for a turning animation (ACE); remembered per run."""
        turn_speed = portal_dat.turn_speed.get(motion_table_id)
        if turn_speed is not None:
            return turn_speed

        turn_motion = int(MotionCommand.TurnRight)
        motion_data = MotionTable.get_motion_data(motion_table_id, turn_motion, portal_dat)
        if motion_data is None:
            return portal_dat.mode.scalar(0.0)

        speed = abs(motion_data.omega.z)
        portal_dat.turn_speed[motion_table_id] = speed
        return speed

    @staticmethod
    @anchor(None, "MotionTable.cs:GetMotionData")
    def get_motion_data(motion_table_id: int, motion: int, portal_dat, current_style: int | None = None):
        """Returns the MotionData for a motionTable and motion ID (ACE); `current_style` None is null."""
        if motion_table_id == 0:
            return None

        motion_table = portal_dat.read_from_dat(motion_table_id, DatMotionTable)
        if current_style is None:
            current_style = motion_table.default_style
        motion_id = motion & 0xFFFFFF
        key = _shl16(current_style) | motion_id
        return motion_table.cycles.get(key)

    @staticmethod
    @anchor(None, "MotionTable.cs:GetLinkData")
    def get_link_data(motion_table_id: int, motion: int, portal_dat, current_style: int | None = None):
        if motion_table_id == 0:
            return None

        motion_table = portal_dat.read_from_dat(motion_table_id, DatMotionTable)
        if current_style is None:
            current_style = motion_table.default_style
        key = _shl16(current_style) | (int(MotionCommand.Ready) & 0xFFFF)
        links = motion_table.links.get(key)
        if links is None:
            return None
        return links.get(motion)

    @staticmethod
    @anchor(None, "MotionTable.cs:GetAnimDist")
    def get_anim_dist(motion_data, portal_dat):
        """Returns the movement distance per second from an animation (ACE): the length of the sum of
        the PosFrames' origins, over their count, times the first animation's framerate."""
        mode = portal_dat.mode
        offset = mode.vec(0, 0, 0)
        total_frames = 0
        for anim in motion_data.anims:
            animation = portal_dat.read_from_dat(anim.anim_id, DatAnimation)
            for frame in animation.pos_frames:
                # orientation? (ACE)
                offset = offset + frame.origin
                total_frames += 1
        dist = offset.length()
        if dist == 0.0:
            return mode.scalar(0.0)
        return dist / mode.scalar(total_frames) * motion_data.anims[0].framerate

    @staticmethod
    @anchor(None, "MotionTable.cs:HasDefaultScript")
    def has_default_script(motion_table_id: int, motion: int, current_style: int, portal_dat) -> bool:
        """Returns TRUE if this animation has a DefaultScript hook type (ACE)."""
        motion_data = MotionTable.get_link_data(motion_table_id, motion, portal_dat, current_style)
        if motion_data is None:
            return False

        for anim in motion_data.anims:
            animation = portal_dat.read_from_dat(anim.anim_id, DatAnimation)
            if animation is None:
                continue

            for frame in animation.part_frames:
                for hook in frame.hooks:
                    if hook.hook_type == AnimationHookType.DefaultScript:
                        return True
        return False


# MotionTable.emptyList: the one empty list GetAttackFrames returns for table 0
_EMPTY_LIST: list = []
