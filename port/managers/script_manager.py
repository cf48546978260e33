"""ScriptManager: ScriptManager(obj), AddScript, UpdateScripts.

ACE's Physics/Scripts/ScriptManager.cs (the one class of ACE's Scripts folder the physics makes, kept
with the other managers): PhysicsObj.play_script_internal makes one for an object that plays a
script (InitDefaults plays its Setup's DefaultScript). ACE's server runs no PhysicsScript: AddScript
answers false without reading the script, and UpdateScripts does nothing, so a ScriptManager only
exists -- PhysicsObj's update steps call UpdateScripts on it each tick.
"""

from __future__ import annotations

from dataclasses import dataclass

from ..anchors import anchor


@dataclass(slots=True, eq=False)
class ScriptManager:
    physics_obj: object = None
    # CurrData, LastData, HookIndex and NextHookTime: ACE declares them and never sets them
    curr_data: object = None
    last_data: object = None
    hook_index: int = 0
    next_hook_time: float = 0.0  # double

    @staticmethod
    @anchor("ScriptManager::ScriptManager", "ScriptManager.cs:ScriptManager")
    def create(obj) -> "ScriptManager":
        """``new ScriptManager(obj)``: PhysObj = obj."""
        return ScriptManager(physics_obj=obj)

    @anchor("ScriptManager::AddScript", "ScriptManager.cs:AddScript")
    def add_script(self, script_id: int) -> bool:
        """ACE's body is `return false`: the script is neither read nor queued."""
        return False

    @anchor("ScriptManager::UpdateScripts", "ScriptManager.cs:UpdateScripts")
    def update_scripts(self) -> None:
        """ACE's body is empty."""
