"""Tick scenes of a target gone from the world and of a RequestPos into no cell (issue 40's coverage; shard
ticks-0073), drawn over strategies/motion.py's draw_managed_chase:

    draw_world_exit(draw, clock, only=None)   one of ARMS, named ``world:<arm>:<what>:<the chase's name>``

- ``gone_chase``: a chase whose target the server destroys at a tick, and then a MoveToObject at it (feature
  objects.gone_targets): a monster's AttackTarget outlives its Destroy, and Monster_Navigation.StartTurn still
  passes AttackTarget.PhysicsObj, now out of ServerObjectManager. TargetManager.SetTarget finds no target (no
  voyeur), HandleTargetting waits for a first update that never comes and, 10 s on, times the target out
  (ClearTarget of a target gone); one scene in two runs on a slow clock (0.25 s to 1 s a tick) to get there.
- ``no_cell``: a chase on the request_pos driver (Player.UpdatePlayerPosition) in which a tick's RequestPos names
  no cell of the mover's landblock (feature ticks.no_cell_requests: low word 0x0000 or 0x0041..0x00FF, which
  ValidateMovement lets through and LScape.get_landcell answers null for): no update that tick.

- ``table_exit``: a chase whose target (a creature) has the mover's motion table (feature objects.motion_tables: its
  WorldObject's MotionTableId, so SetMotionTableID makes its MotionTableManager and MovementManager and
  update_object animates it) and is destroyed at a tick: DestroyObject's leave_world (LeaveGround on walkable
  ground) and exit_world (PartArray.HandleExitWorld, MovementManager.HandleExitWorld, MotionInterp.HandleExitWorld)
  reach its managers; one scene in two moves the target at it after (a gone_chase).

- ``unentered`` (drawn only with `only`: ARMS keeps seed 73's draws): beside a chase, a creature whose Setup has no
  parts (setup.no_parts: makeObject gives it no PartArray, so its enter_world fails and it never enters the world)
  that the server destroys at a tick: WorldObject.Destroy of an object on no landblock does nothing to its physics.

A draw that finds no chase to change (no destroyed target; no request_pos driver) is named ``world:<arm>:none:``
(tests/runner/world_exit_scenes.py leaves those out). No campaign kind draws these: a draw added to the targets
kind would move every seeded sample the tests pin.
"""

from __future__ import annotations

from dataclasses import replace

from hypothesis import strategies as st

from acconform.motion_scene import ObjectMoveInput
from acconform.scene import Position, Scene

ARMS = ("gone_chase", "no_cell", "table_exit")
SLOW_DTS = st.sampled_from((0.25, 0.5, 1.0, 0.5))  # a tick of a slow clock: 10 s pass in 10 to 40 ticks
NO_CELL_LOWS = st.sampled_from((0x0000, 0x0041, 0x0080, 0x00FF))  # get_landcell: gid_to_lcoord answers null
TRIES = 12  # chases drawn until one has what the arm changes


def _slow_or_plain(clock):
    def slow(draw, n: int):
        if draw(st.booleans()):
            return clock(draw, n)
        dt = draw(SLOW_DTS)
        start, _, _ = clock(draw, 1)
        return start, [dt] * n, f"slow{dt:g}"
    return slow


def _gone(scene: Scene) -> tuple[int, int] | None:
    """(the tick the target is destroyed at, its id), or None."""
    for i, step in enumerate(scene.ticks.steps):
        for o in step.others:
            if o.destroy:
                return i, o.id
    return None


def _gone_chase(draw, clock) -> Scene | None:
    from .motion import _params_of_first, draw_managed_chase

    for _ in range(TRIES):
        scene = draw_managed_chase(draw, _slow_or_plain(clock))
        gone = _gone(scene)
        if gone is None or gone[0] >= len(scene.ticks.steps) - 1:
            continue
        at_gone, target = gone
        steps = list(scene.ticks.steps)
        free = [i for i in range(at_gone + 1, len(steps)) if steps[i].move_to_object is None]
        if not free:
            continue
        at = free[draw(st.integers(0, min(len(free) - 1, 3)))]  # soon after the Destroy: time left for the timeout
        steps[at] = replace(steps[at], move_to_object=ObjectMoveInput(target, _params_of_first(steps)))
        return scene.replace(ticks=replace(scene.ticks, steps=tuple(steps)),
                             name=f"world:gone_chase:moveto@{at}:{scene.name}")
    return None


def _no_cell(draw, clock) -> Scene | None:
    from .motion import draw_managed_chase

    for _ in range(TRIES):
        scene = draw_managed_chase(draw, clock)
        if scene.ticks.driver != "request_pos":
            continue
        steps = list(scene.ticks.steps)
        n = len(steps)
        at = draw(st.integers(0, n - 1))
        run = draw(st.integers(1, max(1, min(3, n - at))))
        low = draw(NO_CELL_LOWS)
        for i in range(at, at + run):
            r = steps[i].request_pos
            steps[i] = replace(steps[i], request_pos=Position((r.cell & 0xFFFF0000) | low, r.frame))
        return scene.replace(ticks=replace(scene.ticks, steps=tuple(steps)),
                             name=f"world:no_cell:{low:04X}@{at}x{run}:{scene.name}")
    return None


def _destroy_at(scene: Scene, oid: int, at: int) -> Scene:
    """The scene with other `oid` destroyed at tick `at` (its inputs there replaced, none after)."""
    from acconform.scene import OtherInputs

    steps = []
    for i, step in enumerate(scene.ticks.steps):
        rows = tuple(o for o in step.others if o.id != oid)
        if i == at:
            rows += (OtherInputs(oid, destroy=True),)
        steps.append(replace(step, others=rows) if rows != step.others else step)
    return scene.replace(ticks=replace(scene.ticks, steps=tuple(steps)))


JUMP_UPS = st.sampled_from((1.0, 2.5, 4.0, 0.5))


def _jump_at(scene: Scene, oid: int, at: int, up: float) -> Scene:
    """The scene with player other `oid` jumping straight up at tick `at` (its jump input, a local velocity)."""
    steps = list(scene.ticks.steps)
    rows = list(steps[at].others)
    for k, o in enumerate(rows):
        if o.id == oid:
            rows[k] = replace(o, jump=(0.0, 0.0, up))
            break
    else:
        from acconform.scene import OtherInputs

        rows.append(OtherInputs(oid, jump=(0.0, 0.0, up)))
    steps[at] = replace(steps[at], others=tuple(rows))
    return scene.replace(ticks=replace(scene.ticks, steps=tuple(steps)))


def _table_exit(draw, clock) -> Scene | None:
    from .motion import draw_managed_chase

    for _ in range(TRIES):
        scene = draw_managed_chase(draw, clock)
        gone = _gone(scene)
        if gone is None or scene.mover.motion_table is None:
            continue
        others = tuple(replace(o, motion_table=True) if o.id == gone[1] else o for o in scene.others)
        scene = scene.replace(others=others, name=f"world:table_exit:gone@{gone[0]}:{scene.name}")
        target = next(o for o in scene.others if o.id == gone[1])
        if target.weenie == "player" and gone[0] >= 2 and draw(st.booleans()):
            # a jump first (Player.HandleActionJump: set_on_walkable(false) -> MotionInterp.LeaveGround), then the
            # landing (HitGround) moves it back to its interpreted state before the Destroy
            scene = _jump_at(scene, gone[1], draw(st.integers(0, gone[0] - 1)), draw(JUMP_UPS))
            scene = scene.replace(name=scene.name + ":jump")
        elif draw(st.booleans()):
            # destroyed at once (tick 0 or 1: its EnterDefaultState's animations and motions still pending)
            early = draw(st.integers(0, min(gone[0], 1)))
            scene = _destroy_at(scene, gone[1], early)
            gone = (early, gone[1])
            scene = scene.replace(name=scene.name + f":early@{early}")
        if draw(st.booleans()):
            steps = list(scene.ticks.steps)
            free = [i for i in range(gone[0] + 1, len(steps)) if steps[i].move_to_object is None]
            if free:
                from .motion import _params_of_first

                at = free[draw(st.integers(0, len(free) - 1))]
                steps[at] = replace(steps[at], move_to_object=ObjectMoveInput(gone[1], _params_of_first(steps)))
                scene = scene.replace(ticks=replace(scene.ticks, steps=tuple(steps)), name=scene.name + f":moveto@{at}")
        return scene
    return None


def _unentered(draw, clock) -> Scene | None:
    from acconform.flags import PLAYER_KILLER_STATUS_NPK
    from acconform.scene import OtherInputs, SetupRec

    from .motion import draw_managed_chase

    scene = draw_managed_chase(draw, clock)
    target = scene.others[0]
    (bx, by, bz), (tx, ty, _) = scene.mover.begin.frame.origin, target.begin.frame.origin
    ghost_id = max(o.id for o in scene.others if o.weenie != "player") + 1 if any(
        o.weenie != "player" for o in scene.others) else 0x80000100
    ghost = replace(target, id=ghost_id, weenie="creature", setup=SetupRec(()), motion_table=False,
                    begin=Position(scene.mover.begin.cell, replace(target.begin.frame, origin=(2 * bx - tx, 2 * by - ty, bz))))
    if target.weenie == "player":
        ghost = replace(ghost, player_killer_status=PLAYER_KILLER_STATUS_NPK)  # an NPC's
    n = len(scene.ticks.steps)
    at = draw(st.integers(0, n - 1))
    steps = list(scene.ticks.steps)
    steps[at] = replace(steps[at], others=steps[at].others + (OtherInputs(ghost.id, destroy=True),))
    return scene.replace(others=scene.others + (ghost,), ticks=replace(scene.ticks, steps=tuple(steps)),
                         name=f"world:unentered:gone@{at}:{scene.name}")


def draw_world_exit(draw, clock, only: str | None = None) -> Scene:
    """One scene of an arm (`only`, or drawn)."""
    arm = only or draw(st.sampled_from(ARMS))
    scene = {"gone_chase": _gone_chase, "no_cell": _no_cell, "table_exit": _table_exit, "unentered": _unentered}[arm](draw, clock)
    if scene is None:
        from .motion import draw_managed_chase

        scene = draw_managed_chase(draw, clock)
        return scene.replace(name=f"world:{arm}:none:")
    return scene
