"""AnimHook: Execute -- what ACE's physics does with an animation hook PhysicsObj.process_hooks runs.

ACE's Physics/Hooks/AnimHook.cs. Only AnimationDone acts (PhysicsObj.Hook_AnimDone, which tells the
MotionTableManager an animation ended); every other type is ignored: ACE's Ethereal case is
commented out, and sounds, scripts, parts and the rest are the client's. A null hook (a type
DatLoader's ReadHook does not know) reads HookType on null: NullReferenceException, as in ACE.
"""

from __future__ import annotations

from .anchors import anchor
from .dat.animation_hook import AnimationHookType


@anchor(None, "AnimHook.cs:Execute")
def anim_hook_execute(obj, anim_hook) -> None:
    if anim_hook.hook_type == AnimationHookType.AnimationDone:
        obj.hook_anim_done()
