"""MotionTable: Unpack, GetDefaultMotion, GetAnimationLength (four overloads), GetCycleLength, GetAttackFrames, GetAnimData -- a 0x09 MotionTable record: style defaults, cycles, modifiers and links (ACE.DatLoader FileTypes/MotionTable.cs).

The keys are ``style << 16 | (motion & 0xFFFFFF)`` (a cycle or modifier) and, for Links, the same
key of the state linked from, then the motion linked to. The dictionaries are never removed from,
so a Python dict keeps .NET's order. The length and attack-frame helpers read Animation records
through DatManager.PortalDat (the run's PortalDat here, passed in); GetAttackFrames' static cache
is the PortalDat's (`attack_frames`, per run). GetAnimationFinalPositionFromStart works on
ACE.Entity.Position, the game's position, which nothing in the physics uses: not ported.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from acconform.motion_enums import MotionCommand
from acconform.numerics import wrap_i32

from ..anchors import anchor
from .motion_data import MotionData
from .unpackable_extensions import dictionary_add, unpack_uint_dict, unpack_uint_dict_of_dicts


@dataclass(slots=True, eq=False)
class MotionTable:
    id: int = 0
    default_style: int = 0
    style_defaults: dict = field(default_factory=dict)  # style -> its default substate
    cycles: dict = field(default_factory=dict)  # style << 16 | substate -> MotionData
    modifiers: dict = field(default_factory=dict)  # style << 16 | modifier (or the modifier alone) -> MotionData
    links: dict = field(default_factory=dict)  # style << 16 | from -> {to motion -> MotionData}

    @staticmethod
    @anchor(None, "ACE.DatLoader/FileTypes/MotionTable.cs:Unpack")
    def unpack(reader) -> "MotionTable":
        m = MotionTable()
        m.id = reader.read_uint32()

        m.default_style = reader.read_uint32()

        num_style_defaults = reader.read_uint32()
        for _ in range(num_style_defaults):
            key = reader.read_uint32()
            dictionary_add(m.style_defaults, key, reader.read_uint32())

        m.cycles = unpack_uint_dict(reader, MotionData.unpack)

        m.modifiers = unpack_uint_dict(reader, MotionData.unpack)

        m.links = unpack_uint_dict_of_dicts(reader, MotionData.unpack)
        return m

    @anchor(None, "ACE.DatLoader/FileTypes/MotionTable.cs:GetDefaultMotion")
    def get_default_motion(self, style: int) -> int:
        """The default substate for the stance, or MotionCommand.Invalid."""
        if style in self.style_defaults:
            return self.style_defaults[style]

        return MotionCommand.Invalid

    @anchor(None, "ACE.DatLoader/FileTypes/MotionTable.cs:GetAnimationLength(MotionCommand)")
    def get_animation_length_of_motion(self, motion: int, portal_dat):
        default_stance = self.default_style
        default_motion = self.get_default_motion(default_stance)

        return self.get_animation_length(default_stance, motion, default_motion, portal_dat)

    @anchor(None, "ACE.DatLoader/FileTypes/MotionTable.cs:GetAnimationLength(MotionStance, MotionCommand, MotionCommand?)")
    def get_animation_length_nullable(self, stance: int, motion: int, current_motion, portal_dat):
        """`current_motion` None is C#'s null: the stance's default motion."""
        if current_motion is None:
            current_motion = self.get_default_motion(stance)

        return self.get_animation_length(stance, motion, current_motion, portal_dat)

    @anchor(None, "ACE.DatLoader/FileTypes/MotionTable.cs:GetCycleLength")
    def get_cycle_length(self, stance: int, motion: int, portal_dat):
        key = ((stance << 16) & 0xFFFFFFFF) | (motion & 0xFFFFF)  # 0xFFFFF, five Fs, as ACE writes it

        motion_data = self.cycles.get(key)

        if motion_data is None:
            return portal_dat.mode.scalar(0.0)

        length = portal_dat.mode.scalar(0.0)
        for anim in motion_data.anims:
            length += self.get_animation_length_of_anim(anim, portal_dat)

        return length

    @anchor(None, "ACE.DatLoader/FileTypes/MotionTable.cs:GetAttackFrames")
    def get_attack_frames(self, motion_table_id: int, stance: int, motion: int, portal_dat) -> list:
        """A list of (time, AttackHook), remembered per (table id, stance, motion) in the run's
        PortalDat as ACE remembers it in a static ConcurrentDictionary."""
        from .animation import Animation
        from .animation_hooks import AttackHook

        attack_frame_params = (motion_table_id, stance, motion)
        attack_frames = portal_dat.attack_frames.get(attack_frame_params)
        if attack_frames is not None:
            return attack_frames

        portal_dat.read_from_dat(motion_table_id, MotionTable)  # ACE reads it into a local it never uses

        default_motion = self.get_default_motion(stance)

        anim_data = self.get_anim_data(stance, motion, default_motion)

        frame_nums = []
        attack_hooks = []
        total_frames = 0

        for anim in anim_data:
            animation = portal_dat.read_from_dat(anim.anim_id, Animation)

            for frame in animation.part_frames:
                for hook in frame.hooks:
                    if isinstance(hook, AttackHook):
                        frame_nums.append(total_frames)
                        attack_hooks.append(hook)
                total_frames += 1
        scalar = portal_dat.mode.scalar
        attack_frames = []
        for i in range(len(frame_nums)):
            attack_frames.append((scalar(frame_nums[i]) / scalar(total_frames), attack_hooks[i]))  # div 0? (ACE)

        portal_dat.attack_frames.setdefault(attack_frame_params, attack_frames)

        return attack_frames

    @anchor(None, "ACE.DatLoader/FileTypes/MotionTable.cs:GetAnimData")
    def get_anim_data(self, stance: int, motion: int, current_motion: int) -> list:
        anim_data: list = []

        motion_hash = ((stance << 16) & 0xFFFFFFFF) | (current_motion & 0xFFFFF)

        link = self.links.get(motion_hash)
        if link is None:
            return anim_data

        motion_data = link.get(motion)
        if motion_data is None:
            motion_hash = (stance << 16) & 0xFFFFFFFF
            link = self.links.get(motion_hash)
            if link is None:
                return anim_data
            motion_data = link.get(motion)
            if motion_data is None:
                return anim_data
        return motion_data.anims

    @anchor(None, "ACE.DatLoader/FileTypes/MotionTable.cs:GetAnimationLength(MotionStance, MotionCommand, MotionCommand)")
    def get_animation_length(self, stance: int, motion: int, current_motion: int, portal_dat):
        anim_data = self.get_anim_data(stance, motion, current_motion)

        length = portal_dat.mode.scalar(0.0)
        for anim in anim_data:
            length += self.get_animation_length_of_anim(anim, portal_dat)

        return length

    @anchor(None, "ACE.DatLoader/FileTypes/MotionTable.cs:GetAnimationLength(AnimData)")
    def get_animation_length_of_anim(self, anim, portal_dat):
        from .animation import Animation

        high_frame = anim.high_frame

        # get the maximum # of animation frames (ACE)
        animation = portal_dat.read_from_dat(anim.anim_id, Animation)

        if anim.high_frame == -1:
            high_frame = wrap_i32(animation.num_frames)

        if high_frame > animation.num_frames:
            high_frame = wrap_i32(animation.num_frames)

        num_frames = wrap_i32(high_frame - anim.low_frame)

        # framerates can be negative, which tells the client to play in reverse (ACE)
        return type(anim.framerate)(num_frames) / abs(anim.framerate)
