"""ScriptManager (ACE's Physics/Scripts/ScriptManager.cs) and the PhysicsObj routines that make and
step it: play_script_internal, InitDefaults' DefaultScript, UpdateObjectInternal's UpdateScripts."""

from types import SimpleNamespace

import pytest

from acconform.flags import PhysicsState
from acconform.numerics import EXACT
from acconform.port.managers.script_manager import ScriptManager
from acconform.port.physics_obj import PhysicsObj
from acconform.port.physics_timer import PhysicsTimer


def _obj(static: bool = False) -> PhysicsObj:
    obj = PhysicsObj.create(EXACT, PhysicsTimer(0.0))
    obj.init_object_begin(0, not static)
    return obj


def _setup(default_script: int, default_animation: int = 0):
    """The Setup members InitDefaults reads (no motion table: SetMotionTableID is not reached)."""
    return SimpleNamespace(default_script=default_script, default_motion_table=0, default_animation=default_animation)


@pytest.mark.anchor("ScriptManager::AddScript")
def test_add_script_refuses_every_script_as_aces_server_runs_none():
    manager = ScriptManager.create(object())
    assert manager.add_script(0x33000001) is False
    assert (manager.curr_data, manager.last_data, manager.hook_index, manager.next_hook_time) == (None, None, 0, 0.0)


@pytest.mark.anchor("ScriptManager::ScriptManager")
def test_a_script_manager_knows_its_object():
    obj = _obj()
    assert ScriptManager.create(obj).physics_obj is obj


@pytest.mark.anchor("CPhysicsObj::play_script_internal")
def test_play_script_internal_makes_the_script_manager_once_and_answers_add_scripts_false():
    obj = _obj()
    assert obj.play_script_internal(0x33000001) is False
    manager = obj.script_manager
    assert isinstance(manager, ScriptManager) and manager.physics_obj is obj
    assert obj.play_script_internal(0x33000002) is False
    assert obj.script_manager is manager


@pytest.mark.anchor("CPhysicsObj::play_script_internal")
def test_script_zero_makes_no_script_manager():
    obj = _obj()
    assert obj.play_script_internal(0) is False
    assert obj.script_manager is None


@pytest.mark.anchor("CPhysicsObj::InitDefaults")
def test_a_setups_default_script_makes_the_script_manager_and_marks_only_a_static():
    mover, static = _obj(), _obj(static=True)
    mover.init_defaults(_setup(0x33000001))
    static.init_defaults(_setup(0x33000001))
    assert mover.script_manager is not None and static.script_manager is not None
    assert not mover.state & PhysicsState.HasDefaultScript
    assert static.state & PhysicsState.HasDefaultScript


@pytest.mark.anchor("CPhysicsObj::InitDefaults")
def test_a_setup_without_a_default_script_leaves_the_script_manager_null():
    static = _obj(static=True)
    static.init_defaults(_setup(0))
    assert static.script_manager is None and not static.state & PhysicsState.HasDefaultScript


@pytest.mark.anchor("ScriptManager::UpdateScripts")
def test_update_scripts_changes_nothing_on_the_manager_or_its_object():
    obj = _obj()
    obj.play_script_internal(0x33000001)
    manager = obj.script_manager
    before = (manager.curr_data, manager.last_data, manager.hook_index, manager.next_hook_time, obj.state,
              obj.transient_state, obj.script_manager)
    assert manager.update_scripts() is None
    assert (manager.curr_data, manager.last_data, manager.hook_index, manager.next_hook_time, obj.state,
            obj.transient_state, obj.script_manager) == before
