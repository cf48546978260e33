"""Shrinking a scene that did not come from Hypothesis: a recorded scene that differs.

A live campaign's scenes are Hypothesis' own draws, and Hypothesis shrinks them. A replayed
corpus scene was drawn long ago, so Hypothesis cannot shrink it; `shrink_scene` does, greedily,
on the scene record itself: it tries a smaller scene (fewer objects, EnvCells, Environments,
landblocks; one sphere; no velocity, slide or placement; flat bare terrain; a shorter path;
fewer flags; for a tick scene fewer ticks, fewer inputs and simpler time steps; fewer other movers and fewer of
their inputs) and keeps it when `still_fails(candidate)` says the difference is still there. A
candidate that is no valid scene (`validate_scene` refuses it) is never run.

It knows nothing of ACE: the caller's `still_fails` compares the implementation with whatever
stands in for ACE (the runner uses the built-in port, after checking that it agrees with ACE's
recorded answer on the original scene). Deterministic: the same scene and predicate give the
same result. `budget` bounds the candidates tried.

Never larger: a candidate larger than the scene first given in any measure (`Size`: its JSON's
bytes, landblocks, objects, polygons, BSP nodes, cells, ticks) is never run, so the scene
returned is no larger than the one given in every measure (a simpler time step or a midpoint can
take more digits than the value it replaces). `no_larger` is the one test of it, which the
runner also applies to what Hypothesis' shrinker hands back before this shrink starts from it.
"""

from __future__ import annotations

from dataclasses import dataclass, fields, replace
from typing import Callable, Iterator

from .errors import InvalidScene
from .flags import PLAYER_KILLER_STATUS_NPK, PhysicsState, TransientState
from .numerics import to_f32
from .scene import (BSPLeaf, BSPNode, Building, CellBSPLeaf, CellBSPNode, EnvCell, Landblock, OtherMover, PolygonRec,
                    StaticObject, OTHER_INPUTS, TICK_INPUTS, Scene, validate_scene)

DEFAULT_BUDGET = 300  # candidates tried per scene (each costs a run on both sides)


def scene_bytes(scene: Scene) -> int:
    return len(scene.dumps().encode("utf-8"))


@dataclass(frozen=True, slots=True)
class Size:
    """A scene's size in every measure a shrink must not grow."""

    bytes: int
    landblocks: int
    objects: int  # static objects, buildings and other movers
    polygons: int  # every polygon record: objects', Environments' cell structures', buildings'
    bsp_nodes: int  # nodes and leaves of every BSP, physics and cell
    cells: int  # EnvCells
    ticks: int  # a tick scene's steps

    def exceeds(self, other: "Size") -> list[str]:
        """The measures in which this size is larger than `other`'s."""
        return [f.name for f in fields(self) if getattr(self, f.name) > getattr(other, f.name)]


_COUNTED = {Landblock: "landblocks", StaticObject: "objects", Building: "objects", OtherMover: "objects", PolygonRec: "polygons",
            BSPNode: "bsp_nodes", BSPLeaf: "bsp_nodes", CellBSPNode: "bsp_nodes", CellBSPLeaf: "bsp_nodes",
            EnvCell: "cells"}


def size(scene: Scene) -> Size:
    """`scene`'s size in every measure (`Size`)."""
    counts = dict.fromkeys(("landblocks", "objects", "polygons", "bsp_nodes", "cells"), 0)
    stack: list = [scene]
    while stack:
        x = stack.pop()
        if isinstance(x, (tuple, list)):
            stack.extend(y for y in x if not isinstance(y, (int, float, str, bool, type(None))))
        elif hasattr(x, "__dataclass_fields__"):
            name = _COUNTED.get(type(x))
            if name is not None:
                counts[name] += 1
            for f in fields(x):
                v = getattr(x, f.name)
                if not isinstance(v, (int, float, str, bool, type(None))):
                    stack.append(v)
        elif isinstance(x, dict):
            stack.extend(x.values())
    ticks = len(scene.ticks.steps) if scene.ticks is not None else 0
    return Size(scene_bytes(scene), ticks=ticks, **counts)


def no_larger(given: "Scene | Size", scene: Scene) -> bool:
    """Whether `scene` is no larger than `given` (a scene or its Size) in every measure: the one test a
    shrink's result must pass, on every path (acconform.shrink, Hypothesis' shrinker, the runner's)."""
    limit = given if isinstance(given, Size) else size(given)
    return not size(scene).exceeds(limit)


def _without(items: tuple, i: int) -> tuple:
    return items[:i] + items[i + 1:]


def _cells(scene: Scene) -> Iterator[Scene]:
    """Fewer EnvCells: per landblock the last one (they are numbered without gaps), then the
    Environments no cell names any more."""
    for c in reversed(scene.env_cells):
        block = c.id >> 16
        last = max(x.id for x in scene.env_cells if x.id >> 16 == block)
        if c.id == last:
            yield scene.replace(env_cells=tuple(x for x in scene.env_cells if x is not c))
    used = {c.environment for c in scene.env_cells}
    if any(e.id not in used for e in scene.environments):
        yield scene.replace(environments=tuple(e for e in scene.environments if e.id in used))


def _landblocks(scene: Scene) -> Iterator[Scene]:
    for i in reversed(range(len(scene.landblocks))):
        if len(scene.landblocks) > 1:
            yield scene.replace(landblocks=_without(scene.landblocks, i))
    flat = tuple(replace(lb, heights=(0,) * len(lb.heights), terrain=(0,) * len(lb.terrain))
                 for lb in scene.landblocks if lb.has_terrain)
    if any(lb.has_terrain and (any(lb.heights) or any(lb.terrain)) for lb in scene.landblocks):
        it = iter(flat)
        yield scene.replace(landblocks=tuple(next(it) if lb.has_terrain else lb for lb in scene.landblocks))
    for i, lb in enumerate(scene.landblocks):
        if lb.has_terrain and any(lb.terrain):
            yield scene.replace(landblocks=scene.landblocks[:i] + (replace(lb, terrain=(0,) * len(lb.terrain)),)
                                + scene.landblocks[i + 1:])


def _mover(scene: Scene) -> Iterator[Scene]:
    m = scene.mover

    def with_(**kw):
        return scene.replace(mover=replace(m, **kw))

    if len(m.spheres) > 1:
        yield with_(spheres=m.spheres[:1])
    if m.placement is not None:
        yield with_(placement=None)
    if m.velocity != (0.0, 0.0, 0.0):
        yield with_(velocity=(0.0, 0.0, 0.0))
    if m.sliding_normal is not None:
        yield with_(sliding_normal=None)
    if m.contact_plane is not None:
        yield with_(contact_plane=None)
    if m.scale != 1.0:
        yield with_(scale=1.0)
    if m.end is not None and m.end != m.begin:  # a tick scene's mover has no end
        yield with_(end=m.begin)
        if m.end.cell == m.begin.cell:  # halfway along the path, in the same cell
            a, b = m.begin.frame.origin, m.end.frame.origin
            mid = tuple(to_f32((x + y) / 2) for x, y in zip(a, b))
            if mid != b:
                yield with_(end=replace(m.end, frame=replace(m.end.frame, origin=mid)))
    for flags, name in ((PhysicsState, "state"), (TransientState, "transient_state")):
        value = getattr(m, name)
        for f in flags:
            if value & f.value:
                yield with_(**{name: value & ~f.value})


# the simplest time step a tick shrinks to: 30 fps, a clock at 1000 s (the example tick scenes')
SIMPLE_DT = 1 / 30
SIMPLE_START = 1000.0


def _motion_table(scene: Scene) -> Iterator[Scene]:
    """The mover's motion table made smaller: its links, modifiers and cycles left out (all, then one by
    one), an animation's frames cut to one or to half, and animations no entry plays left out."""
    t = scene.mover.motion_table
    if t is None:
        return

    def with_(**kw):
        return scene.replace(mover=replace(scene.mover, motion_table=replace(t, **kw)))

    for name in ("links", "modifiers", "cycles"):
        entries = getattr(t, name)
        if entries and name != "cycles":
            yield with_(**{name: ()})
        for i in reversed(range(len(entries))):
            yield with_(**{name: _without(entries, i)})
    played = sorted({a.animation for e in t.cycles + t.links + t.modifiers for a in e.data.anims})
    if len(played) < len(t.animations):
        index = {old: new for new, old in enumerate(played)}

        def renumbered(e):
            anims = tuple(replace(a, animation=index[a.animation]) for a in e.data.anims)
            return replace(e, data=replace(e.data, anims=anims))

        yield with_(animations=tuple(t.animations[i] for i in played), cycles=tuple(map(renumbered, t.cycles)),
                    links=tuple(map(renumbered, t.links)), modifiers=tuple(map(renumbered, t.modifiers)))
    for i, a in enumerate(t.animations):
        n = len(a.pos_frames)
        for keep in sorted({1, n // 2} - {0, n}):
            yield with_(animations=t.animations[:i] + (replace(a, pos_frames=a.pos_frames[:keep]),) + t.animations[i + 1:])


def _inputs(step) -> bool:
    return bool(step.others) or any(getattr(step, name) is not None for name in TICK_INPUTS)


def _fewer_others(scene: Scene) -> Iterator[Scene]:
    """Fewer other movers: all, then each, last first; a mover's inputs go with it (tried before the ticks:
    a whole mover is the biggest cut)."""
    others = scene.others
    if others:
        yield _without_others(scene, {o.id for o in others})
        for o in reversed(others):
            yield _without_others(scene, {o.id})


def _without_others(scene: Scene, ids: set) -> Scene:
    """The scene without the other movers `ids` and their children (a child names an earlier other as its parent:
    it goes with it)."""
    ids = set(ids)
    for o in scene.others:
        if o.parent is not None and o.parent.id in ids:
            ids.add(o.id)
    ticks = scene.ticks
    if ticks is not None:
        ticks = replace(ticks, steps=tuple(replace(st, others=tuple(o for o in st.others if o.id not in ids))
                                           for st in ticks.steps))
    return scene.replace(others=tuple(o for o in scene.others if o.id not in ids), ticks=ticks)


def _others(scene: Scene) -> Iterator[Scene]:
    """Fewer of the other movers' inputs (each step's entry, then each input of it), and simpler others (at
    rest, not PK, scale 1, one sphere)."""
    others = scene.others
    if not others:
        return
    if scene.ticks is not None:
        steps = scene.ticks.steps
        for i, step in enumerate(steps):
            for k, inputs in enumerate(step.others):
                yield scene.replace(ticks=replace(scene.ticks, steps=steps[:i] + (replace(step, others=_without(step.others, k)),)
                                                  + steps[i + 1:]))
                for name in OTHER_INPUTS:
                    if getattr(inputs, name) is not None:
                        one = replace(step, others=step.others[:k] + (replace(inputs, **{name: None}),) + step.others[k + 1:])
                        yield scene.replace(ticks=replace(scene.ticks, steps=steps[:i] + (one,) + steps[i + 1:]))
    for k, o in enumerate(others):
        for change in ({"velocity": (0.0, 0.0, 0.0)}, {"player_killer_status": PLAYER_KILLER_STATUS_NPK},
                       {"scale": 1.0}, {"spheres": o.spheres[:1]}):
            if any(getattr(o, f) != v for f, v in change.items()):
                yield scene.replace(others=others[:k] + (replace(o, **change),) + others[k + 1:])


def _ticks(scene: Scene) -> Iterator[Scene]:
    """Fewer ticks (the first half, all but the last, runs of ticks left out or merged into one,
    halves first), fewer inputs (each input of each step; a request_pos driver's RequestPos stays),
    simpler time steps (every dt, then each dt, 1/30 s; the clock's start 1000 s)."""
    t = scene.ticks
    steps = t.steps

    def with_(**kw):
        return scene.replace(ticks=replace(t, **kw))

    if len(steps) > 1:
        yield with_(steps=steps[: len(steps) // 2])
        yield with_(steps=steps[:-1])
        # runs of ticks left out, or merged into one tick of their time steps where only the run's
        # first tick has inputs (update_object cuts a long tick into quanta, so the mover often goes
        # the same way in fewer ticks): halves, then quarters, ... then single ticks and pairs, as
        # delta debugging does, so a difference deep in a long walk comes down to a few ticks
        k = len(steps) // 2
        while k >= 1:
            for start in range(0, len(steps) - k, k):
                yield with_(steps=steps[:start] + steps[start + k:])
            for start in range(0, len(steps) - k, k):
                run = steps[start:start + k + 1]
                if not any(_inputs(st) for st in run[1:]):
                    yield with_(steps=steps[:start] + (replace(run[0], dt=sum(st.dt for st in run)),) + steps[start + k + 1:])
            k //= 2
    for i, step in enumerate(steps):
        for name in TICK_INPUTS:
            if name != "request_pos" and getattr(step, name) is not None:
                yield with_(steps=steps[:i] + (replace(step, **{name: None}),) + steps[i + 1:])
    if any(s.dt != SIMPLE_DT for s in steps):
        yield with_(steps=tuple(replace(s, dt=SIMPLE_DT) for s in steps))
        for i, step in enumerate(steps):
            if step.dt != SIMPLE_DT:
                yield with_(steps=steps[:i] + (replace(step, dt=SIMPLE_DT),) + steps[i + 1:])
    if t.start != SIMPLE_START:
        yield with_(start=SIMPLE_START)


def _candidates(scene: Scene) -> Iterator[Scene]:
    yield from _fewer_others(scene)
    if scene.ticks is not None:
        yield from _ticks(scene)
    if scene.objects:
        yield scene.replace(objects=())
        for i in reversed(range(len(scene.objects))):
            yield scene.replace(objects=_without(scene.objects, i))
    yield from _others(scene)
    yield from _cells(scene)
    yield from _landblocks(scene)
    yield from _mover(scene)
    yield from _motion_table(scene)
    if scene.engine_mode != "server":  # the default mode: a placement or ticks run in it too
        yield scene.replace(engine_mode="server")


def shrink_scene(scene: Scene, still_fails: Callable[[Scene], bool], budget: int = DEFAULT_BUDGET) -> tuple[Scene, int]:
    """The smallest scene found from `scene` for which `still_fails` holds, and the candidates tried.

    Greedy: the first candidate that still fails replaces the scene and the candidates start
    over from it; done when none does or `budget` candidates were tried. A candidate larger than
    `scene` in any measure (`no_larger`) is never run: the scene returned is never larger."""
    limit = size(scene)
    tried = 0
    improved = True
    while improved and tried < budget:
        improved = False
        for c in _candidates(scene):
            if tried >= budget:
                break
            try:
                c = validate_scene(c)
            except InvalidScene:
                continue
            if not no_larger(limit, c):
                continue
            tried += 1
            if still_fails(c):
                scene = c
                improved = True
                break
    return scene, tried
