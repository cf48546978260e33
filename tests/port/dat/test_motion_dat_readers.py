"""port/dat's motion-layer readers (MotionTable, MotionData, AnimData, Animation, AnimationFrame,
AnimationHook and its classes) on acconform/dat.py's bytes: every field back, every byte read."""

from __future__ import annotations

import struct

import numpy as np
import pytest

from acconform import dat
from acconform.dat import HookRec
from acconform.numerics import EXACT
from acconform.port.dat import animation_hooks as hooks
from acconform.port.dat.animation import Animation
from acconform.port.dat.animation_hook import AnimationHook, AnimationHookType as H
from acconform.port.dat.binary_reader import BinaryReader
from acconform.port.dat.motion_table import MotionTable
from acconform.port.dat.setup_model import SetupModel

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "animation"))
import motion_tables as mt  # noqa: E402


def _read(data: bytes, make):
    reader = BinaryReader(data, EXACT)
    value = make(reader)
    assert reader.position == len(data), "bytes left unread"
    return value


@pytest.mark.anchor("ACE.DatLoader/FileTypes/MotionTable.cs:Unpack")
def test_a_motion_table_reads_back_its_styles_cycles_modifiers_and_links():
    table = _read(mt.table().data, MotionTable.unpack)
    assert table.id == mt.TABLE_ID and table.default_style == mt.NON_COMBAT
    assert table.style_defaults == {mt.NON_COMBAT: mt.READY, mt.HAND_COMBAT: mt.READY}
    walk = table.cycles[mt.key(mt.NON_COMBAT, mt.WALK)]
    assert walk.bitfield == 1 and walk.velocity == EXACT.vec(0, 3.12, 0) and walk.omega == EXACT.vec(0, 0, 0)
    assert [(a.anim_id, a.low_frame, a.high_frame, a.framerate) for a in walk.anims] == [(mt.A_WALK, 0, -1, np.float32(30))]
    assert table.modifiers[mt.key(mt.NON_COMBAT, mt.MODIFIER)].omega == EXACT.vec(0, 0, 1.5)
    assert list(table.links) == [mt.key(mt.NON_COMBAT, mt.READY), mt.key(mt.NON_COMBAT, mt.WALK), mt.key(mt.NON_COMBAT, 0)]
    action = table.links[mt.key(mt.NON_COMBAT, mt.READY)][mt.ACTION].anims[0]
    assert (action.low_frame, action.high_frame, action.framerate) == (1, 4, np.float32(15))


@pytest.mark.anchor("ACE.DatLoader/FileTypes/Animation.cs:Unpack")
def test_an_animation_reads_back_its_pos_frames_part_frames_and_hooks():
    anim = _read(mt.ANIMATIONS[0].data, Animation.unpack)
    assert (anim.id, anim.flags, anim.num_parts, anim.num_frames) == (mt.A_READY, 1, 1, 4)
    assert len(anim.pos_frames) == 4 and len(anim.part_frames) == 4
    assert anim.part_frames[0].frames[0].origin == EXACT.vec(0, 0, 0.5)
    got = [(type(h).__name__, h.hook_type, h.direction) for h in anim.part_frames[1].hooks]
    assert got == [("EtherealHook", H.Ethereal, 1), ("SoundHook", H.Sound, -1), ("AnimationHook", H.AnimationDone, 0)]
    assert anim.part_frames[1].hooks[0].ethereal == 1 and anim.part_frames[1].hooks[1].id == 7


@pytest.mark.anchor("ACE.DatLoader/FileTypes/Animation.cs:Unpack")
def test_an_animation_without_pos_frames_has_none():
    rec = dat.animation_record(0x03000099, 2, [dat.AnimationFrameRec((((0, 0, 0), (1, 0, 0, 0)),) * 2)])
    anim = _read(rec.data, Animation.unpack)
    assert anim.flags == 0 and anim.pos_frames == [] and len(anim.part_frames[0].frames) == 2


# the bytes each hook class reads after its type and direction, as its Unpack reads them
_U, _F = struct.Struct("<I"), struct.Struct("<f")
HOOK_FIELDS = {
    H.Sound: _U.pack(1), H.SoundTable: _U.pack(2), H.Attack: _U.pack(3) + _F.pack(1.5) * 6,
    H.ReplaceObject: struct.pack("<HH", 0x102, 0x8001) + struct.pack("<H", 0x0002), H.Ethereal: _U.pack(1),
    H.TransparentPart: _U.pack(1) + _F.pack(0.5) * 3, H.Luminous: _F.pack(0.5) * 3, H.LuminousPart: _U.pack(1) + _F.pack(0.5) * 3,
    H.Diffuse: _F.pack(0.5) * 3, H.DiffusePart: _U.pack(1) + _F.pack(0.5) * 3, H.Scale: _F.pack(0.5) * 2,
    H.CreateParticle: _U.pack(1) + _U.pack(2) + _F.pack(0) * 3 + _F.pack(1) + _F.pack(0) * 3 + _U.pack(3),
    H.DestroyParticle: _U.pack(1), H.StopParticle: _U.pack(1), H.NoDraw: _U.pack(1), H.DefaultScript: b"",
    H.DefaultScriptPart: _U.pack(1), H.CallPES: _U.pack(1) + _F.pack(0.25), H.Transparent: _F.pack(0.5) * 3,
    H.SoundTweaked: _U.pack(1) + _F.pack(0.5) * 3, H.SetOmega: _F.pack(1.0) * 3, H.TextureVelocity: _F.pack(0.5) * 2,
    H.TextureVelocityPart: _U.pack(1) + _F.pack(0.5) * 2, H.SetLight: _U.pack(1),
    H.CreateBlockingParticle: _U.pack(1) + _U.pack(2) + _F.pack(0) * 3 + _F.pack(1) + _F.pack(0) * 3 + _U.pack(3),
    H.AnimationDone: b"",
}


@pytest.mark.anchor("ACE.DatLoader/Entity/AnimationHook.cs:ReadHook")
def test_every_hook_type_ace_reads_is_read_to_its_last_byte_as_its_class():
    assert set(HOOK_FIELDS) == set(hooks.HOOK_CLASSES)
    for hook_type, fields in HOOK_FIELDS.items():
        hook = _read(dat.animation_hook(HookRec(int(hook_type), -1, fields)), AnimationHook.read_hook)
        assert type(hook) is hooks.HOOK_CLASSES[hook_type] and (hook.hook_type, hook.direction) == (hook_type, -1)
    replace = _read(dat.animation_hook(HookRec(int(H.ReplaceObject), 0, HOOK_FIELDS[H.ReplaceObject])), AnimationHook.read_hook)
    # the part index is the low byte of a ushort; the id a known-type DataID of two ushorts (0x8001: high word 1)
    assert (replace.ap_change.part_index, replace.ap_change.part_id) == (0x02, 0x01000000 + 0x00010002)


@pytest.mark.anchor("ACE.DatLoader/Entity/AnimationHook.cs:ReadHook")
def test_a_hook_type_ace_does_not_read_is_null_and_reads_nothing():
    for hook_type in (H.NoOp, H.Unknown, 27):
        reader = BinaryReader(dat.animation_hook(HookRec(int(hook_type), 1)), EXACT)
        assert AnimationHook.read_hook(reader) is None and reader.position == 0


@pytest.mark.anchor("ACE.DatLoader/FileTypes/SetupModel.cs:Unpack")
def test_a_setup_names_its_default_animation_and_motion_table_only_when_given():
    plain = dat.setup(0x02000005, [0x01000005])
    named = dat.setup(0x02000005, [0x01000005], default_animation=mt.A_READY, default_motion_table=mt.TABLE_ID)
    assert len(plain) == len(named) and plain[:-20] == named[:-20] and plain[-20:] == bytes(20)
    s = _read(named, SetupModel.unpack)
    assert (s.default_animation, s.default_script, s.default_motion_table) == (mt.A_READY, 0, mt.TABLE_ID)


@pytest.mark.anchor("ACE.DatLoader/FileTypes/Animation.cs:Unpack")
def test_a_scene_animation_without_root_motion_and_with_hooks_is_written_as_ace_reads_it():
    from acconform.motion_scene import ANIMATION_BASE, AnimationSpec, AnimRef, HookSpec, MotionDataSpec, MotionEntry, MotionTableSpec
    from acconform.scene import Frame

    nc, ready = 0x8000003D, 0x41000003
    frames = (Frame((0.0, 0.1, 0.0)), Frame((0.0, 0.2, 0.0)))
    table = MotionTableSpec(nc, ((nc, ready),), (AnimationSpec(frames, False, (HookSpec(1, "AnimationDone", -1),
                                                                                HookSpec(1, "Ethereal"))),),
                            (MotionEntry(nc, ready, MotionDataSpec((AnimRef(0, 30.0),))),), default_animation=0)
    anim = _read(dat.motion_records(table)[1].data, Animation.unpack)
    assert anim.flags == 0 and anim.pos_frames == [] and anim.num_frames == 2 and anim.part_frames[0].hooks == []
    got = [(type(h).__name__, h.hook_type, h.direction) for h in anim.part_frames[1].hooks]
    assert got == [("AnimationHook", H.AnimationDone, -1), ("EtherealHook", H.Ethereal, 0)]
    from acconform.scene import Mover, Position

    mover = Mover((), Position(0xA9B40001, Frame((12.0, 12.0, 20.0))), None, 0.4, 0.4, motion_table=table)
    setup = next(r for r in dat.mover_records(mover).records if r.kind == "SetupModel")
    assert _read(setup.data, SetupModel.unpack).default_animation == ANIMATION_BASE
